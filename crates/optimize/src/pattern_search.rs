//! Generalized pattern search (Torczon 1997; Audet & Dennis 2003) on the unit-scaled box:
//! a complete poll of the 2n directions `±e_i` times the mesh size, the mesh doubled after a
//! successful iteration and halved after a failed one, an optional search step (one Latin
//! hypercube, evaluated at the first iteration), trial points projected onto the bounds, and
//! nonlinear constraints as an extreme barrier (an infeasible or failed point counts as
//! [`crate::BARRIER`]; from an infeasible start the search first walks to feasibility by
//! Deb's rules, i.e. by falling total violation).
//!
//! The state after each iteration ([`PatternSearchState`]) holds everything the next
//! iterations depend on; a run resumed from it continues exactly as an uninterrupted one.

use crate::batch::{evaluate_batch, Progress};
use crate::lhs::{latin_hypercube, LhsOptions};
use crate::problem::{require, ConstrainedProblem, Evaluation, OptimizeError};
use serde::{Deserialize, Serialize};

/// Settings of the pattern search (mesh sizes in unit-cube coordinates).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct PatternSearchOptions {
    /// Initial mesh size (0 < mesh <= `max_mesh`).
    pub initial_mesh: f64,
    /// Stop when the mesh falls below this.
    pub min_mesh: f64,
    /// Largest mesh size.
    pub max_mesh: f64,
    /// Mesh factor after a successful iteration (>= 1).
    pub expansion: f64,
    /// Mesh factor after a failed poll (in (0, 1)).
    pub contraction: f64,
    /// Stop when this many evaluations have been made (checked after each iteration).
    pub max_evaluations: usize,
    /// Points of the Latin hypercube of the search step (0: no search step).
    pub search_points: usize,
    /// Seed of that hypercube.
    pub seed: u64,
    /// Hypercubes drawn for its maximin criterion.
    pub maximin_candidates: usize,
}

impl Default for PatternSearchOptions {
    fn default() -> Self {
        Self {
            initial_mesh: 0.25,
            min_mesh: 1e-4,
            max_mesh: 1.0,
            expansion: 2.0,
            contraction: 0.5,
            max_evaluations: 5000,
            search_points: 0,
            seed: 0,
            maximin_candidates: 10,
        }
    }
}

impl PatternSearchOptions {
    /// Checks every setting.
    pub fn validate(&self) -> Result<(), OptimizeError> {
        require(
            self.max_mesh.is_finite() && self.max_mesh > 0.0,
            "max_mesh",
            "finite and > 0",
        )?;
        require(
            self.initial_mesh > 0.0 && self.initial_mesh <= self.max_mesh,
            "initial_mesh",
            "in (0, max_mesh]",
        )?;
        require(
            self.min_mesh > 0.0 && self.min_mesh < self.initial_mesh,
            "min_mesh",
            "in (0, initial_mesh)",
        )?;
        require(
            self.expansion.is_finite() && self.expansion >= 1.0,
            "expansion",
            ">= 1",
        )?;
        require(
            self.contraction > 0.0 && self.contraction < 1.0,
            "contraction",
            "in (0, 1)",
        )?;
        require(self.max_evaluations >= 1, "max_evaluations", ">= 1")?;
        require(self.maximin_candidates >= 1, "maximin_candidates", ">= 1")
    }
}

/// Why a pattern search stopped.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PatternStop {
    /// The mesh fell below `min_mesh`: the point is a mesh-local optimum.
    MeshConverged,
    /// `max_evaluations` was reached.
    EvaluationLimit,
}

/// The whole state of a pattern search between iterations.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PatternSearchState {
    /// Incumbent in unit-cube coordinates.
    pub u: Vec<f64>,
    /// Incumbent in the problem's units.
    pub x: Vec<f64>,
    /// Its evaluation.
    pub eval: Evaluation,
    /// Current mesh size.
    pub mesh: f64,
    /// Completed iterations.
    pub iteration: usize,
    /// Evaluations made so far (the start point included).
    pub evaluations: usize,
    /// Set once the search has stopped.
    pub stop: Option<PatternStop>,
    /// Whether the search step of the first iteration has been evaluated.
    #[serde(default)]
    pub search_done: bool,
}

impl PatternSearchState {
    /// The incumbent's value under the extreme barrier.
    pub fn value(&self) -> f64 {
        self.eval.barrier_value()
    }
}

/// A pattern search of one problem with fixed settings.
pub struct PatternSearch<'a, P: ConstrainedProblem + ?Sized> {
    problem: &'a P,
    options: PatternSearchOptions,
}

impl<'a, P: ConstrainedProblem + ?Sized> PatternSearch<'a, P> {
    /// A search of `problem` with validated `options`.
    pub fn new(problem: &'a P, options: PatternSearchOptions) -> Result<Self, OptimizeError> {
        options.validate()?;
        Ok(Self { problem, options })
    }

    /// The state at `x0` (projected onto the bounds and evaluated once).
    pub fn start(&self, x0: &[f64]) -> Result<PatternSearchState, OptimizeError> {
        let b = self.problem.bounds();
        require(x0.len() == b.dim(), "x0", "one value per variable")?;
        require(x0.iter().all(|v| v.is_finite()), "x0", "finite")?;
        let u: Vec<f64> = b.to_unit(x0).iter().map(|v| v.clamp(0.0, 1.0)).collect();
        let x = b.from_unit(&u);
        let eval = self.problem.evaluate(&x);
        Ok(PatternSearchState {
            u,
            x,
            eval,
            mesh: self.options.initial_mesh,
            iteration: 0,
            evaluations: 1,
            stop: None,
            search_done: false,
        })
    }

    /// Checks a saved state as strictly as an input: it belongs to this problem (one
    /// unit-cube coordinate per variable, in [0, 1]; `x` the image of `u`; one finite value
    /// per constraint), its mesh is one this search can reach (finite, in
    /// [`min_mesh` x `contraction`, `max_mesh`], on the grid `initial_mesh` x
    /// `contraction`^k when `expansion` x `contraction` = 1), its counts are consistent (at
    /// least one evaluation per iteration besides the start point) and a stop agrees with
    /// its mesh or count.
    pub fn check_state(&self, s: &PatternSearchState) -> Result<(), OptimizeError> {
        let bad = |what: String| {
            Err(OptimizeError::Checkpoint(format!(
                "pattern-search state: {what}"
            )))
        };
        let b = self.problem.bounds();
        let o = &self.options;
        if s.u.len() != b.dim() || s.x.len() != b.dim() {
            return bad(format!(
                "{} unit coordinates and {} values for a problem of {} variables",
                s.u.len(),
                s.x.len(),
                b.dim()
            ));
        }
        if s.eval.constraints.len() != self.problem.n_constraints() {
            return bad(format!(
                "{} constraint values for a problem of {}",
                s.eval.constraints.len(),
                self.problem.n_constraints()
            ));
        }
        if let Some(u) = s.u.iter().find(|u| !(0.0..=1.0).contains(*u)) {
            return bad(format!("unit coordinate {u:?} outside [0, 1]"));
        }
        if s.x != b.from_unit(&s.u) {
            return bad("the point x is not the image of its unit coordinates u".into());
        }
        if !(s.eval.f.is_finite() && s.eval.constraints.iter().all(|c| c.is_finite())) {
            return bad("an objective or constraint value that is not finite".into());
        }
        if !(s.mesh.is_finite() && s.mesh >= o.min_mesh * o.contraction && s.mesh <= o.max_mesh) {
            return bad(format!(
                "mesh {:?} outside [{:?}, {:?}]",
                s.mesh,
                o.min_mesh * o.contraction,
                o.max_mesh
            ));
        }
        if o.expansion * o.contraction == 1.0 && !on_grid(s.mesh, o) {
            return bad(format!(
                "mesh {:?} is not {:?} times a power of {:?}",
                s.mesh, o.initial_mesh, o.contraction
            ));
        }
        if s.evaluations < 1 + s.iteration {
            return bad(format!(
                "{} evaluations for {} iterations",
                s.evaluations, s.iteration
            ));
        }
        let consistent = match s.stop {
            Some(PatternStop::MeshConverged) => s.mesh < o.min_mesh,
            Some(PatternStop::EvaluationLimit) => s.evaluations >= o.max_evaluations,
            None => true,
        };
        if !consistent {
            return bad(format!(
                "stop {:?} with mesh {} and {} evaluations",
                s.stop, s.mesh, s.evaluations
            ));
        }
        if s.search_done && o.search_points == 0
            || s.iteration > 0 && o.search_points > 0 && !s.search_done
        {
            return bad("a search step that these settings do not make".into());
        }
        Ok(())
    }

    /// One iteration: the search step at iteration 0 (if configured; a success skips the
    /// poll), otherwise a complete poll; then the mesh update and the stopping tests. The
    /// batches are evaluated in parallel ([`PatternSearch::ask`], [`PatternSearch::tell`]).
    pub fn step(&self, s: &mut PatternSearchState) -> Result<(), OptimizeError> {
        let iteration = s.iteration;
        let b = self.problem.bounds();
        while s.stop.is_none() && s.iteration == iteration {
            let xs: Vec<Vec<f64>> = self.ask(s)?.iter().map(|u| b.from_unit(u)).collect();
            let evals = evaluate_batch(self.problem, &xs);
            self.tell(s, evals)?;
        }
        Ok(())
    }

    /// The next batch in unit-cube coordinates (empty once stopped): the search hypercube
    /// at the first iteration if configured and not yet evaluated, else the poll points.
    /// Evaluate them anywhere (in order) and hand the results to [`PatternSearch::tell`].
    pub fn ask(&self, s: &PatternSearchState) -> Result<Vec<Vec<f64>>, OptimizeError> {
        if s.stop.is_some() {
            return Ok(Vec::new());
        }
        if self.in_search(s) {
            return latin_hypercube(&LhsOptions {
                points: self.options.search_points,
                dim: s.u.len(),
                seed: self.options.seed,
                maximin_candidates: self.options.maximin_candidates,
            });
        }
        let mut units = Vec::with_capacity(2 * s.u.len());
        for i in 0..s.u.len() {
            for sign in [1.0, -1.0] {
                let mut u = s.u.clone();
                u[i] = (u[i] + sign * s.mesh).clamp(0.0, 1.0);
                if u[i] != s.u[i] {
                    units.push(u);
                }
            }
        }
        Ok(units)
    }

    /// Advances by the evaluations of the batch [`PatternSearch::ask`] gives for `s` (in
    /// its order): moves to the best improving point, then (after a poll, or a successful
    /// search) updates the mesh and tests the stops; a failed search leaves the poll of the
    /// same iteration to come.
    pub fn tell(
        &self,
        s: &mut PatternSearchState,
        evals: Vec<Evaluation>,
    ) -> Result<(), OptimizeError> {
        let units = self.ask(s)?;
        require(
            evals.len() == units.len()
                && evals
                    .iter()
                    .all(|e| e.constraints.len() == self.problem.n_constraints()),
            "evals",
            "one evaluation per asked point, with every constraint",
        )?;
        if s.stop.is_some() {
            return Ok(());
        }
        let searching = self.in_search(s);
        let success = self.accept(s, units, evals);
        if searching {
            s.search_done = true;
            if !success {
                return Ok(());
            }
        }
        if success {
            s.mesh = (s.mesh * self.options.expansion).min(self.options.max_mesh);
        } else {
            s.mesh *= self.options.contraction;
        }
        s.iteration += 1;
        if s.mesh < self.options.min_mesh {
            s.stop = Some(PatternStop::MeshConverged);
        } else if s.evaluations >= self.options.max_evaluations {
            s.stop = Some(PatternStop::EvaluationLimit);
        }
        Ok(())
    }

    fn in_search(&self, s: &PatternSearchState) -> bool {
        s.iteration == 0 && self.options.search_points > 0 && !s.search_done
    }

    /// Iterates until a stop, calling `checkpoint` after every iteration (a failing
    /// checkpoint stops the run with its error).
    pub fn run(
        &self,
        mut s: PatternSearchState,
        progress: &dyn Progress,
        checkpoint: &mut dyn FnMut(&PatternSearchState) -> Result<(), String>,
    ) -> Result<PatternSearchState, OptimizeError> {
        self.check_state(&s)?;
        while s.stop.is_none() {
            self.step(&mut s)?;
            progress.report(
                "pattern search",
                s.evaluations,
                self.options.max_evaluations,
                s.value(),
            );
            checkpoint(&s).map_err(|e| OptimizeError::Invalid {
                field: "checkpoint",
                reason: e,
            })?;
        }
        Ok(s)
    }

    /// Moves to the first best of the evaluated `units` if it beats the incumbent: under the
    /// extreme barrier from a feasible incumbent; by Deb's rules (less total violation)
    /// while the incumbent is still infeasible.
    fn accept(
        &self,
        s: &mut PatternSearchState,
        units: Vec<Vec<f64>>,
        evals: Vec<Evaluation>,
    ) -> bool {
        let b = self.problem.bounds();
        let xs: Vec<Vec<f64>> = units.iter().map(|u| b.from_unit(u)).collect();
        s.evaluations += evals.len();
        let feasible = s.eval.is_feasible();
        let mut best: Option<usize> = None;
        for (i, e) in evals.iter().enumerate() {
            let incumbent = best.map_or(&s.eval, |j| &evals[j]);
            let better = if feasible {
                e.barrier_value() < incumbent.barrier_value()
            } else {
                e.deb_cmp(incumbent).is_lt()
            };
            if better {
                best = Some(i);
            }
        }
        match best {
            Some(i) => {
                s.u = units[i].clone();
                s.x = xs[i].clone();
                s.eval = evals[i].clone();
                true
            }
            None => false,
        }
    }
}

/// Whether `mesh` is `initial_mesh` or `max_mesh` times an integral power of `contraction`
/// (the sizes a search that halves and doubles can reach), to a relative 1e-12.
fn on_grid(mesh: f64, o: &PatternSearchOptions) -> bool {
    [o.initial_mesh, o.max_mesh].iter().any(|base| {
        let k = (mesh / base).ln() / o.contraction.ln();
        let near = base * o.contraction.powi(k.round() as i32);
        k.is_finite() && ((near - mesh) / mesh).abs() < 1e-12
    })
}
