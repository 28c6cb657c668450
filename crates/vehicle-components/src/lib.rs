//! The component layer shared by the subsystem crates and the vehicle models, after the
//! Chrono::Vehicle templates (`ChTerrain`, `ChTire`, `ChSuspension`) but in plain-data,
//! pure-function style: components own no hidden state and allocate nothing in their
//! right-hand sides.
//!
//! - [`terrain`]: [`Terrain`] (height, unit normal, friction at (x, y); x forward, y left,
//!   z up, SI) and [`FlatTerrain`];
//! - [`component`]: the [`Component`] trait (named states with units and typical
//!   magnitudes, initial state, allocation-free `evaluate(input, state, d_state) -> output`,
//!   record channels);
//! - [`layout`]: [`StateLayout`], contiguous blocks of one global state vector;
//! - [`recorder`]: [`Channels`] declared from components and the bounded, column-major
//!   [`Recorder`];
//! - [`params`]: [`ParamSet`] / [`ParamSpec`], parameters by name with bounds;
//! - [`cab_seat`]: [`CabSeat`], the cab on elastomer mounts with the operator's suspension
//!   seat, driven by the frame's motion (`docs/layouts.md`);
//! - [`inputs`]: the steering-wheel inputs [`SteerInput`] (section 3.3) and
//!   [`path_driver`]: the pure-pursuit [`PathDriver`] on a [`Course`] (section 3.4.1), the
//!   driver inputs every vehicle model shares.
//!
//! Details and conventions: `docs/vehicle-components.md`.
//!
//! ```
//! use vehicle_components::{FlatTerrain, Terrain, DEFAULT_FRICTION};
//! let ground = FlatTerrain::new(0.0, DEFAULT_FRICTION).unwrap();
//! assert_eq!(ground.normal(10.0, -2.0), [0.0, 0.0, 1.0]);
//! ```

pub mod cab_seat;
pub mod component;
pub mod error;
pub mod inputs;
pub mod layout;
pub mod params;
pub mod path_driver;
pub mod recorder;
pub mod sampled;
pub mod terrain;

pub use cab_seat::{CabMount, CabParams, CabSeat, CabSeatOutput, Cushion, FrameMotion, SeatParams};
pub use component::{ChannelInfo, Component, StateInfo};
pub use error::{ComponentError, ParamError};
pub use inputs::{InputError, SteerInput};
pub use layout::{BlockId, StateLayout, MAX_STATES};
pub use params::{check_specs, within_ranges, ParamSet, ParamSpec};
pub use path_driver::{Course, PathDriver};
pub use recorder::{Channels, Recorder, MAX_CELLS, MAX_ROWS};
pub use terrain::{
    gradient_normal, FlatTerrain, Terrain, TerrainPoint, DEFAULT_FRICTION, NORMAL_STEP_M,
};
