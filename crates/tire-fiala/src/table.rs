//! Piecewise-linear lookup with linear extrapolation, shared by the load-dependent
//! cornering stiffness (section 2.2.1) and the load-deflection table (Fig 6.4).

use crate::error::TireError;

/// Validated `(x, y)` breakpoints with strictly increasing `x`.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Table {
    xs: Vec<f64>,
    ys: Vec<f64>,
}

impl Table {
    /// Validate `rows` (`[x, y]`): at least `min_rows`, all finite, `x` strictly increasing.
    pub(crate) fn new(
        table: &'static str,
        rows: &[[f64; 2]],
        min_rows: usize,
    ) -> Result<Self, TireError> {
        if rows.len() < min_rows {
            return Err(TireError::InvalidTable {
                table,
                reason: format!("needs at least {min_rows} rows, got {}", rows.len()),
            });
        }
        for (i, r) in rows.iter().enumerate() {
            if !(r[0].is_finite() && r[1].is_finite()) {
                return Err(TireError::InvalidTable {
                    table,
                    reason: format!("row {i} has a non-finite entry {:?}", r),
                });
            }
            if i > 0 && r[0] <= rows[i - 1][0] {
                return Err(TireError::InvalidTable {
                    table,
                    reason: format!(
                        "row {i}: abscissa {} is not greater than the previous {}",
                        r[0],
                        rows[i - 1][0]
                    ),
                });
            }
        }
        Ok(Self {
            xs: rows.iter().map(|r| r[0]).collect(),
            ys: rows.iter().map(|r| r[1]).collect(),
        })
    }

    /// Index `i` of the segment `[x_i, x_{i+1}]` used for `x` (end segments extrapolate).
    #[inline]
    fn segment(&self, x: f64) -> usize {
        let n = self.xs.len();
        // partition_point: number of breakpoints <= x.
        let k = self.xs.partition_point(|&xi| xi <= x);
        k.clamp(1, n - 1) - 1
    }

    /// Linear interpolation inside, linear extrapolation with the end segment's slope
    /// outside. A one-row table is constant.
    #[inline]
    pub(crate) fn eval(&self, x: f64) -> f64 {
        if self.xs.len() == 1 {
            return self.ys[0];
        }
        let i = self.segment(x);
        let (x0, x1, y0, y1) = (self.xs[i], self.xs[i + 1], self.ys[i], self.ys[i + 1]);
        y0 + (y1 - y0) * (x - x0) / (x1 - x0)
    }

    /// Slope dy/dx of the segment used for `x` (0 for a one-row table).
    #[inline]
    pub(crate) fn slope(&self, x: f64) -> f64 {
        if self.xs.len() == 1 {
            return 0.0;
        }
        let i = self.segment(x);
        (self.ys[i + 1] - self.ys[i]) / (self.xs[i + 1] - self.xs[i])
    }

    /// The breakpoints as `[x, y]` rows.
    pub(crate) fn rows(&self) -> Vec<[f64; 2]> {
        self.xs
            .iter()
            .zip(&self.ys)
            .map(|(&x, &y)| [x, y])
            .collect()
    }

    pub(crate) fn xs(&self) -> &[f64] {
        &self.xs
    }

    pub(crate) fn ys(&self) -> &[f64] {
        &self.ys
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interpolates_and_extrapolates() {
        let t = Table::new("t", &[[0.0, 0.0], [1.0, 2.0], [3.0, 4.0]], 1).unwrap();
        assert_eq!(t.eval(0.5), 1.0);
        assert_eq!(t.eval(2.0), 3.0);
        assert_eq!(t.eval(5.0), 6.0); // slope 1 beyond the end
        assert_eq!(t.eval(-1.0), -2.0); // slope 2 before the start
        assert_eq!(t.slope(-1.0), 2.0);
        assert_eq!(t.slope(10.0), 1.0);
    }

    #[test]
    fn rejects_bad_rows() {
        assert!(Table::new("t", &[], 1).is_err());
        assert!(Table::new("t", &[[0.0, 1.0], [0.0, 2.0]], 1).is_err());
        assert!(Table::new("t", &[[0.0, f64::NAN]], 1).is_err());
        let one = Table::new("t", &[[2.0, 7.0]], 1).unwrap();
        assert_eq!(one.eval(-100.0), 7.0);
    }
}
