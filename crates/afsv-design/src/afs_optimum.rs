//! The chapter-4 solver sequence (section 4.3.5): pattern search with a Latin-hypercube
//! search step from several starts (the current design and a maximin Latin hypercube of
//! further starts), each down to a coarse screening mesh; the best of them continued to the
//! fine mesh; then SQP from that pattern-search point. The pattern search sees
//! the [`AfsProblem::screened`] view (an infeasible point is not simulated); SQP the full
//! problem, whose objective it differentiates just outside the active boundary.
//!
//! The run is resumable: [`AfsRunState`] holds the finished starts, the pattern search in
//! progress and the SQP log, and [`optimise`] continues from it with identical results.

use crate::afs_design::AfsDesign;
use crate::afs_problem::{AfsProblem, DesignEvaluation};
use crate::afs_resume::{check_run_state, screening_options};
use crate::error::DesignError;
use optimize::lhs::{latin_hypercube, LhsOptions};
use optimize::pattern_search::{PatternSearch, PatternSearchOptions, PatternSearchState};
use optimize::sqp::{sqp, LoggedEvaluation, SqpOptions};
use optimize::{ConstrainedProblem, OptimizeError, Progress};
use serde::{Deserialize, Serialize};

/// Largest number of starts (bounds the allocation).
pub const MAX_STARTS: usize = 1000;

/// Settings of the solver sequence.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct AfsOptimisationSettings {
    /// Starts besides the current design, from a maximin Latin hypercube.
    pub extra_starts: usize,
    /// Seed of the starts and of each start's search hypercube (seed + 1 + start index).
    pub seed: u64,
    /// Pattern search of each start (its `seed` is set per start); `min_mesh` is the final
    /// mesh of the best start.
    pub pattern: PatternSearchOptions,
    /// Mesh below which a start's search stops (screening); the best start then continues
    /// to `pattern.min_mesh`. Equal to `pattern.min_mesh`: every start runs to the end.
    pub screen_min_mesh: f64,
    /// SQP from the best pattern-search point.
    pub sqp: SqpOptions,
}

impl Default for AfsOptimisationSettings {
    /// 4 extra starts; pattern search from mesh 0.25 with a 75-point (15 n) search
    /// hypercube, every start to mesh 1/32, the best on to 1/512; SQP with central differences at a unit step of 1e-2 (the noise
    /// of F is about 2e-5 at rtol 1e-8, docs/optimisation.md), at most 40 calls.
    fn default() -> Self {
        Self {
            extra_starts: 4,
            seed: 1,
            pattern: PatternSearchOptions {
                initial_mesh: 0.25,
                min_mesh: 1.0 / 512.0,
                search_points: 75,
                max_evaluations: 2000,
                ..PatternSearchOptions::default()
            },
            screen_min_mesh: 1.0 / 32.0,
            sqp: SqpOptions {
                fd_step: 1e-2,
                central: true,
                max_calls: 40,
                ftol_rel: 1e-6,
                xtol_abs: 1e-4,
                constraint_margin: 1e-9,
            },
        }
    }
}

/// A resumable run: screened starts, the screening search in progress, the refinement of
/// the best start, the SQP log.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct AfsRunState {
    /// Pattern searches of the screened starts, in start order.
    pub finished: Vec<PatternSearchState>,
    /// The screening search in progress.
    pub current: Option<PatternSearchState>,
    /// The refinement of the best start (finished once its `stop` is set).
    pub refined: Option<PatternSearchState>,
    /// SQP evaluations so far.
    pub sqp_log: Vec<LoggedEvaluation>,
}

/// One start's outcome.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StartOutcome {
    /// The start design.
    pub start: AfsDesign,
    /// The design the pattern search ended at.
    pub end: AfsDesign,
    /// Its F at the end of the screening (`null` in JSON if no feasible point was found).
    pub f: Option<f64>,
    /// Evaluations of this start's screening (search step, polls and the start point).
    pub evaluations: usize,
    /// Pattern-search iterations.
    pub iterations: usize,
}

/// Outcome of [`optimise`].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AfsOptimum {
    /// Every start, in order.
    pub starts: Vec<StartOutcome>,
    /// The best pattern-search point (PS column of Tables 4.3/4.4), fully evaluated.
    pub ps: DesignEvaluation,
    /// The SQP refinement of it (PS/SQP column).
    pub ps_sqp: DesignEvaluation,
    /// Whether SQP improved on the pattern search.
    pub sqp_improved: bool,
    /// SLSQP's termination status.
    pub sqp_status: String,
    /// Pattern-search evaluations (screening of all starts and refinement of the best).
    pub evaluations_ps: usize,
    /// SQP evaluations.
    pub evaluations_sqp: usize,
    /// Spread (max - min) of F over the screened starts that ended feasible.
    pub start_spread_f: f64,
}

impl AfsOptimum {
    /// Whether the run found a feasible design: the PS/SQP point (the best of the run by
    /// Deb's rules) meets every constraint. When it does not, no point met them all, and the
    /// point is the least infeasible one found, not an optimum.
    pub fn feasible(&self) -> bool {
        self.ps_sqp.is_feasible()
    }
}

fn opt_err(e: OptimizeError) -> DesignError {
    DesignError::Shape {
        field: "optimiser",
        reason: e.to_string(),
    }
}

/// The start designs: the current design, then `extra_starts` points of a maximin Latin
/// hypercube of the bounds.
pub fn start_points(
    problem: &AfsProblem,
    s: &AfsOptimisationSettings,
) -> Result<Vec<Vec<f64>>, DesignError> {
    if s.extra_starts >= MAX_STARTS {
        return Err(DesignError::Invalid {
            field: "extra_starts",
            value: s.extra_starts as f64,
            reason: "must be below 1000",
        });
    }
    let mut starts = vec![problem.vector_of(&problem.current_design())];
    if s.extra_starts > 0 {
        let units = latin_hypercube(&LhsOptions {
            points: s.extra_starts,
            dim: problem.bounds().dim(),
            seed: s.seed,
            maximin_candidates: 20,
        })
        .map_err(opt_err)?;
        starts.extend(units.iter().map(|u| problem.bounds().from_unit(u)));
    }
    Ok(starts)
}

/// Runs (or continues `resume`) the solver sequence; `checkpoint` receives the run state
/// after every pattern-search iteration and every SQP batch.
pub fn optimise(
    problem: &AfsProblem,
    s: &AfsOptimisationSettings,
    resume: AfsRunState,
    progress: &dyn Progress,
    checkpoint: &mut dyn FnMut(&AfsRunState) -> Result<(), String>,
) -> Result<AfsOptimum, DesignError> {
    let starts = start_points(problem, s)?;
    let screened = problem.screened();
    if !(s.screen_min_mesh >= s.pattern.min_mesh && s.screen_min_mesh < s.pattern.initial_mesh) {
        return Err(DesignError::Invalid {
            field: "screen_min_mesh",
            value: s.screen_min_mesh,
            reason: "must be in [pattern.min_mesh, pattern.initial_mesh)",
        });
    }
    s.pattern.validate().map_err(opt_err)?;
    // A resumed state is an input: checked before anything runs or is written.
    check_run_state(problem, s, &resume)?;
    let mut run = resume;
    let ck_err = |e: String| DesignError::Shape {
        field: "checkpoint",
        reason: e,
    };
    while run.finished.len() < starts.len() {
        let i = run.finished.len();
        let ps = PatternSearch::new(&screened, screening_options(s, i)).map_err(opt_err)?;
        let state = match run.current.take() {
            Some(st) => st,
            None => ps.start(&starts[i]).map_err(opt_err)?,
        };
        let mut snapshot = AfsRunState {
            finished: run.finished.clone(),
            ..AfsRunState::default()
        };
        let end = ps
            .run(state, progress, &mut |st| {
                snapshot.current = Some(st.clone());
                checkpoint(&snapshot)
            })
            .map_err(opt_err)?;
        run.finished.push(end);
        checkpoint(&run).map_err(ck_err)?;
    }
    let best = (0..run.finished.len())
        .min_by(|&a, &b| run.finished[a].eval.deb_cmp(&run.finished[b].eval))
        .unwrap_or(0);
    // Refinement of the best start: the same search continued to the fine mesh.
    let refine = PatternSearch::new(&screened, s.pattern).map_err(opt_err)?;
    let mut state = run.refined.take().unwrap_or_else(|| {
        let mut st = run.finished[best].clone();
        st.stop = None;
        st
    });
    if state.stop.is_none() {
        let mut snapshot = AfsRunState {
            finished: run.finished.clone(),
            ..AfsRunState::default()
        };
        state = refine
            .run(state, progress, &mut |st| {
                snapshot.refined = Some(st.clone());
                checkpoint(&snapshot)
            })
            .map_err(opt_err)?;
    }
    let screened_evals = run.finished[best].evaluations;
    let refine_evals = state.evaluations - screened_evals;
    let ps_x = state.x.clone();
    run.refined = Some(state);
    let frozen = run.clone();
    let log = std::mem::take(&mut run.sqp_log);
    let r = sqp(problem, &ps_x, &s.sqp, log, progress, &mut |log| {
        checkpoint(&AfsRunState {
            sqp_log: log.to_vec(),
            ..frozen.clone()
        })
    })
    .map_err(opt_err)?;
    let full = |x: &[f64]| problem.evaluate_design(&problem.design_of(x)?);
    let outcomes: Vec<StartOutcome> = run
        .finished
        .iter()
        .zip(&starts)
        .map(|(st, x0)| -> Result<StartOutcome, DesignError> {
            Ok(StartOutcome {
                start: problem.design_of(x0)?,
                end: problem.design_of(&st.x)?,
                f: st.eval.is_feasible().then_some(st.eval.f),
                evaluations: st.evaluations,
                iterations: st.iteration,
            })
        })
        .collect::<Result<_, _>>()?;
    let fs: Vec<f64> = outcomes.iter().filter_map(|o| o.f).collect();
    let spread =
        fs.iter().fold(f64::MIN, |a, b| a.max(*b)) - fs.iter().fold(f64::MAX, |a, b| a.min(*b));
    Ok(AfsOptimum {
        evaluations_ps: outcomes.iter().map(|o| o.evaluations).sum::<usize>() + refine_evals,
        evaluations_sqp: r.evaluations,
        start_spread_f: if fs.is_empty() { 0.0 } else { spread },
        starts: outcomes,
        ps: full(&ps_x)?,
        ps_sqp: full(&r.x)?,
        sqp_improved: r.improved,
        sqp_status: r.status,
    })
}
