//! ISO 2631-1 at the seat and the SEAT value of a ride run: the cab on its mounts and the
//! suspension seat (`vehicle_components::cab_seat`) driven by the front unit's motion that
//! a run records (issue 23, "cab and seat suspension"; `docs/layouts.md`).
//!
//! The run records the acceleration of the a_wz point (`VehicleParams::cab_point_m`) in the
//! front unit's body axes, and the unit's angular acceleration and rate. The frame is
//! rigid, so its acceleration at the centre O of the cab's mount plane, placed
//! [`CabSeatLayout::mount_centre_from_cab_point_m`] from the a_wz point, is
//! `a_O = a_cab + alpha x r + omega x (omega x r)`. That motion, linear between the
//! samples, drives the cab and seat (one-way: their reaction on the frame is left out, an
//! error of about the mass ratio times `|T - 1|`, bounded in `vehicle_components::cab_seat`),
//! integrated from their static equilibrium with fixed-step RK4 at a quarter of the record's
//! interval (the fastest mode of the generic cab, its 7.1 Hz bounce, and the seat on a
//! stop, about 7 Hz, get over 100 steps per period at the 200 Hz of the ride runs).
//!
//! Measures over the ride window (from `t_start_s`, after the run-in):
//! - `a_wz` on the frame (at the a_wz point, the quantity of D1) and on the cab floor at the
//!   seat base and on the seat pan, each the W_k-weighted RMS (ISO 2631-1);
//! - SEAT = seat pan over floor (ISO 10326-1 / EN ISO 7096, `perf_measures::seat`);
//! - the seat's peak-to-peak travel and the share of the window it spends on its stops.

use odeint::{Control, Integrator, OdeSystem, Solver};
use perf_measures::iso2631::exposure::weighted_rms;
use perf_measures::iso2631::{weight_fft, FilterMethod};
use perf_measures::{seat_value, SeatValue, Weighting};
use rayon::prelude::*;
use serde::Serialize;
use vehicle_components::{CabParams, CabSeat, Component, ComponentError, FrameMotion, SeatParams};

use crate::error::{measure, VehicleError};
use crate::params::VehicleParams;
use crate::scenarios::{ride, RideMeasures, RideSpec, RUN_IN_M};
use crate::simulate::RunRecord;

/// RK4 steps per record interval.
const SUBSTEPS: f64 = 4.0;

/// A cab and seat and where the cab sits on the front unit.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, serde::Deserialize)]
pub struct CabSeatLayout {
    /// The cab on its mounts.
    pub cab: CabParams,
    /// The suspension seat.
    pub seat: SeatParams,
    /// Centre O of the mount plane from the a_wz point, in the front unit's body axes (m).
    /// Generic: `[0, 0, 0]`, the mount plane at the cab-floor height of the a_wz point.
    pub mount_centre_from_cab_point_m: [f64; 3],
}

impl CabSeatLayout {
    /// The generic cab and seat ([`CabParams::generic`], [`SeatParams::generic`]) with the
    /// mount plane centred on the a_wz point.
    pub fn generic() -> Self {
        Self {
            cab: CabParams::generic(),
            seat: SeatParams::generic(),
            mount_centre_from_cab_point_m: [0.0; 3],
        }
    }

    /// The component under the vehicle's gravity (every field checked).
    pub fn build(&self, p: &VehicleParams) -> Result<CabSeat, VehicleError> {
        for (field, v) in [
            "mount_centre_from_cab_point_m[0]",
            "mount_centre_from_cab_point_m[1]",
            "mount_centre_from_cab_point_m[2]",
        ]
        .into_iter()
        .zip(self.mount_centre_from_cab_point_m)
        {
            if !(v.is_finite() && v.abs() <= 10.0) {
                return Err(VehicleError::InvalidParameter {
                    field,
                    value: v,
                    reason: "must be finite and within 10 m of the a_wz point",
                });
            }
        }
        CabSeat::new(self.cab, self.seat, p.gravity_m_s2).map_err(component)
    }
}

fn component(e: ComponentError) -> VehicleError {
    match e {
        ComponentError::InvalidParameter {
            field,
            value,
            reason,
        } => VehicleError::InvalidParameter {
            field,
            value,
            reason,
        },
        other => measure("cab_seat", other),
    }
}

/// The frame's motion at O for every sample of `rec` (module docs), O being `offset_m` from
/// the a_wz point. Errors when a channel it reads is not as long as the record's time.
pub fn frame_motion(rec: &RunRecord, offset_m: [f64; 3]) -> Result<Vec<FrameMotion>, VehicleError> {
    let n = rec.t_s.len();
    let channels = [
        &rec.cab_accel_m_s2,
        &rec.front_angular_accel_rad_s2,
        &rec.front_rate_rad_s,
    ];
    if channels.iter().any(|c| c.iter().any(|v| v.len() != n)) {
        return Err(measure(
            "cab_seat",
            "the record's cab acceleration, angular acceleration and rate channels must each hold one value per time",
        ));
    }
    Ok((0..n)
        .map(|i| {
            let at_cab = FrameMotion {
                accel_m_s2: [0, 1, 2].map(|k| rec.cab_accel_m_s2[k][i]),
                angular_accel_rad_s2: [0, 1, 2].map(|k| rec.front_angular_accel_rad_s2[k][i]),
                rate_rad_s: [0, 1, 2].map(|k| rec.front_rate_rad_s[k][i]),
            };
            FrameMotion {
                accel_m_s2: at_cab.point_accel(offset_m),
                ..at_cab
            }
        })
        .collect())
}

/// The recorded response of the cab and seat, one row per input sample.
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct CabSeatRecord {
    /// Time (s).
    pub t_s: Vec<f64>,
    /// Cab-floor vertical acceleration at the seat base (m/s², kinematic).
    pub floor_accel_m_s2: Vec<f64>,
    /// Seat-pan vertical acceleration (m/s², kinematic).
    pub seat_accel_m_s2: Vec<f64>,
    /// Seat travel from mid-travel (m, up positive).
    pub seat_travel_m: Vec<f64>,
    /// End-stop force on the seat (N).
    pub stop_force_n: Vec<f64>,
    /// Cab roll and pitch relative to the frame (rad).
    pub cab_roll_pitch_rad: [Vec<f64>; 2],
    /// Power of the frame's inertial forces, `P_in` (W).
    pub power_in_w: Vec<f64>,
    /// Power dissipated in the dampers, `D` (W).
    pub dissipation_w: Vec<f64>,
    /// Energy of the relative motion, `E` (J): `dE/dt = P_in - D`.
    pub energy_j: Vec<f64>,
}

/// The ODE of the cab and seat under a sampled frame motion, linear between the samples.
struct Driven<'a> {
    cs: &'a CabSeat,
    t0: f64,
    dt: f64,
    frame: &'a [FrameMotion],
}

impl Driven<'_> {
    fn input(&self, t: f64) -> FrameMotion {
        let x = ((t - self.t0) / self.dt).max(0.0);
        let i = (x.floor() as usize).min(self.frame.len() - 2);
        let w = (x - i as f64).clamp(0.0, 1.0);
        let (a, b) = (&self.frame[i], &self.frame[i + 1]);
        let lerp = |u: [f64; 3], v: [f64; 3]| [0, 1, 2].map(|k| u[k] + w * (v[k] - u[k]));
        FrameMotion {
            accel_m_s2: lerp(a.accel_m_s2, b.accel_m_s2),
            angular_accel_rad_s2: lerp(a.angular_accel_rad_s2, b.angular_accel_rad_s2),
            rate_rad_s: lerp(a.rate_rad_s, b.rate_rad_s),
        }
    }
}

impl OdeSystem for Driven<'_> {
    fn dim(&self) -> usize {
        self.cs.n_states()
    }
    fn rhs(&self, t: f64, y: &[f64], dydt: &mut [f64]) {
        self.cs.evaluate(&self.input(t), y, dydt);
    }
}

/// Drive `cs` with the frame motion `frame` sampled at the uniform times `t_s` (at least 2),
/// from its static equilibrium under the first sample.
pub fn cab_seat_run(
    cs: &CabSeat,
    t_s: &[f64],
    frame: &[FrameMotion],
) -> Result<CabSeatRecord, VehicleError> {
    if t_s.len() < 2 || frame.len() != t_s.len() {
        return Err(measure(
            "cab_seat",
            format!(
                "needs at least 2 samples and one frame motion per sample ({} times, {} motions)",
                t_s.len(),
                frame.len()
            ),
        ));
    }
    let dt = t_s[1] - t_s[0];
    if !(dt.is_finite() && dt > 0.0) {
        return Err(measure("cab_seat", "the times must increase"));
    }
    let sys = Driven {
        cs,
        t0: t_s[0],
        dt,
        frame,
    };
    let mut y0 = vec![0.0; cs.n_states()];
    cs.initial_state(&frame[0], &mut y0);
    let n = t_s.len();
    let mut rec = CabSeatRecord::default();
    let cols = [
        &mut rec.t_s,
        &mut rec.floor_accel_m_s2,
        &mut rec.seat_accel_m_s2,
        &mut rec.seat_travel_m,
        &mut rec.stop_force_n,
        &mut rec.power_in_w,
        &mut rec.dissipation_w,
        &mut rec.energy_j,
    ];
    for c in cols {
        c.reserve_exact(n);
    }
    for c in &mut rec.cab_roll_pitch_rad {
        c.reserve_exact(n);
    }
    let mut d = vec![0.0; y0.len()];
    Integrator::new(
        Solver::Rk4 {
            step: dt / SUBSTEPS,
        },
        1e-6,
        1e-9,
    )
    .with_max_steps(usize::MAX)
    .integrate(&sys, t_s[0], &y0, t_s, |t, y| {
        let o = cs.evaluate(&sys.input(t), y, &mut d);
        rec.t_s.push(t);
        rec.floor_accel_m_s2.push(o.floor_accel_m_s2);
        rec.seat_accel_m_s2.push(o.seat_accel_m_s2);
        rec.seat_travel_m.push(o.seat_travel_m);
        rec.stop_force_n.push(o.stop_force_n);
        rec.cab_roll_pitch_rad[0].push(o.cab_roll_rad);
        rec.cab_roll_pitch_rad[1].push(o.cab_pitch_rad);
        rec.power_in_w.push(o.power_in_w);
        rec.dissipation_w.push(o.dissipation_w);
        rec.energy_j.push(cs.energy_j(y));
        Control::Continue
    })?;
    Ok(rec)
}

/// ISO 2631-1 on the frame and at the seat, and SEAT, of one ride window.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SeatRideMeasures {
    /// a_wz on the frame at the a_wz point (m/s²): D1's measure.
    pub a_wz_frame_m_s2: f64,
    /// a_wz on the cab floor at the seat base (m/s²).
    pub a_wz_floor_m_s2: f64,
    /// a_wz on the seat pan, where the operator sits (m/s²).
    pub a_wz_seat_m_s2: f64,
    /// SEAT, seat pan over floor, with crest factors and the VDV ratio.
    pub seat: SeatValue,
    /// Peak-to-peak seat travel in the window (m).
    pub seat_travel_p2p_m: f64,
    /// Share of the window's samples with the seat on an end stop.
    pub stop_fraction: f64,
}

/// The seat measures of ride run `rec` from `t_start_s` on, with the cab and seat `layout`
/// (module docs).
pub fn seat_ride_measures(
    p: &VehicleParams,
    rec: &RunRecord,
    t_start_s: f64,
    layout: &CabSeatLayout,
) -> Result<SeatRideMeasures, VehicleError> {
    let cs = layout.build(p)?;
    let frame = frame_motion(rec, layout.mount_centre_from_cab_point_m)?;
    let out = cab_seat_run(&cs, &rec.t_s, &frame)?;
    let i0 = rec.t_s.partition_point(|&t| t < t_start_s);
    if rec.len() < i0 + 64 {
        return Err(measure(
            "a_wz_seat",
            "the ride window holds fewer than 64 samples",
        ));
    }
    let fs = 1.0 / (rec.t_s[1] - rec.t_s[0]);
    let frame_w = weight_fft(Weighting::Wk, &rec.cab_accel_m_s2[2][i0..], fs)
        .map_err(|e| measure("a_wz", e))?;
    let seat = seat_value(
        &out.floor_accel_m_s2[i0..],
        &out.seat_accel_m_s2[i0..],
        fs,
        FilterMethod::Fft,
    )
    .map_err(|e| measure("seat", e))?;
    let travel = &out.seat_travel_m[i0..];
    let hi = travel.iter().fold(f64::MIN, |m, v| m.max(*v));
    let lo = travel.iter().fold(f64::MAX, |m, v| m.min(*v));
    let on_stop = out.stop_force_n[i0..].iter().filter(|f| **f != 0.0).count();
    Ok(SeatRideMeasures {
        a_wz_frame_m_s2: weighted_rms(&frame_w).map_err(|e| measure("a_wz", e))?,
        a_wz_floor_m_s2: seat.a_w_floor_m_s2,
        a_wz_seat_m_s2: seat.a_w_seat_m_s2,
        seat,
        seat_travel_p2p_m: hi - lo,
        stop_fraction: on_stop as f64 / travel.len() as f64,
    })
}

/// One D1-type ride run on terrain `seed` and its frame and seat measures.
pub fn ride_with_seat(
    p: &VehicleParams,
    spec: &RideSpec,
    seed: u64,
    layout: &CabSeatLayout,
) -> Result<(RideMeasures, SeatRideMeasures), VehicleError> {
    layout.build(p)?;
    let (rec, m) = ride(p, spec, seed)?;
    let s = seat_ride_measures(p, &rec, RUN_IN_M / (spec.speed_kmh / 3.6), layout)?;
    Ok((m, s))
}

/// [`ride_with_seat`] over `seeds` (in parallel), in seed order.
pub fn ride_with_seat_over_seeds(
    p: &VehicleParams,
    spec: &RideSpec,
    seeds: &[u64],
    layout: &CabSeatLayout,
) -> Result<Vec<(RideMeasures, SeatRideMeasures)>, VehicleError> {
    seeds
        .par_iter()
        .map(|&s| ride_with_seat(p, spec, s, layout))
        .collect()
}

#[cfg(test)]
mod tests;
