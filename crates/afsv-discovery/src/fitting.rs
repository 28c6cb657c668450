//! Fitting configurations (baseline values plus effects) to the training records and
//! scoring them on the held-out records; start points and scouting of candidate effects.

use super::engine::{DiscoveryOptions, FitOutcome, SCOUT_ITERATIONS};
use super::layout::RecordSet;
use super::stats;
use super::{ActiveEffect, DiscoveryError, DiscoveryModel, EffectSpec, ParamSpec};
use optimize::least_squares::{fit, BroydenUpdates, FitOptions, Problem};

/// A configuration to fit: which baseline parameters are free and which effects are on.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Config {
    pub baseline: Vec<f64>,
    pub free_baseline: Vec<usize>,
    pub effects: Vec<(usize, Vec<f64>)>,
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

    /// The effects as the model takes them.
    pub fn active(&self) -> Vec<ActiveEffect<'_>> {
        self.effects
            .iter()
            .map(|(index, values)| ActiveEffect {
                index: *index,
                values,
            })
            .collect()
    }
}

/// A fitted configuration with its effective sample size.
pub(crate) type Fitted = (FitOutcome, Config, f64);

struct Objective<'a, M: DiscoveryModel + ?Sized> {
    model: &'a M,
    set: &'a RecordSet<'a, M::Prepared>,
    config: &'a Config,
}

impl<M: DiscoveryModel + ?Sized> Problem for Objective<'_, M> {
    fn n_params(&self) -> usize {
        self.config.pack().len()
    }
    fn n_residuals(&self) -> usize {
        self.set.n
    }
    fn residuals(&self, p: &[f64], r: &mut [f64]) -> Result<(), String> {
        // The least-squares solver takes the failure as text (it reports the start point's).
        let c = self.config.unpack(p);
        self.set
            .residuals(self.model, &c.baseline, &c.active(), r)
            .map_err(|e| e.to_string())
    }
}

/// What the fits of one discovery run share.
pub(crate) struct Context<'a, M: DiscoveryModel + ?Sized> {
    pub model: &'a M,
    pub train: RecordSet<'a, M::Prepared>,
    /// A subset of the training records spanning their conditions, for scouting start
    /// points (the whole training set when it is small).
    pub scout: Option<RecordSet<'a, M::Prepared>>,
    /// The scouting records (the subset, else all training records) in the model's coarse
    /// replays ([`DiscoveryModel::coarse`]), for ranking start points and scouting; `None`
    /// when the model has none.
    pub coarse: Option<RecordSet<'a, M::Prepared>>,
    pub holdout: RecordSet<'a, M::Prepared>,
    pub base_specs: Vec<ParamSpec>,
    pub catalogue: Vec<EffectSpec>,
    /// Catalogue entries from here on are placebos ([`super::placebo`]), never candidates.
    pub real: usize,
    pub opts: &'a DiscoveryOptions,
}

impl<M: DiscoveryModel + ?Sized> Context<'_, M> {
    /// The records start points are ranked and scouted on: the coarse replays of the
    /// scouting subset where the model has them, else the subset, else all training records.
    fn scout_set(&self) -> &RecordSet<'_, M::Prepared> {
        self.coarse
            .as_ref()
            .or(self.scout.as_ref())
            .unwrap_or(&self.train)
    }

    fn bounds(&self, config: &Config) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
        let mut lo = Vec::new();
        let mut hi = Vec::new();
        let mut typ = Vec::new();
        let effect_specs = config
            .effects
            .iter()
            .flat_map(|(e, _)| self.catalogue[*e].params.iter());
        let base_specs = config.free_baseline.iter().map(|&i| &self.base_specs[i]);
        for s in base_specs.chain(effect_specs) {
            lo.push(s.lower);
            hi.push(s.upper);
            typ.push(s.typical);
        }
        (lo, hi, typ)
    }

    /// Least-squares fit of the free parameters of `config` on `set`; returns the fitted
    /// configuration, the standard errors of the free parameters, whether the fit
    /// converged, and its residual sum of squares. Every fit updates its Jacobian between
    /// finite-difference ones ([`JACOBIAN_REFRESH`]); `stop` says which convergence test
    /// ends it and whether the standard errors are wanted.
    fn fit_on(
        &self,
        config: &Config,
        set: &RecordSet<'_, M::Prepared>,
        max_iter: usize,
        stop: Stop,
    ) -> Result<(Config, Vec<f64>, bool, f64), DiscoveryError> {
        let p0 = config.pack();
        if p0.is_empty() {
            let r = set.residual_vec(self.model, &config.baseline, &config.active())?;
            return Ok((config.clone(), Vec::new(), true, sum_sq(&r)));
        }
        let resolvable_decrease = match stop {
            Stop::Statistical => {
                let r = set.residual_vec(self.model, &config.baseline, &config.active())?;
                resolvable_decrease(stats::effective_samples(&set.segment_slices(&r)))
            }
            Stop::Converged => 0.0,
        };
        let (lower, upper, typical) = self.bounds(config);
        let obj = Objective {
            model: self.model,
            set,
            config,
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
                broyden: Some(BroydenUpdates {
                    refresh_every: JACOBIAN_REFRESH,
                    exact_at_solution: stop == Stop::Converged,
                }),
                resolvable_decrease,
            },
        )?;
        Ok((
            config.unpack(&res.params),
            res.std_errors,
            res.converged,
            res.rss,
        ))
    }

    /// Fit a configuration on the training records (or just evaluate it when nothing is free)
    /// and score it on the held-out records. `n_eff` fixes the effective sample size used in
    /// the information criteria so that models compared within a round share it.
    ///
    /// With a scouting subset, the fit runs to convergence on the subset first and is then
    /// polished on all training records ([`DiscoveryOptions::polish_iterations`]): the
    /// subset spans the records' conditions, so its optimum is close, and most iterations
    /// then cost a fraction of a full replay.
    pub fn fit(&self, config: Config, n_eff: Option<f64>) -> Result<Fitted, DiscoveryError> {
        self.fit_until(config, n_eff, Stop::Converged)
    }

    /// The baseline's calibration: [`Self::fit`], with the fit on the scouting subset ended
    /// by the statistical stop ([`Stop::Statistical`]). The calibrated baseline is where
    /// the search starts and every candidate frees it again; a misspecified baseline
    /// otherwise crawls along a valley for its whole iteration limit.
    pub fn calibrate(&self, config: Config) -> Result<Fitted, DiscoveryError> {
        self.fit_until(config, None, Stop::Statistical)
    }

    /// A fit ended early: on the scouting records, by the statistical stop
    /// ([`Stop::Statistical`]), then scored on all records without a polish. `None` without a
    /// scouting subset, where every fit runs on all training records ([`Self::fit`]).
    pub fn fit_scouted(
        &self,
        config: Config,
        n_eff: Option<f64>,
    ) -> Result<Option<Fitted>, DiscoveryError> {
        let Some(scout) = &self.scout else {
            return Ok(None);
        };
        let (fitted, _, converged, _) =
            self.fit_on(&config, scout, self.opts.max_iter, Stop::Statistical)?;
        self.score(fitted, &[], converged, n_eff).map(Some)
    }

    /// [`Self::fit`] with `subset_stop` ending the fit on the scouting subset.
    fn fit_until(
        &self,
        config: Config,
        n_eff: Option<f64>,
        subset_stop: Stop,
    ) -> Result<Fitted, DiscoveryError> {
        let (start, max_iter) = match &self.scout {
            Some(scout) => (
                self.fit_on(&config, scout, self.opts.max_iter, subset_stop)?
                    .0,
                self.opts.polish_iterations,
            ),
            None => (config, self.opts.max_iter),
        };
        self.polish(start, max_iter, n_eff)
    }

    /// More iterations on all training records for a configuration already fitted by
    /// [`Self::fit`], and score.
    pub fn refit(&self, config: Config, n_eff: Option<f64>) -> Result<Fitted, DiscoveryError> {
        let max_iter = if self.scout.is_some() {
            self.opts.polish_iterations
        } else {
            self.opts.max_iter
        };
        self.polish(config, max_iter, n_eff)
    }

    /// Fit on all training records from `start` and score.
    fn polish(
        &self,
        start: Config,
        max_iter: usize,
        n_eff: Option<f64>,
    ) -> Result<Fitted, DiscoveryError> {
        let (fitted, se, converged, _) =
            self.fit_on(&start, &self.train, max_iter, Stop::Converged)?;
        self.score(fitted, &se, converged, n_eff)
    }

    /// Fit a configuration on all training records for up to
    /// [`DiscoveryOptions::max_iter`] iterations (the final model's fit to convergence),
    /// and score.
    pub fn converge(&self, config: Config, n_eff: Option<f64>) -> Result<Fitted, DiscoveryError> {
        self.polish(config, self.opts.max_iter, n_eff)
    }

    /// A short fit of a scouted configuration: [`DiscoveryOptions::polish_iterations`] on
    /// all training records, then scored (the placebos' budget in [`super::form`]).
    pub fn polish_short(&self, config: Config, n_eff: f64) -> Result<Fitted, DiscoveryError> {
        self.polish(config, self.opts.polish_iterations, Some(n_eff))
    }

    /// Residual sum of squares of a configuration on the scouting records.
    pub fn scout_rss(&self, config: &Config) -> Result<f64, DiscoveryError> {
        let r = self
            .scout_set()
            .residual_vec(self.model, &config.baseline, &config.active())?;
        Ok(sum_sq(&r))
    }

    /// Score a fitted configuration on the training and held-out records.
    fn score(
        &self,
        fitted: Config,
        se: &[f64],
        converged: bool,
        n_eff: Option<f64>,
    ) -> Result<Fitted, DiscoveryError> {
        let rt = self
            .train
            .residual_vec(self.model, &fitted.baseline, &fitted.active())?;
        let rh = self
            .holdout
            .residual_vec(self.model, &fitted.baseline, &fitted.active())?;
        let rss = sum_sq(&rt);
        let n = self.train.n as f64;
        let n_eff_here = stats::effective_samples(&self.train.segment_slices(&rt));
        let n_eff = n_eff.unwrap_or(n_eff_here);
        let k = fitted.pack().len();
        let mut baseline_se = vec![None; fitted.baseline.len()];
        let mut baseline_at_bound = vec![false; fitted.baseline.len()];
        for (j, &i) in fitted.free_baseline.iter().enumerate() {
            baseline_se[i] = se.get(j).copied().filter(|v| v.is_finite());
            baseline_at_bound[i] = at_bound(fitted.baseline[i], &self.base_specs[i]);
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
                    .map(|(j, (s, &val))| super::EffectParam {
                        name: s.name.clone(),
                        value: val,
                        std_error: se.get(off + j).copied().filter(|v| v.is_finite()),
                        at_bound: at_bound(val, s),
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
            baseline_at_bound,
            effect_params,
            train_mse: rss / n,
            holdout_mse: sum_sq(&rh) / self.holdout.n as f64,
            bic: stats::bic(rss, n, n_eff, k),
            aic: stats::aic(rss, n, n_eff, k),
            k,
            converged,
        };
        Ok((outcome, fitted, n_eff_here))
    }

    /// Start values of effect `e`: its nominal start, its "off" corner at the lower bounds
    /// and five points spread over its bounds (log-spaced where the range spans decades).
    fn effect_starts(&self, e: usize) -> Vec<Vec<f64>> {
        let specs = &self.catalogue[e].params;
        let fractions = [0.5, 0.1, 0.9, 0.3, 0.7];
        // The lower bounds switch most effects off (zero play, droop, friction): starting
        // there, the candidate can only improve on the model as it stands.
        let mut starts = vec![
            specs.iter().map(|s| s.initial).collect(),
            specs.iter().map(|s| s.lower).collect::<Vec<f64>>(),
        ];
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
        starts.dedup();
        starts
    }

    /// Start values `(baseline, effect)` for effect `e` added to `base`: each of
    /// [`Self::effect_starts`] with the baseline as fitted and at its nominal values, in
    /// order of scouting-set error, except that the best start on the *other* baseline
    /// comes second. Guards against starting where the effect is inactive (a saturation
    /// limit above the signal, a dead zone of zero width) and the gradient is zero, and
    /// against a calibration that has bent the baseline towards the missing effect: on
    /// independent strut records, the calibrated Coulomb friction (5x) and polytropic
    /// exponent absorbed a hidden gas heat transfer, every start on the calibrated baseline
    /// beat every start on the nominal one at first, and six iterations from them never
    /// reached the truth's basin.
    fn ranked_starts(
        &self,
        base: &Config,
        nominal_baseline: &[f64],
        e: usize,
    ) -> Vec<(Vec<f64>, Vec<f64>)> {
        let set = self.scout_set();
        let mut bases = vec![base.baseline.clone()];
        if nominal_baseline != base.baseline.as_slice() {
            bases.push(nominal_baseline.to_vec());
        }
        let mut r = vec![0.0; set.n];
        // (rss, which baseline, effect start)
        let mut ranked: Vec<(f64, usize, Vec<f64>)> = Vec::new();
        for start in self.effect_starts(e) {
            for (k, b) in bases.iter().enumerate() {
                let mut cfg = base.clone();
                cfg.baseline.clone_from(b);
                cfg.effects.push((e, start.clone()));
                if set
                    .residuals(self.model, &cfg.baseline, &cfg.active(), &mut r)
                    .is_ok()
                {
                    ranked.push((sum_sq(&r), k, start.clone()));
                }
            }
        }
        ranked.sort_by(|a, b| a.0.total_cmp(&b.0));
        if let Some(other) = ranked
            .iter()
            .position(|(_, k, _)| ranked.first().is_some_and(|f| f.1 != *k))
        {
            let item = ranked.remove(other);
            ranked.insert(1.min(ranked.len()), item);
        }
        if ranked.is_empty() {
            let nominal = self.catalogue[e].params.iter().map(|s| s.initial).collect();
            ranked.push((f64::INFINITY, 0, nominal));
        }
        ranked
            .into_iter()
            .map(|(_, k, s)| (bases[k].clone(), s))
            .collect()
    }

    /// Scout candidate effect `e` added to `current`: rank its start points, give the best
    /// few ([`DiscoveryOptions::starts`]) short fits on the scouting records, and fit the
    /// best to convergence there. Returns the configuration and its scouting-set residual
    /// sum of squares. The error surface of an effect parameter is often not convex once
    /// the baseline has been calibrated without it, and the start with the lowest initial
    /// error is then the wrong basin.
    pub fn scout_candidate(
        &self,
        current: &Config,
        nominal_baseline: &[f64],
        e: usize,
    ) -> Result<(Config, f64), DiscoveryError> {
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
        let set = self.scout_set();
        let k = self.opts.starts.max(1).min(starts.len());
        let mut best: Option<(f64, Config)> = None;
        let mut last_err = None;
        for start in &starts[..k] {
            match self.fit_on(&config_at(start), set, SCOUT_ITERATIONS, Stop::Statistical) {
                Ok((cfg, _, _, rss)) => {
                    if best.as_ref().is_none_or(|(b, _)| rss < *b) {
                        best = Some((rss, cfg));
                    }
                }
                Err(e) => last_err = Some(e),
            }
        }
        match (best, last_err) {
            (Some((rss, cfg)), _) => Ok((cfg, rss)),
            (None, Some(e)) => Err(e),
            (None, None) => Err(DiscoveryError::NoStartPoint {
                effect: self.catalogue[e].name.clone(),
            }),
        }
    }

    /// Fit a scouted candidate to convergence (on the scouting records first, then polished
    /// on all training records, as [`Self::fit`]) and score it.
    pub fn finish_candidate(&self, scouted: Config, n_eff: f64) -> Result<Fitted, DiscoveryError> {
        self.fit(scouted, Some(n_eff))
    }

    /// Per-channel errors of a configuration on a record set.
    pub fn channel_errors(
        &self,
        set: &RecordSet<'_, M::Prepared>,
        config: &Config,
    ) -> Vec<super::ChannelError> {
        let r = set
            .residual_vec(self.model, &config.baseline, &config.active())
            .ok();
        set.per_channel(r.as_deref())
    }
}

/// Which test ends a fit of [`Context::fit_on`]. Both update the Jacobian between
/// finite-difference ones ([`JACOBIAN_REFRESH`]).
#[derive(Debug, Clone, Copy, PartialEq)]
enum Stop {
    /// The statistical stop ([`resolvable_decrease`]) besides the relative decrease of
    /// 1e-8; the standard errors come from the last (possibly updated) Jacobian and are
    /// not used. For fits that only lead to another: scouting, and the calibration's fit on
    /// the scouting records before its polish on all training records.
    Statistical,
    /// Only the relative decrease of 1e-8 (or a step along a finite-difference Jacobian
    /// that finds no decrease); the standard errors from a finite-difference Jacobian at
    /// the solution. For the fits on all training records, which are scored and reported,
    /// and the finalists' and the attribution check's fits on the scouting records (a
    /// finalist stopped early leaves the final fit more to do than its iteration limit
    /// allows; a reference stopped early would favour the candidate it is checked
    /// against).
    Converged,
}

/// Accepted steps between finite-difference Jacobians of a discovery fit; Broyden rank-1
/// updates in between (`optimize::least_squares::BroydenUpdates`).
pub(crate) const JACOBIAN_REFRESH: usize = 3;

/// Relative decrease of a residual sum of squares the records cannot resolve: the standard
/// error of a mean square over `n_eff` effective samples, `sqrt(2 / n_eff)` (the variance
/// of a Gaussian residual's square is twice its squared variance; docs/discovery.md,
/// "Statistics", for `n_eff`).
pub(crate) fn resolvable_decrease(n_eff: f64) -> f64 {
    (2.0 / n_eff.max(1.0)).sqrt()
}

/// True when `value` sits on (within 1e-6 of the range of) one of its bounds.
pub(crate) fn at_bound(value: f64, spec: &ParamSpec) -> bool {
    let span = (spec.upper - spec.lower).abs();
    let tol = 1e-6
        * if span.is_finite() && span > 0.0 {
            span
        } else {
            value.abs().max(1.0)
        };
    (value - spec.lower).abs() <= tol || (spec.upper - value).abs() <= tol
}

/// Sum of squares.
pub(crate) fn sum_sq(r: &[f64]) -> f64 {
    r.iter().map(|v| v * v).sum()
}

/// A scouted candidate: its catalogue index and its configuration with the scouting-set
/// residual sum of squares, or why scouting failed.
pub(crate) type Scouted = (usize, Result<(Config, f64), DiscoveryError>);

/// `k` record indices spread evenly over the records sorted by their conditions, so that
/// every load, speed range and manoeuvre is represented.
pub(crate) fn spanning_subset(conditions: &[String], k: usize) -> Vec<usize> {
    let mut order: Vec<usize> = (0..conditions.len()).collect();
    order.sort_by(|&a, &b| conditions[a].cmp(&conditions[b]).then(a.cmp(&b)));
    let n = order.len();
    let mut picked: Vec<usize> = (0..k.min(n)).map(|i| order[i * n / k.min(n)]).collect();
    picked.sort_unstable();
    picked
}

/// The candidates worth a fit to convergence: the `k` with the lowest scouting error, of
/// which all but the best must have lowered the scouting records' error (against the
/// round's reference `ref_rss`) by at least half the held-out gain the rule requires, and
/// by at least [`RIVAL_SHARE`] of what the best lowered it by. A candidate that has not
/// done the first on the training subset is not expected to pass on the held-out records;
/// one that has not done the second is not expected to overtake the best, and only the
/// round's best can be named (the others' full fits would only be reported). The best one
/// is always fitted, so the report can say how close the round came.
pub(crate) fn finalists(scouted: &[Scouted], k: usize, ref_rss: f64, min_gain: f64) -> Vec<usize> {
    let mut ok: Vec<(usize, f64)> = scouted
        .iter()
        .filter_map(|(e, r)| r.as_ref().ok().map(|(_, rss)| (*e, *rss)))
        .collect();
    ok.sort_by(|a, b| a.1.total_cmp(&b.1));
    let best_gain = ok.first().map_or(0.0, |(_, rss)| ref_rss - rss);
    ok.into_iter()
        .enumerate()
        .filter(|(i, (_, rss))| {
            *i == 0
                || (ref_rss - rss >= 0.5 * min_gain * ref_rss
                    && ref_rss - rss >= RIVAL_SHARE * best_gain)
        })
        .take(k.max(1))
        .map(|(_, (e, _))| e)
        .collect()
}

/// Share of the best candidate's scouting gain another candidate must reach to be fitted
/// to convergence in the same round ([`finalists`]).
pub(crate) const RIVAL_SHARE: f64 = 0.1;

#[cfg(test)]
mod tests {
    use super::*;

    fn scouted(e: usize, rss: f64) -> Scouted {
        let config = Config {
            baseline: Vec::new(),
            free_baseline: Vec::new(),
            effects: Vec::new(),
        };
        (e, Ok((config, rss)))
    }

    #[test]
    fn resolvable_decrease_is_the_mean_squares_standard_error() {
        assert_eq!(resolvable_decrease(2.0), 1.0);
        assert!((resolvable_decrease(20_000.0) - 0.01).abs() < 1e-15);
        // Fewer than one effective sample counts as one.
        assert_eq!(resolvable_decrease(0.0), resolvable_decrease(1.0));
    }

    #[test]
    fn finalists_beyond_the_best_must_rival_it() {
        // Reference 100; the best removes 97, the others 1.8 and 20.
        let s = [scouted(0, 98.2), scouted(1, 3.0), scouted(2, 80.0)];
        // Both others pass the rule's half gain (1 %); only the 20 reaches a tenth of 97.
        assert_eq!(finalists(&s, 3, 100.0, 0.02), vec![1, 2]);
        // Two comparable candidates are both fitted.
        let s = [scouted(0, 50.0), scouted(1, 40.0), scouted(2, 99.5)];
        assert_eq!(finalists(&s, 3, 100.0, 0.02), vec![1, 0]);
        // The best is fitted even when it gains nothing.
        let s = [scouted(0, 100.5), scouted(1, 101.0)];
        assert_eq!(finalists(&s, 3, 100.0, 0.02), vec![0]);
    }
}
