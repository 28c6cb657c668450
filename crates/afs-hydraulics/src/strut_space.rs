//! The strut-space core of the AFS component (Eqs 6.6-6.8): the hydraulics seen from the two
//! steering struts, with no articulation joint.
//!
//! The planar vehicle knows an articulation angle; the 3-D vehicle of Chapter 6 knows the world
//! positions of the four spherical strut mounts. Both reduce to the same four numbers per
//! instant: each strut's extension from its initial length and its extension rate. This module
//! takes those ([`StrutInput`]) and returns the strut axial forces and the hydraulic outputs
//! ([`StrutOutput`]); [`AfsSystem::derivatives`] is the planar adapter over it.
//!
//! **Convention.** Both displacements are extensions, `d_L = l_L - l_0`, `d_R = l_R - l_0`,
//! and both forces are positive extending, so a strut delivers the power `F ḋ` to its mounts.
//! Eq 6.7 of the dissertation measures the right strut's *shortening* (`d_R = l_0 - l_R`, see
//! docs/afs-hydraulics.md); with that sign flipped, Eqs 6.6-6.8 are exactly the code below.

use crate::fluid::{cavitation_factor, chamber_volumes};
use crate::system::AfsSystem;
use crate::valve::{normalised_opening, orifice_flow};

/// The two struts' motion and the steering-wheel angle at one instant.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct StrutInput {
    /// d_L = l_L - l_0, left-strut extension from its initial length (m).
    pub disp_left: f64,
    /// d_R = l_R - l_0, right-strut extension from its initial length (m). Eq 6.7's d_R is
    /// the negative of this (it measures shortening).
    pub disp_right: f64,
    /// Left-strut extension rate ḋ_L (m/s).
    pub vel_left: f64,
    /// Right-strut extension rate ḋ_R (m/s), positive extending.
    pub vel_right: f64,
    /// Steering-wheel angle theta_sw (rad); + = right-hand turn (valve feeds P_c).
    pub steer_wheel: f64,
}

/// What the strut-space core computes at one instant (besides the state derivatives).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct StrutOutput {
    /// F_L, left strut axial force (N), positive pushing its mounts apart, Eq 6.8 / 3.3.
    pub force_left: f64,
    /// F_R, right strut axial force (N), positive extending, Eq 6.8 (corrected) / 3.3.
    pub force_right: f64,
    /// q_1, flow from the valve into the struts (m³/s), + into the P_c group. Eq 3.11.
    pub q_supply: f64,
    /// q_2, flow from the struts to the reservoir (m³/s), + out of the P_r group. Eq 3.12.
    pub q_return: f64,
    /// Hydraulic supply power P_s,eff·|q_1| (W), the denominator integrand of Eq 4.7.
    pub supply_power: f64,
    /// Power the struts deliver to their mounts, F_L ḋ_L + F_R ḋ_R (W); in the planar
    /// limit it equals T_s·dtheta/dt, the numerator integrand of Eq 4.7.
    pub strut_power: f64,
    /// X = theta_sw - theta_h (or the lagged spool), clipped to the ±8.1 deg pin (rad).
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
}

impl AfsSystem {
    /// Chamber-group volumes (V_1, V_2) at strut extensions `d_L`, `d_R` (m³), Eq 6.7 / 3.7.
    pub fn strut_volumes(&self, disp_left: f64, disp_right: f64) -> (f64, f64) {
        let p = self.params();
        chamber_volumes(
            p.dead_volume_m3,
            p.piston_area_m2,
            p.annulus_area_m2,
            disp_left,
            disp_right,
            self.min_volume(),
        )
    }

    /// State derivatives and outputs from the struts' motion. Allocation-free.
    ///
    /// - Eq 6.7: V_1 = V_0 + A_c d_L - A_r d_R, V_2 = V_0 - A_r d_L + A_c d_R (extensions).
    /// - Eq 6.6 / 3.4 with Eqs 3.5-3.6: V_1/B dP_c = q_c - (A_c ḋ_L - A_r ḋ_R) - q_l,
    ///   V_2/B dP_r = q_r - (-A_r ḋ_L + A_c ḋ_R) + q_l; leakage k_l0 + k_l |ḋ| per strut;
    ///   (q_c, q_r) = (q_1, -q_2) for X > X_0 and (-q_2, q_1) for X < -X_0; cavitation floor
    ///   on expansion.
    /// - Eqs 3.9-3.12: X = theta_sw - theta_h, q_1, q_2 with the normalised opening.
    /// - Eq 3.10: dtheta_h/dt = sign(X) q_1/(k_theta eta_g).
    /// - Eq 6.8 / 3.3: F_L = A_c P_c - A_r P_r - mu_v ḋ_L, F_R = A_c P_r - A_r P_c - mu_v ḋ_R
    ///   (+ optional Coulomb friction per strut).
    ///
    /// `state.len()` and `dstate.len()` must be at least [`AfsSystem::n_states`].
    // Inlined into the planar adapter: without it the adapter costs 7 % of the planar
    // evaluate (49.5 ns instead of 46.5 ns, criterion `afs_derivatives_baseline`).
    #[inline(always)]
    pub fn strut_derivatives(
        &self,
        input: &StrutInput,
        state: &[f64],
        dstate: &mut [f64],
    ) -> StrutOutput {
        let p = self.params();
        let ext = self.extensions();
        let (pc, pr, theta_h) = (state[0], state[1], state[2]);
        let (ac, ar) = (p.piston_area_m2, p.annulus_area_m2);
        let (v_left, v_right) = (input.vel_left, input.vel_right);

        // volumes (Eq 6.7) and their rates
        let (v1, v2) = self.strut_volumes(input.disp_left, input.disp_right);
        let dv1 = ac * v_left - ar * v_right;
        let dv2 = -ar * v_left + ac * v_right;

        // leakage (Eqs 3.5, 3.6 with |ḋ| per strut)
        let (kll, klr) = if ext.constant_leakage_only {
            (p.leak_const, p.leak_const)
        } else {
            (
                p.leak_const + p.leak_velocity * v_left.abs(),
                p.leak_const + p.leak_velocity * v_right.abs(),
            )
        };
        let q_leak = (kll + klr) * (pc - pr);

        // valve (Eqs 3.9, 3.11, 3.12); with the valve-lag extension the metering spool
        // follows the commanded X with a first-order lag (state 3)
        let x_cmd = input.steer_wheel - theta_h;
        let x = match &ext.valve_lag {
            None => x_cmd,
            Some(lag) => {
                dstate[3] = (x_cmd - state[3]) / lag.tau_s;
                state[3]
            }
        };
        let xi = normalised_opening(x, p.dead_band_rad, p.spool_limit_rad);
        let (mut q_c, mut q_r, mut q1, mut q2, mut p_sup) =
            (0.0, 0.0, 0.0, 0.0, p.supply_pressure_pa);
        if xi > 0.0 {
            let ret = |p_drain: f64| {
                p.return_factor
                    * xi
                    * orifice_flow(
                        p_drain - p.reservoir_pressure_pa,
                        p.valve_a0_per_pa,
                        p.valve_am,
                        p.valve_av,
                        p.sqrt_regularisation_pa,
                    )
            };
            if x > 0.0 {
                let (ps, qs) = self.supply_flow(xi, pc);
                let qd = ret(pr);
                (q_c, q_r, q1, q2, p_sup) = (qs, -qd, qs, qd, ps);
            } else {
                let (ps, qs) = self.supply_flow(xi, pr);
                let qd = ret(pc);
                (q_c, q_r, q1, q2, p_sup) = (-qd, qs, -qs, -qd, ps);
            }
        }

        // continuity with cavitation floor (Eqs 6.6 / 3.4 / 4.5)
        let net_c = q_c - dv1 - q_leak;
        let net_r = q_r - dv2 + q_leak;
        let mut b_c = self.bulk_modulus(pc);
        if net_c < 0.0 {
            b_c *= cavitation_factor(pc, p.cavitation_pressure_pa, p.cavitation_band_pa);
        }
        let mut b_r = self.bulk_modulus(pr);
        if net_r < 0.0 {
            b_r *= cavitation_factor(pr, p.cavitation_pressure_pa, p.cavitation_band_pa);
        }
        dstate[0] = b_c / v1 * net_c;
        dstate[1] = b_r / v2 * net_r;
        // gerotor (Eq 3.10); q1 is signed like X
        dstate[2] = q1 * self.inv_gerotor();

        // strut forces (Eq 6.8 / 3.3)
        let mut f_l = ac * pc - ar * pr - p.seal_viscous_n_s_m * v_left;
        let mut f_r = ac * pr - ar * pc - p.seal_viscous_n_s_m * v_right;
        if let Some(cf) = &ext.coulomb_friction {
            f_l -= cf.force_n * (v_left / cf.velocity_scale_m_s).tanh();
            f_r -= cf.force_n * (v_right / cf.velocity_scale_m_s).tanh();
        }

        StrutOutput {
            force_left: f_l,
            force_right: f_r,
            q_supply: q1,
            q_return: q2,
            supply_power: p_sup * q1.abs(),
            strut_power: f_l * v_left + f_r * v_right,
            spool_opening: x.clamp(-p.spool_limit_rad, p.spool_limit_rad),
            valve_opening: xi,
            p_c: pc,
            p_r: pr,
            supply_pressure: p_sup,
            q_leak,
        }
    }

    /// Stored compression energy of both chamber groups (J) at strut extensions `d_L`, `d_R`
    /// and `state`, relative to the reservoir pressure. With the valve closed, no leakage and
    /// no friction, d/dt(energy) = -(F_L ḋ_L + F_R ḋ_R) along every trajectory.
    pub fn strut_hydraulic_energy(&self, disp_left: f64, disp_right: f64, state: &[f64]) -> f64 {
        let (v1, v2) = self.strut_volumes(disp_left, disp_right);
        self.group_energy(v1, v2, state)
    }
}
