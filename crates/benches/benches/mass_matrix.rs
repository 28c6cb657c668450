//! Cost of one forward-dynamics evaluation (kinematics + CRBA + RNEA + sparse L^T D L
//! solve) for the 14-DOF truck tree, and of CRBA, RNEA and the factorisation and solve
//! alone.
#[path = "../../multibody/tests/support/vehicle.rs"]
mod vehicle;

use criterion::{criterion_group, criterion_main, Criterion};
use multibody::{
    bias_forces, forward_dynamics, mass_matrix, solve_mass_matrix, update_kinematics, Workspace,
};
use nalgebra::{UnitQuaternion, Vector3};
use std::hint::black_box;
use vehicle::{springs, truck, TRUCK_SPRINGS};

fn bench(c: &mut Criterion) {
    let model = truck(Vector3::new(0.0, 0.0, -9.81));
    let mut ws = Workspace::new(&model);
    let r = UnitQuaternion::from_euler_angles(0.5, -0.1, 0.3).into_inner();
    let q = [
        0.0, 0.0, 1.5, r.w, r.i, r.j, r.k, 0.05, -0.03, 0.02, 0.04, 0.3, -1.0, 2.0, 0.5,
    ];
    let v = [
        0.3, -0.2, 0.1, 5.0, 0.0, 1.0, 0.2, -0.4, 0.3, -0.5, 10.0, 10.0, 11.0, 9.0,
    ];
    let mut tau = [0.0; 14];
    springs(&model, &TRUCK_SPRINGS, &q, &mut tau);
    c.bench_function("truck14_forward_dynamics", |b| {
        b.iter(|| {
            update_kinematics(&model, &mut ws, black_box(&q), black_box(&v)).unwrap();
            forward_dynamics(&model, &mut ws, black_box(&tau)).unwrap()[0]
        })
    });
    update_kinematics(&model, &mut ws, &q, &v).unwrap();
    c.bench_function("truck14_crba", |b| {
        b.iter(|| mass_matrix(&model, black_box(&mut ws)).unwrap()[(0, 0)])
    });
    c.bench_function("truck14_rnea_bias", |b| {
        b.iter(|| bias_forces(&model, black_box(&mut ws)).unwrap()[0])
    });
    mass_matrix(&model, &mut ws).unwrap();
    let mut x = [0.0; 14];
    c.bench_function("truck14_ltdl_solve", |b| {
        b.iter(|| {
            x.copy_from_slice(black_box(&tau));
            solve_mass_matrix(&model, &mut ws, &mut x).unwrap();
            x[0]
        })
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
