//! `afsv batch evaluate`: evaluates one shard of a batch of design points that
//! `afsv optimize afs --ask` wrote, and the JSON Lines formats of the ask/tell commands
//! (docs/optimisation.md, "Running on a cluster").
//!
//! A batch file is a header line and one line per point; a results file a header line and
//! one line per evaluated point. Shard `I/N` evaluates the points whose 0-based index in
//! the batch is `I - 1` modulo `N` (round robin, so every shard gets a share of each
//! phase). Every header carries the problem descriptions, so a shard needs nothing but the
//! batch file, and `--tell` checks that the results belong to the problem and batch it
//! asked for.

use super::optimize::{problem_of, ProblemDesc};
use super::CmdResult;
use afsv::output::{OutputGuard, OutputKind};
use afsv_design::{AfsProblem, AfsVariable};
use optimize::{Bounds, ConstrainedProblem, Evaluation, BARRIER};
use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::io::{BufRead, IsTerminal, Read};
use std::path::{Path, PathBuf};

/// Version of the batch and results formats (2: headers carry the asking state's
/// SHA-256, [`BatchHeader::state_sha256`]).
pub const FORMAT_VERSION: u32 = 2;
/// `format` of a batch file's header.
pub const BATCH_FORMAT: &str = "afsv-batch";
/// `format` of a results file's header.
pub const RESULTS_FORMAT: &str = "afsv-results";
/// Largest number of points in one batch (bounds every allocation that follows a file).
pub const MAX_BATCH_POINTS: usize = 1_000_000;
/// Longest line of a batch or results file (bytes).
pub const MAX_LINE_BYTES: usize = 1 << 20;
/// Largest number of shards.
pub const MAX_SHARDS: usize = 100_000;

/// `afsv batch` subcommands.
#[derive(clap::Subcommand)]
pub enum Command {
    /// Evaluate one shard of a batch file written by `afsv optimize afs --ask` and write its results (JSON Lines) for `--tell`.
    Evaluate(EvaluateArgs),
}

/// Options of `afsv batch evaluate`.
#[derive(clap::Args)]
pub struct EvaluateArgs {
    /// The batch file (JSON Lines) written by `afsv optimize afs --ask`.
    pub batch: PathBuf,
    /// The shard "I/N" (1 <= I <= N): the points whose 0-based index is I-1 modulo N.
    #[arg(long, default_value = "1/1", value_parser = shard)]
    pub shard: (usize, usize),
    /// Results file (JSON Lines) to write.
    #[arg(short, long)]
    pub output: PathBuf,
    /// Replace an existing output file afsv did not write.
    #[arg(long)]
    pub force: bool,
    /// Print the summary as JSON even on a terminal.
    #[arg(long)]
    pub json: bool,
}

/// Whether the point of 0-based `index` belongs to shard `(i, n)` (`i` in 1..=n): round
/// robin, `index mod n == i - 1`.
pub fn in_shard(index: usize, (i, n): (usize, usize)) -> bool {
    index % n == i - 1
}

fn shard(s: &str) -> Result<(usize, usize), String> {
    let bad = || format!("expected \"I/N\" with 1 <= I <= N <= {MAX_SHARDS}, got {s:?}");
    let (i, n) = s.split_once('/').ok_or_else(bad)?;
    let (i, n): (usize, usize) = (
        i.trim().parse().map_err(|_| bad())?,
        n.trim().parse().map_err(|_| bad())?,
    );
    if 1 <= i && i <= n && n <= MAX_SHARDS {
        Ok((i, n))
    } else {
        Err(bad())
    }
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

/// `serde_json`'s message without its " at line L column C" (each line is parsed alone;
/// callers that report a position give it themselves).
pub fn message(e: &serde_json::Error) -> String {
    let m = e.to_string();
    match m.rsplit_once(" at line ") {
        Some((head, _)) => head.to_string(),
        None => m,
    }
}

/// A JSON Lines file: the header (line 1), which `check` accepts before any record is read,
/// and at most `max_records` records, each with its line number. Blank lines are skipped; a
/// line longer than [`MAX_LINE_BYTES`], a record beyond `max_records` or a malformed line
/// is an error naming `label`, the file, line and column.
pub fn read_jsonl<H: DeserializeOwned, T: DeserializeOwned>(
    label: &str,
    path: &Path,
    max_records: usize,
    check: &dyn Fn(&H) -> Result<(), String>,
) -> Result<(H, Vec<(usize, T)>), String> {
    let at = |line: usize| format!("{label} {}:{line}", path.display());
    let file = std::fs::File::open(path).map_err(|e| format!("{label} {}: {e}", path.display()))?;
    let mut reader = std::io::BufReader::new(file);
    let mut header: Option<H> = None;
    let mut records = Vec::new();
    let mut buf = String::new();
    for line_no in 1usize.. {
        buf.clear();
        let n = reader
            .by_ref()
            .take(MAX_LINE_BYTES as u64 + 1)
            .read_line(&mut buf)
            .map_err(|e| format!("{}: {e}", at(line_no)))?;
        if n == 0 {
            break;
        }
        if n > MAX_LINE_BYTES {
            return Err(format!(
                "{}: line longer than {MAX_LINE_BYTES} bytes",
                at(line_no)
            ));
        }
        if buf.trim().is_empty() {
            continue;
        }
        let parse_err =
            |e: serde_json::Error| format!("{}:{}: {}", at(line_no), e.column(), message(&e));
        if header.is_none() {
            let h = serde_json::from_str(&buf).map_err(parse_err)?;
            check(&h)?;
            header = Some(h);
            continue;
        }
        if records.len() == max_records {
            return Err(format!("{}: more than {max_records} records", at(line_no)));
        }
        records.push((line_no, serde_json::from_str(&buf).map_err(parse_err)?));
    }
    let header = header.ok_or_else(|| format!("{label} {}: empty file", path.display()))?;
    Ok((header, records))
}

/// Reads and checks a batch file: its header (format, version, variables, problem count)
/// and its points (count as the header says, ids in order, problem indices in range).
pub fn read_batch(label: &str, path: &Path) -> Result<(BatchHeader, Vec<BatchPoint>), String> {
    let bad = |what: String| format!("{label} {}: {what}", path.display());
    let check = |h: &BatchHeader| {
        if h.format != BATCH_FORMAT || h.version != FORMAT_VERSION {
            return Err(bad(format!(
                "not a batch file of version {FORMAT_VERSION} (format {:?}, version {})",
                h.format, h.version
            )));
        }
        if !is_sha256_hex(&h.state_sha256) {
            return Err(bad(format!(
                "state_sha256 {:?} is not a SHA-256 in hex",
                h.state_sha256
            )));
        }
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
        read_jsonl(label, path, MAX_BATCH_POINTS, &check)?;
    if h.points != lines.len() {
        return Err(bad(format!(
            "the header announces {} points, the file holds {}",
            h.points,
            lines.len()
        )));
    }
    for (i, (line, p)) in lines.iter().enumerate() {
        if p.id != point_id(h.batch, i) || p.problem >= h.problems.len() {
            return Err(bad(format!(
                "line {line}: point {:?} of problem {}: expected id {:?} and a problem below {}",
                p.id,
                p.problem,
                point_id(h.batch, i),
                h.problems.len()
            )));
        }
    }
    Ok((h, lines.into_iter().map(|(_, p)| p).collect()))
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

/// Writes `header` and `lines` as JSON Lines to `path` (through a unique temporary file
/// renamed into place, so a reader never sees half a file).
pub fn write_jsonl<H: Serialize, T: Serialize>(
    path: &Path,
    header: &H,
    lines: &[T],
) -> Result<(), String> {
    let mut text = serde_json::to_string(header).map_err(|e| e.to_string())? + "\n";
    for l in lines {
        text += &serde_json::to_string(l).map_err(|e| e.to_string())?;
        text.push('\n');
    }
    afsv_records::atomic::write(path, text).map_err(|e| format!("{}: {e}", path.display()))
}

/// Run `afsv batch`.
pub fn run(cmd: Command) -> CmdResult {
    match cmd {
        Command::Evaluate(a) => evaluate(&a),
    }
}

/// One problem's points of one kind (screened or not) as a solver problem that counts
/// progress.
struct Counted<'a> {
    problem: &'a AfsProblem,
    screened: bool,
    progress: &'a afsv::progress::Progress,
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
        self.progress.step("");
        e
    }
}

/// The result line of point `id` at `x` with its evaluation `e`: a failed evaluation gets
/// the reason (the design or simulation error), a screened one its status.
fn result_line(id: &str, problem: &AfsProblem, x: &[f64], e: &Evaluation) -> PointResult {
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

fn evaluate(a: &EvaluateArgs) -> CmdResult {
    let (shard_i, shard_n) = a.shard;
    let mut guard = OutputGuard::new(a.force);
    guard.input("BATCH", &a.batch)?;
    guard.output("-o", &a.output, OutputKind::JsonLines)?;
    let t = std::time::Instant::now();
    let (header, points) = read_batch("BATCH", &a.batch)?;
    let mine: Vec<(usize, &BatchPoint)> = points
        .iter()
        .enumerate()
        .filter(|(i, _)| in_shard(*i, a.shard))
        .collect();
    let xs: Vec<Vec<f64>> = mine
        .iter()
        .map(|(_, p)| point_vector(p))
        .collect::<Result<_, _>>()
        .map_err(|e| format!("BATCH {}: {e}", a.batch.display()))?;
    // The problems this shard's points need (each simulates the current design once).
    let mut problems: Vec<Option<AfsProblem>> = vec![None; header.problems.len()];
    for (_, p) in &mine {
        if problems[p.problem].is_none() {
            problems[p.problem] =
                Some(problem_of(&header.problems[p.problem]).map_err(|e| {
                    format!("BATCH {}: problem {}: {e}", a.batch.display(), p.problem)
                })?);
        }
    }
    let progress = afsv::progress::Progress::new("afsv batch evaluate", "points", Some(mine.len()));
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
                progress: &progress,
            };
            for (j, e) in idx
                .into_iter()
                .zip(optimize::evaluate_batch(&counted, &group))
            {
                evals[j] = Some(e);
            }
        }
    }
    progress.finish();
    let mut lines = Vec::with_capacity(mine.len());
    for (((_, p), x), e) in mine.iter().zip(&xs).zip(evals) {
        let (Some(problem), Some(e)) = (&problems[p.problem], e) else {
            return Err(format!("point {}: not evaluated", p.id).into());
        };
        lines.push(result_line(&p.id, problem, x, &e));
    }
    let shard_text = format!("{shard_i}/{shard_n}");
    let out = ResultsHeader {
        format: RESULTS_FORMAT.into(),
        version: FORMAT_VERSION,
        written_by: "afsv batch evaluate".into(),
        sign_convention: afsv_records::SIGN_CONVENTION.into(),
        batch: header.batch,
        state_sha256: header.state_sha256.clone(),
        shard: shard_text.clone(),
        points: lines.len(),
        problems: header.problems.clone(),
    };
    write_jsonl(&a.output, &out, &lines)?;
    let count = |s: &str| lines.iter().filter(|l| l.status == s).count();
    let summary = serde_json::json!({
        "batch": header.batch, "shard": shard_text, "points": lines.len(),
        "evaluated": count("evaluated"), "screened": count("screened"), "failed": count("failed"),
        "results": a.output.display().to_string(), "seconds": t.elapsed().as_secs_f64(),
    });
    if a.json || !std::io::stdout().is_terminal() {
        afsv::output::print_json(&summary)?;
    } else {
        println!(
            "batch {} shard {shard_text}: {} points ({} evaluated, {} screened, {} failed) written to {} in {:.1} s",
            header.batch,
            lines.len(),
            count("evaluated"),
            count("screened"),
            count("failed"),
            a.output.display(),
            t.elapsed().as_secs_f64()
        );
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn file(name: &str, text: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("afsv-batch-unit-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let p = dir.join(name);
        std::fs::write(&p, text).unwrap();
        p
    }

    fn accept(_: &serde_json::Value) -> Result<(), String> {
        Ok(())
    }

    #[test]
    fn shards_parse_and_are_bounded() {
        assert_eq!(shard("2/3"), Ok((2, 3)));
        assert_eq!(shard(" 1 / 1 "), Ok((1, 1)));
        for bad in [
            "0/3", "4/3", "1/0", "1/100001", "1", "a/b", "1/2/3", "-1/2", "",
        ] {
            assert!(shard(bad).unwrap_err().contains("I/N"), "{bad}");
        }
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
    fn json_lines_errors_name_line_and_column_and_bounds_hold() {
        let ok = file("ok.jsonl", "{\"h\":1}\n\n[1]\n[2]\n");
        let (h, recs): (serde_json::Value, Vec<(usize, Vec<u32>)>) =
            read_jsonl("X", &ok, 2, &accept).unwrap();
        assert_eq!(h["h"], 1);
        assert_eq!(recs, vec![(3, vec![1]), (4, vec![2])]);
        let e = read_jsonl::<serde_json::Value, Vec<u32>>("X", &ok, 1, &accept).unwrap_err();
        assert!(e.ends_with("ok.jsonl:4: more than 1 records"), "{e}");
        let bad = file("bad.jsonl", "{}\n[1, x]\n");
        let e = read_jsonl::<serde_json::Value, Vec<u32>>("X", &bad, 9, &accept).unwrap_err();
        assert!(e.contains("bad.jsonl:2:5: expected value"), "{e}");
        let long = file(
            "long.jsonl",
            &format!("{{}}\n[{}]\n", "1,".repeat(MAX_LINE_BYTES)),
        );
        let e = read_jsonl::<serde_json::Value, Vec<u32>>("X", &long, 9, &accept).unwrap_err();
        assert!(e.contains("long.jsonl:2: line longer than"), "{e}");
        let empty = file("empty.jsonl", "\n");
        let e = read_jsonl::<serde_json::Value, Vec<u32>>("X", &empty, 9, &accept).unwrap_err();
        assert!(e.ends_with("empty file"), "{e}");
        let refuse = |_: &serde_json::Value| Err("not this header".to_string());
        let e = read_jsonl::<serde_json::Value, Vec<u32>>("X", &ok, 9, &refuse).unwrap_err();
        assert_eq!(e, "not this header");
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
