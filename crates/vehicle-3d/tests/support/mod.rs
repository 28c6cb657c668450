//! Helpers shared by the vehicle's integration tests.

use odeint::{Control, Integrator, Problem, Solver};
use vehicle_3d::Vehicle;

/// Fixed RK4 steps (both runs of a comparison take the same steps), `channel` sampled
/// every 10 ms over `t_end` s.
pub fn sampled(
    v: &Vehicle,
    y0: &[f64],
    t_end: f64,
    mut channel: impl FnMut(&[f64]) -> Vec<f64>,
) -> Vec<Vec<f64>> {
    let t_out: Vec<f64> = (0..=(t_end * 100.0).round() as usize)
        .map(|i| i as f64 * 0.01)
        .collect();
    let mut out = Vec::new();
    Integrator::new(Solver::Rk4 { step: 2e-4 }, 1e-6, 1e-6)
        .run(
            v,
            &Problem::new(0.0, y0, &t_out),
            &mut odeint::Workspace::new(y0.len()),
            |s| {
                out.push(channel(s.y));
                Control::Continue
            },
        )
        .unwrap();
    out
}
