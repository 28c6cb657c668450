//! Spatial (6D) vector algebra: Plücker transforms, cross products and rigid-body
//! spatial inertia (Featherstone, "Rigid Body Dynamics Algorithms", 2008, chapter 2).
//!
//! Every spatial vector is a [`Vector6`] ordered `[angular; linear]`: a motion vector is
//! `[omega; v_O]` (angular velocity, velocity of the body point at the frame origin `O`),
//! a force vector is `[n_O; f]` (moment about `O`, force).

use nalgebra::{Isometry3, Matrix3, Matrix6, Vector3, Vector6};

/// Skew-symmetric matrix `[a]x` with `[a]x b = a x b`.
pub fn skew(a: &Vector3<f64>) -> Matrix3<f64> {
    Matrix3::new(0.0, -a.z, a.y, a.z, 0.0, -a.x, -a.y, a.x, 0.0)
}

/// Angular (first three) part of a spatial vector.
pub fn angular(m: &Vector6<f64>) -> Vector3<f64> {
    Vector3::new(m[0], m[1], m[2])
}

/// Linear (last three) part of a spatial vector.
pub fn linear(m: &Vector6<f64>) -> Vector3<f64> {
    Vector3::new(m[3], m[4], m[5])
}

/// Spatial vector from its angular and linear parts, order `[angular; linear]`.
pub fn spatial(angular: &Vector3<f64>, linear: &Vector3<f64>) -> Vector6<f64> {
    Vector6::new(
        angular.x, angular.y, angular.z, linear.x, linear.y, linear.z,
    )
}

/// Spatial motion cross product `v x m` (Featherstone 2008, ch. 2, spatial cross products).
pub fn cross_motion(v: &Vector6<f64>, m: &Vector6<f64>) -> Vector6<f64> {
    let (w, vo) = (angular(v), linear(v));
    let (mw, mo) = (angular(m), linear(m));
    spatial(&w.cross(&mw), &(w.cross(&mo) + vo.cross(&mw)))
}

/// Spatial force cross product `v x* f` (Featherstone 2008, ch. 2, spatial cross products), equal to
/// `-(v x)^T f`.
pub fn cross_force(v: &Vector6<f64>, f: &Vector6<f64>) -> Vector6<f64> {
    let (w, vo) = (angular(v), linear(v));
    let (n, fl) = (angular(f), linear(f));
    spatial(&(w.cross(&n) + vo.cross(&fl)), &w.cross(&fl))
}

/// Plücker coordinate transform `B X A` from frame A to frame B (Featherstone 2008,
/// ch. 2, coordinate transforms): `X = [E 0; -E [r]x E]`.
///
/// `rot` is `E`, the rotation taking A coordinates to B coordinates, and `pos` is `r`,
/// the position of B's origin expressed in A coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpatialTransform {
    /// `E`: coordinates in A to coordinates in B (the transpose of B's axes in A).
    pub rot: Matrix3<f64>,
    /// `r`: origin of B in A coordinates.
    pub pos: Vector3<f64>,
}

impl SpatialTransform {
    /// The identity transform (B coincides with A).
    pub fn identity() -> Self {
        Self {
            rot: Matrix3::identity(),
            pos: Vector3::zeros(),
        }
    }

    /// Transform from A to B where `pose` is the pose of frame B in frame A
    /// (B's axes and origin expressed in A): `E = R^T`, `r = t`.
    pub fn from_pose(pose: &Isometry3<f64>) -> Self {
        Self {
            rot: pose.rotation.to_rotation_matrix().into_inner().transpose(),
            pos: pose.translation.vector,
        }
    }

    /// `X m`: a motion vector in A coordinates expressed in B (Featherstone 2008, ch. 2).
    pub fn apply_motion(&self, m: &Vector6<f64>) -> Vector6<f64> {
        let w = angular(m);
        let v = linear(m);
        spatial(&(self.rot * w), &(self.rot * (v - self.pos.cross(&w))))
    }

    /// `X^-1 m`: a motion vector in B coordinates expressed in A.
    pub fn inverse_apply_motion(&self, m: &Vector6<f64>) -> Vector6<f64> {
        let w = self.rot.transpose() * angular(m);
        let v = self.rot.transpose() * linear(m);
        spatial(&w, &(v + self.pos.cross(&w)))
    }

    /// `X* f = X^-T f`: a force vector in A coordinates expressed in B
    /// (Featherstone 2008, ch. 2).
    pub fn apply_force(&self, f: &Vector6<f64>) -> Vector6<f64> {
        let n = angular(f);
        let fl = linear(f);
        spatial(&(self.rot * (n - self.pos.cross(&fl))), &(self.rot * fl))
    }

    /// `X^T f`: a force vector in B coordinates expressed in A (the transpose used by
    /// RNEA and CRBA to pass forces from a body to its parent).
    pub fn transpose_apply_force(&self, f: &Vector6<f64>) -> Vector6<f64> {
        let n = self.rot.transpose() * angular(f);
        let fl = self.rot.transpose() * linear(f);
        spatial(&(n + self.pos.cross(&fl)), &fl)
    }

    /// Composition `C X A = (C X B)(B X A)` with `self = C X B` and `a_to_b = B X A`
    /// (Featherstone 2008, ch. 2).
    pub fn after(&self, a_to_b: &SpatialTransform) -> SpatialTransform {
        SpatialTransform {
            rot: self.rot * a_to_b.rot,
            pos: a_to_b.pos + a_to_b.rot.transpose() * self.pos,
        }
    }

    /// The 6x6 motion-transform matrix `[E 0; -E [r]x E]`.
    pub fn motion_matrix(&self) -> Matrix6<f64> {
        let mut x = Matrix6::zeros();
        let lower = -self.rot * skew(&self.pos);
        x.fixed_view_mut::<3, 3>(0, 0).copy_from(&self.rot);
        x.fixed_view_mut::<3, 3>(3, 3).copy_from(&self.rot);
        x.fixed_view_mut::<3, 3>(3, 0).copy_from(&lower);
        x
    }

    /// `X^T I X`: a spatial inertia in B coordinates expressed in A
    /// (Featherstone 2008, ch. 2, inertia transform; used by CRBA, Table 6.2).
    pub fn transform_inertia_to_parent(&self, inertia: &Matrix6<f64>) -> Matrix6<f64> {
        let x = self.motion_matrix();
        x.transpose() * inertia * x
    }
}

/// Spatial inertia of a rigid body about its frame origin, in its own coordinates
/// (Featherstone 2008, ch. 2, spatial inertia): `[I_c + m [c]x [c]x^T, m [c]x; m [c]x^T, m 1]`.
///
/// `mass` in kg, `com` the centre of mass in body coordinates, `inertia_com` the 3x3
/// rotational inertia about the centre of mass in body axes.
pub fn rigid_body_inertia(
    mass: f64,
    com: &Vector3<f64>,
    inertia_com: &Matrix3<f64>,
) -> Matrix6<f64> {
    let cx = skew(com);
    let mut i = Matrix6::zeros();
    let upper_left = inertia_com + mass * cx * cx.transpose();
    i.fixed_view_mut::<3, 3>(0, 0).copy_from(&upper_left);
    i.fixed_view_mut::<3, 3>(0, 3).copy_from(&(mass * cx));
    i.fixed_view_mut::<3, 3>(3, 0)
        .copy_from(&(mass * cx.transpose()));
    i.fixed_view_mut::<3, 3>(3, 3)
        .copy_from(&(mass * Matrix3::identity()));
    i
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Translation3, UnitQuaternion};

    fn sample() -> SpatialTransform {
        let pose = Isometry3::from_parts(
            Translation3::new(0.3, -1.2, 0.7),
            UnitQuaternion::from_euler_angles(0.4, -0.9, 1.3),
        );
        SpatialTransform::from_pose(&pose)
    }

    fn close(a: &Vector6<f64>, b: &Vector6<f64>) -> bool {
        (a - b).norm() <= 1e-12 * (1.0 + a.norm())
    }

    #[test]
    fn motion_and_force_transforms_match_the_matrix_forms() {
        let x = sample();
        let m = Vector6::new(0.1, -0.4, 0.9, 1.5, 0.2, -0.7);
        let xm = x.motion_matrix();
        assert!(close(&x.apply_motion(&m), &(xm * m)));
        assert!(close(&x.transpose_apply_force(&m), &(xm.transpose() * m)));
        let xinv = xm.try_inverse().expect("Plücker transforms are invertible");
        assert!(close(&x.inverse_apply_motion(&m), &(xinv * m)));
        assert!(close(&x.apply_force(&m), &(xinv.transpose() * m)));
    }

    #[test]
    fn composition_matches_matrix_product() {
        let a = sample();
        let b = SpatialTransform::from_pose(&Isometry3::from_parts(
            Translation3::new(-0.5, 0.1, 2.0),
            UnitQuaternion::from_euler_angles(-1.1, 0.2, 0.3),
        ));
        let ab = b.after(&a);
        let diff = ab.motion_matrix() - b.motion_matrix() * a.motion_matrix();
        assert!(diff.norm() < 1e-12);
    }

    #[test]
    fn force_cross_is_minus_transpose_of_motion_cross() {
        let v = Vector6::new(0.3, -0.2, 0.5, 1.0, -2.0, 0.4);
        let f = Vector6::new(-1.0, 0.7, 0.2, 0.3, 0.9, -0.5);
        let m = Vector6::new(0.6, 0.1, -0.8, -0.3, 0.4, 1.1);
        // (v x* f) . m = -f . (v x m)
        let lhs = cross_force(&v, &f).dot(&m);
        let rhs = -f.dot(&cross_motion(&v, &m));
        assert!((lhs - rhs).abs() < 1e-12);
    }

    #[test]
    fn inertia_about_origin_gives_momentum_of_com() {
        let m = 2.5;
        let c = Vector3::new(0.2, -0.1, 0.4);
        let ic = Matrix3::new(1.0, 0.1, 0.0, 0.1, 2.0, 0.2, 0.0, 0.2, 3.0);
        let i = rigid_body_inertia(m, &c, &ic);
        let v = Vector6::new(0.3, -0.2, 0.5, 1.0, -2.0, 0.4);
        let (w, vo) = (angular(&v), linear(&v));
        let vc = vo + w.cross(&c);
        let h = i * v;
        assert!((linear(&h) - m * vc).norm() < 1e-12);
        assert!((angular(&h) - (ic * w + c.cross(&(m * vc)))).norm() < 1e-12);
    }
}
