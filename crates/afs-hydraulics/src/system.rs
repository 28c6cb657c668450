//! The AFS component: parameters, states (P_c, P_r, theta_h), the supply flow, and the
//! planar adapter (articulation, its rate, steering-wheel angle -> joint torque) over the
//! strut-space core in `strut_space`.

use crate::error::AfsError;
use crate::extensions::AfsExtensions;
use crate::fluid::{chamber_energy_const, chamber_energy_general};
use crate::kinematics::{strut_kinematics, StrutKinematics};
use crate::params::AfsParams;
use crate::strut_space::StrutInput;
use crate::valve::{orifice_flow, orifice_flow_slope};

/// Inputs from the vehicle at one instant.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct AfsInput {
    /// Articulation angle theta (rad); + = the paper's right-hand turn (left strut extends).
    pub theta: f64,
    /// Articulation rate dtheta/dt (rad/s).
    pub theta_dot: f64,
    /// Steering-wheel angle theta_sw (rad); + = right-hand turn (valve feeds P_c).
    pub steer_wheel: f64,
}

/// Everything the component computes at one instant (besides the state derivatives).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct AfsOutput {
    /// Steering torque T_s about the joint (N·m); positive drives theta positive.
    /// T_s = F_L h_L - F_R h_R (Eq 3.1, obtained by virtual work).
    pub torque: f64,
    /// F_L, left strut force (N), positive pushing its mounts apart (extending), Eq 3.3.
    pub force_left: f64,
    /// F_R, right strut force (N), positive extending, Eq 3.3.
    pub force_right: f64,
    /// q_1, flow from the valve into the struts (m³/s), signed: + into the P_c group
    /// (right-hand turn), - into the P_r group (left-hand turn). Eq 3.11.
    pub q_supply: f64,
    /// q_2, flow from the struts to the reservoir (m³/s), signed: + out of the P_r group,
    /// - out of the P_c group. Eq 3.12.
    pub q_return: f64,
    /// Hydraulic supply power P_s,eff·|q_1| (W), the denominator integrand of Eq 4.7.
    pub supply_power: f64,
    /// Mechanical power delivered to the joint T_s·dtheta/dt (W), numerator of Eq 4.7.
    pub strut_power: f64,
    /// X = theta_sw - theta_h, relative spool angle (rad), clipped to the ±8.1 deg pin.
    pub spool_opening: f64,
    /// Normalised valve opening xi in [0, 1] (0 inside the dead band).
    pub valve_opening: f64,
    /// P_c (Pa, absolute), equal to `state[0]`.
    pub p_c: f64,
    /// P_r (Pa, absolute), equal to `state[1]`.
    pub p_r: f64,
    /// Supply pressure at the valve inlet (Pa); P_s unless the supply-droop extension is on.
    pub supply_pressure: f64,
    /// Total piston-seal leakage from the P_c to the P_r group, q_lL + q_lR (m³/s), Eq 3.5.
    pub q_leak: f64,
    /// d_L = l_L - l_0 (m), + = left strut extends (it extends in a right-hand turn).
    pub strut_left_disp: f64,
    /// d_R = l_R - l_0 (m), + = right strut extends.
    pub strut_right_disp: f64,
    /// Left steering arm h_L (m), Eq 3.2.
    pub arm_left: f64,
    /// Right steering arm h_R (m), Eq 3.2.
    pub arm_right: f64,
}

/// Hydraulic articulated frame steering component (Chapter 3.2.1, Chapter 4.2).
///
/// State vector (`N_STATES` = 3):
/// - `state[0]` = P_c (Pa, absolute): left piston side + right rod side, Eq 3.4 line 1;
/// - `state[1]` = P_r (Pa, absolute): left rod side + right piston side, Eq 3.4 line 2;
/// - `state[2]` = theta_h (rad): valve housing / gerotor angle, Eq 3.10 in rate form
///   dtheta_h/dt = sign(X)·|q_1|/(k_theta eta_g);
/// - `state[3]` = x_v (rad), only with the [`crate::ValveLag`] extension: the lagged spool
///   displacement that meters the flows ([`AfsSystem::n_states`] = 4).
///
/// Tolerances: pressures are 1e4..1.4e7 Pa and theta_h is O(0.1..10) rad. Integrate the
/// SI states with per-state absolute tolerances `atol * AfsSystem::STATE_TYPICAL[i]`
/// (`odeint::Atol::scaled`), e.g. atol 1e-6: 1 Pa for P_c, P_r and 1e-6 rad for theta_h.
#[derive(Debug, Clone, PartialEq)]
pub struct AfsSystem {
    params: AfsParams,
    ext: AfsExtensions,
    l0: f64,
    v_min: f64,
    inv_gerotor: f64,
}

impl AfsSystem {
    /// Number of states: [P_c, P_r, theta_h].
    pub const N_STATES: usize = 3;
    /// Typical magnitudes of the states (Pa, Pa, rad): they set the per-state absolute
    /// tolerances of a run (`atol * STATE_TYPICAL[i]`) and the component's
    /// [`vehicle_components::StateInfo::typical`].
    pub const STATE_TYPICAL: [f64; 3] = [1.0e6, 1.0e6, 1.0];

    /// Build the component with the baseline model (all extensions off).
    pub fn new(params: AfsParams) -> Result<Self, AfsError> {
        params.validate()?;
        let l0 = params.initial_strut_length();
        Ok(Self {
            v_min: params.min_volume_fraction * params.dead_volume_m3,
            inv_gerotor: 1.0 / (params.gerotor_displacement * params.gerotor_efficiency),
            l0,
            params,
            ext: AfsExtensions::default(),
        })
    }

    /// Switch on the given extensions (validated).
    pub fn with_extensions(mut self, ext: AfsExtensions) -> Result<Self, AfsError> {
        ext.validate()?;
        self.ext = ext;
        Ok(self)
    }

    /// Number of states of this configuration: [`Self::N_STATES`], plus the lagged spool
    /// displacement x_v (rad, index 3) when the valve-lag extension is on.
    pub fn n_states(&self) -> usize {
        Self::N_STATES + usize::from(self.ext.valve_lag.is_some())
    }

    /// The parameters.
    pub fn params(&self) -> &AfsParams {
        &self.params
    }

    /// The active extensions.
    pub fn extensions(&self) -> &AfsExtensions {
        &self.ext
    }

    /// Initial strut length l_0 (m).
    pub fn initial_strut_length(&self) -> f64 {
        self.l0
    }

    /// Strut kinematics at articulation `theta` (Eqs 3.2, 3.8).
    pub fn kinematics(&self, theta: f64) -> StrutKinematics {
        let p = &self.params;
        strut_kinematics(p.l1_m, p.l2_m, p.a0_rad, self.l0, theta)
    }

    /// Chamber-group volumes (V_1, V_2) at articulation `theta` (m³), Eq 3.7.
    pub fn volumes(&self, theta: f64) -> (f64, f64) {
        let k = self.kinematics(theta);
        self.strut_volumes(k.disp_left, k.disp_right)
    }

    /// Smallest chamber-group volume the continuity equations allow (m³).
    pub(crate) fn min_volume(&self) -> f64 {
        self.v_min
    }

    /// 1/(k_theta eta_g), the gerotor's rad per m³ (Eq 3.10).
    pub(crate) fn inv_gerotor(&self) -> f64 {
        self.inv_gerotor
    }

    /// Static equilibrium state at articulation `theta` with the valve centred
    /// (theta_h = 0, so a zero steering-wheel angle is inside the dead band): the two group
    /// pressures average `standby_pressure_pa` and give zero hydraulic torque,
    /// P_c (A_c h_L + A_r h_R) = P_r (A_r h_L + A_c h_R). At theta = 0 both equal the standby pressure.
    pub fn initial_state(&self, theta: f64) -> [f64; 3] {
        let p = &self.params;
        let k = self.kinematics(theta);
        let a = p.piston_area_m2 * k.arm_left + p.annulus_area_m2 * k.arm_right;
        let b = p.annulus_area_m2 * k.arm_left + p.piston_area_m2 * k.arm_right;
        let ps = p.standby_pressure_pa;
        // p_c = 2 ps b/(a+b), p_r = 2 ps a/(a+b)
        let (pc, pr) = if a + b > 0.0 {
            (2.0 * ps * b / (a + b), 2.0 * ps * a / (a + b))
        } else {
            (ps, ps)
        };
        [pc, pr, 0.0]
    }

    /// Effective bulk modulus at pressure `p` (Pa): B_eff, or the entrained-air law.
    #[inline]
    pub fn bulk_modulus(&self, p: f64) -> f64 {
        match &self.ext.entrained_air {
            None => self.params.bulk_modulus_pa,
            Some(air) => air.bulk_modulus(
                self.params.bulk_modulus_pa,
                p.max(self.params.cavitation_pressure_pa).max(1.0),
            ),
        }
    }

    /// Supply pressure at the valve and the supply flow magnitude for opening `xi` and fed
    /// chamber pressure `p_fed`: Eq 3.11 (with the inlet check valve), plus the droop
    /// extension P = P_s - r q solved by safeguarded Newton iteration.
    #[inline]
    pub(crate) fn supply_flow(&self, xi: f64, p_fed: f64) -> (f64, f64) {
        let p = &self.params;
        let g = |dp: f64| {
            let q = xi
                * orifice_flow(
                    dp,
                    p.valve_a0_per_pa,
                    p.valve_am,
                    p.valve_av,
                    p.sqrt_regularisation_pa,
                );
            if p.inlet_check_valve {
                q.max(0.0)
            } else {
                q
            }
        };
        let ps = p.supply_pressure_pa;
        match &self.ext.supply_droop {
            None => (ps, g(ps - p_fed)),
            Some(d) => {
                let r = d.droop_pa_s_per_m3;
                let q0 = g(ps - p_fed);
                if q0 == 0.0 || r == 0.0 {
                    return (ps, q0);
                }
                // root of h(P) = P - ps + r g(P - p_fed) between p_fed and ps
                let (mut lo, mut hi) = if p_fed < ps { (p_fed, ps) } else { (ps, p_fed) };
                let mut x = ps - r * q0;
                if !(x > lo && x < hi) {
                    x = 0.5 * (lo + hi);
                }
                for _ in 0..60 {
                    let hval = x - ps + r * g(x - p_fed);
                    if hval.abs() <= 1e-9 * ps {
                        break;
                    }
                    if hval > 0.0 {
                        hi = x;
                    } else {
                        lo = x;
                    }
                    let slope_g = if p.inlet_check_valve && g(x - p_fed) <= 0.0 {
                        0.0
                    } else {
                        xi * orifice_flow_slope(
                            x - p_fed,
                            p.valve_a0_per_pa,
                            p.valve_am,
                            p.valve_av,
                            p.sqrt_regularisation_pa,
                        )
                    };
                    let dh = 1.0 + r * slope_g;
                    let mut xn = x - hval / dh;
                    if !(dh > 0.0 && xn > lo && xn < hi) {
                        xn = 0.5 * (lo + hi);
                    }
                    x = xn;
                }
                (x, g(x - p_fed))
            }
        }
    }

    /// Evaluate the state derivatives and the outputs from the articulation joint's motion:
    /// the planar adapter over [`AfsSystem::strut_derivatives`]. Allocation-free.
    ///
    /// - Eqs 3.2, 3.8: strut lengths and arms at theta; the struts extend at
    ///   ḋ_L = h_L dtheta and ḋ_R = -h_R dtheta.
    /// - Eqs 3.3-3.12 in strut space (see [`AfsSystem::strut_derivatives`]).
    /// - Eq 3.1: T_s = F_L h_L - F_R h_R (virtual work).
    ///
    /// `state.len()` and `dstate.len()` must be at least [`Self::n_states`].
    pub fn derivatives(&self, input: &AfsInput, state: &[f64], dstate: &mut [f64]) -> AfsOutput {
        let thd = input.theta_dot;
        let k = self.kinematics(input.theta);
        let s = self.strut_derivatives(
            &StrutInput {
                disp_left: k.disp_left,
                disp_right: k.disp_right,
                vel_left: k.arm_left * thd,
                vel_right: -k.arm_right * thd,
                steer_wheel: input.steer_wheel,
            },
            state,
            dstate,
        );
        let torque = s.force_left * k.arm_left - s.force_right * k.arm_right;
        AfsOutput {
            torque,
            force_left: s.force_left,
            force_right: s.force_right,
            q_supply: s.q_supply,
            q_return: s.q_return,
            supply_power: s.supply_power,
            strut_power: torque * thd,
            spool_opening: s.spool_opening,
            valve_opening: s.valve_opening,
            p_c: s.p_c,
            p_r: s.p_r,
            supply_pressure: s.supply_pressure,
            q_leak: s.q_leak,
            strut_left_disp: k.disp_left,
            strut_right_disp: k.disp_right,
            arm_left: k.arm_left,
            arm_right: k.arm_right,
        }
    }

    /// Stored compression energy of both chamber groups (J) at articulation `theta` and
    /// `state`, relative to the reservoir pressure: with the valve closed, no leakage and no
    /// friction, d/dt(hydraulic_energy) = -T_s dtheta/dt along every trajectory (the
    /// energy-conservation check of the coupled model). The cavitation floor is dissipative
    /// and not represented (it is inactive above cavitation + band pressure).
    pub fn hydraulic_energy(&self, theta: f64, state: &[f64]) -> f64 {
        let (v1, v2) = self.volumes(theta);
        self.group_energy(v1, v2, state)
    }

    /// Compression energy of the two chamber groups at volumes `v1`, `v2` (J).
    pub(crate) fn group_energy(&self, v1: f64, v2: f64, state: &[f64]) -> f64 {
        let pref = self.params.reservoir_pressure_pa;
        match &self.ext.entrained_air {
            None => {
                let b = self.params.bulk_modulus_pa;
                chamber_energy_const(v1, state[0], b, pref)
                    + chamber_energy_const(v2, state[1], b, pref)
            }
            Some(_) => {
                let b = |pp: f64| self.bulk_modulus(pp);
                chamber_energy_general(v1, state[0], pref, b, 400)
                    + chamber_energy_general(v2, state[1], pref, b, 400)
            }
        }
    }

    /// Linearised torsional stiffness of the closed hydraulic circuit at `theta` and the
    /// given pressures (N·m/rad): B(P_c)(A_c h_L + A_r h_R)²/V_1 + B(P_r)(A_r h_L + A_c h_R)²/V_2.
    pub fn hydraulic_stiffness(&self, theta: f64, state: &[f64]) -> f64 {
        let p = &self.params;
        let k = self.kinematics(theta);
        let (v1, v2) = self.volumes(theta);
        let a = p.piston_area_m2 * k.arm_left + p.annulus_area_m2 * k.arm_right;
        let b = p.annulus_area_m2 * k.arm_left + p.piston_area_m2 * k.arm_right;
        self.bulk_modulus(state[0]) * a * a / v1 + self.bulk_modulus(state[1]) * b * b / v2
    }

    /// Steady-state steering ratio of the volume-regulated valve (rad articulation per rad
    /// steering wheel) at `theta` without leakage or compressibility: once X returns into the
    /// dead band, the delivered volume k_theta·eta_g·theta_sw fills the strut volume
    /// (A_c h_L + A_r h_R) dtheta.
    pub fn kinematic_steering_ratio(&self, theta: f64) -> f64 {
        let p = &self.params;
        let k = self.kinematics(theta);
        p.gerotor_displacement * p.gerotor_efficiency
            / (p.piston_area_m2 * k.arm_left + p.annulus_area_m2 * k.arm_right)
    }
}
