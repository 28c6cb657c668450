//! `afsv optimize hps --state` on the command line, without a vehicle run: the first
//! `--ask` writes the nominal design and the initial population (the same bytes when
//! asked again), and `--tell` refuses results that do not answer every asked run, and
//! other options than the state's. (The ask/tell run reaching the in-process optimum bit
//! for bit: `crates/afsv-design/tests/hps_optimum.rs`.)

mod cli_support;
use cli_support::{afsv, json, scratch};
use std::path::Path;

const SMALL: [&str; 6] = [
    "--population",
    "4",
    "--generations",
    "1",
    "--reevaluation-seeds",
    "2",
];

fn optimize(extra: &[&str]) -> std::process::Output {
    let mut args = vec!["--quiet", "optimize", "hps", "--json"];
    args.extend(SMALL);
    args.extend(extra);
    afsv(&args)
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

fn stderr(out: &std::process::Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

#[test]
fn the_first_batch_holds_the_nominal_and_the_population_and_tell_checks_its_results() {
    let state = scratch("hps", "state.json");
    let batch = scratch("hps", "batch.jsonl");
    let status = json(&optimize(&["--state", s(&state), "--ask", s(&batch)]));
    assert_eq!(
        (&status["batch"], &status["phase"], &status["points"]),
        (&0.into(), &"initial".into(), &5.into())
    );
    let text = std::fs::read_to_string(&batch).unwrap();
    let lines: Vec<serde_json::Value> = text
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(lines[0]["format"], "afsv-hps-batch");
    assert_eq!(lines.len(), 6);
    // point 0: the nominal design (Table 6.3) on the search seed
    assert_eq!(lines[1]["task"], "search");
    assert_eq!(lines[1]["x"], serde_json::json!([0.038, 8e-6, 1.1e-5]));
    assert!(lines[1..].iter().all(|p| p["seed"] == 1));
    // asking again, before any tell, gives the same batch
    json(&optimize(&["--state", s(&state), "--ask", s(&batch)]));
    assert_eq!(std::fs::read_to_string(&batch).unwrap(), text);

    // results answering only the first run
    let results = scratch("hps", "results.jsonl");
    let mut header = lines[0].clone();
    let problem = header["problem"].take();
    let head = serde_json::json!({
        "format": "afsv-hps-results", "version": 1, "written_by": "test",
        "sign_convention": "afsv-v1", "batch": 0, "state_sha256": header["state_sha256"],
        "shard": "1/1", "points": 1, "problem": problem,
    });
    let one = serde_json::json!({"id": "b0-0", "status": "evaluated",
        "values": {"a_wz_m_s2": 0.7, "d_s_m": 0.07}});
    std::fs::write(&results, format!("{head}\n{one}\n")).unwrap();
    let before = std::fs::read(&state).unwrap();
    let out = optimize(&["--state", s(&state), "--tell", s(&results)]);
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    assert!(
        stderr(&out).contains("4 of the 5 asked points of batch 0 have no result (first: b0-1)"),
        "{}",
        stderr(&out)
    );
    assert_eq!(stderr(&out).lines().count(), 1);
    assert_eq!(
        std::fs::read(&state).unwrap(),
        before,
        "a refused tell leaves the state"
    );

    // other options than the state's
    let out = afsv(&[
        "--quiet",
        "optimize",
        "hps",
        "--population",
        "6",
        "--state",
        s(&state),
        "--tell",
        s(&results),
    ]);
    assert_eq!(out.status.code(), Some(1));
    let e = stderr(&out);
    assert!(e.contains("written for other settings"), "{e}");
    assert!(e.len() < 600, "a short message: {e}");
    // --state needs --ask or --tell
    let out = optimize(&["--state", s(&state)]);
    assert!(
        stderr(&out).contains("give --ask FILE or --tell"),
        "{}",
        stderr(&out)
    );
}
