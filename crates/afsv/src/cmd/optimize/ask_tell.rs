//! The ask/tell driver of `afsv optimize afs --state`: the state file, `--ask` (the next
//! batch, or the report once the run is done) and `--tell` (the results of every shard).

use super::{report, AfsArgs};
use crate::cmd::CmdResult;
use afsv_design::afs_batch::{BatchHeader, ProblemDesc};
use afsv_design::afs_state::AskTellState;
use afsv_design::report::afs::asked_text;
use afsv_design::{AfsAskTell, AfsOptimisationSettings, AfsProblem, Objective};
use afsv_records::jsonl::write_jsonl;
use afsv_records::stored::write_json;
use serde_json::{json, Value};
use std::path::Path;

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

impl AskTell<'_> {
    pub(super) fn run(&self) -> CmdResult {
        let drivers: Vec<AfsAskTell> = self
            .problems
            .iter()
            .map(|p| AfsAskTell::new(p, self.settings))
            .collect::<Result<_, _>>()?;
        let state = AskTellState::read(
            "--state",
            self.state_path,
            self.stored.as_deref(),
            self.args.ask_tell.ask.is_some(),
            &self.settings,
            &self.settings_json,
            self.problems,
        )?;
        let id = afsv_records::stored::StateIdentity::of(self.stored.clone(), &state)?;
        match &self.args.ask_tell.ask {
            Some(path) => self.ask(&drivers, &state, &id, path),
            None => self.tell(&drivers, state, &id.sha),
        }
    }

    /// Writes the next batch (identified by `id`, the state's SHA-256, and its number),
    /// and a new state's file; once finished, the report.
    fn ask(
        &self,
        drivers: &[AfsAskTell],
        state: &AskTellState,
        id: &afsv_records::stored::StateIdentity,
        path: &Path,
    ) -> CmdResult {
        let asked = state.asked(drivers, &self.descs)?;
        let points = asked.as_ref().map_or(&[][..], |a| &a.points[..]);
        let header = BatchHeader::asked(
            state.batch,
            &id.sha,
            asked.is_none(),
            points.len(),
            &self.descs,
        );
        write_jsonl(path, &header, points)?;
        id.write_if_new(self.state_path)?;
        let Some(asked) = asked else {
            super::finished_notice("afs", state.batch, path);
            let outcomes = state.finish(drivers, &self.descs)?;
            return report(self.args, &self.objective, self.problems, &outcomes);
        };
        let status = json!({
            "batch": state.batch, "finished": false, "points": asked.points.len(),
            "batch_file": path.display().to_string(), "phases": asked.phases,
        });
        afsv::output::print_json_or_text(self.args.output.json, &status, || {
            asked_text(state.batch, &asked, path) + "\n"
        })?;
        Ok(())
    }

    fn tell(&self, drivers: &[AfsAskTell], mut state: AskTellState, sha: &str) -> CmdResult {
        let asked = state.asked(drivers, &self.descs)?.ok_or_else(|| {
            format!(
                "--state {}: the run has finished; --ask prints its report",
                self.state_path.display()
            )
        })?;
        let evals = state.results(
            &self.args.ask_tell.tell,
            sha,
            &asked,
            &self.descs,
            self.problems,
        )?;
        state.tell(drivers, &asked, evals)?;
        write_json(self.state_path, &state)?;
        let finished = state.asked(drivers, &self.descs)?.is_none();
        super::print_told(
            self.args.output.json,
            state.batch - 1,
            asked.points.len(),
            "points",
            finished,
        )
    }
}
