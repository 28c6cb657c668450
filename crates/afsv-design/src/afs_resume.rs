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
use optimize::pattern_search::{PatternSearch, PatternSearchOptions, PatternSearchState};
use optimize::{ConstrainedProblem, Evaluation};

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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::afs_optimum::optimise;
    use crate::{AfsProblemSpec, AhpHierarchy, Objective};
    use optimize::Silent;

    use crate::afs_ask_tell::tests::small;

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
