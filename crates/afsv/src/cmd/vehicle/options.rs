//! The options of `afsv vehicle` and their bounds: speeds, seed counts, durations (the
//! `--terrain` and `--steer` texts are `afsv_design::vehicle_case`'s). Every value is
//! checked when it is parsed, so a bad one is a one-line error naming the option.

use super::super::args;
pub(super) use afsv_design::vehicle_case::{parse_steer, parse_terrain, MAX_DURATION_S};
use afsv_design::vehicle_case::{MAX_STEER_DEG, RAMP_RATE_DEG_S};

/// Help of `--paper-form` (the vehicle commands and `afsv evaluate`).
pub(crate) const PAPER_FORM_HELP: &str = "Use the printed Eq 3.13 yaw inertias (m L² counted twice) instead of the energy-consistent equations, to reproduce the dissertation's lower yaw frequency; for comparison with the paper, never for design (docs/vehicle-3d.md)";

/// Largest number of terrain seeds of one command.
pub(super) const MAX_SEEDS: usize = 1000;

/// Highest speed the options accept (km/h): above the truck's top speed.
pub(super) const MAX_SPEED_KMH: f64 = 80.0;

/// A number > 0 of `unit` at most `max`.
fn at_most(s: &str, max: f64, unit: &str) -> Result<f64, String> {
    let v = args::positive_f64(s)?;
    if v <= max {
        Ok(v)
    } else {
        Err(format!("must be at most {max} {unit}"))
    }
}

/// A speed in km/h within (0, [`MAX_SPEED_KMH`]].
pub(super) fn speed_kmh(s: &str) -> Result<f64, String> {
    at_most(s, MAX_SPEED_KMH, "km/h")
}

/// A seed count within 1..=[`MAX_SEEDS`].
pub(super) fn seed_count(s: &str) -> Result<usize, String> {
    let n: usize = s
        .trim()
        .parse()
        .map_err(|_| format!("`{}` is not a whole number", s.trim()))?;
    if (1..=MAX_SEEDS).contains(&n) {
        Ok(n)
    } else {
        Err(format!("must be 1 to {MAX_SEEDS}"))
    }
}

/// A steering-wheel ramp rate within [`RAMP_RATE_DEG_S`] (deg/s).
pub(super) fn ramp_rate(s: &str) -> Result<f64, String> {
    let v = args::positive_f64(s)?;
    let (lo, hi) = RAMP_RATE_DEG_S;
    if (lo..=hi).contains(&v) {
        Ok(v)
    } else {
        Err(format!("must be {lo} to {hi} deg/s"))
    }
}

/// A steering-wheel angle within (0, [`MAX_STEER_DEG`]] (deg).
pub(super) fn steer_peak(s: &str) -> Result<f64, String> {
    at_most(s, MAX_STEER_DEG, "deg")
}

/// A duration within (0, [`MAX_DURATION_S`]] s.
pub(super) fn duration_s(s: &str) -> Result<f64, String> {
    at_most(s, MAX_DURATION_S, "s")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The largest accepted values (a run at each would take minutes; the refusals just
    /// above them are checked through the binary, tests/cli_vehicle.rs).
    #[test]
    fn bounded_options_accept_their_limits() {
        assert_eq!(seed_count("1000").unwrap(), 1000);
        assert!(duration_s("600").is_ok());
        assert!(ramp_rate("0.01").is_ok() && ramp_rate("1000").is_ok());
        assert!(steer_peak("1000").is_ok());
    }
}
