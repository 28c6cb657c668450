//! `afsv roll`: a run writes its record and sidecar and prints finite measures; the
//! measures of a left and a right ramp agree; the plausible truck, the ramp rate, the
//! stops and the detection rule are options; the truck parameter set dumps and checks;
//! bad input is a one-line error naming the field or option.

mod cli_support;
use cli_support::{afsv, json, scratch};

#[test]
fn simulate_writes_a_record_and_prints_the_measures() {
    let out = scratch("roll", "run.csv");
    let path = out.to_str().unwrap();
    let v = json(&afsv(&["roll", "simulate", "--seed", "2", "-o", path]));
    let rollover = v["rollover_s"].as_f64().unwrap();
    assert!(rollover > 10.0 && rollover < 60.0, "{v}");
    assert!(v["sp_drt_g"].as_f64().unwrap() > 0.1);
    let rec = afsv_records::Record::read(&out).unwrap();
    assert_eq!(rec.len(), v["samples"].as_u64().unwrap() as usize);
    assert!(rec.column("normal_force_rear_right_outer_n").is_some());
    assert!(rec.meta["written_by"].as_str().unwrap().starts_with("afsv"));
    // rerunning onto afsv's own record is allowed
    assert!(afsv(&["roll", "simulate", "--smooth", "-o", path])
        .status
        .success());
}

#[test]
fn a_jump_on_very_wavy_ground_is_marked_not_written_as_nan() {
    // Waviness 3 on class E throws the truck off the ground within the first second: the
    // LTR (Eq 2.11) has no load to transfer there. The record must stay readable.
    let out = scratch("roll", "jump.csv");
    let path = out.to_str().unwrap();
    let v = json(&afsv(&[
        "roll",
        "simulate",
        "--duration",
        "5",
        "--waviness",
        "3",
        "-o",
        path,
    ]));
    let first = v["first_airborne_s"].as_f64().unwrap();
    assert!(first > 0.0 && first < 5.0, "{v}");
    assert!(v["airborne_time_s"].as_f64().unwrap() > 0.0, "{v}");
    let rec = afsv_records::Record::read(&out).unwrap();
    let air = rec.column("airborne").unwrap();
    let ltr = rec.column("ltr").unwrap();
    assert!(air.contains(&1.0));
    for (a, l) in air.iter().zip(ltr) {
        assert!(
            l.is_finite() && (*a == 0.0 || *l == 0.0),
            "airborne {a}, LTR {l}"
        );
    }
}

#[test]
fn left_and_right_ramps_give_the_same_smooth_measures() {
    let left = json(&afsv(&["roll", "measures", "--smooth", "--json"]));
    let right = json(&afsv(&[
        "roll",
        "measures",
        "--smooth",
        "--direction",
        "right",
    ]));
    let (l, r) = (
        left["drt_g"].as_f64().unwrap(),
        right["drt_g"].as_f64().unwrap(),
    );
    assert!((l - r).abs() < 1e-4, "{l} vs {r}");
    assert!((l - 0.288).abs() < 0.01, "calibrated smooth DRT {l}");
    // never airborne on smooth ground: a plain zero, not "-0.0"
    assert_eq!(left["airborne_time_s"].to_string(), "0.0");
}

#[test]
fn truck_parameters_dump_and_check() {
    let file = scratch("roll", "truck.json");
    let f = file.to_str().unwrap();
    json(&afsv(&["params", "dump", "truck", "-o", f]));
    let v = json(&afsv(&["params", "check", "truck", f]));
    assert_eq!(v["parameters"]["cg_height_m"], 3.15);
    std::fs::write(&file, r#"{"cg_to_front_axle_m": 9.0}"#).unwrap();
    let out = afsv(&["params", "check", "truck", f]);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("cg_to_front_axle_m"));
}

#[test]
fn bad_input_is_a_one_line_error() {
    for (args, needle) in [
        (
            vec![
                "roll", "measures", "--smooth", "--seed", "7", "--class", "A",
            ],
            "--seed",
        ),
        (vec!["roll", "study", "cg", "--seeds", "0"], "--seeds"),
        (vec!["roll", "study", "sideways"], "sideways"),
        (vec!["roll", "measures", "--waviness", "nan"], "finite"),
        (vec!["roll", "measures", "--band", "0.02,20"], "band.n_max"),
        (vec!["roll", "measures", "--duration", "1e9"], "--duration"),
        (vec!["roll", "measures", "--truck", "stiff"], "stiff"),
        (
            vec![
                "roll",
                "measures",
                "--truck",
                "plausible",
                "--params",
                "p.json",
            ],
            "--params",
        ),
        (vec!["roll", "measures", "--ramp-rate", "0"], "--ramp-rate"),
        (
            vec!["roll", "measures", "--sp-threshold", "1.5"],
            "--sp-threshold",
        ),
        (
            vec!["roll", "measures", "--sp-max-dip", "-1"],
            "--sp-max-dip",
        ),
        (
            vec!["roll", "study", "trucks", "--truck", "plausible"],
            "--truck",
        ),
        (
            vec!["roll", "study", "sensitivity", "--ramp-rate", "3"],
            "--ramp-rate",
        ),
        (
            vec!["roll", "study", "sensitivity", "--plot", "s.svg"],
            "--plot",
        ),
    ] {
        let out = afsv(&args);
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success(), "{args:?}");
        assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(needle), "{args:?}: {err}");
    }
}

#[test]
fn a_piped_study_prints_one_progress_line_per_run() {
    let out = afsv(&["roll", "study", "waviness", "--seeds", "1"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v = json(&out);
    let runs = v["points"].as_array().unwrap().len();
    let err = String::from_utf8_lossy(&out.stderr);
    let lines: Vec<&str> = err
        .lines()
        .filter(|l| l.starts_with("afsv roll study: "))
        .collect();
    assert_eq!(lines.len(), runs, "{err}");
    assert!(
        lines[runs - 1].contains(&format!("{runs}/{runs} runs")),
        "{err}"
    );
    assert!(lines[0].contains("ETA"), "{err}");
}

#[test]
fn the_plausible_truck_ramp_rate_stops_and_rule_are_options() {
    let m = |args: &[&str]| {
        let mut all = vec!["roll", "measures", "--smooth", "--json"];
        all.extend_from_slice(args);
        json(&afsv(&all))
    };
    let plausible = m(&["--truck", "plausible"]);
    let drt = plausible["drt_g"].as_f64().unwrap();
    assert!((drt - 0.387).abs() < 0.01, "plausible smooth DRT {drt}");
    assert_eq!(plausible["truck"], "plausible");
    // no stops: the soft calibrated truck rolls over earlier, at a lower a_y
    let free = m(&["--no-bump-stops"]);
    assert!(free["first_bump_stop_s"].is_null(), "{free}");
    assert!(free["drt_g"].as_f64().unwrap() < 0.25, "{free}");
    // half the ramp rate: the run lasts long enough (default duration 2 + 290/2.5 s)
    let slow = m(&["--ramp-rate", "2.5"]);
    let t = slow["rollover_s"].as_f64().unwrap();
    assert!(t > 50.0 && t < 122.0, "rollover at {t} s");
    // a looser rule never gives a shorter period on the same run
    let strict = m(&["--sp-threshold", "0.98", "--sp-max-dip", "0.1"]);
    let loose = m(&["--sp-threshold", "0.9", "--sp-max-dip", "1"]);
    assert_eq!(loose["sustained_period_rule"]["threshold"], 0.9);
    let (s, l) = (
        strict["sustained_period_s"].as_f64().unwrap_or(0.0),
        loose["sustained_period_s"].as_f64().unwrap(),
    );
    assert!(l > s, "loose {l} s, strict {s} s");
}

#[test]
fn study_trucks_compares_both_trucks_with_and_without_stops() {
    let out = afsv(&["roll", "study", "trucks", "--seeds", "1"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v = json(&out);
    let points = v["points"].as_array().unwrap();
    let groups: Vec<&str> = points
        .iter()
        .map(|p| p["group"].as_str().unwrap())
        .collect();
    assert_eq!(
        groups,
        [
            "calibrated",
            "calibrated, no stops",
            "plausible",
            "plausible, no stops"
        ]
    );
    let smooth = |i: usize| points[i]["smooth_drt_g"].as_f64().unwrap();
    assert!(
        smooth(2) > smooth(0) + 0.05,
        "{} vs {}",
        smooth(2),
        smooth(0)
    );
    let peak = |i: usize| points[i]["peak_ay_g"]["mean"].as_f64().unwrap();
    assert!(peak(1) < peak(0) && peak(0) < peak(2), "{points:?}");
}

#[test]
fn a_measured_road_equal_to_a_seed_gives_its_record_and_a_short_one_is_refused() {
    // the terrain the truck synthesizes for a 60 s run: 800 m of class E at 5 cm, seed 3
    let road = scratch("roll-road", "road.csv");
    let out = afsv(&[
        "terrain",
        "generate",
        "--length",
        "800",
        "--dx",
        "0.05",
        "--seed",
        "3",
        "-o",
        road.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let (seeded, measured) = (
        scratch("roll-road", "seed.csv"),
        scratch("roll-road", "road-run.csv"),
    );
    let a = json(&afsv(&[
        "roll",
        "simulate",
        "--seed",
        "3",
        "-o",
        seeded.to_str().unwrap(),
    ]));
    let b = json(&afsv(&[
        "roll",
        "simulate",
        "--road",
        road.to_str().unwrap(),
        "-o",
        measured.to_str().unwrap(),
    ]));
    assert_eq!(
        std::fs::read(&seeded).unwrap(),
        std::fs::read(&measured).unwrap()
    );
    assert_eq!(a["drt_g"], b["drt_g"]);
    assert_eq!(b["terrain"]["kind"], "measured two-track road");
    // the road is an input: named in the provenance, never an output
    assert!(b["provenance"]["inputs"].to_string().contains("road.csv"));
    let clash = afsv(&[
        "roll",
        "simulate",
        "--road",
        road.to_str().unwrap(),
        "-o",
        road.to_str().unwrap(),
    ]);
    assert!(!clash.status.success());
    // a run longer than the road carries: one line with the length it needs
    let out = afsv(&[
        "roll",
        "measures",
        "--road",
        road.to_str().unwrap(),
        "--duration",
        "200",
        "--json",
    ]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        !out.status.success() && err.contains("needs") && err.lines().count() == 1,
        "{err}"
    );
}
