//! Whole-command timings of `cargo xtask bench`: what users run, timed as they run it. The
//! release `afsv` binary is built, then each command is run `runs` times (after one
//! unmeasured warm-up run) in a scratch folder, like hyperfine; the table gives the median,
//! the fastest and the slowest wall time, and for the simulation studies the median per
//! simulation (two runs, a pulse and a step, per configuration of the yaw measures).

use std::path::Path;
use std::process::{Command, Stdio};
use std::time::Instant;

/// One timed command: its label, its arguments and how many simulations it runs.
struct Timed {
    label: &'static str,
    args: Vec<String>,
    simulations: Option<usize>,
}

fn commands(samples: &Path) -> Vec<Timed> {
    let sample = |f: &str| samples.join(f).to_string_lossy().into_owned();
    let v = |a: &[&str]| a.iter().map(|s| s.to_string()).collect::<Vec<String>>();
    vec![
        Timed {
            label: "yaw measures (pulse + step)",
            args: v(&["yaw", "measures"]),
            simulations: Some(2),
        },
        Timed {
            label: "yaw sensitivity (4 params x 4 levels x 2 loads)",
            args: v(&["yaw", "sensitivity"]),
            simulations: Some(68),
        },
        Timed {
            label: "yaw simulate pulse -o (10 s, 200 Hz record)",
            args: v(&["yaw", "simulate", "--input", "pulse", "-o", "pulse.csv"]),
            simulations: Some(1),
        },
        Timed {
            label: "hps characterize (lab programme, 7 records)",
            args: v(&["hps", "characterize", "--strut", "lab-1orifice"]),
            simulations: Some(7),
        },
        Timed {
            label: "hps identify samples/strut-bench-1hz (n,gamma0,cb)",
            args: vec![
                "hps".into(),
                "identify".into(),
                "-i".into(),
                sample("strut-bench-1hz.csv"),
                "--fit".into(),
                "n,gamma0,cb".into(),
            ],
            simulations: None,
        },
        Timed {
            label: "measures wbv samples/path-change-accel",
            args: vec![
                "measures".into(),
                "wbv".into(),
                "-i".into(),
                sample("path-change-accel.csv"),
                "--channel".into(),
                "y=lateral_accel_front_m_s2".into(),
            ],
            simulations: None,
        },
        Timed {
            label: "evaluate --json",
            args: v(&["evaluate", "--json"]),
            simulations: None,
        },
    ]
}

/// Build the binary (`profile`: release by default, or dist) and print the whole-command
/// table.
pub fn command_timings(root: &Path, runs: usize, profile: Option<&str>) -> Result<(), String> {
    let profile = profile.unwrap_or("release");
    let status = Command::new(std::env::var("CARGO").unwrap_or_else(|_| "cargo".into()))
        .current_dir(root)
        .args(["build", "--profile", profile, "-q", "-p", "afsv"])
        .status()
        .map_err(|e| format!("cannot build afsv: {e}"))?;
    if !status.success() {
        return Err(format!("cargo build -p afsv failed ({status})"));
    }
    let bin = root.join("target").join(profile).join("afsv");
    let dir = std::env::temp_dir().join(format!("afsv-bench-{}", std::process::id()));
    std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    println!();
    println!(
        "{:<52} {:>10} {:>10} {:>10} {:>14}",
        format!("command ({runs} runs, median)"),
        "median",
        "min",
        "max",
        "per simulation"
    );
    for c in commands(&root.join("samples")) {
        let mut times = Vec::with_capacity(runs);
        for i in 0..=runs {
            let t0 = Instant::now();
            let status = Command::new(&bin)
                .arg("--quiet")
                .args(&c.args)
                .current_dir(&dir)
                .stdout(Stdio::null())
                .stderr(Stdio::null())
                .status()
                .map_err(|e| format!("cannot run {}: {e}", bin.display()))?;
            let dt = t0.elapsed().as_secs_f64();
            if !status.success() {
                return Err(format!("afsv {} failed ({status})", c.args.join(" ")));
            }
            if i > 0 {
                times.push(dt);
            }
        }
        let (med, lo, hi) = stats(&mut times);
        let per_sim = c
            .simulations
            .map(|n| super::human_time(med * 1e9 / n as f64))
            .unwrap_or_default();
        println!(
            "{:<52} {:>10} {:>10} {:>10} {:>14}",
            c.label,
            super::human_time(med * 1e9),
            super::human_time(lo * 1e9),
            super::human_time(hi * 1e9),
            per_sim
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
    Ok(())
}

/// Median, minimum and maximum of `t` (sorted in place; `t` is not empty).
fn stats(t: &mut [f64]) -> (f64, f64, f64) {
    t.sort_by(f64::total_cmp);
    let n = t.len();
    let med = if n % 2 == 1 {
        t[n / 2]
    } else {
        0.5 * (t[n / 2 - 1] + t[n / 2])
    };
    (med, t[0], t[n - 1])
}

#[cfg(test)]
mod tests {
    use super::stats;

    #[test]
    fn median_min_max() {
        assert_eq!(stats(&mut [3.0, 1.0, 2.0]), (2.0, 1.0, 3.0));
        assert_eq!(stats(&mut [4.0, 1.0, 2.0, 3.0]), (2.5, 1.0, 4.0));
        assert_eq!(stats(&mut [5.0]), (5.0, 5.0, 5.0));
    }
}
