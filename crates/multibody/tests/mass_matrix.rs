//! Mass-matrix properties over random trees and states: symmetric, positive definite,
//! equal column by column to RNEA with unit accelerations (zero velocity and gravity), and
//! consistent with the body-sum kinetic energy 1/2 v^T H v; and the RNEA bias forces obey
//! the power balance v^T C = d/dt(potential) + 1/2 v^T Hdot v (Hdot by central differences);
//! forward dynamics inverts inverse dynamics on branched trees with fixed joints and
//! agrees with a direct Cholesky solve of H; the articulated-body algorithm gives the same
//! accelerations with external forces.
#[path = "support/random_tree.rs"]
mod random_tree;

use multibody::{
    bias_forces, forward_dynamics, forward_dynamics_aba, inverse_dynamics, kinetic_energy,
    mass_matrix, potential_energy, update_kinematics, Model, Workspace,
};
use nalgebra::{SymmetricEigen, Vector3};
use proptest::prelude::*;
use random_tree::{random_body, random_tree};

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

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]
    #[test]
    fn the_articulated_body_algorithm_equals_crba_forward_dynamics(
        bodies in prop::collection::vec(random_body(), 1..9),
        seed in 0u64..1000,
    ) {
        let (model, q, v) = random_tree(&bodies);
        let nv = model.nv();
        let mut ws = Workspace::new(&model);
        let tau: Vec<f64> = (0..nv).map(|k| ((seed + 5 * k as u64) % 11) as f64 - 5.0).collect();
        update_kinematics(&model, &mut ws, &q, &v).unwrap();
        // a force and a moment on every body, at a point off its origin
        for b in 0..model.num_bodies() {
            let s = (seed + b as u64) as f64;
            let force = Vector3::new(s.sin(), (2.0 * s).cos(), 0.5 - (s * 0.3).sin()) * 20.0;
            let point = Vector3::new(0.1 * s.cos(), -0.2, 0.3 * (s * 0.7).sin());
            ws.apply_force_world(b, &force, &point);
            ws.apply_moment_world(b, &Vector3::new(0.0, 3.0 * s.cos(), -1.0));
        }
        let crba = forward_dynamics(&model, &mut ws, &tau).unwrap().clone();
        let aba = forward_dynamics_aba(&model, &mut ws, &tau).unwrap().clone();
        let scale = 1.0 + crba.amax();
        for k in 0..nv {
            prop_assert!((aba[k] - crba[k]).abs() <= 1e-9 * scale, "vdot[{k}] ABA {} vs CRBA {}", aba[k], crba[k]);
        }
    }
}
