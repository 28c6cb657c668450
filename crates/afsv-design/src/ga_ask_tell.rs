//! One `--ask` or `--tell` of a genetic-algorithm run split into ask and tell
//! ([`crate::hps_ask_tell`], [`crate::layout_ask_tell`]), against its state file: the step
//! both drivers take the same way, written once over the [`GaAskTell`] trait.
//!
//! - `--ask`: the state's next batch is written (header identified by the state's SHA-256,
//!   then one point a line; no point once the run has finished), and a new state's file
//!   with it; [`GaStep::Asked`] or [`GaStep::Finished`] says which.
//! - `--tell`: the results files of the state's batch are read and checked, the run
//!   advanced by them and the state rewritten ([`GaStep::Told`]); a finished run has
//!   nothing to tell and is refused.
//!
//! Every error keeps the message of the step that failed ([`AskTellError`]).

use crate::error::DesignError;
use afsv_records::jsonl::write_jsonl;
use afsv_records::stored::{write_json, StateIdentity};
use serde::Serialize;
use std::path::{Path, PathBuf};

/// Why an ask or a tell failed: the driver refused the state or the results
/// ([`DesignError`]), or a file could not be read, checked or written (its message).
/// Either way the message is the failing step's own.
#[derive(Debug, thiserror::Error)]
pub enum AskTellError {
    /// The driver refused.
    #[error(transparent)]
    Design(#[from] DesignError),
    /// A state, batch or results file could not be read, checked or written.
    #[error("{0}")]
    Files(String),
}

impl From<String> for AskTellError {
    fn from(message: String) -> Self {
        AskTellError::Files(message)
    }
}

/// A genetic-algorithm ask/tell driver with its state file: what [`ask_or_tell`] needs.
pub trait GaAskTell {
    /// The state file (its run and the number of the next batch).
    type State: Serialize;
    /// First line of a batch file.
    type Header: Serialize;
    /// One point line of a batch file.
    type Point: Serialize;

    /// The number of `state`'s next batch (batches told so far).
    fn batch(state: &Self::State) -> usize;

    /// The file of `state`'s next batch, its header identified by the state's SHA-256
    /// `sha`: the header, the points and the phase (`None` once the run has finished: then
    /// no point).
    #[allow(clippy::type_complexity)]
    fn batch_file(
        &self,
        state: &Self::State,
        sha: &str,
    ) -> Result<(Self::Header, Vec<Self::Point>, Option<String>), DesignError>;

    /// Reads the results files `tell` of `state`'s batch (checked against `sha`), advances
    /// the run by them and counts the batch as told; the number of points told, `None`
    /// (and `state` unchanged) when the run has finished.
    fn tell_results(
        &self,
        state: &mut Self::State,
        tell: &[PathBuf],
        sha: &str,
    ) -> Result<Option<usize>, AskTellError>;

    /// Whether `state`'s run has finished.
    fn finished(&self, state: &Self::State) -> Result<bool, DesignError>;
}

/// What one [`ask_or_tell`] did.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum GaStep {
    /// `--ask` wrote batch `batch` of `points` points in phase `phase`.
    Asked {
        /// The batch's number.
        batch: usize,
        /// Its phase.
        phase: String,
        /// Its points.
        points: usize,
    },
    /// `--ask` found the run finished after `batches` batches and wrote a batch of no
    /// point: the driver's `finish` gives the result.
    Finished {
        /// Batches told.
        batches: usize,
    },
    /// `--tell` told batch `batch` of `points` points; `finished`: nothing is left to ask.
    Told {
        /// The batch told.
        batch: usize,
        /// Its points.
        points: usize,
        /// Whether the run has finished.
        finished: bool,
    },
}

/// One `--ask` (`ask`: the batch file to write) or `--tell` (`tell`: the results files)
/// against the state file `path`, whose text as read under the run lock is `stored`
/// (`None`: a new state, written by its first `--ask`) and whose content is `state`.
pub fn ask_or_tell<D: GaAskTell>(
    driver: &D,
    state: &mut D::State,
    stored: Option<String>,
    path: &Path,
    ask: Option<&Path>,
    tell: &[PathBuf],
) -> Result<GaStep, AskTellError> {
    let id = StateIdentity::of(stored, state)?;
    if let Some(batch_path) = ask {
        let (header, points, phase) = driver.batch_file(state, &id.sha)?;
        write_jsonl(batch_path, &header, &points)?;
        id.write_if_new(path)?;
        let batch = D::batch(state);
        return Ok(match phase {
            None => GaStep::Finished { batches: batch },
            Some(phase) => GaStep::Asked {
                batch,
                phase,
                points: points.len(),
            },
        });
    }
    let Some(points) = driver.tell_results(state, tell, &id.sha)? else {
        return Err(AskTellError::Files(format!(
            "--state {}: the run has finished; --ask prints its report",
            path.display()
        )));
    };
    write_json(path, state)?;
    Ok(GaStep::Told {
        batch: D::batch(state) - 1,
        points,
        finished: driver.finished(state)?,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::layout_ask_tell::{
        evaluate_layout_shard, read_layout_batch, LayoutAskTellState, LayoutResultsHeader,
    };
    use crate::layout_optimum::tests::tiny;
    use crate::{optimise_layout, LayoutAskTell, LayoutGaSettings, LayoutProblem};
    use optimize::Silent;

    /// A fresh directory for one test's files.
    fn dir(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("afsv-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    /// The state file's text and content, read as the CLI reads it.
    fn read(
        path: &Path,
        create: bool,
        problem: &LayoutProblem,
        ga: &LayoutGaSettings,
    ) -> Result<(Option<String>, LayoutAskTellState), String> {
        let stored = std::fs::read_to_string(path).ok();
        let st = LayoutAskTellState::read(
            "--state",
            path,
            stored.as_deref(),
            create,
            problem.desc(),
            ga,
        )?;
        Ok((stored, st))
    }

    /// Asked and told through the files, in two shards, the run reaches the in-process
    /// optimum; telling a finished run, or a tell before any ask, is refused by name.
    #[test]
    fn asking_and_telling_through_files_equals_the_in_process_run() {
        let d = dir("ga-ask-tell");
        let problem = tiny().problem().unwrap();
        let ga = LayoutGaSettings {
            population: 4,
            generations: 1,
            seed: 5,
        };
        let driver = LayoutAskTell::new(&problem, ga).unwrap();
        let state = d.join("state.json");
        let batch = d.join("batch.jsonl");
        let e = read(&state, false, &problem, &ga).unwrap_err();
        assert!(
            e.contains("does not exist; start the run with --ask"),
            "{e}"
        );
        let mut phases = Vec::new();
        let batches = loop {
            let (stored, mut st) = read(&state, true, &problem, &ga).unwrap();
            let step = ask_or_tell(&driver, &mut st, stored, &state, Some(&batch), &[]).unwrap();
            let (number, phase) = match step {
                GaStep::Asked { batch, phase, .. } => (batch, phase),
                GaStep::Finished { batches } => break batches,
                GaStep::Told { .. } => panic!("an ask told"),
            };
            phases.push(phase);
            let (header, points) = read_layout_batch("--ask", &batch).unwrap();
            let mut results = Vec::new();
            for i in 1..=2 {
                let r = evaluate_layout_shard("b", &header, &points, (i, 2), &|| {}).unwrap();
                let file = d.join(format!("r{i}.jsonl"));
                let h = LayoutResultsHeader::of_shard(&header, (i, 2), r.len());
                write_jsonl(&file, &h, &r).unwrap();
                results.push(file);
            }
            let (stored, mut st) = read(&state, false, &problem, &ga).unwrap();
            let told = ask_or_tell(&driver, &mut st, stored, &state, None, &results).unwrap();
            assert!(
                matches!(told, GaStep::Told { batch, points: p, .. } if batch == number && p == points.len()),
                "{told:?}"
            );
        };
        assert_eq!(phases, ["nominal", "initial", "generation 1"]);
        assert_eq!(batches, 3);
        let (stored, mut st) = read(&state, false, &problem, &ga).unwrap();
        let e = ask_or_tell(&driver, &mut st, stored, &state, None, &[]).unwrap_err();
        assert!(e
            .to_string()
            .ends_with("the run has finished; --ask prints its report"));
        let ours = driver.finish(&st.run).unwrap();
        assert_eq!(ours, optimise_layout(&problem, &ga, &Silent).unwrap());
        let _ = std::fs::remove_dir_all(&d);
    }
}
