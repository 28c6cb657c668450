"""The built-in design problem of Chapter 6: the front-axle hydro-pneumatic strut (HPS)
design of section 6.5.2 by a genetic algorithm, as ``afsv optimize hps`` runs it."""

from __future__ import annotations

import json
import os
from dataclasses import dataclass
from typing import Any, Dict, Optional, Tuple, Union

from . import _afsv
from .vehicle import Vehicle, vehicle_ref


def _num(v: Optional[float]) -> float:
    """A JSON number, null (a measure not computed: NaN) as NaN."""
    return float("nan") if v is None else float(v)


@dataclass(frozen=True)
class HpsDesign:
    """One Chapter 6 strut design chi (m²): piston area A_hc, one check valve's opening
    A_v and one bleed orifice's opening A_b (Table 6.3 gives the nominal 0.038, 8e-6,
    11e-6)."""

    a_hc: float
    a_v: float
    a_b: float

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "HpsDesign":
        return cls(a_hc=d["a_hc"], a_v=d["a_v"], a_b=d["a_b"])


@dataclass(frozen=True)
class RideValues:
    """a_wz (W_k-weighted vertical RMS at the seat, ISO 2631-1, m/s²) and d_s (the HPS
    peak-to-peak travel, m) of one D1 ride run (unloaded, 20 km/h, class E)."""

    a_wz_m_s2: float
    d_s_m: float

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "RideValues":
        return cls(a_wz_m_s2=_num(d["a_wz_m_s2"]), d_s_m=_num(d["d_s_m"]))


@dataclass(frozen=True)
class Spread:
    """Mean, sample SD and count of a measure over terrain seeds (NaN and n = 0 when it was
    not computed)."""

    mean: float
    sd: float
    n: int

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "Spread":
        return cls(mean=_num(d["mean"]), sd=_num(d["sd"]), n=int(d["n"]))


@dataclass(frozen=True)
class HpsAssessment:
    """A design over the re-evaluation seeds: D1 a_wz unloaded, D2 SP-DRT loaded (LTR,
    Eq 2.11; NaN when `roll` was off) and D3 omega_z loaded on smooth ground (Hz)."""

    a_wz_m_s2: Spread
    sp_drt_m_s2: Spread
    omega_z_hz: float

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "HpsAssessment":
        return cls(
            a_wz_m_s2=Spread._of(d["a_wz_m_s2"]),
            sp_drt_m_s2=Spread._of(d["sp_drt_m_s2"]),
            omega_z_hz=_num(d["omega_z_hz"]),
        )


@dataclass(frozen=True)
class HpsGaSettings:
    """The settings of the run: GA population and generations, the GA's seed, the search's
    terrain seed, the box of Eq 6.20 (lower bounds from the chapter; the upper bounds, +30 %
    A_hc, 2 x A_v and 4 x A_b of Table 6.3, are an assumption), the a_wz limit (m/s²), the
    re-evaluation seeds and whether SP-DRT was re-evaluated."""

    population: int
    generations: int
    ga_seed: int
    terrain_seed: int
    lower: Tuple[float, float, float]
    upper: Tuple[float, float, float]
    a_wz_limit_m_s2: float
    reevaluation_seeds: int
    reevaluate_roll: bool

    @classmethod
    def _of(cls, d: Dict[str, Any]) -> "HpsGaSettings":
        lo, hi = d["lower"], d["upper"]
        return cls(
            population=d["population"], generations=d["generations"], ga_seed=d["ga_seed"],
            terrain_seed=d["terrain_seed"], lower=(lo[0], lo[1], lo[2]), upper=(hi[0], hi[1], hi[2]),
            a_wz_limit_m_s2=d["a_wz_limit_m_s2"], reevaluation_seeds=d["reevaluation_seeds"],
            reevaluate_roll=d["reevaluate_roll"],
        )


@dataclass(frozen=True)
class HpsOptimum:
    """The result of :func:`optimize_hps`, field for field the JSON of
    ``afsv optimize hps --json``.

    * `design`, `objective` (Eq 6.19; the nominal design has F = 2), `feasible` (a_wz <= the
      limit of Eq 6.20 on the search seed);
    * `nominal_ride` (a_wzn, d_sn) and `optimum_ride` on the search seed;
    * `nominal_over_seeds`, `optimum_over_seeds`: both designs over the re-evaluation seeds;
    * `evaluations`: vehicle runs of the search;
    * `strut`: the optimum's full strut parameter set (what ``--strut-out`` writes, the
      ``hps=`` file of :func:`simulate_vehicle`; :meth:`save_strut` writes it);
    * `speed_sweep`: D4 on the optimum (Fig 6.16) as a dict, when asked."""

    settings: HpsGaSettings
    nominal_design: HpsDesign
    design: HpsDesign
    objective: float
    feasible: bool
    nominal_ride: RideValues
    optimum_ride: RideValues
    evaluations: int
    nominal_over_seeds: HpsAssessment
    optimum_over_seeds: HpsAssessment
    strut: Dict[str, Any]
    speed_sweep: Optional[Dict[str, Any]]
    strut_json: str
    raw: Dict[str, Any]

    def save_strut(self, path: Union[str, "os.PathLike[str]"]) -> None:
        """Write the optimum's strut parameters to `path`, byte for byte the file of
        ``afsv optimize hps --strut-out`` (JSON, read by ``hps=`` and ``--hps``)."""
        with open(path, "w", encoding="utf-8") as f:
            f.write(self.strut_json)

    def to_dict(self) -> Dict[str, Any]:
        """The result as the CLI's JSON object (NaN as None), plus ``speed_sweep``."""
        return dict(self.raw)


def optimize_hps(
    vehicle: Union[None, str, Vehicle] = None,
    *,
    population: int = 20,
    generations: int = 10,
    seed: int = 1,
    terrain_seed: int = 1,
    reevaluation_seeds: int = 10,
    roll: bool = True,
    speed_sweep: bool = False,
) -> HpsOptimum:
    """The Chapter 6 HPS design optimisation of ``afsv optimize hps`` (section 6.5.2),
    with the same arguments and the same numbers.

    A real-coded genetic algorithm (SBX crossover, polynomial mutation, Deb's feasibility
    rules; `population` even, 4 to 1000, over `generations`, 1 to 1000, from `seed`) over
    chi = [A_hc, A_v, A_b] minimises ``F(chi) = a_wz / a_wzn + d_s / d_sn`` (Eq 6.19) for
    the unloaded vehicle at 20 km/h on ISO 8608 class E (D1), subject to
    ``a_wz <= 0.85 m/s²`` and ``chi >= [0.026, 4e-6, 7e-6] m²`` (Eq 6.20); a_wzn and d_sn
    are the nominal design's (Table 6.3, the vehicle's front-axle strut, which starts in
    the initial population) on the same terrain. Every design runs on the one terrain
    `terrain_seed`; the optimum and the nominal are then re-evaluated over
    `reevaluation_seeds` seeds (1 to 100; from `terrain_seed`) with SP-DRT (D2, skipped
    when `roll` is False, the costliest runs) and omega_z (D3): the rows of Table 6.4.
    With `speed_sweep`, D4 follows on the optimum: both loads at 10-30 km/h, with the
    speed at which a_wz crosses the 8 h caution zone (Fig 6.16).

    `vehicle`: an articulated description whose front axle has a strut (default: the
    prototype). Each generation costs `population` vehicle runs; the runs go in parallel
    in Rust with the GIL released. An infeasible best (no design met the a_wz limit) is
    returned with ``feasible`` False, where the CLI exits with its not-earned status."""
    out = json.loads(_afsv.optimize_hps(
        vehicle_ref(vehicle), population, generations, seed, terrain_seed, reevaluation_seeds,
        bool(roll), bool(speed_sweep),
    ))
    strut_json = out.pop("strut_json")
    return HpsOptimum(
        settings=HpsGaSettings._of(out["settings"]),
        nominal_design=HpsDesign._of(out["nominal_design"]),
        design=HpsDesign._of(out["design"]),
        objective=out["objective"],
        feasible=out["feasible"],
        nominal_ride=RideValues._of(out["nominal_ride"]),
        optimum_ride=RideValues._of(out["optimum_ride"]),
        evaluations=out["evaluations"],
        nominal_over_seeds=HpsAssessment._of(out["nominal_over_seeds"]),
        optimum_over_seeds=HpsAssessment._of(out["optimum_over_seeds"]),
        strut=json.loads(strut_json),
        speed_sweep=out["speed_sweep"],
        strut_json=strut_json,
        raw=out,
    )
