//! Torque-free rigid body on a floating base: conservation of kinetic energy and of the
//! world spatial momentum, and the analytic body-frame precession of an axisymmetric body.
#[path = "support/rk4.rs"]
mod rk4;

use multibody::{
    forward_dynamics, kinetic_energy, spatial_momentum, update_kinematics, Body, Joint, Model,
    ModelBuilder, Workspace,
};
use nalgebra::{Isometry3, Matrix3, Rotation3, UnitQuaternion, Vector3};
use rk4::rk4_step;

fn free_body(mass: f64, com: Vector3<f64>, inertia: Matrix3<f64>) -> Model {
    let mut b = ModelBuilder::new(Vector3::zeros());
    b.add_body(Body {
        name: "body".into(),
        parent: None,
        joint: Joint::Floating,
        placement: Isometry3::identity(),
        mass,
        com,
        inertia,
    });
    b.build().expect("valid body")
}

fn accel(model: &Model) -> impl FnMut(&mut Workspace, &[f64], &[f64], &mut [f64]) + '_ {
    move |ws, q, v, vd| {
        update_kinematics(model, ws, q, v).expect("dimensions match");
        let a = forward_dynamics(model, ws, &[0.0; 6]).expect("positive definite");
        vd.copy_from_slice(a.as_slice());
    }
}

fn initial_q(orientation: UnitQuaternion<f64>) -> Vec<f64> {
    let c = orientation.quaternion().coords; // [i, j, k, w]
    vec![1.0, 2.0, 3.0, c[3], c[0], c[1], c[2]]
}

#[test]
fn asymmetric_body_conserves_energy_and_world_momentum() {
    let principal = Matrix3::from_diagonal(&Vector3::new(2.0, 3.0, 4.5));
    let r = Rotation3::from_euler_angles(0.3, -0.5, 0.8).into_inner();
    let model = free_body(
        5.0,
        Vector3::new(0.1, -0.2, 0.05),
        r * principal * r.transpose(),
    );
    let mut ws = Workspace::new(&model);
    let mut q = initial_q(UnitQuaternion::from_euler_angles(0.7, -0.4, 1.9));
    let mut v = vec![0.4, -1.1, 0.7, 0.3, 0.2, -0.5];
    update_kinematics(&model, &mut ws, &q, &v).unwrap();
    let e0 = kinetic_energy(&model, &ws).unwrap();
    let h0 = spatial_momentum(&model, &ws).unwrap();
    let mut f = accel(&model);
    let dt = 1e-3;
    let (mut max_de, mut max_dh) = (0.0_f64, 0.0_f64);
    for _ in 0..10_000 {
        rk4_step(&model, &mut ws, &mut q, &mut v, dt, &mut f);
        update_kinematics(&model, &mut ws, &q, &v).unwrap();
        let e = kinetic_energy(&model, &ws).unwrap();
        let h = spatial_momentum(&model, &ws).unwrap();
        max_de = max_de.max((e - e0).abs() / e0);
        max_dh = max_dh.max((h - h0).norm() / h0.norm());
    }
    assert!(max_de < 1e-8, "relative kinetic-energy drift {max_de:e}");
    assert!(max_dh < 1e-8, "relative spatial-momentum drift {max_dh:e}");
}

#[test]
fn axisymmetric_body_precesses_at_the_analytic_rate() {
    let (i1, i3) = (1.0, 2.0);
    let model = free_body(
        3.0,
        Vector3::zeros(),
        Matrix3::from_diagonal(&Vector3::new(i1, i1, i3)),
    );
    let mut ws = Workspace::new(&model);
    let (a, w3) = (0.1, 1.3);
    let mut q = initial_q(UnitQuaternion::from_euler_angles(0.5, 0.2, -0.3));
    let mut v = vec![a, 0.0, w3, 0.0, 0.0, 0.0];
    let mut f = accel(&model);
    let (dt, steps) = (1e-3, 5_000);
    for _ in 0..steps {
        rk4_step(&model, &mut ws, &mut q, &mut v, dt, &mut f);
    }
    // Euler's equations: omega_xy rotates in the body frame at Omega = (I3 - I1)/I1 w3.
    let omega = (i3 - i1) / i1 * w3;
    let t = dt * steps as f64;
    let expected = Vector3::new(a * (omega * t).cos(), a * (omega * t).sin(), w3);
    let got = Vector3::new(v[0], v[1], v[2]);
    assert!((got - expected).norm() < 1e-10 * a, "{got} vs {expected}");
}
