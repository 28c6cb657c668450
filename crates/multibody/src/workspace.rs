//! Preallocated per-model buffers and the external-force accumulator.
//!
//! [`Workspace::new`] allocates every per-body buffer and the `nv x nv` / `nv` matrices
//! once; the kinematics and dynamics functions only write into them, so the hot path
//! (one ODE right-hand-side evaluation) performs no heap allocation.

use crate::error::DynamicsError;
use crate::inertia::RigidInertia;
use crate::ltdl::NONE;
use crate::model::Model;
use crate::spatial::{spatial, SpatialTransform};
use nalgebra::{DMatrix, DVector, Matrix6, Vector3, Vector6};

/// Per-evaluation state of one [`Model`]: transforms, velocities, accelerations, forces,
/// composite inertias, mass matrix (dense and packed), bias vector, accelerations and the
/// factor buffer.
#[derive(Debug, Clone)]
pub struct Workspace {
    /// `i X lambda(i)`: parent-to-body transforms.
    pub(crate) x_up: Vec<SpatialTransform>,
    /// `i X 0`: world-to-body transforms (body pose).
    pub(crate) x_world: Vec<SpatialTransform>,
    /// Body spatial velocities, body coordinates.
    pub(crate) vel: Vec<Vector6<f64>>,
    /// Joint velocities `S_i qdot_i`, body coordinates.
    pub(crate) vel_joint: Vec<Vector6<f64>>,
    /// RNEA accelerations, body coordinates.
    pub(crate) acc: Vec<Vector6<f64>>,
    /// Spatial accelerations of the last [`crate::update_accelerations`], body coordinates
    /// (without the gravity offset RNEA uses).
    pub(crate) acc_abs: Vec<Vector6<f64>>,
    /// RNEA joint forces, body coordinates.
    pub(crate) force: Vec<Vector6<f64>>,
    /// External forces on each body, body coordinates, about the body origin.
    pub(crate) f_ext: Vec<Vector6<f64>>,
    /// CRBA composite inertias, in the coordinates of each tree's root body.
    pub(crate) ic: Vec<RigidInertia>,
    /// Joint velocities of the last kinematics update.
    pub(crate) v: DVector<f64>,
    /// Joint-space mass matrix `H(q)`.
    pub(crate) h: DMatrix<f64>,
    /// Bias forces `C(q, v)`.
    pub(crate) c: DVector<f64>,
    /// Joint accelerations of the last forward-dynamics call.
    pub(crate) vdot: DVector<f64>,
    /// Transforms `i X r` from each body's tree-root body frame (CRBA in one frame per tree).
    pub(crate) x_root: Vec<SpatialTransform>,
    /// Motion subspace columns of every dof in its tree-root body frame.
    pub(crate) cdof: Vec<Vector6<f64>>,
    /// Packed rows of `H` along the ancestor chains (length `nv (nv + 1) / 2`, the
    /// model's [`crate::ltdl::DofTree`] uses the front).
    pub(crate) hs: Vec<f64>,
    /// Packed `L^T D L` factor of the last solve, same layout as `hs`.
    pub(crate) ldl: Vec<f64>,
    /// Dof parent array of the model whose sparsity pattern `h` holds (its other entries
    /// are zero).
    pub(crate) h_pattern: Vec<usize>,
    /// Articulated-body algorithm (`forward_dynamics_aba`), in each tree's root frame:
    /// body velocities `v̄_i`.
    pub(crate) aba_v: Vec<Vector6<f64>>,
    /// Velocity-product accelerations `c̄_i` (the bias forces `p^A_i` use `force`, the
    /// accelerations `acc`).
    pub(crate) aba_c: Vec<Vector6<f64>>,
    /// `I^A_i`.
    pub(crate) aba_ia: Vec<Matrix6<f64>>,
    /// `U_i = I^A_i S_i` of a one-dof joint.
    pub(crate) aba_u: Vec<Vector6<f64>>,
    /// `D_i = S_i^T U_i` of a one-dof joint.
    pub(crate) aba_d: Vec<f64>,
    /// `u_i = tau_i - S_i^T p^A_i` of a one-dof joint.
    pub(crate) aba_uj: Vec<f64>,
    /// Whether `h` and `hs` hold the mass matrix at the current kinematics.
    pub(crate) h_current: bool,
    /// Whether the dense `h` holds the packed `hs` (else [`Workspace::mass_matrix`]
    /// fills it first).
    pub(crate) h_dense_current: bool,
    /// Whether `update_kinematics` has filled the pose and velocity buffers.
    pub(crate) kinematics_ready: bool,
}

impl Workspace {
    /// Allocates all buffers for `model` (the only allocation of the crate's hot path).
    pub fn new(model: &Model) -> Self {
        let nb = model.num_bodies();
        let nv = model.nv();
        Self {
            x_up: vec![SpatialTransform::identity(); nb],
            x_world: vec![SpatialTransform::identity(); nb],
            vel: vec![Vector6::zeros(); nb],
            vel_joint: vec![Vector6::zeros(); nb],
            acc: vec![Vector6::zeros(); nb],
            acc_abs: vec![Vector6::zeros(); nb],
            force: vec![Vector6::zeros(); nb],
            f_ext: vec![Vector6::zeros(); nb],
            ic: vec![RigidInertia::zero(); nb],
            v: DVector::zeros(nv),
            h: DMatrix::zeros(nv, nv),
            c: DVector::zeros(nv),
            vdot: DVector::zeros(nv),
            x_root: vec![SpatialTransform::identity(); nb],
            cdof: vec![Vector6::zeros(); nv],
            hs: vec![0.0; nv * (nv + 1) / 2],
            ldl: vec![0.0; nv * (nv + 1) / 2],
            h_pattern: model.dofs.parent.clone(),
            aba_v: vec![Vector6::zeros(); nb],
            aba_c: vec![Vector6::zeros(); nb],
            aba_ia: vec![Matrix6::zeros(); nb],
            aba_u: vec![Vector6::zeros(); nb],
            aba_d: vec![0.0; nb],
            aba_uj: vec![0.0; nb],
            h_current: false,
            h_dense_current: true,
            kinematics_ready: false,
        }
    }

    /// Fails unless this workspace was built for `model` and the kinematics are current.
    pub(crate) fn check(&self, model: &Model) -> Result<(), DynamicsError> {
        self.check_size(model)?;
        if self.kinematics_ready {
            Ok(())
        } else {
            Err(DynamicsError::KinematicsNotUpdated)
        }
    }

    /// Fails unless this workspace was built for `model`.
    pub(crate) fn check_size(&self, model: &Model) -> Result<(), DynamicsError> {
        if self.x_up.len() == model.num_bodies() && self.v.len() == model.nv() {
            Ok(())
        } else {
            Err(DynamicsError::WorkspaceMismatch {
                workspace_bodies: self.x_up.len(),
                workspace_nv: self.v.len(),
                model_bodies: model.num_bodies(),
                model_nv: model.nv(),
            })
        }
    }

    /// Joint-space mass matrix of the last [`crate::mass_matrix`] or
    /// [`crate::forward_dynamics`] call. Those compute only its packed rows along the
    /// ancestor chains (the structural non-zeros, section 6.5 of Featherstone 2008); the
    /// dense symmetric matrix is written from them on the first request after each call,
    /// hence `&mut self`. Allocation free.
    pub fn mass_matrix(&mut self) -> &DMatrix<f64> {
        if !self.h_dense_current {
            let nv = self.h.nrows();
            let mut packed = self.hs.iter();
            for k in 0..nv {
                // Row k holds the chain k, λ(k), λ(λ(k)), ... of the model's parent array.
                let mut j = k;
                while j != NONE {
                    let h = *packed.next().expect("one packed entry per chain link");
                    self.h[(k, j)] = h;
                    self.h[(j, k)] = h;
                    j = self.h_pattern[j];
                }
            }
            self.h_dense_current = true;
        }
        &self.h
    }

    /// Bias forces of the last [`crate::bias_forces`] or [`crate::forward_dynamics`] call.
    pub fn bias_forces(&self) -> &DVector<f64> {
        &self.c
    }

    /// Joint accelerations of the last [`crate::forward_dynamics`] call.
    pub fn accelerations(&self) -> &DVector<f64> {
        &self.vdot
    }

    /// Removes all external forces (done by [`crate::update_kinematics`]).
    pub fn clear_external_forces(&mut self) {
        self.f_ext.iter_mut().for_each(|f| *f = Vector6::zeros());
    }

    /// Adds a world-frame force `force` (N) acting at the world point `point` (m) on
    /// `body`, using the pose of the last [`crate::update_kinematics`] call.
    ///
    /// # Panics
    /// If `body` is out of range.
    pub fn apply_force_world(&mut self, body: usize, force: &Vector3<f64>, point: &Vector3<f64>) {
        let x = &self.x_world[body];
        let f = x.rot * force;
        let r = x.rot * (point - x.pos);
        self.f_ext[body] += spatial(&r.cross(&f), &f);
    }

    /// Adds a body-frame force `force` (N) acting at the body point `point` (m, body
    /// coordinates) on `body`.
    ///
    /// # Panics
    /// If `body` is out of range.
    pub fn apply_force_body(&mut self, body: usize, force: &Vector3<f64>, point: &Vector3<f64>) {
        self.f_ext[body] += spatial(&point.cross(force), force);
    }

    /// Adds a pure world-frame moment `moment` (N m) on `body`.
    ///
    /// # Panics
    /// If `body` is out of range.
    pub fn apply_moment_world(&mut self, body: usize, moment: &Vector3<f64>) {
        let m = self.x_world[body].rot * moment;
        self.f_ext[body] += spatial(&m, &Vector3::zeros());
    }
}
