//! How many samples one command may ask a run for: the memory and the time a record of
//! `duration / dt` rows (or a profile of `length / dx` points, a strut programme of
//! `cycles / freq * rate`) takes grow with it, so an option that asks for more than a
//! bound is refused before anything runs, with a one-line error naming the option, what was
//! counted and the bound ([`check_samples`]); and the seed counts of the studies
//! ([`check_seeds`], [`seed_list`]).

use crate::report::show;

/// Largest number of samples (time or space steps, rows) a command allocates for one record
/// of a few columns (strut records, terrain profiles: about 1 GB of memory at the limit).
pub const MAX_SAMPLES: f64 = 1e7;

/// Largest number of output samples of a strut run on the command line (the CSV of 1e7
/// rows alone takes half a minute to write).
pub const MAX_HPS_SAMPLES: f64 = 1e6;

/// Largest number of output samples of a yaw-plane run (about 40 columns and the solver's
/// dense output: 1.3 GB of memory and 0.7 GB of CSV at the limit).
pub const MAX_YAW_SAMPLES: f64 = afsv_dynamics::yaw_plane::simulate::MAX_OUTPUT_SAMPLES;

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

/// A terrain profile of `length / dx` points (`afsv terrain generate`) within
/// [`MAX_SAMPLES`].
pub fn check_profile(length: f64, dx: f64) -> Result<(), String> {
    check_samples(
        &format!("--length {}", show(length)),
        &format!("length/dx with --dx {}", show(dx)),
        length / dx,
        MAX_SAMPLES,
    )
}

/// A harmonic strut run of `cycles / freq * rate` output samples (`afsv hps harmonic`)
/// within [`MAX_HPS_SAMPLES`].
pub fn check_cycles(cycles: f64, freq: f64, rate: f64) -> Result<(), String> {
    check_samples(
        &format!("--cycles {}", show(cycles)),
        &format!(
            "cycles / freq * rate with --freq {} --rate {}",
            show(freq),
            show(rate)
        ),
        cycles / freq * rate,
        MAX_HPS_SAMPLES,
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

/// The `n` common terrain seeds from `first` on (`crate::fan_out::seed_range`), `n` within
/// 1..=`max` ([`check_seeds`]).
pub fn seed_list(first: u64, n: usize, max: usize) -> Result<Vec<u64>, String> {
    check_seeds(n, max)?;
    Ok(crate::fan_out::seed_range(first, n as u64))
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

    #[test]
    fn profiles_runs_and_seeds_within_their_bounds() {
        assert!(check_profile(100.0, 0.05).is_ok());
        let e = check_profile(1e6, 0.05).unwrap_err();
        assert!(
            e.starts_with("--length 1000000: at most 1e7 samples"),
            "{e}"
        );
        assert!(check_cycles(5.0, 2.0, 360.0).is_ok());
        let e = check_cycles(1e4, 0.1, 360.0).unwrap_err();
        assert!(e.contains("--freq 0.1 --rate 360"), "{e}");
        assert!(check_duration(10.0, 1e-6, MAX_YAW_SAMPLES).is_err());
        assert!(check_seeds(1, 100).is_ok() && check_seeds(100, 100).is_ok());
        assert_eq!(
            check_seeds(0, 100).unwrap_err(),
            "--seeds 0: must be 1 to 100"
        );
    }

    proptest! {
        #[test]
        fn sample_bound_is_exact(n in 0.0f64..2e7) {
            prop_assert_eq!(check_samples("--x", "n", n, MAX_SAMPLES).is_ok(), n <= MAX_SAMPLES);
        }
    }
}
