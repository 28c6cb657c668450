//! Tables 4.3 / 4.4 and the section 4.3.5 text: the printed optimum designs evaluated with
//! our model, their measure ratios and the Eq 4.8 objective (`afsv_design`); and the
//! optimum locations of our own chapter-4 optimisation (`afsv_design::optimise`) against
//! the printed ones.

use super::ahp::ahp_levels;
use super::{Ctx, TEST_SPEED_M_S};
use crate::fixtures::Fixtures;
use afs_hydraulics::AfsParams;
use afsv_design::{
    optimise, AfsDesign, AfsDesignBounds, AfsOptimisationSettings, AfsProblem, AfsProblemSpec,
    AfsRunState, DesignMeasures, Measure, MeasureRatios, Objective,
};
use afsv_dynamics::{measures_for, EquationForm, Load, MeasureSpec, VehicleParams, YawMeasures};
use std::collections::BTreeMap;

/// One printed design evaluated with our model.
struct Evaluated {
    /// Ratios to the current design, energy-consistent equations.
    ec: MeasureRatios,
    /// Ratios to the current design, printed Eq 3.13.
    pf: MeasureRatios,
    /// Measures, energy-consistent equations.
    m_ec: YawMeasures,
}

/// The current design and the four printed optima (Table 4.3/4.4 x PS, PS/SQP).
struct Chapter4 {
    /// Measures of the current design, energy-consistent equations.
    nominal_ec: YawMeasures,
    /// Keyed by (table, key).
    designs: BTreeMap<(String, String), Evaluated>,
}

impl Chapter4 {
    fn get(&self, table: &str, key: &str) -> &Evaluated {
        &self.designs[&(table.to_string(), key.to_string())]
    }
}

/// The design of column `key` of Table `table` (4.3 or 4.4) from the fixtures.
fn printed_design(fx: &Fixtures, table: &str, key: &str) -> Result<AfsDesign, String> {
    let g = |n: &str| fx.num(&format!("{table}_opt_{n}"), Some(key));
    AfsDesign::from_table_units(g("a0")?, g("l1")?, g("l2")?, g("a_v")?, g("b_eff")?)
        .map_err(|e| e.to_string())
}

/// Relative tolerance of the design evaluations (see [`evaluate`]).
const CONVERGED_RTOL: f64 = 1e-8;

/// Measures (loaded, 50 km/h) of every printed design, both equation forms, with converged
/// integration.
fn evaluate(fx: &Fixtures) -> Result<Chapter4, String> {
    let v = VehicleParams::nominal(Load::Loaded);
    let measure = |d: &AfsDesign, form: EquationForm| -> Result<YawMeasures, String> {
        let a = d.apply(&AfsParams::nominal()).map_err(|e| e.to_string())?;
        let mut s = MeasureSpec::default();
        s.options.form = form;
        // Converged numerics: at the default tolerances (rtol 1e-5) the integration error
        // of a design's damping ratio is ~0.05 %, the size of the margin of the
        // relaxed-vs-bounded damping change; rtol 1e-8 moves every measure by < 0.05 %
        // and no more with tighter settings.
        s.options.rtol = CONVERGED_RTOL;
        measures_for(&v, &a, Some(Load::Loaded), TEST_SPEED_M_S, &s).map_err(|e| e.to_string())
    };
    let ratios = |m: &YawMeasures, m0: &YawMeasures| -> Result<MeasureRatios, String> {
        let d = DesignMeasures::from_yaw(m).map_err(|e| e.to_string())?;
        let d0 = DesignMeasures::from_yaw(m0).map_err(|e| e.to_string())?;
        MeasureRatios::new(&d, &d0).map_err(|e| e.to_string())
    };
    let current = printed_design(fx, "t4_3", "current")?;
    let nominal_ec = measure(&current, EquationForm::EnergyConsistent)?;
    let nominal_pf = measure(&current, EquationForm::PaperEq313)?;
    let mut designs = BTreeMap::new();
    for table in ["t4_3", "t4_4"] {
        for key in ["ps", "ps_sqp"] {
            let d = printed_design(fx, table, key)?;
            let m_ec = measure(&d, EquationForm::EnergyConsistent)?;
            let m_pf = measure(&d, EquationForm::PaperEq313)?;
            designs.insert(
                (table.into(), key.into()),
                Evaluated {
                    ec: ratios(&m_ec, &nominal_ec)?,
                    pf: ratios(&m_pf, &nominal_pf)?,
                    m_ec,
                },
            );
        }
    }
    Ok(Chapter4 {
        nominal_ec,
        designs,
    })
}

/// Measures of the printed optimum designs of Tables 4.3/4.4 with our model (the design
/// values come from the fixtures; the optimisation itself is not reproduced).
pub(super) fn check_chapter4(ctx: &mut Ctx) -> Result<(), String> {
    let fx = ctx.fx();
    let w = match ctx.cache.ahp_w.clone() {
        Some(w) => w,
        None => ahp_levels(fx)?.composite.to_vec(),
    };
    let objective = Objective::from_slice(&w).map_err(|e| e.to_string())?;
    let c4 = evaluate(fx)?;
    compare_tables(ctx, &c4, &objective);
    compare_text_scalars(ctx, &c4);
    compare_step_response(ctx, &c4);
    compare_optimum(ctx, &objective)
}

/// The optimum locations (`t4_3_opt_*`, `t4_4_opt_*`, PS and PS/SQP columns) from our
/// optimisation at a reduced budget, as `afsv optimize afs` otherwise (0.25 m minimum
/// full-lock arm): 2 starts instead of 5, screening to mesh 1/16 instead of 1/32, the best
/// refined to 1/256 instead of 1/512 (about 480 instead of 1100 evaluations per table). It
/// lands within 0.001 in F of the default run, in the same basin (docs/optimisation.md).
fn compare_optimum(ctx: &mut Ctx, objective: &Objective) -> Result<(), String> {
    let mut settings = AfsOptimisationSettings {
        extra_starts: 1,
        screen_min_mesh: 1.0 / 16.0,
        ..AfsOptimisationSettings::default()
    };
    settings.pattern.min_mesh = 1.0 / 256.0;
    let names = ["a0", "l1", "l2", "a_v", "b_eff"];
    for (table, relaxed) in [("t4_3", false), ("t4_4", true)] {
        let spec = AfsProblemSpec {
            bounds: if relaxed {
                AfsDesignBounds::table_4_2_relaxed()
            } else {
                AfsDesignBounds::table_4_2()
            },
            ..AfsProblemSpec::default()
        };
        let upper = spec.bounds.upper.table_units();
        let problem = AfsProblem::new(spec, *objective).map_err(|e| e.to_string())?;
        let o = optimise(
            &problem,
            &settings,
            AfsRunState::default(),
            &optimize::Silent,
            &mut |_| Ok(()),
        )
        .map_err(|e| e.to_string())?;
        for (key, e) in [("ps", &o.ps), ("ps_sqp", &o.ps_sqp)] {
            let t = e.design.table_units();
            let g = &e.geometry;
            let why = format!(
                "our optimisation (reduced budget: 2 starts, {} evaluations), F = {:.4}, L_max/L_min = {:.4} (Eq 4.10 active), full-lock arm {:.3} m (constraint 0.25 m), l_2/l_1 = {:.3}; our yaw mode gains more from long arms than the paper's, so our optimum keeps a larger scale (L/L_0 = {:.3} against the printed 0.79/0.74) at the printed shape",
                o.evaluations_ps + if key == "ps" { 0 } else { o.evaluations_sqp },
                e.f,
                g.stroke_ratio,
                g.min_arm_m,
                g.l2_over_l1,
                e.ratios.get(Measure::StrutLength),
            );
            for (i, name) in names.iter().enumerate() {
                let on_bound = (t[i] / upper[i] - 1.0).abs() < 0.01;
                let note = if i >= 3 {
                    format!(
                        "{}; {} its upper bound {} to 1 %",
                        why,
                        if on_bound { "at" } else { "NOT at" },
                        upper[i]
                    )
                } else {
                    why.clone()
                };
                ctx.compare(&format!("{table}_opt_{name}"), Some(key), None, t[i], note);
            }
        }
    }
    Ok(())
}

/// The "normalized objective" columns and F of Tables 4.3/4.4.
fn compare_tables(ctx: &mut Ctx, c4: &Chapter4, objective: &Objective) {
    let why: [(Measure, &str); 6] = [
        (Measure::StrutLength, "kinematic: l_0 of Eq 3.7 at the printed design / current"),
        (Measure::YawFrequency, "our yaw mode is 5.5 Hz (energy-consistent) and reacts differently to A_0, l_1, l_2; the optimiser's model is not available to compare"),
        (Measure::DampingRatio, "damping from the single-DOF fit of our model"),
        (Measure::SteeringGain, "step-response gain of our model"),
        (Measure::Overshoot, "step-response overshoot of our model"),
        (Measure::ResponseRate, "psi = steady articulation / 0-100 % rise time of our model; it rises at every printed optimum (the faster yaw mode shortens the rise more than the gain falls) while the paper's falls, so the paper's psi was probably defined otherwise (not stated)"),
    ];
    let ctx_note = "loaded, 50 km/h, Table 4.3/4.4 design (A_0, l_1, l_2, a_v, B_eff) evaluated with our model, energy-consistent";
    for table in ["t4_3", "t4_4"] {
        for key in ["ps", "ps_sqp"] {
            let e = c4.get(table, key);
            for (m, why) in why {
                ctx.compare(
                    &format!("{table}_norm_{}", m.name()),
                    Some(key),
                    None,
                    e.ec.get(m),
                    format!(
                        "{ctx_note}; printed Eq 3.13 gives {:.3}; {why}",
                        e.pf.get(m)
                    ),
                );
            }
            ctx.compare(
                &format!("{table}_objective_f"),
                Some(key),
                None,
                objective.value(&e.ec),
                format!(
                    "F = W.V with our AHP weights and our ratios (off mainly through psi, see the response-rate row); printed Eq 3.13 gives {:.3}",
                    objective.value(&e.pf)
                ),
            );
        }
    }
}

/// Text scalars of section 4.3.5 that restate Table 4.3/4.4 numbers.
fn compare_text_scalars(ctx: &mut Ctx, c4: &Chapter4) {
    use Measure::*;
    let pct = |r: f64| 100.0 * (r - 1.0);
    let t3s = &c4.get("t4_3", "ps_sqp").ec;
    let t3p = &c4.get("t4_3", "ps").ec;
    let t4s = &c4.get("t4_4", "ps_sqp").ec;
    let note = "from the Table 4.3 design with our model (energy-consistent)";
    ctx.compare(
        "s4_opt_strut_length_reduction",
        None,
        None,
        pct(t3s.get(StrutLength)),
        "kinematic, Table 4.3 PS/SQP design",
    );
    ctx.compare(
        "s4_opt_yaw_frequency_gain",
        Some("ps"),
        None,
        t3p.get(YawFrequency),
        note,
    );
    ctx.compare(
        "s4_opt_yaw_frequency_gain",
        Some("ps_sqp"),
        None,
        t3s.get(YawFrequency),
        note,
    );
    ctx.compare(
        "s4_opt_damping_gain",
        Some("ps"),
        None,
        pct(t3p.get(DampingRatio)),
        note,
    );
    ctx.compare(
        "s4_opt_damping_gain",
        Some("ps_sqp"),
        None,
        pct(t3s.get(DampingRatio)),
        note,
    );
    ctx.compare(
        "s4_opt_overshoot_rate_reduction",
        Some("overshoot_min"),
        None,
        pct(t3s.get(Overshoot)),
        format!("PS/SQP design; {note}; our overshoot falls more at this design than the paper's"),
    );
    ctx.compare(
        "s4_opt_overshoot_rate_reduction",
        Some("overshoot_max"),
        None,
        pct(t3p.get(Overshoot)),
        "PS design; ".to_string() + note,
    );
    ctx.compare(
        "s4_opt_overshoot_rate_reduction",
        Some("rate_min"),
        None,
        pct(t3s.get(ResponseRate)),
        format!("PS/SQP design; {note}; our psi rises at the optimum, see t4_3_norm_response_rate"),
    );
    ctx.compare(
        "s4_opt_overshoot_rate_reduction",
        Some("rate_max"),
        None,
        pct(t3p.get(ResponseRate)),
        format!("PS design; {note}; our psi rises at the optimum, see t4_3_norm_response_rate"),
    );
    let rel = |a: f64, b: f64| 100.0 * (a / b - 1.0);
    let note = "Table 4.4 vs Table 4.3 PS/SQP design with our model (energy-consistent)";
    for (key, a, b) in [
        ("strut_length", t4s.get(StrutLength), t3s.get(StrutLength)),
        (
            "yaw_frequency",
            t4s.get(YawFrequency),
            t3s.get(YawFrequency),
        ),
        (
            "steering_gain",
            t4s.get(SteeringGain),
            t3s.get(SteeringGain),
        ),
        ("overshoot", t4s.get(Overshoot), t3s.get(Overshoot)),
        (
            "response_rate",
            t4s.get(ResponseRate),
            t3s.get(ResponseRate),
        ),
        (
            "damping_ratio",
            t4s.get(DampingRatio),
            t3s.get(DampingRatio),
        ),
    ] {
        ctx.compare(
            "s4_relaxed_vs_bounded_changes",
            Some(key),
            None,
            rel(a, b),
            note,
        );
    }
    ctx.compare(
        "s4_optimal_vs_current_strut_length",
        None,
        None,
        pct(t4s.get(StrutLength)),
        "kinematic, Table 4.4 PS/SQP design",
    );
}

/// The section 4.3.5 statement on the Table 4.4 PS/SQP step response against the current design.
fn compare_step_response(ctx: &mut Ctx, c4: &Chapter4) {
    let m_opt = &c4.get("t4_4", "ps_sqp").m_ec;
    let nom_ec = &c4.nominal_ec;
    let checks = [
        (
            "higher frequency",
            m_opt.natural_frequency_hz > nom_ec.natural_frequency_hz,
        ),
        (
            "lower pulse peak",
            m_opt.pulse_peak_articulation_deg < nom_ec.pulse_peak_articulation_deg,
        ),
        (
            "lower overshoot",
            m_opt.overshoot_percent < nom_ec.overshoot_percent,
        ),
        (
            "lower steering gain",
            m_opt.steering_gain < nom_ec.steering_gain,
        ),
        (
            "comparable response rate (within 15 %)",
            (m_opt.response_rate_deg_s / nom_ec.response_rate_deg_s - 1.0).abs() < 0.15,
        ),
        (
            "no efficiency gain",
            m_opt.power_efficiency <= nom_ec.power_efficiency * 1.02,
        ),
    ];
    let failed: Vec<&str> = checks.iter().filter(|c| !c.1).map(|c| c.0).collect();
    ctx.qualitative(
        "s4_optimal_vs_current_step_response",
        None,
        failed.is_empty(),
        format!(
            "Table 4.4 PS/SQP design vs current, our model: frequency {:.2} vs {:.2} Hz, pulse peak {:.3} vs {:.3} deg, overshoot {:.1} vs {:.1} %, gain {:.4} vs {:.4}, rate {:.1} vs {:.1} deg/s, efficiency {:.4} vs {:.4}{}",
            m_opt.natural_frequency_hz, nom_ec.natural_frequency_hz,
            m_opt.pulse_peak_articulation_deg, nom_ec.pulse_peak_articulation_deg,
            m_opt.overshoot_percent, nom_ec.overshoot_percent,
            m_opt.steering_gain, nom_ec.steering_gain,
            m_opt.response_rate_deg_s, nom_ec.response_rate_deg_s,
            m_opt.power_efficiency, nom_ec.power_efficiency,
            if failed.is_empty() { String::new() } else { format!("; not as reported: {}", failed.join(", ")) }
        ),
    );
}
