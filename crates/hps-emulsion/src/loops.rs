//! Hysteresis loops of a harmonic strut record (section 5.4, Figs 5.5-5.12): the samples of
//! one excitation period, from which the pressure-deflection, force-deflection,
//! force-velocity and damping-force-velocity loops are drawn. Damping force = strut force
//! minus the quasi-static spring force of the gas (`StrutRecord::damping_force`).

use crate::error::{positive, HpsError};
use crate::simulate::StrutRecord;
use serde::Serialize;

/// The samples of one excitation period, closed: the first and last samples lie one period
/// apart, so a loop drawn through them closes. SI units and the record's sign convention.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HysteresisLoop {
    /// Time (s).
    pub time: Vec<f64>,
    /// Deflection, positive in compression (m).
    pub displacement: Vec<f64>,
    /// Deflection rate (m/s).
    pub velocity: Vec<f64>,
    /// Strut force, positive when compressive (N).
    pub force: Vec<f64>,
    /// Piston-side pressure (Pa, absolute).
    pub p_piston: Vec<f64>,
    /// Rod-side pressure (Pa, absolute).
    pub p_rod: Vec<f64>,
    /// Strut force minus the gas spring force (N).
    pub damping_force: Vec<f64>,
}

/// Relative slack on the period boundaries for round-off in the sample times.
const BOUNDARY_SLACK: f64 = 1e-9;

impl HysteresisLoop {
    /// The samples of `rec` whose times lie in `[t0, t1]` (within round-off).
    fn between(rec: &StrutRecord, t0: f64, t1: f64, period: f64) -> Self {
        let eps = BOUNDARY_SLACK * period;
        let idx: Vec<usize> = (0..rec.time.len())
            .filter(|&i| rec.time[i] >= t0 - eps && rec.time[i] <= t1 + eps)
            .collect();
        let pick = |v: &[f64]| idx.iter().map(|&i| v[i]).collect::<Vec<f64>>();
        Self {
            time: pick(&rec.time),
            displacement: pick(&rec.displacement),
            velocity: pick(&rec.velocity),
            force: pick(&rec.force),
            p_piston: pick(&rec.p_piston),
            p_rod: pick(&rec.p_rod),
            damping_force: idx
                .iter()
                .map(|&i| rec.force[i] - rec.spring_force[i])
                .collect(),
        }
    }

    /// The last period `1/frequency_hz` of `rec` (the steady cycle the loop plots show).
    pub fn last_period(rec: &StrutRecord, frequency_hz: f64) -> Result<Self, HpsError> {
        positive("frequency_hz", frequency_hz)?;
        let period = 1.0 / frequency_hz;
        let (t_first, t_end) = match (rec.time.first(), rec.time.last()) {
            (Some(&a), Some(&b)) => (a, b),
            _ => return Err(HpsError::InvalidExcitation("empty record".into())),
        };
        if t_end - t_first < period * (1.0 - BOUNDARY_SLACK) {
            return Err(HpsError::InvalidExcitation(
                "record shorter than one period".into(),
            ));
        }
        Ok(Self::between(rec, t_end - period, t_end, period))
    }

    /// Every complete period `[t_0 + k T, t_0 + (k + 1) T]` of `rec`, `T = 1/frequency_hz`,
    /// in order (one loop per excitation cycle; the start-up transient is in the first).
    pub fn per_cycle(rec: &StrutRecord, frequency_hz: f64) -> Result<Vec<Self>, HpsError> {
        positive("frequency_hz", frequency_hz)?;
        let period = 1.0 / frequency_hz;
        let (t0, t_end) = match (rec.time.first(), rec.time.last()) {
            (Some(&a), Some(&b)) => (a, b),
            _ => return Err(HpsError::InvalidExcitation("empty record".into())),
        };
        let cycles = ((t_end - t0) / period + BOUNDARY_SLACK).floor() as usize;
        Ok((0..cycles)
            .map(|k| {
                let start = t0 + k as f64 * period;
                Self::between(rec, start, start + period, period)
            })
            .collect())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{simulate_displacement, Excitation, HpsExtensions, SimOptions, StrutParams};

    fn record(cycles: f64) -> StrutRecord {
        let opts = SimOptions {
            output_rate_hz: 200.0,
            ..SimOptions::default()
        };
        let exc = Excitation::harmonic(2.0, 0.01, cycles);
        simulate_displacement(
            &StrutParams::front_axle(),
            &HpsExtensions::none(),
            &exc,
            &opts,
        )
        .unwrap()
    }

    #[test]
    fn last_period_is_one_closed_cycle() {
        let rec = record(3.0);
        let l = HysteresisLoop::last_period(&rec, 2.0).unwrap();
        // 0.5 s at 200 Hz: 100 intervals, 101 samples with both ends.
        assert_eq!(l.time.len(), 101);
        assert!((l.time[100] - l.time[0] - 0.5).abs() < 1e-9);
        assert!((l.displacement[0] - l.displacement[100]).abs() < 1e-6);
        let i = rec.time.len() - 1;
        assert_eq!(l.damping_force[100], rec.force[i] - rec.spring_force[i]);
    }

    #[test]
    fn per_cycle_splits_whole_periods() {
        let rec = record(3.0);
        let loops = HysteresisLoop::per_cycle(&rec, 2.0).unwrap();
        assert_eq!(loops.len(), 3);
        for (k, l) in loops.iter().enumerate() {
            assert!((l.time[0] - 0.5 * k as f64).abs() < 1e-9);
            assert_eq!(l.time.len(), 101);
        }
        assert_eq!(loops[2], HysteresisLoop::last_period(&rec, 2.0).unwrap());
    }

    #[test]
    fn bad_requests_are_errors() {
        let rec = record(1.0);
        assert!(HysteresisLoop::last_period(&rec, 0.0).is_err());
        assert!(HysteresisLoop::last_period(&rec, 1.0).is_err());
        assert!(HysteresisLoop::per_cycle(&rec, f64::NAN).is_err());
        assert!(HysteresisLoop::per_cycle(&rec, 1.0).unwrap().is_empty());
    }
}
