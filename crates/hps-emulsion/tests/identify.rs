//! Identification from a synthesized noisy record recovers the parameters within their
//! standard errors.

use hps_emulsion::*;
use rand_chacha::rand_core::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

fn gauss(rng: &mut ChaCha8Rng) -> f64 {
    let u1 = ((rng.next_u64() >> 11) as f64 + 0.5) / (1u64 << 53) as f64;
    let u2 = ((rng.next_u64() >> 11) as f64) / (1u64 << 53) as f64;
    (-2.0 * u1.ln()).sqrt() * (2.0 * std::f64::consts::PI * u2).cos()
}

#[test]
fn recovers_synthesized_parameters_within_standard_errors() {
    let truth = StrutParams::lab(LabConfig::OneOrifice)
        .with_gamma0(0.05)
        .unwrap();
    let mut truth = truth;
    truth.c_b = 0.72;
    truth.n = 1.35;
    let exc = Excitation::harmonic(2.0, 0.0187, 2.0);
    let rec = simulate_displacement(
        &truth,
        &HpsExtensions::none(),
        &exc,
        &SimOptions {
            rtol: 1e-9,
            atol: 1e-12,
            ..Default::default()
        },
    )
    .unwrap();
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    let mut noisy = |v: &[f64], sd: f64| {
        v.iter()
            .map(|x| x + sd * gauss(&mut rng))
            .collect::<Vec<f64>>()
    };
    let meas = Measured {
        time: rec.time.clone(),
        displacement: rec.displacement.clone(),
        velocity: Some(rec.velocity.clone()),
        force: Some(noisy(&rec.force, 20.0)),
        p_piston: Some(noisy(&rec.p_piston, 5e3)),
        p_rod: Some(noisy(&rec.p_rod, 5e3)),
    };
    let start = StrutParams::lab(LabConfig::OneOrifice)
        .with_gamma0(0.02)
        .unwrap();
    let which = FitParam::parse_list("n,gamma0,cb").unwrap();
    let res = identify(
        &meas,
        &start,
        &HpsExtensions::none(),
        &which,
        &IdentifyOptions::default(),
    )
    .unwrap();
    let want = [truth.n, truth.gamma0, truth.c_b];
    for (fv, w) in res.fitted.iter().zip(want) {
        assert!(fv.std_error.is_finite() && fv.std_error > 0.0, "{fv:?}");
        assert!(
            (fv.value - w).abs() < 3.0 * fv.std_error,
            "{:?}: {} vs truth {} (se {})",
            fv.param,
            fv.value,
            w,
            fv.std_error
        );
    }
    eprintln!("{res:?}");
    assert!(res.nrmse.force.unwrap() < res.nrmse_initial.force.unwrap());
    assert!(res.nrmse.p_rod.unwrap() < 0.01);
}

#[test]
fn identification_rejects_bad_requests() {
    assert!(FitParam::parse_list("n,zz").is_err());
    assert!(FitParam::parse_list("n,n").is_err());
    assert_eq!(FitParam::parse("Mu_V").unwrap(), FitParam::MuV);
    let meas = Measured {
        time: vec![0.0, 0.1, 0.2],
        displacement: vec![0.0; 3],
        ..Default::default()
    };
    let p = StrutParams::lab(LabConfig::TwoOrifices);
    assert!(matches!(
        identify(
            &meas,
            &p,
            &HpsExtensions::none(),
            &[FitParam::N],
            &IdentifyOptions::default()
        ),
        Err(HpsError::Identification(_))
    ));
}
