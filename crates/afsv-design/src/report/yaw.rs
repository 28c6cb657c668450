//! The record of `afsv yaw simulate` (the yaw-plane model of Chapters 3-4, crate
//! `afsv-dynamics`): its sidecar, and the summary printed once it is written; the
//! measures of `afsv yaw measures` ([`measures_json`]).

use afsv_dynamics::{Manoeuvre, SimOptions, YawMeasures, YawPlaneParams, YawRecord};
use serde_json::{json, Value};
use std::path::Path;

/// The sidecar of a yaw-plane run's record: the model and its equation form, the
/// manoeuvre (its label and the `--input` specification `input` it came from) at its
/// constant speed, the load and parameter set `p`, the solver with its tolerance and
/// counters, and the sample rate (1 / `opts.output_dt_s`).
pub fn simulate_sidecar(
    p: &YawPlaneParams,
    man: &Manoeuvre,
    input: &str,
    opts: &SimOptions,
    rec: &YawRecord,
) -> Value {
    json!({
        "written_by": "afsv yaw simulate",
        "sample_rate_hz": 1.0 / opts.output_dt_s,
        "model": "afsv-dynamics yaw-plane (chapter 3)",
        "equation_form": opts.form,
        "manoeuvre": man.label,
        "input": input,
        "speed_m_s": man.speed_m_s,
        "load": p.load,
        "excitation": input,
        "params": p,
        "solver": opts.solver,
        "rtol": opts.rtol,
        "solver_stats": rec.stats,
    })
}

/// What `afsv yaw simulate` prints once the record `output` is written with `columns`:
/// the files, the sample count, the signed peak articulation ([`super::signed_peak`],
/// deg) and the solver counters.
pub fn simulate_summary(output: &Path, columns: &[String], rec: &YawRecord) -> Value {
    json!({
        "output": output,
        "sidecar": output.with_extension("json"),
        "samples": rec.time_s.len(),
        "columns": columns,
        "peak_articulation_deg": super::signed_peak(&rec.articulation_deg),
        "solver_stats": rec.stats,
    })
}

/// The yaw-plane measures `m` as JSON, with the caveat of a decay fit that is not one mode
/// (`"decay_fit_caveat"`) when there is one.
pub fn measures_json(m: &YawMeasures) -> Value {
    let mut v = json!(m);
    if let Some(caveat) = m.decay_fit_caveat() {
        v["decay_fit_caveat"] = json!(caveat);
    }
    v
}

#[cfg(test)]
mod tests {
    use super::*;
    use afsv_dynamics::{simulate, SteerInput};

    /// A short pulse run's sidecar names what made it, and the summary's peak is the
    /// record's largest articulation with its sign.
    #[test]
    fn the_sidecar_and_summary_describe_the_run() {
        let p = YawPlaneParams::nominal(afsv_dynamics::Load::Loaded);
        let man = Manoeuvre::open_loop(10.0, 1.0, SteerInput::pulse_deg(-30.0, 0.2, 0.1), "pulse");
        let opts = SimOptions {
            output_dt_s: 0.01,
            ..SimOptions::default()
        };
        let rec = simulate(&p.vehicle, &p.afs_system().unwrap(), &man, &opts).unwrap();
        let side = simulate_sidecar(&p, &man, "pulse:-30", &opts, &rec);
        assert_eq!(side["manoeuvre"], "pulse");
        assert_eq!(side["input"], "pulse:-30");
        assert_eq!(side["speed_m_s"], 10.0);
        assert!((side["sample_rate_hz"].as_f64().unwrap() - 100.0).abs() < 1e-9);
        let names = vec!["time_s".to_string()];
        let sum = simulate_summary(Path::new("run.csv"), &names, &rec);
        assert_eq!(sum["sidecar"], "run.json");
        let peak = sum["peak_articulation_deg"].as_f64().unwrap();
        let largest = rec
            .articulation_deg
            .iter()
            .fold(0.0f64, |m, v| m.max(v.abs()));
        assert_eq!(peak.abs(), largest);
        assert!(peak != 0.0 && rec.articulation_deg.contains(&peak));
    }
}
