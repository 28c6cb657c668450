//! Value parsers for numeric options, shared by every subcommand: a number that is not
//! finite (nan, inf), or out of the option's range, is refused when the command line is
//! parsed, with a one-line message naming the value and the rule.
//!
//! Use as `#[arg(long, allow_hyphen_values = true, value_parser = args::positive_f64)]`.

pub use afsv_design::report::show;

/// Largest number of samples (time or space steps, rows) a command allocates for one record
/// of a few columns (strut records, terrain profiles: about 1 GB of memory at the limit).
pub const MAX_SAMPLES: f64 = 1e7;

/// Largest number of output samples of a strut run on the command line (the CSV of 1e7
/// rows alone takes half a minute to write).
pub const MAX_HPS_SAMPLES: f64 = 1e6;

/// Largest number of output samples of a yaw-plane run (about 40 columns and the solver's
/// dense output: 1.3 GB of memory and 0.7 GB of CSV at the limit).
pub const MAX_YAW_SAMPLES: f64 = afsv_dynamics::yaw_plane::simulate::MAX_OUTPUT_SAMPLES;

fn number(s: &str) -> Result<f64, String> {
    let t = s.trim();
    if t.is_empty() {
        return Err("expected a number, got an empty value".into());
    }
    let v: f64 = t.parse().map_err(|_| format!("`{t}` is not a number"))?;
    if !v.is_finite() {
        return Err(format!("`{t}` is not a finite number"));
    }
    Ok(v)
}

/// Any finite number.
pub fn finite_f64(s: &str) -> Result<f64, String> {
    number(s)
}

/// A finite number > 0.
pub fn positive_f64(s: &str) -> Result<f64, String> {
    let v = number(s)?;
    if v > 0.0 {
        Ok(v)
    } else {
        Err("must be > 0".into())
    }
}

/// A finite number >= 0.
pub fn nonneg_f64(s: &str) -> Result<f64, String> {
    let v = number(s)?;
    if v >= 0.0 {
        Ok(v)
    } else {
        Err("must be >= 0".into())
    }
}

/// A finite fraction in [0, 1).
pub fn fraction_f64(s: &str) -> Result<f64, String> {
    let v = number(s)?;
    if (0.0..1.0).contains(&v) {
        Ok(v)
    } else {
        Err("must lie in [0, 1)".into())
    }
}

/// A finite fraction in (0, 1).
pub fn open_fraction_f64(s: &str) -> Result<f64, String> {
    let v = number(s)?;
    if v > 0.0 && v < 1.0 {
        Ok(v)
    } else {
        Err("must lie in (0, 1)".into())
    }
}

/// `--json` of the commands whose JSON a terminal asks for explicitly (a pipe always gets
/// JSON).
#[derive(clap::Args, Debug, Clone, Copy, Default)]
pub struct JsonOutput {
    /// Print JSON even on a terminal.
    #[arg(long)]
    pub json: bool,
}

/// `count` samples (e.g. duration/dt) must not exceed `max` (e.g. [`MAX_SAMPLES`]): the
/// error names `option` and what was counted.
pub fn check_samples(option: &str, what: &str, count: f64, max: f64) -> Result<(), String> {
    if count.is_finite() && count <= max {
        Ok(())
    } else {
        Err(format!(
            "{option}: at most {max:e} samples ({what}); got {}",
            show(count)
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn refuses_non_finite_and_empty() {
        for bad in [
            "nan", "NaN", "inf", "-inf", "infinity", "", " ", "1e309", "abc", "2^64",
        ] {
            assert!(finite_f64(bad).is_err(), "{bad}");
            assert!(positive_f64(bad).is_err(), "{bad}");
            assert!(nonneg_f64(bad).is_err(), "{bad}");
        }
        assert_eq!(positive_f64("1e-320").unwrap(), 1e-320);
        assert!(positive_f64("0").is_err());
        assert!(positive_f64("-1").is_err());
        assert!(nonneg_f64("-1").is_err());
        assert_eq!(nonneg_f64("0").unwrap(), 0.0);
        assert!(fraction_f64("1").is_err());
        assert!(open_fraction_f64("0").is_err());
        assert!(
            check_samples("--duration", "duration/dt", 1e308, MAX_SAMPLES)
                .unwrap_err()
                .contains("--duration")
        );
        assert!(check_samples("--duration", "duration/dt", f64::INFINITY, MAX_SAMPLES).is_err());
        assert!(check_samples("--duration", "duration/dt", 2001.0, MAX_SAMPLES).is_ok());
    }

    proptest! {
        #[test]
        fn finite_numbers_round_trip(v in proptest::num::f64::ANY) {
            let s = v.to_string();
            let r = finite_f64(&s);
            prop_assert_eq!(r.is_ok(), v.is_finite());
            if let Ok(x) = r {
                prop_assert_eq!(x, v);
            }
            prop_assert_eq!(positive_f64(&s).is_ok(), v.is_finite() && v > 0.0);
            prop_assert_eq!(nonneg_f64(&s).is_ok(), v.is_finite() && v >= 0.0);
            prop_assert_eq!(fraction_f64(&s).is_ok(), v.is_finite() && (0.0..1.0).contains(&v));
        }

        #[test]
        fn never_panics_on_any_text(s in ".*") {
            let _ = finite_f64(&s);
            let _ = positive_f64(&s);
            let _ = nonneg_f64(&s);
            let _ = open_fraction_f64(&s);
        }

        #[test]
        fn accepted_values_are_in_range(s in "[-+]?[0-9]{0,4}(\\.[0-9]{0,3})?(e[-+]?[0-9]{1,3})?") {
            if let Ok(v) = positive_f64(&s) { prop_assert!(v.is_finite() && v > 0.0); }
            if let Ok(v) = nonneg_f64(&s) { prop_assert!(v.is_finite() && v >= 0.0); }
            if let Ok(v) = open_fraction_f64(&s) { prop_assert!(v > 0.0 && v < 1.0); }
        }

        #[test]
        fn sample_bound_is_exact(n in 0.0f64..2e7) {
            prop_assert_eq!(check_samples("--x", "n", n, MAX_SAMPLES).is_ok(), n <= MAX_SAMPLES);
        }
    }
}
