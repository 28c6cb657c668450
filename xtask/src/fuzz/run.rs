//! Running one case: the binary in its own scratch folder with a timeout and a memory
//! limit, classified as a clean rejection, a success or a failure.

use super::gen::Case;
use super::Opts;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum Outcome {
    Rejected,
    Success,
    Panic,
    Hang,
    Abort,
    NonFinite,
    Modified,
}

impl Outcome {
    pub(crate) fn failed(self) -> bool {
        !matches!(self, Outcome::Rejected | Outcome::Success)
    }
}

pub(crate) struct Result1 {
    pub(crate) id: usize,
    pub(crate) group: &'static str,
    pub(crate) outcome: Outcome,
    pub(crate) detail: String,
    pub(crate) args: Vec<String>,
    pub(crate) multi_line: bool,
    pub(crate) seconds: f64,
}

pub(crate) fn fnv(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325u64, |h, b| {
        (h ^ *b as u64).wrapping_mul(0x100_0000_01b3)
    })
}

/// `NaN`, `inf` or `infinity` as a word of `text` (not inside a longer word).
pub(crate) fn non_finite_token(text: &str) -> Option<String> {
    let lower = text.to_ascii_lowercase();
    for tok in ["nan", "inf"] {
        let mut from = 0;
        while let Some(i) = lower[from..].find(tok) {
            let s = from + i;
            let before = lower[..s].chars().next_back();
            let mut e = s + tok.len();
            if tok == "inf" && lower[e..].starts_with("inity") {
                e += 5;
            }
            let after = lower[e..].chars().next();
            let word = |c: Option<char>| c.is_some_and(|c| c.is_ascii_alphanumeric() || c == '_');
            if !word(before) && !word(after) {
                let lo = s.saturating_sub(30);
                return Some(text[lo..(e + 30).min(text.len())].to_string());
            }
            from = e;
        }
    }
    None
}

/// Groups whose successes are iterative fits (identification, discovery, sweeps of many
/// simulations): a well-formed but hard record may take several seconds, so they get
/// three times the timeout.
pub(crate) const SLOW_GROUPS: &[&str] = &[
    "hps identify",
    "discover",
    "synth",
    "yaw sensitivity",
    "evaluate",
];

pub(crate) fn timeout_of(group: &str, opts: &Opts) -> Duration {
    if SLOW_GROUPS.contains(&group) {
        opts.timeout * 3
    } else {
        opts.timeout
    }
}

pub(crate) fn run_case(
    bin: &Path,
    dir: &Path,
    case: &Case,
    opts: &Opts,
) -> (Outcome, String, bool) {
    let timeout = timeout_of(case.group, opts);
    let _ = std::fs::remove_dir_all(dir);
    std::fs::create_dir_all(dir).expect("scratch folder");
    let mut hashes = Vec::new();
    for (name, bytes) in &case.files {
        let p = dir.join(name);
        std::fs::write(&p, bytes).expect("write case file");
        hashes.push((name.clone(), fnv(bytes)));
    }
    let out_path = dir.join(".stdout");
    let err_path = dir.join(".stderr");
    let script = format!(
        "ulimit -v {} 2>/dev/null; exec \"$0\" \"$@\"",
        opts.mem_mib * 1024
    );
    let child = Command::new("sh")
        .arg("-c")
        .arg(script)
        .arg(bin)
        .args(&case.args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(std::fs::File::create(&out_path).expect("stdout file"))
        .stderr(std::fs::File::create(&err_path).expect("stderr file"))
        .spawn();
    let mut child = match child {
        Ok(c) => c,
        Err(e) => return (Outcome::Abort, format!("cannot start: {e}"), false),
    };
    let start = Instant::now();
    let mut nap = Duration::from_micros(500);
    let status = loop {
        match child.try_wait() {
            Ok(Some(s)) => break Some(s),
            Ok(None) if start.elapsed() > timeout => {
                let _ = child.kill();
                let _ = child.wait();
                break None;
            }
            Ok(None) => {
                std::thread::sleep(nap);
                nap = (nap * 2).min(Duration::from_millis(20));
            }
            Err(e) => return (Outcome::Abort, format!("wait: {e}"), false),
        }
    };
    let stdout = std::fs::read(&out_path).unwrap_or_default();
    let stderr =
        String::from_utf8_lossy(&std::fs::read(&err_path).unwrap_or_default()).into_owned();
    // Progress lines (`afsv yaw sensitivity: 3/34 ...`, afsv::progress) may precede an error.
    let stderr: String = stderr
        .lines()
        .filter(|l| !is_progress_line(l))
        .map(|l| format!("{l}\n"))
        .collect();
    let first_err = stderr.lines().next().unwrap_or("").to_string();
    // Inputs must be as they were.
    for (name, h) in &hashes {
        match std::fs::read(dir.join(name)) {
            Ok(b) if fnv(&b) == *h => {}
            Ok(_) => {
                return (
                    Outcome::Modified,
                    format!("{name} was modified; {first_err}"),
                    false,
                )
            }
            Err(_) => {
                return (
                    Outcome::Modified,
                    format!("{name} was removed; {first_err}"),
                    false,
                )
            }
        }
    }
    let Some(status) = status else {
        return (Outcome::Hang, format!("no exit after {timeout:?}"), false);
    };
    if stderr.contains("panicked") || stderr.contains("internal error") {
        return (Outcome::Panic, first_err, false);
    }
    #[cfg(unix)]
    {
        use std::os::unix::process::ExitStatusExt;
        if let Some(sig) = status.signal() {
            return (Outcome::Abort, format!("signal {sig}; {first_err}"), false);
        }
    }
    // Exit 3: the result is printed but the command says it was not earned (a fit on a
    // bound); `afsv discover` reports its outcome in the exit code (3 model-form
    // discrepancy, 4 nothing missing; docs/discovery.md). Either way the output must be as
    // clean as a success's.
    let code = status.code();
    let printed = code == Some(0)
        || (code == Some(3) && first_err.starts_with("afsv: not earned:"))
        || (matches!(code, Some(3 | 4)) && case.group == "discover");
    match code {
        _ if printed => {
            let text = String::from_utf8_lossy(&stdout);
            if let Some(t) = non_finite_token(&text) {
                return (Outcome::NonFinite, format!("stdout: ...{t}..."), false);
            }
            if let Ok(v) = serde_json::from_slice::<serde_json::Value>(&stdout) {
                let nulls = afsv::output::unexplained_nulls(&v);
                if !nulls.is_empty() {
                    return (
                        Outcome::NonFinite,
                        format!(
                            "null without reason at {}",
                            nulls[..nulls.len().min(3)].join(", ")
                        ),
                        false,
                    );
                }
            }
            // Files the command wrote (CSV, sidecars, reports) carry no NaN/inf either.
            if let Some(d) = written_non_finite(dir, &case.files) {
                return (Outcome::NonFinite, d, false);
            }
            (Outcome::Success, String::new(), false)
        }
        Some(1) | Some(2) if first_err.starts_with("afsv: error:") => {
            let multi = stderr.trim_end().lines().count() > 1;
            if multi {
                let all: String = stderr.chars().take(300).collect();
                (Outcome::Rejected, format!("{all:?}"), true)
            } else {
                (Outcome::Rejected, first_err, false)
            }
        }
        Some(c) => (Outcome::Abort, format!("exit {c}; {first_err}"), false),
        None => (Outcome::Abort, first_err, false),
    }
}

/// A progress line of `afsv::progress`: `afsv SUBCOMMAND...: N/TOTAL ... elapsed...`
/// (errors start with `afsv:`).
fn is_progress_line(line: &str) -> bool {
    line.starts_with("afsv ") && line.contains(" elapsed")
}

pub(crate) fn written_non_finite(dir: &Path, inputs: &[(String, Vec<u8>)]) -> Option<String> {
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).ok()?.flatten() {
            let p = e.path();
            if p.is_dir() {
                stack.push(p);
                continue;
            }
            let name = p.strip_prefix(dir).ok()?.to_string_lossy().into_owned();
            if name.starts_with(".std") || inputs.iter().any(|(n, _)| *n == name) {
                continue;
            }
            if !(name.ends_with(".csv") || name.ends_with(".json") || name.ends_with(".md")) {
                continue;
            }
            let text = std::fs::read_to_string(&p).unwrap_or_default();
            if let Some(t) = non_finite_token(&text) {
                return Some(format!("{name}: ...{t}..."));
            }
        }
    }
    None
}

pub(crate) fn quote(args: &[String]) -> String {
    args.iter()
        .map(|a| {
            if !a.is_empty()
                && a.chars()
                    .all(|c| c.is_ascii_alphanumeric() || "-_.,:=/+".contains(c))
            {
                a.clone()
            } else {
                format!("'{}'", a.replace('\'', "'\\''"))
            }
        })
        .collect::<Vec<_>>()
        .join(" ")
}
