//! The ask/tell driver of `afsv optimize afs --state`: the state file, `--ask` (the next
//! batch, or the report once the run is done) and `--tell` (the results of every shard).

use super::super::batch::{self, BatchHeader, BatchPoint, PointResult, ResultsHeader};
use super::{parse_stored, report, same_settings, AfsArgs, ProblemDesc, RunOutcome};
use crate::cmd::CmdResult;
use afsv_design::{
    AfsAsk, AfsAskTell, AfsOptimisationSettings, AfsProblem, AfsRunState, AfsVariable, Objective,
};
use optimize::Evaluation;
use serde::{Deserialize, Serialize};
use serde_json::{json, Value};
use std::collections::HashMap;
use std::io::IsTerminal;
use std::path::Path;

/// The ask/tell state file: one run state per configuration, the settings it belongs to,
/// and the number of batches told.
#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct AskTellState {
    written_by: String,
    sign_convention: String,
    format: String,
    version: u32,
    /// The settings of the command line the state belongs to.
    settings: Value,
    /// Batches told so far: the number of the next batch.
    batch: usize,
    /// One run per configuration (with, then without the arm constraint).
    runs: Vec<AfsRunState>,
}

/// `format` of the state file.
const STATE_FORMAT: &str = "afsv-ask-tell-state";
/// `version` of the state file.
const STATE_VERSION: u32 = 1;

/// One `--ask` or `--tell` of an ask/tell run.
pub(super) struct AskTell<'a> {
    pub(super) args: &'a AfsArgs,
    pub(super) state_path: &'a Path,
    /// The state file's text as read (under the run lock), `None` if it does not exist.
    pub(super) stored: Option<String>,
    pub(super) settings: AfsOptimisationSettings,
    pub(super) settings_json: Value,
    pub(super) descs: Vec<ProblemDesc>,
    pub(super) problems: &'a [AfsProblem],
    pub(super) objective: Objective,
}

/// A batch as asked: its points and, per configuration, how many of them it holds.
struct Asked {
    points: Vec<BatchPoint>,
    per_run: Vec<usize>,
    phases: Vec<Value>,
}

impl AskTell<'_> {
    pub(super) fn run(&self) -> CmdResult {
        let drivers: Vec<AfsAskTell> = self
            .problems
            .iter()
            .map(|p| AfsAskTell::new(p, self.settings))
            .collect::<Result<_, _>>()?;
        let created = self.stored.is_none();
        let state = match &self.stored {
            Some(text) => {
                let st: AskTellState = parse_stored("--state", self.state_path, text)?;
                same_settings(
                    "--state",
                    self.state_path,
                    &st.settings,
                    &self.settings_json,
                )?;
                if st.format != STATE_FORMAT
                    || st.version != STATE_VERSION
                    || st.runs.len() != self.problems.len()
                {
                    return Err(format!(
                        "--state {}: not an ask/tell state of version {STATE_VERSION} with {} runs",
                        self.state_path.display(),
                        self.problems.len()
                    )
                    .into());
                }
                for (i, (run, problem)) in st.runs.iter().zip(self.problems).enumerate() {
                    afsv_design::check_run_state(problem, &self.settings, run).map_err(|e| {
                        format!("--state {}: run {}: {e}", self.state_path.display(), i + 1)
                    })?;
                }
                st
            }
            None if self.args.ask.is_none() => {
                return Err(format!(
                    "--state {}: does not exist; start the run with --ask",
                    self.state_path.display()
                )
                .into())
            }
            None => AskTellState {
                written_by: "afsv optimize afs".into(),
                sign_convention: afsv_records::SIGN_CONVENTION.into(),
                format: STATE_FORMAT.into(),
                version: STATE_VERSION,
                settings: self.settings_json.clone(),
                batch: 0,
                runs: vec![AfsRunState::default(); self.problems.len()],
            },
        };
        // The identity of what this state asks: the SHA-256 of the file's content (as it
        // is, or as a new state will be written).
        let text = match &self.stored {
            Some(t) => t.clone(),
            None => serde_json::to_string(&state)?,
        };
        let sha = afsv_records::provenance::sha256_hex(text.as_bytes());
        match &self.args.ask {
            Some(path) => self.ask(&drivers, &state, created.then_some(&text), &sha, path),
            None => self.tell(&drivers, state, &sha),
        }
    }

    /// The batch the state asks for (`None`: every run has finished).
    fn asked(&self, drivers: &[AfsAskTell], state: &AskTellState) -> Result<Option<Asked>, String> {
        let mut asked = Asked {
            points: Vec::new(),
            per_run: Vec::new(),
            phases: Vec::new(),
        };
        let mut finished = true;
        for (k, (d, run)) in drivers.iter().zip(&state.runs).enumerate() {
            let AfsAsk::Evaluate(b) = d.ask(run).map_err(|e| e.to_string())? else {
                asked.per_run.push(0);
                continue;
            };
            finished = false;
            if asked.points.len() + b.points.len() > batch::MAX_BATCH_POINTS {
                return Err(format!(
                    "a batch of more than {} points",
                    batch::MAX_BATCH_POINTS
                ));
            }
            asked.per_run.push(b.points.len());
            let start = match b.phase {
                afsv_design::AfsPhase::StartPoint { start }
                | afsv_design::AfsPhase::Screening { start } => Some(start),
                _ => None,
            };
            asked.phases.push(json!({"run": self.descs[k].label, "phase": b.phase.name(), "start": start, "points": b.points.len()}));
            for x in &b.points {
                let index = asked.points.len();
                asked.points.push(BatchPoint {
                    id: batch::point_id(state.batch, index),
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

    /// Writes the next batch (identified by `sha`, the state's SHA-256, and its number),
    /// and a new state's file (`created`: its text); once finished, the report.
    fn ask(
        &self,
        drivers: &[AfsAskTell],
        state: &AskTellState,
        created: Option<&String>,
        sha: &str,
        path: &Path,
    ) -> CmdResult {
        let asked = self.asked(drivers, state)?;
        let points = asked.as_ref().map_or(&[][..], |a| &a.points[..]);
        let header = BatchHeader {
            format: batch::BATCH_FORMAT.into(),
            version: batch::FORMAT_VERSION,
            written_by: "afsv optimize afs --ask".into(),
            sign_convention: afsv_records::SIGN_CONVENTION.into(),
            batch: state.batch,
            state_sha256: sha.into(),
            finished: asked.is_none(),
            points: points.len(),
            variables: batch::variable_names(),
            problems: self.descs.clone(),
        };
        batch::write_jsonl(path, &header, points)?;
        if let Some(text) = created {
            afsv_records::atomic::write(self.state_path, text)
                .map_err(|e| format!("{}: {e}", self.state_path.display()))?;
        }
        let Some(asked) = asked else {
            if !afsv::progress::is_quiet() {
                eprintln!(
                "afsv optimize afs: the run has finished after {} batches; {} holds no point; the report follows",
                state.batch,
                path.display()
            );
            }
            let outcomes = drivers
                .iter()
                .zip(&state.runs)
                .zip(&self.descs)
                .map(|((d, run), desc)| {
                    let t = std::time::Instant::now();
                    let optimum = d.finish(run)?;
                    Ok(RunOutcome {
                        label: desc.label.clone(),
                        min_arm_m: desc.min_steering_arm_m,
                        optimum,
                        seconds: t.elapsed().as_secs_f64(),
                    })
                })
                .collect::<Result<Vec<_>, afsv_design::DesignError>>()?;
            return report(self.args, &self.objective, self.problems, &outcomes);
        };
        let status = json!({
            "batch": state.batch, "finished": false, "points": asked.points.len(),
            "batch_file": path.display().to_string(), "phases": asked.phases,
        });
        if self.args.json || !std::io::stdout().is_terminal() {
            afsv::output::print_json(&status)?;
        } else {
            println!(
                "batch {}: {} points written to {} ({})",
                state.batch,
                asked.points.len(),
                path.display(),
                asked
                    .phases
                    .iter()
                    .map(|p| format!(
                        "{} {}: {}",
                        p["run"].as_str().unwrap_or(""),
                        p["phase"].as_str().unwrap_or(""),
                        p["points"]
                    ))
                    .collect::<Vec<_>>()
                    .join("; ")
            );
        }
        Ok(())
    }

    /// Reads every results file and returns the evaluations in the batch's order, checking
    /// that every asked id comes exactly once, no other id comes, and every file belongs to
    /// this batch and these problems.
    fn results(
        &self,
        state: &AskTellState,
        sha: &str,
        asked: &Asked,
    ) -> Result<Vec<Evaluation>, String> {
        let index: HashMap<&str, usize> = asked
            .points
            .iter()
            .enumerate()
            .map(|(i, p)| (p.id.as_str(), i))
            .collect();
        let mut found: Vec<Option<(Evaluation, String)>> = vec![None; asked.points.len()];
        for path in &self.args.tell {
            let file = path.display();
            let check = |h: &ResultsHeader| {
                if h.format != batch::RESULTS_FORMAT || h.version != batch::FORMAT_VERSION {
                    return Err(format!(
                        "--tell {file}: not a results file of version {} (format {:?}, version {})",
                        batch::FORMAT_VERSION,
                        h.format,
                        h.version
                    ));
                }
                if h.problems != self.descs {
                    return Err(format!("--tell {file}: results of another problem or other settings than this state's"));
                }
                if h.batch != state.batch {
                    return Err(format!(
                        "--tell {file}: results of batch {}, the state asked batch {}",
                        h.batch, state.batch
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
            let (_, lines): (ResultsHeader, Vec<(usize, PointResult)>) =
                batch::read_jsonl("--tell", path, asked.points.len(), &check)?;
            for (line, r) in lines {
                let Some(&i) = index.get(r.id.as_str()) else {
                    return Err(format!(
                        "--tell {file}:{line}: id {:?} was not asked in batch {}",
                        r.id, state.batch
                    ));
                };
                let nc = self.problems[asked.points[i].problem].constraints().len();
                if r.constraints.len() != nc {
                    return Err(format!(
                        "--tell {file}:{line}: id {:?}: {} constraint values, the problem has {nc}",
                        r.id,
                        r.constraints.len()
                    ));
                }
                if let Some((_, first)) = &found[i] {
                    return Err(format!(
                        "--tell {file}:{line}: id {:?} already came in {first}",
                        r.id
                    ));
                }
                found[i] = Some((r.evaluation(), format!("{file}:{line}")));
            }
        }
        let missing: Vec<&str> = asked
            .points
            .iter()
            .zip(&found)
            .filter(|(_, f)| f.is_none())
            .map(|(p, _)| p.id.as_str())
            .collect();
        if let Some(first) = missing.first() {
            return Err(format!(
                "--tell: {} of the {} asked points of batch {} have no result (first: {first}); give every shard's results file",
                missing.len(),
                asked.points.len(),
                state.batch
            ));
        }
        Ok(found.into_iter().flatten().map(|(e, _)| e).collect())
    }

    fn tell(&self, drivers: &[AfsAskTell], mut state: AskTellState, sha: &str) -> CmdResult {
        let asked = self.asked(drivers, &state)?.ok_or_else(|| {
            format!(
                "--state {}: the run has finished; --ask prints its report",
                self.state_path.display()
            )
        })?;
        let mut evals = self.results(&state, sha, &asked)?.into_iter();
        for ((d, run), n) in drivers
            .iter()
            .zip(state.runs.iter_mut())
            .zip(&asked.per_run)
        {
            let mine: Vec<Evaluation> = evals.by_ref().take(*n).collect();
            if *n > 0 {
                d.tell(run, mine)?;
            }
        }
        state.batch += 1;
        super::write_json(self.state_path, &state)?;
        let finished = self.asked(drivers, &state)?.is_none();
        let status = json!({"told": state.batch - 1, "points": asked.points.len(), "next_batch": state.batch, "finished": finished});
        if self.args.json || !std::io::stdout().is_terminal() {
            afsv::output::print_json(&status)?;
        } else {
            println!(
                "batch {} told ({} points); {}",
                state.batch - 1,
                asked.points.len(),
                if finished {
                    "the run has finished: --ask prints the report"
                } else {
                    "next: --ask"
                }
            );
        }
        Ok(())
    }
}
