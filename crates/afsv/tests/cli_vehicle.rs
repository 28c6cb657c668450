//! `afsv vehicle`: the design runs report the scenario measures as mean ± SD over the seeds
//! (checked against the per-seed values), the HGCZ verdict agrees with the zone bounds, the
//! HPS option switches the strut in, `simulate` writes an afsv-v1 record (a right-hand
//! pulse gives positive steering, articulation and yaw rate), plots are written, the
//! vehicle-3d parameter set dumps and checks, and bad input is a one-line error.

mod cli_support;
use cli_support::{afsv, json, scratch};
use serde_json::Value;

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// The mean and sample SD of `values`, by hand.
fn mean_sd(values: &[f64]) -> (f64, f64) {
    let n = values.len() as f64;
    let mean = values.iter().sum::<f64>() / n;
    let var = values.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0);
    (mean, var.sqrt())
}

fn per_seed(v: &Value, measure: &str) -> Vec<f64> {
    v["per_seed"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| num(&r["measures"][measure]))
        .collect()
}

#[test]
fn ride_reports_mean_and_sd_over_the_seeds_with_the_hgcz_verdict() {
    let out = afsv(&["vehicle", "ride", "--seeds", "2", "--length-m", "30"]);
    let v = json(&out);
    let a = per_seed(&v, "a_wz_m_s2");
    assert_eq!(a.len(), 2);
    assert_ne!(a[0], a[1], "two seeds give two terrains");
    let (mean, sd) = mean_sd(&a);
    assert!((num(&v["a_wz_m_s2"]["mean"]) - mean).abs() < 1e-12, "{v}");
    assert!((num(&v["a_wz_m_s2"]["sd"]) - sd).abs() < 1e-12, "{v}");
    assert_eq!(v["a_wz_m_s2"]["n"], 2);
    assert!(mean > 0.1 && mean < 10.0, "a_wz {mean}");
    // the W_k weighting lowers the RMS of a vertical ride signal dominated by 1-2 Hz
    assert!(num(&v["a_z_rms_m_s2"]["mean"]) > mean);
    let zone = &v["hgcz"];
    let (lo, hi) = (num(&zone["lower_m_s2"]), num(&zone["upper_m_s2"]));
    assert!((lo - 3.0 / 48f64.sqrt()).abs() < 1e-12 && (hi - 2.0 * lo).abs() < 1e-12);
    let expected = if mean < lo {
        "below"
    } else if mean <= hi {
        "within"
    } else {
        "above"
    };
    assert_eq!(zone["a_wz_mean_zone"], expected);
    assert!(v["strut_travel_p2p_m"].is_null());
    assert!(v["strut_travel_p2p_m_reason"]
        .as_str()
        .unwrap()
        .contains("rigid"));
    // a piped multi-seed run reports one progress line per run
    let err = String::from_utf8_lossy(&out.stderr);
    let lines: Vec<&str> = err
        .lines()
        .filter(|l| l.starts_with("afsv vehicle ride: "))
        .collect();
    assert_eq!(lines.len(), 2, "{err}");
    assert!(lines[1].contains("2/2 runs"), "{err}");
    assert!(v["seat"].is_null() && v["seat_reason"].as_str().unwrap().contains("--seat"));
}

/// `--seat generic` reads ISO 2631-1 at the seat as well: the frame's numbers are the ride's
/// own, SEAT is the seat's a_wz over the floor's in each run, and the zone verdict at the
/// seat follows the seat's mean.
#[test]
fn ride_with_the_generic_seat_reports_the_seat_and_seat_value() {
    let args = ["vehicle", "ride", "--seeds", "2", "--length-m", "30"];
    let frame = json(&afsv(&args));
    let v = json(&afsv(&[&args[..], &["--seat", "generic"]].concat()));
    assert_eq!(v["a_wz_m_s2"], frame["a_wz_m_s2"]);
    let seat = &v["seat"];
    let runs = seat["per_run"].as_array().unwrap();
    assert_eq!(runs.len(), 2);
    for r in runs {
        let ratio = num(&r["a_wz_seat_m_s2"]) / num(&r["a_wz_floor_m_s2"]);
        assert!(
            (num(&r["seat"]["seat"]) - ratio).abs() < 1e-9 * ratio,
            "{r}"
        );
    }
    let mean = num(&seat["a_wz_seat_m_s2"]["mean"]);
    let zone = &frame["hgcz"];
    let expected = if mean < num(&zone["lower_m_s2"]) {
        "below"
    } else if mean <= num(&zone["upper_m_s2"]) {
        "within"
    } else {
        "above"
    };
    assert_eq!(seat["a_wz_seat_mean_zone"], expected, "{seat}");
    let bad = afsv(&[&args[..], &["--seat", "soft"]].concat());
    assert!(!bad.status.success());
}

#[test]
fn the_hps_option_switches_the_front_strut_in() {
    let strut = scratch("vehicle", "strut.json");
    let s = strut.to_str().unwrap();
    json(&afsv(&["params", "dump", "strut", "-o", s]));
    let base = ["vehicle", "ride", "--seed", "4", "--length-m", "30"];
    let rigid = json(&afsv(&base));
    let nominal = json(&afsv(&[&base[..], &["--hps", "nominal"]].concat()));
    let from_file = json(&afsv(&[&base[..], &["--hps", s]].concat()));
    assert_eq!(nominal["front_axle"], "suspended");
    let travel = num(&nominal["strut_travel_p2p_m"]["mean"]);
    assert!(travel > 1e-3 && travel < 0.5, "d_s {travel}");
    // the dumped front-axle strut is the nominal one
    assert_eq!(nominal["a_wz_m_s2"], from_file["a_wz_m_s2"]);
    assert_ne!(rigid["a_wz_m_s2"], nominal["a_wz_m_s2"]);
    // a bad strut file names its field
    let text = std::fs::read_to_string(&strut).unwrap();
    let mut p: Value = serde_json::from_str(&text).unwrap();
    p["a_hc"] = serde_json::json!(-1.0);
    std::fs::write(&strut, p.to_string()).unwrap();
    let out = afsv(&[&base[..], &["--hps", s]].concat());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success());
    assert!(err.contains("--hps") && err.contains("a_hc"), "{err}");
}

#[test]
fn yaw_on_smooth_ground_fits_the_articulation_decay_and_plots_it() {
    let plot = scratch("vehicle", "yaw.svg");
    let p = plot.to_str().unwrap();
    let v = json(&afsv(&["vehicle", "yaw", "--plot", p]));
    let omega = num(&v["omega_z_hz"]["mean"]);
    let damped = num(&v["damped_frequency_hz"]["mean"]);
    let zeta = num(&v["damping_ratio"]["mean"]);
    assert!(omega > 1.0 && omega < 10.0, "omega_z {omega}");
    assert!(zeta > 0.0 && zeta < 1.0, "zeta {zeta}");
    // omega_d = omega_n sqrt(1 - zeta^2)
    assert!((damped - omega * (1.0 - zeta * zeta).sqrt()).abs() < 1e-6 * omega);
    assert_eq!(v["omega_z_hz"]["n"], 1);
    assert!(v["per_seed"][0]["seed"].is_null());
    assert_eq!(v["terrain"]["kind"], "smooth ground");
    let svg = std::fs::read_to_string(&plot).unwrap();
    assert!(svg.contains("written_by: afsv") && svg.contains("single-DOF fit"));
    // a larger pulse gives a larger articulation (less than in proportion)
    let big = json(&afsv(&["vehicle", "yaw", "--pulse-deg", "60"]));
    assert!(
        num(&big["peak_articulation_deg"]["mean"]) > 1.2 * num(&v["peak_articulation_deg"]["mean"])
    );
    // the fit is honest about its form: the hydraulic steering's free response is not one
    // decaying mode, and the output says so
    assert_eq!(v["yaw_inertia_form"], "energy_consistent");
    assert!(num(&v["per_seed"][0]["measures"]["fit_residual_to_noise"]) > 3.0);
    assert!(v["fit_caveat"].as_str().unwrap().contains("window"));
    // --paper-form: the printed Eq 3.13 counts m L² twice, so the yaw mode drops (towards
    // the dissertation's 2.81 Hz) and the output names the form
    let paper = json(&afsv(&["vehicle", "yaw", "--paper-form"]));
    assert_eq!(paper["yaw_inertia_form"], "paper_eq_3_13");
    let low = num(&paper["omega_z_hz"]["mean"]);
    assert!(low < 0.7 * omega, "paper form {low} Hz against {omega} Hz");
}

#[test]
fn roll_to_rollover_reports_sp_drt_within_the_sustained_period() {
    let plot = scratch("vehicle", "roll.svg");
    let p = plot.to_str().unwrap();
    let v = json(&afsv(&[
        "vehicle",
        "roll",
        "--terrain",
        "class:C,mc:0.3",
        "--seed",
        "2",
        "--ramp-deg-s",
        "20",
        "--plot",
        p,
    ]));
    let m = &v["per_seed"][0]["measures"];
    assert_eq!(v["per_seed"][0]["seed"], 2);
    let (lo, hi) = (
        num(&m["sustained_range_m_s2"][0]),
        num(&m["sustained_range_m_s2"][1]),
    );
    let sp = num(&v["sp_drt_m_s2"]["mean"]);
    // an RMS lies between the smallest and largest value it averages
    assert!(lo <= sp && sp <= hi, "{lo} <= {sp} <= {hi}");
    assert!(hi <= num(&v["peak_ay_m_s2"]["mean"]) + 1e-12);
    let (a, b) = (num(&m["sustained_s"][0]), num(&m["sustained_s"][1]));
    let rollover = num(&v["rollover_s"]["mean"]);
    assert!(1.0 < a && a < b && b <= rollover, "{a} {b} {rollover}");
    assert!((num(&v["sustained_period_s"]["mean"]) - (b - a)).abs() < 1e-12);
    assert_eq!(v["rolled_over"], 1);
    assert_eq!(v["terrain"]["class"], "C");
    let svg = std::fs::read_to_string(&plot).unwrap();
    assert!(svg.contains("written_by: afsv") && svg.contains("sustained period"));
}

/// At its defaults `vehicle roll --seed N` is D2 on the terrain of seed N, the run
/// `afsv evaluate` makes: the same duration, so the same terrain length and realisation.
#[test]
fn a_roll_seed_reads_the_terrain_evaluate_reads() {
    use vehicle_3d::scenarios::{roll, RollSpec};
    use vehicle_3d::{FrontAxle, VehicleParams};
    let v = json(&afsv(&["vehicle", "roll", "--seed", "3", "--json"]));
    let (_, m) = roll(
        &VehicleParams::nominal(),
        &RollSpec::d2(FrontAxle::Rigid),
        3,
    )
    .unwrap();
    let rollover = m.rollover_s.expect("D2 rolls over");
    assert!(
        (num(&v["rollover_s"]["mean"]) - rollover).abs() < 1e-9,
        "{} against {rollover}",
        v["rollover_s"]
    );
    assert!((num(&v["sp_drt_m_s2"]["mean"]) - m.sp_drt_m_s2).abs() < 1e-9);
}

#[test]
fn simulate_writes_an_afsv_v1_record_of_a_right_hand_pulse() {
    let out = scratch("vehicle", "run.csv");
    let path = out.to_str().unwrap();
    let args = [
        "vehicle",
        "simulate",
        "--steer",
        "pulse:30,0.2,0.5",
        "--duration",
        "2",
        "--speed-kmh",
        "30",
        "-o",
        path,
    ];
    let v = json(&afsv(&args));
    let rec = afsv_records::Record::read(&out).unwrap();
    assert_eq!(rec.len(), v["samples"].as_u64().unwrap() as usize);
    assert_eq!(rec.len(), 401);
    for name in [
        "time_s",
        "steer_wheel_deg",
        "speed_m_s",
        "articulation_deg",
        "strut_left_disp_m",
        "p_c_pa",
        "p_r_pa",
        "yaw_rate_front_deg_s",
        "cab_accel_z_m_s2",
        "front_pitch_accel_rad_s2",
        "rear_lateral_accel_m_s2",
        "rear_ltr",
        "hps_travel_left_m",
        "hps_travel_right_m",
        "normal_force_front_left_n",
        "normal_force_rear_right_n",
    ] {
        assert!(rec.column(name).is_some(), "no column {name}");
    }
    let col = |n: &str| rec.column(n).unwrap().to_vec();
    let extreme = |x: &[f64]| {
        x.iter()
            .fold(0.0f64, |m, v| if v.abs() > m.abs() { *v } else { m })
    };
    // afsv-v1: a right-hand turn is positive in the steering, articulation and yaw rate;
    // during the pulse (0.5-0.7 s, before the return swing) the front unit turns right
    let pulse = col("time_s").iter().filter(|t| **t <= 0.7).count();
    assert!((extreme(&col("steer_wheel_deg")[..pulse]) - 30.0).abs() < 0.5);
    assert!(extreme(&col("articulation_deg")[..pulse]) > 0.1);
    assert!(extreme(&col("yaw_rate_front_deg_s")[..pulse]) > 0.1);
    // ... and the left strut extends in it
    assert!(extreme(&col("strut_left_disp_m")[..pulse]) > 0.0);
    let speed = col("speed_m_s");
    assert!((speed[0] - 30.0 / 3.6).abs() < 0.05, "{}", speed[0]);
    assert!(col("hps_travel_left_m").iter().all(|z| *z == 0.0));
    assert!(col("p_c_pa").iter().all(|p| *p > 0.0), "absolute pressures");
    assert_eq!(rec.meta["sign_convention"], "afsv-v1");
    assert_eq!(rec.meta["load"], "loaded");
    assert_eq!(rec.meta["manoeuvre"], "pulse");
    assert!(rec.meta["written_by"].as_str().unwrap().starts_with("afsv"));
    // rerunning onto afsv's own record is allowed
    assert!(afsv(&args).status.success());
    // a parameter file is never an output, and a foreign file needs --force
    let params = scratch("vehicle", "vehicle.json");
    let pf = params.to_str().unwrap();
    json(&afsv(&["params", "dump", "vehicle-3d", "-o", pf]));
    let run =
        |extra: &[&str]| afsv(&[&["vehicle", "simulate", "--duration", "0.2"][..], extra].concat());
    let same = run(&["--params", pf, "-o", pf]);
    assert!(!same.status.success());
    assert!(String::from_utf8_lossy(&same.stderr).contains("same file as the input --params"));
    let foreign = scratch("vehicle", "foreign.csv");
    std::fs::write(&foreign, "time_s\n0\n").unwrap();
    let f = foreign.to_str().unwrap();
    let refused = run(&["-o", f]);
    assert!(String::from_utf8_lossy(&refused.stderr).contains("--force"));
    assert_eq!(std::fs::read_to_string(&foreign).unwrap(), "time_s\n0\n");
    assert!(run(&["-o", f, "--force"]).status.success());
}

#[test]
fn simulate_on_a_terrain_with_the_hps_moves_the_struts() {
    let out = scratch("vehicle", "rough.csv");
    let path = out.to_str().unwrap();
    let v = json(&afsv(&[
        "vehicle",
        "simulate",
        "--terrain",
        "class:D,seed:5",
        "--hps",
        "nominal",
        "--load",
        "unloaded",
        "--duration",
        "3",
        "-o",
        path,
    ]));
    assert_eq!(v["samples"], 601);
    let rec = afsv_records::Record::read(&out).unwrap();
    let z = rec.column("hps_travel_left_m").unwrap();
    let span =
        z.iter().fold(f64::MIN, |m, v| m.max(*v)) - z.iter().fold(f64::MAX, |m, v| m.min(*v));
    assert!(span > 1e-3, "strut travel span {span}");
    assert_eq!(rec.meta["terrain"]["class"], "D");
    assert_eq!(rec.meta["terrain"]["seeds"][0], 5);
    assert_eq!(rec.meta["load"], "unloaded");
}

#[test]
fn vehicle_parameters_dump_and_check() {
    let file = scratch("vehicle", "params.json");
    let f = file.to_str().unwrap();
    json(&afsv(&["params", "dump", "vehicle-3d", "-o", f]));
    let v = json(&afsv(&["params", "check", "vehicle-3d", f]));
    assert_eq!(v["valid"], true);
    assert_eq!(v["parameters"]["front_axle_to_joint_m"], 1.68);
    for (text, needle) in [
        (r#"{"wheel_base_m": 5.0}"#, "wheel_base_m"),
        (r#"{"payload": {"mass_kg": 1.0, "colour": 3}}"#, "colour"),
        (r#"{"rear_track_m": -2.0}"#, "rear_track_m"),
    ] {
        std::fs::write(&file, text).unwrap();
        let out = afsv(&["params", "check", "vehicle-3d", f]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success(), "{text}");
        assert!(err.contains(needle), "{text}: {err}");
    }
    // the vehicle commands read the file and name it in the error
    let out = afsv(&["vehicle", "yaw", "--params", f]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("params.json") && err.contains("rear_track_m"),
        "{err}"
    );
}

#[test]
fn bad_input_is_a_one_line_error() {
    for (args, needle) in [
        (vec!["vehicle", "ride", "--speed-kmh", "81"], "--speed-kmh"),
        (vec!["vehicle", "ride", "--speed-kmh", "0"], "--speed-kmh"),
        (vec!["vehicle", "ride", "--seeds", "1001"], "--seeds"),
        (
            vec!["vehicle", "ride", "--seeds", "1", "--seed", "2"],
            "--seed",
        ),
        (vec!["vehicle", "ride", "--terrain", "class:Z"], "class `Z`"),
        (vec!["vehicle", "ride", "--terrain", "mc:nan"], "mc `nan`"),
        (vec!["vehicle", "ride", "--terrain", "mc:-1"], "mc `-1`"),
        (
            vec!["vehicle", "ride", "--terrain", "class:E,class:C"],
            "twice",
        ),
        (
            vec!["vehicle", "ride", "--terrain", "slope:3"],
            "unknown key `slope`",
        ),
        (vec!["vehicle", "ride", "--terrain", "E"], "KEY:VALUE"),
        (vec!["vehicle", "ride", "--terrain", "seed:-1"], "seed `-1`"),
        (
            vec![
                "vehicle",
                "ride",
                "--terrain",
                "class:C,seed:4",
                "--seed",
                "4",
            ],
            "seed:N",
        ),
        (
            vec![
                "vehicle",
                "ride",
                "--terrain",
                "class:C,seed:4",
                "--seeds",
                "2",
            ],
            "seed:N",
        ),
        (
            vec!["vehicle", "ride", "--terrain", "smooth", "--seeds", "2"],
            "smooth ground",
        ),
        (
            vec!["vehicle", "ride", "--speed-kmh", "80.01"],
            "--speed-kmh",
        ),
        (vec!["vehicle", "ride", "--seeds", "0"], "--seeds"),
        (vec!["vehicle", "ride", "--seeds", "1e3"], "--seeds"),
        (
            vec!["vehicle", "simulate", "--duration", "600.5", "-o", "x.csv"],
            "--duration",
        ),
        (
            vec!["vehicle", "roll", "--ramp-deg-s", "0.009"],
            "--ramp-deg-s",
        ),
        (
            vec!["vehicle", "roll", "--ramp-deg-s", "1000.1"],
            "--ramp-deg-s",
        ),
        (
            vec!["vehicle", "yaw", "--pulse-deg", "1000.1"],
            "--pulse-deg",
        ),
        (
            vec!["vehicle", "ride", "--terrain", "smooth"],
            "--terrain smooth",
        ),
        (vec!["vehicle", "ride", "--length-m", "1"], "--length-m"),
        (vec!["vehicle", "ride", "--speed-kmh", "0.1"], "--length-m"),
        (vec!["vehicle", "yaw", "--seeds", "3"], "smooth ground"),
        (
            vec![
                "vehicle",
                "yaw",
                "--terrain",
                "class:E,seed:1",
                "--seed",
                "2",
            ],
            "seed:N",
        ),
        (
            vec!["vehicle", "yaw", "--hps", "no-such-strut.json"],
            "--hps",
        ),
        (vec!["vehicle", "yaw", "--load", "heavy"], "heavy"),
        (vec!["vehicle", "roll", "--duration", "1e9"], "--duration"),
        (
            vec!["vehicle", "simulate", "--steer", "pulse:30", "-o", "x.csv"],
            "--steer",
        ),
        (
            vec![
                "vehicle",
                "simulate",
                "--steer",
                "ramp:inf,1",
                "-o",
                "x.csv",
            ],
            "--steer",
        ),
        (
            vec!["vehicle", "simulate", "--dt", "1e-9", "-o", "x.csv"],
            "--duration",
        ),
        (
            vec!["vehicle", "ride", "--vehicle", "chapter2-truck"],
            "rigid truck",
        ),
        (
            vec!["vehicle", "ride", "--vehicle", "no-such-truck.toml"],
            "no-such-truck.toml",
        ),
        (
            vec![
                "vehicle",
                "ride",
                "--vehicle",
                "prototype",
                "--params",
                "p.json",
            ],
            "--params",
        ),
        (
            vec!["vehicle", "path-change", "--offset-m", "21"],
            "--offset-m",
        ),
        (
            vec!["vehicle", "path-change", "--offset-m", "nan"],
            "--offset-m",
        ),
        (
            vec!["vehicle", "path-change", "--duration", "0"],
            "--duration",
        ),
        (
            vec!["vehicle", "path-change", "--seed", "2"],
            "smooth ground",
        ),
        (
            vec!["vehicle", "path-change", "--speed-kmh", "90"],
            "--speed-kmh",
        ),
        (vec!["vehicle", "measures", "--seeds", "101"], "--seeds"),
        (vec!["vehicle", "measures", "--seeds", "0"], "--seeds"),
        (
            vec!["vehicle", "measures", "--seeds", "2", "--seed", "1"],
            "--seed",
        ),
        (vec!["vehicle", "measures", "--load", "heavy"], "heavy"),
        (
            vec!["vehicle", "measures", "--hps", "no-such-strut.json"],
            "--hps",
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
fn path_change_follows_the_course_mirrors_and_writes_record_and_plot() {
    let out = scratch("vehicle", "path_change.csv");
    let plot = scratch("vehicle", "path_change.svg");
    let (o, p) = (out.to_str().unwrap(), plot.to_str().unwrap());
    let right = json(&afsv(&["vehicle", "path-change", "-o", o, "--plot", p]));
    assert_eq!(num(&right["speed_kmh"]), 15.3, "the Table 3.2 loaded speed");
    let m = &right["measures"];
    assert!(num(&m["max_deviation_m"]) < 1.0, "{m}");
    assert!((num(&m["final_offset_m"]) - 4.5).abs() < 0.1, "{m}");
    let theta = num(&m["peak_articulation_deg"]);
    assert!(theta.abs() > 5.0 && theta.abs() < 30.0, "{theta}");
    // the record: afsv-v1 signs, the driver steers right first (positive wheel angle)
    let rec = afsv_records::Record::read(&out).unwrap();
    let sw = rec.require("steer_wheel_deg", &out).unwrap();
    let first = sw.iter().find(|a| a.abs() > 1.0).copied().unwrap();
    assert!(first > 0.0, "first wheel motion {first}");
    let art = rec.require("articulation_deg", &out).unwrap();
    let peak = art
        .iter()
        .fold(0.0f64, |a, v| if v.abs() > a.abs() { *v } else { a });
    assert!((peak - theta).abs() < 1e-6, "{peak} vs {theta}");
    let svg = std::fs::read_to_string(&plot).unwrap();
    for caption in [
        "articulation angle",
        "left-strut displacement",
        "yaw rate",
        "lateral acceleration",
    ] {
        assert!(svg.contains(caption), "{caption}");
    }
    // a left offset mirrors the peaks
    let left = json(&afsv(&["vehicle", "path-change", "--offset-m", "-4.5"]));
    let l = &left["measures"];
    for key in [
        "peak_articulation_deg",
        "peak_yaw_rate_deg_s",
        "peak_lateral_accel_m_s2",
        "final_offset_m",
    ] {
        let (a, b) = (num(&m[key]), num(&l[key]));
        assert!((a + b).abs() < 1e-6 * a.abs(), "{key}: {a} vs {b}");
    }
    // unloaded: its own default speed
    let u = json(&afsv(&["vehicle", "path-change", "--load", "unloaded"]));
    assert_eq!(num(&u["speed_kmh"]), 19.2);
}

#[test]
fn measures_of_one_configuration_agree_with_the_scenario_commands() {
    let v = json(&afsv(&["vehicle", "measures", "--seed", "1"]));
    assert_eq!(v["seeds"], serde_json::json!([1]));
    assert!(v["d1_ride"]["strut_travel_p2p_m"].is_null());
    let ride = json(&afsv(&["vehicle", "ride", "--seed", "1"]));
    let (a, b) = (
        num(&v["d1_ride"]["a_wz_m_s2"]["mean"]),
        num(&ride["a_wz_m_s2"]["mean"]),
    );
    assert!((a - b).abs() < 1e-12 * b, "a_wz {a} vs ride {b}");
    let yaw = json(&afsv(&["vehicle", "yaw"]));
    let (a, b) = (
        num(&v["d3_yaw"]["omega_z_hz"]),
        num(&yaw["omega_z_hz"]["mean"]),
    );
    assert!((a - b).abs() < 1e-12 * b, "omega_z {a} vs yaw {b}");
    assert!(num(&v["d2_roll"]["sp_drt_m_s2"]["mean"]) > 1.0);
    // with the HPS and the unloaded ride: the strut travel is reported
    let h = json(&afsv(&[
        "vehicle", "measures", "--seed", "1", "--hps", "nominal", "--load", "unloaded",
    ]));
    assert_eq!(h["ride_load"], "unloaded");
    assert!(num(&h["d1_ride"]["strut_travel_p2p_m"]["mean"]) > 0.0);
}

#[test]
fn simulate_with_components_adds_every_strut_channel_and_keeps_the_record() {
    let (plain, full) = (
        scratch("vehicle-components", "plain.csv"),
        scratch("vehicle-components", "full.csv"),
    );
    let run = |path: &std::path::Path, more: &[&str]| {
        let mut a = vec![
            "vehicle",
            "simulate",
            "--hps",
            "nominal",
            "--steer",
            "pulse:30,0.2,0.5",
            "--duration",
            "1.5",
            "-o",
            path.to_str().unwrap(),
        ];
        a.extend_from_slice(more);
        json(&afsv(&a))
    };
    let a = run(&plain, &[]);
    let b = run(&full, &["--components"]);
    let (na, nb) = (
        a["columns"].as_array().unwrap().len(),
        b["columns"].as_array().unwrap().len(),
    );
    // the steering's 10 channels and the two front struts' 8 each
    assert_eq!(nb, na + 10 + 2 * 8);
    // the record's own columns are the same, value for value
    let rows = |p: &std::path::Path| -> Vec<Vec<String>> {
        std::fs::read_to_string(p)
            .unwrap()
            .lines()
            .map(|l| l.split(',').map(str::to_string).collect())
            .collect()
    };
    let (ra, rb) = (rows(&plain), rows(&full));
    assert_eq!(ra.len(), rb.len());
    for (x, y) in ra.iter().zip(&rb) {
        assert_eq!(x[..], y[..na]);
    }
    assert!(rb[0].contains(&"hps_front_right_gas_volume_m3".to_string()));
    let sidecar: serde_json::Value =
        serde_json::from_slice(&std::fs::read(full.with_extension("json")).unwrap()).unwrap();
    assert_eq!(
        sidecar["component_channels"]["units"]["steering_p_c_pa"],
        "Pa"
    );
}

/// The `--terrain`, `--steer` and seed options as the outputs state them: the record's
/// sidecar (terrain keys in any order, the default coherence, a seed in the terrain; the
/// pulse and ramp inputs with the ramp's default limit) and the ride's report (the seeds
/// from one place: the scenario's ten, `--seeds N`, `--seed S`, or the terrain's `seed:N`).
#[test]
fn terrain_steer_and_seed_options_reach_the_outputs() {
    let csv = scratch("vehicle-options", "run.csv");
    let sidecar = |args: &[&str]| -> Value {
        let mut a = vec!["vehicle", "simulate", "--duration", "0.05"];
        a.extend_from_slice(args);
        a.extend(["-o", csv.to_str().unwrap()]);
        json(&afsv(&a));
        let text = std::fs::read_to_string(csv.with_extension("json")).unwrap();
        serde_json::from_str(&text).unwrap()
    };
    let t = sidecar(&["--terrain", "mc:0.2,class:c"])["terrain"].clone();
    assert_eq!(
        (t["class"].as_str(), num(&t["m_c_cycles_per_m"])),
        (Some("C"), 0.2)
    );
    assert_eq!(t["seeds"], serde_json::json!([1]));
    let t = sidecar(&["--terrain", "class:H,seed:7"])["terrain"].clone();
    assert_eq!(
        (num(&t["m_c_cycles_per_m"]), &t["seeds"]),
        (0.3, &serde_json::json!([7]))
    );
    let t = sidecar(&["--terrain", "flat"])["terrain"].clone();
    assert_eq!(t["kind"], "smooth ground");
    assert_eq!(sidecar(&["--steer", "none"])["steer"]["kind"], "none");
    let s = sidecar(&["--steer", "pulse:30,0.2,1"])["steer"].clone();
    assert_eq!(s["kind"], "pulse");
    assert_eq!(num(&s["amplitude_rad"]), 30f64.to_radians());
    assert_eq!((num(&s["duration_s"]), num(&s["start_s"])), (0.2, 1.0));
    let s = sidecar(&["--steer", "ramp:5,1", "--speed-kmh", "80"])["steer"].clone();
    assert!(
        (num(&s["rate_rad_s"]) - 5f64.to_radians()).abs() < 1e-15,
        "{s}"
    );
    assert_eq!(num(&s["start_s"]), 1.0);
    assert!(
        (num(&s["limit_rad"]) - 1000f64.to_radians()).abs() < 1e-12,
        "{s}"
    );
    let s = sidecar(&["--steer", "ramp:-5,1"])["steer"].clone();
    assert!(num(&s["rate_rad_s"]) < 0.0, "a left-hand ramp: {s}");

    let ride = |args: &[&str]| -> Value {
        let mut a = vec!["--quiet", "vehicle", "ride", "--length-m", "10"];
        a.extend_from_slice(args);
        json(&afsv(&a))["terrain"].clone()
    };
    let seeds = |args: &[&str]| ride(args)["seeds"].clone();
    assert_eq!(seeds(&[]), serde_json::json!((1..=10).collect::<Vec<_>>()));
    assert_eq!(seeds(&["--seeds", "3"]), serde_json::json!([1, 2, 3]));
    assert_eq!(seeds(&["--seed", "7"]), serde_json::json!([7]));
    assert_eq!(
        seeds(&["--terrain", "class:C,seed:4"]),
        serde_json::json!([4])
    );
    // an explicit terrain replaces the scenario's default
    assert_eq!(ride(&["--terrain", "class:B"])["class"], "B");
}
