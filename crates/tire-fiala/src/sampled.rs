//! A profile sampled once along a track, for the caches that envelope it at every grid
//! point ([`crate::EffectiveTrack`], [`crate::InstantaneousTrack`]).
//!
//! [`crate::Envelope::contacts_at`] samples the profile under a wheel on the global grid
//! `x_k = k h` and, for the tandem cams, works out every segment's slope, tangent offset
//! and lift. Along a cache the windows of neighbouring grid points overlap almost entirely
//! (four tire radii, about 4 m, every 5 cm on the 3-D vehicle's tracks), so the same
//! samples and segments were computed again and again: a quarter of a D2 roll run's cache
//! build. A [`SampledProfile`] holds them once for a whole range;
//! [`crate::Envelope::contacts_in`] and [`crate::Envelope::cam_base_in`] read a window of
//! it. The window holds the very samples (`(i0 + i) h`, the global grid point) and segment
//! values a window sampled on its own holds, so the contacts are the same to the bit.

use crate::cams::{segment, SegmentView};
use crate::effective_track::MAX_TRACK_POINTS;
use crate::envelope::{Envelope, Samples};
use crate::error::TireError;
use crate::terrain::Profile;

/// A profile's samples on the global grid of an [`Envelope`] over a range of x, with the
/// segments its cams see ([`crate::Envelope::sample`]).
#[derive(Debug, Clone, PartialEq)]
pub struct SampledProfile {
    /// Global index of the first sample (an integer, held as a float).
    first: f64,
    /// Sample spacing (m): the envelope's.
    h: f64,
    /// Cam radius the segments are for (m): the envelope's.
    rc: f64,
    z: Vec<f64>,
    slope: Vec<f64>,
    offset: Vec<f64>,
    lift: Vec<f64>,
}

impl SampledProfile {
    /// `profile` at every grid point of `envelope` from below `x_lo` to above `x_hi` (m),
    /// and the segments between them. Refuses a range that is not finite or inverted, and
    /// more than [`MAX_TRACK_POINTS`] samples (the allocation a user's track asks for).
    pub(crate) fn new<P: Profile + ?Sized>(
        envelope: &Envelope,
        profile: &P,
        (x_lo, x_hi): (f64, f64),
    ) -> Result<Self, TireError> {
        let h = envelope.sample_spacing();
        let (first, last) = ((x_lo / h).floor(), (x_hi / h).ceil());
        let count = last - first + 1.0;
        if !(first.is_finite() && last.is_finite() && count >= 1.0) {
            return Err(TireError::InvalidParameter {
                field: "track_length_m",
                value: x_hi - x_lo,
                reason: "the sampled range must be finite and not inverted",
            });
        }
        if count > MAX_TRACK_POINTS as f64 {
            return Err(TireError::InvalidParameter {
                field: "track_length_m",
                value: x_hi - x_lo,
                reason: "needs more profile samples than MAX_TRACK_POINTS",
            });
        }
        let z: Vec<f64> = (0..count as usize)
            .map(|i| profile.height_at((first + i as f64) * h))
            .collect();
        let rc = envelope.cam_radius();
        let n = z.len() - 1;
        let (mut slope, mut offset, mut lift) = (
            Vec::with_capacity(n),
            Vec::with_capacity(n),
            Vec::with_capacity(n),
        );
        for pair in z.windows(2) {
            let (m, o, l) = segment(pair[0], pair[1], h, rc);
            slope.push(m);
            offset.push(o);
            lift.push(l);
        }
        Ok(Self {
            first,
            h,
            rc,
            z,
            slope,
            offset,
            lift,
        })
    }

    /// Range of x sampled `(x_first, x_last)` (m).
    pub fn range(&self) -> (f64, f64) {
        let last = self.first + (self.z.len() - 1) as f64;
        (self.first * self.h, last * self.h)
    }

    /// The window of `n` samples from the global index `i0` (an integer held as a float)
    /// and its `n − 1` segments, when it lies inside the sampled range and `envelope` has
    /// the spacing and cam radius the samples were taken for; `None` otherwise.
    pub(crate) fn window<'a>(
        &'a self,
        envelope: &Envelope,
        i0: f64,
        n: usize,
    ) -> Option<(Samples<'a>, SegmentView<'a>)> {
        if envelope.sample_spacing() != self.h || envelope.cam_radius() != self.rc || n == 0 {
            return None;
        }
        let k = i0 - self.first;
        if !(k >= 0.0 && k + n as f64 <= self.z.len() as f64) {
            return None;
        }
        let k = k as usize;
        let samples = Samples {
            x0: i0 * self.h,
            h: self.h,
            z: &self.z[k..k + n],
        };
        let segments = SegmentView {
            slope: &self.slope[k..k + n - 1],
            offset: &self.offset[k..k + n - 1],
            lift: &self.lift[k..k + n - 1],
        };
        Some((samples, segments))
    }
}
