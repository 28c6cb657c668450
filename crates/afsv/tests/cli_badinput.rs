//! Bad input on the command line: every case of the fuzz report is a one-line error (no
//! panic, no huge allocation, no hang), outputs never replace inputs, and no NaN, infinity
//! or unexplained `null` reaches stdout.

mod cli_support;
use cli_support::{afsv, json, scratch};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

fn tmp(name: &str) -> PathBuf {
    scratch("badinput", name)
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// `args` fail with one line on stderr that contains every needle, and no panic.
fn fails(args: &[&str], needles: &[&str]) {
    let t = Instant::now();
    let out = afsv(args);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "{args:?} succeeded");
    assert_eq!(
        out.status.code(),
        Some(if err.contains("invalid value") { 2 } else { 1 }),
        "{args:?}: {err}"
    );
    assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
    assert!(
        !err.contains("panicked") && !err.contains("internal error"),
        "{args:?}: {err}"
    );
    for n in needles {
        assert!(err.contains(n), "{args:?}: `{n}` not in {err}");
    }
    assert!(
        t.elapsed() < Duration::from_secs(10),
        "{args:?} took {:?}",
        t.elapsed()
    );
}

/// A short afsv-written yaw record (CSV + sidecar) at `name`.
fn yaw_record(name: &str) -> PathBuf {
    let p = tmp(name);
    json(&afsv(&["yaw", "simulate", "--duration", "2", "-o", s(&p)]));
    p
}

fn read(p: &Path) -> Vec<u8> {
    std::fs::read(p).unwrap()
}

#[test]
fn decay_window_outside_the_record_is_an_error_not_a_panic() {
    let rec = yaw_record("decay.csv");
    let base = [
        "measures",
        "decay",
        "-i",
        s(&rec),
        "--column",
        "articulation_deg",
    ];
    let with = |extra: &[&'static str]| {
        let mut v: Vec<&str> = base.to_vec();
        v.extend_from_slice(extra);
        v
    };
    fails(&with(&["--end-s=-1"]), &["fewer than 2 samples"]);
    fails(&with(&["--end-s", "0"]), &["fewer than 2 samples"]);
    fails(&with(&["--start-s", "5"]), &["fewer than 2 samples"]);
    fails(
        &with(&["--end-s", "nan"]),
        &["--end-s", "not a finite number"],
    );
    fails(
        &with(&["--start-s", "nan"]),
        &["--start-s", "not a finite number"],
    );
    fails(&with(&["--start-s", "inf"]), &["--start-s"]);
}

#[test]
fn sample_counts_are_bounded_before_allocation() {
    let o = tmp("big.csv");
    let o = s(&o);
    fails(
        &["yaw", "simulate", "--duration", "1e308", "-o", o],
        &["--duration 1e308", "at most 1e6 samples"],
    );
    fails(
        &["yaw", "simulate", "--duration", "9999999999", "-o", o],
        &["--duration", "at most 1e6"],
    );
    fails(
        &["yaw", "simulate", "--dt", "1e-320", "-o", o],
        &["--dt", "at most 1e6"],
    );
    fails(
        &["hps", "harmonic", "--cycles", "1e308"],
        &["--cycles 1e308", "at most 1e6"],
    );
    fails(
        &["hps", "harmonic", "--cycles", "9999999999"],
        &["--cycles", "at most 1e6"],
    );
    fails(
        &["hps", "harmonic", "--rate", "18446744073709551616"],
        &["--rate", "at most 1e6"],
    );
    fails(
        &["hps", "harmonic", "--freq", "1e-320"],
        &["--freq", "at most 1e6"],
    );
    fails(
        &["terrain", "generate", "--length", "1e12"],
        &["--length", "at most 1e7"],
    );
    assert!(!Path::new(o).exists());
}

#[test]
fn wbv_with_a_femtosecond_time_step_is_refused_quickly() {
    let p = tmp("fs.csv");
    let mut text = String::from("time_s,az_m_s2\n");
    for i in 0..200 {
        text += &format!("{:e},{}\n", i as f64 * 1e-14, (i as f64 * 0.3).sin());
    }
    std::fs::write(&p, text).unwrap();
    fails(&["measures", "wbv", "-i", s(&p)], &["fs_hz"]);
}

#[test]
fn non_finite_numbers_are_refused_for_every_numeric_option() {
    let rec = yaw_record("nonfinite.csv");
    let r = s(&rec);
    let cases: Vec<Vec<&str>> = vec![
        vec!["yaw", "simulate", "-o", "x.csv", "--speed-kmh"],
        vec!["yaw", "simulate", "-o", "x.csv", "--duration"],
        vec!["yaw", "simulate", "-o", "x.csv", "--dt"],
        vec!["yaw", "simulate", "-o", "x.csv", "--rtol"],
        vec!["yaw", "simulate", "-o", "x.csv", "--input-time"],
        vec!["yaw", "measures", "--speed-kmh"],
        vec!["yaw", "sensitivity", "--speed-kmh"],
        vec!["yaw", "leakage", "--steer-wheel-deg"],
        vec!["hps", "harmonic", "--freq"],
        vec!["hps", "harmonic", "--amp-mm"],
        vec!["hps", "harmonic", "--cycles"],
        vec!["hps", "harmonic", "--rate"],
        vec!["hps", "harmonic", "--gamma0"],
        vec!["hps", "characterize", "--gamma0"],
        vec!["hps", "identify", "-i", r, "--warmup"],
        vec!["tire", "sweep", "--fz", "1e5", "--c-slip"],
        vec!["tire", "sweep", "--fz", "1e5", "--u-max"],
        vec!["tire", "envelope", "--profile", r, "--radius"],
        vec!["tire", "envelope", "--profile", r, "--spacing-m"],
        vec!["terrain", "generate", "--length"],
        vec!["terrain", "generate", "--dx"],
        vec!["terrain", "psd", "-i", r, "--overlap"],
        vec!["terrain", "psd", "-i", r, "--track-width"],
        vec!["measures", "weighting", "-w", "wk", "--freqs", "1", "--fs"],
        vec!["measures", "weighting", "-w", "wk", "--freqs"],
        vec!["measures", "wbv", "-i", r, "--hours"],
        vec![
            "measures", "step", "-i", r, "--input", "a", "--output", "b", "--t-step",
        ],
        vec![
            "measures",
            "step",
            "-i",
            r,
            "--input",
            "a",
            "--output",
            "b",
            "--settle-fraction",
        ],
        vec!["measures", "check", "--iir-fs"],
        vec!["evaluate", "--speed-kmh"],
    ];
    for case in &cases {
        for bad in ["nan", "inf", "-inf", ""] {
            let mut args = case.clone();
            args.push(bad);
            let option = case.iter().rev().find(|a| a.starts_with("--")).unwrap();
            fails(&args, &[option]);
        }
    }
}

#[test]
fn silent_acceptances_are_errors() {
    let rec = yaw_record("silent.csv");
    fails(
        &["hps", "identify", "-i", s(&rec), "--warmup=-1"],
        &["--warmup", ">= 0"],
    );
    fails(&["tire", "sweep", "--fz", "-1"], &["--fz", "> 0"]);
    fails(&["tire", "sweep", "--fz", "0"], &["--fz", "> 0"]);
    fails(&["tire", "sweep", "--fz", "-10:10:5"], &["--fz", "> 0"]);
    fails(&["hps", "harmonic", "--amp-mm", "0"], &["--amp-mm", "> 0"]);
    fails(
        &["yaw", "simulate", "--duration", "0", "-o", "x.csv"],
        &["--duration"],
    );
}

#[test]
fn outputs_never_replace_inputs() {
    // A record replayed into its own name, by any spelling of it.
    let rec = yaw_record("in.csv");
    let before = (read(&rec), read(&rec.with_extension("json")));
    let spec = format!("csv:{}:steer_wheel_deg", s(&rec));
    fails(
        &["yaw", "simulate", "--input", &spec, "-o", s(&rec)],
        &["same file as the input --input"],
    );
    let dotted = rec.parent().unwrap().join(".").join("in.csv");
    fails(
        &["yaw", "simulate", "--input", &spec, "-o", s(&dotted)],
        &["same file"],
    );
    #[cfg(unix)]
    {
        let link = tmp("link.csv");
        std::os::unix::fs::symlink(&rec, &link).unwrap();
        fails(
            &["yaw", "simulate", "--input", &spec, "-o", s(&link)],
            &["same file"],
        );
    }
    // Its sidecar is an input too: another CSV whose sidecar is in.json.
    let other = rec.with_extension("json");
    let spec_json_side = format!("csv:{}:steer_wheel_deg", s(&rec));
    fails(
        &[
            "yaw",
            "simulate",
            "--input",
            &spec_json_side,
            "-o",
            s(&other),
        ],
        &["same file"],
    );
    assert_eq!((read(&rec), read(&rec.with_extension("json"))), before);

    // The parameter file is not replaced by a sidecar.
    let params = tmp("p.json");
    json(&afsv(&["params", "dump", "yaw-plane", "-o", s(&params)]));
    let p_before = read(&params);
    let csv = params.with_extension("csv");
    fails(
        &[
            "yaw",
            "simulate",
            "--params",
            s(&params),
            "-o",
            s(&csv),
            "--force",
        ],
        &["sidecar", "--params"],
    );
    assert_eq!(read(&params), p_before);
    assert!(!csv.exists());

    // Tire parameters are not replaced by an SVG.
    let t = tmp("t.json");
    std::fs::write(&t, "{}\n").unwrap();
    fails(
        &[
            "tire",
            "sweep",
            "--fz",
            "1e5",
            "--params",
            s(&t),
            "--plot",
            s(&t),
            "--force",
        ],
        &["--plot", "same file", "--params"],
    );
    assert_eq!(read(&t), b"{}\n");
}

#[test]
fn outputs_never_replace_each_other() {
    let y = tmp("y.json");
    fails(&["yaw", "simulate", "-o", s(&y)], &["sidecar", ".json"]);
    assert!(!y.exists());
    fails(&["terrain", "generate", "-o", s(&y)], &["sidecar", ".json"]);
    fails(&["hps", "harmonic", "-o", s(&y)], &["sidecar", ".json"]);
    let c = tmp("h.csv");
    fails(
        &[
            "hps",
            "harmonic",
            "-o",
            s(&c),
            "--plot",
            s(&c.with_extension("json")),
        ],
        &["same file"],
    );
    fails(
        &["hps", "harmonic", "-o", s(&c), "--plot", s(&c)],
        &["same file"],
    );
    assert!(!c.exists());
}

#[test]
fn foreign_files_need_force_and_foreign_sidecars_are_kept() {
    // A CSV afsv did not write needs --force.
    let csv = tmp("foreign.csv");
    std::fs::write(&csv, "mine\n1\n").unwrap();
    for args in [
        vec!["yaw", "simulate", "--duration", "1", "-o", s(&csv)],
        vec!["hps", "harmonic", "-o", s(&csv)],
        vec!["terrain", "generate", "-o", s(&csv)],
    ] {
        fails(&args, &["not written by afsv", "--force"]);
        assert_eq!(read(&csv), b"mine\n1\n");
    }
    json(&afsv(&["terrain", "generate", "-o", s(&csv), "--force"]));
    // Now afsv wrote it (its sidecar says so): re-running needs no --force.
    json(&afsv(&[
        "yaw",
        "simulate",
        "--duration",
        "1",
        "-o",
        s(&csv),
    ]));
    json(&afsv(&[
        "yaw",
        "simulate",
        "--duration",
        "1",
        "-o",
        s(&csv),
    ]));
    let side: serde_json::Value =
        serde_json::from_slice(&read(&csv.with_extension("json"))).unwrap();
    assert_eq!(side["written_by"], "afsv yaw simulate");

    // A JSON afsv did not write at the sidecar's name is never replaced, even with --force.
    let csv2 = tmp("keep.csv");
    let side2 = csv2.with_extension("json");
    std::fs::write(&side2, "{\"notes\": \"mine\"}\n").unwrap();
    for force in [false, true] {
        let mut args = vec!["hps", "harmonic", "-o", s(&csv2)];
        if force {
            args.push("--force");
        }
        fails(&args, &["sidecar", "never replaces"]);
    }
    assert_eq!(read(&side2), b"{\"notes\": \"mine\"}\n");
    assert!(!csv2.exists());

    // SVGs: afsv's own are replaced freely, others need --force.
    let svg = tmp("plot.svg");
    json(&afsv(&["tire", "sweep", "--fz", "1e5", "--plot", s(&svg)]));
    json(&afsv(&["tire", "sweep", "--fz", "1e5", "--plot", s(&svg)]));
    std::fs::write(&svg, "<svg/>").unwrap();
    fails(
        &["tire", "sweep", "--fz", "1e5", "--plot", s(&svg)],
        &["--force"],
    );
    fails(&["hps", "harmonic", "--plot", s(&svg)], &["--force"]);
    json(&afsv(&[
        "tire",
        "sweep",
        "--fz",
        "1e5",
        "--plot",
        s(&svg),
        "--force",
    ]));

    // Parameter files carry no marker: an existing one needs --force.
    let p = tmp("dump.json");
    std::fs::write(&p, "{}").unwrap();
    fails(&["params", "dump", "yaw-plane", "-o", s(&p)], &["--force"]);
    json(&afsv(&[
        "params",
        "dump",
        "yaw-plane",
        "-o",
        s(&p),
        "--force",
    ]));
}

#[test]
fn identify_honours_the_sidecar_strut_and_reports_a_fit_on_a_bound() {
    let rec = tmp("fa.csv");
    json(&afsv(&[
        "hps",
        "harmonic",
        "--strut",
        "front-axle",
        "--cycles",
        "3",
        "-o",
        s(&rec),
    ]));
    let v = json(&afsv(&["hps", "identify", "-i", s(&rec)]));
    assert_eq!(v["strut"], "front-axle");
    assert_eq!(v["strut_source"], "sidecar");
    assert_eq!(v["converged"], true, "{v}");
    fails(
        &["hps", "identify", "-i", s(&rec), "--strut", "lab-1orifice"],
        &["--strut", "front-axle"],
    );

    // Without the sidecar the record does not say which strut it is: no guess.
    let bare = tmp("bare.csv");
    std::fs::copy(&rec, &bare).unwrap();
    fails(
        &["hps", "identify", "-i", s(&bare)],
        &["--strut", "bare.csv"],
    );
    // The lab strut fitted to front-axle data ends on bounds and worse in force: the
    // result is printed, says so, and the exit status (3) says it was not earned.
    let out = afsv(&["hps", "identify", "-i", s(&bare), "--strut", "lab-1orifice"]);
    assert_eq!(out.status.code(), Some(3), "{out:?}");
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["strut_source"], "--strut");
    assert_eq!(v["converged"], false, "{v}");
    let problems = v["problems"].to_string();
    assert!(problems.contains("bound"), "{problems}");
    assert!(v["fitted"]
        .as_array()
        .unwrap()
        .iter()
        .any(|f| f["at_bound"] != "no"));
    assert!(String::from_utf8_lossy(&out.stderr).contains("afsv: not earned: hps identify"));
    // A strut file is accepted wherever a built-in strut is.
    let strut = tmp("my-strut.json");
    json(&afsv(&[
        "params",
        "dump",
        "strut",
        "-o",
        s(&strut),
        "--force",
    ]));
    let v = json(&afsv(&[
        "hps",
        "identify",
        "-i",
        s(&bare),
        "--strut",
        s(&strut),
    ]));
    assert_eq!(v["converged"], true, "{v}");
}

#[test]
fn stdout_has_no_unexplained_null() {
    let rec = yaw_record("nulls.csv");
    for args in [
        vec![
            "measures",
            "weighting",
            "-w",
            "wk",
            "--freqs",
            "0.5,100,400",
            "--fs",
            "200",
        ],
        vec![
            "hps", "harmonic", "--freq", "0.1", "--amp-mm", "1", "--cycles", "1",
        ],
        vec![
            "tire",
            "sweep",
            "--fz",
            "1e5",
            "--alpha-deg",
            "0:1:1",
            "--kappa",
            "-1:1:1",
        ],
        vec![
            "measures",
            "decay",
            "-i",
            s(&rec),
            "--column",
            "articulation_deg",
        ],
        vec!["yaw", "measures"],
    ] {
        let out = afsv(&args);
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(
            !text.contains("NaN") && !text.contains("inf"),
            "{args:?}: {text}"
        );
        if out.status.success() {
            let v: serde_json::Value = serde_json::from_str(&text).unwrap();
            assert!(
                afsv::output::unexplained_nulls(&v).is_empty(),
                "{args:?}: {v}"
            );
        }
    }
}

#[test]
fn a_column_name_with_line_breaks_gives_a_one_line_error() {
    // A quoted header field that runs over several lines becomes a column name with
    // line breaks (the reader accepts it); the message shows them escaped.
    let p = tmp("quoted.csv");
    std::fs::write(&p, "\"x_m\",\"left_m\",\"right_m\n0, 1, 2\"\n").unwrap();
    fails(
        &["tire", "envelope", "--profile", s(&p), "--track", "right"],
        &["right_m\\n0"],
    );
}
