//! The calibrate / locate / try / name loop of [`discover`](super).

use super::signature::{channel_signature, std_dev, ChannelSignature};
use super::stats::{self, SignificanceRule};
use super::{ActiveEffect, DiscoveryModel, ParamSpec};
use crate::record::Record;
use optimize::least_squares::{fit, FitOptions, Problem};
use rayon::prelude::*;

/// Settings of [`discover`].
#[derive(Debug, Clone, PartialEq)]
pub struct DiscoveryOptions {
    /// When an effect counts as significant.
    pub rule: SignificanceRule,
    /// Stop after naming this many effects.
    pub max_effects: usize,
    /// Levenberg-Marquardt iteration limit per fit.
    pub max_iter: usize,
    /// Restrict the catalogue to these effect names (all when `None`).
    pub candidates: Option<Vec<String>>,
    /// Free the baseline's calibrated parameters again while fitting each candidate.
    pub refit_baseline: bool,
    /// Band split for the residual signatures (Hz).
    pub split_hz: f64,
    /// Start points scouted per candidate: each gets a short fit of
    /// [`SCOUT_ITERATIONS`], and the best is fitted to convergence. 1 = fit the best start
    /// point only.
    pub starts: usize,
}

/// Levenberg-Marquardt iterations of a scouting fit (see [`DiscoveryOptions::starts`]).
pub const SCOUT_ITERATIONS: usize = 6;

impl Default for DiscoveryOptions {
    fn default() -> Self {
        Self {
            rule: SignificanceRule::default(),
            max_effects: 4,
            max_iter: 30,
            candidates: None,
            refit_baseline: true,
            split_hz: 2.0,
            starts: 3,
        }
    }
}

/// Something to tell the user while fits run (e.g. advance a progress bar).
pub trait Progress: Sync {
    /// A fit of `what` finished.
    fn fit_done(&self, what: &str);
}

impl Progress for () {
    fn fit_done(&self, _: &str) {}
}

/// Error of one channel over a set of records.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ChannelError {
    /// Channel name.
    pub channel: String,
    /// RMS error in channel units.
    pub rmse: f64,
    /// RMS error over the channel's standard deviation (training-set scale).
    pub nrmse: f64,
    /// Samples compared.
    pub samples: usize,
}

/// A fitted configuration: baseline values plus active effects.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct FitOutcome {
    /// Names of the active effects.
    pub effects: Vec<String>,
    /// Baseline parameter names.
    pub baseline_names: Vec<String>,
    /// Baseline parameter values.
    pub baseline: Vec<f64>,
    /// Their standard errors (`NaN` for parameters held fixed).
    pub baseline_se: Vec<f64>,
    /// Per active effect: parameter names, values and standard errors.
    pub effect_params: Vec<Vec<(String, f64, f64)>>,
    /// Normalised residual mean square on the training records.
    pub train_mse: f64,
    /// Normalised residual mean square on the held-out records.
    pub holdout_mse: f64,
    /// Effective-sample BIC on the training records (see [`stats`]).
    pub bic: f64,
    /// Effective-sample AIC on the training records.
    pub aic: f64,
    /// Number of fitted parameters.
    pub k: usize,
    /// Whether the least-squares fit met its convergence test.
    pub converged: bool,
}

/// One candidate tried in one round.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct EffectChoice {
    /// Effect name.
    pub effect: String,
    /// The fitted configuration, or why it failed.
    pub outcome: Result<FitOutcome, String>,
    /// Relative decrease of the held-out error against the round's starting model.
    pub holdout_gain: f64,
    /// BIC decrease against the round's starting model.
    pub bic_drop: f64,
}

/// One round of the greedy search.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Step {
    /// Candidates tried, best held-out error first.
    pub candidates: Vec<EffectChoice>,
    /// The effect named in this round, if any was significant.
    pub named: Option<String>,
    /// Set when the best candidate failed the attribution check: refitting the model as it
    /// stood, started from that candidate's solution, explained the same gap, so the round
    /// was repeated against the better-fitted model.
    pub attribution: Option<String>,
}

/// Everything the workflow found.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Discovery {
    /// Model name.
    pub model: String,
    /// Channels compared.
    pub channels: Vec<String>,
    /// Nominal (uncalibrated) baseline.
    pub nominal: FitOutcome,
    /// Calibrated baseline.
    pub calibrated: FitOutcome,
    /// Where the calibrated baseline disagrees, per training and held-out record and channel.
    pub signatures: Vec<(String, ChannelSignature)>,
    /// Greedy rounds.
    pub steps: Vec<Step>,
    /// Effects named, in order.
    pub named: Vec<String>,
    /// Final model (calibrated baseline plus named effects).
    pub final_model: FitOutcome,
    /// Per-channel errors: (training before, training after, held-out before, held-out after).
    pub channel_errors: Vec<(ChannelError, ChannelError, ChannelError, ChannelError)>,
    /// Estimated measurement-noise share of the normalised held-out error.
    pub holdout_noise_mse: f64,
    /// Fraction of the reducible held-out error removed by the named effects.
    pub gap_shrink: f64,
    /// When nothing was named: the best candidate's share of the reducible gap.
    pub best_unnamed_shrink: Option<(String, f64)>,
}

/// A fitted configuration with its effective sample size.
type Fitted = (FitOutcome, Config, f64);

/// Which channels of which record are compared, and their normalisation.
struct Layout {
    channels: Vec<String>,
    scales: Vec<f64>,
    /// Per record: (channel index, first sample compared, offset into the residual vector,
    /// length).
    segments: Vec<Vec<(usize, usize, usize, usize)>>,
    n: usize,
}

impl Layout {
    fn new<M: DiscoveryModel + ?Sized>(
        model: &M,
        records: &[Record],
        channels: &[String],
        scales: &[f64],
        baseline: &[f64],
    ) -> Result<Self, String> {
        let mut segments = Vec::with_capacity(records.len());
        let mut n = 0;
        for rec in records {
            let pred = model.simulate(rec, baseline, &[])?;
            let mut segs = Vec::new();
            for (c, name) in channels.iter().enumerate() {
                if let (Some(meas), Some(Some(p))) = (rec.column(name), pred.get(c)) {
                    let len = meas.len().min(p.len());
                    let skip = model.skip_samples(rec).min(len);
                    segs.push((c, skip, n, len - skip));
                    n += len - skip;
                }
            }
            segments.push(segs);
        }
        if n == 0 {
            return Err(format!(
                "no record has any of the channels the model predicts ({})",
                channels.join(", ")
            ));
        }
        Ok(Self {
            channels: channels.to_vec(),
            scales: scales.to_vec(),
            segments,
            n,
        })
    }

    /// Normalised residuals of all records for the given configuration.
    fn residuals<M: DiscoveryModel + ?Sized>(
        &self,
        model: &M,
        records: &[Record],
        baseline: &[f64],
        effects: &[ActiveEffect<'_>],
        out: &mut [f64],
    ) -> Result<(), String> {
        let preds: Vec<Result<Vec<Option<Vec<f64>>>, String>> = records
            .par_iter()
            .map(|rec| model.simulate(rec, baseline, effects))
            .collect();
        for ((rec, segs), pred) in records.iter().zip(&self.segments).zip(preds) {
            let pred = pred?;
            for &(c, skip, off, len) in segs {
                let meas = rec
                    .column(&self.channels[c])
                    .ok_or("record lost a channel")?;
                let p = pred
                    .get(c)
                    .and_then(|p| p.as_ref())
                    .ok_or_else(|| format!("model stopped predicting `{}`", self.channels[c]))?;
                if p.len() < skip + len || meas.len() < skip + len {
                    return Err(format!("prediction of `{}` is too short", self.channels[c]));
                }
                let s = self.scales[c];
                for i in 0..len {
                    out[off + i] = (p[skip + i] - meas[skip + i]) / s;
                }
            }
        }
        Ok(())
    }

    /// Per-channel RMS of normalised residuals `r` (NaN everywhere when `ok` is false, i.e.
    /// the configuration could not be simulated).
    fn per_channel(&self, r: &[f64], ok: bool) -> Vec<ChannelError> {
        (0..self.channels.len())
            .map(|c| {
                let (mut s, mut n) = (0.0, 0usize);
                for &(ch, _, off, len) in self.segments.iter().flatten() {
                    if ch == c {
                        s += r[off..off + len].iter().map(|v| v * v).sum::<f64>();
                        n += len;
                    }
                }
                let nrmse = if ok && n > 0 {
                    (s / n as f64).sqrt()
                } else {
                    f64::NAN
                };
                ChannelError {
                    channel: self.channels[c].clone(),
                    rmse: nrmse * self.scales[c],
                    nrmse,
                    samples: n,
                }
            })
            .collect()
    }

    fn segment_slices<'a>(&self, r: &'a [f64]) -> Vec<&'a [f64]> {
        self.segments
            .iter()
            .flatten()
            .map(|&(_, _, off, len)| &r[off..off + len])
            .collect()
    }
}

/// A configuration to fit: which baseline parameters are free and which effects are on.
#[derive(Clone)]
struct Config {
    baseline: Vec<f64>,
    free_baseline: Vec<usize>,
    effects: Vec<(usize, Vec<f64>)>,
}

impl Config {
    fn pack(&self) -> Vec<f64> {
        let mut p: Vec<f64> = self
            .free_baseline
            .iter()
            .map(|&i| self.baseline[i])
            .collect();
        for (_, v) in &self.effects {
            p.extend_from_slice(v);
        }
        p
    }

    fn unpack(&self, p: &[f64]) -> Config {
        let mut c = self.clone();
        for (k, &i) in self.free_baseline.iter().enumerate() {
            c.baseline[i] = p[k];
        }
        let mut off = self.free_baseline.len();
        for (_, v) in c.effects.iter_mut() {
            let n = v.len();
            v.copy_from_slice(&p[off..off + n]);
            off += n;
        }
        c
    }

    fn active(&self) -> Vec<ActiveEffect<'_>> {
        self.effects
            .iter()
            .map(|(index, values)| ActiveEffect {
                index: *index,
                values,
            })
            .collect()
    }
}

struct Objective<'a, M: ?Sized> {
    model: &'a M,
    records: &'a [Record],
    layout: &'a Layout,
    config: Config,
}

impl<M: DiscoveryModel + ?Sized> Problem for Objective<'_, M> {
    fn n_params(&self) -> usize {
        self.config.pack().len()
    }
    fn n_residuals(&self) -> usize {
        self.layout.n
    }
    fn residuals(&self, p: &[f64], r: &mut [f64]) -> Result<(), String> {
        let c = self.config.unpack(p);
        self.layout
            .residuals(self.model, self.records, &c.baseline, &c.active(), r)
    }
}

struct Context<'a, M: ?Sized> {
    model: &'a M,
    train: &'a [Record],
    holdout: &'a [Record],
    lt: Layout,
    lh: Layout,
    base_specs: Vec<ParamSpec>,
    catalogue: Vec<super::EffectSpec>,
    opts: &'a DiscoveryOptions,
}

impl<M: DiscoveryModel + ?Sized> Context<'_, M> {
    fn bounds(&self, config: &Config) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
        let mut lo = Vec::new();
        let mut hi = Vec::new();
        let mut typ = Vec::new();
        for &i in &config.free_baseline {
            let s = &self.base_specs[i];
            lo.push(s.lower);
            hi.push(s.upper);
            typ.push(s.typical);
        }
        for (e, _) in &config.effects {
            for s in &self.catalogue[*e].params {
                lo.push(s.lower);
                hi.push(s.upper);
                typ.push(s.typical);
            }
        }
        (lo, hi, typ)
    }

    /// Fit a configuration on the training records (or just evaluate it when nothing is free)
    /// and score it on the held-out records. `n_eff` fixes the effective sample size used in
    /// the information criteria so that models compared within a round share it.
    fn fit(&self, config: Config, n_eff: Option<f64>) -> Result<Fitted, String> {
        self.fit_for(config, n_eff, self.opts.max_iter)
    }

    /// [`Self::fit`] with an iteration limit.
    fn fit_for(
        &self,
        config: Config,
        n_eff: Option<f64>,
        max_iter: usize,
    ) -> Result<Fitted, String> {
        let p0 = config.pack();
        let (params, se, converged) = if p0.is_empty() {
            (Vec::new(), Vec::new(), true)
        } else {
            let (lower, upper, typical) = self.bounds(&config);
            let obj = Objective {
                model: self.model,
                records: self.train,
                layout: &self.lt,
                config: config.clone(),
            };
            let res = fit(
                &obj,
                &p0,
                &FitOptions {
                    max_iter,
                    ftol: 1e-8,
                    xtol: 1e-8,
                    lower: Some(lower),
                    upper: Some(upper),
                    diff_step: 1e-3,
                    typical: Some(typical),
                },
            )
            .map_err(|e| e.to_string())?;
            (res.params, res.std_errors, res.converged)
        };
        let fitted = if params.is_empty() {
            config.clone()
        } else {
            config.unpack(&params)
        };
        let mut rt = vec![0.0; self.lt.n];
        self.lt.residuals(
            self.model,
            self.train,
            &fitted.baseline,
            &fitted.active(),
            &mut rt,
        )?;
        let mut rh = vec![0.0; self.lh.n];
        self.lh.residuals(
            self.model,
            self.holdout,
            &fitted.baseline,
            &fitted.active(),
            &mut rh,
        )?;
        let rss: f64 = rt.iter().map(|v| v * v).sum();
        let n = self.lt.n as f64;
        let n_eff_here = stats::effective_samples(&self.lt.segment_slices(&rt));
        let n_eff = n_eff.unwrap_or(n_eff_here);
        let k = p0.len();
        let mut baseline_se = vec![f64::NAN; fitted.baseline.len()];
        for (j, &i) in fitted.free_baseline.iter().enumerate() {
            baseline_se[i] = se.get(j).copied().unwrap_or(f64::NAN);
        }
        let mut off = fitted.free_baseline.len();
        let mut effect_params = Vec::new();
        for (e, v) in &fitted.effects {
            let specs = &self.catalogue[*e].params;
            effect_params.push(
                specs
                    .iter()
                    .zip(v)
                    .enumerate()
                    .map(|(j, (s, &val))| {
                        (
                            s.name.clone(),
                            val,
                            se.get(off + j).copied().unwrap_or(f64::NAN),
                        )
                    })
                    .collect(),
            );
            off += v.len();
        }
        let outcome = FitOutcome {
            effects: fitted
                .effects
                .iter()
                .map(|(e, _)| self.catalogue[*e].name.clone())
                .collect(),
            baseline_names: self.base_specs.iter().map(|s| s.name.clone()).collect(),
            baseline: fitted.baseline.clone(),
            baseline_se,
            effect_params,
            train_mse: rss / n,
            holdout_mse: rh.iter().map(|v| v * v).sum::<f64>() / self.lh.n as f64,
            bic: stats::bic(rss, n, n_eff, k),
            aic: stats::aic(rss, n, n_eff, k),
            k,
            converged,
        };
        Ok((outcome, fitted, n_eff_here))
    }

    /// Start values `(baseline, effect)` for effect `e` added to `base`, best training error
    /// first: the effect's nominal start, its "off" corner and a few points spread over its
    /// bounds (log-spaced where the range spans decades), each with the better of the
    /// baseline as fitted and at its nominal values. Guards against starting where the
    /// effect is inactive (a saturation limit above the signal, a dead zone of zero width)
    /// and the gradient is zero, and against a calibration that has bent the baseline
    /// towards the missing effect.
    fn ranked_starts(
        &self,
        base: &Config,
        nominal_baseline: &[f64],
        e: usize,
    ) -> Vec<(Vec<f64>, Vec<f64>)> {
        let specs = &self.catalogue[e].params;
        let nominal: Vec<f64> = specs.iter().map(|s| s.initial).collect();
        let fractions = [0.5, 0.1, 0.9, 0.3, 0.7];
        // The lower bounds switch most effects off (zero play, leakage, droop, friction):
        // starting there, the candidate can only improve on the model as it stands.
        let mut starts = vec![nominal.clone(), specs.iter().map(|s| s.lower).collect()];
        for k in 0..fractions.len() {
            starts.push(
                specs
                    .iter()
                    .enumerate()
                    .map(|(j, s)| {
                        let f = fractions[(k + j) % fractions.len()];
                        if s.lower > 0.0 && s.upper / s.lower >= 100.0 && s.upper.is_finite() {
                            (s.lower.ln() + f * (s.upper.ln() - s.lower.ln())).exp()
                        } else if s.lower.is_finite() && s.upper.is_finite() {
                            s.lower + f * (s.upper - s.lower)
                        } else {
                            s.initial
                        }
                    })
                    .collect(),
            );
        }
        // The calibrated baseline may have absorbed part of the missing effect (viscous
        // friction standing in for Coulomb friction): each start is also tried with the
        // baseline back at its nominal values.
        let mut bases = vec![base.baseline.clone()];
        if nominal_baseline != base.baseline.as_slice() {
            bases.push(nominal_baseline.to_vec());
        }
        let mut r = vec![0.0; self.lt.n];
        // Per effect start: the better of the two baselines.
        let mut ranked: Vec<(f64, Vec<f64>, Vec<f64>)> = Vec::new();
        for start in starts {
            let mut best: Option<(f64, Vec<f64>)> = None;
            for b in &bases {
                let mut cfg = base.clone();
                cfg.baseline.clone_from(b);
                cfg.effects.push((e, start.clone()));
                if self
                    .lt
                    .residuals(self.model, self.train, &cfg.baseline, &cfg.active(), &mut r)
                    .is_ok()
                {
                    let rss: f64 = r.iter().map(|v| v * v).sum();
                    if best.as_ref().is_none_or(|(b_rss, _)| rss < *b_rss) {
                        best = Some((rss, b.clone()));
                    }
                }
            }
            if let Some((rss, b)) = best {
                if !ranked.iter().any(|(_, _, s)| *s == start) {
                    ranked.push((rss, b, start));
                }
            }
        }
        ranked.sort_by(|a, b| a.0.total_cmp(&b.0));
        if ranked.is_empty() {
            ranked.push((f64::INFINITY, base.baseline.clone(), nominal));
        }
        ranked.into_iter().map(|(_, b, s)| (b, s)).collect()
    }

    /// Fit candidate effect `e` added to `current`: scout the best few start points
    /// ([`DiscoveryOptions::starts`]) with short fits, then fit the best to convergence.
    /// The error surface of an effect parameter is often not convex once the baseline has
    /// been calibrated without it (a tire relaxation length trades against the cornering
    /// stiffness, so a tiny length can look better than the true one from the calibrated
    /// point), and the start with the lowest initial error is then the wrong basin.
    fn fit_candidate(
        &self,
        current: &Config,
        nominal_baseline: &[f64],
        e: usize,
        n_eff: f64,
    ) -> Result<Fitted, String> {
        let all_base: Vec<usize> = (0..current.baseline.len()).collect();
        let starts = if self.opts.refit_baseline {
            self.ranked_starts(current, nominal_baseline, e)
        } else {
            self.ranked_starts(current, &current.baseline, e)
        };
        let config_at = |(b, s): &(Vec<f64>, Vec<f64>)| {
            let mut cfg = current.clone();
            cfg.free_baseline = if self.opts.refit_baseline {
                all_base.clone()
            } else {
                Vec::new()
            };
            cfg.baseline.clone_from(b);
            cfg.effects.push((e, s.clone()));
            cfg
        };
        let k = self.opts.starts.max(1).min(starts.len());
        if k == 1 {
            return self.fit(config_at(&starts[0]), Some(n_eff));
        }
        let mut best: Option<Fitted> = None;
        let mut last_err = String::new();
        for start in &starts[..k] {
            match self.fit_for(config_at(start), Some(n_eff), SCOUT_ITERATIONS) {
                Ok(f) => {
                    if best.as_ref().is_none_or(|b| f.0.train_mse < b.0.train_mse) {
                        best = Some(f);
                    }
                }
                Err(msg) => last_err = msg,
            }
        }
        let (_, cfg, _) = best.ok_or(last_err)?;
        self.fit(cfg, Some(n_eff))
    }

    fn channel_errors(
        &self,
        records: &[Record],
        layout: &Layout,
        config: &Config,
    ) -> Vec<ChannelError> {
        let mut r = vec![0.0; layout.n];
        let ok = layout
            .residuals(
                self.model,
                records,
                &config.baseline,
                &config.active(),
                &mut r,
            )
            .is_ok();
        layout.per_channel(&r, ok)
    }
}

/// Per-channel error of a configuration given as baseline values and active effects,
/// normalised by each channel's standard deviation over `records`.
pub fn evaluate_errors<M: DiscoveryModel + ?Sized>(
    model: &M,
    records: &[Record],
    baseline: &[f64],
    effects: &[ActiveEffect<'_>],
) -> Result<Vec<ChannelError>, String> {
    let channels = model.channels();
    let scales = channel_scales(records, &channels);
    let layout = Layout::new(model, records, &channels, &scales, baseline)?;
    let mut r = vec![0.0; layout.n];
    layout.residuals(model, records, baseline, effects, &mut r)?;
    Ok(layout.per_channel(&r, true))
}

fn channel_scales(records: &[Record], channels: &[String]) -> Vec<f64> {
    channels
        .iter()
        .map(|c| {
            let all: Vec<f64> = records
                .iter()
                .filter_map(|r| r.column(c))
                .flatten()
                .copied()
                .collect();
            let s = std_dev(&all);
            if s > 0.0 {
                s
            } else {
                1.0
            }
        })
        .collect()
}

/// Calibrate the baseline's uncertain parameters on `train` (step 0 of the workflow).
pub fn calibrate<M: DiscoveryModel + ?Sized>(
    model: &M,
    train: &[Record],
    opts: &DiscoveryOptions,
) -> Result<FitOutcome, String> {
    let d = discover_inner(model, train, train, &[], &[], opts, &(), false)?;
    Ok(d.calibrated)
}

/// Run the whole workflow: calibrate on `train`, locate, try the catalogue, name the
/// significant effects, and measure the gap on `holdout`. Record names label the signatures.
pub fn discover<M: DiscoveryModel + ?Sized>(
    model: &M,
    train: &[Record],
    holdout: &[Record],
    train_names: &[String],
    holdout_names: &[String],
    opts: &DiscoveryOptions,
    progress: &dyn Progress,
) -> Result<Discovery, String> {
    discover_inner(
        model,
        train,
        holdout,
        train_names,
        holdout_names,
        opts,
        progress,
        true,
    )
}

#[allow(clippy::too_many_arguments)]
fn discover_inner<M: DiscoveryModel + ?Sized>(
    model: &M,
    train: &[Record],
    holdout: &[Record],
    train_names: &[String],
    holdout_names: &[String],
    opts: &DiscoveryOptions,
    progress: &dyn Progress,
    search: bool,
) -> Result<Discovery, String> {
    if train.is_empty() || holdout.is_empty() {
        return Err("need at least one training and one held-out record".into());
    }
    let channels = model.channels();
    let base_specs = model.baseline_params();
    let catalogue = model.catalogue();
    if let Some(names) = &opts.candidates {
        for n in names {
            if !catalogue.iter().any(|e| &e.name == n) {
                return Err(format!(
                    "unknown effect `{n}` for model {} (catalogue: {})",
                    model.name(),
                    catalogue
                        .iter()
                        .map(|e| e.name.as_str())
                        .collect::<Vec<_>>()
                        .join(", ")
                ));
            }
        }
    }
    let nominal_base: Vec<f64> = base_specs.iter().map(|s| s.initial).collect();
    let scales = channel_scales(train, &channels);
    let lt = Layout::new(model, train, &channels, &scales, &nominal_base)?;
    let lh = Layout::new(model, holdout, &channels, &scales, &nominal_base)?;
    let ctx = Context {
        model,
        train,
        holdout,
        lt,
        lh,
        base_specs,
        catalogue,
        opts,
    };
    let all_base: Vec<usize> = (0..nominal_base.len()).collect();
    let nominal_cfg = Config {
        baseline: nominal_base.clone(),
        free_baseline: Vec::new(),
        effects: Vec::new(),
    };
    let (nominal, _, _) = ctx.fit(nominal_cfg.clone(), None)?;
    let (mut current, mut current_cfg, mut n_eff) = ctx.fit(
        Config {
            free_baseline: all_base.clone(),
            ..nominal_cfg.clone()
        },
        None,
    )?;
    progress.fit_done("baseline calibration");
    let calibrated = current.clone();
    let calibrated_cfg = current_cfg.clone();

    // Step 2: locate the disagreement of the calibrated baseline.
    let mut signatures = Vec::new();
    for (set, names) in [(train, train_names), (holdout, holdout_names)] {
        for (i, rec) in set.iter().enumerate() {
            let label = names
                .get(i)
                .cloned()
                .unwrap_or_else(|| format!("record {i}"));
            let pred = model.simulate(rec, &calibrated_cfg.baseline, &[])?;
            let t: Vec<f64> = rec
                .column("time_s")
                .map(<[f64]>::to_vec)
                .unwrap_or_else(|| (0..rec.len()).map(|i| i as f64).collect());
            let phases = model.phases(rec);
            for (c, ch) in channels.iter().enumerate() {
                if let (Some(meas), Some(Some(p))) = (rec.column(ch), pred.get(c)) {
                    signatures.push((
                        label.clone(),
                        channel_signature(ch, &t, meas, p, &phases, None, opts.split_hz),
                    ));
                }
            }
        }
    }

    let mut steps = Vec::new();
    let mut named = Vec::new();
    let mut best_unnamed = None;
    // Noise floor of the held-out records in normalised units.
    let mut noise_sum = 0.0;
    let mut noise_n = 0usize;
    for (rec, segs) in holdout.iter().zip(&ctx.lh.segments) {
        for &(c, skip, _, len) in segs {
            if let Some(meas) = rec.column(&channels[c]) {
                noise_sum += stats::noise_variance(&meas[skip..skip + len])
                    / (scales[c] * scales[c])
                    * len as f64;
                noise_n += len;
            }
        }
    }
    let holdout_noise_mse = if noise_n > 0 {
        noise_sum / noise_n as f64
    } else {
        0.0
    };
    let baseline_gap = (calibrated.holdout_mse - holdout_noise_mse).max(0.0);
    // Rounds repeated after a failed attribution check (each lowers the reference's training
    // error, so this only bounds the run time).
    const MAX_REPEATS: usize = 2;
    let mut repeats = 0;
    while search && named.len() < opts.max_effects {
        // No candidate can pass the gap-fraction test when less than that fraction of the
        // baseline's gap is left: stop without trying.
        if !named.is_empty()
            && current.holdout_mse - holdout_noise_mse < opts.rule.min_gap_fraction * baseline_gap
        {
            break;
        }
        if !named.is_empty() && repeats == 0 {
            // Refit the model as it stands, so that candidates are not credited with the
            // improvement that more iterations on the same model would give anyway.
            let (o, cfg, ne) = ctx.fit(current_cfg.clone(), Some(n_eff))?;
            if o.train_mse <= current.train_mse {
                current = o;
                current_cfg = cfg;
                n_eff = ne;
            }
            progress.fit_done("refit of the current model");
        }
        let tried: Vec<usize> = (0..ctx.catalogue.len())
            .filter(|&e| !current_cfg.effects.iter().any(|(a, _)| *a == e))
            .filter(|&e| {
                opts.candidates
                    .as_ref()
                    .is_none_or(|names| names.contains(&ctx.catalogue[e].name))
            })
            .collect();
        if tried.is_empty() {
            break;
        }
        let results: Vec<(usize, Result<Fitted, String>)> = tried
            .par_iter()
            .map(|&e| {
                let r = ctx.fit_candidate(&current_cfg, &nominal_base, e, n_eff);
                progress.fit_done(&ctx.catalogue[e].name);
                (e, r)
            })
            .collect();
        // The round's reference must be scored with the same n_eff and parameter count
        // convention as the candidates: its BIC counts all parameters it has free.
        let k_ref = all_base.len() * usize::from(opts.refit_baseline)
            + current_cfg
                .effects
                .iter()
                .map(|(_, v)| v.len())
                .sum::<usize>();
        let ref_bic = stats::bic(
            current.train_mse * ctx.lt.n as f64,
            ctx.lt.n as f64,
            n_eff,
            k_ref,
        );
        let mut choices: Vec<(EffectChoice, Option<(Config, f64)>)> = results
            .into_iter()
            .map(|(e, r)| match r {
                Ok((o, cfg, ne)) => {
                    let gain = if current.holdout_mse > 0.0 {
                        (current.holdout_mse - o.holdout_mse) / current.holdout_mse
                    } else {
                        0.0
                    };
                    let drop = ref_bic - o.bic;
                    (
                        EffectChoice {
                            effect: ctx.catalogue[e].name.clone(),
                            outcome: Ok(o),
                            holdout_gain: gain,
                            bic_drop: drop,
                        },
                        Some((cfg, ne)),
                    )
                }
                Err(msg) => (
                    EffectChoice {
                        effect: ctx.catalogue[e].name.clone(),
                        outcome: Err(msg),
                        holdout_gain: f64::NEG_INFINITY,
                        bic_drop: f64::NEG_INFINITY,
                    },
                    None,
                ),
            })
            .collect();
        choices.sort_by(|a, b| b.0.holdout_gain.total_cmp(&a.0.holdout_gain));
        let accepted = choices.first().and_then(|(c, cfg)| {
            let o = c.outcome.as_ref().ok()?;
            opts.rule
                .accepts(
                    ref_bic,
                    o.bic,
                    current.holdout_mse,
                    o.holdout_mse,
                    baseline_gap,
                )
                .then(|| (o.clone(), cfg.clone()))
        });
        // Attribution check: the gain must come from the effect, not from a better optimum
        // of the model as it stands. Refit that model started from the candidate's solution
        // (without the candidate); if it comes as close, the round is repeated against it.
        let mut attribution = None;
        if let Some((o, Some((cfg, _)))) = &accepted {
            let mut probe = cfg.clone();
            probe.effects.pop();
            let (ro, rcfg, rne) = ctx.fit(probe, Some(n_eff))?;
            progress.fit_done("attribution check");
            let ref_bic_probe = stats::bic(
                ro.train_mse * ctx.lt.n as f64,
                ctx.lt.n as f64,
                n_eff,
                k_ref,
            );
            if ro.train_mse < current.train_mse
                && !opts.rule.accepts(
                    ref_bic_probe,
                    o.bic,
                    ro.holdout_mse,
                    o.holdout_mse,
                    baseline_gap,
                )
            {
                attribution = Some(format!(
                    "{} failed the attribution check: the model without it, refitted from its solution, reaches train MSE {:.3e} / held-out MSE {:.3e}; round repeated",
                    o.effects.last().map_or("?", String::as_str),
                    ro.train_mse,
                    ro.holdout_mse
                ));
                current = ro;
                current_cfg = rcfg;
                n_eff = rne;
            }
        }
        if attribution.is_some() {
            steps.push(Step {
                candidates: choices.into_iter().map(|(c, _)| c).collect(),
                named: None,
                attribution,
            });
            repeats += 1;
            if repeats <= MAX_REPEATS {
                continue;
            }
            break;
        }
        let step_named = accepted
            .as_ref()
            .map(|(o, _)| o.effects.last().cloned().unwrap_or_default());
        if step_named.is_none() && named.is_empty() {
            if let Some((c, _)) = choices.first() {
                if let Ok(o) = &c.outcome {
                    best_unnamed = Some((c.effect.clone(), o.holdout_mse));
                }
            }
        }
        steps.push(Step {
            candidates: choices.into_iter().map(|(c, _)| c).collect(),
            named: step_named.clone(),
            attribution: None,
        });
        match (accepted, step_named) {
            (Some((o, Some((cfg, ne)))), Some(name)) => {
                named.push(name);
                repeats = 0;
                current = o;
                current_cfg = cfg;
                n_eff = ne;
            }
            _ => break,
        }
    }

    let gap_shrink = stats::gap_shrink(
        calibrated.holdout_mse,
        current.holdout_mse,
        holdout_noise_mse,
    );
    let best_unnamed_shrink = best_unnamed.map(|(name, mse)| {
        (
            name,
            stats::gap_shrink(calibrated.holdout_mse, mse, holdout_noise_mse),
        )
    });
    let tb = ctx.channel_errors(train, &ctx.lt, &calibrated_cfg);
    let ta = ctx.channel_errors(train, &ctx.lt, &current_cfg);
    let hb = ctx.channel_errors(holdout, &ctx.lh, &calibrated_cfg);
    let ha = ctx.channel_errors(holdout, &ctx.lh, &current_cfg);
    let channel_errors = tb
        .into_iter()
        .zip(ta)
        .zip(hb.into_iter().zip(ha))
        .map(|((a, b), (c, d))| (a, b, c, d))
        .collect();
    Ok(Discovery {
        model: model.name().to_string(),
        channels,
        nominal,
        calibrated,
        signatures,
        steps,
        named,
        final_model: current,
        channel_errors,
        holdout_noise_mse,
        gap_shrink,
        best_unnamed_shrink,
    })
}
