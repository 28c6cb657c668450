//! `afsv tire sweep` and `afsv tire envelope` end to end.

mod cli_support;
use cli_support::{afsv, json, scratch};

#[test]
fn sweep_lateral_rows_and_plot() {
    let svg = tmp("fy.svg");
    let out = afsv(&[
        "tire",
        "sweep",
        "--fz",
        "100000",
        "--alpha-deg",
        "-20:20:0.5",
        "--plot",
        svg.to_str().unwrap(),
    ]);
    let v = json(&out);
    let rows = v.as_array().unwrap();
    assert_eq!(rows.len(), 81);
    for key in [
        "fz_n",
        "kappa",
        "alpha_deg",
        "fx_n",
        "fy_n",
        "mz_nm",
        "my_nm",
    ] {
        assert!(rows[0].get(key).is_some(), "missing {key}");
    }
    // Odd in alpha, bounded by U_max F_z, positive for positive alpha.
    let fy = |i: usize| rows[i]["fy_n"].as_f64().unwrap();
    assert_eq!(rows[40]["alpha_deg"].as_f64().unwrap(), 0.0);
    assert_eq!(fy(40), 0.0);
    assert!(fy(60) > 0.0);
    assert!((fy(0) + fy(80)).abs() < 1e-9);
    assert!(rows
        .iter()
        .all(|r| r["fy_n"].as_f64().unwrap().abs() <= 0.8 * 1e5));
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.contains("<svg") && text.contains("polyline"));
}

#[test]
fn sweep_longitudinal_with_overrides() {
    let out = afsv(&[
        "tire",
        "sweep",
        "--fz",
        "50000:100000:50000",
        "--kappa",
        "-0.5:0.5:0.01",
        "--c-slip",
        "2e6",
        "--u-max",
        "0.9",
        "--u-min",
        "0.7",
        "--c-alpha-per-rad",
        "3e5",
        "--width-m",
        "0.6",
    ]);
    let v = json(&out);
    let rows = v.as_array().unwrap();
    assert_eq!(rows.len(), 2 * 101);
    // Small-slip slope equals --c-slip.
    let r = rows
        .iter()
        .find(|r| (r["kappa"].as_f64().unwrap() - 0.01).abs() < 1e-12)
        .unwrap();
    assert!((r["fx_n"].as_f64().unwrap() - 2e6 * 0.01).abs() < 1e-6);
    assert!(rows.iter().all(|r| r["fy_n"].as_f64().unwrap() == 0.0));
}

#[test]
fn sweep_params_file_and_errors() {
    let p = tmp("tire.json");
    std::fs::write(
        &p,
        r#"{"u_max": 0.5, "u_min": 0.5, "cornering_stiffness_table": []}"#,
    )
    .unwrap();
    let v = json(&afsv(&[
        "tire",
        "sweep",
        "--fz",
        "1e5",
        "--alpha-deg",
        "80",
        "--params",
        p.to_str().unwrap(),
    ]));
    assert!((v[0]["fy_n"].as_f64().unwrap() - 0.5e5).abs() < 1e-6);
    // A range that does not land on its stop ends below it.
    let v = json(&afsv(&[
        "tire",
        "sweep",
        "--fz",
        "1e5",
        "--alpha-deg",
        "0:1:0.3",
    ]));
    assert_eq!(v.as_array().unwrap().len(), 4);

    for (args, needle) in [
        (
            vec!["--fz", "1e5", "--alpha-deg", "20:-20:0.5"],
            "below start",
        ),
        (vec!["--fz", "1e5", "--alpha-deg", "-20:20:0"], "step"),
        (vec!["--fz", "1e5", "--alpha-deg", "0:a:1"], "stop `a`"),
        (vec!["--fz", "1e5", "--alpha-deg", "0:1"], "start:stop:step"),
        (vec!["--fz", "1e5", "--alpha-deg", "nan"], "not finite"),
        (vec!["--fz", "abc"], "--fz"),
        (vec!["--fz", "1e5", "--u-max", "0.3"], "u_max"),
        (
            vec!["--fz", "1e5", "--params", "/nonexistent/t.json"],
            "t.json",
        ),
    ] {
        let mut a = vec!["tire", "sweep"];
        a.extend(args);
        let out = afsv(&a);
        assert!(!out.status.success());
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(needle), "{err}");
        assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    }
}

#[test]
fn envelope_flat_and_step_profile() {
    let csv = tmp("profile.csv");
    let mut text = String::from("x_m,left_m,right_m\n");
    for i in 0..=100 {
        let x = i as f64 * 0.05;
        let left = if x >= 2.5 { 0.1 } else { 0.0 };
        text.push_str(&format!("{x},{left},0.0\n"));
    }
    std::fs::write(&csv, text).unwrap();
    for method in ["cams", "circle"] {
        // Right track is flat: z_eff 0 and wheel height R - deflection everywhere.
        let v = json(&afsv(&[
            "tire",
            "envelope",
            "--profile",
            csv.to_str().unwrap(),
            "--radius",
            "1.0",
            "--method",
            method,
            "--track",
            "right",
            "--deflection-m",
            "0.08",
        ]));
        for r in v.as_array().unwrap() {
            assert!(r["z_eff_m"].as_f64().unwrap().abs() < 1e-9);
            assert!((r["wheel_z_m"].as_f64().unwrap() - 0.92).abs() < 1e-9);
        }
    }
    let v = json(&afsv(&[
        "tire",
        "envelope",
        "--profile",
        csv.to_str().unwrap(),
        "--method",
        "cams",
        "--deflection-m",
        "0.08",
    ]));
    let rows = v.as_array().unwrap();
    assert_eq!(rows.len(), 101);
    let z: Vec<f64> = rows
        .iter()
        .map(|r| r["z_eff_m"].as_f64().unwrap())
        .collect();
    // The point profile jumps 0.1 m between two samples; the enveloped one rises gradually.
    let max_jump = z
        .windows(2)
        .map(|w| (w[1] - w[0]).abs())
        .fold(0.0, f64::max);
    assert!(max_jump < 0.05, "{max_jump}");
    assert!(z[0].abs() < 1e-9 && (z[100] - 0.1).abs() < 1e-9);
}

#[test]
fn envelope_errors_are_one_line() {
    let csv = tmp("bad.csv");
    std::fs::write(&csv, "x_m,left_m\n0,0\n1,0\n").unwrap();
    for (args, needle) in [
        (vec!["--track", "right"], "right_m"),
        (vec!["--radius", "-1"], "radius"),
        (vec!["--deflection-m", "2"], "deflection"),
    ] {
        let mut a = vec!["tire", "envelope", "--profile", csv.to_str().unwrap()];
        a.extend(args);
        let out = afsv(&a);
        assert!(!out.status.success());
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(needle), "{err}");
        assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    }
    let unsorted = tmp("unsorted.csv");
    std::fs::write(&unsorted, "x_m,left_m,right_m\n0,0,0\n2,0,0\n1,0,0\n").unwrap();
    let out = afsv(&["tire", "envelope", "--profile", unsorted.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success() && err.contains("increase"), "{err}");
}

#[test]
fn help_documents_the_options() {
    let out = afsv(&["tire", "sweep", "--help"]);
    let h = String::from_utf8_lossy(&out.stdout);
    for opt in [
        "--fz",
        "--alpha-deg",
        "--kappa",
        "--params",
        "--c-slip",
        "--c-alpha-per-rad",
        "--u-max",
        "--u-min",
        "--width-m",
        "--plot",
    ] {
        assert!(h.contains(opt), "{opt} missing from help");
    }
    let out = afsv(&["tire", "envelope", "--help"]);
    let h = String::from_utf8_lossy(&out.stdout);
    for opt in [
        "--profile",
        "--radius",
        "--method",
        "--track",
        "--deflection-m",
        "cams",
        "circle",
    ] {
        assert!(h.contains(opt), "{opt} missing from help");
    }
}

fn tmp(name: &str) -> std::path::PathBuf {
    scratch("tire", name)
}

#[test]
fn sweep_plot_names_the_tire_and_conditions_with_units() {
    let svg = tmp("units.svg");
    let out = afsv(&[
        "tire",
        "sweep",
        "--fz",
        "50000:100000:50000",
        "--alpha-deg",
        "-10:10:1",
        "--plot",
        svg.to_str().unwrap(),
    ]);
    json(&out);
    let text = std::fs::read_to_string(&svg).unwrap();
    for must in [
        "Fiala lateral force F_y versus slip angle",
        "nominal 29.5R29 tire; F_z = 50, 100 kN; kappa = 0",
        "slip angle alpha (deg)",
        "lateral force F_y (kN)",
        "Fz = 50 kN, kappa = 0",
    ] {
        assert!(text.contains(must), "`{must}` missing from the SVG");
    }
    let svg = tmp("fx.svg");
    let out = afsv(&[
        "tire",
        "sweep",
        "--fz",
        "100000",
        "--kappa",
        "0:0.5:0.05",
        "--plot",
        svg.to_str().unwrap(),
    ]);
    json(&out);
    let text = std::fs::read_to_string(&svg).unwrap();
    for must in [
        "slip ratio kappa (-)",
        "longitudinal force F_x (kN)",
        "alpha = 0 deg",
    ] {
        assert!(text.contains(must), "`{must}` missing from the SVG");
    }
}
