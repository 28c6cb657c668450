//! Errors of the 3-D vehicle, its runs and its measures: the run error the multibody
//! vehicles share ([`vehicle_run::RunError`]), with its parameter checks.

/// What went wrong building, running or measuring the vehicle. Every variant names its cause.
pub use vehicle_run::RunError as VehicleError;

pub(crate) use vehicle_run::{finite, measure, non_negative, positive, rejected};
