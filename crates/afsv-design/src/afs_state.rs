//! The state file of the ask/tell optimisation (`afsv optimize afs --state`): one run state
//! per configuration, the settings it belongs to and the batches told; the batch it asks
//! for ([`AskTellState::asked`]) and the results that answer it ([`AskTellState::results`],
//! every asked point exactly once, from this state's batch).

use crate::afs_batch::{
    point_id, BatchPoint, PointResult, ProblemDesc, ResultsHeader, FORMAT_VERSION,
    MAX_BATCH_POINTS, RESULTS_FORMAT,
};
use crate::batch_files::collect_results;
use crate::report::afs::AfsRun;
use crate::{
    AfsAsk, AfsAskTell, AfsOptimisationSettings, AfsProblem, AfsRunState, AfsVariable, DesignError,
};
use afsv_records::stored::{parse_stored, same_settings};
use optimize::Evaluation;
use serde::{Deserialize, Serialize};
use serde_json::{json, Value};
use std::path::{Path, PathBuf};

/// The ask/tell state file: one run state per configuration, the settings it belongs to,
/// and the number of batches told.
#[derive(Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AskTellState {
    /// The command that wrote it.
    pub written_by: String,
    /// `afsv-v1`.
    pub sign_convention: String,
    /// [`STATE_FORMAT`].
    pub format: String,
    /// [`STATE_VERSION`].
    pub version: u32,
    /// The settings of the command line the state belongs to.
    pub settings: Value,
    /// Batches told so far: the number of the next batch.
    pub batch: usize,
    /// One run per configuration (with, then without the arm constraint).
    pub runs: Vec<AfsRunState>,
}

/// `format` of the state file.
pub const STATE_FORMAT: &str = "afsv-ask-tell-state";
/// `version` of the state file.
pub const STATE_VERSION: u32 = 1;

/// A batch as asked: its points and, per configuration, how many of them it holds.
pub struct Asked {
    /// The batch's points, in order.
    pub points: Vec<BatchPoint>,
    /// Per configuration, how many of the points are its.
    pub per_run: Vec<usize>,
    /// Per configuration with points: its label, phase, start and point count (JSON).
    pub phases: Vec<Value>,
}

impl AskTellState {
    /// The state of `flag` `path` from its `stored` text (as read under the run lock), checked
    /// against the command's settings and problems; a new state when there is none and
    /// `create` allows one.
    pub fn read(
        flag: &str,
        path: &Path,
        stored: Option<&str>,
        create: bool,
        settings: &AfsOptimisationSettings,
        settings_json: &Value,
        problems: &[AfsProblem],
    ) -> Result<Self, String> {
        Ok(match stored {
            Some(text) => {
                let st: AskTellState = parse_stored(flag, path, text)?;
                same_settings(flag, path, &st.settings, settings_json)?;
                if st.format != STATE_FORMAT
                    || st.version != STATE_VERSION
                    || st.runs.len() != problems.len()
                {
                    return Err(format!(
                        "{flag} {}: not an ask/tell state of version {STATE_VERSION} with {} runs",
                        path.display(),
                        problems.len()
                    ));
                }
                for (i, (run, problem)) in st.runs.iter().zip(problems).enumerate() {
                    crate::check_run_state(problem, settings, run)
                        .map_err(|e| format!("{flag} {}: run {}: {e}", path.display(), i + 1))?;
                }
                st
            }
            None if !create => {
                return Err(format!(
                    "{flag} {}: does not exist; start the run with --ask",
                    path.display()
                ))
            }
            None => AskTellState {
                written_by: "afsv optimize afs".into(),
                sign_convention: afsv_records::SIGN_CONVENTION.into(),
                format: STATE_FORMAT.into(),
                version: STATE_VERSION,
                settings: settings_json.clone(),
                batch: 0,
                runs: vec![AfsRunState::default(); problems.len()],
            },
        })
    }

    /// The batch the state asks for (`None`: every run has finished).
    pub fn asked(
        &self,
        drivers: &[AfsAskTell],
        descs: &[ProblemDesc],
    ) -> Result<Option<Asked>, String> {
        let mut asked = Asked {
            points: Vec::new(),
            per_run: Vec::new(),
            phases: Vec::new(),
        };
        let mut finished = true;
        for (k, (d, run)) in drivers.iter().zip(&self.runs).enumerate() {
            let AfsAsk::Evaluate(b) = d.ask(run).map_err(|e| e.to_string())? else {
                asked.per_run.push(0);
                continue;
            };
            finished = false;
            if asked.points.len() + b.points.len() > MAX_BATCH_POINTS {
                return Err(format!("a batch of more than {} points", MAX_BATCH_POINTS));
            }
            asked.per_run.push(b.points.len());
            let start = match b.phase {
                crate::AfsPhase::StartPoint { start } | crate::AfsPhase::Screening { start } => {
                    Some(start)
                }
                _ => None,
            };
            asked.phases.push(json!({"run": descs[k].label, "phase": b.phase.name(), "start": start, "points": b.points.len()}));
            for x in &b.points {
                let index = asked.points.len();
                asked.points.push(BatchPoint {
                    id: point_id(self.batch, index),
                    problem: k,
                    phase: b.phase.name().into(),
                    screened: b.phase.screened(),
                    x: AfsVariable::ALL
                        .iter()
                        .zip(x)
                        .map(|(v, x)| (v.name().to_string(), *x))
                        .collect(),
                });
            }
        }
        Ok((!finished).then_some(asked))
    }

    /// Tells every run its share of `evals`, the results of the batch `asked` in its order
    /// ([`Asked::per_run`] points per run, a run with none is not told), and counts the
    /// batch as told.
    pub fn tell(
        &mut self,
        drivers: &[AfsAskTell],
        asked: &Asked,
        evals: Vec<Evaluation>,
    ) -> Result<(), DesignError> {
        let mut evals = evals.into_iter();
        for ((d, run), n) in drivers.iter().zip(self.runs.iter_mut()).zip(&asked.per_run) {
            let mine: Vec<Evaluation> = evals.by_ref().take(*n).collect();
            if *n > 0 {
                d.tell(run, mine)?;
            }
        }
        self.batch += 1;
        Ok(())
    }

    /// The results of the finished runs, one per configuration of `descs` (its label and
    /// steering-arm bound), each with the wall time of its final step.
    pub fn finish(
        &self,
        drivers: &[AfsAskTell],
        descs: &[ProblemDesc],
    ) -> Result<Vec<AfsRun>, DesignError> {
        drivers
            .iter()
            .zip(&self.runs)
            .zip(descs)
            .map(|((d, run), desc)| {
                let t = std::time::Instant::now();
                let optimum = d.finish(run)?;
                Ok(AfsRun {
                    label: desc.label.clone(),
                    min_arm_m: desc.min_steering_arm_m,
                    optimum,
                    seconds: t.elapsed().as_secs_f64(),
                })
            })
            .collect()
    }

    /// Reads every results file (`--tell`) and returns the evaluations in the batch's order, checking
    /// that every asked id comes exactly once, no other id comes, and every file belongs to
    /// this batch and these problems.
    pub fn results(
        &self,
        tell: &[PathBuf],
        sha: &str,
        asked: &Asked,
        descs: &[ProblemDesc],
        problems: &[AfsProblem],
    ) -> Result<Vec<Evaluation>, String> {
        let check = |h: &ResultsHeader, file: &str| {
            if h.format != RESULTS_FORMAT || h.version != FORMAT_VERSION {
                return Err(format!(
                    "--tell {file}: not a results file of version {} (format {:?}, version {})",
                    FORMAT_VERSION, h.format, h.version
                ));
            }
            if h.problems != descs {
                return Err(format!(
                    "--tell {file}: results of another problem or other settings than this state's"
                ));
            }
            if h.batch != self.batch {
                return Err(format!(
                    "--tell {file}: results of batch {}, the state asked batch {}",
                    h.batch, self.batch
                ));
            }
            if h.state_sha256 != sha {
                return Err(format!(
                    "--tell {file}: results of batch {} as another state asked it (state SHA-256 {}..., this state's {}...): they belong to another run or an older copy of this state; evaluate this state's batch (--ask) and tell its results",
                    h.batch,
                    h.state_sha256.get(..12).unwrap_or(&h.state_sha256),
                    &sha[..12]
                ));
            }
            Ok(())
        };
        let take = |r: &PointResult, i: usize| {
            let nc = problems[asked.points[i].problem].constraints().len();
            if r.constraints.len() != nc {
                return Err(format!(
                    "{} constraint values, the problem has {nc}",
                    r.constraints.len()
                ));
            }
            Ok(r.evaluation())
        };
        let ids: Vec<&str> = asked.points.iter().map(|p| p.id.as_str()).collect();
        collect_results(tell, self.batch, &ids, &check, &take)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_missing_state_is_new_only_when_asked_and_a_stored_one_must_match() {
        let path = Path::new("state.json");
        let settings = AfsOptimisationSettings::default();
        let now = json!({"seed": 1});
        let e = AskTellState::read("--state", path, None, false, &settings, &now, &[]).unwrap_err();
        assert!(e.contains("does not exist"), "{e}");
        let st = AskTellState::read("--state", path, None, true, &settings, &now, &[]).unwrap();
        assert_eq!((st.batch, st.runs.len(), &st.settings), (0, 0, &now));
        let text = serde_json::to_string(&st).unwrap();
        let back =
            AskTellState::read("--state", path, Some(&text), false, &settings, &now, &[]).unwrap();
        assert_eq!(back.format, STATE_FORMAT);
        let other = json!({"seed": 2});
        let e = AskTellState::read("--state", path, Some(&text), false, &settings, &other, &[])
            .unwrap_err();
        assert!(e.contains("other settings"), "{e}");
        // a state that asks nothing has finished
        assert!(st.asked(&[], &[]).unwrap().is_none());
    }
}
