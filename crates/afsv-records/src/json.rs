//! JSON output rules of the toolkit's front ends: no NaN or infinity (a non-finite number is
//! `null`), and every `null` carries a `"<field>_reason"` sibling saying why; the unit
//! conversions of a record read, as JSON.

use serde_json::Value;

/// Reason given to a `null` that the command did not explain itself.
pub const NULL_REASON: &str = "not available: not computed for this input or not a finite number";

/// A JSON number for `v`, or `null` when it is not finite.
pub fn finite_or_null(v: f64) -> Value {
    if v.is_finite() {
        Value::from(v)
    } else {
        Value::Null
    }
}

fn holds_null(v: &Value) -> bool {
    match v {
        Value::Null => true,
        Value::Array(a) => a.iter().any(holds_null),
        _ => false,
    }
}

/// Give every object field that is `null` (or an array holding a `null` at any depth) a
/// sibling `"<field>_reason"` string unless it has one or the object has a `"reason"` field.
pub fn annotate_nulls(v: &mut Value) {
    match v {
        Value::Object(map) => {
            let missing: Vec<String> = map
                .iter()
                .filter(|(k, v)| {
                    holds_null(v)
                        && !k.ends_with("_reason")
                        && !map.contains_key(&format!("{k}_reason"))
                        && !map.contains_key("reason")
                })
                .map(|(k, _)| k.clone())
                .collect();
            for k in missing {
                map.insert(format!("{k}_reason"), Value::from(NULL_REASON));
            }
            for (_, child) in map.iter_mut() {
                annotate_nulls(child);
            }
        }
        Value::Array(a) => a.iter_mut().for_each(annotate_nulls),
        _ => {}
    }
}

/// Give every `null` field of the object `v` (not nested) the sibling `"<field>_reason":
/// reason`, unless it has one. Returns `v`.
pub fn explain_nulls(mut v: Value, reason: &str) -> Value {
    if let Some(obj) = v.as_object_mut() {
        let absent: Vec<String> = obj
            .iter()
            .filter(|(k, v)| v.is_null() && !obj.contains_key(&format!("{k}_reason")))
            .map(|(k, _)| format!("{k}_reason"))
            .collect();
        for k in absent {
            obj.insert(k, Value::from(reason));
        }
    }
    v
}

/// Every `null` in `v` that is not explained (the rule of [`annotate_nulls`]), as JSON
/// pointer-like paths. Also used by `cargo xtask fuzz`.
pub fn unexplained_nulls(v: &Value) -> Vec<String> {
    let mut out = Vec::new();
    walk_nulls(v, "", false, &mut out);
    out
}

fn walk_nulls(v: &Value, path: &str, explained: bool, out: &mut Vec<String>) {
    match v {
        Value::Null if !explained => out.push(if path.is_empty() {
            "/".into()
        } else {
            path.into()
        }),
        Value::Object(map) => {
            for (k, child) in map {
                let ok = map.contains_key(&format!("{k}_reason")) || map.contains_key("reason");
                walk_nulls(child, &format!("{path}/{k}"), ok, out);
            }
        }
        Value::Array(a) => {
            for (i, child) in a.iter().enumerate() {
                walk_nulls(child, &format!("{path}/{i}"), explained, out);
            }
        }
        _ => {}
    }
}

/// The channels a record was converted from another unit on reading, as JSON
/// (`[{"from": "az_g", "to": "az_m_s2", "factor": 9.80665}, ...]`), so a command's output says
/// which channels it used and how.
pub fn unit_conversions(rec: &crate::Record) -> Value {
    Value::Array(
        rec.unit_conversions
            .iter()
            .map(|c| serde_json::json!({ "from": c.from, "to": c.to, "factor": c.factor }))
            .collect(),
    )
}

/// `serde_json`'s message without its " at line L column C" (each line is parsed alone;
/// callers that report a position give it themselves).
pub fn message(e: &serde_json::Error) -> String {
    let m = e.to_string();
    match m.rsplit_once(" at line ") {
        Some((head, _)) => head.to_string(),
        None => m,
    }
}

/// The columns `names` (in that order) from JSON objects that each hold them as numbers;
/// a field missing or not a finite number is an error naming the row.
pub fn from_rows(rows: &[Value], names: &[&str]) -> Result<crate::Record, String> {
    let mut rec = crate::Record::new();
    for name in names {
        let col = rows
            .iter()
            .enumerate()
            .map(|(i, r)| {
                r.get(*name)
                    .and_then(Value::as_f64)
                    .ok_or_else(|| format!("row {} has no number `{name}`", i + 1))
            })
            .collect::<Result<Vec<f64>, String>>()?;
        rec.push_column(name, col).map_err(|e| e.to_string())?;
    }
    Ok(rec)
}

/// Named numeric columns from arrays of equal length in the JSON object `obj` (those of
/// `names` that it has).
pub fn from_columns(obj: &Value, names: &[&str]) -> Result<crate::Record, String> {
    let mut rec = crate::Record::new();
    for name in names {
        let Some(arr) = obj.get(*name).and_then(Value::as_array) else {
            continue;
        };
        let col = arr
            .iter()
            .map(|v| v.as_f64().ok_or_else(|| format!("`{name}` holds {v}")))
            .collect::<Result<Vec<f64>, String>>()?;
        rec.push_column(name, col).map_err(|e| e.to_string())?;
    }
    Ok(rec)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nulls_get_reasons() {
        let mut v = serde_json::json!({"a": f64::NAN, "b": [1.0, null], "c": null, "c_reason": "x", "d": {"e": null}});
        annotate_nulls(&mut v);
        assert_eq!(v["a_reason"], NULL_REASON);
        assert_eq!(v["b_reason"], NULL_REASON);
        assert_eq!(v["c_reason"], "x");
        assert_eq!(v["d"]["e_reason"], NULL_REASON);
        assert!(unexplained_nulls(&v).is_empty());
        assert_eq!(
            unexplained_nulls(&serde_json::json!({"a": [null]})),
            vec!["/a/0"]
        );
        assert_eq!(unexplained_nulls(&Value::Null), vec!["/"]);
    }

    #[test]
    fn rows_become_columns_and_a_missing_field_is_named() {
        let rows = vec![
            serde_json::json!({"x_m": 0.0, "name": "a", "z_m": 1.5}),
            serde_json::json!({"x_m": 0.5, "name": "b", "z_m": -2.0}),
        ];
        let rec = from_rows(&rows, &["z_m", "x_m"]).unwrap();
        assert_eq!(rec.names(), ["z_m", "x_m"]);
        assert_eq!(rec.column("z_m").unwrap(), &[1.5, -2.0]);
        let bad = vec![
            serde_json::json!({"x_m": 0.0}),
            serde_json::json!({"y": 1.0}),
        ];
        assert!(from_rows(&bad, &["x_m"]).unwrap_err().contains("row 2"));
    }
}
