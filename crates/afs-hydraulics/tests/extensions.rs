//! Each switchable extension does what its physics says.

use afs_hydraulics::{
    AfsExtensions, AfsInput, AfsParams, AfsSystem, CoulombFriction, EntrainedAir, SupplyDroop,
};

const DEG: f64 = std::f64::consts::PI / 180.0;

fn sys(ext: AfsExtensions) -> AfsSystem {
    AfsSystem::new(AfsParams::nominal())
        .unwrap()
        .with_extensions(ext)
        .unwrap()
}

#[test]
fn supply_droop_solves_the_implicit_supply_pressure() {
    let r = 9.0e8; // 30 bar at 200 L/min
    let base = sys(AfsExtensions::default());
    let droop = sys(AfsExtensions {
        supply_droop: Some(SupplyDroop {
            droop_pa_s_per_m3: r,
        }),
        ..Default::default()
    });
    let inp = AfsInput {
        theta: 0.0,
        theta_dot: 0.0,
        steer_wheel: 20.0 * DEG,
    };
    for pc in [1.0e5, 3.0e6, 9.0e6, 13.0e6] {
        let st = [pc, 1.0e6, 0.0];
        let mut d = [0.0; 3];
        let o0 = base.derivatives(&inp, &st, &mut d);
        let o1 = droop.derivatives(&inp, &st, &mut d);
        let ps = base.params().supply_pressure_pa;
        assert!((o1.supply_pressure - (ps - r * o1.q_supply)).abs() < 1e-6 * ps);
        assert!(o1.q_supply < o0.q_supply && o1.q_supply > 0.0);
        assert!(o1.supply_pressure > pc);
    }
    // left-hand turn: same droop on the mirrored feed
    let mut d = [0.0; 3];
    let o = droop.derivatives(
        &AfsInput {
            steer_wheel: -20.0 * DEG,
            ..inp
        },
        &[1.0e6, 2.0e6, 0.0],
        &mut d,
    );
    assert!(o.q_supply < 0.0);
    assert!((o.supply_pressure - (13.5e6 + r * o.q_supply)).abs() < 1e-6 * 13.5e6);
}

#[test]
fn coulomb_friction_opposes_strut_motion() {
    let fc = 4000.0;
    let base = sys(AfsExtensions::default());
    let fric = sys(AfsExtensions {
        coulomb_friction: Some(CoulombFriction {
            force_n: fc,
            velocity_scale_m_s: 1e-3,
        }),
        ..Default::default()
    });
    let st = [2.0e6, 2.0e6, 0.0];
    let mut d = [0.0; 3];
    for thd in [0.3, -0.3] {
        let inp = AfsInput {
            theta: 0.0,
            theta_dot: thd,
            steer_wheel: 0.0,
        };
        let t0 = base.derivatives(&inp, &st, &mut d).torque;
        let o = fric.derivatives(&inp, &st, &mut d);
        let k = fric.kinematics(0.0);
        // full Coulomb level at |v| >> v_s, resisting the articulation on both struts
        let expect = -thd.signum() * fc * (k.arm_left + k.arm_right);
        assert!((o.torque - t0 - expect).abs() < 1e-6 * fc);
        assert!(o.torque * thd < t0 * thd);
    }
    // smooth through zero velocity
    let inp = AfsInput {
        theta: 0.0,
        theta_dot: 0.0,
        steer_wheel: 0.0,
    };
    assert_eq!(
        fric.derivatives(&inp, &st, &mut d).torque,
        base.derivatives(&inp, &st, &mut d).torque
    );
}

#[test]
fn entrained_air_softens_the_circuit_at_low_pressure() {
    let air = sys(AfsExtensions {
        entrained_air: Some(EntrainedAir {
            air_fraction_atm: 0.01,
            polytropic_index: 1.0,
            atmospheric_pressure_pa: 101_325.0,
        }),
        ..Default::default()
    });
    let b_oil = air.params().bulk_modulus_pa;
    let b_low = air.bulk_modulus(1.0e6);
    let b_high = air.bulk_modulus(1.3e7);
    // hand value at 10 bar, isothermal: x = 0.01/0.99 · 0.101325 = 1.0235e-3,
    // 1/B = (1/1.6e9 + x/1e6)/(1 + x)
    let x = 0.01 / 0.99 * 0.101_325;
    let hand = (1.0 + x) / (1.0 / 1.6e9 + x / 1.0e6);
    assert!((b_low / hand - 1.0).abs() < 1e-12);
    assert!(b_low < 0.5 * b_oil && b_low < b_high && b_high < b_oil);
    let base = sys(AfsExtensions::default());
    let st = [1.0e6, 1.0e6, 0.0];
    assert!(air.hydraulic_stiffness(0.0, &st) < 0.5 * base.hydraulic_stiffness(0.0, &st));
}

#[test]
fn constant_leakage_ignores_strut_speed() {
    let c = sys(AfsExtensions {
        constant_leakage_only: true,
        ..Default::default()
    });
    let base = sys(AfsExtensions::default());
    let st = [8.0e6, 2.0e6, 0.0];
    let mut d = [0.0; 3];
    let p = c.params();
    for thd in [0.0, 0.5] {
        let inp = AfsInput {
            theta: 0.1,
            theta_dot: thd,
            steer_wheel: 0.0,
        };
        let q = c.derivatives(&inp, &st, &mut d).q_leak;
        assert!((q - 2.0 * p.leak_const * 6.0e6).abs() < 1e-20);
        let qb = base.derivatives(&inp, &st, &mut d).q_leak;
        if thd == 0.0 {
            assert_eq!(q, qb);
        } else {
            // Eq 3.6: k_lL + k_lR = 2 k_l0 + k_l (h_L + h_R)|dtheta|
            let k = base.kinematics(0.1);
            let expect =
                (2.0 * p.leak_const + p.leak_velocity * (k.arm_left + k.arm_right) * thd) * 6.0e6;
            assert!((qb - expect).abs() < 1e-12 * expect);
        }
    }
}

#[test]
fn valve_lag_meters_the_flow_by_the_lagged_spool() {
    use afs_hydraulics::ValveLag;
    let tau = 0.04;
    let lag = sys(AfsExtensions {
        valve_lag: Some(ValveLag { tau_s: tau }),
        ..Default::default()
    });
    let base = sys(AfsExtensions::default());
    assert_eq!(lag.n_states(), 4);
    assert_eq!(base.n_states(), 3);
    let inp = AfsInput {
        theta: 0.0,
        theta_dot: 0.0,
        steer_wheel: 10.0 * DEG,
    };
    // Spool still centred: no flow yet, and the spool moves towards X at (X - x_v)/tau.
    let mut d = [0.0; 4];
    let o = lag.derivatives(&inp, &[2.0e6, 2.0e6, 0.0, 0.0], &mut d);
    assert_eq!(o.q_supply, 0.0);
    assert!((d[3] - 10.0 * DEG / tau).abs() < 1e-12);
    // Spool at the commanded opening: the same flows and pressure rates as without the lag.
    let o_lag = lag.derivatives(&inp, &[2.0e6, 2.0e6, 0.0, 10.0 * DEG], &mut d);
    assert!(d[3].abs() < 1e-12);
    let mut d0 = [0.0; 3];
    let o_base = base.derivatives(&inp, &[2.0e6, 2.0e6, 0.0], &mut d0);
    assert!((o_lag.q_supply - o_base.q_supply).abs() < 1e-12 * o_base.q_supply.abs());
    assert!((d[0] - d0[0]).abs() <= 1e-9 * d0[0].abs());
    // A non-positive time constant is refused with the field named.
    let err = AfsSystem::new(AfsParams::nominal())
        .unwrap()
        .with_extensions(AfsExtensions {
            valve_lag: Some(ValveLag { tau_s: 0.0 }),
            ..Default::default()
        })
        .unwrap_err();
    assert!(err.to_string().contains("valve_lag.tau_s"), "{err}");
}
