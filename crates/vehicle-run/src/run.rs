//! A run's settings and its integrator: the output grid, bounded before it is allocated,
//! and Dormand-Prince (or the run's solver) with per-state absolute tolerances from the
//! states' typical magnitudes (`odeint::Atol::scaled`).

use odeint::{Atol, Integrator, OdeError, Solver};

use crate::error::{positive, rejected, RunError};

/// The span of a run: how long, how often it is recorded, how accurately and in how large
/// steps at most.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RunSpan {
    /// End time (s).
    pub t_end_s: f64,
    /// Output interval (s).
    pub output_dt_s: f64,
    /// Relative tolerance.
    pub rtol: f64,
    /// Largest step (s).
    pub max_step_s: f64,
}

impl RunSpan {
    /// Check the fields and bound the number of output samples by `max_samples`; returns
    /// the number of samples, `floor(t_end / dt) + 1`.
    pub fn samples(&self, max_samples: usize) -> Result<usize, RunError> {
        positive("t_end_s", self.t_end_s)?;
        positive("output_dt_s", self.output_dt_s)?;
        positive("rtol", self.rtol)?;
        positive("max_step_s", self.max_step_s)?;
        let n = (self.t_end_s / self.output_dt_s).floor() + 1.0;
        if n > max_samples as f64 {
            return Err(rejected(
                "output_dt_s",
                self.output_dt_s,
                "too many output samples (raise output_dt_s or lower t_end_s)",
            ));
        }
        Ok(n as usize)
    }

    /// The output times `0, dt, 2 dt, ...` of a run of `n` samples ([`RunSpan::samples`]).
    pub fn output_times(&self, n: usize) -> Vec<f64> {
        (0..n).map(|i| i as f64 * self.output_dt_s).collect()
    }
}

/// The settings of a multibody vehicle's run (each vehicle's `RunOptions`): the span they
/// fix, and their check, written once here.
pub trait RunSettings {
    /// Largest number of output samples of one run.
    const MAX_SAMPLES: usize;

    /// The run's span: end time, output interval, tolerance, largest step.
    fn span(&self) -> RunSpan;

    /// Check the fields and bound the sample count by [`RunSettings::MAX_SAMPLES`];
    /// returns the number of samples ([`RunSpan::samples`]).
    fn validate(&self) -> Result<usize, RunError> {
        self.span().samples(Self::MAX_SAMPLES)
    }
}

/// The integrator of a run: `solver` at the span's relative tolerance, the absolute
/// tolerance of state `i` `rtol * typical[i]`, steps of at most the span's largest step.
pub fn integrator(
    solver: Solver,
    span: &RunSpan,
    typical: impl IntoIterator<Item = f64>,
) -> Integrator {
    Integrator::new(solver, span.rtol, Atol::scaled(span.rtol, typical))
        .with_max_step(span.max_step_s)
}

/// The run error of an integration error: a collapsing step names its dominant state
/// (`state_name`), everything else is passed on with its time and state.
pub fn run_error(e: OdeError, state_name: impl Fn(usize) -> String) -> RunError {
    match e {
        OdeError::StepSizeCollapsed { dominant_state, .. } => RunError::Stiff {
            state: state_name(dominant_state),
            source: e,
        },
        other => RunError::Integration(other),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn span() -> RunSpan {
        RunSpan {
            t_end_s: 1.0,
            output_dt_s: 0.25,
            rtol: 1e-4,
            max_step_s: 0.01,
        }
    }

    #[test]
    fn the_grid_has_floor_t_over_dt_plus_one_samples_and_is_bounded() {
        let s = span();
        assert_eq!(s.samples(100), Ok(5));
        assert_eq!(s.output_times(5), [0.0, 0.25, 0.5, 0.75, 1.0]);
        let e = s.samples(4).unwrap_err().to_string();
        assert!(e.contains("output_dt_s") && e.contains("too many"), "{e}");
        let bad = RunSpan {
            max_step_s: f64::NAN,
            ..s
        };
        assert!(bad
            .samples(100)
            .unwrap_err()
            .to_string()
            .contains("max_step_s"));
    }

    #[test]
    fn settings_are_checked_through_their_span_against_their_own_bound() {
        struct Few(RunSpan);
        impl RunSettings for Few {
            const MAX_SAMPLES: usize = 4;
            fn span(&self) -> RunSpan {
                self.0
            }
        }
        assert_eq!(
            Few(RunSpan {
                t_end_s: 0.5,
                ..span()
            })
            .validate(),
            Ok(3)
        );
        let e = Few(span()).validate().unwrap_err().to_string();
        assert!(e.contains("too many output samples"), "{e}");
    }

    #[test]
    fn a_collapsing_step_names_its_state_and_other_errors_pass_through() {
        let collapsed = OdeError::StepSizeCollapsed {
            t: 1.0,
            h: 1e-14,
            projected_steps: 1e9,
            max_steps: 1000,
            dominant_state: 3,
            state: vec![0.0; 4],
        };
        match run_error(collapsed, |i| format!("state {i}")) {
            RunError::Stiff { state, .. } => assert_eq!(state, "state 3"),
            other => panic!("{other:?}"),
        }
        let limit = OdeError::TooManySteps {
            max_steps: 10,
            t: 0.5,
            state: vec![1.0],
        };
        assert!(matches!(
            run_error(limit, |_| String::new()),
            RunError::Integration(OdeError::TooManySteps { .. })
        ));
    }
}
