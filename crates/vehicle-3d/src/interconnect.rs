//! Hydraulic interconnection of the 3-D vehicle's struts (issue 23, `docs/layouts.md`,
//! "Interconnected struts" and "Pitch interconnection"): struts with sealed pistons joined
//! in cross-coupled pairs by two lines with accumulators each
//! ([`hps_emulsion::interconnect`]), a line joining one strut's piston side to the other's
//! rod side.
//!
//! - [`Link::Roll`]: the two front struts (left-right), one pair.
//! - [`Link::Pitch`]: on each side the front and the rear strut (front-rear), two pairs; the
//!   vehicle has struts on both axles.
//!
//! [`LinkedVehicle`] extends a [`Vehicle`] with suspended axles: its state is the vehicle's
//! with each pair's two accumulator gas volumes appended. The vehicle's right-hand side
//! gives everything (the strut forces depend on the chamber pressures, friction and travel,
//! not on the flow paths, so they are the vehicle's own); the linked struts' state rates
//! are then replaced by those of their pair, and the accumulators' rates appended. The
//! vehicle without a link is untouched: nothing here runs in its right-hand side. The
//! Rosenbrock-W method treats each pair's two struts and two lines as one implicit block
//! (the lines couple the rod side of one strut to the other's piston side); a strut outside
//! every pair keeps its own block.

use hps_emulsion::interconnect::{sealed_piston, CrossCoupledPair, LineParams};
use hps_emulsion::HpsStrut;
use odeint::OdeSystem;
use serde::{Deserialize, Serialize};
use vehicle_components::FlatTerrain;

use crate::error::{measure, rejected, VehicleError};
use crate::model::FrontAxle;
use crate::params::{Load, VehicleParams};
use crate::scenarios::{
    ride_measures, ride_options, ride_tracks, roll_measures, roll_options, roll_tracks,
    yaw_measures, yaw_options, RideMeasures, RideSpec, RollMeasures, RollSpec, YawMeasures,
    YawSpec, OUTPUT_DT_S, RUN_IN_M,
};
use crate::simulate::{simulate_system, RunOptions, RunRecord};
use crate::suspension::AxleStruts;
use crate::tires::TireTracks;
use crate::vehicle::{Vehicle, VehicleOptions};
use std::sync::Arc;

/// Largest state count of one strut a pair block holds (the strut with every extension
/// has 5).
const MAX_STRUT_STATES: usize = 8;
/// Largest pair state: two struts and two lines.
const MAX_PAIR: usize = 2 * MAX_STRUT_STATES + 2;

/// Which struts are interconnected, and by which lines.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub enum Link {
    /// The two front struts, left-right: one line design for both lines
    /// ([`LineParams::front_axle_roll`]).
    Roll(LineParams),
    /// On each side the front and the rear strut: `[the line at the front strut's piston
    /// side, the line at the rear strut's piston side]`, both sides alike
    /// ([`LineParams::side_pitch`], [`Link::pitch_of`]).
    Pitch([LineParams; 2]),
}

impl Link {
    /// The generic pitch link of `p`, whose rear axle is suspended
    /// ([`VehicleParams::rear_hps`]): [`LineParams::side_pitch`] at the ratio of the rear
    /// strut's rod area to the front strut's (1.457 for the prototype's scaled rear strut).
    pub fn pitch_of(p: &VehicleParams) -> Result<Self, VehicleError> {
        let rear = p.rear_hps.ok_or_else(|| {
            rejected(
                "rear_hps",
                f64::NAN,
                "the pitch interconnection needs struts on the rear axle",
            )
        })?;
        Ok(Self::Pitch(LineParams::side_pitch(rear.a_hr / p.hps.a_hr)?))
    }

    /// Validate the lines (the error names the field).
    pub fn validate(&self) -> Result<(), VehicleError> {
        match self {
            Self::Roll(l) => l.validate()?,
            Self::Pitch(ls) => {
                for l in ls {
                    l.validate()?;
                }
            }
        }
        Ok(())
    }
}

/// A line design alone is the front roll link (the runs below take either).
impl From<&LineParams> for Link {
    fn from(line: &LineParams) -> Self {
        Self::Roll(*line)
    }
}

impl From<&Link> for Link {
    fn from(link: &Link) -> Self {
        *link
    }
}

/// One cross-coupled pair of the vehicle's struts: where its struts' and lines' states
/// sit in the linked state, and how its struts move.
#[derive(Debug)]
struct LinkedPair {
    pair: CrossCoupledPair,
    /// Each strut's first state in the vehicle's state.
    states_at: [usize; 2],
    /// Each strut's carrier joint `(q, v)`.
    carrier: [(usize, usize); 2],
    /// Each strut's static travel (m).
    static_travel: [f64; 2],
    /// The pair's first accumulator state (line 0; line 1 follows).
    lines_at: usize,
}

impl LinkedPair {
    /// The pair of `axles[k]`'s strut on side `sides[k]`, lines `lines`, its accumulators
    /// at `lines_at`.
    fn new(
        axles: [&AxleStruts; 2],
        sides: [usize; 2],
        lines: [&LineParams; 2],
        lines_at: usize,
    ) -> Result<Self, VehicleError> {
        let mut struts = Vec::with_capacity(2);
        for a in axles {
            let s = HpsStrut::ported(&sealed_piston(a.strut.params()), a.strut.extensions())?;
            if s.n_states() > MAX_STRUT_STATES {
                return Err(rejected(
                    "hps",
                    s.n_states() as f64,
                    "too many strut states",
                ));
            }
            struts.push(s);
        }
        let struts: [HpsStrut; 2] = [struts[0].clone(), struts[1].clone()];
        Ok(Self {
            pair: CrossCoupledPair::with_lines(struts, lines)?,
            states_at: [0, 1].map(|k| axles[k].states(sides[k]).start),
            carrier: [0, 1].map(|k| axles[k].carriers[sides[k]]),
            static_travel: axles.map(|a| a.static_travel_m),
            lines_at,
        })
    }

    /// The pair's state indices in the linked state, in the pair's order.
    fn block(&self) -> Vec<usize> {
        let mut b = Vec::with_capacity(self.pair.n_states());
        for k in 0..2 {
            let n = self.pair.struts()[k].n_states();
            b.extend(self.states_at[k]..self.states_at[k] + n);
        }
        b.extend([self.lines_at, self.lines_at + 1]);
        b
    }

    /// The pair's state gathered from `y` (velocities from `v_at`), and the struts'
    /// travels and rates.
    #[inline]
    fn gather(
        &self,
        y: &[f64],
        v_at: usize,
        s: &mut [f64; MAX_PAIR],
    ) -> ([f64; 2], [f64; 2], usize) {
        let mut m = 0;
        for k in 0..2 {
            let n = self.pair.struts()[k].n_states();
            s[m..m + n].copy_from_slice(&y[self.states_at[k]..self.states_at[k] + n]);
            m += n;
        }
        s[m..m + 2].copy_from_slice(&y[self.lines_at..self.lines_at + 2]);
        let z = [0, 1].map(|k| self.static_travel[k] + y[self.carrier[k].0]);
        let zdot = self.carrier.map(|(_, vi)| y[v_at + vi]);
        (z, zdot, m + 2)
    }

    /// The pair's rates `d` (in the pair's order) scattered into `dydt`.
    #[inline]
    fn scatter(&self, d: &[f64], dydt: &mut [f64]) {
        let mut m = 0;
        for k in 0..2 {
            let n = self.pair.struts()[k].n_states();
            dydt[self.states_at[k]..self.states_at[k] + n].copy_from_slice(&d[m..m + n]);
            m += n;
        }
        dydt[self.lines_at..self.lines_at + 2].copy_from_slice(&d[m..m + 2]);
    }
}

/// A vehicle with struts interconnected by a [`Link`] (module docs).
#[derive(Debug)]
pub struct LinkedVehicle {
    vehicle: Vehicle,
    link: Link,
    pairs: Vec<LinkedPair>,
    blocks: Vec<Vec<usize>>,
    /// The vehicle's own stiff blocks kept (struts outside every pair), by the vehicle's
    /// block index, after the pairs' blocks.
    own_blocks: Vec<usize>,
}

impl LinkedVehicle {
    /// A stiff block past the pairs' as the vehicle's own block index, with the vehicle's
    /// state count; `None` past the last block.
    fn own_block(&self, block: usize) -> Option<(usize, usize)> {
        let b = *self.own_blocks.get(block.checked_sub(self.pairs.len())?)?;
        Some((b, self.vehicle.offsets().dim))
    }

    /// Link the struts of `vehicle` by `link`: [`Link::Roll`] needs the front-axle HPS
    /// ([`FrontAxle::Suspended`]), [`Link::Pitch`] struts on both axles. The linked struts
    /// become [`HpsStrut::ported`] with sealed pistons, their other parameters and
    /// extensions the vehicle's.
    pub fn new(vehicle: Vehicle, link: &Link) -> Result<Self, VehicleError> {
        link.validate()?;
        let dim = vehicle.offsets().dim;
        let [front, rear] = vehicle.axle_struts();
        let (pairs, own_blocks) = match (link, front, rear) {
            (Link::Roll(line), Some(f), _) => (
                vec![LinkedPair::new([f, f], [0, 1], [line, line], dim)?],
                (2..vehicle.stiff_blocks().len()).collect(),
            ),
            (Link::Pitch([at_front, at_rear]), Some(f), Some(r)) => (
                (0..2)
                    .map(|side| {
                        LinkedPair::new([f, r], [side, side], [at_front, at_rear], dim + 2 * side)
                    })
                    .collect::<Result<Vec<_>, _>>()?,
                Vec::new(),
            ),
            (Link::Roll(_), None, _) => {
                return Err(rejected(
                    "link",
                    f64::NAN,
                    "the roll interconnection needs the front-axle HPS",
                ))
            }
            (Link::Pitch(_), _, _) => {
                return Err(rejected(
                    "link",
                    f64::NAN,
                    "the pitch interconnection needs struts on both axles",
                ))
            }
        };
        let mut blocks: Vec<Vec<usize>> = pairs.iter().map(LinkedPair::block).collect();
        blocks.extend(
            own_blocks
                .iter()
                .map(|&b| vehicle.stiff_blocks()[b].clone()),
        );
        Ok(Self {
            vehicle,
            link: *link,
            pairs,
            blocks,
            own_blocks,
        })
    }

    /// The vehicle.
    pub fn vehicle(&self) -> &Vehicle {
        &self.vehicle
    }

    /// The link.
    pub fn link(&self) -> &Link {
        &self.link
    }

    /// The interconnected strut pairs: [`Link::Roll`] one (left strut, right strut),
    /// [`Link::Pitch`] two (left side, right side; each front strut, rear strut).
    pub fn pairs(&self) -> impl Iterator<Item = &CrossCoupledPair> {
        self.pairs.iter().map(|p| &p.pair)
    }

    /// Index of pair `i`'s line `k` accumulator state in the linked state.
    pub fn line_state(&self, i: usize, k: usize) -> usize {
        self.pairs[i].lines_at + k
    }

    /// The static state: the vehicle's, every strut at its static travel carrying its
    /// static force, with each pair's circuits at the pressures
    /// ([`CrossCoupledPair::circuit_pressures`]) at which the pair carries what its struts
    /// carry alone at their static pressures (the lines charged at the static state). When
    /// a pair's struts rest at one pressure this is the vehicle's state with the
    /// accumulators at that pressure: bit for bit for the roll pair (one strut design), to
    /// round-off for the pitch pairs of a loaded vehicle with the similar rear strut.
    pub fn initial_state(&self) -> Result<Vec<f64>, VehicleError> {
        let mut y = self.vehicle.initial_state();
        y.resize(self.dim(), 0.0);
        let mut s = [0.0; MAX_PAIR];
        for lp in &self.pairs {
            // at rest a strut's rod-side state is its (static) pressure
            let p = lp.states_at.map(|at| y[at + 1]);
            if !p.iter().all(|v| v.is_finite()) {
                return Err(rejected(
                    "hps",
                    f64::NAN,
                    "no static equilibrium of the linked struts",
                ));
            }
            let q = lp.pair.circuit_pressures(p);
            let m = lp.pair.n_states();
            lp.pair.rest_state_at(q, &mut s[..m])?;
            lp.scatter(&s[..m], &mut y);
        }
        Ok(y)
    }

    /// Run from `y0` (the state of [`LinkedVehicle::initial_state`], perhaps perturbed),
    /// recorded as the vehicle's run with every line's node pressure.
    pub fn simulate_from(
        &self,
        y0: &[f64],
        options: &RunOptions,
    ) -> Result<LinkedRun, VehicleError> {
        let dim = self.vehicle.offsets().dim;
        let mut t = self.vehicle.state_layout().typicals().to_vec();
        t.extend_from_slice(&y0[dim..]);
        let lines: Vec<(usize, &hps_emulsion::HydraulicLine)> = self
            .pairs
            .iter()
            .flat_map(|lp| (0..2).map(move |k| (lp.lines_at + k, lp.pair.line(k))))
            .collect();
        let mut node = vec![Vec::new(); lines.len()];
        let record = simulate_system(&self.vehicle, self, y0, t, options, |_, y| {
            for (ch, (at, line)) in node.iter_mut().zip(&lines) {
                ch.push(line.pressure(y[*at]));
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
        self.vehicle.offsets().dim + 2 * self.pairs.len()
    }

    fn rhs(&self, t: f64, y: &[f64], dydt: &mut [f64]) {
        let o = *self.vehicle.offsets();
        self.vehicle.rhs(t, &y[..o.dim], &mut dydt[..o.dim]);
        let mut s = [0.0; MAX_PAIR];
        let mut d = [0.0; MAX_PAIR];
        for lp in &self.pairs {
            let (z, zdot, m) = lp.gather(y, o.v, &mut s);
            lp.pair.evaluate(z, zdot, &s[..m], &mut d[..m]);
            lp.scatter(&d[..m], dydt);
        }
        if dydt[..o.dim].iter().any(|v| v.is_nan()) {
            dydt.fill(f64::NAN);
        }
    }

    fn stiff_blocks(&self) -> &[Vec<usize>] {
        &self.blocks
    }

    /// A pair block's rates: the pair's evaluate, as the right-hand side scatters it; a kept
    /// strut's block is the vehicle's own.
    fn block_rhs(&self, t: f64, y: &[f64], block: usize, out: &mut [f64]) -> bool {
        let Some(lp) = self.pairs.get(block) else {
            return self
                .own_block(block)
                .is_some_and(|(b, dim)| self.vehicle.block_rhs(t, &y[..dim], b, out));
        };
        let mut s = [0.0; MAX_PAIR];
        let (z, zdot, m) = lp.gather(y, self.vehicle.offsets().v, &mut s);
        lp.pair.evaluate(z, zdot, &s[..m], &mut out[..m]);
        true
    }

    /// A pair block's Jacobian by forward differences of the pair's evaluate with the
    /// struts' travels and rates held; a kept strut's block is the vehicle's own.
    fn block_jacobian(&self, t: f64, y: &[f64], block: usize, jac: &mut [f64]) -> bool {
        let Some(lp) = self.pairs.get(block) else {
            return self
                .own_block(block)
                .is_some_and(|(b, dim)| self.vehicle.block_jacobian(t, &y[..dim], b, jac));
        };
        let mut s = [0.0; MAX_PAIR];
        let (z, zdot, m) = lp.gather(y, self.vehicle.offsets().v, &mut s);
        let (mut f0, mut f1) = ([0.0; MAX_PAIR], [0.0; MAX_PAIR]);
        lp.pair.evaluate(z, zdot, &s[..m], &mut f0[..m]);
        let [s0, s1] = lp.pair.struts();
        let n0 = s0.n_states();
        let n01 = n0 + s1.n_states();
        for c in 0..m {
            let typical = if c < n0 {
                s0.state_typical(c)
            } else if c < n01 {
                s1.state_typical(c - n0)
            } else {
                s[c].abs()
            };
            let base = s[c];
            let h = f64::EPSILON.sqrt() * base.abs().max(typical);
            s[c] = base + h;
            lp.pair.evaluate(z, zdot, &s[..m], &mut f1[..m]);
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
    /// The vehicle's record ([`fn@crate::simulate`]).
    pub record: RunRecord,
    /// Node (accumulator) pressure of every line at each sample (Pa): entry `2 i + k` is
    /// pair `i`'s line `k` ([`LinkedVehicle::pairs`]). Roll: line 0 from the left piston side
    /// to the right rod side, line 1 the mirror. Pitch: the left side's pair, then the
    /// right's; line 0 from the front piston side to the rear rod side, line 1 from the
    /// rear piston side to the front rod side.
    pub node_pressure_pa: Vec<Vec<f64>>,
}

/// D1 (section 6.4) with the struts interconnected by `link` (a [`Link`], or a
/// `&LineParams` for the front roll link): the record and its measures, on the terrain of `seed` (the same tracks as [`crate::scenarios::ride`]).
pub fn ride_linked(
    p: &VehicleParams,
    spec: &RideSpec,
    seed: u64,
    link: impl Into<Link>,
) -> Result<(LinkedRun, RideMeasures), VehicleError> {
    ride_linked_on(p, spec, ride_tracks(p, spec, seed)?, link.into())
}

/// [`ride_linked`] on the enveloping cache `tracks` of [`crate::scenarios::ride_tracks`]
/// (shared with the runs of other layouts on the same seed and load).
pub fn ride_linked_on(
    p: &VehicleParams,
    spec: &RideSpec,
    tracks: Arc<TireTracks>,
    link: impl Into<Link>,
) -> Result<(LinkedRun, RideMeasures), VehicleError> {
    let speed = spec.speed_kmh / 3.6;
    let v = Vehicle::on_tracks(p, spec.load, ride_options(spec), tracks)?;
    let linked = LinkedVehicle::new(v, &link.into())?;
    let rec = linked.simulate_from(
        &linked.initial_state()?,
        &RunOptions {
            t_end_s: (RUN_IN_M + spec.length_m) / speed,
            output_dt_s: OUTPUT_DT_S,
            ..RunOptions::default()
        },
    )?;
    let m = ride_measures(
        &rec.record,
        RUN_IN_M / speed,
        spec.front_axle,
        p.rear_hps.is_some(),
    )?;
    Ok((rec, m))
}

/// D2 (section 6.4) to rollover with the struts interconnected by `link`.
pub fn roll_linked(
    p: &VehicleParams,
    spec: &RollSpec,
    seed: u64,
    link: impl Into<Link>,
) -> Result<(LinkedRun, RollMeasures), VehicleError> {
    roll_linked_on(p, spec, roll_tracks(p, spec, seed)?, link.into())
}

/// [`roll_linked`] on the enveloping cache `tracks` of [`crate::scenarios::roll_tracks`].
pub fn roll_linked_on(
    p: &VehicleParams,
    spec: &RollSpec,
    tracks: Arc<TireTracks>,
    link: impl Into<Link>,
) -> Result<(LinkedRun, RollMeasures), VehicleError> {
    let v = Vehicle::on_tracks(p, spec.load, roll_options(spec), tracks)?;
    let linked = LinkedVehicle::new(v, &link.into())?;
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

/// D3 (section 6.4, smooth ground) with the struts interconnected by `link`: the
/// yaw-mode run of [`crate::scenarios::yaw`] (its terrain must be smooth).
pub fn yaw_linked(
    p: &VehicleParams,
    spec: &YawSpec,
    link: impl Into<Link>,
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
    let linked = LinkedVehicle::new(v, &link.into())?;
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

/// Suspension pitch travel (m) at each sample of `rec`: the mean travel of the front
/// struts less that of the rear struts (compression positive; the front travel alone on a
/// rigid rear axle). Bounce moves it little, pitch of the units over their axles fully.
pub fn suspension_pitch_travel_m(rec: &RunRecord) -> Vec<f64> {
    (0..rec.len())
        .map(|i| {
            0.5 * (rec.hps_travel_m[0][i] + rec.hps_travel_m[1][i]
                - rec.rear_hps_travel_m[0][i]
                - rec.rear_hps_travel_m[1][i])
        })
        .collect()
}

/// How the front unit is set moving for a free response.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Kick {
    /// A roll rate of the front unit (rad/s).
    Roll,
    /// A vertical velocity of the front unit (m/s).
    Bounce,
    /// A pitch rate of the front unit (rad/s, nose down positive about the body y axis).
    Pitch,
}

/// The free response of the loaded vehicle with the front-axle HPS (and the rear struts of
/// `p.rear_hps`, if any), linked by `link` or plain, rolling at 20 km/h on smooth ground
/// for `t_end_s`, released from its static state with the front unit's roll rate, pitch
/// rate (rad/s) or vertical velocity (m/s) raised by `size`.
pub fn free_response(
    p: &VehicleParams,
    link: Option<&Link>,
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
        Kick::Pitch => o.v + 1,
        Kick::Bounce => o.v + 5,
    };
    match link {
        Some(l) => {
            let linked = LinkedVehicle::new(v, l)?;
            let mut y0 = linked.initial_state()?;
            y0[at] += size;
            Ok(linked.simulate_from(&y0, &run)?.record)
        }
        None => {
            let mut y0 = v.initial_state();
            y0[at] += size;
            simulate_system(
                &v,
                &v,
                &y0,
                v.state_layout().typicals().to_vec(),
                &run,
                |_, _| {},
            )
        }
    }
}

#[cfg(test)]
mod tests;
