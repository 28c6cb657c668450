//! The field courses of Fig 3.6 and their Table 3.2 speeds. The course geometry and the
//! pure-pursuit driver ([`Course`], [`PathDriver`]) live in the component layer
//! (`vehicle_components::path_driver`), shared with the 3-D vehicle.

use serde::{Deserialize, Serialize};
pub use vehicle_components::path_driver::{Course, PathDriver};

/// Which field course of Fig 3.6.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FieldCourse {
    /// 13.5 m radius steady turn.
    SteadyTurn,
    /// 4.5 m offset, 18 m gate path change.
    PathChange,
}

/// Table 3.2 mean speeds (km/h) for a course and load condition.
pub fn table_3_2_speeds_kmh(course: FieldCourse, load: crate::Load) -> &'static [f64] {
    use crate::Load::*;
    match (course, load) {
        (FieldCourse::SteadyTurn, Loaded) => &[13.4],
        (FieldCourse::SteadyTurn, Unloaded) => &[18.5, 24.0],
        (FieldCourse::PathChange, Loaded) => &[15.3],
        (FieldCourse::PathChange, Unloaded) => &[19.2, 22.8],
    }
}
