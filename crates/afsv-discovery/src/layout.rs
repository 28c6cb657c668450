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
    /// The channel's normalisation for this record ([`ChannelScales::of_record`]).
    pub scale: f64,
}

/// Normalisation of each channel: its standard deviation over the training records, and
/// over each scaling group's training records ([`DiscoveryModel::scaling_group`]) for
/// models that scale each experiment kind by its own spread.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct ChannelScales {
    /// Over all training records (1 for a constant or absent channel).
    pub all: Vec<f64>,
    /// Per scaling group: its name and each channel's standard deviation over the group's
    /// training records (the whole set's where the group's is zero or absent).
    pub groups: Vec<(String, Vec<f64>)>,
}

impl ChannelScales {
    /// The scales of `records` (prepared as `prepared`) for `model`'s channels.
    pub fn new<M: DiscoveryModel + ?Sized>(
        model: &M,
        records: &[Record],
        prepared: &[M::Prepared],
        channels: &[String],
    ) -> Self {
        let all = channel_scales(records.iter(), channels, None);
        let mut names: Vec<String> = Vec::new();
        let kinds: Vec<Option<String>> = prepared.iter().map(|p| model.scaling_group(p)).collect();
        for k in kinds.iter().flatten() {
            if !names.contains(k) {
                names.push(k.clone());
            }
        }
        let groups = names
            .into_iter()
            .map(|g| {
                let recs = records
                    .iter()
                    .zip(&kinds)
                    .filter(|(_, k)| k.as_deref() == Some(g.as_str()))
                    .map(|(r, _)| r);
                let scales = channel_scales(recs, channels, Some(&all));
                (g, scales)
            })
            .collect();
        Self { all, groups }
    }

    /// The whole set's scales for every record, whatever the model's scaling groups.
    pub fn whole_set(records: &[Record], channels: &[String]) -> Self {
        Self {
            all: channel_scales(records.iter(), channels, None),
            groups: Vec::new(),
        }
    }

    /// The scales of a record of scaling group `group` (the whole set's for `None` or a
    /// group without training records).
    pub fn of_record(&self, group: Option<&str>) -> &[f64] {
        group
            .and_then(|g| self.groups.iter().find(|(n, _)| n == g))
            .map_or(&self.all, |(_, s)| s)
    }
}

/// Records with their prepared inputs and the layout of their residuals.
pub(crate) struct RecordSet<'a, P> {
    /// The records.
    pub records: Vec<&'a Record>,
    /// Their prepared inputs, one per record.
    pub prepared: Vec<&'a P>,
    /// Channel names.
    pub channels: Vec<String>,
    /// Normalisation of each channel (training-set standard deviations; each segment holds
    /// its own in [`Segment::scale`]).
    pub scales: ChannelScales,
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
        scales: &ChannelScales,
        baseline: &[f64],
    ) -> Result<Self, DiscoveryError> {
        let preds: Vec<_> = prepared
            .par_iter()
            .map(|p| model.simulate(p, baseline, &[]))
            .collect();
        let mut segments = Vec::with_capacity(records.len());
        let mut n = 0;
        for ((rec, prep), pred) in records.iter().zip(&prepared).zip(preds) {
            let pred = pred?;
            let kind = model.scaling_group(prep);
            let scale = scales.of_record(kind.as_deref());
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
                        scale: scale[c],
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
            scales: scales.clone(),
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
                let scale = s.scale;
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
    /// not be simulated), and the RMS of the residuals in the channel's unit.
    pub fn per_channel(&self, r: Option<&[f64]>) -> Vec<super::ChannelError> {
        (0..self.channels.len())
            .map(|c| {
                let (mut s, mut s_unit, mut n) = (0.0, 0.0, 0usize);
                for seg in self.segments.iter().flatten().filter(|s| s.channel == c) {
                    if let Some(r) = r {
                        let sq = r[seg.offset..seg.offset + seg.len]
                            .iter()
                            .map(|v| v * v)
                            .sum::<f64>();
                        s += sq;
                        s_unit += sq * seg.scale * seg.scale;
                    }
                    n += seg.len;
                }
                let nrmse = r.filter(|_| n > 0).map(|_| (s / n as f64).sqrt());
                super::ChannelError {
                    channel: self.channels[c].clone(),
                    rmse: nrmse.map(|_| (s_unit / n as f64).sqrt()),
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
                    let scale = s.scale;
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
                    let scale = s.scale;
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

/// Standard deviation of each channel over `records` (`fallback`'s entry, else 1, for a
/// constant or absent channel).
fn channel_scales<'r>(
    records: impl Iterator<Item = &'r Record> + Clone,
    channels: &[String],
    fallback: Option<&[f64]>,
) -> Vec<f64> {
    channels
        .iter()
        .enumerate()
        .map(|(k, c)| {
            let all: Vec<f64> = records
                .clone()
                .filter_map(|r| r.column(c))
                .flatten()
                .copied()
                .collect();
            let s = super::signature::std_dev(&all);
            if s > 0.0 {
                s
            } else {
                fallback.map_or(1.0, |f| f[k])
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{EffectSpec, ParamSpec, Phase};

    /// One channel `y`, predicted as zero; the scaling group is the sidecar's `kind` when
    /// `grouped`.
    struct Kinds {
        grouped: bool,
    }

    impl DiscoveryModel for Kinds {
        type Prepared = Option<String>;
        fn name(&self) -> &str {
            "kinds"
        }
        fn channels(&self) -> Vec<String> {
            vec!["y".into()]
        }
        fn baseline_params(&self) -> Vec<ParamSpec> {
            Vec::new()
        }
        fn catalogue(&self) -> Vec<EffectSpec> {
            Vec::new()
        }
        fn prepare(&self, record: &Record) -> Result<Option<String>, DiscoveryError> {
            Ok(record.meta["kind"].as_str().map(str::to_string))
        }
        fn condition(&self, kind: &Option<String>) -> String {
            format!("{kind:?}")
        }
        fn scaling_group(&self, kind: &Option<String>) -> Option<String> {
            kind.clone().filter(|_| self.grouped)
        }
        fn simulate(
            &self,
            _: &Option<String>,
            _: &[f64],
            _: &[ActiveEffect<'_>],
        ) -> Result<Vec<Option<Vec<f64>>>, DiscoveryError> {
            Ok(vec![Some(vec![0.0; 4])])
        }
        fn phases(&self, _: &Record) -> Vec<Phase> {
            Vec::new()
        }
    }

    fn record(kind: &str, y: [f64; 4]) -> Record {
        let mut r = Record::new();
        r.push_column("y", y.to_vec()).unwrap();
        r.meta = serde_json::json!({ "kind": kind });
        r
    }

    /// Scales of each record's segment, residual RMS in the channel's unit over `holdout`.
    fn laid_out(grouped: bool, holdout: &[Record]) -> (Vec<f64>, f64) {
        let model = Kinds { grouped };
        let train = [
            record("ride", [10.0, -10.0, 10.0, -10.0]),
            record("ride", [20.0, -20.0, 20.0, -20.0]),
            record("change", [1.0, -1.0, 1.0, -1.0]),
        ];
        let tp: Vec<_> = train.iter().map(|r| model.prepare(r).unwrap()).collect();
        let channels = model.channels();
        let scales = ChannelScales::new(&model, &train, &tp, &channels);
        let hp: Vec<_> = holdout.iter().map(|r| model.prepare(r).unwrap()).collect();
        let set = RecordSet::new(
            &model,
            holdout.iter().collect(),
            hp.iter().collect(),
            &channels,
            &scales,
            &[],
        )
        .unwrap();
        let r = set.residual_vec(&model, &[], &[]).unwrap();
        let rmse = set.per_channel(Some(&r))[0].rmse.unwrap();
        (
            set.segments.iter().flatten().map(|s| s.scale).collect(),
            rmse,
        )
    }

    #[test]
    fn each_experiment_kind_is_scaled_by_its_own_spread_where_the_model_asks() {
        let holdout = [
            record("ride", [15.0, -15.0, 15.0, -15.0]),
            record("change", [2.0, -2.0, 2.0, -2.0]),
            record("other", [3.0, -3.0, 3.0, -3.0]),
        ];
        let std = |v: &[f64]| crate::signature::std_dev(v);
        let all = std(&[
            10.0, -10.0, 10.0, -10.0, 20.0, -20.0, 20.0, -20.0, 1.0, -1.0, 1.0, -1.0,
        ]);
        let ride = std(&[10.0, -10.0, 10.0, -10.0, 20.0, -20.0, 20.0, -20.0]);
        let change = std(&[1.0, -1.0, 1.0, -1.0]);
        // The default: every record by the whole training set's spread.
        let (whole, rmse_whole) = laid_out(false, &holdout);
        assert_eq!(whole, vec![all; 3]);
        // Grouped: each kind by its own training records' spread, a kind without training
        // records by the whole set's.
        let (grouped, rmse_grouped) = laid_out(true, &holdout);
        assert_eq!(grouped, vec![ride, change, all]);
        assert!(ride > 10.0 * change);
        // The error in the channel's unit does not depend on the scaling.
        let rms = ((15.0f64.powi(2) + 2.0f64.powi(2) + 3.0f64.powi(2)) / 3.0).sqrt();
        assert!((rmse_whole - rms).abs() < 1e-12 * rms);
        assert!((rmse_grouped - rms).abs() < 1e-12 * rms);
    }
}
