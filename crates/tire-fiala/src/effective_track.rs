//! A precomputed effective contact along one track, so the enveloping (circle-line
//! Eqs 2.2-2.4 or tandem cams Eqs 6.1-6.3) does not run inside a vehicle's right-hand side.
//!
//! The contact of a tire under a reference deflection `delta_ref` is computed once per run
//! on a uniform grid along the track: the wheel-centre height `z_ref(s)` at which the
//! enveloped deflection equals `delta_ref`, and the slope `theta(s)` of P1P2 (Eqs 2.4 / 6.3).
//! During the run the deflection is the normal penetration of the wheel into that effective
//! line, `delta = delta_ref + (z_ref(s) - z_c) cos theta(s)`: exact on a plane, and to first
//! order in the load change on rough ground. Its rate with the line held fixed is
//! `v_s sin theta - v_z cos theta`.

use crate::envelope::Envelope;
use crate::error::{positive, TireError};
use crate::terrain::Profile;

/// Largest number of grid points of one effective track (bounds the allocation).
pub const MAX_TRACK_POINTS: usize = 4_000_000;

/// Newton steps per grid point of the cache (at most).
pub const NEWTON_ITERATIONS: usize = 4;

/// Newton steps smaller than this (m) end the iteration of a grid point: the step after
/// it is second order, far below 10 µm.
pub const NEWTON_TOLERANCE_M: f64 = 1e-3;

/// The enveloped contact of one tire along one track at a reference deflection (module
/// docs), on a uniform grid in the path coordinate `s`.
#[derive(Debug, Clone, PartialEq)]
pub struct EffectiveTrack {
    s0: f64,
    ds: f64,
    reference_deflection: f64,
    wheel_z: Vec<f64>,
    slope: Vec<f64>,
}

/// The contact of one tire at one instant, from an [`EffectiveTrack`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TrackContact {
    /// Normal penetration delta (m), positive in contact.
    pub deflection: f64,
    /// Slope theta of the effective line P1P2 along the path (rad), Eqs 2.4 / 6.3.
    pub slope: f64,
}

impl EffectiveTrack {
    /// Precompute the track of `profile` for `s` in `[s_start, s_end]` at grid spacing
    /// `ds` (m) with `envelope`, at deflection `reference_deflection` (m, in
    /// `[0, radius)`). At most [`MAX_TRACK_POINTS`] grid points.
    pub fn build<P: Profile + ?Sized>(
        profile: &P,
        (s_start, s_end): (f64, f64),
        ds: f64,
        envelope: &Envelope,
        reference_deflection: f64,
    ) -> Result<Self, TireError> {
        let ds = positive("track_grid_m", ds)?;
        let radius = envelope.radius();
        if !(reference_deflection.is_finite() && (0.0..radius).contains(&reference_deflection)) {
            return Err(TireError::InvalidParameter {
                field: "reference_deflection_m",
                value: reference_deflection,
                reason: "must be in [0, free radius)",
            });
        }
        let span = s_end - s_start;
        if !(s_start.is_finite() && span.is_finite() && span >= 0.0) {
            return Err(TireError::InvalidParameter {
                field: "track_length_m",
                value: span,
                reason: "the track range must be finite and not inverted",
            });
        }
        let n = (span / ds).ceil() + 2.0;
        if n > MAX_TRACK_POINTS as f64 {
            return Err(TireError::InvalidParameter {
                field: "track_length_m",
                value: span,
                reason: "too many enveloping grid points (length / grid above 4e6)",
            });
        }
        let n = n as usize;
        let mut wheel_z = Vec::with_capacity(n);
        let mut slope = Vec::with_capacity(n);
        let mut z = f64::NAN;
        for i in 0..n {
            let s = s_start + i as f64 * ds;
            if !z.is_finite() {
                z = profile.height_at(s) + radius - reference_deflection;
            }
            // Newton on the wheel height, d(delta)/dz = -cos(theta), warm-started from the
            // previous grid point (one step is usually enough); the profile under the
            // wheel is sampled once for all its iterations.
            let c = envelope.contacts_at(profile, s, |contact| {
                let mut c = contact(z);
                for _ in 0..NEWTON_ITERATIONS {
                    let step = (c.deflection - reference_deflection) / c.slope.cos().max(0.1);
                    z += step;
                    c = contact(z);
                    if step.abs() < NEWTON_TOLERANCE_M {
                        break;
                    }
                }
                c
            });
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
    /// grid): linear interpolation of the cache, then the penetration of the module docs.
    #[inline]
    pub fn contact(&self, s: f64, z_c: f64) -> TrackContact {
        let u = ((s - self.s0) / self.ds).max(0.0);
        let last = self.wheel_z.len() - 1;
        let i = (u as usize).min(last - 1);
        let w = (u - i as f64).min(1.0);
        let z_ref = self.wheel_z[i] + w * (self.wheel_z[i + 1] - self.wheel_z[i]);
        let slope = self.slope[i] + w * (self.slope[i + 1] - self.slope[i]);
        TrackContact {
            deflection: self.reference_deflection + (z_ref - z_c) * slope.cos(),
            slope,
        }
    }

    /// Path range covered `(s_start, s_end)` (m).
    pub fn range(&self) -> (f64, f64) {
        (self.s0, self.s0 + (self.wheel_z.len() - 1) as f64 * self.ds)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::envelope::EnvelopeMethod;

    #[test]
    fn flat_track_gives_the_exact_penetration() {
        let flat = |_x: f64| 0.1;
        for method in [EnvelopeMethod::CircleLine, EnvelopeMethod::TandemCams] {
            let env = Envelope::new(method, 1.06, 0.01).unwrap();
            let t = EffectiveTrack::build(&flat, (0.0, 10.0), 0.5, &env, 0.08).unwrap();
            let c = t.contact(3.3, 1.06 + 0.1 - 0.05);
            assert!((c.deflection - 0.05).abs() < 1e-6, "{method:?}: {c:?}");
            assert!(c.slope.abs() < 1e-12);
        }
    }

    #[test]
    fn cache_agrees_with_direct_enveloping_on_a_ramp_and_a_bump() {
        let bump = |x: f64| 0.05 * x + 0.1 * (-(x - 5.0) * (x - 5.0)).exp();
        let (r, dref) = (1.06, 0.08);
        for method in [EnvelopeMethod::CircleLine, EnvelopeMethod::TandemCams] {
            let env = Envelope::new(method, r, 0.01).unwrap();
            let t = EffectiveTrack::build(&bump, (0.0, 10.0), 0.02, &env, dref).unwrap();
            for &s in &[2.0, 4.5, 5.0, 5.31, 7.0] {
                let exact = env.at_deflection(&bump, s, dref).unwrap();
                let c = t.contact(s, exact.wheel_z);
                assert!(
                    (c.deflection - dref).abs() < 2e-4,
                    "{method:?} s = {s}: {c:?}"
                );
                assert!((c.slope - exact.contact.slope).abs() < 2e-3, "s = {s}");
                // a wheel 1 cm lower: first order in the load change
                let lower = env.contact(&bump, s, exact.wheel_z - 0.01).deflection;
                let cached = t.contact(s, exact.wheel_z - 0.01).deflection;
                assert!(
                    (lower - cached).abs() < 1.5e-3,
                    "{method:?} s = {s}: {lower} vs {cached}"
                );
            }
        }
    }

    #[test]
    fn bad_settings_are_named() {
        let flat = |_x: f64| 0.0;
        let env = Envelope::new(EnvelopeMethod::TandemCams, 1.0, 0.01).unwrap();
        let err = EffectiveTrack::build(&flat, (0.0, 1e9), 1e-3, &env, 0.05).unwrap_err();
        assert!(err.to_string().contains("track_length_m"), "{err}");
        let err = EffectiveTrack::build(&flat, (0.0, 1.0), 0.1, &env, 1.5).unwrap_err();
        assert!(err.to_string().contains("reference_deflection_m"), "{err}");
    }
}
