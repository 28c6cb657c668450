"""The design optimisers of the toolkit (crate ``optimize``, docs/optimisation.md) on a
Python objective: generalised pattern search, SLSQP and a genetic algorithm over a box with
inequality constraints c_j(x) <= 0 (the solvers of Chapters 4 and 6)."""

from __future__ import annotations

import json
from dataclasses import dataclass
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np

from . import _afsv

Objective = Callable[[np.ndarray], Union[float, Tuple[float, Sequence[float]]]]


@dataclass
class OptimizeResult:
    """The best point found: `x`, objective `f`, constraint values (feasible where all
    <= 0), the number of objective calls and the solver's stop reason."""

    x: np.ndarray
    f: float
    constraints: List[float]
    feasible: bool
    evaluations: int
    status: str


def minimize(
    fun: Objective,
    bounds: Sequence[Tuple[float, float]],
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
    by `fun` ends the run and is raised here."""
    b = [(float(lo), float(hi)) for lo, hi in bounds]

    def call(x: List[float]) -> Any:
        return fun(np.array(x, dtype=np.float64))

    out = json.loads(_afsv.minimize(
        call, [lo for lo, _ in b], [hi for _, hi in b], int(n_constraints), method,
        None if x0 is None else [float(v) for v in x0],
        None if options is None else json.dumps(options),
    ))
    return OptimizeResult(
        x=np.array(out["x"], dtype=np.float64), f=out["f"], constraints=out["constraints"],
        feasible=out["feasible"], evaluations=out["evaluations"], status=out["status"],
    )
