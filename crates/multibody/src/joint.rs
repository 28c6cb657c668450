//! Joint models: joint transform `X_J(q)`, motion subspace `S` and the map from the
//! joint velocity to the configuration derivative (Featherstone, "Rigid Body Dynamics
//! Algorithms", 2008, chapter 4, Table 4.1).
//!
//! All joints here have a constant motion subspace in body coordinates, so the
//! velocity-product term `c_J` (Featherstone ch. 3/4, `c_J = S-ring qdot`) is zero.

use crate::spatial::SpatialTransform;
use nalgebra::{Matrix6, Quaternion, Rotation3, Unit, UnitQuaternion, Vector3};

/// The joint connecting a body to its parent, acting between the parent's joint frame
/// (the placement) and the body frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Joint {
    /// Six-DOF free joint. Configuration `q = [x, y, z, qw, qx, qy, qz]`: the body origin
    /// in the joint frame (the world for a root with identity placement) and the unit
    /// quaternion (scalar first) rotating body axes into joint-frame axes. Velocity
    /// `v = [omega; v_O]` in body coordinates (angular velocity, velocity of the body
    /// origin), so `S = 1_6`.
    Floating,
    /// Rotation by `q` (rad) about `axis` (joint-frame coordinates, unit length after
    /// validation); `S = [axis; 0]`.
    Revolute {
        /// Rotation axis.
        axis: Vector3<f64>,
    },
    /// Translation by `q` (m) along `axis` (joint-frame coordinates, unit length after
    /// validation); `S = [0; axis]`.
    Prismatic {
        /// Translation axis.
        axis: Vector3<f64>,
    },
    /// Rigid connection, no degree of freedom.
    Fixed,
}

impl Joint {
    /// Number of configuration coordinates (7 for `Floating`).
    pub fn nq(&self) -> usize {
        match self {
            Joint::Floating => 7,
            Joint::Revolute { .. } | Joint::Prismatic { .. } => 1,
            Joint::Fixed => 0,
        }
    }

    /// Number of velocity coordinates (degrees of freedom; 6 for `Floating`).
    pub fn nv(&self) -> usize {
        match self {
            Joint::Floating => 6,
            Joint::Revolute { .. } | Joint::Prismatic { .. } => 1,
            Joint::Fixed => 0,
        }
    }

    /// Joint transform `X_J(q)` from the joint frame to the body frame
    /// (Featherstone 2008, Table 4.1). `q` holds this joint's `nq()` entries. The
    /// floating-joint quaternion is normalised when read, so integration drift does not
    /// distort the kinematics. Revolute and prismatic axes are assumed unit length, as
    /// [`crate::ModelBuilder::build`] stores them.
    pub fn transform(&self, q: &[f64]) -> SpatialTransform {
        match self {
            Joint::Floating => {
                let r = floating_rotation(q);
                SpatialTransform {
                    rot: r.to_rotation_matrix().into_inner().transpose(),
                    pos: Vector3::new(q[0], q[1], q[2]),
                }
            }
            Joint::Revolute { axis } => {
                let r = Rotation3::from_axis_angle(&Unit::new_unchecked(*axis), q[0]);
                SpatialTransform {
                    rot: r.into_inner().transpose(),
                    pos: Vector3::zeros(),
                }
            }
            Joint::Prismatic { axis } => SpatialTransform {
                rot: nalgebra::Matrix3::identity(),
                pos: axis * q[0],
            },
            Joint::Fixed => SpatialTransform::identity(),
        }
    }

    /// Motion subspace `S` in body coordinates; only the first `nv()` columns are used.
    pub fn motion_subspace(&self) -> Matrix6<f64> {
        let mut s = Matrix6::zeros();
        match self {
            Joint::Floating => s = Matrix6::identity(),
            Joint::Revolute { axis } => s.fixed_view_mut::<3, 1>(0, 0).copy_from(axis),
            Joint::Prismatic { axis } => s.fixed_view_mut::<3, 1>(3, 0).copy_from(axis),
            Joint::Fixed => {}
        }
        s
    }

    /// Configuration derivative `qdot` from the joint velocity `v`: identity for 1-DOF
    /// joints; for `Floating`, `pdot = R v_O` and `Qdot = 1/2 Q (0, omega)`
    /// (quaternion product, body-frame angular velocity).
    pub fn velocity_to_qdot(&self, q: &[f64], v: &[f64], qdot: &mut [f64]) {
        match self {
            Joint::Floating => {
                let r = floating_rotation(q);
                let pdot = r * Vector3::new(v[3], v[4], v[5]);
                let quat = Quaternion::new(q[3], q[4], q[5], q[6]);
                let omega = Quaternion::new(0.0, v[0], v[1], v[2]);
                let qd = quat * omega * 0.5;
                qdot[..3].copy_from_slice(pdot.as_slice());
                qdot[3] = qd.w;
                qdot[4] = qd.i;
                qdot[5] = qd.j;
                qdot[6] = qd.k;
            }
            Joint::Revolute { .. } | Joint::Prismatic { .. } => qdot[0] = v[0],
            Joint::Fixed => {}
        }
    }
}

/// Unit quaternion of a floating joint's configuration `[x, y, z, qw, qx, qy, qz]`.
pub fn floating_rotation(q: &[f64]) -> UnitQuaternion<f64> {
    UnitQuaternion::from_quaternion(Quaternion::new(q[3], q[4], q[5], q[6]))
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector6;

    #[test]
    fn revolute_transform_rotates_body_axes_about_the_axis() {
        let j = Joint::Revolute { axis: Vector3::z() };
        let x = j.transform(&[std::f64::consts::FRAC_PI_2]);
        // Body x axis points along joint-frame y: a joint-frame y vector is body x.
        let v = x.rot * Vector3::y();
        assert!((v - Vector3::x()).norm() < 1e-15);
    }

    #[test]
    fn floating_transform_and_subspace_are_consistent() {
        let j = Joint::Floating;
        let s = j.motion_subspace();
        assert_eq!(s, Matrix6::identity());
        let q = [1.0, 2.0, 3.0, 0.5, 0.5, 0.5, 0.5];
        let x = j.transform(&q);
        let body_origin_in_body = x.apply_motion(&Vector6::zeros());
        assert_eq!(body_origin_in_body, Vector6::zeros());
        assert!((x.pos - Vector3::new(1.0, 2.0, 3.0)).norm() < 1e-15);
    }

    #[test]
    fn quaternion_derivative_preserves_the_norm() {
        let q = [0.0, 0.0, 0.0, 0.8, 0.0, 0.6, 0.0];
        let v = [0.3, -1.0, 2.0, 0.0, 0.0, 0.0];
        let mut qd = [0.0; 7];
        Joint::Floating.velocity_to_qdot(&q, &v, &mut qd);
        let dot: f64 = (3..7).map(|k| q[k] * qd[k]).sum();
        assert!(dot.abs() < 1e-15);
    }
}
