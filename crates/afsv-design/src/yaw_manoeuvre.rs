//! The yaw-plane runs of `afsv yaw`: the manoeuvre a `--input` text names (`pulse[:DEG]`,
//! `step:DEG`, `ramp:DEG_PER_S[:LIMIT_DEG]`, `csv:FILE:COLUMN`, `turn`, `path-change`;
//! section 3.3 and Fig 3.6), the parameter set of a run (a parameter file or a
//! description's load case) and the section 3.3 test definition the measures use.

use afsv_dynamics::yaw_plane::analysis::MeasureSpec;
use afsv_dynamics::yaw_plane::simulate::Recording;
use afsv_dynamics::YawPlaneParams;
use afsv_dynamics::{Course, EquationForm, Load, Manoeuvre, PathDriver, SteerInput};
use afsv_dynamics::{SimOptions, Solver};
use afsv_records::Record;
use std::path::Path;

/// Peak of the default steering-wheel pulse (deg), section 3.3.
pub const PULSE_DEG: f64 = 30.0;

/// Where a `ramp:RATE` without a limit holds the steering wheel (deg).
pub const RAMP_LIMIT_DEG: f64 = 720.0;

/// The parameter set of a yaw-plane run: the file `params` (validated, within the
/// registry's ranges), else the `load` case of the description `vehicle` (the prototype's
/// Table 3.1 columns by default).
pub fn yaw_plane_params(
    params: Option<&Path>,
    vehicle: Option<&Path>,
    load: Load,
) -> Result<YawPlaneParams, String> {
    if let Some(path) = params {
        return crate::param_files::read_yaw_plane(path);
    }
    let p = crate::described::articulated(vehicle)?.yaw_plane_params(load);
    p.validate().map_err(|e| e.to_string())?;
    Ok(p)
}

/// A speed in km/h as m/s: finite and >= 0.
pub fn speed_m_s(kmh: f64) -> Result<f64, String> {
    if kmh.is_finite() && kmh >= 0.0 {
        Ok(kmh / 3.6)
    } else {
        Err(format!("--speed-kmh must be finite and >= 0, got {kmh}"))
    }
}

/// The section 3.3 test definition in `form`, recording only the channels the measures
/// read (the same numbers as a full record, without the per-sample cost of the others).
pub fn measures_spec(form: EquationForm) -> MeasureSpec {
    let mut spec = MeasureSpec::default();
    spec.options.form = form;
    spec.options.recording = Recording::Measures;
    spec
}

/// Fixed step of the RK4 integrator of a recorded run (s).
pub const RK4_STEP_S: f64 = 2e-4;

/// The integrator settings of a recorded run (`afsv yaw simulate`): `solver` at the
/// relative tolerance `rtol` (absolute tolerance a tenth of it), samples every `dt` (s),
/// the yaw equations in `form`.
pub fn sim_options(solver: Solver, rtol: f64, dt: f64, form: EquationForm) -> SimOptions {
    SimOptions {
        solver,
        rtol,
        atol: rtol * 0.1,
        output_dt_s: dt,
        form,
        ..SimOptions::default()
    }
}

/// How `form` is named in the sensitivity table's heading.
pub fn form_text(form: EquationForm) -> &'static str {
    match form {
        EquationForm::EnergyConsistent => "energy-consistent Eq 3.13",
        EquationForm::PaperEq313 => "Eq 3.13 as printed",
    }
}

/// The record file a `csv:FILE:COLUMN` input reads.
pub fn csv_input_file(spec: &str) -> Option<&str> {
    let parts: Vec<&str> = spec.splitn(3, ':').collect();
    match parts.as_slice() {
        ["csv", file, _] => Some(file),
        _ => None,
    }
}

fn number(what: &str, s: &str) -> Result<f64, String> {
    s.parse::<f64>()
        .ok()
        .filter(|v| v.is_finite())
        .ok_or_else(|| format!("--input {what}: `{s}` is not a finite number"))
}

/// The manoeuvre `spec` names at `speed` (m/s) for `duration` (s), its input at `t0` (s):
/// a pulse (0.2 s half sine, [`PULSE_DEG`] by default), a step, a ramp (held at its limit,
/// [`RAMP_LIMIT_DEG`] by default), a record's column (`_deg` or `_rad`, with `time_s`),
/// or the driver on the Fig 3.6 steady turn or path change.
pub fn manoeuvre(spec: &str, speed: f64, t0: f64, duration: f64) -> Result<Manoeuvre, String> {
    let parts: Vec<&str> = spec.splitn(3, ':').collect();
    let open = |input: SteerInput, label: &str| Manoeuvre::open_loop(speed, duration, input, label);
    let ramp = |rate: f64, limit: f64| SteerInput::Ramp {
        rate_rad_s: rate.to_radians(),
        start_s: t0,
        limit_rad: limit.abs().to_radians(),
    };
    let driver =
        |course: Course, label| Manoeuvre::course(speed, duration, PathDriver::new(course), label);
    Ok(match parts.as_slice() {
        ["pulse"] => open(SteerInput::pulse_deg(PULSE_DEG, 0.2, t0), "pulse"),
        ["pulse", a] => open(SteerInput::pulse_deg(number("pulse peak", a)?, 0.2, t0), "pulse"),
        ["step", a] => open(SteerInput::step_deg(number("step", a)?, t0), "step"),
        ["ramp", r] => open(ramp(number("ramp rate", r)?, RAMP_LIMIT_DEG), "ramp"),
        ["ramp", r, l] => open(ramp(number("ramp rate", r)?, number("ramp limit", l)?), "ramp"),
        ["csv", file, column] => open(record_input(Path::new(file), column)?, "csv"),
        ["turn"] => driver(Course::steady_turn_fig_3_6(), "steady_turn"),
        ["path-change"] => driver(Course::path_change_fig_3_6(), "path_change"),
        _ => {
            return Err(format!(
                "--input `{spec}` not understood (expected pulse[:DEG], step:DEG, ramp:DEG_S[:LIMIT_DEG], csv:FILE:COLUMN, turn or path-change)"
            ))
        }
    })
}

/// The steering-wheel angle of `column` of the record at `path` against its `time_s`,
/// in radians (the column's name ends in `_deg` or `_rad`).
fn record_input(path: &Path, column: &str) -> Result<SteerInput, String> {
    let rec = Record::read(path).map_err(|e| e.to_string())?;
    let t = rec
        .require("time_s", path)
        .map_err(|e| e.to_string())?
        .to_vec();
    let col = rec.require(column, path).map_err(|e| e.to_string())?;
    let scale = if column.ends_with("_deg") {
        std::f64::consts::PI / 180.0
    } else if column.ends_with("_rad") {
        1.0
    } else {
        return Err(format!(
            "--input csv: column `{column}` must end in _deg or _rad to state its unit"
        ));
    };
    let input = SteerInput::Table {
        time_s: t,
        angle_rad: col.iter().map(|v| v * scale).collect(),
    };
    input.validate().map_err(|e| e.to_string())?;
    Ok(input)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_recorded_run_keeps_the_solver_defaults_it_does_not_set() {
        let o = sim_options(
            Solver::Rk4 { step: RK4_STEP_S },
            1e-5,
            0.005,
            EquationForm::PaperEq313,
        );
        let d = SimOptions::default();
        assert_eq!((o.rtol, o.atol, o.output_dt_s), (1e-5, 1e-5 * 0.1, 0.005));
        assert_eq!(
            (o.form, o.max_step_s),
            (EquationForm::PaperEq313, d.max_step_s)
        );
        assert!(matches!(o.solver, Solver::Rk4 { step } if step == 2e-4));
    }

    #[test]
    fn the_input_texts_name_their_manoeuvres() {
        let m = manoeuvre("pulse", 10.0, 0.5, 5.0).unwrap();
        assert_eq!(
            (m.label.as_str(), m.speed_m_s, m.duration_s),
            ("pulse", 10.0, 5.0)
        );
        assert_eq!(manoeuvre("step:10", 10.0, 0.5, 5.0).unwrap().label, "step");
        assert_eq!(
            manoeuvre("ramp:5:90", 10.0, 0.5, 5.0).unwrap().label,
            "ramp"
        );
        assert_eq!(
            manoeuvre("turn", 3.0, 0.5, 5.0).unwrap().label,
            "steady_turn"
        );
        assert!(manoeuvre("step:nan", 10.0, 0.5, 5.0)
            .unwrap_err()
            .contains("not a finite number"));
        assert!(manoeuvre("wiggle", 10.0, 0.5, 5.0)
            .unwrap_err()
            .contains("not understood"));
        assert_eq!(csv_input_file("csv:a.csv:steer_deg"), Some("a.csv"));
        assert_eq!(csv_input_file("pulse:3"), None);
    }

    #[test]
    fn speeds_and_forms() {
        assert_eq!(speed_m_s(36.0).unwrap(), 10.0);
        assert!(speed_m_s(-1.0).is_err() && speed_m_s(f64::NAN).is_err());
        let s = measures_spec(EquationForm::PaperEq313);
        assert_eq!(s.options.form, EquationForm::PaperEq313);
        assert_eq!(form_text(EquationForm::PaperEq313), "Eq 3.13 as printed");
        let p = yaw_plane_params(None, None, Load::Unloaded).unwrap();
        assert_eq!(p.load, Some(Load::Unloaded));
    }
}
