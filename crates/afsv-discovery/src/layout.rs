//! Which channels of which record are compared, their normalisation, and the residual
//! vector of a configuration over a set of prepared records.

use super::{ActiveEffect, DiscoveryError, DiscoveryModel};
use afsv_records::Record;
use rayon::prelude::*;

/// One compared channel of one record: where it sits in the residual vector.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Segment {
    /// Channel index (into the model's channels).
    pub channel: usize,
    /// First sample compared.
    pub skip: usize,
    /// Offset into the residual vector.
    pub offset: usize,
    /// Samples compared.
    pub len: usize,
}

/// Records with their prepared inputs and the layout of their residuals.
pub(crate) struct RecordSet<'a, P> {
    /// The records.
    pub records: Vec<&'a Record>,
    /// Their prepared inputs, one per record.
    pub prepared: Vec<&'a P>,
    /// Channel names.
    pub channels: Vec<String>,
    /// Normalisation of each channel (training-set standard deviation).
    pub scales: Vec<f64>,
    /// Per record: its compared segments.
    pub segments: Vec<Vec<Segment>>,
    /// Length of the residual vector.
    pub n: usize,
}

impl<'a, P: Send + Sync> RecordSet<'a, P> {
    /// Lay out `records` by the channels a simulation of `baseline` predicts.
    pub fn new<M: DiscoveryModel<Prepared = P> + ?Sized>(
        model: &M,
        records: Vec<&'a Record>,
        prepared: Vec<&'a P>,
        channels: &[String],
        scales: &[f64],
        baseline: &[f64],
    ) -> Result<Self, DiscoveryError> {
        let preds: Vec<_> = prepared
            .par_iter()
            .map(|p| model.simulate(p, baseline, &[]))
            .collect();
        let mut segments = Vec::with_capacity(records.len());
        let mut n = 0;
        for (rec, pred) in records.iter().zip(preds) {
            let pred = pred?;
            let mut segs = Vec::new();
            for (c, name) in channels.iter().enumerate() {
                if let (Some(meas), Some(Some(p))) = (rec.column(name), pred.get(c)) {
                    let len = meas.len().min(p.len());
                    let skip = model.skip_samples(rec).min(len);
                    segs.push(Segment {
                        channel: c,
                        skip,
                        offset: n,
                        len: len - skip,
                    });
                    n += len - skip;
                }
            }
            segments.push(segs);
        }
        if n == 0 {
            return Err(DiscoveryError::NoChannels {
                channels: channels.join(", "),
            });
        }
        Ok(Self {
            records,
            prepared,
            channels: channels.to_vec(),
            scales: scales.to_vec(),
            segments,
            n,
        })
    }

    /// Normalised residuals of all records for the given configuration (records replayed
    /// in parallel).
    pub fn residuals<M: DiscoveryModel<Prepared = P> + ?Sized>(
        &self,
        model: &M,
        baseline: &[f64],
        effects: &[ActiveEffect<'_>],
        out: &mut [f64],
    ) -> Result<(), DiscoveryError> {
        let preds: Vec<_> = self
            .prepared
            .par_iter()
            .map(|p| model.simulate(p, baseline, effects))
            .collect();
        for ((rec, segs), pred) in self.records.iter().zip(&self.segments).zip(preds) {
            let pred = pred?;
            for s in segs {
                let name = &self.channels[s.channel];
                let meas = rec
                    .column(name)
                    .ok_or_else(|| DiscoveryError::ChannelLost {
                        channel: name.clone(),
                    })?;
                let p = pred
                    .get(s.channel)
                    .and_then(|p| p.as_ref())
                    .ok_or_else(|| DiscoveryError::PredictionMissing {
                        channel: name.clone(),
                    })?;
                if p.len() < s.skip + s.len || meas.len() < s.skip + s.len {
                    return Err(DiscoveryError::PredictionTooShort {
                        channel: name.clone(),
                    });
                }
                let scale = self.scales[s.channel];
                let dst = &mut out[s.offset..s.offset + s.len];
                for (i, d) in dst.iter_mut().enumerate() {
                    *d = (p[s.skip + i] - meas[s.skip + i]) / scale;
                }
            }
        }
        Ok(())
    }

    /// Residual vector of a configuration, allocated.
    pub fn residual_vec<M: DiscoveryModel<Prepared = P> + ?Sized>(
        &self,
        model: &M,
        baseline: &[f64],
        effects: &[ActiveEffect<'_>],
    ) -> Result<Vec<f64>, DiscoveryError> {
        let mut r = vec![0.0; self.n];
        self.residuals(model, baseline, effects, &mut r)?;
        Ok(r)
    }

    /// Per-channel RMS of normalised residuals `r` (`None` for a configuration that could
    /// not be simulated).
    pub fn per_channel(&self, r: Option<&[f64]>) -> Vec<super::ChannelError> {
        (0..self.channels.len())
            .map(|c| {
                let (mut s, mut n) = (0.0, 0usize);
                for seg in self.segments.iter().flatten().filter(|s| s.channel == c) {
                    if let Some(r) = r {
                        s += r[seg.offset..seg.offset + seg.len]
                            .iter()
                            .map(|v| v * v)
                            .sum::<f64>();
                    }
                    n += seg.len;
                }
                let nrmse = r.filter(|_| n > 0).map(|_| (s / n as f64).sqrt());
                super::ChannelError {
                    channel: self.channels[c].clone(),
                    rmse: nrmse.map(|v| v * self.scales[c]),
                    nrmse,
                    samples: n,
                }
            })
            .collect()
    }

    /// The residual slices of every compared segment.
    pub fn segment_slices<'r>(&self, r: &'r [f64]) -> Vec<&'r [f64]> {
        self.segments
            .iter()
            .flatten()
            .map(|s| &r[s.offset..s.offset + s.len])
            .collect()
    }

    /// Sum of squared residuals of each record.
    pub fn per_record_sse(&self, r: &[f64]) -> Vec<f64> {
        self.segments
            .iter()
            .map(|segs| {
                segs.iter()
                    .map(|s| {
                        r[s.offset..s.offset + s.len]
                            .iter()
                            .map(|v| v * v)
                            .sum::<f64>()
                    })
                    .sum()
            })
            .collect()
    }

    /// Measurement-noise variance of the compared samples, in normalised units, averaged
    /// over all samples (fourth-difference estimate per record and channel).
    pub fn noise_mse(&self) -> f64 {
        let (mut sum, mut n) = (0.0, 0usize);
        for (rec, segs) in self.records.iter().zip(&self.segments) {
            for s in segs {
                if let Some(meas) = rec.column(&self.channels[s.channel]) {
                    let scale = self.scales[s.channel];
                    sum +=
                        optimize::noise::measurement_noise_variance(&meas[s.skip..s.skip + s.len])
                            / (scale * scale)
                            * s.len as f64;
                    n += s.len;
                }
            }
        }
        if n > 0 {
            sum / n as f64
        } else {
            0.0
        }
    }

    /// As [`Self::noise_mse`], each record and channel's estimate bounded by the same
    /// estimate on its part of `residual` (a configuration's normalised residuals, laid out
    /// as [`Self::residual_vec`] gives them). Both are upper bounds of the noise: the
    /// measured channel's adds the signal's own high-frequency content, the residual's the
    /// model error's, and the noise is in both.
    pub fn noise_mse_bounded(&self, residual: &[f64]) -> f64 {
        let (mut sum, mut n) = (0.0, 0usize);
        for (rec, segs) in self.records.iter().zip(&self.segments) {
            for s in segs {
                if let (Some(meas), Some(r)) = (
                    rec.column(&self.channels[s.channel]),
                    residual.get(s.offset..s.offset + s.len),
                ) {
                    let scale = self.scales[s.channel];
                    let measured =
                        optimize::noise::measurement_noise_variance(&meas[s.skip..s.skip + s.len])
                            / (scale * scale);
                    let left = optimize::noise::measurement_noise_variance(r);
                    sum += measured.min(left) * s.len as f64;
                    n += s.len;
                }
            }
        }
        if n > 0 {
            sum / n as f64
        } else {
            0.0
        }
    }
}

/// Standard deviation of each channel over `records` (1 for a constant or absent channel).
pub(crate) fn channel_scales(records: &[Record], channels: &[String]) -> Vec<f64> {
    channels
        .iter()
        .map(|c| {
            let all: Vec<f64> = records
                .iter()
                .filter_map(|r| r.column(c))
                .flatten()
                .copied()
                .collect();
            let s = super::signature::std_dev(&all);
            if s > 0.0 {
                s
            } else {
                1.0
            }
        })
        .collect()
}

/// The names of `n` records: `names` where given, else `"{set} record k"` (1-based).
pub(crate) fn labels(names: &[String], n: usize, set: &str) -> Vec<String> {
    (0..n)
        .map(|i| {
            names
                .get(i)
                .cloned()
                .unwrap_or_else(|| format!("{set} record {}", i + 1))
        })
        .collect()
}
