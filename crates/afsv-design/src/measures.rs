//! The six measures of the chapter-4 objective (section 4.3.1) and their ratios to the
//! current design (the "normalized objective" columns of Tables 4.3 and 4.4).

use crate::error::{non_negative, positive, DesignError};
use afsv_dynamics::YawMeasures;
use serde::Serialize;

/// One measure of the objective vector V of Eq 4.8, in the paper's order.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Measure {
    /// L: initial strut length l_0 (Eq 3.7); smaller is better.
    StrutLength,
    /// omega: yaw-mode natural frequency from the free decay after the pulse; larger is better.
    YawFrequency,
    /// zeta: yaw-mode damping ratio from the same fit; larger is better.
    DampingRatio,
    /// Gamma: steering gain, steady articulation over steering-wheel angle; larger is better.
    SteeringGain,
    /// OS: percent overshoot of the articulation step response; smaller is better.
    Overshoot,
    /// psi: response rate, steady articulation over the 0-100 % rise time; larger is better.
    ResponseRate,
}

impl Measure {
    /// The six measures in the order of V (Eq 4.8) and of the AHP level III (Eq 4.15).
    pub const ALL: [Measure; 6] = [
        Measure::StrutLength,
        Measure::YawFrequency,
        Measure::DampingRatio,
        Measure::SteeringGain,
        Measure::Overshoot,
        Measure::ResponseRate,
    ];

    /// Position in V (0-based).
    pub fn index(self) -> usize {
        self as usize
    }

    /// Snake-case name (`strut_length`, ..., as in the fixtures).
    pub fn name(self) -> &'static str {
        match self {
            Measure::StrutLength => "strut_length",
            Measure::YawFrequency => "yaw_frequency",
            Measure::DampingRatio => "damping_ratio",
            Measure::SteeringGain => "steering_gain",
            Measure::Overshoot => "overshoot",
            Measure::ResponseRate => "response_rate",
        }
    }

    /// Whether a larger value is better: then V holds the inverse ratio (Eq 4.8).
    pub fn larger_is_better(self) -> bool {
        !matches!(self, Measure::StrutLength | Measure::Overshoot)
    }
}

/// The six measures of one design (section 4.3.1), in the units of [`YawMeasures`].
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DesignMeasures {
    /// Values indexed by [`Measure::index`]: l_0 (m), natural frequency (Hz), damping ratio
    /// (-), steering gain (deg/deg), overshoot (%), response rate (deg/s).
    values: [f64; 6],
}

impl DesignMeasures {
    /// The measures of one design. Every value must be finite and positive, except the
    /// overshoot, which may be zero (a response without overshoot).
    pub fn new(values: [f64; 6]) -> Result<Self, DesignError> {
        for m in Measure::ALL {
            let v = values[m.index()];
            if m == Measure::Overshoot {
                non_negative(m.name(), v)?;
            } else {
                positive(m.name(), v)?;
            }
        }
        Ok(Self { values })
    }

    /// The six measures of a yaw-plane evaluation (pulse and step, `afsv_dynamics::measures_for`).
    pub fn from_yaw(m: &YawMeasures) -> Result<Self, DesignError> {
        Self::new([
            m.strut_length_m,
            m.natural_frequency_hz,
            m.damping_ratio,
            m.steering_gain,
            m.overshoot_percent,
            m.response_rate_deg_s,
        ])
    }

    /// Value of measure `m`.
    pub fn get(&self, m: Measure) -> f64 {
        self.values[m.index()]
    }
}

/// Plain ratios design / current of the six measures (L/L_0, omega/omega_0, ...), as Tables
/// 4.3 and 4.4 print them; the current design's ratios are all 1.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct MeasureRatios {
    /// Ratios indexed by [`Measure::index`].
    ratios: [f64; 6],
}

impl MeasureRatios {
    /// Ratios of `design` to `current`. The current overshoot must be positive (it divides).
    pub fn new(design: &DesignMeasures, current: &DesignMeasures) -> Result<Self, DesignError> {
        positive("current.overshoot", current.get(Measure::Overshoot))?;
        Ok(Self {
            ratios: Measure::ALL.map(|m| design.get(m) / current.get(m)),
        })
    }

    /// Ratio of measure `m` (design / current).
    pub fn get(&self, m: Measure) -> f64 {
        self.ratios[m.index()]
    }

    /// The objective vector of Eq 4.8,
    /// `V = [L/L_0, omega_0/omega, zeta_0/zeta, Gamma_0/Gamma, OS/OS_0, psi_0/psi]`: the plain
    /// ratio where smaller is better, its inverse where larger is better, so that every
    /// entry falls as the design improves and `V = [1, ..., 1]` at the current design.
    pub fn objective_vector(&self) -> [f64; 6] {
        Measure::ALL.map(|m| {
            let r = self.get(m);
            if m.larger_is_better() {
                1.0 / r
            } else {
                r
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn measures(v: [f64; 6]) -> DesignMeasures {
        DesignMeasures::new(v).unwrap()
    }

    #[test]
    fn ratios_of_the_current_design_are_one() {
        let m = measures([1.9, 5.5, 0.3, 0.2, 12.0, 40.0]);
        let r = MeasureRatios::new(&m, &m).unwrap();
        assert_eq!(r.objective_vector(), [1.0; 6]);
    }

    #[test]
    fn objective_vector_inverts_the_larger_is_better_ratios() {
        let cur = measures([2.0, 5.0, 0.25, 0.2, 10.0, 40.0]);
        let des = measures([1.0, 10.0, 0.5, 0.1, 5.0, 20.0]);
        let r = MeasureRatios::new(&des, &cur).unwrap();
        assert_eq!(r.get(Measure::YawFrequency), 2.0);
        assert_eq!(r.objective_vector(), [0.5, 0.5, 0.5, 2.0, 0.5, 2.0]);
    }

    #[test]
    fn invalid_measures_name_the_field() {
        let e = DesignMeasures::new([1.0, 5.0, f64::NAN, 0.2, 10.0, 40.0]).unwrap_err();
        assert!(e.to_string().contains("damping_ratio"), "{e}");
        assert!(DesignMeasures::new([1.0, 5.0, 0.3, 0.2, -1.0, 40.0]).is_err());
        let no_overshoot = measures([1.0, 5.0, 0.3, 0.2, 0.0, 40.0]);
        let e = MeasureRatios::new(&no_overshoot, &no_overshoot).unwrap_err();
        assert!(e.to_string().contains("current.overshoot"), "{e}");
    }
}
