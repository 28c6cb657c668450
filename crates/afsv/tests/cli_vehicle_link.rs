//! A vehicle description with a `[link]` (docs/vehicles.md): `afsv vehicle yaw` runs the
//! linked vehicle and says so, the same description without the link runs as before, the
//! path change runs it too, and the commands that cannot run the link (the Chapter 6
//! studies of the front strut alone), or `--hps off`, refuse it in one line. `vehicle measures` and
//! `evaluate` run the link (their library code is tested in afsv-design's
//! `tests/linked_measures.rs`).

mod cli_support;
use cli_support::{afsv, json, scratch};

/// The prototype's description with an `hps` front axle, and `extra` appended.
fn description(name: &str, extra: &str) -> std::path::PathBuf {
    let out = afsv(&["params", "dump", "vehicle"]);
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    let text = text.replacen("suspension = \"rigid\"", "suspension = \"hps\"", 1);
    let path = scratch("link", name);
    std::fs::write(&path, text + extra).unwrap();
    path
}

fn stderr(out: &std::process::Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

#[test]
fn a_roll_link_runs_in_vehicle_yaw_and_is_refused_where_it_cannot_run() {
    let plain = description("plain.toml", "");
    let linked = description("roll.toml", "\n[link]\nkind = \"roll\"\n");
    let yaw = |v: &std::path::Path| {
        json(&afsv(&[
            "--quiet",
            "vehicle",
            "yaw",
            "--json",
            "--vehicle",
            v.to_str().unwrap(),
        ]))
    };
    let (a, b) = (yaw(&plain), yaw(&linked));
    assert!(a.get("link").is_none());
    assert!(
        b["link"]["Roll"]["diameter_m"].as_f64() == Some(0.038),
        "{}",
        b["link"]
    );
    let omega = |v: &serde_json::Value| v["omega_z_hz"]["mean"].as_f64().unwrap();
    assert!(omega(&a).is_finite() && omega(&b).is_finite());
    assert_ne!(omega(&a), omega(&b), "the link changes the run");
    let l = linked.to_str().unwrap();
    let path_change = |v: &str| json(&afsv(&["vehicle", "path-change", "--json", "--vehicle", v]));
    let (a, b) = (path_change(plain.to_str().unwrap()), path_change(l));
    assert!(a.get("link").is_none());
    assert!(b["link"]["Roll"].is_object(), "{}", b["link"]);
    let articulation =
        |v: &serde_json::Value| v["measures"]["peak_articulation_deg"].as_f64().unwrap();
    assert!(articulation(&a).abs() > 5.0 && articulation(&b).abs() > 5.0);
    assert_ne!(
        articulation(&a),
        articulation(&b),
        "the link changes the run"
    );
    for (args, says) in [
        (
            vec!["vehicle", "yaw", "--vehicle", l, "--hps", "off"],
            "--hps off",
        ),
        (
            vec!["optimize", "hps", "--vehicle", l],
            "interconnects its struts",
        ),
        (
            vec!["study", "hps-sensitivity", "--vehicle", l],
            "interconnects its struts",
        ),
    ] {
        let out = afsv(&args);
        assert_eq!(out.status.code(), Some(1), "{args:?}");
        assert!(stderr(&out).contains(says), "{}", stderr(&out));
        assert_eq!(stderr(&out).lines().count(), 1, "{}", stderr(&out));
    }
}
