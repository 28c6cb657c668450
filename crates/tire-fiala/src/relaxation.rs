//! First-order slip lag with a relaxation length (Eqs 2.7 and 3.16), written as state
//! derivatives that the vehicle integrator owns.
//!
//! Eq 3.16, `(sigma / u) d(alpha)/dt + alpha = alpha_s`, gives
//! `d(alpha)/dt = (alpha_s - alpha) |u| / sigma`: a time constant `tau = sigma / |u|`
//! that grows without bound as the speed goes to zero. To stay well behaved at standstill
//! the speed is regularised smoothly,
//! `|u|_eff = sqrt(u^2 + u_0^2)` with `u_0 =` [`LOW_SPEED_REGULARISATION`], so the time
//! constant is capped at `sigma / u_0` and the rate is finite, smooth and never divides by
//! zero. The error this introduces is below 0.5 % above 1 m/s. The same law lags the slip
//! ratio with the longitudinal relaxation length.

use vehicle_components::StateInfo;

use crate::error::{positive, TireError};
use crate::params::TireParams;

/// The states of the slip lags of Eq 3.16 for one tire, in the order of
/// [`Relaxation::rates`]: the lagged slip ratio kappa and slip angle alpha, both with the
/// typical magnitude 0.05 (a slip ratio of 5 %, a slip angle of 3 deg).
pub const SLIP_LAG_STATES: [StateInfo; 2] = [
    StateInfo::new("slip_ratio", "-", 0.05),
    StateInfo::new("slip_angle_rad", "rad", 0.05),
];

/// The state of the contact-velocity lag of Eq 2.7 for one tire
/// ([`contact_velocity_lag_rate`]): the lagged lateral contact velocity V_sy, typical
/// magnitude 0.1 m/s.
pub const CONTACT_VELOCITY_LAG_STATE: StateInfo =
    StateInfo::new("lateral_velocity_lag_m_s", "m/s", 0.1);

/// Speed u_0 (m/s) of the low-speed regularisation `|u|_eff = sqrt(u^2 + u_0^2)`.
pub const LOW_SPEED_REGULARISATION: f64 = 0.1;

/// Smallest relaxation length (m) [`slip_lag_rate`] uses, so a zero or negative length
/// passed by mistake cannot divide by zero. Validated constructors reject such lengths.
pub const MIN_RELAXATION_LENGTH: f64 = 1e-3;

/// Regularised speed magnitude `sqrt(u^2 + u_0^2)` (m/s).
#[inline]
pub fn regularised_speed(speed: f64) -> f64 {
    speed.hypot(LOW_SPEED_REGULARISATION)
}

/// First-order slip lag (Eqs 2.7, 3.16): d(alpha)/dt = (alpha_ss - alpha) * |u| / sigma,
/// regularised at low speed.
///
/// `alpha` is the lagged slip (state), `alpha_steady` the steady-state slip of Eq 3.17
/// (or a slip ratio for the longitudinal lag), `speed` the wheel's forward speed (m/s, any
/// sign) and `relaxation_length` sigma (m). Returns the state derivative (1/s). `|u|` is
/// replaced by [`regularised_speed`] and sigma by `max(sigma, MIN_RELAXATION_LENGTH)`.
#[inline]
pub fn slip_lag_rate(alpha: f64, alpha_steady: f64, speed: f64, relaxation_length: f64) -> f64 {
    lag_rate(
        alpha,
        alpha_steady,
        regularised_speed(speed),
        relaxation_length,
    )
}

/// [`slip_lag_rate`] with the regularised speed `|u|_eff` ([`regularised_speed`]) given, for
/// a model that also takes its slip from it and evaluates it once.
#[inline]
pub fn lag_rate(alpha: f64, alpha_steady: f64, regularised: f64, relaxation_length: f64) -> f64 {
    (alpha_steady - alpha) * regularised / relaxation_length.max(MIN_RELAXATION_LENGTH)
}

/// Eq 2.7 in velocity form: d(V_sy)/dt = |V_x|_eff / sigma_y (V_y - V_sy), the lagged
/// lateral contact velocity `v_sy` the state, with `|V_x|_eff` = [`regularised_speed`] of
/// the forward speed given as `regularised` (the slip angle of Eq 2.6 takes it too, so a
/// model evaluates it once per tire).
#[inline]
pub fn contact_velocity_lag_rate(
    v_sy: f64,
    v_y: f64,
    regularised: f64,
    relaxation_length: f64,
) -> f64 {
    lag_rate(v_sy, v_y, regularised, relaxation_length)
}

/// Longitudinal and lateral relaxation lengths of one tire (validated).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Relaxation {
    /// Longitudinal relaxation length (m), lags the slip ratio kappa.
    pub longitudinal_length: f64,
    /// Lateral relaxation length sigma_y (m), lags the slip angle alpha.
    pub lateral_length: f64,
}

impl Relaxation {
    /// Both lengths finite and > 0.
    pub fn new(longitudinal_length: f64, lateral_length: f64) -> Result<Self, TireError> {
        Ok(Self {
            longitudinal_length: positive("longitudinal_relaxation_length_m", longitudinal_length)?,
            lateral_length: positive("lateral_relaxation_length_m", lateral_length)?,
        })
    }

    /// From a parameter set.
    pub fn from_params(p: &TireParams) -> Result<Self, TireError> {
        Self::new(
            p.longitudinal_relaxation_length_m,
            p.lateral_relaxation_length_m,
        )
    }

    /// Derivatives `[d kappa/dt, d alpha/dt]` of the lagged slips `state = [kappa, alpha]`
    /// towards the steady-state slips `steady = [kappa_s, alpha_s]` at forward speed `speed`.
    #[inline]
    pub fn rates(&self, state: [f64; 2], steady: [f64; 2], speed: f64) -> [f64; 2] {
        [
            slip_lag_rate(state[0], steady[0], speed, self.longitudinal_length),
            slip_lag_rate(state[1], steady[1], speed, self.lateral_length),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn time_constant_is_sigma_over_u() {
        // u = 10 m/s, sigma = 1.2 m: tau = 0.12 s (regularisation error < 1e-4).
        let r = slip_lag_rate(0.0, 0.1, 10.0, 1.2);
        assert!((r - 0.1 / 0.12).abs() / r < 1e-4);
        // Symmetric in the direction of travel.
        assert_eq!(slip_lag_rate(0.0, 0.1, -10.0, 1.2), r);
    }

    #[test]
    fn zero_speed_and_zero_length_are_finite() {
        let r = slip_lag_rate(0.0, 0.1, 0.0, 1.2);
        assert!((r - 0.1 * LOW_SPEED_REGULARISATION / 1.2).abs() < 1e-15);
        assert!(slip_lag_rate(0.0, 0.1, 0.0, 0.0).is_finite());
        assert!(slip_lag_rate(0.0, 0.1, 3.0, -1.0).is_finite());
        assert!(Relaxation::new(0.0, 1.0).is_err());
    }

    #[test]
    fn integrated_lag_matches_the_exponential() {
        // Explicit Euler with a small step: alpha(t) = alpha_s (1 - exp(-t u / sigma)).
        let (u, sigma, alpha_s) = (5.0, 1.0, 0.05);
        let dt = 1e-5;
        let mut a = 0.0;
        let mut t = 0.0;
        while t < 0.2 - 1e-12 {
            a += dt * slip_lag_rate(a, alpha_s, u, sigma);
            t += dt;
        }
        let ueff = regularised_speed(u);
        let exact = alpha_s * (1.0 - (-0.2 * ueff / sigma).exp());
        assert!((a - exact).abs() < 1e-5, "{a} vs {exact}");
    }
}
