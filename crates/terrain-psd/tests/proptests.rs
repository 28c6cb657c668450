//! Property tests: bad inputs (negative alpha, n_min >= n_max, NaN, ...) give errors, never
//! panics; valid inputs give finite profiles and spectra of the promised size.

use proptest::prelude::*;
use terrain_psd::*;

fn nasty() -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(f64::NAN),
        Just(f64::INFINITY),
        Just(f64::NEG_INFINITY),
        Just(0.0),
        Just(-0.0),
        -1e6..-1e-12f64,
    ]
}

fn spec_with(psd: PowerLawPsd, band: Band, coherence: CoherenceModel) -> TwoTrackSpec {
    // Struct literals bypass the constructors, so `synthesize` must validate again.
    TwoTrackSpec {
        psd,
        band,
        coherence,
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    #[test]
    fn bad_alpha_is_an_error(alpha in nasty(), w in 0.0..4.0f64) {
        prop_assert!(PowerLawPsd::new(alpha, w).is_err());
        prop_assert!(PowerLawPsd::from_gd_n0(alpha, w).is_err());
        let spec = spec_with(PowerLawPsd { alpha_r: alpha, waviness: w }, Band::PAPER, CoherenceModel::PAPER);
        prop_assert!(synthesize(&spec, 10.0, 0.05, 1).is_err());
    }

    #[test]
    fn bad_waviness_is_an_error(w in prop_oneof![Just(f64::NAN), Just(f64::INFINITY), -10.0..-1e-9f64, 10.0001..1e9f64]) {
        prop_assert!(PowerLawPsd::new(1e-5, w).is_err());
        let spec = spec_with(PowerLawPsd { alpha_r: 1e-5, waviness: w }, Band::PAPER, CoherenceModel::PAPER);
        prop_assert!(synthesize(&spec, 10.0, 0.05, 1).is_err());
    }

    #[test]
    fn inverted_or_nan_band_is_an_error(a in 0.001..10.0f64, d in 0.0..10.0f64, nan_side in 0..3u8) {
        // n_min >= n_max
        let (n_min, n_max) = match nan_side {
            0 => (a + d, a),
            1 => (f64::NAN, a),
            _ => (a, f64::NAN),
        };
        prop_assert!(Band::new(n_min, n_max).is_err());
        let spec = spec_with(PowerLawPsd::paper_nominal(), Band { n_min, n_max }, CoherenceModel::PAPER);
        prop_assert!(synthesize(&spec, 10.0, 0.05, 1).is_err());
        let text = format!("{},{}", n_min, n_max);
        prop_assert!(text.parse::<Band>().is_err());
    }

    #[test]
    fn bad_coherence_parameters_are_errors(v in nasty()) {
        prop_assert!(CoherenceModel::piecewise(v).is_err());
        prop_assert!(CoherenceModel::zhang(v).is_err());
        prop_assert!(CoherenceModel::bogsjo(0.2, v).is_err());
        if v.is_nan() || v.is_infinite() || v < 0.0 {
            prop_assert!(CoherenceModel::bogsjo(v, 1.0).is_err());
        }
        for c in [
            CoherenceModel::Piecewise { m_c: v },
            CoherenceModel::Zhang { speed_m_s: v },
            CoherenceModel::Bogsjo { rho: 0.1, half_track_m: v },
        ] {
            let spec = spec_with(PowerLawPsd::paper_nominal(), Band::PAPER, c);
            prop_assert!(synthesize(&spec, 10.0, 0.05, 1).is_err());
        }
    }

    #[test]
    fn bad_length_or_spacing_is_an_error(v in nasty()) {
        let spec = TwoTrackSpec::paper_nominal();
        prop_assert!(synthesize(&spec, v, 0.05, 1).is_err());
        prop_assert!(synthesize(&spec, 10.0, v, 1).is_err());
    }

    #[test]
    fn parsers_never_panic(s in ".{0,24}") {
        let _ = s.parse::<Band>();
        let _ = s.parse::<IsoClass>();
        let _ = s.parse::<OffRoadTerrain>();
        let _ = s.parse::<Window>();
        let _ = s.parse::<Detrend>();
        let _ = CoherenceModel::parse(&s, Some(1.0), Some(10.0));
        let _ = CoherenceModel::parse(&s, None, None);
    }

    #[test]
    fn valid_inputs_give_finite_profiles(
        log_alpha in -9.0..-2.0f64,
        w in 0.0..4.0f64,
        n_min in 0.05..1.0f64,
        width in 0.01..5.0f64,
        dx in 0.02..0.1f64,
        length in 0.5..60.0f64,
        m_c in 0.01..2.0f64,
        seed in any::<u64>(),
    ) {
        let band = Band::new(n_min, (n_min + width).min(0.5 / dx)).unwrap_or(Band { n_min, n_max: 0.5 / dx });
        let spec = TwoTrackSpec::new(
            PowerLawPsd::new(10f64.powf(log_alpha), w).unwrap(),
            band,
            CoherenceModel::piecewise(m_c).unwrap(),
        );
        if let Ok(spec) = spec {
            let p = synthesize(&spec, length, dx, seed).unwrap();
            prop_assert_eq!(p.len(), (length / dx).round() as usize + 1);
            prop_assert!(p.left_m.iter().chain(&p.right_m).all(|v| v.is_finite()));
        }
    }

    #[test]
    fn welch_never_panics(
        x in prop::collection::vec(-1e3..1e3f64, 0..300),
        seg in 0usize..400,
        overlap in prop_oneof![Just(f64::NAN), Just(1.0), -1.0..1.5f64],
        dx in prop_oneof![Just(0.0), Just(f64::NAN), 1e-3..1.0f64],
        linear in any::<bool>(),
    ) {
        let cfg = WelchConfig {
            segment_len: seg,
            overlap,
            window: Window::Hann,
            detrend: if linear { Detrend::Linear } else { Detrend::Mean },
        };
        if let Ok(s) = welch_psd(&x, dx, &cfg) {
            prop_assert_eq!(s.freq.len(), seg / 2 + 1);
            prop_assert!(s.psd.iter().all(|v| v.is_finite() && *v >= 0.0));
            prop_assert!(s.segments >= 1);
        }
        let y: Vec<f64> = x.iter().rev().copied().collect();
        if let Ok(c) = cross_spectrum(&x, &y, dx, &cfg) {
            prop_assert!(c.coherence.iter().all(|v| (0.0..=1.0).contains(v)));
        }
        let _ = cross_slope_psd(&x, &y, dx, 2.28, &cfg);
        let _ = WelchConfig::auto(x.len());
    }
}
