//! Fiala off-road tire: handling forces, relaxation, vertical contact and terrain enveloping.
//!
//! Implements sections 2.2.1, 3.2.2 (Eqs 3.15-3.17) and 6.2.2 (Eqs 6.1-6.3, Table 6.2) of
//! the dissertation, plus the empirical off-road cornering laws of Eqs 1.3 and 1.4:
//!
//! - [`fiala`]: the ADAMS Fiala handling model (F_x, F_y, M_z, M_y) with load-dependent
//!   cornering stiffness; [`cornering`]: the linear model of Eq 3.15, the Table 6.2
//!   stiffness table and Eqs 1.3 / 1.4, all behind [`HandlingModel`];
//! - [`relaxation`]: first-order slip lag (Eqs 2.7, 3.16) as state derivatives;
//! - [`effective_track`]: the enveloping precomputed along a track for vehicle runs
//!   ([`TireTrack`]: at a reference or the instantaneous deflection);
//! - [`assembly`]: a vehicle's tires as one `vehicle_components::Component`
//!   ([`TireAssembly`]): their tracks, the vertical contact and a handling law (Chapter 2's
//!   linear cornering or Chapter 6's Fiala) with its lags, forces in world axes;
//! - [`vertical`]: point contact with lift-off (Eq 2.1) and a load-deflection table;
//! - [`terrain`] and [`envelope`]: the single-track [`Profile`] under a wheel (from any
//!   `vehicle_components::Terrain`) and the circle-line (Eqs 2.2-2.4) and tandem-cam
//!   (Eqs 6.1-6.3) effective contact.
//!
//! Axes and signs: ISO wheel axes (x forward, y left, z up); slip angle with the sign of
//! Eq 3.17 (`alpha = -atan(V_sy/|V_x|)`), so `F_y ≈ C_alpha alpha` is positive to the left;
//! aligning moment with the paper's sign (same as alpha). Details in `docs/tire-fiala.md`.
//!
//! ```
//! use tire_fiala::{Fiala, HandlingModel, TireParams};
//! let tire = Fiala::new(&TireParams::nominal()).unwrap();
//! let f = tire.forces(150e3, 0.0, 2f64.to_radians());
//! assert!(f.fy > 0.0 && f.fy < 0.8 * 150e3);
//! ```

pub mod assembly;
mod cams;
pub mod cornering;
pub mod effective_track;
pub mod envelope;
pub mod error;
pub mod fiala;
pub mod model;
mod on_demand;
pub mod params;
mod registry;
pub mod relaxation;
pub mod sampled;
mod table;
pub mod terrain;
pub mod vertical;

pub use assembly::{
    Contact, FialaLaw, HandlingLaw, LinearCorneringLaw, PathFrame, TireAssembly, TireContact,
    TireInput, TireOutput, Wheel, ROLLING_SIGN_SPEED_M_S,
};
pub use cornering::{
    CorneringStiffnessTable, ExponentialCornering, LinearCornering, TractionDependentCornering,
};
pub use effective_track::{EffectiveTrack, InstantaneousTrack, TireTrack, TrackContact};
pub use envelope::{EffectiveContact, Envelope, EnvelopeMethod, EnvelopedPoint};
pub use error::TireError;
pub use fiala::Fiala;
pub use model::{HandlingModel, TireForces};
pub use params::TireParams;
pub use relaxation::{
    contact_velocity_lag_rate, lag_rate, regularised_speed, slip_lag_rate, Relaxation,
    LOW_SPEED_REGULARISATION,
};
pub use sampled::SampledProfile;
pub use terrain::{PolylineProfile, Profile, Track};
pub use vertical::{LoadDeflectionTable, VerticalContact};
