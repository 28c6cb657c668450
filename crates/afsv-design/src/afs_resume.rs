//! Checks of a stored chapter-4 run state ([`AfsRunState`], from a checkpoint or an
//! ask/tell state file) before a run continues from it: the state is an input like any
//! other, so it is checked as strictly as one. [`check_run_state`] refuses a state whose
//! phases do not follow the solver sequence of [`crate::afs_optimum`], whose pattern-search
//! states break [`PatternSearch::check_state`] (unit cube, mesh range and grid, counts,
//! stops), whose SQP log is malformed, or whose stored evaluations are not what the
//! problem gives at the stored points (each incumbent, and the first and best SQP entries,
//! evaluated again: a few simulations).

use crate::afs_optimum::{start_points, AfsOptimisationSettings, AfsRunState};
use crate::afs_problem::AfsProblem;
use crate::error::DesignError;
use afsv_records::stored::{parse_stored, same_settings};
use optimize::pattern_search::{PatternSearch, PatternSearchOptions, PatternSearchState};
use optimize::{ConstrainedProblem, Evaluation};
use serde::{Deserialize, Serialize};
use serde_json::Value;
use std::path::Path;

/// The pattern-search settings of screened start `i`: its own seed (seed + 1 + i) and the
/// screening mesh as its final mesh (section 4.3.5).
pub fn screening_options(s: &AfsOptimisationSettings, i: usize) -> PatternSearchOptions {
    PatternSearchOptions {
        seed: s.seed.wrapping_add(1 + i as u64),
        min_mesh: s.screen_min_mesh,
        ..s.pattern
    }
}

fn refused(reason: String) -> DesignError {
    DesignError::Shape {
        field: "stored run state",
        reason,
    }
}

/// Whether `stored` is, bit for bit, what the problem gives at `x` (`screen`: the
/// pattern searches' view, else SQP's).
fn same_evaluation(
    problem: &AfsProblem,
    x: &[f64],
    screen: bool,
    stored: &Evaluation,
    what: &str,
) -> Result<(), DesignError> {
    let now = problem.evaluate_point(x, screen);
    let same = now.f.to_bits() == stored.f.to_bits()
        && now.constraints.len() == stored.constraints.len()
        && now
            .constraints
            .iter()
            .zip(&stored.constraints)
            .all(|(a, b)| a.to_bits() == b.to_bits());
    if same {
        Ok(())
    } else {
        Err(refused(format!(
            "{what}: the stored objective {:?} is not the problem's {:?} at its point (edited, or written for another problem)",
            stored.f, now.f
        )))
    }
}

/// Checks `run` against `problem` and settings `s` before a resume (see the module
/// documentation); `Ok` for a fresh (default) state.
pub fn check_run_state(
    problem: &AfsProblem,
    s: &AfsOptimisationSettings,
    run: &AfsRunState,
) -> Result<(), DesignError> {
    let starts = start_points(problem, s)?.len();
    let screened = problem.screened();
    let ps_err = |what: String| {
        move |e: optimize::OptimizeError| match e {
            optimize::OptimizeError::Checkpoint(m) => refused(format!("{what}: {m}")),
            e => refused(format!("{what}: {e}")),
        }
    };
    let check = |st: &PatternSearchState, o: PatternSearchOptions, what: String| {
        PatternSearch::new(&screened, o)
            .and_then(|ps| ps.check_state(st))
            .map_err(ps_err(what.clone()))?;
        same_evaluation(problem, &st.x, true, &st.eval, &what)
    };
    if run.finished.len() > starts {
        return Err(refused(format!(
            "{} finished starts, these settings have {starts}",
            run.finished.len()
        )));
    }
    for (i, st) in run.finished.iter().enumerate() {
        if st.stop.is_none() {
            return Err(refused(format!("finished start {i} has not stopped")));
        }
        check(st, screening_options(s, i), format!("start {i}"))?;
    }
    if let Some(st) = &run.current {
        let i = run.finished.len();
        // (It may have stopped: a checkpoint is written after every iteration, the last
        // one too, before the search moves to the finished ones.)
        if i == starts {
            return Err(refused(
                "a screening search in progress after the last start".into(),
            ));
        }
        check(
            st,
            screening_options(s, i),
            format!("start {i} (in progress)"),
        )?;
    }
    if let Some(st) = &run.refined {
        if run.finished.len() < starts || run.current.is_some() {
            return Err(refused(
                "a refinement before every start was screened".into(),
            ));
        }
        check(st, s.pattern, "the refinement".into())?;
    }
    if !run.sqp_log.is_empty() {
        if run.refined.as_ref().is_none_or(|r| r.stop.is_none()) {
            return Err(refused(
                "an SQP log before the refinement has finished".into(),
            ));
        }
        let b = problem.bounds();
        let best = run
            .sqp_log
            .iter()
            .min_by(|a, b| a.eval.deb_cmp(&b.eval))
            .unwrap_or(&run.sqp_log[0]);
        for (l, what) in [
            (&run.sqp_log[0], "the first SQP entry"),
            (best, "the best SQP entry"),
        ] {
            if l.u.len() != b.dim() || !l.u.iter().all(|u| (0.0..=1.0).contains(u)) {
                return Err(refused(format!("{what}: not a point of the unit cube")));
            }
            same_evaluation(problem, &b.from_unit(&l.u), false, &l.eval, what)?;
        }
    }
    Ok(())
}

/// The checkpoint file of a resumable run (`afsv optimize afs --checkpoint`): one run
/// state per configuration, in order, with the settings of the command line it belongs to.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AfsCheckpoint {
    /// The command that wrote it.
    pub written_by: String,
    /// Sign convention of the toolkit's files (`afsv-v1`).
    pub sign_convention: String,
    /// The settings of the command line the checkpoint belongs to.
    pub settings: Value,
    /// The run states so far, one per configuration started.
    pub runs: Vec<AfsRunState>,
}

impl AfsCheckpoint {
    /// A checkpoint of no run yet, for `settings`, written by `written_by`.
    pub fn new(written_by: &str, settings: Value) -> Self {
        Self {
            written_by: written_by.into(),
            sign_convention: afsv_records::SIGN_CONVENTION.into(),
            settings,
            runs: Vec::new(),
        }
    }

    /// The checkpoint stored as `text` at `path` (given as `flag`), for a command line with
    /// `settings` and `configs` configurations: refused when it does not parse, was
    /// written for other settings or holds more runs than there are configurations.
    pub fn read(
        flag: &str,
        path: &Path,
        text: &str,
        settings: &Value,
        configs: usize,
    ) -> Result<Self, String> {
        let ck: Self = parse_stored(flag, path, text)?;
        same_settings(flag, path, &ck.settings, settings)?;
        if ck.runs.len() > configs {
            return Err(format!(
                "{flag} {}: {} runs, these options make {configs}",
                path.display(),
                ck.runs.len()
            ));
        }
        Ok(ck)
    }

    /// Every stored run checked against its problem ([`check_run_state`]) before any run
    /// continues, so a refused resume leaves the file as it was.
    pub fn check_runs(
        &self,
        flag: &str,
        path: &Path,
        problems: &[AfsProblem],
        s: &AfsOptimisationSettings,
    ) -> Result<(), String> {
        for (i, (run, problem)) in self.runs.iter().zip(problems).enumerate() {
            check_run_state(problem, s, run).map_err(|e| {
                format!(
                    "{flag} {}: run {}: {e}; remove it to start afresh",
                    path.display(),
                    i + 1
                )
            })?;
        }
        Ok(())
    }

    /// The state of run `i` after an iteration: it replaces run `i` and drops any later
    /// run (a resumed configuration restarts the ones after it).
    pub fn record(&mut self, i: usize, state: &AfsRunState) {
        self.runs.truncate(i);
        self.runs.push(state.clone());
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::afs_optimum::optimise;
    use crate::{AfsProblemSpec, AhpHierarchy, Objective};
    use optimize::Silent;

    use crate::afs_ask_tell::tests::small;

    #[test]
    fn a_checkpoint_is_refused_for_other_settings_or_too_many_runs_and_checks_its_runs() {
        let w = AhpHierarchy::chapter4().weights().unwrap().composite;
        let p = AfsProblem::new(AfsProblemSpec::default(), Objective::new(w).unwrap()).unwrap();
        let s = small();
        let path = Path::new("ck.json");
        let settings = serde_json::json!({"seed": 1});
        let mut ck = AfsCheckpoint::new("afsv optimize afs", settings.clone());
        assert_eq!(ck.sign_convention, "afsv-v1");
        let fresh = AfsRunState::default();
        ck.record(0, &fresh);
        ck.record(1, &fresh);
        ck.record(0, &fresh);
        assert_eq!(
            ck.runs.len(),
            1,
            "a run recorded again drops the later ones"
        );
        let text = serde_json::to_string(&ck).unwrap();
        let back = AfsCheckpoint::read("--checkpoint", path, &text, &settings, 1).unwrap();
        assert_eq!(back, ck);
        back.check_runs("--checkpoint", path, std::slice::from_ref(&p), &s)
            .unwrap();
        let other = serde_json::json!({"seed": 2});
        let e = AfsCheckpoint::read("--checkpoint", path, &text, &other, 1).unwrap_err();
        assert!(e.contains("written for other settings"), "{e}");
        let e = AfsCheckpoint::read("--checkpoint", path, &text, &settings, 0).unwrap_err();
        assert_eq!(e, "--checkpoint ck.json: 1 runs, these options make 0");
        let mut bad = ck.clone();
        bad.runs[0].sqp_log.push(optimize::sqp::LoggedEvaluation {
            u: vec![0.5; 5],
            eval: Evaluation {
                f: 1.0,
                constraints: Vec::new(),
            },
        });
        let e = bad
            .check_runs("--checkpoint", path, std::slice::from_ref(&p), &s)
            .unwrap_err();
        assert!(
            e.starts_with("--checkpoint ck.json: run 1: ")
                && e.ends_with("remove it to start afresh"),
            "{e}"
        );
    }

    #[test]
    fn every_checkpoint_of_a_run_passes_and_tampered_ones_are_refused() {
        let w = AhpHierarchy::chapter4().weights().unwrap().composite;
        let p = AfsProblem::new(AfsProblemSpec::default(), Objective::new(w).unwrap()).unwrap();
        let s = small();
        let mut snapshots = Vec::new();
        optimise(&p, &s, AfsRunState::default(), &Silent, &mut |st| {
            snapshots.push(st.clone());
            Ok(())
        })
        .unwrap();
        assert!(snapshots.len() > 5, "{}", snapshots.len());
        for st in &snapshots {
            check_run_state(&p, &s, st).unwrap();
        }
        let done = snapshots.last().unwrap().clone();
        assert!(done.refined.is_some() && !done.sqp_log.is_empty());
        let refuse = |edit: &dyn Fn(&mut AfsRunState), want: &str| {
            let mut t = done.clone();
            edit(&mut t);
            let e = check_run_state(&p, &s, &t).unwrap_err().to_string();
            assert!(e.contains(want), "{want:?} not in {e}");
        };
        refuse(&|t| t.finished[0].mesh = 1e308, "mesh 1e308 outside");
        refuse(
            &|t| t.finished[1].mesh = 0.1,
            "mesh 0.1 is not 0.25 times a power of 0.5",
        );
        refuse(&|t| t.finished[0].u[0] = -0.1, "outside [0, 1]");
        refuse(&|t| t.finished[0].x[1] *= 1.01, "not the image");
        refuse(&|t| t.finished[0].stop = None, "has not stopped");
        refuse(&|t| t.finished[0].evaluations = 0, "0 evaluations for");
        refuse(
            &|t| t.finished[0].eval.constraints.pop().map_or((), |_| ()),
            "constraint values",
        );
        refuse(
            &|t| t.finished.push(t.finished[0].clone()),
            "finished starts",
        );
        refuse(
            &|t| t.refined.as_mut().unwrap().eval.f += 1e-9,
            "is not the problem's",
        );
        refuse(&|t| t.sqp_log[0].eval.f = 0.5, "the first SQP entry");
        refuse(
            &|t| t.current = Some(t.finished[0].clone()),
            "after the last start",
        );
        refuse(
            &|t| {
                t.refined = None;
            },
            "an SQP log before",
        );
    }
}
