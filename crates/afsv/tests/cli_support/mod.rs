//! Helpers shared by the command-line tests: run the `afsv` binary, read its JSON, and make
//! scratch paths. Each test crate uses a subset.
#![allow(dead_code)]

use std::path::PathBuf;
use std::process::{Command, Output};

/// Run `afsv` with `args` and collect its output.
pub fn afsv(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_afsv"))
        .args(args)
        .output()
        .expect("run afsv")
}

/// The JSON `afsv` printed on stdout; panics with its stderr when it failed.
pub fn json(out: &Output) -> serde_json::Value {
    assert!(
        out.status.success(),
        "stderr: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("JSON on stdout")
}

/// A fresh path `name` in this process's scratch folder for test group `group` (the folder
/// exists; whatever an earlier run left at the path is removed).
pub fn scratch(group: &str, name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("afsv-cli-{group}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    let _ = std::fs::remove_dir_all(&path);
    let _ = std::fs::remove_file(&path);
    path
}

/// The fenced ```` ```sh ```` blocks of a Markdown file, in order (other fences, e.g.
/// ```` ```text ````, are not runnable examples).
pub fn sh_blocks(markdown: &str) -> Vec<String> {
    let mut blocks = Vec::new();
    let mut current: Option<String> = None;
    for line in markdown.lines() {
        let fence = line.trim_start().starts_with("```");
        match (&mut current, fence) {
            (None, true) if line.trim() == "```sh" => current = Some(String::new()),
            (Some(block), false) => {
                block.push_str(line);
                block.push('\n');
            }
            (Some(_), true) => blocks.extend(current.take()),
            _ => {}
        }
    }
    blocks
}

/// The repository root (two levels above this crate).
pub fn repo_root() -> PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .canonicalize()
        .unwrap()
}

/// Run `script` with `sh -e` in `dir`, with the built `afsv` first on the PATH and `env`
/// set; returns the output.
pub fn run_script(script: &str, dir: &std::path::Path, env: &[(&str, &str)]) -> Output {
    let bin_dir = std::path::Path::new(env!("CARGO_BIN_EXE_afsv"))
        .parent()
        .unwrap()
        .to_path_buf();
    let path = std::env::var_os("PATH").unwrap_or_default();
    let mut paths = vec![bin_dir];
    paths.extend(std::env::split_paths(&path));
    let mut cmd = Command::new("sh");
    cmd.arg("-e")
        .arg("-c")
        .arg(script)
        .current_dir(dir)
        .env("PATH", std::env::join_paths(paths).unwrap());
    for (k, v) in env {
        cmd.env(k, v);
    }
    cmd.output().expect("run sh")
}

/// The first word of `text` that reads as a non-finite number (`NaN`, `inf`, `-inf`,
/// `Infinity`), if any.
pub fn non_finite_word(text: &str) -> Option<String> {
    text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '-' || c == '.'))
        .find(|w| {
            let w = w.trim_start_matches('-').to_ascii_lowercase();
            w == "nan" || w == "inf" || w == "infinity"
        })
        .map(str::to_string)
}
