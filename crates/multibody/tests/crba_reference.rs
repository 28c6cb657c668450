//! The mass matrix of the common-frame CRBA equals, entry by entry (to 1e-12 of its
//! largest entry), the body-coordinate CRBA of Featherstone 2008, Table 6.2 (the crate's
//! earlier algorithm, rebuilt here from the public API with 6x6 matrices) on random trees,
//! structural zeros included; forward dynamics by the sparse `L^T D L` solve agrees with a
//! dense Cholesky solve of that reference matrix and is backward stable, and the dense
//! matrix the workspace gives after it is the current one; a workspace reused
//! for a model of the same size but another tree gives the fresh workspace's results.
#[path = "support/random_tree.rs"]
mod random_tree;

use multibody::spatial::{rigid_body_inertia, SpatialTransform};
use multibody::{
    bias_forces, forward_dynamics, mass_matrix, solve_mass_matrix, update_kinematics, Body, Joint,
    Model, ModelBuilder, Workspace,
};
use nalgebra::{DMatrix, DVector, Isometry3, Matrix3, Matrix6, SymmetricEigen, Vector3};
use proptest::prelude::*;
use random_tree::{random_body, random_tree};

/// `i X 0` of every body, from the public pose accessors.
fn world_transform(ws: &Workspace, i: usize) -> SpatialTransform {
    SpatialTransform {
        rot: ws.body_rotation(i).transpose(),
        pos: ws.body_position(i),
    }
}

/// `X^-1` of a Plücker transform `(E, r)`: `(E^T, -E r)`.
fn inverse(x: &SpatialTransform) -> SpatialTransform {
    SpatialTransform {
        rot: x.rot.transpose(),
        pos: -(x.rot * x.pos),
    }
}

/// Featherstone 2008, Table 6.2, in body coordinates: `I^c_λ(i) += X^T I^c_i X` and every
/// column `F = I^c_i S_i` carried to the ancestors by `F <- X^T F`. Also returns the mask
/// of the entries it writes (the others are structural zeros).
fn reference_crba(model: &Model, ws: &Workspace) -> (DMatrix<f64>, DMatrix<bool>) {
    let bodies = model.bodies();
    let x_up: Vec<Matrix6<f64>> = (0..bodies.len())
        .map(|i| {
            let xi = world_transform(ws, i);
            match bodies[i].parent {
                None => xi.motion_matrix(),
                Some(p) => xi.after(&inverse(&world_transform(ws, p))).motion_matrix(),
            }
        })
        .collect();
    let mut ic: Vec<Matrix6<f64>> = bodies
        .iter()
        .map(|b| rigid_body_inertia(b.mass, &b.com, &b.inertia))
        .collect();
    for i in (0..bodies.len()).rev() {
        if let Some(p) = bodies[i].parent {
            let in_parent = x_up[i].transpose() * ic[i] * x_up[i];
            ic[p] += in_parent;
        }
    }
    let nv = model.nv();
    let mut h = DMatrix::zeros(nv, nv);
    let mut written = DMatrix::from_element(nv, nv, false);
    for i in 0..bodies.len() {
        let ni = bodies[i].joint.nv();
        let s_i = bodies[i].joint.motion_subspace();
        let mut f = ic[i] * s_i.columns(0, ni);
        let oi = model.v_offset(i);
        let block = s_i.columns(0, ni).transpose() * &f;
        h.view_mut((oi, oi), (ni, ni)).copy_from(&block);
        written.view_mut((oi, oi), (ni, ni)).fill(true);
        let mut j = i;
        while let Some(p) = bodies[j].parent {
            f = x_up[j].transpose() * f;
            j = p;
            let nj = bodies[j].joint.nv();
            let oj = model.v_offset(j);
            let block = bodies[j].joint.motion_subspace().columns(0, nj).transpose() * &f;
            h.view_mut((oj, oi), (nj, ni)).copy_from(&block);
            h.view_mut((oi, oj), (ni, nj)).copy_from(&block.transpose());
            written.view_mut((oj, oi), (nj, ni)).fill(true);
            written.view_mut((oi, oj), (ni, nj)).fill(true);
        }
    }
    (h, written)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]
    #[test]
    fn common_frame_crba_equals_the_body_coordinate_crba(
        bodies in prop::collection::vec(random_body(), 1..10)
    ) {
        let (model, q, v) = random_tree(&bodies);
        let mut ws = Workspace::new(&model);
        update_kinematics(&model, &mut ws, &q, &v).unwrap();
        let (reference, written) = reference_crba(&model, &ws);
        let h = mass_matrix(&model, &mut ws).unwrap();
        let scale = reference.amax();
        for ((a, b), w) in h.iter().zip(reference.iter()).zip(written.iter()) {
            prop_assert!((a - b).abs() <= 1e-12 * scale, "{a} vs reference {b}");
            if !w {
                prop_assert_eq!(*a, 0.0);
            }
        }
    }

    #[test]
    fn sparse_forward_dynamics_matches_a_dense_cholesky_solve(
        bodies in prop::collection::vec(random_body(), 1..10),
        seed in 0u64..1000,
    ) {
        let (model, q, v) = random_tree(&bodies);
        let nv = model.nv();
        let tau: Vec<f64> = (0..nv).map(|k| ((seed + 5 * k as u64) % 11) as f64 - 5.0).collect();
        let mut ws = Workspace::new(&model);
        // An earlier evaluation at another configuration, its dense H read.
        let neutral = model.neutral_configuration();
        update_kinematics(&model, &mut ws, neutral.as_slice(), &v).unwrap();
        forward_dynamics(&model, &mut ws, &tau).unwrap();
        ws.mass_matrix();
        update_kinematics(&model, &mut ws, &q, &v).unwrap();
        let (h, _) = reference_crba(&model, &ws);
        let c = bias_forces(&model, &mut ws).unwrap().clone();
        let b = DVector::from_column_slice(&tau) - &c;
        let dense = h.clone().cholesky().expect("H is positive definite").solve(&b);
        let got = forward_dynamics(&model, &mut ws, &tau).unwrap().clone();
        // Backward stable: the residual is at rounding level of the data.
        let residual = (&h * &got - &b).amax();
        prop_assert!(residual <= 1e-12 * (h.amax() * got.amax() + b.amax()), "residual {residual}");
        // Forward error bounded by the condition number times rounding.
        let eig = SymmetricEigen::new(h.clone()).eigenvalues;
        let condition = eig.max() / eig.min();
        let error = (&got - &dense).amax();
        prop_assert!(error <= 1e-14 * condition * (1.0 + dense.amax()),
            "error {error}, condition {condition}");
        // The dense H read after forward dynamics is this configuration's, not the
        // earlier one's, and equals the mass_matrix function's.
        let h_fd = ws.mass_matrix().clone();
        prop_assert!((&h_fd - &h).amax() <= 1e-12 * h.amax());
        prop_assert_eq!(&h_fd, mass_matrix(&model, &mut ws).unwrap());
        // solve_mass_matrix gives the same solution for the same right-hand side.
        let mut x = b.as_slice().to_vec();
        solve_mass_matrix(&model, &mut ws, &mut x).unwrap();
        for k in 0..nv {
            prop_assert_eq!(x[k], got[k]);
        }
    }
}

fn body(name: &str, parent: Option<usize>, joint: Joint) -> Body {
    Body {
        name: name.into(),
        parent,
        joint,
        placement: Isometry3::translation(0.3, -0.2, 0.5),
        mass: 2.0,
        com: Vector3::new(0.1, 0.0, -0.2),
        inertia: Matrix3::from_diagonal(&Vector3::new(0.5, 0.7, 0.9)),
    }
}

/// A floating base with three revolute bodies, as a chain or as a star.
fn three_links(chain: bool) -> Model {
    let mut b = ModelBuilder::new(Vector3::new(0.0, 0.0, -9.81));
    b.add_body(body("base", None, Joint::Floating));
    for k in 1..4 {
        let parent = if chain { k - 1 } else { 0 };
        let axis = Vector3::new(1.0, k as f64, 0.5);
        b.add_body(body(
            &format!("link{k}"),
            Some(parent),
            Joint::Revolute { axis },
        ));
    }
    b.build().expect("valid tree")
}

#[test]
fn a_workspace_reused_for_another_tree_of_the_same_size_gives_that_trees_results() {
    let (chain, star) = (three_links(true), three_links(false));
    let q = [0.1, 0.2, 0.3, 0.9, 0.1, -0.3, 0.2, 0.4, -0.7, 1.1];
    let v = [0.5, -0.2, 0.3, 1.0, 0.0, -1.0, 2.0, -1.5, 0.7];
    let tau = [1.0, 0.0, -2.0, 3.0, 0.5, 0.0, 1.0, -1.0, 0.2];
    let mut shared = Workspace::new(&chain);
    update_kinematics(&chain, &mut shared, &q, &v).unwrap();
    let h_chain = mass_matrix(&chain, &mut shared).unwrap().clone();
    update_kinematics(&star, &mut shared, &q, &v).unwrap();
    let vdot_shared = forward_dynamics(&star, &mut shared, &tau).unwrap().clone();
    let mut fresh = Workspace::new(&star);
    update_kinematics(&star, &mut fresh, &q, &v).unwrap();
    let vdot_fresh = forward_dynamics(&star, &mut fresh, &tau).unwrap().clone();
    assert_eq!(shared.mass_matrix(), fresh.mass_matrix());
    assert_eq!(vdot_shared, vdot_fresh);
    // The chain couples links 1 and 3; the star does not.
    assert_ne!(h_chain[(6, 8)], 0.0);
    assert_eq!(shared.mass_matrix()[(6, 8)], 0.0);
}
