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

#[test]
fn hps_sensitivity_refuses_bad_changes_by_name() {
    let many = vec!["1"; 21].join(",");
    for (changes, needle) in [
        ("-100", "above -100"),
        ("x", "item 1"),
        ("nan", "--changes"),
        (many.as_str(), "at most 20"),
    ] {
        let out = afsv(&["study", "hps-sensitivity", "--changes", changes]);
        assert!(!out.status.success(), "{changes} accepted");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(needle), "{changes}: {err}");
    }
}

/// `afsv study speed-sweep` on two speeds and one seed: both loads at each speed, the
/// caution-zone bound of ISO 2631-1 Eq B.1, a_wz rising with speed, the plot written.
#[test]
fn speed_sweep_reports_both_loads_and_the_caution_zone() {
    let dir = scratch("study", "sweep");
    std::fs::create_dir_all(&dir).unwrap();
    let svg = dir.join("sweep.svg");
    let out = afsv(&[
        "study",
        "speed-sweep",
        "--speeds",
        "15, 30",
        "--seeds",
        "1",
        "--plot",
        svg.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v = json(&out);
    let upper = v["hgcz_upper_m_s2"].as_f64().unwrap();
    assert!((upper - 6.0 / 48f64.sqrt()).abs() < 1e-12, "{upper}");
    let points = v["points"].as_array().unwrap();
    assert_eq!(points.len(), 4);
    for load in ["unloaded", "loaded"] {
        let a: Vec<f64> = points
            .iter()
            .filter(|p| p["load"] == load)
            .map(|p| p["a_wz_m_s2"]["mean"].as_f64().unwrap())
            .collect();
        assert!(a[1] > a[0], "{load}: a_wz must rise with speed, {a:?}");
        assert!(points
            .iter()
            .all(|p| p["d_s_m"]["mean"].as_f64().unwrap() > 0.0));
    }
    assert_eq!(v["crossings"].as_array().unwrap().len(), 2);
    assert!(std::fs::read_to_string(&svg).unwrap().contains("<svg"));
}

#[test]
fn speed_sweep_refuses_bad_requests_by_name() {
    for (args, needle) in [
        (&["--speeds", "20,10"][..], "ascending"),
        (&["--speeds", "20,x"], "item 2"),
        (&["--speeds", "inf"], "--speeds"),
        (&["--design", "1,2,3,4"], "at most 3"),
        (&["--design", "0.038,8"], "three values"),
        (&["--design", "0.038,-8,11"], "--design"),
        (&["--seeds", "0"], "--seeds"),
        (&["--hps", "/nonexistent/strut.json"], "strut.json"),
    ] {
        let mut a = vec!["study", "speed-sweep"];
        a.extend_from_slice(args);
        let out = afsv(&a);
        assert!(!out.status.success(), "{args:?} accepted");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(needle), "{args:?}: {err}");
    }
}

/// `afsv optimize hps` on its smallest request writes the optimum's strut file (which
/// `afsv params check strut` accepts and `study speed-sweep --hps` reads) and, with
/// `--speed-sweep`, the D4 sweep of the optimum; a foreign `--strut-out` file is kept.
#[test]
fn hps_optimum_writes_its_strut_and_sweeps_it() {
    let dir = scratch("study", "optimum");
    std::fs::create_dir_all(&dir).unwrap();
    let strut = dir.join("optimum.json");
    let out = afsv(&[
        "optimize",
        "hps",
        "--population",
        "4",
        "--generations",
        "1",
        "--reevaluation-seeds",
        "1",
        "--no-roll",
        "--speed-sweep",
        "--strut-out",
        strut.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v = json(&out);
    assert_eq!(v["speed_sweep"]["points"].as_array().unwrap().len(), 10);
    let check = afsv(&["params", "check", "strut", strut.to_str().unwrap()]);
    assert!(check.status.success());
    let a_hc = json(&check)["parameters"]["a_hc"].as_f64().unwrap();
    assert!((a_hc - v["design"]["a_hc"].as_f64().unwrap()).abs() < 1e-15);
    let sweep = afsv(&[
        "study",
        "speed-sweep",
        "--hps",
        strut.to_str().unwrap(),
        "--speeds",
        "20",
        "--seeds",
        "1",
    ]);
    assert!(sweep.status.success());
    std::fs::write(dir.join("mine.json"), "user data").unwrap();
    let refused = afsv(&[
        "optimize",
        "hps",
        "--population",
        "4",
        "--generations",
        "1",
        "--strut-out",
        dir.join("mine.json").to_str().unwrap(),
    ]);
    assert!(!refused.status.success());
    assert_eq!(
        std::fs::read_to_string(dir.join("mine.json")).unwrap(),
        "user data"
    );
}

/// `afsv study layouts` on its smallest request (one seed, two D4 speeds, the rigid
/// baseline and the layout with every element: struts on both axles, the front roll link):
/// a frame and a seat row per layout on the same vehicle runs, the operator's verdicts read from the
/// reported numbers, and bad requests refused by name before any run.
#[test]
fn layouts_report_frame_and_seat_rows_consistent_with_their_numbers() {
    let out = afsv(&[
        "study",
        "layouts",
        "--seeds",
        "1",
        "--speeds",
        "10,20",
        "--speed-kmh",
        "20",
        "--layouts",
        "rigid,front-rear-roll",
        "--json",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v = json(&out);
    let rows = v["rows"].as_array().unwrap();
    let names: Vec<(&str, bool)> = rows
        .iter()
        .map(|r| {
            (
                r["layout"].as_str().unwrap(),
                r["at_seat"].as_bool().unwrap(),
            )
        })
        .collect();
    assert_eq!(
        names,
        [
            ("rigid", false),
            ("rigid", true),
            ("front-rear-roll", false),
            ("front-rear-roll", true)
        ]
    );
    let upper = v["hgcz_8h_m_s2"][1].as_f64().unwrap();
    let mean = |r: &serde_json::Value, k: &str| r[k]["mean"].as_f64().unwrap();
    for pair in rows.chunks(2) {
        // the seat rides on the frame row's runs: every vehicle measure is the same
        for k in ["a_wz_frame_m_s2", "sp_drt_m_s2"] {
            assert_eq!(pair[0][k], pair[1][k], "{k}");
        }
        assert!(pair[0]["a_wz_seat_m_s2"].is_null() && pair[0]["seat_ratio"].is_null());
        for (r, operator) in [
            (&pair[0], mean(&pair[0], "a_wz_frame_m_s2")),
            (&pair[1], mean(&pair[1], "a_wz_seat_m_s2")),
        ] {
            // the ride speed is a D4 speed: its D4 point is the reported ride
            let d4 = r["d4_a_wz_m_s2"].as_array().unwrap();
            assert!((d4[1].as_f64().unwrap() - operator).abs() <= 1e-12 * operator);
            let (a, b) = (d4[0].as_f64().unwrap(), d4[1].as_f64().unwrap());
            let crossing = &r["d4_crossing"]["speed_kmh"];
            if a <= upper && b > upper {
                let want = 10.0 + (upper - a) / (b - a) * 10.0;
                assert!((crossing.as_f64().unwrap() - want).abs() < 1e-9);
            } else {
                assert!(crossing.is_null());
            }
            let zone = if operator > upper {
                "above"
            } else if operator < v["hgcz_8h_m_s2"][0].as_f64().unwrap() {
                "below"
            } else {
                "within"
            };
            assert_eq!(r["hgcz_8h"], zone);
        }
    }
    assert!(rows[0]["strut_travel_m"].is_null());
    assert!(mean(&rows[2], "strut_travel_m") > 0.0);
    // the struts on both axles with the front roll link lower the frame's a_wz (the front
    // HPS alone halves it at 20 km/h, section 6.5)
    assert!(mean(&rows[2], "a_wz_frame_m_s2") < 0.8 * mean(&rows[0], "a_wz_frame_m_s2"));
    for (args, needle) in [
        (&["--layouts", "rigid,bogus"][..], "unknown layout `bogus`"),
        (&["--layouts", "rigid,rigid"][..], "named twice"),
        (&["--seat", "soft"][..], "--seat"),
        (&["--speeds", "20,10"][..], "ascending"),
        (&["--speed-kmh", "200"][..], "ride_speed_kmh"),
        (&["--seeds", "0"][..], "--seeds"),
    ] {
        let out = afsv(&[&["study", "layouts"][..], args].concat());
        assert!(!out.status.success(), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            err.contains(needle) && err.lines().count() == 1,
            "{args:?}: {err}"
        );
    }
}
