//! Point accelerations against a central difference of point velocities along the motion:
//! the truck tree of `support/vehicle.rs`, tilted, moving, with deflected springs.
#[path = "support/vehicle.rs"]
mod vehicle;

use multibody::{forward_dynamics, update_accelerations, update_kinematics, Model, Workspace};
use nalgebra::{UnitQuaternion, Vector3};
use vehicle::{springs, truck, TRUCK_SPRINGS};

fn state() -> (Vec<f64>, Vec<f64>) {
    let c = UnitQuaternion::from_euler_angles(0.1, -0.05, 0.7).into_inner();
    let q = vec![
        0.0, 0.0, 1.5, c.w, c.i, c.j, c.k, 0.05, -0.03, 0.02, 0.04, 0.3, -1.0, 2.0, 0.5,
    ];
    let v = vec![
        0.3, -0.2, 0.1, 5.0, 0.0, 1.0, 0.2, -0.4, 0.3, -0.5, 10.0, 10.0, 11.0, 9.0,
    ];
    (q, v)
}

/// Joint accelerations at `(q, v)` with the spring forces of the tree.
fn vdot(model: &Model, ws: &mut Workspace, q: &[f64], v: &[f64]) -> Vec<f64> {
    update_kinematics(model, ws, q, v).unwrap();
    let mut tau = vec![0.0; model.nv()];
    springs(model, &TRUCK_SPRINGS, q, &mut tau);
    forward_dynamics(model, ws, &tau)
        .unwrap()
        .as_slice()
        .to_vec()
}

#[test]
fn point_acceleration_is_the_rate_of_the_point_velocity() {
    let model = truck(Vector3::new(0.0, 0.0, -9.81));
    let mut ws = Workspace::new(&model);
    let (q, v) = state();
    let a = vdot(&model, &mut ws, &q, &v);
    update_accelerations(&model, &mut ws, &a).unwrap();
    let point = Vector3::new(0.4, -0.3, 0.8);
    let exact: Vec<_> = (0..model.num_bodies())
        .map(|b| ws.point_acceleration(b, &point))
        .collect();
    // (q, v) advanced and retreated by h along (qdot, vdot): second-order central difference
    let h = 1e-6;
    let mut qdot = vec![0.0; model.nq()];
    model.velocity_to_qdot(&q, &v, &mut qdot);
    let moved = |s: f64| {
        let q: Vec<f64> = q.iter().zip(&qdot).map(|(x, d)| x + s * d).collect();
        let v: Vec<f64> = v.iter().zip(&a).map(|(x, d)| x + s * d).collect();
        (q, v)
    };
    let velocities = |s: f64, ws: &mut Workspace| {
        let (q, v) = moved(s);
        update_kinematics(&model, ws, &q, &v).unwrap();
        (0..model.num_bodies())
            .map(|b| ws.point_velocity(b, &point))
            .collect::<Vec<_>>()
    };
    let (ahead, behind) = (velocities(h, &mut ws), velocities(-h, &mut ws));
    for b in 0..model.num_bodies() {
        let fd = (ahead[b] - behind[b]) / (2.0 * h);
        let err = (fd - exact[b]).norm();
        assert!(
            err < 1e-5 * (1.0 + exact[b].norm()),
            "body {b}: exact {:?} vs difference {:?}",
            exact[b],
            fd
        );
    }
}

#[test]
fn accelerations_need_current_kinematics() {
    let model = truck(Vector3::new(0.0, 0.0, -9.81));
    let mut ws = Workspace::new(&model);
    let a = vec![0.0; model.nv()];
    assert!(update_accelerations(&model, &mut ws, &a).is_err());
    let (q, v) = state();
    update_kinematics(&model, &mut ws, &q, &v).unwrap();
    assert!(update_accelerations(&model, &mut ws, &a[1..]).is_err());
}
