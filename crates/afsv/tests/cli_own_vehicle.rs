//! A user's own vehicle through the commands: the example description
//! `samples/vehicles/adt-28t.toml` (a 28 t articulated dump truck with a suspended front axle
//! and its own strut file, yaw-plane data derived from its units) runs through `params check`,
//! `evaluate`, `vehicle ride`, `yaw measures`, `study speed-sweep` and `hps characterize`
//! and gives numbers of its own; the prototype dumped to a file and read back gives the
//! built-in's numbers bit for bit, as does the Chapter 2 truck; and a description without a strut is refused where a strut
//! is designed.

mod cli_support;
use cli_support::{afsv, json, repo_root, scratch};
use std::sync::OnceLock;

fn adt() -> String {
    repo_root()
        .join("samples/vehicles/adt-28t.toml")
        .to_string_lossy()
        .into_owned()
}

/// `v` without its `"provenance"` (which names the input files, so differs between a
/// built-in and a file).
fn without_provenance(mut v: serde_json::Value) -> serde_json::Value {
    v.as_object_mut().unwrap().remove("provenance");
    v
}

/// `afsv evaluate adt-28t.toml --seeds 1` (the file as the positional `VEHICLE`), run once for the tests that compare
/// with it (the chain of commands is split into tests so that libtest runs them side by
/// side; each command runs once, as before).
fn evaluated() -> &'static serde_json::Value {
    static E: OnceLock<serde_json::Value> = OnceLock::new();
    E.get_or_init(|| json(&afsv(&["evaluate", &adt(), "--seeds", "1"])))
}

/// `a_wz` of the D1 ride in [`evaluated`]: (unsuspended, nominal HPS).
fn evaluated_a_wz() -> (f64, f64) {
    let d = &evaluated()["design_measures_3d"];
    let of = |case: &str| {
        d[case]["ride_loaded"]["a_wz_m_s2"]["mean"]
            .as_f64()
            .unwrap()
    };
    (of("unsuspended"), of("nominal_hps"))
}

/// `afsv vehicle ride --vehicle adt-28t.toml --seeds 1 --json` plus `extra`.
fn ride(extra: &[&str]) -> serde_json::Value {
    let f = adt();
    let mut args = vec!["vehicle", "ride", "--vehicle", &f, "--seeds", "1", "--json"];
    args.extend_from_slice(extra);
    json(&afsv(&args))
}

/// [`ride`] with the described front axle (HPS), run once for the tests that compare with it.
fn suspended_ride() -> &'static serde_json::Value {
    static R: OnceLock<serde_json::Value> = OnceLock::new();
    R.get_or_init(|| ride(&[]))
}

#[test]
fn an_own_truck_is_checked_and_evaluated_with_its_own_strut() {
    let f = adt();
    let check = json(&afsv(&["params", "check", "vehicle", &f]));
    assert_eq!(check["kind"], "articulated");
    assert_eq!(check["front_suspension"], "hps");
    assert_eq!(check["yaw_plane"], "derived from the units and tire");
    assert_eq!(
        check["parameters"]["front_unit.mass_kg"], 13500.0,
        "{check}"
    );

    // The main job: both front axles, the strut from the description's file.
    let e = evaluated();
    assert!(e["vehicle"].as_str().unwrap().contains("28 t"), "{e}");
    let src = e["front_axle_strut"]["source"].as_str().unwrap();
    assert!(src.ends_with("adt-28t-front-strut.json"), "{src}");
    let (rigid, hps) = evaluated_a_wz();
    assert!(hps < rigid, "the strut lowers a_wz: {hps} vs {rigid}");

    // The vehicle is named once: the positional file and `--vehicle` together are refused.
    let both = afsv(&["evaluate", &f, "--vehicle", "prototype", "--seeds", "1"]);
    assert_eq!(both.status.code(), Some(2), "{both:?}");
    let err = String::from_utf8_lossy(&both.stderr);
    assert!(err.contains("cannot be used with"), "{err}");
}

/// `vehicle ride` (loaded by default) takes the described front axle (HPS) unless told
/// otherwise.
#[test]
fn an_own_truck_rides_the_evaluated_case_with_and_without_its_strut() {
    let (rigid, hps) = evaluated_a_wz();
    let suspended = suspended_ride();
    let off = ride(&["--hps", "off"]);
    assert_eq!(
        suspended["a_wz_m_s2"]["mean"].as_f64().unwrap(),
        hps,
        "evaluate and vehicle ride run the same D1 case: {suspended}"
    );
    assert_eq!(off["a_wz_m_s2"]["mean"].as_f64().unwrap(), rigid);
}

/// The yaw-plane model takes the derived data: another vehicle, another yaw mode.
#[test]
fn an_own_truck_has_a_yaw_mode_of_its_own() {
    let own = json(&afsv(&["yaw", "measures", "--vehicle", &adt()]));
    let proto = json(&afsv(&["yaw", "measures"]));
    let (fo, fp) = (
        own["natural_frequency_hz"].as_f64().unwrap(),
        proto["natural_frequency_hz"].as_f64().unwrap(),
    );
    assert!(fo.is_finite() && (fo - fp).abs() > 0.1, "{fo} vs {fp}");
}

/// The design studies take it, with its strut as the nominal design.
#[test]
fn an_own_truck_runs_the_speed_sweep() {
    let sweep = json(&afsv(&[
        "study",
        "speed-sweep",
        "--vehicle",
        &adt(),
        "--speeds",
        "20",
        "--seeds",
        "1",
        "--json",
    ]));
    let points = sweep["points"].as_array().unwrap();
    assert_eq!(points.len(), 2, "{sweep}");
}

/// On a measured road (a two-track CSV in mm): the file's profile, read and converted.
#[test]
fn an_own_truck_rides_a_measured_road_in_mm() {
    let f = adt();
    let road = scratch("own", "road.csv");
    json(&afsv(&[
        "terrain",
        "generate",
        "--class",
        "D",
        "--length",
        "200",
        "--seed",
        "4",
        "-o",
        road.to_str().unwrap(),
    ]));
    let text = std::fs::read_to_string(&road).unwrap();
    let mut mm = String::from("x_m,left_mm,right_mm\n");
    for line in text.lines().skip(1) {
        let v: Vec<f64> = line.split(',').map(|c| c.parse().unwrap()).collect();
        mm += &format!("{},{},{}\n", v[0], v[1] * 1e3, v[2] * 1e3);
    }
    let road_mm = scratch("own", "road-mm.csv");
    std::fs::write(&road_mm, mm).unwrap();
    let on_road = json(&afsv(&[
        "vehicle",
        "ride",
        "--vehicle",
        &f,
        "--road",
        road_mm.to_str().unwrap(),
        "--json",
    ]));
    assert_eq!(on_road["terrain"]["kind"], "measured two-track road");
    assert_eq!(on_road["terrain"]["samples"], 4001);
    let conv = on_road["terrain"]["unit_conversions"].to_string();
    assert!(conv.contains("left_mm"), "{conv}");
    let a = on_road["a_wz_m_s2"]["mean"].as_f64().unwrap();
    assert!(
        a > 0.05 && a < suspended_ride()["a_wz_m_s2"]["mean"].as_f64().unwrap(),
        "class D is smoother than E: {a}"
    );
}

/// The HPS GA on it: this truck's strut cannot meet a_wz <= 0.85 m/s² in one generation, so
/// the best found is printed and the exit status says it is no optimum.
#[test]
fn an_own_truck_runs_the_hps_ga() {
    let out = afsv(&[
        "optimize",
        "hps",
        "--vehicle",
        &adt(),
        "--population",
        "4",
        "--generations",
        "1",
        "--reevaluation-seeds",
        "1",
        "--no-roll",
        "--json",
    ]);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    if v["feasible"] == true {
        assert!(out.status.success());
    } else {
        assert_eq!(out.status.code(), Some(3), "{out:?}");
        assert!(String::from_utf8_lossy(&out.stderr).contains("not earned"));
    }
    assert!(v["nominal_ride"]["a_wz_m_s2"].as_f64().unwrap() > 0.0);
}

/// The strut file works wherever a built-in strut does.
#[test]
fn an_own_strut_file_is_characterized() {
    let strut = repo_root().join("samples/vehicles/adt-28t-front-strut.json");
    let c = json(&afsv(&[
        "hps",
        "characterize",
        "--strut",
        strut.to_str().unwrap(),
    ]));
    assert_eq!(c["tests"].as_array().unwrap().len(), 43);
}

#[test]
fn the_dumped_prototype_reads_back_to_the_built_in_numbers_bit_for_bit() {
    let file = scratch("own", "prototype.toml");
    json(&afsv(&[
        "params",
        "dump",
        "vehicle",
        "-o",
        file.to_str().unwrap(),
    ]));
    let f = file.to_str().unwrap();
    for args in [
        vec!["vehicle", "ride", "--seeds", "1", "--json"],
        vec!["vehicle", "yaw", "--json"],
        vec!["yaw", "measures"],
    ] {
        let builtin = without_provenance(json(&afsv(&args)));
        let mut with_file = args.clone();
        with_file.extend(["--vehicle", f]);
        let described = json(&afsv(&with_file));
        // The output names the description it read, with its SHA-256.
        let inputs = described["provenance"]["inputs"].to_string();
        assert!(
            inputs.contains("prototype.toml") && inputs.contains("sha256"),
            "{inputs}"
        );
        assert_eq!(without_provenance(described), builtin, "{args:?}");
    }
}

#[test]
fn the_dumped_chapter2_truck_reads_back_to_the_built_in_numbers_bit_for_bit() {
    let file = scratch("own", "truck.toml");
    json(&afsv(&[
        "params",
        "dump",
        "vehicle",
        "--builtin",
        "chapter2-truck",
        "-o",
        file.to_str().unwrap(),
    ]));
    let strip = |v: serde_json::Value| {
        let mut v = without_provenance(v);
        v.as_object_mut().unwrap().remove("truck");
        v
    };
    let builtin = strip(json(&afsv(&["roll", "measures", "--json"])));
    let described = json(&afsv(&[
        "roll",
        "measures",
        "--json",
        "--vehicle",
        file.to_str().unwrap(),
    ]));
    assert_eq!(described["truck"], file.to_str().unwrap());
    assert_eq!(strip(described), builtin);
    // An articulated description is no rigid truck, and the other way round.
    for args in [
        vec!["roll", "measures", "--vehicle", "prototype"],
        vec!["vehicle", "yaw", "--vehicle", file.to_str().unwrap()],
    ] {
        let out = afsv(&args);
        assert!(!out.status.success(), "{args:?}");
        assert!(String::from_utf8_lossy(&out.stderr).contains("--vehicle"));
    }
}

#[test]
fn a_measured_road_of_the_synthesised_profile_gives_the_seed_run_bit_for_bit() {
    // `vehicle ride --seed 1` synthesises 165 m of class E at 5 cm (15 m behind the start,
    // 20 m run-in, 100 m window, 30 m beyond); the same profile written by `terrain
    // generate` and read back as a measured road gives the same run.
    let road = scratch("own", "seed1.csv");
    json(&afsv(&[
        "terrain",
        "generate",
        "--class",
        "E",
        "--length",
        "165",
        "--dx",
        "0.05",
        "--seed",
        "1",
        "-o",
        road.to_str().unwrap(),
    ]));
    let synth = json(&afsv(&["vehicle", "ride", "--seed", "1", "--json"]));
    let measured = json(&afsv(&[
        "vehicle",
        "ride",
        "--road",
        road.to_str().unwrap(),
        "--json",
    ]));
    assert_eq!(measured["a_wz_m_s2"], synth["a_wz_m_s2"]);
    assert_eq!(
        measured["provenance"]["inputs"][0]["file"],
        road.to_str().unwrap()
    );
    assert_eq!(
        measured["per_seed"][0]["measures"],
        synth["per_seed"][0]["measures"]
    );
    // The same profile as an ASAM OpenCRG file (LDFI, two long sections at plus and minus
    // half the prototype's 2.28 m front track) gives the run of a record holding the same
    // 14-digit values, bit for bit. (Against the full-precision record a_wz differs by
    // 6e-4: the adaptive steps follow the last digits of the road.)
    let (crg, rounded) = (scratch("own", "seed1.crg"), scratch("own", "seed1-14.csv"));
    let (crg_text, csv_text) = crg_of(&road);
    std::fs::write(&crg, crg_text).unwrap();
    std::fs::write(&rounded, csv_text).unwrap();
    let ride_on = |file: &std::path::Path| {
        json(&afsv(&[
            "vehicle",
            "ride",
            "--road",
            file.to_str().unwrap(),
            "--json",
        ]))
    };
    let (from_crg, from_csv) = (ride_on(&crg), ride_on(&rounded));
    assert_eq!(from_crg["terrain"]["format"], "OpenCRG");
    assert_eq!(from_crg["a_wz_m_s2"], from_csv["a_wz_m_s2"]);
    assert_eq!(
        from_crg["per_seed"][0]["measures"],
        from_csv["per_seed"][0]["measures"]
    );
    // A road too short for the window says how long it must be.
    let out = afsv(&[
        "vehicle",
        "ride",
        "--road",
        road.to_str().unwrap(),
        "--length-m",
        "200",
    ]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        !out.status.success() && err.contains("needs 265.0 m"),
        "{err}"
    );
}

#[test]
fn a_vehicle_without_a_strut_is_refused_where_a_strut_is_designed() {
    let text = std::fs::read_to_string(adt()).unwrap();
    let no_strut = text
        .replace("suspension = \"hps\"", "suspension = \"rigid\"")
        .replace("strut = \"adt-28t-front-strut.json\"\n", "");
    let file = scratch("own", "no-strut.toml");
    std::fs::write(&file, no_strut).unwrap();
    let f = file.to_str().unwrap();
    for args in [
        vec!["optimize", "hps", "--vehicle", f],
        vec!["study", "hps-sensitivity", "--vehicle", f],
        vec!["vehicle", "ride", "--vehicle", f, "--hps", "nominal"],
    ] {
        let out = afsv(&args);
        assert!(!out.status.success(), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains("no strut"), "{args:?}: {err}");
        assert_eq!(err.lines().count(), 1, "{err}");
    }
    // The rigid vehicle itself runs: no HPS column, and the JSON says why.
    let e = json(&afsv(&["evaluate", "--vehicle", f, "--seeds", "1"]));
    assert!(e["design_measures_3d"]["nominal_hps"].is_null());
    assert!(e["front_axle_strut_reason"]
        .as_str()
        .unwrap()
        .contains("no strut"));
}

/// The two-track record `csv` (x_m, left_m, right_m at a uniform step) as an OpenCRG ASCII
/// file with long sections at v = -1.14 m (right) and +1.14 m (left), LDFI fields of 14
/// digits, and as a record holding the same 14-digit values.
fn crg_of(csv: &std::path::Path) -> (String, String) {
    let text = std::fs::read_to_string(csv).unwrap();
    let rows: Vec<Vec<f64>> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|c| c.parse().unwrap()).collect())
        .collect();
    let dx = rows[1][0] - rows[0][0];
    let mut crg = format!(
        "$CT\nthe seed-1 class E profile\n$\n$ROAD_CRG\nREFERENCE_LINE_INCREMENT = {dx}\n\
         LONG_SECTION_V_RIGHT = -1.14\nLONG_SECTION_V_LEFT = 1.14\n\
         LONG_SECTION_V_INCREMENT = 2.28\n$\n$KD_Definition\n#:LDFI\n\
         D:long section 1,m\nD:long section 2,m\n$\n$$$$\n"
    );
    let mut record = String::from("x_m,left_m,right_m\n");
    for r in &rows {
        let (left, right) = (format!("{:.13e}", r[1]), format!("{:.13e}", r[2]));
        crg += &format!("{right:>20}{left:>20}\n");
        record += &format!("{},{left},{right}\n", r[0]);
    }
    (crg, record)
}
