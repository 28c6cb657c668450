//! Fixture files: reading `fixtures/reported/*.json` (common schema and `hps_lab.json`).

use super::ValidateError;
use serde::Serialize;
use serde_json::Value;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// One reported quantity, from any fixture file.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Fixture {
    /// Fixture file name.
    pub file: String,
    /// Unique id.
    pub id: String,
    /// `parameter`, `result`, `qualitative` or `literature`.
    pub kind: String,
    /// Description.
    pub description: String,
    /// Table / section reference.
    pub reference: String,
    /// `value` or `values` as printed.
    pub value: Value,
    /// Unit as printed (normalized spelling).
    pub unit: String,
    /// The `tolerance` object (common schema; `hps_lab.json` tolerances are converted).
    pub tolerance: Value,
    /// The fixture's `status` field (regression rule).
    pub status: String,
    /// Keys of a partly reproduced multi-valued fixture that are guarded.
    pub reproduced_keys: Vec<String>,
}

impl Fixture {
    /// The number at `key` (`.`-separated path into `values`; `None` = the scalar `value`).
    pub fn number(&self, key: Option<&str>) -> Option<f64> {
        let path: Vec<&str> = key.map(|k| k.split('.').collect()).unwrap_or_default();
        descend(&self.value, &path)?.as_f64()
    }

    /// Whether the fixture marks the row at `key` as reproduced (so it must not regress).
    pub fn guards(&self, key: Option<&str>) -> bool {
        let s = self.status.trim();
        if s == "reproduced" || s.starts_with("reproduced ") || s.starts_with("reproduced(") {
            return true;
        }
        match key {
            Some(k) => self.reproduced_keys.iter().any(|r| r == k),
            None => false,
        }
    }
}

/// All fixtures by id.
#[derive(Debug, Clone, Default)]
pub struct Fixtures {
    /// Fixtures keyed by id.
    pub by_id: BTreeMap<String, Fixture>,
}

impl Fixtures {
    /// Fixture `id`.
    pub fn get(&self, id: &str) -> Option<&Fixture> {
        self.by_id.get(id)
    }

    /// Number of fixture `id` at `key`; an error names the missing entry.
    pub fn num(&self, id: &str, key: Option<&str>) -> Result<f64, String> {
        self.get(id).and_then(|f| f.number(key)).ok_or_else(|| {
            format!(
                "fixture `{id}` has no number at `{}`",
                key.unwrap_or("value")
            )
        })
    }
}

/// Read every `*.json` fixture in `dir`.
pub fn load_fixtures(dir: &Path) -> Result<Fixtures, ValidateError> {
    let io = |path: &Path| {
        let p = path.to_path_buf();
        move |source| ValidateError::Io { path: p, source }
    };
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .map_err(io(dir))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .collect();
    files.sort();
    let mut out = Fixtures::default();
    for path in files {
        let text = std::fs::read_to_string(&path).map_err(io(&path))?;
        let bad = |reason: String| ValidateError::Fixture {
            path: path.clone(),
            reason,
        };
        let doc: Value = serde_json::from_str(&text).map_err(|e| bad(e.to_string()))?;
        let file = path
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        let qs = doc["quantities"]
            .as_array()
            .ok_or_else(|| bad("no `quantities` array".into()))?;
        for q in qs {
            let f = if q.get("kind").is_some() {
                parse_common(&file, q)
            } else {
                parse_hps_lab(&file, q)
            }
            .map_err(&bad)?;
            if out.by_id.contains_key(&f.id) {
                return Err(bad(format!("duplicate id `{}`", f.id)));
            }
            out.by_id.insert(f.id.clone(), f);
        }
    }
    Ok(out)
}

fn text(q: &Value, field: &str) -> String {
    q.get(field)
        .and_then(Value::as_str)
        .unwrap_or_default()
        .to_string()
}

fn parse_common(file: &str, q: &Value) -> Result<Fixture, String> {
    let id = q["id"].as_str().ok_or("quantity without `id`")?.to_string();
    let value = q
        .get("values")
        .or_else(|| q.get("value"))
        .cloned()
        .unwrap_or(Value::Null);
    let reproduced_keys = q
        .get("reproduced_keys")
        .and_then(Value::as_array)
        .map(|a| {
            a.iter()
                .filter_map(|k| k.as_str().map(String::from))
                .collect()
        })
        .unwrap_or_default();
    Ok(Fixture {
        file: file.to_string(),
        kind: text(q, "kind"),
        description: text(q, "description"),
        reference: text(q, "reference"),
        unit: text(q, "unit"),
        tolerance: q.get("tolerance").cloned().unwrap_or(Value::Null),
        status: text(q, "status"),
        value,
        id,
        reproduced_keys,
    })
}

/// `hps_lab.json`: `{id, description, value, unit, ref, tolerance: number|null,
/// tolerance_kind: "relative" | "absolute <unit>", status?}`; read as it is.
fn parse_hps_lab(file: &str, q: &Value) -> Result<Fixture, String> {
    let id = q["id"].as_str().ok_or("quantity without `id`")?.to_string();
    let tol = q.get("tolerance").and_then(Value::as_f64);
    let kind_text = text(q, "tolerance_kind");
    let tolerance = match tol {
        Some(t) if kind_text.starts_with("absolute") => serde_json::json!({ "absolute": t }),
        Some(t) => serde_json::json!({ "relative": t }),
        None => Value::Null,
    };
    let status = text(q, "status");
    let kind = if tol.is_some() || !status.is_empty() {
        "result"
    } else {
        "parameter"
    };
    Ok(Fixture {
        file: file.to_string(),
        kind: kind.into(),
        description: text(q, "description"),
        reference: text(q, "ref"),
        value: q.get("value").cloned().unwrap_or(Value::Null),
        unit: text(q, "unit"),
        tolerance,
        status,
        reproduced_keys: Vec::new(),
        id,
    })
}

/// The value at `path` (object keys or array indices) below `v`; a number met on the way
/// applies to everything below it.
pub(super) fn descend<'a>(mut v: &'a Value, path: &[&str]) -> Option<&'a Value> {
    for seg in path {
        if v.is_number() {
            // A scalar applies to every entry below it.
            return Some(v);
        }
        v = match v {
            Value::Object(m) => m.get(*seg)?,
            Value::Array(a) => a.get(seg.parse::<usize>().ok()?)?,
            _ => return None,
        };
    }
    Some(v)
}

/// A JSON array of numeric arrays as rows.
pub(super) fn matrix(v: &Value) -> Result<Vec<Vec<f64>>, String> {
    v.as_array()
        .ok_or("not a matrix")?
        .iter()
        .map(|r| {
            r.as_array()
                .ok_or_else(|| "matrix row is not an array".to_string())?
                .iter()
                .map(|x| x.as_f64().ok_or_else(|| "non-numeric entry".to_string()))
                .collect()
        })
        .collect()
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::Tolerance;
    use serde_json::json;

    /// A test fixture with the given status and guarded keys.
    pub(crate) fn fixture(status: &str, keys: &[&str]) -> Fixture {
        Fixture {
            file: "x.json".into(),
            id: "q".into(),
            kind: "result".into(),
            description: String::new(),
            reference: String::new(),
            value: json!({"a": 1.0, "b": [2.0, 3.0]}),
            unit: "1".into(),
            tolerance: json!({"relative": 0.1}),
            status: status.into(),
            reproduced_keys: keys.iter().map(|k| k.to_string()).collect(),
        }
    }

    #[test]
    fn guard_rule_follows_status_and_keys() {
        assert!(fixture("reproduced", &[]).guards(Some("a")));
        assert!(fixture("reproduced (one orifice, 2 Hz)", &[]).guards(None));
        assert!(!fixture("pending", &[]).guards(None));
        assert!(!fixture("not modelled", &[]).guards(None));
        let p = fixture("partially reproduced", &["a"]);
        assert!(p.guards(Some("a")));
        assert!(!p.guards(Some("b.0")));
        assert_eq!(p.number(Some("b.1")), Some(3.0));
    }

    #[test]
    fn hps_lab_schema_is_read_as_is() {
        let q = json!({"id": "p", "description": "d", "value": 0.5, "unit": "MPa", "ref": "5.4.2",
                       "tolerance": 0.1, "tolerance_kind": "absolute MPa", "status": "reproduced (x)"});
        let f = parse_hps_lab("hps_lab.json", &q).unwrap();
        assert_eq!(f.kind, "result");
        assert_eq!(
            Tolerance::from_fixture(&f.tolerance, None),
            Some(Tolerance::Absolute(0.1))
        );
        assert!(f.guards(None));
        let q = json!({"id": "k", "description": "d", "value": 50, "unit": "s/m", "ref": "5.3.2", "tolerance": null});
        assert_eq!(parse_hps_lab("hps_lab.json", &q).unwrap().kind, "parameter");
    }
}
