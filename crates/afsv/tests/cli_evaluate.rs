//! `afsv evaluate` and `afsv check` end to end (stdout is a pipe here, so both print JSON).

mod cli_support;
use cli_support::{afsv, json};

#[test]
fn evaluate_prints_the_vehicle_assessment_without_self_checks() {
    let piped = json(&afsv(&["evaluate"]));
    let explicit = json(&afsv(&["evaluate", "--json"]));
    assert_eq!(piped, explicit);
    for key in ["vehicle", "terrain", "yaw_plane", "front_axle_strut"] {
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
