"""Runs of the four models, each returning a :class:`Record` with the channels of the
matching CLI command (``afsv yaw simulate``, ``afsv hps harmonic``, ``afsv roll simulate``,
``afsv vehicle simulate``). The runs release the GIL; a diverging solver raises
:class:`afsv.SolverError` with the time and the last finite state."""

from __future__ import annotations

import json
from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

from . import _afsv
from ._arrays import maybe_bytes, whole
from .record import Record
from .vehicle import Vehicle, vehicle_ref

VehicleArg = Union[None, str, Vehicle]


def _yaw_args(
    vehicle: VehicleArg = None,
    *,
    params: Optional[Dict[str, Any]] = None,
    load: str = "loaded",
    speed_kmh: float = 50.0,
    input: str = "pulse",
    table: Optional[Tuple[Sequence[float], Sequence[float]]] = None,
    input_time: float = 0.5,
    duration: float = 10.0,
    dt: float = 0.005,
    solver: str = "dopri",
    rtol: float = 1e-5,
    form: str = "energy-consistent",
    rk4_step: float = 2e-4,
) -> Dict[str, Any]:
    """The native arguments of one yaw-plane run."""
    return dict(
        vehicle=vehicle_ref(vehicle),
        params_json=None if params is None else json.dumps(params),
        load=load,
        speed_kmh=float(speed_kmh),
        input=input,
        table_t=None if table is None else maybe_bytes("table times", table[0]),
        table_deg=None if table is None else maybe_bytes("table angles", table[1]),
        input_time=float(input_time),
        duration=float(duration),
        dt=float(dt),
        solver=solver,
        rtol=float(rtol),
        form=form,
        rk4_step=float(rk4_step),
    )


def simulate_yaw(
    vehicle: VehicleArg = None,
    *,
    params: Optional[Dict[str, Any]] = None,
    load: str = "loaded",
    speed_kmh: float = 50.0,
    input: str = "pulse",
    table: Optional[Tuple[Sequence[float], Sequence[float]]] = None,
    input_time: float = 0.5,
    duration: float = 10.0,
    dt: float = 0.005,
    solver: str = "dopri",
    rtol: float = 1e-5,
    form: str = "energy-consistent",
    rk4_step: float = 2e-4,
) -> Record:
    """The yaw-plane vehicle of Chapter 3 (Eqs 3.13-3.17) with the hydraulic frame steering
    (Eqs 3.1-3.12).

    `input` is the CLI's ``--input``: ``pulse[:PEAK_DEG]`` (0.2 s half-sine), ``step:DEG``,
    ``ramp:DEG_PER_S[:LIMIT_DEG]``, ``turn`` or ``path-change`` (the Fig 3.6 courses with the
    driver); or give `table` = (times s, steering-wheel angles deg). `params` is a raw
    yaw-plane set (``afsv params dump yaw-plane``) instead of a description. `form`:
    ``energy-consistent`` or ``paper-eq-3-13``. `solver`: dopri, rosenbrock or rk4 (fixed
    step `rk4_step`, s)."""
    args = _yaw_args(
        vehicle, params=params, load=load, speed_kmh=speed_kmh, input=input, table=table,
        input_time=input_time, duration=duration, dt=dt, solver=solver, rtol=rtol, form=form,
        rk4_step=rk4_step,
    )
    cols, meta = _afsv.simulate_yaw(**args)
    return Record(cols, meta)


def simulate_yaw_batch(runs: Sequence[Dict[str, Any]]) -> List[Record]:
    """Many yaw-plane runs in parallel in Rust (all cores, GIL released): `runs` is a list
    of keyword-argument dicts of :func:`simulate_yaw` (e.g. ``[{"speed_kmh": v} for v in
    speeds]``); the records come back in that order, each equal to its single run. Every
    run is checked before any starts."""
    jobs = [_yaw_args(**kw) for kw in runs]
    return [Record(cols, meta) for cols, meta in _afsv.simulate_yaw_batch(jobs)]


def simulate_strut(
    strut: str = "front-axle",
    *,
    freq: float = 2.0,
    amp_mm: float = 7.5,
    cycles: float = 5.0,
    gamma0: Optional[float] = None,
    rate: float = 360.0,
    solver: str = "auto",
) -> Record:
    """A harmonic displacement test of the hydro-pneumatic strut with gas-oil emulsion
    (Chapter 5, Eqs 5.1-5.12). `strut`: ``front-axle`` (Table 6.3), ``lab-1orifice``,
    ``lab-2orifice`` or a strut parameter file. The last cycle's loop metrics (stiffness,
    damping, energy) are in ``rec.meta["last_cycle"]``."""
    cols, meta = _afsv.simulate_strut(
        str(strut), float(freq), float(amp_mm), float(cycles),
        None if gamma0 is None else float(gamma0), float(rate), solver,
    )
    return Record(cols, meta)


def characterize_strut(strut: str = "lab-1orifice", *, gamma0: Optional[float] = None) -> Dict[str, Any]:
    """The laboratory programme of Chapter 5 (0.1 Hz at 5/25/50 mm; 1-8 Hz at peak
    velocities 0.05-0.2356 m/s): stiffness, damping and energy per test."""
    return json.loads(_afsv.characterize_strut(str(strut), None if gamma0 is None else float(gamma0)))


def simulate_truck(
    vehicle: VehicleArg = None,
    *,
    truck: str = "calibrated",
    cg_height_m: Optional[float] = None,
    ramp_rate: Optional[float] = None,
    no_bump_stops: bool = False,
    direction: str = "left",
    terrain_class: Optional[str] = "E",
    waviness: float = 2.0,
    band: Tuple[float, float] = (0.02, 5.0),
    mc: float = 0.3,
    seed: int = 1,
    duration: Optional[float] = None,
    dt: float = 0.01,
    sp_threshold: Optional[float] = None,
    sp_max_dip: Optional[float] = None,
) -> Record:
    """The rigid 50 t mining truck of Chapter 2: a ramp steer to absolute rollover on the
    two-track terrain of Eqs 2.8-2.10 (`terrain_class` None: level ground). The roll
    measures (DRT, SP-DRT with LTR of Eq 2.11, SSF) are in ``rec.meta["measures"]``.
    `truck`: ``calibrated`` or ``plausible``, unless `vehicle` names a rigid-truck
    description."""
    cols, meta = _afsv.simulate_truck(
        vehicle_ref(vehicle), truck,
        None if cg_height_m is None else float(cg_height_m),
        None if ramp_rate is None else float(ramp_rate),
        bool(no_bump_stops), direction, terrain_class, float(waviness),
        (float(band[0]), float(band[1])), float(mc), whole("seed", seed),
        None if duration is None else float(duration), float(dt),
        None if sp_threshold is None else float(sp_threshold),
        None if sp_max_dip is None else float(sp_max_dip),
    )
    return Record(cols, meta)


def simulate_vehicle(
    vehicle: VehicleArg = None,
    *,
    load: str = "loaded",
    speed_kmh: float = 20.0,
    terrain_class: Optional[str] = None,
    mc: float = 0.3,
    seed: int = 1,
    hps: Optional[str] = None,
    steer: Sequence[Any] = ("none",),
    duration: float = 10.0,
    dt: float = 0.005,
) -> Record:
    """The integrated 3-D articulated vehicle of Chapter 6 on smooth ground, or on the
    ISO 8608 two-track terrain of Eqs 6.4-6.5 (`terrain_class` A-H, coherence cut-off `mc`
    cycles/m, `seed`). `steer`: ``("none",)``, ``("pulse", DEG, DUR_S, START_S)`` or
    ``("ramp", DEG_PER_S, START_S[, LIMIT_DEG])``. `hps`: ``"off"``, ``"nominal"`` or a strut
    file (default: as the description says)."""
    if isinstance(steer, str) or not steer:
        raise TypeError("steer: expected a tuple such as ('none',) or ('pulse', 30, 0.2, 1.0)")
    cols, meta = _afsv.simulate_vehicle(
        vehicle_ref(vehicle), load, float(speed_kmh), terrain_class, float(mc), whole("seed", seed),
        hps, str(steer[0]), [float(v) for v in steer[1:]], float(duration), float(dt),
    )
    return Record(cols, meta)


_MODELS = {
    "yaw": simulate_yaw,
    "strut": simulate_strut,
    "truck": simulate_truck,
    "vehicle": simulate_vehicle,
}


def simulate(model: str, *args: Any, **kwargs: Any) -> Record:
    """One run of `model`: ``"yaw"`` (:func:`simulate_yaw`), ``"strut"``
    (:func:`simulate_strut`), ``"truck"`` (:func:`simulate_truck`) or ``"vehicle"``
    (:func:`simulate_vehicle`); the other arguments go to that function."""
    try:
        f = _MODELS[model]
    except KeyError:
        raise ValueError(f"model `{model}`: expected one of {', '.join(_MODELS)}") from None
    return f(*args, **kwargs)
