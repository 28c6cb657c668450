//! The layout optimisation of [`crate::layout_optimum`] split into ask (the next batch of
//! designs) and tell (advance by their measures), so that its runs go anywhere: other
//! processes, a cluster's array tasks (`afsv optimize layout --state --ask/--tell`, `afsv
//! batch evaluate --shard I/N`; docs/optimisation.md "Running on a cluster").
//!
//! A run asks, in order: the un-varied layout (batch 0, one point: the nominal measures
//! that `F * nominal` constraints resolve against), the GA's initial population
//! ([`optimize::ga::GeneticAlgorithm::initial`]), then each generation's children. A shard
//! returns the raw measures of its points; tell scores them against the stored nominal
//! measures ([`LayoutProblem::evaluation`]) and advances the GA exactly as the in-process
//! [`crate::optimise_layout`] does, so both reach the same optimum bit for bit (the JSON
//! numbers round-trip exactly).
//!
//! The files: a batch (header [`LayoutBatchHeader`], one [`LayoutBatchPoint`] a line), a
//! results file (header [`LayoutResultsHeader`], one [`LayoutPointResult`] a line) and the
//! state ([`LayoutAskTellState`]). Every header carries the whole problem, so a shard needs
//! nothing but its batch file; a tell takes results only for its own state's batch (the
//! state's SHA-256 and batch number).

use crate::afs_batch::{in_shard, point_id};
use crate::batch_files::{
    check_results_header, collect_results, read_batch_file, BatchHeaderFields, BatchKind, PointId,
};
use crate::error::DesignError;
use crate::layout_optimum::{
    result, LayoutGaSettings, LayoutOptimum, LayoutProblem, LayoutProblemDesc, Measured, Scored,
};
use optimize::ga::{GaOptions, GaState, GeneticAlgorithm};
use optimize::{Evaluation, OptimizeError};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Version of the layout batch, results and state formats.
pub const LAYOUT_FORMAT_VERSION: u32 = 1;
/// `format` of a layout batch file's header.
pub const LAYOUT_BATCH_FORMAT: &str = "afsv-layout-batch";
/// `format` of a layout results file's header.
pub const LAYOUT_RESULTS_FORMAT: &str = "afsv-layout-results";
/// `format` of the layout ask/tell state file.
pub const LAYOUT_STATE_FORMAT: &str = "afsv-layout-state";

/// Where a layout run stands: the nominal measures once told, then the GA's state.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LayoutRunState {
    /// The un-varied layout's measures (batch 0).
    pub nominal: Option<Measured>,
    /// The GA after its initial population and each generation told.
    pub ga: Option<GaState>,
}

/// The phase of a batch.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LayoutPhase {
    /// The un-varied layout (one point).
    Nominal,
    /// The GA's initial population.
    Initial,
    /// The children of generation `n` (1-based).
    Generation(usize),
}

impl LayoutPhase {
    /// `nominal`, `initial` or `generation N`.
    pub fn name(self) -> String {
        match self {
            LayoutPhase::Nominal => "nominal".into(),
            LayoutPhase::Initial => "initial".into(),
            LayoutPhase::Generation(n) => format!("generation {n}"),
        }
    }
}

/// The next batch of a run: designs in the variables' order (`None`: the un-varied layout).
#[derive(Debug, Clone, PartialEq)]
pub struct LayoutBatch {
    /// Its phase.
    pub phase: LayoutPhase,
    /// The points.
    pub points: Vec<Option<Vec<f64>>>,
}

/// What [`LayoutAskTell::ask`] found.
#[derive(Debug, Clone, PartialEq)]
pub enum LayoutAsk {
    /// Measure these points and tell their measures.
    Evaluate(LayoutBatch),
    /// The GA has run its generations; [`LayoutAskTell::finish`] gives the result.
    Finished,
}

/// The ask/tell driver of one problem with fixed GA settings.
pub struct LayoutAskTell<'a> {
    problem: &'a LayoutProblem,
    settings: LayoutGaSettings,
    options: GaOptions,
}

fn opt(e: OptimizeError) -> DesignError {
    DesignError::Shape {
        field: "ga",
        reason: e.to_string(),
    }
}

impl<'a> LayoutAskTell<'a> {
    /// The driver of `problem` with `settings` (checked).
    pub fn new(
        problem: &'a LayoutProblem,
        settings: LayoutGaSettings,
    ) -> Result<Self, DesignError> {
        Ok(Self {
            problem,
            options: settings.options()?,
            settings,
        })
    }

    fn ga<'s>(
        &self,
        scored: &'s Scored<'s>,
    ) -> Result<GeneticAlgorithm<'s, Scored<'s>>, DesignError> {
        GeneticAlgorithm::new(scored, self.options).map_err(opt)
    }

    /// The next batch of `run` (a pure function of the state), or [`LayoutAsk::Finished`].
    pub fn ask(&self, run: &LayoutRunState) -> Result<LayoutAsk, DesignError> {
        let Some(nominal) = &run.nominal else {
            return Ok(LayoutAsk::Evaluate(LayoutBatch {
                phase: LayoutPhase::Nominal,
                points: vec![None],
            }));
        };
        let scored = Scored {
            problem: self.problem,
            nominal,
        };
        let ga = self.ga(&scored)?;
        let b = self.problem.variable_bounds();
        let (phase, units) = match &run.ga {
            None => (
                LayoutPhase::Initial,
                ga.initial(&[self.problem.nominal_x()]).map_err(opt)?,
            ),
            Some(st) => {
                ga.check_state(st).map_err(opt)?;
                if st.generation >= self.options.generations {
                    return Ok(LayoutAsk::Finished);
                }
                (LayoutPhase::Generation(st.generation + 1), ga.ask(st))
            }
        };
        Ok(LayoutAsk::Evaluate(LayoutBatch {
            phase,
            points: units.iter().map(|u| Some(b.from_unit(u))).collect(),
        }))
    }

    /// Advances `run` by the measures of the batch [`LayoutAskTell::ask`] gives for it, in
    /// its order (an `Err` is a design whose runs failed: it scores as failed; the nominal
    /// layout must not fail). A wrong count leaves `run` unchanged.
    pub fn tell(
        &self,
        run: &mut LayoutRunState,
        measures: Vec<Result<Measured, String>>,
    ) -> Result<(), DesignError> {
        let asked = match self.ask(run)? {
            LayoutAsk::Evaluate(b) => b,
            LayoutAsk::Finished => {
                return Err(DesignError::Shape {
                    field: "measures",
                    reason: "the run has finished; nothing was asked".into(),
                })
            }
        };
        if measures.len() != asked.points.len() {
            return Err(DesignError::Shape {
                field: "measures",
                reason: format!(
                    "expected {} designs' measures, got {}",
                    asked.points.len(),
                    measures.len()
                ),
            });
        }
        let Some(nominal) = &run.nominal else {
            let m = measures.into_iter().next().expect("one point asked");
            let m = m.map_err(|e| DesignError::Simulation(format!("the nominal layout: {e}")))?;
            if let Some(missing) = self
                .problem
                .needed()
                .into_iter()
                .find(|k| !m.contains_key(k))
            {
                return Err(DesignError::Shape {
                    field: "measures",
                    reason: format!("the nominal layout's results lack {}", missing.name()),
                });
            }
            run.nominal = Some(m);
            return Ok(());
        };
        let scored = Scored {
            problem: self.problem,
            nominal,
        };
        let evals: Vec<Evaluation> = measures
            .iter()
            .map(|m| match m {
                Ok(m) => self.problem.evaluation(m, nominal),
                Err(_) => Evaluation::failed(self.problem.desc().constraints.len()),
            })
            .collect();
        let ga = self.ga(&scored)?;
        let next = match &run.ga {
            None => {
                let units = ga.initial(&[self.problem.nominal_x()]).map_err(opt)?;
                ga.start_told(units, evals).map_err(opt)?
            }
            Some(st) => {
                let mut st = st.clone();
                ga.tell(&mut st, evals).map_err(opt)?;
                st
            }
        };
        run.ga = Some(next);
        Ok(())
    }

    /// The result of a finished run (the optimum measured once more, as in-process).
    pub fn finish(&self, run: &LayoutRunState) -> Result<LayoutOptimum, DesignError> {
        let (Some(nominal), Some(st), LayoutAsk::Finished) =
            (&run.nominal, &run.ga, self.ask(run)?)
        else {
            return Err(DesignError::Shape {
                field: "state",
                reason: "the run has not finished; ask for the next batch".into(),
            });
        };
        let best = st.best();
        result(
            self.problem,
            &self.settings,
            nominal,
            &best.u,
            &best.x,
            st.evaluations,
        )
    }
}

/// First line of a layout batch file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LayoutBatchHeader {
    /// [`LAYOUT_BATCH_FORMAT`].
    pub format: String,
    /// [`LAYOUT_FORMAT_VERSION`].
    pub version: u32,
    /// `afsv optimize layout --ask`.
    pub written_by: String,
    /// `afsv-v1`.
    pub sign_convention: String,
    /// Number of the batch (batches told before it).
    pub batch: usize,
    /// SHA-256 (hex) of the state file's content when it asked this batch.
    pub state_sha256: String,
    /// Whether the run has finished (then the batch holds no point).
    pub finished: bool,
    /// The phase (`nominal`, `initial`, `generation N`; empty when finished).
    pub phase: String,
    /// Number of point lines that follow.
    pub points: usize,
    /// The problem, whole.
    pub problem: LayoutProblemDesc,
}

/// One design of a layout batch.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LayoutBatchPoint {
    /// Identifier, `b<batch>-<index>`.
    pub id: String,
    /// The un-varied layout (then `x` is empty).
    pub nominal: bool,
    /// The variables by name (SI).
    pub x: BTreeMap<String, f64>,
}

/// First line of a layout results file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LayoutResultsHeader {
    /// [`LAYOUT_RESULTS_FORMAT`].
    pub format: String,
    /// [`LAYOUT_FORMAT_VERSION`].
    pub version: u32,
    /// `afsv batch evaluate`.
    pub written_by: String,
    /// `afsv-v1`.
    pub sign_convention: String,
    /// The batch's number.
    pub batch: usize,
    /// The batch's state SHA-256, carried over.
    pub state_sha256: String,
    /// The shard, "I/N".
    pub shard: String,
    /// Number of result lines that follow.
    pub points: usize,
    /// The batch's problem.
    pub problem: LayoutProblemDesc,
}

impl LayoutResultsHeader {
    /// The header of the results of the shard `shard` (I, N) of the batch `header`, with
    /// `points` result lines, written by `afsv batch evaluate`.
    pub fn of_shard(header: &LayoutBatchHeader, shard: (usize, usize), points: usize) -> Self {
        Self {
            format: LAYOUT_RESULTS_FORMAT.into(),
            version: LAYOUT_FORMAT_VERSION,
            written_by: "afsv batch evaluate".into(),
            sign_convention: afsv_records::SIGN_CONVENTION.into(),
            batch: header.batch,
            state_sha256: header.state_sha256.clone(),
            shard: format!("{}/{}", shard.0, shard.1),
            points,
            problem: header.problem.clone(),
        }
    }
}

/// One measured design of a layout results file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LayoutPointResult {
    /// The point's id.
    pub id: String,
    /// `evaluated` or `failed`.
    pub status: String,
    /// The needed measures (means over the seeds); empty when failed.
    pub measures: Measured,
    /// Why the design failed.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub reason: Option<String>,
}

impl LayoutPointResult {
    /// The measures, or why the design failed.
    pub fn outcome(&self) -> Result<Measured, String> {
        match self.status.as_str() {
            "evaluated" => Ok(self.measures.clone()),
            _ => Err(self
                .reason
                .clone()
                .unwrap_or_else(|| "the design failed".into())),
        }
    }
}

/// The points of `batch` number `number` in file form.
pub fn batch_points(
    desc: &LayoutProblemDesc,
    number: usize,
    batch: &LayoutBatch,
) -> Vec<LayoutBatchPoint> {
    batch
        .points
        .iter()
        .enumerate()
        .map(|(i, p)| LayoutBatchPoint {
            id: point_id(number, i),
            nominal: p.is_none(),
            x: p.iter()
                .flat_map(|x| desc.variables.iter().zip(x))
                .map(|(v, x)| (v.name.clone(), *x))
                .collect(),
        })
        .collect()
}

/// What an `--ask` of batch `number` writes for `asked`: the header, identified by the
/// asking state's SHA-256 `state_sha256`, and the points (none once the run has finished,
/// with the header's `finished` set).
pub fn batch_file(
    desc: &LayoutProblemDesc,
    number: usize,
    state_sha256: &str,
    asked: &LayoutAsk,
) -> (LayoutBatchHeader, Vec<LayoutBatchPoint>) {
    let (phase, points) = match asked {
        LayoutAsk::Evaluate(b) => (b.phase.name(), batch_points(desc, number, b)),
        LayoutAsk::Finished => (String::new(), Vec::new()),
    };
    let header = LayoutBatchHeader {
        format: LAYOUT_BATCH_FORMAT.into(),
        version: LAYOUT_FORMAT_VERSION,
        written_by: "afsv optimize layout --ask".into(),
        sign_convention: afsv_records::SIGN_CONVENTION.into(),
        batch: number,
        state_sha256: state_sha256.into(),
        finished: *asked == LayoutAsk::Finished,
        phase,
        points: points.len(),
        problem: desc.clone(),
    };
    (header, points)
}

/// The design of a batch point in the variables' order (`None`: the nominal layout).
pub fn point_design(
    desc: &LayoutProblemDesc,
    p: &LayoutBatchPoint,
) -> Result<Option<Vec<f64>>, String> {
    if p.nominal {
        return if p.x.is_empty() {
            Ok(None)
        } else {
            Err(format!(
                "point {}: the nominal point carries no variables",
                p.id
            ))
        };
    }
    if p.x.len() != desc.variables.len() {
        return Err(format!(
            "point {}: {} variables, the problem has {}",
            p.id,
            p.x.len(),
            desc.variables.len()
        ));
    }
    desc.variables
        .iter()
        .map(|v| {
            p.x.get(&v.name)
                .copied()
                .ok_or_else(|| format!("point {}: no variable {}", p.id, v.name))
        })
        .collect::<Result<Vec<f64>, String>>()
        .map(Some)
}

/// Reads and checks a layout batch file: format, version, SHA-256, point count and ids.
pub fn read_layout_batch(
    label: &str,
    path: &Path,
) -> Result<(LayoutBatchHeader, Vec<LayoutBatchPoint>), String> {
    let kind = BatchKind {
        what: "layout batch file",
        format: LAYOUT_BATCH_FORMAT,
        version: LAYOUT_FORMAT_VERSION,
    };
    let (h, lines) = read_batch_file(label, path, &kind, &|_: &LayoutBatchHeader| Ok(()))?;
    Ok((h, lines.into_iter().map(|(_, p)| p).collect()))
}

impl BatchHeaderFields for LayoutBatchHeader {
    fn format(&self) -> &str {
        &self.format
    }
    fn version(&self) -> u32 {
        self.version
    }
    fn state_sha256(&self) -> &str {
        &self.state_sha256
    }
    fn batch(&self) -> usize {
        self.batch
    }
    fn points(&self) -> usize {
        self.points
    }
}

impl PointId for LayoutBatchPoint {
    fn id(&self) -> &str {
        &self.id
    }
}

impl PointId for LayoutPointResult {
    fn id(&self) -> &str {
        &self.id
    }
}

/// Measures the points of shard `shard` of a layout batch in parallel, in the batch's
/// order; `step` is called after each point. `label` names the batch file in errors.
pub fn evaluate_layout_shard(
    label: &str,
    header: &LayoutBatchHeader,
    points: &[LayoutBatchPoint],
    shard: (usize, usize),
    step: &(dyn Fn() + Sync),
) -> Result<Vec<LayoutPointResult>, String> {
    let mine: Vec<&LayoutBatchPoint> = points
        .iter()
        .enumerate()
        .filter(|(i, _)| in_shard(*i, shard))
        .map(|(_, p)| p)
        .collect();
    let designs: Vec<Option<Vec<f64>>> = mine
        .iter()
        .map(|p| point_design(&header.problem, p))
        .collect::<Result<_, _>>()
        .map_err(|e| format!("{label}: {e}"))?;
    let problem = header
        .problem
        .problem()
        .map_err(|e| format!("{label}: the problem: {e}"))?;
    Ok(mine
        .par_iter()
        .zip(designs.par_iter())
        .map(|(p, x)| {
            let out = problem.measure(x.as_deref());
            step();
            match out {
                Ok(measures) => LayoutPointResult {
                    id: p.id.clone(),
                    status: "evaluated".into(),
                    measures,
                    reason: None,
                },
                Err(e) => LayoutPointResult {
                    id: p.id.clone(),
                    status: "failed".into(),
                    measures: Measured::new(),
                    reason: Some(e),
                },
            }
        })
        .collect())
}

impl crate::ga_ask_tell::GaAskTell for LayoutAskTell<'_> {
    type State = LayoutAskTellState;
    type Header = LayoutBatchHeader;
    type Point = LayoutBatchPoint;

    fn batch(state: &LayoutAskTellState) -> usize {
        state.batch
    }

    fn batch_file(
        &self,
        state: &LayoutAskTellState,
        sha: &str,
    ) -> Result<(LayoutBatchHeader, Vec<LayoutBatchPoint>, Option<String>), DesignError> {
        let asked = self.ask(&state.run)?;
        let (header, points) = batch_file(self.problem.desc(), state.batch, sha, &asked);
        let phase = (asked != LayoutAsk::Finished).then(|| header.phase.clone());
        Ok((header, points, phase))
    }

    fn tell_results(
        &self,
        state: &mut LayoutAskTellState,
        tell: &[PathBuf],
        sha: &str,
    ) -> Result<Option<usize>, crate::ga_ask_tell::AskTellError> {
        let LayoutAsk::Evaluate(b) = self.ask(&state.run)? else {
            return Ok(None);
        };
        let points = batch_points(self.problem.desc(), state.batch, &b);
        let results = state.results(tell, sha, &points)?;
        self.tell(&mut state.run, results)?;
        state.batch += 1;
        Ok(Some(points.len()))
    }

    fn finished(&self, state: &LayoutAskTellState) -> Result<bool, DesignError> {
        Ok(self.ask(&state.run)? == LayoutAsk::Finished)
    }
}

/// The layout ask/tell state file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LayoutAskTellState {
    /// The command that wrote it.
    pub written_by: String,
    /// `afsv-v1`.
    pub sign_convention: String,
    /// [`LAYOUT_STATE_FORMAT`].
    pub format: String,
    /// [`LAYOUT_FORMAT_VERSION`].
    pub version: u32,
    /// The problem the state belongs to.
    pub problem: LayoutProblemDesc,
    /// The GA settings it belongs to.
    pub ga: LayoutGaSettings,
    /// Batches told so far: the number of the next batch.
    pub batch: usize,
    /// The run.
    pub run: LayoutRunState,
}

impl LayoutAskTellState {
    /// The state `flag` `path` holds in `stored` (read under the run lock), which must
    /// belong to `problem` and `ga`; a new state when there is none and `create` allows one.
    pub fn read(
        flag: &str,
        path: &Path,
        stored: Option<&str>,
        create: bool,
        problem: &LayoutProblemDesc,
        ga: &LayoutGaSettings,
    ) -> Result<Self, String> {
        match stored {
            Some(text) => {
                let st: LayoutAskTellState = afsv_records::stored::parse_stored(flag, path, text)?;
                if st.format != LAYOUT_STATE_FORMAT || st.version != LAYOUT_FORMAT_VERSION {
                    return Err(format!(
                        "{flag} {}: not a layout ask/tell state of version {LAYOUT_FORMAT_VERSION}",
                        path.display()
                    ));
                }
                let json = |p: &LayoutProblemDesc, g: &LayoutGaSettings| serde_json::json!({"problem": p, "ga": g});
                afsv_records::stored::same_settings(
                    flag,
                    path,
                    &json(&st.problem, &st.ga),
                    &json(problem, ga),
                )?;
                Ok(st)
            }
            None if !create => Err(format!(
                "{flag} {}: does not exist; start the run with --ask",
                path.display()
            )),
            None => Ok(Self {
                written_by: "afsv optimize layout".into(),
                sign_convention: afsv_records::SIGN_CONVENTION.into(),
                format: LAYOUT_STATE_FORMAT.into(),
                version: LAYOUT_FORMAT_VERSION,
                problem: problem.clone(),
                ga: *ga,
                batch: 0,
                run: LayoutRunState::default(),
            }),
        }
    }

    /// Reads every results file (`--tell`) and returns the outcomes in the batch's order,
    /// checking that every asked id comes exactly once, no other id comes, and every file
    /// belongs to this state's batch (`sha`: the state's SHA-256) and problem.
    pub fn results(
        &self,
        tell: &[PathBuf],
        sha: &str,
        asked: &[LayoutBatchPoint],
    ) -> Result<Vec<Result<Measured, String>>, String> {
        let kind = BatchKind {
            what: "a layout results file",
            format: LAYOUT_RESULTS_FORMAT,
            version: LAYOUT_FORMAT_VERSION,
        };
        let check = |h: &LayoutResultsHeader, file: &str| {
            check_results_header(
                file,
                &kind,
                (&h.format, h.version),
                h.problem == self.problem,
                (h.batch, &h.state_sha256),
                (self.batch, sha),
            )
        };
        let ids: Vec<&str> = asked.iter().map(|p| p.id.as_str()).collect();
        collect_results(
            tell,
            self.batch,
            &ids,
            &check,
            &|r: &LayoutPointResult, _| Ok(r.outcome()),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::layout_optimum::tests::tiny;
    use crate::optimise_layout;
    use optimize::Silent;
    use std::collections::HashMap;

    /// In-process and ask/tell through the files' JSON give the same optimum, bit for bit.
    #[test]
    fn ask_tell_through_json_equals_the_in_process_run() {
        let problem = tiny().problem().unwrap();
        let ga = LayoutGaSettings {
            population: 4,
            generations: 2,
            seed: 7,
        };
        let theirs = optimise_layout(&problem, &ga, &Silent).unwrap();
        let driver = LayoutAskTell::new(&problem, ga).unwrap();
        let mut run = LayoutRunState::default();
        let mut phases = Vec::new();
        let mut number = 0;
        let sha = "0".repeat(64);
        loop {
            let asked = driver.ask(&run).unwrap();
            let LayoutAsk::Evaluate(b) = &asked else {
                break;
            };
            phases.push(b.phase);
            let (header, points) = batch_file(problem.desc(), number, &sha, &asked);
            assert_eq!(points, batch_points(problem.desc(), number, b));
            assert!(!header.finished && header.points == points.len() && header.batch == number);
            // through the files' text, two shards
            let header = through(&header);
            let points: Vec<LayoutBatchPoint> = points.iter().map(through).collect();
            let mut results: Vec<LayoutPointResult> = Vec::new();
            for i in 1..=2 {
                for r in evaluate_layout_shard("b", &header, &points, (i, 2), &|| {}).unwrap() {
                    results.push(through(&r));
                }
            }
            let by_id: HashMap<String, LayoutPointResult> =
                results.into_iter().map(|r| (r.id.clone(), r)).collect();
            let ordered: Vec<Result<Measured, String>> =
                points.iter().map(|p| by_id[&p.id].outcome()).collect();
            let before = run.clone();
            let short = ordered[..ordered.len() - 1].to_vec();
            assert!(driver.tell(&mut run, short).is_err());
            assert_eq!(run, before, "a refused tell leaves the state");
            driver.tell(&mut run, ordered).unwrap();
            number += 1;
        }
        assert_eq!(
            phases,
            vec![
                LayoutPhase::Nominal,
                LayoutPhase::Initial,
                LayoutPhase::Generation(1),
                LayoutPhase::Generation(2)
            ]
        );
        let (done, none) = batch_file(problem.desc(), number, &sha, &LayoutAsk::Finished);
        assert!(done.finished && done.points == 0 && none.is_empty() && done.phase.is_empty());
        let ours = driver.finish(&run).unwrap();
        assert_eq!(ours, theirs);
        assert_eq!(ours.evaluations, 4 * 3);
        // the optimum is no worse than the nominal design, which seeds the population
        let obj = |m: &Measured| m[&ours.objective];
        assert!(ours.feasible && obj(&ours.optimum) <= obj(&ours.nominal));
    }

    /// `v` written as a file line and read back.
    fn through<T: Serialize + serde::de::DeserializeOwned>(v: &T) -> T {
        serde_json::from_str(&serde_json::to_string(v).unwrap()).unwrap()
    }
}
