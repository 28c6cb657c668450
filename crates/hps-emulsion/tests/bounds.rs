//! Inputs that would allocate without bound or be silently accepted are errors naming the
//! field.

use hps_emulsion::*;

#[test]
fn harmonic_sample_count_is_bounded() {
    let p = StrutParams::front_axle();
    for (cycles, rate, freq) in [
        (1e308, 360.0, 2.0),
        (5.0, 2f64.powi(64), 2.0),
        (5.0, 360.0, 1e-320),
        (9_999_999_999.0, 360.0, 2.0),
    ] {
        let e = simulate_displacement(
            &p,
            &HpsExtensions::none(),
            &Excitation::harmonic(freq, 0.0075, cycles),
            &SimOptions {
                output_rate_hz: rate,
                ..SimOptions::default()
            },
        )
        .unwrap_err();
        let msg = e.to_string();
        assert!(
            msg.contains("output samples") && msg.contains("cycles"),
            "{msg}"
        );
    }
}

#[test]
fn negative_warmup_is_refused() {
    let p = StrutParams::lab(LabConfig::OneOrifice);
    let rec = simulate_displacement(
        &p,
        &HpsExtensions::none(),
        &Excitation::harmonic(2.0, 0.01, 2.0),
        &SimOptions::default(),
    )
    .unwrap();
    let meas = Measured {
        time: rec.time.clone(),
        displacement: rec.displacement.clone(),
        velocity: None,
        force: Some(rec.force.clone()),
        p_piston: None,
        p_rod: None,
    };
    for w in [-1.0, f64::NAN] {
        let opts = IdentifyOptions {
            warmup_s: w,
            ..IdentifyOptions::default()
        };
        let e = identify(
            &meas,
            &p,
            &HpsExtensions::none(),
            &[FitParam::Gamma0],
            &opts,
        )
        .unwrap_err();
        assert!(e.to_string().contains("warmup_s"), "{e}");
    }
}
