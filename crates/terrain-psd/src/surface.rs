//! A synthesized (or measured) two-track profile as a terrain surface a tire can drive on:
//! [`TwoTrackTerrain`] implements [`vehicle_components::Terrain`].
//!
//! Geometry (terrain frame x forward, y left, z up, as in `vehicle_components::terrain`):
//! the left track `q(x)` lies on the line `y = +B/2`, the right track `p(x)` on `y = -B/2`,
//! `B` the track width ([`SurfaceParams::track_width_m`]), and x runs along the profile from 0
//! to its length. The height is
//!
//! ```text
//! h(x, y) = p(x_c) + t (q(x_c) - p(x_c)),   t = clamp((y + B/2) / B, 0, 1),
//! x_c = clamp(x, 0, length)
//! ```
//!
//! with `q`, `p` linearly interpolated between samples ([`TwoTrackProfile::heights_at`]):
//! between the tracks the surface is ruled (linear across y), so its cross slope is exactly
//! the roll excitation `(q - p)/B` of [`TwoTrackProfile::cross_slope_rad`]; outside the tracks
//! it holds the nearer track's height, and beyond the ends of the profile it holds the end
//! values. Interpolating across y (rather than taking the nearest track) keeps the surface
//! continuous, so the gradient normal is defined everywhere. The friction coefficient is
//! uniform, [`SurfaceParams::friction`].

use serde::{Deserialize, Serialize};
use vehicle_components::{Terrain, DEFAULT_FRICTION};

use crate::error::{non_negative, positive, Result, TerrainError};
use crate::summary::AFSV_TRACK_WIDTH_M;
use crate::synth::TwoTrackProfile;

/// Surface parameters of a two-track terrain, SI units.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct SurfaceParams {
    /// Track width B (m), the lateral distance between the left and right tracks. Nominal:
    /// 2.28 m, the track of the 35-t AFSV (Table 6.1).
    pub track_width_m: f64,
    /// Tire-terrain friction coefficient mu (-). Nominal: 0.8, an assumption (dry haul
    /// road; the paper gives none).
    pub friction: f64,
}

impl SurfaceParams {
    /// Track width of Table 6.1 and the assumed friction of a dry haul road.
    pub fn nominal() -> Self {
        Self {
            track_width_m: AFSV_TRACK_WIDTH_M,
            friction: DEFAULT_FRICTION,
        }
    }

    /// Check every field: `track_width_m` finite and > 0, `friction` finite and >= 0.
    pub fn validate(&self) -> Result<()> {
        positive("track_width_m", self.track_width_m)?;
        non_negative("friction", self.friction)?;
        Ok(())
    }
}

impl Default for SurfaceParams {
    fn default() -> Self {
        Self::nominal()
    }
}

/// A two-track profile laid out on the ground plane (module docs for the geometry).
#[derive(Debug, Clone, PartialEq)]
pub struct TwoTrackTerrain {
    profile: TwoTrackProfile,
    params: SurfaceParams,
}

impl TwoTrackTerrain {
    /// Validated: `params` as in [`SurfaceParams::validate`]; the profile has a finite
    /// `dx_m > 0`, at least 2 samples, tracks of equal length and finite elevations.
    pub fn new(profile: TwoTrackProfile, params: SurfaceParams) -> Result<Self> {
        params.validate()?;
        positive("dx", profile.dx_m)?;
        if profile.left_m.len() != profile.right_m.len() {
            return Err(TerrainError::Signal(format!(
                "left track has {} samples, right track {}",
                profile.left_m.len(),
                profile.right_m.len()
            )));
        }
        if profile.len() < 2 {
            return Err(TerrainError::Signal(
                "a terrain profile needs at least 2 samples".into(),
            ));
        }
        let bad = profile
            .left_m
            .iter()
            .chain(&profile.right_m)
            .position(|z| !z.is_finite());
        if let Some(i) = bad {
            let (track, k) = if i < profile.len() {
                ("left", i)
            } else {
                ("right", i - profile.len())
            };
            return Err(TerrainError::Signal(format!(
                "{track} track elevation {k} is not finite"
            )));
        }
        Ok(Self { profile, params })
    }

    /// The profile.
    pub fn profile(&self) -> &TwoTrackProfile {
        &self.profile
    }

    /// The surface parameters.
    pub fn params(&self) -> &SurfaceParams {
        &self.params
    }
}

impl Terrain for TwoTrackTerrain {
    /// Module docs: interpolated along x, linear across y between the tracks, held outside.
    /// NaN coordinates give NaN.
    #[inline]
    fn height(&self, x: f64, y: f64) -> f64 {
        let xc = x.clamp(0.0, self.profile.length_m());
        let Some((left, right)) = self.profile.heights_at(xc) else {
            return f64::NAN;
        };
        let b = self.params.track_width_m;
        let t = ((y + 0.5 * b) / b).clamp(0.0, 1.0);
        right + t * (left - right)
    }

    #[inline]
    fn friction(&self, _x: f64, _y: f64) -> f64 {
        self.params.friction
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::synth::{synthesize, TwoTrackSpec};

    fn ramp() -> TwoTrackProfile {
        // Left rises 1 cm per sample, right falls 1 cm per sample, dx = 0.5 m.
        TwoTrackProfile {
            dx_m: 0.5,
            left_m: vec![0.0, 0.01, 0.02, 0.03],
            right_m: vec![0.0, -0.01, -0.02, -0.03],
        }
    }

    fn params(b: f64) -> SurfaceParams {
        SurfaceParams {
            track_width_m: b,
            friction: 0.6,
        }
    }

    #[test]
    fn tracks_lie_at_plus_and_minus_half_the_track_width() {
        let t = TwoTrackTerrain::new(ramp(), params(2.0)).unwrap();
        assert_eq!(t.height(1.0, 1.0), 0.02);
        assert_eq!(t.height(1.0, -1.0), -0.02);
        assert_eq!(t.height(1.0, 0.0), 0.0);
        assert!((t.height(1.25, 0.5) - 0.5 * (0.025 + 0.0)).abs() < 1e-15);
        // Held outside the tracks and beyond the ends.
        assert_eq!(t.height(1.0, 3.0), 0.02);
        assert_eq!(t.height(1.0, -7.0), -0.02);
        assert_eq!(t.height(-4.0, 1.0), 0.0);
        assert_eq!(t.height(9.0, 1.0), 0.03);
        assert!(t.height(f64::NAN, 0.0).is_nan());
        assert_eq!(t.friction(0.3, 0.1), 0.6);
    }

    #[test]
    fn normal_carries_the_cross_slope() {
        // At (0.75, 0): q = 0.015, p = -0.015, so dh/dy = (q - p)/B = 0.015 and
        // dh/dx = (q' + p')/2 = 0.
        let t = TwoTrackTerrain::new(ramp(), params(2.0)).unwrap();
        let n = t.normal(0.75, 0.0);
        let (q_x, p_x) = t.profile().heights_at(0.75).unwrap();
        let hy = (q_x - p_x) / 2.0;
        assert!((hy - 0.015).abs() < 1e-15);
        let q = (1.0f64 + hy * hy).sqrt();
        assert!(n[0].abs() < 1e-12, "{n:?}");
        assert!((n[1] + hy / q).abs() < 1e-12, "{n:?}");
        assert!((n[2] - 1.0 / q).abs() < 1e-12, "{n:?}");
        // At a sample the same slope as the profile's roll excitation.
        let cross = t.profile().cross_slope_rad(2.0);
        assert!(
            (t.normal(0.5, 0.0)[1] + cross[1] / (1.0 + cross[1] * cross[1]).sqrt()).abs() < 1e-9
        );
    }

    #[test]
    fn a_synthesized_profile_is_a_terrain() {
        let spec = TwoTrackSpec::paper_nominal();
        let p = synthesize(&spec, 20.0, 0.05, 4).unwrap();
        let (l, r) = (p.left_m[100], p.right_m[100]);
        let t = TwoTrackTerrain::new(p, SurfaceParams::nominal()).unwrap();
        let half = 0.5 * AFSV_TRACK_WIDTH_M;
        assert!((t.height(5.0, half) - l).abs() < 1e-12);
        assert!((t.height(5.0, -half) - r).abs() < 1e-12);
        for i in 0..200 {
            let x = -1.0 + 0.11 * i as f64;
            let y = -2.0 + 0.02 * i as f64;
            let n = t.normal(x, y);
            let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            assert!((len - 1.0).abs() < 1e-12 && n[2] > 0.0);
            assert!(t.height(x, y).is_finite());
        }
    }

    #[test]
    fn construction_validates_profile_and_params() {
        assert!(TwoTrackTerrain::new(ramp(), params(0.0)).is_err());
        let mut p = params(2.0);
        p.friction = f64::NAN;
        let e = TwoTrackTerrain::new(ramp(), p).unwrap_err().to_string();
        assert!(e.contains("friction"), "{e}");
        let mut r = ramp();
        r.right_m.pop();
        assert!(TwoTrackTerrain::new(r, params(2.0)).is_err());
        let mut r = ramp();
        r.dx_m = -1.0;
        assert!(TwoTrackTerrain::new(r, params(2.0)).is_err());
        let mut r = ramp();
        r.right_m[2] = f64::INFINITY;
        let e = TwoTrackTerrain::new(r, params(2.0))
            .unwrap_err()
            .to_string();
        assert!(e.contains("right track elevation 2"), "{e}");
        let short = TwoTrackProfile {
            dx_m: 0.1,
            left_m: vec![0.0],
            right_m: vec![0.0],
        };
        assert!(TwoTrackTerrain::new(short, params(2.0)).is_err());
        let q: SurfaceParams = serde_json::from_str(r#"{"friction": 0.5}"#).unwrap();
        assert_eq!(q.track_width_m, AFSV_TRACK_WIDTH_M);
        assert!(serde_json::from_str::<SurfaceParams>(r#"{"mu": 0.5}"#).is_err());
    }
}
