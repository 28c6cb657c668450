//! One shard of any ask/tell batch file, evaluated whole (`afsv batch evaluate`): the
//! header's `format` picks the reader and the evaluation of [`crate::afs_batch`],
//! [`crate::hps_ask_tell`] or [`crate::layout_ask_tell`], and the shard's results file is
//! written for the `--tell` of the run that asked.

use crate::afs_batch::{evaluate_shard, in_shard, read_batch, ResultsHeader, MAX_SHARDS};
use crate::hps_ask_tell::HPS_BATCH_FORMAT;
use crate::hps_ask_tell::{evaluate_hps_shard, read_hps_batch, HpsResultsHeader};
use crate::layout_ask_tell::LAYOUT_BATCH_FORMAT;
use crate::layout_ask_tell::{evaluate_layout_shard, read_layout_batch, LayoutResultsHeader};
use afsv_records::jsonl::write_jsonl;
use std::io::{BufRead, Read};
use std::path::Path;

/// What one shard's evaluation wrote: the batch's number and its points by status.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ShardOutcome {
    /// The batch's number.
    pub batch: usize,
    /// Points evaluated.
    pub evaluated: usize,
    /// Chapter-4 points screened out as infeasible (not simulated).
    pub screened: usize,
    /// Points whose evaluation failed.
    pub failed: usize,
}

impl ShardOutcome {
    /// The counts of the result lines `statuses`.
    fn of<'a>(batch: usize, statuses: impl Iterator<Item = &'a str> + Clone) -> Self {
        let count = |s: &str| statuses.clone().filter(|t| *t == s).count();
        Self {
            batch,
            evaluated: count("evaluated"),
            screened: count("screened"),
            failed: count("failed"),
        }
    }

    /// All the points of the shard the results file holds.
    pub fn points(&self) -> usize {
        self.evaluated + self.screened + self.failed
    }
}

/// The progress of a shard's evaluation.
pub trait ShardProgress: Sync {
    /// Once the batch is read: the shard holds `points` of `unit` (`points`, `designs` or
    /// `runs`).
    fn start(&self, unit: &'static str, points: usize);
    /// After each point.
    fn step(&self);
}

/// The `format` the batch file's header (its first line) names; `None` for anything
/// else, unreadable files included, which go to the chapter-4 reader and its errors.
fn batch_format(path: &Path) -> Option<String> {
    let file = std::fs::File::open(path).ok()?;
    let mut line = String::new();
    std::io::BufReader::new(file)
        .take(afsv_records::jsonl::MAX_LINE_BYTES as u64)
        .read_line(&mut line)
        .ok()?;
    let v = serde_json::from_str::<serde_json::Value>(&line).ok()?;
    v["format"].as_str().map(str::to_string)
}

/// The shard `"I/N"` of a batch (`--shard`), 1 <= I <= N <= [`MAX_SHARDS`]: the points
/// whose 0-based index is I-1 modulo N.
pub fn parse_shard(s: &str) -> Result<(usize, usize), String> {
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

/// The points of `shard` (I, N) among `n`.
fn mine(n: usize, shard: (usize, usize)) -> usize {
    (0..n).filter(|&i| in_shard(i, shard)).count()
}

/// Evaluates the points of `shard` (I, N) of the batch file `batch` (`label` names it in
/// errors) and writes their results to `output`, in the batch's order.
pub fn evaluate_batch_shard(
    label: &str,
    batch: &Path,
    shard: (usize, usize),
    output: &Path,
    progress: &dyn ShardProgress,
) -> Result<ShardOutcome, String> {
    let step = || progress.step();
    let in_file = format!("{label} {}", batch.display());
    match batch_format(batch).as_deref() {
        Some(LAYOUT_BATCH_FORMAT) => {
            let (header, points) = read_layout_batch(label, batch)?;
            progress.start("designs", mine(points.len(), shard));
            let lines = evaluate_layout_shard(&in_file, &header, &points, shard, &step)?;
            let out = LayoutResultsHeader::of_shard(&header, shard, lines.len());
            write_jsonl(output, &out, &lines)?;
            Ok(ShardOutcome::of(
                header.batch,
                lines.iter().map(|l| l.status.as_str()),
            ))
        }
        Some(HPS_BATCH_FORMAT) => {
            let (header, points) = read_hps_batch(label, batch)?;
            progress.start("runs", mine(points.len(), shard));
            let lines = evaluate_hps_shard(&header, &points, shard, &step);
            let out = HpsResultsHeader::of_shard(&header, shard, lines.len());
            write_jsonl(output, &out, &lines)?;
            Ok(ShardOutcome::of(
                header.batch,
                lines.iter().map(|l| l.status.as_str()),
            ))
        }
        _ => {
            let (header, points) = read_batch(label, batch)?;
            progress.start("points", mine(points.len(), shard));
            let lines = evaluate_shard(&in_file, &header, &points, shard, &step)?;
            let out = ResultsHeader::of_shard(&header, shard, lines.len());
            write_jsonl(output, &out, &lines)?;
            Ok(ShardOutcome::of(
                header.batch,
                lines.iter().map(|l| l.status.as_str()),
            ))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::{AtomicUsize, Ordering};

    #[test]
    fn shards_are_one_based_and_bounded() {
        assert_eq!(parse_shard("1/1").unwrap(), (1, 1));
        assert_eq!(parse_shard(" 2 / 3 ").unwrap(), (2, 3));
        for bad in ["0/2", "3/2", "1", "a/b", "1/0"] {
            assert!(parse_shard(bad).unwrap_err().contains("I/N"), "{bad}");
        }
        assert!(parse_shard(&format!("1/{}", MAX_SHARDS + 1)).is_err());
    }

    /// Counts what a shard reports.
    #[derive(Default)]
    struct Counted {
        started: AtomicUsize,
        steps: AtomicUsize,
    }

    impl ShardProgress for Counted {
        fn start(&self, unit: &'static str, points: usize) {
            assert_eq!(unit, "designs");
            self.started.store(points, Ordering::Relaxed);
        }
        fn step(&self) {
            self.steps.fetch_add(1, Ordering::Relaxed);
        }
    }

    /// The nominal batch of a layout run is told by its format, evaluated in the first of
    /// two shards (its one point) and in the second (none), each with its results file; a
    /// file that is no batch is refused by the chapter-4 reader, named.
    #[test]
    fn a_layout_batch_is_recognised_and_its_shards_written() {
        use crate::layout_ask_tell::{batch_file, LayoutAskTell, LayoutRunState};
        let d = std::env::temp_dir().join(format!("afsv-batch-shard-{}", std::process::id()));
        std::fs::create_dir_all(&d).unwrap();
        let problem = crate::layout_optimum::tests::tiny().problem().unwrap();
        let ga = crate::LayoutGaSettings {
            population: 4,
            generations: 1,
            seed: 1,
        };
        let asked = LayoutAskTell::new(&problem, ga)
            .unwrap()
            .ask(&LayoutRunState::default())
            .unwrap();
        let (header, points) = batch_file(problem.desc(), 0, &"0".repeat(64), &asked);
        let batch = d.join("b.jsonl");
        write_jsonl(&batch, &header, &points).unwrap();
        for (i, n) in [(1, 1), (2, 2)] {
            let counted = Counted::default();
            let out = d.join(format!("r{i}.jsonl"));
            let o = evaluate_batch_shard("BATCH", &batch, (i, n), &out, &counted).unwrap();
            let expected = usize::from(i == 1);
            assert_eq!(o.points(), expected);
            assert_eq!(o.evaluated + o.failed, expected);
            assert_eq!(counted.started.load(Ordering::Relaxed), expected);
            assert_eq!(counted.steps.load(Ordering::Relaxed), expected);
            let text = std::fs::read_to_string(&out).unwrap();
            assert_eq!(text.lines().count(), 1 + expected);
        }
        let junk = d.join("junk.jsonl");
        std::fs::write(&junk, "not json\n").unwrap();
        let e = evaluate_batch_shard(
            "BATCH",
            &junk,
            (1, 1),
            &d.join("x.jsonl"),
            &Counted::default(),
        )
        .unwrap_err();
        assert!(e.starts_with("BATCH "), "{e}");
        let _ = std::fs::remove_dir_all(&d);
    }
}
