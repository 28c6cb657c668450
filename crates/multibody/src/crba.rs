//! The composite-rigid-body algorithm (Featherstone, "Rigid Body Dynamics Algorithms",
//! 2008, section 6.2) evaluated in one common frame per tree, as MuJoCo's `mj_crb` does.
//!
//! Featherstone's Table 6.2 keeps every composite inertia in its own body's coordinates,
//! so it transforms each composite to its parent, `I^c_λ += X^T I^c_i X`, and carries every
//! column `F = I^c_i S_i` down the ancestor chain, `F <- X^T F`, one spatial transform per
//! ancestor and column. Here every quantity is instead expressed in the frame of the
//! tree's root body `r`, with the transform `i X r` composed once per body
//! (`i X r = i X λ(i) · λ(i) X r`). Then, with `S̄_k = (i X r)^-1 S_k` the motion
//! subspace column of dof `k` (joint of body `i`) in root coordinates, and
//! `Ī_i = (i X r)^T I_i (i X r)` the body inertia there:
//!
//! - composite inertias are plain sums, `Ī^c_i = Ī_i + Σ_{children c} Ī^c_c`
//!   (no transform per edge);
//! - `H[k, j] = S̄_j^T Ī^c_i S̄_k` for every dof `j` on the ancestor chain of `k`
//!   (including `k`): one product `F = Ī^c_i S̄_k` per dof and one 6-vector dot product
//!   per structural non-zero, no transform per ancestor; for a floating root,
//!   `S̄ = 1` and the entry is a component of `F`.
//!
//! The body inertias enter by the parallel-axis theorem about their transformed centres of
//! mass ([`RigidInertia::body_in`]); massless bodies are skipped.
//!
//! The root frame (rather than the world frame) keeps the lever arms short, so no precision
//! is lost to large positions, and makes `S̄ = S` for the root joint itself. The result
//! fills the packed rows of the tree-sparse factorisation ([`crate::ltdl`]), from which the
//! dense matrix of [`crate::mass_matrix`] is filled when asked for.

use crate::inertia::RigidInertia;
use crate::joint::Joint;
use crate::model::Model;
use crate::spatial::{spatial, SpatialTransform};
use crate::workspace::Workspace;
use nalgebra::{Vector3, Vector6};

/// Fills `ws.hs` (packed rows of `H`) at the configuration of the last kinematics update
/// (the caller has checked the workspace); the dense `ws.h` is filled from them on request
/// ([`Workspace::mass_matrix`]).
pub(crate) fn crba(model: &Model, ws: &mut Workspace) {
    let bodies = model.bodies();
    bodies_in_root_frames(model, ws);
    for (i, body) in bodies.iter().enumerate().rev() {
        if let Some(p) = body.parent {
            let ic = ws.ic[i];
            ws.ic[p] += ic;
        }
    }
    let tree = &model.dofs;
    for (i, link) in model.links.iter().enumerate() {
        if link.nv == 6 && tree.unit_axis[link.v_offset] == 0 {
            // A floating root: S̄ = 1, so its block is the composite inertia itself.
            let start = tree.row(link.v_offset).start;
            floating_root_block(&ws.ic[i], &mut ws.hs[start..start + 21]);
            continue;
        }
        for k in link.v_offset..link.v_offset + link.nv {
            let f = ws.ic[i].apply(&ws.cdof[k]);
            let (start, general, unit) = tree.split_row(k);
            let row = &mut ws.hs[start..start + general.len() + unit.len()];
            let (h_general, h_unit) = row.split_at_mut(general.len());
            for (h, &j) in h_general.iter_mut().zip(general) {
                *h = ws.cdof[j].dot(&f);
            }
            // A floating root's S̄_j = e_m: the entry is a component of F. Its dofs come
            // last in the chain, in descending order.
            if let Some(&first) = unit.first() {
                let m0 = tree.unit_axis[first];
                for (t, h) in h_unit.iter_mut().enumerate() {
                    *h = f[m0 - t];
                }
            }
        }
    }
    if ws.h_pattern != tree.parent {
        // Another model of the same size used this workspace: clear its non-zeros.
        ws.h.fill(0.0);
        ws.h_pattern.copy_from_slice(&tree.parent);
    }
    ws.h_dense_current = false;
    ws.h_current = true;
}

/// Every body's transform from its tree's root body `i X r` into `ws.x_root`, its own
/// inertia in root coordinates `Ī_i` into `ws.ic` (zero for a massless body), and its
/// motion subspace columns in root coordinates `S̄` into `ws.cdof` (module docs): what CRBA
/// and the articulated-body algorithm ([`crate::aba`]) both start from.
pub(crate) fn bodies_in_root_frames(model: &Model, ws: &mut Workspace) {
    let bodies = model.bodies();
    for (i, (body, link)) in bodies.iter().zip(&model.links).enumerate() {
        let dofs = link.v_offset..link.v_offset + link.nv;
        match body.parent {
            None => {
                ws.x_root[i] = SpatialTransform::identity();
                ws.ic[i] = link.rigid_inertia;
                for (k, s) in ws.cdof[dofs].iter_mut().enumerate() {
                    *s = link.subspace.column(k).into_owned();
                }
            }
            Some(p) => {
                let x = if bodies[p].parent.is_none() {
                    ws.x_up[i]
                } else {
                    ws.x_up[i].after(&ws.x_root[p])
                };
                ws.x_root[i] = x;
                ws.ic[i] = if body.mass == 0.0 {
                    RigidInertia::zero()
                } else {
                    RigidInertia::body_in(
                        body.mass,
                        &body.com,
                        &body.inertia,
                        link.inertia_diagonal,
                        &x,
                    )
                };
                subspace_in_root(&body.joint, &x, &mut ws.cdof[dofs]);
            }
        }
    }
}

/// The 21 packed entries of a floating root's rows (row `m` at `m (m + 1) / 2`, columns
/// `m, m - 1, ..., 0`): with `S̄ = 1`, `H[m, j] = I^c[j, m]` for the root's composite
/// inertia `I^c = [Ī, h×; h×^T, m 1]` (Featherstone 2008, ch. 2), the entries of
/// `F = I^c e_m` without the products by zeros.
fn floating_root_block(ic: &RigidInertia, block: &mut [f64]) {
    let block: &mut [f64; 21] = block.try_into().expect("a floating root has 21 entries");
    let h = &ic.h;
    // Column m of I^c, rows 0..=m (the upper triangle).
    let column = |m: usize, j: usize| match (j, m) {
        (j, m) if m < 3 => ic.ibar[(j, m)],
        (j, m) if j < 3 => match (j, m - 3) {
            (0, 1) => -h.z,
            (0, 2) => h.y,
            (1, 0) => h.z,
            (1, 2) => -h.x,
            (2, 0) => -h.y,
            (2, 1) => h.x,
            _ => 0.0,
        },
        (j, m) if j == m => ic.mass,
        _ => 0.0,
    };
    for m in 0..6 {
        let row = m * (m + 1) / 2;
        for t in 0..=m {
            block[row + t] = column(m, m - t);
        }
    }
}

/// The motion subspace columns of `joint` in root coordinates, `(i X r)^-1 S` with
/// `x = i X r`, specialised per joint type (Featherstone 2008, Table 4.1:
/// revolute `S = [a; 0]`, prismatic `S = [0; a]`, floating `S = 1`).
fn subspace_in_root(joint: &Joint, x: &SpatialTransform, out: &mut [Vector6<f64>]) {
    let et = x.rot.transpose();
    match joint {
        Joint::Revolute { axis } => {
            let w = et * axis;
            out[0] = spatial(&w, &x.pos.cross(&w));
        }
        Joint::Prismatic { axis } => out[0] = spatial(&Vector3::zeros(), &(et * axis)),
        Joint::Floating => {
            for k in 0..3 {
                let w = et.column(k).into_owned();
                out[k] = spatial(&w, &x.pos.cross(&w));
                out[k + 3] = spatial(&Vector3::zeros(), &w);
            }
        }
        Joint::Fixed => {}
    }
}
