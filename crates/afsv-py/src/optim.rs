//! The design optimisers of crate `optimize` (pattern search, SLSQP, genetic algorithm over
//! a box with constraints `c_j(x) <= 0`, docs/optimisation.md) on a Python objective.
//!
//! The solvers run with the GIL released; each evaluation takes the GIL to call the Python
//! function (the solvers' parallel batches are then serialised by the GIL, in the solvers'
//! own order, so a run is deterministic). An exception in the objective stops counting:
//! that point is a failed evaluation (`Evaluation::failed`), the run finishes, and the first
//! exception is raised.

use crate::{py_err, to_json, value_err};
use optimize::ga::{GaOptions, GeneticAlgorithm};
use optimize::pattern_search::{PatternSearch, PatternSearchOptions};
use optimize::sqp::{sqp, SqpOptions};
use optimize::{Bounds, ConstrainedProblem, Evaluation, Silent};
use pyo3::prelude::*;
use serde::de::DeserializeOwned;
use serde::Serialize;
use serde_json::{json, Value};
use std::sync::Mutex;

/// A problem whose objective and constraints come from a Python callable
/// `fun(x) -> f` or `fun(x) -> (f, [c_1, ..., c_m])`, `x` a list of floats.
struct PyProblem {
    fun: Py<PyAny>,
    bounds: Bounds,
    n_constraints: usize,
    /// The first exception the callable raised (or its wrong result).
    error: Mutex<Option<PyErr>>,
    /// Evaluations made.
    calls: Mutex<usize>,
}

impl PyProblem {
    /// Call the Python objective at `x`.
    fn call(&self, py: Python<'_>, x: &[f64]) -> PyResult<Evaluation> {
        let out = self.fun.call1(py, (x.to_vec(),))?;
        let out = out.bind(py);
        if let Ok(f) = out.extract::<f64>() {
            if self.n_constraints != 0 {
                return Err(value_err(format!(
                    "the objective returned a number; with n_constraints = {} it must return (f, [c_1, ...])",
                    self.n_constraints
                )));
            }
            return Ok(Evaluation {
                f,
                constraints: Vec::new(),
            });
        }
        let (f, c): (f64, Vec<f64>) = out.extract().map_err(|_| {
            pyo3::exceptions::PyTypeError::new_err(
                "the objective must return a float or (float, list of floats)",
            )
        })?;
        if c.len() != self.n_constraints {
            return Err(value_err(format!(
                "the objective returned {} constraint values, n_constraints is {}",
                c.len(),
                self.n_constraints
            )));
        }
        Ok(Evaluation { f, constraints: c })
    }
}

impl ConstrainedProblem for PyProblem {
    fn bounds(&self) -> &Bounds {
        &self.bounds
    }
    fn n_constraints(&self) -> usize {
        self.n_constraints
    }
    fn evaluate(&self, x: &[f64]) -> Evaluation {
        if let Ok(mut n) = self.calls.lock() {
            *n += 1;
        }
        let failed_before = self.error.lock().map(|e| e.is_some()).unwrap_or(true);
        if failed_before {
            return Evaluation::failed(self.n_constraints);
        }
        Python::attach(|py| match self.call(py, x) {
            Ok(e) => e,
            Err(err) => {
                if let Ok(mut slot) = self.error.lock() {
                    slot.get_or_insert(err);
                }
                Evaluation::failed(self.n_constraints)
            }
        })
    }
}

/// `defaults` with the keys of `given` (a JSON object) replaced; an unknown key is an error
/// naming the known ones.
fn options<T: Serialize + DeserializeOwned>(defaults: T, given: Option<&str>) -> PyResult<T> {
    let Some(text) = given else {
        return Ok(defaults);
    };
    let mut base = to_json(&defaults)?;
    let given: Value =
        serde_json::from_str(text).map_err(|e| value_err(format!("options: {e}")))?;
    let (Some(obj), Some(over)) = (base.as_object_mut(), given.as_object()) else {
        return Err(value_err("options: expected a dict"));
    };
    for (k, v) in over {
        if !obj.contains_key(k) {
            let known: Vec<&String> = obj.keys().collect();
            return Err(value_err(format!(
                "options: unknown option `{k}` (known: {})",
                known
                    .iter()
                    .map(|s| s.as_str())
                    .collect::<Vec<_>>()
                    .join(", ")
            )));
        }
        obj.insert(k.clone(), v.clone());
    }
    serde_json::from_value(base).map_err(|e| value_err(format!("options: {e}")))
}

/// Run `method` on `problem` from `x0` (None: the centre of the box) with the GIL released:
/// the best point, its evaluation and the stop reason.
fn run<P: ConstrainedProblem>(
    py: Python<'_>,
    problem: &P,
    method: &str,
    x0: Option<Vec<f64>>,
    options_json: Option<&str>,
) -> PyResult<(Vec<f64>, Evaluation, String)> {
    let bounds = problem.bounds();
    let n = bounds.lower().len();
    let x0 = match x0 {
        Some(x) if x.len() != n => {
            return Err(value_err(format!(
                "x0 has {} values, the bounds {n}",
                x.len()
            )))
        }
        Some(x) => x,
        None => bounds.from_unit(&vec![0.5; n]),
    };
    let out: Result<_, optimize::OptimizeError> = match method {
        "pattern-search" => {
            let o = options(PatternSearchOptions::default(), options_json)?;
            py.detach(|| {
                let ps = PatternSearch::new(problem, o)?;
                let s = ps.start(&x0)?;
                let s = ps.run(s, &Silent, &mut |_| Ok(()))?;
                let status = serde_json::to_value(s.stop)
                    .ok()
                    .and_then(|v| v.as_str().map(String::from))
                    .unwrap_or_default();
                Ok((s.x, s.eval, status))
            })
        }
        "sqp" => {
            let o = options(SqpOptions::default(), options_json)?;
            py.detach(|| {
                let r = sqp(problem, &x0, &o, Vec::new(), &Silent, &mut |_| Ok(()))?;
                Ok((r.x, r.eval, r.status))
            })
        }
        "ga" => {
            let o = options(GaOptions::default(), options_json)?;
            py.detach(|| {
                let ga = GeneticAlgorithm::new(problem, o)?;
                let s = ga.start(std::slice::from_ref(&x0))?;
                let s = ga.run(s, &Silent, &mut |_| Ok(()))?;
                let best = s.best().clone();
                Ok((best.x, best.eval, format!("{} generations", s.generation)))
            })
        }
        other => {
            return Err(value_err(format!(
                "method `{other}`: expected pattern-search, sqp or ga"
            )))
        }
    };
    out.map_err(|e| py_err(py, &e))
}

/// Minimise over the box `[lower, upper]` with `n_constraints` inequality constraints
/// `c_j(x) <= 0`: `fun` is a Python callable, or a built-in problem (`AfsProblem`, whose
/// own bounds and constraints are used and which runs without Python in the loop).
/// `method` is `pattern-search` (GPS with an optional Latin-hypercube search step, extreme
/// barrier), `sqp` (SLSQP with finite-difference gradients) or `ga` (SBX, polynomial
/// mutation, Deb's rules); `options` a JSON object of the method's options. Returns JSON:
/// `x`, `f`, `constraints`, `feasible`, `evaluations` (Python calls; null for a built-in
/// problem), `status`.
#[pyfunction]
#[pyo3(signature = (fun, lower, upper, n_constraints, method, x0, options_json))]
#[allow(clippy::too_many_arguments)]
fn minimize(
    py: Python<'_>,
    fun: Py<PyAny>,
    lower: Vec<f64>,
    upper: Vec<f64>,
    n_constraints: usize,
    method: &str,
    x0: Option<Vec<f64>>,
    options_json: Option<&str>,
) -> PyResult<String> {
    if let Ok(builtin) = fun.bind(py).cast::<crate::design::PyAfsProblem>() {
        let p = builtin.get();
        let (x, eval, status) = run(py, &p.inner, method, x0, options_json)?;
        return Ok(result_json(x, eval, None, status));
    }
    if !fun.bind(py).is_callable() {
        return Err(pyo3::exceptions::PyTypeError::new_err(
            "fun: expected a callable",
        ));
    }
    let bounds = Bounds::new(lower, upper).map_err(|e| py_err(py, &e))?;
    let problem = PyProblem {
        fun,
        bounds,
        n_constraints,
        error: Mutex::new(None),
        calls: Mutex::new(0),
    };
    let out = run(py, &problem, method, x0, options_json);
    if let Some(err) = problem.error.lock().ok().and_then(|mut e| e.take()) {
        return Err(err);
    }
    let (x, eval, status) = out?;
    let calls = problem.calls.lock().map(|n| *n).unwrap_or(0);
    Ok(result_json(x, eval, Some(calls), status))
}

/// The JSON of a finished run.
fn result_json(x: Vec<f64>, eval: Evaluation, calls: Option<usize>, status: String) -> String {
    json!({
        "x": x,
        "f": eval.f,
        "constraints": eval.constraints,
        "feasible": eval.is_feasible(),
        "evaluations": calls,
        "status": status,
    })
    .to_string()
}

/// Register the optimiser functions.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(minimize, m)?)?;
    Ok(())
}
