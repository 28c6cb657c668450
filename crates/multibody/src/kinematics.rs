//! Forward kinematics: body poses and spatial velocities by one outward pass over the
//! tree (Featherstone, "Rigid Body Dynamics Algorithms", 2008, ch. 4 and the first
//! loop of RNEA Table 5.1), plus point kinematics for contact and mount points.

use crate::error::DynamicsError;
use crate::joint::Joint;
use crate::model::{Link, Model};
use crate::spatial::{angular, cross_motion, linear, SpatialTransform};
use crate::workspace::Workspace;
use nalgebra::{Matrix3, Vector3, Vector6};

/// `S_i x_i` for the `nv` columns of the link's motion subspace, reading `x` at the
/// link's velocity offset.
pub(crate) fn subspace_times(link: &Link, x: &[f64]) -> Vector6<f64> {
    let mut out = Vector6::zeros();
    for k in 0..link.nv {
        out += link.subspace.column(k) * x[link.v_offset + k];
    }
    out
}

/// `iXλ = X_J(q) X_T` (Featherstone 2008, ch. 4): [`SpatialTransform::after`] specialised
/// per joint type, leaving out the products by the zero offset of a revolute joint, by the
/// identity rotation of a prismatic joint, and by a placement rotation that is exactly the
/// identity. The same values as `joint.transform(q).after(&link.x_tree)`.
fn joint_after_placement(joint: &Joint, q: &[f64], link: &Link) -> SpatialTransform {
    let tree = &link.x_tree;
    match joint {
        Joint::Revolute { .. } => {
            let rot = joint.transform(q).rot;
            SpatialTransform {
                rot: if link.tree_translation_only {
                    rot
                } else {
                    rot * tree.rot
                },
                pos: tree.pos,
            }
        }
        Joint::Prismatic { axis } => {
            let offset = axis * q[0];
            SpatialTransform {
                rot: tree.rot,
                pos: if link.tree_translation_only {
                    tree.pos + offset
                } else {
                    tree.pos + tree.rot.transpose() * offset
                },
            }
        }
        Joint::Floating if link.tree_translation_only => {
            let x = joint.transform(q);
            SpatialTransform {
                rot: x.rot,
                pos: tree.pos + x.pos,
            }
        }
        Joint::Floating => joint.transform(q).after(tree),
        Joint::Fixed => *tree,
    }
}

/// Computes every body's transforms `i X lambda(i)`, pose `i X 0` and spatial velocity
/// (body coordinates) at state `(q, v)`, stores `v` for the dynamics, and clears the
/// external forces. Call once per ODE right-hand-side evaluation, before applying
/// external forces and calling [`crate::forward_dynamics`]. Allocation free.
///
/// `q` has length [`Model::nq`], `v` length [`Model::nv`].
pub fn update_kinematics(
    model: &Model,
    ws: &mut Workspace,
    q: &[f64],
    v: &[f64],
) -> Result<(), DynamicsError> {
    ws.check_size(model)?;
    check_len("q", q, model.nq())?;
    check_len("v", v, model.nv())?;
    for (i, (body, link)) in model.bodies().iter().zip(&model.links).enumerate() {
        let qi = &q[link.q_offset..link.q_offset + body.joint.nq()];
        let x_up = joint_after_placement(&body.joint, qi, link);
        let vj = subspace_times(link, v);
        let (x_world, vel) = match body.parent {
            Some(p) => (
                x_up.after(&ws.x_world[p]),
                x_up.apply_motion(&ws.vel[p]) + vj,
            ),
            None => (x_up, vj),
        };
        ws.x_up[i] = x_up;
        ws.x_world[i] = x_world;
        ws.vel[i] = vel;
        ws.vel_joint[i] = vj;
    }
    ws.v.copy_from_slice(v);
    ws.clear_external_forces();
    ws.kinematics_ready = true;
    ws.h_current = false;
    Ok(())
}

/// Computes every body's spatial acceleration (body coordinates) from the joint
/// accelerations `vdot` at the state of the last [`update_kinematics`]:
/// `a_i = X_up a_parent + S_i vdot_i + v_i x S_i v_i` (Featherstone 2008, Table 5.1, with
/// `c_J = 0` for this crate's joints), for [`Workspace::point_acceleration`]. Allocation free.
pub fn update_accelerations(
    model: &Model,
    ws: &mut Workspace,
    vdot: &[f64],
) -> Result<(), DynamicsError> {
    ws.check(model)?;
    check_len("vdot", vdot, model.nv())?;
    for (i, (body, link)) in model.bodies().iter().zip(&model.links).enumerate() {
        let aj = subspace_times(link, vdot) + cross_motion(&ws.vel[i], &ws.vel_joint[i]);
        ws.acc_abs[i] = match body.parent {
            Some(p) => ws.x_up[i].apply_motion(&ws.acc_abs[p]) + aj,
            None => aj,
        };
    }
    Ok(())
}

/// Fails with [`DynamicsError::DimensionMismatch`] unless `x.len() == expected`.
pub(crate) fn check_len(
    argument: &'static str,
    x: &[f64],
    expected: usize,
) -> Result<(), DynamicsError> {
    if x.len() == expected {
        Ok(())
    } else {
        Err(DynamicsError::DimensionMismatch {
            argument,
            expected,
            got: x.len(),
        })
    }
}

impl Workspace {
    /// Rotation matrix of `body` (body axes in world coordinates: world = R body) from the
    /// last [`update_kinematics`].
    ///
    /// # Panics
    /// If `body` is out of range.
    pub fn body_rotation(&self, body: usize) -> Matrix3<f64> {
        self.x_world[body].rot.transpose()
    }

    /// World position of `body`'s frame origin, m.
    ///
    /// # Panics
    /// If `body` is out of range.
    pub fn body_position(&self, body: usize) -> Vector3<f64> {
        self.x_world[body].pos
    }

    /// Spatial velocity `[omega; v_O]` of `body` in body coordinates.
    ///
    /// # Panics
    /// If `body` is out of range.
    pub fn body_velocity(&self, body: usize) -> Vector6<f64> {
        self.vel[body]
    }

    /// World position of the point fixed in `body` at `point` (body coordinates), m.
    ///
    /// # Panics
    /// If `body` is out of range.
    pub fn point_position(&self, body: usize, point: &Vector3<f64>) -> Vector3<f64> {
        let x = &self.x_world[body];
        x.pos + x.rot.transpose() * point
    }

    /// World velocity of the point fixed in `body` at `point` (body coordinates), m/s:
    /// `R (v_O + omega x r)`.
    ///
    /// # Panics
    /// If `body` is out of range.
    pub fn point_velocity(&self, body: usize, point: &Vector3<f64>) -> Vector3<f64> {
        let v = &self.vel[body];
        self.x_world[body].rot.transpose() * (linear(v) + angular(v).cross(point))
    }

    /// Spatial acceleration `[alpha; a_O]` of `body` in body coordinates from the last
    /// [`update_accelerations`] (`alpha` is the angular acceleration in body axes).
    ///
    /// # Panics
    /// If `body` is out of range.
    pub fn body_acceleration(&self, body: usize) -> Vector6<f64> {
        self.acc_abs[body]
    }

    /// World acceleration of the point fixed in `body` at `point` (body coordinates), m/s²,
    /// from the last [`update_accelerations`]: `R (a_O + alpha x r + omega x (v_O + omega x r))`
    /// with the spatial acceleration `[alpha; a_O]` and velocity `[omega; v_O]`.
    ///
    /// # Panics
    /// If `body` is out of range.
    pub fn point_acceleration(&self, body: usize, point: &Vector3<f64>) -> Vector3<f64> {
        let (a, v) = (&self.acc_abs[body], &self.vel[body]);
        let w = angular(v);
        let local = linear(a) + angular(a).cross(point) + w.cross(&(linear(v) + w.cross(point)));
        self.x_world[body].rot.transpose() * local
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Isometry3, Matrix6, Translation3, UnitQuaternion};

    fn link(placement: &Isometry3<f64>) -> Link {
        let x_tree = SpatialTransform::from_pose(placement);
        Link {
            tree_translation_only: x_tree.rot == Matrix3::identity(),
            x_tree,
            inertia: Matrix6::identity(),
            rigid_inertia: crate::inertia::RigidInertia::zero(),
            inertia_diagonal: true,
            subspace: Matrix6::identity(),
            nv: 0,
            q_offset: 0,
            v_offset: 0,
        }
    }

    #[test]
    fn joint_after_placement_equals_the_general_composition() {
        let axis = Vector3::new(0.3, -0.8, 0.52).normalize();
        let joints = [
            (Joint::Revolute { axis }, vec![0.7]),
            (Joint::Prismatic { axis }, vec![-0.4]),
            (Joint::Floating, vec![0.2, -1.0, 3.0, 0.8, 0.2, -0.4, 0.4]),
            (Joint::Fixed, vec![]),
        ];
        let shift = Translation3::new(1.2, -0.3, 0.45);
        let placements = [
            Isometry3::from_parts(shift, UnitQuaternion::identity()),
            Isometry3::from_parts(shift, UnitQuaternion::from_euler_angles(0.3, -0.2, 1.1)),
        ];
        for placement in &placements {
            let link = link(placement);
            for (joint, q) in &joints {
                let general = joint.transform(q).after(&link.x_tree);
                let special = joint_after_placement(joint, q, &link);
                assert_eq!(special, general, "{joint:?} at {placement:?}");
            }
        }
    }
}
