//! Measured roads (`--road FILE` of `afsv vehicle ride` and `afsv roll simulate|measures`):
//! a record (docs/records.md) with the columns `x_m` (uniformly spaced), `left_m` and
//! `right_m`, other length units (`left_mm`, `x_km`) converted on read and the conversions
//! reported; or an ASAM OpenCRG ASCII file (`.crg`, docs/terrain-psd.md), sampled along two
//! wheel tracks. The file is declared an input (never overwritten, named with its SHA-256
//! in the provenance). [`ride`]: the D1 ride of the 3-D vehicle on such a road, sampled
//! along its two wheel tracks at plus and minus half the front track.

use crate::report::vehicle::{Ground, NO_STRUT};
use afsv_records::guard::OutputGuard;
use afsv_records::Record;
use serde_json::{json, Value};
use std::path::Path;
use terrain_psd::TwoTrackProfile;
use vehicle_3d::scenarios::{measured_ride_tracks, ride_on, RideMeasures, RideSpec};
use vehicle_3d::{RunRecord, VehicleParams};

/// Largest measured road read (samples per track): 200 km at 2 cm.
const MAX_ROAD_SAMPLES: usize = 10_000_000;

/// Largest OpenCRG file read (bytes): 10 million rows of eight 10-character sections.
const MAX_CRG_BYTES: u64 = 1 << 30;

/// The two tracks of the road in `file` (an OpenCRG file read at plus and minus
/// `half_track`, m) and what the reading did (format, unit conversions, track offsets).
pub fn read(file: &Path, half_track: f64) -> Result<(TwoTrackProfile, Value), String> {
    OutputGuard::new(false).record_input("--road", file)?;
    let is_crg = file
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("crg"));
    if is_crg {
        crg_profile(file, half_track)
    } else {
        record_profile(file)
    }
}

/// The two tracks of a record file, and what its reading converted.
fn record_profile(file: &Path) -> Result<(TwoTrackProfile, Value), String> {
    let shown = file.display();
    let rec = Record::read(file).map_err(|e| e.to_string())?;
    let column = |name: &str| rec.require(name, file).map_err(|e| e.to_string());
    let (x, left, right) = (column("x_m")?, column("left_m")?, column("right_m")?);
    if x.len() > MAX_ROAD_SAMPLES {
        return Err(format!(
            "{shown}: {} samples, more than the {MAX_ROAD_SAMPLES} a road may have",
            x.len()
        ));
    }
    let profile =
        TwoTrackProfile::from_samples(x, left, right).map_err(|e| format!("{shown}: {e}"))?;
    let format = json!({
        "format": "afsv record",
        "unit_conversions": afsv_records::json::unit_conversions(&rec),
    });
    Ok((profile, format))
}

/// The two tracks of an OpenCRG file at plus and minus `half_track` (m).
fn crg_profile(file: &Path, half_track: f64) -> Result<(TwoTrackProfile, Value), String> {
    let shown = file.display();
    let size = std::fs::metadata(file)
        .map_err(|e| format!("{shown}: {e}"))?
        .len();
    if size > MAX_CRG_BYTES {
        return Err(format!(
            "{shown}: {size} bytes, more than the {MAX_CRG_BYTES} an OpenCRG road may have"
        ));
    }
    let bytes = std::fs::read(file).map_err(|e| format!("{shown}: {e}"))?;
    let road = terrain_psd::read_crg(&bytes, half_track).map_err(|e| format!("{shown}: {e}"))?;
    let format = json!({
        "format": "OpenCRG",
        "track_offsets_m": [half_track, -half_track],
        "start_u_m": road.start_u_m,
        "sections_v_m": road.sections_v_m,
    });
    Ok((road.profile, format))
}

/// One D1 ride of `p` on the measured road in `file`: its record, measures and ground.
pub fn ride(
    p: &VehicleParams,
    spec: &RideSpec,
    file: &Path,
    link: Option<&vehicle_3d::interconnect::Link>,
) -> Result<(RunRecord, RideMeasures, Ground), String> {
    let shown = file.display();
    let (profile, format) = read(file, 0.5 * p.front_track_m)?;
    let (dx, n) = (profile.dx_m, profile.len());
    let tracks = measured_ride_tracks(p, spec, profile).map_err(|e| format!("{shown}: {e}"))?;
    let (rec, m) = match link {
        Some(l) => {
            vehicle_3d::interconnect::ride_linked_on(p, spec, tracks, l).map(|(r, m)| (r.record, m))
        }
        None => ride_on(p, spec, tracks),
    }
    .map_err(|e| e.to_string())?;
    let length = dx * (n - 1) as f64;
    let mut road = json!({
        "kind": "measured two-track road",
        "file": file,
        "length_m": length,
        "dx_m": dx,
        "samples": n,
    });
    if let (Value::Object(extra), Some(o)) = (format, road.as_object_mut()) {
        o.extend(extra);
    }
    let ground = Ground {
        json: road,
        text: format!("measured road {shown} ({length:.0} m at {dx} m)"),
        per_run: json!([{
            "road": file,
            "measures": afsv_records::json::explain_nulls(json!(m), NO_STRUT),
        }]),
    };
    Ok((rec, m, ground))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_record_road_is_read_with_its_conversions() {
        let dir = std::env::temp_dir().join(format!("afsv-road-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let file = dir.join("road.csv");
        let rows: String = (0..50)
            .map(|i| format!("{},{},{}\n", 0.1 * i as f64, i % 3, i % 2))
            .collect();
        std::fs::write(&file, format!("x_m,left_mm,right_m\n{rows}")).unwrap();
        let (profile, format) = read(&file, 1.0).unwrap();
        assert_eq!(profile.len(), 50);
        assert_eq!(format["format"], "afsv record");
        assert!(format["unit_conversions"].to_string().contains("left_mm"));
        assert!(read(&dir.join("none.csv"), 1.0).is_err());
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
