//! The optimum of a one-variable design sweep: the largest sample of a uniformly spaced
//! sweep refined by the parabola through it and its two neighbours (section 3.4.3 locates
//! the yaw-frequency peak over A_0 this way).

use crate::error::DesignError;
use serde::Serialize;

/// The maximum of a sampled sweep.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SweepPeak {
    /// Abscissa of the vertex of the parabola through the largest sample and its
    /// neighbours, kept within one step of that sample (the sample itself at either end).
    pub x: f64,
    /// Index of the largest sample.
    pub index: usize,
    /// The largest sample.
    pub y_max: f64,
}

/// Peak of `y(x)` over a uniform grid `x` (at least 3 finite, strictly increasing samples).
/// With y_-, y_0, y_+ around the largest sample the vertex lies at
/// `x_0 + h (y_- - y_+) / (2 (y_- - 2 y_0 + y_+))`, `h` the grid step.
pub fn parabolic_peak(x: &[f64], y: &[f64]) -> Result<SweepPeak, DesignError> {
    if x.len() != y.len() || x.len() < 3 {
        return Err(DesignError::Shape {
            field: "sweep",
            reason: format!(
                "needs >= 3 (x, y) pairs, got {} x and {} y",
                x.len(),
                y.len()
            ),
        });
    }
    for (field, v) in [("sweep.x", x), ("sweep.y", y)] {
        if let Some(&bad) = v.iter().find(|v| !v.is_finite()) {
            return Err(DesignError::Invalid {
                field,
                value: bad,
                reason: "must be finite",
            });
        }
    }
    if let Some(w) = x.windows(2).find(|w| w[1] <= w[0]) {
        return Err(DesignError::Invalid {
            field: "sweep.x",
            value: w[1],
            reason: "must be strictly increasing",
        });
    }
    let i = (0..y.len())
        .max_by(|&a, &b| y[a].total_cmp(&y[b]))
        .unwrap_or(0);
    let x_peak = if i > 0 && i + 1 < y.len() {
        let (y0, y1, y2) = (y[i - 1], y[i], y[i + 1]);
        let den = y0 - 2.0 * y1 + y2;
        let off = if den.abs() > 0.0 {
            0.5 * (y0 - y2) / den
        } else {
            0.0
        };
        x[i] + (x[1] - x[0]) * off.clamp(-1.0, 1.0)
    } else {
        x[i]
    };
    Ok(SweepPeak {
        x: x_peak,
        index: i,
        y_max: y[i],
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parabola_vertex_is_exact() {
        let x: Vec<f64> = (0..7).map(|i| -3.0 + i as f64).collect();
        let y: Vec<f64> = x.iter().map(|v| 2.0 - (v - 0.3f64).powi(2)).collect();
        let p = parabolic_peak(&x, &y).unwrap();
        assert!((p.x - 0.3).abs() < 1e-12, "{p:?}");
        assert_eq!(p.index, 3);
    }

    #[test]
    fn peak_at_an_end_is_that_sample() {
        let p = parabolic_peak(&[0.0, 1.0, 2.0], &[1.0, 2.0, 3.0]).unwrap();
        assert_eq!((p.x, p.index, p.y_max), (2.0, 2, 3.0));
    }

    #[test]
    fn bad_sweeps_are_refused() {
        assert!(parabolic_peak(&[0.0, 1.0], &[1.0, 2.0]).is_err());
        assert!(parabolic_peak(&[0.0, 1.0, 1.0], &[1.0, 2.0, 3.0]).is_err());
        let e = parabolic_peak(&[0.0, 1.0, 2.0], &[1.0, f64::NAN, 3.0]).unwrap_err();
        assert!(e.to_string().contains("sweep.y"), "{e}");
    }
}
