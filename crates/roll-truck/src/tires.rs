//! The tires of Chapter 2: circle-line enveloping on the two-track terrain (Eqs 2.2-2.4),
//! vertical contact with loss of contact (Eq 2.1), linear cornering with the stiffness
//! interpolated against the instantaneous load (Eq 2.5) and lateral relaxation
//! (Eqs 2.6-2.7).
//!
//! Terrain: every left tire runs on the left track `q(s)` of the two-track terrain, every
//! right tire on the right track `p(s)` (the two tracks of Eq 2.10; the chapter gives no
//! track spacing for the coherence model, so front and rear wheels share the two
//! profiles). The profiles are read through [`vehicle_components::Terrain`] on the lines
//! `y = +-B/2` of the terrain, and `s` is the distance along the truck's path: the road is
//! laid along the path the truck drives (as a TruckSim road follows its reference path), so
//! a cornering truck stays on its two tracks.
//!
//! Enveloping cache: the circle-line contact of a tire under its static load is
//! precomputed once per run on a grid along each track ([`EffectiveTrack`]), one cache per
//! side shared by the front and rear tires at the mean of their static deflections: the
//! wheel height `z_ref(s)` at which the circle-line deflection equals that deflection
//! `delta_ref`, and the slope `theta(s)` of P1P2 (Eq 2.4). During the run the deflection is
//! the normal penetration of the wheel into that effective line,
//! `delta = delta_ref + (z_ref(s) - z_c) cos theta(s)`, exact on a plane and to first order
//! in the load change on rough ground, and its rate is `v_s sin theta - v_z cos theta`.

use tire_fiala::{Envelope, EnvelopeMethod, Profile};

use crate::error::{positive, TruckError};

/// Largest number of grid points of one effective track (bounds the allocation).
pub const MAX_TRACK_POINTS: usize = 4_000_000;

/// Newton steps per grid point of the cache (at most).
pub const NEWTON_ITERATIONS: usize = 4;

/// Newton steps smaller than this (m) end the iteration of a grid point: the step after
/// it is second order, far below 10 µm (18 N of tire force at the Table 2.3 rate).
pub const NEWTON_TOLERANCE_M: f64 = 1e-3;

/// The circle-line contact of one tire along one track at its static deflection
/// (module docs), on a uniform grid in the path coordinate `s`.
#[derive(Debug, Clone, PartialEq)]
pub struct EffectiveTrack {
    s0: f64,
    ds: f64,
    reference_deflection: f64,
    wheel_z: Vec<f64>,
    slope: Vec<f64>,
}

/// The contact of one tire at one instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Contact {
    /// Normal penetration delta (m), positive in contact.
    pub deflection: f64,
    /// Slope theta of the effective line P1P2 along the path (rad), Eq 2.4.
    pub slope: f64,
}

impl EffectiveTrack {
    /// Precompute the track of `profile` for `s` in `[s_start, s_end]` at grid spacing
    /// `ds` (m) with the circle-line enveloping of a tire of free radius `radius` sampled
    /// at `sample_spacing`, at deflection `reference_deflection` (m, in `[0, radius)`).
    pub fn build<P: Profile + ?Sized>(
        profile: &P,
        (s_start, s_end): (f64, f64),
        ds: f64,
        radius: f64,
        sample_spacing: f64,
        reference_deflection: f64,
    ) -> Result<Self, TruckError> {
        let ds = positive("track_grid_m", ds)?;
        let envelope = Envelope::new(EnvelopeMethod::CircleLine, radius, sample_spacing)?;
        let span = s_end - s_start;
        if !(s_start.is_finite() && span.is_finite() && span >= 0.0) {
            return Err(crate::error::rejected(
                "track_length_m",
                span,
                "the track range must be finite and not inverted",
            ));
        }
        let n = (span / ds).ceil() as usize + 2;
        if n > MAX_TRACK_POINTS {
            return Err(crate::error::rejected(
                "track_length_m",
                span,
                "too many enveloping grid points (length / grid above 4e6)",
            ));
        }
        let mut wheel_z = Vec::with_capacity(n);
        let mut slope = Vec::with_capacity(n);
        let mut z = f64::NAN;
        for i in 0..n {
            let s = s_start + i as f64 * ds;
            if !z.is_finite() {
                z = profile.height_at(s) + radius - reference_deflection;
            }
            // Newton on the wheel height, d(delta)/dz = -cos(theta), warm-started from the
            // previous grid point (one step is usually enough).
            let mut c = envelope.contact(profile, s, z);
            for _ in 0..NEWTON_ITERATIONS {
                let step = (c.deflection - reference_deflection) / c.slope.cos().max(0.1);
                z += step;
                c = envelope.contact(profile, s, z);
                if step.abs() < NEWTON_TOLERANCE_M {
                    break;
                }
            }
            wheel_z.push(z);
            slope.push(c.slope);
        }
        Ok(Self {
            s0: s_start,
            ds,
            reference_deflection,
            wheel_z,
            slope,
        })
    }

    /// Contact of a wheel with centre height `z_c` at path coordinate `s` (clamped to the
    /// grid): linear interpolation of the cache, then the penetration of module docs.
    #[inline]
    pub fn contact(&self, s: f64, z_c: f64) -> Contact {
        let u = ((s - self.s0) / self.ds).max(0.0);
        let last = self.wheel_z.len() - 1;
        let i = (u as usize).min(last - 1);
        let w = (u - i as f64).min(1.0);
        let z_ref = self.wheel_z[i] + w * (self.wheel_z[i + 1] - self.wheel_z[i]);
        let slope = self.slope[i] + w * (self.slope[i + 1] - self.slope[i]);
        Contact {
            deflection: self.reference_deflection + (z_ref - z_c) * slope.cos(),
            slope,
        }
    }

    /// Path range covered `(s_start, s_end)` (m).
    pub fn range(&self) -> (f64, f64) {
        (self.s0, self.s0 + (self.wheel_z.len() - 1) as f64 * self.ds)
    }
}

/// Lateral force law of Eqs 2.5-2.6: `F_y = -k_ty(F_z) alpha`, `alpha = atan(V_sy / |V_x|)`
/// with `k_ty = coefficient * max(F_z, 0)` (the line through the Table 2.3 point), the
/// speed regularised as in `tire_fiala::relaxation`. Zero out of contact.
#[inline]
pub fn lateral_force(coefficient_per_rad: f64, normal_force: f64, v_sy: f64, v_x: f64) -> f64 {
    let alpha = (v_sy / tire_fiala::relaxation::regularised_speed(v_x)).atan();
    -coefficient_per_rad * normal_force.max(0.0) * alpha
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flat_track_gives_the_exact_penetration() {
        let flat = |_x: f64| 0.1;
        let t = EffectiveTrack::build(&flat, (0.0, 10.0), 0.5, 1.06, 0.01, 0.08).unwrap();
        let c = t.contact(3.3, 1.06 + 0.1 - 0.05);
        assert!((c.deflection - 0.05).abs() < 1e-6, "{c:?}");
        assert!(c.slope.abs() < 1e-12);
    }

    #[test]
    fn cache_agrees_with_direct_circle_line_on_a_ramp_and_a_bump() {
        let bump = |x: f64| 0.05 * x + 0.1 * (-(x - 5.0) * (x - 5.0)).exp();
        let (r, dref) = (1.06, 0.08);
        let t = EffectiveTrack::build(&bump, (0.0, 10.0), 0.02, r, 0.01, dref).unwrap();
        let env = Envelope::new(EnvelopeMethod::CircleLine, r, 0.01).unwrap();
        for &s in &[2.0, 4.5, 5.0, 5.31, 7.0] {
            let exact = env.at_deflection(&bump, s, dref).unwrap();
            let c = t.contact(s, exact.wheel_z);
            assert!((c.deflection - dref).abs() < 2e-4, "s = {s}: {c:?}");
            assert!((c.slope - exact.contact.slope).abs() < 2e-3, "s = {s}");
            // a wheel 1 cm lower: first order in the load change; on the crest of this
            // bump (curvature radius 5 m) the circle-line deflection grows 1.4 mm less
            let lower = env.contact(&bump, s, exact.wheel_z - 0.01).deflection;
            let cached = t.contact(s, exact.wheel_z - 0.01).deflection;
            assert!(
                (lower - cached).abs() < 1.5e-3,
                "s = {s}: {lower} vs {cached}"
            );
        }
    }

    #[test]
    fn lateral_force_is_odd_in_slip_and_zero_without_load() {
        let f = lateral_force(57.3, 140e3, 0.1, 10.0);
        assert!(f < 0.0);
        assert_eq!(lateral_force(57.3, 140e3, -0.1, 10.0), -f);
        assert_eq!(lateral_force(57.3, 0.0, 0.1, 10.0), 0.0);
        assert_eq!(lateral_force(57.3, -5.0, 0.1, 10.0), 0.0);
    }
}
