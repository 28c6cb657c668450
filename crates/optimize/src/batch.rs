//! Parallel evaluation of a batch of points (rayon). Results come back in the order of the
//! points, and every reduction over them is done afterwards in that order, so a run gives
//! the same bytes on any number of threads.

use crate::problem::{ConstrainedProblem, Evaluation};
use rayon::prelude::*;

/// Reports a solver's progress (a CLI draws a bar on stderr; the library prints nothing).
pub trait Progress: Sync {
    /// `done` of `total` evaluations (or iterations) of the phase `phase`, best value so far.
    fn report(&self, phase: &str, done: usize, total: usize, best: f64);
}

/// A [`Progress`] that reports nothing.
#[derive(Debug, Clone, Copy, Default)]
pub struct Silent;

impl Progress for Silent {
    fn report(&self, _phase: &str, _done: usize, _total: usize, _best: f64) {}
}

/// Evaluates `points` (in the problem's own units) in parallel; the i-th result belongs to
/// the i-th point.
pub fn evaluate_batch<P: ConstrainedProblem + ?Sized>(
    problem: &P,
    points: &[Vec<f64>],
) -> Vec<Evaluation> {
    points.par_iter().map(|x| problem.evaluate(x)).collect()
}
