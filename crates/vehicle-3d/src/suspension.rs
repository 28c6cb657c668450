//! HPS struts on any axle (`docs/layouts.md`, "HPS on any axle"): the struts of one
//! suspended axle as the vehicle drives them, the designer's default rear strut, the static
//! travel (on an end stop when the load lies outside what the strut carries within its
//! travel), and the struts' stored energy for the energy balance.
//!
//! Each strut acts between its unit and a massless wheel carrier that slides along the
//! unit's z at the wheel centre (ratio 1, [`crate::model`]); its travel is
//! `z_s = z_static + c` with `c` the carrier coordinate (positive up = compression), its
//! force (Eq 6.9, compressive positive) plus the end stop's pushes the unit up and the
//! carrier down.

use std::ops::Range;

use vehicle_components::{Component, StateLayout};

use hps_emulsion::{
    emulsion::emulsion, HpsExtensions, HpsStrut, StrutMotion, StrutOutputs, StrutParams,
};

use crate::error::{positive, rejected, VehicleError};
use crate::params::{Load, VehicleParams};
use crate::statics::{strut_static_deflection, Statics};
use crate::vehicle::{end_stop_force, END_STOP_STIFFNESS_N_M};

/// Largest overrun of the travel a static equilibrium may sit at on an end stop (m): half
/// the 10 mm oil margin of the rod-side chamber (`hps_emulsion::params::ROD_DEAD_LENGTH`).
const STATIC_STOP_OVERRUN_M: f64 = 0.005;

/// The front strut scaled by `ratio` for an axle whose static strut load is `ratio` times
/// the front's: similitude at equal pressure. Piston, rod and orifice areas and the gas and
/// oil volumes scale with `ratio`, so at equal travel and rate the pressures follow the same
/// histories, every pressure force scales with `ratio`, and with the corner mass scaled by
/// the same factor the bounce frequency and damping ratio stay the front's; travel, fluid
/// and gas data are kept. Seal friction and piston leakage scale with the seal's perimeter,
/// `sqrt(ratio)` (as `StrutParams::front_axle` scales the laboratory strut's friction).
pub fn scaled_strut(front: &StrutParams, ratio: f64) -> Result<StrutParams, VehicleError> {
    positive("rear_hps.scale", ratio)?;
    let perimeter = ratio.sqrt();
    let mut p = *front;
    p.a_hc *= ratio;
    p.a_hr *= ratio;
    p.a_b *= ratio;
    p.a_v *= ratio;
    p.v_g0 *= ratio;
    p.v_c0 *= ratio;
    p.v_r0 *= ratio;
    p.k_l *= perimeter;
    p.friction.mu_v *= perimeter;
    p.friction.f_c *= perimeter;
    p.friction.f_s *= perimeter;
    p.validate()?;
    Ok(p)
}

impl VehicleParams {
    /// Ratio of the loaded rear strut load to the loaded front strut load (each the tire
    /// load less its wheel end's weight): the factor [`VehicleParams::default_rear_strut`]
    /// scales the front strut by. The prototype: 189.7 kN / 130.2 kN = 1.457.
    pub fn rear_strut_load_ratio(&self) -> Result<f64, VehicleError> {
        let s = Statics::of(self, Load::Loaded)?;
        Ok(s.rear_strut_force_n(self) / s.front_strut_force_n(self))
    }

    /// The designer's default rear strut: the front strut ([`VehicleParams::hps`]) scaled
    /// ([`scaled_strut`]) so that, loaded, it sits at the front's static travel and pressure.
    pub fn default_rear_strut(&self) -> Result<StrutParams, VehicleError> {
        scaled_strut(&self.hps, self.rear_strut_load_ratio()?)
    }
}

/// Static travel (m, compression positive) of `strut` under `force` (N): within the travel
/// where the strut carries it there ([`strut_static_deflection`], the same bits as before
/// the rear axle could be suspended), otherwise on the end stop, where the stop's spring
/// ([`end_stop_force`]) takes the difference. A passive strut scaled for the loaded rear
/// axle tops out unloaded (the load ratio is 3.7), and rests on its extension stop.
pub fn static_travel(strut: &HpsStrut, force: f64) -> Result<f64, VehicleError> {
    if let Ok(z) = strut_static_deflection(strut, force) {
        return Ok(z);
    }
    let travel = strut.params().travel;
    let g = |z: f64| -> Result<f64, VehicleError> {
        Ok(strut.static_force(z)? + end_stop_force(z, 0.0, travel) - force)
    };
    let reach = travel + STATIC_STOP_OVERRUN_M;
    let (mut lo, mut hi) = (-reach, reach);
    if !(g(lo)? <= 0.0 && g(hi)? >= 0.0) {
        return Err(rejected(
            "hps",
            force,
            "the strut cannot carry this static load, not even on its end stops",
        ));
    }
    for _ in 0..80 {
        let mid = 0.5 * (lo + hi);
        if g(mid)? < 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(0.5 * (lo + hi))
}

/// The two struts of one suspended axle, left then right.
#[derive(Debug)]
pub struct AxleStruts {
    /// The strut (both sides alike).
    pub strut: HpsStrut,
    /// Static travel under the axle's static load (m, compression positive).
    pub static_travel_m: f64,
    /// The carriers' joint indices `(q, v)`, left then right.
    pub carriers: [(usize, usize); 2],
    /// Index of the left strut's first state in the vehicle's state; the right strut's
    /// follow.
    pub states_at: usize,
}

impl AxleStruts {
    /// The struts of `params` with `ext` carrying `force` each at rest.
    pub(crate) fn new(
        params: &StrutParams,
        ext: &HpsExtensions,
        force: f64,
        carriers: [(usize, usize); 2],
        states_at: usize,
    ) -> Result<Self, VehicleError> {
        let strut = HpsStrut::new(params, ext)?;
        let static_travel_m = static_travel(&strut, force)?;
        Ok(Self {
            strut,
            static_travel_m,
            carriers,
            states_at,
        })
    }

    /// Append both struts' state blocks to `layout`, labelled `labels` (left, right); the
    /// layout must be `states_at` long.
    pub(crate) fn add_states(
        &self,
        layout: &mut StateLayout,
        labels: [&str; 2],
    ) -> Result<(), VehicleError> {
        debug_assert_eq!(layout.len(), self.states_at);
        for label in labels {
            layout.add(label, self.strut.states())?;
        }
        Ok(())
    }

    /// States per strut.
    pub fn n_states(&self) -> usize {
        self.strut.n_states()
    }

    /// The state indices of strut `side` (0 left, 1 right).
    pub fn states(&self, side: usize) -> Range<usize> {
        let n = self.n_states();
        self.states_at + side * n..self.states_at + (side + 1) * n
    }

    /// Travel and rate of strut `side` from the vehicle state `y` whose velocities start
    /// at `v_at`.
    #[inline]
    pub fn motion(&self, y: &[f64], v_at: usize, side: usize) -> (f64, f64) {
        let (qi, vi) = self.carriers[side];
        (self.static_travel_m + y[qi], y[v_at + vi])
    }

    /// Strut `side`'s travel, rate and outputs at the vehicle state `y` (velocities from
    /// `v_at`), its state rates into `d_state` (its own states' length).
    #[inline]
    pub fn evaluate(
        &self,
        y: &[f64],
        v_at: usize,
        side: usize,
        d_state: &mut [f64],
    ) -> (f64, f64, StrutOutputs) {
        let (z, zdot) = self.motion(y, v_at, side);
        let motion = StrutMotion {
            deflection_m: z,
            velocity_m_s: zdot,
        };
        let out = Component::evaluate(&self.strut, &motion, &y[self.states(side)], d_state);
        (z, zdot, out)
    }

    /// Both struts' forces (Eq 6.9 plus the end stop, compressive positive) applied to the
    /// carriers' joint forces `tau`, their state rates into `dydt`; returns the travels and
    /// forces, left then right. Allocation free.
    #[inline]
    pub(crate) fn apply(
        &self,
        y: &[f64],
        v_at: usize,
        tau: &mut [f64],
        dydt: &mut [f64],
    ) -> ([f64; 2], [f64; 2]) {
        let (mut travel, mut force) = ([0.0; 2], [0.0; 2]);
        for side in 0..2 {
            let at = self.states(side);
            let (z, zdot, out) = self.evaluate(y, v_at, side, &mut dydt[at]);
            let stop = end_stop_force(z, zdot, self.strut.params().travel);
            tau[self.carriers[side].1] -= out.force + stop;
            travel[side] = z;
            force[side] = out.force + stop;
        }
        (travel, force)
    }

    /// Both struts' static states at their static travel into `y` (NaN where the strut has
    /// none, which `simulate` reports).
    pub(crate) fn initial_state(&self, y: &mut [f64]) {
        for side in 0..2 {
            let at = self.states(side);
            if self
                .strut
                .initial_state(self.static_travel_m, &mut y[at.clone()])
                .is_err()
            {
                y[at].fill(f64::NAN);
            }
        }
    }

    /// Energy stored in both struts (J) at `y`, relative to the reference state: the free
    /// gas `(P_hc V_g - P_h0 V_g0) / (n - 1)` (Eq 6.10), the emulsion of each chamber its
    /// mass times the specific compression energy `e(P) = -integral P dv` of Eqs 6.14-6.16,
    /// the ambient pressure on the rod end `p_amb A_hr z_s`, and the end stop's spring.
    /// Along a motion its rate is the strut's power less the orifice, leakage and friction
    /// losses (`tests/rear_hps.rs`). Baseline struts only (no extension).
    pub fn stored_energy(&self, y: &[f64], v_at: usize) -> Result<f64, VehicleError> {
        if !self.strut.extensions().is_baseline() {
            return Err(rejected(
                "field.hps",
                f64::NAN,
                "the strut energy is implemented for the baseline strut only",
            ));
        }
        let p = self.strut.params();
        let n = p.n;
        // specific compression energy of the emulsion per kg of oil (Eqs 6.14-6.16)
        let specific = |pr: f64| {
            let gas = p.gamma0 * (pr * (p.p_h0 / pr).powf(1.0 / n) - p.p_h0) / (n - 1.0);
            ((pr * pr - p.p_h0 * p.p_h0) / (2.0 * p.beta_h) + gas) / p.rho_h
        };
        let mut total = 0.0;
        for side in 0..2 {
            let (z, zdot) = self.motion(y, v_at, side);
            let at = self.states(side);
            let out = self.strut.outputs(z, zdot, &y[at]);
            let (pc, pr, vg) = (out.p_piston, out.p_rod, out.gas_volume);
            let vc = p.v_c0 + p.v_g0 - p.a_hc * z - vg;
            let vr = p.v_r0 + p.a_ann() * z;
            let rho =
                |pressure: f64| emulsion(pressure, p.p_h0, n, p.beta_h, p.rho_h, p.gamma0).rho;
            let over = (z.abs() - p.travel).max(0.0);
            total += (pc * vg - p.p_h0 * p.v_g0) / (n - 1.0)
                + rho(pc) * vc * specific(pc)
                + rho(pr) * vr * specific(pr)
                + p.p_amb * p.a_hr * z
                + 0.5 * END_STOP_STIFFNESS_N_M * over * over;
        }
        Ok(total)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_scaled_strut_carries_the_scaled_load_at_the_same_travel() {
        let front = StrutParams::front_axle();
        let rear = scaled_strut(&front, 1.457).unwrap();
        let ext = HpsExtensions::default();
        let (f, r) = (
            HpsStrut::new(&front, &ext).unwrap(),
            HpsStrut::new(&rear, &ext).unwrap(),
        );
        for z in [-0.1, -0.02, 0.0, 0.05, 0.1] {
            let (ff, fr) = (f.static_force(z).unwrap(), r.static_force(z).unwrap());
            assert!((fr / ff - 1.457).abs() < 1e-9, "{z}: {ff} {fr}");
        }
        assert!((rear.friction.f_c / front.friction.f_c - 1.457f64.sqrt()).abs() < 1e-12);
        assert!(scaled_strut(&front, -1.0).is_err());
    }

    #[test]
    fn a_load_beyond_the_struts_reach_rests_on_its_stop() {
        let strut = HpsStrut::new(&StrutParams::front_axle(), &HpsExtensions::default()).unwrap();
        let travel = strut.params().travel;
        // fully extended the strut pushes with its gas force; a lighter load tops it out
        let top = strut.static_force(-travel).unwrap();
        let z = static_travel(&strut, 0.5 * top).unwrap();
        let over = 0.5 * top / END_STOP_STIFFNESS_N_M;
        assert!(
            z < -travel && (z + travel + over).abs() < 1e-2 * over,
            "{z}"
        );
        // inside the travel: the bits of the plain solver
        let f = strut.static_force(0.03).unwrap();
        assert_eq!(
            static_travel(&strut, f).unwrap(),
            strut_static_deflection(&strut, f).unwrap()
        );
        assert!(static_travel(&strut, 1e9).is_err());
    }
}
