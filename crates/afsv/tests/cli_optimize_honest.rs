//! `afsv optimize afs` and `afsv batch evaluate` say what they did not earn and refuse what
//! is not theirs (issue 27): an infeasible best point is not an optimum (exit 3); `--quiet`
//! silences stderr; one run at a time holds a checkpoint; a tampered or truncated
//! checkpoint is refused, named, and left as it was; results asked by another state are
//! refused; temporary names never touch a user's files; a wide CSV header fails at once.
//! Every run is the reduced one of cli_cluster.rs (a fraction of a second).

mod cli_support;
use cli_support::{afsv, json, scratch};
use std::path::Path;
use std::process::{Command, Stdio};

/// The reduced chapter-4 run (one start, 5-point search, meshes 1/8 and 1/16, 3 SQP calls).
const SMALL: &str = "--starts 0 --search-points 5 --screen-mesh 0.125 --min-mesh 0.0625 --sqp-calls 3 --no-arm-comparison";

fn optimize(extra: &[&str]) -> std::process::Output {
    let mut args = vec!["optimize", "afs", "--json"];
    args.extend(SMALL.split_whitespace());
    args.extend(extra);
    afsv(&args)
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

fn stderr(out: &std::process::Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// Asserts a refusal (exit 1) in one line of stderr that contains every one of `want`.
fn refused(out: &std::process::Output, want: &[&str]) {
    let err = stderr(out);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    for w in want {
        assert!(err.contains(w), "{w:?} not in {err}");
    }
}

#[test]
fn an_infeasible_best_point_is_not_earned_and_names_the_violated_constraint() {
    let geometry = [
        "--front-mount-dir-deg",
        "30",
        "--tire-point=1,-0.5",
        "--engine-point=1.2,-0.2",
    ];
    let out = optimize(&geometry);
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(3), "{err}");
    assert!(
        err.contains("afsv: not earned: optimize afs: no feasible design found")
            && err.contains("eq_4_9_engine = +0.416"),
        "{err}"
    );
    // The report is still printed, and says so itself.
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let run = &v["runs"][0];
    assert_eq!(run["feasible"], false, "{run}");
    assert_eq!(run["violated_constraints"][0]["name"], "eq_4_9_engine");
    // The same options without Eq 4.9 find a feasible optimum: exit 0, no violation.
    let v = json(&optimize(&[]));
    assert_eq!(v["runs"][0]["feasible"], true);
    assert_eq!(v["runs"][0]["violated_constraints"], serde_json::json!([]));
}

#[test]
fn the_ask_tell_report_of_an_infeasible_run_is_not_earned_either() {
    let state = scratch("honest-ask", "state.json");
    let batch = scratch("honest-ask", "b.jsonl");
    let results = scratch("honest-ask", "r.jsonl");
    let geometry = [
        "--front-mount-dir-deg",
        "30",
        "--tire-point=1,-0.5",
        "--engine-point=1.2,-0.2",
    ];
    let with = |extra: &[&str]| {
        let mut a = geometry.to_vec();
        a.extend(extra);
        optimize(&a)
    };
    for _ in 0..100 {
        let asked = with(&["--state", s(&state), "--ask", s(&batch)]);
        if asked.status.code() == Some(3) {
            let err = stderr(&asked);
            assert!(
                err.contains("no feasible design found") && err.contains("eq_4_9_engine = +0.416"),
                "{err}"
            );
            let v: serde_json::Value = serde_json::from_slice(&asked.stdout).unwrap();
            assert_eq!(v["runs"][0]["feasible"], false);
            return;
        }
        json(&asked);
        json(&afsv(&["batch", "evaluate", s(&batch), "-o", s(&results)]));
        json(&with(&["--state", s(&state), "--tell", s(&results)]));
    }
    panic!("the ask/tell run did not finish in 100 batches");
}

#[test]
fn quiet_silences_the_summary_line() {
    let loud = optimize(&[]);
    assert!(stderr(&loud).contains("run with the steering-arm constraint done"));
    let mut args = vec!["--quiet", "optimize", "afs", "--json"];
    args.extend(SMALL.split_whitespace());
    let quiet = afsv(&args);
    assert!(quiet.status.success());
    assert_eq!(stderr(&quiet), "");
    assert!(json(&quiet)["runs"][0]["feasible"] == true);
}

#[test]
fn a_second_run_on_a_checkpoint_is_refused_while_the_first_holds_it() {
    let ck = scratch("honest-lock", "ck.json");
    let lock = scratch("honest-lock", "ck.json.lock");
    // A run long enough to be caught holding the lock (the default settings: minutes).
    let mut first = Command::new(env!("CARGO_BIN_EXE_afsv"))
        .args(["optimize", "afs", "--json", "--no-arm-comparison"])
        .args(["--checkpoint", s(&ck)])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let pid = first.id().to_string();
    let t = std::time::Instant::now();
    while !std::fs::read_to_string(&lock).is_ok_and(|l| l.contains(&format!("pid: {pid}"))) {
        assert!(t.elapsed().as_secs() < 30, "the first run took no lock");
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    let second = afsv(&[
        "optimize",
        "afs",
        "--no-arm-comparison",
        "--checkpoint",
        s(&ck),
    ]);
    refused(
        &second,
        &[
            "--checkpoint",
            "another run holds it",
            &format!("pid {pid}"),
            "running",
        ],
    );
    first.kill().unwrap();
    first.wait().unwrap();
    // A killed run leaves no lock that holds: its lock file is taken over, and the next
    // run (other options) gets as far as the settings check.
    let written = ck.exists();
    let out = optimize(&["--checkpoint", s(&ck)]);
    if written {
        refused(&out, &["written for other settings"]);
    } else {
        json(&out);
    }
    assert!(!lock.exists(), "the lock file was left behind");
}

#[test]
fn tampered_and_truncated_checkpoints_are_refused_and_left_as_they_were() {
    let ck = scratch("honest-ck", "ck.json");
    let first = json(&optimize(&["--checkpoint", s(&ck)]));
    let good = std::fs::read_to_string(&ck).unwrap();
    let v: serde_json::Value = serde_json::from_str(&good).unwrap();
    let tampered = |edit: &dyn Fn(&mut serde_json::Value), want: &[&str]| {
        let mut t = v.clone();
        edit(&mut t);
        let text = serde_json::to_string(&t).unwrap();
        std::fs::write(&ck, &text).unwrap();
        refused(&optimize(&["--checkpoint", s(&ck)]), want);
        assert_eq!(std::fs::read_to_string(&ck).unwrap(), text, "rewritten");
    };
    tampered(
        &|t| t["runs"][0]["finished"][0]["mesh"] = 1e308.into(),
        &["--checkpoint", "run 1", "start 0", "mesh 1e308 outside"],
    );
    tampered(
        &|t| t["runs"][0]["refined"]["u"][2] = 1.5.into(),
        &["the refinement", "outside [0, 1]"],
    );
    tampered(
        &|t| {
            let f = t["runs"][0]["refined"]["eval"]["f"].as_f64().unwrap();
            t["runs"][0]["refined"]["eval"]["f"] = (f * 0.99).into();
        },
        &["the refinement", "is not the problem's"],
    );
    tampered(
        &|t| t["runs"][0]["sqp_log"][0]["eval"]["f"] = 0.5.into(),
        &["the first SQP entry", "is not the problem's"],
    );
    tampered(
        &|t| t["runs"][0]["finished"][0]["evaluations"] = 0.into(),
        &["start 0", "0 evaluations for"],
    );
    // Truncated: named so, with where it ends, not "not written by afsv".
    let half = &good[..good.len() / 2];
    std::fs::write(&ck, half).unwrap();
    refused(
        &optimize(&["--checkpoint", s(&ck)]),
        &["truncated: not valid JSON", "line 1 column"],
    );
    assert_eq!(std::fs::read_to_string(&ck).unwrap(), half);
    std::fs::write(&ck, "").unwrap();
    refused(&optimize(&["--checkpoint", s(&ck)]), &["empty (0 bytes)"]);
    // The untouched checkpoint still resumes to the same report.
    std::fs::write(&ck, &good).unwrap();
    let again = json(&optimize(&["--checkpoint", s(&ck)]));
    assert_eq!(again["runs"][0]["ps_sqp"], first["runs"][0]["ps_sqp"]);
}

#[test]
fn results_asked_by_another_state_are_refused() {
    let ours = scratch("honest-tell", "ours.json");
    let theirs = scratch("honest-tell", "theirs.json");
    let (b1, b2) = (
        scratch("honest-tell", "b1.jsonl"),
        scratch("honest-tell", "b2.jsonl"),
    );
    let r2 = scratch("honest-tell", "r2.jsonl");
    // Two runs of the same problem at the same batch number (other seeds).
    json(&optimize(&["--state", s(&ours), "--ask", s(&b1)]));
    json(&optimize(&[
        "--seed",
        "2",
        "--state",
        s(&theirs),
        "--ask",
        s(&b2),
    ]));
    json(&afsv(&["batch", "evaluate", s(&b2), "-o", s(&r2)]));
    let header: serde_json::Value = serde_json::from_str(
        std::fs::read_to_string(&r2)
            .unwrap()
            .lines()
            .next()
            .unwrap(),
    )
    .unwrap();
    let sha = sha256sum(&theirs);
    assert_eq!(header["state_sha256"], sha, "{header}");
    let before = std::fs::read(&ours).unwrap();
    refused(
        &optimize(&["--state", s(&ours), "--tell", s(&r2)]),
        &["results of batch 0 as another state asked it", &sha[..12]],
    );
    assert_eq!(std::fs::read(&ours).unwrap(), before);
    // Their own state takes them.
    json(&optimize(&[
        "--seed",
        "2",
        "--state",
        s(&theirs),
        "--tell",
        s(&r2),
    ]));
}

/// SHA-256 (hex) of a file, by the system's `sha256sum` (an independent implementation).
fn sha256sum(path: &Path) -> String {
    let out = Command::new("sha256sum").arg(path).output().unwrap();
    String::from_utf8(out.stdout).unwrap()[..64].to_string()
}

#[test]
fn temporary_names_never_touch_a_users_files() {
    let ck = scratch("honest-tmp", "ck.json");
    let user_ck = scratch("honest-tmp", "ck.partial");
    let user_lock_like = scratch("honest-tmp", "ck.json.partial");
    std::fs::write(&user_ck, "my ck.partial").unwrap();
    std::fs::write(&user_lock_like, "my ck.json.partial").unwrap();
    json(&optimize(&["--checkpoint", s(&ck)]));
    let state = scratch("honest-tmp", "state.json");
    let batch = scratch("honest-tmp", "b.jsonl");
    let results = scratch("honest-tmp", "r.jsonl");
    let user_r = scratch("honest-tmp", "r.partial");
    std::fs::write(&user_r, "my r.partial").unwrap();
    json(&optimize(&["--state", s(&state), "--ask", s(&batch)]));
    json(&afsv(&["batch", "evaluate", s(&batch), "-o", s(&results)]));
    assert_eq!(std::fs::read_to_string(&user_ck).unwrap(), "my ck.partial");
    assert_eq!(
        std::fs::read_to_string(&user_lock_like).unwrap(),
        "my ck.json.partial"
    );
    assert_eq!(std::fs::read_to_string(&user_r).unwrap(), "my r.partial");
    // Nothing else is left beside them: no temporary file, no lock file.
    let dir = ck.parent().unwrap();
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(
        names,
        [
            "b.jsonl",
            "ck.json",
            "ck.json.partial",
            "ck.partial",
            "r.jsonl",
            "r.partial",
            "state.json"
        ]
    );
}

#[test]
fn a_wide_csv_header_is_refused_at_once_with_a_short_message() {
    let wide = scratch("honest-csv", "wide.csv");
    let names: Vec<String> = (0..100_000).map(|j| format!("c{j}_x")).collect();
    std::fs::write(&wide, names.join(",") + "\n").unwrap();
    let t = std::time::Instant::now();
    let out = afsv(&["measures", "decay", "-i", s(&wide), "--column", "c1_x"]);
    assert!(t.elapsed().as_secs_f64() < 5.0, "{:?}", t.elapsed());
    refused(
        &out,
        &["wide.csv:1:4097", "100000 columns", "more than the 4096"],
    );
    assert!(stderr(&out).len() < 300, "{}", stderr(&out));
    // At the limit it reads, and the missing time column lists ten names and a count.
    std::fs::write(
        &wide,
        names[..4096].join(",") + "\n" + &vec!["1"; 4096].join(",") + "\n",
    )
    .unwrap();
    let out = afsv(&["measures", "decay", "-i", s(&wide), "--column", "c1_x"]);
    refused(&out, &["no column `time_s`", "c9_x, ... and 4086 more"]);
}

#[test]
fn a_described_vehicle_is_optimised_and_stored_in_the_state() {
    let without_clock = |out: &std::process::Output| {
        let mut v = json(out);
        v.as_object_mut().unwrap().remove("provenance");
        for r in v["runs"].as_array_mut().unwrap() {
            r.as_object_mut().unwrap().remove("seconds");
        }
        v
    };
    // the built-in prototype's yaw-plane data and steering are Table 3.1's: the same run
    let nominal = without_clock(&optimize(&[]));
    assert_eq!(
        without_clock(&optimize(&["--vehicle", "prototype"])),
        nominal
    );
    // a 28 t truck of its own starts from its own steering and loaded vehicle
    let adt = cli_support::repo_root().join("samples/vehicles/adt-28t.toml");
    let own = without_clock(&optimize(&["--vehicle", s(&adt)]));
    assert_ne!(own["current"], nominal["current"]);
    // an ask/tell state carries the whole description, so shards need no file
    let state = scratch("honest", "vehicle-state.json");
    let batch = scratch("honest", "vehicle-batch.jsonl");
    let out = optimize(&[
        "--vehicle",
        s(&adt),
        "--state",
        s(&state),
        "--ask",
        s(&batch),
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    let text = std::fs::read_to_string(&batch).unwrap();
    assert!(
        text.contains("\"vehicle\"") && text.contains("\"steering\""),
        "{text}"
    );
}
