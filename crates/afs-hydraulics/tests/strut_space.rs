//! Tests of the strut-space core (Eqs 6.6-6.8): a hand-computed case, the planar adapter,
//! mirror symmetry of the two struts, and energy conservation of the closed circuit driven
//! through arbitrary (non-planar) strut motions.

use afs_hydraulics::{
    AfsExtensions, AfsInput, AfsParams, AfsSystem, CoulombFriction, StrutInput, ValveLag,
};
use proptest::prelude::*;
use vehicle_components::{Component, StateLayout};

const DEG: f64 = std::f64::consts::PI / 180.0;

fn nominal() -> AfsSystem {
    AfsSystem::new(AfsParams::nominal()).unwrap()
}

/// A closed, lossless circuit: no leakage and no seal friction.
fn lossless() -> AfsSystem {
    let mut p = AfsParams::nominal();
    p.leak_const = 0.0;
    p.leak_velocity = 0.0;
    p.seal_viscous_n_s_m = 0.0;
    AfsSystem::new(p).unwrap()
}

#[test]
fn forces_at_rest_are_the_pressure_areas() {
    let sys = nominal();
    let p = sys.params().clone();
    let (pc, pr) = (8.0e6, 3.0e6);
    let mut d = [0.0; 3];
    let out = sys.strut_derivatives(&StrutInput::default(), &[pc, pr, 0.0], &mut d);
    let f_l = p.piston_area_m2 * pc - p.annulus_area_m2 * pr;
    let f_r = p.piston_area_m2 * pr - p.annulus_area_m2 * pc;
    assert!((out.force_left - f_l).abs() <= 1e-9 * f_l.abs());
    assert!((out.force_right - f_r).abs() <= 1e-9 * f_r.abs());
    // no motion, valve centred: only the constant leakage moves the pressures
    let q_leak = 2.0 * p.leak_const * (pc - pr);
    assert!((out.q_leak - q_leak).abs() <= 1e-12 * q_leak.abs());
    let (v1, v2) = sys.strut_volumes(0.0, 0.0);
    assert_eq!((v1, v2), (p.dead_volume_m3, p.dead_volume_m3));
    let b = p.bulk_modulus_pa;
    assert!((d[0] - b / v1 * (-q_leak)).abs() <= 1e-9 * (b / v1 * q_leak).abs());
    assert!((d[1] - b / v2 * q_leak).abs() <= 1e-9 * (b / v2 * q_leak).abs());
    assert_eq!(d[2], 0.0);
}

#[test]
fn volumes_follow_eq_6_7_with_extensions() {
    let sys = nominal();
    let p = sys.params().clone();
    let (dl, dr) = (0.05, -0.03);
    let (v1, v2) = sys.strut_volumes(dl, dr);
    // Eq 6.7 with the paper's d_R (shortening) = -dr
    let (ac, ar, v0) = (p.piston_area_m2, p.annulus_area_m2, p.dead_volume_m3);
    assert!((v1 - (v0 + ac * dl + ar * (-dr))).abs() < 1e-15);
    assert!((v2 - (v0 - ar * dl - ac * (-dr))).abs() < 1e-15);
}

fn with_friction_and_lag() -> AfsSystem {
    nominal()
        .with_extensions(AfsExtensions {
            coulomb_friction: Some(CoulombFriction {
                force_n: 2500.0,
                velocity_scale_m_s: 2e-3,
            }),
            valve_lag: Some(ValveLag { tau_s: 0.03 }),
            ..AfsExtensions::default()
        })
        .unwrap()
}

proptest! {
    /// The planar evaluate is the strut-space core at ḋ_L = h_L θ̇, ḋ_R = -h_R θ̇, and its
    /// torque is the virtual-work torque: T_s θ̇ = F_L ḋ_L + F_R ḋ_R.
    #[test]
    fn planar_adapter_is_the_strut_core(
        theta in -40.0f64..40.0, theta_dot in -30.0f64..30.0, sw in -20.0f64..20.0,
        pc in 1.0e6f64..1.3e7, pr in 1.0e6f64..1.3e7, th in -15.0f64..15.0, xv in -10.0f64..10.0,
    ) {
        let sys = with_friction_and_lag();
        let (theta, theta_dot) = (theta * DEG, theta_dot * DEG);
        let state = [pc, pr, th * DEG, xv * DEG];
        let mut d_planar = [0.0; 4];
        let planar = sys.derivatives(
            &AfsInput { theta, theta_dot, steer_wheel: sw * DEG }, &state, &mut d_planar);
        let k = sys.kinematics(theta);
        let mut d_strut = [0.0; 4];
        let strut = sys.strut_derivatives(
            &StrutInput {
                disp_left: k.disp_left,
                disp_right: k.disp_right,
                vel_left: k.arm_left * theta_dot,
                vel_right: -k.arm_right * theta_dot,
                steer_wheel: sw * DEG,
            },
            &state,
            &mut d_strut,
        );
        prop_assert_eq!(d_planar, d_strut);
        prop_assert_eq!(planar.force_left, strut.force_left);
        prop_assert_eq!(planar.force_right, strut.force_right);
        let scale = planar.torque.abs().max(1.0) * theta_dot.abs().max(1e-3);
        prop_assert!((planar.strut_power - strut.strut_power).abs() <= 1e-9 * scale,
            "T θ̇ = {} vs Σ F ḋ = {}", planar.strut_power, strut.strut_power);
    }

    /// Swapping the struts, the chamber groups and the steering direction mirrors every
    /// output: F_L <-> F_R, dP_c <-> dP_r, dθ_h -> -dθ_h, q_1 -> -q_1.
    #[test]
    fn mirror_symmetry_of_the_two_struts(
        dl in -0.2f64..0.2, dr in -0.2f64..0.2, vl in -0.5f64..0.5, vr in -0.5f64..0.5,
        sw in -20.0f64..20.0, pc in 1.0e6f64..1.3e7, pr in 1.0e6f64..1.3e7,
        th in -15.0f64..15.0, xv in -10.0f64..10.0,
    ) {
        let sys = with_friction_and_lag();
        let input = StrutInput {
            disp_left: dl, disp_right: dr, vel_left: vl, vel_right: vr, steer_wheel: sw * DEG,
        };
        let mirrored = StrutInput {
            disp_left: dr, disp_right: dl, vel_left: vr, vel_right: vl, steer_wheel: -sw * DEG,
        };
        let (mut d, mut dm) = ([0.0; 4], [0.0; 4]);
        let a = sys.strut_derivatives(&input, &[pc, pr, th * DEG, xv * DEG], &mut d);
        let b = sys.strut_derivatives(&mirrored, &[pr, pc, -th * DEG, -xv * DEG], &mut dm);
        let close = |x: f64, y: f64| (x - y).abs() <= 1e-9 * x.abs().max(y.abs()).max(1e-12);
        prop_assert!(close(a.force_left, b.force_right));
        prop_assert!(close(a.force_right, b.force_left));
        prop_assert!(close(d[0], dm[1]) && close(d[1], dm[0]));
        prop_assert!(close(d[2], -dm[2]) && close(d[3], -dm[3]));
        prop_assert!(close(a.q_supply, -b.q_supply));
        prop_assert!(close(a.strut_power, b.strut_power));
    }

    /// With the valve closed and no losses the circuit is a pair of oil springs: along any
    /// strut motion, not only the planar one, dE/dt = -(F_L ḋ_L + F_R ḋ_R).
    #[test]
    fn closed_circuit_conserves_energy_in_strut_space(
        dl in -0.2f64..0.2, dr in -0.2f64..0.2, vl in -0.5f64..0.5, vr in -0.5f64..0.5,
        pc in 2.0e6f64..1.2e7, pr in 2.0e6f64..1.2e7,
    ) {
        let sys = lossless();
        let state = [pc, pr, 0.0];
        let input = StrutInput {
            disp_left: dl, disp_right: dr, vel_left: vl, vel_right: vr, steer_wheel: 0.0,
        };
        let mut d = [0.0; 3];
        let out = sys.strut_derivatives(&input, &state, &mut d);
        prop_assert_eq!(out.valve_opening, 0.0);
        // central difference of E along the trajectory
        let h = 1e-6;
        let at = |s: f64| {
            let y = [pc + s * d[0], pr + s * d[1], 0.0];
            sys.strut_hydraulic_energy(dl + s * vl, dr + s * vr, &y)
        };
        let de_dt = (at(h) - at(-h)) / (2.0 * h);
        let power = out.force_left * vl + out.force_right * vr;
        prop_assert!((de_dt + power).abs() <= 1e-5 * power.abs().max(1.0),
            "dE/dt = {de_dt}, -ΣFḋ = {}", -power);
    }
}

#[test]
fn the_strut_core_is_a_component_of_the_layer() {
    let sys = with_friction_and_lag();
    let infos = Component::states(&sys);
    assert_eq!(infos.len(), 4);
    let names: Vec<&str> = infos.iter().map(|s| s.name).collect();
    assert_eq!(
        names,
        ["p_c_pa", "p_r_pa", "theta_h_rad", "valve_spool_rad"]
    );
    assert_eq!(Component::states(&nominal()).len(), 3);
    let mut layout = StateLayout::new();
    let block = layout.add("afs", infos).unwrap();
    assert_eq!(layout.range(block), 0..4);
    let mut y = [0.0; 4];
    Component::initial_state(&sys, &StrutInput::default(), &mut y);
    let ps = sys.params().standby_pressure_pa;
    assert_eq!(y, [ps, ps, 0.0, 0.0]);
    // evaluate is the strut core; record writes its channels
    let input = StrutInput {
        disp_left: 0.02,
        disp_right: -0.01,
        vel_left: 0.1,
        vel_right: -0.05,
        steer_wheel: 0.3,
    };
    let (mut d1, mut d2) = ([0.0; 4], [0.0; 4]);
    let a = Component::evaluate(&sys, &input, &y, &mut d1);
    let b = sys.strut_derivatives(&input, &y, &mut d2);
    assert_eq!((a, d1), (b, d2));
    let mut row = vec![0.0; sys.channels().len()];
    sys.record(&a, &mut row);
    assert_eq!(row[0], a.force_left);
    assert_eq!(row[9], a.strut_power);
    assert!(row.iter().all(|v| v.is_finite()));
}
