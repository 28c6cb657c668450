//! Fixed-step classical Runge-Kutta 4 on the state `[q, v]`, written for the tests only.
use multibody::{Model, Workspace};

/// Advances `(q, v)` by one step `dt`. `accel(ws, q, v, vdot)` writes the joint
/// accelerations; `qdot` comes from [`Model::velocity_to_qdot`]. Quaternions are
/// renormalised after the step.
pub fn rk4_step<F>(
    model: &Model,
    ws: &mut Workspace,
    q: &mut [f64],
    v: &mut [f64],
    dt: f64,
    accel: &mut F,
) where
    F: FnMut(&mut Workspace, &[f64], &[f64], &mut [f64]),
{
    let mut deriv = |ws: &mut Workspace, q: &[f64], v: &[f64]| {
        let mut qd = vec![0.0; model.nq()];
        let mut vd = vec![0.0; model.nv()];
        model.velocity_to_qdot(q, v, &mut qd);
        accel(ws, q, v, &mut vd);
        (qd, vd)
    };
    let axpy = |x: &[f64], k: &[f64], h: f64| -> Vec<f64> {
        x.iter().zip(k).map(|(a, b)| a + h * b).collect()
    };
    let (k1q, k1v) = deriv(ws, q, v);
    let (k2q, k2v) = deriv(ws, &axpy(q, &k1q, dt / 2.0), &axpy(v, &k1v, dt / 2.0));
    let (k3q, k3v) = deriv(ws, &axpy(q, &k2q, dt / 2.0), &axpy(v, &k2v, dt / 2.0));
    let (k4q, k4v) = deriv(ws, &axpy(q, &k3q, dt), &axpy(v, &k3v, dt));
    for i in 0..q.len() {
        q[i] += dt / 6.0 * (k1q[i] + 2.0 * k2q[i] + 2.0 * k3q[i] + k4q[i]);
    }
    for i in 0..v.len() {
        v[i] += dt / 6.0 * (k1v[i] + 2.0 * k2v[i] + 2.0 * k3v[i] + k4v[i]);
    }
    model.normalize_quaternions(q);
}
