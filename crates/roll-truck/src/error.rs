//! Errors of the truck model, its runs and its studies: the run error the multibody
//! vehicles share ([`vehicle_run::RunError`]), with its parameter checks.

/// What went wrong building, running or measuring the truck. Every variant names its cause.
pub use vehicle_run::RunError as TruckError;

pub(crate) use vehicle_run::{non_negative, positive, rejected};
