//! `afsv params dump | check | list` for every parameter set.

mod cli_support;
use cli_support::{afsv, json, scratch};

const SETS: [&str; 5] = ["yaw-plane", "strut", "tire", "terrain", "surface"];

#[test]
fn every_set_dumps_checks_back_and_lists_its_named_parameters() {
    for set in SETS {
        let path = scratch("params", &format!("{set}.json"));
        let written = json(&afsv(&[
            "params",
            "dump",
            set,
            "-o",
            path.to_str().unwrap(),
        ]));
        assert_eq!(written["written"], path.to_str().unwrap());
        let checked = json(&afsv(&["params", "check", set, path.to_str().unwrap()]));
        assert_eq!(checked["valid"], true, "{set}");
        let listed = json(&afsv(&["params", "list", set]));
        let specs = listed["parameters"].as_array().unwrap();
        assert!(!specs.is_empty(), "{set}");
        // check reports the value of every listed name, and it is the nominal one
        for s in specs {
            let name = s["name"].as_str().unwrap();
            assert_eq!(checked["parameters"][name], s["nominal"], "{set}.{name}");
            let (lo, hi) = (s["lower"].as_f64().unwrap(), s["upper"].as_f64().unwrap());
            let v = s["nominal"].as_f64().unwrap();
            assert!(lo <= v && v <= hi, "{set}.{name}: {v} outside [{lo}, {hi}]");
        }
    }
}

#[test]
fn unknown_fields_are_refused_with_line_and_column_in_every_set() {
    for set in SETS {
        let path = scratch("params-bad", &format!("{set}.json"));
        std::fs::write(&path, "{\n  \"no_such_field\": 1\n}\n").unwrap();
        let out = afsv(&["params", "check", set, path.to_str().unwrap()]);
        assert!(!out.status.success(), "{set}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            err.contains("no_such_field") && err.contains("line 2"),
            "{set}: {err}"
        );
        assert_eq!(err.lines().count(), 1, "{set}: {err}");
    }
}

#[test]
fn strut_dump_offers_every_built_in_strut() {
    let front = json(&afsv(&["params", "dump", "strut"]));
    let lab = json(&afsv(&[
        "params",
        "dump",
        "strut",
        "--strut",
        "lab-1orifice",
    ]));
    assert_eq!(front["a_hc"], 0.038);
    assert_ne!(front["a_hc"], lab["a_hc"]);
    assert_eq!(lab["n_b"], 1);
}

#[test]
fn a_value_outside_its_registry_range_is_refused_where_the_file_is_read() {
    // The bleed area x 1e6 passes the strut's own validation but would make every run
    // stiff and slow: `params check` and every command that reads the file refuse it at
    // once, naming the parameter and its range.
    let path = scratch("params", "wide-bleed.json");
    json(&afsv(&[
        "params",
        "dump",
        "strut",
        "-o",
        path.to_str().unwrap(),
    ]));
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
    v["a_b"] = serde_json::json!(v["a_b"].as_f64().unwrap() * 1e6);
    std::fs::write(&path, v.to_string()).unwrap();
    for args in [
        vec!["params", "check", "strut", path.to_str().unwrap()],
        vec!["hps", "harmonic", "--strut", path.to_str().unwrap()],
    ] {
        let out = afsv(&args);
        assert_eq!(out.status.code(), Some(1), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            err.contains("`a_b` = 11 is outside [0.0000001, 0.001]"),
            "{args:?}: {err}"
        );
    }
}

/// The nominal `set` as printed by `params dump SET` on stdout, with `field` (a JSON
/// pointer) set to `value` (none: as printed), written to a scratch file.
fn dumped_with(set: &str, field: &str, value: Option<f64>) -> std::path::PathBuf {
    let out = afsv(&["params", "dump", set]);
    assert!(out.status.success());
    let mut v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    if let Some(value) = value {
        *v.pointer_mut(field).unwrap() = serde_json::json!(value);
    }
    let path = scratch(
        "params",
        &format!("printed-{set}{}.json", field.replace('/', "-")),
    );
    std::fs::write(&path, v.to_string()).unwrap();
    path
}

#[test]
fn a_printed_dump_reads_back_and_meaningless_zeros_are_refused() {
    // `params dump SET > file` is a parameter file as it stands
    for set in [
        "strut",
        "tire",
        "yaw-plane",
        "vehicle-3d",
        "truck",
        "seat",
        "cab",
    ] {
        let path = dumped_with(set, "", None);
        let out = afsv(&["params", "check", set, path.to_str().unwrap()]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(out.status.success(), "{set}: {err}");
    }
    // values that would mean no orifice, no gas, no tire pressure, no valve, no tire
    for (set, field, name) in [
        ("strut", "/c_b", "c_b"),
        ("strut", "/v_c0", "v_c0"),
        ("strut", "/a_b", "a_b"),
        ("strut", "/p_amb", "p_amb"),
        ("tire", "/charge_pressure_pa", "charge_pressure_pa"),
        ("yaw-plane", "/afs/valve_am", "valve_am"),
        (
            "yaw-plane",
            "/vehicle/c_alpha_f_n_per_rad",
            "c_alpha_f_n_per_rad",
        ),
        ("yaw-plane", "/vehicle/half_track_m", "half_track_m"),
        ("vehicle-3d", "/steering/valve_am", "valve_am"),
        ("vehicle-3d", "/hps/v_c0", "v_c0"),
        (
            "vehicle-3d",
            "/tire/charge_pressure_pa",
            "charge_pressure_pa",
        ),
    ] {
        let path = dumped_with(set, field, Some(0.0));
        let out = afsv(&["params", "check", set, path.to_str().unwrap()]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{set}{field}: {err}");
        assert!(
            err.contains(&format!("`{name}` = 0 is outside")),
            "{set}{field}: {err}"
        );
    }
}
