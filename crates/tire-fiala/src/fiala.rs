//! The Fiala handling model as implemented in ADAMS/Tire, which the paper used for the
//! 29.5R29 (section 6.2.2): friction interpolated on a comprehensive slip, saturating
//! longitudinal force, brush-polynomial lateral force and aligning moment, and a rolling
//! resistance moment proportional to the load.
//!
//! With F_z > 0, slip ratio kappa and slip angle alpha (signs in [`crate::model`]):
//!
//! - comprehensive slip `S = min(1, sqrt(kappa^2 + tan^2 alpha))`,
//!   friction `U = U_max - (U_max - U_min) S`;
//! - critical slip `kappa_c = U F_z / (2 C_slip)`: `F_x = C_slip kappa` for
//!   `|kappa| <= kappa_c`, else `F_x = sign(kappa) (U F_z - (U F_z)^2 / (4 |kappa| C_slip))`;
//! - `H = 1 - C_alpha |tan alpha| / (3 U F_z)`; below the critical slip angle
//!   `atan(3 U F_z / C_alpha)` (H > 0): `F_y = sign(alpha) U F_z (1 - H^3)` and
//!   `M_z = sign(alpha) 2 U F_z R2 (1 - H) H^3` with `R2 = b / 2`; beyond it (full
//!   sliding) `F_y = sign(alpha) U F_z`, `M_z = 0`;
//! - `M_y = -f_r R F_z` (forward rolling).
//!
//! C_alpha may depend on F_z through a [`CorneringStiffnessTable`].

use crate::cornering::CorneringStiffnessTable;
use crate::error::TireError;
use crate::model::{clamp_alpha, loaded, HandlingModel, TireForces};
use crate::params::TireParams;

/// Validated Fiala tire (handling part of [`TireParams`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Fiala {
    c_alpha: CorneringStiffnessTable,
    c_slip: f64,
    u_max: f64,
    u_min: f64,
    half_width: f64,
    radius: f64,
    rolling_resistance: f64,
}

impl Fiala {
    /// Build from a parameter set after [`TireParams::validate`].
    pub fn new(params: &TireParams) -> Result<Self, TireError> {
        params.validate()?;
        Ok(Self {
            c_alpha: params.cornering_table()?,
            c_slip: params.longitudinal_stiffness_n,
            u_max: params.u_max,
            u_min: params.u_min,
            half_width: 0.5 * params.width_m,
            radius: params.unloaded_radius_m,
            rolling_resistance: params.rolling_resistance_coefficient,
        })
    }

    /// Cornering stiffness C_alpha (N/rad) at load `fz`.
    #[inline]
    pub fn cornering_stiffness(&self, fz: f64) -> f64 {
        self.c_alpha.at(fz)
    }

    /// Longitudinal slip stiffness C_slip (N).
    #[inline]
    pub fn longitudinal_stiffness(&self) -> f64 {
        self.c_slip
    }

    /// Friction coefficient U at comprehensive slip `S = min(1, sqrt(kappa^2 + tan^2 alpha))`.
    #[inline]
    pub fn friction(&self, kappa: f64, alpha: f64) -> f64 {
        let t = clamp_alpha(alpha).tan();
        let s = (kappa * kappa + t * t).sqrt().min(1.0);
        self.u_max - (self.u_max - self.u_min) * s
    }

    /// Critical slip ratio `|U F_z / (2 C_slip)|` beyond which F_x saturates.
    #[inline]
    pub fn critical_slip_ratio(&self, fz: f64, kappa: f64, alpha: f64) -> f64 {
        (self.friction(kappa, alpha) * fz / (2.0 * self.c_slip)).abs()
    }

    /// Critical slip angle `atan(3 U F_z / C_alpha)` (rad) beyond which the tread slides.
    #[inline]
    pub fn critical_slip_angle(&self, fz: f64, kappa: f64, alpha: f64) -> f64 {
        let c = self.c_alpha.at(fz);
        if c <= 0.0 {
            return std::f64::consts::FRAC_PI_2;
        }
        (3.0 * self.friction(kappa, alpha) * fz / c).atan()
    }
}

impl HandlingModel for Fiala {
    #[inline]
    fn forces(&self, fz: f64, kappa: f64, alpha: f64) -> TireForces {
        self.forces_on_surface(fz, kappa, alpha, 1.0)
    }
}

impl Fiala {
    /// Peak friction coefficient U_max of the parameter set (-).
    #[inline]
    pub fn peak_friction(&self) -> f64 {
        self.u_max
    }

    /// Forces on a surface whose friction is `friction_scale` times the one the tire's
    /// U_max / U_min were given for: `U = friction_scale (U_max - (U_max - U_min) S)`, the
    /// rest as in [`HandlingModel::forces`] (which is `friction_scale = 1`). A
    /// `friction_scale` that is not finite or below 0 counts as 0 (no horizontal force).
    #[inline]
    pub fn forces_on_surface(
        &self,
        fz: f64,
        kappa: f64,
        alpha: f64,
        friction_scale: f64,
    ) -> TireForces {
        if !loaded(fz) {
            return TireForces::ZERO;
        }
        let scale = if friction_scale.is_finite() {
            friction_scale.max(0.0)
        } else {
            0.0
        };
        let alpha = clamp_alpha(alpha);
        let tan_a = alpha.tan();
        let s = (kappa * kappa + tan_a * tan_a).sqrt().min(1.0);
        let u = scale * (self.u_max - (self.u_max - self.u_min) * s);
        let ufz = u * fz;

        // Longitudinal force: linear up to the critical slip, saturating beyond.
        let kappa_c = ufz / (2.0 * self.c_slip);
        let fx = if kappa.abs() <= kappa_c {
            self.c_slip * kappa
        } else {
            kappa.signum() * (ufz - ufz * ufz / (4.0 * kappa.abs() * self.c_slip))
        };

        // Lateral force and aligning moment: brush polynomial in H, sliding beyond H = 0.
        let c_alpha = self.c_alpha.at(fz);
        let h = 1.0 - c_alpha * tan_a.abs() / (3.0 * ufz);
        let sign = if alpha > 0.0 {
            1.0
        } else if alpha < 0.0 {
            -1.0
        } else {
            0.0
        };
        let (fy, mz) = if h > 0.0 {
            let h3 = h * h * h;
            (
                sign * ufz * (1.0 - h3),
                sign * 2.0 * ufz * self.half_width * (1.0 - h) * h3,
            )
        } else {
            (sign * ufz, 0.0)
        };

        TireForces {
            fx,
            fy,
            mz,
            my: -self.rolling_resistance * self.radius * fz,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tire() -> Fiala {
        let mut p = TireParams::nominal();
        p.cornering_stiffness_table.clear();
        p.cornering_stiffness_n_per_rad = 4.0e5;
        Fiala::new(&p).unwrap()
    }

    #[test]
    fn hand_computed_point() {
        // fz = 100 kN, alpha = 5 deg, kappa = 0: tan = 0.0874887, S = tan,
        // U = 0.8 - 0.2 S = 0.7825023, U fz = 78 250.23,
        // H = 1 - 4e5 * 0.0874887 / (3 * 78 250.23) = 0.8509250,
        // F_y = 78 250.23 (1 - H^3) = 30 037.75,
        // M_z = 2 * 78 250.23 * 0.35 * (1 - H) * H^3 = 5 031.09.
        let f = tire().forces(1e5, 0.0, 5f64.to_radians());
        let t = 5f64.to_radians().tan();
        let u = 0.8 - 0.2 * t;
        let h: f64 = 1.0 - 4e5 * t / (3.0 * u * 1e5);
        assert!((f.fy - u * 1e5 * (1.0 - h.powi(3))).abs() < 1e-6);
        assert!((f.fy - 30_037.75).abs() < 0.01, "{}", f.fy);
        assert!((f.mz - 5_031.09).abs() < 0.01, "{}", f.mz);
        assert_eq!(f.fx, 0.0);
        assert!((f.my + 0.03 * 1.0 * 1e5).abs() < 1e-9);
    }

    #[test]
    fn longitudinal_saturation_formula() {
        // kappa = 0.2, alpha = 0: S = 0.2, U = 0.76, U fz = 76 kN, kappa_c = 0.038,
        // F_x = 76e3 - 76e3^2 / (4 * 0.2 * 1e6) = 68 780.
        let f = tire().forces(1e5, 0.2, 0.0);
        assert!((f.fx - 68_780.0).abs() < 1e-6, "{}", f.fx);
        assert_eq!(f.fy, 0.0);
        assert_eq!(f.mz, 0.0);
    }

    #[test]
    fn surface_friction_scales_the_friction_coefficient() {
        let t = tire();
        // Full sliding at 60 deg: F_y = U F_z with U = U_min (S = 1).
        let a = 60f64.to_radians();
        assert_eq!(t.forces_on_surface(1e5, 0.0, a, 1.0), t.forces(1e5, 0.0, a));
        let half = t.forces_on_surface(1e5, 0.0, a, 0.5);
        assert!((half.fy - 0.5 * 0.6 * 1e5).abs() < 1e-6, "{half:?}");
        // The linear range is friction independent, the rolling resistance too.
        let small = t.forces_on_surface(1e5, 1e-4, 0.0, 0.5);
        assert!((small.fx - 1e6 * 1e-4).abs() < 1e-9);
        assert_eq!(small.my, t.forces(1e5, 1e-4, 0.0).my);
        for bad in [0.0, -1.0, f64::NAN] {
            let f = t.forces_on_surface(1e5, 0.2, 0.1, bad);
            assert_eq!((f.fx, f.fy, f.mz), (0.0, 0.0, 0.0), "{bad}");
        }
        assert_eq!(t.peak_friction(), 0.8);
    }

    #[test]
    fn zero_load_gives_nothing() {
        let t = tire();
        assert_eq!(t.forces(0.0, 0.3, 0.2), TireForces::ZERO);
        assert_eq!(t.forces(-5.0, 0.3, 0.2), TireForces::ZERO);
        assert_eq!(t.forces(f64::NAN, 0.3, 0.2), TireForces::ZERO);
    }

    #[test]
    fn load_dependent_stiffness_is_used() {
        let t = Fiala::new(&TireParams::nominal()).unwrap();
        let l = crate::cornering::TABLE_6_2_STATIC_LOADS_N;
        let a = 1e-6;
        let slope = t.forces(l[3], 0.0, a).fy / a;
        let expect = 7.5e3 * 180.0 / std::f64::consts::PI;
        assert!(
            (slope - expect).abs() / expect < 1e-4,
            "{slope} vs {expect}"
        );
    }
}
