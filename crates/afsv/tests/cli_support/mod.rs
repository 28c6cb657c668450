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
