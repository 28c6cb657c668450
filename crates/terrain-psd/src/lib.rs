//! Terrain displacement PSD models, two-track synthesis with coherence, and spectral
//! estimators (Chapter 2.2.2 and section 6.2.3 of the dissertation).
//!
//! - [`psd`]: power-law PSD `G_d(n) = alpha_r n^-w` (Eq 2.8), ISO 8608 classes A-H
//!   (Eq 1.6, Table 2.4), off-road terrains of Tables 1.2 / 2.4, spatial band.
//! - [`coherence`]: left/right coherence models: piecewise linear (Eq 2.10 / 6.5), Bogsjö
//!   (Eq 1.9), Zhang (Eq 1.8), fully coherent, independent.
//! - [`synth`]: random-phase spectral synthesis of two tracks whose expected PSDs and coherence
//!   equal the targets on every synthesized line (replaces the third-order filters of Fig 2.4).
//! - [`spectral`]: Welch PSD, cross-spectral density, magnitude-squared coherence (Eq 2.9),
//!   cross-slope (roll excitation) PSD of Fig 2.7.
//! - [`summary`]: measured-vs-target summary of the nominal terrain for `afsv evaluate`.
//! - [`surface`]: a two-track profile laid out on the ground plane as a
//!   `vehicle_components::Terrain` ([`TwoTrackTerrain`], [`SurfaceParams`]).
//! - [`opencrg`]: a measured road in the ASAM OpenCRG format (regular-grid ASCII, straight
//!   reference line) read as the two wheel tracks of a [`TwoTrackProfile`].
//! - `registry`: the synthesis spec and the surface parameters by name
//!   (`vehicle_components::ParamSet`, names in `docs/terrain-psd.md`).
//!
//! Units: elevations in m, spatial frequency `n` in cycles/m, PSDs in m^2/(cycle/m) = m^3.
//! Nothing here panics on bad input: constructors and functions return [`TerrainError`].
//!
//! ```
//! use terrain_psd::{synthesize, TwoTrackSpec, WelchConfig, cross_spectrum};
//! let spec = TwoTrackSpec::paper_nominal(); // class E, 0.02-5 cycles/m, m_c = 0.3
//! let prof = synthesize(&spec, 100.0, 0.05, 1).unwrap();
//! assert_eq!(prof.len(), 2001);
//! let cs = cross_spectrum(&prof.left_m, &prof.right_m, 0.05, &WelchConfig::new(512)).unwrap();
//! assert_eq!(cs.freq.len(), 257);
//! ```

pub mod coherence;
pub mod error;
mod fft;
pub mod opencrg;
pub mod psd;
mod registry;
pub mod spectral;
pub mod summary;
pub mod surface;
pub mod synth;

pub use coherence::CoherenceModel;
pub use error::{Result, TerrainError};
pub use opencrg::{read_crg, CrgRoad};
pub use psd::{Band, IsoClass, OffRoadTerrain, PowerLawPsd};
pub use spectral::{
    cross_slope_psd, cross_spectrum, welch_psd, CrossSpectrum, Detrend, Spectrum, WelchConfig,
    Window,
};
pub use summary::{
    default_terrain_summary, terrain_summary, Criterion, Fidelity, Summary, SummaryConfig,
};
pub use surface::{SurfaceParams, TwoTrackTerrain};
pub use synth::{synthesize, synthesize_track, uniform_spacing, TwoTrackProfile, TwoTrackSpec};
