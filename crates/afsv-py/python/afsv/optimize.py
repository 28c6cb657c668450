"""The design optimisers of the toolkit (crate ``optimize``, docs/optimisation.md) on a
Python objective: generalised pattern search, SLSQP and a genetic algorithm over a box with
inequality constraints c_j(x) <= 0 (the solvers of Chapters 4 and 6)."""

from __future__ import annotations

import json
from dataclasses import dataclass
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np

from . import _afsv
from ._arrays import whole

Objective = Callable[[np.ndarray], Union[float, Tuple[float, Sequence[float]]]]


@dataclass
class OptimizeResult:
    """The best point found: `x`, objective `f`, constraint values (feasible where all
    <= 0), the number of Python objective calls (None for a built-in problem) and the
    solver's stop reason."""

    x: np.ndarray
    f: float
    constraints: List[float]
    feasible: bool
    evaluations: Optional[int]
    status: str


def minimize(
    fun: Union[Objective, "_afsv.AfsProblem"],
    bounds: Optional[Sequence[Tuple[float, float]]] = None,
    *,
    n_constraints: int = 0,
    method: str = "pattern-search",
    x0: Optional[Sequence[float]] = None,
    options: Optional[Dict[str, Any]] = None,
) -> OptimizeResult:
    """Minimise `fun(x)` over the box `bounds` = [(lo, hi), ...].

    `fun` gets `x` as a float64 array and returns f, or (f, [c_1, ..., c_m]) with
    `n_constraints` = m constraints c_j(x) <= 0. `method`: ``pattern-search`` (GPS on the
    unit-scaled box, extreme barrier, optional Latin-hypercube search step),
    ``sqp`` (SLSQP, finite-difference gradients) or ``ga`` (SBX crossover, polynomial
    mutation, Deb's feasibility rules). `options` replaces the method's defaults (e.g.
    ``{"min_mesh": 1e-5}``, ``{"max_calls": 50}``, ``{"population": 20, "generations": 30,
    "seed": 1}``); an unknown key is a ValueError listing the known ones. An exception raised
    by `fun` ends the run and is raised here.

    `fun` may instead be a built-in problem (:class:`AfsProblem`, Chapter 4): its own
    bounds and constraints apply and the whole run stays in Rust."""
    if isinstance(fun, _afsv.AfsProblem):
        lo_hi: Tuple[List[float], List[float]] = fun.bounds
        target: Any = fun
    else:
        if bounds is None:
            raise TypeError("bounds: required for a Python objective")
        b = [(float(lo), float(hi)) for lo, hi in bounds]
        lo_hi = ([lo for lo, _ in b], [hi for _, hi in b])

        def target(x: List[float]) -> Any:
            return fun(np.array(x, dtype=np.float64))

    out = json.loads(_afsv.minimize(
        target, lo_hi[0], lo_hi[1], whole("n_constraints", n_constraints), method,
        None if x0 is None else [float(v) for v in x0],
        None if options is None else json.dumps(options),
    ))
    return OptimizeResult(
        x=np.array(out["x"], dtype=np.float64), f=out["f"], constraints=out["constraints"],
        feasible=out["feasible"], evaluations=out["evaluations"], status=out["status"],
    )


AfsProblem = _afsv.AfsProblem


def optimize_afs(
    *,
    relaxed: bool = False,
    min_arm_m: Optional[float] = 0.25,
    starts: int = 4,
    seed: int = 1,
    search_points: int = 75,
    screen_mesh: float = 1.0 / 32.0,
    min_mesh: float = 1.0 / 512.0,
    sqp_calls: int = 40,
    rtol: float = 1e-8,
    form: str = "energy-consistent",
) -> Dict[str, Any]:
    """The Chapter 4 frame-steering optimisation of ``afsv optimize afs`` (one
    configuration): minimise the Eq 4.8 objective with the AHP weights of Eq 4.17 over
    [A_0, l_1, l_2, a_v, B_eff] (Table 4.2; B_eff up to 2.08 GPa when `relaxed`), subject to
    Eq 4.10 and a full-lock steering arm >= `min_arm_m` (None: no arm constraint), by
    multi-start pattern search (maximin Latin-hypercube starts) and SQP. Returns the
    optimum: ``starts``, ``ps`` and ``ps_sqp`` (design, measures, ratios to the current
    design), evaluations."""
    return json.loads(_afsv.optimize_afs(
        bool(relaxed), None if min_arm_m is None else float(min_arm_m), whole("starts", starts), whole("seed", seed),
        whole("search_points", search_points), float(screen_mesh), float(min_mesh), whole("sqp_calls", sqp_calls), float(rtol), form,
    ))
