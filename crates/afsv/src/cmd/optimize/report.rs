//! What `afsv optimize afs` prints and draws: the JSON and text reports, the Fig 4.9 plots
//! and the progress spinner.

use super::{AfsArgs, RunOutcome};
use afsv_design::afs_problem::FullLockGeometry;
use afsv_design::{
    AfsDesign, AfsOptimum, AfsProblem, AfsVariable, DesignEvaluation, Measure, Objective,
};
use serde_json::{json, Value};
use std::io::IsTerminal;

pub(super) fn write_plots(
    a: &AfsArgs,
    problem: &AfsProblem,
    opt: &AfsDesign,
) -> Result<(), String> {
    if a.plot_step.is_none() && a.plot_pulse.is_none() {
        return Ok(());
    }
    let (p_opt, s_opt) = problem.responses(opt).map_err(|e| e.to_string())?;
    let (p_cur, s_cur) = problem
        .responses(&problem.current_design())
        .map_err(|e| e.to_string())?;
    for (path, title, opt, cur) in [
        (
            &a.plot_step,
            "30 deg steering step, loaded, 50 km/h",
            &s_opt,
            &s_cur,
        ),
        (
            &a.plot_pulse,
            "0.2 s steering pulse, loaded, 50 km/h",
            &p_opt,
            &p_cur,
        ),
    ] {
        let Some(path) = path else { continue };
        let series = [
            afsv_plot::Series {
                label: "optimum (PS/SQP)",
                x: &opt.time_s,
                y: &opt.articulation_deg,
            },
            afsv_plot::Series {
                label: "current design",
                x: &cur.time_s,
                y: &cur.articulation_deg,
            },
        ];
        afsv_plot::line_plot(path, title, "time (s)", "articulation angle (deg)", &series)?;
        afsv::output::mark_svg(path)?;
    }
    Ok(())
}

/// Progress on stderr: a spinner on a terminal, a line per finished run otherwise;
/// nothing under `afsv --quiet`.
pub(super) struct Bar(Option<indicatif::ProgressBar>);

impl Bar {
    pub(super) fn new() -> Result<Self, String> {
        if afsv::progress::is_quiet() || !std::io::stderr().is_terminal() {
            return Ok(Bar(None));
        }
        let bar = indicatif::ProgressBar::new_spinner();
        bar.set_style(
            indicatif::ProgressStyle::with_template("{spinner} {elapsed} {msg}")
                .map_err(|e| e.to_string())?,
        );
        bar.enable_steady_tick(std::time::Duration::from_millis(200));
        Ok(Bar(Some(bar)))
    }

    pub(super) fn done(&self, label: &str, o: &AfsOptimum, seconds: f64) {
        if afsv::progress::is_quiet() {
            return;
        }
        let line = format!(
            "afsv optimize afs: run {label} done: F = {:.4}{}, {} evaluations, {seconds:.1} s",
            o.ps_sqp.f,
            if o.feasible() {
                ""
            } else {
                " (no feasible design)"
            },
            o.evaluations_ps + o.evaluations_sqp
        );
        match &self.0 {
            Some(b) => b.println(line),
            None => eprintln!("{line}"),
        }
    }

    pub(super) fn finish(&self) {
        if let Some(b) = &self.0 {
            b.finish_and_clear();
        }
    }
}

impl optimize::Progress for Bar {
    fn report(&self, phase: &str, done: usize, total: usize, best: f64) {
        if let Some(b) = &self.0 {
            let best = if best < optimize::BARRIER {
                format!("{best:.4}")
            } else {
                "-".into()
            };
            b.set_message(format!(
                "{phase}: {done} evaluations (limit {total}), best F {best}"
            ));
        }
    }
}

fn design_json(d: &AfsDesign) -> Value {
    let mut m = serde_json::Map::new();
    for v in AfsVariable::ALL {
        m.insert(v.name().into(), json!(d.get(v)));
    }
    let t = d.table_units();
    m.insert(
        "table_units".into(),
        json!({"a0_deg": t[0], "l1_m": t[1], "l2_m": t[2], "a_v": t[3], "b_eff_gpa": t[4]}),
    );
    Value::Object(m)
}

fn evaluation_json(e: &DesignEvaluation) -> Value {
    let ratios: serde_json::Map<String, Value> = Measure::ALL
        .iter()
        .map(|m| (m.name().to_string(), json!(e.ratios.get(*m))))
        .collect();
    let v: serde_json::Map<String, Value> = Measure::ALL
        .iter()
        .zip(e.objective_vector)
        .map(|(m, v)| (m.name().to_string(), json!(v)))
        .collect();
    json!({
        "design": design_json(&e.design),
        "f": e.f,
        "ratios_as_tables_4_3_4_4": ratios,
        "objective_vector_eq_4_8": v,
        "measures": e.measures,
        "geometry": e.geometry,
        "constraints": e.constraints.iter().map(|(c, v)| json!({"name": c.name(), "value": v, "active": v.abs() < 1e-3})).collect::<Vec<_>>(),
    })
}

pub(super) fn to_json(
    a: &AfsArgs,
    objective: &Objective,
    current: &DesignEvaluation,
    runs: &[RunOutcome],
) -> Value {
    json!({
        "problem": {
            "variables": AfsVariable::ALL.iter().map(|v| v.name()).collect::<Vec<_>>(),
            "b_eff_upper_bound_gpa": if a.relaxed { 2.08 } else { 1.7 },
            "load": "loaded", "speed_kmh": 50.0, "rtol": a.rtol,
            "weights_eq_4_17": Measure::ALL.iter().map(|m| (m.name().to_string(), json!(objective.weight(*m)))).collect::<serde_json::Map<_, _>>(),
        },
        "current": evaluation_json(current),
        "runs": runs.iter().map(|r| json!({
            "label": r.label,
            "min_steering_arm_m": r.min_arm_m,
            "ps": evaluation_json(&r.optimum.ps),
            "ps_sqp": evaluation_json(&r.optimum.ps_sqp),
            "feasible": r.optimum.feasible(),
            "violated_constraints": r.optimum.ps_sqp.violated().iter().map(|(c, v)| json!({"name": c.name(), "value": v})).collect::<Vec<_>>(),
            "sqp_improved": r.optimum.sqp_improved,
            "sqp_status": r.optimum.sqp_status,
            "evaluations": {"pattern_search": r.optimum.evaluations_ps, "sqp": r.optimum.evaluations_sqp},
            "starts": r.optimum.starts,
            "start_spread_f": r.optimum.start_spread_f,
            "seconds": r.seconds,
        })).collect::<Vec<_>>(),
    })
}

/// The constraints the run's PS/SQP point violates, with their values
/// (`eq_4_9_engine = +0.416`; a constraint holds where its value is <= 0).
pub(super) fn violations(o: &AfsOptimum) -> String {
    o.ps_sqp
        .violated()
        .iter()
        .map(|(c, v)| {
            if v.abs() >= 1e-3 {
                format!("{} = {v:+.3}", c.name())
            } else {
                format!("{} = {v:+.2e}", c.name())
            }
        })
        .collect::<Vec<_>>()
        .join(", ")
}

fn geometry_line(g: &FullLockGeometry) -> String {
    format!(
        "L_max/L_min {:.3} (Eq 4.10: < 2), smallest full-lock arm {:.3} m, l_2/l_1 {:.3}",
        g.stroke_ratio, g.min_arm_m, g.l2_over_l1
    )
}

pub(super) fn to_text(a: &AfsArgs, current: &DesignEvaluation, runs: &[RunOutcome]) -> String {
    let mut s = format!(
        "Chapter 4 AFS design optimisation (loaded, 50 km/h; B_eff <= {} GPa, {})\n",
        if a.relaxed { "2.08" } else { "1.7" },
        if a.relaxed { "Table 4.4" } else { "Table 4.3" }
    );
    for r in runs {
        let (ps, sq) = (&r.optimum.ps, &r.optimum.ps_sqp);
        s += &format!(
            "\n{} ({:.1} s, {} PS + {} SQP evaluations, SQP {}):\n",
            r.label,
            r.seconds,
            r.optimum.evaluations_ps,
            r.optimum.evaluations_sqp,
            r.optimum.sqp_status
        );
        s += &format!(
            "  {:<22} {:>10} {:>10} {:>10}\n",
            "parameter", "current", "PS", "PS/SQP"
        );
        let (tc, tp, ts) = (
            current.design.table_units(),
            ps.design.table_units(),
            sq.design.table_units(),
        );
        for (i, v) in AfsVariable::ALL.iter().enumerate() {
            s += &format!(
                "  {:<22} {:>10.3} {:>10.3} {:>10.3}\n",
                v.table_label(),
                tc[i],
                tp[i],
                ts[i]
            );
        }
        s += "  ratio to current (Tables 4.3/4.4 print these; Eq 4.8 inverts omega, zeta, Gamma, psi)\n";
        for m in Measure::ALL {
            s += &format!(
                "  {:<22} {:>10} {:>10.3} {:>10.3}\n",
                m.name(),
                "1",
                ps.ratios.get(m),
                sq.ratios.get(m)
            );
        }
        s += "  V of Eq 4.8 (L/L_0, omega_0/omega, zeta_0/zeta, Gamma_0/Gamma, OS/OS_0, psi_0/psi)\n";
        for (name, e) in [("PS", ps), ("PS/SQP", sq)] {
            let v: Vec<String> = e
                .objective_vector
                .iter()
                .map(|v| format!("{v:.3}"))
                .collect();
            s += &format!("  {:<22} {}\n", name, v.join(" "));
        }
        s += &format!(
            "  {:<22} {:>10.3} {:>10.4} {:>10.4}\n",
            "F = W.V (Eq 4.8)", current.f, ps.f, sq.f
        );
        if !r.optimum.feasible() {
            s += &format!(
                "  NO FEASIBLE DESIGN FOUND: the PS/SQP column is the least infeasible point, not an optimum; violated: {}\n",
                violations(&r.optimum)
            );
        }
        s += &format!(
            "  PS:     {}\n  PS/SQP: {}\n",
            geometry_line(&ps.geometry),
            geometry_line(&sq.geometry)
        );
        s += &format!(
            "  {} starts, spread of their F {:.4}\n",
            r.optimum.starts.len(),
            r.optimum.start_spread_f
        );
    }
    s += &format!("\ncurrent design: {}\n", geometry_line(&current.geometry));
    s
}
