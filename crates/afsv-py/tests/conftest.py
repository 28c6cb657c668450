"""Shared helpers: the CLI binary (AFSV_BIN, default target/release/afsv of this workspace),
running it, and reading its CSV records exactly (shortest round-trip floats)."""

from __future__ import annotations

import csv
import json
import os
import subprocess
from pathlib import Path
from typing import Any, Dict, List

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[3]


@pytest.fixture(scope="session")
def afsv_bin() -> Path:
    path = Path(os.environ.get("AFSV_BIN", ROOT / "target" / "release" / "afsv"))
    if not path.is_file():
        pytest.fail(f"the CLI binary {path} is missing: build it with `cargo build --release -p afsv` (or set AFSV_BIN)")
    return path


@pytest.fixture
def cli(afsv_bin: Path, tmp_path: Path):
    """Run `afsv ARGS...` in a scratch folder; its stdout parsed as JSON (None if empty)."""

    def run(*args: str) -> Any:
        p = subprocess.run([str(afsv_bin), "--quiet", *args], cwd=tmp_path, capture_output=True, text=True)
        if p.returncode != 0:
            raise AssertionError(f"afsv {' '.join(args)} failed ({p.returncode}): {p.stderr}")
        return json.loads(p.stdout) if p.stdout.strip() else None

    return run


def read_csv(path: Path) -> Dict[str, np.ndarray]:
    """The columns of a CLI record, parsed with Python's float (exact for Rust's `{}`)."""
    with open(path, newline="") as f:
        rows: List[List[str]] = list(csv.reader(f))
    names, body = rows[0], rows[1:]
    return {n: np.array([float(r[i]) for r in body], dtype=np.float64) for i, n in enumerate(names)}


def assert_same_record(rec: Any, cols: Dict[str, np.ndarray]) -> None:
    """Every channel of the Python record equals the CLI's column bit for bit, same names
    in the same order."""
    assert rec.names == list(cols), (rec.names, list(cols))
    for name, want in cols.items():
        got = rec[name]
        assert got.dtype == np.float64 and got.shape == want.shape, name
        # array_equal is exact; NaN never appears in a record (the CLI refuses it)
        assert np.array_equal(got, want), f"{name}: max diff {np.max(np.abs(got - want))}"


def without_reasons(v: Any) -> Any:
    """The CLI's JSON without its `*_reason` explanations of nulls (presentation only)."""
    if isinstance(v, dict):
        return {k: without_reasons(x) for k, x in v.items() if not k.endswith("_reason")}
    return v
