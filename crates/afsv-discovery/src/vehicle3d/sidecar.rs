//! What a record's sidecar says of its conditions: a field, also under the path-change
//! command's `spec`, and the ground the vehicle commands write.

use crate::DiscoveryError;
use afsv_records::Record;
use serde_json::Value;
use terrain_psd::IsoClass;
use vehicle_3d::scenarios::TerrainSpec;

/// A sidecar field, also looked up under the path-change command's `spec`.
pub(super) fn meta<'a>(record: &'a Record, key: &str) -> Option<&'a Value> {
    record
        .meta
        .get(key)
        .or_else(|| record.meta.get("spec").and_then(|s| s.get(key)))
        .filter(|v| !v.is_null())
}

/// The ground of a record from its sidecar's `terrain` (as the vehicle commands write it:
/// class, m_c, band, seeds; `smooth ground` or none is flat).
pub(super) fn terrain_of(record: &Record) -> Result<Option<(TerrainSpec, u64)>, DiscoveryError> {
    let Some(t) = record
        .meta
        .get("terrain")
        .filter(|t| t.get("class").is_some())
    else {
        return Ok(None);
    };
    let bad = |field: &'static str| DiscoveryError::Sidecar {
        field,
        reason: format!("terrain {t} lacks it or it is malformed"),
    };
    let class: IsoClass = t["class"]
        .as_str()
        .and_then(|c| c.parse().ok())
        .ok_or_else(|| bad("terrain.class"))?;
    let mut spec = TerrainSpec {
        class,
        ..TerrainSpec::default()
    };
    if let Some(m) = t.get("m_c_cycles_per_m").and_then(Value::as_f64) {
        spec.m_c = m;
    }
    if let Some(b) = t.get("band_cycles_per_m").and_then(Value::as_array) {
        let f = |i: usize| {
            b.get(i)
                .and_then(Value::as_f64)
                .ok_or_else(|| bad("terrain.band"))
        };
        spec.band = (f(0)?, f(1)?);
    }
    let seed = t
        .get("seeds")
        .and_then(|s| s.get(0))
        .or_else(|| t.get("seed"))
        .and_then(Value::as_u64)
        .ok_or_else(|| bad("terrain.seeds"))?;
    Ok(Some((spec, seed)))
}
