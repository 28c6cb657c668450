//! `afsv study hps-sensitivity` end to end on its smallest request (one seed, one change,
//! ride only): JSON with every variable, NaN-free, and the plot written through the guard.

mod cli_support;
use cli_support::{afsv, json, scratch};

#[test]
fn hps_sensitivity_reports_every_variable_and_plots() {
    let dir = scratch("study", "hps");
    std::fs::create_dir_all(&dir).unwrap();
    let svg = dir.join("s.svg");
    let out = afsv(&[
        "study",
        "hps-sensitivity",
        "--seeds",
        "1",
        "--changes",
        "30",
        "--no-roll",
        "--no-yaw",
        "--plot",
        svg.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v = json(&out);
    let rows = v["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 3);
    for (r, name) in rows
        .iter()
        .zip(["piston_area", "check_valve_area", "bleed_area"])
    {
        assert_eq!(r["variable"], name);
        assert!(
            r["measures"]["a_wz_unloaded_m_s2"]["mean"]
                .as_f64()
                .unwrap()
                > 0.0
        );
        assert!(
            r["measures"]["omega_z_hz"].is_null(),
            "not run: null with a reason"
        );
    }
    assert!(std::fs::read_to_string(&svg).unwrap().contains("<svg"));
    // the plot is afsv's now: a second run may replace it, a foreign file may not be
    std::fs::write(dir.join("mine.svg"), "user data").unwrap();
    let refused = afsv(&[
        "study",
        "hps-sensitivity",
        "--seeds",
        "1",
        "--plot",
        dir.join("mine.svg").to_str().unwrap(),
    ]);
    assert!(!refused.status.success());
    assert_eq!(
        std::fs::read_to_string(dir.join("mine.svg")).unwrap(),
        "user data"
    );
}
