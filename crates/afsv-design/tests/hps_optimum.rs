//! The Eq 6.19 GA on its smallest budget: the nominal design seeds the population, so with
//! elitism the optimum is never worse than F = 2; (determinism and resumption of the GA itself: `optimize`'s tests).

use afsv_design::{optimise_hps, HpsGaSettings};
use vehicle_3d::VehicleParams;

#[test]
fn ga_improves_on_the_nominal_design() {
    let p = VehicleParams::nominal();
    let settings = HpsGaSettings {
        population: 4,
        generations: 1,
        reevaluation_seeds: 1,
        reevaluate_roll: false,
        ..HpsGaSettings::default()
    };
    let a = optimise_hps(&p, &settings, &optimize::Silent).unwrap();
    // F of the nominal design is 2 by definition (Eq 6.19 normalises by it)
    assert!(a.objective <= 2.0 + 1e-12, "{}", a.objective);
    assert!(a.feasible);
    assert_eq!(a.evaluations, 4 * 2 + 2);
    for (x, (lo, hi)) in [a.design.a_hc, a.design.a_v, a.design.a_b]
        .into_iter()
        .zip(settings.lower.into_iter().zip(settings.upper))
    {
        assert!((lo..=hi).contains(&x), "{x} outside [{lo}, {hi}]");
    }
    let f = a.optimum_ride.a_wz_m_s2 / a.nominal_ride.a_wz_m_s2
        + a.optimum_ride.d_s_m / a.nominal_ride.d_s_m;
    assert!((f - a.objective).abs() < 1e-12);
    assert!(a.optimum_over_seeds.omega_z_hz > 1.0);
    assert!(a.optimum_over_seeds.sp_drt_m_s2.mean.is_nan());
}
