//! Hydro-pneumatic suspension strut with gas-oil emulsion (Chapter 5, section 6.2.5).
//!
//! The strut has a piston-side chamber shared by gas and oil and an oil-filled annular
//! rod-side chamber, joined by bleed orifices, check valves (open in compression only) and
//! piston leakage. The model (Eqs 5.1-5.12 = 6.9-6.18) gives the strut force from both
//! chamber pressures and the seal friction; the emulsion's gas fraction, density and bulk
//! modulus follow the pressure.
//!
//! Sign convention (docs/records.md): deflection `z_s` positive in compression from the static
//! mid-stroke position, force positive when compressive, absolute pressures.
//!
//! - [`StrutParams`]: parameter sets ([`StrutParams::front_axle`], Table 6.3;
//!   [`StrutParams::lab`], the chapter 5 strut identified in [`lab`]).
//! - [`HpsStrut`]: the strut as a force element with its own states, one allocation-free
//!   evaluate, and a `vehicle_components::Component` ([`StrutMotion`] in, force out) for a
//!   vehicle model.
//! - [`simulate_displacement`]: prescribed-displacement runs (harmonic or sampled).
//! - [`mod@characterize`], [`lab_programme`], [`loop_metrics`]: the harmonic characterisation;
//!   [`HysteresisLoop`]: the samples of one period for the loop plots.
//! - [`mod@identify`]: least-squares identification from a record.
//! - [`HpsExtensions`]: switchable physical extensions for the model-discrepancy workflow;
//!   [`StrutLaws`]: the readings of ambiguous laws (calibration switches).
//! - [`interconnect`]: two struts cross-connected by hydraulic lines with accumulators (roll
//!   or pitch interconnection, `docs/layouts.md`).
//! - [`thermal`]: the loaded strut's gas and body temperatures over hours, the ride height
//!   they set, and a levelling valve (`docs/layouts.md`).
//!
//! See `docs/hps-emulsion.md` for the equation-to-code map and every modelling choice.

// Index loops over fixed-size arrays of channels read closest to the equations.
#![allow(clippy::needless_range_loop)]

pub mod characterize;
pub mod component;
pub mod emulsion;
pub mod error;
pub mod extensions;
pub mod fit_checks;
pub mod flow;
pub mod friction;
pub mod identify;
pub mod interconnect;
pub mod lab;
pub mod laws;
pub mod loops;
pub mod params;
pub mod registry;
pub mod simulate;
pub mod strut;
pub mod thermal;

pub use characterize::{
    characterize, front_axle_summary, lab_programme, loop_metrics, run_harmonic, summary,
    HarmonicTest, LoopMetrics, StrutSummary,
};
pub use component::StrutMotion;
pub use error::HpsError;
pub use extensions::{
    AsymmetricFriction, GasFractionGrowth, HeatTransfer, HpsExtensions, ValveLag,
};
pub use identify::{
    identify, ChannelNrmse, FitParam, FittedValue, IdentifyOptions, IdentifyResult, Measured,
};
pub use interconnect::{sealed_piston, CrossCoupledPair, HydraulicLine, LineEnd, LineParams};
pub use lab::{identify_lab, LabConfig, LabIdentification, LabReported};
pub use laws::{OrificeDensity, OrificeTransition, StrutLaws, LAMINAR_TRANSITION_PA};
pub use loops::HysteresisLoop;
pub use params::{FrictionParams, StrutParams};
pub use registry::STRUT_PARAMS;
pub use simulate::{
    simulate_displacement, simulate_strut, simulate_strut_from, Excitation, SimOptions, Solver,
    StrutRecord,
};
pub use strut::{ChamberCompliance, ChamberInflow, HpsStrut, StrutOutputs};
pub use thermal::{
    mean_dissipation_w, LevellingValve, ThermalConditions, ThermalParams, ThermalRecord,
    ThermalStrut,
};
