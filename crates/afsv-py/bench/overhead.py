"""Overheads of the Python package (docs/python.md, "Overheads"; beside `cargo xtask bench`):

1. `afsv.evaluate()` from Python against `afsv evaluate --json` (the release binary), median
   wall time of `--repeat` runs each, interleaved, same seeds;
2. a sweep of `--points` yaw-plane runs called from a Python loop: the share of the wall
   time spent outside Rust (the loop, argument handling, the Record and its numpy views),
   i.e. 1 - (time inside the native call) / (total).

Run from the repository root after `cargo build --release -p afsv` and an install of the
package (scripts/python-test.sh or `pip install ./crates/afsv-py`):

    target/py-venv/bin/python crates/afsv-py/bench/overhead.py [--seeds 10] [--repeat 3] [--points 100]
"""

from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

import afsv
from afsv import _afsv

ROOT = Path(__file__).resolve().parents[3]


def median_times(fs, repeat: int):
    """Median wall time of each function, the functions run in turn `repeat` times
    (interleaved, so a change in the machine's load hits both alike)."""
    times = [[] for _ in fs]
    for _ in range(repeat):
        for f, ts in zip(fs, times):
            t0 = time.perf_counter()
            f()
            ts.append(time.perf_counter() - t0)
    return [statistics.median(ts) for ts in times]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--seeds", type=int, default=10, help="terrain seeds of evaluate (CLI default 10)")
    ap.add_argument("--repeat", type=int, default=3, help="runs per timing (median)")
    ap.add_argument("--points", type=int, default=100, help="yaw-plane runs of the sweep")
    ap.add_argument("--afsv", default=str(ROOT / "target" / "release" / "afsv"), help="the CLI binary")
    a = ap.parse_args()

    cli = [a.afsv, "--quiet", "evaluate", "--json", "--seeds", str(a.seeds)]
    t_cli, t_py = median_times(
        [lambda: subprocess.run(cli, check=True, capture_output=True), lambda: afsv.evaluate(seeds=a.seeds)],
        a.repeat,
    )

    inside = [0.0]
    native = _afsv.simulate_yaw

    def timed(*args, **kwargs):
        t0 = time.perf_counter()
        try:
            return native(*args, **kwargs)
        finally:
            inside[0] += time.perf_counter() - t0

    _afsv.simulate_yaw = timed
    try:
        speeds = np.linspace(10.0, 60.0, a.points)
        t0 = time.perf_counter()
        peaks = []
        for v in speeds:
            rec = afsv.simulate_yaw(speed_kmh=float(v), input="pulse:30", duration=6)
            peaks.append(float(np.max(np.abs(rec.articulation_deg))))
        t_sweep = time.perf_counter() - t0
    finally:
        _afsv.simulate_yaw = native
    out = {
        "evaluate": {
            "seeds": a.seeds,
            "repeat": a.repeat,
            "cli_s": round(t_cli, 3),
            "python_s": round(t_py, 3),
            "python_over_cli": round(t_py / t_cli, 4),
        },
        "yaw_sweep": {
            "points": a.points,
            "total_s": round(t_sweep, 4),
            "inside_rust_s": round(inside[0], 4),
            "outside_rust_fraction": round(1.0 - inside[0] / t_sweep, 4),
            "per_point_ms": round(1e3 * t_sweep / a.points, 3),
        },
    }
    json.dump(out, sys.stdout, indent=2)
    print()


if __name__ == "__main__":
    main()
