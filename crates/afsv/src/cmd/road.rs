//! Measured roads (`--road FILE` of `afsv vehicle ride` and `afsv roll simulate|measures`):
//! a record (docs/records.md) with the columns `x_m` (uniformly spaced), `left_m` and
//! `right_m`, other length units (`left_mm`, `x_km`) converted on read and the conversions
//! reported; or an ASAM OpenCRG ASCII file (`.crg`, docs/terrain-psd.md), sampled along two
//! wheel tracks. The file is declared an input (never overwritten, named with its SHA-256
//! in the provenance).

use afsv::output::OutputGuard;
use afsv_records::Record;
use serde_json::{json, Value};
use std::path::Path;
use terrain_psd::TwoTrackProfile;

/// Largest measured road read (samples per track): 200 km at 2 cm.
const MAX_ROAD_SAMPLES: usize = 10_000_000;

/// Largest OpenCRG file read (bytes): 10 million rows of eight 10-character sections.
const MAX_CRG_BYTES: u64 = 1 << 30;

/// The two tracks of the road in `file` (an OpenCRG file read at plus and minus
/// `half_track`, m) and what the reading did (format, unit conversions, track offsets).
pub(crate) fn read(file: &Path, half_track: f64) -> Result<(TwoTrackProfile, Value), String> {
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
        "unit_conversions": afsv::output::unit_conversions(&rec),
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
