//! The tire assembly against the single pieces it composes, on flat ground, on a step and
//! under mirror symmetry.

use proptest::prelude::*;
use tire_fiala::{
    regularised_speed, Envelope, EnvelopeMethod, Fiala, HandlingModel, Relaxation, TireAssembly,
    TireParams, Track, VerticalContact, WheelInput,
};
use vehicle_components::{Component, FlatTerrain, Terrain, DEFAULT_FRICTION};

const METHODS: [EnvelopeMethod; 2] = [EnvelopeMethod::CircleLine, EnvelopeMethod::TandemCams];
const SPACING: f64 = 0.005;

fn flat() -> FlatTerrain {
    FlatTerrain::new(0.0, DEFAULT_FRICTION).unwrap()
}

fn assembly<T: Terrain>(m: EnvelopeMethod, terrain: T) -> TireAssembly<T> {
    TireAssembly::new(&TireParams::nominal(), m, SPACING, terrain).unwrap()
}

fn rolling(x: f64, y: f64, z: f64, v: [f64; 3], heading: f64, spin: f64) -> WheelInput {
    WheelInput {
        position: [x, y, z],
        velocity: v,
        heading,
        spin,
    }
}

/// A 0.1 m step at x = 0, the same across y, friction 0.8.
struct Step;

impl Terrain for Step {
    fn height(&self, x: f64, _y: f64) -> f64 {
        if x >= 0.0 {
            0.1
        } else {
            0.0
        }
    }
    fn friction(&self, _x: f64, _y: f64) -> f64 {
        DEFAULT_FRICTION
    }
}

#[test]
fn on_flat_ground_it_reduces_to_the_single_pieces() {
    let p = TireParams::nominal();
    let vertical = VerticalContact::from_params(&p).unwrap();
    let fiala = Fiala::new(&p).unwrap();
    let relax = Relaxation::from_params(&p).unwrap();
    for m in METHODS {
        let tire = assembly(m, flat());
        let env = Envelope::new(m, p.unloaded_radius_m, SPACING).unwrap();
        let input = rolling(12.3, -0.7, 0.93, [8.0, 0.4, -0.05], 0.0, 8.5);
        let state = [0.02, -0.01];
        let mut d = [0.0; 2];
        let out = tire.evaluate(&input, &state, &mut d);
        // The pieces by hand.
        let c = env.contact(
            &Track {
                terrain: flat(),
                y: -0.7,
            },
            12.3,
            0.93,
        );
        assert_eq!(out.contact, c);
        let fz = vertical.normal_force(c.deflection, 0.05);
        assert_eq!(out.normal_force, fz);
        let speed = regularised_speed(8.0);
        let steady = [
            (8.5 * (1.0 - c.deflection) - 8.0) / speed,
            -(0.4 / speed).atan(),
        ];
        assert_eq!([out.slip_ratio_steady, out.slip_angle_steady], steady);
        assert_eq!(d, relax.rates(state, steady, 8.0));
        let f = fiala.forces(fz, 0.02, -0.01);
        assert_eq!(out.wheel_forces, f);
        assert_eq!(out.force, [f.fx, f.fy, fz]);
        assert_eq!(out.point[..2], [12.3, -0.7]);
        assert!(out.point[2].abs() < 1e-12, "{:?}", out.point);
        assert!(fz > 0.0 && f.fy < 0.0 && f.fx > 0.0, "{out:?}");
        // Initial state: the steady slips, at rest.
        let mut s0 = [0.0; 2];
        tire.initial_state(&input, &mut s0);
        assert_eq!(s0, steady);
        tire.evaluate(&input, &s0, &mut d);
        assert_eq!(d, [0.0, 0.0]);
    }
}

#[test]
fn heading_rotates_the_wheel_axes_on_flat_ground() {
    let tire = assembly(EnvelopeMethod::TandemCams, flat());
    let state = [0.01, 0.03];
    let mut d0 = [0.0; 2];
    let straight = tire.evaluate(
        &rolling(5.0, 1.0, 0.92, [6.0, -0.3, 0.0], 0.0, 6.2),
        &state,
        &mut d0,
    );
    let psi: f64 = 0.7;
    let (s, c) = psi.sin_cos();
    let v = [6.0 * c + 0.3 * s, 6.0 * s - 0.3 * c, 0.0];
    let mut d1 = [0.0; 2];
    let turned = tire.evaluate(&rolling(-3.0, 8.0, 0.92, v, psi, 6.2), &state, &mut d1);
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-9 * (1.0 + a.abs().max(b.abs()));
    assert!(close(turned.normal_force, straight.normal_force));
    assert!(close(turned.wheel_forces.fx, straight.wheel_forces.fx));
    assert!(close(turned.wheel_forces.fy, straight.wheel_forces.fy));
    assert!(close(d1[0], d0[0]) && close(d1[1], d0[1]));
    // The terrain-frame force is the wheel-frame one rotated by psi.
    let (fx, fy) = (straight.force[0], straight.force[1]);
    assert!(close(turned.force[0], fx * c - fy * s));
    assert!(close(turned.force[1], fx * s + fy * c));
}

#[test]
fn on_a_step_it_envelopes_like_the_enveloping_alone() {
    // As in the enveloping tests: the wheel held at 0.08 m deflection over a 0.1 m step.
    let vertical = VerticalContact::from_params(&TireParams::nominal()).unwrap();
    for m in METHODS {
        let tire = assembly(m, Step);
        let env = Envelope::new(m, 1.0, SPACING).unwrap();
        let track = Track {
            terrain: Step,
            y: 0.4,
        };
        let mut d = [0.0; 2];
        let mut z_eff = Vec::new();
        for i in 0..=300 {
            let x = -1.5 + 0.01 * i as f64;
            let wheel_z = env.at_deflection(&track, x, 0.08).unwrap().wheel_z;
            let input = rolling(x, 0.4, wheel_z, [3.0, 0.0, 0.0], 0.0, 3.0);
            let out = tire.evaluate(&input, &[0.0, 0.0], &mut d);
            assert_eq!(out.contact, env.contact(&track, x, wheel_z), "{m:?} at {x}");
            // The circle's deflection jumps where its intersection with the step edge
            // appears, so only the cams hold 0.08 m everywhere.
            if m == EnvelopeMethod::TandemCams {
                assert!((out.contact.deflection - 0.08).abs() < 1e-9, "at {x}");
            }
            let fz = vertical.normal_force(out.contact.deflection, out.deflection_rate);
            assert_eq!(out.normal_force, fz);
            z_eff.push(out.contact.z_eff);
        }
        assert!(
            z_eff[0].abs() < 1e-9 && (z_eff[300] - 0.1).abs() < 1e-9,
            "{m:?}"
        );
        if m == EnvelopeMethod::TandemCams {
            // Smooth and monotone (the point contact would jump by the full 0.1 m).
            let max_jump = z_eff
                .windows(2)
                .map(|w| (w[1] - w[0]).abs())
                .fold(0.0, f64::max);
            assert!(max_jump < 0.012, "max jump {max_jump}");
            assert!(z_eff.windows(2).all(|w| w[1] >= w[0] - 1e-9));
        }
    }
}

#[test]
fn lift_off_gives_no_force_and_a_finite_lag() {
    let tire = assembly(EnvelopeMethod::CircleLine, flat());
    let mut d = [0.0; 2];
    let out = tire.evaluate(
        &rolling(0.0, 0.0, 1.3, [0.0, 0.0, 2.0], 0.0, 0.0),
        &[0.1, 0.2],
        &mut d,
    );
    assert_eq!(out.force, [0.0, 0.0, 0.0]);
    assert_eq!(out.normal_force, 0.0);
    assert!(d.iter().all(|v| v.is_finite()));
    let mut row = [f64::NAN; 8];
    tire.record(&out, &mut row);
    assert!(row.iter().all(|v| v.is_finite()));
    assert_eq!(tire.channels().len(), row.len());
    assert_eq!(tire.n_states(), 2);
}

#[test]
fn terrain_friction_sets_the_peak_friction() {
    let slick = FlatTerrain::new(0.0, 0.4).unwrap();
    let dry = assembly(EnvelopeMethod::CircleLine, flat());
    let wet = assembly(EnvelopeMethod::CircleLine, slick);
    let input = rolling(0.0, 0.0, 0.9, [5.0, 0.0, 0.0], 0.0, 5.0);
    let mut d = [0.0; 2];
    // Full sliding at 60 deg: F_y = U_min-equivalent times F_z, halved by mu 0.4 / 0.8.
    let a = [0.0, 60f64.to_radians()];
    let fd = dry.evaluate(&input, &a, &mut d);
    let fw = wet.evaluate(&input, &a, &mut d);
    assert_eq!(fw.friction, 0.4);
    assert!(
        (fw.wheel_forces.fy - 0.5 * fd.wheel_forces.fy).abs() < 1e-6 * fd.wheel_forces.fy.abs()
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn mirrored_slip_gives_mirrored_lateral_force(
        vx in 0.5..20.0f64, vy in -3.0..3.0f64, vz in -0.5..0.5f64, z in 0.85..1.0f64,
        kappa in -0.3..0.3f64, alpha in -0.4..0.4f64, spin in 0.0..25.0f64,
        cams in prop::bool::ANY,
    ) {
        let m = if cams { EnvelopeMethod::TandemCams } else { EnvelopeMethod::CircleLine };
        let tire = assembly(m, flat());
        let mut d = [0.0; 2];
        let mut dm = [0.0; 2];
        let out = tire.evaluate(&rolling(1.0, 0.0, z, [vx, vy, vz], 0.0, spin), &[kappa, alpha], &mut d);
        let mir = tire.evaluate(&rolling(1.0, 0.0, z, [vx, -vy, vz], 0.0, spin), &[kappa, -alpha], &mut dm);
        prop_assert_eq!(mir.wheel_forces.fy, -out.wheel_forces.fy);
        prop_assert_eq!(mir.wheel_forces.mz, -out.wheel_forces.mz);
        prop_assert_eq!(mir.wheel_forces.fx, out.wheel_forces.fx);
        prop_assert_eq!(mir.force[1], -out.force[1]);
        prop_assert_eq!(mir.force[2], out.force[2]);
        prop_assert_eq!(mir.slip_angle_steady, -out.slip_angle_steady);
        prop_assert_eq!(dm, [d[0], -d[1]]);
        prop_assert!(out.force.iter().all(|f| f.is_finite()));
    }
}
