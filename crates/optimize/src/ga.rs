//! A real-coded genetic algorithm on the unit-scaled box (Deb 2000; Deb & Agrawal 1995):
//! binary tournaments under Deb's feasibility rules (no penalty parameter), simulated
//! binary crossover (SBX) and polynomial mutation, both bounded, and elitist (mu + lambda)
//! survival: parents and children are ranked together by Deb's rules and the best
//! `population` survive, so the best point never gets lost.
//!
//! All random numbers are drawn in the calling thread from one seeded stream whose position
//! is part of [`GaState`]; only the evaluations run in parallel. A run therefore gives the
//! same bytes on any number of threads, and one resumed from a saved state continues
//! exactly as an uninterrupted one.

use crate::batch::{evaluate_batch, Progress};
use crate::lhs::{latin_hypercube, LhsOptions};
use crate::problem::{require, ConstrainedProblem, Evaluation, OptimizeError};
use crate::rng::{Stream, StreamState};
use serde::{Deserialize, Serialize};

/// Largest population (bounds the allocation of a generation).
pub const MAX_POPULATION: usize = 100_000;

/// Settings of the genetic algorithm.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct GaOptions {
    /// Individuals per generation (even, 4 ..= [`MAX_POPULATION`]).
    pub population: usize,
    /// Generations after the initial one.
    pub generations: usize,
    /// Probability that a pair of parents is crossed.
    pub crossover_probability: f64,
    /// SBX distribution index (larger: children closer to the parents).
    pub eta_crossover: f64,
    /// Probability that one variable of a child mutates (`None`: 1 / n).
    pub mutation_probability: Option<f64>,
    /// Polynomial-mutation distribution index.
    pub eta_mutation: f64,
    /// Seed of the random stream.
    pub seed: u64,
}

impl Default for GaOptions {
    fn default() -> Self {
        Self {
            population: 40,
            generations: 50,
            crossover_probability: 0.9,
            eta_crossover: 15.0,
            mutation_probability: None,
            eta_mutation: 20.0,
            seed: 0,
        }
    }
}

impl GaOptions {
    /// Checks every setting.
    pub fn validate(&self) -> Result<(), OptimizeError> {
        require(
            (4..=MAX_POPULATION).contains(&self.population) && self.population % 2 == 0,
            "population",
            "even, 4 ..= 100000",
        )?;
        require(
            (0.0..=1.0).contains(&self.crossover_probability),
            "crossover_probability",
            "in [0, 1]",
        )?;
        require(
            self.eta_crossover.is_finite() && self.eta_crossover >= 0.0,
            "eta_crossover",
            "finite and >= 0",
        )?;
        require(
            self.eta_mutation.is_finite() && self.eta_mutation >= 0.0,
            "eta_mutation",
            "finite and >= 0",
        )?;
        if let Some(p) = self.mutation_probability {
            require(
                (0.0..=1.0).contains(&p),
                "mutation_probability",
                "in [0, 1]",
            )?;
        }
        Ok(())
    }
}

/// One member of a population.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Individual {
    /// Unit-cube coordinates.
    pub u: Vec<f64>,
    /// The problem's units.
    pub x: Vec<f64>,
    /// Evaluation.
    pub eval: Evaluation,
}

/// The whole state of a GA between generations.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct GaState {
    /// Completed generations (0: the initial population).
    pub generation: usize,
    /// The population, best first by Deb's rules.
    pub population: Vec<Individual>,
    /// Position of the random stream.
    pub rng: StreamState,
    /// Designs evaluated so far: the initial population and every generation's children,
    /// counting a child that reused a known design's evaluation ([`GeneticAlgorithm::step`]).
    pub evaluations: usize,
}

impl GaState {
    /// The best individual.
    pub fn best(&self) -> &Individual {
        &self.population[0]
    }
}

/// A GA of one problem with fixed settings.
pub struct GeneticAlgorithm<'a, P: ConstrainedProblem + ?Sized> {
    problem: &'a P,
    options: GaOptions,
}

impl<'a, P: ConstrainedProblem + ?Sized> GeneticAlgorithm<'a, P> {
    /// A GA of `problem` with validated `options`.
    pub fn new(problem: &'a P, options: GaOptions) -> Result<Self, OptimizeError> {
        options.validate()?;
        Ok(Self { problem, options })
    }

    /// The initial population: the `seeds` (problem units, projected onto the bounds; at
    /// most `population`) and a Latin hypercube for the rest, evaluated and ranked
    /// ([`GeneticAlgorithm::initial`], then [`GeneticAlgorithm::start_told`]).
    pub fn start(&self, seeds: &[Vec<f64>]) -> Result<GaState, OptimizeError> {
        let units = self.initial(seeds)?;
        let b = self.problem.bounds();
        let xs: Vec<Vec<f64>> = units.iter().map(|u| b.from_unit(u)).collect();
        let evals = evaluate_batch(self.problem, &xs);
        self.start_told(units, evals)
    }

    /// The initial population in unit-cube coordinates, before any evaluation: the
    /// `seeds` (problem units, projected onto the bounds; at most `population`), then a
    /// Latin hypercube of seed `seed` for the rest. Evaluate them anywhere (in order) and
    /// hand the results to [`GeneticAlgorithm::start_told`].
    pub fn initial(&self, seeds: &[Vec<f64>]) -> Result<Vec<Vec<f64>>, OptimizeError> {
        let b = self.problem.bounds();
        let n = b.dim();
        require(
            seeds.len() <= self.options.population,
            "seeds",
            "at most `population`",
        )?;
        require(
            seeds
                .iter()
                .all(|s| s.len() == n && s.iter().all(|v| v.is_finite())),
            "seeds",
            "finite, one value per variable",
        )?;
        let mut units: Vec<Vec<f64>> = seeds
            .iter()
            .map(|s| b.to_unit(s).iter().map(|v| v.clamp(0.0, 1.0)).collect())
            .collect();
        let rest = self.options.population - units.len();
        if rest > 0 {
            units.extend(latin_hypercube(&LhsOptions {
                points: rest,
                dim: n,
                seed: self.options.seed,
                maximin_candidates: 1,
            })?);
        }
        Ok(units)
    }

    /// The state of generation 0 from the initial population `units`
    /// ([`GeneticAlgorithm::initial`]) and their evaluations, in its order, ranked.
    pub fn start_told(
        &self,
        units: Vec<Vec<f64>>,
        evals: Vec<Evaluation>,
    ) -> Result<GaState, OptimizeError> {
        let (n, nc) = (self.problem.bounds().dim(), self.problem.n_constraints());
        require(
            units.len() == self.options.population
                && evals.len() == units.len()
                && units.iter().all(|u| u.len() == n)
                && evals.iter().all(|e| e.constraints.len() == nc),
            "evals",
            "one evaluation per initial individual, with every constraint",
        )?;
        let b = self.problem.bounds();
        let population: Vec<Individual> = units
            .into_iter()
            .zip(evals)
            .map(|(u, eval)| Individual {
                x: b.from_unit(&u),
                u,
                eval,
            })
            .collect();
        let evaluations = population.len();
        let mut s = GaState {
            generation: 0,
            population,
            // The hypercube used `seed`; the operators draw from the next stream.
            rng: Stream::new(self.options.seed.wrapping_add(1)).state(),
            evaluations,
        };
        rank(&mut s.population);
        Ok(s)
    }

    /// Checks that a saved state belongs to this problem and these settings.
    pub fn check_state(&self, s: &GaState) -> Result<(), OptimizeError> {
        let (n, nc) = (self.problem.bounds().dim(), self.problem.n_constraints());
        let ok = s.population.len() == self.options.population
            && s.population
                .iter()
                .all(|i| i.u.len() == n && i.eval.constraints.len() == nc);
        if ok {
            Ok(())
        } else {
            Err(OptimizeError::Checkpoint(
                "GA state of another population size, dimension or constraint count".into(),
            ))
        }
    }

    /// One generation: `population` children from tournament-selected parents by SBX and
    /// polynomial mutation, evaluated in parallel, then (mu + lambda) survival
    /// ([`GeneticAlgorithm::ask`], [`GeneticAlgorithm::tell`]).
    ///
    /// A child equal to an individual of the population, or to an earlier child, takes
    /// that design's evaluation instead of a new one ([`ConstrainedProblem::evaluate`] is a
    /// function of `x`): a child is an unchanged copy of a parent when neither crossover
    /// nor mutation touched it, about one child in sixteen with the default settings. The
    /// state is the one [`GeneticAlgorithm::ask`] and [`GeneticAlgorithm::tell`] give with
    /// every child evaluated.
    pub fn step(&self, s: &mut GaState) -> Result<(), OptimizeError> {
        let evals = self.evaluate_children(&s.population, &self.ask(s));
        self.tell(s, evals)
    }

    /// The evaluations of `children` (unit coordinates), in their order: known designs
    /// (equal unit coordinates in `population` or earlier in `children`) reuse theirs, the
    /// others are evaluated in parallel.
    fn evaluate_children(
        &self,
        population: &[Individual],
        children: &[Vec<f64>],
    ) -> Vec<Evaluation> {
        enum Source {
            Known(usize),
            Fresh(usize),
        }
        let mut fresh: Vec<&Vec<f64>> = Vec::new();
        let sources: Vec<Source> = children
            .iter()
            .map(|c| {
                if let Some(i) = population.iter().position(|p| p.u == *c) {
                    Source::Known(i)
                } else if let Some(k) = fresh.iter().position(|f| *f == c) {
                    Source::Fresh(k)
                } else {
                    fresh.push(c);
                    Source::Fresh(fresh.len() - 1)
                }
            })
            .collect();
        let b = self.problem.bounds();
        let xs: Vec<Vec<f64>> = fresh.iter().map(|u| b.from_unit(u)).collect();
        let evals = evaluate_batch(self.problem, &xs);
        sources
            .into_iter()
            .map(|s| match s {
                Source::Known(i) => population[i].eval.clone(),
                Source::Fresh(k) => evals[k].clone(),
            })
            .collect()
    }

    /// The children of the next generation in unit-cube coordinates. Evaluate them
    /// anywhere (in order) and hand the results to [`GeneticAlgorithm::tell`].
    pub fn ask(&self, s: &GaState) -> Vec<Vec<f64>> {
        self.children(s).0
    }

    /// Advances one generation with the evaluations of the children [`GeneticAlgorithm::ask`]
    /// gives for `s` (in its order): (mu + lambda) survival under Deb's rules.
    pub fn tell(&self, s: &mut GaState, evals: Vec<Evaluation>) -> Result<(), OptimizeError> {
        let (children, rng) = self.children(s);
        require(
            evals.len() == children.len()
                && evals
                    .iter()
                    .all(|e| e.constraints.len() == self.problem.n_constraints()),
            "evals",
            "one evaluation per asked child, with every constraint",
        )?;
        let b = self.problem.bounds();
        s.rng = rng;
        s.evaluations += evals.len();
        s.population
            .extend(children.into_iter().zip(evals).map(|(u, eval)| Individual {
                x: b.from_unit(&u),
                u,
                eval,
            }));
        rank(&mut s.population);
        s.population.truncate(self.options.population);
        s.generation += 1;
        Ok(())
    }

    /// The children of `s` and the stream position after drawing them.
    fn children(&self, s: &GaState) -> (Vec<Vec<f64>>, StreamState) {
        let mut rng = Stream::restore(s.rng);
        let mut children = Vec::with_capacity(self.options.population);
        while children.len() < self.options.population {
            let a = tournament(&s.population, &mut rng);
            let b = tournament(&s.population, &mut rng);
            let (mut c1, mut c2) = (a.u.clone(), b.u.clone());
            if rng.uniform() < self.options.crossover_probability {
                sbx(&mut c1, &mut c2, self.options.eta_crossover, &mut rng);
            }
            for c in [&mut c1, &mut c2] {
                self.mutate(c, &mut rng);
            }
            children.push(c1);
            children.push(c2);
        }
        (children, rng.state())
    }

    /// Runs to `generations`, calling `checkpoint` after every generation.
    pub fn run(
        &self,
        mut s: GaState,
        progress: &dyn Progress,
        checkpoint: &mut dyn FnMut(&GaState) -> Result<(), String>,
    ) -> Result<GaState, OptimizeError> {
        self.check_state(&s)?;
        while s.generation < self.options.generations {
            self.step(&mut s)?;
            progress.report(
                "genetic algorithm",
                s.generation,
                self.options.generations,
                s.best().eval.barrier_value(),
            );
            checkpoint(&s).map_err(|e| OptimizeError::Invalid {
                field: "checkpoint",
                reason: e,
            })?;
        }
        Ok(s)
    }

    /// Bounded polynomial mutation of each variable with the mutation probability.
    fn mutate(&self, u: &mut [f64], rng: &mut Stream) {
        let p = self
            .options
            .mutation_probability
            .unwrap_or(1.0 / u.len() as f64);
        let pow = 1.0 / (self.options.eta_mutation + 1.0);
        for y in u.iter_mut() {
            if rng.uniform() >= p {
                continue;
            }
            let r = rng.uniform();
            let dq = if r < 0.5 {
                let xy = 1.0 - *y;
                let val = 2.0 * r + (1.0 - 2.0 * r) * xy.powf(self.options.eta_mutation + 1.0);
                val.powf(pow) - 1.0
            } else {
                let xy = *y;
                let val =
                    2.0 * (1.0 - r) + 2.0 * (r - 0.5) * xy.powf(self.options.eta_mutation + 1.0);
                1.0 - val.powf(pow)
            };
            *y = (*y + dq).clamp(0.0, 1.0);
        }
    }
}

/// Stable sort by Deb's rules (best first).
fn rank(pop: &mut [Individual]) {
    pop.sort_by(|a, b| a.eval.deb_cmp(&b.eval));
}

/// Binary tournament under Deb's rules (the first drawn wins a tie).
fn tournament<'p>(pop: &'p [Individual], rng: &mut Stream) -> &'p Individual {
    let a = &pop[rng.index(pop.len())];
    let b = &pop[rng.index(pop.len())];
    if b.eval.deb_cmp(&a.eval).is_lt() {
        b
    } else {
        a
    }
}

/// Bounded simulated binary crossover on [0, 1] (Deb & Agrawal 1995), each variable
/// crossed with probability 1/2.
fn sbx(c1: &mut [f64], c2: &mut [f64], eta: f64, rng: &mut Stream) {
    let betaq = |beta: f64, r: f64| {
        let alpha = 2.0 - beta.powf(-(eta + 1.0));
        if r <= 1.0 / alpha {
            (r * alpha).powf(1.0 / (eta + 1.0))
        } else {
            (1.0 / (2.0 - r * alpha)).powf(1.0 / (eta + 1.0))
        }
    };
    for (a, b) in c1.iter_mut().zip(c2.iter_mut()) {
        if rng.uniform() >= 0.5 || (*a - *b).abs() < 1e-14 {
            continue;
        }
        let (y1, y2) = (a.min(*b), a.max(*b));
        let r = rng.uniform();
        let lo = 0.5 * ((y1 + y2) - betaq(1.0 + 2.0 * y1 / (y2 - y1), r) * (y2 - y1));
        let hi = 0.5 * ((y1 + y2) + betaq(1.0 + 2.0 * (1.0 - y2) / (y2 - y1), r) * (y2 - y1));
        let (lo, hi) = (lo.clamp(0.0, 1.0), hi.clamp(0.0, 1.0));
        if rng.uniform() < 0.5 {
            (*a, *b) = (hi, lo);
        } else {
            (*a, *b) = (lo, hi);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn operators_stay_in_the_unit_box_and_keep_the_mean_of_sbx() {
        let mut rng = Stream::new(3);
        let (mut sum, mut count) = (0.0, 0);
        for _ in 0..2000 {
            let (mut a, mut b) = (vec![0.3, 0.9], vec![0.5, 0.95]);
            sbx(&mut a, &mut b, 15.0, &mut rng);
            for v in a.iter().chain(&b) {
                assert!((0.0..=1.0).contains(v));
            }
            sum += a[0] + b[0];
            count += 1;
        }
        // SBX is symmetric about the parents' mean away from the bounds.
        assert!(
            (sum / count as f64 - 0.8).abs() < 0.01,
            "{}",
            sum / count as f64
        );
    }

    #[test]
    fn invalid_settings_name_the_field() {
        let e = GaOptions {
            population: 5,
            ..GaOptions::default()
        }
        .validate()
        .unwrap_err();
        assert!(e.to_string().contains("population"), "{e}");
        let e = GaOptions {
            mutation_probability: Some(1.5),
            ..GaOptions::default()
        }
        .validate()
        .unwrap_err();
        assert!(e.to_string().contains("mutation_probability"), "{e}");
    }
    /// A quadratic bowl with one constraint that counts its evaluations.
    struct Counted {
        bounds: crate::Bounds,
        calls: std::sync::atomic::AtomicUsize,
    }

    impl ConstrainedProblem for Counted {
        fn bounds(&self) -> &crate::Bounds {
            &self.bounds
        }
        fn n_constraints(&self) -> usize {
            1
        }
        fn evaluate(&self, x: &[f64]) -> Evaluation {
            self.calls
                .fetch_add(1, std::sync::atomic::Ordering::Relaxed);
            Evaluation {
                f: (x[0] - 0.3).powi(2) + (x[1] + 0.2).powi(2),
                constraints: vec![x[0] + x[1] - 1.0],
            }
        }
    }

    #[test]
    fn a_step_reuses_known_designs_and_ends_where_ask_and_tell_end() {
        let p = Counted {
            bounds: crate::Bounds::new(vec![-1.0, -1.0], vec![1.0, 1.0]).unwrap(),
            calls: 0.into(),
        };
        let calls = || p.calls.load(std::sync::atomic::Ordering::Relaxed);
        for (crossover, mutation) in [(0.0, 0.0), (0.9, 0.5)] {
            let ga = GeneticAlgorithm::new(
                &p,
                GaOptions {
                    population: 12,
                    crossover_probability: crossover,
                    mutation_probability: Some(mutation),
                    ..GaOptions::default()
                },
            )
            .unwrap();
            let start = ga.start(&[]).unwrap();
            let (mut stepped, mut told) = (start.clone(), start);
            for _ in 0..3 {
                let asked = ga.ask(&told);
                let new_designs = asked
                    .iter()
                    .enumerate()
                    .filter(|(k, u)| {
                        !asked[..*k].contains(u) && told.population.iter().all(|i| i.u != **u)
                    })
                    .count();
                let before = calls();
                ga.step(&mut stepped).unwrap();
                assert_eq!(calls() - before, new_designs);
                let b = p.bounds();
                let evals = asked.iter().map(|u| p.evaluate(&b.from_unit(u))).collect();
                ga.tell(&mut told, evals).unwrap();
                assert_eq!(stepped, told);
                if mutation == 0.0 {
                    // every child is a copy of a parent: nothing new to evaluate
                    assert_eq!(new_designs, 0);
                } else {
                    assert!(new_designs > 0, "{new_designs}");
                }
            }
        }
    }
}
