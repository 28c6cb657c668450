//! Cornering-force laws other than Fiala: the linear model of Eq 3.15, the load-dependent
//! cornering stiffness of section 2.2.1 / Table 6.2, and the empirical off-road laws of
//! Eq 1.3 (exponential, McAllister) and Eq 1.4 (traction-dependent, Krick).

use crate::error::{finite, non_negative, positive, TireError};
use crate::model::{clamp_alpha, loaded, HandlingModel, TireForces};
use crate::table::Table;

/// Linear cornering model of Eq 3.15: Y = C_alpha * alpha, M_z = k_mz * alpha.
///
/// Signs: alpha as in Eq 3.17 (positive when the contact patch slides to the right), Y
/// positive to the left, M_z with the paper's sign (same as alpha); see [`crate::model`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinearCornering {
    /// Cornering stiffness C_alpha (N/rad); Table 3.1 gives 4.5 kN/deg front (loaded).
    pub cornering_stiffness: f64,
    /// Aligning-moment coefficient k_mz (N m/rad); Table 3.1 gives 3.8 kN m/deg front.
    pub aligning_coefficient: f64,
}

impl LinearCornering {
    /// Validated model: `cornering_stiffness` finite and > 0, `aligning_coefficient` finite
    /// and >= 0.
    pub fn new(cornering_stiffness: f64, aligning_coefficient: f64) -> Result<Self, TireError> {
        Ok(Self {
            cornering_stiffness: positive("cornering_stiffness", cornering_stiffness)?,
            aligning_coefficient: non_negative("aligning_coefficient", aligning_coefficient)?,
        })
    }

    /// Cornering force Y = C_alpha alpha (Eq 3.15), N.
    #[inline]
    pub fn lateral_force(&self, alpha: f64) -> f64 {
        self.cornering_stiffness * alpha
    }

    /// Aligning moment M_z = k_mz alpha (Eq 3.15), N m, paper's sign.
    #[inline]
    pub fn aligning_moment(&self, alpha: f64) -> f64 {
        self.aligning_coefficient * alpha
    }
}

impl HandlingModel for LinearCornering {
    /// Eq 3.15 behind the common interface: no longitudinal force, no rolling resistance,
    /// and nothing at all when `fz <= 0` (lift-off). The load does not otherwise enter.
    #[inline]
    fn forces(&self, fz: f64, _kappa: f64, alpha: f64) -> TireForces {
        if !loaded(fz) {
            return TireForces::ZERO;
        }
        let a = clamp_alpha(alpha);
        TireForces {
            fx: 0.0,
            fy: self.lateral_force(a),
            mz: self.aligning_moment(a),
            my: 0.0,
        }
    }
}

/// Cornering stiffness of the 29.5R29 from Table 6.2, N/deg: front axle, loaded vehicle.
pub const C_ALPHA_FRONT_LOADED_N_PER_DEG: f64 = 6.8e3;
/// Table 6.2: front axle, unloaded vehicle (N/deg).
pub const C_ALPHA_FRONT_UNLOADED_N_PER_DEG: f64 = 6.1e3;
/// Table 6.2: rear axle, loaded vehicle (N/deg).
pub const C_ALPHA_REAR_LOADED_N_PER_DEG: f64 = 7.5e3;
/// Table 6.2: rear axle, unloaded vehicle (N/deg).
pub const C_ALPHA_REAR_UNLOADED_N_PER_DEG: f64 = 3.7e3;

/// Static load per tire (N) that goes with each Table 6.2 entry, derived from the Table 6.1
/// masses and geometry (pitch-rigid articulation joint, g = 9.81 m/s^2; derivation in
/// `docs/tire-fiala.md`): `[front unloaded, front loaded, rear unloaded, rear loaded]`.
pub const TABLE_6_2_STATIC_LOADS_N: [f64; 4] = [122_692.0, 149_828.0, 71_056.0, 209_316.0];

/// Load-dependent cornering stiffness C_alpha(F_z): linear interpolation between rows and
/// linear extrapolation beyond them (section 2.2.1, as in TruckSim), floored at zero.
#[derive(Debug, Clone, PartialEq)]
pub struct CorneringStiffnessTable {
    table: Table,
}

impl CorneringStiffnessTable {
    /// Rows `[F_z (N), C_alpha (N/rad)]`, loads strictly increasing, stiffness >= 0; one
    /// row makes a constant.
    pub fn new(rows: &[[f64; 2]]) -> Result<Self, TireError> {
        let table = Table::new("cornering_stiffness_table", rows, 1)?;
        if let Some(i) = table.ys().iter().position(|&c| c < 0.0) {
            return Err(TireError::InvalidTable {
                table: "cornering_stiffness_table",
                reason: format!("row {i}: cornering stiffness must be >= 0"),
            });
        }
        Ok(Self { table })
    }

    /// A load-independent stiffness `c_alpha` (N/rad).
    pub fn constant(c_alpha: f64) -> Result<Self, TireError> {
        positive("cornering_stiffness_n_per_rad", c_alpha)?;
        Self::new(&[[0.0, c_alpha]])
    }

    /// The four Table 6.2 values (kN/deg, converted to N/rad) at the static tire loads of
    /// [`TABLE_6_2_STATIC_LOADS_N`], sorted by load. The front and rear pairs lie close to
    /// one line (0.026 and 0.027 kN/deg per kN), which supports one table for both axles.
    pub fn table_6_2() -> Self {
        let k = 180.0 / std::f64::consts::PI;
        let l = TABLE_6_2_STATIC_LOADS_N;
        let rows = [
            [l[2], C_ALPHA_REAR_UNLOADED_N_PER_DEG * k],
            [l[0], C_ALPHA_FRONT_UNLOADED_N_PER_DEG * k],
            [l[1], C_ALPHA_FRONT_LOADED_N_PER_DEG * k],
            [l[3], C_ALPHA_REAR_LOADED_N_PER_DEG * k],
        ];
        Self::new(&rows).expect("Table 6.2 rows are valid")
    }

    /// C_alpha (N/rad) at normal load `fz` (N); never negative.
    #[inline]
    pub fn at(&self, fz: f64) -> f64 {
        self.table.eval(fz).max(0.0)
    }

    /// The rows `[F_z, C_alpha]`.
    pub fn rows(&self) -> Vec<[f64; 2]> {
        self.table.rows()
    }
}

/// Exponential cornering law of Eq 1.3 (McAllister): F_y = A F_z (1 - exp(-B alpha)),
/// made odd in alpha: F_y = A F_z sign(alpha) (1 - exp(-B |alpha|)).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ExponentialCornering {
    /// A (-): the saturation level of F_y / F_z (a friction-like coefficient).
    pub a: f64,
    /// B (1/rad): initial slope of F_y / (A F_z); C_alpha = A B F_z at small slip.
    pub b: f64,
}

impl ExponentialCornering {
    /// Validated law: `a` and `b` finite and > 0.
    pub fn new(a: f64, b: f64) -> Result<Self, TireError> {
        Ok(Self {
            a: positive("a", a)?,
            b: positive("b", b)?,
        })
    }

    /// F_y (N) of Eq 1.3 at load `fz` (N) and slip angle `alpha` (rad); 0 when `fz <= 0`.
    #[inline]
    pub fn lateral_force(&self, fz: f64, alpha: f64) -> f64 {
        if !loaded(fz) {
            return 0.0;
        }
        let a = clamp_alpha(alpha);
        self.a * fz * a.signum() * (-(-self.b * a.abs()).exp_m1())
    }
}

impl HandlingModel for ExponentialCornering {
    /// Eq 1.3 lateral force only (no F_x, M_z or M_y in the law).
    #[inline]
    fn forces(&self, fz: f64, _kappa: f64, alpha: f64) -> TireForces {
        TireForces {
            fy: self.lateral_force(fz, alpha),
            ..TireForces::ZERO
        }
    }
}

/// Traction-dependent cornering of Eq 1.4 (Krick): F_y = (1 + a F_x) C_alpha alpha.
///
/// The paper's `±` is carried by the sign of `a` (1/N) together with the sign of F_x
/// (positive traction, negative braking): a negative `a` reduces the cornering force under
/// traction and raises it under braking. The factor `1 + a F_x` is floored at 0 so the
/// force never reverses. F_x comes from a linear longitudinal stiffness saturated at
/// `friction * F_z`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TractionDependentCornering {
    /// C_alpha (N/rad).
    pub cornering_stiffness: f64,
    /// a (1/N), signed; see the type docs.
    pub traction_factor: f64,
    /// C_slip (N per unit slip ratio) giving F_x = C_slip kappa below saturation.
    pub longitudinal_stiffness: f64,
    /// Friction coefficient bounding |F_x| <= friction F_z.
    pub friction: f64,
}

impl TractionDependentCornering {
    /// Validated law: stiffnesses and friction finite and > 0, `traction_factor` finite.
    pub fn new(
        cornering_stiffness: f64,
        traction_factor: f64,
        longitudinal_stiffness: f64,
        friction: f64,
    ) -> Result<Self, TireError> {
        Ok(Self {
            cornering_stiffness: positive("cornering_stiffness", cornering_stiffness)?,
            traction_factor: finite("traction_factor", traction_factor)?,
            longitudinal_stiffness: positive("longitudinal_stiffness", longitudinal_stiffness)?,
            friction: positive("friction", friction)?,
        })
    }

    /// F_y (N) of Eq 1.4 for a given tractive force `fx` (N) and slip angle `alpha` (rad).
    #[inline]
    pub fn lateral_force(&self, fx: f64, alpha: f64) -> f64 {
        (1.0 + self.traction_factor * fx).max(0.0) * self.cornering_stiffness * alpha
    }
}

impl HandlingModel for TractionDependentCornering {
    #[inline]
    fn forces(&self, fz: f64, kappa: f64, alpha: f64) -> TireForces {
        if !loaded(fz) {
            return TireForces::ZERO;
        }
        let limit = self.friction * fz;
        let fx = (self.longitudinal_stiffness * kappa).clamp(-limit, limit);
        TireForces {
            fx,
            fy: self.lateral_force(fx, clamp_alpha(alpha)),
            ..TireForces::ZERO
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const DEG: f64 = std::f64::consts::PI / 180.0;

    #[test]
    fn linear_model_is_eq_3_15() {
        let m = LinearCornering::new(4.5e3 / DEG, 3.8e3 / DEG).unwrap();
        assert!((m.lateral_force(2.0 * DEG) - 9.0e3).abs() < 1e-9);
        assert!((m.aligning_moment(-DEG) + 3.8e3).abs() < 1e-9);
        assert_eq!(m.forces(0.0, 0.0, 0.1), TireForces::ZERO);
        assert!(LinearCornering::new(f64::NAN, 1.0).is_err());
        assert!(LinearCornering::new(1.0, -1.0).is_err());
    }

    #[test]
    fn table_6_2_reproduces_the_paper_values_at_their_loads() {
        let t = CorneringStiffnessTable::table_6_2();
        let l = TABLE_6_2_STATIC_LOADS_N;
        for (load, kn_per_deg) in [(l[0], 6.1), (l[1], 6.8), (l[2], 3.7), (l[3], 7.5)] {
            assert!((t.at(load) * DEG / 1e3 - kn_per_deg).abs() < 1e-9);
        }
        // Linear interpolation between front-unloaded and front-loaded loads.
        let mid = 0.5 * (l[0] + l[1]);
        assert!((t.at(mid) * DEG / 1e3 - 6.45).abs() < 1e-9);
        // Extrapolation below the first row never goes negative.
        assert_eq!(t.at(-1e7), 0.0);
    }

    #[test]
    fn static_loads_follow_from_table_6_1() {
        // Table 6.1: front unit 21 000 kg at 2.13 m ahead of the joint, rear unit 18 500 kg
        // at 2.84 m behind, payload 33 720 kg at 2.6 m behind; axles 1.68 m ahead and
        // 3.44 m behind the joint (wheelbase 5.12 m).
        let g = 9.81;
        let axle = |masses: &[(f64, f64)]| {
            let m: f64 = masses.iter().map(|p| p.0).sum();
            let x = masses.iter().map(|p| p.0 * p.1).sum::<f64>() / m;
            let front = m * g * (x + 3.44) / 5.12;
            (front / 2.0, (m * g - front) / 2.0)
        };
        let (fu, ru) = axle(&[(21_000.0, 2.13), (18_500.0, -2.84)]);
        let (fl, rl) = axle(&[(21_000.0, 2.13), (18_500.0, -2.84), (33_720.0, -2.6)]);
        let l = TABLE_6_2_STATIC_LOADS_N;
        for (a, b) in [(fu, l[0]), (fl, l[1]), (ru, l[2]), (rl, l[3])] {
            assert!((a - b).abs() < 1.0, "{a} vs {b}");
        }
    }

    #[test]
    fn exponential_law_eq_1_3() {
        let m = ExponentialCornering::new(0.6, 5.0).unwrap();
        let fz = 1e5;
        let alpha = 0.1;
        let expect = 0.6 * fz * (1.0 - (-0.5f64).exp());
        assert!((m.lateral_force(fz, alpha) - expect).abs() < 1e-6);
        assert_eq!(m.lateral_force(fz, -alpha), -m.lateral_force(fz, alpha));
        assert!(m.lateral_force(fz, 1.5) <= 0.6 * fz);
        // Small-slip slope A B F_z.
        let s = m.lateral_force(fz, 1e-7) / 1e-7;
        assert!((s - 0.6 * 5.0 * fz).abs() / s < 1e-6);
    }

    #[test]
    fn traction_law_eq_1_4() {
        let m = TractionDependentCornering::new(3e5, -2e-6, 1e6, 0.7).unwrap();
        // kappa 0.02 -> F_x = 20 kN, factor 1 - 0.04.
        let f = m.forces(1e5, 0.02, 0.05);
        assert!((f.fx - 2e4).abs() < 1e-9);
        assert!((f.fy - 0.96 * 3e5 * 0.05).abs() < 1e-6);
        // Saturation of F_x at friction * F_z.
        assert!((m.forces(1e5, 1.0, 0.0).fx - 7e4).abs() < 1e-9);
        // Huge braking factor never flips the force sign.
        let m2 = TractionDependentCornering::new(3e5, 1e-3, 1e6, 0.7).unwrap();
        assert!(m2.forces(1e5, -1.0, 0.05).fy >= 0.0);
    }
}
