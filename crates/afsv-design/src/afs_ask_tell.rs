//! Ask/tell for the whole chapter-4 solver sequence of [`crate::afs_optimum`], so that its
//! evaluations can run anywhere (other processes, a cluster's array tasks): [`AfsAskTell::ask`]
//! gives the next batch of design points of the phase the run is in (the start point of a
//! screened start, that start's search hypercube and polls, the refinement polls of the best
//! start, the SQP batches), [`AfsAskTell::tell`] advances an [`AfsRunState`] by their
//! evaluations, in the batch's order. The state is the same one [`optimise`] checkpoints,
//! and once [`AfsAskTell::ask`] says [`AfsAsk::Finished`], [`AfsAskTell::finish`] replays
//! the complete state through [`optimise`] itself (no evaluation is repeated: pattern
//! searches are finished and the SQP log holds every point), so the result is the
//! in-process one, bit for bit.
//!
//! The phases advance as in [`optimise`]: the pattern search of start `i` begins with the
//! evaluation of its start point (projected onto the bounds, as
//! [`PatternSearch::start`] does) and runs to the screening mesh ([`PatternSearch::ask`] /
//! [`PatternSearch::tell`]); after the last start the best one (Deb's rules, first of
//! equals) continues to the fine mesh; then SLSQP from it, replayed on its evaluation log
//! ([`sqp_ask`]).

use crate::afs_optimum::{
    optimise, start_points, AfsOptimisationSettings, AfsOptimum, AfsRunState,
};
use crate::afs_problem::AfsProblem;
use crate::error::DesignError;
use optimize::pattern_search::{PatternSearch, PatternSearchOptions, PatternSearchState};
use optimize::sqp::{sqp_ask, LoggedEvaluation, SqpStep};
use optimize::{Bounds, ConstrainedProblem, Evaluation, OptimizeError, Silent};

/// The phase a batch belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AfsPhase {
    /// The start point of screened start `start` (one point).
    StartPoint {
        /// Index of the start (0: the current design).
        start: usize,
    },
    /// A search hypercube or poll of screened start `start`.
    Screening {
        /// Index of the start.
        start: usize,
    },
    /// A poll of the refinement of the best start.
    Refinement,
    /// A batch of SLSQP (a point and its difference points, or a line-search point).
    Sqp,
}

impl AfsPhase {
    /// Snake-case name (`start_point`, `screening`, `refinement`, `sqp`).
    pub fn name(self) -> &'static str {
        match self {
            AfsPhase::StartPoint { .. } => "start_point",
            AfsPhase::Screening { .. } => "screening",
            AfsPhase::Refinement => "refinement",
            AfsPhase::Sqp => "sqp",
        }
    }

    /// Whether the points are evaluated by the screened view ([`AfsProblem::screened`]: an
    /// infeasible point is not simulated), as the pattern searches see the problem; SQP
    /// sees the full problem ([`AfsProblem::evaluate_point`] with `screen = false`).
    pub fn screened(self) -> bool {
        self != AfsPhase::Sqp
    }
}

/// The next batch of a run.
#[derive(Debug, Clone, PartialEq)]
pub struct AfsBatch {
    /// Its phase.
    pub phase: AfsPhase,
    /// The design points in the problem's units ([`crate::AfsVariable::ALL`]'s order,
    /// SI), to evaluate with [`AfsProblem::evaluate_point`] at `phase.screened()`.
    pub points: Vec<Vec<f64>>,
}

/// What [`AfsAskTell::ask`] found.
#[derive(Debug, Clone, PartialEq)]
pub enum AfsAsk {
    /// Evaluate these points and tell their evaluations.
    Evaluate(AfsBatch),
    /// Every phase has finished; [`AfsAskTell::finish`] gives the result.
    Finished,
}

/// The step a run state is at, with what its tell needs.
enum Step {
    StartPoint(usize, Vec<f64>),
    Screening(usize, PatternSearchState, Vec<Vec<f64>>),
    Refinement(PatternSearchState, Vec<Vec<f64>>),
    Sqp(Vec<Vec<f64>>),
    Finished,
}

/// The ask/tell driver of one chapter-4 problem with fixed settings.
pub struct AfsAskTell<'a> {
    problem: &'a AfsProblem,
    settings: AfsOptimisationSettings,
    starts: Vec<Vec<f64>>,
}

fn opt_err(e: OptimizeError) -> DesignError {
    DesignError::Shape {
        field: "optimiser",
        reason: e.to_string(),
    }
}

/// A problem that answers every point with one known evaluation: the start point's, so
/// that [`PatternSearch::start`] builds the state from an evaluation made elsewhere.
struct Answered<'a> {
    bounds: &'a Bounds,
    eval: Evaluation,
}

impl ConstrainedProblem for Answered<'_> {
    fn bounds(&self) -> &Bounds {
        self.bounds
    }
    fn n_constraints(&self) -> usize {
        self.eval.constraints.len()
    }
    fn evaluate(&self, _x: &[f64]) -> Evaluation {
        self.eval.clone()
    }
}

impl<'a> AfsAskTell<'a> {
    /// The driver of `problem` under `settings` (validated as [`optimise`] does).
    pub fn new(
        problem: &'a AfsProblem,
        settings: AfsOptimisationSettings,
    ) -> Result<Self, DesignError> {
        let starts = start_points(problem, &settings)?;
        let s = &settings;
        if !(s.screen_min_mesh >= s.pattern.min_mesh && s.screen_min_mesh < s.pattern.initial_mesh)
        {
            return Err(DesignError::Invalid {
                field: "screen_min_mesh",
                value: s.screen_min_mesh,
                reason: "must be in [pattern.min_mesh, pattern.initial_mesh)",
            });
        }
        s.pattern.validate().map_err(opt_err)?;
        Ok(Self {
            problem,
            settings,
            starts,
        })
    }

    /// The pattern-search settings of screened start `i` (as in [`optimise`]).
    fn screening_options(&self, i: usize) -> PatternSearchOptions {
        crate::afs_resume::screening_options(&self.settings, i)
    }

    /// Where `run` stands and the unit-cube points (or the start point) it needs next.
    fn step(&self, run: &AfsRunState) -> Result<Step, DesignError> {
        let screened = self.problem.screened();
        let bounds = self.problem.bounds();
        let i = run.finished.len();
        if i > self.starts.len() {
            return Err(DesignError::Shape {
                field: "state",
                reason: "it holds more starts than these settings".into(),
            });
        }
        if i < self.starts.len() {
            let ps = PatternSearch::new(&screened, self.screening_options(i)).map_err(opt_err)?;
            return Ok(match &run.current {
                None => {
                    // The projection PatternSearch::start applies before it evaluates.
                    let u: Vec<f64> = bounds
                        .to_unit(&self.starts[i])
                        .iter()
                        .map(|v| v.clamp(0.0, 1.0))
                        .collect();
                    Step::StartPoint(i, bounds.from_unit(&u))
                }
                Some(st) => {
                    ps.check_state(st).map_err(opt_err)?;
                    let units = ps.ask(st).map_err(opt_err)?;
                    Step::Screening(i, st.clone(), units)
                }
            });
        }
        if run.current.is_some() {
            return Err(DesignError::Shape {
                field: "state",
                reason: "a screening search in progress after the last start".into(),
            });
        }
        let state = match &run.refined {
            Some(st) => st.clone(),
            None => {
                let best = (0..run.finished.len())
                    .min_by(|&a, &b| run.finished[a].eval.deb_cmp(&run.finished[b].eval))
                    .unwrap_or(0);
                let mut st = run.finished[best].clone();
                st.stop = None;
                st
            }
        };
        if state.stop.is_none() {
            let refine = PatternSearch::new(&screened, self.settings.pattern).map_err(opt_err)?;
            refine.check_state(&state).map_err(opt_err)?;
            let units = refine.ask(&state).map_err(opt_err)?;
            return Ok(Step::Refinement(state, units));
        }
        let step = sqp_ask(
            bounds,
            self.problem.n_constraints(),
            &state.x,
            &self.settings.sqp,
            run.sqp_log.clone(),
        )
        .map_err(opt_err)?;
        Ok(match step {
            SqpStep::Need(units) => Step::Sqp(units),
            SqpStep::Done(_) => Step::Finished,
        })
    }

    /// The next batch of `run` (a pure function of the state: asking again gives the same
    /// batch), or [`AfsAsk::Finished`].
    pub fn ask(&self, run: &AfsRunState) -> Result<AfsAsk, DesignError> {
        let b = self.problem.bounds();
        let units = |u: &[Vec<f64>]| u.iter().map(|u| b.from_unit(u)).collect();
        Ok(match self.step(run)? {
            Step::StartPoint(start, x) => AfsAsk::Evaluate(AfsBatch {
                phase: AfsPhase::StartPoint { start },
                points: vec![x],
            }),
            Step::Screening(start, _, u) => AfsAsk::Evaluate(AfsBatch {
                phase: AfsPhase::Screening { start },
                points: units(&u),
            }),
            Step::Refinement(_, u) => AfsAsk::Evaluate(AfsBatch {
                phase: AfsPhase::Refinement,
                points: units(&u),
            }),
            Step::Sqp(u) => AfsAsk::Evaluate(AfsBatch {
                phase: AfsPhase::Sqp,
                points: units(&u),
            }),
            Step::Finished => AfsAsk::Finished,
        })
    }

    /// Advances `run` by `evals`, the evaluations of the batch [`AfsAskTell::ask`] gives
    /// for it, in its order. A wrong count, a wrong constraint count or a finished run is
    /// an error and leaves `run` unchanged.
    pub fn tell(&self, run: &mut AfsRunState, evals: Vec<Evaluation>) -> Result<(), DesignError> {
        let nc = self.problem.n_constraints();
        let check = |asked: usize| {
            if evals.len() == asked && evals.iter().all(|e| e.constraints.len() == nc) {
                Ok(())
            } else {
                Err(DesignError::Shape {
                    field: "evaluations",
                    reason: format!(
                        "expected {asked} evaluations with {nc} constraints each, got {}",
                        evals.len()
                    ),
                })
            }
        };
        let screened = self.problem.screened();
        match self.step(run)? {
            Step::Finished => {
                return Err(DesignError::Shape {
                    field: "evaluations",
                    reason: "the run has finished; nothing was asked".into(),
                })
            }
            Step::StartPoint(i, _) => {
                check(1)?;
                let answered = Answered {
                    bounds: self.problem.bounds(),
                    eval: evals[0].clone(),
                };
                let ps =
                    PatternSearch::new(&answered, self.screening_options(i)).map_err(opt_err)?;
                run.current = Some(ps.start(&self.starts[i]).map_err(opt_err)?);
            }
            Step::Screening(i, mut st, units) => {
                check(units.len())?;
                let ps =
                    PatternSearch::new(&screened, self.screening_options(i)).map_err(opt_err)?;
                ps.tell(&mut st, evals).map_err(opt_err)?;
                if st.stop.is_some() {
                    run.finished.push(st);
                    run.current = None;
                } else {
                    run.current = Some(st);
                }
            }
            Step::Refinement(mut st, units) => {
                check(units.len())?;
                let refine =
                    PatternSearch::new(&screened, self.settings.pattern).map_err(opt_err)?;
                refine.tell(&mut st, evals).map_err(opt_err)?;
                run.refined = Some(st);
            }
            Step::Sqp(units) => {
                check(units.len())?;
                run.sqp_log.extend(
                    units
                        .into_iter()
                        .zip(evals)
                        .map(|(u, eval)| LoggedEvaluation { u, eval }),
                );
            }
        }
        Ok(())
    }

    /// The result of a finished run: [`optimise`] on the complete state, which evaluates
    /// only the full reports of the PS and PS/SQP designs. An unfinished run is an error.
    pub fn finish(&self, run: &AfsRunState) -> Result<AfsOptimum, DesignError> {
        if !matches!(self.step(run)?, Step::Finished) {
            return Err(DesignError::Shape {
                field: "state",
                reason: "the run has not finished; ask for the next batch".into(),
            });
        }
        optimise(
            self.problem,
            &self.settings,
            run.clone(),
            &Silent,
            &mut |_| Ok(()),
        )
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::{AfsProblemSpec, AhpHierarchy, Objective};
    use optimize::pattern_search::PatternSearchOptions;
    use optimize::sqp::SqpOptions;

    /// A run small enough for a unit test: two starts, a 5-point search step, screening to
    /// mesh 1/8, refinement to 1/16, three SQP calls.
    pub(crate) fn small() -> AfsOptimisationSettings {
        AfsOptimisationSettings {
            extra_starts: 1,
            seed: 3,
            pattern: PatternSearchOptions {
                initial_mesh: 0.25,
                min_mesh: 1.0 / 16.0,
                search_points: 5,
                max_evaluations: 400,
                ..PatternSearchOptions::default()
            },
            screen_min_mesh: 1.0 / 8.0,
            sqp: SqpOptions {
                max_calls: 3,
                fd_step: 1e-2,
                ..SqpOptions::default()
            },
        }
    }

    fn problem() -> AfsProblem {
        let w = AhpHierarchy::chapter4().weights().unwrap().composite;
        AfsProblem::new(AfsProblemSpec::default(), Objective::new(w).unwrap()).unwrap()
    }

    #[test]
    fn ask_and_tell_through_every_phase_equal_the_in_process_run() {
        let p = problem();
        let driver = AfsAskTell::new(&p, small()).unwrap();
        let mut run = AfsRunState::default();
        let mut phases = Vec::new();
        let mut evaluated = 0;
        while let AfsAsk::Evaluate(batch) = driver.ask(&run).unwrap() {
            // Asking is a pure function of the state.
            assert_eq!(driver.ask(&run).unwrap(), AfsAsk::Evaluate(batch.clone()));
            if phases.last() != Some(&batch.phase) {
                phases.push(batch.phase);
            }
            let evals: Vec<Evaluation> = batch
                .points
                .iter()
                .map(|x| p.evaluate_point(x, batch.phase.screened()))
                .collect();
            evaluated += evals.len();
            // A wrong count is refused and leaves the state as it was.
            let before = run.clone();
            let mut short = evals.clone();
            short.push(Evaluation::failed(p.n_constraints()));
            assert!(driver.tell(&mut run, short).is_err());
            assert_eq!(run, before);
            driver.tell(&mut run, evals).unwrap();
        }
        assert_eq!(
            phases,
            vec![
                AfsPhase::StartPoint { start: 0 },
                AfsPhase::Screening { start: 0 },
                AfsPhase::StartPoint { start: 1 },
                AfsPhase::Screening { start: 1 },
                AfsPhase::Refinement,
                AfsPhase::Sqp,
            ]
        );
        assert!(driver
            .tell(&mut run, vec![Evaluation::failed(p.n_constraints())])
            .is_err());
        let ours = driver.finish(&run).unwrap();
        let theirs = optimise(&p, &small(), AfsRunState::default(), &Silent, &mut |_| {
            Ok(())
        })
        .unwrap();
        assert_eq!(ours, theirs);
        assert_eq!(
            evaluated,
            theirs.evaluations_ps + theirs.evaluations_sqp,
            "every evaluation of the in-process run was asked once"
        );
    }

    #[test]
    fn unfinished_runs_and_bad_settings_are_refused() {
        let p = problem();
        let driver = AfsAskTell::new(&p, small()).unwrap();
        let e = driver.finish(&AfsRunState::default()).unwrap_err();
        assert!(e.to_string().contains("not finished"), "{e}");
        let bad = AfsOptimisationSettings {
            screen_min_mesh: 0.5,
            ..small()
        };
        let e = AfsAskTell::new(&p, bad).err().unwrap();
        assert!(e.to_string().contains("screen_min_mesh"), "{e}");
        let many = AfsOptimisationSettings {
            extra_starts: 5000,
            ..small()
        };
        assert!(AfsAskTell::new(&p, many).is_err());
    }
}
