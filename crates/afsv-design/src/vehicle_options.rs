//! The bounded numbers of the `afsv vehicle` options ([`crate::vehicle_case`]'s runs):
//! speeds, seed counts, steering ramps and peaks, durations, course offsets. Each is a
//! value parser: a value outside its bounds is refused with the rule, in one line, when the
//! command line is parsed.

use crate::value_lists::{finite_f64, positive_f64};
use crate::vehicle_case::{MAX_DURATION_S, MAX_STEER_DEG, RAMP_RATE_DEG_S};

/// Largest number of terrain seeds of one command.
pub const MAX_SEEDS: usize = 1000;

/// Highest speed the options accept (km/h): above the truck's top speed.
pub const MAX_SPEED_KMH: f64 = 80.0;

/// Largest lateral offset of a path-change course (m): a lane change of a few truck widths.
pub const MAX_OFFSET_M: f64 = 20.0;

/// A number > 0 of `unit` at most `max`.
fn at_most(s: &str, max: f64, unit: &str) -> Result<f64, String> {
    let v = positive_f64(s)?;
    if v <= max {
        Ok(v)
    } else {
        Err(format!("must be at most {max} {unit}"))
    }
}

/// A speed in km/h within (0, [`MAX_SPEED_KMH`]].
pub fn speed_kmh(s: &str) -> Result<f64, String> {
    at_most(s, MAX_SPEED_KMH, "km/h")
}

/// A seed count within 1..=[`MAX_SEEDS`].
pub fn seed_count(s: &str) -> Result<usize, String> {
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
pub fn ramp_rate(s: &str) -> Result<f64, String> {
    let v = positive_f64(s)?;
    let (lo, hi) = RAMP_RATE_DEG_S;
    if (lo..=hi).contains(&v) {
        Ok(v)
    } else {
        Err(format!("must be {lo} to {hi} deg/s"))
    }
}

/// A steering-wheel angle within (0, [`MAX_STEER_DEG`]] (deg).
pub fn steer_peak(s: &str) -> Result<f64, String> {
    at_most(s, MAX_STEER_DEG, "deg")
}

/// A duration within (0, [`MAX_DURATION_S`]] s.
pub fn duration_s(s: &str) -> Result<f64, String> {
    at_most(s, MAX_DURATION_S, "s")
}

/// A signed course offset within ±[`MAX_OFFSET_M`] (m).
pub fn offset_m(s: &str) -> Result<f64, String> {
    let v = finite_f64(s)?;
    if v.abs() <= MAX_OFFSET_M {
        Ok(v)
    } else {
        Err(format!("must be at most {MAX_OFFSET_M} m in magnitude"))
    }
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

    /// Just outside each bound, and the offset's sign.
    #[test]
    fn bounded_options_refuse_beyond_their_limits() {
        assert_eq!(seed_count("1001").unwrap_err(), "must be 1 to 1000");
        assert!(seed_count("0").is_err() && seed_count("1.5").is_err());
        assert_eq!(speed_kmh("80.5").unwrap_err(), "must be at most 80 km/h");
        assert!(duration_s("600.1").is_err() && ramp_rate("0.005").is_err());
        assert_eq!(offset_m("-20").unwrap(), -20.0);
        assert!(offset_m("20.01").unwrap_err().contains("in magnitude"));
    }
}
