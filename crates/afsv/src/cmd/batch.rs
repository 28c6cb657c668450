//! `afsv batch evaluate`: evaluates one shard of a batch of design points that
//! `afsv optimize afs --ask`, `afsv optimize hps --ask` or `afsv optimize layout --ask`
//! wrote (docs/optimisation.md, "Running on a cluster"); the batch header's `format` tells
//! which. The formats and the shard's evaluation are `afsv_design::afs_batch`,
//! `afsv_design::hps_ask_tell` and `afsv_design::layout_ask_tell`.

use super::CmdResult;
use afsv::output::{OutputGuard, OutputKind};
use afsv_design::afs_batch::{evaluate_shard, in_shard, read_batch, ResultsHeader, MAX_SHARDS};
use afsv_design::hps_ask_tell::{
    evaluate_hps_shard, read_hps_batch, HpsResultsHeader, HPS_BATCH_FORMAT,
};
use afsv_design::layout_ask_tell::{
    evaluate_layout_shard, read_layout_batch, LayoutResultsHeader, LAYOUT_BATCH_FORMAT,
};
use afsv_records::jsonl::write_jsonl;
use std::io::{BufRead, IsTerminal, Read};
use std::path::{Path, PathBuf};

/// `afsv batch` subcommands.
#[derive(clap::Subcommand)]
pub enum Command {
    /// Evaluate one shard of a batch file written by `afsv optimize afs|hps|layout --ask` and write its results (JSON Lines) for `--tell`.
    Evaluate(EvaluateArgs),
}

/// Options of `afsv batch evaluate`.
#[derive(clap::Args)]
pub struct EvaluateArgs {
    /// The batch file (JSON Lines) written by `afsv optimize afs|hps|layout --ask`.
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

/// Run `afsv batch`.
pub fn run(cmd: Command) -> CmdResult {
    match cmd {
        Command::Evaluate(a) => evaluate(&a),
    }
}

/// The `format` the batch file's header (its first line) names; `None` for anything
/// else, unreadable files included, which goes to the chapter-4 reader and its errors.
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

fn evaluate(a: &EvaluateArgs) -> CmdResult {
    let mut guard = OutputGuard::new(a.force);
    guard.input("BATCH", &a.batch)?;
    guard.output("-o", &a.output, OutputKind::JsonLines)?;
    let t = std::time::Instant::now();
    match batch_format(&a.batch).as_deref() {
        Some(LAYOUT_BATCH_FORMAT) => return evaluate_layout(a, t),
        Some(HPS_BATCH_FORMAT) => return evaluate_hps(a, t),
        _ => {}
    }
    let (header, points) = read_batch("BATCH", &a.batch)?;
    let mine = (0..points.len()).filter(|&i| in_shard(i, a.shard)).count();
    let progress = afsv::progress::Progress::new("afsv batch evaluate", "points", Some(mine));
    let label = format!("BATCH {}", a.batch.display());
    let lines = evaluate_shard(&label, &header, &points, a.shard, &|| progress.step(""))?;
    progress.finish();
    let shard_text = format!("{}/{}", a.shard.0, a.shard.1);
    let out = ResultsHeader::of_shard(&header, a.shard, lines.len());
    write_jsonl(&a.output, &out, &lines)?;
    summary(a, header.batch, &shard_text, t, &|s| {
        lines.iter().filter(|l| l.status == s).count()
    })
}

/// One shard of a layout batch (`afsv optimize layout --ask`).
fn evaluate_layout(a: &EvaluateArgs, t: std::time::Instant) -> CmdResult {
    let (header, points) = read_layout_batch("BATCH", &a.batch)?;
    let mine = (0..points.len()).filter(|&i| in_shard(i, a.shard)).count();
    let progress = afsv::progress::Progress::new("afsv batch evaluate", "designs", Some(mine));
    let label = format!("BATCH {}", a.batch.display());
    let lines = evaluate_layout_shard(&label, &header, &points, a.shard, &|| progress.step(""))?;
    progress.finish();
    let shard_text = format!("{}/{}", a.shard.0, a.shard.1);
    let out = LayoutResultsHeader::of_shard(&header, a.shard, lines.len());
    write_jsonl(&a.output, &out, &lines)?;
    summary(a, header.batch, &shard_text, t, &|s| {
        lines.iter().filter(|l| l.status == s).count()
    })
}

/// One shard of an HPS batch (`afsv optimize hps --ask`).
fn evaluate_hps(a: &EvaluateArgs, t: std::time::Instant) -> CmdResult {
    let (header, points) = read_hps_batch("BATCH", &a.batch)?;
    let mine = (0..points.len()).filter(|&i| in_shard(i, a.shard)).count();
    let progress = afsv::progress::Progress::new("afsv batch evaluate", "runs", Some(mine));
    let lines = evaluate_hps_shard(&header, &points, a.shard, &|| progress.step(""));
    progress.finish();
    let shard_text = format!("{}/{}", a.shard.0, a.shard.1);
    let out = HpsResultsHeader::of_shard(&header, a.shard, lines.len());
    write_jsonl(&a.output, &out, &lines)?;
    summary(a, header.batch, &shard_text, t, &|s| {
        lines.iter().filter(|l| l.status == s).count()
    })
}

/// The shard's summary on stdout: JSON, or a line on a terminal; `count` gives the points
/// of a status.
fn summary(
    a: &EvaluateArgs,
    batch: usize,
    shard_text: &str,
    t: std::time::Instant,
    count: &dyn Fn(&str) -> usize,
) -> CmdResult {
    let points = count("evaluated") + count("screened") + count("failed");
    let summary = serde_json::json!({
        "batch": batch, "shard": shard_text, "points": points,
        "evaluated": count("evaluated"), "screened": count("screened"), "failed": count("failed"),
        "results": a.output.display().to_string(), "seconds": t.elapsed().as_secs_f64(),
    });
    if a.json || !std::io::stdout().is_terminal() {
        afsv::output::print_json(&summary)?;
    } else {
        println!(
            "batch {batch} shard {shard_text}: {points} points ({} evaluated, {} screened, {} failed) written to {} in {:.1} s",
            count("evaluated"),
            count("screened"),
            count("failed"),
            a.output.display(),
            t.elapsed().as_secs_f64()
        );
    }
    Ok(())
}
