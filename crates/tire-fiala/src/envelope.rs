//! Effective tire-terrain contact on a rough profile: the circle-line intersection of
//! section 2.2.1 (Eqs 2.2-2.4, Fig 2.2) and the two tandem cams of section 6.2.2
//! (Eqs 6.1-6.3, Fig 6.3). Both reduce the profile under the tire to an effective
//! elevation `z_oi = (z_P1 + z_P2) / 2` (Eqs 2.3, 6.2), a slope
//! `theta = atan((z_P2 - z_P1) / dx)` (Eqs 2.4, 6.3) and a contact length `dx`.
//!
//! Deflection: Eqs 2.2/6.1 print `delta = (z_oi - z_u) / cos theta`. This module returns
//! the normal penetration of the wheel circle into the effective line P1P2,
//! `delta = R - ((z_c - z_oi) - tan(theta) (x_c - x_m)) cos(theta)`, which equals Eq 2.2 on
//! level ground (z_u = z_c - R) and to first order in theta, and is zero for a wheel just
//! touching an inclined plane (the printed form is not);
//! [`EffectiveContact::deflection_eq_2_2`] gives the printed form. See `docs/tire-fiala.md`.
//!
//! The profile is sampled on a global grid `x_i = i h` (spacing `h` fixed by the
//! settings), so results move continuously with the wheel for the cam method. No
//! allocation: samples live in a fixed stack buffer of [`MAX_SAMPLES`].

use crate::cams::{Cams, SegmentView, Segments};
use crate::error::{positive, TireError};
use crate::sampled::SampledProfile;
use crate::terrain::Profile;
use arrayvec::ArrayVec;

/// Capacity of the stack sample buffer; the sample spacing is widened if the window needs
/// more.
pub const MAX_SAMPLES: usize = 1024;

/// Fixed-point iterations of the cam spacing (see [`EnvelopeMethod::TandemCams`]).
pub const CAM_ITERATIONS: usize = 3;

/// How the tire envelopes the terrain.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum EnvelopeMethod {
    /// Section 2.2.1: intersect the undeformed wheel circle with the profile; P1 and P2
    /// are the rearmost and foremost intersection points, their elevations taken on the
    /// circle. Contact length on level ground `2 sqrt(2 R delta - delta^2)`.
    CircleLine,
    /// Section 6.2.2: two cams (arcs of radius `cam_radius`, default the free radius)
    /// placed at `x_c -+ a`, `a = sqrt(2 R delta - delta^2)` the half contact length of the
    /// deflected circle, each resting on the profile at one point; `z_Pi` is the height of
    /// the cam's base (the profile as enveloped by the cam). delta and a are found by
    /// [`CAM_ITERATIONS`] fixed-point steps from a single central cam.
    TandemCams,
}

impl std::str::FromStr for EnvelopeMethod {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "circle" | "circle_line" | "circle-line" => Ok(Self::CircleLine),
            "cams" | "tandem_cams" | "tandem-cams" => Ok(Self::TandemCams),
            _ => Err(format!(
                "unknown enveloping method `{s}` (use `cams` or `circle`)"
            )),
        }
    }
}

/// Effective contact of one wheel (Eqs 2.2-2.4 / 6.1-6.3).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct EffectiveContact {
    /// Whether the tire touches the terrain (deflection > 0).
    pub in_contact: bool,
    /// Rear contact point P1 `(x, z)` (m).
    pub p1: (f64, f64),
    /// Front contact point P2 `(x, z)` (m).
    pub p2: (f64, f64),
    /// Effective elevation z_oi = (z_P1 + z_P2) / 2 (m), Eqs 2.3 / 6.2.
    pub z_eff: f64,
    /// Effective slope theta = atan((z_P2 - z_P1) / dx) (rad), Eqs 2.4 / 6.3; positive
    /// uphill in +x.
    pub slope: f64,
    /// Contact length dx = x_P2 - x_P1 (m), the projection of P1P2 on x.
    pub contact_length: f64,
    /// Tire deflection delta (m) normal to P1P2, positive in compression; out of contact it
    /// is minus the (sampled) vertical clearance.
    pub deflection: f64,
}

impl EffectiveContact {
    /// x of the midpoint of P1P2 (m).
    pub fn x_mid(&self) -> f64 {
        0.5 * (self.p1.0 + self.p2.0)
    }

    /// Deflection as printed in Eqs 2.2 / 6.1, `(z_oi - z_u) / cos theta` with
    /// `z_u = z_c - R` (wheel-centre height `z_c`, free radius `R`).
    pub fn deflection_eq_2_2(&self, wheel_z: f64, radius: f64) -> f64 {
        (self.z_eff - (wheel_z - radius)) / self.slope.cos()
    }
}

/// A wheel placed on the profile at a prescribed deflection: the "effective profile".
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct EnvelopedPoint {
    /// Wheel-centre height z_c (m) giving the prescribed deflection.
    pub wheel_z: f64,
    /// The contact at that height.
    pub contact: EffectiveContact,
}

/// Enveloping settings for one tire.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Envelope {
    method: EnvelopeMethod,
    radius: f64,
    cam_radius: f64,
    spacing: f64,
}

impl Envelope {
    /// `radius` the free radius R (m), `sample_spacing` the profile sampling step (m; use
    /// the profile's own resolution or finer; 0.01 m is a good default). The spacing is
    /// widened if the window would need more than [`MAX_SAMPLES`] points.
    pub fn new(
        method: EnvelopeMethod,
        radius: f64,
        sample_spacing: f64,
    ) -> Result<Self, TireError> {
        let radius = positive("radius", radius)?;
        let spacing = positive("sample_spacing", sample_spacing)?;
        Ok(Self {
            method,
            radius,
            cam_radius: radius,
            spacing,
        }
        .fit_spacing())
    }

    /// Use cams of radius `cam_radius` (m) instead of the free radius.
    pub fn with_cam_radius(mut self, cam_radius: f64) -> Result<Self, TireError> {
        self.cam_radius = positive("cam_radius", cam_radius)?;
        Ok(self.fit_spacing())
    }

    fn window_half_width(&self) -> f64 {
        match self.method {
            EnvelopeMethod::CircleLine => self.radius,
            EnvelopeMethod::TandemCams => self.radius + self.cam_radius,
        }
    }

    fn fit_spacing(mut self) -> Self {
        let need = 2.0 * self.window_half_width() / (MAX_SAMPLES - 3) as f64;
        if self.spacing < need {
            self.spacing = need;
        }
        self
    }

    /// The enveloping method.
    pub fn method(&self) -> EnvelopeMethod {
        self.method
    }

    /// Free radius R (m).
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// Sample spacing actually used (m).
    pub fn sample_spacing(&self) -> f64 {
        self.spacing
    }

    /// Cam radius (m): the free radius unless [`Envelope::with_cam_radius`] set another.
    pub fn cam_radius(&self) -> f64 {
        self.cam_radius
    }

    /// Height of the base of a cam of [`EnvelopeMethod::TandemCams`] centred at `x`, resting
    /// on `profile` sampled on the global grid (section 6.2.2: the profile as the cam
    /// envelopes it); minus infinity where no sample lies under the cam. The base the
    /// tandem cams of [`Envelope::contact`] rest on.
    pub fn cam_base<P: Profile + ?Sized>(&self, profile: &P, x: f64) -> f64 {
        let (i0, n) = self.cam_window(x);
        let mut buf = ArrayVec::<f64, MAX_SAMPLES>::new();
        buf.extend((0..n).map(|i| profile.height_at(grid_x(i0, i, self.spacing))));
        let samples = Samples {
            x0: i0 * self.spacing,
            h: self.spacing,
            z: &buf,
        };
        Cams::on(&samples, self.cam_radius, &mut Segments::new()).base(x)
    }

    /// [`Envelope::cam_base`] read from `sampled` (the profile sampled once over a range,
    /// [`Envelope::sample`]) where there is one and the cam's window lies inside it, else
    /// from `profile`: the same base to the bit.
    pub fn cam_base_in<P: Profile + ?Sized>(
        &self,
        sampled: Option<&SampledProfile>,
        profile: &P,
        x: f64,
    ) -> f64 {
        let (i0, n) = self.cam_window(x);
        match sampled.and_then(|sampled| sampled.window(self, i0, n)) {
            Some((samples, segments)) => Cams::over(&samples, self.cam_radius, segments).base(x),
            None => self.cam_base(profile, x),
        }
    }

    /// The first global sample index (as a float) and the number of samples of the window a
    /// cam centred at `x` reads: one sample beyond the cam each side, the segment its rim
    /// ends on.
    fn cam_window(&self, x: f64) -> (f64, usize) {
        let i0 = ((x - self.cam_radius) / self.spacing).ceil() - 1.0;
        let i1 = ((x + self.cam_radius) / self.spacing).floor() + 1.0;
        (i0, ((i1 - i0) as usize + 1).min(MAX_SAMPLES))
    }

    /// The first global sample index (as a float) and the number of samples of the window
    /// the contact of a wheel at `x_c` reads: the profile within the window's half width.
    fn contact_window(&self, x_c: f64) -> (f64, usize) {
        let half = self.window_half_width();
        let i0 = ((x_c - half) / self.spacing).ceil();
        let i1 = ((x_c + half) / self.spacing).floor();
        (i0, ((i1 - i0) as usize + 1).min(MAX_SAMPLES))
    }

    /// The profile sampled once on the global grid over `(x_lo, x_hi)` (m), with the cams'
    /// segment data: what every contact and cam base inside that range reads, so that a
    /// cache along a track ([`crate::EffectiveTrack`], [`crate::InstantaneousTrack`])
    /// samples each point once instead of once per overlapping window. At most
    /// [`crate::effective_track::MAX_TRACK_POINTS`] samples.
    pub fn sample<P: Profile + ?Sized>(
        &self,
        profile: &P,
        (x_lo, x_hi): (f64, f64),
    ) -> Result<SampledProfile, TireError> {
        SampledProfile::new(self, profile, (x_lo, x_hi))
    }

    /// Effective contact of a wheel with centre at `(x_c, z_c)` on `profile`.
    pub fn contact<P: Profile + ?Sized>(
        &self,
        profile: &P,
        x_c: f64,
        z_c: f64,
    ) -> EffectiveContact {
        self.contacts_at(profile, x_c, |contact| contact(z_c))
    }

    /// Calls `solve` with the contact at `x_c` as a function of the wheel-centre height:
    /// the profile window is sampled once (and, for the cams, the segment data and the
    /// central cam's base computed once) for every height `solve` asks, so a search for the
    /// height of a given deflection (a Newton or bisection on `z_c`) pays the sampling once.
    /// Each contact equals [`Envelope::contact`] at that height, bit for bit.
    pub fn contacts_at<P: Profile + ?Sized, R>(
        &self,
        profile: &P,
        x_c: f64,
        solve: impl FnOnce(&dyn Fn(f64) -> EffectiveContact) -> R,
    ) -> R {
        // stack buffers filled to the window's length only: zero-filling all MAX_SAMPLES
        // points cost more than the sampling itself
        let (i0, n) = self.contact_window(x_c);
        let mut buf = ArrayVec::<f64, MAX_SAMPLES>::new();
        buf.extend((0..n).map(|i| profile.height_at(grid_x(i0, i, self.spacing))));
        let samples = Samples {
            x0: i0 * self.spacing,
            h: self.spacing,
            z: &buf,
        };
        self.contacts_on(profile, &samples, None, x_c, solve)
    }

    /// [`Envelope::contacts_at`] read from `sampled` (the profile sampled once over a range,
    /// [`Envelope::sample`]) where there is one and the wheel's window lies inside it, else
    /// from `profile`: the same contacts to the bit.
    pub fn contacts_in<P: Profile + ?Sized, R>(
        &self,
        sampled: Option<&SampledProfile>,
        profile: &P,
        x_c: f64,
        solve: impl FnOnce(&dyn Fn(f64) -> EffectiveContact) -> R,
    ) -> R {
        let (i0, n) = self.contact_window(x_c);
        match sampled.and_then(|sampled| sampled.window(self, i0, n)) {
            Some((samples, segments)) => {
                self.contacts_on(profile, &samples, Some(segments), x_c, solve)
            }
            None => self.contacts_at(profile, x_c, solve),
        }
    }

    /// The contacts at `x_c` on the window `samples` (and, for the cams, its `segments` when
    /// they are at hand, else computed here).
    fn contacts_on<P: Profile + ?Sized, R>(
        &self,
        profile: &P,
        samples: &Samples,
        segments: Option<SegmentView>,
        x_c: f64,
        solve: impl FnOnce(&dyn Fn(f64) -> EffectiveContact) -> R,
    ) -> R {
        match self.method {
            EnvelopeMethod::CircleLine => {
                solve(&|z_c| self.circle_line(profile, samples, x_c, z_c))
            }
            EnvelopeMethod::TandemCams => {
                let mut own = Segments::new();
                let cams = match segments {
                    Some(view) => Cams::over(samples, self.cam_radius, view),
                    None => Cams::on(samples, self.cam_radius, &mut own),
                };
                let central = cams.base(x_c);
                solve(&|z_c| self.tandem_cams(&cams, central, x_c, z_c))
            }
        }
    }

    fn circle_line<P: Profile + ?Sized>(
        &self,
        profile: &P,
        s: &Samples,
        x_c: f64,
        z_c: f64,
    ) -> EffectiveContact {
        let r = self.radius;
        let circle = |x: f64| z_c - (r * r - (x - x_c) * (x - x_c)).max(0.0).sqrt();
        let gap = |x: f64| profile.height_at(x) - circle(x);
        let mut first = None;
        let mut last = None;
        let mut best = (f64::NEG_INFINITY, x_c, f64::NAN);
        for (i, &z) in s.z.iter().enumerate() {
            let x = s.x(i);
            let g = z - circle(x);
            if g > 0.0 {
                if first.is_none() {
                    first = Some(i);
                }
                last = Some(i);
            }
            if g > best.0 {
                best = (g, x, z);
            }
        }
        let (Some(first), Some(last)) = (first, last) else {
            // No intersection: collapse to the point of least clearance.
            let (g, x, z) = best;
            let z = if z.is_finite() { z } else { z_c - r };
            let g = if g.is_finite() { g } else { -r };
            return EffectiveContact {
                in_contact: false,
                p1: (x, z),
                p2: (x, z),
                z_eff: z,
                slope: 0.0,
                contact_length: 0.0,
                deflection: g.min(0.0),
            };
        };
        let xl = if first == 0 { x_c - r } else { s.x(first - 1) };
        let xr = if last + 1 == s.z.len() {
            x_c + r
        } else {
            s.x(last + 1)
        };
        let x1 = crossing(&gap, xl, s.x(first));
        let x2 = crossing(&gap, xr, s.x(last));
        let p1 = (x1, circle(x1));
        let p2 = (x2, circle(x2));
        finish(p1, p2, r, x_c, z_c)
    }

    /// The cams' contact at wheel-centre height `z_c`; `central` is the base of the cam
    /// centred under the wheel, `cams.base(x_c)`, which does not depend on `z_c`.
    fn tandem_cams(&self, cams: &Cams, central: f64, x_c: f64, z_c: f64) -> EffectiveContact {
        let r = self.radius;
        let base = |xj: f64| cams.base(xj);
        let b0 = central;
        let b0 = if b0.is_finite() { b0 } else { z_c - r - 1.0 };
        let mut delta = r - (z_c - b0);
        if delta <= 0.0 {
            return EffectiveContact {
                in_contact: false,
                p1: (x_c, b0),
                p2: (x_c, b0),
                z_eff: b0,
                slope: 0.0,
                contact_length: 0.0,
                deflection: delta,
            };
        }
        let mut contact = None;
        for _ in 0..CAM_ITERATIONS {
            let d = delta.clamp(0.0, r);
            let a = (2.0 * r * d - d * d).max(0.0).sqrt();
            let (b1, b2) = if a > 0.0 {
                let b1 = base(x_c - a);
                let b2 = base(x_c + a);
                (
                    if b1.is_finite() { b1 } else { b0 },
                    if b2.is_finite() { b2 } else { b0 },
                )
            } else {
                (b0, b0)
            };
            let c = finish((x_c - a, b1), (x_c + a, b2), r, x_c, z_c);
            delta = c.deflection;
            contact = Some(c);
        }
        contact.expect("CAM_ITERATIONS > 0")
    }

    /// Place the wheel at `x_c` so that its deflection equals `deflection` (m, >= 0) and
    /// return the wheel height and contact: the effective profile a tire under constant
    /// load sees (the enveloping filter of Fig 1.2). Bisection on the wheel height.
    pub fn at_deflection<P: Profile + ?Sized>(
        &self,
        profile: &P,
        x_c: f64,
        deflection: f64,
    ) -> Result<EnvelopedPoint, TireError> {
        let r = self.radius;
        if !(deflection.is_finite() && (0.0..r).contains(&deflection)) {
            return Err(TireError::InvalidParameter {
                field: "deflection",
                value: deflection,
                reason: "must be finite, >= 0 and below the radius",
            });
        }
        let z0 = profile.height_at(x_c);
        let z0 = if z0.is_finite() { z0 } else { 0.0 };
        Ok(self.contacts_at(profile, x_c, |contact| {
            place(contact, z0 + r - deflection, 0.25 * r, deflection)
        }))
    }
}

/// The wheel height at which `contact` gives `deflection` (bisection: the deflection falls
/// as the wheel rises), starting from `z_start` and widening by `step`.
fn place(
    contact: &dyn Fn(f64) -> EffectiveContact,
    z_start: f64,
    step: f64,
    deflection: f64,
) -> EnvelopedPoint {
    let f = |z: f64| contact(z).deflection - deflection;
    let (mut lo, mut hi) = (z_start, z_start);
    let mut k = 0;
    while f(lo) < 0.0 && k < 64 {
        lo -= step;
        k += 1;
    }
    k = 0;
    while f(hi) > 0.0 && k < 64 {
        hi += step;
        k += 1;
    }
    // f decreases with the wheel height: f(lo) >= 0 >= f(hi).
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if f(mid) > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
        if hi - lo < 1e-12 {
            break;
        }
    }
    let wheel_z = 0.5 * (lo + hi);
    EnvelopedPoint {
        wheel_z,
        contact: contact(wheel_z),
    }
}

/// The x of sample `i` of a window whose first sample has the global index `i0` (an
/// integer held as a float): `(i0 + i) h`, the global grid point itself, so a window of a
/// [`SampledProfile`] holds the very samples a window sampled on its own would.
#[inline]
fn grid_x(i0: f64, i: usize, h: f64) -> f64 {
    (i0 + i as f64) * h
}

/// Profile samples on the global grid.
pub(crate) struct Samples<'a> {
    /// x of the first sample (m).
    pub(crate) x0: f64,
    /// Spacing (m).
    pub(crate) h: f64,
    /// Heights (m).
    pub(crate) z: &'a [f64],
}

impl Samples<'_> {
    /// x of sample `i` (m). The index goes through `i64`: the same value as `i as f64` for
    /// any window (fewer than [`MAX_SAMPLES`] points), in one instruction where the
    /// unsigned conversion takes a branchy sequence on x86-64 (a quarter of the cam base's
    /// cost).
    #[inline]
    pub(crate) fn x(&self, i: usize) -> f64 {
        self.x0 + i as i64 as f64 * self.h
    }
}

/// Root of `gap` between `outside` (gap <= 0) and `inside` (gap > 0): bisection (robust to
/// steps in the profile) then one secant step in the final bracket.
fn crossing<G: Fn(f64) -> f64>(gap: &G, outside: f64, inside: f64) -> f64 {
    let (mut a, mut b) = (outside, inside);
    let (mut ga, mut gb) = (gap(a), gap(b));
    if ga > 0.0 || ga.is_nan() {
        return a; // terrain above the circle all the way to the rim
    }
    for _ in 0..20 {
        let m = 0.5 * (a + b);
        let gm = gap(m);
        if gm > 0.0 {
            b = m;
            gb = gm;
        } else {
            a = m;
            ga = gm;
        }
    }
    if gb - ga > 0.0 {
        a + (b - a) * (-ga) / (gb - ga)
    } else {
        0.5 * (a + b)
    }
}

/// Eqs 2.3/2.4 (6.2/6.3) and the normal deflection from the contact points.
fn finish(p1: (f64, f64), p2: (f64, f64), r: f64, x_c: f64, z_c: f64) -> EffectiveContact {
    let dx = p2.0 - p1.0;
    let z_eff = 0.5 * (p1.1 + p2.1);
    let slope = if dx > 1e-12 {
        ((p2.1 - p1.1) / dx).atan()
    } else {
        0.0
    };
    let x_m = 0.5 * (p1.0 + p2.0);
    let deflection = r - ((z_c - z_eff) - slope.tan() * (x_c - x_m)) * slope.cos();
    EffectiveContact {
        in_contact: deflection > 0.0,
        p1,
        p2,
        z_eff,
        slope,
        contact_length: dx.max(0.0),
        deflection,
    }
}
