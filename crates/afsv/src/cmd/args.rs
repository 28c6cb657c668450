//! Value parsers for numeric options, shared by every subcommand (the number rules are
//! `afsv_design::value_lists`'s, re-exported): a number that is not finite (nan, inf), or
//! out of the option's range, is refused when the command line is parsed, with a one-line
//! message naming the value and the rule; sample bounds of a run.
//!
//! Use as `#[arg(long, allow_hyphen_values = true, value_parser = args::positive_f64)]`.

pub use afsv_design::report::show;
pub use afsv_design::value_lists::{
    finite_f64, fraction_f64, nonneg_f64, open_fraction_f64, positive_f64,
};

/// Largest number of samples (time or space steps, rows) a command allocates for one record
/// of a few columns (strut records, terrain profiles: about 1 GB of memory at the limit).
pub const MAX_SAMPLES: f64 = 1e7;

/// Largest number of output samples of a strut run on the command line (the CSV of 1e7
/// rows alone takes half a minute to write).
pub const MAX_HPS_SAMPLES: f64 = 1e6;

/// Largest number of output samples of a yaw-plane run (about 40 columns and the solver's
/// dense output: 1.3 GB of memory and 0.7 GB of CSV at the limit).
pub const MAX_YAW_SAMPLES: f64 = afsv_dynamics::yaw_plane::simulate::MAX_OUTPUT_SAMPLES;

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

/// `duration / dt` output samples of a run must not exceed `max` ([`check_samples`] of
/// `--duration` with `--dt`).
pub fn check_duration(duration: f64, dt: f64, max: f64) -> Result<(), String> {
    check_samples(
        &format!("--duration {}", show(duration)),
        &format!("duration/dt with --dt {}", show(dt)),
        duration / dt,
        max,
    )
}

/// `--seeds N` within 1..=`max`.
pub fn check_seeds(n: usize, max: usize) -> Result<(), String> {
    if (1..=max).contains(&n) {
        Ok(())
    } else {
        Err(format!("--seeds {n}: must be 1 to {max}"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn sample_bounds_name_the_option() {
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
        fn sample_bound_is_exact(n in 0.0f64..2e7) {
            prop_assert_eq!(check_samples("--x", "n", n, MAX_SAMPLES).is_ok(), n <= MAX_SAMPLES);
        }
    }
}
