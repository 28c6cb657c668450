//! The terrain a vehicle drives on, after Chrono::Vehicle's `ChTerrain`: height, unit
//! normal and friction coefficient at a point of the ground plane.
//!
//! Convention (used by every implementation and every user):
//!
//! - terrain frame: right-handed, x forward (the direction of travel of a profile), y to
//!   the left, z up; SI units (m);
//! - [`Terrain::height`] is the elevation z (m) of the surface above the point (x, y);
//! - [`Terrain::normal`] is the unit outward normal (pointing out of the ground, `n_z > 0`)
//!   of the surface z = h(x, y); by default it comes from the height gradient,
//!   `n = (-dh/dx, -dh/dy, 1) / sqrt(1 + (dh/dx)^2 + (dh/dy)^2)`, with central differences
//!   of step [`NORMAL_STEP_M`];
//! - [`Terrain::friction`] is the tire-road friction coefficient mu (-, >= 0) at (x, y);
//!   a tire model takes its peak friction from it.
//!
//! Implementations return finite heights for finite (x, y); the default normal falls back to
//! the vertical `(0, 0, 1)` where the difference quotient is not finite, so a normal is
//! never NaN.

use crate::error::{finite, non_negative, ComponentError};

/// Step (m) of the central differences of the default [`Terrain::normal`].
pub const NORMAL_STEP_M: f64 = 1e-3;

/// A friction coefficient for terrains that do not know better (-): the default of
/// Chrono's `FlatTerrain`, a dry haul road.
pub const DEFAULT_FRICTION: f64 = 0.8;

/// Height, normal and friction at one point, as [`Terrain::properties`] returns them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TerrainPoint {
    /// Elevation z (m).
    pub height: f64,
    /// Unit outward normal `[n_x, n_y, n_z]`.
    pub normal: [f64; 3],
    /// Friction coefficient mu (-).
    pub friction: f64,
}

/// A rigid terrain surface z = h(x, y) with a friction coefficient (module docs for the
/// convention). Mirrors `ChTerrain::GetHeight / GetNormal / GetCoefficientFriction`.
pub trait Terrain {
    /// Elevation z (m, up) of the surface at `(x, y)` (m).
    fn height(&self, x: f64, y: f64) -> f64;

    /// Friction coefficient mu (-) at `(x, y)`.
    fn friction(&self, x: f64, y: f64) -> f64;

    /// Unit outward normal at `(x, y)`; by default from the height gradient
    /// ([`gradient_normal`]).
    fn normal(&self, x: f64, y: f64) -> [f64; 3] {
        gradient_normal(self, x, y)
    }

    /// All three at once (`ChTerrain::GetProperties`).
    fn properties(&self, x: f64, y: f64) -> TerrainPoint {
        TerrainPoint {
            height: self.height(x, y),
            normal: self.normal(x, y),
            friction: self.friction(x, y),
        }
    }
}

impl<T: Terrain + ?Sized> Terrain for &T {
    #[inline]
    fn height(&self, x: f64, y: f64) -> f64 {
        (**self).height(x, y)
    }
    #[inline]
    fn friction(&self, x: f64, y: f64) -> f64 {
        (**self).friction(x, y)
    }
    #[inline]
    fn normal(&self, x: f64, y: f64) -> [f64; 3] {
        (**self).normal(x, y)
    }
}

/// A shared terrain is the terrain: what a cache that outlives its builder's borrow holds
/// (the 3-D vehicle's enveloping caches built on demand).
impl<T: Terrain + ?Sized> Terrain for std::sync::Arc<T> {
    #[inline]
    fn height(&self, x: f64, y: f64) -> f64 {
        (**self).height(x, y)
    }
    #[inline]
    fn friction(&self, x: f64, y: f64) -> f64 {
        (**self).friction(x, y)
    }
    #[inline]
    fn normal(&self, x: f64, y: f64) -> [f64; 3] {
        (**self).normal(x, y)
    }
}

/// Unit normal of `z = h(x, y)` from central differences of step [`NORMAL_STEP_M`]:
/// `(-h_x, -h_y, 1) / sqrt(1 + h_x^2 + h_y^2)`; `(0, 0, 1)` where a difference is not
/// finite.
pub fn gradient_normal<T: Terrain + ?Sized>(terrain: &T, x: f64, y: f64) -> [f64; 3] {
    let h = NORMAL_STEP_M;
    let hx = (terrain.height(x + h, y) - terrain.height(x - h, y)) / (2.0 * h);
    let hy = (terrain.height(x, y + h) - terrain.height(x, y - h)) / (2.0 * h);
    if !(hx.is_finite() && hy.is_finite()) {
        return [0.0, 0.0, 1.0];
    }
    let norm = (1.0 + hx * hx + hy * hy).sqrt();
    [-hx / norm, -hy / norm, 1.0 / norm]
}

/// Level ground of infinite extent at elevation `height` (m) with a uniform friction
/// coefficient (Chrono's `FlatTerrain`). Its normal is exactly `(0, 0, 1)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlatTerrain {
    height: f64,
    friction: f64,
}

impl FlatTerrain {
    /// Validated: `height` finite, `friction` finite and >= 0.
    pub fn new(height: f64, friction: f64) -> Result<Self, ComponentError> {
        Ok(Self {
            height: finite("height", height)?,
            friction: non_negative("friction", friction)?,
        })
    }

    /// Elevation (m).
    pub fn elevation(&self) -> f64 {
        self.height
    }
}

impl Terrain for FlatTerrain {
    #[inline]
    fn height(&self, _x: f64, _y: f64) -> f64 {
        self.height
    }
    #[inline]
    fn friction(&self, _x: f64, _y: f64) -> f64 {
        self.friction
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    struct Plane {
        sx: f64,
        sy: f64,
    }

    impl Terrain for Plane {
        fn height(&self, x: f64, y: f64) -> f64 {
            self.sx * x + self.sy * y
        }
        fn friction(&self, _x: f64, _y: f64) -> f64 {
            0.5
        }
    }

    #[test]
    fn flat_terrain_is_level_with_vertical_normal() {
        let f = FlatTerrain::new(1.5, 0.6).unwrap();
        let p = f.properties(3.0, -2.0);
        assert_eq!(p.height, 1.5);
        assert_eq!(p.normal, [0.0, 0.0, 1.0]);
        assert_eq!(p.friction, 0.6);
        assert_eq!(f.elevation(), 1.5);
        assert!(FlatTerrain::new(f64::INFINITY, 0.8).is_err());
        let e = FlatTerrain::new(0.0, -0.1).unwrap_err().to_string();
        assert!(e.contains("friction"), "{e}");
    }

    #[test]
    fn plane_normal_matches_the_analytic_one() {
        let p = Plane { sx: 0.1, sy: -0.2 };
        let n = p.normal(4.0, 1.0);
        let q = (1.0f64 + 0.01 + 0.04).sqrt();
        let expect = [-0.1 / q, 0.2 / q, 1.0 / q];
        for i in 0..3 {
            assert!((n[i] - expect[i]).abs() < 1e-12, "{n:?} vs {expect:?}");
        }
        // Through a reference the same.
        let by_ref: &dyn Terrain = &p;
        assert_eq!((&by_ref).normal(4.0, 1.0), n);
    }

    #[test]
    fn non_finite_height_gives_a_vertical_normal() {
        struct Hole;
        impl Terrain for Hole {
            fn height(&self, x: f64, _y: f64) -> f64 {
                if x > 0.0 {
                    f64::NAN
                } else {
                    0.0
                }
            }
            fn friction(&self, _x: f64, _y: f64) -> f64 {
                0.8
            }
        }
        assert_eq!(Hole.normal(0.0, 0.0), [0.0, 0.0, 1.0]);
        assert_eq!(Hole.normal(f64::NAN, 0.0), [0.0, 0.0, 1.0]);
    }

    proptest! {
        #[test]
        fn normal_is_a_unit_vector_pointing_up(
            a in -2.0..2.0f64, k in 0.1..10.0f64, x in -50.0..50.0f64, y in -5.0..5.0f64,
        ) {
            struct Waves { a: f64, k: f64 }
            impl Terrain for Waves {
                fn height(&self, x: f64, y: f64) -> f64 {
                    self.a * (self.k * x).sin() * (0.5 * self.k * y).cos()
                }
                fn friction(&self, _x: f64, _y: f64) -> f64 { 0.7 }
            }
            let n = Waves { a, k }.normal(x, y);
            let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            prop_assert!((len - 1.0).abs() < 1e-12);
            prop_assert!(n[2] > 0.0);
        }

        #[test]
        fn flat_normal_is_z_everywhere(z in -100.0..100.0f64, x in -1e4..1e4f64, y in -1e4..1e4f64) {
            let flat = FlatTerrain::new(z, DEFAULT_FRICTION).unwrap();
            prop_assert_eq!(flat.normal(x, y), [0.0, 0.0, 1.0]);
        }
    }
}
