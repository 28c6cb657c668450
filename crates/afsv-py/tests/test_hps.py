"""The built-in Chapter 6 problem (`afsv.optimize_hps`, the GA of `afsv optimize hps`):
argument errors with the CLI's messages, and agreement with the CLI to the last digit
(opt-in, AFSV_PY_SLOW=1: the smallest GA still makes 14 vehicle runs per side, and the D4
sweep 10 more)."""

from __future__ import annotations

import math
import os
import re
import subprocess
import threading
import time
from pathlib import Path

import pytest

import afsv
from conftest import without_reasons

slow = pytest.mark.skipif(
    os.environ.get("AFSV_PY_SLOW") != "1",
    reason="a GA run of the 3-D vehicle; run with AFSV_PY_SLOW=1 bash scripts/python-test.sh",
)


def cli_error(afsv_bin: Path, *args: str, cwd: Path) -> str:
    """The message of a failing `afsv ARGS...` (without the `afsv: error: ` prefix)."""
    p = subprocess.run([str(afsv_bin), "--quiet", *args], cwd=cwd, capture_output=True, text=True)
    assert p.returncode != 0, f"afsv {' '.join(args)} should fail"
    m = re.search(r"afsv: error: (.*)", p.stderr)
    assert m, p.stderr
    return m.group(1).strip()


@pytest.mark.parametrize(
    "flag, value",
    [("population", "3"), ("population", "2"), ("population", "1002"), ("generations", "0"),
     ("generations", "1001"), ("reevaluation-seeds", "0"), ("reevaluation-seeds", "101")],
)
def test_bad_counts_give_the_clis_message(afsv_bin: Path, tmp_path: Path, flag: str, value: str) -> None:
    want = cli_error(afsv_bin, "optimize", "hps", f"--{flag}", value, cwd=tmp_path)
    name = flag.replace("-", "_")
    with pytest.raises(ValueError) as e:
        afsv.optimize_hps(**{name: int(value)})
    # the CLI's message, with the Python argument's name for the option's
    assert str(e.value) == want.replace(f"--{flag}", name)


def test_a_vehicle_without_a_front_strut_gives_the_clis_message(afsv_bin: Path, tmp_path: Path) -> None:
    toml = afsv.load_vehicle("prototype").toml
    no_strut, n = re.subn(r'(?m)^strut = "front-axle"\n', "", toml)
    assert n == 1
    path = tmp_path / "no-strut.toml"
    path.write_text(no_strut)
    want = cli_error(afsv_bin, "optimize", "hps", "--vehicle", str(path), cwd=tmp_path)
    with pytest.raises(ValueError) as e:
        afsv.optimize_hps(str(path))
    assert str(e.value) == want and "gives the front axle no strut" in want


def test_other_bad_arguments() -> None:
    with pytest.raises(ValueError, match="population -4: must be even, 4 to 1000"):
        afsv.optimize_hps(population=-4)
    with pytest.raises(ValueError, match="seed -1: must be 0 to 18446744073709551615"):
        afsv.optimize_hps(seed=-1)
    with pytest.raises(ValueError, match="terrain_seed 18446744073709551616"):
        afsv.optimize_hps(terrain_seed=2**64)
    with pytest.raises(TypeError):
        afsv.optimize_hps(population=4.0)  # type: ignore[arg-type]
    with pytest.raises(TypeError):
        afsv.optimize_hps(generations="2")  # type: ignore[arg-type]
    with pytest.raises(TypeError, match="vehicle: expected a Vehicle"):
        afsv.optimize_hps(3)  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="is a rigid truck"):
        afsv.optimize_hps("chapter2-truck")


# The smallest GA (4 designs, 2 generations) on one re-evaluation seed without the D2
# runs, then the D4 speed sweep (10 runs). With the default GA seed the optimum moves off
# the nominal design (F about 1.86), so the search itself is compared, not only the
# nominal's re-evaluation.
GA_SEED = 1


@slow
def test_hps_ga_matches_the_cli(cli, tmp_path: Path) -> None:
    out = cli(
        "optimize", "hps", "--json", "--population", "4", "--generations", "2", "--seed", str(GA_SEED),
        "--reevaluation-seeds", "1", "--no-roll", "--strut-out", "cli-strut.json", "--speed-sweep",
    )
    # the run releases the GIL: a Python thread keeps counting meanwhile
    result = {}
    ticks = []
    th = threading.Thread(target=lambda: result.setdefault("r", afsv.optimize_hps(
        population=4, generations=2, seed=GA_SEED, reevaluation_seeds=1, roll=False, speed_sweep=True)))
    th.start()
    while th.is_alive():
        ticks.append(1)
        time.sleep(0.01)
    th.join()
    got = result["r"]
    assert len(ticks) > 10
    # every number of `--json`, bit for bit (JSON floats round-trip exactly)
    want = without_reasons({k: v for k, v in out.items() if k != "provenance"})
    assert got.to_dict() == want
    # D4 on the optimum (Fig 6.16): both loads at the five speeds on the one seed
    sweep = got.speed_sweep
    assert sweep is not None and sweep["seeds"] == [1] and len(sweep["points"]) == 10
    # the typed view carries the same values
    assert got.design == afsv.HpsDesign(**out["design"])
    assert got.nominal_design == afsv.HpsDesign(0.038, 8e-6, 11e-6)  # Table 6.3
    assert got.objective == out["objective"] < 2.0  # Eq 6.19: the nominal has F = 2
    assert got.feasible and got.optimum_ride.a_wz_m_s2 <= got.settings.a_wz_limit_m_s2 == 0.85
    assert got.nominal_ride.a_wz_m_s2 == out["nominal_ride"]["a_wz_m_s2"]
    assert got.evaluations == out["evaluations"] == 4 + 2 * 4 + 2
    a = got.optimum_over_seeds
    assert a.a_wz_m_s2 == afsv.Spread(out["optimum_over_seeds"]["a_wz_m_s2"]["mean"], 0.0, 1)
    assert a.omega_z_hz == out["optimum_over_seeds"]["omega_z_hz"]
    assert math.isnan(a.sp_drt_m_s2.mean) and a.sp_drt_m_s2.n == 0  # roll=False
    assert got.settings.lower == (0.026, 4e-6, 7e-6)  # Eq 6.20
    # the strut file is the CLI's --strut-out, byte for byte
    got.save_strut(tmp_path / "py-strut.json")
    assert (tmp_path / "py-strut.json").read_bytes() == (tmp_path / "cli-strut.json").read_bytes()
    assert got.strut["a_hc"] == got.design.a_hc
