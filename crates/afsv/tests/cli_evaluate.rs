//! `afsv evaluate` and `afsv check` end to end (stdout is a pipe here, so both print JSON).

mod cli_support;
use cli_support::{afsv, json};

#[test]
fn evaluate_prints_the_vehicle_assessment_without_self_checks() {
    // one terrain seed keeps the test short (the default is 10)
    let piped = json(&afsv(&["evaluate", "--seeds", "1"]));
    let explicit = json(&afsv(&["evaluate", "--seeds", "1", "--json"]));
    assert_eq!(piped, explicit);
    for key in [
        "vehicle",
        "design_measures_3d",
        "terrain",
        "yaw_plane",
        "front_axle_strut",
    ] {
        assert!(piped.get(key).is_some(), "missing {key}: {piped}");
    }
    assert!(piped.get("iso2631_weighting_check").is_none());
    assert_eq!(piped["yaw_plane"]["stable"], true);
    let zeta = piped["yaw_plane"]["loaded"]["damping_ratio"]
        .as_f64()
        .unwrap();
    assert!(zeta > 0.0 && zeta < 1.0, "{zeta}");
    // the terrain section describes the terrain, not the synthesis fidelity
    assert!(piped["terrain"].get("octave_bands").is_none());
    assert!(piped["terrain"]["rms_left_m"].as_f64().unwrap() > 0.0);
    // the three design measures of the 3-D vehicle, unsuspended and with the HPS
    let d = &piped["design_measures_3d"];
    assert_eq!(d["seeds"], serde_json::json!([1]));
    for axle in ["unsuspended", "nominal_hps"] {
        let a = &d[axle];
        let awz = a["ride_unloaded"]["a_wz_m_s2"]["mean"].as_f64().unwrap();
        assert!(awz > 0.3 && awz < 3.0, "{axle}: {awz}");
        assert!(a["sp_drt_m_s2"]["mean"].as_f64().unwrap() > 1.0);
        assert!(a["yaw"]["omega_z_hz"].as_f64().unwrap() > 1.0);
        assert!(a["ride_loaded"]["hgcz_8h"].is_string());
    }
    assert!(d["unsuspended"]["ride_unloaded"]["strut_travel_m"].is_null());
    assert!(
        d["nominal_hps"]["ride_unloaded"]["strut_travel_m"]["mean"]
            .as_f64()
            .unwrap()
            > 0.0
    );
    // bounded seed count
    assert!(!afsv(&["evaluate", "--seeds", "0"]).status.success());
    assert!(!afsv(&["evaluate", "--seeds", "101"]).status.success());
}

#[test]
fn check_runs_the_self_checks_and_passes() {
    let v = json(&afsv(&["check"]));
    assert_eq!(v["pass"], true);
    assert_eq!(v["iso2631_weighting"]["pass"], true);
    assert_eq!(v["terrain_synthesis"]["fidelity"]["pass"], true);
    assert_eq!(
        v["terrain_synthesis"]["fidelity"]["criteria"]
            .as_array()
            .unwrap()
            .len(),
        4
    );
    let bad = afsv(&["check", "--seed", "nan"]);
    assert!(!bad.status.success());
}
