//! Mass-matrix properties over random trees and states: symmetric, positive definite,
//! equal column by column to RNEA with unit accelerations (zero velocity and gravity), and
//! consistent with the body-sum kinetic energy 1/2 v^T H v; and the RNEA bias forces obey
//! the power balance v^T C = d/dt(potential) + 1/2 v^T Hdot v (Hdot by central differences);
//! forward dynamics inverts inverse dynamics on branched trees with fixed joints and
//! agrees with a direct Cholesky solve of H.
use multibody::{
    bias_forces, forward_dynamics, inverse_dynamics, kinetic_energy, mass_matrix, potential_energy,
    update_kinematics, Body, Joint, Model, ModelBuilder, Workspace,
};
use nalgebra::{
    Isometry3, Matrix3, Rotation3, SymmetricEigen, Translation3, UnitQuaternion, Vector3,
};
use proptest::prelude::*;
use std::f64::consts::PI;

/// Random parameters of one body plus its joint state.
#[derive(Debug, Clone)]
struct RandomBody {
    parent_seed: usize,
    kind: u8,
    axis: [f64; 3],
    offset: [f64; 3],
    tilt: [f64; 3],
    mass: f64,
    com: [f64; 3],
    moments: [f64; 3],
    q: [f64; 3],
    v: [f64; 6],
}

fn random_body() -> impl Strategy<Value = RandomBody> {
    let unit = || [-1.0..1.0_f64, -1.0..1.0, -1.0..1.0];
    let angles = || [-PI..PI, -PI..PI, -PI..PI];
    (
        (0..1000usize, 0..4u8, unit(), unit(), angles()),
        (0.1..10.0_f64, unit(), [0.1..2.0_f64, 0.1..2.0, 0.1..2.0]),
        (
            angles(),
            [
                -2.0..2.0_f64,
                -2.0..2.0,
                -2.0..2.0,
                -2.0..2.0,
                -2.0..2.0,
                -2.0..2.0,
            ],
        ),
    )
        .prop_map(|(a, b, c)| RandomBody {
            parent_seed: a.0,
            kind: a.1,
            axis: a.2,
            offset: a.3,
            tilt: a.4,
            mass: b.0,
            com: b.1,
            moments: b.2,
            q: c.0,
            v: c.1,
        })
}

fn joint(r: &RandomBody, index: usize) -> Joint {
    let axis = Vector3::from(r.axis) + Vector3::new(0.0, 0.0, 1.5); // never zero
    match (index, r.kind) {
        (0, _) | (_, 0) => Joint::Floating,
        (_, 1) => Joint::Revolute { axis },
        (_, 2) => Joint::Prismatic { axis },
        _ => Joint::Fixed,
    }
}

/// Tree (body 0 floating, so nv > 0), configuration and velocity.
fn random_tree(bodies: &[RandomBody]) -> (Model, Vec<f64>, Vec<f64>) {
    let mut b = ModelBuilder::new(Vector3::new(0.3, -0.2, -9.81));
    for (i, r) in bodies.iter().enumerate() {
        let rot = Rotation3::from_euler_angles(r.tilt[2], r.tilt[0], r.tilt[1]).into_inner();
        b.add_body(Body {
            name: format!("b{i}"),
            parent: (i > 0 && r.parent_seed % (i + 1) < i).then(|| r.parent_seed % (i + 1)),
            joint: joint(r, i),
            placement: Isometry3::from_parts(
                Translation3::from(Vector3::from(r.offset)),
                UnitQuaternion::from_euler_angles(r.tilt[0], r.tilt[1], r.tilt[2]),
            ),
            mass: r.mass,
            com: Vector3::from(r.com),
            inertia: rot * Matrix3::from_diagonal(&Vector3::from(r.moments)) * rot.transpose(),
        });
    }
    let model = b.build().expect("random tree is valid");
    let (mut q, mut v) = (Vec::new(), Vec::new());
    for (body, r) in model.bodies().iter().zip(bodies) {
        match body.joint {
            Joint::Floating => {
                let c = UnitQuaternion::from_euler_angles(r.q[0], r.q[1], r.q[2]).into_inner();
                q.extend_from_slice(&[r.offset[0], r.offset[1], r.offset[2], c.w, c.i, c.j, c.k]);
                v.extend_from_slice(&r.v);
            }
            Joint::Revolute { .. } | Joint::Prismatic { .. } => {
                q.push(r.q[0]);
                v.push(r.v[0]);
            }
            Joint::Fixed => {}
        }
    }
    (model, q, v)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]
    #[test]
    fn crba_is_symmetric_definite_and_equals_rnea_columns(
        bodies in prop::collection::vec(random_body(), 1..9)
    ) {
        let (mut model, q, v) = random_tree(&bodies);
        let nv = model.nv();
        let mut ws = Workspace::new(&model);
        update_kinematics(&model, &mut ws, &q, &v).unwrap();
        let h = mass_matrix(&model, &mut ws).unwrap().clone();
        let scale = h.amax();
        prop_assert!((&h - h.transpose()).amax() <= 1e-14 * scale);
        let min_eig = SymmetricEigen::new(h.clone()).eigenvalues.min();
        prop_assert!(min_eig > 0.0, "min eigenvalue {min_eig}");

        // Kinetic energy from body velocities equals 1/2 v^T H v.
        let ke = kinetic_energy(&model, &ws).unwrap();
        let vv = nalgebra::DVector::from_column_slice(&v);
        let ke_h = 0.5 * vv.dot(&(&h * &vv));
        prop_assert!((ke - ke_h).abs() <= 1e-11 * (1.0 + ke), "{ke} vs {ke_h}");

        // Column j of H is the RNEA torque for vdot = e_j at v = 0, g = 0.
        model.set_gravity(Vector3::zeros());
        update_kinematics(&model, &mut ws, &q, &vec![0.0; nv]).unwrap();
        let mut e = vec![0.0; nv];
        let mut tau = vec![0.0; nv];
        for j in 0..nv {
            e[j] = 1.0;
            inverse_dynamics(&model, &mut ws, &e, &mut tau).unwrap();
            e[j] = 0.0;
            for i in 0..nv {
                prop_assert!((tau[i] - h[(i, j)]).abs() <= 1e-12 * scale,
                    "H[{i},{j}] = {} but RNEA gives {}", h[(i, j)], tau[i]);
            }
        }
    }
}

/// Configuration `q + s qdot(q, v)`, quaternions renormalised.
fn shifted(model: &Model, q: &[f64], v: &[f64], s: f64) -> Vec<f64> {
    let mut qdot = vec![0.0; model.nq()];
    model.velocity_to_qdot(q, v, &mut qdot);
    let mut qs: Vec<f64> = q.iter().zip(&qdot).map(|(a, b)| a + s * b).collect();
    model.normalize_quaternions(&mut qs);
    qs
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]
    #[test]
    fn bias_forces_satisfy_the_power_balance(
        bodies in prop::collection::vec(random_body(), 1..9)
    ) {
        let (model, q, v) = random_tree(&bodies);
        let mut ws = Workspace::new(&model);
        let vv = nalgebra::DVector::from_column_slice(&v);
        let zero_v = vec![0.0; model.nv()];
        let h = 1e-6;
        let mut at = |s: f64| {
            update_kinematics(&model, &mut ws, &shifted(&model, &q, &v, s), &zero_v).unwrap();
            let pe = potential_energy(&model, &ws).unwrap();
            (mass_matrix(&model, &mut ws).unwrap().clone(), pe)
        };
        let ((h_plus, pe_plus), (h_minus, pe_minus)) = (at(h), at(-h));
        let h_dot = (h_plus - h_minus) / (2.0 * h);
        let pe_dot = (pe_plus - pe_minus) / (2.0 * h);
        update_kinematics(&model, &mut ws, &q, &v).unwrap();
        let power = vv.dot(bias_forces(&model, &mut ws).unwrap());
        let expected = pe_dot + 0.5 * vv.dot(&(&h_dot * &vv));
        let scale = 1.0 + power.abs() + pe_dot.abs();
        prop_assert!((power - expected).abs() < 1e-6 * scale, "{power} vs {expected}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]
    #[test]
    fn forward_dynamics_inverts_inverse_dynamics_on_branched_trees(
        bodies in prop::collection::vec(random_body(), 1..9),
        seed in 0u64..1000,
    ) {
        let (model, q, v) = random_tree(&bodies);
        let nv = model.nv();
        let mut ws = Workspace::new(&model);
        let vdot: Vec<f64> = (0..nv).map(|k| ((seed + 7 * k as u64) % 13) as f64 - 6.0).collect();
        update_kinematics(&model, &mut ws, &q, &v).unwrap();
        let mut tau = vec![0.0; nv];
        inverse_dynamics(&model, &mut ws, &vdot, &mut tau).unwrap();
        let h = mass_matrix(&model, &mut ws).unwrap().clone();
        let c = bias_forces(&model, &mut ws).unwrap().clone();
        let rhs = nalgebra::DVector::from_column_slice(&tau) - &c;
        let dense = h.clone().cholesky().expect("H is positive definite").solve(&rhs);
        let got = forward_dynamics(&model, &mut ws, &tau).unwrap().clone();
        let scale = 1.0 + dense.amax();
        for k in 0..nv {
            prop_assert!((got[k] - vdot[k]).abs() <= 1e-7 * scale, "vdot[{k}] {} vs {}", got[k], vdot[k]);
            prop_assert!((got[k] - dense[k]).abs() <= 1e-9 * scale, "vdot[{k}] {} vs dense {}", got[k], dense[k]);
        }
    }
}
