//! The shipped sample records (`samples/`): the commands of `samples/README.md` regenerate
//! them (within 1e-3 of each column's range), and each gives the result that README states.

mod cli_support;
use afsv_records::Record;
use cli_support::{afsv, json, repo_root, run_script, scratch, sh_blocks};
use std::path::Path;

const RECORDS: [&str; 3] = ["path-change-steer", "path-change-accel", "strut-bench-1hz"];

#[test]
fn samples_are_small_and_regenerate_from_their_documented_commands() {
    let root = repo_root();
    let readme = std::fs::read_to_string(root.join("samples/README.md")).unwrap();
    let blocks = sh_blocks(&readme);
    assert_eq!(
        blocks.len(),
        1,
        "samples/README.md has one sh block of commands"
    );
    let dir = scratch("samples", "regen");
    std::fs::create_dir_all(dir.join("samples")).unwrap();
    let out = run_script(&blocks[0], &dir, &[]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    for name in RECORDS {
        let shipped = root.join("samples").join(format!("{name}.csv"));
        let size = std::fs::metadata(&shipped).unwrap().len();
        assert!(size < 200_000, "{name}.csv is {size} bytes");
        assert!(root.join("samples").join(format!("{name}.json")).is_file());
        let a = Record::read(&shipped).unwrap();
        let b = Record::read(&dir.join("samples").join(format!("{name}.csv"))).unwrap();
        assert_eq!(a.names(), b.names(), "{name}");
        for col in a.names() {
            let (x, y) = (a.column(col).unwrap(), b.column(col).unwrap());
            assert_eq!(x.len(), y.len(), "{name}.{col}");
            let range = x.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            let worst = x
                .iter()
                .zip(y)
                .fold(0.0f64, |m, (p, q)| m.max((p - q).abs()));
            assert!(
                worst <= 1e-3 * range + 1e-12,
                "{name}.{col}: regenerated differs by {worst:e} (range {range:e}); rerun the commands of samples/README.md"
            );
        }
    }
}

fn sample(name: &str) -> String {
    repo_root()
        .join("samples")
        .join(name)
        .to_string_lossy()
        .into_owned()
}

#[test]
fn steering_sample_replays_to_its_recorded_articulation() {
    let out = scratch("samples", "replay.csv");
    let input = format!("csv:{}:steer_wheel_deg", sample("path-change-steer.csv"));
    let v = json(&afsv(&[
        "yaw",
        "simulate",
        "--speed-kmh",
        "20",
        "--duration",
        "12",
        "--dt",
        "0.02",
        "--input",
        &input,
        "-o",
        out.to_str().unwrap(),
    ]));
    let peak = v["peak_articulation_deg"].as_f64().unwrap();
    assert!((peak + 12.29).abs() < 0.01, "peak {peak}");
    let recorded = Record::read(Path::new(&sample("path-change-steer.csv"))).unwrap();
    let replay = Record::read(&out).unwrap();
    let (a, b) = (
        recorded.column("articulation_deg").unwrap(),
        replay.column("articulation_deg").unwrap(),
    );
    assert_eq!(a.len(), b.len());
    let worst = a
        .iter()
        .zip(b)
        .fold(0.0f64, |m, (p, q)| m.max((p - q).abs()));
    assert!(
        worst < 0.01,
        "replay differs from the record by {worst} deg"
    );
}

#[test]
fn acceleration_sample_gives_the_documented_exposure() {
    let v = json(&afsv(&[
        "measures",
        "wbv",
        "-i",
        &sample("path-change-accel.csv"),
        "--channel",
        "y=lateral_accel_front_m_s2",
        "--hours",
        "8",
    ]));
    assert_eq!(v["channels"]["y"], "lateral_accel_front_m_s2");
    assert_eq!(v["axes"].as_array().unwrap().len(), 1);
    let aw = v["axes"][0]["a_w"].as_f64().unwrap();
    let a8 = v["a8"].as_f64().unwrap();
    assert!((aw - 0.089).abs() < 0.001, "a_w {aw}");
    assert!((a8 - 0.125).abs() < 0.001, "A(8) {a8}");
    assert_eq!(v["eu_level"], "below_action");
    assert_eq!(v["hgcz_zone"], "below");
    // a named column the record lacks is an error, not a silent axis drop
    let out = afsv(&[
        "measures",
        "wbv",
        "-i",
        &sample("path-change-accel.csv"),
        "--channel",
        "z=vertical_m_s2",
    ]);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("vertical_m_s2"), "{err}");
    let out = afsv(&[
        "measures",
        "wbv",
        "-i",
        &sample("path-change-accel.csv"),
        "--channel",
        "y=lateral_accel_front_g",
    ]);
    assert!(String::from_utf8_lossy(&out.stderr).contains("_m_s2"));
}

#[test]
fn strut_sample_identifies_its_strut_within_the_noise() {
    let v = json(&afsv(&[
        "hps",
        "identify",
        "-i",
        &sample("strut-bench-1hz.csv"),
        "--fit",
        "n,gamma0,cb",
    ]));
    assert_eq!(v["strut"], "front-axle");
    assert_eq!(v["strut_source"], "sidecar");
    assert_eq!(v["converged"], true);
    let value = |p: &str| {
        v["fitted"]
            .as_array()
            .unwrap()
            .iter()
            .find(|f| f["param"] == p)
            .unwrap()["value"]
            .as_f64()
            .unwrap()
    };
    assert!((value("n") - 1.4).abs() < 0.01, "n {}", value("n"));
    assert!(
        (value("gamma0") - 0.02).abs() < 0.001,
        "gamma0 {}",
        value("gamma0")
    );
    assert!((value("cb") - 0.7).abs() < 0.01, "cb {}", value("cb"));
    assert!(v["nrmse"]["force"].as_f64().unwrap() < 0.005);
}
