//! Vertical contact with lift-off (Eq 2.1) and the nonlinear load-deflection curve that
//! replaces the linear spring for the 29.5R29 (section 6.2.2, Fig 6.4).

use crate::error::{non_negative, positive, TireError};
use crate::params::TireParams;
use crate::table::Table;

/// Tire load as a function of deflection, from rows `[deflection (m), load (N)]`:
/// linear interpolation, the last segment's slope beyond the last row, and zero load for
/// zero or negative deflection. An implicit `[0, 0]` row is added when absent.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadDeflectionTable {
    table: Table,
}

impl LoadDeflectionTable {
    /// Validate rows: deflections strictly increasing and >= 0, loads >= 0 and
    /// non-decreasing, at least one row with positive deflection.
    pub fn new(rows: &[[f64; 2]]) -> Result<Self, TireError> {
        let mut all = Vec::with_capacity(rows.len() + 1);
        if rows.first().is_none_or(|r| r[0] != 0.0) {
            all.push([0.0, 0.0]);
        }
        all.extend_from_slice(rows);
        let table = Table::new("load_deflection", &all, 2)?;
        let (xs, ys) = (table.xs(), table.ys());
        if xs[0] < 0.0 {
            return Err(TireError::InvalidTable {
                table: "load_deflection",
                reason: "deflections must be >= 0".into(),
            });
        }
        for i in 0..ys.len() {
            if ys[i] < 0.0 || (i > 0 && ys[i] < ys[i - 1]) {
                return Err(TireError::InvalidTable {
                    table: "load_deflection",
                    reason: format!(
                        "load at deflection {} must be >= 0 and non-decreasing",
                        xs[i]
                    ),
                });
            }
        }
        if ys[ys.len() - 1] <= ys[0] {
            return Err(TireError::InvalidTable {
                table: "load_deflection",
                reason: "the load must rise with deflection somewhere".into(),
            });
        }
        Ok(Self { table })
    }

    /// ASSUMPTION (Fig 6.4 is not in the text): a progressive curve for the 29.5R29,
    /// `F = k_1 delta + k_2 delta^2` with initial stiffness `k_1` = 1.2e6 N/m and
    /// `k_2` = 4.306e6 N/m^2, chosen so the assumed rated load of
    /// 206 kN (21 t, close to the 209 kN static load of a loaded rear tire derived from
    /// Table 6.1) is reached at 0.12 m deflection (12 % of the 1.0 m free radius, about
    /// 17 % of the section height), tabulated every 0.02 m up to 0.2 m. The tangent
    /// stiffness runs from 1.2 to 2.9 kN/mm, bracketing the 1.8 kN/mm of the Table 2.3 tire.
    pub fn default_29_5r29() -> Self {
        let (k1, k2) = (1.2e6, 4.306e6);
        let rows: Vec<[f64; 2]> = (0..=10)
            .map(|i| {
                let d = 0.02 * i as f64;
                [d, (k1 * d + k2 * d * d).round()]
            })
            .collect();
        Self::new(&rows).expect("default table is valid")
    }

    /// A linear spring `k_t` (N/m), Eq 2.1's `k_t delta`.
    pub fn linear(stiffness: f64) -> Result<Self, TireError> {
        positive("vertical_stiffness_n_per_m", stiffness)?;
        Self::new(&[[0.0, 0.0], [1.0, stiffness]])
    }

    /// Elastic load (N) at deflection `delta` (m); 0 for `delta <= 0`.
    #[inline]
    pub fn load(&self, delta: f64) -> f64 {
        if delta > 0.0 {
            self.table.eval(delta).max(0.0)
        } else {
            0.0
        }
    }

    /// Tangent stiffness dF/d(delta) (N/m) at `delta` (the first segment's below zero).
    #[inline]
    pub fn stiffness(&self, delta: f64) -> f64 {
        self.table.slope(delta.max(0.0))
    }

    /// Deflection (m) at which the elastic load equals `load` (N), e.g. the static
    /// deflection; 0 for `load <= 0`. Inverse of [`LoadDeflectionTable::load`].
    pub fn deflection_at(&self, load: f64) -> f64 {
        if load.is_nan() || load <= 0.0 {
            return 0.0;
        }
        let (xs, ys) = (self.table.xs(), self.table.ys());
        let n = xs.len();
        for i in 0..n - 1 {
            if load <= ys[i + 1] && ys[i + 1] > ys[i] {
                return xs[i] + (load - ys[i]) * (xs[i + 1] - xs[i]) / (ys[i + 1] - ys[i]);
            }
        }
        // Beyond the table: extrapolate with the last positive slope.
        let mut i = n - 2;
        while ys[i + 1] <= ys[i] {
            i -= 1; // at least one rising segment exists (checked in `new`)
        }
        let slope = (ys[i + 1] - ys[i]) / (xs[i + 1] - xs[i]);
        xs[n - 1] + (load - ys[n - 1]) / slope
    }

    /// Elastic energy (J) stored at deflection `delta` (m): the exact integral of
    /// [`LoadDeflectionTable::load`] from 0 (piecewise linear, the last segment extended);
    /// 0 for `delta <= 0`.
    pub fn energy(&self, delta: f64) -> f64 {
        if delta.is_nan() || delta <= 0.0 {
            return 0.0;
        }
        let xs = self.table.xs();
        let n = xs.len();
        let mut e = 0.0;
        for i in 0..n - 1 {
            let (x0, x1) = (
                xs[i],
                if i == n - 2 {
                    delta.max(xs[i + 1])
                } else {
                    xs[i + 1]
                },
            );
            let end = x1.min(delta);
            if end <= x0 {
                break;
            }
            // trapezoid of the (clamped at 0) linear load over [x0, end]
            e += 0.5 * (self.load(x0) + self.load(end)) * (end - x0);
        }
        e
    }

    /// The rows `[deflection, load]`, including the `[0, 0]` row.
    pub fn rows(&self) -> Vec<[f64; 2]> {
        self.table.rows()
    }
}

/// Point-contact vertical tire force with lift-off (Eq 2.1):
/// `F_z = F_el(delta) + c_t d(delta)/dt` for `delta > 0`, else 0, and never negative (the
/// damper cannot pull the wheel onto the ground).
#[derive(Debug, Clone, PartialEq)]
pub struct VerticalContact {
    stiffness: LoadDeflectionTable,
    damping: f64,
}

impl VerticalContact {
    /// From a load-deflection curve and a damping coefficient c_t (N s/m, >= 0).
    pub fn new(stiffness: LoadDeflectionTable, damping: f64) -> Result<Self, TireError> {
        Ok(Self {
            stiffness,
            damping: non_negative("vertical_damping_n_s_per_m", damping)?,
        })
    }

    /// From a parameter set (`load_deflection`, `vertical_damping_n_s_per_m`).
    pub fn from_params(p: &TireParams) -> Result<Self, TireError> {
        Self::new(
            LoadDeflectionTable::new(&p.load_deflection)?,
            p.vertical_damping_n_s_per_m,
        )
    }

    /// The load-deflection curve.
    pub fn load_deflection(&self) -> &LoadDeflectionTable {
        &self.stiffness
    }

    /// The damping coefficient c_t (N s/m).
    pub fn damping(&self) -> f64 {
        self.damping
    }

    /// Normal force F_z (N) of Eq 2.1 at deflection `delta` (m, positive in compression)
    /// and deflection rate `delta_rate` (m/s); exactly 0 when `delta <= 0`.
    #[inline]
    pub fn normal_force(&self, delta: f64, delta_rate: f64) -> f64 {
        if delta > 0.0 {
            (self.stiffness.load(delta) + self.damping * delta_rate).max(0.0)
        } else {
            0.0
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn energy_is_the_integral_of_the_load() {
        let t = LoadDeflectionTable::default_29_5r29();
        for &d in &[0.0, 0.013, 0.05, 0.2, 0.27] {
            let n = 20_000;
            let h = d / n as f64;
            let fine: f64 = (0..n)
                .map(|i| 0.5 * (t.load(i as f64 * h) + t.load((i + 1) as f64 * h)) * h)
                .sum();
            assert!(
                (t.energy(d) - fine).abs() <= 1e-6 * (1.0 + fine),
                "{d}: {} vs {fine}",
                t.energy(d)
            );
        }
        let lin = LoadDeflectionTable::linear(2.0e6).unwrap();
        assert!((lin.energy(0.1) - 0.5 * 2.0e6 * 0.01).abs() < 1e-6);
        assert_eq!(t.energy(-0.1), 0.0);
    }

    #[test]
    fn default_table_reaches_rated_load() {
        let t = LoadDeflectionTable::default_29_5r29();
        assert!((t.load(0.12) - 206_006.0).abs() < 1.0);
        assert!((t.deflection_at(206_006.0) - 0.12).abs() < 1e-9);
        // Progressive: tangent stiffness grows with deflection.
        assert!(t.stiffness(0.01) < t.stiffness(0.11));
        // Beyond the table: last slope.
        let s = t.stiffness(0.3);
        assert!((t.load(0.3) - t.load(0.2) - 0.1 * s).abs() < 1e-6);
        assert!((t.deflection_at(t.load(0.3)) - 0.3).abs() < 1e-9);
    }

    #[test]
    fn lift_off_gives_exactly_zero() {
        let c = VerticalContact::new(LoadDeflectionTable::linear(1.8e6).unwrap(), 6e3).unwrap();
        assert_eq!(c.normal_force(-0.01, -5.0), 0.0);
        assert_eq!(c.normal_force(0.0, 5.0), 0.0);
        // Eq 2.1 inside contact.
        assert!((c.normal_force(0.01, 0.2) - (1.8e4 + 1.2e3)).abs() < 1e-9);
        // Fast rebound: no pulling force.
        assert_eq!(c.normal_force(0.001, -10.0), 0.0);
    }

    #[test]
    fn rejects_bad_tables() {
        assert!(LoadDeflectionTable::new(&[[0.1, 5.0], [0.2, 4.0]]).is_err());
        assert!(LoadDeflectionTable::new(&[[-0.1, 0.0], [0.2, 4.0]]).is_err());
        assert!(LoadDeflectionTable::new(&[[0.0, 0.0]]).is_err());
        assert!(VerticalContact::new(LoadDeflectionTable::default_29_5r29(), -1.0).is_err());
    }
}
