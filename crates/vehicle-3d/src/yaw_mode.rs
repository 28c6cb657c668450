//! Which of the 3-D model's additions moves the yaw mode (the analysis of
//! `docs/vehicle-3d.md`, "Yaw mode"): the D3 pulse on smooth ground with one change at a
//! time against the nominal 3-D vehicle.
//!
//! The yaw-plane model of Chapter 3 gives 5.51 Hz (energy-consistent equations) or 3.04 Hz
//! (Eq 3.13 as printed); Chapter 6 reports 2.81 Hz for its 3-D model. The candidates the
//! 3-D model adds are the rear unit's roll freedom, the tires' vertical compliance, their
//! lateral compliance (the relaxation length: 1.2 m in Table 6.2, 0.4 m in Chapter 3), and
//! the strut geometry (3-D mounts; identical to the planar layout by construction at the
//! default mounts, `model::tests`).

use rayon::prelude::*;
use serde::Serialize;

use crate::error::VehicleError;
use crate::model::FrontAxle;
use crate::params::VehicleParams;
use crate::scenarios::{yaw, YawMeasures, YawSpec};

/// One variant of the analysis.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct YawModeVariant {
    /// What was changed.
    pub change: &'static str,
    /// The D3 measures with the change.
    pub measures: YawMeasures,
}

/// Multiplier of the tire load-deflection curve that makes the tires vertically rigid.
pub const RIGID_TIRE_FACTOR: f64 = 20.0;

/// The D3 pulse (unsuspended, loaded, smooth ground) for the nominal vehicle and each
/// change of the module docs, in parallel.
pub fn yaw_mode_analysis(p: &VehicleParams) -> Result<Vec<YawModeVariant>, VehicleError> {
    let spec = YawSpec::d3(FrontAxle::Rigid);
    let mut variants: Vec<(&'static str, VehicleParams, bool)> =
        vec![("nominal 3-D vehicle", p.clone(), false)];
    variants.push(("rear-unit roll locked", p.clone(), true));
    let mut stiff = p.clone();
    for row in &mut stiff.tire.load_deflection {
        row[1] *= RIGID_TIRE_FACTOR;
    }
    variants.push(("tires vertically 20x stiffer", stiff, false));
    let mut short = p.clone();
    short.tire.lateral_relaxation_length_m = 0.4;
    short.tire.longitudinal_relaxation_length_m = 0.4;
    variants.push(("relaxation length 0.4 m (Chapter 3)", short, false));
    let mut long = p.clone();
    long.tire.lateral_relaxation_length_m = 3.6;
    long.tire.longitudinal_relaxation_length_m = 3.6;
    variants.push(("relaxation length 3.6 m (3x Table 6.2)", long, false));
    let mut soft = p.clone();
    soft.steering.bulk_modulus_pa *= 0.25;
    variants.push((
        "steering oil bulk modulus / 4 (not a 3-D addition)",
        soft,
        false,
    ));
    variants
        .into_par_iter()
        .map(|(change, params, lock)| {
            let spec = YawSpec {
                lock_rear_roll: lock,
                ..spec
            };
            yaw(&params, &spec, 0).map(|(_, measures)| YawModeVariant { change, measures })
        })
        .collect()
}
