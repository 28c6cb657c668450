//! The checks every ask/tell optimisation makes of its batch and results files (the afs,
//! layout and HPS formats: `afs_batch`, `layout_ask_tell`, `hps_ask_tell`): a batch file
//! has the right format and version, a state SHA-256 in hex, as many points as its header
//! announces and the ids `b<batch>-<index>` in order ([`read_batch_file`]); the results
//! files of a tell answer every asked id exactly once and no other ([`collect_results`]).
//! A results file's header answers the state that asked ([`check_results_header`]).

use crate::afs_batch::{is_sha256_hex, point_id, MAX_BATCH_POINTS};
use serde::de::DeserializeOwned;
use std::collections::HashMap;
use std::path::{Path, PathBuf};

/// What the readers need of a batch file's header.
pub trait BatchHeaderFields {
    /// Its `format`.
    fn format(&self) -> &str;
    /// Its `version`.
    fn version(&self) -> u32;
    /// The asking state's SHA-256 (hex).
    fn state_sha256(&self) -> &str;
    /// The batch's number.
    fn batch(&self) -> usize;
    /// The number of point lines announced.
    fn points(&self) -> usize;
}

/// A batch point or a result line: its id.
pub trait PointId {
    /// The id, `b<batch>-<index>`.
    fn id(&self) -> &str;
}

/// The kind of a batch file, for its checks and messages.
pub struct BatchKind<'a> {
    /// What a wrong file is not, e.g. "batch file", "layout batch file".
    pub what: &'a str,
    /// The expected `format`.
    pub format: &'a str,
    /// The expected `version`.
    pub version: u32,
}

/// Reads and checks a batch file (`label` names it in errors): format, version and the
/// state SHA-256 of its header, then `check` of the header, then the point count and ids.
/// The points come with their line numbers.
pub fn read_batch_file<H, P>(
    label: &str,
    path: &Path,
    kind: &BatchKind,
    check: &dyn Fn(&H) -> Result<(), String>,
) -> Result<(H, Vec<(usize, P)>), String>
where
    H: BatchHeaderFields + DeserializeOwned,
    P: PointId + DeserializeOwned,
{
    let bad = |what: String| format!("{label} {}: {what}", path.display());
    let head = |h: &H| {
        if h.format() != kind.format || h.version() != kind.version {
            return Err(bad(format!(
                "not a {} of version {} (format {:?}, version {})",
                kind.what,
                kind.version,
                h.format(),
                h.version()
            )));
        }
        if !is_sha256_hex(h.state_sha256()) {
            return Err(bad(format!(
                "state_sha256 {:?} is not a SHA-256 in hex",
                h.state_sha256()
            )));
        }
        check(h)
    };
    let (h, lines): (H, Vec<(usize, P)>) =
        afsv_records::jsonl::read_jsonl(label, path, MAX_BATCH_POINTS, &head)?;
    if h.points() != lines.len() {
        return Err(bad(format!(
            "the header announces {} points, the file holds {}",
            h.points(),
            lines.len()
        )));
    }
    for (i, (line, p)) in lines.iter().enumerate() {
        if p.id() != point_id(h.batch(), i) {
            return Err(bad(format!(
                "line {line}: point {:?}, expected id {:?}",
                p.id(),
                point_id(h.batch(), i)
            )));
        }
    }
    Ok((h, lines))
}

/// The header checks of a results file (`file` names it) against the state that tells it:
/// the format and version of `kind`, the same problem (`same_problem`), and the batch
/// `(number, state SHA-256)` the state asked (`asked`); `got` is the header's
/// `(format, version)` and `from` its `(batch, state SHA-256)`.
pub fn check_results_header(
    file: &str,
    kind: &BatchKind,
    got: (&str, u32),
    same_problem: bool,
    from: (usize, &str),
    asked: (usize, &str),
) -> Result<(), String> {
    if got.0 != kind.format || got.1 != kind.version {
        return Err(format!(
            "--tell {file}: not {} of version {} (format {:?}, version {})",
            kind.what, kind.version, got.0, got.1
        ));
    }
    if !same_problem {
        return Err(format!(
            "--tell {file}: results of another problem than this state's"
        ));
    }
    if from != asked {
        return Err(format!(
            "--tell {file}: results of batch {} as another state asked it; this state asks batch {} (evaluate this state's batch, --ask, and tell its results)",
            from.0, asked.0
        ));
    }
    Ok(())
}

/// Reads the results files of a tell (`--tell`) and returns what `take` makes of each
/// result, in the order of `asked` (the ids of batch `batch`). Every file's header passes
/// `check` (given the file's name); every asked id comes exactly once, no other id comes.
/// `take` gets a result and its index in `asked`, and may refuse it.
pub fn collect_results<H, R, T>(
    tell: &[PathBuf],
    batch: usize,
    asked: &[&str],
    check: &dyn Fn(&H, &str) -> Result<(), String>,
    take: &dyn Fn(&R, usize) -> Result<T, String>,
) -> Result<Vec<T>, String>
where
    H: DeserializeOwned,
    R: PointId + DeserializeOwned,
    T: Clone,
{
    let index: HashMap<&str, usize> = asked.iter().enumerate().map(|(i, p)| (*p, i)).collect();
    let mut found: Vec<Option<(T, String)>> = vec![None; asked.len()];
    for path in tell {
        let file = path.display().to_string();
        let (_, lines): (H, Vec<(usize, R)>) =
            afsv_records::jsonl::read_jsonl("--tell", path, asked.len(), &|h: &H| check(h, &file))?;
        for (line, r) in lines {
            let Some(&i) = index.get(r.id()) else {
                return Err(format!(
                    "--tell {file}:{line}: id {:?} was not asked in batch {batch}",
                    r.id()
                ));
            };
            let t =
                take(&r, i).map_err(|e| format!("--tell {file}:{line}: id {:?}: {e}", r.id()))?;
            if let Some((_, first)) = &found[i] {
                return Err(format!(
                    "--tell {file}:{line}: id {:?} already came in {first}",
                    r.id()
                ));
            }
            found[i] = Some((t, format!("{file}:{line}")));
        }
    }
    let missing = found.iter().filter(|f| f.is_none()).count();
    if let Some(first) = asked.iter().zip(&found).find(|(_, f)| f.is_none()) {
        return Err(format!(
            "--tell: {missing} of the {} asked points of batch {batch} have no result (first: {}); give every shard's results file",
            asked.len(),
            first.0
        ));
    }
    Ok(found.into_iter().flatten().map(|(t, _)| t).collect())
}
