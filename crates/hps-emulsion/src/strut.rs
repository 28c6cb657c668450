//! The strut as a force element with its own states (Eqs 5.1-5.12): given deflection and
//! velocity it returns the force and the state derivatives in one allocation-free evaluate,
//! so a vehicle model can embed it ([`crate::component`] makes it a
//! `vehicle_components::Component`); [`crate::simulate`] drives it by a prescribed
//! displacement.
//!
//! State vector (SI; [`HpsStrut::state_typical`] gives each state's typical magnitude, from
//! which a run builds per-state absolute tolerances):
//!
//! | index | name | unit | typical | equation |
//! |---|---|---|---|---|
//! | 0 | `V_g`, free gas volume | m^3 | V_g0 | Eq 5.5 (with Eq 5.4 for P_hc) |
//! | 1 | `P_hr`, rod-side pressure | Pa | P_h0 | Eq 5.6 |
//! | 2 | `u`, filtered velocity amplitude | m/s | [`VELOCITY_TYPICAL`] | [`HpsStrut::amplitude_rate`] |
//! | 3 (heat transfer on) | `theta = T_g / T_0`, gas temperature ratio | - | 1 | [`crate::HeatTransfer`] |
//! | last (valve lag on) | `x_v`, check-valve opening | - | 1 | [`crate::ValveLag`] |
//!
//! The laws the text states in terms of the motion's peak velocity (the friction band `v_h`,
//! section 5.3.1, and the gas-fraction growth of Fig 5.4b) run on the state `u`, a peak
//! detector of `|z_s'|` with fast attack and slow release: under a steady harmonic motion
//! `u` sits within a few per mille of the peak velocity, so no peak has to be known before
//! the run (docs/hps-emulsion.md, "Velocity amplitude").

use crate::emulsion::{emulsion_from_ratio, emulsion_volume, Emulsion};
use crate::error::HpsError;
use crate::extensions::HpsExtensions;
use crate::flow::piston_to_rod_flow;
use crate::friction::{friction_force, FrictionLevels};
use crate::laws::StrutLaws;
use crate::params::StrutParams;
use vehicle_components::StateInfo;

/// Width of the cavitation guard above the vapour pressure (Pa): a falling chamber pressure is
/// slowed by `1 - exp(-(P - p_vap)/CAVITATION_BAND)`, which is exactly 1.0 in f64 once
/// `P - p_vap > 0.37 MPa`.
pub const CAVITATION_BAND: f64 = 10_000.0;

/// Attack time constant of the velocity amplitude `u` (s): `u` rises towards `|z_s'|` with
/// it whenever the speed exceeds `u`. One twenty-fifth of the period of the fastest
/// laboratory test (8 Hz, section 5.2), so `u` follows a growing motion within a cycle.
pub const VELOCITY_ATTACK_S: f64 = 0.02;

/// Release time constant of the velocity amplitude `u` (s): `u` decays with it when the
/// speed is below `u`. Twenty periods of the slowest laboratory test (0.1 Hz), so over one
/// 0.1 Hz cycle `u` falls by at most 5 % between velocity peaks (1.25 % at the stroke
/// reversals, where the friction band acts); gas that the motion has churned into the oil
/// leaves it on this scale of minutes, not within a cycle.
pub const VELOCITY_RELEASE_S: f64 = 200.0;

/// Typical magnitude of the velocity amplitude `u` (m/s): the largest peak velocity of the
/// laboratory programme, 0.2356 m/s (section 5.2), rounded.
pub const VELOCITY_TYPICAL: f64 = 0.2;

/// Index of the velocity-amplitude state `u`.
pub const STATE_U: usize = 2;

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
    /// Filtered velocity amplitude `u` (m/s), the state the peak-velocity laws run on.
    pub velocity_amplitude: f64,
}

/// External volume flows into the two chambers (m^3/s) through ports to hydraulic lines
/// ([`crate::interconnect`]), at the chamber's density: they enter the continuity equations
/// 5.5 (piston side) and 5.6 (rod side) beside the piston displacement.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ChamberInflow {
    /// Into the piston-side chamber (m^3/s).
    pub piston: f64,
    /// Into the rod-side chamber (m^3/s).
    pub rod: f64,
}

impl ChamberInflow {
    /// No external flow: the strut of Eqs 5.5-5.6 as printed.
    pub const NONE: Self = Self {
        piston: 0.0,
        rod: 0.0,
    };
}

/// Hydraulic compliances `dV/dP` of the two chambers (m^3/Pa):
/// [`HpsStrut::chamber_compliances`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ChamberCompliance {
    /// Piston side: free gas and emulsion.
    pub piston: f64,
    /// Rod side: emulsion.
    pub rod: f64,
}

/// Reference (static, `z_s = 0`, `P_h0`) volumes and gas fraction in effect at one velocity
/// amplitude: the parameters' own, or those of [`StrutParams::with_gamma0`] at the grown gas
/// fraction when [`crate::GasFractionGrowth`] is on.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Reference {
    gamma0: f64,
    v_g0: f64,
    v_c0: f64,
    v_r0: f64,
    /// `d v_g0 / d u` (m^3 s/m): the free gas the growth law takes per unit of `u`.
    dvg0_du: f64,
}

/// The gas-fraction growth law on the state `u` (Fig 5.4b): `gamma_0(u) = gamma_0 + k u`,
/// capped where the free gas would no longer cover the compression stroke.
#[derive(Debug, Clone, Copy, PartialEq)]
struct GasGrowth {
    k_gamma: f64,
    oil_c: f64,
    oil_r: f64,
    /// Free plus entrapped gas at `P_h0` (m^3), conserved when gas moves.
    total_gas: f64,
    gamma_cap: f64,
}

impl GasGrowth {
    fn new(p: &StrutParams, k_gamma: f64) -> Self {
        let (oil_c, oil_r) = p.oil_volumes();
        let total_gas = p.v_g0 + p.gamma0 * (oil_c + oil_r);
        // The largest gas fraction `StrutParams::validate` accepts for a fixed gamma_0:
        // free gas above A_hr * travel at P_h0, gamma_0 below 0.5.
        let cap = (total_gas - p.a_hr * p.travel) / (oil_c + oil_r);
        Self {
            k_gamma,
            oil_c,
            oil_r,
            total_gas,
            gamma_cap: (cap * (1.0 - 1e-6)).min(0.5 * (1.0 - 1e-6)),
        }
    }

    #[inline]
    fn reference(&self, base_gamma0: f64, u: f64) -> Reference {
        let raw = base_gamma0 + self.k_gamma * u.max(0.0);
        let (gamma0, slope) = if raw < self.gamma_cap {
            (raw, self.k_gamma)
        } else {
            (self.gamma_cap, 0.0)
        };
        let oil = self.oil_c + self.oil_r;
        Reference {
            gamma0,
            v_g0: self.total_gas - gamma0 * oil,
            v_c0: self.oil_c * (1.0 + gamma0),
            v_r0: self.oil_r * (1.0 + gamma0),
            dvg0_du: -slope * oil,
        }
    }
}

/// A strut ready to run: validated parameters, extensions and derived constants.
#[derive(Debug, Clone, PartialEq)]
pub struct HpsStrut {
    params: StrutParams,
    ext: HpsExtensions,
    laws: StrutLaws,
    /// Regularisation pressure of the orifice root under `laws` (Pa).
    p_reg: f64,
    levels: FrictionLevels,
    growth: Option<GasGrowth>,
    a_ann: f64,
    ca_b: f64,
    ca_v: f64,
    inv_n: f64,
    idx_theta: Option<usize>,
    idx_valve: Option<usize>,
    states: [StateInfo; 5],
    n_states: usize,
}

impl HpsStrut {
    /// Build a strut. Nothing about the motion is needed: the friction band `v_h` (section
    /// 5.3.1) and, with [`crate::GasFractionGrowth`], the gas fraction follow the
    /// velocity-amplitude state `u`. Errors name the offending parameter.
    pub fn new(params: &StrutParams, ext: &HpsExtensions) -> Result<Self, HpsError> {
        Self::build(params, ext, false)
    }

    /// A strut whose chambers also have ports to hydraulic lines ([`crate::interconnect`]):
    /// as [`HpsStrut::new`], but a sealed piston (no bleed orifice, check valve or leakage,
    /// the damping moved into the lines' ports) is accepted
    /// ([`StrutParams::validate_ported`]).
    pub fn ported(params: &StrutParams, ext: &HpsExtensions) -> Result<Self, HpsError> {
        Self::build(params, ext, true)
    }

    fn build(params: &StrutParams, ext: &HpsExtensions, ported: bool) -> Result<Self, HpsError> {
        params.validate_ported(ported)?;
        ext.validate()?;
        let p = *params;
        let levels = match ext.asymmetric_friction {
            Some(a) => FrictionLevels::scaled(&p.friction, a.compression, a.extension),
            None => FrictionLevels::scaled(&p.friction, 1.0, 1.0),
        };
        let mut states = [
            StateInfo::new("gas_volume_m3", "m³", p.v_g0),
            StateInfo::new("p_rod_pa", "Pa", p.p_h0),
            StateInfo::new("velocity_amplitude_m_s", "m/s", VELOCITY_TYPICAL),
            StateInfo::new("gas_temperature_ratio", "-", 1.0),
            StateInfo::new("valve_opening", "-", 1.0),
        ];
        let mut n_states = 3;
        let idx_theta = ext.heat_transfer.map(|_| {
            n_states += 1;
            n_states - 1
        });
        let idx_valve = ext.valve_lag.map(|_| {
            states[n_states] = states[4];
            n_states += 1;
            n_states - 1
        });
        Ok(Self {
            a_ann: p.a_ann(),
            ca_b: p.c_b * p.n_b as f64 * p.a_b,
            ca_v: p.c_v * p.n_v as f64 * p.a_v,
            inv_n: 1.0 / p.n,
            growth: ext
                .gas_fraction_growth
                .map(|g| GasGrowth::new(&p, g.k_gamma)),
            params: p,
            ext: *ext,
            laws: StrutLaws::default(),
            p_reg: p.p_reg,
            levels,
            idx_theta,
            idx_valve,
            states,
            n_states,
        })
    }

    /// Parameters as given (with [`crate::GasFractionGrowth`] the gas fraction in effect at
    /// a velocity amplitude is [`HpsStrut::params_at`]'s).
    pub fn params(&self) -> &StrutParams {
        &self.params
    }

    /// Parameters in effect at velocity amplitude `u` (m/s): the given ones, or with
    /// gas-fraction growth those of [`StrutParams::with_gamma0`] at `gamma_0(u)`.
    pub fn params_at(&self, u: f64) -> StrutParams {
        let r = self.reference(u);
        StrutParams {
            gamma0: r.gamma0,
            v_g0: r.v_g0,
            v_c0: r.v_c0,
            v_r0: r.v_r0,
            ..self.params
        }
    }

    /// Extensions in effect.
    pub fn extensions(&self) -> &HpsExtensions {
        &self.ext
    }

    /// The same strut with the readings `laws` of the ambiguous laws ([`StrutLaws`]; a
    /// strut is built with the default readings).
    pub fn with_laws(mut self, laws: StrutLaws) -> Self {
        self.p_reg = laws.orifice_regularisation(self.params.p_reg);
        self.laws = laws;
        self
    }

    /// Readings of the ambiguous laws in effect.
    pub fn laws(&self) -> &StrutLaws {
        &self.laws
    }

    /// Friction transition band v_h (m/s) at velocity amplitude `u`.
    pub fn v_h(&self, u: f64) -> f64 {
        self.params.friction.v_h(u)
    }

    /// Number of states (3 for the baseline).
    pub fn n_states(&self) -> usize {
        self.n_states
    }

    /// The states in order: record name with unit, SI unit, typical magnitude.
    pub fn states(&self) -> &[StateInfo] {
        &self.states[..self.n_states]
    }

    /// Typical magnitude of state `i` in its SI unit: V_g0 for the gas volume, P_h0 for the
    /// rod-side pressure, [`VELOCITY_TYPICAL`] for the velocity amplitude, 1 for the
    /// temperature ratio and the valve opening. A run's absolute tolerance of state `i` is
    /// `atol * state_typical(i)`.
    pub fn state_typical(&self, i: usize) -> f64 {
        self.states[i].typical
    }

    #[inline]
    fn reference(&self, u: f64) -> Reference {
        let p = &self.params;
        match &self.growth {
            Some(g) => g.reference(p.gamma0, u),
            None => Reference {
                gamma0: p.gamma0,
                v_g0: p.v_g0,
                v_c0: p.v_c0,
                v_r0: p.v_r0,
                dvg0_du: 0.0,
            },
        }
    }

    /// Polytropic exponent of the free gas at rest (1 with heat transfer: the static gas is
    /// isothermal).
    fn static_gas_exponent(&self) -> f64 {
        if self.ext.heat_transfer.is_some() {
            1.0
        } else {
            self.params.n
        }
    }

    /// Static equilibrium pressure (Pa) at deflection `z` (m) and velocity amplitude `u`
    /// (m/s, only with gas-fraction growth): both chambers at one pressure, gas and emulsion
    /// compressed from the reference state, total volume reduced by `A_hr z` (Eqs 5.4, 5.7,
    /// 5.8). With heat transfer the static gas is isothermal.
    pub fn static_pressure_at(&self, z: f64, u: f64) -> Result<f64, HpsError> {
        let p = &self.params;
        let r = self.reference(u);
        let gas_n = self.static_gas_exponent();
        let target = r.v_g0 + r.v_c0 + r.v_r0 - p.a_hr * z;
        let g = |pr: f64| {
            r.v_g0 * (p.p_h0 / pr).powf(1.0 / gas_n)
                + emulsion_volume(r.v_c0 + r.v_r0, pr, p.p_h0, p.n, p.beta_h, r.gamma0)
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

    /// Static equilibrium pressure (Pa) at deflection `z` (m), at rest (`u = 0`).
    pub fn static_pressure(&self, z: f64) -> Result<f64, HpsError> {
        self.static_pressure_at(z, 0.0)
    }

    /// Fill `state` with the static equilibrium at deflection `z` (m) and the velocity
    /// amplitude `u0` (m/s, >= 0): a driver that knows the motion's peak velocity starts
    /// with `u0` = that peak, so a harmonic test starts in its steady state; a vehicle starts
    /// at rest (`u0 = 0`).
    pub fn initial_state_at(&self, z: f64, u0: f64, state: &mut [f64]) -> Result<(), HpsError> {
        if state.len() != self.n_states {
            return Err(HpsError::InvalidExcitation(format!(
                "state buffer has {} entries, the strut has {}",
                state.len(),
                self.n_states
            )));
        }
        if !(u0.is_finite() && u0 >= 0.0) {
            return Err(HpsError::InvalidParameter {
                field: "u0",
                value: u0,
                reason: "initial velocity amplitude must be finite and >= 0",
            });
        }
        let pe = self.static_pressure_at(z, u0)?;
        self.write_rest_state(pe, u0, state);
        Ok(())
    }

    /// Write the state at rest with both chambers at pressure `pe` (Pa) and velocity
    /// amplitude `u0` (m/s): the free gas compressed to `pe` from the reference state (the
    /// static gas law), gas at the wall temperature, check valves closed.
    fn write_rest_state(&self, pe: f64, u0: f64, state: &mut [f64]) {
        state[0] = self.reference(u0).v_g0
            * (self.params.p_h0 / pe).powf(1.0 / self.static_gas_exponent());
        state[1] = pe;
        state[STATE_U] = u0;
        if let Some(i) = self.idx_theta {
            state[i] = 1.0;
        }
        if let Some(i) = self.idx_valve {
            state[i] = 0.0;
        }
    }

    /// Fill `state` with the strut at rest with both chambers at pressure `p` (Pa): the
    /// static state of a ported strut ([`HpsStrut::ported`]), whose deflection at a pressure
    /// depends on the oil in its lines, not on the strut alone.
    pub fn rest_state_at_pressure(&self, p: f64, state: &mut [f64]) -> Result<(), HpsError> {
        if state.len() != self.n_states {
            return Err(HpsError::InvalidExcitation(format!(
                "state buffer has {} entries, the strut has {}",
                state.len(),
                self.n_states
            )));
        }
        if !(p.is_finite() && p > self.params.p_vap) {
            return Err(HpsError::InvalidParameter {
                field: "p",
                value: p,
                reason: "rest pressure must be finite and above the vapour pressure",
            });
        }
        self.write_rest_state(p, 0.0, state);
        Ok(())
    }

    /// Fill `state` with the static equilibrium at deflection `z` (m), at rest (`u = 0`).
    pub fn initial_state(&self, z: f64, state: &mut [f64]) -> Result<(), HpsError> {
        self.initial_state_at(z, 0.0, state)
    }

    /// Write the reference state: `z_s = 0` at rest, free gas `V_g0` at `P_h0` in both
    /// chambers (the static equilibrium at mid-stroke by the definition of the reference),
    /// gas at the wall temperature, check valves closed.
    pub(crate) fn reference_state(&self, state: &mut [f64]) {
        state.fill(0.0);
        state[0] = self.params.v_g0;
        state[1] = self.params.p_h0;
        if let Some(i) = self.idx_theta {
            state[i] = 1.0;
        }
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

    /// Rate of the velocity amplitude `u` (m/s^2) at speed `|zdot|`: a peak detector with
    /// attack [`VELOCITY_ATTACK_S`] and release [`VELOCITY_RELEASE_S`],
    /// `u' = max(|zdot| - u, 0) / tau_a - u / tau_r`.
    #[inline]
    pub fn amplitude_rate(zdot: f64, u: f64) -> f64 {
        (zdot.abs() - u).max(0.0) / VELOCITY_ATTACK_S - u / VELOCITY_RELEASE_S
    }

    /// Piston-side pressure P_hc (Pa, Eq 5.4 or the heat-transfer gas law) and the gas ratio
    /// `(P_h0 / P_hc)^(1/n)` of the entrapped gas (Eq 5.9), for the relative gas volume
    /// `v = V_g / V_g0`.
    #[inline]
    fn piston_pressure(&self, v: f64, state: &[f64]) -> (f64, f64) {
        let p = &self.params;
        match self.idx_theta {
            Some(i) => {
                let p_c = p.p_h0 * state[i] / v;
                (p_c, (p.p_h0 / p_c).powf(self.inv_n))
            }
            // (P_h0 / (P_h0 v^-n))^(1/n) = v: no second power.
            None => (p.p_h0 * v.powf(-p.n), v),
        }
    }

    /// Everything one evaluate needs: reference volumes at `u`, both pressures, the flow of
    /// Eq 5.12 (bleed orifices, check valves scaled by the valve-lag opening when that
    /// extension is on, laminar leakage) and both chambers' emulsion (Eqs 5.9-5.11).
    #[inline]
    fn chambers(&self, state: &[f64]) -> Chambers {
        let p = &self.params;
        let r = self.reference(state[STATE_U]);
        let v = (state[0] / r.v_g0).max(1e-9);
        let (p_c, ratio_c) = self.piston_pressure(v, state);
        let p_r_raw = state[1];
        let p_r = self.rod_pressure(p_r_raw);
        let ec = emulsion_from_ratio(p_c, ratio_c, p.p_h0, p.n, p.beta_h, p.rho_h, r.gamma0);
        let ratio_r = if r.gamma0 > 0.0 {
            (p.p_h0 / p_r).powf(self.inv_n)
        } else {
            0.0
        };
        let er = emulsion_from_ratio(p_r, ratio_r, p.p_h0, p.n, p.beta_h, p.rho_h, r.gamma0);
        let dp = p_c - p_r;
        let opening = match self.idx_valve {
            Some(i) => state[i].clamp(0.0, 1.0),
            None => 1.0,
        };
        // Eq 5.12 with one density for both orifice laws (by default the mean of both
        // chambers, `StrutLaws`).
        let rho_bar = self.laws.orifice_rho(p_c, ec.rho, p_r, er.rho);
        let q = piston_to_rod_flow(
            self.ca_b, self.ca_v, opening, p.k_l, dp, rho_bar, self.p_reg,
        );
        Chambers {
            r,
            vg: r.v_g0 * v,
            p_c,
            p_r,
            p_r_raw,
            q,
            ec,
            er,
        }
    }

    /// Eq 5.7 (x = z_s): the emulsion volumes `(V_c, V_r)` of both chambers; they cannot go
    /// below zero.
    #[inline]
    fn emulsion_volumes(&self, c: &Chambers, z: f64) -> (f64, f64) {
        let r = &c.r;
        let vc = (r.v_c0 + r.v_g0 - self.params.a_hc * z - c.vg).max(0.0);
        let vr = (r.v_r0 + self.a_ann * z).max(1e-12);
        (vc, vr)
    }

    /// Hydraulic compliances (m^3/Pa) of both chambers at deflection `z` and `state`, the
    /// linearisation of Eqs 5.4-5.7 and 5.11: piston side `V_g / (n P_hc) + V_c / beta_c`,
    /// rod side `V_r / beta_r` (the baseline gas law; a quasi-static spring's compliance).
    pub fn chamber_compliances(&self, z: f64, state: &[f64]) -> ChamberCompliance {
        let c = self.chambers(state);
        let (vc, vr) = self.emulsion_volumes(&c, z);
        ChamberCompliance {
            piston: c.vg / (self.params.n * c.p_c) + vc / c.ec.beta,
            rod: vr / c.er.beta,
        }
    }

    /// Rod-side pressure from its state, held above the vapour pressure.
    #[inline]
    fn rod_pressure(&self, p_r_raw: f64) -> f64 {
        p_r_raw.max(self.params.p_vap.max(1.0))
    }

    /// Both chamber pressures `(P_hc, P_hr)` (Pa, absolute) at `state`, as
    /// [`HpsStrut::evaluate`] computes them (Eq 5.4 for the piston side): what a hydraulic
    /// line at the chambers' ports sees.
    #[inline]
    pub fn chamber_pressures(&self, state: &[f64]) -> (f64, f64) {
        let r = self.reference(state[STATE_U]);
        let v = (state[0] / r.v_g0).max(1e-9);
        (
            self.piston_pressure(v, state).0,
            self.rod_pressure(state[1]),
        )
    }

    /// State derivatives at deflection `z` (m), velocity `zdot` (m/s): Eq 5.5 for the gas
    /// volume (with Eq 5.4 giving P_hc'), Eq 5.6 for P_hr, flows of Eq 5.12, emulsion
    /// properties of Eqs 5.9-5.11, volumes of Eq 5.7 (`x` of Eq 5.7 is `z_s`), the velocity
    /// amplitude of [`HpsStrut::amplitude_rate`]. No allocation.
    #[inline]
    pub fn derivatives(&self, z: f64, zdot: f64, state: &[f64], dstate: &mut [f64]) {
        let c = self.chambers(state);
        self.rates(&c, z, zdot, ChamberInflow::NONE, state, dstate);
    }

    #[inline]
    fn rates(
        &self,
        c: &Chambers,
        z: f64,
        zdot: f64,
        inflow: ChamberInflow,
        state: &[f64],
        dstate: &mut [f64],
    ) {
        let p = &self.params;
        let r = &c.r;
        let (vc, vr) = self.emulsion_volumes(c, z);
        let u_dot = Self::amplitude_rate(zdot, state[STATE_U]);
        // Eq 5.5 with P_hc' = -n P_hc V_g'/V_g (Eq 5.4), or the heat-transfer gas law.
        let (n_eff, heat) = match (self.idx_theta, self.ext.heat_transfer) {
            (Some(i), Some(h)) => {
                let th = state[i].max(1e-9);
                (h.kappa, vc / c.ec.beta * c.p_c * (1.0 - th) / (h.tau * th))
            }
            _ => (p.n, 0.0),
        };
        // Gas the growth law moves from the free gas into the emulsion leaves at the current
        // pressure: V_g falls with V_g0(u) at fixed V_g/V_g0, so P_hc does not jump.
        let transfer = c.vg / r.v_g0 * r.dvg0_du * u_dot;
        // An external inflow enters Eq 5.5 beside the flow to the rod side (`q - 0.0` is `q`
        // bit for bit: the strut without lines is unchanged).
        let vg_dot = (c.q - inflow.piston - p.a_hc * zdot + heat)
            / (1.0 + n_eff * c.p_c * vc / (c.ec.beta * c.vg))
            + transfer;
        dstate[0] = vg_dot;
        // Eq 5.6
        // The external inflow offsets the annulus' displacement (`x - 0.0` is `x` bit for bit).
        let displaced = self.a_ann * zdot - inflow.rod;
        let mut pr_dot = c.er.beta / vr * (c.ec.rho / c.er.rho * c.q - displaced);
        if pr_dot < 0.0 {
            let guard = 1.0 - (-(c.p_r_raw - p.p_vap) / CAVITATION_BAND).exp();
            pr_dot *= guard.clamp(0.0, 1.0);
        }
        dstate[1] = pr_dot;
        dstate[STATE_U] = u_dot;
        if let (Some(i), Some(h)) = (self.idx_theta, self.ext.heat_transfer) {
            let th = state[i];
            dstate[i] = -(h.kappa - 1.0) * th * (vg_dot - transfer) / c.vg + (1.0 - th) / h.tau;
        }
        if let (Some(i), Some(l)) = (self.idx_valve, self.ext.valve_lag) {
            let target = if c.p_c - c.p_r > 0.0 { 1.0 } else { 0.0 };
            dstate[i] = (target - state[i]) / l.tau;
        }
    }

    /// The one state-space evaluate: state derivatives into `dstate` (as
    /// [`HpsStrut::derivatives`]) and all outputs (Eq 5.1 force, pressures, friction with the
    /// band `v_h(u)`) at deflection `z` (m) and velocity `zdot` (m/s). No allocation.
    #[inline]
    pub fn evaluate(&self, z: f64, zdot: f64, state: &[f64], dstate: &mut [f64]) -> StrutOutputs {
        self.evaluate_with_inflow(z, zdot, ChamberInflow::NONE, state, dstate)
    }

    /// As [`HpsStrut::evaluate`], with external volume flows into the chambers (hydraulic
    /// lines at their ports, [`crate::interconnect`]) in the continuity equations 5.5 and
    /// 5.6. With [`ChamberInflow::NONE`] it is [`HpsStrut::evaluate`], bit for bit.
    #[inline]
    pub fn evaluate_with_inflow(
        &self,
        z: f64,
        zdot: f64,
        inflow: ChamberInflow,
        state: &[f64],
        dstate: &mut [f64],
    ) -> StrutOutputs {
        let c = self.chambers(state);
        self.rates(&c, z, zdot, inflow, state, dstate);
        self.outputs_of(&c, z, zdot, state)
    }

    /// Strut force F_h (N, positive compressive), Eq 5.1 with absolute pressures:
    /// `P_hc A_hc - P_hr (A_hc - A_hr) - p_amb A_hr + F_f`.
    #[inline]
    pub fn force(&self, z: f64, zdot: f64, state: &[f64]) -> f64 {
        self.outputs(z, zdot, state).force
    }

    /// All outputs at one instant.
    pub fn outputs(&self, z: f64, zdot: f64, state: &[f64]) -> StrutOutputs {
        let c = self.chambers(state);
        self.outputs_of(&c, z, zdot, state)
    }

    #[inline]
    fn outputs_of(&self, c: &Chambers, z: f64, zdot: f64, state: &[f64]) -> StrutOutputs {
        let p = &self.params;
        let u = state[STATE_U];
        let f_f = friction_force(&p.friction, &self.levels, z, zdot, p.friction.v_h(u));
        StrutOutputs {
            force: c.p_c * p.a_hc - c.p_r * self.a_ann - p.p_amb * p.a_hr + f_f,
            p_piston: c.p_c,
            p_rod: c.p_r,
            friction: f_f,
            spring_force: (c.p_c - p.p_amb) * p.a_hr,
            gas_volume: state[0],
            flow: c.q,
            velocity_amplitude: u,
        }
    }
}

/// Pressures, flow and emulsion of both chambers at one state.
#[derive(Debug, Clone, Copy)]
struct Chambers {
    r: Reference,
    vg: f64,
    p_c: f64,
    p_r: f64,
    p_r_raw: f64,
    q: f64,
    ec: Emulsion,
    er: Emulsion,
}
