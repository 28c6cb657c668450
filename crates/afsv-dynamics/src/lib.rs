//! Vehicle models of articulated frame-steered vehicles: the yaw-plane model of
//! Chapter 3 (Eqs 3.13-3.17, 4.1) coupled to the hydraulic frame steering of
//! `afs-hydraulics`, its inputs and path-following driver, and the analyses of
//! sections 3.3-3.4 and 4.3.1 (yaw-mode frequency/damping, step metrics, power
//! efficiency, sensitivity).
//!
//! Entry points: [`simulate`] (one manoeuvre -> [`YawRecord`]), [`yaw_measures`]
//! (the five measures at a speed for a load condition), [`sensitivity`].
//! Equation-to-code map and modelling choices: `docs/afs-yaw-plane.md`.

pub mod actuator;
mod afs_coupling;
pub mod analysis;
pub mod driver;
pub mod error;
pub mod inputs;
pub mod mechanics;
pub mod model;
pub mod params;
pub mod simulate;

pub use actuator::{ActuatorOutput, EquivalentTorsion, SteeringActuator};
pub use analysis::{
    measures_for, sensitivity, yaw_measures, MeasureSpec, SensitivityParam, SensitivityTable,
    YawMeasures,
};
pub use driver::{table_3_2_speeds_kmh, Course, FieldCourse, PathDriver};
pub use error::DynError;
pub use inputs::SteerInput;
pub use mechanics::EquationForm;
pub use model::{SteerSource, YawPlaneModel};
pub use odeint::Solver;
pub use params::{Load, VehicleParams, YawPlaneParams};
pub use simulate::{simulate, Manoeuvre, SimOptions, SolverStats, YawRecord};
