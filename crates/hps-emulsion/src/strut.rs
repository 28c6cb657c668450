//! The strut as a force element with its own states (Eqs 5.1-5.12): given deflection and
//! velocity it returns the force and the state derivatives, allocation-free, so a vehicle
//! model can embed it; [`crate::simulate`] drives it by a prescribed displacement.
//!
//! State vector (SI; [`HpsStrut::state_typical`] gives each state's typical magnitude, from
//! which a run builds per-state absolute tolerances):
//!
//! | index | name | unit | typical | equation |
//! |---|---|---|---|---|
//! | 0 | `V_g`, free gas volume | m^3 | V_g0 | Eq 5.5 (with Eq 5.4 for P_hc) |
//! | 1 | `P_hr`, rod-side pressure | Pa | P_h0 | Eq 5.6 |
//! | 2 (heat transfer on) | `theta = T_g / T_0`, gas temperature ratio | - | 1 | [`crate::HeatTransfer`] |
//! | last (valve lag on) | `x_v`, check-valve opening | - | 1 | [`crate::ValveLag`] |

use crate::emulsion::{emulsion, emulsion_volume, Emulsion};
use crate::error::HpsError;
use crate::extensions::HpsExtensions;
use crate::flow::{check_valve_flow, orifice_flow};
use crate::friction::{friction_force, FrictionLevels};
use crate::params::StrutParams;

/// Width of the cavitation guard above the vapour pressure (Pa): a falling chamber pressure is
/// slowed by `1 - exp(-(P - p_vap)/CAVITATION_BAND)`, which is exactly 1.0 in f64 once
/// `P - p_vap > 0.37 MPa`.
pub const CAVITATION_BAND: f64 = 10_000.0;

/// Everything the strut reports at one instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StrutOutputs {
    /// Total strut force F_h (N, positive compressive), Eq 5.1.
    pub force: f64,
    /// Piston-side pressure P_hc (Pa, absolute), Eq 5.4.
    pub p_piston: f64,
    /// Rod-side pressure P_hr (Pa, absolute).
    pub p_rod: f64,
    /// Seal friction F_f (N), Eqs 5.2-5.3.
    pub friction: f64,
    /// Gas-spring force `(P_hc - p_amb) A_hr` (N) (section 5.4.2: "spring force P_hc A_hr").
    pub spring_force: f64,
    /// Free gas volume V_g (m^3).
    pub gas_volume: f64,
    /// Total flow from the piston to the rod side q_b + q_c + q_l (m^3/s), Eq 5.12.
    pub flow: f64,
}

/// A strut ready to run: validated parameters, extensions and derived constants.
#[derive(Debug, Clone, PartialEq)]
pub struct HpsStrut {
    params: StrutParams,
    ext: HpsExtensions,
    v_peak: f64,
    v_h: f64,
    levels: FrictionLevels,
    a_ann: f64,
    ca_b: f64,
    ca_v: f64,
    idx_theta: Option<usize>,
    idx_valve: Option<usize>,
    n_states: usize,
}

impl HpsStrut {
    /// Build a strut. `v_peak` (m/s) is the peak strut velocity of the motion the strut will see:
    /// it sets the friction band `v_h` (section 5.3.1) and, with [`crate::GasFractionGrowth`],
    /// the gas fraction. Errors name the offending parameter.
    pub fn new(params: &StrutParams, ext: &HpsExtensions, v_peak: f64) -> Result<Self, HpsError> {
        params.validate()?;
        ext.validate()?;
        if !(v_peak.is_finite() && v_peak >= 0.0) {
            return Err(HpsError::InvalidParameter {
                field: "v_peak",
                value: v_peak,
                reason: "peak velocity must be finite and >= 0",
            });
        }
        let mut p = *params;
        if let Some(g) = ext.gas_fraction_growth {
            p = p.with_gamma0(p.gamma0 + g.k_gamma * v_peak)?;
        }
        let levels = match ext.asymmetric_friction {
            Some(a) => FrictionLevels::scaled(&p.friction, a.compression, a.extension),
            None => FrictionLevels::scaled(&p.friction, 1.0, 1.0),
        };
        let mut n_states = 2;
        let idx_theta = ext.heat_transfer.map(|_| {
            n_states += 1;
            n_states - 1
        });
        let idx_valve = ext.valve_lag.map(|_| {
            n_states += 1;
            n_states - 1
        });
        Ok(Self {
            v_h: p.friction.v_h(v_peak),
            a_ann: p.a_ann(),
            ca_b: p.c_b * p.n_b as f64 * p.a_b,
            ca_v: p.c_v * p.n_v as f64 * p.a_v,
            params: p,
            ext: *ext,
            v_peak,
            levels,
            idx_theta,
            idx_valve,
            n_states,
        })
    }

    /// Parameters in effect (after extensions that modify them, e.g. gas-fraction growth).
    pub fn params(&self) -> &StrutParams {
        &self.params
    }

    /// Extensions in effect.
    pub fn extensions(&self) -> &HpsExtensions {
        &self.ext
    }

    /// Peak velocity the strut was built for (m/s).
    pub fn v_peak(&self) -> f64 {
        self.v_peak
    }

    /// Friction transition band v_h in use (m/s).
    pub fn v_h(&self) -> f64 {
        self.v_h
    }

    /// Number of states (2 for the baseline).
    pub fn n_states(&self) -> usize {
        self.n_states
    }

    /// Names and units of the states, in order.
    pub fn state_names(&self) -> Vec<&'static str> {
        let mut v = vec!["V_g free gas volume (m^3)", "P_hr rod-side pressure (Pa)"];
        if self.idx_theta.is_some() {
            v.push("T_g/T_0 (-)");
        }
        if self.idx_valve.is_some() {
            v.push("x_v valve opening (-)");
        }
        v
    }

    /// Typical magnitude of state `i` in its SI unit: V_g0 for the gas volume, P_h0 for the
    /// rod-side pressure, 1 for the temperature ratio and the valve opening. A run's
    /// absolute tolerance of state `i` is `atol * state_typical(i)`.
    pub fn state_typical(&self, i: usize) -> f64 {
        match i {
            0 => self.params.v_g0,
            1 => self.params.p_h0,
            _ => 1.0,
        }
    }

    /// Static equilibrium pressure (Pa) at deflection `z` (m): both chambers at one pressure,
    /// gas and emulsion compressed from the reference state, total volume reduced by `A_hr z`
    /// (Eqs 5.4, 5.7, 5.8). With heat transfer the static gas is isothermal.
    pub fn static_pressure(&self, z: f64) -> Result<f64, HpsError> {
        let p = &self.params;
        let gas_n = if self.ext.heat_transfer.is_some() {
            1.0
        } else {
            p.n
        };
        let target = p.v_g0 + p.v_c0 + p.v_r0 - p.a_hr * z;
        let g = |pr: f64| {
            p.v_g0 * (p.p_h0 / pr).powf(1.0 / gas_n)
                + emulsion_volume(p.v_c0 + p.v_r0, pr, p.p_h0, p.n, p.beta_h, p.gamma0)
                - target
        };
        // g decreases with pressure; bisect in log pressure.
        let (mut lo, mut hi) = (p.p_vap.max(1.0), p.p_h0 * 1e3);
        if !(g(lo) > 0.0 && g(hi) < 0.0) {
            return Err(HpsError::OutOfRange {
                t: 0.0,
                reason: format!("no static equilibrium at z = {z} m"),
            });
        }
        for _ in 0..200 {
            let mid = (lo * hi).sqrt();
            if g(mid) > 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
            if hi / lo - 1.0 < 1e-15 {
                break;
            }
        }
        Ok(0.5 * (lo + hi))
    }

    /// Fill `state` with the static equilibrium at deflection `z` (m).
    pub fn initial_state(&self, z: f64, state: &mut [f64]) -> Result<(), HpsError> {
        if state.len() != self.n_states {
            return Err(HpsError::InvalidExcitation(format!(
                "state buffer has {} entries, the strut has {}",
                state.len(),
                self.n_states
            )));
        }
        let p = &self.params;
        let pe = self.static_pressure(z)?;
        let gas_n = if self.ext.heat_transfer.is_some() {
            1.0
        } else {
            p.n
        };
        state[0] = p.v_g0 * (p.p_h0 / pe).powf(1.0 / gas_n);
        state[1] = pe;
        if let Some(i) = self.idx_theta {
            state[i] = 1.0;
        }
        if let Some(i) = self.idx_valve {
            state[i] = 0.0;
        }
        Ok(())
    }

    /// Static strut force (N) at deflection `z`: `P A_hr - p_amb A_hr` at equilibrium.
    pub fn static_force(&self, z: f64) -> Result<f64, HpsError> {
        Ok((self.static_pressure(z)? - self.params.p_amb) * self.params.a_hr)
    }

    /// Static stiffness dF/dz (N/m) at deflection `z` (central difference over +-0.1 mm).
    pub fn static_stiffness(&self, z: f64) -> Result<f64, HpsError> {
        let h = 1e-4;
        Ok((self.static_force(z + h)? - self.static_force(z - h)?) / (2.0 * h))
    }

    /// Relative gas volume `V_g / V_g0`, kept above 1e-9.
    #[inline]
    fn relative_gas_volume(&self, state: &[f64]) -> f64 {
        (state[0] / self.params.v_g0).max(1e-9)
    }

    #[inline]
    fn piston_pressure(&self, state: &[f64]) -> f64 {
        let p = &self.params;
        let v = self.relative_gas_volume(state);
        match self.idx_theta {
            Some(i) => p.p_h0 * state[i] / v,
            None => p.p_h0 * v.powf(-p.n),
        }
    }

    /// Flow from the piston-side to the rod-side chamber (m^3/s, Eq 5.12: bleed orifices,
    /// check valves scaled by the valve-lag opening when that extension is on, laminar
    /// leakage) and the emulsion properties of both chambers (Eqs 5.9-5.11).
    #[inline]
    fn chamber_flow(&self, p_c: f64, p_r: f64, state: &[f64]) -> (f64, Emulsion, Emulsion) {
        let p = &self.params;
        let ec = emulsion(p_c, p.p_h0, p.n, p.beta_h, p.rho_h, p.gamma0);
        let er = emulsion(p_r, p.p_h0, p.n, p.beta_h, p.rho_h, p.gamma0);
        let rho_bar = 0.5 * (ec.rho + er.rho);
        let dp = p_c - p_r;
        let opening = match self.idx_valve {
            Some(i) => state[i].clamp(0.0, 1.0),
            None => 1.0,
        };
        let q = orifice_flow(self.ca_b, dp, rho_bar, p.p_reg)
            + check_valve_flow(self.ca_v, dp, rho_bar, p.p_reg, opening)
            + p.k_l * dp;
        (q, ec, er)
    }

    /// State derivatives at deflection `z` (m), velocity `zdot` (m/s): Eq 5.5 for the gas
    /// volume (with Eq 5.4 giving P_hc'), Eq 5.6 for P_hr, flows of Eq 5.12, emulsion
    /// properties of Eqs 5.9-5.11, volumes of Eq 5.7 (`x` of Eq 5.7 is `z_s`). No allocation.
    pub fn derivatives(&self, z: f64, zdot: f64, state: &[f64], dstate: &mut [f64]) {
        let p = &self.params;
        let v = self.relative_gas_volume(state);
        let p_c = self.piston_pressure(state);
        let p_r_raw = state[1];
        let p_r = p_r_raw.max(p.p_vap.max(1.0));
        let vg = p.v_g0 * v;
        // Eq 5.7 (x = z_s); emulsion volumes cannot go below zero.
        let vc = (p.v_c0 + p.v_g0 - p.a_hc * z - vg).max(0.0);
        let vr = (p.v_r0 + self.a_ann * z).max(1e-12);
        let (q, ec, er) = self.chamber_flow(p_c, p_r, state);
        let dp = p_c - p_r;
        // Eq 5.5 with P_hc' = -n P_hc V_g'/V_g (Eq 5.4), or the heat-transfer gas law.
        let (n_eff, heat) = match (self.idx_theta, self.ext.heat_transfer) {
            (Some(i), Some(h)) => {
                let th = state[i].max(1e-9);
                (h.kappa, vc / ec.beta * p_c * (1.0 - th) / (h.tau * th))
            }
            _ => (p.n, 0.0),
        };
        let vg_dot = (q - p.a_hc * zdot + heat) / (1.0 + n_eff * p_c * vc / (ec.beta * vg));
        dstate[0] = vg_dot;
        // Eq 5.6
        let mut pr_dot = er.beta / vr * (ec.rho / er.rho * q - self.a_ann * zdot);
        if pr_dot < 0.0 {
            let guard = 1.0 - (-(p_r_raw - p.p_vap) / CAVITATION_BAND).exp();
            pr_dot *= guard.clamp(0.0, 1.0);
        }
        dstate[1] = pr_dot;
        if let (Some(i), Some(h)) = (self.idx_theta, self.ext.heat_transfer) {
            let th = state[i];
            dstate[i] = -(h.kappa - 1.0) * th * vg_dot / vg + (1.0 - th) / h.tau;
        }
        if let (Some(i), Some(l)) = (self.idx_valve, self.ext.valve_lag) {
            let target = if dp > 0.0 { 1.0 } else { 0.0 };
            dstate[i] = (target - state[i]) / l.tau;
        }
    }

    /// Strut force F_h (N, positive compressive), Eq 5.1 with absolute pressures:
    /// `P_hc A_hc - P_hr (A_hc - A_hr) - p_amb A_hr + F_f`.
    #[inline]
    pub fn force(&self, z: f64, zdot: f64, state: &[f64]) -> f64 {
        self.outputs(z, zdot, state).force
    }

    /// All outputs at one instant.
    pub fn outputs(&self, z: f64, zdot: f64, state: &[f64]) -> StrutOutputs {
        let p = &self.params;
        let p_c = self.piston_pressure(state);
        let p_r = state[1].max(p.p_vap.max(1.0));
        let f_f = friction_force(&p.friction, &self.levels, z, zdot, self.v_h);
        let force = p_c * p.a_hc - p_r * self.a_ann - p.p_amb * p.a_hr + f_f;
        let (flow, _, _) = self.chamber_flow(p_c, p_r, state);
        StrutOutputs {
            force,
            p_piston: p_c,
            p_rod: p_r,
            friction: f_f,
            spring_force: (p_c - p.p_amb) * p.a_hr,
            gas_volume: state[0],
            flow,
        }
    }
}
