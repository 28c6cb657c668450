//! The yaw-plane articulated vehicle of Chapter 3 (Eqs 3.13-3.17, 4.1): two rigid units
//! joined at the articulation joint, linear tires with slip lag, and the frame-steering
//! actuator seam, with its manoeuvres, path-following driver and the analyses of
//! sections 3.3-3.4 and 4.3.1.
//!
//! | module | what |
//! |---|---|
//! | [`params`] | Table 3.1 vehicle columns, the whole yaw-plane set, load conditions |
//! | [`registry`] | the named parameters of both sets |
//! | [`mechanics`] | Eq 3.13 (both forms), tire forces Eqs 3.15-3.17 |
//! | [`actuator`] | the articulation-actuator seam (`SteeringActuator`) and the torsion idealisation |
//! | [`model`] | the coupled first-order model (`YawPlaneModel`) and its state layout |
//! | [`simulate`] | manoeuvres, integration and the record (`YawRecord`) |
//! | [`driver`] | the path-following driver and the field courses (Table 3.2) |
//! | [`analysis`] | yaw-mode frequency and damping, step metrics, power efficiency, sensitivity |

pub mod actuator;
mod afs_coupling;
pub mod analysis;
pub mod driver;
pub mod mechanics;
pub mod model;
pub mod params;
pub mod registry;
pub mod simulate;
