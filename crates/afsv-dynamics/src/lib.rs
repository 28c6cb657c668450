//! Vehicle models of articulated frame-steered vehicles: the yaw-plane model of
//! Chapter 3 (Eqs 3.13-3.17, 4.1) coupled to the hydraulic frame steering of
//! `afs-hydraulics`, its inputs and path-following driver, and the analyses of
//! sections 3.3-3.4 and 4.3.1 (yaw-mode frequency/damping, step metrics, power
//! efficiency, sensitivity).
//!
//! The yaw-plane model lives in [`yaw_plane`]; its main types are re-exported here.
//! The steering-wheel signals ([`SteerInput`]) and the path-following driver
//! ([`PathDriver`] on a [`Course`]) live in the component layer (`vehicle-components`),
//! shared with the 3-D vehicle; they are re-exported here.
//!
//! Entry points: [`simulate`] (one manoeuvre -> [`YawRecord`]), [`yaw_measures`]
//! (the five measures at a speed for a load condition), [`sensitivity`].
//! Equation-to-code map and modelling choices: `docs/afs-yaw-plane.md`.

pub mod error;
pub mod yaw_plane;

pub use error::DynError;
pub use odeint::Solver;
pub use vehicle_components::{InputError, SteerInput};
pub use yaw_plane::actuator::{ActuatorOutput, EquivalentTorsion, SteeringActuator};
pub use yaw_plane::analysis::{
    measures_for, sensitivity, yaw_measures, MeasureSpec, SensitivityParam, SensitivityTable,
    YawMeasures,
};
pub use yaw_plane::driver::{table_3_2_speeds_kmh, Course, FieldCourse, PathDriver};
pub use yaw_plane::mechanics::EquationForm;
pub use yaw_plane::model::{SteerSource, YawPlaneModel};
pub use yaw_plane::params::{Load, VehicleParams, YawPlaneParams};
pub use yaw_plane::registry::{VEHICLE_PARAMS, YAW_PLANE_PARAMS};
pub use yaw_plane::simulate::{simulate, Manoeuvre, SimOptions, SolverStats, YawRecord};
