//! Revolute-joint checks: a physical pendulum against its closed-form period (small and
//! large amplitude) and energy conservation; a double pendulum against an independently
//! derived Lagrangian mass matrix and Coriolis/gravity vector.
#[path = "support/rk4.rs"]
mod rk4;

use multibody::{
    bias_forces, forward_dynamics, kinetic_energy, mass_matrix, potential_energy,
    update_kinematics, Body, Joint, Model, ModelBuilder, Workspace,
};
use nalgebra::{Isometry3, Matrix2, Matrix3, Rotation3, Vector2, Vector3};
use proptest::prelude::*;
use rk4::rk4_step;
use std::f64::consts::PI;

const G: f64 = 9.81;

fn link(
    name: &str,
    parent: Option<usize>,
    at_z: f64,
    mass: f64,
    com_z: f64,
    i: Matrix3<f64>,
) -> Body {
    Body {
        name: name.into(),
        parent,
        joint: Joint::Revolute { axis: Vector3::y() },
        placement: Isometry3::translation(0.0, 0.0, at_z),
        mass,
        com: Vector3::new(0.0, 0.0, com_z),
        inertia: i,
    }
}

/// Pendulum: mass 2 kg, centre of mass 0.8 m below the pivot, Iyy = 0.15 kg m².
fn pendulum() -> (Model, f64) {
    let inertia = Matrix3::from_diagonal(&Vector3::new(0.1, 0.15, 0.05));
    let mut b = ModelBuilder::new(Vector3::new(0.0, 0.0, -G));
    b.add_body(link("pendulum", None, 0.0, 2.0, -0.8, inertia));
    let i_pivot = 0.15 + 2.0 * 0.8 * 0.8;
    (b.build().expect("valid"), i_pivot / (2.0 * G * 0.8))
}

fn accel(model: &Model) -> impl FnMut(&mut Workspace, &[f64], &[f64], &mut [f64]) + '_ {
    move |ws, q, v, vd| {
        update_kinematics(model, ws, q, v).expect("dimensions");
        vd.copy_from_slice(
            forward_dynamics(model, ws, &[0.0])
                .expect("definite")
                .as_slice(),
        );
    }
}

/// Releases the pendulum at rest from `theta0`; returns the measured period (two
/// successive same-direction zero crossings, linear interpolation) and the largest
/// energy error relative to m g L.
fn swing(theta0: f64) -> (f64, f64) {
    let (model, _) = pendulum();
    let mut ws = Workspace::new(&model);
    let (mut q, mut v) = (vec![theta0], vec![0.0]);
    let energy = |ws: &mut Workspace, q: &[f64], v: &[f64]| {
        update_kinematics(&model, ws, q, v).unwrap();
        kinetic_energy(&model, ws).unwrap() + potential_energy(&model, ws).unwrap()
    };
    let e0 = energy(&mut ws, &q, &v);
    let mut f = accel(&model);
    let dt = 1e-4;
    let (mut t, mut crossings, mut max_de) = (0.0, Vec::new(), 0.0_f64);
    while crossings.len() < 3 {
        let prev = q[0];
        rk4_step(&model, &mut ws, &mut q, &mut v, dt, &mut f);
        t += dt;
        if prev > 0.0 && q[0] <= 0.0 {
            crossings.push(t - dt * q[0] / (q[0] - prev));
        }
        max_de = max_de.max((energy(&mut ws, &q, &v) - e0).abs() / (2.0 * G * 0.8));
    }
    ((crossings[2] - crossings[0]) / 2.0, max_de)
}

/// Complete elliptic integral of the first kind K(k) by the arithmetic-geometric mean.
fn elliptic_k(k: f64) -> f64 {
    let (mut a, mut b) = (1.0, (1.0 - k * k).sqrt());
    for _ in 0..30 {
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    PI / (2.0 * a)
}

#[test]
fn small_amplitude_period_matches_the_linear_formula() {
    let (_, ratio) = pendulum();
    let t0 = 2.0 * PI * ratio.sqrt();
    let theta0: f64 = 0.01;
    let (period, de) = swing(theta0);
    assert!((period - t0).abs() / t0 < 1e-5, "period {period} vs {t0}");
    // With the first finite-amplitude correction theta0^2/16 = 6.25e-6.
    let corrected = t0 * (1.0 + theta0 * theta0 / 16.0);
    assert!(
        (period - corrected).abs() / t0 < 1e-8,
        "period {period} vs {corrected}"
    );
    assert!(de < 1e-12, "energy error {de:e}");
}

#[test]
fn large_amplitude_period_and_energy_match_the_exact_solution() {
    let (_, ratio) = pendulum();
    let theta0: f64 = 2.5;
    let exact = 4.0 * ratio.sqrt() * elliptic_k((theta0 / 2.0).sin());
    let (period, de) = swing(theta0);
    assert!(
        (period - exact).abs() / exact < 1e-8,
        "period {period} vs {exact}"
    );
    assert!(de < 1e-10, "energy error {de:e}");
}

/// Double pendulum about y: link 1 (pivot at the origin) and link 2 (pivot `l1` below
/// the first pivot); relative joint angles.
struct Double {
    m: [f64; 2],
    c: [f64; 2],
    l1: f64,
    iyy: [f64; 2],
}

fn inertia(moments: [f64; 3], euler: [f64; 3]) -> Matrix3<f64> {
    let r = Rotation3::from_euler_angles(euler[0], euler[1], euler[2]).into_inner();
    r * Matrix3::from_diagonal(&Vector3::from(moments)) * r.transpose()
}

impl Double {
    /// Hand-derived Lagrangian in absolute angles phi = T theta, T = [1 0; 1 1]:
    /// M = [I1 + m1 c1² + m2 l1², m2 l1 c2 cos(phi1 - phi2); sym, I2 + m2 c2²],
    /// C_phi = k sin(phi1 - phi2) [phi2'²; -phi1'²] with k = m2 l1 c2,
    /// G_phi = g [(m1 c1 + m2 l1) sin phi1; m2 c2 sin phi2]; mapped by T^T (.) T.
    fn lagrangian(&self, th: Vector2<f64>, thd: Vector2<f64>) -> (Matrix2<f64>, Vector2<f64>) {
        let t = Matrix2::new(1.0, 0.0, 1.0, 1.0);
        let (p, pd) = (t * th, t * thd);
        let k = self.m[1] * self.l1 * self.c[1];
        let s = (p[0] - p[1]).sin();
        let m12 = k * (p[0] - p[1]).cos();
        let m_abs = Matrix2::new(
            self.iyy[0] + self.m[0] * self.c[0].powi(2) + self.m[1] * self.l1.powi(2),
            m12,
            m12,
            self.iyy[1] + self.m[1] * self.c[1].powi(2),
        );
        let coriolis = Vector2::new(k * s * pd[1].powi(2), -k * s * pd[0].powi(2));
        let gravity = G * Vector2::new(
            (self.m[0] * self.c[0] + self.m[1] * self.l1) * p[0].sin(),
            self.m[1] * self.c[1] * p[1].sin(),
        );
        (
            t.transpose() * m_abs * t,
            t.transpose() * (coriolis + gravity),
        )
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]
    #[test]
    fn double_pendulum_matches_the_lagrangian(
        m in [0.2..5.0_f64, 0.2..5.0],
        c in [0.05..1.5_f64, 0.05..1.5],
        l1 in 0.2..2.0_f64,
        moments in [[0.05..1.0_f64, 0.05..1.0, 0.05..1.0], [0.05..1.0, 0.05..1.0, 0.05..1.0]],
        euler in [[-PI..PI, -PI..PI, -PI..PI], [-PI..PI, -PI..PI, -PI..PI]],
        th in [-PI..PI, -PI..PI],
        thd in [-5.0..5.0_f64, -5.0..5.0],
    ) {
        let i = [inertia(moments[0], euler[0]), inertia(moments[1], euler[1])];
        let mut b = ModelBuilder::new(Vector3::new(0.0, 0.0, -G));
        b.add_body(link("upper", None, 0.0, m[0], -c[0], i[0]));
        b.add_body(link("lower", Some(0), -l1, m[1], -c[1], i[1]));
        let model = b.build().expect("valid");
        let mut ws = Workspace::new(&model);
        update_kinematics(&model, &mut ws, &th, &thd).unwrap();
        let h = mass_matrix(&model, &mut ws).unwrap().clone();
        let cvec = bias_forces(&model, &mut ws).unwrap().clone();
        let d = Double { m, c, l1, iyy: [i[0][(1, 1)], i[1][(1, 1)]] };
        let (h_ref, c_ref) = d.lagrangian(Vector2::from(th), Vector2::from(thd));
        let h_scale = 1.0 + h_ref.norm();
        let c_scale = 1.0 + c_ref.norm();
        for r in 0..2 {
            prop_assert!((c_ref[r] - cvec[r]).abs() < 1e-10 * c_scale, "C {} vs {}", cvec, c_ref);
            for k in 0..2 {
                prop_assert!((h_ref[(r, k)] - h[(r, k)]).abs() < 1e-10 * h_scale, "H {} vs {}", h, h_ref);
            }
        }
    }
}
