//! Section 6.5 on the 3-D vehicle: the HPS sensitivity study (Table 6.4), the GA optimum
//! (Table 6.5) and the D4 speed sweep of the optimum (Fig 6.16), each at a reduced budget so
//! that the validation stays within a minute: 3 terrain seeds per rough-terrain number
//! (`afsv study` and `afsv optimize hps` default to 10) and a GA of 12 × 6 instead of
//! 20 × 10 (`afsv optimize hps` defaults). The numbers therefore scatter by a few percent
//! against the default runs of docs/optimisation.md.

use super::chapter6::VALIDATION_SEEDS;
use super::Ctx;
use afsv_design::hps_optimum::{optimise_hps, HpsGaSettings, HpsOptimum};
use afsv_design::hps_sensitivity::{
    hps_sensitivity, HpsMeasures, HpsSensitivity, HpsVariable, StudyScope, TABLE_6_4_CHANGES,
};
use afsv_design::hps_speed_sweep::{hps_speed_sweep, SpeedSweep};
use afsv_design::HpsDesign;
use vehicle_3d::scenarios::{ride_over_seeds, RideSpec};
use vehicle_3d::{FrontAxle, Load, VehicleParams};

fn seeds() -> Vec<u64> {
    (1..=VALIDATION_SEEDS).collect()
}

/// Relative change in percent.
fn pct(v: f64, nominal: f64) -> f64 {
    100.0 * (v / nominal - 1.0)
}

/// The fixture key of a Table 6.4 change.
fn change_key(c: f64) -> String {
    if c == 0.0 {
        "nominal".into()
    } else {
        format!("{:+.0}%", 100.0 * c)
    }
}

type Pick = fn(&HpsMeasures) -> f64;

/// The four measures of Table 6.4 with their fixture-id stems.
const MEASURES: [(&str, Pick); 4] = [
    ("awz_unloaded", |m| m.a_wz_unloaded_m_s2.mean),
    ("awz_loaded", |m| m.a_wz_loaded_m_s2.mean),
    ("sp_drt_loaded", |m| m.sp_drt_m_s2.mean),
    ("omega_z_loaded", |m| m.omega_z_hz),
];

fn id_suffix(v: HpsVariable) -> &'static str {
    match v {
        HpsVariable::PistonArea => "a_hc",
        HpsVariable::CheckValveArea => "a_v",
        HpsVariable::BleedArea => "a_b",
    }
}

/// The measures of `v` at each change of `s` with the nominal, changes ascending, each with
/// its failed runs.
fn column(s: &HpsSensitivity, v: HpsVariable) -> Vec<(f64, &HpsMeasures, &[String])> {
    let mut c: Vec<(f64, &HpsMeasures, &[String])> = s
        .rows
        .iter()
        .filter(|r| r.variable == v)
        .map(|r| (r.change, &r.measures, &r.failures[..]))
        .collect();
    c.push((0.0, &s.nominal, &[]));
    c.sort_by(|a, b| a.0.total_cmp(&b.0));
    c
}

/// Table 6.4 and the section 6.5.1 statements about it.
pub(super) fn check_table_6_4(ctx: &mut Ctx) -> Result<(), String> {
    let p = VehicleParams::nominal();
    let scope = StudyScope {
        roll: true,
        yaw: true,
    };
    let s = hps_sensitivity(&p, &TABLE_6_4_CHANGES, &seeds(), scope, &|_| ())
        .map_err(|e| e.to_string())?;
    let n = s.seeds.len();
    for v in HpsVariable::ALL {
        let col = column(&s, v);
        for (stem, pick) in MEASURES {
            let id = format!("t6_4_{stem}_{}", id_suffix(v));
            let nominal = pick(&s.nominal);
            for &(c, m, failures) in &col {
                let x = pick(m);
                if !x.is_finite() {
                    ctx.not_reproducible(
                        &id,
                        Some(&change_key(c)),
                        format!("a run of this design failed: {}", failures.join("; ")),
                    );
                    continue;
                }
                let why = if stem.starts_with("omega") {
                    format!(
                        "D3 on smooth ground; {:+.1} % against the nominal",
                        pct(x, nominal)
                    )
                } else {
                    format!(
                        "mean over {n} common terrain seeds; {:+.1} % against the nominal {nominal:.3}",
                        pct(x, nominal)
                    )
                };
                ctx.compare(&id, Some(&change_key(c)), None, x, why);
            }
        }
    }
    // Section 6.5.1: the a_wz change at -30 % and +30 % A_hc
    let a_hc = column(&s, HpsVariable::PistonArea);
    for (key, c, pick) in [
        ("minus30_unloaded", -0.3, MEASURES[0].1),
        ("minus30_loaded", -0.3, MEASURES[1].1),
        ("plus30_unloaded", 0.3, MEASURES[0].1),
        ("plus30_loaded", 0.3, MEASURES[1].1),
    ] {
        let m = a_hc
            .iter()
            .find(|r| r.0 == c)
            .ok_or("the study lacks a ±30 % A_hc row")?
            .1;
        if !pick(m).is_finite() {
            ctx.not_reproducible(
                "s6_hps_a_hc_sensitivity_awz",
                Some(key),
                "a ride run of this design failed (Table 6.4 row)",
            );
            continue;
        }
        ctx.compare(
            "s6_hps_a_hc_sensitivity_awz",
            Some(key),
            None,
            pct(pick(m), pick(&s.nominal)),
            format!("Table 6.4 study, {n} seeds"),
        );
    }
    // Section 6.6: every directional change under 4 %
    let mut worst = (0.0f64, String::new());
    let mut skipped = 0;
    for r in &s.rows {
        for (name, pick) in [MEASURES[2], MEASURES[3]] {
            let d = pct(pick(&r.measures), pick(&s.nominal)).abs();
            if !d.is_finite() {
                skipped += 1;
                continue;
            }
            if d > worst.0 {
                worst = (
                    d,
                    format!("{name} at {} {}", r.variable.symbol(), change_key(r.change)),
                );
            }
        }
    }
    ctx.compare(
        "s6_hps_directional_sensitivity_bound",
        None,
        None,
        worst.0,
        format!(
            "largest |change| of SP-DRT and omega_z over Table 6.4: {}{}",
            worst.1,
            if skipped > 0 {
                format!(" ({skipped} cells n/a: failed runs)")
            } else {
                String::new()
            }
        ),
    );
    a_b_trend(ctx, &s);
    Ok(())
}

/// `s6_hps_a_b_trend`: a_wz falls with A_b (both loads), A_v has little effect on it, and
/// neither moves SP-DRT or omega_z.
fn a_b_trend(ctx: &mut Ctx, s: &HpsSensitivity) {
    let a_b = column(s, HpsVariable::BleedArea);
    let a_v = column(s, HpsVariable::CheckValveArea);
    let falls = |pick: Pick| a_b.windows(2).all(|w| pick(w[1].1) < pick(w[0].1));
    let spread_pct = |col: &[(f64, &HpsMeasures, &[String])], pick: Pick| {
        let v: Vec<f64> = col
            .iter()
            .map(|r| pick(r.1))
            .filter(|x| x.is_finite())
            .collect();
        let (lo, hi) = v
            .iter()
            .fold((f64::MAX, f64::MIN), |(l, h), x| (l.min(*x), h.max(*x)));
        100.0 * (hi - lo) / pick(&s.nominal)
    };
    let falls_unloaded = falls(MEASURES[0].1);
    let falls_loaded = falls(MEASURES[1].1);
    let a_v_ride = spread_pct(&a_v, MEASURES[0].1).max(spread_pct(&a_v, MEASURES[1].1));
    let directional = [&a_b, &a_v]
        .iter()
        .flat_map(|col| {
            [
                spread_pct(col, MEASURES[2].1),
                spread_pct(col, MEASURES[3].1),
            ]
        })
        .fold(0.0, f64::max);
    // "little effect": the A_v column spans less than a third of the A_b column
    let a_b_ride = spread_pct(&a_b, MEASURES[0].1).max(spread_pct(&a_b, MEASURES[1].1));
    let passed = falls_unloaded && falls_loaded && a_v_ride < a_b_ride / 3.0 && directional < 4.0;
    ctx.qualitative(
        "s6_hps_a_b_trend",
        None,
        passed,
        format!(
            "a_wz falls monotonically with A_b: unloaded {falls_unloaded}, loaded {falls_loaded}; a_wz span over A_v {a_v_ride:.1} % against {a_b_ride:.1} % over A_b (need < 1/3); largest directional span over A_v, A_b {directional:.1} % (need < 4 %)"
        ),
    );
}

/// The GA settings of the validation (module docs).
fn ga_settings() -> HpsGaSettings {
    HpsGaSettings {
        population: 12,
        generations: 6,
        reevaluation_seeds: VALIDATION_SEEDS as usize,
        ..HpsGaSettings::default()
    }
}

/// Table 6.5, the section 6.5.2 outcome and the D4 speed sweep of the optimum.
pub(super) fn check_hps_optimum(ctx: &mut Ctx) -> Result<(), String> {
    let p = VehicleParams::nominal();
    let settings = ga_settings();
    let o = optimise_hps(&p, &settings, &optimize::Silent).map_err(|e| e.to_string())?;
    table_6_5(ctx, &o, &settings);
    outcome(ctx, &p, &o)?;
    let mut best = p.clone();
    best.hps = o.design.apply(&p.hps).map_err(|e| e.to_string())?;
    let sweep = hps_speed_sweep(&best, &[10.0, 15.0, 20.0, 25.0, 30.0], &seeds(), &|_| ())
        .map_err(|e| e.to_string())?;
    speed_rows(ctx, &sweep);
    Ok(())
}

fn budget(o: &HpsOptimum, s: &HpsGaSettings) -> String {
    format!(
        "GA {} × {} ({} runs, reduced from 20 × 10), search seed {}",
        s.population, s.generations, o.evaluations, s.terrain_seed
    )
}

fn table_6_5(ctx: &mut Ctx, o: &HpsOptimum, s: &HpsGaSettings) {
    let b = budget(o, s);
    let d: HpsDesign = o.design;
    for (id, v, upper) in [
        ("t6_5_a_hc", d.a_hc, s.upper[0]),
        ("t6_5_a_v", d.a_v * 1e6, s.upper[1] * 1e6),
        ("t6_5_a_b", d.a_b * 1e6, s.upper[2] * 1e6),
    ] {
        ctx.compare(
            id,
            Some("optimal"),
            None,
            v,
            format!("{b}; assumed upper bound {upper:.4}"),
        );
    }
    let n = o.optimum_over_seeds.a_wz_m_s2.n;
    for (key, ride, seeds) in [
        ("nominal", &o.nominal_ride, &o.nominal_over_seeds),
        ("optimal", &o.optimum_ride, &o.optimum_over_seeds),
    ] {
        ctx.compare(
            "t6_5_awz",
            Some(key),
            None,
            seeds.a_wz_m_s2.mean,
            format!(
                "unloaded D1, mean over {n} seeds ({:.3} on the search seed); {b}",
                ride.a_wz_m_s2
            ),
        );
        ctx.compare(
            "t6_5_sp_drt",
            Some(key),
            None,
            seeds.sp_drt_m_s2.mean,
            format!("loaded D2, mean over {n} seeds"),
        );
        ctx.compare(
            "t6_5_omega_z",
            Some(key),
            None,
            seeds.omega_z_hz,
            "loaded D3 on smooth ground (our yaw mode sits near 5.7 Hz, docs/vehicle-3d.md)",
        );
        ctx.compare(
            "t6_5_d_s",
            Some(key),
            None,
            ride.d_s_m,
            "largest strut's peak-to-peak travel on the search seed (the objective's d_s)",
        );
    }
    ctx.echo(
        crate::Echo::ByConstruction,
        "t6_5_objective_f",
        Some("nominal"),
        None,
        2.0,
        "Eq 6.19 normalises by the nominal design, so its F is 2",
    );
    ctx.compare(
        "t6_5_objective_f",
        Some("optimal"),
        None,
        o.objective,
        format!("{b}; feasible: {}", o.feasible),
    );
}

/// `s6_hps_opt_outcome`: the optimum against the nominal and the unsuspended vehicle.
fn outcome(ctx: &mut Ctx, p: &VehicleParams, o: &HpsOptimum) -> Result<(), String> {
    // the chapter-6 check ran the same rigid D1 on the same seeds
    let rigid_awz = match ctx.cache.rigid_awz_unloaded {
        Some(a) => a,
        None => {
            let rigid =
                ride_over_seeds(p, &RideSpec::d1(Load::Unloaded, FrontAxle::Rigid), &seeds())
                    .map_err(|e| e.to_string())?;
            rigid.iter().map(|m| m.a_wz_m_s2).sum::<f64>() / rigid.len() as f64
        }
    };
    let opt = o.optimum_over_seeds.a_wz_m_s2.mean;
    let nom = o.nominal_over_seeds.a_wz_m_s2.mean;
    let rows = [
        (
            "a_hc_change_percent",
            pct(o.design.a_hc, o.nominal_design.a_hc),
            "A_hc of the optimum against Table 6.3".to_string(),
        ),
        ("d_s_m", o.optimum_ride.d_s_m, "search seed".to_string()),
        ("objective_f", o.objective, "Eq 6.19".to_string()),
        (
            "awz_m_per_s2",
            opt,
            format!("mean over {} seeds", o.optimum_over_seeds.a_wz_m_s2.n),
        ),
        (
            "awz_vs_nominal_percent",
            pct(opt, nom),
            format!("{opt:.3} against the nominal HPS {nom:.3} m/s², same seeds"),
        ),
        (
            "awz_vs_unsuspended_percent",
            pct(opt, rigid_awz),
            format!("{opt:.3} against the unsuspended {rigid_awz:.3} m/s², same seeds"),
        ),
    ];
    for (key, v, why) in rows {
        ctx.compare("s6_hps_opt_outcome", Some(key), None, v, why);
    }
    Ok(())
}

/// `s6_hps_opt_hcgz_speed` per load and `s6_hps_opt_speed_trends`.
fn speed_rows(ctx: &mut Ctx, s: &SpeedSweep) {
    for c in &s.crossings {
        let load = c.load.to_string();
        match c.speed_kmh {
            Some(v) => ctx.compare(
                "s6_hps_opt_hcgz_speed",
                None,
                Some(&load),
                v,
                format!(
                    "D4 on the GA optimum, 10-30 km/h in 5 km/h steps, {} seeds; a_wz crosses the 8 h bound {:.3} m/s² (linear interpolation)",
                    s.seeds.len(),
                    s.hgcz_upper_m_s2
                ),
            ),
            None => ctx.qualitative(
                "s6_hps_opt_hcgz_speed",
                None,
                false,
                format!(
                    "{load}: a_wz does not cross the 8 h bound within 10-30 km/h (above at 10 km/h: {})",
                    c.above_at_lowest
                ),
            ),
        }
    }
    let rising = |load: Load, f: fn(&afsv_design::hps_speed_sweep::SpeedPoint) -> f64| {
        let v: Vec<f64> = s.of_load(load).map(f).collect();
        v.windows(2).all(|w| w[1] > w[0])
    };
    let mut rises = true;
    for load in [Load::Unloaded, Load::Loaded] {
        rises &= rising(load, |p| p.a_wz_m_s2.mean) && rising(load, |p| p.a_z_rms_m_s2.mean);
    }
    let pairs: Vec<_> = s
        .of_load(Load::Unloaded)
        .zip(s.of_load(Load::Loaded))
        .collect();
    // "comparable": within 25 % of each other at every speed
    let comparable = pairs
        .iter()
        .map(|(u, l)| (l.a_wz_m_s2.mean / u.a_wz_m_s2.mean - 1.0).abs())
        .fold(0.0, f64::max);
    let loaded_travel_larger = pairs
        .iter()
        .filter(|(u, l)| l.d_s_m.mean > u.d_s_m.mean)
        .count();
    ctx.qualitative(
        "s6_hps_opt_speed_trends",
        None,
        rises && comparable < 0.25 && loaded_travel_larger == pairs.len(),
        format!(
            "a_wz and unweighted RMS rise with speed for both loads: {rises}; loaded and unloaded a_wz within {:.0} % of each other (need 25 %); loaded d_s larger at {loaded_travel_larger} of {} speeds",
            100.0 * comparable,
            pairs.len()
        ),
    );
}
