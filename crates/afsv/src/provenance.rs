//! Where an output comes from: the tool, its version, the git commit it was built from, and
//! every input file the run read with its SHA-256 (`afsv_records::provenance`). Every JSON
//! that `afsv` prints ([`crate::output::print_json`]) and every record sidecar it writes
//! ([`stamp_record`]) carries it under `"provenance"`.

use serde_json::{json, Value};

/// The git commit the binary was built from, when it was built from a checkout.
pub const COMMIT: Option<&str> = option_env!("AFSV_GIT_COMMIT");

/// The provenance of this run so far.
pub fn stamp() -> Value {
    let mut v = json!({
        "tool": "afsv",
        "version": env!("CARGO_PKG_VERSION"),
        "commit": COMMIT,
        "inputs": afsv_records::provenance::inputs(),
    });
    if COMMIT.is_none() {
        v["commit_reason"] = "not built from a git checkout".into();
    }
    v
}

/// `rec` with the sidecar fields `meta` and the run's provenance ([`stamp_record`]),
/// written to `path` (CSV and sidecar, whole or not at all); the record as written.
pub fn write_record(
    path: &std::path::Path,
    mut rec: afsv_records::Record,
    meta: Value,
) -> Result<afsv_records::Record, afsv_records::RecordError> {
    rec.meta = meta;
    stamp_record(&mut rec);
    rec.write(path)?;
    Ok(rec)
}

/// Put the provenance into a record's sidecar metadata (making it an object if it was
/// empty).
pub fn stamp_record(rec: &mut afsv_records::Record) {
    if !rec.meta.is_object() {
        rec.meta = json!({});
    }
    rec.meta["provenance"] = stamp();
}
