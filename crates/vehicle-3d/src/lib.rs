//! The integrated 3-D articulated frame-steered vehicle of Chapter 6: the 35 t articulated
//! mining dump truck with hydraulic frame steering (Chapter 3, Eqs 6.6-6.8), optional
//! front-axle hydro-pneumatic suspension (Chapter 5, Eqs 6.9-6.18) and Fiala tires with
//! tandem-cam enveloping on two-track terrain (Eqs 6.1-6.5, Table 6.2), on the multibody
//! core in minimal coordinates.
//!
//! - [`params`]: Table 6.1 and every documented assumption, [`registry`]: the same by name;
//!   [`statics`]: the hand tire loads; [`model`]: the tree (14 DOF, 16 with the front
//!   HPS, 18 with HPS on both axles; 4 more with the rear bogie);
//! - [`steering`]: the struts between their 3-D mounts; [`tires`]: the tires' cached
//!   tracks (evaluated by `tire_fiala::TireAssembly`, Fiala law); [`vehicle`]: the ODE system; [`simulate`](mod@simulate): a recorded run;
//!   [`channels`]: its channels in the record convention `afsv-v1`;
//!   [`component_record`]: every component's own channels along a run (a `Recorder`);
//! - [`scenarios`]: the design runs D1 (ride), D2 (roll), D3 (yaw) and their measures;
//!   [`path_change`](mod@path_change): the V3 path change (section 6.3) with the
//!   path-following driver (re-exported by `scenarios`);
//!   [`yaw_mode`]: which addition of the 3-D model moves the yaw mode;
//! - [`bogie`]: the rear walking-beam bogie (a tandem, one beam and strut per side);
//! - [`suspension`]: HPS struts on any axle (the rear strut's default, static travel,
//!   stored energy);
//! - [`cab_ride`]: the cab on mounts and the suspension seat driven by a ride run's frame
//!   motion: a_wz on the frame and at the seat, SEAT (`docs/layouts.md`);
//! - [`interconnect`]: the front struts roll-interconnected by hydraulic lines
//!   (`docs/layouts.md`).
//!
//! Model notes: `docs/vehicle-3d.md`.

pub mod bogie;
pub mod cab_ride;
pub mod channels;
pub mod component_record;
pub mod error;
pub mod field;
pub mod interconnect;
pub mod model;
pub mod params;
pub mod path_change;
pub mod registry;
pub mod scenarios;
pub mod simulate;
mod state_layout;
pub mod statics;
pub mod steering;
mod stiff_block;
pub mod suspension;
pub mod tires;
pub mod vehicle;
pub mod yaw_mode;

pub use bogie::BogieParams;
pub use error::VehicleError;
pub use field::{FieldEffects, SpeedSetpoint};
pub use model::FrontAxle;
pub use params::{DriveParams, Load, RigidPart, VehicleParams, YawInertiaForm};
pub use simulate::{simulate, RunOptions, RunRecord};
pub use statics::Statics;
pub use tires::{CamSpacing, TireTracks};
pub use vehicle::{Vehicle, VehicleOptions};
