//! The rigid two-axle 50-t mining truck of Chapter 2 on the multibody core, and its roll
//! stability on rough terrain: the dynamic rollover threshold on a smooth road (DRT) and
//! the RMS lateral acceleration over the sustained period of near-unity LTR on rough
//! terrain (SP-DRT), with the parametric studies of section 2.4.
//!
//! - [`params`]: Tables 2.1-2.3 and the documented assumptions; [`registry`] names them.
//! - [`statics`]: the hand calculation of the static loads (note 1.9) and of the roll
//!   stability floor.
//! - [`model`]: the 10-DOF tree with its roll centres; [`suspension`]: struts and bump
//!   stops; [`tires`]: Eqs 2.1-2.7; [`driver`]: ramp steer and PI speed control;
//!   [`vehicle`]: the ODE system.
//! - [`simulate`](mod@simulate): a run to absolute rollover (an `odeint` event);
//!   [`channels`]: its channels in the record convention `afsv-v1`;
//!   [`measures`]: LTR (Eq 2.11), DRT, SP-DRT, the peaks of three a_y channels, SSF;
//!   [`calibration`]: the one calibrated roll compliance; [`studies`]: section 2.4 over
//!   terrain seeds and the calibrated against the plausible truck
//!   ([`TruckParams::plausible`]); [`sensitivity`]: ΔT against the unstated steering ramp
//!   and detection rule.
//!
//! See `docs/roll-truck.md` for the map from equations to code and every assumption.

pub mod calibration;
pub mod channels;
pub mod driver;
mod error;
mod findings;
pub mod measures;
pub mod model;
pub mod params;
pub mod registry;
pub mod sensitivity;
pub mod simulate;
pub mod statics;
pub mod studies;
pub mod suspension;
pub mod tires;
pub mod vehicle;

pub use driver::SteerDirection;
pub use error::TruckError;
pub use findings::{r_squared, Finding};
pub use params::{BuiltinTruck, TruckParams};
pub use simulate::{simulate, RunOptions, RunRecord};
pub use vehicle::{ModelOptions, TruckVehicle};
