//! The report of `afsv optimize afs` (Chapter 4): its runs ([`AfsRun`]: one
//! [`crate::AfsOptimum`] per configuration) as JSON and as text tables in the layout of
//! Tables 4.3/4.4.

use crate::afs_problem::FullLockGeometry;
use crate::{AfsDesign, AfsOptimum, AfsVariable, DesignEvaluation, Measure, Objective};
use serde_json::{json, Value};

/// One configuration's run: its label, the minimum steering arm it was run with, its
/// optimum and its wall time.
pub struct AfsRun {
    /// The configuration's label (with or without the steering-arm constraint).
    pub label: String,
    /// The minimum full-lock steering arm of the run (m), if constrained.
    pub min_arm_m: Option<f64>,
    /// The run's result.
    pub optimum: AfsOptimum,
    /// Wall time of the run (s).
    pub seconds: f64,
}

/// The design vector by name, and in the units of Tables 4.3/4.4 (`table_units`).
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

/// One evaluated design: the design, F, the ratios of Tables 4.3/4.4, V of Eq 4.8, the
/// measures, the geometry and the constraints with their values.
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

/// The report as JSON: the problem (`relaxed`: the B_eff bound of Table 4.4, `rtol`: the
/// integration tolerance, the Eq 4.17 weights of `objective`), the `current` design and
/// every run.
pub fn to_json(
    relaxed: bool,
    rtol: f64,
    objective: &Objective,
    current: &DesignEvaluation,
    runs: &[AfsRun],
) -> Value {
    json!({
        "problem": {
            "variables": AfsVariable::ALL.iter().map(|v| v.name()).collect::<Vec<_>>(),
            "b_eff_upper_bound_gpa": if relaxed { 2.08 } else { 1.7 },
            "load": "loaded", "speed_kmh": 50.0, "rtol": rtol,
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
pub fn violations(o: &AfsOptimum) -> String {
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

/// Whether every run found a feasible design: else an error naming, per infeasible run,
/// the constraints its least infeasible point violates ([`violations`]).
pub fn earned(runs: &[AfsRun]) -> Result<(), String> {
    let infeasible: Vec<String> = runs
        .iter()
        .filter(|r| !r.optimum.feasible())
        .map(|r| format!("run {}: {}", r.label, violations(&r.optimum)))
        .collect();
    if infeasible.is_empty() {
        Ok(())
    } else {
        Err(infeasible.join("; "))
    }
}

/// The full-lock geometry of a design in one line (Eq 4.10, the smallest arm, l_2/l_1).
fn geometry_line(g: &FullLockGeometry) -> String {
    format!(
        "L_max/L_min {:.3} (Eq 4.10: < 2), smallest full-lock arm {:.3} m, l_2/l_1 {:.3}",
        g.stroke_ratio, g.min_arm_m, g.l2_over_l1
    )
}

/// The report as text: per run the table of Tables 4.3/4.4 (current, PS, PS/SQP), the ratios,
/// V and F of Eq 4.8, the feasibility and the geometry; `relaxed` as in [`to_json`].
pub fn to_text(relaxed: bool, current: &DesignEvaluation, runs: &[AfsRun]) -> String {
    let mut s = format!(
        "Chapter 4 AFS design optimisation (loaded, 50 km/h; B_eff <= {} GPa, {})\n",
        if relaxed { "2.08" } else { "1.7" },
        if relaxed { "Table 4.4" } else { "Table 4.3" }
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

/// The line of an asked batch (`afsv optimize afs --ask` on a terminal): its number, its
/// points, the file they went to and each run's phase.
pub fn asked_text(batch: usize, asked: &crate::afs_state::Asked, file: &std::path::Path) -> String {
    let phases = asked
        .phases
        .iter()
        .map(|p| {
            format!(
                "{} {}: {}",
                p["run"].as_str().unwrap_or(""),
                p["phase"].as_str().unwrap_or(""),
                p["points"]
            )
        })
        .collect::<Vec<_>>()
        .join("; ");
    format!(
        "batch {batch}: {} points written to {} ({phases})",
        asked.points.len(),
        file.display()
    )
}
