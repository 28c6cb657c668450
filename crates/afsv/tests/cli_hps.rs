//! CLI tests of `afsv hps`.

mod cli_support;
use cli_support::{afsv, scratch};

#[test]
fn harmonic_writes_record_sidecar_and_plot_then_identify_reads_it() {
    let csv = tmp("rec.csv");
    let svg = tmp("loops.svg");
    let out = afsv(&[
        "hps",
        "harmonic",
        "--strut",
        "lab-1orifice",
        "--freq",
        "2",
        "--amp-mm",
        "18.75",
        "--cycles",
        "2",
        "--gamma0",
        "0.03",
        "-o",
        csv.to_str().unwrap(),
        "--plot",
        svg.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let m = &v["last_cycle"];
    assert!(
        m["peak_damping_extension_n"].as_f64().unwrap()
            > m["peak_damping_compression_n"].as_f64().unwrap()
    );
    assert!(m["dissipated_energy_j"].as_f64().unwrap() > 0.0);
    let text = std::fs::read_to_string(&csv).unwrap();
    assert!(text.starts_with("time_s,displacement_m,velocity_m_s,force_n,p_piston_pa,p_rod_pa"));
    let side: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(csv.with_extension("json")).unwrap())
            .unwrap();
    assert_eq!(side["sign_convention"], "afsv-v1");
    assert_eq!(side["sample_rate_hz"], 360.0);
    assert!(std::fs::read_to_string(&svg).unwrap().contains("<svg"));

    // Identify gamma0 and C_b back from the record (start: the nominal strut, gamma0 4 %).
    let out = afsv(&[
        "hps",
        "identify",
        "-i",
        csv.to_str().unwrap(),
        "--fit",
        "gamma0,cb",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let g = v["fitted"][0]["value"].as_f64().unwrap();
    assert!((g - 0.03).abs() < 1e-3, "{v}");
    assert!(v["nrmse"]["force"].as_f64().unwrap() < 1e-3);
}

#[test]
fn characterize_prints_table() {
    let out = afsv(&["hps", "characterize", "--strut", "lab-2orifice"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let tests = v["tests"].as_array().unwrap();
    assert_eq!(tests.len(), 43);
    assert!(tests
        .iter()
        .all(|t| t["effective_stiffness_n_m"].as_f64().unwrap() > 0.0));
}

#[test]
fn errors_are_one_line() {
    for args in [
        vec![
            "hps",
            "harmonic",
            "--strut",
            "lab-1orifice",
            "--amp-mm",
            "200",
        ],
        vec!["hps", "harmonic", "--gamma0", "0.6"],
        vec!["hps", "identify", "-i", "/nonexistent/rec.csv"],
        vec![
            "hps",
            "identify",
            "-i",
            "/nonexistent/rec.csv",
            "--fit",
            "n,bogus",
        ],
    ] {
        let out = afsv(&args);
        assert!(!out.status.success(), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(err.trim().lines().count(), 1, "{args:?}: {err}");
        assert!(err.starts_with("afsv: error:"), "{err}");
    }
    let out = afsv(&["hps", "harmonic", "--help"]);
    assert!(String::from_utf8_lossy(&out.stdout).contains("--amp-mm"));
}

#[test]
fn loop_plot_has_title_conditions_and_units_and_piped_runs_print_progress_lines() {
    let csv = tmp("titled.csv");
    let svg = tmp("titled.svg");
    let out = afsv(&[
        "hps",
        "harmonic",
        "--strut",
        "lab-1orifice",
        "--freq",
        "1",
        "--amp-mm",
        "10",
        "--cycles",
        "2",
        "-o",
        csv.to_str().unwrap(),
        "--plot",
        svg.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&svg).unwrap();
    for must in [
        "strut loops, last period",
        "titled.csv, lab-1orifice strut",
        "1 Hz, 10 mm amplitude",
        "pressure (MPa)",
        "deflection (mm)",
        "force (kN)",
        "velocity (m/s)",
        "damping force (kN)",
        "P_hc piston side",
        "P_hr rod side",
    ] {
        assert!(text.contains(must), "the loop plot lacks `{must}`");
    }

    // stderr is a pipe here: one progress line per lab test, with count and ETA.
    let out = afsv(&["hps", "characterize", "--strut", "lab-1orifice"]);
    assert!(out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    let lines: Vec<&str> = err.lines().collect();
    assert_eq!(lines.len(), 43, "{err}");
    assert!(lines[0].starts_with("afsv hps characterize: 1/43 tests (0.1 Hz, 5.0 mm), "));
    assert!(lines[42].starts_with("afsv hps characterize: 43/43 tests (8 Hz, "));
    assert!(lines.iter().all(|l| l.contains(" elapsed, ETA ")), "{err}");

    let out = afsv(&[
        "hps",
        "identify",
        "-i",
        csv.to_str().unwrap(),
        "--fit",
        "gamma0",
    ]);
    assert!(out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    let lines: Vec<&str> = err.lines().collect();
    assert_eq!(lines.len(), 2, "{err}");
    assert!(lines[0].starts_with("afsv hps identify: 1/2 steps (read 721 samples), "));
    assert!(lines[1].starts_with("afsv hps identify: 2/2 steps (fitted in "));

    // --quiet switches progress off.
    let out = afsv(&["--quiet", "hps", "characterize", "--strut", "lab-1orifice"]);
    assert!(out.status.success());
    assert!(out.stderr.is_empty());
}

fn tmp(name: &str) -> std::path::PathBuf {
    scratch("hps", name)
}
