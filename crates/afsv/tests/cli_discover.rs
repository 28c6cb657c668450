//! `afsv synth` and `afsv discover` from the command line.

mod cli_support;
use cli_support::{afsv, scratch};

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

/// Records as another tool would write them: columns in another order, an extra column, a
/// byte-order mark and CRLF line ends, 100 Hz instead of 200 Hz, a clock that starts at
/// 1000 s, and no sidecar (speed from its column).
#[test]
fn records_written_elsewhere_are_read_and_the_effect_is_named() {
    let data = tmp("elsewhere-synth");
    let foreign = tmp("elsewhere");
    let report = tmp("elsewhere-report");
    let out = afsv(&[
        "synth",
        "--model",
        "yaw-plane",
        "--effects",
        "velocity-leakage",
        "--seed",
        "11",
        "-o",
        data.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    for set in ["train", "holdout"] {
        std::fs::create_dir_all(foreign.join(set)).unwrap();
        for entry in std::fs::read_dir(data.join(set)).unwrap().flatten() {
            let path = entry.path();
            if path.extension().is_none_or(|e| e != "csv") {
                continue;
            }
            let rec = afsv::record::Record::read(&path).unwrap();
            let mut names: Vec<String> = rec.names().to_vec();
            names.reverse();
            let mut text = String::from("\u{feff}");
            text += &names.join(",");
            text += ",oil_temp_c\r\n";
            for i in (0..rec.len()).step_by(2) {
                for name in &names {
                    let mut v = rec.column(name).unwrap()[i];
                    if name == "time_s" {
                        v += 1000.0;
                    }
                    text += &format!("{v:.9e},");
                }
                text += "41.5\r\n";
            }
            std::fs::write(foreign.join(set).join(path.file_name().unwrap()), text).unwrap();
        }
    }
    let out = afsv(&[
        "discover",
        "--model",
        "yaw-plane",
        "--train",
        foreign.join("train").to_str().unwrap(),
        "--holdout",
        foreign.join("holdout").to_str().unwrap(),
        "-o",
        report.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["named"], serde_json::json!(["velocity-leakage"]), "{v}");
    assert!(
        v["gap_shrink"].as_f64().unwrap() > 0.7,
        "{}",
        v["gap_shrink"]
    );
    for d in [&data, &foreign, &report] {
        let _ = std::fs::remove_dir_all(d);
    }
}

fn tmp(name: &str) -> std::path::PathBuf {
    scratch("discover", name)
}
