//! The ground seen by one wheel: a single track ([`Profile`], elevation along x) for the
//! in-plane enveloping, taken from any [`vehicle_components::Terrain`] ([`Track`]), a
//! measured or synthesized polyline, a closure or level ground.

use vehicle_components::{FlatTerrain, Terrain};

use crate::error::TireError;

/// A single track: terrain elevation (m) along a line, as a function of `x` (m).
/// This is what the in-plane enveloping of one wheel needs. Non-finite heights are ignored
/// by the enveloping routines (treated as "no ground there").
pub trait Profile {
    /// Elevation at longitudinal position `x`.
    fn height_at(&self, x: f64) -> f64;
}

/// Any `Fn(x) -> z` is a profile.
impl<F: Fn(f64) -> f64> Profile for F {
    #[inline]
    fn height_at(&self, x: f64) -> f64 {
        self(x)
    }
}

/// Level ground is the same profile on every line.
impl Profile for FlatTerrain {
    #[inline]
    fn height_at(&self, _x: f64) -> f64 {
        self.elevation()
    }
}

/// The track of a [`Terrain`] under a wheel at lateral position `y` (m).
#[derive(Debug, Clone, Copy)]
pub struct Track<T> {
    /// The terrain.
    pub terrain: T,
    /// Lateral position of the wheel's mid-plane (m).
    pub y: f64,
}

impl<T: Terrain> Profile for Track<T> {
    #[inline]
    fn height_at(&self, x: f64) -> f64 {
        self.terrain.height(x, self.y)
    }
}

/// A measured or synthesized profile given at points `(x_i, z_i)`, x strictly increasing:
/// linear interpolation between points, constant (end value) outside the range.
#[derive(Debug, Clone, PartialEq)]
pub struct PolylineProfile {
    xs: Vec<f64>,
    zs: Vec<f64>,
}

impl PolylineProfile {
    /// Validate: same length (>= 2), all finite, `xs` strictly increasing.
    pub fn new(xs: Vec<f64>, zs: Vec<f64>) -> Result<Self, TireError> {
        let bad = |reason: String| TireError::InvalidTable {
            table: "profile",
            reason,
        };
        if xs.len() != zs.len() {
            return Err(bad(format!(
                "{} x values but {} elevations",
                xs.len(),
                zs.len()
            )));
        }
        if xs.len() < 2 {
            return Err(bad("needs at least 2 points".into()));
        }
        for i in 0..xs.len() {
            if !(xs[i].is_finite() && zs[i].is_finite()) {
                return Err(bad(format!("point {i} is not finite")));
            }
            if i > 0 && xs[i] <= xs[i - 1] {
                return Err(bad(format!(
                    "x must increase strictly: point {i} has x = {} after {}",
                    xs[i],
                    xs[i - 1]
                )));
            }
        }
        Ok(Self { xs, zs })
    }

    /// The x coordinates (m).
    pub fn xs(&self) -> &[f64] {
        &self.xs
    }

    /// The elevations (m).
    pub fn zs(&self) -> &[f64] {
        &self.zs
    }
}

impl Profile for PolylineProfile {
    #[inline]
    fn height_at(&self, x: f64) -> f64 {
        let n = self.xs.len();
        if x.is_nan() {
            return f64::NAN;
        }
        if x <= self.xs[0] {
            return self.zs[0];
        }
        if x >= self.xs[n - 1] {
            return self.zs[n - 1];
        }
        let k = self.xs.partition_point(|&xi| xi <= x); // 1..n-1
        let (x0, x1) = (self.xs[k - 1], self.xs[k]);
        let (z0, z1) = (self.zs[k - 1], self.zs[k]);
        z0 + (z1 - z0) * (x - x0) / (x1 - x0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn polyline_interpolates_and_holds_ends() {
        let p = PolylineProfile::new(vec![0.0, 1.0, 3.0], vec![0.0, 1.0, 0.0]).unwrap();
        assert_eq!(p.height_at(0.5), 0.5);
        assert_eq!(p.height_at(2.0), 0.5);
        assert_eq!(p.height_at(-4.0), 0.0);
        assert_eq!(p.height_at(9.0), 0.0);
        assert_eq!(p.height_at(1.0), 1.0);
        assert!(PolylineProfile::new(vec![0.0, 0.0], vec![0.0, 1.0]).is_err());
        assert!(PolylineProfile::new(vec![0.0], vec![0.0]).is_err());
    }

    #[test]
    fn track_and_closure_are_profiles() {
        struct Slope;
        impl Terrain for Slope {
            fn height(&self, x: f64, y: f64) -> f64 {
                0.1 * x + 0.01 * y
            }
            fn friction(&self, _x: f64, _y: f64) -> f64 {
                0.8
            }
        }
        let t = Track {
            terrain: Slope,
            y: 2.0,
        };
        assert!((t.height_at(1.0) - 0.12).abs() < 1e-15);
        let f = |x: f64| 2.0 * x;
        assert_eq!(f.height_at(3.0), 6.0);
        let flat = FlatTerrain::new(0.3, 0.8).unwrap();
        assert_eq!(flat.height_at(1.0), 0.3);
    }
}
