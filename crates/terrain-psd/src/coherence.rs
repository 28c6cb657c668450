//! Coherence between the left and right tracks (Eqs 1.8, 1.9, 2.9, 2.10 / 6.5).
//!
//! Coherence here always means the magnitude-squared coherence of Eq 2.9,
//! `gamma^2(n) = |G_qp(n)|^2 / (Q(n) P(n))`, in `[0, 1]`, as a function of the spatial
//! frequency `n` (cycles/m).

use crate::error::{non_negative, positive, Result, TerrainError};
use serde::{Deserialize, Serialize};
use std::fmt;

/// Zhang's cut-off frequency (Hz) in Eq 1.8.
pub const ZHANG_CUTOFF_HZ: f64 = 2.0;

/// Coherence model of the two tracks.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(tag = "model", rename_all = "snake_case")]
pub enum CoherenceModel {
    /// Piecewise-linear model of Eq 2.10 / 6.5: `gamma^2 = 1 - 0.9 n/m_c` for `n <= m_c`,
    /// 0.1 above. The paper's nominal `m_c` is 0.3 cycles/m.
    Piecewise {
        /// Cut-off spatial frequency `m_c` (cycles/m), > 0.
        m_c: f64,
    },
    /// Bogsjö's exponential model, Eq 1.9: coherence `gamma(n) = exp(-2 rho T n)`, so
    /// `gamma^2(n) = exp(-4 rho T n)`.
    Bogsjo {
        /// Constant `rho` (dimensionless), >= 0.
        rho: f64,
        /// Half-track width `T` (m), > 0.
        half_track_m: f64,
    },
    /// Zhang's temporal piecewise-linear model, Eq 1.8: `gamma^2(f) = 1 - 0.45 f` for
    /// `f <= 2 Hz`, 0.1 above, mapped to space with `f = n u`; it is Eq 2.10 with
    /// `m_c = 2 Hz / u`.
    Zhang {
        /// Forward speed `u` (m/s), > 0.
        speed_m_s: f64,
    },
    /// Fully coherent tracks (`gamma^2 = 1`): identical left and right profiles.
    Full,
    /// Independent tracks (`gamma^2 = 0`).
    Independent,
}

impl CoherenceModel {
    /// The paper's nominal model: piecewise linear with `m_c = 0.3` cycles/m (sections 2.2.2, 6.2.3).
    pub const PAPER: CoherenceModel = CoherenceModel::Piecewise { m_c: 0.3 };

    /// Validated piecewise-linear model (Eq 2.10).
    pub fn piecewise(m_c: f64) -> Result<Self> {
        positive("m_c", m_c)?;
        Ok(Self::Piecewise { m_c })
    }

    /// Validated Bogsjö model (Eq 1.9).
    pub fn bogsjo(rho: f64, half_track_m: f64) -> Result<Self> {
        non_negative("rho", rho)?;
        positive("half_track", half_track_m)?;
        Ok(Self::Bogsjo { rho, half_track_m })
    }

    /// Validated Zhang model (Eq 1.8) at forward speed `speed_m_s`.
    pub fn zhang(speed_m_s: f64) -> Result<Self> {
        positive("speed", speed_m_s)?;
        Ok(Self::Zhang { speed_m_s })
    }

    /// Check the parameters (see the constructors).
    pub fn validate(&self) -> Result<()> {
        match *self {
            Self::Piecewise { m_c } => Self::piecewise(m_c).map(|_| ()),
            Self::Bogsjo { rho, half_track_m } => Self::bogsjo(rho, half_track_m).map(|_| ()),
            Self::Zhang { speed_m_s } => Self::zhang(speed_m_s).map(|_| ()),
            Self::Full | Self::Independent => Ok(()),
        }
    }

    /// Magnitude-squared coherence `gamma^2(n)` at spatial frequency `n` (cycles/m), in [0, 1].
    pub fn msc(&self, n: f64) -> f64 {
        let n = n.abs();
        let v = match *self {
            Self::Piecewise { m_c } => piecewise_msc(n, m_c),
            Self::Bogsjo { rho, half_track_m } => (-4.0 * rho * half_track_m * n).exp(),
            Self::Zhang { speed_m_s } => zhang_temporal_msc(n * speed_m_s),
            Self::Full => 1.0,
            Self::Independent => 0.0,
        };
        if v.is_nan() {
            0.0
        } else {
            v.clamp(0.0, 1.0)
        }
    }

    /// Parse a command-line spec: `piecewise:M_C`, `bogsjo:RHO` (needs `half_track_m`),
    /// `zhang` (needs `speed_m_s`), `full`, `none` (alias `independent`).
    pub fn parse(spec: &str, half_track_m: Option<f64>, speed_m_s: Option<f64>) -> Result<Self> {
        let unknown = || TerrainError::Unknown {
            what: "coherence model",
            given: spec.to_string(),
            expected: "piecewise:M_C, bogsjo:RHO, zhang, full, none",
        };
        let (name, arg) = match spec.split_once(':') {
            Some((n, a)) => (n.trim().to_ascii_lowercase(), Some(a.trim())),
            None => (spec.trim().to_ascii_lowercase(), None),
        };
        let number = |what: &'static str| -> Result<f64> {
            let a = arg.ok_or(TerrainError::Syntax {
                what,
                given: spec.to_string(),
                expected: "MODEL:NUMBER, e.g. piecewise:0.3 or bogsjo:0.2",
            })?;
            a.parse::<f64>().map_err(|_| TerrainError::Syntax {
                what,
                given: a.to_string(),
                expected: "a number",
            })
        };
        match name.as_str() {
            "piecewise" => Self::piecewise(number("piecewise cut-off m_c")?),
            "bogsjo" | "bogsjö" => {
                let rho = number("Bogsjö constant rho")?;
                let t = half_track_m.ok_or(TerrainError::Missing {
                    what: "bogsjo coherence",
                    needs: "the half-track width T in m (--half-track)",
                })?;
                Self::bogsjo(rho, t)
            }
            "zhang" if arg.is_none() => {
                let u = speed_m_s.ok_or(TerrainError::Missing {
                    what: "zhang coherence",
                    needs: "the forward speed u in m/s (--speed)",
                })?;
                Self::zhang(u)
            }
            "full" if arg.is_none() => Ok(Self::Full),
            "none" | "independent" if arg.is_none() => Ok(Self::Independent),
            _ => Err(unknown()),
        }
    }

    /// Short spec string, the inverse of [`CoherenceModel::parse`] (without the extra arguments).
    pub fn spec(&self) -> String {
        match *self {
            Self::Piecewise { m_c } => format!("piecewise:{m_c}"),
            Self::Bogsjo { rho, .. } => format!("bogsjo:{rho}"),
            Self::Zhang { .. } => "zhang".into(),
            Self::Full => "full".into(),
            Self::Independent => "none".into(),
        }
    }
}

impl Default for CoherenceModel {
    fn default() -> Self {
        Self::PAPER
    }
}

impl fmt::Display for CoherenceModel {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Self::Piecewise { m_c } => {
                write!(f, "piecewise-linear (Eq 2.10), m_c = {m_c} cycles/m")
            }
            Self::Bogsjo { rho, half_track_m } => {
                write!(
                    f,
                    "Bogsjö exponential (Eq 1.9), rho = {rho}, T = {half_track_m} m"
                )
            }
            Self::Zhang { speed_m_s } => write!(
                f,
                "Zhang (Eq 1.8) at u = {speed_m_s} m/s, i.e. m_c = {} cycles/m",
                ZHANG_CUTOFF_HZ / speed_m_s
            ),
            Self::Full => f.write_str("fully coherent"),
            Self::Independent => f.write_str("independent"),
        }
    }
}

/// Eq 2.10 / 6.5: `1 - 0.9 n/m_c` for `n <= m_c`, 0.1 above.
pub fn piecewise_msc(n: f64, m_c: f64) -> f64 {
    if n <= m_c {
        1.0 - 0.9 * n / m_c
    } else {
        0.1
    }
}

/// Eq 1.8 (Zhang, temporal): `1 - 0.45 f` for `f <= 2` Hz, 0.1 above.
pub fn zhang_temporal_msc(f_hz: f64) -> f64 {
    if f_hz <= ZHANG_CUTOFF_HZ {
        1.0 - 0.45 * f_hz
    } else {
        0.1
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn piecewise_matches_eq_2_10() {
        let c = CoherenceModel::PAPER;
        assert_eq!(c.msc(0.0), 1.0);
        assert!((c.msc(0.15) - 0.55).abs() < 1e-12);
        assert!((c.msc(0.3) - 0.1).abs() < 1e-12);
        assert_eq!(c.msc(0.31), 0.1);
        assert_eq!(c.msc(4.0), 0.1);
    }

    #[test]
    fn zhang_is_piecewise_with_cutoff_two_hz_over_speed() {
        let u = 50.0 / 3.6;
        let z = CoherenceModel::zhang(u).unwrap();
        let p = CoherenceModel::piecewise(2.0 / u).unwrap();
        for i in 0..200 {
            let n = i as f64 * 0.005;
            assert!((z.msc(n) - p.msc(n)).abs() < 1e-12, "n = {n}");
        }
        assert!((zhang_temporal_msc(1.0) - 0.55).abs() < 1e-12);
        assert_eq!(zhang_temporal_msc(2.5), 0.1);
    }

    #[test]
    fn bogsjo_is_the_square_of_eq_1_9() {
        let b = CoherenceModel::bogsjo(0.2, 1.14).unwrap();
        let n: f64 = 0.4;
        let gamma = (-2.0 * 0.2 * 1.14 * n).exp();
        assert!((b.msc(n) - gamma * gamma).abs() < 1e-14);
        assert_eq!(b.msc(0.0), 1.0);
    }

    #[test]
    fn parse_specs() {
        assert_eq!(
            CoherenceModel::parse("piecewise:0.3", None, None).unwrap(),
            CoherenceModel::PAPER
        );
        assert_eq!(
            CoherenceModel::parse("bogsjo:0.2", Some(1.14), None).unwrap(),
            CoherenceModel::Bogsjo {
                rho: 0.2,
                half_track_m: 1.14
            }
        );
        assert!(CoherenceModel::parse("bogsjo:0.2", None, None).is_err());
        assert!(CoherenceModel::parse("zhang", None, None).is_err());
        assert!(CoherenceModel::parse("zhang", None, Some(0.0)).is_err());
        assert!(CoherenceModel::parse("zhang", None, Some(10.0)).is_ok());
        assert_eq!(
            CoherenceModel::parse("none", None, None).unwrap(),
            CoherenceModel::Independent
        );
        assert_eq!(
            CoherenceModel::parse("FULL", None, None).unwrap(),
            CoherenceModel::Full
        );
        for bad in [
            "piecewise",
            "piecewise:-1",
            "piecewise:nan",
            "piecewise:x",
            "iso",
            "full:1",
            "",
        ] {
            assert!(
                CoherenceModel::parse(bad, Some(1.0), Some(1.0)).is_err(),
                "{bad}"
            );
        }
        for c in [
            CoherenceModel::PAPER,
            CoherenceModel::Full,
            CoherenceModel::Independent,
        ] {
            assert_eq!(CoherenceModel::parse(&c.spec(), None, None).unwrap(), c);
        }
    }
}
