//! `afsv batch evaluate`: evaluates one shard of a batch of design points that
//! `afsv optimize afs --ask`, `afsv optimize hps --ask` or `afsv optimize layout --ask`
//! wrote (docs/optimisation.md, "Running on a cluster"); the batch header's `format` tells
//! which (`afsv_design::batch_shard`; the formats are `afsv_design::afs_batch`,
//! `afsv_design::hps_ask_tell` and `afsv_design::layout_ask_tell`).

use super::CmdResult;
use afsv::output::{OutputGuard, OutputKind};
use afsv_design::batch_shard::{evaluate_batch_shard, parse_shard, ShardOutcome, ShardProgress};
use std::path::PathBuf;

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
    #[arg(long, default_value = "1/1", value_parser = parse_shard)]
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

/// Run `afsv batch`.
pub fn run(cmd: Command) -> CmdResult {
    match cmd {
        Command::Evaluate(a) => evaluate(&a),
    }
}

/// Progress of `afsv batch evaluate`, started once the batch is read.
struct ShardBar(std::sync::OnceLock<afsv::progress::Progress>);

impl ShardProgress for ShardBar {
    fn start(&self, unit: &'static str, points: usize) {
        let p = afsv::progress::Progress::new("afsv batch evaluate", unit, Some(points));
        let _ = self.0.set(p);
    }
    fn step(&self) {
        if let Some(p) = self.0.get() {
            p.step("");
        }
    }
}

fn evaluate(a: &EvaluateArgs) -> CmdResult {
    let mut guard = OutputGuard::new(a.force);
    guard.input("BATCH", &a.batch)?;
    guard.output("-o", &a.output, OutputKind::JsonLines)?;
    let t = std::time::Instant::now();
    let bar = ShardBar(std::sync::OnceLock::new());
    let outcome = evaluate_batch_shard("BATCH", &a.batch, a.shard, &a.output, &bar);
    if let Some(p) = bar.0.get() {
        p.finish();
    }
    summary(a, &outcome?, t)
}

/// The shard's summary on stdout: JSON, or a line on a terminal.
fn summary(a: &EvaluateArgs, o: &ShardOutcome, t: std::time::Instant) -> CmdResult {
    let (batch, points) = (o.batch, o.points());
    let shard_text = format!("{}/{}", a.shard.0, a.shard.1);
    let summary = serde_json::json!({
        "batch": batch, "shard": shard_text, "points": points,
        "evaluated": o.evaluated, "screened": o.screened, "failed": o.failed,
        "results": a.output.display().to_string(), "seconds": t.elapsed().as_secs_f64(),
    });
    afsv::output::print_json_or_text(a.json, &summary, || {
        format!(
            "batch {batch} shard {shard_text}: {points} points ({} evaluated, {} screened, {} failed) written to {} in {:.1} s\n",
            o.evaluated,
            o.screened,
            o.failed,
            a.output.display(),
            t.elapsed().as_secs_f64()
        )
    })?;
    Ok(())
}
