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

use crate::envelope::{EffectiveContact, Envelope};
use crate::error::{positive, TireError};
use crate::on_demand::Grid;
use crate::sampled::SampledProfile;
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
///
/// Built whole ([`EffectiveTrack::build`]) or chunk by chunk as a run first reads it
/// ([`EffectiveTrack::on_demand`], for runs that may stop early): the same values to the
/// bit either way.
#[derive(Debug, PartialEq)]
pub struct EffectiveTrack {
    s0: f64,
    ds: f64,
    reference_deflection: f64,
    /// Per grid point the wheel-centre height `z_ref` and the slope `theta`.
    points: Grid,
}

/// The contact of one tire at one instant, from an [`EffectiveTrack`] (the default: all
/// zero, a placeholder).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct TrackContact {
    /// Normal penetration delta (m), positive in contact.
    pub deflection: f64,
    /// Slope theta of the effective line P1P2 along the path (rad), Eqs 2.4 / 6.3.
    pub slope: f64,
    /// `sin theta`, for the contact frame.
    pub sin_slope: f64,
    /// `cos theta`, which the penetration takes too.
    pub cos_slope: f64,
}

impl TrackContact {
    /// Out of contact or on level ground: `deflection` at slope 0.
    fn level(deflection: f64) -> Self {
        Self {
            deflection,
            slope: 0.0,
            sin_slope: 0.0,
            cos_slope: 1.0,
        }
    }
}

impl EffectiveTrack {
    /// Precompute the track of `profile` for `s` in `[s_start, s_end]` at grid spacing
    /// `ds` (m) with `envelope`, at deflection `reference_deflection` (m, in
    /// `[0, radius)`). At most [`MAX_TRACK_POINTS`] grid points.
    pub fn build<P: Profile + ?Sized>(
        profile: &P,
        range: (f64, f64),
        ds: f64,
        envelope: &Envelope,
        reference_deflection: f64,
    ) -> Result<Self, TireError> {
        let mut walk = NewtonWalk::start(profile, range, ds, envelope, reference_deflection)?;
        let points = (0..walk.n).map(|_| walk.next(profile)).collect();
        Ok(Self {
            s0: walk.s0,
            ds: walk.ds,
            reference_deflection,
            points: Grid::built(points),
        })
    }

    /// [`EffectiveTrack::build`] deferred: the grid is built in order, a chunk of 256
    /// points at a time, when a contact first reads it, so a run that stops early builds
    /// only the part it reached. The same values to the bit as [`EffectiveTrack::build`];
    /// the track owns `profile` until its last chunk is built.
    pub fn on_demand<P: Profile + Send + 'static>(
        profile: P,
        range: (f64, f64),
        ds: f64,
        envelope: &Envelope,
        reference_deflection: f64,
    ) -> Result<Self, TireError> {
        let mut walk = NewtonWalk::start(&profile, range, ds, envelope, reference_deflection)?;
        Ok(Self {
            s0: walk.s0,
            ds: walk.ds,
            reference_deflection,
            points: Grid::on_demand(walk.n, Box::new(move || walk.next(&profile))),
        })
    }

    /// Contact of a wheel with centre height `z_c` at path coordinate `s` (clamped to the
    /// grid): linear interpolation of the cache, then the penetration of the module docs.
    #[inline]
    pub fn contact(&self, s: f64, z_c: f64) -> TrackContact {
        let u = ((s - self.s0) / self.ds).max(0.0);
        let last = self.points.len() - 1;
        let i = (u as usize).min(last - 1);
        let w = (u - i as f64).min(1.0);
        let ([z0, slope0], [z1, slope1]) = self.points.cell(i);
        let z_ref = z0 + w * (z1 - z0);
        let slope = slope0 + w * (slope1 - slope0);
        let (sin_slope, cos_slope) = slope.sin_cos();
        TrackContact {
            deflection: self.reference_deflection + (z_ref - z_c) * cos_slope,
            slope,
            sin_slope,
            cos_slope,
        }
    }

    /// Path range covered `(s_start, s_end)` (m).
    pub fn range(&self) -> (f64, f64) {
        (self.s0, self.s0 + (self.points.len() - 1) as f64 * self.ds)
    }
}

/// The effective track's grid points in order ([`EffectiveTrack::build`]): at each, Newton
/// on the wheel height (`d(delta)/dz = -cos(theta)`) from the previous point's height (on
/// the 3-D vehicle's class E D2 tracks 1.7 steps a point on average: 2.7 enveloped contacts,
/// one per step and one to start), the profile under the wheel sampled once for all its
/// iterations.
struct NewtonWalk {
    s0: f64,
    ds: f64,
    reference_deflection: f64,
    radius: f64,
    envelope: Envelope,
    /// The profile sampled once for every grid point's window (none when the range needs
    /// more samples than a cache may hold: each window then samples its own).
    sampled: Option<SampledProfile>,
    /// Grid points in all, and the next one's index.
    n: usize,
    i: usize,
    /// The last point's wheel height (not finite before the first).
    z: f64,
}

impl NewtonWalk {
    fn start<P: Profile + ?Sized>(
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
        let n = grid_points((s_start, s_end), 0.0, ds)?;
        let reach = radius + envelope.cam_radius() + 2.0 * envelope.sample_spacing();
        let s_last = s_start + (n - 1) as f64 * ds;
        let sampled = envelope
            .sample(profile, (s_start - reach, s_last + reach))
            .ok();
        Ok(Self {
            s0: s_start,
            ds,
            reference_deflection,
            radius,
            envelope: *envelope,
            sampled,
            n,
            i: 0,
            z: f64::NAN,
        })
    }

    /// The next grid point's wheel height and slope.
    fn next<P: Profile + ?Sized>(&mut self, profile: &P) -> [f64; 2] {
        let s = self.s0 + self.i as f64 * self.ds;
        self.i += 1;
        if !self.z.is_finite() {
            self.z = profile.height_at(s) + self.radius - self.reference_deflection;
        }
        let reference_deflection = self.reference_deflection;
        let z = &mut self.z;
        let mut newton = |contact: &dyn Fn(f64) -> EffectiveContact| {
            let mut c = contact(*z);
            for _ in 0..NEWTON_ITERATIONS {
                let step = (c.deflection - reference_deflection) / c.slope.cos().max(0.1);
                *z += step;
                c = contact(*z);
                if step.abs() < NEWTON_TOLERANCE_M {
                    break;
                }
            }
            c
        };
        let c = self
            .envelope
            .contacts_in(self.sampled.as_ref(), profile, s, &mut newton);
        [self.z, c.slope]
    }
}

/// The tandem cams of section 6.2.2 (Eqs 6.1-6.3) spaced at the tire's *instantaneous*
/// deflection: the paper makes the contact length P1P2 depend on the deflection, which an
/// [`EffectiveTrack`] fixes at its reference deflection.
///
/// The cache holds the cams' base `b(s)` ([`Envelope::cam_base`]) on a uniform grid along
/// the track, linear between grid points; the contact is then found as
/// [`Envelope::contact`] finds it for [`crate::EnvelopeMethod::TandemCams`]: from the
/// central cam's deflection `delta = R - (z_c - b(s))` (out of contact when not positive),
/// [`CAM_ITERATIONS`] steps of: half contact length `a = sqrt(2 R delta - delta^2)`, cams at
/// `s -+ a` with bases `b1`, `b2`, `z_oi = (b1 + b2) / 2` (Eq 6.2),
/// `theta = atan((b2 - b1) / 2a)` (Eq 6.3) and the normal penetration
/// `delta = R - (z_c - z_oi) cos theta` (Eq 6.1 in the normal form of `envelope`'s docs).
/// Continuous in `s` and `z_c`, no allocation; seven base look-ups per contact against one
/// for an [`EffectiveTrack`].
#[derive(Debug, Clone, PartialEq)]
pub struct InstantaneousTrack {
    s0: f64,
    ds: f64,
    radius: f64,
    base: Vec<f64>,
}

/// Fixed-point steps of the cam spacing in [`InstantaneousTrack::contact`]: those of the
/// on-line cams ([`crate::envelope::CAM_ITERATIONS`]).
pub const CAM_ITERATIONS: usize = crate::envelope::CAM_ITERATIONS;

impl InstantaneousTrack {
    /// The cams' base along `profile` for wheel positions `s` in `[s_start, s_end]` (the
    /// grid reaches one free radius beyond each end: the cams' reach) at spacing `ds`
    /// (m), with `envelope` (tandem cams only). At most [`MAX_TRACK_POINTS`] grid points.
    pub fn build<P: Profile + ?Sized>(
        profile: &P,
        (s_start, s_end): (f64, f64),
        ds: f64,
        envelope: &Envelope,
    ) -> Result<Self, TireError> {
        if envelope.method() != crate::envelope::EnvelopeMethod::TandemCams {
            return Err(TireError::InvalidParameter {
                field: "envelope",
                value: f64::NAN,
                reason: "only the tandem cams have a spacing to follow the deflection",
            });
        }
        let ds = positive("track_grid_m", ds)?;
        let radius = envelope.radius();
        let n = grid_points((s_start, s_end), 2.0 * radius, ds)?;
        let s0 = s_start - radius;
        // the profile sampled once for every cam's window (none beyond a cache's size)
        let reach = envelope.cam_radius() + 2.0 * envelope.sample_spacing();
        let s_last = s0 + (n - 1) as f64 * ds;
        let sampled = envelope.sample(profile, (s0 - reach, s_last + reach)).ok();
        let base = (0..n)
            .map(|i| envelope.cam_base_in(sampled.as_ref(), profile, s0 + i as f64 * ds))
            .collect::<Vec<_>>();
        if let Some(b) = base.iter().find(|b| !b.is_finite()) {
            return Err(TireError::InvalidParameter {
                field: "profile",
                value: *b,
                reason: "the cams found no finite profile under them",
            });
        }
        Ok(Self {
            s0,
            ds,
            radius,
            base,
        })
    }

    /// The cams' base at `s` (clamped to the grid), linear between grid points.
    #[inline]
    fn base_at(&self, s: f64) -> f64 {
        let u = ((s - self.s0) / self.ds).max(0.0);
        let last = self.base.len() - 1;
        let i = (u as usize).min(last - 1);
        let w = (u - i as f64).min(1.0);
        self.base[i] + w * (self.base[i + 1] - self.base[i])
    }

    /// Contact of a wheel with centre height `z_c` at path coordinate `s` (type docs).
    #[inline]
    pub fn contact(&self, s: f64, z_c: f64) -> TrackContact {
        let r = self.radius;
        let b0 = self.base_at(s);
        let mut contact = TrackContact::level(r - (z_c - b0));
        if contact.deflection <= 0.0 {
            return contact;
        }
        for _ in 0..CAM_ITERATIONS {
            let d = contact.deflection.clamp(0.0, r);
            let a = (2.0 * r * d - d * d).max(0.0).sqrt();
            let (b1, b2) = if a > 0.0 {
                (self.base_at(s - a), self.base_at(s + a))
            } else {
                (b0, b0)
            };
            let slope = if a > 0.5e-12 {
                ((b2 - b1) / (2.0 * a)).atan()
            } else {
                0.0
            };
            let cos_slope = slope.cos();
            contact = TrackContact {
                deflection: r - (z_c - 0.5 * (b1 + b2)) * cos_slope,
                slope,
                sin_slope: 0.0,
                cos_slope,
            };
        }
        contact.sin_slope = contact.slope.sin();
        contact
    }

    /// Path range of the wheel positions covered `(s_start, s_end)` (m).
    pub fn range(&self) -> (f64, f64) {
        let end = self.s0 + (self.base.len() - 1) as f64 * self.ds;
        (self.s0 + self.radius, end - self.radius)
    }
}

/// One tire's enveloping cache along its track: the contact at a reference deflection
/// ([`EffectiveTrack`]) or the tandem cams spaced at the instantaneous deflection
/// ([`InstantaneousTrack`]). What [`crate::TireAssembly`] reads per tire.
#[derive(Debug, PartialEq)]
pub enum TireTrack {
    /// The contact cached at a reference deflection, the penetration linearised about it.
    Static(EffectiveTrack),
    /// The cams' base cached, the cams spaced on line at the instantaneous deflection.
    Instantaneous(InstantaneousTrack),
}

impl TireTrack {
    /// Contact of a wheel with centre height `z_c` at path coordinate `s`.
    #[inline]
    pub fn contact(&self, s: f64, z_c: f64) -> TrackContact {
        match self {
            Self::Static(t) => t.contact(s, z_c),
            Self::Instantaneous(t) => t.contact(s, z_c),
        }
    }

    /// Path range covered `(s_start, s_end)` (m).
    pub fn range(&self) -> (f64, f64) {
        match self {
            Self::Static(t) => t.range(),
            Self::Instantaneous(t) => t.range(),
        }
    }
}

/// Grid points of a cache at spacing `ds` over the path range `(s_start, s_end)` widened by
/// `margin` (m): the range's length plus the margin, in steps, plus two. Refuses a range that
/// is not finite or inverted, and more than [`MAX_TRACK_POINTS`] points (the allocation a
/// user's track length asks for).
fn grid_points((s_start, s_end): (f64, f64), margin: f64, ds: f64) -> Result<usize, TireError> {
    let span = s_end - s_start;
    if !(s_start.is_finite() && span.is_finite() && span >= 0.0) {
        return Err(TireError::InvalidParameter {
            field: "track_length_m",
            value: span,
            reason: "the track range must be finite and not inverted",
        });
    }
    let n = ((span + margin) / ds).ceil() + 2.0;
    if n > MAX_TRACK_POINTS as f64 {
        return Err(TireError::InvalidParameter {
            field: "track_length_m",
            value: span,
            reason: "too many enveloping grid points (length / grid above 4e6)",
        });
    }
    Ok(n as usize)
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

    /// A rough two-scale profile (bumps of a few cm, wavelengths 0.46-3 m).
    fn rough(x: f64) -> f64 {
        0.04 * (2.1 * x).sin() + 0.025 * (5.3 * x + 1.0).sin() + 0.012 * (13.7 * x + 2.0).sin()
    }

    #[test]
    fn instantaneous_spacing_agrees_with_the_online_cams() {
        let (r, d_static) = (1.0, 0.09);
        let env = Envelope::new(EnvelopeMethod::TandemCams, r, 0.01).unwrap();
        let fixed = EffectiveTrack::build(&rough, (0.0, 12.0), 0.02, &env, d_static).unwrap();
        // the cams' base has cusps in the valleys, where the spacing's fixed point is
        // unstable and the three steps amplify a difference in the base: the grid must be
        // fine (largest error 2.4e-3 m at a 0.02 m grid, 1.6e-4 at 0.01, 6.7e-5 at 0.005)
        let inst = InstantaneousTrack::build(&rough, (0.0, 12.0), 0.005, &env).unwrap();
        let (lo, hi) = inst.range();
        assert!(lo <= 0.0 && hi >= 12.0, "{lo} {hi}");
        let (mut worst_inst, mut worst_fixed) = (0.0f64, 0.0f64);
        for &s in &[2.0, 3.37, 4.5, 6.05, 8.8, 10.1] {
            for d in [-0.01f64, 0.01, 0.03, 0.06, 0.09, 0.13, 0.17] {
                // a wheel height at which the on-line cams give about deflection d
                let z = env.at_deflection(&rough, s, d.max(0.0)).unwrap().wheel_z - d.min(0.0);
                let exact = env.contact(&rough, s, z);
                let (a, b) = (inst.contact(s, z), fixed.contact(s, z));
                worst_inst = worst_inst.max((a.deflection - exact.deflection).abs());
                worst_fixed = worst_fixed.max((b.deflection - exact.deflection).abs());
                assert!(
                    (a.slope - exact.slope).abs() < 2e-3,
                    "s = {s}, d = {d}: {a:?} vs {exact:?}"
                );
            }
        }
        println!("largest deflection error: instantaneous {worst_inst:.2e} m, static {worst_fixed:.2e} m");
        // the cached bases follow the on-line cams to a tenth of a millimetre; the cache at
        // the static deflection misses by millimetres away from it
        assert!(worst_inst < 1e-4, "instantaneous: {worst_inst}");
        assert!(worst_fixed > 1e-3, "static: {worst_fixed}");
    }

    /// A track built on demand holds the points of the track built at once, to the bit,
    /// whatever order the contacts read it in: each grid point's Newton iteration starts
    /// from the previous point's height, so the points are built in order.
    #[test]
    fn a_track_built_on_demand_is_the_track_built_at_once() {
        let env = Envelope::new(EnvelopeMethod::TandemCams, 1.0, 0.01).unwrap();
        let at_once = EffectiveTrack::build(&rough, (0.0, 40.0), 0.02, &env, 0.08).unwrap();
        let later = EffectiveTrack::on_demand(rough, (0.0, 40.0), 0.02, &env, 0.08).unwrap();
        assert_eq!(later.range(), at_once.range());
        for s in [33.3, 0.01, 17.0, 39.99, 5.2, 40.0, 0.0] {
            for z in [0.9, 0.95, 1.02] {
                let (a, b) = (at_once.contact(s, z), later.contact(s, z));
                assert_eq!(a.deflection.to_bits(), b.deflection.to_bits(), "{s} {z}");
                assert_eq!(a.slope.to_bits(), b.slope.to_bits(), "{s} {z}");
            }
        }
        assert_eq!(later, at_once);
        let err = EffectiveTrack::on_demand(rough, (0.0, 1.0), 0.1, &env, 1.5).unwrap_err();
        assert!(err.to_string().contains("reference_deflection_m"), "{err}");
    }

    #[test]
    fn instantaneous_spacing_on_a_plane_is_the_exact_penetration() {
        let flat = |_x: f64| 0.1;
        let env = Envelope::new(EnvelopeMethod::TandemCams, 1.0, 0.01).unwrap();
        let t = InstantaneousTrack::build(&flat, (0.0, 5.0), 0.1, &env).unwrap();
        for d in [-0.02, 0.0, 0.05, 0.15, 0.25] {
            let c = t.contact(2.2, 1.1 - d);
            assert!((c.deflection - d).abs() < 1e-12, "{d}: {c:?}");
            assert!(c.slope.abs() < 1e-12);
        }
    }

    #[test]
    fn instantaneous_settings_are_named() {
        let flat = |_x: f64| 0.0;
        let cams = Envelope::new(EnvelopeMethod::TandemCams, 1.0, 0.01).unwrap();
        let circle = Envelope::new(EnvelopeMethod::CircleLine, 1.0, 0.01).unwrap();
        let err = |env: &Envelope, range: (f64, f64), ds: f64| {
            InstantaneousTrack::build(&flat, range, ds, env)
                .unwrap_err()
                .to_string()
        };
        assert!(err(&circle, (0.0, 1.0), 0.1).contains("envelope"));
        assert!(err(&cams, (0.0, 1.0), 0.0).contains("track_grid_m"));
        assert!(err(&cams, (1.0, 0.0), 0.1).contains("track_length_m"));
        assert!(err(&cams, (0.0, 1e9), 1e-3).contains("track_length_m"));
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
