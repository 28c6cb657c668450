//! `afsv vehicle ride --seat`: ISO 2631-1 read where the operator sits. The cab on its
//! mounts and the suspension seat (docs/layouts.md) are driven by each ride run's
//! front-unit motion; the report (`afsv_design::report::vehicle`) adds a_wz on the cab floor
//! and the seat pan, the seat's 8 h health-guidance verdict, SEAT (ISO 10326-1), seat travel
//! and time on its stops.

use super::CaseArgs;
use vehicle_3d::cab_ride::{seat_ride_measures, CabSeatLayout, SeatRideMeasures};
use vehicle_3d::{RunRecord, VehicleParams};

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
