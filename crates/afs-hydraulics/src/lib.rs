//! Hydraulic articulated frame steering (AFS) component: strut kinematics, steering valve
//! with gerotor feedback, fluid continuity with leakage, seal friction, strut forces and the
//! steering torque about the articulation joint (Chapter 3.2.1, Chapter 4.2, Eqs 6.6-6.8).
//!
//! The component has a narrow interface so any vehicle model can use it: the vehicle gives
//! the articulation angle, its rate and the steering-wheel angle ([`AfsInput`]); the
//! component owns three states (P_c, P_r, theta_h) and returns their derivatives plus the
//! torque, strut forces, flows and powers ([`AfsOutput`]).
//!
//! Underneath is the strut-space core ([`AfsSystem::strut_derivatives`], Eqs 6.6-6.8): it
//! takes the two struts' extensions and extension rates ([`StrutInput`]) and returns their
//! axial forces ([`StrutOutput`]), so a 3-D vehicle that computes strut lengths from its mount
//! points uses the same hydraulics; the planar evaluate is an adapter over it.
//!
//! Sign convention (docs/records.md): positive steering-wheel angle and articulation are the
//! paper's right-hand turn, in which the valve feeds the P_c group (left-strut piston side +
//! right-strut rod side) and the left strut extends. A positive torque drives theta
//! positive. See `docs/afs-hydraulics.md` for the derivation and the unit choices.

mod component;
mod error;
pub mod extensions;
pub mod fluid;
pub mod kinematics;
pub mod params;
pub mod registry;
pub mod sensor;
mod strut_space;
mod system;
pub mod valve;

pub use error::AfsError;
pub use extensions::{AfsExtensions, CoulombFriction, EntrainedAir, SupplyDroop, ValveLag};
pub use kinematics::{strut_kinematics, StrutKinematics};
pub use params::AfsParams;
pub use registry::AFS_PARAMS;
pub use sensor::backlash;
pub use strut_space::{StrutInput, StrutOutput};
pub use system::{AfsInput, AfsOutput, AfsSystem};
