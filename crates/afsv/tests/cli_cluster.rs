//! Ask/tell on the command line: `afsv optimize afs --state S --ask batch.jsonl`, then
//! `afsv batch evaluate --shard I/3` as three concurrent processes, then `--tell` with the
//! three results files, looped until the run finishes, gives the in-process optimum byte
//! for byte; and the refusals of results that do not belong to the asked batch.

mod cli_support;
use cli_support::{afsv, json, scratch};
use std::path::Path;
use std::process::{Command, Stdio};

/// The smallest chapter-4 run the options allow to be meaningful: the current design as
/// the only start, a 5-point search step, screening to mesh 1/8, refinement to 1/16, three
/// SLSQP calls; both configurations (with and without the arm constraint).
const SMALL: &str =
    "--starts 0 --search-points 5 --screen-mesh 0.125 --min-mesh 0.0625 --sqp-calls 3";

fn optimize(extra: &[&str]) -> std::process::Output {
    let mut args = vec!["optimize", "afs", "--json"];
    args.extend(SMALL.split_whitespace());
    args.extend(extra);
    afsv(&args)
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// The report without its wall-clock times.
fn without_seconds(mut v: serde_json::Value) -> String {
    for r in v["runs"].as_array_mut().unwrap() {
        r.as_object_mut().unwrap().remove("seconds");
    }
    serde_json::to_string(&v).unwrap()
}

fn stderr(out: &std::process::Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

#[test]
fn ask_evaluate_in_three_shard_processes_and_tell_give_the_in_process_optimum() {
    let state = scratch("cluster", "state.json");
    let batch = scratch("cluster", "batch.jsonl");
    let results: Vec<_> = (1..=3)
        .map(|i| scratch("cluster", &format!("results-{i}.jsonl")))
        .collect();
    let mut batches = 0;
    let report = loop {
        let asked = optimize(&["--state", s(&state), "--ask", s(&batch)]);
        let v = json(&asked);
        let header = std::fs::read_to_string(&batch).unwrap();
        let header = header.lines().next().unwrap();
        if header.contains("\"finished\":true") {
            assert!(
                stderr(&asked).contains("has finished"),
                "{}",
                stderr(&asked)
            );
            break v;
        }
        assert_eq!(v["batch"], batches, "{v}");
        // Asking again gives the same batch, byte for byte (the state did not move).
        let first = std::fs::read(&batch).unwrap();
        json(&optimize(&["--state", s(&state), "--ask", s(&batch)]));
        assert_eq!(std::fs::read(&batch).unwrap(), first);
        let shards: Vec<_> = results
            .iter()
            .enumerate()
            .map(|(i, r)| {
                Command::new(env!("CARGO_BIN_EXE_afsv"))
                    .args(["batch", "evaluate", s(&batch), "-o", s(r), "--json"])
                    .args(["--shard", &format!("{}/3", i + 1)])
                    .stdout(Stdio::piped())
                    .stderr(Stdio::piped())
                    .spawn()
                    .unwrap()
            })
            .collect();
        let mut evaluated = 0;
        for child in shards {
            let out = child.wait_with_output().unwrap();
            evaluated += json(&out)["points"].as_u64().unwrap();
        }
        assert_eq!(evaluated, v["points"].as_u64().unwrap(), "{v}");
        let mut tell = vec!["--state", s(&state), "--tell"];
        tell.extend(results.iter().map(|r| s(r)));
        let told = json(&optimize(&tell));
        assert_eq!(told["told"], batches);
        batches += 1;
        assert!(batches < 200, "the run does not finish");
    };
    let in_process = json(&optimize(&[]));
    assert_eq!(without_seconds(report), without_seconds(in_process));
    // The ask/tell run took one batch per pattern-search iteration and SQP batch.
    assert!(batches > 10, "{batches}");
    // Once finished, a tell is refused.
    let out = optimize(&["--state", s(&state), "--tell", s(&results[0])]);
    assert!(!out.status.success());
    assert!(stderr(&out).contains("has finished"), "{}", stderr(&out));
}

#[test]
fn results_that_do_not_belong_to_the_asked_batch_are_refused_in_one_line() {
    let state = scratch("cluster-bad", "state.json");
    let batch = scratch("cluster-bad", "batch.jsonl");
    let all = scratch("cluster-bad", "all.jsonl");
    let part = scratch("cluster-bad", "part.jsonl");
    let refuse = |args: &[&str], want: &str| {
        let out = optimize(args);
        let err = stderr(&out);
        assert!(!out.status.success(), "{args:?} succeeded");
        assert!(err.contains(want) && err.lines().count() == 1, "{err}");
    };
    refuse(
        &["--state", s(&state), "--tell", s(&all)],
        "start the run with --ask",
    );
    json(&optimize(&["--state", s(&state), "--ask", s(&batch)]));
    json(&afsv(&["batch", "evaluate", s(&batch), "-o", s(&all)]));
    json(&afsv(&[
        "batch",
        "evaluate",
        s(&batch),
        "--shard",
        "2/2",
        "-o",
        s(&part),
    ]));
    // A shard missing: the first asked point without a result is named.
    refuse(
        &["--state", s(&state), "--tell", s(&part)],
        "have no result (first: b0-0)",
    );
    // The same point twice.
    refuse(
        &["--state", s(&state), "--tell", s(&all), s(&part)],
        "already came in",
    );
    // A stranger and a malformed line, with line and column.
    let text = std::fs::read_to_string(&all).unwrap();
    let stranger = scratch("cluster-bad", "stranger.jsonl");
    std::fs::write(&stranger, text.replace("\"b0-1\"", "\"b7-1\"")).unwrap();
    refuse(
        &["--state", s(&state), "--tell", s(&stranger)],
        "id \"b7-1\" was not asked in batch 0",
    );
    let malformed = scratch("cluster-bad", "malformed.jsonl");
    let mut lines: Vec<&str> = text.lines().collect();
    lines[1] = "{\"id\": \"b0-0\", \"status\": 3}";
    std::fs::write(&malformed, lines.join("\n")).unwrap();
    refuse(
        &["--state", s(&state), "--tell", s(&malformed)],
        "malformed.jsonl:2:26: invalid type",
    );
    // Results of another problem (the relaxed bound) or with other settings.
    let other_state = scratch("cluster-bad", "other.json");
    let other_batch = scratch("cluster-bad", "other.jsonl");
    let other = scratch("cluster-bad", "other-results.jsonl");
    json(&optimize(&[
        "--relaxed",
        "--state",
        s(&other_state),
        "--ask",
        s(&other_batch),
    ]));
    json(&afsv(&[
        "batch",
        "evaluate",
        s(&other_batch),
        "-o",
        s(&other),
    ]));
    refuse(
        &["--state", s(&state), "--tell", s(&other)],
        "another problem",
    );
    refuse(
        &["--relaxed", "--state", s(&state), "--tell", s(&all)],
        "written for other settings",
    );
    // The good results advance the state; then they belong to an old batch.
    json(&optimize(&["--state", s(&state), "--tell", s(&all)]));
    refuse(
        &["--state", s(&state), "--tell", s(&all)],
        "results of batch 0, the state asked batch 1",
    );
    // Files afsv did not write are neither read as state nor replaced without --force.
    let foreign = scratch("cluster-bad", "foreign.jsonl");
    std::fs::write(&foreign, "mine\n").unwrap();
    refuse(
        &["--state", s(&state), "--ask", s(&foreign)],
        "was not written by afsv",
    );
    let out = afsv(&["batch", "evaluate", s(&batch), "-o", s(&foreign)]);
    assert!(stderr(&out).contains("--force"), "{}", stderr(&out));
    let out = afsv(&["batch", "evaluate", s(&batch), "-o", s(&batch)]);
    assert!(
        stderr(&out).contains("same file as the input"),
        "{}",
        stderr(&out)
    );
    for bad in [
        "0/3", "4/3", "1/0", "x", "1/100001", "1", "a/b", "1/2/3", "",
    ] {
        let out = afsv(&[
            "batch",
            "evaluate",
            s(&batch),
            "--shard",
            bad,
            "-o",
            s(&part),
        ]);
        assert!(
            !out.status.success() && stderr(&out).contains("I/N"),
            "{bad}"
        );
    }
    refuse(&["--state", s(&state)], "give --ask FILE or --tell");
}
