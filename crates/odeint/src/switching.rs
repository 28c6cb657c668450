//! When [`crate::Solver::Auto`] hands a run between Dormand-Prince and ROS34PW2, on a model
//! that declares stiff blocks ([`crate::OdeSystem::stiff_blocks`]).
//!
//! Dormand-Prince runs first and watches for stiffness (its step held at the stability
//! boundary, [`crate::dopri5`]). When it finds it, ROS34PW2 takes over on trial for
//! [`TRIAL_STEPS`] accepted steps; if it advanced more simulated time per right-hand side
//! than Dormand-Prince did over its last phase, it keeps the run, otherwise Dormand-Prince
//! takes it back and acts on stiffness again only after [`COOLDOWN_STEPS`] accepted steps.
//! A stiff design (a small strut orifice) thus runs implicitly, and a run whose explicit
//! steps are only moderately limited keeps the cheaper explicit method.

use crate::Stats;

/// Accepted ROS34PW2 steps of a trial before its pace is compared.
pub(crate) const TRIAL_STEPS: usize = 100;

/// Accepted Dormand-Prince steps after a failed trial before stiffness is acted on again.
pub(crate) const COOLDOWN_STEPS: usize = 2000;

/// Why a phase of a run ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Flow {
    /// The run is over (end time, or the observer stopped it).
    Done,
    /// The other method takes over at the current time.
    Switch,
}

/// Where a phase began: time, right-hand sides and accepted steps so far.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct Mark {
    t: f64,
    rhs: usize,
    accepted: usize,
}

/// The switching rule of the method running now.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum SwitchRule {
    /// No switching (every solver but a switching `Auto`).
    Never,
    /// The explicit method: hand over at detected stiffness from `not_before` accepted steps on.
    Watching { not_before: usize, phase: Mark },
    /// The implicit method on trial: keep the run if its pace beats `explicit_pace`.
    Trial { explicit_pace: f64, phase: Mark },
}

impl SwitchRule {
    /// The explicit phase, acting on stiffness once `accepted` reaches the first phase's 0 or,
    /// after a failed trial, `accepted + COOLDOWN_STEPS`.
    pub(crate) fn watching(accepted: usize) -> Self {
        let not_before = if accepted == 0 {
            0
        } else {
            accepted + COOLDOWN_STEPS
        };
        Self::Watching {
            not_before,
            phase: Mark::default(),
        }
    }

    /// The implicit trial against the explicit phase's pace (simulated s per RHS call).
    pub(crate) fn trial(explicit_pace: f64) -> Self {
        Self::Trial {
            explicit_pace,
            phase: Mark::default(),
        }
    }

    /// Start a phase at `t`.
    pub(crate) fn start_phase(&mut self, t: f64, stats: &Stats) {
        let mark = Mark {
            t,
            rhs: stats.rhs_evals,
            accepted: stats.accepted,
        };
        match self {
            Self::Never => {}
            Self::Watching { phase, .. } | Self::Trial { phase, .. } => *phase = mark,
        }
    }

    /// Simulated time per right-hand-side call since the phase began.
    pub(crate) fn phase_pace(&self, t: f64, stats: &Stats) -> f64 {
        match self {
            Self::Never => 0.0,
            Self::Watching { phase, .. } | Self::Trial { phase, .. } => {
                (t - phase.t) / stats.rhs_evals.saturating_sub(phase.rhs).max(1) as f64
            }
        }
    }

    /// After an accepted step at `t`: hand the run over now? `stiff` is the running
    /// method's stiffness verdict. A successful trial ends the switching.
    pub(crate) fn switch_now(&mut self, t: f64, stats: &Stats, stiff: bool) -> bool {
        match *self {
            Self::Never => false,
            Self::Watching { not_before, .. } => stiff && stats.accepted >= not_before,
            Self::Trial {
                explicit_pace,
                phase,
            } => {
                if stats.accepted - phase.accepted < TRIAL_STEPS {
                    return false;
                }
                if self.phase_pace(t, stats) >= explicit_pace {
                    *self = Self::Never;
                    false
                } else {
                    true
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn stats(rhs_evals: usize, accepted: usize) -> Stats {
        Stats {
            rhs_evals,
            accepted,
            ..Stats::default()
        }
    }

    #[test]
    fn watching_acts_on_stiffness_after_its_cooldown() {
        let mut first = SwitchRule::watching(0);
        assert!(!first.switch_now(1.0, &stats(60, 10), false));
        assert!(first.switch_now(1.0, &stats(60, 10), true));
        let mut again = SwitchRule::watching(500);
        assert!(!again.switch_now(1.0, &stats(9000, 500 + COOLDOWN_STEPS - 1), true));
        assert!(again.switch_now(1.0, &stats(9000, 500 + COOLDOWN_STEPS), true));
    }

    #[test]
    fn a_trial_keeps_the_faster_method() {
        // explicit pace 1e-4 s per call; the trial starts at t = 1 after 1 000 calls
        let start = stats(1000, 200);
        let mut won = SwitchRule::trial(1e-4);
        won.start_phase(1.0, &start);
        assert!(!won.switch_now(1.01, &stats(1010, 250), false), "too early");
        // 100 steps, 400 calls, 0.2 s: 5e-4 s per call beats 1e-4
        assert!(!won.switch_now(1.2, &stats(1400, 300), false));
        assert_eq!(won, SwitchRule::Never);
        let mut lost = SwitchRule::trial(1e-4);
        lost.start_phase(1.0, &start);
        // 0.02 s in 400 calls: 5e-5 s per call, slower
        assert!(lost.switch_now(1.02, &stats(1400, 300), false));
    }
}
