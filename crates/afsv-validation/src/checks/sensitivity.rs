//! Section 3.4.3: parameter sensitivity of the yaw-plane measures, the A_0 of the longest
//! steering arm and of the yaw-frequency peak.

use super::{Ctx, DEG, TEST_SPEED_M_S};
use afs_hydraulics::AfsParams;
use afsv_design::{a0_of_longest_initial_arm, parabolic_peak};
use afsv_dynamics::yaw_plane::analysis::MeasureChanges;
use afsv_dynamics::{
    measures_for, sensitivity, EquationForm, Load, MeasureSpec, SensitivityParam, SensitivityTable,
    VehicleParams,
};

/// The section 3.4.3 sensitivity tables at 50 km/h, energy-consistent and printed Eq 3.13
/// forms (computed once per run).
pub(super) fn sens_tables(ctx: &mut Ctx) -> Result<[SensitivityTable; 2], String> {
    if let Some(t) = &ctx.cache.sens {
        return Ok(t.clone());
    }
    let mut out = Vec::new();
    for form in [EquationForm::EnergyConsistent, EquationForm::PaperEq313] {
        let mut spec = MeasureSpec::default();
        spec.options.form = form;
        out.push(sensitivity(TEST_SPEED_M_S, &spec).map_err(|e| e.to_string())?);
    }
    let t: [SensitivityTable; 2] = [out.remove(0), out.remove(0)];
    ctx.cache.sens = Some(t.clone());
    Ok(t)
}

/// The change of the measures for `p` varied by `pct` % at `load`.
fn change(
    t: &SensitivityTable,
    load: Load,
    p: SensitivityParam,
    pct: f64,
) -> Result<MeasureChanges, String> {
    t.rows
        .iter()
        .find(|r| r.load == load && r.parameter == p && (r.variation_percent - pct).abs() < 1e-9)
        .map(|r| r.change)
        .ok_or_else(|| {
            format!(
                "no sensitivity row for {} {} {pct}",
                load.name(),
                p.symbol()
            )
        })
}

/// One measure of a sensitivity row.
type Pick = fn(&MeasureChanges) -> f64;
const DAMPING: Pick = |c| c.damping;
const GAIN: Pick = |c| c.gain;
const OVERSHOOT: Pick = |c| c.overshoot;

/// Section 3.4.3 sensitivity percentages, energy-consistent model (printed Eq 3.13 in the note).
pub(super) fn check_sensitivity(ctx: &mut Ctx) -> Result<(), String> {
    let [ec, pf] = sens_tables(ctx)?;
    compare_arm_peak(ctx)?;
    compare_percentages(ctx, &ec, &pf)?;
    compare_both_loads(ctx, &ec, &pf)?;
    compare_trends(ctx, &ec)?;
    plot_sensitivity(ctx, &ec)
}

/// Kinematics: the A_0 that maximises the initial steering arm h(0) (Eq 3.2).
fn compare_arm_peak(ctx: &mut Ctx) -> Result<(), String> {
    let a = AfsParams::nominal();
    let a0_best = a0_of_longest_initial_arm(a.l1_m, a.l2_m).map_err(|e| e.to_string())?;
    ctx.compare(
        "s3_sens_a0_arm_length_peak",
        None,
        None,
        100.0 * (a0_best / a.a0_rad - 1.0),
        format!(
            "maximum of the initial steering arm h(0) (afsv_design::a0_of_longest_initial_arm: cos A_0 = l_2/l_1) at A_0 = {:.2} deg",
            a0_best / DEG
        ),
    );
    Ok(())
}

/// Percentages quoted for one load (or for an unstated load, compared loaded).
fn compare_percentages(
    ctx: &mut Ctx,
    ec: &SensitivityTable,
    pf: &SensitivityTable,
) -> Result<(), String> {
    use SensitivityParam::*;
    type Case<'a> = (
        &'a str,
        Option<&'a str>,
        Load,
        SensitivityParam,
        f64,
        Pick,
        &'a str,
    );
    let cases: [Case; 9] = [
        ("s3_sens_kl_damping_loaded", None, Load::Loaded, LeakVelocity, 30.0, DAMPING, ""),
        ("s3_sens_muv_damping_loaded", None, Load::Loaded, SealViscous, 30.0, DAMPING, ""),
        (
            "s3_sens_muv_damping_unloaded",
            None,
            Load::Unloaded,
            SealViscous,
            30.0,
            DAMPING,
            "our seal friction acts more on the light unloaded rear unit (faster 7.3 Hz yaw mode); mu_v's unit is not printed (docs/afs-hydraulics.md)",
        ),
        ("s3_sens_kl_minus30_damping", None, Load::Loaded, LeakVelocity, -30.0, DAMPING, "load not stated; loaded used"),
        (
            "s3_sens_beff_damping",
            None,
            Load::Loaded,
            BulkModulus,
            30.0,
            DAMPING,
            "load not stated; loaded used. Our yaw mode is stiffer (5.5 Hz vs the paper's lower frequency), so zeta ~ c/(2 sqrt(kJ)) falls more with B_eff",
        ),
        ("s3_sens_beff_overshoot", Some("loaded"), Load::Loaded, BulkModulus, 30.0, OVERSHOOT, ""),
        ("s3_sens_beff_overshoot", Some("unloaded"), Load::Unloaded, BulkModulus, 30.0, OVERSHOOT, ""),
        ("s3_sens_beff_minus30_overshoot", None, Load::Loaded, BulkModulus, -30.0, OVERSHOOT, "load not stated; loaded used"),
        (
            "s3_sens_kl_muv_overshoot",
            Some("k_l_plus30"),
            Load::Loaded,
            LeakVelocity,
            30.0,
            OVERSHOOT,
            "our velocity-dependent leakage (k_l h |dtheta/dt|) acts only while the struts move and our rise is faster, so it trims overshoot less",
        ),
    ];
    for (id, key, load, p, pct, pick, why) in cases {
        let s = pick(&change(ec, load, p, pct)?);
        let s_pf = pick(&change(pf, load, p, pct)?);
        let note = format!(
            "{} {} {pct:+}%, energy-consistent Eq 3.13 at 50 km/h; printed Eq 3.13 gives {:+.2}%. {why}",
            load.name(),
            p.symbol(),
            s_pf
        );
        ctx.compare(id, key, None, s, note.trim_end_matches(". ").to_string());
    }
    Ok(())
}

/// Fixtures quoted for both loads: one row per load.
fn compare_both_loads(
    ctx: &mut Ctx,
    ec: &SensitivityTable,
    pf: &SensitivityTable,
) -> Result<(), String> {
    use SensitivityParam::*;
    /// (fixture id, key, parameter, variation %, measure, reason it may differ)
    type BothCase<'a> = (
        &'a str,
        Option<&'a str>,
        SensitivityParam,
        f64,
        Pick,
        &'a str,
    );
    let both: [BothCase; 2] = [
        ("s3_sens_a0_gain", None, A0, 30.0, GAIN, ""),
        (
            "s3_sens_kl_muv_overshoot",
            Some("mu_v_plus30"),
            SealViscous,
            30.0,
            OVERSHOOT,
            "",
        ),
    ];
    for (id, key, p, pct, pick, why) in both {
        for load in Load::ALL {
            let s = pick(&change(ec, load, p, pct)?);
            let s_pf = pick(&change(pf, load, p, pct)?);
            ctx.compare(
                id,
                key,
                Some(load.name()),
                s,
                format!(
                    "{} {pct:+}%, energy-consistent; printed Eq 3.13 gives {s_pf:+.2}%{why}",
                    p.symbol()
                ),
            );
        }
    }
    Ok(())
}

/// Qualitative trends (signs), both loads.
fn compare_trends(ctx: &mut Ctx, ec: &SensitivityTable) -> Result<(), String> {
    use SensitivityParam::*;
    let mut fails = Vec::new();
    let mut n = 0;
    let mut expect = |ok: bool, what: String| {
        n += 1;
        if !ok {
            fails.push(what);
        }
    };
    for load in Load::ALL {
        let l = load.name();
        let c = |p, pct| change(ec, load, p, pct);
        expect(
            c(BulkModulus, 30.0)?.frequency > 5.0 && c(BulkModulus, -30.0)?.frequency < -5.0,
            format!("{l}: frequency rises strongly with B_eff"),
        );
        for p in [LeakVelocity, SealViscous] {
            for pct in [-30.0, 30.0] {
                expect(
                    c(p, pct)?.frequency.abs() < 1.0,
                    format!("{l}: frequency insensitive to {}", p.symbol()),
                );
                let d = c(p, pct)?.damping;
                expect(
                    d * pct > 0.0,
                    format!("{l}: damping rises with {}", p.symbol()),
                );
                let g = c(p, pct)?.gain;
                expect(
                    g * pct < 0.0,
                    format!("{l}: gain falls with {}", p.symbol()),
                );
            }
        }
        expect(
            c(BulkModulus, 30.0)?.damping < 0.0,
            format!("{l}: damping falls slightly with B_eff"),
        );
        expect(
            c(A0, 30.0)?.gain > 5.0,
            format!("{l}: gain rises strongly with A_0"),
        );
        expect(
            c(BulkModulus, 30.0)?.gain > 0.0,
            format!("{l}: gain rises slightly with B_eff"),
        );
        expect(
            c(BulkModulus, 30.0)?.overshoot < -10.0 && c(BulkModulus, -30.0)?.overshoot > 10.0,
            format!("{l}: overshoot falls strongly with B_eff"),
        );
        for p in [LeakVelocity, SealViscous] {
            expect(
                c(p, 30.0)?.overshoot < 0.0,
                format!("{l}: overshoot falls with {}", p.symbol()),
            );
        }
    }
    let ok = fails.is_empty();
    ctx.qualitative(
        "s3_sens_qualitative_trends",
        None,
        ok,
        if ok {
            format!("all {n} sign checks of section 3.4.3 pass (energy-consistent, both loads)")
        } else {
            format!(
                "{} of {n} sign checks fail: {}",
                fails.len(),
                fails.join("; ")
            )
        },
    );
    Ok(())
}

/// Plots: % change per measure vs variation, loaded, one curve per parameter.
fn plot_sensitivity(ctx: &mut Ctx, ec: &SensitivityTable) -> Result<(), String> {
    let picks: [(&str, &str, Pick); 4] = [
        ("frequency", "yaw frequency", |c| c.frequency),
        ("damping", "damping ratio", DAMPING),
        ("gain", "steering gain", GAIN),
        ("overshoot", "overshoot", OVERSHOOT),
    ];
    for (file, name, pick) in picks {
        let mut series = Vec::new();
        for p in SensitivityParam::ALL {
            let xs = vec![-30.0, -15.0, 0.0, 15.0, 30.0];
            let ys: Vec<f64> = xs
                .iter()
                .map(|&v| {
                    if v == 0.0 {
                        Ok(0.0)
                    } else {
                        change(ec, Load::Loaded, p, v).map(|c| pick(&c))
                    }
                })
                .collect::<Result<_, _>>()?;
            series.push((p.symbol().to_string(), xs, ys));
        }
        ctx.plot(
            &format!("sensitivity_{file}.svg"),
            &format!("Section 3.4.3 sensitivity, loaded, 50 km/h: {name}"),
            "parameter variation (%)",
            &format!("{name} change (%)"),
            series,
        );
    }
    Ok(())
}

/// Location of the yaw-frequency peak over A_0 (section 3.4.3: about -7.5 %).
pub(super) fn check_a0_peak(ctx: &mut Ctx) -> Result<(), String> {
    let steps: Vec<f64> = (0..=10).map(|i| -17.5 + 2.5 * i as f64).collect();
    let spec = MeasureSpec::default();
    let mut series = Vec::new();
    for load in Load::ALL {
        let v = VehicleParams::nominal(load);
        let mut f = Vec::new();
        for &s in &steps {
            let a = SensitivityParam::A0.scaled(&AfsParams::nominal(), 1.0 + s / 100.0);
            let m = measures_for(&v, &a, Some(load), TEST_SPEED_M_S, &spec)
                .map_err(|e| e.to_string())?;
            f.push(m.natural_frequency_hz);
        }
        let peak = parabolic_peak(&steps, &f).map_err(|e| e.to_string())?;
        ctx.compare(
            "s3_sens_a0_frequency_peak",
            None,
            Some(load.name()),
            peak.x,
            format!(
                "A_0 swept -17.5..+7.5 % in 2.5 % steps, parabolic peak; {:.3} Hz at the peak vs {:.3} Hz nominal",
                peak.y_max, f[7]
            ),
        );
        series.push((load.name().to_string(), steps.clone(), f));
    }
    ctx.plot(
        "a0_frequency_sweep.svg",
        "Yaw-mode frequency vs A_0 (energy-consistent, 50 km/h)",
        "A_0 variation (%)",
        "natural frequency (Hz)",
        series,
    );
    Ok(())
}
