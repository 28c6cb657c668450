//! `afsv yaw` and `afsv params` end to end.

mod cli_support;
use cli_support::scratch;

/// Run `afsv`: (success, stdout, stderr).
fn afsv(args: &[&str]) -> (bool, String, String) {
    let out = cli_support::afsv(args);
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn simulate_writes_record_with_design_columns_and_sidecar() {
    let out = tmp("pulse.csv");
    let (ok, stdout, err) = afsv(&[
        "yaw",
        "simulate",
        "--load",
        "loaded",
        "--speed-kmh",
        "50",
        "--input",
        "pulse",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    assert_eq!(v["samples"], 2001);
    let rec = afsv_records::Record::read(&out).unwrap();
    for c in [
        "time_s",
        "steer_wheel_deg",
        "speed_m_s",
        "articulation_deg",
        "strut_left_disp_m",
        "p_c_pa",
        "p_r_pa",
        "yaw_rate_front_deg_s",
    ] {
        assert!(rec.column(c).is_some(), "missing {c}");
    }
    assert_eq!(rec.meta["sign_convention"], "afsv-v1");
    assert_eq!(rec.meta["load"], "loaded");
    // Positive pulse = right-hand turn: the first articulation swing is positive and the
    // left strut extends.
    let a = rec.column("articulation_deg").unwrap();
    let first = a.iter().find(|v| v.abs() > 0.05).copied().unwrap();
    assert!(first > 0.0);
    let d = rec.column("strut_left_disp_m").unwrap();
    let i = a.iter().position(|v| v.abs() > 0.05).unwrap();
    assert!(d[i] > 0.0);

    // The record's steering column replays as a measured input.
    let out2 = tmp("replay.csv");
    let spec = format!("csv:{}:steer_wheel_deg", out.display());
    let (ok, _, err) = afsv(&[
        "yaw",
        "simulate",
        "--input",
        &spec,
        "-o",
        out2.to_str().unwrap(),
    ]);
    assert!(ok, "{err}");
    let b = afsv_records::Record::read(&out2).unwrap();
    let pa = a.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let pb = b
        .column("articulation_deg")
        .unwrap()
        .iter()
        .fold(0.0f64, |m, v| m.max(v.abs()));
    assert!((pa - pb).abs() < 0.1 * pa, "{pa} vs {pb}");
}

#[test]
fn measures_and_sensitivity_print_json() {
    let (ok, stdout, err) = afsv(&["yaw", "measures", "--load", "unloaded", "--speed-kmh", "50"]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    for k in [
        "natural_frequency_hz",
        "damping_ratio",
        "steering_gain",
        "rise_time_s",
        "overshoot_percent",
        "power_efficiency",
    ] {
        assert!(v[k].as_f64().unwrap().is_finite(), "{k}");
    }
    // the hydraulic steering's free response is not one decaying mode: the fit says so
    let ratio =
        v["decay_fit_rmse_deg"].as_f64().unwrap() / v["decay_fit_noise_rms_deg"].as_f64().unwrap();
    assert!(ratio > 3.0, "{ratio}");
    assert!(v["decay_fit_caveat"]
        .as_str()
        .unwrap()
        .contains("not one decaying mode"));
    let (ok, stdout, err) = afsv(&["yaw", "measures", "--form", "paper-eq-3-13"]);
    assert!(ok, "{err}");
    let p: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    assert_eq!(p["form"], "paper_eq_3_13");

    let (ok, stdout, err) = afsv(&["yaw", "sensitivity", "--table"]);
    assert!(ok, "{err}");
    assert!(stdout.contains("B_eff") && stdout.contains("unloaded"));
    assert!(stdout.contains("energy-consistent Eq 3.13") && !stdout.contains("EnergyConsistent"));
    assert_eq!(
        stdout.lines().filter(|l| l.starts_with("loaded ")).count(),
        16
    );
}

#[test]
fn params_dump_load_and_validation() {
    let file = tmp("params.json");
    let (ok, _, err) = afsv(&[
        "params",
        "dump",
        "yaw-plane",
        "--load",
        "unloaded",
        "-o",
        file.to_str().unwrap(),
    ]);
    assert!(ok, "{err}");
    let (ok, stdout, _) = afsv(&["params", "check", "yaw-plane", file.to_str().unwrap()]);
    assert!(ok && stdout.contains("\"valid\": true"));
    // Loading the dumped set gives the same measures as --load unloaded.
    let (_, a, _) = afsv(&["yaw", "measures", "--load", "unloaded"]);
    let (ok, b, err) = afsv(&["yaw", "measures", "--params", file.to_str().unwrap()]);
    assert!(ok, "{err}");
    let (a, b): (serde_json::Value, serde_json::Value) = (
        serde_json::from_str(&a).unwrap(),
        serde_json::from_str(&b).unwrap(),
    );
    let (fa, fb) = (
        a["natural_frequency_hz"].as_f64().unwrap(),
        b["natural_frequency_hz"].as_f64().unwrap(),
    );
    assert!((fa - fb).abs() < 1e-6 * fa);

    // Bad parameters: one line naming the field, non-zero exit.
    let text = std::fs::read_to_string(&file).unwrap();
    for (from, to, field) in [
        ("\"l1_m\": 1.96", "\"l1_m\": 0.0", "l1_m"),
        ("\"m_r_kg\": 18500.0", "\"m_r_kg\": -1.0", "m_r_kg"),
    ] {
        assert!(text.contains(from), "{from}");
        let bad = tmp(&format!("bad_{field}.json"));
        std::fs::write(&bad, text.replace(from, to)).unwrap();
        let (ok, _, err) = afsv(&["yaw", "measures", "--params", bad.to_str().unwrap()]);
        assert!(!ok);
        assert_eq!(err.trim().lines().count(), 1, "{err}");
        assert!(err.contains(field), "{err}");
    }
}

#[test]
fn bad_input_is_a_one_line_error() {
    let out = tmp("x.csv");
    for input in ["step:abc", "wiggle", "csv:/nonexistent.csv:steer_wheel_deg"] {
        let (ok, _, err) = afsv(&[
            "yaw",
            "simulate",
            "--input",
            input,
            "-o",
            out.to_str().unwrap(),
        ]);
        assert!(!ok, "{input}");
        assert_eq!(err.trim().lines().count(), 1, "{err}");
        assert!(err.starts_with("afsv: error:"), "{err}");
    }
    let (ok, stdout, _) = afsv(&["yaw", "simulate", "--help"]);
    assert!(ok && stdout.contains("csv:FILE:COLUMN") && stdout.contains("path-change"));
}

fn tmp(name: &str) -> std::path::PathBuf {
    scratch("yaw", name)
}

#[test]
fn sensitivity_reports_progress_lines_with_count_and_eta_when_piped() {
    let (ok, stdout, err) = afsv(&["yaw", "sensitivity"]);
    assert!(ok, "{err}");
    serde_json::from_str::<serde_json::Value>(&stdout).expect("stdout stays JSON");
    let lines: Vec<&str> = err.lines().collect();
    assert_eq!(lines.len(), 34, "{err}");
    for (i, l) in lines.iter().enumerate() {
        let prefix = format!("afsv yaw sensitivity: {}/34 configurations, ", i + 1);
        assert!(l.starts_with(&prefix), "line {i}: {l}");
        assert!(l.contains(" s elapsed, ETA "), "{l}");
    }
    assert!(lines[33].ends_with("ETA 0.00 s"), "{}", lines[33]);
    let (ok, _, err) = afsv(&["--quiet", "yaw", "sensitivity"]);
    assert!(ok && err.is_empty(), "{err}");
}

#[test]
fn simulate_writes_only_the_chosen_columns() {
    let out = tmp("cols.csv");
    let (ok, stdout, err) = afsv(&[
        "yaw",
        "simulate",
        "--duration",
        "2",
        "--columns",
        "articulation_deg,steer_wheel_deg",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&stdout).unwrap();
    assert_eq!(
        v["columns"],
        serde_json::json!(["time_s", "articulation_deg", "steer_wheel_deg"])
    );
    let header = std::fs::read_to_string(&out).unwrap();
    assert!(header.starts_with("time_s,articulation_deg,steer_wheel_deg\n"));
    for (cols, msg) in [
        (
            "articulation_deg,yaw_rate",
            "no column `yaw_rate` (known: time_s,",
        ),
        (
            "articulation_deg,articulation_deg",
            "`articulation_deg` is named twice",
        ),
    ] {
        let (ok, _, err) = afsv(&[
            "yaw",
            "simulate",
            "--duration",
            "1",
            "--columns",
            cols,
            "-o",
            tmp("bad.csv").to_str().unwrap(),
        ]);
        assert!(!ok && err.contains(msg), "{err}");
    }
}

#[test]
fn sensitivity_varies_a_described_vehicle() {
    let table = |args: &[&str]| -> serde_json::Value {
        let (ok, stdout, err) = afsv(args);
        assert!(ok, "{err}");
        let mut v: serde_json::Value = serde_json::from_str(&stdout).unwrap();
        v.as_object_mut().unwrap().remove("provenance");
        v
    };
    // the built-in prototype's yaw-plane data are Table 3.1's: the same table, bit for bit
    let nominal = table(&["yaw", "sensitivity"]);
    assert_eq!(
        table(&["yaw", "sensitivity", "--vehicle", "prototype"]),
        nominal
    );
    // a 28 t truck of its own: other nominal measures, every row about them
    let own = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../samples/vehicles/adt-28t.toml");
    let t = table(&["yaw", "sensitivity", "--vehicle", own.to_str().unwrap()]);
    assert_eq!(t["rows"].as_array().unwrap().len(), 32);
    let f = |v: &serde_json::Value| v["nominal"][0]["natural_frequency_hz"].as_f64().unwrap();
    assert!(
        (f(&t) / f(&nominal) - 1.0).abs() > 0.01,
        "{} vs {}",
        f(&t),
        f(&nominal)
    );
}

#[test]
fn leakage_runs_a_described_vehicle() {
    let run = |args: &[&str]| -> serde_json::Value {
        let (ok, stdout, err) = afsv(args);
        assert!(ok, "{err}");
        let mut v: serde_json::Value = serde_json::from_str(&stdout).unwrap();
        v.as_object_mut().unwrap().remove("provenance");
        v
    };
    let nominal = run(&["yaw", "leakage"]);
    assert_eq!(run(&["yaw", "leakage", "--vehicle", "prototype"]), nominal);
    let own = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../samples/vehicles/adt-28t.toml");
    let t = run(&["yaw", "leakage", "--vehicle", own.to_str().unwrap()]);
    let r2 = |v: &serde_json::Value| v["gain_efficiency_fig_4_7"]["r_squared"].as_f64().unwrap();
    assert!(
        r2(&t) > 0.9 && r2(&t) != r2(&nominal),
        "{} vs {}",
        r2(&t),
        r2(&nominal)
    );
    assert_eq!(
        t["steady_turn_decay"].as_array().unwrap().len(),
        nominal["steady_turn_decay"].as_array().unwrap().len()
    );
}
