//! Folders of records: the record files a folder holds, a report folder kept apart from the
//! records it reports on, and the rule by which a folder of records the toolkit wrote
//! (`train/`, `holdout/` and a `truth.json` marker, as `afsv synth` writes them) may be
//! replaced. Like [`crate::guard`], no file the toolkit did not write is ever deleted.

use crate::{ReadOptions, Record};
use std::path::{Path, PathBuf};

/// `"written_by"` of the `truth.json` that marks a folder `afsv synth` wrote.
pub const SYNTH_WRITTEN_BY: &str = "afsv synth";

/// The CSV files of the given files and folders (a folder: its `*.csv`, sorted); a folder
/// without any, or a path that is neither, is an error naming it.
pub fn csv_files(inputs: &[PathBuf]) -> Result<Vec<PathBuf>, String> {
    let mut out = Vec::new();
    for p in inputs {
        if p.is_dir() {
            let v: Vec<PathBuf> = list_dir(p)?
                .into_iter()
                .filter(|f| f.extension().is_some_and(|x| x == "csv"))
                .collect();
            if v.is_empty() {
                return Err(format!("{}: no .csv records in this folder", p.display()));
            }
            out.extend(v);
        } else if p.is_file() {
            out.push(p.clone());
        } else {
            return Err(format!("{}: no such file or folder", p.display()));
        }
    }
    Ok(out)
}

/// Read every file of `files` ([`Record::read_with`]) with its name (the file stem).
pub fn read_records(
    files: &[PathBuf],
    opts: &ReadOptions,
) -> Result<(Vec<Record>, Vec<String>), String> {
    let mut recs = Vec::new();
    let mut names = Vec::new();
    for f in files {
        recs.push(Record::read_with(f, opts).map_err(|e| e.to_string())?);
        names.push(
            f.file_stem()
                .map(|s| s.to_string_lossy().into_owned())
                .unwrap_or_default(),
        );
    }
    Ok((recs, names))
}

/// Refuse a report folder `output` (given as `-o`) that is an existing file or that holds
/// any record of `train` or `holdout` (the report's plots would land among them), and a
/// record given as both training and held-out (the held-out test would then measure
/// nothing). Paths are compared canonically ([`crate::guard::canonical_path`]), so `x`,
/// `./x` and a link to `x` are the same.
pub fn check_report_folder(
    output: &Path,
    train: &[PathBuf],
    holdout: &[PathBuf],
) -> Result<(), String> {
    if output.exists() && !output.is_dir() {
        return Err(format!(
            "-o {}: exists and is not a folder; the report is a folder (report.md, report.json, plots)",
            output.display()
        ));
    }
    let out = crate::guard::canonical_path(output)?;
    let canon = |f: &PathBuf| crate::guard::canonical_path(f);
    let train_c = train.iter().map(canon).collect::<Result<Vec<_>, _>>()?;
    let hold_c = holdout.iter().map(canon).collect::<Result<Vec<_>, _>>()?;
    for (f, c) in train
        .iter()
        .zip(&train_c)
        .chain(holdout.iter().zip(&hold_c))
    {
        if c.parent() == Some(out.as_path()) {
            return Err(format!(
                "-o {}: holds the input record {}; choose a folder of its own for the report",
                output.display(),
                f.display()
            ));
        }
    }
    if let Some((f, _)) = holdout
        .iter()
        .zip(&hold_c)
        .find(|(_, c)| train_c.contains(c))
    {
        return Err(format!(
            "{} is both a training and a held-out record; the held-out records must be others",
            f.display()
        ));
    }
    Ok(())
}

/// The files to delete before `afsv synth` writes into `dir` (given as `-o`): none when
/// `dir` does not exist or is empty. A non-empty `dir` is replaced only with `force` and
/// only when the toolkit wrote all of it: a `truth.json` with `"written_by":
/// "afsv synth"` ([`SYNTH_WRITTEN_BY`]), and `train/` and `holdout/` holding nothing but
/// records (CSV) with toolkit-written sidecars ([`crate::guard::is_afsv_json`]). Anything
/// else in it is refused, so no file the toolkit did not write is ever deleted.
pub fn synth_folder_to_replace(dir: &Path, force: bool) -> Result<Vec<PathBuf>, String> {
    if !dir.exists() {
        return Ok(Vec::new());
    }
    if !dir.is_dir() {
        return Err(format!(
            "-o {}: exists and is not a folder; synth writes a folder (train/, holdout/, truth.json)",
            dir.display()
        ));
    }
    let entries = list_dir(dir)?;
    if entries.is_empty() {
        return Ok(Vec::new());
    }
    let foreign = |what: &str| {
        format!(
            "-o {}: {what}; afsv synth did not write this folder, so it is never replaced (choose another folder)",
            dir.display()
        )
    };
    let truth = dir.join("truth.json");
    let text = std::fs::read_to_string(&truth).map_err(|_| foreign("has no truth.json"))?;
    let by_synth = serde_json::from_str::<serde_json::Value>(&text)
        .ok()
        .and_then(|v| v.get("written_by")?.as_str().map(|s| s == SYNTH_WRITTEN_BY))
        .unwrap_or(false);
    if !by_synth {
        return Err(foreign(
            "its truth.json does not say `\"written_by\": \"afsv synth\"`",
        ));
    }
    let mut files = vec![truth.clone()];
    for e in entries {
        if e == truth {
            continue;
        }
        let name = e.file_name().unwrap_or_default();
        if !(is_real_dir(&e) && (name == "train" || name == "holdout")) {
            return Err(foreign(&format!("holds {}", e.display())));
        }
        files.extend(synth_records(&e).map_err(|f| foreign(&format!("holds {}", f.display())))?);
    }
    if !force {
        return Err(format!(
            "-o {}: exists (written by an earlier afsv synth); add --force to replace it",
            dir.display()
        ));
    }
    Ok(files)
}

/// The records and sidecars in `sub` when all are toolkit-written, else the first other
/// file.
fn synth_records(sub: &Path) -> Result<Vec<PathBuf>, PathBuf> {
    let mut files = Vec::new();
    for f in list_dir(sub).map_err(|_| sub.to_path_buf())? {
        let ext = f.extension().and_then(|x| x.to_str());
        let afsv_json = |j: &Path| {
            j.is_file() && std::fs::read_to_string(j).is_ok_and(|t| crate::guard::is_afsv_json(&t))
        };
        let ours = !is_link(&f)
            && f.is_file()
            && match ext {
                Some("csv") => afsv_json(&f.with_extension("json")),
                Some("json") => afsv_json(&f) && f.with_extension("csv").is_file(),
                _ => false,
            };
        if !ours {
            return Err(f);
        }
        files.push(f);
    }
    Ok(files)
}

/// True when `p` is a symbolic link (never followed when replacing a folder).
fn is_link(p: &Path) -> bool {
    std::fs::symlink_metadata(p).map_or(true, |m| m.file_type().is_symlink())
}

/// True when `p` is a folder and not a link to one.
fn is_real_dir(p: &Path) -> bool {
    !is_link(p) && p.is_dir()
}

/// Entries of `dir`, sorted.
fn list_dir(dir: &Path) -> Result<Vec<PathBuf>, String> {
    let mut v = std::fs::read_dir(dir)
        .map_err(|e| format!("{}: {e}", dir.display()))?
        .map(|e| e.map(|e| e.path()))
        .collect::<Result<Vec<_>, _>>()
        .map_err(|e| format!("{}: {e}", dir.display()))?;
    v.sort();
    Ok(v)
}
