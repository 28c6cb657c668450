//! `afsv yaw leakage`: the leakage effects of the steering circuit on the yaw-plane vehicle
//! (section 3.4.1, Fig 4.7): the decay of the articulation in a steady turn at the Table 3.2
//! speeds, both loads, and the correlation of steering gain and power efficiency over a
//! leakage sweep (loaded, 50 km/h).

use afsv_dynamics::yaw_plane::analysis::{
    gain_efficiency_correlation_of, steady_turn_decay_of, GainEfficiency, MeasureSpec,
    SteadyTurnDecay,
};
use afsv_dynamics::{DynError, Load, SimOptions};
use afsv_vehicle::ArticulatedVehicle;
use serde::Serialize;

/// The leakage analyses of one vehicle.
#[derive(Serialize)]
pub struct Leakage {
    /// The steady-turn articulation decay per load case and Table 3.2 speed.
    pub steady_turn_decay: Vec<SteadyTurnDecay>,
    /// Steering gain against power efficiency over a leakage sweep (Fig 4.7).
    pub gain_efficiency_fig_4_7: GainEfficiency,
}

/// The leakage analyses of the yaw-plane data of `d` with the steering wheel held at
/// `steer_wheel_deg` (deg) for the steady turns (10 s each).
pub fn leakage(d: &ArticulatedVehicle, steer_wheel_deg: f64) -> Result<Leakage, DynError> {
    let of = |load: Load| d.yaw_plane_params(load);
    let opts = SimOptions::default();
    let mut decay = Vec::new();
    for load in Load::ALL {
        for &v in afsv_dynamics::table_3_2_speeds_kmh(afsv_dynamics::FieldCourse::SteadyTurn, load)
        {
            decay.push(steady_turn_decay_of(
                &of(load),
                load,
                v / 3.6,
                steer_wheel_deg,
                10.0,
                &opts,
            )?);
        }
    }
    let ge =
        gain_efficiency_correlation_of(&of(Load::Loaded), 50.0 / 3.6, &MeasureSpec::default())?;
    Ok(Leakage {
        steady_turn_decay: decay,
        gain_efficiency_fig_4_7: ge,
    })
}
