//! Rigid-body spatial inertia by its ten parameters (mass, first moment, rotational
//! inertia about the frame origin), the form CRBA accumulates (Featherstone, "Rigid Body
//! Dynamics Algorithms", 2008, ch. 2, spatial inertia and its coordinate transform).
//!
//! `I = [Ī, h×; h×^T, m 1]` with `h = m c` and `Ī = I_c + m c× c×^T` about the origin.
//! Composite inertias are sums of these, so they keep the form; transforming the ten
//! parameters costs a few 3x3 products instead of the two 6x6 products of `X^T I X`.

use crate::spatial::{angular, linear, skew, spatial, SpatialTransform};
use nalgebra::{Matrix3, Vector3, Vector6};

/// Spatial inertia `[Ī, h×; h×^T, m 1]` about a frame origin, in that frame's axes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct RigidInertia {
    /// Mass m, kg.
    pub(crate) mass: f64,
    /// First moment of mass `h = m c`, kg m.
    pub(crate) h: Vector3<f64>,
    /// Rotational inertia about the frame origin `Ī`, kg m².
    pub(crate) ibar: Matrix3<f64>,
}

impl RigidInertia {
    /// Zero inertia (a massless body).
    pub(crate) fn zero() -> Self {
        Self {
            mass: 0.0,
            h: Vector3::zeros(),
            ibar: Matrix3::zeros(),
        }
    }

    /// The body of `mass` with centre of mass `com` and rotational inertia `inertia_com`
    /// about it (body axes): `h = m c`, `Ī = I_c + m c× c×^T`.
    pub(crate) fn new(mass: f64, com: &Vector3<f64>, inertia_com: &Matrix3<f64>) -> Self {
        let cx = skew(com);
        Self {
            mass,
            h: mass * com,
            ibar: inertia_com + mass * cx * cx.transpose(),
        }
    }

    /// The rigid body of `mass` with centre of mass `com` and rotational inertia
    /// `inertia_com` about it (B coordinates) expressed in A coordinates, `x = B X A`: the
    /// same as `RigidInertia::new(mass, com, inertia_com).in_parent(x)`, by the
    /// parallel-axis theorem about the transformed centre of mass (Featherstone 2008,
    /// ch. 2): `c_A = r + E^T c`, `h_A = m c_A`, `Ī_A = E^T I_c E + m (|c_A|² 1 - c_A c_A^T)`.
    /// Two 3x3 products instead of the four of [`Self::in_parent`]; with `diagonal` (the
    /// off-diagonal entries of `inertia_com` are zero, the caller has checked) the first
    /// product is the row scaling `I_c E`, with the same values.
    #[inline]
    pub(crate) fn body_in(
        mass: f64,
        com: &Vector3<f64>,
        inertia_com: &Matrix3<f64>,
        diagonal: bool,
        x: &SpatialTransform,
    ) -> Self {
        let e = &x.rot;
        let c = x.pos + e.tr_mul(com);
        let mc = mass * c;
        // E^T I_c E is symmetric: one product M = I_c E, then the six entries of E^T M.
        let m = if diagonal {
            Matrix3::from_fn(|r, k| inertia_com[(r, r)] * e[(r, k)])
        } else {
            inertia_com * e
        };
        let entry = |a: usize, b: usize| {
            e[(0, a)] * m[(0, b)] + e[(1, a)] * m[(1, b)] + e[(2, a)] * m[(2, b)] - mc[a] * c[b]
        };
        let diagonal = mc.dot(&c);
        let (xy, xz, yz) = (entry(0, 1), entry(0, 2), entry(1, 2));
        let ibar = Matrix3::new(
            entry(0, 0) + diagonal,
            xy,
            xz,
            xy,
            entry(1, 1) + diagonal,
            yz,
            xz,
            yz,
            entry(2, 2) + diagonal,
        );
        Self { mass, h: mc, ibar }
    }

    /// `I m`: the momentum `[Ī ω + h × v; m v - h × ω]` of motion `m = [ω; v]`.
    pub(crate) fn apply(&self, m: &Vector6<f64>) -> Vector6<f64> {
        let (w, v) = (angular(m), linear(m));
        spatial(
            &(self.ibar * w + self.h.cross(&v)),
            &(self.mass * v - self.h.cross(&w)),
        )
    }

    /// `X^T I X` for `x = B X A` and `self` in B coordinates: the same inertia in A
    /// coordinates (Featherstone 2008, ch. 2): with `h' = E^T h`,
    /// `h_A = h' + m r` and `Ī_A = E^T Ī E - m r× r× - r× h'× - h'× r×`. The reference for
    /// [`Self::body_in`], which CRBA uses.
    #[cfg(test)]
    pub(crate) fn in_parent(&self, x: &SpatialTransform) -> Self {
        let et = x.rot.transpose();
        let hp = et * self.h;
        let rx = skew(&x.pos);
        let hx = skew(&hp);
        let cross = rx * hx;
        Self {
            mass: self.mass,
            h: hp + self.mass * x.pos,
            ibar: et * self.ibar * x.rot - self.mass * rx * rx - cross - cross.transpose(),
        }
    }

    /// The 6x6 matrix `[Ī, h×; h×^T, m 1]`.
    #[cfg(test)]
    pub(crate) fn matrix(&self) -> nalgebra::Matrix6<f64> {
        let hx = skew(&self.h);
        let mut i = nalgebra::Matrix6::zeros();
        i.fixed_view_mut::<3, 3>(0, 0).copy_from(&self.ibar);
        i.fixed_view_mut::<3, 3>(0, 3).copy_from(&hx);
        i.fixed_view_mut::<3, 3>(3, 0).copy_from(&hx.transpose());
        i.fixed_view_mut::<3, 3>(3, 3)
            .copy_from(&(self.mass * Matrix3::identity()));
        i
    }
}

impl std::ops::AddAssign for RigidInertia {
    fn add_assign(&mut self, other: Self) {
        self.mass += other.mass;
        self.h += other.h;
        self.ibar += other.ibar;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spatial::rigid_body_inertia;
    use nalgebra::{Isometry3, Translation3, UnitQuaternion};

    fn body() -> (f64, Vector3<f64>, Matrix3<f64>) {
        let ic = Matrix3::new(3.0, 0.2, -0.1, 0.2, 4.0, 0.3, -0.1, 0.3, 5.0);
        (2.5, Vector3::new(0.2, -0.1, 0.4), ic)
    }

    #[test]
    fn matrix_form_is_the_rigid_body_inertia() {
        let (m, c, ic) = body();
        let i = RigidInertia::new(m, &c, &ic);
        assert!((i.matrix() - rigid_body_inertia(m, &c, &ic)).norm() < 1e-12);
        let v = Vector6::new(0.3, -0.2, 0.5, 1.0, -2.0, 0.4);
        assert!((i.apply(&v) - i.matrix() * v).norm() < 1e-12);
    }

    #[test]
    fn transform_to_parent_matches_x_transpose_i_x() {
        let (m, c, ic) = body();
        let i = RigidInertia::new(m, &c, &ic);
        let x = SpatialTransform::from_pose(&Isometry3::from_parts(
            Translation3::new(0.3, -1.2, 0.7),
            UnitQuaternion::from_euler_angles(0.4, -0.9, 1.3),
        ));
        let xm = x.motion_matrix();
        let expected = xm.transpose() * i.matrix() * xm;
        let got = i.in_parent(&x).matrix();
        assert!((got - expected).norm() < 1e-12 * expected.norm());
        // A composite (sum) transforms as the sum of its parts.
        let mut sum = i;
        sum += RigidInertia::new(0.0, &Vector3::zeros(), &Matrix3::zeros());
        sum += RigidInertia::new(1.0, &Vector3::new(-0.5, 0.0, 0.1), &Matrix3::identity());
        let direct = RigidInertia::body_in(m, &c, &ic, false, &x).matrix();
        assert!((direct - i.in_parent(&x).matrix()).norm() < 1e-12 * expected.norm());
        // A diagonal inertia by the row-scaling product: the same values as the full one.
        let diag = Matrix3::from_diagonal(&ic.diagonal());
        let scaled = RigidInertia::body_in(m, &c, &diag, true, &x);
        assert_eq!(scaled, RigidInertia::body_in(m, &c, &diag, false, &x));
        let reference = RigidInertia::new(m, &c, &diag).in_parent(&x).matrix();
        assert!((scaled.matrix() - reference).norm() < 1e-12 * reference.norm());
        let expected = xm.transpose() * sum.matrix() * xm;
        assert!((sum.in_parent(&x).matrix() - expected).norm() < 1e-12 * expected.norm());
    }
}
