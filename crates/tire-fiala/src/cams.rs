//! The cams of section 6.2.2 (Eqs 6.1-6.3) on a sampled window of the profile: the height
//! of the base of a cam of radius `r_c` centred at `x_j` resting on the profile, the
//! profile as the cam envelopes it. [`crate::envelope`] places two such cams under a wheel
//! (the tandem cams); the caches of [`crate::effective_track`] read them along a track.
//!
//! A cam rests either on a vertex of the sampled (piecewise-linear) profile or tangent to
//! a segment between two samples; [`Cams::base`] is the largest of those candidates, with
//! the candidates that cannot be the largest skipped (docs/tire-fiala.md).

use crate::envelope::{Samples, MAX_SAMPLES};
use arrayvec::ArrayVec;

/// How far below the best cam base so far a profile vertex must lie to be skipped (m): far
/// above the round-off of the cam's drop (about 1e-16 m), far below any height that matters.
const PRUNE_GUARD_M: f64 = 1e-9;

/// What a cam of radius `rc` sees of the segment from height `z0` to `z1` over the spacing
/// `h`: its slope m, the offset `rc m / sqrt(1 + m²)` of the cam's tangent point and the
/// cam's lift `rc (sqrt(1 + m²) − 1)` there.
#[inline]
pub(crate) fn segment(z0: f64, z1: f64, h: f64, rc: f64) -> (f64, f64, f64) {
    let m = (z1 - z0) / h;
    let q = (1.0 + m * m).sqrt();
    (m, rc * m / q, rc * (q - 1.0))
}

/// The cams of section 6.2.2 on one sampled window: per segment the slope m, the tangent
/// offset rc m / sqrt(1 + m^2) and the base lift rc (sqrt(1 + m^2) - 1), computed once for
/// all cam evaluations.
pub(crate) struct Cams<'a> {
    s: &'a Samples<'a>,
    rc: f64,
    seg: SegmentView<'a>,
    /// The largest `|offset|` of the window's segments: a cam at `x_j` touches no segment
    /// farther than that from `x_j`.
    reach: f64,
    /// The window's highest sample (minus infinity for none).
    top: f64,
}

/// A window's segments as [`segment`] gives them, one entry per pair of neighbouring
/// samples: borrowed from a [`Segments`] buffer or from a [`SampledProfile`].
#[derive(Clone, Copy)]
pub(crate) struct SegmentView<'a> {
    pub(crate) slope: &'a [f64],
    pub(crate) offset: &'a [f64],
    pub(crate) lift: &'a [f64],
}

/// The window's segments as cams of one radius see them: each one's slope, the offset of a
/// cam's tangent point on it and the cam's lift there. Stack storage in the caller's frame
/// that [`Cams::on`] fills: returned inside the cams by value, its 24 kB were copied on
/// every window (24 600 instructions of `memcpy`, 15 % of a loaded D1 ride of `afsv vehicle
/// ride` with the HPS).
pub(crate) struct Segments {
    slope: ArrayVec<f64, MAX_SAMPLES>,
    offset: ArrayVec<f64, MAX_SAMPLES>,
    lift: ArrayVec<f64, MAX_SAMPLES>,
}

impl Segments {
    #[inline]
    pub(crate) fn new() -> Self {
        Self {
            slope: ArrayVec::new(),
            offset: ArrayVec::new(),
            lift: ArrayVec::new(),
        }
    }
}

impl<'a> Cams<'a> {
    /// The cams of radius `rc` on the window `s`, their segments computed into `seg`.
    pub(crate) fn on(s: &'a Samples<'a>, rc: f64, seg: &'a mut Segments) -> Self {
        seg.slope.clear();
        seg.offset.clear();
        seg.lift.clear();
        for i in 0..s.z.len().saturating_sub(1) {
            let (m, offset, lift) = segment(s.z[i], s.z[i + 1], s.h, rc);
            seg.slope.push(m);
            seg.offset.push(offset);
            seg.lift.push(lift);
        }
        let seg: &'a Segments = seg;
        let view = SegmentView {
            slope: &seg.slope,
            offset: &seg.offset,
            lift: &seg.lift,
        };
        Self::over(s, rc, view)
    }

    /// The cams of radius `rc` on the window `s` with its segments `seg` (one per pair of
    /// neighbouring samples): the largest offset and the highest sample.
    pub(crate) fn over(s: &'a Samples<'a>, rc: f64, seg: SegmentView<'a>) -> Self {
        Cams {
            s,
            rc,
            reach: seg.offset.iter().fold(0.0, |r: f64, o| r.max(o.abs())),
            top: s.z.iter().fold(f64::NEG_INFINITY, |t, z| t.max(*z)),
            seg,
        }
    }

    /// Height of the base of a cam centred at `xj` resting on the profile (minus infinity
    /// when no sample lies under it): the largest of the vertex and segment candidates
    /// below, the same to the bit as over every candidate in any order. Two bounds skip
    /// candidates that cannot be the largest:
    /// - a segment's tangent point lies within `reach` (the window's largest tangent offset)
    ///   of `xj`, so only the segments there are tried (one more index on each side for
    ///   round-off);
    /// - a vertex at distance `d` has the candidate `z − (rc − sqrt(rc² − d²))`, at most
    ///   `z − d² / (2 rc)`; a vertex whose bound lies below the best so far by more than
    ///   [`PRUNE_GUARD_M`] (far above the round-off of either) is skipped without its
    ///   square root, and with the window's highest sample `top` only the vertices with
    ///   `d² < 2 rc (top − best + guard)` are visited at all. The segments go first: they
    ///   set a high best at no square root.
    pub(crate) fn base(&self, xj: f64) -> f64 {
        let (s, rc) = (self.s, self.rc);
        let nseg = s.z.len().saturating_sub(1);
        let lo = fast_ceil(((xj - rc) - s.x0) / s.h).max(0.0) as usize;
        let hi = (fast_floor(((xj + rc) - s.x0) / s.h).max(-1.0) + 1.0) as usize;
        let hi = hi.min(s.z.len());
        let mut b = f64::NEG_INFINITY;
        // Segments between samples (linear): the cam touches a segment of slope m at
        // x_j + rc m / sqrt(1 + m^2), base z_line(x_j) - rc + rc sqrt(1 + m^2).
        let near = (fast_floor((xj - self.reach - s.x0) / s.h) - 2.0).max(0.0) as usize;
        let far = (fast_ceil((xj + self.reach - s.x0) / s.h) + 2.0).max(0.0) as usize;
        let (first, end) = (lo.saturating_sub(1).max(near), hi.min(nseg).min(far));
        if first < end {
            let seg = &self.seg;
            let (offset, slope, lift) = (
                &seg.offset[first..end],
                &seg.slope[first..end],
                &seg.lift[first..end],
            );
            let z = &s.z[first..end];
            // each segment's right end is the next one's left end: the same x
            let mut left = s.x(first);
            for (k, (((&o, &m), &l), &z)) in offset.iter().zip(slope).zip(lift).zip(z).enumerate() {
                let right = s.x(first + k + 1);
                let xt = xj + o;
                if xt >= left && xt <= right {
                    let v = z + m * (xj - left) + l;
                    if v > b {
                        b = v;
                    }
                }
                left = right;
            }
        }
        // Vertices of the sampled profile under the cam: with the best so far `b`, only
        // those with `top − d² / (2 rc) > b − guard`, i.e. `d² < 2 rc (top − b + guard)`.
        let curvature = 0.5 / rc;
        let mut floor = b - PRUNE_GUARD_M;
        let (mut lo, mut hi) = (lo, hi);
        if b.is_finite() {
            let span = (2.0 * rc * (self.top - floor)).max(0.0).sqrt();
            let near = (fast_floor((xj - span - s.x0) / s.h) - 1.0).max(0.0) as usize;
            let far = (fast_ceil((xj + span - s.x0) / s.h) + 2.0).max(0.0) as usize;
            lo = lo.max(near);
            hi = hi.min(far);
        }
        if lo < hi {
            for (k, &z) in s.z[lo..hi].iter().enumerate() {
                let d = s.x(lo + k) - xj;
                if z - curvature * d * d <= floor {
                    continue;
                }
                let v = z - (rc - (rc * rc - d * d).max(0.0).sqrt());
                if v > b {
                    b = v;
                    floor = b - PRUNE_GUARD_M;
                }
            }
        }
        b
    }
}

/// `v.floor()` without the library call (the baseline x86-64 target has no rounding
/// instruction, and `f64::floor` is a call): the same value for every `v`, but a negative
/// zero for `v` in (−1, −0] may come out as +0 (the cam base only compares and truncates
/// these).
#[inline]
fn fast_floor(v: f64) -> f64 {
    if v.abs() < 4.5e15 {
        let t = v as i64 as f64;
        if t > v {
            t - 1.0
        } else {
            t
        }
    } else {
        v.floor()
    }
}

/// `v.ceil()` without the library call, as [`fast_floor`].
#[inline]
fn fast_ceil(v: f64) -> f64 {
    if v.abs() < 4.5e15 {
        let t = v as i64 as f64;
        if t < v {
            t + 1.0
        } else {
            t
        }
    } else {
        v.ceil()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The cam base over every vertex and segment under the cam, vertices first: the
    /// definition [`Cams::base`] must give to the bit.
    fn base_over_every_sample(c: &Cams, xj: f64) -> f64 {
        let (s, rc) = (c.s, c.rc);
        let nseg = s.z.len().saturating_sub(1);
        let lo = (((xj - rc) - s.x0) / s.h).ceil().max(0.0) as usize;
        let hi = ((((xj + rc) - s.x0) / s.h).floor().max(-1.0) + 1.0) as usize;
        let hi = hi.min(s.z.len());
        let mut b = f64::NEG_INFINITY;
        for i in lo..hi {
            let d = s.x(i) - xj;
            b = b.max(s.z[i] - (rc - (rc * rc - d * d).max(0.0).sqrt()));
        }
        for i in lo.saturating_sub(1)..hi.min(nseg) {
            let xt = xj + c.seg.offset[i];
            if xt >= s.x(i) && xt <= s.x(i + 1) {
                b = b.max(s.z[i] + c.seg.slope[i] * (xj - s.x(i)) + c.seg.lift[i]);
            }
        }
        b
    }

    /// On rough profiles with steps, plateaus and spikes, cams of several radii give the
    /// same base with the low vertices skipped as over every sample, at cam centres on and
    /// between the samples and beyond the window's ends.
    #[test]
    fn skipping_low_vertices_leaves_the_cam_base_unchanged_to_the_bit() {
        let mut checked = 0;
        for (h, rc) in [(0.01, 0.8), (0.02, 0.3), (0.005, 1.2)] {
            let z: Vec<f64> = (0..400)
                .map(|i| {
                    let x = i as f64;
                    let step = ((i * 7919) % 13) as f64 / 13.0;
                    let spike = if i % 97 == 0 { 0.08 } else { 0.0 };
                    let plateau = if (150..180).contains(&i) { 0.0 } else { 1.0 };
                    plateau * (0.05 * (1.7 * x).sin() + 0.03 * (0.031 * x + 0.2).sin())
                        + 0.01 * step
                        + spike
                })
                .collect();
            let samples = Samples { x0: -1.0, h, z: &z };
            let mut segments = Segments::new();
            let cams = Cams::on(&samples, rc, &mut segments);
            let span = 400.0 * h;
            for k in 0..=2000 {
                let xj = -1.0 - 0.5 + (span + 1.0) * k as f64 / 2000.0;
                let (fast, every) = (cams.base(xj), base_over_every_sample(&cams, xj));
                assert_eq!(fast.to_bits(), every.to_bits(), "h {h}, rc {rc}, xj {xj}");
                checked += usize::from(fast.is_finite());
            }
        }
        assert!(checked > 5000, "{checked} finite bases");
    }
}
