//! The chapter-4 optimisation's unit cost and its solver overhead: one evaluation of F at
//! the bounded optimum (pulse + step, loaded, 50 km/h, rtol 1e-8, two 10 s simulations;
//! `_sim20s` gives its real-time factor) and a screened infeasible point (no simulation).
//! `afsv optimize afs` makes about 1000 evaluations per configuration (docs/optimisation.md).

use afsv_design::{AfsDesign, AfsProblem, AfsProblemSpec, AhpHierarchy, Objective};
use criterion::{criterion_group, criterion_main, Criterion};
use optimize::ConstrainedProblem;
use std::hint::black_box;

fn bench(c: &mut Criterion) {
    let w = AhpHierarchy::chapter4().weights().unwrap().composite;
    let p = AfsProblem::new(AfsProblemSpec::default(), Objective::new(w).unwrap()).unwrap();
    let opt = AfsDesign::from_table_units(53.9, 2.149, 0.932, 7.2, 1.7).unwrap();
    let x = p.vector_of(&opt);
    c.bench_function("afs_objective_eval_sim20s", |b| {
        b.iter(|| p.evaluate(black_box(&x)))
    });
    let bad = AfsDesign::from_table_units(45.0, 1.96, 0.64, 4.8, 1.6).unwrap();
    let xb = p.vector_of(&bad);
    let screened = p.screened();
    c.bench_function("afs_objective_screened_infeasible", |b| {
        b.iter(|| screened.evaluate(black_box(&xb)))
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
