//! Slow thermal model of a loaded strut: gas temperature, strut-body temperature, the ride
//! height they set, and an optional levelling valve (`docs/layouts.md`, "HPS temperature and
//! ride height"). Time scale minutes to hours; the strut's fast gas law is
//! [`crate::HeatTransfer`] and this module reuses its parameters.
//!
//! Two lumped nodes, SI units, temperatures in kelvin:
//!
//! - **gas** (the free nitrogen charge, mass `m_g` from the static state, heat capacity at
//!   constant pressure `C_g = m_g c_p`: at a constant static load `F` the gas pressure is
//!   fixed, `P = F / A_hr + p_amb`, so slow heating is isobaric);
//! - **body** (steel of the strut plus its oil, `C_b = m_s c_s + m_oil c_oil`), which takes
//!   the damping dissipation `P_d` (orifices, leakage and seal friction heat the oil).
//!
//! ```text
//!   C_g T_g' = G_gb (T_b - T_g)
//!   C_b T_b' = P_d - G_gb (T_b - T_g) - G_ba (T_b - T_amb)
//!   G_gb = m_g c_v / tau        (the gas-wall exchange of HeatTransfer: T' = ... + (T_0 - T)/tau)
//!   G_ba = h_a A_a              (body to ambient)
//! ```
//!
//! Steady state: `T_b = T_g = T_amb + P_d / G_ba`. The enclosed volume at the fixed pressure
//! grows with temperature (ideal gas at constant pressure, oil thermal expansion), and with
//! both chambers at one static pressure the strut is a plunger of area `A_hr`, so the ride
//! height rises by
//!
//! ```text
//!   dh = [ V_g (T_g/T_ref - 1) + V_e (T_b/T_ref - 1) + beta_T V_oil (T_b - T_ref) + V_lev ] / A_hr
//! ```
//!
//! (`V_g`, `V_e`, `V_oil`: free gas (isothermal at rest: `V_g0 P_h0 / P`), entrapped gas
//! (Eq 5.9) and oil (Eq 5.8) at `P` and the charge temperature `T_ref`; `V_lev` the oil a levelling valve has added). The static
//! stiffness is `A_hr^2` over the compliance `(V_g(T_g) + V_e(T_b)) / (n P) + V_oil / beta_h`
//! (Eqs 5.4, 5.8-5.11 linearised at `P`): a hot strut is softer, and levelling oil does not
//! give the stiffness back.

use crate::error::HpsError;
use crate::extensions::{HeatTransfer, HpsExtensions};
use crate::params::StrutParams;
use crate::strut::HpsStrut;
use odeint::{Atol, Control, Integrator, OdeSystem, Solver};
use serde::{Deserialize, Serialize};

/// Specific gas constant of nitrogen (J/(kg K)): `8.314462 / 0.0280134`.
pub const R_NITROGEN: f64 = 296.8;
/// 0 degC in kelvin.
pub const KELVIN_AT_0C: f64 = 273.15;

/// Largest output grid of one run (samples).
const MAX_SAMPLES: f64 = 1e6;

/// Parameters of the two thermal nodes of one strut.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ThermalParams {
    /// The gas-wall exchange of the fast gas law ([`crate::HeatTransfer`]): its time constant
    /// `tau` at constant volume gives the gas-body conductance `G_gb = m_g c_v / tau`, its
    /// `kappa` the nitrogen's `c_v = R / (kappa - 1)`, `c_p = kappa c_v`.
    pub gas: HeatTransfer,
    /// Specific gas constant R of the charge (J/(kg K)).
    pub gas_constant_j_kg_k: f64,
    /// Temperature at which the strut's gas data (`p_h0`, `v_g0`) and the static ride height
    /// hold: the charge temperature T_ref (K).
    pub charge_temperature_k: f64,
    /// Steel mass of the strut body (kg).
    pub steel_mass_kg: f64,
    /// Specific heat of the steel (J/(kg K)).
    pub steel_specific_heat_j_kg_k: f64,
    /// Specific heat of the oil (J/(kg K)).
    pub oil_specific_heat_j_kg_k: f64,
    /// Volumetric thermal expansion coefficient of the oil beta_T (1/K).
    pub oil_expansion_per_k: f64,
    /// Outer surface of the strut that gives heat to the air A_a (m^2).
    pub outer_area_m2: f64,
    /// Heat-transfer coefficient body to ambient h_a (W/(m^2 K)).
    pub ambient_htc_w_m2_k: f64,
}

/// Piston area of the Table 6.3 strut (m^2), the size [`ThermalParams::for_strut`] scales from.
const FRONT_AXLE_A_HC: f64 = 0.038;

impl ThermalParams {
    /// The thermal data of the Table 6.3 front-axle strut. None of it is in the dissertation;
    /// each value is an assumption stated here and in docs/layouts.md:
    /// - gas-wall `tau` 3 s, kappa 1.4 (nitrogen): gas-charged accumulators of a few litres
    ///   have thermal time constants of seconds (Pourmovahed & Otis 1990); the slow model is
    ///   insensitive to it (the gas follows the body within `kappa tau`);
    /// - charge temperature 20 degC;
    /// - steel 150 kg: a 220 mm bore (A_hc 0.038 m^2) with 20 mm walls, a hollow 180 mm
    ///   rod and end eyes over about 0.7 m; specific heats 490 (steel) and 1900 (mineral
    ///   oil) J/(kg K), oil expansion 7e-4 1/K (mineral hydraulic oil);
    /// - outer surface 0.75 m^2 (cylinder 0.26 m x 0.7 m and the exposed rod), h_a 20
    ///   W/(m^2 K): forced convection in the air stream of a vehicle at working speed.
    pub fn front_axle() -> Self {
        Self {
            gas: HeatTransfer {
                tau: 3.0,
                kappa: 1.4,
            },
            gas_constant_j_kg_k: R_NITROGEN,
            charge_temperature_k: KELVIN_AT_0C + 20.0,
            steel_mass_kg: 150.0,
            steel_specific_heat_j_kg_k: 490.0,
            oil_specific_heat_j_kg_k: 1900.0,
            oil_expansion_per_k: 7e-4,
            outer_area_m2: 0.75,
            ambient_htc_w_m2_k: 20.0,
        }
    }

    /// [`ThermalParams::front_axle`] for a strut of piston area `A_hc`, at the front strut's
    /// length: steel mass with `A_hc / 0.038 m^2`, outer surface with its square root (the
    /// perimeter), as `vehicle_3d`'s scaled rear strut scales areas and volumes.
    pub fn for_strut(strut: &StrutParams) -> Result<Self, HpsError> {
        crate::error::positive("a_hc", strut.a_hc)?;
        let ratio = strut.a_hc / FRONT_AXLE_A_HC;
        let mut p = Self::front_axle();
        p.steel_mass_kg *= ratio;
        p.outer_area_m2 *= ratio.sqrt();
        p.validate()?;
        Ok(p)
    }

    /// Validate every field against its plausible range (the error names the field).
    pub fn validate(&self) -> Result<(), HpsError> {
        HpsExtensions {
            heat_transfer: Some(self.gas),
            ..HpsExtensions::none()
        }
        .validate()?;
        within("thermal.gas.tau", self.gas.tau, 1e-3, 1e3)?;
        within(
            "thermal.gas_constant_j_kg_k",
            self.gas_constant_j_kg_k,
            50.0,
            5000.0,
        )?;
        within(
            "thermal.charge_temperature_k",
            self.charge_temperature_k,
            200.0,
            450.0,
        )?;
        within("thermal.steel_mass_kg", self.steel_mass_kg, 1e-3, 1e5)?;
        within(
            "thermal.steel_specific_heat_j_kg_k",
            self.steel_specific_heat_j_kg_k,
            100.0,
            5000.0,
        )?;
        within(
            "thermal.oil_specific_heat_j_kg_k",
            self.oil_specific_heat_j_kg_k,
            100.0,
            5000.0,
        )?;
        within(
            "thermal.oil_expansion_per_k",
            self.oil_expansion_per_k,
            0.0,
            3e-3,
        )?;
        within("thermal.outer_area_m2", self.outer_area_m2, 1e-4, 100.0)?;
        within(
            "thermal.ambient_htc_w_m2_k",
            self.ambient_htc_w_m2_k,
            0.1,
            1e4,
        )?;
        Ok(())
    }
}

/// `value` finite and within `[lo, hi]`, else an error naming `field`.
fn within(field: &'static str, value: f64, lo: f64, hi: f64) -> Result<(), HpsError> {
    if value.is_finite() && value >= lo && value <= hi {
        Ok(())
    } else {
        Err(HpsError::InvalidParameter {
            field,
            value,
            reason: "outside its plausible range (see the rustdoc of the field's struct)",
        })
    }
}

/// A levelling valve: adds or drains oil when the ride height leaves a deadband about the
/// static ride height at the charge temperature, slowly and at a limited flow:
/// `V_lev' = -clamp(A_hr e / tau_v, -q_max, q_max)` with `e` the ride-height error beyond the
/// deadband (`dh - clamp(dh, -d, d)`). A first-order approach to the deadband edge: it never
/// crosses the edge, so it cannot overshoot.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LevellingValve {
    /// Half-width d of the deadband (m): inside it the valve is shut.
    pub deadband_m: f64,
    /// Time constant tau_v (s): slow, so the valve does not answer the ride motion.
    pub time_constant_s: f64,
    /// Largest flow q_max (m^3/s) of the levelling pump or the drain.
    pub max_flow_m3_s: f64,
}

impl LevellingValve {
    /// Assumed defaults (not in the dissertation; section 5.5 asks for a ride-height
    /// control): deadband +-5 mm (a mechanical height valve's dead zone), time constant
    /// 30 s (tens of seconds, slow against the ride's 1-3 Hz), 0.1 L/s (6 L/min) flow.
    pub fn default_valve() -> Self {
        Self {
            deadband_m: 0.005,
            time_constant_s: 30.0,
            max_flow_m3_s: 1e-4,
        }
    }

    /// Validate every field (the error names the field).
    pub fn validate(&self) -> Result<(), HpsError> {
        within("levelling.deadband_m", self.deadband_m, 0.0, 0.1)?;
        within(
            "levelling.time_constant_s",
            self.time_constant_s,
            0.1,
            3600.0,
        )?;
        within("levelling.max_flow_m3_s", self.max_flow_m3_s, 1e-9, 0.1)?;
        Ok(())
    }
}

/// Working conditions of one run.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ThermalConditions {
    /// Ambient temperature T_amb (K).
    pub ambient_k: f64,
    /// Mean damping dissipation P_d into the strut (W, >= 0).
    pub power_w: f64,
    /// Gas temperature at the start (K).
    pub initial_gas_k: f64,
    /// Body temperature at the start (K).
    pub initial_body_k: f64,
}

impl ThermalConditions {
    /// A strut that starts at the ambient temperature (parked overnight) and works at
    /// `power_w`.
    pub fn cold_start(ambient_k: f64, power_w: f64) -> Self {
        Self {
            ambient_k,
            power_w,
            initial_gas_k: ambient_k,
            initial_body_k: ambient_k,
        }
    }

    fn validate(&self) -> Result<(), HpsError> {
        within("ambient_k", self.ambient_k, 200.0, 450.0)?;
        within("power_w", self.power_w, 0.0, 1e6)?;
        within("initial_gas_k", self.initial_gas_k, 200.0, 600.0)?;
        within("initial_body_k", self.initial_body_k, 200.0, 600.0)?;
        Ok(())
    }
}

/// Time histories of a run (SI, temperatures in K).
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct ThermalRecord {
    /// Time (s).
    pub time_s: Vec<f64>,
    /// Gas temperature T_g (K).
    pub gas_k: Vec<f64>,
    /// Body temperature T_b (K).
    pub body_k: Vec<f64>,
    /// Ride-height change from the static ride height at the charge temperature (m, up
    /// positive = strut extended).
    pub ride_height_m: Vec<f64>,
    /// Oil the levelling valve has added (m^3, negative when drained).
    pub levelled_m3: Vec<f64>,
    /// Static stiffness (N/m).
    pub stiffness_n_m: Vec<f64>,
    /// Heat the body has given to the ambient since the start (J).
    pub heat_lost_j: Vec<f64>,
}

/// A strut under a constant static load with its thermal nodes and, optionally, a
/// levelling valve.
#[derive(Debug, Clone, PartialEq)]
pub struct ThermalStrut {
    params: StrutParams,
    thermal: ThermalParams,
    levelling: Option<LevellingValve>,
    load_n: f64,
    static_travel_m: f64,
    pressure_pa: f64,
    gas_volume_m3: f64,
    entrapped_gas_m3: f64,
    oil_volume_m3: f64,
    gas_mass_kg: f64,
    gas_capacity_j_k: f64,
    body_capacity_j_k: f64,
    g_gas_body_w_k: f64,
    g_body_ambient_w_k: f64,
}

impl ThermalStrut {
    /// The strut `params` carrying the static load `load_n` (N) at the charge temperature,
    /// with the thermal nodes `thermal`. The static state is the strut's own with the fast
    /// gas law [`crate::HeatTransfer`] (`thermal.gas`), whose gas at rest is isothermal
    /// ([`HpsStrut::initial_state`] at the deflection where its static force is the load):
    /// `V_g = V_g0 P_h0 / P`, so the gas mass `m_g = P V_g / (R T_ref) = P_h0 V_g0 / (R T_ref)`
    /// is the charge's at every load. Errors name the offending parameter; a load the strut
    /// cannot carry within its travel is refused.
    pub fn new(
        params: &StrutParams,
        thermal: &ThermalParams,
        load_n: f64,
    ) -> Result<Self, HpsError> {
        thermal.validate()?;
        crate::error::positive("load_n", load_n)?;
        // Over hours the gas is isothermal at rest: the strut with the fast heat-transfer
        // law has that static equilibrium (`HpsStrut::static_pressure`, gas exponent 1).
        let strut = HpsStrut::new(
            params,
            &HpsExtensions {
                heat_transfer: Some(thermal.gas),
                ..HpsExtensions::none()
            },
        )?;
        let z = static_deflection(&strut, load_n)?;
        let mut state = vec![0.0; strut.n_states()];
        strut.initial_state(z, &mut state)?;
        let p = params;
        let pressure = strut.static_pressure(z)?;
        let (oil_c, oil_r) = p.oil_volumes();
        let oil0 = oil_c + oil_r;
        // Eq 5.9: entrapped gas at the pressure; Eq 5.8: the oil compressed to it.
        let entrapped = p.gamma0 * oil0 * (p.p_h0 / pressure).powf(1.0 / p.n);
        let oil = oil0 * (1.0 - (pressure - p.p_h0) / p.beta_h);
        let gas = state[0];
        let t = thermal;
        let gas_mass = pressure * gas / (t.gas_constant_j_kg_k * t.charge_temperature_k);
        let c_v = t.gas_constant_j_kg_k / (t.gas.kappa - 1.0);
        Ok(Self {
            params: *p,
            thermal: *t,
            levelling: None,
            load_n,
            static_travel_m: z,
            pressure_pa: pressure,
            gas_volume_m3: gas,
            entrapped_gas_m3: entrapped,
            oil_volume_m3: oil,
            gas_mass_kg: gas_mass,
            gas_capacity_j_k: gas_mass * t.gas.kappa * c_v,
            body_capacity_j_k: t.steel_mass_kg * t.steel_specific_heat_j_kg_k
                + p.rho_h * oil0 * t.oil_specific_heat_j_kg_k,
            g_gas_body_w_k: gas_mass * c_v / t.gas.tau,
            g_body_ambient_w_k: t.ambient_htc_w_m2_k * t.outer_area_m2,
        })
    }

    /// The same strut with a levelling valve.
    pub fn with_levelling(mut self, valve: LevellingValve) -> Result<Self, HpsError> {
        valve.validate()?;
        self.levelling = Some(valve);
        Ok(self)
    }

    /// The levelling valve, if any.
    pub fn levelling(&self) -> Option<&LevellingValve> {
        self.levelling.as_ref()
    }

    /// The strut's parameters.
    pub fn params(&self) -> &StrutParams {
        &self.params
    }

    /// The thermal parameters.
    pub fn thermal(&self) -> &ThermalParams {
        &self.thermal
    }

    /// Static load (N).
    pub fn load_n(&self) -> f64 {
        self.load_n
    }

    /// Static deflection at the charge temperature (m, compression positive from
    /// mid-stroke), with the isothermal gas of a strut at rest for hours (the pseudo-static
    /// exponent `n` of `HpsStrut::new`'s statics sits a few mm lower: 5.7 mm on the loaded
    /// prototype's front strut).
    pub fn static_travel_m(&self) -> f64 {
        self.static_travel_m
    }

    /// Static pressure P (Pa, absolute), fixed by the load: `F / A_hr + p_amb`.
    pub fn pressure_pa(&self) -> f64 {
        self.pressure_pa
    }

    /// Free gas volume at P and the charge temperature (m^3).
    pub fn gas_volume_m3(&self) -> f64 {
        self.gas_volume_m3
    }

    /// Gas mass `P V_g / (R T_ref)` (kg).
    pub fn gas_mass_kg(&self) -> f64 {
        self.gas_mass_kg
    }

    /// Heat capacities `(C_g, C_b)` (J/K): gas at constant pressure, body (steel and oil).
    pub fn capacities_j_k(&self) -> (f64, f64) {
        (self.gas_capacity_j_k, self.body_capacity_j_k)
    }

    /// Conductances `(G_gb, G_ba)` (W/K): gas to body, body to ambient.
    pub fn conductances_w_k(&self) -> (f64, f64) {
        (self.g_gas_body_w_k, self.g_body_ambient_w_k)
    }

    /// Steady temperature of both nodes (K): `T_amb + P_d / G_ba`.
    pub fn steady_temperature_k(&self, ambient_k: f64, power_w: f64) -> f64 {
        ambient_k + power_w / self.g_body_ambient_w_k
    }

    /// The two time constants of the linear two-node system (s), fast (gas) then slow
    /// (body): `-1 / lambda` for the eigenvalues `lambda` of
    /// `[[-a, a], [c, -(c + d)]]`, `a = G_gb / C_g`, `c = G_gb / C_b`, `d = G_ba / C_b`.
    pub fn time_constants_s(&self) -> [f64; 2] {
        let a = self.g_gas_body_w_k / self.gas_capacity_j_k;
        let c = self.g_gas_body_w_k / self.body_capacity_j_k;
        let d = self.g_body_ambient_w_k / self.body_capacity_j_k;
        let s = a + c + d;
        let root = ((a - c - d).powi(2) + 4.0 * a * c).sqrt();
        // lambda = (-s -+ root)/2; the slow one as 2 a d / (s + root) (no cancellation).
        [2.0 / (s + root), (s + root) / (2.0 * a * d)]
    }

    /// Ride-height change (m, up positive) at gas temperature `gas_k`, body temperature
    /// `body_k` and levelled oil `levelled_m3` (module docs).
    pub fn ride_height_m(&self, gas_k: f64, body_k: f64, levelled_m3: f64) -> f64 {
        self.volume_change_m3(gas_k, body_k, levelled_m3) / self.params.a_hr
    }

    /// Ride-height change per kelvin of a uniformly warmer strut (m/K):
    /// `(V_g / T_ref + V_e / T_ref + beta_T V_oil) / A_hr`.
    pub fn ride_height_per_kelvin(&self) -> f64 {
        let t = self.thermal.charge_temperature_k;
        ((self.gas_volume_m3 + self.entrapped_gas_m3) / t
            + self.thermal.oil_expansion_per_k * self.oil_volume_m3)
            / self.params.a_hr
    }

    fn volume_change_m3(&self, gas_k: f64, body_k: f64, levelled_m3: f64) -> f64 {
        let t = &self.thermal;
        let t_ref = t.charge_temperature_k;
        self.gas_volume_m3 * (gas_k / t_ref - 1.0)
            + self.entrapped_gas_m3 * (body_k / t_ref - 1.0)
            + t.oil_expansion_per_k * self.oil_volume_m3 * (body_k - t_ref)
            + levelled_m3
    }

    /// Static stiffness (N/m) at the temperatures and levelled oil: `A_hr^2` over the
    /// compliance `(V_g(T_g) + V_e(T_b)) / (n P) + V_oil / beta_h` (Eqs 5.4, 5.8-5.11
    /// linearised at the fixed pressure, the polytropic gas of the ride's motions; at the
    /// charge temperature it is `A_hr^2` over the sum of [`HpsStrut::chamber_compliances`]
    /// at the static state).
    pub fn stiffness_n_m(&self, gas_k: f64, body_k: f64, levelled_m3: f64) -> f64 {
        let p = &self.params;
        let t_ref = self.thermal.charge_temperature_k;
        let gas = self.gas_volume_m3 * gas_k / t_ref + self.entrapped_gas_m3 * body_k / t_ref;
        let oil = self.oil_volume_m3 * (1.0 + self.thermal.oil_expansion_per_k * (body_k - t_ref))
            + levelled_m3;
        p.a_hr * p.a_hr / (gas / (p.n * self.pressure_pa) + oil / p.beta_h)
    }

    /// The strut's parameter set at gas temperature `gas_k`, body temperature `body_k` and
    /// levelled oil `levelled_m3`: the same hardware with the same gas and oil masses, for a
    /// dynamic run of the warm (or cold) strut, e.g. a D1 ride after a shift.
    ///
    /// The reference state of a parameter set is mid-stroke (`z_s = 0`) with both chambers at
    /// `P_h0`. At the new state, with `'` for its values:
    /// - the rod-side chamber's emulsion volume is geometry and stays `V_r0`; the piston side
    ///   holds the rest of the emulsion, so the free gas gives way to the oil's growth:
    ///   `V_g0' + V_c0' = V_g0 + V_c0`;
    /// - the oil (Eq 5.8 at the reference pressure, expanded by `beta_T`, plus the levelled
    ///   oil, a volume at the static pressure `P`):
    ///   `V_oil' = (V_oil (1 + beta_T (T_b - T_ref)) + V_lev / (1 - (P - P_h0) / beta_h)) (1 - (P_h0' - P_h0) / beta_h)`;
    /// - the entrapped gas keeps its mass at the oil's temperature, in Eq 5.9's form:
    ///   `gamma0' V_oil' P_h0'^(1/n) = gamma0 V_oil P_h0^(1/n) T_b / T_ref`;
    /// - the free gas keeps its mass (ideal gas): `P_h0' V_g0' = P_h0 V_g0 T_g / T_ref`;
    ///
    /// solved by fixed-point iteration on `P_h0'` (each pass moves it by the oil's and the
    /// entrapped gas's small share of the volume). With these, the strut's isothermal static
    /// state at its load sits [`ThermalStrut::ride_height_m`] higher and has
    /// [`ThermalStrut::stiffness_n_m`] (tested to second order in `1/beta_h`). At the charge
    /// temperature with no levelled oil it is this strut's set to round-off. Errors: a
    /// temperature not finite and > 0; levelled oil not finite, or draining more oil than
    /// the piston side holds; oil filling the free gas volume at mid-stroke; a set that fails
    /// [`StrutParams::validate`].
    pub fn strut_at(
        &self,
        gas_k: f64,
        body_k: f64,
        levelled_m3: f64,
    ) -> Result<StrutParams, HpsError> {
        crate::error::positive("gas_k", gas_k)?;
        crate::error::positive("body_k", body_k)?;
        if !levelled_m3.is_finite() {
            return Err(HpsError::InvalidParameter {
                field: "levelled_m3",
                value: levelled_m3,
                reason: "must be finite",
            });
        }
        let p = &self.params;
        let t_ref = self.thermal.charge_temperature_k;
        let (oil_c, oil_r) = p.oil_volumes();
        let oil = oil_c + oil_r;
        let levelled_at_reference = levelled_m3 / (1.0 - (self.pressure_pa - p.p_h0) / p.beta_h);
        let expanded = oil * (1.0 + self.thermal.oil_expansion_per_k * (body_k - t_ref))
            + levelled_at_reference;
        let gas_charge = p.p_h0 * p.v_g0 * gas_k / t_ref;
        let entrapped_charge = p.gamma0 * oil * p.p_h0.powf(1.0 / p.n) * body_k / t_ref;
        if expanded <= p.v_r0 / (1.0 + p.gamma0) {
            return Err(HpsError::InvalidParameter {
                field: "levelled_m3",
                value: levelled_m3,
                reason: "drains more oil than the piston side holds",
            });
        }
        let enclosed = p.v_g0 + p.v_c0;
        let mut q = *p;
        for _ in 0..100 {
            let oil_new = expanded * (1.0 - (q.p_h0 - p.p_h0) / p.beta_h);
            q.gamma0 = entrapped_charge / (oil_new * q.p_h0.powf(1.0 / p.n));
            q.v_r0 = p.v_r0;
            q.v_c0 = oil_new * (1.0 + q.gamma0) - q.v_r0;
            q.v_g0 = enclosed - q.v_c0;
            if q.v_g0 <= 0.0 {
                let (field, value) = if levelled_m3 > 0.0 {
                    ("levelled_m3", levelled_m3)
                } else {
                    ("body_k", body_k)
                };
                return Err(HpsError::InvalidParameter {
                    field,
                    value,
                    reason: "the oil would fill the free gas volume at mid-stroke",
                });
            }
            let next = gas_charge / q.v_g0;
            let done = (next - q.p_h0).abs() <= 1e-14 * next;
            q.p_h0 = next;
            if done {
                break;
            }
        }
        q.validate()?;
        Ok(q)
    }

    /// Run `duration_s` under `cond`, sampled every `output_dt_s`: temperatures, ride height,
    /// levelled oil, stiffness and the heat lost to the ambient (odeint Rosenbrock23, the
    /// gas node being stiff against the body). A valve that drains the piston side's whole
    /// oil (only at absurd temperatures: it drains the thermal growth) ends the run with an
    /// error at that time.
    pub fn run(
        &self,
        cond: &ThermalConditions,
        duration_s: f64,
        output_dt_s: f64,
    ) -> Result<ThermalRecord, HpsError> {
        cond.validate()?;
        crate::error::positive("duration_s", duration_s)?;
        crate::error::positive("output_dt_s", output_dt_s)?;
        let samples = duration_s / output_dt_s;
        if samples > MAX_SAMPLES {
            return Err(HpsError::InvalidExcitation(format!(
                "duration_s / output_dt_s = {samples:e} samples, at most {MAX_SAMPLES:e}"
            )));
        }
        let mut ts = odeint::output_grid(0.0, duration_s, output_dt_s);
        if duration_s - ts[ts.len() - 1] > 1e-9 * duration_s {
            ts.push(duration_s);
        }
        let sys = Nodes {
            strut: self,
            ambient_k: cond.ambient_k,
            power_w: cond.power_w,
        };
        let y0 = [cond.initial_gas_k, cond.initial_body_k, 0.0, 0.0];
        let mut rec = ThermalRecord::default();
        let piston_side_oil = self.params.oil_volumes().0;
        let mut drained_at = None;
        let mut observe = |t: f64, y: &[f64]| {
            if -y[2] >= piston_side_oil {
                drained_at = Some(t);
                return Control::Stop;
            }
            rec.time_s.push(t);
            rec.gas_k.push(y[0]);
            rec.body_k.push(y[1]);
            rec.ride_height_m.push(self.ride_height_m(y[0], y[1], y[2]));
            rec.levelled_m3.push(y[2]);
            rec.stiffness_n_m.push(self.stiffness_n_m(y[0], y[1], y[2]));
            rec.heat_lost_j.push(y[3]);
            Control::Continue
        };
        let typical = [
            300.0,
            300.0,
            self.params.a_hr * 0.01,
            self.body_capacity_j_k * 10.0,
        ];
        Integrator::new(Solver::Rosenbrock23, 1e-8, Atol::scaled(1e-8, typical))
            .with_max_steps(10_000_000)
            .integrate(&sys, 0.0, &y0, &ts, &mut observe)?;
        if let Some(t) = drained_at {
            return Err(HpsError::OutOfRange {
                t,
                reason: format!(
                    "the levelling valve drained the piston side's {:.2} L of oil",
                    piston_side_oil * 1e3
                ),
            });
        }
        Ok(rec)
    }

    /// Levelling flow into the strut (m^3/s) at ride-height change `dh` (m): zero without a
    /// valve or inside the deadband.
    #[inline]
    pub fn levelling_flow_m3_s(&self, dh: f64) -> f64 {
        match &self.levelling {
            None => 0.0,
            Some(v) => {
                let excess = dh - dh.clamp(-v.deadband_m, v.deadband_m);
                let q = self.params.a_hr * excess / v.time_constant_s;
                -q.clamp(-v.max_flow_m3_s, v.max_flow_m3_s)
            }
        }
    }
}

/// Mean power (W) the strut `params` turns into heat along a displacement record (`time_s`
/// strictly increasing, `displacement_m` the deflection `z_s`, compression positive, e.g. a
/// vehicle ride's strut travel): the record replayed through the strut
/// ([`crate::simulate_displacement`], sampled excitation, velocity by central differences,
/// starting at rest in static equilibrium), `P_d = (int F z' dt - int_{z_0}^{z_end} F_s dz)
/// / T`: the work done on the strut less the change of its static spring energy (`F_s` the
/// static force, [`HpsStrut::static_force`], Simpson's rule). What is left is the orifice,
/// leakage and friction losses (Eqs 5.1-5.12) plus the change of the dynamic part of the
/// stored energy, which does not grow with the record's length.
pub fn mean_dissipation_w(
    params: &StrutParams,
    time_s: &[f64],
    displacement_m: &[f64],
) -> Result<f64, HpsError> {
    let exc = crate::Excitation::Samples {
        time_s: time_s.to_vec(),
        displacement_m: displacement_m.to_vec(),
        velocity_m_s: None,
    };
    let ext = HpsExtensions::none();
    let rec = crate::simulate_displacement(params, &ext, &exc, &crate::SimOptions::default())?;
    let mut work = 0.0;
    for i in 1..rec.time.len() {
        let dt = rec.time[i] - rec.time[i - 1];
        work +=
            0.5 * dt * (rec.force[i] * rec.velocity[i] + rec.force[i - 1] * rec.velocity[i - 1]);
    }
    let strut = HpsStrut::new(params, &ext)?;
    let (z0, z1) = (displacement_m[0], displacement_m[displacement_m.len() - 1]);
    let intervals = 16;
    let h = (z1 - z0) / intervals as f64;
    let mut spring = 0.0;
    for k in 0..=intervals {
        let w = if k == 0 || k == intervals {
            1.0
        } else if k % 2 == 1 {
            4.0
        } else {
            2.0
        };
        spring += w * strut.static_force(z0 + k as f64 * h)?;
    }
    spring *= h / 3.0;
    let duration = time_s[time_s.len() - 1] - time_s[0];
    Ok((work - spring) / duration)
}

/// Deflection (m) at which `strut`'s static force is `load` (N), by bisection over the
/// travel; a load outside the travel is refused.
fn static_deflection(strut: &HpsStrut, load: f64) -> Result<f64, HpsError> {
    let travel = strut.params().travel;
    let (mut lo, mut hi) = (-travel, travel);
    if !(strut.static_force(lo)? <= load && strut.static_force(hi)? >= load) {
        return Err(HpsError::InvalidParameter {
            field: "load_n",
            value: load,
            reason: "the strut cannot carry this static load within its travel",
        });
    }
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if strut.static_force(mid)? < load {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(0.5 * (lo + hi))
}

/// The right-hand side: states `[T_g, T_b, V_lev, Q_lost]`.
struct Nodes<'a> {
    strut: &'a ThermalStrut,
    ambient_k: f64,
    power_w: f64,
}

impl OdeSystem for Nodes<'_> {
    fn dim(&self) -> usize {
        4
    }

    #[inline]
    fn rhs(&self, _t: f64, y: &[f64], dydt: &mut [f64]) {
        let s = self.strut;
        let to_gas = s.g_gas_body_w_k * (y[1] - y[0]);
        let lost = s.g_body_ambient_w_k * (y[1] - self.ambient_k);
        dydt[0] = to_gas / s.gas_capacity_j_k;
        dydt[1] = (self.power_w - to_gas - lost) / s.body_capacity_j_k;
        dydt[2] = s.levelling_flow_m3_s(s.ride_height_m(y[0], y[1], y[2]));
        dydt[3] = lost;
    }

    fn is_stiff(&self) -> bool {
        true
    }
}
