//! Forward dynamics by the articulated-body algorithm (Featherstone, "Rigid Body Dynamics
//! Algorithms", 2008, section 7.3, Table 7.1), in one common frame per tree, the root
//! body's, as [`crate::crba`] computes the mass matrix: no joint-space mass matrix, and no
//! spatial transform between a body and its parent.
//!
//! With every quantity in the coordinates of the tree's root body `r` (an inertial frame
//! that coincides with the root body at this instant), `S̄_i`, `Ī_i` and `i X r` from
//! [`crate::crba::bodies_in_root_frames`]:
//!
//! 1. Root to leaves: the velocity `v̄_i = v̄_λ(i) + S̄_i q̇_i`, the velocity-product
//!    acceleration `c̄_i = v̄_i × S̄_i q̇_i` (the rate of change `v̄_i × S̄_i` of the root-frame
//!    subspace times `q̇_i`), and the articulated inertia and bias force start as the
//!    body's own, `I^A_i = Ī_i`, `p^A_i = v̄_i ×* Ī_i v̄_i − (i X r)^T f^x_i` (the external
//!    forces accumulated since the last [`crate::update_kinematics`], in body coordinates).
//! 2. Leaves to root: `U_i = I^A_i S̄_i`, `D_i = S̄_i^T U_i`, `u_i = τ_i − S̄_i^T p^A_i`; the
//!    parent receives, in the same frame, `I^a_i = I^A_i − U_i D_i^-1 U_i^T` and
//!    `p^a_i = p^A_i + I^a_i c̄_i + U_i D_i^-1 u_i`.
//! 3. Root to leaves: `a'_i = ā_λ(i) + c̄_i` (a root's parent acceleration is the fictitious
//!    `−a_g` in its own coordinates, as in RNEA), `q̈_i = D_i^-1 (u_i − U_i^T a'_i)`,
//!    `ā_i = a'_i + S̄_i q̈_i`.
//!
//! A one-dof joint makes `D_i` a scalar. A floating joint (`S = 1_6` in body coordinates,
//! so `S̄ = (i X r)^-1`) gives `I^a = 0` and `p^a = (i X r)^T τ_i`, the joint's wrench in
//! root coordinates; its body's acceleration is `ā_i = (I^A_i)^-1 (p^a − p^A_i)`, through
//! the `L D Lᵀ` factors of its 6 × 6 articulated inertia, and `q̈_i = (i X r)(ā_i − a'_i)`.
//! A fixed joint passes its whole articulated inertia and bias force.
//!
//! The same accelerations as [`crate::forward_dynamics`] (CRBA and the tree-sparse
//! `Lᵀ D L`) to round-off, with fewer operations on a floating body carrying a few one-dof
//! joints (docs/numerics.md, "Multibody core"). Allocation free.

use crate::crba::bodies_in_root_frames;
use crate::error::DynamicsError;
use crate::inertia::RigidInertia;
use crate::kinematics::check_len;
use crate::model::Model;
use crate::spatial::{cross_force, cross_motion, spatial};
use crate::workspace::Workspace;
use nalgebra::{Matrix6, Vector3, Vector6};

/// Forward dynamics by the articulated-body algorithm (module docs): writes and returns the
/// joint accelerations `vdot` (length `nv`) for joint forces `tau` at the state of the last
/// [`crate::update_kinematics`], with gravity and the accumulated external forces. `tau`
/// as for [`crate::forward_dynamics`] (a floating joint's entries are a body-coordinate
/// wrench `[moment; force]` about the body origin). Unlike it, leaves neither `H` nor `C`
/// in the workspace.
///
/// Fails with [`DynamicsError::MassMatrixNotPositiveDefinite`] when a joint's articulated
/// inertia is not positive definite (a massless subtree on a joint), as the mass matrix
/// then is not.
pub fn forward_dynamics_aba<'w>(
    model: &Model,
    ws: &'w mut Workspace,
    tau: &[f64],
) -> Result<&'w nalgebra::DVector<f64>, DynamicsError> {
    ws.check(model)?;
    check_len("tau", tau, model.nv())?;
    bodies_in_root_frames(model, ws);
    let bodies = model.bodies();
    let qd = ws.v.as_slice();
    for (i, (body, link)) in bodies.iter().zip(&model.links).enumerate() {
        let dofs = link.v_offset..link.v_offset + link.nv;
        let mut v_joint = Vector6::zeros();
        for (s, &qd_k) in ws.cdof[dofs.clone()].iter().zip(&qd[dofs]) {
            v_joint += s * qd_k;
        }
        let v = match body.parent {
            Some(p) => ws.aba_v[p] + v_joint,
            None => v_joint,
        };
        ws.aba_v[i] = v;
        ws.aba_c[i] = cross_motion(&v, &v_joint);
        let f_ext = match body.parent {
            Some(_) => ws.x_root[i].transpose_apply_force(&ws.f_ext[i]),
            None => ws.f_ext[i],
        };
        if body.mass == 0.0 {
            ws.aba_ia[i] = Matrix6::zeros();
            ws.force[i] = -f_ext;
        } else {
            let inertia = &ws.ic[i];
            set_inertia(&mut ws.aba_ia[i], inertia);
            ws.force[i] = cross_force(&v, &inertia.apply(&v)) - f_ext;
        }
    }
    for (i, (body, link)) in bodies.iter().zip(&model.links).enumerate().rev() {
        let pa = ws.force[i];
        if link.nv == 1 {
            let k = link.v_offset;
            let s = &ws.cdof[k];
            let u = mul(&ws.aba_ia[i], s);
            let d = s.dot(&u);
            if !(d.is_finite() && d > 0.0) {
                return Err(DynamicsError::MassMatrixNotPositiveDefinite);
            }
            (ws.aba_u[i], ws.aba_d[i], ws.aba_uj[i]) = (u, d, tau[k] - s.dot(&pa));
        }
        // a root passes nothing on
        let Some(p) = body.parent else { continue };
        let c = ws.aba_c[i];
        let ia = &mut ws.aba_ia[i];
        // what the parent receives: `I^a` into `ia` in place, `p^a` returned
        let pass = match link.nv {
            // a fixed joint: `S̄ q̇ = 0`, so `c̄ = 0` and the whole `p^A` passes on
            0 => pa,
            1 => {
                let (u, d, uj) = (ws.aba_u[i], ws.aba_d[i], ws.aba_uj[i]);
                subtract_outer(ia, &u, d);
                pa + mul(ia, &c) + u * (uj / d)
            }
            _ => {
                let t = Vector6::from_column_slice(&tau[link.v_offset..link.v_offset + 6]);
                ws.x_root[i].transpose_apply_force(&t)
            }
        };
        if link.nv != 6 {
            let (parents, rest) = ws.aba_ia.split_at_mut(i);
            parents[p] += &rest[0];
        }
        ws.force[p] += pass;
    }
    let a_base = spatial(&Vector3::zeros(), &(-model.gravity()));
    for (i, (body, link)) in bodies.iter().zip(&model.links).enumerate() {
        let a = ws.aba_c[i]
            + match body.parent {
                Some(p) => ws.acc[p],
                None => ws.x_up[i].apply_motion(&a_base),
            };
        let k = link.v_offset;
        ws.acc[i] = match link.nv {
            0 => a,
            1 => {
                let qdd = (ws.aba_uj[i] - ws.aba_u[i].dot(&a)) / ws.aba_d[i];
                ws.vdot[k] = qdd;
                a + ws.cdof[k] * qdd
            }
            _ => {
                let t = Vector6::from_column_slice(&tau[k..k + 6]);
                let mut acc = match body.parent {
                    Some(_) => ws.x_root[i].transpose_apply_force(&t),
                    None => t,
                } - ws.force[i];
                solve_spd(&ws.aba_ia[i], &mut acc)?;
                let qdd = match body.parent {
                    Some(_) => ws.x_root[i].apply_motion(&(acc - a)),
                    None => acc - a,
                };
                ws.vdot.rows_mut(k, 6).copy_from(&qdd);
                acc
            }
        };
    }
    Ok(&ws.vdot)
}

/// Writes the 6 × 6 matrix `[Ī, h×; h×^T, m 1]` of `inertia` into `m` in place.
#[inline(always)]
fn set_inertia(m: &mut Matrix6<f64>, inertia: &RigidInertia) {
    let (h, ibar, mass) = (&inertia.h, &inertia.ibar, inertia.mass);
    let hx = [[0.0, -h.z, h.y], [h.z, 0.0, -h.x], [-h.y, h.x, 0.0]];
    for r in 0..3 {
        for c in 0..3 {
            m[(r, c)] = ibar[(r, c)];
            m[(r, c + 3)] = hx[r][c];
            m[(r + 3, c)] = hx[c][r];
            m[(r + 3, c + 3)] = if r == c { mass } else { 0.0 };
        }
    }
}

/// Solves `m x = b` in place (`x` holds `b`) for a symmetric positive definite 6 × 6 `m`
/// by its `L D Lᵀ` factors (unit lower `L`, from the lower triangle of `m`), in fixed-size
/// loops.
#[inline(always)]
fn solve_spd(m: &Matrix6<f64>, x: &mut Vector6<f64>) -> Result<(), DynamicsError> {
    let mut l = [[0.0; 6]; 6];
    let mut d = [0.0; 6];
    for j in 0..6 {
        let mut dj = m[(j, j)];
        for k in 0..j {
            dj -= l[j][k] * l[j][k] * d[k];
        }
        if !(dj.is_finite() && dj > 0.0) {
            return Err(DynamicsError::MassMatrixNotPositiveDefinite);
        }
        d[j] = dj;
        for i in j + 1..6 {
            let mut a = m[(i, j)];
            for k in 0..j {
                a -= l[i][k] * l[j][k] * d[k];
            }
            l[i][j] = a / dj;
        }
    }
    for i in 0..6 {
        for k in 0..i {
            x[i] -= l[i][k] * x[k];
        }
    }
    for i in 0..6 {
        x[i] /= d[i];
    }
    for i in (0..6).rev() {
        for k in i + 1..6 {
            x[i] -= l[k][i] * x[k];
        }
    }
    Ok(())
}

/// `m v` for a 6 × 6 matrix, written out (nalgebra's generic product does not unroll).
#[inline(always)]
fn mul(m: &Matrix6<f64>, v: &Vector6<f64>) -> Vector6<f64> {
    let mut out = Vector6::zeros();
    for c in 0..6 {
        for r in 0..6 {
            out[r] += m[(r, c)] * v[c];
        }
    }
    out
}

/// `m -= u uᵀ / d` (symmetric rank-one update).
#[inline(always)]
fn subtract_outer(m: &mut Matrix6<f64>, u: &Vector6<f64>, d: f64) {
    for c in 0..6 {
        let uc = u[c] / d;
        for r in 0..6 {
            m[(r, c)] -= u[r] * uc;
        }
    }
}
