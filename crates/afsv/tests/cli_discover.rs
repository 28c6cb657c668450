//! `afsv synth` and `afsv discover` from the command line.

use std::path::PathBuf;
use std::process::Command;

fn afsv(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_afsv"))
        .args(args)
        .output()
        .expect("afsv runs")
}

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("afsv-cli-discover-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

#[test]
fn synth_then_discover_names_the_hidden_effect() {
    let data = tmp("data");
    let report = tmp("report");
    let out = afsv(&[
        "synth",
        "--model",
        "hps-strut",
        "--effects",
        "gas-heat-transfer=3",
        "--seed",
        "5",
        "-o",
        data.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(data.join("truth.json").is_file());
    let before: Vec<_> = std::fs::read_dir(data.join("train"))
        .unwrap()
        .flatten()
        .collect();
    let out = afsv(&[
        "discover",
        "--model",
        "hps-strut",
        "--train",
        data.join("train").to_str().unwrap(),
        "--holdout",
        data.join("holdout").to_str().unwrap(),
        "--effects",
        "gas-heat-transfer,check-valve-lag",
        "-o",
        report.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["named"], serde_json::json!(["gas-heat-transfer"]));
    assert!(v["gap_shrink"].as_f64().unwrap() > 0.7);
    let md = std::fs::read_to_string(report.join("report.md")).unwrap();
    assert!(md.contains("gas-heat-transfer"));
    assert!(report.join("report.json").is_file());
    assert!(std::fs::read_dir(&report)
        .unwrap()
        .flatten()
        .any(|e| e.path().extension().is_some_and(|x| x == "svg")));
    // Inputs untouched.
    let after: Vec<_> = std::fs::read_dir(data.join("train"))
        .unwrap()
        .flatten()
        .collect();
    assert_eq!(before.len(), after.len());
    // synth refuses a non-empty folder.
    let out = afsv(&[
        "synth",
        "--model",
        "hps-strut",
        "-o",
        data.to_str().unwrap(),
    ]);
    assert!(!out.status.success());
    std::fs::remove_dir_all(&data).unwrap();
    std::fs::remove_dir_all(&report).unwrap();
}

#[test]
fn bad_input_gives_one_line_errors() {
    let out = afsv(&[
        "synth",
        "--model",
        "hps-strut",
        "--effects",
        "no-such-effect",
        "-o",
        "/tmp/x-afsv-none",
    ]);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(err.trim().lines().count(), 1, "{err}");
    assert!(err.contains("unknown effect"), "{err}");
    let out = afsv(&[
        "discover",
        "--model",
        "yaw-plane",
        "--train",
        "/nonexistent",
        "--holdout",
        "/nonexistent",
        "-o",
        "/tmp/x",
    ]);
    assert!(!out.status.success());
    assert_eq!(
        String::from_utf8_lossy(&out.stderr).trim().lines().count(),
        1
    );
    let out = afsv(&["discover", "--model", "nope"]);
    assert!(!out.status.success());
    assert_eq!(
        String::from_utf8_lossy(&out.stderr).trim().lines().count(),
        1
    );
}

#[test]
fn list_effects_prints_the_catalogue() {
    let out = afsv(&["discover", "--model", "yaw-plane", "--list-effects"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["catalogue"].as_array().unwrap().len(), 6);
}
