//! The interface every steady-state handling model implements, and its output.
//!
//! Axes and signs (see `docs/tire-fiala.md`): ISO 8855 wheel axes, x forward along the
//! wheel heading, y to the left, z up. The slip angle has the paper's sign (Eq 3.17):
//! `alpha = -atan(V_sy / |V_x|)`, positive when the contact patch slides to the right,
//! so a positive slip angle gives a positive (leftward) lateral force, `F_y ≈ C_alpha alpha`.
//! The longitudinal slip ratio is `kappa = (omega R_e - V_x) / |V_x|`, positive in traction,
//! so `F_x ≈ C_slip kappa` is positive forward.

use serde::{Deserialize, Serialize};

/// Forces and moments at the contact patch of one tire.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
pub struct TireForces {
    /// Longitudinal force F_x (N), positive forward (traction).
    pub fx: f64,
    /// Lateral (cornering) force F_y = Y (N), positive to the left; same sign as alpha.
    pub fy: f64,
    /// Aligning moment M_z (N m) with the paper's sign (Eqs 3.13, 3.15): same sign as
    /// alpha at small slip, i.e. it acts to reduce the slip angle. The moment about the
    /// upward z axis applied to the wheel is `-mz` ([`TireForces::yaw_moment_z_up`]).
    pub mz: f64,
    /// Rolling-resistance moment M_y (N m) about the wheel's y axis (left), negative for a
    /// wheel rolling forward (it opposes the spin).
    pub my: f64,
}

impl TireForces {
    /// All zero: the force set of a wheel out of contact (F_z <= 0).
    pub const ZERO: Self = Self {
        fx: 0.0,
        fy: 0.0,
        mz: 0.0,
        my: 0.0,
    };

    /// Moment about the upward z axis (right-handed, ISO) acting on the wheel: `-mz`.
    #[inline]
    pub fn yaw_moment_z_up(&self) -> f64 {
        -self.mz
    }
}

/// A steady-state tire handling model: forces from normal load and slips.
///
/// Every implementation returns [`TireForces::ZERO`] for `fz <= 0` (or NaN): a tire out
/// of contact transmits nothing. Slip angles are clamped to `[-pi/2, pi/2]`.
pub trait HandlingModel {
    /// Forces for normal load `fz` (N, positive in compression), longitudinal slip ratio
    /// `kappa` (-) and slip angle `alpha` (rad), signs as in the module docs.
    fn forces(&self, fz: f64, kappa: f64, alpha: f64) -> TireForces;
}

impl<T: HandlingModel + ?Sized> HandlingModel for &T {
    #[inline]
    fn forces(&self, fz: f64, kappa: f64, alpha: f64) -> TireForces {
        (**self).forces(fz, kappa, alpha)
    }
}

/// Clamp a slip angle to `[-pi/2, pi/2]` (NaN stays NaN; callers check `fz` first).
#[inline]
pub(crate) fn clamp_alpha(alpha: f64) -> f64 {
    alpha.clamp(-std::f64::consts::FRAC_PI_2, std::f64::consts::FRAC_PI_2)
}

/// `true` when the tire carries load (`fz > 0`, not NaN).
#[inline]
pub(crate) fn loaded(fz: f64) -> bool {
    fz > 0.0 && fz.is_finite()
}
