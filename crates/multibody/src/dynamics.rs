//! Joint-space dynamics `H(q) vdot + C(q, v) = tau`: the composite-rigid-body algorithm
//! for `H` (Featherstone, "Rigid Body Dynamics Algorithms", 2008, Table 6.2), the
//! recursive Newton-Euler algorithm for `C` and inverse dynamics (Table 5.1), and forward
//! dynamics by the tree-sparse `L^T D L` solve of the joint-space equation (section 6.5,
//! Tables 6.3 and 6.4).
//!
//! Gravity enters RNEA as a fictitious base acceleration `a_0 = -a_g` (ch. 5);
//! external forces are those accumulated in the [`Workspace`] since the last
//! [`crate::update_kinematics`]. None of these functions allocate.

use crate::crba::crba;
use crate::error::DynamicsError;
use crate::kinematics::{check_len, subspace_times};
use crate::ltdl::DofTree;
use crate::model::Model;
use crate::spatial::{cross_force, cross_motion, spatial};
use crate::workspace::Workspace;
use nalgebra::{DMatrix, Vector3, Vector6};

/// Composite-rigid-body algorithm (Featherstone 2008, section 6.2) in one common frame
/// per tree, the root body's: body inertias and motion subspaces are expressed there once,
/// composite inertias are plain sums, and `H[k, j] = S̄_j^T (Ī^c S̄_k)` along each ancestor
/// chain (docs/numerics.md, "Multibody core"). Fills and returns the symmetric joint-space
/// mass matrix `H(q)` at the configuration of the last [`crate::update_kinematics`].
pub fn mass_matrix<'w>(
    model: &Model,
    ws: &'w mut Workspace,
) -> Result<&'w DMatrix<f64>, DynamicsError> {
    ws.check(model)?;
    crba(model, ws);
    // The dense matrix through the model's precomputed offsets (cheaper than the chain
    // walk of `Workspace::mass_matrix`, which has no model).
    let dense = ws.h.as_mut_slice();
    for (&h, &(lower, upper)) in ws.hs.iter().zip(&model.dofs.dense) {
        dense[lower] = h;
        dense[upper] = h;
    }
    ws.h_dense_current = true;
    Ok(&ws.h)
}

/// RNEA passes (Featherstone 2008, Table 5.1) at the state of the last kinematics update
/// with joint accelerations `vdot` (`None` = zero), leaving the joint-side spatial force
/// of every body in `ws.force`.
fn rnea(model: &Model, ws: &mut Workspace, vdot: Option<&[f64]>) {
    let a_base = spatial(&Vector3::zeros(), &(-model.gravity()));
    for (i, (body, link)) in model.bodies().iter().zip(&model.links).enumerate() {
        let a_parent = body.parent.map_or(a_base, |p| ws.acc[p]);
        let mut a = ws.x_up[i].apply_motion(&a_parent) + cross_motion(&ws.vel[i], &ws.vel_joint[i]);
        if let Some(vd) = vdot {
            a += subspace_times(link, vd);
        }
        let iv = link.rigid_inertia.apply(&ws.vel[i]);
        ws.acc[i] = a;
        ws.force[i] = link.rigid_inertia.apply(&a) + cross_force(&ws.vel[i], &iv) - ws.f_ext[i];
    }
    for (i, body) in model.bodies().iter().enumerate().rev() {
        if let Some(p) = body.parent {
            let fp = ws.x_up[i].transpose_apply_force(&ws.force[i]);
            ws.force[p] += fp;
        }
    }
}

/// `tau_i = S_i^T f_i` for every joint.
fn project(model: &Model, force: &[Vector6<f64>], tau: &mut [f64]) {
    for (link, f) in model.links.iter().zip(force) {
        for k in 0..link.nv {
            tau[link.v_offset + k] = link.subspace.column(k).dot(f);
        }
    }
}

/// Bias forces `C(q, v)` = gravity + Coriolis/centrifugal - external forces in joint
/// space, by RNEA with zero acceleration (Featherstone 2008, Table 5.1, ch. 6).
pub fn bias_forces<'w>(
    model: &Model,
    ws: &'w mut Workspace,
) -> Result<&'w nalgebra::DVector<f64>, DynamicsError> {
    ws.check(model)?;
    rnea(model, ws, None);
    project(model, &ws.force, ws.c.as_mut_slice());
    Ok(&ws.c)
}

/// Inverse dynamics by RNEA (Featherstone 2008, Table 5.1): writes into `tau` the joint
/// forces that produce accelerations `vdot` at the state of the last kinematics update,
/// including gravity and the accumulated external forces.
pub fn inverse_dynamics(
    model: &Model,
    ws: &mut Workspace,
    vdot: &[f64],
    tau: &mut [f64],
) -> Result<(), DynamicsError> {
    ws.check(model)?;
    check_len("vdot", vdot, model.nv())?;
    check_len("tau", tau, model.nv())?;
    rnea(model, ws, Some(vdot));
    project(model, &ws.force, tau);
    Ok(())
}

/// Forward dynamics: solves `H vdot = tau - C` with the CRBA mass matrix (Featherstone
/// 2008, section 6.2) factorised as `H = L^T D L` along the tree (section 6.5, Tables 6.3
/// and 6.4; see [`crate::solve_mass_matrix`]) and returns `vdot` (length `nv`). Also leaves
/// `H` and `C` in the workspace ([`Workspace::mass_matrix`], [`Workspace::bias_forces`]).
///
/// `tau` are the caller's joint forces (springs, dampers, drive torques); floating-joint
/// entries are a body-coordinate wrench `[moment; force]` about the body origin.
pub fn forward_dynamics<'w>(
    model: &Model,
    ws: &'w mut Workspace,
    tau: &[f64],
) -> Result<&'w nalgebra::DVector<f64>, DynamicsError> {
    ws.check(model)?;
    check_len("tau", tau, model.nv())?;
    crba(model, ws);
    rnea(model, ws, None);
    project(model, &ws.force, ws.c.as_mut_slice());
    for ((vd, t), c) in ws.vdot.iter_mut().zip(tau).zip(ws.c.iter()) {
        *vd = t - c;
    }
    ltdl_solve(&model.dofs, &ws.hs, &mut ws.ldl, ws.vdot.as_mut_slice())?;
    Ok(&ws.vdot)
}

/// Solves `H(q) x = b` in place (`x` holds `b` on entry, length `nv`) at the configuration
/// of the last [`crate::update_kinematics`], by the tree-sparse factorisation
/// `H = L^T D L` (Featherstone 2008, section 6.5, Tables 6.3 and 6.4): `L` keeps the
/// sparsity of the expanded parent array, so the factor costs one multiply-add per pair of
/// dofs on a common ancestor chain instead of the dense `nv^3 / 6`. Computes `H` first
/// unless [`mass_matrix`] or [`forward_dynamics`] already did at this configuration;
/// factorises on every call. Allocation free.
pub fn solve_mass_matrix(
    model: &Model,
    ws: &mut Workspace,
    x: &mut [f64],
) -> Result<(), DynamicsError> {
    ws.check(model)?;
    check_len("x", x, model.nv())?;
    if !ws.h_current {
        crba(model, ws);
    }
    ltdl_solve(&model.dofs, &ws.hs, &mut ws.ldl, x)
}

/// Copies the packed `H` into the factor buffer, factorises it and solves in place.
fn ltdl_solve(
    tree: &DofTree,
    hs: &[f64],
    ldl: &mut [f64],
    x: &mut [f64],
) -> Result<(), DynamicsError> {
    let ldl = &mut ldl[..tree.nnz()];
    ldl.copy_from_slice(&hs[..tree.nnz()]);
    if tree.factor(ldl) {
        tree.solve(ldl, x);
        Ok(())
    } else {
        Err(DynamicsError::MassMatrixNotPositiveDefinite)
    }
}
