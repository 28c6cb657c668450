//! The README's examples run as written from an empty folder, twice (no "exists" failure
//! on the second run), on the shipped samples: every ```` ```sh ```` block of README.md is
//! run with `sh -e` in a scratch folder, with the built `afsv` first on the PATH and
//! `SAMPLES` pointing at the repository's `samples/`. Each must exit 0, print no NaN or
//! infinity, and write nothing into the source tree.

mod cli_support;
use cli_support::{non_finite_word, repo_root, run_script, scratch, sh_blocks};

/// Every file under `dir` with its modification time (the source tree's state).
fn tree_state(dir: &std::path::Path, out: &mut Vec<(std::path::PathBuf, std::time::SystemTime)>) {
    for e in std::fs::read_dir(dir).unwrap().flatten() {
        let p = e.path();
        let name = e.file_name();
        if name == "target" || name == ".git" {
            continue;
        }
        if p.is_dir() {
            tree_state(&p, out);
        } else {
            out.push((p, e.metadata().unwrap().modified().unwrap()));
        }
    }
}

#[test]
fn readme_examples_run_twice_from_an_empty_folder() {
    let root = repo_root();
    let readme = std::fs::read_to_string(root.join("README.md")).unwrap();
    let blocks = sh_blocks(&readme);
    assert!(blocks.len() >= 6, "README has {} sh blocks", blocks.len());
    let text = blocks.concat();
    for must in [
        "$SAMPLES/path-change-accel.csv",
        "$SAMPLES/path-change-steer.csv",
        "$SAMPLES/strut-bench-1hz.csv",
    ] {
        assert!(text.contains(must), "the README examples use {must}");
    }
    let dir = scratch("readme", "work");
    std::fs::create_dir_all(&dir).unwrap();
    let samples = root.join("samples");
    let mut before = Vec::new();
    tree_state(&root, &mut before);
    for run in 1..=2 {
        for block in &blocks {
            let out = run_script(block, &dir, &[("SAMPLES", samples.to_str().unwrap())]);
            let stdout = String::from_utf8_lossy(&out.stdout);
            let stderr = String::from_utf8_lossy(&out.stderr);
            assert!(
                out.status.success(),
                "run {run}: block failed:\n{block}\nstderr: {stderr}"
            );
            for (name, s) in [("stdout", &stdout), ("stderr", &stderr)] {
                if let Some(w) = non_finite_word(s) {
                    panic!("run {run}: `{w}` on {name} of:\n{block}");
                }
            }
        }
    }
    for f in [
        "profile.csv",
        "fy.svg",
        "pulse.csv",
        "replay.csv",
        "rec.csv",
        "loops.svg",
        "strut.json",
    ] {
        assert!(
            dir.join(f).is_file(),
            "{f} was not written into the scratch folder"
        );
    }
    let mut after = Vec::new();
    tree_state(&root, &mut after);
    assert_eq!(before, after, "the examples wrote into the source tree");
}

#[test]
fn sh_blocks_are_found_and_other_fences_skipped() {
    let md = "a\n```sh\nafsv one\nafsv two\n```\n```text\nnot run\n```\n```sh\nafsv three\n```\n";
    assert_eq!(sh_blocks(md), vec!["afsv one\nafsv two\n", "afsv three\n"]);
    assert_eq!(non_finite_word("{\"a\": NaN}"), Some("NaN".into()));
    assert_eq!(non_finite_word("x = -inf"), Some("-inf".into()));
    assert_eq!(non_finite_word("information, infinite, nano 1e-5"), None);
}

/// The subcommands clap lists under `afsv ARGS --help` (its "Commands:" section, without
/// `help`).
fn subcommands(args: &[&str]) -> Vec<String> {
    let mut all = args.to_vec();
    all.push("--help");
    let out = cli_support::afsv(&all);
    assert!(out.status.success(), "{all:?}");
    let text = String::from_utf8(out.stdout).unwrap();
    text.lines()
        .skip_while(|l| !l.starts_with("Commands:"))
        .skip(1)
        .take_while(|l| !l.trim().is_empty())
        .filter_map(|l| l.split_whitespace().next())
        .filter(|name| *name != "help")
        .map(str::to_string)
        .collect()
}

#[test]
fn every_subcommand_is_named_in_the_top_help_and_documented() {
    let root = repo_root();
    let mut docs = std::fs::read_to_string(root.join("README.md")).unwrap();
    for e in std::fs::read_dir(root.join("docs")).unwrap().flatten() {
        if e.path().extension().is_some_and(|x| x == "md") {
            docs += &std::fs::read_to_string(e.path()).unwrap();
        }
    }
    let top = cli_support::afsv(&["--help"]);
    let top = String::from_utf8(top.stdout).unwrap();
    let mut missing = Vec::new();
    let groups = subcommands(&[]);
    assert!(groups.len() >= 10, "{groups:?}");
    for group in &groups {
        if !docs.contains(&format!("afsv {group}")) {
            missing.push(format!("`afsv {group}` is in no doc"));
        }
        let line = top
            .lines()
            .find(|l| l.split_whitespace().next() == Some(group.as_str()))
            .unwrap_or_default();
        for sub in subcommands(&[group]) {
            if !line.contains(&format!("`{sub}`")) {
                missing.push(format!("`afsv --help` does not name `{group} {sub}`"));
            }
            if !docs.contains(&format!("afsv {group} {sub}")) {
                missing.push(format!("`afsv {group} {sub}` is in no doc"));
            }
        }
    }
    assert!(missing.is_empty(), "{}", missing.join("\n"));
}
