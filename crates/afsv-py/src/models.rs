//! The yaw-plane model (Chapter 3, Eqs 3.1-3.17) and the hydro-pneumatic strut (Chapter 5,
//! Eqs 5.1-5.12), on the library calls of `afsv yaw simulate`, `afsv hps harmonic` and
//! `afsv hps characterize`. The truck and the 3-D vehicle are in [`crate::vehicles`].

use crate::{f64s, py_err, record_out, to_json, value_err, Columns};
use afsv_dynamics::{
    simulate, Course, EquationForm, Load, Manoeuvre, PathDriver, SimOptions, Solver, SteerInput,
    YawPlaneParams,
};
use hps_emulsion::{
    characterize, lab_programme, loop_metrics, simulate_displacement, Excitation, HarmonicTest,
    HpsExtensions, LabConfig, StrutParams,
};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyTuple};
use rayon::prelude::*;
use serde_json::json;

/// Most output samples of one yaw-plane or strut run (the CLI's bounds).
const MAX_SAMPLES: f64 = 1e6;

/// `n` samples against [`MAX_SAMPLES`]; `what` names the ratio in the error.
fn check_samples(what: &str, n: f64) -> PyResult<()> {
    if n.is_finite() && n <= MAX_SAMPLES {
        Ok(())
    } else {
        Err(value_err(format!(
            "{what} = {n:.0} samples: at most {MAX_SAMPLES:e}"
        )))
    }
}

/// The yaw-plane parameters: a raw `params_json` set (as `afsv params dump yaw-plane`
/// writes), else the `load` case of the vehicle description `vehicle` (the prototype when
/// `None`).
fn yaw_params(
    vehicle: Option<crate::desc::DescRef<'_>>,
    params_json: Option<&str>,
    load: Load,
) -> PyResult<YawPlaneParams> {
    if let Some(text) = params_json {
        let p: YawPlaneParams =
            serde_json::from_str(text).map_err(|e| value_err(format!("params: {e}")))?;
        p.validate().map_err(|e| value_err(e.to_string()))?;
        return Ok(p);
    }
    let d = crate::desc::articulated(vehicle)?;
    let p = d.yaw_plane_params(load);
    p.validate().map_err(|e| value_err(e.to_string()))?;
    Ok(p)
}

/// A finite number of an input specification.
fn number(what: &str, s: &str) -> PyResult<f64> {
    s.parse::<f64>()
        .ok()
        .filter(|v| v.is_finite())
        .ok_or_else(|| value_err(format!("input {what}: `{s}` is not a finite number")))
}

/// The manoeuvre of an input specification (the CLI's `--input`: `pulse[:PEAK_DEG]`,
/// `step:DEG`, `ramp:DEG_PER_S[:LIMIT_DEG]`, `turn`, `path-change`), or of a table of
/// steering-wheel angles (deg) at times (s) when `table` is given.
fn manoeuvre(
    spec: &str,
    table: Option<(Vec<f64>, Vec<f64>)>,
    speed: f64,
    t0: f64,
    duration: f64,
) -> PyResult<Manoeuvre> {
    let open = |input: SteerInput, label: &str| Manoeuvre::open_loop(speed, duration, input, label);
    if let Some((time_s, deg)) = table {
        let input = SteerInput::Table {
            time_s,
            angle_rad: deg.iter().map(|v| v.to_radians()).collect(),
        };
        input.validate().map_err(|e| value_err(e.to_string()))?;
        return Ok(open(input, "table"));
    }
    let parts: Vec<&str> = spec.splitn(3, ':').collect();
    let ramp = |r: &str, limit_deg: f64| -> PyResult<SteerInput> {
        Ok(SteerInput::Ramp {
            rate_rad_s: number("ramp rate", r)?.to_radians(),
            start_s: t0,
            limit_rad: limit_deg.abs().to_radians(),
        })
    };
    Ok(match parts.as_slice() {
        ["pulse"] => open(SteerInput::pulse_deg(30.0, 0.2, t0), "pulse"),
        ["pulse", a] => open(
            SteerInput::pulse_deg(number("pulse peak", a)?, 0.2, t0),
            "pulse",
        ),
        ["step", a] => open(SteerInput::step_deg(number("step", a)?, t0), "step"),
        ["ramp", r] => open(ramp(r, 720.0)?, "ramp"),
        ["ramp", r, l] => open(ramp(r, number("ramp limit", l)?)?, "ramp"),
        ["turn"] => Manoeuvre::course(
            speed,
            duration,
            PathDriver::new(Course::steady_turn_fig_3_6()),
            "steady_turn",
        ),
        ["path-change"] => Manoeuvre::course(
            speed,
            duration,
            PathDriver::new(Course::path_change_fig_3_6()),
            "path_change",
        ),
        _ => {
            return Err(value_err(format!(
                "input `{spec}` not understood (expected pulse[:DEG], step:DEG, ramp:DEG_S[:LIMIT_DEG], turn or path-change, or a table)"
            )))
        }
    })
}

/// A yaw-plane run, checked and set up (the parameter set, steering system, manoeuvre and
/// options of `afsv yaw simulate`), ready to run without the GIL.
struct YawJob {
    p: YawPlaneParams,
    sys: afs_hydraulics::AfsSystem,
    man: Manoeuvre,
    opts: SimOptions,
    input: String,
}

/// Check the arguments of a yaw-plane run and set it up.
#[allow(clippy::too_many_arguments)]
fn yaw_job(
    py: Python<'_>,
    vehicle: Option<crate::desc::DescRef<'_>>,
    params_json: Option<&str>,
    load: &str,
    speed_kmh: f64,
    input: &str,
    table_t: Option<&[u8]>,
    table_deg: Option<&[u8]>,
    input_time: f64,
    duration: f64,
    dt: f64,
    solver: &str,
    rtol: f64,
    form: &str,
    rk4_step: f64,
) -> PyResult<YawJob> {
    for (name, v) in [("duration", duration), ("dt", dt), ("rtol", rtol)] {
        if !(v.is_finite() && v > 0.0) {
            return Err(value_err(format!(
                "{name} {v}: must be a finite number > 0"
            )));
        }
    }
    if !(input_time.is_finite() && input_time >= 0.0) {
        return Err(value_err(format!(
            "input_time {input_time}: must be a finite number >= 0"
        )));
    }
    check_samples("duration/dt", duration / dt)?;
    if !(speed_kmh.is_finite() && speed_kmh >= 0.0) {
        return Err(value_err(format!(
            "speed_kmh must be finite and >= 0, got {speed_kmh}"
        )));
    }
    let load: Load = load.parse().map_err(|e| value_err(format!("load: {e}")))?;
    let form = match form {
        "energy-consistent" => EquationForm::EnergyConsistent,
        "paper-eq-3-13" => EquationForm::PaperEq313,
        other => {
            return Err(value_err(format!(
                "form `{other}`: expected energy-consistent or paper-eq-3-13"
            )))
        }
    };
    let solver = match solver {
        "dopri" => Solver::Dopri5,
        "rosenbrock" => Solver::Rosenbrock23,
        "rk4" if rk4_step.is_finite() && rk4_step > 0.0 => Solver::Rk4 { step: rk4_step },
        "rk4" => return Err(value_err(format!("rk4_step {rk4_step}: must be > 0"))),
        other => {
            return Err(value_err(format!(
                "solver `{other}`: expected dopri, rosenbrock or rk4"
            )))
        }
    };
    let table = match (table_t, table_deg) {
        (Some(t), Some(a)) => Some((f64s("table time", t)?, f64s("table angle", a)?)),
        (None, None) => None,
        _ => return Err(value_err("a steering table needs both times and angles")),
    };
    let p = yaw_params(vehicle, params_json, load)?;
    let speed = speed_kmh / 3.6;
    let sys = p.afs_system().map_err(|e| py_err(py, &e))?;
    let man = manoeuvre(input, table, speed, input_time, duration)?;
    let opts = afsv_design::yaw_manoeuvre::sim_options(solver, rtol, dt, form);
    Ok(YawJob {
        p,
        sys,
        man,
        opts,
        input: input.to_string(),
    })
}

/// The record of a finished run, as the Python `Record` takes it.
fn yaw_out<'py>(
    py: Python<'py>,
    job: &YawJob,
    rec: &afsv_dynamics::YawRecord,
) -> PyResult<Bound<'py, PyTuple>> {
    let cols: Columns = rec
        .columns()
        .into_iter()
        .map(|(n, v)| (n, v.to_vec()))
        .collect();
    let meta = json!({
        "model": "afsv-dynamics yaw-plane (chapter 3)",
        "sample_rate_hz": 1.0 / job.opts.output_dt_s,
        "equation_form": to_json(&job.opts.form)?,
        "manoeuvre": job.man.label,
        "input": job.input,
        "speed_m_s": job.man.speed_m_s,
        "load": to_json(&job.p.load)?,
        "params": to_json(&job.p)?,
        "solver": to_json(&job.opts.solver)?,
        "rtol": job.opts.rtol,
        "solver_stats": to_json(&rec.stats)?,
    });
    record_out(py, &cols, &meta)
}

/// One manoeuvre of the yaw-plane vehicle (Eqs 3.13-3.17 with the hydraulic frame steering
/// of Eqs 3.1-3.12): every channel and state as `afsv yaw simulate` writes them.
#[pyfunction]
#[pyo3(signature = (vehicle, params_json, load, speed_kmh, input, table_t, table_deg, input_time, duration, dt, solver, rtol, form, rk4_step))]
#[allow(clippy::too_many_arguments)]
fn simulate_yaw<'py>(
    py: Python<'py>,
    vehicle: Option<crate::desc::DescArg>,
    params_json: Option<&str>,
    load: &str,
    speed_kmh: f64,
    input: &str,
    table_t: Option<&[u8]>,
    table_deg: Option<&[u8]>,
    input_time: f64,
    duration: f64,
    dt: f64,
    solver: &str,
    rtol: f64,
    form: &str,
    rk4_step: f64,
) -> PyResult<Bound<'py, PyTuple>> {
    let job = yaw_job(
        py,
        crate::desc::as_ref(&vehicle),
        params_json,
        load,
        speed_kmh,
        input,
        table_t,
        table_deg,
        input_time,
        duration,
        dt,
        solver,
        rtol,
        form,
        rk4_step,
    )?;
    let rec = py
        .detach(|| simulate(&job.p.vehicle, &job.sys, &job.man, &job.opts))
        .map_err(|e| py_err(py, &e))?;
    yaw_out(py, &job, &rec)
}

/// The arguments of one run of [`simulate_yaw_batch`], a dict with the keys of
/// [`simulate_yaw`]'s arguments.
#[derive(FromPyObject)]
struct YawArgs {
    #[pyo3(item)]
    vehicle: Option<crate::desc::DescArg>,
    #[pyo3(item)]
    params_json: Option<String>,
    #[pyo3(item)]
    load: String,
    #[pyo3(item)]
    speed_kmh: f64,
    #[pyo3(item)]
    input: String,
    #[pyo3(item)]
    table_t: Option<Py<PyBytes>>,
    #[pyo3(item)]
    table_deg: Option<Py<PyBytes>>,
    #[pyo3(item)]
    input_time: f64,
    #[pyo3(item)]
    duration: f64,
    #[pyo3(item)]
    dt: f64,
    #[pyo3(item)]
    solver: String,
    #[pyo3(item)]
    rtol: f64,
    #[pyo3(item)]
    form: String,
    #[pyo3(item)]
    rk4_step: f64,
}

/// Many yaw-plane runs in parallel (rayon, GIL released): every job is checked first (a bad
/// one raises before anything runs), then the runs share the cores; the records come back
/// in the order of `jobs`. The first failing run's error is raised.
#[pyfunction]
fn simulate_yaw_batch<'py>(
    py: Python<'py>,
    jobs: Vec<YawArgs>,
) -> PyResult<Vec<Bound<'py, PyTuple>>> {
    let mut prepared = Vec::with_capacity(jobs.len());
    for a in &jobs {
        prepared.push(yaw_job(
            py,
            crate::desc::as_ref(&a.vehicle),
            a.params_json.as_deref(),
            &a.load,
            a.speed_kmh,
            &a.input,
            a.table_t.as_ref().map(|b| b.as_bytes(py)),
            a.table_deg.as_ref().map(|b| b.as_bytes(py)),
            a.input_time,
            a.duration,
            a.dt,
            &a.solver,
            a.rtol,
            &a.form,
            a.rk4_step,
        )?);
    }
    let records: Vec<_> = py.detach(|| {
        prepared
            .par_iter()
            .map(|j| simulate(&j.p.vehicle, &j.sys, &j.man, &j.opts))
            .collect()
    });
    let mut out = Vec::with_capacity(records.len());
    for (job, rec) in prepared.iter().zip(records) {
        let rec = rec.map_err(|e| py_err(py, &e))?;
        out.push(yaw_out(py, job, &rec)?);
    }
    Ok(out)
}

/// A strut named as on the command line: `front-axle` (Table 6.3), `lab-1orifice`,
/// `lab-2orifice`, or a strut parameter file; with `gamma0` replacing the emulsion's gas
/// volume fraction.
fn strut_params(strut: &str, gamma0: Option<f64>) -> PyResult<StrutParams> {
    let p = match strut {
        "front-axle" => StrutParams::front_axle(),
        "lab-1orifice" => StrutParams::lab(LabConfig::OneOrifice),
        "lab-2orifice" => StrutParams::lab(LabConfig::TwoOrifices),
        file => afsv_vehicle::read_strut_file(std::path::Path::new(file))
            .map_err(|e| value_err(format!("strut: {e}")))?,
    };
    match gamma0 {
        Some(g) => p.with_gamma0(g).map_err(|e| value_err(e.to_string())),
        None => Ok(p),
    }
}

/// The strut integrator of a name: auto, rosenbrock or dopri.
fn strut_solver(name: &str) -> PyResult<hps_emulsion::Solver> {
    match name {
        "auto" => Ok(hps_emulsion::Solver::Auto),
        "rosenbrock" => Ok(hps_emulsion::Solver::Rosenbrock23),
        "dopri" => Ok(hps_emulsion::Solver::Dopri5),
        other => Err(value_err(format!(
            "solver `{other}`: expected auto, rosenbrock or dopri"
        ))),
    }
}

/// A harmonic displacement test of the strut (Eqs 5.1-5.12): the record of
/// `afsv hps harmonic -o` and the last cycle's loop metrics in the metadata.
#[pyfunction]
#[pyo3(signature = (strut, freq, amp_mm, cycles, gamma0, rate, solver))]
#[allow(clippy::too_many_arguments)]
fn simulate_strut<'py>(
    py: Python<'py>,
    strut: &str,
    freq: f64,
    amp_mm: f64,
    cycles: f64,
    gamma0: Option<f64>,
    rate: f64,
    solver: &str,
) -> PyResult<Bound<'py, PyTuple>> {
    for (name, v) in [
        ("freq", freq),
        ("amp_mm", amp_mm),
        ("cycles", cycles),
        ("rate", rate),
    ] {
        if !(v.is_finite() && v > 0.0) {
            return Err(value_err(format!(
                "{name} {v}: must be a finite number > 0"
            )));
        }
    }
    check_samples("cycles / freq * rate", cycles / freq * rate)?;
    let params = strut_params(strut, gamma0)?;
    let test = HarmonicTest {
        frequency_hz: freq,
        amplitude_m: amp_mm * 1e-3,
    };
    let opts = hps_emulsion::SimOptions {
        output_rate_hz: rate,
        solver: strut_solver(solver)?,
        ..hps_emulsion::SimOptions::default()
    };
    let exc = Excitation::harmonic(freq, test.amplitude_m, cycles);
    let rec = py
        .detach(|| simulate_displacement(&params, &HpsExtensions::none(), &exc, &opts))
        .map_err(|e| py_err(py, &e))?;
    let metrics = loop_metrics(&rec, &test).map_err(|e| {
        value_err(format!(
            "{e}: raise rate or cycles (need >= 1 cycle, 16 samples per cycle)"
        ))
    })?;
    let cols: Columns = rec
        .columns()
        .into_iter()
        .map(|(n, v)| (n.to_string(), v))
        .collect();
    let meta = json!({
        "model": "hps-emulsion",
        "strut": strut,
        "sample_rate_hz": rate,
        "excitation": {"kind": "harmonic", "frequency_hz": freq, "amplitude_m": test.amplitude_m, "cycles": cycles},
        "gamma0": params.gamma0,
        "last_cycle": to_json(&metrics)?,
    });
    record_out(py, &cols, &meta)
}

/// The laboratory programme of Chapter 5 on a strut (`afsv hps characterize`): stiffness,
/// damping and energy per test, as JSON.
#[pyfunction]
#[pyo3(signature = (strut, gamma0))]
fn characterize_strut(py: Python<'_>, strut: &str, gamma0: Option<f64>) -> PyResult<String> {
    let params = strut_params(strut, gamma0)?;
    let tests = lab_programme(params.travel);
    let rows = py
        .detach(|| {
            let mut rows = Vec::with_capacity(tests.len());
            for t in &tests {
                rows.extend(characterize(
                    &params,
                    &HpsExtensions::none(),
                    std::slice::from_ref(t),
                    &hps_emulsion::SimOptions::default(),
                )?);
            }
            Ok::<_, hps_emulsion::HpsError>(rows)
        })
        .map_err(|e| py_err(py, &e))?;
    let out = json!({ "strut": strut, "gamma0": params.gamma0, "tests": to_json(&rows)? });
    Ok(out.to_string())
}

/// Register the yaw-plane and strut functions.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(simulate_yaw, m)?)?;
    m.add_function(wrap_pyfunction!(simulate_yaw_batch, m)?)?;
    m.add_function(wrap_pyfunction!(simulate_strut, m)?)?;
    m.add_function(wrap_pyfunction!(characterize_strut, m)?)?;
    Ok(())
}
