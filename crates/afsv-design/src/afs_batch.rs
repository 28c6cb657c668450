//! The ask/tell optimisation of chapter 4 (`afs_ask_tell`) across processes: what a
//! shard needs to rebuild a problem ([`ProblemDesc`]), the JSON Lines formats of the batch
//! and results files (docs/optimisation.md, "Running on a cluster") and the evaluation of
//! one shard of a batch ([`evaluate_shard`]).
//!
//! A batch file is a header line and one line per point; a results file a header line and
//! one line per evaluated point. Shard `I/N` evaluates the points whose 0-based index in
//! the batch is `I - 1` modulo `N` (round robin, so every shard gets a share of each
//! phase). Every header carries the problem descriptions, so a shard needs nothing but the
//! batch file, and a tell checks that the results belong to the problem and batch it asked
//! for.

use crate::batch_files::{read_batch_file, BatchHeaderFields, BatchKind, PointId};
use crate::{
    AfsDesignBounds, AfsProblem, AfsProblemSpec, AfsVariable, AhpHierarchy, DesignError,
    InterferenceGeometry, Objective,
};
use afsv_dynamics::EquationForm;
use optimize::{Bounds, ConstrainedProblem, Evaluation, BARRIER};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::path::Path;

/// Version of the batch and results formats (2: headers carry the asking state's
/// SHA-256, [`BatchHeader::state_sha256`]).
pub const FORMAT_VERSION: u32 = 2;
/// `format` of a batch file's header.
pub const BATCH_FORMAT: &str = "afsv-batch";
/// `format` of a results file's header.
pub const RESULTS_FORMAT: &str = "afsv-results";
/// Largest number of points in one batch (bounds every allocation that follows a file).
pub const MAX_BATCH_POINTS: usize = 1_000_000;
/// Largest number of shards.
pub const MAX_SHARDS: usize = 100_000;

/// Whether the point of 0-based `index` belongs to shard `(i, n)` (`i` in 1..=n): round
/// robin, `index mod n == i - 1`.
pub fn in_shard(index: usize, (i, n): (usize, usize)) -> bool {
    index % n == i - 1
}

/// First line of a batch file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BatchHeader {
    /// [`BATCH_FORMAT`].
    pub format: String,
    /// [`FORMAT_VERSION`].
    pub version: u32,
    /// `afsv optimize afs --ask`.
    pub written_by: String,
    /// `afsv-v1`.
    pub sign_convention: String,
    /// Number of the batch (batches told before it).
    pub batch: usize,
    /// SHA-256 (hex) of the ask/tell state file's content when it asked this batch: with
    /// `batch`, the identity of the question. `--tell` takes results only for its own
    /// state's current batch. (Absent in a file of version 1: read as empty, refused.)
    #[serde(default)]
    pub state_sha256: String,
    /// Whether the run has finished (then the batch holds no point).
    pub finished: bool,
    /// Number of point lines that follow.
    pub points: usize,
    /// Names of the design variables (`x` of every point).
    pub variables: Vec<String>,
    /// The problems the points belong to (`problem` of a point indexes this list).
    pub problems: Vec<ProblemDesc>,
}

impl BatchHeader {
    /// The header an `--ask` writes for batch `batch` of `points` points over `problems`,
    /// identified by the asking state's SHA-256 `state_sha256` (`finished`: the run has
    /// finished and the batch holds no point).
    pub fn asked(
        batch: usize,
        state_sha256: &str,
        finished: bool,
        points: usize,
        problems: &[ProblemDesc],
    ) -> Self {
        Self {
            format: BATCH_FORMAT.into(),
            version: FORMAT_VERSION,
            written_by: "afsv optimize afs --ask".into(),
            sign_convention: afsv_records::SIGN_CONVENTION.into(),
            batch,
            state_sha256: state_sha256.into(),
            finished,
            points,
            variables: variable_names(),
            problems: problems.to_vec(),
        }
    }
}

/// One point of a batch file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BatchPoint {
    /// Identifier, `b<batch>-<index>`.
    pub id: String,
    /// Index into the header's `problems`.
    pub problem: usize,
    /// Solver phase (`start_point`, `screening`, `refinement`, `sqp`), for the record.
    pub phase: String,
    /// Whether an infeasible point is left unsimulated (pattern search) or simulated (SQP).
    pub screened: bool,
    /// The design variables by name, SI.
    pub x: BTreeMap<String, f64>,
}

/// First line of a results file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ResultsHeader {
    /// [`RESULTS_FORMAT`].
    pub format: String,
    /// [`FORMAT_VERSION`].
    pub version: u32,
    /// `afsv batch evaluate`.
    pub written_by: String,
    /// `afsv-v1`.
    pub sign_convention: String,
    /// The batch's number.
    pub batch: usize,
    /// The batch's [`BatchHeader::state_sha256`], carried over: which state asked for
    /// these results.
    #[serde(default)]
    pub state_sha256: String,
    /// The shard, "I/N".
    pub shard: String,
    /// Number of result lines that follow.
    pub points: usize,
    /// The batch's problems.
    pub problems: Vec<ProblemDesc>,
}

impl ResultsHeader {
    /// The header of the results of the shard `shard` (I, N) of the batch `header`, with
    /// `points` result lines, written by `afsv batch evaluate`.
    pub fn of_shard(header: &BatchHeader, shard: (usize, usize), points: usize) -> Self {
        Self {
            format: RESULTS_FORMAT.into(),
            version: FORMAT_VERSION,
            written_by: "afsv batch evaluate".into(),
            sign_convention: afsv_records::SIGN_CONVENTION.into(),
            batch: header.batch,
            state_sha256: header.state_sha256.clone(),
            shard: format!("{}/{}", shard.0, shard.1),
            points,
            problems: header.problems.clone(),
        }
    }
}

/// One evaluated point of a results file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PointResult {
    /// The point's id.
    pub id: String,
    /// `evaluated`, `screened` (infeasible, not simulated: `f` is the barrier) or `failed`.
    pub status: String,
    /// Objective F (Eq 4.8); `null` when not a finite number.
    pub f: Option<f64>,
    /// Constraint values, feasible where <= 0, in the problem's order.
    pub constraints: Vec<Option<f64>>,
    /// Why the point failed.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub reason: Option<String>,
}

impl PointResult {
    /// The evaluation it holds (`null` back to NaN).
    pub fn evaluation(&self) -> Evaluation {
        Evaluation {
            f: self.f.unwrap_or(f64::NAN),
            constraints: self
                .constraints
                .iter()
                .map(|c| c.unwrap_or(f64::NAN))
                .collect(),
        }
    }
}

/// The design vector of a point ([`AfsVariable::ALL`]'s order), every variable present,
/// no other.
pub fn point_vector(p: &BatchPoint) -> Result<Vec<f64>, String> {
    if p.x.len() != AfsVariable::ALL.len() {
        return Err(format!(
            "point {}: expected the variables {}",
            p.id,
            variable_names().join(", ")
        ));
    }
    AfsVariable::ALL
        .iter()
        .map(|v| {
            p.x.get(v.name())
                .copied()
                .ok_or_else(|| format!("point {}: no variable {}", p.id, v.name()))
        })
        .collect()
}

/// Names of the design variables in the solver's order.
pub fn variable_names() -> Vec<String> {
    AfsVariable::ALL
        .iter()
        .map(|v| v.name().to_string())
        .collect()
}

/// Reads and checks a batch file: its header (format, version, variables, problem count)
/// and its points (count as the header says, ids in order, problem indices in range).
pub fn read_batch(label: &str, path: &Path) -> Result<(BatchHeader, Vec<BatchPoint>), String> {
    let bad = |what: String| format!("{label} {}: {what}", path.display());
    let kind = BatchKind {
        what: "batch file",
        format: BATCH_FORMAT,
        version: FORMAT_VERSION,
    };
    let check = |h: &BatchHeader| {
        if h.variables != variable_names() {
            return Err(bad(format!(
                "variables {:?}, expected {:?}",
                h.variables,
                variable_names()
            )));
        }
        Ok(())
    };
    let (h, lines): (BatchHeader, Vec<(usize, BatchPoint)>) =
        read_batch_file(label, path, &kind, &check)?;
    if let Some((line, p)) = lines.iter().find(|(_, p)| p.problem >= h.problems.len()) {
        return Err(bad(format!(
            "line {line}: point {:?} of problem {}: expected a problem below {}",
            p.id,
            p.problem,
            h.problems.len()
        )));
    }
    Ok((h, lines.into_iter().map(|(_, p)| p).collect()))
}

impl BatchHeaderFields for BatchHeader {
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

impl PointId for BatchPoint {
    fn id(&self) -> &str {
        &self.id
    }
}

impl PointId for PointResult {
    fn id(&self) -> &str {
        &self.id
    }
}

/// Whether `s` is a SHA-256 digest in lower-case hex (64 digits).
pub fn is_sha256_hex(s: &str) -> bool {
    s.len() == 64
        && s.bytes()
            .all(|b| b.is_ascii_digit() || (b'a'..=b'f').contains(&b))
}

/// Id of point `index` of batch `batch`.
pub fn point_id(batch: usize, index: usize) -> String {
    format!("b{batch}-{index}")
}

/// What a shard needs to rebuild one configuration's problem: the command-line settings
/// that define it (written into every batch and results header).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ProblemDesc {
    /// `afs_chapter4`.
    pub kind: String,
    /// The configuration, e.g. "with the steering-arm constraint".
    pub label: String,
    /// The relaxed B_eff bound of Table 4.4.
    pub relaxed: bool,
    /// Minimum full-lock steering arm (m); `null`: no arm constraint.
    pub min_steering_arm_m: Option<f64>,
    /// Relative tolerance of the simulations.
    pub rtol: f64,
    /// `energy_consistent` or `paper_eq_3_13`.
    pub form: String,
    /// The Eq 4.9 geometry, if given.
    pub eq_4_9: Option<Eq49Desc>,
    /// A described vehicle (`--vehicle`); absent: Table 3.1's.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub vehicle: Option<VehicleDesc>,
}

/// The vehicle of `--vehicle` as a problem stores it: its name, its loaded yaw-plane data
/// and its steering.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct VehicleDesc {
    /// The description's name.
    pub name: String,
    /// Its loaded yaw-plane data.
    pub yaw_plane: afsv_dynamics::VehicleParams,
    /// Its steering system (the current design).
    pub steering: afs_hydraulics::AfsParams,
}

/// The Eq 4.9 options as given on the command line.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Eq49Desc {
    /// `--front-mount-dir-deg`.
    pub front_mount_dir_deg: f64,
    /// `--tire-point`.
    pub tire_point: [f64; 2],
    /// `--engine-point`.
    pub engine_point: [f64; 2],
}

/// The `kind` of the chapter-4 problem.
pub const AFS_KIND: &str = "afs_chapter4";

impl ProblemDesc {
    /// The problem specification the description defines (its bounds, arm constraint,
    /// tolerance, equation form, vehicle and Eq 4.9 geometry).
    pub fn spec(&self) -> Result<AfsProblemSpec, String> {
        let d = self;
        if d.kind != AFS_KIND {
            return Err(format!(
                "unknown problem kind {:?} (this afsv knows {AFS_KIND:?})",
                d.kind
            ));
        }
        if !(d.rtol.is_finite() && d.rtol > 0.0) {
            return Err(format!("rtol {}: must be finite and > 0", d.rtol));
        }
        let mut spec = AfsProblemSpec {
            bounds: if d.relaxed {
                AfsDesignBounds::table_4_2_relaxed()
            } else {
                AfsDesignBounds::table_4_2()
            },
            min_steering_arm_m: d.min_steering_arm_m,
            ..AfsProblemSpec::default()
        };
        spec.measure.options.rtol = d.rtol;
        spec.measure.options.form = match d.form.as_str() {
            "energy_consistent" => EquationForm::EnergyConsistent,
            "paper_eq_3_13" => EquationForm::PaperEq313,
            other => return Err(format!("unknown equation form {other:?}")),
        };
        if let Some(v) = &d.vehicle {
            spec.vehicle = v.yaw_plane.clone();
            spec.steering = v.steering.clone();
        }
        if let Some(g) = &d.eq_4_9 {
            spec.interference = Some(
                InterferenceGeometry::new(
                    g.front_mount_dir_deg.to_radians(),
                    g.tire_point,
                    g.engine_point,
                )
                .map_err(|e| e.to_string())?,
            );
        }
        Ok(spec)
    }

    /// The problem the description defines, with the chapter-4 objective (simulates its
    /// current design once).
    pub fn problem(&self) -> Result<AfsProblem, String> {
        let objective = chapter4_objective().map_err(|e| e.to_string())?;
        AfsProblem::new(self.spec()?, objective).map_err(|e| e.to_string())
    }
}

/// The Eq 4.8 objective with the chapter-4 AHP weights (Eqs 4.11-4.17).
pub fn chapter4_objective() -> Result<Objective, DesignError> {
    Objective::new(AhpHierarchy::chapter4().weights()?.composite)
}

/// One problem's points of one kind (screened or not) as a solver problem that counts
/// progress.
struct Counted<'a> {
    problem: &'a AfsProblem,
    screened: bool,
    step: &'a (dyn Fn() + Sync),
}

impl ConstrainedProblem for Counted<'_> {
    fn bounds(&self) -> &Bounds {
        self.problem.bounds()
    }
    fn n_constraints(&self) -> usize {
        self.problem.n_constraints()
    }
    fn evaluate(&self, x: &[f64]) -> Evaluation {
        let e = self.problem.evaluate_point(x, self.screened);
        (self.step)();
        e
    }
}

/// The result line of point `id` at `x` with its evaluation `e`: a failed evaluation gets
/// the reason (the design or simulation error), a screened one its status.
pub fn result_line(id: &str, problem: &AfsProblem, x: &[f64], e: &Evaluation) -> PointResult {
    let failed = e.f == BARRIER && e.constraints.iter().all(|c| *c == BARRIER);
    let (status, reason) = if failed {
        let why = problem
            .design_of(x)
            .and_then(|d| problem.evaluate_design(&d))
            .err()
            .map_or_else(|| "the evaluation failed".to_string(), |e| e.to_string());
        ("failed", Some(why))
    } else if e.f == BARRIER {
        ("screened", None)
    } else {
        ("evaluated", None)
    };
    let finite = |v: f64| v.is_finite().then_some(v);
    PointResult {
        id: id.to_string(),
        status: status.into(),
        f: finite(e.f),
        constraints: e.constraints.iter().map(|c| finite(*c)).collect(),
        reason,
    }
}

/// Evaluates the points of shard `shard` of a batch (`header`, `points`, as
/// [`read_batch`] returns them), in the batch's order: per problem, first the screened
/// points, then the simulated ones, each group in parallel ([`optimize::evaluate_batch`]);
/// `step` is called after each point. `label` names the batch file in errors.
pub fn evaluate_shard(
    label: &str,
    header: &BatchHeader,
    points: &[BatchPoint],
    shard: (usize, usize),
    step: &(dyn Fn() + Sync),
) -> Result<Vec<PointResult>, String> {
    let mine: Vec<(usize, &BatchPoint)> = points
        .iter()
        .enumerate()
        .filter(|(i, _)| in_shard(*i, shard))
        .collect();
    let xs: Vec<Vec<f64>> = mine
        .iter()
        .map(|(_, p)| point_vector(p))
        .collect::<Result<_, _>>()
        .map_err(|e| format!("{label}: {e}"))?;
    // The problems this shard's points need (each simulates the current design once).
    let mut problems: Vec<Option<AfsProblem>> = vec![None; header.problems.len()];
    for (_, p) in &mine {
        if problems[p.problem].is_none() {
            problems[p.problem] = Some(
                header.problems[p.problem]
                    .problem()
                    .map_err(|e| format!("{label}: problem {}: {e}", p.problem))?,
            );
        }
    }
    let mut evals: Vec<Option<Evaluation>> = vec![None; mine.len()];
    for (k, problem) in problems.iter().enumerate() {
        let Some(problem) = problem else { continue };
        for screened in [true, false] {
            let idx: Vec<usize> = (0..mine.len())
                .filter(|&j| mine[j].1.problem == k && mine[j].1.screened == screened)
                .collect();
            let group: Vec<Vec<f64>> = idx.iter().map(|&j| xs[j].clone()).collect();
            let counted = Counted {
                problem,
                screened,
                step,
            };
            for (j, e) in idx
                .into_iter()
                .zip(optimize::evaluate_batch(&counted, &group))
            {
                evals[j] = Some(e);
            }
        }
    }
    let mut lines = Vec::with_capacity(mine.len());
    for (((_, p), x), e) in mine.iter().zip(&xs).zip(evals) {
        let (Some(problem), Some(e)) = (&problems[p.problem], e) else {
            return Err(format!("point {}: not evaluated", p.id));
        };
        lines.push(result_line(&p.id, problem, x, &e));
    }
    Ok(lines)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn an_asked_header_names_the_format_the_variables_and_the_state() {
        let h = BatchHeader::asked(3, "ab", false, 7, &[]);
        assert_eq!(
            (h.format.as_str(), h.version),
            (BATCH_FORMAT, FORMAT_VERSION)
        );
        assert_eq!((h.batch, h.state_sha256.as_str(), h.points), (3, "ab", 7));
        assert_eq!(h.variables.len(), AfsVariable::ALL.len());
        assert_eq!(h.written_by, "afsv optimize afs --ask");
        assert!(!h.finished && h.problems.is_empty());
    }

    proptest! {
        /// The round robin gives every point to exactly one shard, and the shards' sizes
        /// differ by at most one.
        #[test]
        fn every_point_falls_in_exactly_one_shard(points in 0usize..200, n in 1usize..20) {
            for index in 0..points {
                let owners = (1..=n).filter(|&i| in_shard(index, (i, n))).count();
                prop_assert_eq!(owners, 1);
            }
            let sizes: Vec<usize> = (1..=n)
                .map(|i| (0..points).filter(|&k| in_shard(k, (i, n))).count())
                .collect();
            let (lo, hi) = (sizes.iter().min().unwrap(), sizes.iter().max().unwrap());
            prop_assert!(hi - lo <= 1, "{:?}", sizes);
        }
    }

    #[test]
    fn results_round_trip_to_the_same_bits_and_null_reads_as_nan() {
        let r = PointResult {
            id: "b0-0".into(),
            status: "evaluated".into(),
            f: Some(0.1 + 0.2),
            constraints: vec![Some(BARRIER), Some(-1e-300), None],
            reason: None,
        };
        let text = serde_json::to_string(&r).unwrap();
        let back: PointResult = serde_json::from_str(&text).unwrap();
        assert_eq!(back, r);
        let e = back.evaluation();
        assert_eq!(e.f.to_bits(), (0.1f64 + 0.2).to_bits());
        assert_eq!(e.constraints[0], BARRIER);
        assert!(e.constraints[2].is_nan());
        assert!(!text.contains("reason"));
    }
}
