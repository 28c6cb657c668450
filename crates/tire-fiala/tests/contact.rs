//! Vertical contact and enveloping (issue: "Vertical contact with rough terrain").

use proptest::prelude::*;
use tire_fiala::{
    Envelope, EnvelopeMethod, LoadDeflectionTable, PolylineProfile, Profile, TireParams,
    VerticalContact,
};
use vehicle_components::{FlatTerrain, DEFAULT_FRICTION};

fn flat(z: f64) -> FlatTerrain {
    FlatTerrain::new(z, DEFAULT_FRICTION).unwrap()
}

const METHODS: [EnvelopeMethod; 2] = [EnvelopeMethod::CircleLine, EnvelopeMethod::TandemCams];

fn env(method: EnvelopeMethod) -> Envelope {
    Envelope::new(method, 1.0, 0.005).unwrap()
}

#[test]
fn flat_ground_gives_r_minus_wheel_height() {
    for m in METHODS {
        for ground in [0.0, 1.7, -3.2] {
            let flat = flat(ground);
            for z in [0.9, 0.95, 0.999, 0.8] {
                let c = env(m).contact(&flat, 12.345, ground + z);
                assert!((c.deflection - (1.0 - z)).abs() < 1e-9, "{m:?} {z} {c:?}");
                assert!((c.z_eff - ground).abs() < 1e-9);
                assert!(c.slope.abs() < 1e-9);
                assert!(c.in_contact);
                // Eq 2.2 as printed agrees on level ground.
                assert!((c.deflection_eq_2_2(ground + z, 1.0) - (1.0 - z)).abs() < 1e-9);
            }
        }
    }
}

#[test]
fn contact_length_follows_the_circle_geometry() {
    for m in METHODS {
        let mut prev = 0.0;
        for d in [0.01, 0.03, 0.06, 0.1, 0.15] {
            let c = env(m).contact(&flat(0.0), 0.0, 1.0 - d);
            let expect = 2.0 * (2.0 * d - d * d).sqrt();
            assert!((c.contact_length - expect).abs() < 1e-6, "{m:?} {d} {c:?}");
            assert!(c.contact_length > prev);
            prev = c.contact_length;
        }
    }
}

#[test]
fn wheel_above_ground_gives_exactly_zero_force() {
    let vc = VerticalContact::from_params(&TireParams::nominal()).unwrap();
    let bump = |x: f64| 0.1 * (-(x * x) / 0.02).exp();
    for m in METHODS {
        for (x, z) in [(0.0, 1.2), (0.5, 1.05), (-3.0, 1.0001)] {
            let c = env(m).contact(&bump, x, z);
            assert!(!c.in_contact, "{m:?} {c:?}");
            assert!(c.deflection <= 0.0);
            assert_eq!(vc.normal_force(c.deflection, -3.0), 0.0);
            assert_eq!(vc.normal_force(c.deflection, 3.0), 0.0);
        }
    }
    // Clearance is measured: 5 cm above flat ground.
    let c = env(EnvelopeMethod::TandemCams).contact(&flat(0.0), 0.0, 1.05);
    assert!((c.deflection + 0.05).abs() < 1e-9);
}

fn sweep(m: EnvelopeMethod, profile: &dyn Profile, deflection: f64) -> Vec<(f64, f64, f64)> {
    let e = env(m);
    (0..=300)
        .map(|i| {
            let x = -1.5 + 0.01 * i as f64;
            let p = e.at_deflection(profile, x, deflection).unwrap();
            (x, p.contact.z_eff, p.wheel_z)
        })
        .collect()
}

#[test]
fn cams_smooth_a_step() {
    let step = |x: f64| if x >= 0.0 { 0.1 } else { 0.0 };
    let s = sweep(EnvelopeMethod::TandemCams, &step, 0.08);
    // Starts at 0, ends at 0.1, never jumps by more than a small fraction of the step
    // between 1 cm wheel positions (the point contact jumps by the full 0.1 m).
    assert!(s[0].1.abs() < 1e-9 && (s[300].1 - 0.1).abs() < 1e-9);
    let max_jump = s
        .windows(2)
        .map(|w| (w[1].1 - w[0].1).abs())
        .fold(0.0, f64::max);
    assert!(max_jump < 0.012, "max jump {max_jump}");
    let wheel_jump = s
        .windows(2)
        .map(|w| (w[1].2 - w[0].2).abs())
        .fold(0.0, f64::max);
    assert!(wheel_jump < 0.012, "wheel jump {wheel_jump}");
    // Monotone rise.
    assert!(s.windows(2).all(|w| w[1].1 >= w[0].1 - 1e-9));
}

#[test]
fn short_bump_is_filtered_by_both_methods() {
    // 0.1 m high, 0.3 m long cosine bump: much shorter than the ~0.78 m contact length.
    let bump = |x: f64| {
        if x.abs() < 0.15 {
            0.05 * (1.0 + (std::f64::consts::PI * x / 0.15).cos())
        } else {
            0.0
        }
    };
    for m in METHODS {
        let s = sweep(m, &bump, 0.08);
        let peak = s.iter().map(|p| p.1).fold(f64::NEG_INFINITY, f64::max);
        assert!(
            peak < 0.08,
            "{m:?}: enveloped peak {peak} not below the 0.1 m bump"
        );
        assert!(peak > 0.0);
    }
    // Cams: smooth (no jumps larger than 1 cm per 1 cm of travel).
    let s = sweep(EnvelopeMethod::TandemCams, &bump, 0.08);
    let max_jump = s
        .windows(2)
        .map(|w| (w[1].1 - w[0].1).abs())
        .fold(0.0, f64::max);
    assert!(max_jump < 0.01, "{max_jump}");
}

#[test]
fn long_gentle_bump_is_smooth_for_the_circle_too() {
    // 0.05 m high, 4 m long: the intersection stays one connected patch.
    let bump = |x: f64| {
        if x.abs() < 2.0 {
            0.025 * (1.0 + (std::f64::consts::PI * x / 2.0).cos())
        } else {
            0.0
        }
    };
    for m in METHODS {
        let s = sweep(m, &bump, 0.08);
        let max_jump = s
            .windows(2)
            .map(|w| (w[1].1 - w[0].1).abs())
            .fold(0.0, f64::max);
        assert!(max_jump < 2e-3, "{m:?} {max_jump}");
        let peak = s.iter().map(|p| p.1).fold(f64::NEG_INFINITY, f64::max);
        assert!(peak <= 0.05 + 1e-9);
    }
}

#[test]
fn slope_of_an_inclined_plane_is_recovered() {
    let tilt: f64 = 0.1; // 5.7 deg
    let plane = move |x: f64| tilt * x;
    for m in METHODS {
        let p = env(m).at_deflection(&plane, 3.0, 0.06).unwrap();
        assert!((p.contact.slope - tilt.atan()).abs() < 1e-6, "{m:?} {p:?}");
        assert!((p.contact.deflection - 0.06).abs() < 1e-9);
    }
    // A wheel just touching an inclined plane has zero normal deflection (the printed
    // Eq 2.2 would give a spurious positive value).
    let th = tilt.atan();
    let zc = 1.0 / th.cos(); // centre height above the plane point under it, at x = 0
    let c = env(EnvelopeMethod::CircleLine).contact(&plane, 0.0, zc + 1e-6);
    assert!(c.deflection.abs() < 1e-4, "{c:?}");
}

#[test]
fn polyline_profile_with_load_table() {
    let p = PolylineProfile::new(vec![0.0, 10.0], vec![0.0, 0.0]).unwrap();
    let t = LoadDeflectionTable::default_29_5r29();
    let d = t.deflection_at(150e3);
    let c = env(EnvelopeMethod::TandemCams).contact(&p, 5.0, 1.0 - d);
    let vc = VerticalContact::new(t, 35e3).unwrap();
    assert!((vc.normal_force(c.deflection, 0.0) - 150e3).abs() < 1e-3);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// The contacts of one sampled window, asked at several heights in a row, are each the
    /// contact computed on its own: nothing of one height carries over to the next.
    #[test]
    fn one_window_serves_every_height_bit_for_bit(
        x in -50.0..50.0f64, heights in prop::collection::vec(0.6..1.3f64, 1..6),
        amp in 0.0..0.3f64, k in 0.5..20.0f64, cams in prop::bool::ANY,
    ) {
        let prof = move |x: f64| amp * (k * x).sin();
        let m = if cams { EnvelopeMethod::TandemCams } else { EnvelopeMethod::CircleLine };
        let e = env(m);
        let shared = e.contacts_at(&prof, x, |contact| {
            heights.iter().map(|&z| contact(z)).collect::<Vec<_>>()
        });
        for (&z, c) in heights.iter().zip(&shared) {
            prop_assert_eq!(*c, e.contact(&prof, x, z));
        }
    }

    /// A profile sampled once over a range serves every window inside it with the very
    /// contacts and cam bases a window sampled on its own gives, to the bit; a window
    /// reaching past the range, an envelope of another spacing, or no sampled profile at
    /// all, is sampled on its own.
    #[test]
    fn a_profile_sampled_once_gives_each_window_to_the_bit(
        xs in prop::collection::vec(-60.0..60.0f64, 1..8), z in 0.5..1.4f64,
        amp in 0.0..0.3f64, k in 0.5..20.0f64, cams in prop::bool::ANY,
    ) {
        let prof = move |x: f64| amp * (k * x).sin() + 0.02 * (3.1 * k * x + 1.0).sin();
        let m = if cams { EnvelopeMethod::TandemCams } else { EnvelopeMethod::CircleLine };
        let e = env(m);
        let sampled = e.sample(&prof, (-40.0, 40.0)).unwrap();
        let (lo, hi) = sampled.range();
        prop_assert!(lo <= -40.0 && hi >= 40.0 && hi - lo < 80.0 + 3.0 * e.sample_spacing());
        let other = Envelope::new(m, 1.0, 0.5 * e.sample_spacing()).unwrap();
        for &x in &xs {
            for e in [e, other] {
                let own = e.contacts_at(&prof, x, |contact| contact(z));
                let shared = e.contacts_in(Some(&sampled), &prof, x, |contact| contact(z));
                prop_assert_eq!(own, shared);
                prop_assert_eq!(
                    e.cam_base(&prof, x).to_bits(),
                    e.cam_base_in(Some(&sampled), &prof, x).to_bits()
                );
                prop_assert_eq!(own, e.contacts_in(None, &prof, x, |contact| contact(z)));
            }
        }
    }

    #[test]
    fn enveloping_is_finite_and_consistent(
        x in -50.0..50.0f64, z in -0.5..2.0f64, amp in 0.0..0.3f64, k in 0.5..20.0f64,
        cams in prop::bool::ANY,
    ) {
        let prof = move |x: f64| amp * (k * x).sin();
        let m = if cams { EnvelopeMethod::TandemCams } else { EnvelopeMethod::CircleLine };
        let c = env(m).contact(&prof, x, z);
        prop_assert!(c.deflection.is_finite() && c.z_eff.is_finite() && c.slope.is_finite());
        prop_assert!(c.contact_length >= 0.0 && c.contact_length <= 2.0 + 1e-9);
        prop_assert_eq!(c.in_contact, c.deflection > 0.0);
        // z_eff never exceeds the highest terrain under the wheel window.
        prop_assert!(c.z_eff <= amp + 1e-9);
    }
}
