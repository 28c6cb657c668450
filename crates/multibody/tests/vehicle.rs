//! Vehicle-like tree checks: energy conservation with suspension springs under gravity (by
//! CRBA and by the articulated-body algorithm, also across a massless hitch),
//! equivalence of point-force and force + moment application, and static equilibrium of
//! a body on four vertical point springs.
#[path = "support/rk4.rs"]
mod rk4;
#[path = "support/vehicle.rs"]
mod vehicle;

use multibody::{
    forward_dynamics, forward_dynamics_aba, kinetic_energy, potential_energy, update_kinematics,
    Body, Joint, Model, ModelBuilder, Workspace,
};
use nalgebra::{Isometry3, Matrix3, UnitQuaternion, Vector3};
use rk4::rk4_step;
use vehicle::{springs, truck, TRUCK_SPRINGS};

const GRAVITY: Vector3<f64> = Vector3::new(0.0, 0.0, -9.81);

/// Perturbed truck state: tilted chassis, moving and rotating, springs deflected,
/// wheels spinning.
fn perturbed_state(orientation: UnitQuaternion<f64>) -> (Vec<f64>, Vec<f64>) {
    let c = orientation.into_inner();
    let q = vec![
        0.0, 0.0, 1.5, c.w, c.i, c.j, c.k, 0.05, -0.03, 0.02, 0.04, 0.3, -1.0, 2.0, 0.5,
    ];
    let v = vec![
        0.3, -0.2, 0.1, 5.0, 0.0, 1.0, 0.2, -0.4, 0.3, -0.5, 10.0, 10.0, 11.0, 9.0,
    ];
    (q, v)
}

/// A forward-dynamics function: [`forward_dynamics`] or [`forward_dynamics_aba`].
type ForwardDynamics = for<'w> fn(
    &Model,
    &'w mut Workspace,
    &[f64],
) -> Result<&'w nalgebra::DVector<f64>, multibody::DynamicsError>;

/// Integrates `steps` RK4 steps of 1 ms with the joint springs and returns the largest
/// |E(t) - E(0)| relative to the initial kinetic + spring energy, E = kinetic +
/// gravitational + spring.
fn energy_drift(
    fd: ForwardDynamics,
    model: &Model,
    spring_list: &[(&str, f64)],
    q: &mut [f64],
    v: &mut [f64],
    steps: usize,
) -> f64 {
    let mut ws = Workspace::new(model);
    let mut tau = vec![0.0; model.nv()];
    let mut energy = |ws: &mut Workspace, q: &[f64], v: &[f64]| {
        update_kinematics(model, ws, q, v).unwrap();
        let ke = kinetic_energy(model, ws).unwrap();
        let spring = springs(model, spring_list, q, &mut tau);
        (
            ke + potential_energy(model, ws).unwrap() + spring,
            ke + spring,
        )
    };
    let (e0, scale) = energy(&mut ws, q, v);
    let mut tau_rhs = vec![0.0; model.nv()];
    let mut f = |ws: &mut Workspace, q: &[f64], v: &[f64], vd: &mut [f64]| {
        update_kinematics(model, ws, q, v).unwrap();
        springs(model, spring_list, q, &mut tau_rhs);
        vd.copy_from_slice(fd(model, ws, &tau_rhs).unwrap().as_slice());
    };
    let mut max_rel = 0.0_f64;
    for _ in 0..steps {
        rk4_step(model, &mut ws, q, v, 1e-3, &mut f);
        let (e, _) = energy(&mut ws, q, v);
        max_rel = max_rel.max((e - e0).abs() / scale);
    }
    max_rel
}

#[test]
fn sprung_truck_conserves_total_energy() {
    let model = truck(GRAVITY);
    assert_eq!((model.nq(), model.nv()), (15, 14));
    let (mut q, mut v) = perturbed_state(UnitQuaternion::from_euler_angles(0.1, 0.05, 0.3));
    let drift = energy_drift(
        forward_dynamics,
        &model,
        &TRUCK_SPRINGS,
        &mut q,
        &mut v,
        3_000,
    );
    assert!(
        drift < 1e-6,
        "energy drift {drift:e} of the initial kinetic + spring energy"
    );
}

/// Articulated dump truck: front unit (floating) -> articulation yaw revolute -> massless
/// intermediate body -> roll revolute -> rear unit; two prismatic front wheel carriers;
/// four wheel spins. 14 DOF.
fn dump_truck() -> Model {
    let spin = Joint::Revolute { axis: Vector3::y() };
    let bounce = Joint::Prismatic { axis: Vector3::z() };
    let part = |name: &str, parent, joint, at: [f64; 3], mass, com: [f64; 3], i: [f64; 3]| Body {
        name: String::from(name),
        parent: Some(parent),
        joint,
        placement: Isometry3::translation(at[0], at[1], at[2]),
        mass,
        com: Vector3::from(com),
        inertia: Matrix3::from_diagonal(&Vector3::from(i)),
    };
    let mut b = ModelBuilder::new(GRAVITY);
    b.add_body(Body {
        name: "front".into(),
        parent: None,
        joint: Joint::Floating,
        placement: Isometry3::identity(),
        mass: 15_000.0,
        com: Vector3::new(0.5, 0.0, 0.4),
        inertia: Matrix3::from_diagonal(&Vector3::new(8_000.0, 20_000.0, 22_000.0)),
    });
    let yaw = Joint::Revolute { axis: Vector3::z() };
    let hitch = b.add_body(part(
        "hitch",
        0,
        yaw,
        [-1.5, 0.0, 0.0],
        0.0,
        [0.0; 3],
        [0.0; 3],
    ));
    let roll = Joint::Revolute { axis: Vector3::x() };
    let rear_i = [15_000.0, 50_000.0, 55_000.0];
    let rear = b.add_body(part(
        "rear",
        hitch,
        roll,
        [-0.3, 0.0, 0.0],
        25_000.0,
        [-2.5, 0.0, 0.6],
        rear_i,
    ));
    let fl = b.add_body(part(
        "carrier_fl",
        0,
        bounce,
        [1.5, 1.1, -0.4],
        350.0,
        [0.0; 3],
        [15.0; 3],
    ));
    let fr = b.add_body(part(
        "carrier_fr",
        0,
        bounce,
        [1.5, -1.1, -0.4],
        350.0,
        [0.0; 3],
        [15.0; 3],
    ));
    let wheel = [200.0, 380.0, 200.0];
    for (name, parent, y) in [("wheel_fl", fl, 0.3), ("wheel_fr", fr, -0.3)] {
        b.add_body(part(
            name,
            parent,
            spin,
            [0.0, y, 0.0],
            550.0,
            [0.0; 3],
            wheel,
        ));
    }
    for (name, y) in [("wheel_rl", 1.2), ("wheel_rr", -1.2)] {
        b.add_body(part(
            name,
            rear,
            spin,
            [-2.5, y, -0.6],
            550.0,
            [0.0; 3],
            wheel,
        ));
    }
    b.build().expect("the dump-truck tree is valid")
}

#[test]
fn articulated_dump_truck_with_massless_hitch_conserves_total_energy() {
    let model = dump_truck();
    assert_eq!((model.nq(), model.nv()), (15, 14));
    let spring_list = [
        ("hitch", 5.0e5),
        ("rear", 1.0e6),
        ("carrier_fl", 3.0e5),
        ("carrier_fr", 3.0e5),
    ];
    let (q0, v0) = perturbed_state(UnitQuaternion::from_euler_angles(-0.1, 0.05, 1.0));
    for fd in [forward_dynamics as ForwardDynamics, forward_dynamics_aba] {
        let (mut q, mut v) = (q0.clone(), v0.clone());
        let drift = energy_drift(fd, &model, &spring_list, &mut q, &mut v, 3_000);
        assert!(
            drift < 1e-6,
            "energy drift {drift:e} of the initial kinetic + spring energy"
        );
    }
    // and the two algorithms agree at the perturbed state
    let mut ws = Workspace::new(&model);
    update_kinematics(&model, &mut ws, &q0, &v0).unwrap();
    let tau: Vec<f64> = (0..model.nv()).map(|k| 100.0 * k as f64 - 500.0).collect();
    let crba = forward_dynamics(&model, &mut ws, &tau).unwrap().clone();
    let aba = forward_dynamics_aba(&model, &mut ws, &tau).unwrap();
    assert!(
        (aba - &crba).amax() < 1e-10 * (1.0 + crba.amax()),
        "{aba} vs {crba}"
    );
}

#[test]
fn point_force_equals_force_plus_moment_at_the_origin() {
    let model = truck(GRAVITY);
    let mut ws = Workspace::new(&model);
    let (q, v) = perturbed_state(UnitQuaternion::from_euler_angles(0.5, -0.2, 1.0));
    let mut tau = vec![0.0; model.nv()];
    springs(&model, &TRUCK_SPRINGS, &q, &mut tau);
    let axle = model.body_index("axle_roll").unwrap();
    let force = Vector3::new(1.0e4, -3.0e3, 8.0e4);
    let solve = |ws: &mut Workspace, apply: &dyn Fn(&mut Workspace)| {
        update_kinematics(&model, ws, &q, &v).unwrap();
        apply(ws);
        forward_dynamics(&model, ws, &tau).unwrap().clone()
    };
    let point_body = Vector3::new(0.2, 1.3, -0.6);
    update_kinematics(&model, &mut ws, &q, &v).unwrap();
    let point = ws.point_position(axle, &point_body);
    let origin = ws.body_position(axle);
    let r_world = ws.body_rotation(axle);
    let at_point = solve(&mut ws, &|ws| ws.apply_force_world(axle, &force, &point));
    let split = solve(&mut ws, &|ws| {
        ws.apply_force_world(axle, &force, &origin);
        ws.apply_moment_world(axle, &(point - origin).cross(&force));
    });
    let body_frame = solve(&mut ws, &|ws| {
        ws.apply_force_body(axle, &(r_world.transpose() * force), &point_body);
    });
    let free = solve(&mut ws, &|_| {});
    assert!((&at_point - &free).norm() > 1.0, "the force has an effect");
    assert!((&at_point - &split).norm() < 1e-12 * at_point.norm());
    assert!((&at_point - &body_frame).norm() < 1e-12 * at_point.norm());
}

#[test]
fn body_on_four_point_springs_settles_to_loads_summing_to_weight() {
    let mass = 1_500.0;
    let com = Vector3::new(0.3, -0.1, 0.0);
    let mut b = ModelBuilder::new(GRAVITY);
    b.add_body(Body {
        name: "box".into(),
        parent: None,
        joint: Joint::Floating,
        placement: Isometry3::identity(),
        mass,
        com,
        inertia: Matrix3::from_diagonal(&Vector3::new(400.0, 900.0, 1_100.0)),
    });
    let model = b.build().unwrap();
    let corners =
        [(1.2, 0.8), (1.2, -0.8), (-1.2, 0.8), (-1.2, -0.8)].map(|(x, y)| Vector3::new(x, y, -0.4));
    let (k, c) = (1.0e5, 3.0e3);
    let loads = |ws: &Workspace| {
        corners.map(|p| -k * ws.point_position(0, &p).z - c * ws.point_velocity(0, &p).z)
    };
    let mut f = |ws: &mut Workspace, q: &[f64], v: &[f64], vd: &mut [f64]| {
        update_kinematics(&model, ws, q, v).unwrap();
        for (p, fz) in corners.iter().zip(loads(ws)) {
            let at = ws.point_position(0, p);
            ws.apply_force_world(0, &Vector3::new(0.0, 0.0, fz), &at);
        }
        vd.copy_from_slice(forward_dynamics(&model, ws, &[0.0; 6]).unwrap().as_slice());
    };
    let tilt = UnitQuaternion::from_euler_angles(0.05, -0.04, 0.0).into_inner();
    let mut q = vec![0.0, 0.0, 0.45, tilt.w, tilt.i, tilt.j, tilt.k];
    let mut v = vec![0.0; 6];
    let mut ws = Workspace::new(&model);
    for _ in 0..7_500 {
        rk4_step(&model, &mut ws, &mut q, &mut v, 2e-3, &mut f);
    }
    update_kinematics(&model, &mut ws, &q, &v).unwrap();
    let fz = loads(&ws);
    let weight = mass * 9.81;
    let total: f64 = fz.iter().sum();
    assert!(
        (total - weight).abs() < 1e-6 * weight,
        "loads {fz:?} sum {total}"
    );
    // Moment balance about the centre of mass (lever rule): loads are uneven.
    let g = ws.point_position(0, &com);
    let moment: Vector3<f64> = corners
        .iter()
        .zip(fz)
        .map(|(p, fz)| (ws.point_position(0, p) - g).cross(&Vector3::new(0.0, 0.0, fz)))
        .sum();
    assert!(moment.norm() < 1e-6 * weight, "residual moment {moment}");
    assert!(
        fz[0] > fz[3],
        "the front-left corner, nearer the centre of mass, carries more"
    );
    assert!(v.iter().all(|x| x.abs() < 1e-8), "at rest: {v:?}");
}
