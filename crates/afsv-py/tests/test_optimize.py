"""The optimisers on Python objectives: known optima, determinism, errors."""

from __future__ import annotations

import numpy as np
import pytest

import afsv


def circle_problem(x: np.ndarray):
    # min (x-1)^2 + (y-2)^2 subject to x + y <= 2: the optimum is (0.5, 1.5), f = 0.5
    assert isinstance(x, np.ndarray) and x.dtype == np.float64
    return (x[0] - 1.0) ** 2 + (x[1] - 2.0) ** 2, [x[0] + x[1] - 2.0]


@pytest.mark.parametrize(
    "method, options, tol",
    [("pattern-search", {"min_mesh": 1e-6}, 1e-4), ("sqp", None, 1e-6), ("ga", {"seed": 3}, 3e-2)],
)
def test_constrained_optimum(method, options, tol) -> None:
    r = afsv.minimize(circle_problem, [(-3, 3), (-3, 3)], n_constraints=1, method=method, options=options)
    assert r.feasible and r.constraints[0] <= 0
    assert np.allclose(r.x, [0.5, 1.5], atol=tol), r
    assert r.f == pytest.approx(0.5, abs=tol)
    assert r.evaluations > 0 and r.status


def test_same_options_same_bits() -> None:
    a = afsv.minimize(circle_problem, [(-3, 3), (-3, 3)], n_constraints=1, method="ga", options={"seed": 5, "generations": 10})
    b = afsv.minimize(circle_problem, [(-3, 3), (-3, 3)], n_constraints=1, method="ga", options={"seed": 5, "generations": 10})
    assert np.array_equal(a.x, b.x) and a.f == b.f


def test_unconstrained_and_a_model_in_the_loop() -> None:
    # the input-time of a 30 deg step that brings the yaw-plane vehicle to 1 deg articulation
    # at t = 2 s: a one-variable design problem with a simulation inside the objective
    def f(x):
        rec = afsv.simulate_yaw(input="step:30", input_time=float(x[0]), duration=3, dt=0.01)
        return (np.interp(2.0, rec.t, rec.articulation_deg) - 1.0) ** 2

    r = afsv.minimize(f, [(0.0, 1.9)], method="pattern-search", options={"min_mesh": 1e-3})
    assert r.f < 1e-2 and 0.0 <= r.x[0] <= 1.9


def test_errors() -> None:
    with pytest.raises(ZeroDivisionError):
        afsv.minimize(lambda x: 1 / 0, [(0, 1)])
    with pytest.raises(ValueError, match="unknown option `mesh`"):
        afsv.minimize(lambda x: x[0], [(0, 1)], options={"mesh": 1})
    with pytest.raises(ValueError, match="constraint values"):
        afsv.minimize(lambda x: (x[0], [1.0, 2.0]), [(0, 1)], n_constraints=1)
    with pytest.raises(TypeError, match="float or"):
        afsv.minimize(lambda x: "no", [(0, 1)])
    with pytest.raises(ValueError, match="method"):
        afsv.minimize(lambda x: x[0], [(0, 1)], method="newton")
    with pytest.raises(ValueError):
        afsv.minimize(lambda x: x[0], [(1, 0)])
    with pytest.raises(TypeError, match="callable"):
        afsv._afsv.minimize(3, [0.0], [1.0], 0, "sqp", None, None)


def test_chapter4_problem_in_rust() -> None:
    p = afsv.AfsProblem()
    lo, hi = p.bounds
    assert p.variables == ["a0_rad", "l1_m", "l2_m", "valve_av", "bulk_modulus_pa"]
    assert p.n_constraints == 2 and len(lo) == len(hi) == 5
    c = p.current()
    f, cons = p(c)
    # Eq 4.8 is normalised by the current design: F = 1 there (every ratio 1)
    assert f == pytest.approx(1.0, abs=1e-12) and all(v <= 0 for v in cons)
    r = afsv.minimize(p, x0=c, options={"min_mesh": 0.05, "search_points": 0})
    assert r.feasible and r.f < 0.95 and r.evaluations is None
    assert all(lo[i] <= r.x[i] <= hi[i] for i in range(5))
    with pytest.raises(ValueError, match="x has 2 values"):
        p([1.0, 2.0])
