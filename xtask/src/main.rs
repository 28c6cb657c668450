//! Project automation, run as `cargo xtask <task>` (alias in `.cargo/config.toml`).
//!
//! - `bench [CARGO BENCH ARGS...]`: run every criterion bench of the workspace (or those the
//!   harness arguments filter), then print one table of the mean times this run measured. A
//!   benchmark whose id ends in `_sim<N>s` simulates N seconds
//!   (`p` may stand for the decimal point: `_sim1p25s`), and the table adds its real-time
//!   factor = simulated seconds / wall seconds.
//!   Then the whole-command timings of what users run (`commands.rs`: the release binary run
//!   `--runs N` times per command, default 20, median). `bench --commands` prints only these.
//!   `--profile dist` builds both with the workspace's `dist` profile (fat LTO, one codegen
//!   unit) instead of `release`.
//! - `bench --summary`: only print the table of every result on disk, the latest of each
//!   bench (those of benches since removed included).
//! - `bench --no-discovery`: leave out the whole discovery runs (the ignored timing test of
//!   `afsv-discovery`) that follow the criterion table.
//! - `validate [--fixtures DIR] [--out DIR]`: compare our models with the dissertation's
//!   reported numbers (`fixtures/reported/`, see `docs/validation.md`), print the table,
//!   write `target/validation/report.md`, `report.json` and SVG plots; exit non-zero only
//!   when a quantity the fixtures mark as reproduced regresses.
//! - `fuzz [--cases N] [--seed S] [--jobs J] [--timeout SECS] [--mem-mib MIB] [--bin PATH]
//!   [--only GROUPS] [--skip GROUPS] [--keep]`: run the release `afsv` binary on N (default
//!   10,000) generated bad inputs and fail on any panic, hang, abort, non-finite output or
//!   modified input (see `fuzz.rs`).
//! - `slurm-test [--bin PATH]`: as root, install Debian's slurm-wlm and munge, start a
//!   single-node Slurm and run `scripts/slurm/optimize.sh` end to end for `afsv optimize
//!   afs` and a tiny `afsv optimize layout`; each report must equal the in-process run's
//!   (see `slurm.rs`); prints "skipped" without
//!   root, apt-get or network. `--bin` runs that `afsv` binary instead of building one.

mod commands;
mod fuzz;
mod slurm;

use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let result = match args.first().map(String::as_str) {
        Some("bench") => bench(&args[1..]),
        Some("validate") => validate(&args[1..]),
        Some("discover-matrix") => discover_matrix(&args[1..]),
        Some("fuzz") => fuzz::fuzz(&args[1..], &workspace_root()),
        Some("slurm-test") => slurm::slurm_test(&args[1..], &workspace_root()),
        Some("-h") | Some("--help") | None => {
            println!("{}", HELP);
            Ok(())
        }
        Some(other) => Err(format!("unknown task `{other}`\n{HELP}")),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("xtask: error: {e}");
            ExitCode::FAILURE
        }
    }
}

const HELP: &str = "usage: cargo xtask <task>\n\ntasks:\n  bench [--summary] [--commands] [--no-discovery] [--runs N] [--profile release|dist] [ARGS...]  run the criterion benches (ARGS go to the bench harness) and print mean times and real-time factors, then the whole discovery runs and whole afsv commands (median of N runs, default 20); --commands: only those; --no-discovery: without the discovery runs; --profile dist: built with fat LTO and one codegen unit (Cargo.toml)\n  validate [--fixtures DIR] [--out DIR] [--quick]  compare the models with fixtures/reported/ and write target/validation/report.md; --quick skips the chapter-6 design studies (Table 6.4, the GA of Table 6.5, the D4 sweep: about two minutes)\n  fuzz [--cases N] [--seed S] [--jobs J] [--timeout SECS] [--mem-mib MIB] [--bin PATH] [--only GROUPS] [--skip GROUPS] [--keep]  run afsv on N generated bad inputs (default 10000); fail on panics, hangs, aborts, non-finite output or modified inputs\n  discover-matrix [--vehicle3d]  run the discovery workflow on every catalogue effect of the strut and the yaw-plane vehicle and print the detection table (minutes); --vehicle3d: the 3-D adapter's rows instead (null and effect sets of the mild and realistic variants and of the independent 3-D implementation, rigid and with the front-axle HPS; about two hours of CPU, the crate-made HPS rows most of it)\n  slurm-test [--bin PATH]  as root: install slurm-wlm and munge, start a single-node Slurm, run scripts/slurm/optimize.sh end to end for `optimize afs` and a tiny `optimize layout` and compare each with the in-process optimum (skipped without root, apt-get or network); --bin: run that afsv binary instead of building one";

/// The full detection matrix of the discovery workflow (the slow tests of
/// `crates/afsv-discovery/tests/discover_matrix.rs`); with `--vehicle3d`, the 3-D adapter's
/// rows instead ([`VEHICLE3D_MATRIX`]).
fn discover_matrix(args: &[String]) -> Result<(), String> {
    let (tests, filters): (Vec<&str>, Vec<&str>) = match args {
        [] => (vec!["discover_matrix"], Vec::new()),
        [a] if a == "--vehicle3d" => (VEHICLE3D_MATRIX.to_vec(), VEHICLE3D_ROWS.to_vec()),
        _ => return Err(format!("discover-matrix takes only --vehicle3d\n{HELP}")),
    };
    let mut cmd = Command::new(std::env::var("CARGO").unwrap_or_else(|_| "cargo".into()));
    cmd.current_dir(workspace_root())
        .args(["test", "--release", "--workspace"]);
    for t in &tests {
        cmd.args(["--test", t]);
    }
    cmd.args(["--", "--ignored", "--nocapture", "--test-threads", "1"])
        .args(&filters);
    let status = cmd
        .status()
        .map_err(|e| format!("cannot run cargo test: {e}"))?;
    if status.success() {
        Ok(())
    } else {
        Err(format!("the detection matrix has failures ({status})"))
    }
}

/// The 3-D adapter's matrix: its records from the crate with the mild variant of unstated
/// choices, from the realistic variant, and from the independent 3-D implementation (rigid
/// front axle, and with the front-axle HPS).
const VEHICLE3D_MATRIX: [&str; 4] = [
    "discover_vehicle3d",
    "discover_vehicle3d_realistic",
    "discover_independent_vehicle3d",
    "discover_independent_vehicle3d_hps",
];

/// Name parts of the matrix rows among those binaries' ignored tests (the diagnostics and
/// the timing case are left out): a null set names nothing, an effect set names its effect.
const VEHICLE3D_ROWS: [&str; 3] = ["names_nothing", "name_nothing", "is_named_first"];

fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("xtask lives one level below the workspace root")
        .to_path_buf()
}

fn validate(args: &[String]) -> Result<(), String> {
    let root = workspace_root();
    let mut fixtures = root.join("fixtures").join("reported");
    let mut out = root.join("target").join("validation");
    let mut quick = false;
    let mut it = args.iter();
    while let Some(a) = it.next() {
        let mut value = || {
            it.next()
                .map(PathBuf::from)
                .ok_or_else(|| format!("`{a}` needs a directory"))
        };
        match a.as_str() {
            "--fixtures" => fixtures = value()?,
            "--out" => out = value()?,
            "--quick" => quick = true,
            other => return Err(format!("validate: unknown argument `{other}`")),
        }
    }
    let skip = if quick {
        afsv_validation::STUDY_CHECKS
    } else {
        &[]
    };
    let report = afsv_validation::run_skipping(&fixtures, skip).map_err(|e| e.to_string())?;
    print!("{}", report.table_text());
    afsv_validation::write_outputs(&report, &out).map_err(|e| e.to_string())?;
    println!("report: {}", out.join("report.md").display());
    for (name, e) in &report.failed_checks {
        eprintln!("xtask: check `{name}` failed: {e}");
    }
    let regs = report.regressions();
    if regs.is_empty() {
        Ok(())
    } else {
        let list: Vec<String> = regs
            .iter()
            .map(|r| format!("  {}: {}", r.label(), r.note))
            .collect();
        Err(format!(
            "{} quantities marked reproduced no longer are:\n{}",
            regs.len(),
            list.join("\n")
        ))
    }
}

fn bench(args: &[String]) -> Result<(), String> {
    let root = workspace_root();
    let mut args = args.to_vec();
    let runs = match args.iter().position(|a| a == "--runs") {
        Some(i) => {
            let n = args
                .get(i + 1)
                .and_then(|v| v.parse::<usize>().ok())
                .filter(|&n| (1..=1000).contains(&n))
                .ok_or("--runs needs a count from 1 to 1000")?;
            args.drain(i..i + 2);
            n
        }
        None => 20,
    };
    let profile = match args.iter().position(|a| a == "--profile") {
        Some(i) => {
            let name = args
                .get(i + 1)
                .filter(|p| ["release", "dist"].contains(&p.as_str()))
                .cloned()
                .ok_or("--profile needs release or dist")?;
            args.drain(i..i + 2);
            Some(name)
        }
        None => None,
    };
    if args.iter().any(|a| a == "--commands") {
        return commands::command_timings(&root, runs, profile.as_deref());
    }
    // this task's own switches; the rest go to the bench harnesses
    let summary_only = args.iter().any(|a| a == "--summary");
    let no_discovery = args.iter().any(|a| a == "--no-discovery");
    args.retain(|a| a != "--summary" && a != "--no-discovery");
    let args = &args[..];
    // A run lists what it measured; `--summary` lists every result on disk, the latest of
    // each bench (results of benches since removed or filtered out included).
    let since = (!summary_only).then(std::time::SystemTime::now);
    if !summary_only {
        let mut cmd = Command::new(std::env::var("CARGO").unwrap_or_else(|_| "cargo".into()));
        cmd.current_dir(&root)
            .args(["bench", "--workspace", "--exclude", "xtask", "--benches"]);
        if let Some(p) = &profile {
            cmd.args(["--profile", p]);
        }
        cmd.arg("--");
        cmd.args(args);
        let status = cmd
            .status()
            .map_err(|e| format!("cannot run cargo bench: {e}"))?;
        if !status.success() {
            return Err(format!("cargo bench failed ({status})"));
        }
    }
    let dir = root.join("target").join("criterion");
    let mut rows = Vec::new();
    collect(&dir, since, &mut rows)?;
    if rows.is_empty() {
        return Err(format!("no criterion results under {}", dir.display()));
    }
    rows.sort_by(|a, b| a.0.cmp(&b.0));
    println!(
        "{:<60} {:>14} {:>16}",
        "benchmark", "mean", "real-time factor"
    );
    for (id, ns) in rows {
        let rtf = sim_seconds(&id)
            .map(|s| format!("{:.0}x", s / (ns * 1e-9)))
            .unwrap_or_default();
        println!("{:<60} {:>14} {:>16}", id, human_time(ns), rtf);
    }
    if !summary_only && !no_discovery {
        discovery_rows(&root)?;
    }
    if !summary_only {
        commands::command_timings(&root, runs, profile.as_deref())?;
    }
    Ok(())
}

/// Whole discovery runs on independently generated records (64 vehicle records, the
/// 7-record strut programme), timed by an ignored test of the afsv-discovery crate.
fn discovery_rows(root: &std::path::Path) -> Result<(), String> {
    let out = Command::new(std::env::var("CARGO").unwrap_or_else(|_| "cargo".into()))
        .current_dir(root)
        .args([
            "test",
            "--release",
            "-q",
            "-p",
            "afsv-discovery",
            "--test",
            "discover_independent",
            "--",
            "--ignored",
            "--exact",
            "timing",
            "--nocapture",
        ])
        .output()
        .map_err(|e| format!("cannot run the discovery timing: {e}"))?;
    if !out.status.success() {
        return Err(format!(
            "discovery timing failed: {}",
            String::from_utf8_lossy(&out.stderr)
        ));
    }
    for line in String::from_utf8_lossy(&out.stdout).lines() {
        if let Some(row) = line.strip_prefix("bench-row ") {
            let (id, rest) = row.split_once(' ').unwrap_or((row, ""));
            println!("{id:<60} {rest}");
        }
    }
    Ok(())
}

/// Walk `target/criterion` for `new/estimates.json` + `new/benchmark.json` pairs, those
/// written at `since` or later when given.
fn collect(
    dir: &Path,
    since: Option<std::time::SystemTime>,
    rows: &mut Vec<(String, f64)>,
) -> Result<(), String> {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return Ok(());
    };
    for entry in entries.flatten() {
        let path = entry.path();
        if !path.is_dir() {
            continue;
        }
        if path.file_name().is_some_and(|n| n == "new") {
            let est = path.join("estimates.json");
            let meta = path.join("benchmark.json");
            let written = std::fs::metadata(&est).and_then(|m| m.modified());
            if since.is_some_and(|t| written.map_or(true, |w| w < t)) {
                continue;
            }
            if let (Ok(e), Ok(m)) = (
                std::fs::read_to_string(&est),
                std::fs::read_to_string(&meta),
            ) {
                let e: serde_json::Value =
                    serde_json::from_str(&e).map_err(|err| format!("{}: {err}", est.display()))?;
                let m: serde_json::Value =
                    serde_json::from_str(&m).map_err(|err| format!("{}: {err}", meta.display()))?;
                let ns = e["mean"]["point_estimate"].as_f64();
                let id = m["full_id"].as_str().map(str::to_string);
                if let (Some(ns), Some(id)) = (ns, id) {
                    rows.push((id, ns));
                }
            }
        } else if path.file_name().is_some_and(|n| n != "report") {
            collect(&path, since, rows)?;
        }
    }
    Ok(())
}

/// Simulated seconds encoded in a benchmark id as `_sim<N>s` (`p` for the decimal point).
fn sim_seconds(id: &str) -> Option<f64> {
    let last = id.rsplit('/').next()?;
    let pos = last.rfind("_sim")?;
    let tail = &last[pos + 4..];
    let num = tail.strip_suffix('s')?;
    num.replace('p', ".")
        .parse::<f64>()
        .ok()
        .filter(|v| *v > 0.0)
}

fn human_time(ns: f64) -> String {
    if ns < 1e3 {
        format!("{ns:.1} ns")
    } else if ns < 1e6 {
        format!("{:.2} µs", ns / 1e3)
    } else if ns < 1e9 {
        format!("{:.2} ms", ns / 1e6)
    } else {
        format!("{:.2} s", ns / 1e9)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_simulated_seconds() {
        assert_eq!(sim_seconds("yaw/yaw_pulse_sim10s"), Some(10.0));
        assert_eq!(sim_seconds("hps_8hz_sim1p25s"), Some(1.25));
        assert_eq!(sim_seconds("hps_8hz_sim1.25s"), Some(1.25));
        assert_eq!(sim_seconds("fiala_force"), None);
        assert_eq!(sim_seconds("x_simfoos"), None);
    }

    #[test]
    fn formats_times() {
        assert_eq!(human_time(12.0), "12.0 ns");
        assert_eq!(human_time(2.5e6), "2.50 ms");
    }
}
