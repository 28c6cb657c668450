//! Chapter 2: the rigid mining truck of `roll-truck` against sections 2.3-2.4 (fixtures
//! `s2_*`). The smooth-road DRT is the calibration target (by construction, not
//! reproduced); everything else is a prediction. Rough-terrain numbers are means over
//! [`VALIDATION_SEEDS`] terrain seeds (`afsv roll study` uses 10 or more) and only the
//! study points the fixtures compare run (the ends of each sweep, all five cg heights);
//! with so few seeds they scatter by a few percent, so the fixtures do not guard these
//! rows.

use super::Ctx;
use crate::tolerance::Echo;
use perf_measures::roll::SustainedPeriodParams;
use roll_truck::sensitivity::{run_sensitivity, SensitivityCell};
use roll_truck::studies::{run_case, run_variants, Study, StudyPoint, StudyResult, Variant};
use roll_truck::{Finding, RunOptions, SteerDirection, TruckParams};
use terrain_psd::IsoClass;

/// Why ΔT is not reproducible from the paper's data.
const UNSTATED: &str = "ΔT depends on the steering ramp rate and on the rule that detects the sustained period (LTR threshold, tolerated dips), neither given in chapter 2, and it scatters with the terrain seed";

/// The ranges of the calibrated truck's class E ΔT (s) and of its class A -> E ratio over
/// the ramp rates and detection rules of `roll_truck::sensitivity`, on
/// [`VALIDATION_SEEDS`] seeds, as text (`"a-b s"`, `"× a-× b"`).
fn sensitivity_ranges() -> Result<(String, String), String> {
    let seeds: Vec<u64> = (1..=VALIDATION_SEEDS as u64).collect();
    let cells = run_sensitivity(
        &[("calibrated".to_string(), TruckParams::nominal())],
        &seeds,
        &|_, _| {},
    )
    .map_err(|e| e.to_string())?;
    let range = |f: &dyn Fn(&SensitivityCell) -> f64| {
        cells
            .iter()
            .map(f)
            .filter(|v| v.is_finite())
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
                (lo.min(v), hi.max(v))
            })
    };
    let (dt_lo, dt_hi) = range(&|c| c.class_e_s.mean);
    let (r_lo, r_hi) = range(&|c| c.ratio_e_over_a);
    Ok((
        format!("{dt_lo:.1}-{dt_hi:.1} s"),
        format!("× {r_lo:.2}-× {r_hi:.2}"),
    ))
}

/// Terrain seeds per rough-terrain point (few, so that the validation stays fast).
pub(super) const VALIDATION_SEEDS: usize = 3;

/// The variants of study `s` that `keep` selects (the ones the fixtures need), over
/// [`VALIDATION_SEEDS`] seeds.
fn study(s: Study, keep: &dyn Fn(&Variant) -> bool) -> Result<StudyResult, String> {
    let seeds: Vec<u64> = (1..=VALIDATION_SEEDS as u64).collect();
    let variants: Vec<Variant> = s
        .variants(&TruckParams::nominal())
        .map_err(|e| e.to_string())?
        .into_iter()
        .filter(|v| keep(v))
        .collect();
    run_variants(
        s,
        &variants,
        &seeds,
        &RunOptions::default(),
        &SustainedPeriodParams::default(),
        &|_, _| {},
    )
    .map_err(|e| e.to_string())
}

/// Whether `v` sits at one of the abscissae `xs`.
fn at(v: &Variant, xs: &[f64]) -> bool {
    xs.iter().any(|x| (v.x / x - 1.0).abs() < 1e-9)
}

fn found(r: &StudyResult, name: &str) -> f64 {
    r.findings()
        .iter()
        .find(|f: &&Finding| f.name == name)
        .map_or(f64::NAN, |f| f.value)
}

fn seeds_note(p: &StudyPoint, what: &str) -> String {
    format!(
        "{what}; mean ± SD over {} seeds: {:.3} ± {:.3}",
        p.sp_drt_g.n, p.sp_drt_g.mean, p.sp_drt_g.sd
    )
}

/// The chapter-2 rows (module docs).
pub(super) fn check_chapter2(ctx: &mut Ctx) -> Result<(), String> {
    smooth_rows(ctx)?;
    let ranges = sensitivity_ranges()?;
    let cg = study(Study::CgHeight, &|_| true)?;
    nominal_rows(ctx, &cg, &ranges.0)?;
    cg_rows(ctx, &cg);
    let (a, e) = (IsoClass::A.alpha_r(), IsoClass::E.alpha_r());
    let rough = study(Study::Roughness, &|v| {
        v.group == "m_c = 0.3" && at(v, &[a, e])
    })?;
    ctx.compare(
        "s2_drt_change_class_a_to_e",
        Some("drt_change_percent"),
        None,
        found(&rough, "drt_change_a_to_e_pct"),
        "prediction, m_c = 0.3, class A -> E",
    );
    ctx.not_reproducible_from_paper_data(
        "s2_drt_change_class_a_to_e",
        Some("sustained_period_ratio"),
        found(&rough, "sustained_period_ratio_e_over_a"),
        format!("{UNSTATED}; over ramp rates 2.5-10 deg/s and three detection rules the calibrated truck's ratio spans {} ({VALIDATION_SEEDS} seeds; 10 seeds in docs/roll-truck.md, `afsv roll study sensitivity`), so no single number can be checked against × 6.4", ranges.1),
    );
    let w = study(Study::Waviness, &|v| at(v, &[1.6, 2.4]))?;
    ctx.compare(
        "s2_drt_change_waviness",
        None,
        None,
        found(&w, "drt_change_w_1_6_to_2_4_pct"),
        "prediction at alpha_r of class E: w = 2.4 puts much more roughness below 0.1 cycles/m, which this roll-compliant truck follows; the sign matches",
    );
    let band = study(Study::Band, &|v| {
        if v.group.starts_with("lower") {
            at(v, &[0.02, 0.25])
        } else {
            at(v, &[5.0, 10.0])
        }
    })?;
    ctx.compare(
        "s2_drt_change_low_frequency_content",
        None,
        None,
        found(&band, "drt_change_low_frequency_pct"),
        format!(
            "prediction, SP-DRT of 0.02-5 against 0.25-5 cycles/m (the likely reading of Fig 2.14(c)); adding 5-10 cycles/m changes it by {:.1} %",
            found(&band, "drt_change_high_frequency_pct")
        ),
    );
    Ok(())
}

/// Smooth-road rows: the calibrated DRT and the first bump-stop contact.
fn smooth_rows(ctx: &mut Ctx) -> Result<(), String> {
    let p = TruckParams::nominal();
    let run = run_case(
        &p,
        None,
        0,
        SteerDirection::Left,
        &RunOptions::default(),
        &SustainedPeriodParams::default(),
    )
    .map_err(|e| e.to_string())?;
    let drt = run
        .measures
        .drt_g
        .ok_or("the smooth run never reaches LTR = 1")?;
    ctx.echo(
        Echo::ByConstruction,
        "s2_drt_smooth",
        None,
        None,
        drt,
        "calibration target of the strut spacing ratio; the search is limited to roll-stable trucks, whose lowest smooth DRT is this (0.279 g needs a truck that tips over on a straight road); the calibrated truck leans onto its bump stops early in the ramp and its DRT is bump-stop limited",
    );
    let rec = &run.record;
    let first_stop = rec
        .on_bump_stop
        .iter()
        .position(|b| *b)
        .map_or(f64::NAN, |i| rec.t_s[i]);
    ctx.compare(
        "s2_smooth_oscillation_time",
        None,
        None,
        first_stop,
        "prediction: first bump-stop contact on the smooth ramp (assumed ramp 5 deg/s at the steering wheel, ratio 25, from t = 2 s); the calibrated, nearly roll-neutral truck reaches its stops at 0.03 g (with strut spacing ratio 0.5 it would at 29.5 s, LTR = 1 at 38 s, but its DRT is 0.39 g)",
    );
    Ok(())
}

/// Rows of the nominal truck on the nominal class E terrain (the cg study's middle point).
fn nominal_rows(ctx: &mut Ctx, cg: &StudyResult, dt_range: &str) -> Result<(), String> {
    let n = cg
        .points
        .get(cg.points.len() / 2)
        .ok_or("the cg study has no nominal point")?;
    ctx.compare(
        "s2_drt_rough",
        None,
        None,
        n.sp_drt_g.mean,
        seeds_note(n, "prediction, SP-DRT on class E, m_c = 0.3"),
    );
    ctx.not_reproducible_from_paper_data(
        "s2_sustained_period",
        None,
        n.sustained_period_s.mean,
        format!(
            "{UNSTATED}; ± {:.2} s over the seeds with the default rule at 5 deg/s; the calibrated truck's class E ΔT spans {dt_range} over ramp rates 2.5-10 deg/s and the three rules ({VALIDATION_SEEDS} seeds; 10 seeds in docs/roll-truck.md, `afsv roll study sensitivity`)",
            n.sustained_period_s.sd
        ),
    );
    ctx.not_reproducible_from_paper_data(
        "s2_t_lift_a4",
        None,
        n.sustained_end_s.mean,
        "the time of A4 after the ramp start scales roughly inversely with the steering ramp rate, which chapter 2 does not give (assumed 5 deg/s at the steering wheel, ratio 25, from t = 2 s; `afsv roll measures --ramp-rate` shows it)",
    );
    for (key, stat, what) in [
        ("a4", &n.ay_at_a4_g, "|a_y| at A4".to_string()),
        (
            "b_prime",
            &n.ay_at_rollover_g,
            "|a_y| at absolute rollover".to_string(),
        ),
        ("peak", &n.peak_ay_g, peak_note()?),
    ] {
        ctx.compare(
            "s2_ay_at_a4_b_prime",
            Some(key),
            None,
            stat.mean,
            format!("prediction, ± {:.3} g over the seeds: {what}", stat.sd),
        );
    }
    ctx.compare(
        "s2_ay_range_sustained",
        Some("min"),
        None,
        n.sustained_min_g.mean,
        "prediction, lowest |a_y| in the sustained period",
    );
    ctx.compare(
        "s2_ay_range_sustained",
        Some("max"),
        None,
        n.sustained_max_g.mean,
        "prediction, highest |a_y| in the sustained period",
    );
    Ok(())
}

/// Why the peak a_y is low: the calibrated truck without its stops and the plausible
/// truck, on the same seeds (`afsv roll study trucks`).
fn peak_note() -> Result<String, String> {
    let trucks = study(Study::Trucks, &|v| {
        v.group == "calibrated, no stops" || v.group == "plausible"
    })?;
    let peak = |group: &str| {
        trucks
            .points
            .iter()
            .find(|p| p.group == group)
            .map_or(f64::NAN, |p| p.peak_ay_g.mean)
    };
    Ok(format!(
        "peak |a_y| of the whole-vehicle channel (sum of the tire forces; the sprung cg's horizontal a_y peaks about 11 % higher, docs/roll-truck.md); the calibrated truck's very soft roll suspension ends the run early: with its bump stops out of reach the peak falls to {:.3} g, and the plausible truck (strut spacing ratio 0.5) reaches {:.3} g",
        peak("calibrated, no stops"),
        peak("plausible"),
    ))
}

/// Rows of the cg study (Figs 2.10-2.11).
fn cg_rows(ctx: &mut Ctx, cg: &StudyResult) {
    let below = found(cg, "rough_below_smooth_everywhere") == 1.0;
    ctx.compare(
        "s2_drt_rough_vs_smooth_cg",
        Some("cg_2_85m"),
        None,
        found(cg, "gap_lowest_cg_pct"),
        "prediction, rough SP-DRT against smooth DRT at 2.85 m",
    );
    ctx.compare(
        "s2_drt_rough_vs_smooth_cg",
        Some("cg_3_5m"),
        None,
        found(cg, "gap_highest_cg_pct"),
        "prediction at 3.45 m (3.15 + 0.3; the text says 3.5 m); above the nominal 3.15 m the calibrated suspension no longer holds the upright truck statically",
    );
    ctx.compare(
        "s2_drt_correlation_r2",
        None,
        None,
        found(cg, "drt_correlation_r2"),
        format!(
            "prediction over 2.85-3.45 m; rough below smooth at every height: {below}; smooth DRT, SP-DRT and SSF all fall with the cg height: {}",
            found(cg, "smooth_drt_decreasing") == 1.0
                && found(cg, "rough_drt_decreasing") == 1.0
                && found(cg, "ssf_decreasing") == 1.0
        ),
    );
    let series = vec![
        (
            "smooth DRT".to_string(),
            cg.points.iter().map(|p| p.x).collect(),
            cg.points
                .iter()
                .map(|p| p.smooth_drt_g.unwrap_or(f64::NAN))
                .collect(),
        ),
        (
            "rough SP-DRT (mean)".to_string(),
            cg.points.iter().map(|p| p.x).collect(),
            cg.points.iter().map(|p| p.sp_drt_g.mean).collect(),
        ),
    ];
    ctx.plot(
        "s2_drt_cg_height.svg",
        "DRT of the truck against the sprung cg height (Fig 2.10)",
        "sprung cg height (m)",
        "lateral acceleration (g)",
        series,
    );
}
