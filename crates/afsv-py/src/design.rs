//! The built-in design problem of Chapter 4 (crate `afsv-design`): the frame-steering
//! design [A_0, l_1, l_2, a_v, B_eff] of Table 4.2 scored by the Eq 4.8 objective with the
//! AHP weights of Eq 4.17, Eq 4.10 and a minimum full-lock steering arm as constraints, on
//! the library calls of `afsv optimize afs`. The problem is a Python object `AfsProblem`
//! that `afsv.minimize` runs entirely in Rust, and `optimize_afs` is the CLI's multi-start
//! pattern search with SQP refinement.

use crate::{py_err, to_json, value_err};
use afsv_design::{
    optimise, AfsDesignBounds, AfsProblem, AfsProblemSpec, AfsRunState, AhpHierarchy, Objective,
};
use afsv_dynamics::EquationForm;
use optimize::{ConstrainedProblem, Silent};
use pyo3::prelude::*;

/// The Chapter 4 problem as a Python object: `problem(x) -> (F, [c_1, ...])`, `bounds`,
/// `n_constraints`, `variables`; `afsv.minimize(problem, ...)` runs it without Python in
/// the loop.
#[pyclass(module = "afsv._afsv", name = "AfsProblem", frozen)]
pub(crate) struct PyAfsProblem {
    /// The library's problem.
    pub(crate) inner: AfsProblem,
}

/// The problem specification of the CLI's options: bounds of Table 4.2 (B_eff up to
/// 1.7 GPa, or 2.08 GPa when `relaxed`), the minimum full-lock steering arm (`None`: no
/// arm constraint), the simulations' relative tolerance and the form of Eq 3.13.
fn spec(relaxed: bool, min_arm_m: Option<f64>, rtol: f64, form: &str) -> PyResult<AfsProblemSpec> {
    if !(rtol.is_finite() && rtol > 0.0) {
        return Err(value_err(format!("rtol {rtol}: must be finite and > 0")));
    }
    let mut spec = AfsProblemSpec {
        bounds: if relaxed {
            AfsDesignBounds::table_4_2_relaxed()
        } else {
            AfsDesignBounds::table_4_2()
        },
        min_steering_arm_m: min_arm_m,
        ..AfsProblemSpec::default()
    };
    spec.measure.options.rtol = rtol;
    spec.measure.options.form = match form {
        "energy-consistent" => EquationForm::EnergyConsistent,
        "paper-eq-3-13" => EquationForm::PaperEq313,
        other => {
            return Err(value_err(format!(
                "form `{other}`: expected energy-consistent or paper-eq-3-13"
            )))
        }
    };
    Ok(spec)
}

/// The Eq 4.8 objective with the AHP weights of Eq 4.17 (Chapter 4 hierarchy).
fn objective(py: Python<'_>) -> PyResult<Objective> {
    let w = AhpHierarchy::chapter4()
        .weights()
        .map_err(|e| py_err(py, &e))?;
    Objective::new(w.composite).map_err(|e| py_err(py, &e))
}

/// Build the problem (simulates the current design once).
fn problem(py: Python<'_>, s: AfsProblemSpec) -> PyResult<AfsProblem> {
    let obj = objective(py)?;
    py.detach(|| AfsProblem::new(s, obj))
        .map_err(|e| py_err(py, &e))
}

#[pymethods]
impl PyAfsProblem {
    /// The Chapter 4 problem (see the module documentation).
    #[new]
    #[pyo3(signature = (relaxed=false, min_arm_m=Some(afsv_design::afs_problem::DEFAULT_MIN_STEERING_ARM_M), rtol=1e-8, form="energy-consistent"))]
    fn new(
        py: Python<'_>,
        relaxed: bool,
        min_arm_m: Option<f64>,
        rtol: f64,
        form: &str,
    ) -> PyResult<Self> {
        let s = spec(relaxed, min_arm_m, rtol, form)?;
        Ok(Self {
            inner: problem(py, s)?,
        })
    }

    /// `(lower, upper)` of the design variables.
    #[getter]
    fn bounds(&self) -> (Vec<f64>, Vec<f64>) {
        let b = self.inner.bounds();
        (b.lower().to_vec(), b.upper().to_vec())
    }

    /// Number of inequality constraints `c_j <= 0`.
    #[getter]
    fn n_constraints(&self) -> usize {
        self.inner.n_constraints()
    }

    /// The variable names, in order.
    #[getter]
    fn variables(&self) -> Vec<&'static str> {
        afsv_design::AfsVariable::ALL
            .iter()
            .map(|v| v.name())
            .collect()
    }

    /// The current design (Table 3.1 steering) as a point.
    fn current(&self) -> Vec<f64> {
        self.inner.current_design().to_vector().to_vec()
    }

    /// Objective and constraints at `x` (a failed simulation gives the barrier value).
    fn __call__(&self, py: Python<'_>, x: Vec<f64>) -> PyResult<(f64, Vec<f64>)> {
        if x.len() != self.inner.bounds().lower().len() {
            return Err(value_err(format!(
                "x has {} values, the problem {}",
                x.len(),
                self.inner.bounds().lower().len()
            )));
        }
        let e = py.detach(|| self.inner.evaluate(&x));
        Ok((e.f, e.constraints))
    }
}

/// The Chapter 4 optimisation of `afsv optimize afs` (one configuration): multi-start
/// pattern search then SQP, as JSON (`afsv_design::AfsOptimum`: starts, `ps`, `ps_sqp`
/// with design, measures and ratios, evaluations).
#[pyfunction]
#[pyo3(signature = (relaxed, min_arm_m, starts, seed, search_points, screen_mesh, min_mesh, sqp_calls, rtol, form))]
#[allow(clippy::too_many_arguments)]
fn optimize_afs(
    py: Python<'_>,
    relaxed: bool,
    min_arm_m: Option<f64>,
    starts: usize,
    seed: u64,
    search_points: usize,
    screen_mesh: f64,
    min_mesh: f64,
    sqp_calls: usize,
    rtol: f64,
    form: &str,
) -> PyResult<String> {
    if starts >= afsv_design::afs_optimum::MAX_STARTS {
        return Err(value_err(format!(
            "starts must be below {}",
            afsv_design::afs_optimum::MAX_STARTS
        )));
    }
    if !(min_mesh > 0.0 && min_mesh <= screen_mesh && screen_mesh < 0.25) {
        return Err(value_err(format!(
            "screen_mesh {screen_mesh} and min_mesh {min_mesh}: need 0 < min_mesh <= screen_mesh < 0.25 (the initial mesh)"
        )));
    }
    if !(1..=10_000).contains(&sqp_calls) || search_points > 100_000 {
        return Err(value_err(
            "sqp_calls must be 1 to 10000 and search_points at most 100000",
        ));
    }
    let settings = afsv_design::afs_run::settings(
        starts,
        seed,
        search_points,
        (screen_mesh, min_mesh),
        sqp_calls,
    );
    let p = problem(py, spec(relaxed, min_arm_m, rtol, form)?)?;
    let opt = py
        .detach(|| {
            optimise(&p, &settings, AfsRunState::default(), &Silent, &mut |_| {
                Ok(())
            })
        })
        .map_err(|e| py_err(py, &e))?;
    Ok(to_json(&opt)?.to_string())
}

/// Register the Chapter 4 problem.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyAfsProblem>()?;
    m.add_function(wrap_pyfunction!(optimize_afs, m)?)?;
    Ok(())
}
