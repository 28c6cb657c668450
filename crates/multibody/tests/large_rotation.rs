//! Large rotations are exact: frame invariance of the truck rolled by 35 degrees (with the
//! gravity rotated alike), exact gravity response at any roll, exact integration of a
//! constant spin through 180 degrees, and point velocity = d/dt point position.
#[path = "support/rk4.rs"]
mod rk4;
#[path = "support/vehicle.rs"]
mod vehicle;

use multibody::{forward_dynamics, update_kinematics, Body, Joint, Model, ModelBuilder, Workspace};
use nalgebra::{Isometry3, Matrix3, Quaternion, UnitQuaternion, Vector3};
use rk4::rk4_step;
use vehicle::{springs, truck, TRUCK_SPRINGS};

fn quat(q: &[f64]) -> UnitQuaternion<f64> {
    UnitQuaternion::from_quaternion(Quaternion::new(q[3], q[4], q[5], q[6]))
}

fn set_quat(q: &mut [f64], r: UnitQuaternion<f64>) {
    let c = r.into_inner();
    q[3..7].copy_from_slice(&[c.w, c.i, c.j, c.k]);
}

fn simulate(model: &Model, q: &mut [f64], v: &mut [f64], steps: usize) {
    let mut ws = Workspace::new(model);
    let mut tau = vec![0.0; model.nv()];
    let mut f = |ws: &mut Workspace, q: &[f64], v: &[f64], vd: &mut [f64]| {
        update_kinematics(model, ws, q, v).unwrap();
        springs(model, &TRUCK_SPRINGS, q, &mut tau);
        vd.copy_from_slice(forward_dynamics(model, ws, &tau).unwrap().as_slice());
    };
    for _ in 0..steps {
        rk4_step(model, &mut ws, q, v, 1e-3, &mut f);
    }
}

#[test]
fn rolled_truck_with_rotated_gravity_follows_the_rotated_trajectory() {
    let g = Vector3::new(0.0, 0.0, -9.81);
    let roll = UnitQuaternion::from_euler_angles(35f64.to_radians(), 0.0, 20f64.to_radians());
    let mut qa = vec![0.0; 15];
    qa[..3].copy_from_slice(&[0.4, -0.2, 1.0]);
    set_quat(&mut qa, UnitQuaternion::from_euler_angles(0.05, 0.02, 0.1));
    qa[7..].copy_from_slice(&[0.05, -0.03, 0.02, 0.04, 0.3, -1.0, 2.0, 0.5]);
    let mut va = vec![
        0.2, -0.3, 0.1, 3.0, 0.5, 1.0, 0.2, -0.4, 0.3, -0.5, 10.0, 10.0, 11.0, 9.0,
    ];
    let (mut qb, mut vb) = (qa.clone(), va.clone());
    let pb = roll * Vector3::new(qa[0], qa[1], qa[2]);
    qb[..3].copy_from_slice(pb.as_slice());
    set_quat(&mut qb, roll * quat(&qa));

    simulate(&truck(g), &mut qa, &mut va, 2_000);
    simulate(&truck(roll * g), &mut qb, &mut vb, 2_000);

    let pa = roll * Vector3::new(qa[0], qa[1], qa[2]);
    assert!((pa - Vector3::new(qb[0], qb[1], qb[2])).norm() < 1e-9);
    assert!((roll * quat(&qa)).angle_to(&quat(&qb)) < 1e-10);
    for k in 7..15 {
        assert!((qa[k] - qb[k]).abs() < 1e-10, "joint coordinate {k}");
    }
    for k in 0..14 {
        assert!(
            (va[k] - vb[k]).abs() < 1e-9 * (1.0 + va[k].abs()),
            "velocity {k}"
        );
    }
}

fn free_body(gravity: Vector3<f64>) -> Model {
    let mut b = ModelBuilder::new(gravity);
    b.add_body(Body {
        name: "body".into(),
        parent: None,
        joint: Joint::Floating,
        placement: Isometry3::identity(),
        mass: 7.0,
        com: Vector3::new(0.3, -0.2, 0.1),
        inertia: Matrix3::new(2.0, 0.1, 0.0, 0.1, 3.0, 0.2, 0.0, 0.2, 4.0),
    });
    b.build().unwrap()
}

#[test]
fn body_at_rest_accelerates_with_gravity_at_any_roll() {
    let g = Vector3::new(0.0, 0.0, -9.81);
    let model = free_body(g);
    let mut ws = Workspace::new(&model);
    for deg in [0.0, 28.0, 30.0, 60.0, 90.0, 135.0, 179.0] {
        let r = UnitQuaternion::from_euler_angles(f64::to_radians(deg), 0.3, -0.7);
        let mut q = vec![1.0, 2.0, 3.0, 0.0, 0.0, 0.0, 0.0];
        set_quat(&mut q, r);
        update_kinematics(&model, &mut ws, &q, &[0.0; 6]).unwrap();
        let a = forward_dynamics(&model, &mut ws, &[0.0; 6]).unwrap();
        let expected = r.inverse() * g;
        assert!(
            a.rows(0, 3).norm() < 1e-12,
            "no angular acceleration at {deg} deg"
        );
        assert!((a.rows(3, 3) - expected).norm() < 1e-12, "{deg} deg");
    }
}

#[test]
fn constant_spin_integrates_to_the_exact_rotation() {
    // Isotropic inertia: omega is constant in the body frame, R(t) = R0 exp(omega t).
    let mut b = ModelBuilder::new(Vector3::zeros());
    b.add_body(Body {
        name: "ball".into(),
        parent: None,
        joint: Joint::Floating,
        placement: Isometry3::identity(),
        mass: 1.0,
        com: Vector3::zeros(),
        inertia: Matrix3::identity(),
    });
    let model = b.build().unwrap();
    let mut ws = Workspace::new(&model);
    let r0 = UnitQuaternion::from_euler_angles(0.2, 0.1, 0.4);
    let omega = Vector3::new(1.0, 0.5, -0.25);
    let mut q = vec![0.0; 7];
    set_quat(&mut q, r0);
    let mut v = vec![omega.x, omega.y, omega.z, 0.0, 0.0, 0.0];
    let mut f = |ws: &mut Workspace, q: &[f64], v: &[f64], vd: &mut [f64]| {
        update_kinematics(&model, ws, q, v).unwrap();
        vd.copy_from_slice(forward_dynamics(&model, ws, &[0.0; 6]).unwrap().as_slice());
    };
    let t = std::f64::consts::PI / omega.norm(); // a half turn
    let steps = 3_000;
    for _ in 0..steps {
        rk4_step(&model, &mut ws, &mut q, &mut v, t / steps as f64, &mut f);
    }
    let exact = r0 * UnitQuaternion::from_scaled_axis(omega * t);
    assert!(quat(&q).angle_to(&exact) < 1e-11);
}

#[test]
fn point_velocity_is_the_derivative_of_point_position() {
    let model = truck(Vector3::new(0.0, 0.0, -9.81));
    let mut ws = Workspace::new(&model);
    let mut q = vec![0.0; 15];
    set_quat(&mut q, UnitQuaternion::from_euler_angles(0.6, -0.4, 2.0));
    q[7..].copy_from_slice(&[0.05, -0.03, 0.02, 0.5, 0.3, -1.0, 2.0, 0.5]);
    let v = vec![
        0.7, -0.3, 0.4, 3.0, 0.5, 1.0, 0.2, -0.4, 0.3, -0.5, 10.0, 10.0, 11.0, 9.0,
    ];
    let mut qdot = vec![0.0; 15];
    model.velocity_to_qdot(&q, &v, &mut qdot);
    let h = 1e-6;
    let shifted = |s: f64| -> Vec<f64> {
        let mut qs: Vec<f64> = q.iter().zip(&qdot).map(|(a, b)| a + s * b).collect();
        model.normalize_quaternions(&mut qs);
        qs
    };
    let point = Vector3::new(0.3, -0.2, 0.7);
    update_kinematics(&model, &mut ws, &q, &v).unwrap();
    let velocities: Vec<Vector3<f64>> = (0..model.num_bodies())
        .map(|i| ws.point_velocity(i, &point))
        .collect();
    let mut position_at = |s: f64| -> Vec<Vector3<f64>> {
        update_kinematics(&model, &mut ws, &shifted(s), &v).unwrap();
        (0..model.num_bodies())
            .map(|i| ws.point_position(i, &point))
            .collect()
    };
    let (plus, minus) = (position_at(h), position_at(-h));
    for i in 0..model.num_bodies() {
        let fd = (plus[i] - minus[i]) / (2.0 * h);
        assert!(
            (fd - velocities[i]).norm() < 1e-7 * (1.0 + fd.norm()),
            "body {i}"
        );
    }
}
