//! `afsv measures ...` end to end.

mod cli_support;
use cli_support::{afsv, json, scratch};

use std::f64::consts::PI;
use std::fmt::Write as _;

fn one_line_error(out: &std::process::Output, needle: &str) {
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    assert!(err.contains(needle), "{err}");
    assert!(!err.contains("panicked"), "{err}");
}

fn write_csv(name: &str, header: &str, rows: impl Iterator<Item = Vec<f64>>) -> String {
    let mut s = format!("{header}\n");
    for r in rows {
        let cells: Vec<String> = r.iter().map(|v| format!("{v}")).collect();
        writeln!(s, "{}", cells.join(",")).unwrap();
    }
    let p = tmp(name);
    std::fs::write(&p, s).unwrap();
    p.to_str().unwrap().to_string()
}

#[test]
fn weighting_magnitudes() {
    let v = json(&afsv(&[
        "measures",
        "weighting",
        "--weighting",
        "wk",
        "--freqs",
        "0.5,1,2",
        "--fs",
        "1000",
    ]));
    let rows = v["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 3);
    // ISO 2631-1 Table 3: Wk 0.418, 0.482, 0.531.
    for (r, want) in rows.iter().zip([0.418, 0.482, 0.531]) {
        let m = r["magnitude"].as_f64().unwrap();
        assert!((m / want - 1.0).abs() < 0.01, "{m} vs {want}");
        assert!((r["iir_magnitude"].as_f64().unwrap() / m - 1.0).abs() < 0.01);
    }
    one_line_error(
        &afsv(&[
            "measures",
            "weighting",
            "--weighting",
            "wk",
            "--freqs",
            "-1",
        ]),
        "--freqs",
    );
}

#[test]
fn wbv_of_a_vertical_sine() {
    // 60 s at 100 Hz: az = 9.81 + 1.0 sin(2 pi 5 t); a_w = Wk(5)/sqrt(2) = 0.7347.
    let path = write_csv(
        "seat.csv",
        "time_s,az_m_s2",
        (0..6000).map(|i| {
            let t = i as f64 / 100.0;
            vec![t, 9.81 + (2.0 * PI * 5.0 * t).sin()]
        }),
    );
    let v = json(&afsv(&["measures", "wbv", "-i", &path, "--hours", "2"]));
    let aw = v["axes"][0]["a_w"].as_f64().unwrap();
    assert!((aw - 1.0388 / 2f64.sqrt()).abs() < 0.01, "{aw}");
    assert!((v["a_v"].as_f64().unwrap() - aw).abs() < 1e-12);
    // A(8) for 2 h = a_w / 2.
    assert!((v["a8"].as_f64().unwrap() - aw / 2.0).abs() < 1e-9);
    assert_eq!(v["eu_level"], "below_action");
    // Caution zone for 2 h (Eq B.1): 0.87-1.73 m/s^2.
    assert_eq!(v["hgcz_zone"], "below");
    assert_eq!(v["axes"][0]["weighting"], "wk");
    one_line_error(
        &afsv(&["measures", "wbv", "-i", &path, "--weighting", "q=wk"]),
        "unknown axis",
    );
    let none = write_csv(
        "none.csv",
        "time_s,v_m_s",
        (0..10).map(|i| vec![i as f64, 0.0]),
    );
    one_line_error(
        &afsv(&["measures", "wbv", "-i", &none]),
        "no acceleration column",
    );
    one_line_error(
        &afsv(&["measures", "wbv", "-i", "/nonexistent/x.csv"]),
        "x.csv",
    );
}

#[test]
fn wbv_converts_an_acceleration_in_g_and_refuses_an_unknown_unit() {
    // The same vertical sine as above, written in g: same a_w, and the output says so.
    let g = 9.806_65;
    let si = write_csv(
        "seat_si.csv",
        "time_s,az_m_s2",
        (0..6000).map(|i| {
            let t = i as f64 / 100.0;
            vec![t, (2.0 * PI * 5.0 * t).sin()]
        }),
    );
    let in_g = write_csv(
        "seat_g.csv",
        "time_s,az_g",
        (0..6000).map(|i| {
            let t = i as f64 / 100.0;
            vec![t, (2.0 * PI * 5.0 * t).sin() / g]
        }),
    );
    let a = json(&afsv(&["measures", "wbv", "-i", &si]));
    let b = json(&afsv(&["measures", "wbv", "-i", &in_g]));
    let (aw_a, aw_b) = (
        a["axes"][0]["a_w"].as_f64().unwrap(),
        b["axes"][0]["a_w"].as_f64().unwrap(),
    );
    assert!((aw_a - aw_b).abs() < 1e-9 * aw_a, "{aw_a} vs {aw_b}");
    assert_eq!(b["unit_conversions"][0]["from"], "az_g");
    assert_eq!(b["unit_conversions"][0]["to"], "az_m_s2");
    assert!(a.get("unit_conversions").is_none());
    let bad = write_csv(
        "seat_ft.csv",
        "time_s,az_ft_s2",
        (0..10).map(|i| vec![i as f64 / 100.0, 0.0]),
    );
    one_line_error(&afsv(&["measures", "wbv", "-i", &bad]), "az_ft_s2");
}

#[test]
fn decay_fit_of_articulation_record() {
    // Pulse at t < 1 s, then free decay at 2.81 Hz, zeta 0.15, settling at 0.4 deg.
    let wn = 2.0 * PI * 2.81;
    let wd = wn * (1.0f64 - 0.15 * 0.15).sqrt();
    let path = write_csv(
        "pulse.csv",
        "time_s,steer_wheel_deg,articulation_deg",
        (0..500).map(|i| {
            let t = i as f64 * 0.01;
            let y = if t < 1.0 {
                0.0
            } else {
                0.4 + 3.0 * (-0.15 * wn * (t - 1.0)).exp() * (wd * (t - 1.0)).cos()
            };
            vec![t, 0.0, y]
        }),
    );
    let v = json(&afsv(&[
        "measures",
        "decay",
        "-i",
        &path,
        "--column",
        "articulation_deg",
        "--start-s",
        "1",
    ]));
    let f = &v["fit"];
    assert!(
        (f["natural_frequency_hz"].as_f64().unwrap() - 2.81).abs() < 1e-3,
        "{v}"
    );
    assert!(
        (f["damping_ratio"].as_f64().unwrap() - 0.15).abs() < 1e-3,
        "{v}"
    );
    assert!((f["offset"].as_f64().unwrap() - 0.4).abs() < 1e-3, "{v}");
    // Automatic onset finds the same decay (largest deviation at t = 1 s).
    let v = json(&afsv(&[
        "measures",
        "decay",
        "-i",
        &path,
        "--column",
        "articulation_deg",
    ]));
    assert!((v["start_s"].as_f64().unwrap() - 1.0).abs() < 1e-9);
    assert_eq!(v["problems"].as_array().unwrap().len(), 0, "{v}");
    // A window that starts before the pulse ends is not one free decay: the fit is
    // printed, its problem named, and the exit status (3) says it was not earned.
    let early = [
        "measures",
        "decay",
        "-i",
        &path,
        "--column",
        "articulation_deg",
    ];
    let mut args = early.to_vec();
    args.extend(["--start-s", "0.5"]);
    let out = afsv(&args);
    assert_eq!(out.status.code(), Some(3), "{out:?}");
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("times the noise"), "{err}");
    args.push("--accept-poor-fit");
    let v = json(&afsv(&args));
    assert_eq!(v["accepted_despite_problems"], true);
    one_line_error(
        &afsv(&["measures", "decay", "-i", &path, "--column", "yaw_deg"]),
        "yaw_deg",
    );
    one_line_error(
        &afsv(&[
            "measures",
            "decay",
            "-i",
            &path,
            "--column",
            "steer_wheel_deg",
            "--start-s",
            "2",
        ]),
        "constant",
    );
}

#[test]
fn step_metrics_of_second_order_response() {
    let (wn, z) = (2.0 * PI * 0.8, 0.4);
    let wd = wn * (1.0f64 - z * z).sqrt();
    let path = write_csv(
        "step.csv",
        "time_s,steer_wheel_deg,articulation_deg",
        (0..2001).map(|i| {
            let t = i as f64 * 0.01;
            let tau = t - 1.0;
            let (u, y) = if tau < 0.0 {
                (0.0, 0.0)
            } else {
                let s = (1.0 - z * z).sqrt();
                (
                    30.0,
                    6.0 * (1.0
                        - (-z * wn * tau).exp() * ((wd * tau).cos() + z / s * (wd * tau).sin())),
                )
            };
            vec![t, u, y]
        }),
    );
    let v = json(&afsv(&[
        "measures",
        "step",
        "-i",
        &path,
        "--input",
        "steer_wheel_deg",
        "--output",
        "articulation_deg",
    ]));
    let m = &v["metrics"];
    assert!((m["gain"].as_f64().unwrap() - 0.2).abs() < 1e-3, "{v}");
    let os = 100.0 * (-PI * z / (1.0f64 - z * z).sqrt()).exp();
    assert!(
        (m["overshoot_percent"].as_f64().unwrap() - os).abs() < 0.1,
        "{v}"
    );
    assert!((v["t_step_s"].as_f64().unwrap() - 0.99).abs() < 1e-9, "{v}");
    one_line_error(
        &afsv(&[
            "measures",
            "step",
            "-i",
            &path,
            "--input",
            "nope",
            "--output",
            "articulation_deg",
        ]),
        "nope",
    );
}

#[test]
fn weighting_check_passes() {
    let v = json(&afsv(&["measures", "check"]));
    assert_eq!(v["pass"], true, "{v}");
    assert!(v["max_analog_error_percent"].as_f64().unwrap() < 2.0);
    assert_eq!(v["weightings"].as_array().unwrap().len(), 6);
}

#[test]
fn help_is_complete() {
    let out = afsv(&["measures", "--help"]);
    let text = String::from_utf8_lossy(&out.stdout);
    for sub in ["weighting", "wbv", "decay", "step", "check"] {
        assert!(text.contains(sub), "{text}");
    }
    let out = afsv(&["measures", "wbv", "--help"]);
    let text = String::from_utf8_lossy(&out.stdout);
    for opt in ["--input", "--hours", "--weighting", "--k", "--method"] {
        assert!(text.contains(opt), "{text}");
    }
}

fn tmp(name: &str) -> std::path::PathBuf {
    scratch("measures", name)
}
