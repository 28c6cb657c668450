"""Errors, shapes, dtypes and units of the Python API; nothing panics across the boundary."""

from __future__ import annotations

import subprocess
import threading
import time
from pathlib import Path

import numpy as np
import pytest

import afsv


def test_record_channels_are_float64_arrays_of_one_length() -> None:
    rec = afsv.simulate_yaw(duration=2, dt=0.01)
    assert len(rec) == 201 and rec.t[0] == 0.0 and rec.t[-1] == pytest.approx(2.0)
    for name in rec:
        a = rec[name]
        assert isinstance(a, np.ndarray) and a.dtype == np.float64 and a.shape == (201,), name
    assert rec.articulation_deg is rec["articulation_deg"]
    assert "time_s" in rec and rec.names[0] == "time_s"
    # units: the 50 km/h default in m/s, a km/h-free record
    assert rec.speed_m_s[0] == pytest.approx(50 / 3.6)
    assert rec.meta["speed_m_s"] == pytest.approx(50 / 3.6)
    with pytest.raises(KeyError, match="no channel `nope`"):
        rec["nope"]
    with pytest.raises(AttributeError):
        rec.nope


def test_to_pandas_only_when_pandas_is_importable() -> None:
    rec = afsv.simulate_strut(cycles=2)
    try:
        import pandas  # noqa: F401
    except ImportError:
        with pytest.raises(ImportError, match="needs pandas"):
            rec.to_pandas()
    else:
        df = rec.to_pandas()
        assert list(df.columns) == rec.names and len(df) == len(rec)


def test_bad_arguments_raise_value_error_with_the_library_message() -> None:
    with pytest.raises(ValueError, match="choose one PSD model"):
        afsv.synthesize(iso_class="E", terrain="pasture")
    with pytest.raises(ValueError, match="iso_class"):
        afsv.synthesize(iso_class="Z")
    with pytest.raises(ValueError, match="coherence"):
        afsv.synthesize(coherence="wobbly")
    with pytest.raises(ValueError, match="dt"):
        afsv.simulate_yaw(dt=-1)
    with pytest.raises(ValueError, match="not understood"):
        afsv.simulate_yaw(input="zigzag")
    with pytest.raises(ValueError, match="load"):
        afsv.simulate_yaw(load="half")
    with pytest.raises(ValueError, match="travel"):
        afsv.simulate_strut(amp_mm=500)
    with pytest.raises(ValueError, match="samples"):
        afsv.simulate_strut(cycles=1e9)
    with pytest.raises(ValueError, match="rigid truck"):
        afsv.simulate_vehicle("chapter2-truck")
    with pytest.raises(ValueError, match="articulated"):
        afsv.simulate_truck("prototype")
    with pytest.raises(ValueError, match="speed_kmh"):
        afsv.simulate_vehicle(speed_kmh=500)
    with pytest.raises(ValueError, match="model `boat`"):
        afsv.simulate("boat")
    with pytest.raises(ValueError, match="weighting"):
        afsv.iso2631(np.arange(100) * 0.01, az=np.zeros(100), weightings=("wd", "wd", "wq"))


def test_bad_types_raise_type_error() -> None:
    with pytest.raises(TypeError):
        afsv.welch_psd(["a", "b"], 0.1)
    with pytest.raises(TypeError):
        afsv.simulate_vehicle(steer="pulse")
    with pytest.raises(TypeError):
        afsv.simulate_yaw(vehicle=42)
    with pytest.raises(ValueError, match="1-D"):
        afsv.ltr(np.zeros((2, 2)), np.zeros(2), np.zeros(2), np.zeros(2))
    with pytest.raises(ValueError, match="1-D"):
        afsv.decay(0.0, 1.0)


def test_a_bad_description_names_file_line_and_field(tmp_path: Path) -> None:
    text = afsv.load_vehicle("prototype").toml.replace('format = "afsv-vehicle-1"', 'format = "afsv-vehicle-9"')
    (tmp_path / "bad.toml").write_text(text)
    with pytest.raises(ValueError, match="bad.toml"):
        afsv.load_vehicle(tmp_path / "bad.toml")
    with pytest.raises(ValueError):
        afsv.Vehicle.from_toml("format = 3")
    with pytest.raises(ValueError, match="nothing-here.toml"):
        afsv.load_vehicle(tmp_path / "nothing-here.toml")


def test_diverging_solver_raises_solver_error_with_time_and_state() -> None:
    # fixed-step RK4 at 0.1 s is far beyond the steering circuit's stability limit
    with pytest.raises(afsv.SolverError) as e:
        afsv.simulate_yaw(solver="rk4", rk4_step=0.1, dt=0.1)
    err = e.value
    assert isinstance(err, RuntimeError)
    assert 0.0 < err.t < 10.0
    assert isinstance(err.state, dict) and "articulation_rad" in err.state
    assert all(isinstance(v, float) for v in err.state.values())
    assert "diverged" in str(err) and "articulation" in err.reason


@pytest.mark.parametrize("solver", ["dopri", "rosenbrock"])
def test_diverging_strut_raises_solver_error_with_time_and_state(afsv_bin: Path, tmp_path: Path, solver: str) -> None:
    # 100 mm at 100 Hz (peak velocity 63 m/s): the orifice flow of Eqs 5.1-5.12 drives the
    # chamber pressure past 1 GPa within 7 ms and the step size to 1e-13 s
    with pytest.raises(afsv.SolverError) as e:
        afsv.simulate_strut(freq=100, amp_mm=100, solver=solver)
    err = e.value
    assert 0.0 < err.t < 0.01
    # the strut's states are unnamed: the last finite state as a list (z, P, v)
    assert isinstance(err.state, list) and len(err.state) == 3
    assert all(isinstance(v, float) and np.isfinite(v) for v in err.state)
    assert err.state[1] > 1e9
    assert "solver diverged at t = " in err.reason and err.reason == str(err)
    # the CLI fails on the same run with the same message (time and state to the digit)
    p = subprocess.run(
        [str(afsv_bin), "--quiet", "hps", "harmonic", "--freq", "100", "--amp-mm", "100", "--solver", solver],
        cwd=tmp_path, capture_output=True, text=True,
    )
    assert p.returncode != 0 and p.stderr.strip() == f"afsv: error: {err}"


def test_psd_of_synthesized_terrain_follows_eq_2_8_in_band() -> None:
    rec = afsv.synthesize(iso_class="E", length=2000, dx=0.05, seed=4, coherence="none")
    s = afsv.welch_psd(rec.left_m, 0.05, segment_m=51.2)
    band = (s.freq > 0.1) & (s.freq < 2.0)
    target = rec.meta["terrain"]["psd"]["alpha_r"] * s.freq[band] ** -2.0
    ratio_db = 10 * np.log10(np.mean(s.psd[band] / target))
    assert abs(ratio_db) < 1.0
    assert s.freq.dtype == np.float64 and s.freq.shape == s.psd.shape


def test_runs_release_the_gil() -> None:
    # a Python thread keeps counting while a run is in Rust
    ticks = []
    stop = threading.Event()

    def count() -> None:
        while not stop.is_set():
            ticks.append(1)
            time.sleep(0.001)

    th = threading.Thread(target=count)
    th.start()
    time.sleep(0.01)
    before = len(ticks)
    t0 = time.perf_counter()
    # long enough to last well over 0.1 s on a fast machine (20 s of it took 0.09 s)
    afsv.simulate_vehicle(terrain_class="E", duration=120)
    elapsed = time.perf_counter() - t0
    during = len(ticks) - before
    stop.set()
    th.join()
    assert elapsed > 0.1, elapsed
    # with the GIL held through the run the thread could not tick at all in between
    assert during >= 20, (during, elapsed)


def test_records_from_files_and_arrays(tmp_path: Path) -> None:
    with pytest.raises(ValueError, match="missing.csv"):
        afsv.read_record(tmp_path / "missing.csv")
    (tmp_path / "bad.csv").write_text("time_s,x_m\n0,1\n0.1,zz\n")
    with pytest.raises(ValueError, match="bad.csv:3"):
        afsv.read_record(tmp_path / "bad.csv")
    r = afsv.Record.from_arrays({"time_s": [0.0, 0.1, 0.2], "x_m": np.array([1.0, 2.0, 3.0])}, {"note": "mine"})
    assert r.names == ["time_s", "x_m"] and r.meta == {"note": "mine"} and r.x_m.dtype == np.float64
    with pytest.raises(ValueError, match="samples"):
        afsv.Record.from_arrays({"time_s": [0.0, 0.1], "x_m": [1.0]})


def test_yaw_batch_runs_in_parallel_and_equals_single_runs() -> None:
    runs = [{"speed_kmh": v, "input": "step:20", "duration": 3} for v in (20.0, 35.0, 50.0)]
    batch = afsv.simulate_yaw_batch(runs)
    assert len(batch) == 3
    for kw, rec in zip(runs, batch):
        single = afsv.simulate_yaw(**kw)
        assert rec.names == single.names
        assert all(np.array_equal(rec[n], single[n]) for n in rec.names)
        assert rec.meta["speed_m_s"] == pytest.approx(kw["speed_kmh"] / 3.6)
    with pytest.raises(ValueError, match="load"):
        afsv.simulate_yaw_batch([{"speed_kmh": 20.0}, {"load": "half"}])
    with pytest.raises(TypeError):
        afsv.simulate_yaw_batch([{"sped_kmh": 20.0}])
    with pytest.raises(afsv.SolverError):
        afsv.simulate_yaw_batch([{"duration": 2}, {"solver": "rk4", "rk4_step": 0.1, "dt": 0.1}])


@pytest.mark.parametrize(
    "call",
    [
        lambda **kw: afsv.evaluate(**kw),
        lambda **kw: afsv.simulate_truck(**kw),
        lambda **kw: afsv.simulate_vehicle(terrain_class="E", **kw),
        lambda **kw: afsv.synthesize(iso_class="E", **kw),
        lambda **kw: afsv.optimize_afs(**kw),
    ],
)
def test_seeds_are_whole_numbers(call) -> None:
    # checked before any run: a negative seed is a ValueError (not OverflowError), a
    # fractional one a TypeError (not truncated)
    with pytest.raises(ValueError, match="seed -1: must be a whole number from 0 to 18446744073709551615"):
        call(seed=-1)
    with pytest.raises(TypeError, match="seed: expected an int, got float"):
        call(seed=1.5)
    with pytest.raises(ValueError, match="seed 18446744073709551616"):
        call(seed=2**64)


def test_counts_are_whole_numbers() -> None:
    with pytest.raises(ValueError, match="seeds -1"):
        afsv.evaluate(seeds=-1)
    with pytest.raises(ValueError, match="starts -1"):
        afsv.optimize_afs(starts=-1)
    with pytest.raises(TypeError, match="sqp_calls: expected an int, got str"):
        afsv.optimize_afs(sqp_calls="4")
    with pytest.raises(TypeError, match="n_constraints"):
        afsv.minimize(lambda x: x[0], [(0, 1)], n_constraints=0.5)
    assert afsv.simulate_truck(seed=np.uint64(3), duration=0.5).meta["rollover_s"] is None
