//! Sequential quadratic programming from a given point: the SLSQP method of Kraft (1988)
//! from the `slsqp` crate (a pure-Rust translation of NLopt's implementation), on the
//! unit-scaled box, with the gradients of the objective and of every constraint by finite
//! differences (central where the step fits inside the box, one-sided at a bound), each
//! gradient's 2n points evaluated in parallel.
//!
//! Every evaluation is kept in an ordered log with a cache keyed by the point's bits. SLSQP
//! is deterministic, so a run resumed from a saved log replays the logged values (no
//! evaluation is repeated) and continues exactly as an uninterrupted run.

use crate::batch::{evaluate_batch, Progress, Silent};
use crate::problem::{require, Bounds, ConstrainedProblem, Evaluation, OptimizeError};
use serde::{Deserialize, Serialize};
use std::cell::RefCell;
use std::collections::HashMap;

/// Settings of [`sqp`].
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct SqpOptions {
    /// Finite-difference step in unit-cube coordinates (> 0, < 0.5).
    pub fd_step: f64,
    /// Central differences (2n evaluations per gradient) rather than forward (n).
    pub central: bool,
    /// Largest number of SLSQP function calls (each gradient call costs 1 + n or 1 + 2n
    /// evaluations).
    pub max_calls: usize,
    /// Stop when F changes by less than this relative amount.
    pub ftol_rel: f64,
    /// Stop when every unit coordinate moves by less than this.
    pub xtol_abs: f64,
    /// SLSQP sees each constraint as `c_j + margin <= 0`: it converges onto the boundary
    /// up to round-off, and the margin keeps its end point feasible in exact terms.
    pub constraint_margin: f64,
}

impl Default for SqpOptions {
    fn default() -> Self {
        Self {
            fd_step: 1e-3,
            central: true,
            max_calls: 100,
            ftol_rel: 1e-8,
            xtol_abs: 1e-6,
            constraint_margin: 1e-9,
        }
    }
}

/// One logged evaluation (unit-cube point and its result).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct LoggedEvaluation {
    /// Point in unit-cube coordinates.
    pub u: Vec<f64>,
    /// Its evaluation.
    pub eval: Evaluation,
}

/// Outcome of [`sqp`].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SqpResult {
    /// Final point in the problem's units: the best feasible point among those SLSQP
    /// visited (iterates and line-search points), or the start if none beats it.
    pub x: Vec<f64>,
    /// Its evaluation.
    pub eval: Evaluation,
    /// Whether a visited point beat the start.
    pub improved: bool,
    /// SLSQP's termination status.
    pub status: String,
    /// Problem evaluations of this run, replayed ones included.
    pub evaluations: usize,
    /// Of those, replayed from the log given to [`sqp`].
    pub replayed: usize,
    /// The evaluation log (the checkpoint of a later resume).
    pub log: Vec<LoggedEvaluation>,
}

/// Caches and logs the evaluations of one SQP run.
struct Evaluator<'a> {
    /// The problem, or `None` when only the log answers (ask mode: a missing point is
    /// recorded in `wanted` and answered with a placeholder).
    problem: Option<&'a dyn ConstrainedProblem>,
    bounds: &'a Bounds,
    nc: usize,
    wanted: RefCell<Option<Batch>>,
    options: SqpOptions,
    cache: RefCell<HashMap<Vec<u64>, Evaluation>>,
    log: RefCell<Vec<LoggedEvaluation>>,
    checkpoint: RefCell<&'a mut SqpCheckpoint<'a>>,
    progress: &'a dyn Progress,
    error: RefCell<Option<String>>,
    /// The points SLSQP asked for (its iterates and line-search points, not the
    /// difference points), in order.
    visited: RefCell<Vec<Vec<f64>>>,
}

/// The checkpoint callback of [`sqp`]: receives the whole evaluation log.
pub type SqpCheckpoint<'a> = dyn FnMut(&[LoggedEvaluation]) -> Result<(), String> + 'a;

/// A constraint callback as SLSQP calls it.
type ConstraintFn<'a> = dyn Fn(&[f64], Option<&mut [f64]>, &mut ()) -> f64 + 'a;

fn key(u: &[f64]) -> Vec<u64> {
    u.iter().map(|v| v.to_bits()).collect()
}

impl Evaluator<'_> {
    /// Evaluations of `units` (cached where known; the rest in one parallel batch).
    fn many(&self, units: &[Vec<f64>]) -> Vec<Evaluation> {
        let mut miss: Vec<Vec<f64>> = Vec::new();
        {
            let cache = self.cache.borrow();
            for u in units {
                if !cache.contains_key(&key(u)) && !miss.contains(u) {
                    miss.push(u.clone());
                }
            }
        }
        let Some(problem) = self.problem else {
            // Ask mode: record the first batch that is missing; answer every missing point
            // with one constant placeholder, whose zero differences end SLSQP quickly.
            if !miss.is_empty() && self.wanted.borrow().is_none() {
                *self.wanted.borrow_mut() = Some(miss);
            }
            let placeholder = Evaluation {
                f: 0.0,
                constraints: vec![-1.0; self.nc],
            };
            let cache = self.cache.borrow();
            return units
                .iter()
                .map(|u| {
                    cache
                        .get(&key(u))
                        .cloned()
                        .unwrap_or_else(|| placeholder.clone())
                })
                .collect();
        };
        if !miss.is_empty() && self.error.borrow().is_none() {
            let xs: Vec<Vec<f64>> = miss.iter().map(|u| self.bounds.from_unit(u)).collect();
            let evals = evaluate_batch(problem, &xs);
            let mut cache = self.cache.borrow_mut();
            let mut log = self.log.borrow_mut();
            for (u, e) in miss.into_iter().zip(evals) {
                cache.insert(key(&u), e.clone());
                log.push(LoggedEvaluation { u, eval: e });
            }
            let best = log
                .iter()
                .map(|l| l.eval.barrier_value())
                .fold(f64::MAX, f64::min);
            self.progress
                .report("sqp", log.len(), self.max_evaluations(), best);
            if let Err(e) = (self.checkpoint.borrow_mut())(&log) {
                *self.error.borrow_mut() = Some(e);
            }
        }
        let cache = self.cache.borrow();
        let failed = Evaluation::failed(self.nc);
        units
            .iter()
            .map(|u| {
                cache
                    .get(&key(u))
                    .cloned()
                    .unwrap_or_else(|| failed.clone())
            })
            .collect()
    }

    /// An upper bound of the evaluations (for the progress bar).
    fn max_evaluations(&self) -> usize {
        let n = self.bounds.dim();
        self.options.max_calls * (1 + if self.options.central { 2 * n } else { n })
    }

    /// Value (and gradient into `grad`) of `pick` of the evaluation at `u`.
    fn value(&self, u: &[f64], grad: Option<&mut [f64]>, pick: &dyn Fn(&Evaluation) -> f64) -> f64 {
        let u: Vec<f64> = u.iter().map(|v| v.clamp(0.0, 1.0)).collect();
        self.visited.borrow_mut().push(u.clone());
        let Some(g) = grad else {
            return pick(&self.many(std::slice::from_ref(&u))[0]);
        };
        let h = self.options.fd_step;
        let mut pts = vec![u.clone()];
        // (index of the + point, index of the - point, step between them) per variable.
        let mut pairs = Vec::with_capacity(u.len());
        for i in 0..u.len() {
            let (up, down) = (u[i] + h <= 1.0, u[i] - h >= 0.0);
            let plus = |pts: &mut Vec<Vec<f64>>, d: f64| {
                let mut p = u.clone();
                p[i] += d;
                pts.push(p);
                pts.len() - 1
            };
            pairs.push(if self.options.central && up && down {
                (plus(&mut pts, h), plus(&mut pts, -h), 2.0 * h)
            } else if up {
                (plus(&mut pts, h), 0, h)
            } else {
                (0, plus(&mut pts, -h), h)
            });
        }
        let evals = self.many(&pts);
        let vals: Vec<f64> = evals.iter().map(pick).collect();
        for (gi, (p, m, d)) in g.iter_mut().zip(pairs) {
            *gi = (vals[p] - vals[m]) / d;
        }
        vals[0]
    }
}

/// SLSQP from `x0` (projected onto the bounds), continuing a saved `log` (empty for a new
/// run); `checkpoint` receives the whole log after every batch of new evaluations.
pub fn sqp<P: ConstrainedProblem>(
    problem: &P,
    x0: &[f64],
    options: &SqpOptions,
    log: Vec<LoggedEvaluation>,
    progress: &dyn Progress,
    checkpoint: &mut SqpCheckpoint<'_>,
) -> Result<SqpResult, OptimizeError> {
    let source = Source {
        problem: Some(problem),
        bounds: problem.bounds(),
        nc: problem.n_constraints(),
    };
    drive(source, x0, options, log, progress, checkpoint).map(|(r, _)| r)
}

/// What [`sqp_ask`] found: the next batch to evaluate, or the end of the run.
#[derive(Debug, Clone, PartialEq)]
pub enum SqpStep {
    /// Unit-cube points to evaluate next; append each with its evaluation to the log
    /// (as a [`LoggedEvaluation`], in this order) and ask again.
    Need(Vec<Vec<f64>>),
    /// The run is complete; the result equals the one of [`sqp`] with the same inputs.
    Done(SqpResult),
}

/// The ask half of an SQP run evaluated elsewhere: SLSQP replayed on `log` up to the first
/// point the log does not hold. A problem's shape (`bounds`, `n_constraints`) is all it
/// needs; the loop "ask, evaluate, append, ask" gives exactly the run of [`sqp`].
pub fn sqp_ask(
    bounds: &Bounds,
    n_constraints: usize,
    x0: &[f64],
    options: &SqpOptions,
    log: Vec<LoggedEvaluation>,
) -> Result<SqpStep, OptimizeError> {
    let source = Source {
        problem: None,
        bounds,
        nc: n_constraints,
    };
    let (r, wanted) = drive(source, x0, options, log, &Silent, &mut |_| Ok(()))?;
    Ok(match wanted {
        Some(w) => SqpStep::Need(w),
        None => SqpStep::Done(r),
    })
}

/// Checks a saved log as strictly as an input: one unit coordinate in [0, 1] per variable
/// and one value per constraint in every entry, finite values, no point twice, and no more
/// entries than `max_calls` calls with their difference points can make.
fn check_log(
    log: &[LoggedEvaluation],
    n: usize,
    nc: usize,
    options: &SqpOptions,
) -> Result<(), OptimizeError> {
    let bad = |what: String| Err(OptimizeError::Checkpoint(format!("SQP log: {what}")));
    let most = options.max_calls * (1 + if options.central { 2 * n } else { n });
    if log.len() > most {
        return bad(format!(
            "{} entries, more than the {most} of {} calls",
            log.len(),
            options.max_calls
        ));
    }
    let mut seen = std::collections::HashSet::with_capacity(log.len());
    for (i, l) in log.iter().enumerate() {
        if l.u.len() != n || l.eval.constraints.len() != nc {
            return bad(format!(
                "entry {i} of another dimension or constraint count"
            ));
        }
        if !l.u.iter().all(|u| (0.0..=1.0).contains(u)) {
            return bad(format!("entry {i} outside the unit cube"));
        }
        if !(l.eval.f.is_finite() && l.eval.constraints.iter().all(|c| c.is_finite())) {
            return bad(format!("entry {i} holds a value that is not finite"));
        }
        if !seen.insert(key(&l.u)) {
            return bad(format!("entry {i} repeats an earlier point"));
        }
    }
    Ok(())
}

/// A batch of unit-cube points.
type Batch = Vec<Vec<f64>>;

/// Where the evaluations come from: a problem, or (ask mode) only the log.
struct Source<'a> {
    problem: Option<&'a dyn ConstrainedProblem>,
    bounds: &'a Bounds,
    nc: usize,
}

/// The SLSQP run shared by [`sqp`] and [`sqp_ask`]; also returns the first missing batch
/// in ask mode.
fn drive(
    source: Source<'_>,
    x0: &[f64],
    options: &SqpOptions,
    log: Vec<LoggedEvaluation>,
    progress: &dyn Progress,
    checkpoint: &mut SqpCheckpoint<'_>,
) -> Result<(SqpResult, Option<Batch>), OptimizeError> {
    let b = source.bounds;
    let n = b.dim();
    require(x0.len() == n, "x0", "one value per variable")?;
    require(x0.iter().all(|v| v.is_finite()), "x0", "finite")?;
    require(
        options.fd_step > 0.0 && options.fd_step < 0.5,
        "fd_step",
        "in (0, 0.5)",
    )?;
    require(options.max_calls >= 1, "max_calls", ">= 1")?;
    require(
        options.constraint_margin.is_finite() && options.constraint_margin >= 0.0,
        "constraint_margin",
        "finite and >= 0",
    )?;
    let nc = source.nc;
    check_log(&log, n, nc, options)?;
    let replay_len = log.len();
    let cache = log.iter().map(|l| (key(&l.u), l.eval.clone())).collect();
    let ev = Evaluator {
        problem: source.problem,
        bounds: b,
        nc,
        wanted: RefCell::new(None),
        options: *options,
        cache: RefCell::new(cache),
        log: RefCell::new(log),
        checkpoint: RefCell::new(checkpoint),
        progress,
        error: RefCell::new(None),
        visited: RefCell::new(Vec::new()),
    };
    let u0: Vec<f64> = b.to_unit(x0).iter().map(|v| v.clamp(0.0, 1.0)).collect();
    let start = ev.many(std::slice::from_ref(&u0))[0].clone();
    let margin = options.constraint_margin;
    let objective = |u: &[f64], g: Option<&mut [f64]>, _: &mut ()| ev.value(u, g, &|e| e.f);
    let cons: Vec<Box<ConstraintFn<'_>>> = (0..nc)
        .map(|j| {
            let ev = &ev;
            Box::new(move |u: &[f64], g: Option<&mut [f64]>, _: &mut ()| {
                ev.value(u, g, &|e| e.constraints[j] + margin)
            }) as Box<ConstraintFn<'_>>
        })
        .collect();
    let cons_ref: Vec<&ConstraintFn<'_>> = cons.iter().map(|c| c.as_ref()).collect();
    let tols = slsqp::StopTols {
        ftol_rel: options.ftol_rel,
        xtol_abs: vec![options.xtol_abs; n],
        ..slsqp::StopTols::default()
    };
    let bounds = vec![(0.0, 1.0); n];
    let status = match slsqp::minimize(
        objective,
        &u0,
        &bounds,
        &cons_ref,
        (),
        options.max_calls,
        Some(tols),
    ) {
        Ok((s, _, _)) => format!("{s:?}"),
        Err((s, _, _)) => format!("{s:?}"),
    };
    if let Some(e) = ev.error.borrow_mut().take() {
        return Err(OptimizeError::Invalid {
            field: "checkpoint",
            reason: e,
        });
    }
    drop(cons_ref);
    drop(cons);
    // SLSQP's own "best feasible" point uses a zero tolerance on the margin-shifted
    // constraints, which round-off defeats on an active constraint; take the best visited
    // point that is feasible in the problem's terms instead (the first of equals).
    let visited = ev.visited.into_inner();
    let cache = ev.cache.into_inner();
    let mut best = (u0.clone(), start.clone());
    for u in visited {
        if let Some(e) = cache.get(&key(&u)) {
            if e.is_feasible() && e.f < best.1.barrier_value() {
                best = (u, e.clone());
            }
        }
    }
    let improved = best.0 != u0;
    let (u, eval) = best;
    let wanted = ev.wanted.into_inner();
    let log = ev.log.into_inner();
    let evaluations = log.len();
    let result = SqpResult {
        x: b.from_unit(&u),
        eval,
        improved,
        status,
        evaluations,
        replayed: replay_len.min(evaluations),
        log,
    };
    Ok((result, wanted))
}
