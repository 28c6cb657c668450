//! CLI tests of `afsv hps thermal`: the prototype's struts over a shift, the closed-form
//! steady state, the drift per kelvin, levelling, the CSV output and refused input.

mod cli_support;
use cli_support::{afsv, json, scratch};

fn num(v: &serde_json::Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

#[test]
fn a_hot_shift_raises_the_ride_height_by_the_hand_drift_and_levelling_holds_it() {
    let csv = scratch("hps-thermal", "shift.csv");
    let out = afsv(&[
        "hps",
        "thermal",
        "--with-rear",
        "--ambient-c",
        "30",
        "--power-w",
        "300",
        "--hours",
        "24",
        "--step-min",
        "60",
        "--json",
    ]);
    let v = json(&out);
    let axles = v["axles"].as_array().unwrap();
    assert_eq!(axles.len(), 2, "front and the default rear strut, loaded");
    for a in axles {
        let gba = num(&a["body_ambient_conductance_w_k"]);
        // closed-form steady state T_amb + P / G_ba
        let steady = num(&a["steady_temperature_c"]);
        assert!((steady - 30.0 - 300.0 / gba).abs() < 1e-9, "{steady}");
        // 24 h is many body time constants: the end is the steady state
        let slow = num(&a["time_constants_s"][1]);
        assert!(24.0 * 3600.0 > 10.0 * slow, "{slow}");
        let end = &a["end"];
        assert!((num(&end["body_c"]) - steady).abs() < 0.01, "{end}");
        assert!((num(&end["gas_c"]) - steady).abs() < 0.01, "{end}");
        // the drift is the per-kelvin drift times the rise above the charge (20 degC)
        let per_k = num(&a["ride_height_per_kelvin_m"]);
        let drift = num(&end["ride_height_mm"]) * 1e-3;
        assert!(
            (drift / (per_k * (steady - 20.0)) - 1.0).abs() < 1e-3,
            "{drift} vs {}",
            per_k * (steady - 20.0)
        );
        // the static pressure is the load over the rod area plus the atmosphere
        assert!(num(&a["pressure_pa"]) > 4e6);
        // levelled: back to the deadband edge (5 mm), never below the static ride height
        let lev = num(&end["levelled_ride_height_mm"]);
        assert!((0.0..5.2).contains(&lev), "{lev}");
        assert!(num(&end["levelled_oil_l"]) < 0.0);
        // hot gas is softer, levelled or not
        assert!(num(&end["stiffness_ratio"]) < 0.95);
        assert!(num(&end["levelled_stiffness_ratio"]) < 0.95);
        assert_eq!(end["within_travel"], true);
    }
    let rows = v["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 25);
    assert_eq!(
        num(&rows[0]["front_ride_height_mm"]),
        num(&rows[0]["front_levelled_mm"])
    );

    // unloaded, the rear strut scaled for the loaded axle rests on its stop: named, no drift
    let out = afsv(&[
        "hps",
        "thermal",
        "--with-rear",
        "--load",
        "unloaded",
        "--ambient-c",
        "-10",
        "--hours",
        "1",
        "-o",
        csv.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&csv).unwrap();
    assert!(text.starts_with("time_h,front_gas_c,front_body_c,front_ride_height_mm"));
    assert!(!text.contains("rear_"));
    let side: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(csv.with_extension("json")).unwrap())
            .unwrap();
    assert_eq!(side["written_by"], "afsv hps thermal");
    // cold (charged at 20 degC, -10 degC out): the vehicle starts low
    let first: Vec<f64> = text
        .lines()
        .nth(1)
        .unwrap()
        .split(',')
        .map(|x| x.parse().unwrap())
        .collect();
    assert!(first[3] < -20.0, "{first:?}");
}

#[test]
fn refused_input_is_one_line() {
    for args in [
        vec!["hps", "thermal", "--hours", "100"],
        vec!["hps", "thermal", "--power-w", "-1"],
        vec!["hps", "thermal", "--ambient-c", "nan"],
        vec!["hps", "thermal", "--deadband-mm", "500"],
    ] {
        let out = afsv(&args);
        assert!(!out.status.success(), "{args:?} was accepted");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.trim().lines().count() <= 3, "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{err}");
    }
}

#[test]
fn a_d1_ride_sets_the_dissipation() {
    let v = json(&afsv(&[
        "hps", "thermal", "--ride", "--hours", "1", "--json",
    ]));
    let a = &v["axles"][0];
    let p = num(&a["power_w"]);
    // a class E ride at 20 km/h works the strut: tens to hundreds of watts
    assert!((10.0..2000.0).contains(&p), "{p}");
    assert!(a["power_source"].as_str().unwrap().starts_with("D1 ride"));
    // --ride and --power-w exclude each other
    let out = afsv(&["hps", "thermal", "--ride", "--power-w", "100"]);
    assert!(!out.status.success());
}

#[test]
fn the_strut_at_the_end_of_a_shift_is_written_for_a_ride() {
    let (hot, levelled) = (
        scratch("hps-thermal-out", "hot.json"),
        scratch("hps-thermal-out", "levelled.json"),
    );
    let v = json(&afsv(&[
        "hps",
        "thermal",
        "--power-w",
        "640",
        "--hours",
        "8",
        "--strut-out",
        hot.to_str().unwrap(),
        "--strut-out-levelled",
        levelled.to_str().unwrap(),
        "--json",
    ]));
    let read = |p: &std::path::Path| -> serde_json::Value {
        serde_json::from_slice(&std::fs::read(p).unwrap()).unwrap()
    };
    let (h, l) = (read(&hot), read(&levelled));
    let nominal = json(&afsv(&["params", "dump", "strut"]));
    // the same hardware: the rod side is kept; the hot gas charge presses harder at
    // mid-stroke, and the drained oil leaves the levelled strut more gas volume
    assert_eq!(h["v_r0"], nominal["v_r0"]);
    assert!(num(&h["p_h0"]) > 1.1 * num(&nominal["p_h0"]), "{h}");
    assert!(num(&l["v_g0"]) > num(&nominal["v_g0"]), "{l}");
    // each is a valid strut file for `--hps FILE`
    for p in [&hot, &levelled] {
        let out = afsv(&["params", "check", "strut", p.to_str().unwrap()]);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
    assert!(v["axles"].as_array().is_some());
}
