//! Joint-space dynamics `H(q) vdot + C(q, v) = tau`: the composite-rigid-body algorithm
//! for `H` (Featherstone, "Rigid Body Dynamics Algorithms", 2008, Table 6.2), the
//! recursive Newton-Euler algorithm for `C` and inverse dynamics (Table 5.1), and forward
//! dynamics by a Cholesky solve of the joint-space equation (ch. 6).
//!
//! Gravity enters RNEA as a fictitious base acceleration `a_0 = -a_g` (ch. 5);
//! external forces are those accumulated in the [`Workspace`] since the last
//! [`crate::update_kinematics`]. None of these functions allocate.

use crate::error::DynamicsError;
use crate::kinematics::{check_len, subspace_times};
use crate::model::{Link, Model};
use crate::spatial::{cross_force, cross_motion, spatial};
use crate::workspace::Workspace;
use nalgebra::{Cholesky, DMatrix, Vector3, Vector6};

/// Composite-rigid-body algorithm (Featherstone 2008, Table 6.2): fills and returns the
/// symmetric joint-space mass matrix `H(q)` at the configuration of the last
/// [`crate::update_kinematics`].
pub fn mass_matrix<'w>(
    model: &Model,
    ws: &'w mut Workspace,
) -> Result<&'w DMatrix<f64>, DynamicsError> {
    ws.check(model)?;
    crba(model, ws);
    Ok(&ws.h)
}

fn crba(model: &Model, ws: &mut Workspace) {
    for (ic, link) in ws.ic.iter_mut().zip(&model.links) {
        *ic = link.rigid_inertia;
    }
    for (i, body) in model.bodies().iter().enumerate().rev() {
        if let Some(p) = body.parent {
            let ic_parent = ws.ic[i].in_parent(&ws.x_up[i]);
            ws.ic[p] += ic_parent;
        }
    }
    ws.h.fill(0.0);
    for (i, link) in model.links.iter().enumerate() {
        let mut f_store = [Vector6::zeros(); 6];
        let f = &mut f_store[..link.nv];
        for (k, fk) in f.iter_mut().enumerate() {
            *fk = ws.ic[i].apply(&link.subspace.column(k).into_owned());
        }
        set_block(&mut ws.h, link, link, f);
        let mut j = i;
        while let Some(p) = model.bodies()[j].parent {
            for fk in f.iter_mut() {
                *fk = ws.x_up[j].transpose_apply_force(fk);
            }
            j = p;
            set_block(&mut ws.h, &model.links[j], link, f);
        }
    }
}

/// `H[row, col] = S_row^T F` and its mirror `H[col, row]`, where `F` holds the columns
/// of `I^c_col S_col` expressed in the row body's coordinates.
fn set_block(h: &mut DMatrix<f64>, row: &Link, col: &Link, f: &[Vector6<f64>]) {
    for a in 0..row.nv {
        for (k, fk) in f.iter().enumerate() {
            let hij = row.subspace.column(a).dot(fk);
            h[(row.v_offset + a, col.v_offset + k)] = hij;
            h[(col.v_offset + k, row.v_offset + a)] = hij;
        }
    }
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
        let iv = link.inertia * ws.vel[i];
        ws.acc[i] = a;
        ws.force[i] = link.inertia * a + cross_force(&ws.vel[i], &iv) - ws.f_ext[i];
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

/// Forward dynamics: solves `H vdot = tau - C` with a Cholesky factorisation of the CRBA
/// mass matrix (Featherstone 2008, ch. 6) and returns `vdot` (length `nv`).
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
    // The factor borrows the preallocated buffer; `take` leaves an empty matrix
    // (no allocation) and the buffer is handed back below. A dense factorisation: with
    // the floating base, 6 of this crate's typical 10-14 degrees of freedom form one chain,
    // so Featherstone's sparse L^T L (Table 6.3) saves few operations and, with its
    // index-chasing loops, measured slower than nalgebra's Cholesky (docs/multibody.md).
    let mut buffer = std::mem::take(&mut ws.chol);
    buffer.copy_from(&ws.h);
    let chol = Cholesky::new_unchecked(buffer);
    let l = chol.l_dirty();
    let definite = (0..l.nrows()).all(|j| l[(j, j)].is_finite() && l[(j, j)] > 0.0);
    if definite {
        chol.solve_mut(&mut ws.vdot);
    }
    ws.chol = chol.unpack_dirty();
    if definite {
        Ok(&ws.vdot)
    } else {
        Err(DynamicsError::MassMatrixNotPositiveDefinite)
    }
}
