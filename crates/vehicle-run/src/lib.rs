//! The run harness the multibody vehicles share (`roll-truck`, Chapter 2; `vehicle-3d`,
//! Chapter 6): one error type ([`RunError`]) with its parameter checks, the checks of a
//! run's settings and its output grid ([`RunSpan`], [`RunSettings`]), and the integrator every run is
//! integrated with ([`integrator`], [`run_error`]), and a run's record as named columns
//! ([`columns`]), and the states both share ([`states`]: the floating base and the drive,
//! laid out with each vehicle's components in a `vehicle_components::StateLayout`). Each
//! vehicle keeps what is its own: its recorded channels and its events.

mod error;
mod record;
mod run;
pub mod states;

pub use error::{finite, measure, non_negative, positive, rejected, RunError};
pub use record::columns;
pub use run::{integrator, run_error, RunSettings, RunSpan};
