//! `cargo xtask fuzz [--cases N] [--seed S] [--jobs J] [--timeout SECS] [--mem-mib MIB]
//! [--bin PATH] [--only GROUP,...] [--skip GROUP,...] [--keep]`: bad input across the CLI.
//!
//! Generates `N` (default 10,000) cases from the seed, each a command line of one `afsv`
//! subcommand that reads a file or a number plus the files it reads: bad CSVs (wrong
//! headers, NaN/inf cells, huge and tiny time steps, BOMs, ragged rows, 0 and 1 rows, ...),
//! bad sidecars, bad parameter JSONs and bad option values (nan, inf, -1, 0, 1e308,
//! 1e-320, 2^64, empty, ...), and output names that collide with inputs. Every case runs
//! the release binary in its own scratch folder (`target/fuzz/`) with a timeout (20 s; three
//! times that for the iterative fits of `SLOW_GROUPS`) and an
//! address-space limit (`ulimit -v` through `sh`), and is classified as
//!
//! - a clean rejection: exit 1 or 2 with one `afsv: error:` line on stderr;
//! - a success: exit 0, with no NaN/inf in stdout or the files written and no JSON `null`
//!   without a reason (`afsv::output::unexplained_nulls`);
//! - a failure: a panic, a hang (timeout), an abort (signal, allocation failure), a
//!   non-finite output, or an input file modified (inputs are hashed before and after).
//!
//! Prints the counts and per-group table, lists the failures with their command lines
//! (their folders are kept), and exits non-zero when there is any failure. The same seed
//! gives the same cases, whatever `--jobs`.

mod cases;
mod gen;
mod run;

use cases::{make_case, GROUPS};
use run::{quote, run_case, Outcome, Result1, SLOW_GROUPS};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

pub(crate) struct Opts {
    pub(crate) cases: usize,
    pub(crate) seed: u64,
    pub(crate) jobs: usize,
    pub(crate) timeout: Duration,
    pub(crate) mem_mib: u64,
    pub(crate) bin: Option<PathBuf>,
    pub(crate) only: Vec<String>,
    pub(crate) skip: Vec<String>,
    pub(crate) keep: bool,
}

pub(crate) fn parse_opts(args: &[String]) -> Result<Opts, String> {
    let mut o = Opts {
        cases: 10_000,
        seed: 1,
        jobs: std::thread::available_parallelism().map_or(2, |n| n.get().min(4)),
        timeout: Duration::from_secs(20),
        mem_mib: 4096,
        bin: None,
        only: Vec::new(),
        skip: Vec::new(),
        keep: false,
    };
    let mut it = args.iter();
    while let Some(a) = it.next() {
        let mut val = || {
            it.next()
                .cloned()
                .ok_or_else(|| format!("fuzz: `{a}` needs a value"))
        };
        let num = |s: String| -> Result<u64, String> {
            s.parse::<u64>()
                .map_err(|_| format!("fuzz: `{a}`: `{s}` is not a whole number"))
        };
        match a.as_str() {
            "--cases" => o.cases = num(val()?)? as usize,
            "--seed" => o.seed = num(val()?)?,
            "--jobs" => o.jobs = (num(val()?)? as usize).max(1),
            "--timeout" => o.timeout = Duration::from_secs(num(val()?)?.max(1)),
            "--mem-mib" => o.mem_mib = num(val()?)?.max(64),
            "--bin" => o.bin = Some(PathBuf::from(val()?)),
            "--only" => o.only = val()?.split(',').map(str::to_string).collect(),
            "--skip" => o.skip = val()?.split(',').map(str::to_string).collect(),
            "--keep" => o.keep = true,
            other => return Err(format!("fuzz: unknown argument `{other}`")),
        }
    }
    Ok(o)
}

/// Run the fuzz suite (module documentation).
pub fn fuzz(args: &[String], root: &Path) -> Result<(), String> {
    let opts = parse_opts(args)?;
    let bin = match &opts.bin {
        Some(b) => b.clone(),
        None => {
            let status = Command::new(std::env::var("CARGO").unwrap_or_else(|_| "cargo".into()))
                .current_dir(root)
                .args(["build", "--quiet", "--release", "-p", "afsv"])
                .status()
                .map_err(|e| format!("cannot run cargo build: {e}"))?;
            if !status.success() {
                return Err(format!("cargo build -p afsv --release failed ({status})"));
            }
            root.join("target").join("release").join("afsv")
        }
    };
    let bin = std::fs::canonicalize(&bin).map_err(|e| format!("{}: {e}", bin.display()))?;
    let groups: Vec<(&'static str, u32)> = GROUPS
        .iter()
        .copied()
        .filter(|(g, _)| {
            let key = g.split(' ').next().unwrap_or(g);
            let hit = |list: &[String]| list.iter().any(|s| s == g || s == key);
            (opts.only.is_empty() || hit(&opts.only)) && !hit(&opts.skip)
        })
        .collect();
    if groups.is_empty() {
        return Err("fuzz: --only/--skip leave no group".into());
    }
    let yaw_params = Command::new(&bin)
        .args(["params", "dump", "yaw-plane"])
        .output()
        .map_err(|e| format!("cannot run {}: {e}", bin.display()))?;
    let yaw_params = String::from_utf8(yaw_params.stdout).map_err(|e| e.to_string())?;
    let truck_params = Command::new(&bin)
        .args(["params", "dump", "truck"])
        .output()
        .map_err(|e| format!("cannot run {}: {e}", bin.display()))?;
    let truck_params = String::from_utf8(truck_params.stdout).map_err(|e| e.to_string())?;
    let scratch = root
        .join("target")
        .join("fuzz")
        .join(format!("seed-{}", opts.seed));
    let _ = std::fs::remove_dir_all(&scratch);
    std::fs::create_dir_all(&scratch).map_err(|e| format!("{}: {e}", scratch.display()))?;
    println!(
        "fuzz: {} cases, seed {}, {} jobs, timeout {:?} ({} x3), memory limit {} MiB, binary {}",
        opts.cases,
        opts.seed,
        opts.jobs,
        opts.timeout,
        SLOW_GROUPS.join(", "),
        opts.mem_mib,
        bin.display()
    );
    let t0 = Instant::now();
    let results = run_all(&opts, &bin, &scratch, &groups, &yaw_params, &truck_params);
    let elapsed = t0.elapsed();
    print_summary(&results, elapsed);
    let failures: Vec<&Result1> = results.iter().filter(|r| r.outcome.failed()).collect();
    if failures.is_empty() {
        if !opts.keep {
            let _ = std::fs::remove_dir_all(&scratch);
        }
        return Ok(());
    }
    println!();
    for r in failures.iter().take(40) {
        println!(
            "{:?} case {} ({}): afsv {}\n    {}",
            r.outcome,
            r.id,
            scratch.join(format!("case-{:05}", r.id)).display(),
            quote(&r.args),
            r.detail
        );
    }
    if failures.len() > 40 {
        println!("... and {} more", failures.len() - 40);
    }
    Err(format!(
        "{} of {} cases failed",
        failures.len(),
        results.len()
    ))
}

/// Run the cases on `opts.jobs` threads; the results in case order.
fn run_all(
    opts: &Opts,
    bin: &Path,
    scratch: &Path,
    groups: &[(&'static str, u32)],
    yaw_params: &str,
    truck_params: &str,
) -> Vec<Result1> {
    let t0 = Instant::now();
    let next = AtomicUsize::new(0);
    let done = AtomicUsize::new(0);
    let results = Mutex::new(Vec::with_capacity(opts.cases));
    std::thread::scope(|s| {
        for _ in 0..opts.jobs {
            s.spawn(|| loop {
                let id = next.fetch_add(1, Ordering::Relaxed);
                if id >= opts.cases {
                    break;
                }
                let case = make_case(opts.seed, id, groups, yaw_params, truck_params);
                let dir = scratch.join(format!("case-{id:05}"));
                let started = Instant::now();
                let (outcome, detail, multi_line) = run_case(bin, &dir, &case, opts);
                let seconds = started.elapsed().as_secs_f64();
                if !outcome.failed() && !opts.keep {
                    let _ = std::fs::remove_dir_all(&dir);
                }
                results.lock().unwrap().push(Result1 {
                    id,
                    group: case.group,
                    outcome,
                    detail,
                    args: case.args,
                    multi_line,
                    seconds,
                });
                let n = done.fetch_add(1, Ordering::Relaxed) + 1;
                if n.checked_rem(1000) == Some(0) {
                    eprintln!(
                        "fuzz: {n}/{} cases, {:.0} s",
                        opts.cases,
                        t0.elapsed().as_secs_f64()
                    );
                }
            });
        }
    });
    let mut results = results.into_inner().unwrap();
    results.sort_by_key(|r| r.id);
    results
}

/// Print the counts, the slowest case and the per-group table.
fn print_summary(results: &[Result1], elapsed: Duration) {
    let count = |o: Outcome| results.iter().filter(|r| r.outcome == o).count();
    println!();
    println!("cases                 {}", results.len());
    println!("clean rejections      {}", count(Outcome::Rejected));
    println!("successes             {}", count(Outcome::Success));
    println!("panics                {}", count(Outcome::Panic));
    println!("hangs                 {}", count(Outcome::Hang));
    println!("aborts/crashes        {}", count(Outcome::Abort));
    println!("non-finite outputs    {}", count(Outcome::NonFinite));
    println!("input files modified  {}", count(Outcome::Modified));
    println!(
        "multi-line errors     {} (not a failure)",
        results.iter().filter(|r| r.multi_line).count()
    );
    for r in results.iter().filter(|r| r.multi_line).take(5) {
        println!(
            "    multi-line error, case {}: afsv {}\n        {}",
            r.id,
            quote(&r.args),
            r.detail
        );
    }
    if let Some(slow) = results
        .iter()
        .max_by(|a, b| a.seconds.total_cmp(&b.seconds))
    {
        println!(
            "slowest case          {:.1} s (case {}, {})",
            slow.seconds, slow.id, slow.group
        );
    }
    println!("time                  {:.1} s", elapsed.as_secs_f64());
    println!();
    let mut table: BTreeMap<&str, [usize; 3]> = BTreeMap::new();
    for r in results {
        let row = table.entry(r.group).or_default();
        match r.outcome {
            Outcome::Rejected => row[0] += 1,
            Outcome::Success => row[1] += 1,
            _ => row[2] += 1,
        }
    }
    println!(
        "{:<20} {:>8} {:>8} {:>8}",
        "group", "rejected", "success", "FAILED"
    );
    for (g, [a, b, c]) in &table {
        println!("{g:<20} {a:>8} {b:>8} {c:>8}");
    }
}

#[cfg(test)]
mod tests {
    use super::run::non_finite_token;
    use super::*;

    #[test]
    fn cases_are_reproducible_and_cover_every_group() {
        let p = "{\"a\": 1.5, \"b\": [2, 3]}";
        let a: Vec<String> = (0..300)
            .map(|i| make_case(7, i, GROUPS, p, p).args.join(" "))
            .collect();
        let b: Vec<String> = (0..300)
            .map(|i| make_case(7, i, GROUPS, p, p).args.join(" "))
            .collect();
        assert_eq!(a, b);
        let groups: std::collections::BTreeSet<&str> = (0..3000)
            .map(|i| make_case(1, i, GROUPS, p, p).group)
            .collect();
        assert_eq!(groups.len(), GROUPS.len());
    }

    #[test]
    fn finds_non_finite_words_only() {
        assert!(non_finite_token("x = NaN").is_some());
        assert!(non_finite_token("[1, inf]").is_some());
        assert!(non_finite_token("-infinity").is_some());
        assert!(non_finite_token("information, infer, nano, finance").is_none());
    }
}
