//! Chapter 5 and Tables 6.3 / 6.5: the front-axle strut and the laboratory strut.

use super::Ctx;
use crate::fixtures::Fixtures;
use crate::Echo;
use afsv_design::HpsDesign;
use hps_emulsion::{
    identify_lab, run_harmonic, HarmonicTest, HpsExtensions, HpsStrut, LabConfig,
    LabIdentification, LabReported,
};

const MM: f64 = 1e-3;
const MPA: f64 = 1e6;

/// Table 6.3 against `StrutParams::front_axle`, and the nominal column of Table 6.5.
pub(super) fn check_hps_front(ctx: &mut Ctx) -> Result<(), String> {
    let p = hps_emulsion::StrutParams::front_axle();
    let note = "StrutParams::front_axle";
    let (oil_c, oil_r) = p.oil_volumes();
    ctx.echo(
        Echo::ByConstruction,
        "t6_3_total_oil_volume",
        None,
        None,
        (oil_c + oil_r) * 1e3,
        "StrutParams::oil_volumes: StrutParams::front_axle splits the 11.4 L of Table 6.3 between the chambers, so the sum returns it",
    );
    for (id, v) in [
        ("t6_3_piston_area", p.a_hc),
        ("t6_3_rod_area", p.a_hr),
        ("t6_3_check_valve_area", p.a_v * 1e6),
        ("t6_3_check_valve_cd", p.c_v),
        ("t6_3_check_valve_number", p.n_v as f64),
        ("t6_3_bleed_orifice_area", p.a_b * 1e6),
        ("t6_3_bleed_orifice_cd", p.c_b),
        ("t6_3_bleed_orifice_number", p.n_b as f64),
        ("t6_3_strut_travel", p.travel * 1e3),
        ("t6_3_oil_bulk_modulus", p.beta_h / 1e6),
        ("t6_3_oil_density", p.rho_h),
        ("t6_3_initial_gas_volume", p.v_g0 * 1e3),
        ("t6_3_initial_gas_pressure", p.p_h0 / 1e6),
        ("t6_3_initial_gas_fraction", p.gamma0 * 100.0),
        ("t6_3_polytropic_exponent", p.n),
        ("t6_3_leakage_coefficient", p.k_l),
    ] {
        ctx.echo(Echo::Input, id, None, None, v, note);
    }
    let d = HpsDesign::of(&p);
    for (id, v) in [
        ("t6_5_a_hc", d.a_hc),
        ("t6_5_a_v", d.a_v * 1e6),
        ("t6_5_a_b", d.a_b * 1e6),
    ] {
        ctx.echo(
            Echo::Input,
            id,
            Some("nominal"),
            None,
            v,
            "nominal design = afsv_design::HpsDesign::of(StrutParams::front_axle)",
        );
    }
    Ok(())
}

/// The numbers the text reports about the laboratory strut (`hps_lab.json`), in SI units.
fn lab_reported(fx: &Fixtures) -> Result<LabReported, String> {
    let n = |id: &str| fx.num(id, None);
    let (mm, mpa) = (MM, MPA);
    let rep = LabReported {
        oil_volume: n("oil_volume")? * 1e-3,
        charge_pressure: n("charge_pressure")? * mpa,
        static_displacements: [
            n("static_displacement_75mm")? * mm,
            n("static_displacement_100mm")? * mm,
            n("static_displacement_115mm")? * mm,
        ],
        static_pressures: [
            n("static_pressure_75mm")? * mpa,
            n("static_pressure_100mm")? * mpa,
            n("static_pressure_115mm")? * mpa,
        ],
        mid_position_pressure: n("mid_position_pressure")? * mpa,
        saturation_pressure_one: n("saturation_pressure_one_orifice")? * mpa,
        saturation_pressure_two: n("saturation_pressure_two_orifices")? * mpa,
        c_b_one: n("c_b_one_orifice")?,
        c_b_two: n("c_b_two_orifices")?,
        c_v: n("c_v")?,
        k_l: n("k_l")?,
        k_s: n("k_s")?,
        mu_v: n("mu_v")?,
        peak_velocity: n("peak_velocity_max")?,
        p_rod_min_compression: n("p_rod_min_compression")? * mpa,
        n: n("polytropic_exponent")?,
    };
    hps_emulsion::lab::validate_reported(&rep).map_err(|e| e.to_string())?;
    Ok(rep)
}

/// The laboratory strut of chapter 5 identified from `hps_lab.json` (as the hps-emulsion
/// crate does), then simulated.
pub(super) fn check_hps_lab(ctx: &mut Ctx) -> Result<(), String> {
    let rep = lab_reported(ctx.fx())?;
    let one = identify_lab(&rep, LabConfig::OneOrifice);
    let two = identify_lab(&rep, LabConfig::TwoOrifices);
    compare_static(ctx, &rep, &one)?;
    compare_dynamic(ctx, &rep, &one, &two)
}

/// Section 5.4.1: static pressures of the fresh one-orifice strut, with their plot.
fn compare_static(ctx: &mut Ctx, rep: &LabReported, one: &LabIdentification) -> Result<(), String> {
    let (mm, mpa) = (MM, MPA);
    let why = "fresh strut (no emulsion, charged at the bottom) after the one-parameter gas-column fit with n = 1.4 (hps_emulsion::identify_lab), HpsStrut::static_pressure";
    for (i, id) in [
        "static_pressure_75mm",
        "static_pressure_100mm",
        "static_pressure_115mm",
    ]
    .iter()
    .enumerate()
    {
        ctx.compare(id, None, None, one.static_pressures[i] / mpa, why);
    }
    ctx.compare(
        "mid_position_pressure",
        None,
        None,
        one.static_pressures[0] / mpa,
        "fresh strut at mid-stroke (75 mm from the bottom)",
    );
    // Static pressure curve of the fresh strut for the plot.
    let strut = HpsStrut::new(&one.fresh, &HpsExtensions::none()).map_err(|e| e.to_string())?;
    let (mut xs, mut ps) = (Vec::new(), Vec::new());
    for i in 0..=30 {
        let z = 0.020 + 0.100 * i as f64 / 30.0;
        if let Ok(p) = strut.static_pressure(z - one.mid_stroke) {
            xs.push(z / mm);
            ps.push(p / mpa);
        }
    }
    let rx: Vec<f64> = rep.static_displacements.iter().map(|z| z / mm).collect();
    let ry: Vec<f64> = rep.static_pressures.iter().map(|p| p / mpa).collect();
    ctx.plot(
        "hps_static_pressure.svg",
        "Lab HPS: static pressure vs displacement from the bottom (section 5.4.1)",
        "displacement from bottom (mm)",
        "P_hc (MPa, absolute)",
        vec![
            ("model (fresh strut, n = 1.4)".into(), xs, ps),
            ("reported 1.43 / 2.05 / 2.74 MPa".into(), rx, ry),
        ],
    );
    Ok(())
}

/// Sections 5.4.2-5.4.3: rod-side pressure, saturation pressures and loop behaviour.
fn compare_dynamic(
    ctx: &mut Ctx,
    rep: &LabReported,
    one: &LabIdentification,
    two: &LabIdentification,
) -> Result<(), String> {
    let mpa = MPA;
    // Lowest rod-side pressure in compression: one orifice, 2 Hz, the largest peak velocity.
    let test = HarmonicTest::at_peak_velocity(2.0, rep.peak_velocity);
    let opts = hps_emulsion::SimOptions::default();
    let ext = HpsExtensions::none();
    let (_, m1) = run_harmonic(&one.params, &ext, &test, 3.0, &opts).map_err(|e| e.to_string())?;
    let why = "one-orifice lab strut, 2 Hz at 0.2356 m/s, 3 cycles, lowest P_hr of the last (by construction: the annulus was identified from this number with the quasi-steady Eq 5.12, so the dynamic simulation lands on it up to the dynamics left out of that law)";
    ctx.echo(
        Echo::ByConstruction,
        "p_rod_min_compression",
        None,
        None,
        m1.p_rod_min_pa / mpa,
        why,
    );
    ctx.echo(
        Echo::ByConstruction,
        "s5_min_rod_side_pressure",
        None,
        None,
        m1.p_rod_min_pa / mpa,
        why,
    );
    // Saturation pressures: identification inputs (the reference pressure of each strut).
    for (key, id) in [("one_orifice", one), ("two_orifices", two)] {
        ctx.echo(
            Echo::ByConstruction,
            "s5_saturation_pressures",
            Some(key),
            None,
            id.params.p_h0 / mpa,
            "the identification uses it as the mid-stroke reference pressure; predicting it needs the hours-long gas dissolution, outside Eqs 5.1-5.12",
        );
    }
    ctx.not_reproducible(
        "pressure_drop_after_emulsion",
        None,
        "gas dissolution into the oil over hours is outside Eqs 5.1-5.12 (not modelled)",
    );
    // Qualitative dynamic behaviour, the parts our baseline model can speak to.
    let t5 = HarmonicTest::at_peak_velocity(5.0, rep.peak_velocity);
    let (_, a) = run_harmonic(&one.params, &ext, &t5, 3.0, &opts).map_err(|e| e.to_string())?;
    let (_, b) = run_harmonic(&two.params, &ext, &t5, 3.0, &opts).map_err(|e| e.to_string())?;
    let both = a.peak_damping_extension_n > a.peak_damping_compression_n
        && b.peak_damping_extension_n > b.peak_damping_compression_n;
    ctx.qualitative(
        "s5_dynamic_qualitative",
        Some("both"),
        both,
        format!(
            "extension vs compression peak damping force at 5 Hz, 0.2356 m/s: one orifice {:.0} / {:.0} N, two {:.0} / {:.0} N (friction/stiction part not checked)",
            a.peak_damping_extension_n, a.peak_damping_compression_n,
            b.peak_damping_extension_n, b.peak_damping_compression_n
        ),
    );
    ctx.qualitative(
        "s5_dynamic_qualitative",
        Some("one_orifice"),
        a.peak_damping_extension_n > 1.5 * b.peak_damping_extension_n,
        format!(
            "one-orifice extension damping {:.0} N vs two orifices {:.0} N (> 1.5x required); P_hc hysteresis / phase error not checked",
            a.peak_damping_extension_n, b.peak_damping_extension_n
        ),
    );
    ctx.not_reproducible(
        "s5_dynamic_qualitative",
        Some("pseudo_static"),
        "pseudo-static loop hysteresis is attributed to gas heat transfer, which the baseline (adiabatic) model leaves out; a switchable HeatTransfer extension exists but has no identified time constant",
    );
    ctx.not_reproducible(
        "s5_dynamic_qualitative",
        Some("two_orifices"),
        "loop shapes are read from Figs 5.9-5.12, absent from the text",
    );
    ctx.not_reproducible(
        "s5_gamma0_trend",
        None,
        "gamma_0 versus peak velocity is identified from measured loops (Fig 5.4b, absent); the model takes gamma_0 as a parameter",
    );
    Ok(())
}
