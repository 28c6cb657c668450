//! `afsv vehicle ride --seat`: ISO 2631-1 read where the operator sits. The cab on its
//! mounts and the suspension seat (docs/layouts.md) are driven by each ride run's
//! front-unit motion; the report adds a_wz on the cab floor and the seat pan, the seat's
//! 8 h health-guidance verdict, SEAT (ISO 10326-1), seat travel and time on its stops.

use super::{spread, spread_text, CaseArgs, HGCZ_HOURS};
use perf_measures::iso2631::{health_guidance_zone, HgczRelation, HgczZone};
use serde_json::{json, Value};
use vehicle_3d::cab_ride::{seat_ride_measures, CabSeatLayout, SeatRideMeasures};
use vehicle_3d::{RunRecord, VehicleParams};

/// Why a ride has no seat measures.
pub(super) const NO_SEAT: &str =
    "no cab and seat: give --seat generic, or [cab.body] and [seat] in the vehicle description";

/// The cab and seat of the ride: `--seat generic` or `off`, else the description's (none
/// for a raw `--params` set or a description without them).
pub(super) fn layout(case: &CaseArgs, flag: Option<&str>) -> Result<Option<CabSeatLayout>, String> {
    match flag {
        Some("off") => Ok(None),
        Some(_) => Ok(Some(CabSeatLayout::generic())),
        None if case.params.is_some() => Ok(None),
        None => Ok(super::super::described::articulated(case.vehicle.as_deref())?.cab_seat),
    }
}

/// The seat measures of one ride record from `t_window` (s) on.
pub(super) fn of_run(
    p: &VehicleParams,
    rec: &RunRecord,
    t_window: f64,
    layout: Option<&CabSeatLayout>,
) -> Result<Option<SeatRideMeasures>, String> {
    layout
        .map(|l| seat_ride_measures(p, rec, t_window, l).map_err(|e| e.to_string()))
        .transpose()
}

/// Add the seat measures over the runs to the ride report: `"seat"` in `v` (null with a
/// reason when the ride has none) and their lines in `text`.
pub(super) fn report(
    seats: &[SeatRideMeasures],
    v: &mut Value,
    text: &mut String,
) -> Result<(), String> {
    if seats.is_empty() {
        v["seat"] = Value::Null;
        v["seat_reason"] = json!(NO_SEAT);
        return Ok(());
    }
    let floor = spread(seats, |s| s.a_wz_floor_m_s2)?;
    let seat = spread(seats, |s| s.a_wz_seat_m_s2)?;
    let ratio = spread(seats, |s| s.seat.seat)?;
    let travel = spread(seats, |s| s.seat_travel_p2p_m)?;
    let stops = spread(seats, |s| s.stop_fraction)?;
    let zone =
        health_guidance_zone(HGCZ_HOURS, HgczRelation::SqrtTime).map_err(|e| e.to_string())?;
    let verdict = zone.classify(seat.mean);
    v["seat"] = json!({
        "a_wz_floor_m_s2": floor,
        "a_wz_seat_m_s2": seat,
        "a_wz_seat_mean_zone": verdict,
        "seat_ratio": ratio,
        "seat_travel_p2p_m": travel,
        "stop_fraction": stops,
        "per_run": seats,
    });
    let verdict = match verdict {
        HgczZone::Below => "below the zone",
        HgczZone::Within => "within the zone (caution)",
        HgczZone::Above => "above the zone (health risk likely)",
    };
    *text += &spread_text("a_wz on the cab floor", &floor, "m/s²");
    *text += &spread_text("a_wz at the seat", &seat, "m/s²");
    *text += &format!("{:<32} {verdict}\n", "HGCZ verdict at the seat");
    *text += &spread_text("SEAT (seat / floor, ISO 10326-1)", &ratio, "");
    *text += &spread_text("seat travel peak-to-peak", &travel, "m");
    *text += &spread_text("share of time on seat stops", &stops, "");
    Ok(())
}
