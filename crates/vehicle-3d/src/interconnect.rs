//! Roll interconnection of the two front struts (issue 23, `docs/layouts.md`,
//! "Interconnected struts"): the front-axle HPS with each strut's piston sealed and two
//! cross lines with accumulators ([`hps_emulsion::interconnect`]) joining the left strut's
//! piston side to the right strut's rod side and the mirror.
//!
//! [`LinkedVehicle`] extends a [`Vehicle`] built with the front-axle HPS: its state is the
//! vehicle's with the two accumulator gas volumes appended. The vehicle's right-hand side
//! gives everything (the strut forces depend on the chamber pressures, friction and travel,
//! not on the flow paths, so they are the vehicle's own); the struts' state rates are then
//! replaced by those of the interconnected pair, and the accumulators' rates appended. The
//! vehicle without a link is untouched: nothing here runs in its right-hand side. The
//! Rosenbrock-W method treats the two struts and both lines as one implicit block (the
//! lines couple the rod side of one strut to the other's piston side).

use hps_emulsion::interconnect::{sealed_piston, CrossCoupledPair, LineParams};
use hps_emulsion::HpsStrut;
use odeint::OdeSystem;
use serde::Serialize;
use vehicle_components::FlatTerrain;

use crate::error::{measure, rejected, VehicleError};
use crate::model::FrontAxle;
use crate::params::{Load, VehicleParams};
use crate::scenarios::{
    ride_measures, ride_options, ride_tracks, roll_measures, roll_options, roll_tracks,
    yaw_measures, yaw_options, RideMeasures, RideSpec, RollMeasures, RollSpec, YawMeasures,
    YawSpec, OUTPUT_DT_S, RUN_IN_M,
};
use crate::simulate::{simulate_system, typical, RunOptions, RunRecord};
use crate::tires::TireTracks;
use crate::vehicle::{Vehicle, VehicleOptions};
use std::sync::Arc;

/// Largest state count of one strut the pair block holds (the strut with every extension
/// has 5).
const MAX_STRUT_STATES: usize = 8;
/// Largest pair state: two struts and two lines.
const MAX_PAIR: usize = 2 * MAX_STRUT_STATES + 2;

/// A front-HPS vehicle with its front struts cross-connected (module docs).
#[derive(Debug)]
pub struct LinkedVehicle {
    vehicle: Vehicle,
    pair: CrossCoupledPair,
    carrier: [(usize, usize); 2],
    blocks: Vec<Vec<usize>>,
}

impl LinkedVehicle {
    /// Link the front struts of `vehicle` (built with [`FrontAxle::Suspended`]) by two lines
    /// of `line`: the struts become [`HpsStrut::ported`] with sealed pistons, their other
    /// parameters and extensions the vehicle's.
    pub fn new(vehicle: Vehicle, line: &LineParams) -> Result<Self, VehicleError> {
        let (Some(strut), Some(carrier)) = (vehicle.hps_strut(), vehicle.joints().carrier) else {
            return Err(rejected(
                "front_link",
                f64::NAN,
                "the roll interconnection needs the front-axle HPS",
            ));
        };
        let ported = HpsStrut::ported(&sealed_piston(strut.params()), strut.extensions())?;
        let n = ported.n_states();
        if n > MAX_STRUT_STATES {
            return Err(rejected("hps", n as f64, "too many strut states"));
        }
        let pair = CrossCoupledPair::new([ported.clone(), ported], line)?;
        let o = vehicle.offsets();
        let mut block: Vec<usize> = (o.hps..o.hps + 2 * n).collect();
        block.extend([o.dim, o.dim + 1]);
        // the pair first, then the vehicle's own blocks after its two front struts' (the
        // rear struts of a vehicle suspended on both axles)
        let mut blocks = vec![block];
        blocks.extend(vehicle.stiff_blocks().iter().skip(2).cloned());
        Ok(Self {
            vehicle,
            pair,
            carrier,
            blocks,
        })
    }

    /// The vehicle.
    pub fn vehicle(&self) -> &Vehicle {
        &self.vehicle
    }

    /// The interconnected strut pair.
    pub fn pair(&self) -> &CrossCoupledPair {
        &self.pair
    }

    /// The static state: the vehicle's (both struts at their static pressure) with both
    /// accumulators at that pressure.
    pub fn initial_state(&self) -> Result<Vec<f64>, VehicleError> {
        let mut y = self.vehicle.initial_state();
        let p_s = y[self.vehicle.offsets().hps + 1];
        if !p_s.is_finite() {
            return Err(rejected(
                "hps",
                p_s,
                "no static equilibrium of the front struts",
            ));
        }
        let v = self.pair.line().gas_volume_at(p_s)?;
        y.extend([v, v]);
        Ok(y)
    }

    /// The pair's state (left strut, right strut, both lines) gathered from `y`, and the
    /// struts' travels and rates.
    #[inline]
    fn gather(&self, y: &[f64], s: &mut [f64; MAX_PAIR]) -> ([f64; 2], [f64; 2], usize) {
        let o = self.vehicle.offsets();
        let n2 = 2 * o.hps_states;
        s[..n2].copy_from_slice(&y[o.hps..o.hps + n2]);
        s[n2..n2 + 2].copy_from_slice(&y[o.dim..o.dim + 2]);
        let z0 = self.vehicle.hps_static_travel_m();
        let z = self.carrier.map(|(qi, _)| z0 + y[o.q + qi]);
        let zdot = self.carrier.map(|(_, vi)| y[o.v + vi]);
        (z, zdot, n2 + 2)
    }

    /// Run from `y0` (the state of [`LinkedVehicle::initial_state`], perhaps perturbed),
    /// recorded as the vehicle's run with the two lines' node pressures.
    pub fn simulate_from(
        &self,
        y0: &[f64],
        options: &RunOptions,
    ) -> Result<LinkedRun, VehicleError> {
        let dim = self.vehicle.offsets().dim;
        let mut t = typical(&self.vehicle);
        let v = y0[dim];
        t.extend([v, v]);
        let line = self.pair.line();
        let mut node = [Vec::new(), Vec::new()];
        let record = simulate_system(&self.vehicle, self, y0, t, options, |y| {
            for (k, ch) in node.iter_mut().enumerate() {
                ch.push(line.pressure(y[dim + k]));
            }
        })?;
        Ok(LinkedRun {
            record,
            node_pressure_pa: node,
        })
    }
}

impl OdeSystem for LinkedVehicle {
    fn dim(&self) -> usize {
        self.vehicle.offsets().dim + 2
    }

    fn rhs(&self, t: f64, y: &[f64], dydt: &mut [f64]) {
        let o = *self.vehicle.offsets();
        self.vehicle.rhs(t, &y[..o.dim], &mut dydt[..o.dim]);
        let mut s = [0.0; MAX_PAIR];
        let mut d = [0.0; MAX_PAIR];
        let (z, zdot, m) = self.gather(y, &mut s);
        self.pair.evaluate(z, zdot, &s[..m], &mut d[..m]);
        let n2 = m - 2;
        dydt[o.hps..o.hps + n2].copy_from_slice(&d[..n2]);
        dydt[o.dim..o.dim + 2].copy_from_slice(&d[n2..m]);
        if dydt[..o.dim].iter().any(|v| v.is_nan()) {
            dydt.fill(f64::NAN);
        }
    }

    fn stiff_blocks(&self) -> &[Vec<usize>] {
        &self.blocks
    }

    /// The pair block's Jacobian by forward differences of the pair's evaluate with the
    /// struts' travels and rates held; a rear strut's block is the vehicle's own.
    fn block_jacobian(&self, t: f64, y: &[f64], block: usize, jac: &mut [f64]) -> bool {
        if block != 0 {
            let dim = self.vehicle.offsets().dim;
            return block < self.blocks.len()
                && self.vehicle.block_jacobian(t, &y[..dim], block + 1, jac);
        }
        let mut s = [0.0; MAX_PAIR];
        let (z, zdot, m) = self.gather(y, &mut s);
        let (mut f0, mut f1) = ([0.0; MAX_PAIR], [0.0; MAX_PAIR]);
        self.pair.evaluate(z, zdot, &s[..m], &mut f0[..m]);
        let strut = &self.pair.struts()[0];
        let n = strut.n_states();
        for c in 0..m {
            let typical = if c < 2 * n {
                strut.state_typical(c % n)
            } else {
                s[c].abs()
            };
            let base = s[c];
            let h = f64::EPSILON.sqrt() * base.abs().max(typical);
            s[c] = base + h;
            self.pair.evaluate(z, zdot, &s[..m], &mut f1[..m]);
            s[c] = base;
            for r in 0..m {
                jac[r * m + c] = (f1[r] - f0[r]) / h;
            }
        }
        true
    }
}

/// A run of the linked vehicle.
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct LinkedRun {
    /// The vehicle's record ([`crate::simulate`]).
    pub record: RunRecord,
    /// Node (accumulator) pressure of line 0 (left piston side to right rod side) and line
    /// 1 (the mirror) at each sample (Pa).
    pub node_pressure_pa: [Vec<f64>; 2],
}

/// D1 (section 6.4) with the front struts interconnected by `line`: the record and its
/// measures, on the terrain of `seed` (the same tracks as [`crate::scenarios::ride`]).
pub fn ride_linked(
    p: &VehicleParams,
    spec: &RideSpec,
    seed: u64,
    line: &LineParams,
) -> Result<(LinkedRun, RideMeasures), VehicleError> {
    ride_linked_on(p, spec, ride_tracks(p, spec, seed)?, line)
}

/// [`ride_linked`] on the enveloping cache `tracks` of [`crate::scenarios::ride_tracks`]
/// (shared with the runs of other layouts on the same seed and load).
pub fn ride_linked_on(
    p: &VehicleParams,
    spec: &RideSpec,
    tracks: Arc<TireTracks>,
    line: &LineParams,
) -> Result<(LinkedRun, RideMeasures), VehicleError> {
    let speed = spec.speed_kmh / 3.6;
    let v = Vehicle::on_tracks(p, spec.load, ride_options(spec), tracks)?;
    let linked = LinkedVehicle::new(v, line)?;
    let rec = linked.simulate_from(
        &linked.initial_state()?,
        &RunOptions {
            t_end_s: (RUN_IN_M + spec.length_m) / speed,
            output_dt_s: OUTPUT_DT_S,
            ..RunOptions::default()
        },
    )?;
    let m = ride_measures(&rec.record, RUN_IN_M / speed, spec.front_axle)?;
    Ok((rec, m))
}

/// D2 (section 6.4) to rollover with the front struts interconnected by `line`.
pub fn roll_linked(
    p: &VehicleParams,
    spec: &RollSpec,
    seed: u64,
    line: &LineParams,
) -> Result<(LinkedRun, RollMeasures), VehicleError> {
    roll_linked_on(p, spec, roll_tracks(p, spec, seed)?, line)
}

/// [`roll_linked`] on the enveloping cache `tracks` of [`crate::scenarios::roll_tracks`].
pub fn roll_linked_on(
    p: &VehicleParams,
    spec: &RollSpec,
    tracks: Arc<TireTracks>,
    line: &LineParams,
) -> Result<(LinkedRun, RollMeasures), VehicleError> {
    let v = Vehicle::on_tracks(p, spec.load, roll_options(spec), tracks)?;
    let linked = LinkedVehicle::new(v, line)?;
    let rec = linked.simulate_from(
        &linked.initial_state()?,
        &RunOptions {
            t_end_s: spec.t_end_s,
            output_dt_s: 0.01,
            stop_at_rollover: true,
            ..RunOptions::default()
        },
    )?;
    let m = roll_measures(&rec.record)?;
    Ok((rec, m))
}

/// D3 (section 6.4, smooth ground) with the front struts interconnected by `line`: the
/// yaw-mode run of [`crate::scenarios::yaw`] (its terrain must be smooth).
pub fn yaw_linked(
    p: &VehicleParams,
    spec: &YawSpec,
    line: &LineParams,
) -> Result<(LinkedRun, YawMeasures), VehicleError> {
    if spec.terrain.is_some() {
        return Err(measure(
            "yaw_linked",
            "the linked D3 runs on smooth ground only",
        ));
    }
    let flat = FlatTerrain::new(0.0, vehicle_components::DEFAULT_FRICTION)
        .map_err(|e| measure("terrain", e))?;
    let v = Vehicle::new(
        p,
        spec.load,
        yaw_options(spec)?,
        &flat,
        0.5 * p.front_track_m,
    )?;
    let linked = LinkedVehicle::new(v, line)?;
    let rec = linked.simulate_from(
        &linked.initial_state()?,
        &RunOptions {
            t_end_s: spec.t_end_s,
            output_dt_s: OUTPUT_DT_S,
            ..RunOptions::default()
        },
    )?;
    let m = yaw_measures(
        &rec.record,
        spec.pulse_start_s + spec.pulse_s,
        spec.fit_window_s,
    )?;
    Ok((rec, m))
}

/// Suspension roll angle of the front unit over its axle (rad) at each sample of `rec`:
/// `(z_L - z_R) / t_f` from the strut travels (compression positive) and the front track.
pub fn suspension_roll_rad(p: &VehicleParams, rec: &RunRecord) -> Vec<f64> {
    rec.hps_travel_m[0]
        .iter()
        .zip(&rec.hps_travel_m[1])
        .map(|(l, r)| (l - r) / p.front_track_m)
        .collect()
}

/// How the front unit is set moving for a free response.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Kick {
    /// A roll rate of the front unit (rad/s).
    Roll,
    /// A vertical velocity of the front unit (m/s).
    Bounce,
}

/// The free response of the loaded front-HPS vehicle (linked by `line`, or plain) rolling
/// at 20 km/h on smooth ground for `t_end_s`, released from its static state with the
/// front unit's roll rate (rad/s) or vertical velocity (m/s) raised by `size`.
pub fn free_response(
    p: &VehicleParams,
    line: Option<&LineParams>,
    kick: Kick,
    size: f64,
    t_end_s: f64,
) -> Result<RunRecord, VehicleError> {
    let options = VehicleOptions {
        front_axle: FrontAxle::Suspended,
        path_length_m: 20.0 / 3.6 * t_end_s + 5.0,
        ..VehicleOptions::default()
    };
    let flat = FlatTerrain::new(0.0, vehicle_components::DEFAULT_FRICTION)
        .map_err(|e| measure("terrain", e))?;
    let v = Vehicle::new(p, Load::Loaded, options, &flat, 0.5 * p.front_track_m)?;
    let o = *v.offsets();
    let run = RunOptions {
        t_end_s,
        output_dt_s: 0.01,
        ..RunOptions::default()
    };
    // the floating base's velocity is (angular, linear) in body axes
    let at = match kick {
        Kick::Roll => o.v,
        Kick::Bounce => o.v + 5,
    };
    match line {
        Some(l) => {
            let linked = LinkedVehicle::new(v, l)?;
            let mut y0 = linked.initial_state()?;
            y0[at] += size;
            Ok(linked.simulate_from(&y0, &run)?.record)
        }
        None => {
            let mut y0 = v.initial_state();
            y0[at] += size;
            simulate_system(&v, &v, &y0, typical(&v), &run, |_| {})
        }
    }
}

#[cfg(test)]
mod tests;
