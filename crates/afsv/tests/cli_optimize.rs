//! `afsv optimize afs`: one reduced run (one start, with the arm constraint) checked against
//! the chapter-4 targets that hold for our model, resumed from its checkpoint to the same
//! bytes, and the refusals of bad options.

mod cli_support;
use cli_support::{afsv, json, scratch};

#[test]
fn reduced_chapter_4_run_meets_the_targets_and_resumes_identically() {
    let ck = scratch("optimize", "ck.json");
    let step = scratch("optimize", "step.svg");
    let ck_s = ck.to_str().unwrap();
    let args = [
        "optimize",
        "afs",
        "--starts",
        "0",
        "--no-arm-comparison",
        "--json",
        "--checkpoint",
        ck_s,
    ];
    let mut with_plot = args.to_vec();
    with_plot.extend(["--plot-step", step.to_str().unwrap()]);
    let v = json(&afsv(&with_plot));
    let run = &v["runs"][0];
    let opt = &run["ps_sqp"];
    let t = &opt["design"]["table_units"];
    // R4.4: a_v and B_eff at their upper bounds.
    assert!(t["a_v"].as_f64().unwrap() > 7.15, "{t}");
    assert!(t["b_eff_gpa"].as_f64().unwrap() > 0.99 * 1.7, "{t}");
    // R4.3: Eq 4.10 active; the arm constraint holds.
    let g = &opt["geometry"];
    let ratio = g["stroke_ratio"].as_f64().unwrap();
    assert!((1.97..=2.0).contains(&ratio), "{g}");
    assert!(g["min_arm_m"].as_f64().unwrap() >= 0.25 - 1e-9, "{g}");
    // R4.7 shape: l_2/l_1 near 0.43, A_0 near 56 deg (within 6 deg).
    assert!(
        (g["l2_over_l1"].as_f64().unwrap() - 0.43).abs() < 0.03,
        "{g}"
    );
    assert!((t["a0_deg"].as_f64().unwrap() - 56.0).abs() < 6.0, "{t}");
    // F below the current design's 1, higher yaw frequency and damping.
    assert!(opt["f"].as_f64().unwrap() < 0.95);
    assert!(
        opt["ratios_as_tables_4_3_4_4"]["yaw_frequency"]
            .as_f64()
            .unwrap()
            > 1.2
    );
    assert!(
        opt["ratios_as_tables_4_3_4_4"]["damping_ratio"]
            .as_f64()
            .unwrap()
            > 1.0
    );
    assert!(run["evaluations"]["pattern_search"].as_u64().unwrap() > 100);
    assert!(std::fs::read_to_string(&step)
        .unwrap()
        .contains("written_by: afsv"));
    // The finished checkpoint replays to the same numbers.
    let again = json(&afsv(&args));
    let strip = |mut v: serde_json::Value| {
        v["runs"][0]["seconds"] = serde_json::Value::Null;
        v
    };
    assert_eq!(strip(v), strip(again));
}

#[test]
fn bad_options_are_refused_in_one_line() {
    let foreign = scratch("optimize", "foreign.json");
    std::fs::write(&foreign, "{\"mine\": true}").unwrap();
    let out = afsv(&["optimize", "afs", "--checkpoint", foreign.to_str().unwrap()]);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("--checkpoint") && err.lines().count() == 1,
        "{err}"
    );
    let out = afsv(&[
        "optimize",
        "afs",
        "--tire-point",
        "1",
        "--engine-point",
        "0,1",
        "--front-mount-dir-deg",
        "30",
    ]);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("x,y"));
    let out = afsv(&["optimize", "afs", "--tire-point", "0.7,0.8"]);
    assert!(!out.status.success(), "Eq 4.9 needs all three options");
    let out = afsv(&["optimize", "afs", "--min-arm-m", "-1"]);
    assert!(!out.status.success());
}
