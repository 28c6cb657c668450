//! Small multibody core in minimal (joint) coordinates for ODE-integrated vehicle models,
//! after Featherstone, "Rigid Body Dynamics Algorithms", Springer 2008: spatial algebra
//! (chapter 2), kinematic trees (chapter 4), recursive Newton-Euler (Table 5.1), the
//! composite-rigid-body algorithm (section 6.2, evaluated in one frame per tree) and the
//! tree-sparse `L^T D L` factorisation of the mass matrix (section 6.5, Tables 6.3-6.4).
//!
//! Usage per ODE right-hand-side evaluation, with state `[q, v]`:
//!
//! ```
//! use multibody::{Body, Joint, ModelBuilder, Workspace};
//! use nalgebra::{Isometry3, Matrix3, Vector3};
//!
//! let mut builder = ModelBuilder::new(Vector3::new(0.0, 0.0, -9.81));
//! builder.add_body(Body {
//!     name: "chassis".into(),
//!     parent: None,
//!     joint: Joint::Floating,
//!     placement: Isometry3::identity(),
//!     mass: 1000.0,
//!     com: Vector3::zeros(),
//!     inertia: Matrix3::from_diagonal(&Vector3::new(400.0, 900.0, 1000.0)),
//! });
//! let model = builder.build()?;
//! let mut ws = Workspace::new(&model);
//! let q = model.neutral_configuration();
//! let v = vec![0.0; model.nv()];
//! multibody::update_kinematics(&model, &mut ws, q.as_slice(), &v)?;
//! ws.apply_force_world(0, &Vector3::new(0.0, 0.0, 9810.0), &Vector3::zeros());
//! let tau = vec![0.0; model.nv()];
//! let vdot = multibody::forward_dynamics(&model, &mut ws, &tau)?;
//! assert!(vdot.norm() < 1e-9);
//! let mut qdot = vec![0.0; model.nq()];
//! model.velocity_to_qdot(q.as_slice(), &v, &mut qdot);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod aba;
mod crba;
mod dynamics;
mod energy;
mod error;
mod inertia;
pub mod joint;
mod kinematics;
mod ltdl;
mod model;
pub mod spatial;
mod workspace;

pub use aba::forward_dynamics_aba;
pub use dynamics::{
    bias_forces, forward_dynamics, inverse_dynamics, mass_matrix, solve_mass_matrix,
};
pub use energy::{centre_of_mass, kinetic_energy, potential_energy, spatial_momentum};
pub use error::{DynamicsError, ModelError};
pub use joint::Joint;
pub use kinematics::{update_accelerations, update_kinematics};
pub use model::{Body, Model, ModelBuilder};
pub use spatial::SpatialTransform;
pub use workspace::Workspace;
