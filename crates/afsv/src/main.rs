//! `afsv`: command-line front end of the toolkit. Every subcommand prints JSON on stdout
//! (or writes CSV with `-o`), so results can be scripted (`evaluate` and `check` print a
//! readable summary instead when stdout is a terminal); errors go to stderr as one line
//! and the exit code is non-zero.

use clap::{Parser, Subcommand};
use std::process::ExitCode;

mod cmd;

/// Design and assess articulated frame-steered off-road vehicles: terrain, tires,
/// hydraulic steering, hydro-pneumatic suspension, performance measures.
#[derive(Parser)]
#[command(name = "afsv", version, propagate_version = true)]
struct Cli {
    /// No progress lines on stderr (long commands report one line per step by default).
    #[arg(long, global = true)]
    quiet: bool,
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Assess a vehicle (the built-in default, or a description: `afsv evaluate FILE` or `--vehicle FILE`): ride, roll and yaw with their seed spread and paper standing; a summary on a terminal, JSON with --json or when piped.
    Evaluate(cmd::evaluate::Args),
    /// Run the toolkit's self-checks (ISO 2631-1 weightings, terrain synthesis fidelity).
    Check(cmd::check::Args),
    /// Find which physical effect a model is missing from measured records, add it, report the gap shrink.
    Discover(cmd::discover::DiscoverArgs),
    /// Write measurement-like records from a truth model with hidden effects and sensor noise.
    Synth(cmd::discover::SynthArgs),
    /// Hydro-pneumatic suspension strut with gas-oil emulsion: `harmonic`, `characterize`, `identify`, `thermal` (temperatures and ride height over a shift).
    #[command(subcommand)]
    Hps(cmd::hps::Command),
    /// Performance measures on records: `weighting` (ISO 2631-1 filters), `wbv` (exposure), `decay` (free-decay fit), `step` (step metrics), `check` (the weightings against the standard's table).
    #[command(subcommand)]
    Measures(cmd::measures::Command),
    /// Terrain profiles: synthesize two tracks with a PSD and coherence (`generate`), estimate spectra (`psd`).
    #[command(subcommand)]
    Terrain(cmd::terrain::Command),
    /// Tire forces (Fiala) and terrain enveloping: `sweep`, `envelope`.
    #[command(subcommand)]
    Tire(cmd::tire::Command),
    /// Yaw-plane vehicle with hydraulic frame steering: `simulate`, `measures`, `sensitivity`, `leakage`.
    #[command(subcommand)]
    Yaw(cmd::yaw::Command),
    /// Roll stability of the rigid mining truck (chapter 2): `simulate`, `measures`, `study`, `calibrate`.
    #[command(subcommand)]
    Roll(cmd::roll::Command),
    /// Design studies on the 3-D vehicle (chapter 6): `hps-sensitivity` (Table 6.4), `speed-sweep` (D4 against speed), `layouts` (suspension layouts on the frame and at the seat).
    #[command(subcommand)]
    Study(cmd::study::Command),
    /// The 3-D articulated vehicle of chapter 6: `ride`, `roll`, `yaw`, `path-change` (design runs over terrain seeds), `measures` (D1-D3 together), `simulate`.
    #[command(subcommand)]
    Vehicle(cmd::vehicle::Command),
    /// Parameter sets and vehicle descriptions: `dump` the nominal set, `check` a file, `list` the named parameters.
    #[command(subcommand)]
    Params(cmd::params::Command),
    /// Design optimisation: `afs` (Chapter 4 frame steering, pattern search + SQP), `hps` (Chapter 6 front-axle strut, GA), `layout` (any suspension layout over registry-named parameters with constraints on its measures, GA; ask/tell for a cluster).
    #[command(subcommand)]
    Optimize(cmd::optimize::Command),
    /// Batches of design points from `afsv optimize afs --ask` or `afsv optimize layout --ask`: `evaluate` one shard of a batch (e.g. one Slurm array task).
    #[command(subcommand)]
    Batch(cmd::batch::Command),
}

fn main() -> ExitCode {
    // A bug must not greet the user with a backtrace: one line, non-zero exit.
    std::panic::set_hook(Box::new(|info| {
        eprintln!(
            "afsv: internal error (please report): {}",
            one_line(&info.to_string())
        );
    }));
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) if !e.use_stderr() => {
            // --help and --version: print as clap renders them.
            let _ = e.print();
            return ExitCode::SUCCESS;
        }
        Err(e) => {
            // One line: clap's first line names the problem; the usage is one --help away.
            // clap's message runs until the first blank line (e.g. "required arguments were
            // not provided:" followed by their names); join it into one line.
            let text = e.render().to_string();
            let message: Vec<&str> = text
                .lines()
                .take_while(|l| !l.trim().is_empty() && !l.starts_with("Usage:"))
                .map(str::trim)
                .collect();
            let mut message = message.join(" ");
            // clap's suggestions ("tip: a similar argument exists: '--speed-kmh'") follow
            // after a blank line: keep them.
            for tip in text
                .lines()
                .map(str::trim)
                .filter(|l| l.starts_with("tip:"))
            {
                message = format!("{message}; {tip}");
            }
            let message = message.strip_prefix("error: ").unwrap_or(&message);
            eprintln!("afsv: error: {} (see `afsv --help`)", one_line(message));
            return ExitCode::from(2);
        }
    };
    afsv::progress::set_quiet(cli.quiet);
    let result = match cli.command {
        Command::Evaluate(args) => cmd::evaluate::run(args),
        Command::Check(args) => cmd::check::run(args),
        // Its outcome (named / model-form discrepancy / nothing missing) is the exit code.
        Command::Discover(args) => match cmd::discover::run_discover_cmd(args) {
            Ok(code) => return ExitCode::from(code),
            Err(e) => Err(e),
        },
        Command::Synth(args) => cmd::discover::run_synth(args),
        Command::Hps(c) => cmd::hps::run(c),
        Command::Measures(c) => cmd::measures::run(c),
        Command::Terrain(c) => cmd::terrain::run(c),
        Command::Tire(c) => cmd::tire::run(c),
        Command::Yaw(c) => cmd::yaw::run(c),
        Command::Roll(c) => cmd::roll::run(c),
        Command::Study(c) => cmd::study::run(c),
        Command::Vehicle(c) => cmd::vehicle::run(c),
        Command::Params(c) => cmd::params::run(c),
        Command::Optimize(c) => cmd::optimize::run(c),
        Command::Batch(c) => cmd::batch::run(c),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) if e.is::<afsv::output::NotEarned>() => {
            eprintln!("afsv: not earned: {}", one_line(&e.to_string()));
            ExitCode::from(afsv::output::EXIT_NOT_EARNED)
        }
        Err(e) => {
            eprintln!("afsv: error: {}", one_line(&e.to_string()));
            ExitCode::FAILURE
        }
    }
}

/// `text` on one line: line breaks and other control characters (e.g. from a column name
/// read out of a malformed file) are shown escaped.
fn one_line(text: &str) -> String {
    text.trim_end()
        .chars()
        .flat_map(|c| {
            if c.is_control() {
                c.escape_default().collect::<Vec<char>>()
            } else {
                vec![c]
            }
        })
        .collect()
}
