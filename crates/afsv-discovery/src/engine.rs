//! The calibrate / locate / try / name loop of [`discover`](super).

use super::evidence;
use super::fitting::{finalists, spanning_subset, Config, Context, Fitted, Scouted, RIVAL_SHARE};
use super::form::{self, FormRule, NamingTests};
use super::layout::{ChannelScales, RecordSet};
use super::placebo::WithPlacebos;
use super::readings::{self, ReadingChoice, ReadingScore, WithReadings};
use super::signature::{channel_signature, ChannelSignature};
use super::stats::{self, SignificanceRule};
use super::{ActiveEffect, DiscoveryError, DiscoveryModel};
use afsv_records::Record;
use rayon::prelude::*;

mod attribution;
mod outcome;

use attribution::attribution_check;

pub use outcome::{
    ChannelError, Discovery, EffectChoice, EffectParam, FitOutcome, RecordCondition, Step,
};

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
    /// Start points are ranked and scouted on at most this many training records, chosen
    /// to span the records' conditions; the final fit of each candidate uses all of them.
    /// Scouting is only a choice of basin, so a few records per condition suffice, and the
    /// cost of a run then grows with the record count only through the final fits.
    pub scout_records: usize,
    /// Levenberg-Marquardt iterations on all training records after a fit has converged on
    /// the scouting records.
    pub polish_iterations: usize,
    /// Candidates fitted to convergence per round, those with the lowest scouting error
    /// (beyond the best, only those that lowered the scouting error by at least half the
    /// held-out gain the rule requires and by a tenth of what the best lowered it by); the
    /// others stop after scouting (the report lists them as pruned). Each full fit replays
    /// every training record dozens of times.
    pub finalists: usize,
    /// The naming tests a significant candidate must pass to be named ([`form`]).
    pub form: FormRule,
    /// Calibrate every reading of the model's calibration switches
    /// ([`DiscoveryModel::switches`]) and keep the better one; `false` runs the default
    /// readings only (the comparison of docs/discovery.md).
    pub switches: bool,
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
            scout_records: 8,
            polish_iterations: 6,
            finalists: 3,
            form: FormRule::default(),
            switches: true,
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

/// Per-channel error of a configuration given as baseline values and active effects,
/// normalised by each channel's standard deviation over `records` (for every model, also
/// one with scaling groups, [`DiscoveryModel::scaling_group`]: give the records of one kind
/// to see them as the workflow weighs them).
pub fn evaluate_errors<M: DiscoveryModel + ?Sized>(
    model: &M,
    records: &[Record],
    baseline: &[f64],
    effects: &[ActiveEffect<'_>],
) -> Result<Vec<ChannelError>, DiscoveryError> {
    let channels = model.channels();
    let prepared = prepare_all(model, records, &[])?;
    let scales = ChannelScales::whole_set(records, &channels);
    let set = RecordSet::new(
        model,
        records.iter().collect(),
        prepared.iter().collect(),
        &channels,
        &scales,
        baseline,
    )?;
    let r = set.residual_vec(model, baseline, effects)?;
    Ok(set.per_channel(Some(&r)))
}

/// Prepare every record once; an error names the record.
fn prepare_all<M: DiscoveryModel + ?Sized>(
    model: &M,
    records: &[Record],
    names: &[String],
) -> Result<Vec<M::Prepared>, DiscoveryError> {
    records
        .par_iter()
        .enumerate()
        .map(|(i, r)| {
            model.prepare(r).map_err(|e| match names.get(i) {
                Some(n) => e.in_record(n.as_str()),
                None => e.in_record((i + 1).to_string()),
            })
        })
        .collect()
}

/// Calibrate the baseline's uncertain parameters on `train` (step 0 of the workflow), at
/// the model's default readings ([`discover`] also calibrates the other readings of its
/// calibration switches and keeps the better).
pub fn calibrate<M: DiscoveryModel + ?Sized>(
    model: &M,
    train: &[Record],
    opts: &DiscoveryOptions,
) -> Result<FitOutcome, DiscoveryError> {
    let names: Vec<String> = (1..=train.len()).map(|i| i.to_string()).collect();
    let prep = prepare_all(model, train, &names)?;
    let ctx = context(
        model,
        train,
        &prep,
        None,
        train,
        &prep,
        opts,
        model.catalogue().len(),
    )?;
    let nominal = nominal_config(&ctx);
    let (calibrated, _, _) = ctx.calibrate(Config {
        free_baseline: (0..nominal.baseline.len()).collect(),
        ..nominal
    })?;
    Ok(calibrated)
}

/// Run the whole workflow: calibrate on `train`, locate, try the catalogue, name the
/// significant effects, and measure the gap on `holdout`. Record names label the signatures
/// and the evidence.
pub fn discover<M: DiscoveryModel + ?Sized>(
    model: &M,
    train: &[Record],
    holdout: &[Record],
    train_names: &[String],
    holdout_names: &[String],
    opts: &DiscoveryOptions,
    progress: &dyn Progress,
) -> Result<Discovery, DiscoveryError> {
    if train.is_empty() || holdout.is_empty() {
        return Err(DiscoveryError::NoRecords);
    }
    check_candidates(model, opts)?;
    let switches = if opts.switches {
        model.switches()
    } else {
        Vec::new()
    };
    let train_names = super::layout::labels(train_names, train.len(), "train");
    let holdout_names = super::layout::labels(holdout_names, holdout.len(), "holdout");
    // Placebo candidates follow the catalogue; only the naming tests fit them. Records are
    // prepared once: a reading changes the replay, not the prepared inputs.
    let default_reading = WithReadings {
        inner: model,
        choice: vec![0; switches.len()],
    };
    let tp = prepare_all(&WithPlacebos::new(&default_reading), train, &train_names)?;
    let hp = prepare_all(
        &WithPlacebos::new(&default_reading),
        holdout,
        &holdout_names,
    )?;
    // Step 0a: each reading of each switch calibrated, the better kept.
    let calibrate_reading =
        |choice: &[usize], start: Option<&[f64]>| -> Result<(Fitted, f64), DiscoveryError> {
            let read = WithReadings {
                inner: model,
                choice: choice.to_vec(),
            };
            let wrapped = WithPlacebos::new(&read);
            let ctx = context(&wrapped, train, &tp, None, holdout, &hp, opts, wrapped.real)?;
            let nominal = nominal_config(&ctx);
            let fitted = ctx.calibrate(Config {
                free_baseline: (0..nominal.baseline.len()).collect(),
                baseline: start.map_or(nominal.baseline, <[f64]>::to_vec),
                ..nominal
            })?;
            Ok((fitted, ctx.holdout.noise_mse()))
        };
    let (choice, reading_choices, switched_fit) = if switches.is_empty() {
        (Vec::new(), Vec::new(), None)
    } else {
        let (c, r, f) = choose_readings(&switches, opts, calibrate_reading)?;
        (c, r, Some(f))
    };
    let read = WithReadings {
        inner: model,
        choice,
    };
    let wrapped = WithPlacebos::new(&read);
    let real = wrapped.real;
    let model = &wrapped;
    // Coarse replays for scouting (the same for every reading: a reading changes the
    // replay, not the prepared inputs).
    let tc: Option<Vec<_>> = tp.iter().map(|p| model.coarse(p)).collect();
    let ctx = context(model, train, &tp, tc.as_deref(), holdout, &hp, opts, real)?;
    let mut conditions = Vec::new();
    for (set, names, prep) in [
        ("train", &train_names, &tp),
        ("holdout", &holdout_names, &hp),
    ] {
        for (n, p) in names.iter().zip(prep) {
            conditions.push(RecordCondition {
                record: n.clone(),
                set: set.into(),
                condition: model.condition(p),
            });
        }
    }

    // Step 0: the nominal and the calibrated baseline.
    let nominal_cfg = nominal_config(&ctx);
    let (nominal, _, _) = ctx.fit(nominal_cfg.clone(), None)?;
    let start = Config {
        free_baseline: (0..nominal_cfg.baseline.len()).collect(),
        ..nominal_cfg.clone()
    };
    let calibrated_fit = match switched_fit {
        Some(f) => f,
        None => ctx.calibrate(start)?,
    };
    progress.fit_done("baseline calibration");
    let calibrated_cfg = calibrated_fit.1.clone();

    // Step 2: locate the disagreement of the calibrated baseline.
    let mut signatures = locate(&ctx, &ctx.train, &train_names, &calibrated_cfg)?;
    signatures.extend(locate(&ctx, &ctx.holdout, &holdout_names, &calibrated_cfg)?);

    // Steps 3-4: try the catalogue, name what is significant.
    let holdout_noise_mse = if model.broadband_channels() {
        let r =
            ctx.holdout
                .residual_vec(model, &calibrated_cfg.baseline, &calibrated_cfg.active())?;
        ctx.holdout.noise_mse_bounded(&r)
    } else {
        ctx.holdout.noise_mse()
    };
    let search = search(
        &ctx,
        real,
        &nominal_cfg.baseline,
        calibrated_fit,
        holdout_noise_mse,
        progress,
    )?;
    let calibrated = search.calibrated.clone();
    let current = &search.current;

    let gap_shrink = stats::gap_shrink(
        calibrated.holdout_mse,
        current.0.holdout_mse,
        holdout_noise_mse,
    );
    let best_unnamed_shrink = search.best_unnamed.as_ref().map(|(name, mse)| {
        (
            name.clone(),
            stats::gap_shrink(calibrated.holdout_mse, *mse, holdout_noise_mse),
        )
    });
    // Finite even on noise-free records (JSON has no infinity).
    let excess_over_noise =
        (calibrated.holdout_mse / holdout_noise_mse.max(f64::MIN_POSITIVE)).min(f64::MAX);
    let outcome = form::outcome(
        &form::SearchSummary {
            named: &search.named,
            steps: &search.steps,
            rejected_mse: search.rejected,
            best_unnamed: search.best_unnamed.as_ref(),
        },
        calibrated.holdout_mse,
        holdout_noise_mse,
        excess_over_noise,
        &opts.form,
    );
    let evidence = evidence::of_named(&ctx, &search.named, &search.chain, &holdout_names)?;
    let tb = ctx.channel_errors(&ctx.train, &calibrated_cfg);
    let ta = ctx.channel_errors(&ctx.train, &current.1);
    let hb = ctx.channel_errors(&ctx.holdout, &calibrated_cfg);
    let ha = ctx.channel_errors(&ctx.holdout, &current.1);
    let channel_errors = tb
        .into_iter()
        .zip(ta)
        .zip(hb.into_iter().zip(ha))
        .map(|((a, b), (c, d))| (a, b, c, d))
        .collect();
    let calibration_problems = super::calibration::problems(&current.0, &ctx.base_specs);
    let calibration_notes = super::calibration::notes(&current.0, excess_over_noise);
    Ok(Discovery {
        model: model.name().to_string(),
        channels: ctx.train.channels.clone(),
        conditions,
        nominal,
        calibrated,
        readings: reading_choices,
        signatures,
        steps: search.steps,
        named: search.named,
        evidence,
        final_model: current.0.clone(),
        channel_errors,
        holdout_noise_mse,
        gap_shrink,
        best_unnamed_shrink,
        excess_over_noise,
        outcome,
        calibration_problems,
        calibration_notes,
    })
}

/// Step 0a: the calibration switches, one after another: each other reading of a switch is
/// calibrated (`calibrate` gives the fit and the held-out noise floor; the default readings
/// from the nominal values, every other reading from the current readings' calibration,
/// which saves most of its iterations) with the other switches at their readings so far,
/// and replaces the current one when it is [`readings::better`]. Returns the readings
/// kept, what each switch tried, and the calibration under the readings kept.
fn choose_readings(
    switches: &[super::LawSwitch],
    opts: &DiscoveryOptions,
    calibrate: impl Fn(&[usize], Option<&[f64]>) -> Result<(Fitted, f64), DiscoveryError>,
) -> Result<(Vec<usize>, Vec<ReadingChoice>, Fitted), DiscoveryError> {
    let mut choice = vec![0; switches.len()];
    let (mut best, noise) = calibrate(&choice, None)?;
    let score = |reading: &str, f: &Fitted| ReadingScore {
        reading: reading.to_string(),
        train_mse: f.0.train_mse,
        holdout_mse: f.0.holdout_mse,
    };
    let mut out = Vec::new();
    for (k, sw) in switches.iter().enumerate() {
        let mut tried = vec![score(&sw.readings[choice[k]], &best)];
        let mut kept: Option<(usize, Fitted)> = None;
        for r in (0..sw.readings.len()).filter(|&r| r != choice[k]) {
            let mut c = choice.clone();
            c[k] = r;
            let (f, _) = calibrate(&c, Some(&best.1.baseline))?;
            tried.push(score(&sw.readings[r], &f));
            let reference = kept.as_ref().map_or(&best, |(_, f)| f);
            if readings::better(
                (f.0.train_mse, f.0.holdout_mse),
                (reference.0.train_mse, reference.0.holdout_mse),
                noise,
                opts.rule.min_gap_fraction,
            ) {
                kept = Some((r, f));
            }
        }
        if let Some((r, f)) = kept {
            choice[k] = r;
            best = f;
        }
        out.push(ReadingChoice {
            switch: sw.name.clone(),
            chosen: sw.readings[choice[k]].clone(),
            index: choice[k],
            tried,
        });
    }
    Ok((choice, out, best))
}

fn check_candidates<M: DiscoveryModel + ?Sized>(
    model: &M,
    opts: &DiscoveryOptions,
) -> Result<(), DiscoveryError> {
    let catalogue = model.catalogue();
    for n in opts.candidates.iter().flatten() {
        if !catalogue.iter().any(|e| &e.name == n) {
            return Err(DiscoveryError::UnknownEffect {
                effect: n.clone(),
                model: model.name().to_string(),
                catalogue: catalogue
                    .iter()
                    .map(|e| e.name.as_str())
                    .collect::<Vec<_>>()
                    .join(", "),
            });
        }
    }
    Ok(())
}

/// The fitting context: record sets laid out by the nominal baseline, channel scales from
/// the training records (per scaling group where the model has them), and the scouting subset (also in the coarse replays `tc` of the
/// training records, when given).
#[allow(clippy::too_many_arguments)]
fn context<'a, M: DiscoveryModel + ?Sized>(
    model: &'a M,
    train: &'a [Record],
    tp: &'a [M::Prepared],
    tc: Option<&'a [M::Prepared]>,
    holdout: &'a [Record],
    hp: &'a [M::Prepared],
    opts: &'a DiscoveryOptions,
    real: usize,
) -> Result<Context<'a, M>, DiscoveryError> {
    let channels = model.channels();
    let base_specs = model.baseline_params();
    let nominal: Vec<f64> = base_specs.iter().map(|s| s.initial).collect();
    let scales = ChannelScales::new(model, train, tp, &channels);
    let set = |recs: &'a [Record], prep: &'a [M::Prepared], idx: &[usize]| {
        RecordSet::new(
            model,
            idx.iter().map(|&i| &recs[i]).collect(),
            idx.iter().map(|&i| &prep[i]).collect(),
            &channels,
            &scales,
            &nominal,
        )
    };
    let all: Vec<usize> = (0..train.len()).collect();
    let scout_idx = (train.len() > opts.scout_records.max(1)).then(|| {
        let conditions: Vec<String> = tp.iter().map(|p| model.condition(p)).collect();
        spanning_subset(&conditions, opts.scout_records.max(1))
    });
    let scout = match &scout_idx {
        Some(idx) => Some(set(train, tp, idx)?),
        None => None,
    };
    let coarse = match tc {
        Some(tc) => Some(set(train, tc, scout_idx.as_deref().unwrap_or(&all))?),
        None => None,
    };
    Ok(Context {
        model,
        train: set(train, tp, &all)?,
        scout,
        coarse,
        holdout: set(holdout, hp, &(0..holdout.len()).collect::<Vec<_>>())?,
        base_specs,
        catalogue: model.catalogue(),
        real,
        opts,
    })
}

fn nominal_config<M: DiscoveryModel + ?Sized>(ctx: &Context<'_, M>) -> Config {
    Config {
        baseline: ctx.base_specs.iter().map(|s| s.initial).collect(),
        free_baseline: Vec::new(),
        effects: Vec::new(),
    }
}

fn locate<M: DiscoveryModel + ?Sized>(
    ctx: &Context<'_, M>,
    set: &RecordSet<'_, M::Prepared>,
    names: &[String],
    config: &Config,
) -> Result<Vec<(String, ChannelSignature)>, DiscoveryError> {
    let mut out = Vec::new();
    for ((rec, prep), label) in set.records.iter().zip(&set.prepared).zip(names) {
        let pred = ctx.model.simulate(prep, &config.baseline, &[])?;
        let t: Vec<f64> = rec
            .column("time_s")
            .map(<[f64]>::to_vec)
            .unwrap_or_else(|| (0..rec.len()).map(|i| i as f64).collect());
        let phases = ctx.model.phases(rec);
        for (c, ch) in set.channels.iter().enumerate() {
            if let (Some(meas), Some(Some(p))) = (rec.column(ch), pred.get(c)) {
                out.push((
                    label.clone(),
                    channel_signature(ch, &t, meas, p, &phases, None, ctx.opts.split_hz),
                ));
            }
        }
    }
    Ok(out)
}

/// What the greedy search produced.
struct Search {
    calibrated: super::FitOutcome,
    current: Fitted,
    steps: Vec<Step>,
    named: Vec<String>,
    /// The model before each named effect and after it, in naming order.
    chain: Vec<(Config, Config)>,
    best_unnamed: Option<(String, f64)>,
    /// Held-out error of a significant candidate that failed a naming test.
    rejected: Option<f64>,
}

/// Rounds repeated after a failed attribution check (each lowers the reference's training
/// error, so this only bounds the run time).
const MAX_REPEATS: usize = 2;

/// Steps 3-4: try every candidate against the current model, name the best if it passes
/// the significance rule and the attribution check, refit, repeat.
fn search<M: DiscoveryModel + ?Sized>(
    ctx: &Context<'_, M>,
    real: usize,
    nominal_base: &[f64],
    calibrated: Fitted,
    holdout_noise_mse: f64,
    progress: &dyn Progress,
) -> Result<Search, DiscoveryError> {
    let opts = ctx.opts;
    let baseline_gap = (calibrated.0.holdout_mse - holdout_noise_mse).max(0.0);
    let mut s = Search {
        calibrated: calibrated.0.clone(),
        current: calibrated,
        steps: Vec::new(),
        named: Vec::new(),
        chain: Vec::new(),
        best_unnamed: None,
        rejected: None,
    };
    let mut repeats = 0;
    while s.named.len() < opts.max_effects {
        // No candidate can pass the gap-fraction test when less than that fraction of the
        // baseline's gap is left: stop without trying.
        if !s.named.is_empty()
            && s.current.0.holdout_mse - holdout_noise_mse
                < opts.rule.min_gap_fraction * baseline_gap
        {
            break;
        }
        if !s.named.is_empty() && repeats == 0 {
            // Refit the model as it stands, so that candidates are not credited with the
            // improvement that more iterations on the same model would give anyway (it
            // has converged on the scouting records already: polished on all of them).
            let refit = ctx.refit(s.current.1.clone(), Some(s.current.2))?;
            if refit.0.train_mse <= s.current.0.train_mse {
                s.current = refit;
            }
            progress.fit_done("refit of the current model");
        }
        let Some(round) = round(ctx, &s.current, nominal_base, progress)? else {
            break;
        };
        let accepted = round.best.as_ref().filter(|(o, _)| {
            opts.rule.accepts(
                round.ref_bic,
                o.0.bic,
                s.current.0.holdout_mse,
                o.0.holdout_mse,
                baseline_gap,
            )
        });
        if let Some((cand, _)) = accepted {
            if let Some((note, better)) =
                attribution_check(ctx, &s.current, cand, round.k_ref, baseline_gap, progress)?
            {
                s.steps.push(Step {
                    candidates: round.choices,
                    named: None,
                    attribution: Some(note),
                    naming_tests: None,
                });
                s.current = better;
                repeats += 1;
                if repeats <= MAX_REPEATS {
                    continue;
                }
                break;
            }
        }
        let tests = match accepted {
            Some((cand, _)) if opts.form.enabled => {
                let t = form::naming_tests(ctx, &s.current, cand, nominal_base, real)?;
                progress.fit_done("naming tests");
                Some(t)
            }
            _ => None,
        };
        let passed = tests.as_ref().is_none_or(NamingTests::passed);
        let named = accepted
            .filter(|_| passed)
            .map(|(c, name)| (c.clone(), name.clone()));
        if !passed {
            s.rejected = accepted.map(|(c, _)| c.0.holdout_mse);
        }
        if named.is_none() && s.named.is_empty() {
            s.best_unnamed = round
                .best
                .as_ref()
                .map(|(c, name)| (name.clone(), c.0.holdout_mse));
        }
        s.steps.push(Step {
            candidates: round.choices,
            named: named.as_ref().map(|(_, n)| n.clone()),
            attribution: None,
            naming_tests: tests,
        });
        let Some((cand, name)) = named else {
            break;
        };
        s.named.push(name);
        s.chain.push((s.current.1.clone(), cand.1.clone()));
        repeats = 0;
        s.current = cand;
    }
    if !s.named.is_empty() && !s.current.0.converged {
        // The final model was polished for a few iterations only: continue on all training
        // records until a convergence test is met (or the iteration limit says it was not).
        let last = ctx.converge(s.current.1.clone(), Some(s.current.2))?;
        progress.fit_done("final fit to convergence");
        if last.0.train_mse <= s.current.0.train_mse {
            if let Some(link) = s.chain.last_mut() {
                link.1 = last.1.clone();
            }
            s.current = last;
        }
    }
    Ok(s)
}

/// The candidates of one round, scored against the current model.
struct Round {
    choices: Vec<EffectChoice>,
    /// The best candidate (largest held-out gain) with its name.
    best: Option<(Fitted, String)>,
    /// BIC of the round's reference with the same parameter-count convention.
    ref_bic: f64,
    /// Its parameter count.
    k_ref: usize,
}

fn round<M: DiscoveryModel + ?Sized>(
    ctx: &Context<'_, M>,
    current: &Fitted,
    nominal_base: &[f64],
    progress: &dyn Progress,
) -> Result<Option<Round>, DiscoveryError> {
    let opts = ctx.opts;
    let (cur, cfg, n_eff) = current;
    let tried: Vec<usize> = (0..ctx.real)
        .filter(|&e| !cfg.effects.iter().any(|(a, _)| *a == e))
        .filter(|&e| {
            opts.candidates
                .as_ref()
                .is_none_or(|names| names.contains(&ctx.catalogue[e].name))
        })
        .collect();
    if tried.is_empty() {
        return Ok(None);
    }
    // Scout every candidate on the spanning subset, then fit the most promising on all
    // training records.
    let scouted: Vec<Scouted> = tried
        .par_iter()
        .map(|&e| (e, ctx.scout_candidate(cfg, nominal_base, e)))
        .collect();
    let ref_rss = ctx.scout_rss(cfg)?;
    let finalists = finalists(
        &scouted,
        opts.finalists,
        ref_rss,
        opts.rule.min_holdout_gain,
    );
    let results: Vec<(usize, Result<Fitted, String>)> = scouted
        .into_par_iter()
        .map(|(e, r)| {
            // A candidate's failure is kept as text: the report and report.json show it.
            let r = match r {
                Err(err) => Err(err.to_string()),
                Ok((c, _)) if finalists.contains(&e) => {
                    ctx.finish_candidate(c, *n_eff).map_err(|err| err.to_string())
                }
                Ok((_, rss)) => Err(format!(
                        "pruned after scouting: it changed the training error on the scouting records by {:+.1} % (not among the {} best, or less than half the held-out gain the rule requires, or less than {:.0} % of the best candidate's change)",
                        100.0 * (rss - ref_rss) / ref_rss.max(f64::MIN_POSITIVE),
                        opts.finalists,
                        100.0 * RIVAL_SHARE
                    )),
            };
            progress.fit_done(&ctx.catalogue[e].name);
            (e, r)
        })
        .collect();
    // The round's reference is scored with the same n_eff and parameter-count convention
    // as the candidates: its BIC counts all parameters it has free.
    let k_ref = cfg.baseline.len() * usize::from(opts.refit_baseline)
        + cfg.effects.iter().map(|(_, v)| v.len()).sum::<usize>();
    let ref_bic = stats::bic(
        cur.train_mse * ctx.train.n as f64,
        ctx.train.n as f64,
        *n_eff,
        k_ref,
    );
    let mut scored: Vec<(EffectChoice, Option<Fitted>)> = results
        .into_iter()
        .map(|(e, r)| {
            let effect = ctx.catalogue[e].name.clone();
            match r {
                Ok(f) => {
                    let gain = if cur.holdout_mse > 0.0 {
                        (cur.holdout_mse - f.0.holdout_mse) / cur.holdout_mse
                    } else {
                        0.0
                    };
                    let choice = EffectChoice {
                        effect,
                        outcome: Ok(f.0.clone()),
                        holdout_gain: Some(gain),
                        bic_drop: Some(ref_bic - f.0.bic),
                    };
                    (choice, Some(f))
                }
                Err(msg) => (
                    EffectChoice {
                        effect,
                        outcome: Err(msg),
                        holdout_gain: None,
                        bic_drop: None,
                    },
                    None,
                ),
            }
        })
        .collect();
    scored.sort_by(|a, b| {
        let g = |c: &EffectChoice| c.holdout_gain.unwrap_or(f64::NEG_INFINITY);
        g(&b.0).total_cmp(&g(&a.0))
    });
    let best = scored
        .first()
        .and_then(|(c, f)| f.clone().map(|f| (f, c.effect.clone())));
    Ok(Some(Round {
        choices: scored.into_iter().map(|(c, _)| c).collect(),
        best,
        ref_bic,
        k_ref,
    }))
}
