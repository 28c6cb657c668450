//! `afsv terrain generate` and `afsv terrain psd` end to end.

mod cli_support;
use cli_support::{afsv, json, scratch};

/// A failing run: non-zero exit, one stderr line naming `needle`, no panic.
fn fails_with(args: &[&str], needle: &str) {
    let out = afsv(args);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "{args:?} succeeded");
    assert!(!err.contains("panicked"), "{args:?}: {err}");
    assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
    assert!(err.contains(needle), "{args:?}: `{needle}` not in {err}");
    assert!(out.stdout.is_empty(), "{args:?}: stdout not empty");
}

#[test]
fn generate_writes_csv_and_sidecar_and_psd_reads_them_back() {
    let csv = tmp("nominal.csv");
    let p = csv.to_str().unwrap();
    let v = json(&afsv(&[
        "terrain", "generate", "--length", "1000", "--seed", "3", "-o", p,
    ]));
    assert_eq!(v["samples"], 20001);
    assert_eq!(v["terrain"]["psd"]["alpha_r"], 4.096e-5);
    assert_eq!(v["terrain"]["coherence"]["model"], "piecewise");
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("x_m,left_m,right_m"));
    assert_eq!(lines.clone().count(), 20001);
    assert!(lines.nth(3).unwrap().starts_with("0.15,"));
    let side: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(csv.with_extension("json")).unwrap())
            .unwrap();
    assert_eq!(side["seed"], 3);
    assert_eq!(side["terrain"]["band"]["n_min"], 0.02);

    let s = json(&afsv(&["terrain", "psd", "-i", p, "--segment-m", "102.4"]));
    assert_eq!(s["samples"], 20001);
    assert_eq!(s["welch"]["segment_samples"], 2048);
    let spec = &s["spectrum"];
    let n = spec["n_cycles_per_m"].as_array().unwrap();
    assert_eq!(n.len(), 1025);
    for key in [
        "psd_left_m3",
        "psd_right_m3",
        "csd_re_m3",
        "csd_im_m3",
        "coherence",
        "cross_slope_psd_rad2_per_cycle_per_m",
    ] {
        assert_eq!(spec[key].as_array().unwrap().len(), 1025, "{key}");
    }
    assert!(spec["coherence"]
        .as_array()
        .unwrap()
        .iter()
        .all(|c| (0.0..=1.0).contains(&c.as_f64().unwrap())));
    // The sidecar's model gives the targets and the band-averaged errors.
    let t = &s["target"];
    assert!(t["psd_mean_error_db"].as_f64().unwrap().abs() < 1.5, "{t}");
    assert!(
        t["coherence_mean_error"].as_f64().unwrap().abs() < 0.1,
        "{t}"
    );
    // Parseval: the PSD integral is close to the variance (segments of >= 2 longest
    // wavelengths; shorter ones lose or, with mean removal, gain ~8 %: docs/terrain-psd.md).
    let ratio =
        s["psd_integral_left_m2"].as_f64().unwrap() / s["variance_left_m2"].as_f64().unwrap();
    assert!((ratio - 1.0).abs() < 0.1, "{ratio}");

    // --band restricts the reported bins.
    let b = json(&afsv(&[
        "terrain",
        "psd",
        "-i",
        p,
        "--segment-m",
        "102.4",
        "--band",
        "0.1,1",
    ]));
    let n = b["spectrum"]["n_cycles_per_m"].as_array().unwrap();
    assert!(n.iter().all(|v| (0.1..=1.0).contains(&v.as_f64().unwrap())));
    let all = s["spectrum"]["n_cycles_per_m"].as_array().unwrap();
    let inside = all
        .iter()
        .filter(|v| (0.1..=1.0).contains(&v.as_f64().unwrap()))
        .count();
    assert_eq!(n.len(), inside);
    assert_eq!(n.len(), 92);
}

#[test]
fn stdout_json_is_deterministic_per_seed() {
    let a = afsv(&["terrain", "generate", "--length", "20", "--seed", "9"]);
    let b = afsv(&["terrain", "generate", "--length", "20", "--seed", "9"]);
    let c = afsv(&["terrain", "generate", "--length", "20", "--seed", "10"]);
    assert_eq!(a.stdout, b.stdout);
    assert_ne!(a.stdout, c.stdout);
    let v = json(&a);
    assert_eq!(v["x_m"].as_array().unwrap().len(), 401);
    assert_eq!(v["left_m"].as_array().unwrap().len(), 401);
    assert_eq!(v["right_m"].as_array().unwrap().len(), 401);
}

#[test]
fn every_model_and_coherence_option_works() {
    let cases: &[&[&str]] = &[
        &["--class", "a"],
        &["--class", "H"],
        &["--terrain", "forestry"],
        &[
            "--terrain",
            "mvee",
            "--coherence",
            "bogsjo:0.2",
            "--half-track",
            "1.14",
        ],
        &[
            "--alpha",
            "1e-5",
            "--waviness",
            "2.4",
            "--coherence",
            "zhang",
            "--speed",
            "13.89",
        ],
        &[
            "--terrain",
            "plowed",
            "--coherence",
            "none",
            "--band",
            "0.05,2",
        ],
        &[
            "--class",
            "C",
            "--coherence",
            "piecewise:0.9",
            "--dx",
            "0.1",
        ],
    ];
    for extra in cases {
        let mut args = vec!["terrain", "generate", "--length", "50"];
        args.extend_from_slice(extra);
        let v = json(&afsv(&args));
        assert!(v["rms_left_m"].as_f64().unwrap() > 0.0, "{extra:?}");
    }
    let v = json(&afsv(&[
        "terrain",
        "generate",
        "--length",
        "50",
        "--coherence",
        "full",
    ]));
    assert_eq!(v["left_m"], v["right_m"]);
    let v = json(&afsv(&[
        "terrain",
        "generate",
        "--length",
        "10",
        "--terrain",
        "pasture",
    ]));
    assert_eq!(v["terrain"]["psd"]["waviness"], 1.6);
}

#[test]
fn single_track_file_gives_psd_only() {
    let csv = tmp("single.csv");
    let mut text = String::from("x_m,left_m\n");
    for i in 0..256 {
        let x = i as f64 * 0.1;
        text.push_str(&format!("{x},{}\n", (0.7 * x).sin()));
    }
    std::fs::write(&csv, text).unwrap();
    let s = json(&afsv(&["terrain", "psd", "-i", csv.to_str().unwrap()]));
    assert_eq!(s["welch"]["segment_samples"], 32);
    assert!(s["spectrum"].get("psd_left_m3").is_some());
    assert!(s["spectrum"].get("coherence").is_none());
    assert!(s.get("target").is_none());
}

#[test]
fn bad_input_gives_one_line_errors() {
    let g = ["terrain", "generate", "--length", "10"];
    let with = |extra: &[&'static str]| -> Vec<&'static str> {
        let mut v: Vec<&str> = g.to_vec();
        v.extend_from_slice(extra);
        v
    };
    fails_with(&with(&["--alpha", "-1", "--waviness", "2"]), "alpha_r");
    fails_with(&with(&["--alpha", "1e-5", "--waviness", "NaN"]), "waviness");
    fails_with(&with(&["--band", "5,0.02"]), "band");
    fails_with(&with(&["--band", "nan,5"]), "band");
    fails_with(&with(&["--band", "0.02"]), "--band");
    fails_with(&with(&["--class", "Z"]), "ISO 8608 class");
    fails_with(&with(&["--alpha", "1e-5"]), "--waviness");
    fails_with(&with(&["--class", "E", "--terrain", "mvee"]), "choose one");
    fails_with(&with(&["--terrain", "moon"]), "--terrain");
    fails_with(&with(&["--coherence", "bogsjo:0.2"]), "--half-track");
    fails_with(&with(&["--coherence", "zhang"]), "--speed");
    fails_with(&with(&["--coherence", "zhang", "--speed", "-3"]), "speed");
    fails_with(&with(&["--coherence", "piecewise:0"]), "m_c");
    fails_with(&with(&["--coherence", "isotropic"]), "coherence");
    fails_with(&with(&["--half-track", "1.1"]), "--half-track");
    fails_with(&with(&["--dx", "0.2"]), "Nyquist");
    fails_with(&with(&["--dx", "0"]), "dx");
    fails_with(&["terrain", "generate", "--length", "-5"], "length");
    let json_out = tmp("x.json");
    fails_with(
        &["terrain", "generate", "-o", json_out.to_str().unwrap()],
        ".json",
    );

    let missing = tmp("does-not-exist.csv");
    fails_with(
        &["terrain", "psd", "-i", missing.to_str().unwrap()],
        "does-not-exist",
    );
    let uneven = tmp("uneven.csv");
    std::fs::write(
        &uneven,
        "x_m,left_m\n0,0\n0.1,1\n0.3,0\n0.4,1\n0.5,0\n0.6,1\n0.7,0\n0.8,1\n0.9,1\n",
    )
    .unwrap();
    fails_with(
        &["terrain", "psd", "-i", uneven.to_str().unwrap()],
        "uniformly",
    );
    let nox = tmp("nox.csv");
    std::fs::write(&nox, "time_s,left_m\n0,0\n1,1\n").unwrap();
    fails_with(&["terrain", "psd", "-i", nox.to_str().unwrap()], "x_m");
    let short = tmp("short.csv");
    let mut text = String::from("x_m,left_m,right_m\n");
    for i in 0..100 {
        text.push_str(&format!(
            "{},{},{}\n",
            i as f64 * 0.05,
            (i % 7) as f64,
            (i % 5) as f64
        ));
    }
    std::fs::write(&short, text).unwrap();
    let s = short.to_str().unwrap();
    fails_with(
        &["terrain", "psd", "-i", s, "--segment-m", "100"],
        "longer than the signal",
    );
    fails_with(&["terrain", "psd", "-i", s, "--segment-m", "-1"], "segment");
    fails_with(&["terrain", "psd", "-i", s, "--overlap", "1"], "overlap");
    fails_with(&["terrain", "psd", "-i", s, "--window", "kaiser"], "window");
    fails_with(
        &["terrain", "psd", "-i", s, "--detrend", "cubic"],
        "detrend",
    );
    fails_with(
        &["terrain", "psd", "-i", s, "--track-width", "0"],
        "track-width",
    );
    fails_with(&["terrain", "psd", "-i", s, "--band", "1,0.5"], "band");
}

fn tmp(name: &str) -> std::path::PathBuf {
    scratch("terrain", name)
}
