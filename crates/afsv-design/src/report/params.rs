//! The reports of `afsv params`: a parameter set's named parameters with their values
//! ([`named`]) or specifications ([`specs`]), a list of them as text ([`list_text`]), what a
//! vehicle description builds ([`check_vehicle`]), and the registry-range check of a 3-D
//! vehicle set ([`vehicle_3d_in_ranges`]).

use serde_json::{json, Value};
use std::path::Path;
use vehicle_3d::VehicleParams;
use vehicle_components::ParamSet as Named;

/// A parameter list (or the built-in vehicles) as aligned columns for a terminal.
pub fn list_text(list: &Value) -> String {
    let cell = |v: &Value| match v {
        Value::String(s) => s.clone(),
        Value::Null => "-".into(),
        other => other.to_string(),
    };
    let (cols, rows): (&[&str], &Vec<Value>) = match (list.get("parameters"), list.get("builtin")) {
        (Some(Value::Array(r)), _) => {
            (&["name", "unit", "nominal", "lower", "upper", "typical"], r)
        }
        (_, Some(Value::Array(r))) => (&["name", "description"], r),
        _ => return format!("{list}\n"),
    };
    let table: Vec<Vec<String>> = rows
        .iter()
        .map(|r| cols.iter().map(|c| cell(&r[*c])).collect())
        .collect();
    let widths: Vec<usize> = cols
        .iter()
        .enumerate()
        .map(|(j, c)| {
            table
                .iter()
                .map(|r| r[j].chars().count())
                .fold(c.len(), usize::max)
        })
        .collect();
    let line = |items: Vec<&str>| {
        let parts: Vec<String> = items
            .iter()
            .zip(&widths)
            .map(|(s, w)| format!("{s:<w$}"))
            .collect();
        parts.join("  ").trim_end().to_string() + "\n"
    };
    let mut out = format!(
        "{} ({} entries; --json for JSON)\n",
        cell(&list["set"]),
        rows.len()
    );
    out += &line(cols.to_vec());
    for r in &table {
        out += &line(r.iter().map(String::as_str).collect());
    }
    out
}

/// `afsv params check vehicle FILE`: the description read and resolved; what it builds.
pub fn check_vehicle(file: &Path) -> Result<Value, String> {
    let d = afsv_vehicle::load_file(file).map_err(|e| e.to_string())?;
    Ok(match d.vehicle {
        afsv_vehicle::Vehicle::Articulated(a) => {
            let mut v = json!({
            "name": a.name,
            "kind": "articulated",
            "front_suspension": a.front_suspension,
            "front_strut": a.front_strut_source,
            "rear_suspension": a.rear_suspension,
            "rear_strut": a.rear_strut_source,
            "yaw_plane": if a.yaw_plane_derived { "derived from the units and tire" } else { "as given" },
            "parameters": named(&a.params),
            });
            if let Some(l) = &a.link {
                v["link"] = json!(l);
            }
            if let Some(b) = &a.params.bogie {
                v["rear_bogie"] = json!(b);
            }
            v
        }
        afsv_vehicle::Vehicle::RigidTruck(t) => json!({
            "name": t.name,
            "kind": "rigid-truck",
            "parameters": named(&t.params),
        }),
    })
}

/// Every value of a 3-D vehicle set within its registry range: the vehicle's own, its tire's
/// (`tire.`), its steering's (`steering.`) and its strut's (`hps.`).
pub fn vehicle_3d_in_ranges(p: &VehicleParams) -> Result<(), String> {
    let sets: [(&str, &dyn Named); 4] = [
        ("", p),
        ("tire.", &p.tire),
        ("steering.", &p.steering),
        ("hps.", &p.hps),
    ];
    for (prefix, set) in sets {
        vehicle_components::within_ranges(set).map_err(|e| {
            if prefix.is_empty() {
                e
            } else {
                format!("under `{prefix}`: {e}")
            }
        })?;
    }
    Ok(())
}

/// Every named parameter of `p` with its value.
pub fn named(p: &dyn Named) -> Value {
    let map: serde_json::Map<String, Value> = p
        .specs()
        .iter()
        .enumerate()
        .map(|(i, s)| {
            (
                s.name.to_string(),
                afsv_records::json::finite_or_null(p.value(i)),
            )
        })
        .collect();
    Value::Object(map)
}

/// The specification of every named parameter of `p`, with its value in `p`.
pub fn specs(p: &dyn Named) -> Value {
    let rows: Vec<Value> = p
        .specs()
        .iter()
        .enumerate()
        .map(|(i, s)| {
            json!({
                "name": s.name,
                "unit": s.unit,
                "lower": s.lower,
                "upper": s.upper,
                "typical": s.typical,
                "nominal": afsv_records::json::finite_or_null(p.value(i)),
            })
        })
        .collect();
    json!({ "set": p.set_name(), "parameters": rows })
}
