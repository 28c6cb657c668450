//! The design optimisers on standard problems with known optima (Rosenbrock; Deb's
//! constrained Himmelblau; a linear objective on a disc, where the nonlinear constraint is
//! active), with their evaluation counts; checkpoint/resume and thread-count independence.

use optimize::ga::{GaOptions, GaState, GeneticAlgorithm};
use optimize::pattern_search::{
    PatternSearch, PatternSearchOptions, PatternSearchState, PatternStop,
};
use optimize::sqp::{sqp, sqp_ask, LoggedEvaluation, SqpOptions, SqpStep};
use optimize::{Bounds, ConstrainedProblem, Evaluation, Silent};

/// A problem from closures.
struct Test<F: Fn(&[f64]) -> (f64, Vec<f64>) + Sync> {
    bounds: Bounds,
    nc: usize,
    f: F,
}

impl<F: Fn(&[f64]) -> (f64, Vec<f64>) + Sync> ConstrainedProblem for Test<F> {
    fn bounds(&self) -> &Bounds {
        &self.bounds
    }
    fn n_constraints(&self) -> usize {
        self.nc
    }
    fn evaluate(&self, x: &[f64]) -> Evaluation {
        let (f, constraints) = (self.f)(x);
        Evaluation { f, constraints }
    }
}

fn rosenbrock() -> Test<impl Fn(&[f64]) -> (f64, Vec<f64>) + Sync> {
    Test {
        bounds: Bounds::new(vec![-2.0, -2.0], vec![2.0, 2.0]).unwrap(),
        nc: 0,
        f: |x: &[f64]| {
            let (a, b) = (1.0 - x[0], x[1] - x[0] * x[0]);
            (a * a + 100.0 * b * b, vec![])
        },
    }
}

/// Deb (2000), problem of section 4.1: Himmelblau's function on 0 <= x, y <= 6 with
/// g1 = 4.84 - (x - 0.05)^2 - (y - 2.5)^2 >= 0 (active) and g2 = x^2 + (y - 2.5)^2 - 4.84 >= 0;
/// optimum (2.246826, 2.381865), f = 13.59085.
fn himmelblau() -> Test<impl Fn(&[f64]) -> (f64, Vec<f64>) + Sync> {
    Test {
        bounds: Bounds::new(vec![0.0, 0.0], vec![6.0, 6.0]).unwrap(),
        nc: 2,
        f: |x: &[f64]| {
            let (a, b) = (x[0] * x[0] + x[1] - 11.0, x[0] + x[1] * x[1] - 7.0);
            let g1 = 4.84 - (x[0] - 0.05).powi(2) - (x[1] - 2.5).powi(2);
            let g2 = x[0] * x[0] + (x[1] - 2.5).powi(2) - 4.84;
            (a * a + b * b, vec![-g1, -g2])
        },
    }
}
const HIMMELBLAU_X: [f64; 2] = [2.246826, 2.381865];
const HIMMELBLAU_F: f64 = 13.59085;

/// min x + y subject to x^2 + y^2 <= 1: optimum (-1/sqrt 2, -1/sqrt 2), f = -sqrt 2, on the
/// constraint.
fn disc() -> Test<impl Fn(&[f64]) -> (f64, Vec<f64>) + Sync> {
    Test {
        bounds: Bounds::new(vec![-2.0, -2.0], vec![2.0, 2.0]).unwrap(),
        nc: 1,
        f: |x: &[f64]| (x[0] + x[1], vec![x[0] * x[0] + x[1] * x[1] - 1.0]),
    }
}

fn ps_options(search_points: usize) -> PatternSearchOptions {
    PatternSearchOptions {
        min_mesh: 1e-6,
        search_points,
        seed: 11,
        ..PatternSearchOptions::default()
    }
}

fn run_ps<P: ConstrainedProblem>(p: &P, o: PatternSearchOptions, x0: &[f64]) -> PatternSearchState {
    let ps = PatternSearch::new(p, o).unwrap();
    ps.run(ps.start(x0).unwrap(), &Silent, &mut |_| Ok(()))
        .unwrap()
}

#[test]
fn pattern_search_on_rosenbrock() {
    let o = PatternSearchOptions {
        max_evaluations: 50_000,
        ..ps_options(10)
    };
    let s = run_ps(&rosenbrock(), o, &[-1.2, 1.0]);
    assert_eq!(s.stop, Some(PatternStop::MeshConverged));
    assert!(
        (s.x[0] - 1.0).abs() < 0.05 && (s.x[1] - 1.0).abs() < 0.1,
        "{s:?}"
    );
    assert!(s.eval.f < 2e-3, "{}", s.eval.f);
    // The exact count of this seed (our own algorithm, deterministic): a coordinate search
    // crawls along the curved valley.
    assert_eq!(s.evaluations, 13991);
    eprintln!(
        "PS Rosenbrock: {} evaluations, f = {:.2e}",
        s.evaluations, s.eval.f
    );
}

#[test]
fn pattern_search_on_constrained_himmelblau() {
    let s = run_ps(&himmelblau(), ps_options(10), &[1.0, 2.5]);
    assert!(s.eval.is_feasible());
    assert!((s.eval.f - HIMMELBLAU_F).abs() < 0.05, "{s:?}");
    assert!((s.x[0] - HIMMELBLAU_X[0]).abs() < 0.02, "{s:?}");
    assert_eq!(s.evaluations, 647);
    eprintln!(
        "PS Himmelblau: {} evaluations, f = {}",
        s.evaluations, s.eval.f
    );
}

#[test]
fn pattern_search_from_an_infeasible_start_walks_to_feasibility() {
    let s = run_ps(&himmelblau(), ps_options(0), &[5.0, 5.0]);
    // (5, 5) violates g1; the search ends feasible (at a local optimum on g2's boundary).
    assert!(!himmelblau().evaluate(&[5.0, 5.0]).is_feasible());
    assert!(s.eval.is_feasible(), "{s:?}");
}

#[test]
fn sqp_refines_the_pattern_search_on_an_active_nonlinear_constraint() {
    let p = disc();
    let s = run_ps(&p, ps_options(0), &[0.5, 0.5]);
    // A coordinate poll stalls on a curved active constraint (every poll direction leaves
    // the disc or increases f), short of the optimum.
    assert!(s.eval.is_feasible());
    let r = sqp(
        &p,
        &s.x,
        &SqpOptions::default(),
        vec![],
        &Silent,
        &mut |_| Ok(()),
    )
    .unwrap();
    let opt = -std::f64::consts::SQRT_2;
    assert!(r.improved);
    assert!((r.eval.f - opt).abs() < 1e-6, "{r:?}");
    assert!(r.eval.constraints[0].abs() < 1e-6);
    assert!(r.evaluations < 200, "{}", r.evaluations);
    eprintln!(
        "disc: PS f = {} ({} evals), SQP f = {} ({} evals)",
        s.eval.f, s.evaluations, r.eval.f, r.evaluations
    );
}

#[test]
fn sqp_with_difference_gradients_on_rosenbrock_and_himmelblau() {
    let o = SqpOptions {
        fd_step: 1e-6,
        max_calls: 300,
        ..SqpOptions::default()
    };
    let r = sqp(
        &rosenbrock(),
        &[-1.2, 1.0],
        &o,
        vec![],
        &Silent,
        &mut |_| Ok(()),
    )
    .unwrap();
    assert!(
        (r.x[0] - 1.0).abs() < 1e-3 && (r.x[1] - 1.0).abs() < 2e-3,
        "{r:?}"
    );
    eprintln!(
        "SQP Rosenbrock: {} evaluations, status {}",
        r.evaluations, r.status
    );
    let r = sqp(&himmelblau(), &[1.0, 2.5], &o, vec![], &Silent, &mut |_| {
        Ok(())
    })
    .unwrap();
    assert!((r.eval.f - HIMMELBLAU_F).abs() < 1e-4, "{r:?}");
    assert!((r.x[0] - HIMMELBLAU_X[0]).abs() < 1e-4 && (r.x[1] - HIMMELBLAU_X[1]).abs() < 1e-4);
    assert!(r.evaluations < 200, "{}", r.evaluations);
}

fn ga_options() -> GaOptions {
    GaOptions {
        population: 40,
        generations: 60,
        seed: 5,
        ..GaOptions::default()
    }
}

fn run_ga<P: ConstrainedProblem>(p: &P, o: GaOptions) -> GaState {
    let ga = GeneticAlgorithm::new(p, o).unwrap();
    ga.run(ga.start(&[]).unwrap(), &Silent, &mut |_| Ok(()))
        .unwrap()
}

#[test]
fn genetic_algorithm_on_constrained_himmelblau() {
    let s = run_ga(&himmelblau(), ga_options());
    let b = s.best();
    assert!(b.eval.is_feasible());
    assert!((b.eval.f - HIMMELBLAU_F).abs() < 0.05, "{b:?}");
    assert!((b.x[0] - HIMMELBLAU_X[0]).abs() < 0.05, "{b:?}");
    assert_eq!(s.evaluations, 40 * 61);
    // Elitism: the best value never rises from one generation to the next.
    let p = himmelblau();
    let ga = GeneticAlgorithm::new(&p, ga_options()).unwrap();
    let mut s = ga.start(&[]).unwrap();
    let mut prev = s.best().eval.clone();
    for _ in 0..20 {
        ga.step(&mut s).unwrap();
        assert!(s.best().eval.deb_cmp(&prev).is_le());
        prev = s.best().eval.clone();
    }
}

#[test]
fn interrupted_runs_resume_to_identical_bytes() {
    let p = himmelblau();
    // Pattern search: stop after 4 iterations, save, load, continue.
    let ps = PatternSearch::new(&p, ps_options(10)).unwrap();
    let full = run_ps(&p, ps_options(10), &[1.0, 2.5]);
    let mut s = ps.start(&[1.0, 2.5]).unwrap();
    for _ in 0..4 {
        ps.step(&mut s).unwrap();
    }
    let saved = serde_json::to_string(&s).unwrap();
    let resumed = ps
        .run(serde_json::from_str(&saved).unwrap(), &Silent, &mut |_| {
            Ok(())
        })
        .unwrap();
    assert_eq!(
        serde_json::to_string(&resumed).unwrap(),
        serde_json::to_string(&full).unwrap()
    );
    // GA: stop after 7 generations.
    let ga = GeneticAlgorithm::new(&p, ga_options()).unwrap();
    let full = run_ga(&p, ga_options());
    let mut s = ga.start(&[]).unwrap();
    for _ in 0..7 {
        ga.step(&mut s).unwrap();
    }
    let saved = serde_json::to_string(&s).unwrap();
    let resumed = ga
        .run(serde_json::from_str(&saved).unwrap(), &Silent, &mut |_| {
            Ok(())
        })
        .unwrap();
    assert_eq!(
        serde_json::to_string(&resumed).unwrap(),
        serde_json::to_string(&full).unwrap()
    );
    // SQP: a run killed after 9 evaluations (its checkpoint fails) resumes from its log.
    let o = SqpOptions::default();
    let full = sqp(&p, &[1.0, 2.5], &o, vec![], &Silent, &mut |_| Ok(())).unwrap();
    let mut saved = String::new();
    let killed = sqp(&p, &[1.0, 2.5], &o, vec![], &Silent, &mut |log| {
        saved = serde_json::to_string(log).unwrap();
        if log.len() >= 9 {
            Err("killed".into())
        } else {
            Ok(())
        }
    });
    assert!(killed.is_err());
    let log = serde_json::from_str(&saved).unwrap();
    let resumed = sqp(&p, &[1.0, 2.5], &o, log, &Silent, &mut |_| Ok(())).unwrap();
    assert!(resumed.replayed >= 9);
    assert_eq!(resumed.x, full.x);
    assert_eq!(resumed.log, full.log);
}

#[test]
fn results_do_not_depend_on_the_thread_count() {
    let p = himmelblau();
    let on = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| {
            let ps = run_ps(&p, ps_options(10), &[1.0, 2.5]);
            let ga = run_ga(&p, ga_options());
            let sq = sqp(
                &p,
                &ps.x,
                &SqpOptions::default(),
                vec![],
                &Silent,
                &mut |_| Ok(()),
            )
            .unwrap();
            serde_json::to_string(&(ps, ga, sq)).unwrap()
        })
    };
    assert_eq!(on(1), on(3));
}

/// Evaluates `units` as `shards` separate pieces (as separate processes would) and puts
/// the results back in id order.
fn evaluate_in_shards<P: ConstrainedProblem>(
    p: &P,
    units: &[Vec<f64>],
    shards: usize,
) -> Vec<Evaluation> {
    let mut out: Vec<Option<Evaluation>> = vec![None; units.len()];
    for shard in 0..shards {
        for (id, u) in units
            .iter()
            .enumerate()
            .filter(|(id, _)| id % shards == shard)
        {
            out[id] = Some(p.evaluate(&p.bounds().from_unit(u)));
        }
    }
    out.into_iter().map(Option::unwrap).collect()
}

#[test]
fn ask_and_tell_with_sharded_evaluation_equal_the_in_process_runs() {
    let p = himmelblau();
    // Pattern search.
    let ps = PatternSearch::new(&p, ps_options(10)).unwrap();
    let full = run_ps(&p, ps_options(10), &[1.0, 2.5]);
    let mut s = ps.start(&[1.0, 2.5]).unwrap();
    while s.stop.is_none() {
        let units = ps.ask(&s).unwrap();
        let evals = evaluate_in_shards(&p, &units, 3);
        ps.tell(&mut s, evals).unwrap();
    }
    assert_eq!(
        serde_json::to_string(&s).unwrap(),
        serde_json::to_string(&full).unwrap()
    );
    assert!(
        ps.tell(&mut s.clone(), vec![]).is_ok(),
        "a stopped search ignores tells"
    );
    // GA.
    let ga = GeneticAlgorithm::new(&p, ga_options()).unwrap();
    let full = run_ga(&p, ga_options());
    let mut s = ga.start(&[]).unwrap();
    while s.generation < ga_options().generations {
        let units = ga.ask(&s);
        ga.tell(&mut s, evaluate_in_shards(&p, &units, 4)).unwrap();
    }
    assert_eq!(
        serde_json::to_string(&s).unwrap(),
        serde_json::to_string(&full).unwrap()
    );
    assert!(
        ga.tell(&mut s, vec![]).is_err(),
        "a batch of the wrong size is refused"
    );
    // SQP.
    let o = SqpOptions::default();
    let full = sqp(&p, &[1.0, 2.5], &o, vec![], &Silent, &mut |_| Ok(())).unwrap();
    let mut log = Vec::new();
    let mut asks = 0;
    let done = loop {
        match sqp_ask(p.bounds(), p.n_constraints(), &[1.0, 2.5], &o, log.clone()).unwrap() {
            SqpStep::Need(units) => {
                asks += 1;
                let evals = evaluate_in_shards(&p, &units, 2);
                log.extend(
                    units
                        .into_iter()
                        .zip(evals)
                        .map(|(u, eval)| LoggedEvaluation { u, eval }),
                );
            }
            SqpStep::Done(r) => break r,
        }
    };
    assert!(asks > 3);
    assert_eq!(done.x, full.x);
    assert_eq!(done.log, full.log);
    assert_eq!(done.status, full.status);
}

mod invariants {
    use super::*;
    use proptest::prelude::*;
    use std::sync::atomic::{AtomicBool, Ordering};

    /// A shifted quadratic on a random box that records any evaluation outside the box.
    struct Watched {
        bounds: Bounds,
        centre: Vec<f64>,
        outside: AtomicBool,
    }

    impl ConstrainedProblem for Watched {
        fn bounds(&self) -> &Bounds {
            &self.bounds
        }
        fn n_constraints(&self) -> usize {
            1
        }
        fn evaluate(&self, x: &[f64]) -> Evaluation {
            let (lo, hi) = (self.bounds.lower(), self.bounds.upper());
            if x.iter()
                .zip(lo.iter().zip(hi))
                .any(|(v, (l, h))| v < l || v > h)
            {
                self.outside.store(true, Ordering::Relaxed);
            }
            let f = x
                .iter()
                .zip(&self.centre)
                .map(|(a, c)| (a - c) * (a - c))
                .sum();
            // A half-space constraint through the box: x_0 + x_1 <= hi_0 + lo_1.
            Evaluation {
                f,
                constraints: vec![x[0] + x[1] - hi[0] - lo[1]],
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(32))]
        #[test]
        fn every_point_is_inside_the_box_and_the_incumbent_never_worsens(
            lo in prop::collection::vec(-5.0f64..0.0, 3),
            width in prop::collection::vec(0.5f64..5.0, 3),
            centre in prop::collection::vec(-8.0f64..8.0, 3),
            start in prop::collection::vec(0.0f64..1.0, 3),
            seed in 0u64..100,
        ) {
            let hi: Vec<f64> = lo.iter().zip(&width).map(|(l, w)| l + w).collect();
            let p = Watched { bounds: Bounds::new(lo, hi).unwrap(), centre, outside: AtomicBool::new(false) };
            let x0 = p.bounds().from_unit(&start);
            let o = PatternSearchOptions { search_points: 6, seed, ..PatternSearchOptions::default() };
            let ps = PatternSearch::new(&p, o).unwrap();
            let mut s = ps.start(&x0).unwrap();
            let mut prev = s.eval.clone();
            while s.stop.is_none() {
                ps.step(&mut s).unwrap();
                prop_assert!(!s.eval.deb_cmp(&prev).is_gt());
                prev = s.eval.clone();
            }
            prop_assert!(!p.outside.load(Ordering::Relaxed));
            let ga = GeneticAlgorithm::new(&p, GaOptions { population: 8, generations: 5, seed, ..GaOptions::default() }).unwrap();
            let g = ga.run(ga.start(std::slice::from_ref(&x0)).unwrap(), &Silent, &mut |_| Ok(())).unwrap();
            // Elitism: the GA's best is no worse than its seed, the start point.
            prop_assert!(!g.best().eval.deb_cmp(&p.evaluate(&x0)).is_gt());
            prop_assert!(!p.outside.load(Ordering::Relaxed));
        }
    }
}

/// A saved pattern-search state or SQP log is an input: every state a run checkpoints
/// passes, and a state or log edited out of what the solver can produce is refused.
#[test]
fn saved_states_and_logs_outside_what_a_run_makes_are_refused() {
    let p = himmelblau();
    let o = PatternSearchOptions {
        min_mesh: 1e-3,
        ..ps_options(6)
    };
    let ps = PatternSearch::new(&p, o).unwrap();
    let mut saved = Vec::new();
    let end = ps
        .run(ps.start(&[1.0, 1.0]).unwrap(), &Silent, &mut |st| {
            saved.push(st.clone());
            Ok(())
        })
        .unwrap();
    assert!(saved.len() > 5);
    for st in &saved {
        ps.check_state(st).unwrap();
    }
    let refuse = |edit: &dyn Fn(&mut PatternSearchState), want: &str| {
        let mut t = end.clone();
        edit(&mut t);
        let e = ps.check_state(&t).unwrap_err().to_string();
        assert!(e.contains(want), "{want:?} not in {e}");
        // run() refuses it before any evaluation.
        assert!(ps.run(t, &Silent, &mut |_| Ok(())).is_err());
    };
    refuse(&|t| t.mesh = 1e308, "mesh 1e308 outside");
    refuse(&|t| t.mesh = f64::NAN, "outside");
    refuse(&|t| t.mesh = 0.3, "is not 0.25 times a power of 0.5");
    refuse(&|t| t.u[0] = 1.5, "unit coordinate 1.5 outside [0, 1]");
    refuse(&|t| t.x[0] += 1e-9, "not the image");
    refuse(&|t| t.eval.f = f64::INFINITY, "not finite");
    refuse(&|t| t.eval.constraints.push(0.0), "constraint values");
    refuse(&|t| t.evaluations = t.iteration, "evaluations for");
    refuse(
        &|t| t.stop = Some(PatternStop::EvaluationLimit),
        "stop Some(EvaluationLimit)",
    );
    refuse(&|t| t.search_done = false, "a search step");

    let s = run_ps(&p, ps_options(0), &[2.0, 2.0]);
    let opts = SqpOptions {
        max_calls: 5,
        ..SqpOptions::default()
    };
    let r = sqp(&p, &s.x, &opts, vec![], &Silent, &mut |_| Ok(())).unwrap();
    assert!(!r.log.is_empty());
    let again = sqp(&p, &s.x, &opts, r.log.clone(), &Silent, &mut |_| Ok(())).unwrap();
    assert_eq!(again.eval, r.eval);
    let refuse_log = |edit: &dyn Fn(&mut Vec<LoggedEvaluation>), want: &str| {
        let mut log = r.log.clone();
        edit(&mut log);
        let e = sqp(&p, &s.x, &opts, log, &Silent, &mut |_| Ok(()))
            .unwrap_err()
            .to_string();
        assert!(e.contains(want), "{want:?} not in {e}");
    };
    refuse_log(&|l| l[0].u[1] = -0.5, "entry 0 outside the unit cube");
    refuse_log(
        &|l| l[1].eval.f = f64::NAN,
        "entry 1 holds a value that is not finite",
    );
    refuse_log(&|l| l.push(l[0].clone()), "repeats an earlier point");
    refuse_log(
        &|l| {
            let extra: Vec<LoggedEvaluation> = (0..100)
                .map(|k| LoggedEvaluation {
                    u: vec![k as f64 / 100.0, 0.5],
                    eval: l[0].eval.clone(),
                })
                .collect();
            l.extend(extra);
        },
        "more than the",
    );
}
