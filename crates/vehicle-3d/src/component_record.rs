//! Every component's own record channels along a run: the steering hydraulics
//! ([`afs_hydraulics::AfsSystem`]: strut forces, chamber pressures, supply and leakage
//! flows, valve opening, powers) and each axle strut ([`hps_emulsion::HpsStrut`]: force,
//! chamber pressures, friction, spring force, gas volume, orifice flow, velocity
//! amplitude), named by the component layer's [`Channels`] and kept in a [`Recorder`].
//!
//! The [`crate::RunRecord`] holds what the measures and the `afsv-v1` record read; this is
//! the rest of what the components compute, for a user who wants to look inside the
//! hydraulics (a strut's gas volume through a ride, the steering's supply power in a path
//! change). Each sample re-evaluates the components at the recorded state with the inputs
//! the run gave them (the struts' lengths and rates from the kinematics, the carriers'
//! travel and rate), so the values are the run's own (tested against the run record).
//!
//! Names: `time_s`, then `steering_<channel>`, then `hps_<axle>_<side>_<channel>` for each
//! suspended axle (`front`, `rear`; `left`, `right`).

use multibody::Workspace;
use vehicle_components::{Channels, Component, Recorder};
use vehicle_run::RunSettings;

use crate::error::VehicleError;
use crate::simulate::{initial_run, simulate_system, RunOptions, RunRecord};
use crate::vehicle::{Vehicle, MAX_DIM};

/// Most channels one row holds: time, the steering's and four struts'.
const MAX_CHANNELS: usize = 64;

/// The component channels of `vehicle`, in column order (module docs).
pub fn component_channels(vehicle: &Vehicle) -> Result<Channels, VehicleError> {
    let mut ch = Channels::new();
    ch.push("time_s", "s")?;
    ch.extend("steering", Component::channels(vehicle.steering()))?;
    for (axle, struts) in ["front", "rear"].into_iter().zip(vehicle.axle_struts()) {
        if let Some(s) = struts {
            for side in ["left", "right"] {
                ch.extend(&format!("hps_{axle}_{side}"), Component::channels(&s.strut))?;
            }
        }
    }
    Ok(ch)
}

impl Vehicle {
    /// One row of [`component_channels`] at `(t, y)`, with the kinematics of `y` in `ws`
    /// (positions and velocities, as [`multibody::update_kinematics`] leaves them).
    fn component_row(&self, t: f64, y: &[f64], ws: &Workspace, row: &mut [f64]) {
        let o = self.offsets;
        let mut scratch = [0.0; MAX_DIM];
        row[0] = t;
        let (_, input) = self.steering_input(t, y, ws);
        let afs = self.steering();
        let n = Component::channels(afs).len();
        let out = Component::evaluate(
            afs,
            &input,
            &y[o.afs..o.tires],
            &mut scratch[..o.tires - o.afs],
        );
        Component::record(afs, &out, &mut row[1..1 + n]);
        let mut at = 1 + n;
        for struts in self.axle_struts().into_iter().flatten() {
            let n = Component::channels(&struts.strut).len();
            for side in 0..2 {
                let states = struts.n_states();
                let (_, _, out) = struts.evaluate(y, o.v, side, &mut scratch[..states]);
                Component::record(&struts.strut, &out, &mut row[at..at + n]);
                at += n;
            }
        }
    }
}

/// [`crate::simulate()`] that also records every component's channels at each output
/// sample (module docs): the run's record, bit for bit [`crate::simulate()`]'s, and the
/// components' [`Recorder`].
pub fn simulate_components(
    vehicle: &Vehicle,
    options: &RunOptions,
) -> Result<(RunRecord, Recorder), VehicleError> {
    let samples = options.validate()?;
    let channels = component_channels(vehicle)?;
    let width = channels.len();
    if width > MAX_CHANNELS {
        return Err(VehicleError::Measure {
            measure: "component channels",
            reason: format!("{width} channels, at most {MAX_CHANNELS}"),
        });
    }
    // the output grid, and one more for the rollover event's sample
    let mut rec = Recorder::with_capacity(channels, samples + 1)?;
    let mut failed: Option<VehicleError> = None;
    let mut row = [0.0; MAX_CHANNELS];
    let o = vehicle.offsets;
    let (y0, typical) = initial_run(vehicle)?;
    let record = simulate_system(vehicle, vehicle, &y0, typical, options, |t, y| {
        if failed.is_some() {
            return;
        }
        let mut ws = vehicle.ws.borrow_mut();
        let kinematics =
            multibody::update_kinematics(&vehicle.model, &mut ws, &y[o.q..o.v], &y[o.v..o.afs]);
        failed = match kinematics {
            Ok(()) => {
                vehicle.component_row(t, y, &ws, &mut row[..width]);
                rec.push(&row[..width]).err().map(VehicleError::from)
            }
            Err(source) => Some(VehicleError::Dynamics { t, source }),
        };
    })?;
    match failed {
        Some(e) => Err(e),
        None => Ok((record, rec)),
    }
}
