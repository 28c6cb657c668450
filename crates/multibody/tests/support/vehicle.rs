//! A 14-DOF rigid two-axle truck tree shared by the vehicle tests and the bench:
//! floating chassis, two front wheel carriers on prismatic joints, a rear solid axle on
//! a massless bounce (prismatic) body plus a roll revolute, and four wheel spins.
use multibody::{Body, Joint, Model, ModelBuilder};
use nalgebra::{Isometry3, Matrix3, Vector3};

/// Linear springs of the truck: body whose joint carries the spring, stiffness
/// (N/m on the prismatic joints, N m/rad on the rear-axle roll joint).
pub const TRUCK_SPRINGS: [(&str, f64); 4] = [
    ("carrier_fl", 4.0e5),
    ("carrier_fr", 4.0e5),
    ("axle_bounce", 4.0e5),
    ("axle_roll", 2.0e5),
];

fn body(name: &str, parent: usize, joint: Joint, at: [f64; 3], mass: f64, i: [f64; 3]) -> Body {
    Body {
        name: name.into(),
        parent: Some(parent),
        joint,
        placement: Isometry3::translation(at[0], at[1], at[2]),
        mass,
        com: Vector3::zeros(),
        inertia: Matrix3::from_diagonal(&Vector3::from(i)),
    }
}

/// The truck tree under `gravity`.
pub fn truck(gravity: Vector3<f64>) -> Model {
    let bounce = Joint::Prismatic { axis: Vector3::z() };
    let spin = Joint::Revolute { axis: Vector3::y() };
    let mut b = ModelBuilder::new(gravity);
    b.add_body(Body {
        name: "chassis".into(),
        parent: None,
        joint: Joint::Floating,
        placement: Isometry3::identity(),
        mass: 20_000.0,
        com: Vector3::new(0.2, 0.0, 0.3),
        inertia: Matrix3::new(
            12_000.0, 0.0, 1_500.0, 0.0, 40_000.0, 0.0, 1_500.0, 0.0, 45_000.0,
        ),
    });
    let fl = b.add_body(body(
        "carrier_fl",
        0,
        bounce,
        [1.8, 1.0, -0.5],
        400.0,
        [20.0; 3],
    ));
    let fr = b.add_body(body(
        "carrier_fr",
        0,
        bounce,
        [1.8, -1.0, -0.5],
        400.0,
        [20.0; 3],
    ));
    let axle_bounce = b.add_body(body(
        "axle_bounce",
        0,
        bounce,
        [-1.6, 0.0, -0.5],
        0.0,
        [0.0; 3],
    ));
    let roll = Joint::Revolute { axis: Vector3::x() };
    let mut axle = body(
        "axle_roll",
        axle_bounce,
        roll,
        [0.0; 3],
        1_200.0,
        [900.0, 80.0, 900.0],
    );
    axle.com = Vector3::new(0.0, 0.0, -0.1);
    let axle = b.add_body(axle);
    let wheel = [250.0, 450.0, 250.0];
    b.add_body(body("wheel_fl", fl, spin, [0.0, 0.3, 0.0], 600.0, wheel));
    b.add_body(body("wheel_fr", fr, spin, [0.0, -0.3, 0.0], 600.0, wheel));
    b.add_body(body("wheel_rl", axle, spin, [0.0, 1.3, 0.0], 600.0, wheel));
    b.add_body(body("wheel_rr", axle, spin, [0.0, -1.3, 0.0], 600.0, wheel));
    b.build().expect("the truck tree is valid")
}

/// Linear joint springs (rest at q = 0) on the named 1-DOF joints: writes `tau` and
/// returns the spring energy.
pub fn springs(model: &Model, springs: &[(&str, f64)], q: &[f64], tau: &mut [f64]) -> f64 {
    tau.iter_mut().for_each(|t| *t = 0.0);
    let mut energy = 0.0;
    for &(name, k) in springs {
        let body = model.body_index(name).expect("body exists");
        let x = q[model.q_offset(body)];
        tau[model.v_offset(body)] = -k * x;
        energy += 0.5 * k * x * x;
    }
    energy
}
