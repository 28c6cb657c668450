//! Python bindings of the toolkit (PyO3, abi3 for Python >= 3.9), built by maturin into the
//! native module `afsv._afsv` under the pure-Python package `afsv` (`python/afsv`,
//! docs/python.md).
//!
//! The bindings call the same library functions as the `afsv` command-line tool (never the
//! CLI crate), so a run from Python gives the CLI's numbers bit for bit. The boundary is
//! kept small and copy-based:
//!
//! * arrays go in as `bytes` of native-endian float64 (the Python layer passes
//!   `numpy.ascontiguousarray(x, float64).tobytes()`) and come out as `bytearray`s that the
//!   Python layer views with `numpy.frombuffer` (no numpy crate, no buffer protocol, which
//!   abi3 below Python 3.11 lacks);
//! * structured results (measures, sidecar metadata, descriptions) come out as JSON text;
//! * every run releases the GIL (`Python::detach`);
//! * a library error becomes `ValueError` with the library's message, a diverging solver an
//!   [`SolverError`] carrying the time and the last finite state; panics are caught by PyO3
//!   and raised as `pyo3_runtime.PanicException`, never unwound into Python.

use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyByteArray, PyDict, PyList, PyTuple};

mod desc;
mod design;
mod discovery;
mod evaluate;
mod hps;
mod measures;
mod models;
mod optim;
mod terrain;
mod vehicles;

pyo3::create_exception!(
    _afsv,
    SolverError,
    PyRuntimeError,
    "A run diverged (odeint's `Diverged` or step limit, a model's divergence check): \
     attributes `t` (s), `state` (list of floats, or dict name -> value in SI units when \
     the model names its states) and `reason`."
);

/// A column set of a run: `(name, values)` in record order.
pub(crate) type Columns = Vec<(String, Vec<f64>)>;

/// The float64 values packed in `data` (native endianness); `what` names the argument in
/// the error.
pub(crate) fn f64s(what: &str, data: &[u8]) -> PyResult<Vec<f64>> {
    if data.len() % 8 != 0 {
        return Err(PyValueError::new_err(format!(
            "{what}: {} bytes is not a whole number of float64 values",
            data.len()
        )));
    }
    Ok(data
        .chunks_exact(8)
        .map(|c| {
            let mut b = [0u8; 8];
            b.copy_from_slice(c);
            f64::from_ne_bytes(b)
        })
        .collect())
}

/// `values` as a `bytearray` of native-endian float64 (the Python layer's numpy view).
pub(crate) fn to_bytes<'py>(py: Python<'py>, values: &[f64]) -> PyResult<Bound<'py, PyByteArray>> {
    PyByteArray::new_with(py, values.len() * 8, |buf| {
        for (c, v) in buf.chunks_exact_mut(8).zip(values) {
            c.copy_from_slice(&v.to_ne_bytes());
        }
        Ok(())
    })
}

/// A run's result for the Python `Record`: `(columns, meta_json)` with `columns` a list of
/// `(name, bytearray)`.
pub(crate) fn record_out<'py, S: AsRef<str>>(
    py: Python<'py>,
    columns: &[(S, Vec<f64>)],
    meta: &serde_json::Value,
) -> PyResult<Bound<'py, PyTuple>> {
    let list = PyList::empty(py);
    for (name, values) in columns {
        list.append((name.as_ref(), to_bytes(py, values)?))?;
    }
    PyTuple::new(py, [list.into_any(), json_text(py, meta)?.into_any()])
}

/// `v` as JSON text (a Python `str`).
pub(crate) fn json_text<'py>(
    py: Python<'py>,
    v: &serde_json::Value,
) -> PyResult<Bound<'py, pyo3::types::PyString>> {
    let s = serde_json::to_string(v).map_err(|e| PyValueError::new_err(e.to_string()))?;
    Ok(pyo3::types::PyString::new(py, &s))
}

/// `v` serialised to a JSON value (a serialisation failure is a `ValueError`).
pub(crate) fn to_json<T: serde::Serialize>(v: &T) -> PyResult<serde_json::Value> {
    serde_json::to_value(v).map_err(|e| PyValueError::new_err(e.to_string()))
}

/// A plain message as a `ValueError`.
pub(crate) fn value_err(msg: impl Into<String>) -> PyErr {
    PyValueError::new_err(msg.into())
}

/// The named state of a model's divergence message (`name=value, ...`), when every pair
/// parses.
fn named_state(state: &str) -> Option<Vec<(String, f64)>> {
    state
        .split(", ")
        .map(|pair| {
            let (n, v) = pair.split_once('=')?;
            Some((n.trim().to_string(), v.trim().parse().ok()?))
        })
        .collect()
}

/// The Python exception of a library error: [`SolverError`] when the error, or any error
/// in its source chain, is a divergence (with `t` and `state`), else `ValueError` with the
/// library's message.
pub(crate) fn py_err(py: Python<'_>, e: &(dyn std::error::Error + 'static)) -> PyErr {
    let msg = e.to_string();
    let mut cur: Option<&(dyn std::error::Error + 'static)> = Some(e);
    while let Some(err) = cur {
        if let Some(
            odeint::OdeError::Diverged { t, state, .. }
            | odeint::OdeError::TooManySteps { t, state, .. }
            | odeint::OdeError::StepSizeCollapsed { t, state, .. },
        ) = err.downcast_ref::<odeint::OdeError>()
        {
            let list = PyList::new(py, state).ok().map(|l| l.into_any());
            return solver_error(py, &msg, *t, list, &msg);
        }
        if let Some(afsv_dynamics::DynError::Diverged { t, reason, state }) =
            err.downcast_ref::<afsv_dynamics::DynError>()
        {
            let dict = named_state(state).and_then(|pairs| {
                let d = PyDict::new(py);
                for (k, v) in pairs {
                    d.set_item(k, v).ok()?;
                }
                Some(d.into_any())
            });
            return solver_error(py, &msg, *t, dict, reason);
        }
        cur = err.source();
    }
    PyValueError::new_err(msg)
}

/// A [`SolverError`] with its attributes set.
fn solver_error(
    py: Python<'_>,
    msg: &str,
    t: f64,
    state: Option<Bound<'_, PyAny>>,
    reason: &str,
) -> PyErr {
    let err = SolverError::new_err(msg.to_string());
    let value = err.value(py);
    // Setting attributes on a fresh exception instance cannot fail in practice; if it
    // did, the message still carries the time and state.
    let _ = value.setattr("t", t);
    let _ = value.setattr("reason", reason);
    let _ = value.setattr("state", state);
    err
}

/// The native module `afsv._afsv`.
#[pymodule]
fn _afsv(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("SolverError", m.py().get_type::<SolverError>())?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    terrain::register(m)?;
    models::register(m)?;
    measures::register(m)?;
    desc::register(m)?;
    vehicles::register(m)?;
    optim::register(m)?;
    evaluate::register(m)?;
    design::register(m)?;
    hps::register(m)?;
    discovery::register(m)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::{named_state, py_err, SolverError};
    use pyo3::prelude::*;

    #[test]
    fn named_state_reads_the_yaw_models_divergence_state() {
        let s = named_state("articulation_rad=3.932865e1, p_c_pa=-1.000000e6").unwrap();
        assert_eq!(
            s,
            vec![
                ("articulation_rad".to_string(), 39.32865),
                ("p_c_pa".to_string(), -1e6)
            ]
        );
        assert!(named_state("articulation_rad=oops").is_none());
        assert!(named_state("no pairs here").is_none());
    }

    /// The truck and the 3-D vehicle cannot be driven to divergence through the Python API
    /// (their step limit is not an option and no parameter set within the registry ranges
    /// was found that diverges), so their error types are checked here: an integrator
    /// failure anywhere in a model's error chain becomes a `SolverError` with `t`, `state`
    /// and `reason`, anything else a `ValueError`.
    #[test]
    fn every_models_integrator_failure_becomes_a_solver_error() {
        let state = vec![0.5, -2.0, 1e9];
        let diverged = || odeint::OdeError::Diverged {
            t: 1.25,
            h: 1e-14,
            state: state.clone(),
        };
        let limit = || odeint::OdeError::TooManySteps {
            max_steps: 10,
            t: 1.25,
            state: state.clone(),
        };
        let failures: Vec<Box<dyn std::error::Error>> = vec![
            Box::new(hps_emulsion::HpsError::Integration(diverged())),
            Box::new(roll_truck::TruckError::Integration(diverged())),
            Box::new(roll_truck::TruckError::Integration(limit())),
            Box::new(vehicle_3d::VehicleError::Integration(diverged())),
            Box::new(vehicle_3d::VehicleError::Integration(limit())),
            Box::new(vehicle_3d::VehicleError::Stiff {
                state: "steering_p_c_pa".into(),
                source: odeint::OdeError::StepSizeCollapsed {
                    t: 1.25,
                    h: 1e-12,
                    projected_steps: 1e9,
                    max_steps: 1_000_000,
                    dominant_state: 2,
                    state: state.clone(),
                },
            }),
            Box::new(vehicle_3d::VehicleError::Suspension(
                hps_emulsion::HpsError::Integration(diverged()),
            )),
        ];
        Python::initialize();
        Python::attach(|py| {
            for e in &failures {
                let err = py_err(py, e.as_ref());
                assert!(err.is_instance_of::<SolverError>(py), "{e}");
                let v = err.value(py);
                assert_eq!(v.getattr("t").unwrap().extract::<f64>().unwrap(), 1.25);
                assert_eq!(
                    v.getattr("state").unwrap().extract::<Vec<f64>>().unwrap(),
                    state
                );
                let reason: String = v.getattr("reason").unwrap().extract().unwrap();
                assert_eq!(reason, e.to_string());
            }
            let other = vehicle_3d::VehicleError::Measure {
                measure: "a_wz",
                reason: "too short".into(),
            };
            let err = py_err(py, &other);
            assert!(err.is_instance_of::<pyo3::exceptions::PyValueError>(py));
            assert!(!err.is_instance_of::<SolverError>(py));
        });
    }
}
