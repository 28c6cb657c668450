//! The shared driver: convergence order, breakpoints, limits, divergence, events,
//! workspace reuse, per-state tolerances, `Auto`.

mod common;

use common::{loglog_slope, BlowUp, Oscillator, StiffCos};
use odeint::{
    output_grid, Atol, Control, Direction, Event, Integrator, OdeError, OdeSystem, Problem,
    SampleKind, Solver, Workspace,
};

fn final_error(integ: &Integrator) -> (f64, f64) {
    let sys = Oscillator { w: 1.0 };
    let mut e = 0.0;
    let st = integ
        .integrate(&sys, 0.0, &[1.0, 0.0], &[20.0], |t, y| {
            e = (y[0] - t.cos()).abs() + (y[1] + t.sin()).abs();
            Control::Continue
        })
        .unwrap();
    (st.accepted as f64, e)
}

#[test]
fn adaptive_methods_converge_at_their_order() {
    for (solver, lo, hi, tols) in [
        (Solver::Dopri5, 4.0, 6.5, [1e-5, 1e-7, 1e-9, 1e-11]),
        (Solver::Rosenbrock23, 1.6, 3.2, [1e-4, 1e-5, 1e-6, 1e-7]),
    ] {
        let pts: Vec<(f64, f64)> = tols
            .iter()
            .map(|&tol| final_error(&Integrator::new(solver, tol, tol)))
            .collect();
        let order = -loglog_slope(&pts);
        assert!(
            order > lo && order < hi,
            "{solver:?}: order {order} from {pts:?}"
        );
    }
}

#[test]
fn rk4_converges_at_fourth_order() {
    let pts: Vec<(f64, f64)> = [0.2, 0.1, 0.05, 0.025]
        .iter()
        .map(|&step| final_error(&Integrator::new(Solver::Rk4 { step }, 1e-6, 1e-9)))
        .collect();
    let order = -loglog_slope(&pts);
    assert!((order - 4.0).abs() < 0.3, "order {order} from {pts:?}");
}

/// y' = max(0, t - at): y(t) = max(0, t - at)^2 / 2, a kink in the right-hand side that
/// every method here integrates exactly on either side but not across.
struct Ramp {
    at: f64,
}

impl OdeSystem for Ramp {
    fn dim(&self) -> usize {
        1
    }
    fn rhs(&self, t: f64, _y: &[f64], d: &mut [f64]) {
        d[0] = (t - self.at).max(0.0);
    }
}

fn ramp_end(integ: &Integrator, breakpoints: &[f64]) -> f64 {
    let sys = Ramp { at: 0.3337 };
    let mut end = f64::NAN;
    let t_out = [0.5, 1.0];
    let p = Problem::new(0.0, &[0.0], &t_out).with_breakpoints(breakpoints);
    integ
        .run(&sys, &p, &mut Workspace::new(1), |s| {
            end = s.y[0];
            Control::Continue
        })
        .unwrap();
    end - 0.5 * (1.0 - sys.at).powi(2)
}

#[test]
fn breakpoints_are_landed_on() {
    for solver in [
        Solver::Dopri5,
        Solver::Rosenbrock23,
        Solver::Rk4 { step: 0.03 },
    ] {
        let integ = Integrator::new(solver, 1e-6, 1e-9);
        let with = ramp_end(&integ, &[0.3337]);
        let without = ramp_end(&integ, &[]);
        assert!(
            with.abs() < 1e-12,
            "{solver:?}: error {with} with the breakpoint"
        );
        assert!(
            without.abs() > 1e3 * with.abs().max(1e-16),
            "{solver:?}: {without}"
        );
    }
}

#[test]
fn step_limit_is_an_error_with_time_and_state() {
    let sys = Oscillator { w: 10.0 };
    let r = Integrator::new(Solver::Dopri5, 1e-10, 1e-12)
        .with_max_steps(50)
        .integrate(&sys, 0.0, &[1.0, 0.0], &[100.0], |_, _| Control::Continue);
    match r {
        Err(OdeError::TooManySteps {
            max_steps,
            t,
            state,
        }) => {
            assert_eq!(max_steps, 50);
            assert!(t > 0.0 && t < 100.0, "t = {t}");
            assert_eq!(state.len(), 2);
        }
        other => panic!("expected the step limit, got {other:?}"),
    }
}

#[test]
fn divergence_is_an_error_with_time_and_finite_state() {
    for solver in [
        Solver::Dopri5,
        Solver::Rosenbrock23,
        Solver::Rk4 { step: 0.01 },
    ] {
        let r =
            Integrator::new(solver, 1e-6, 1e-9)
                .integrate(&BlowUp, 0.0, &[1.0], &[2.0], |_, _| Control::Continue);
        match r {
            Err(OdeError::Diverged { t, h, state }) => {
                assert!(t > 0.9 && t < 1.05, "{solver:?}: t = {t}");
                assert!(h > 0.0 && state[0].is_finite(), "{solver:?}: {h} {state:?}");
            }
            other => panic!("{solver:?}: expected divergence, got {other:?}"),
        }
    }
}

/// Free fall y'' = -g from height h0 at rest: impact at sqrt(2 h0 / g).
struct Fall;

impl OdeSystem for Fall {
    fn dim(&self) -> usize {
        2
    }
    fn rhs(&self, _t: f64, y: &[f64], d: &mut [f64]) {
        d[0] = y[1];
        d[1] = -9.81;
    }
}

#[test]
fn falling_ball_impact_ends_the_run() {
    let h0 = 10.0;
    let t_impact = (2.0 * h0 / 9.81_f64).sqrt();
    let height = |_t: f64, y: &[f64]| y[0];
    let events = [Event::new(&height, Direction::Falling).terminal()];
    let t_out = output_grid(0.0, 5.0, 0.1);
    for solver in [
        Solver::Dopri5,
        Solver::Rosenbrock23,
        Solver::Rk4 { step: 0.05 },
    ] {
        let mut hits = Vec::new();
        let mut last_t = 0.0;
        let y0 = [h0, 0.0];
        let p = Problem::new(0.0, &y0, &t_out).with_events(&events);
        let st = Integrator::new(solver, 1e-8, 1e-10)
            .run(&Fall, &p, &mut Workspace::with_events(2, 1), |s| {
                last_t = s.t;
                if s.kind == SampleKind::Event(0) {
                    hits.push((s.t, s.y[0], s.y[1]));
                }
                Control::Continue
            })
            .unwrap();
        assert_eq!(hits.len(), 1, "{solver:?}");
        assert_eq!(st.events, 1);
        let (t, y, v) = hits[0];
        // The crossing is as exact as the method's dense output (2nd order for Rosenbrock).
        let tol = if solver == Solver::Rosenbrock23 {
            1e-7
        } else {
            1e-9
        };
        assert!(
            (t - t_impact).abs() < tol,
            "{solver:?}: t {t} vs {t_impact}"
        );
        assert!(
            y.abs() < 1e-8 && (v + 9.81 * t_impact).abs() < 1e-6,
            "{solver:?}: {y} {v}"
        );
        assert_eq!(
            last_t, t,
            "{solver:?}: the run goes on after a terminal event"
        );
    }
}

#[test]
fn oscillator_zero_crossings_with_direction_filter() {
    let w = 2.0;
    let sys = Oscillator { w };
    let x = |_t: f64, y: &[f64]| y[0];
    let t_out = output_grid(0.0, 10.0, 0.5);
    for solver in [
        Solver::Dopri5,
        Solver::Rosenbrock23,
        Solver::Rk4 { step: 0.01 },
    ] {
        let events = [
            Event::new(&x, Direction::Either),
            Event::new(&x, Direction::Rising),
        ];
        let p = Problem::new(0.0, &[1.0, 0.0], &t_out).with_events(&events);
        let mut either = Vec::new();
        let mut rising = Vec::new();
        let mut last = f64::NEG_INFINITY;
        Integrator::new(solver, 1e-9, 1e-12)
            .run(&sys, &p, &mut Workspace::with_events(2, 2), |s| {
                assert!(s.t >= last, "samples out of time order");
                last = s.t;
                match s.kind {
                    SampleKind::Event(0) => {
                        // Located on the dense output to `event_tol` (1e-10 s) in time.
                        assert!(s.y[0].abs() < 1e-9, "{solver:?}: x = {} at {}", s.y[0], s.t);
                        either.push(s.t)
                    }
                    SampleKind::Event(1) => rising.push(s.t),
                    SampleKind::Event(_) | SampleKind::Output(_) => {}
                }
                Control::Continue
            })
            .unwrap();
        let tol = if solver == Solver::Rosenbrock23 {
            1e-5
        } else {
            1e-7
        };
        // x = cos(w t) = 0 at t_k = (k + 1/2) pi / w; rising (x' > 0) for odd k.
        let zeros: Vec<f64> = (0..)
            .map(|k| (k as f64 + 0.5) * std::f64::consts::PI / w)
            .take_while(|&t| t <= 10.0)
            .collect();
        assert_eq!(either.len(), zeros.len(), "{solver:?}");
        for (a, b) in either.iter().zip(&zeros) {
            assert!((a - b).abs() < tol, "{solver:?}: {a} vs {b}");
        }
        let odd: Vec<f64> = zeros.iter().skip(1).step_by(2).copied().collect();
        assert_eq!(rising.len(), odd.len(), "{solver:?}");
        for (a, b) in rising.iter().zip(&odd) {
            assert!((a - b).abs() < tol, "{solver:?}: {a} vs {b}");
        }
    }
}

fn trace(integ: &Integrator, sys: &dyn OdeSystem, y0: &[f64], ws: &mut Workspace) -> Vec<f64> {
    let t_out = output_grid(0.0, 3.0, 0.25);
    let mut v = Vec::new();
    integ
        .run(sys, &Problem::new(0.0, y0, &t_out), ws, |s| {
            v.extend_from_slice(s.y);
            Control::Continue
        })
        .unwrap();
    v
}

#[test]
fn workspace_reuse_gives_identical_results() {
    let osc = Oscillator { w: 3.0 };
    let stiff = StiffCos { k: 20.0 };
    for solver in [
        Solver::Dopri5,
        Solver::Rosenbrock23,
        Solver::Rk4 { step: 0.01 },
    ] {
        let integ = Integrator::new(solver, 1e-7, 1e-10);
        let fresh = trace(&integ, &osc, &[1.0, 0.0], &mut Workspace::new(2));
        let mut ws = Workspace::new(2);
        let first = trace(&integ, &osc, &[1.0, 0.0], &mut ws);
        let other = trace(&integ, &stiff, &[1.0], &mut ws);
        let again = trace(&integ, &osc, &[1.0, 0.0], &mut ws);
        assert_eq!(first, fresh, "{solver:?}");
        assert_eq!(again, fresh, "{solver:?}");
        assert_eq!(other.len(), 13);
    }
}

/// A mass on a gas spring with its pressure as a state: (x, v, p) in SI, p ~ 1e6 Pa.
struct GasSpring {
    /// Scale of the pressure state: 1 for Pa, 1e-6 for MPa.
    scale: f64,
}

impl OdeSystem for GasSpring {
    fn dim(&self) -> usize {
        3
    }
    fn rhs(&self, _t: f64, y: &[f64], d: &mut [f64]) {
        let p = y[2] / self.scale;
        d[0] = y[1];
        d[1] = -(p - 1.0e6) * 1e-5 - 0.3 * y[1];
        d[2] = -40.0 * y[1] * p * self.scale;
    }
}

#[test]
fn per_state_atol_equals_the_scaled_run() {
    let t_out = output_grid(0.0, 5.0, 0.1);
    for solver in [Solver::Dopri5, Solver::Rosenbrock23] {
        let run = |scale: f64, atol: Atol| {
            let mut v = Vec::new();
            let st = Integrator::new(solver, 1e-6, atol)
                .integrate(
                    &GasSpring { scale },
                    0.0,
                    &[0.05, 0.0, 1.0e6 * scale],
                    &t_out,
                    |_, y| {
                        v.push(y[2] / scale);
                        Control::Continue
                    },
                )
                .unwrap();
            (v, st)
        };
        let (scaled, st_scaled) = run(1e-6, Atol::Scalar(1e-8));
        let (si, st_si) = run(1.0, Atol::scaled(1e-8, [1.0, 1.0, 1e6]));
        assert_eq!(st_scaled.accepted, st_si.accepted, "{solver:?}");
        assert_eq!(st_scaled.rejected, st_si.rejected, "{solver:?}");
        for (a, b) in scaled.iter().zip(&si) {
            assert!((a - b).abs() < 1e-9 * a.abs(), "{solver:?}: {a} vs {b}");
        }
    }
}

#[test]
fn bad_per_state_atol_is_refused() {
    let sys = Oscillator { w: 1.0 };
    for atol in [Atol::PerState(vec![1e-9]), Atol::PerState(vec![1e-9, -1.0])] {
        let r = Integrator::new(Solver::Dopri5, 1e-6, atol).integrate(
            &sys,
            0.0,
            &[1.0, 0.0],
            &[1.0],
            |_, _| Control::Continue,
        );
        assert!(matches!(r, Err(OdeError::InvalidInput(_))), "{r:?}");
    }
}

struct Flagged {
    stiff: bool,
}

impl OdeSystem for Flagged {
    fn dim(&self) -> usize {
        1
    }
    fn rhs(&self, _t: f64, y: &[f64], d: &mut [f64]) {
        d[0] = -y[0];
    }
    fn is_stiff(&self) -> bool {
        self.stiff
    }
}

#[test]
fn auto_asks_the_model() {
    assert_eq!(
        Solver::Auto.resolve(&Flagged { stiff: true }),
        Solver::Rosenbrock23
    );
    assert_eq!(
        Solver::Auto.resolve(&Flagged { stiff: false }),
        Solver::Dopri5
    );
    let rk = Solver::Rk4 { step: 0.1 };
    assert_eq!(rk.resolve(&Flagged { stiff: true }), rk);
    let run = |solver: Solver, stiff: bool| {
        Integrator::new(solver, 1e-6, 1e-9)
            .integrate(&Flagged { stiff }, 0.0, &[1.0], &[1.0], |_, _| {
                Control::Continue
            })
            .unwrap()
    };
    assert_eq!(run(Solver::Auto, true), run(Solver::Rosenbrock23, true));
    assert_eq!(run(Solver::Auto, false), run(Solver::Dopri5, false));
}

#[test]
fn solver_serialises_in_snake_case() {
    let cases = [
        (Solver::Dopri5, "\"dopri5\""),
        (Solver::Tsit5, "\"tsit5\""),
        (Solver::Rosenbrock23, "\"rosenbrock23\""),
        (Solver::Auto, "\"auto\""),
        (Solver::Rk4 { step: 0.5 }, "{\"rk4\":{\"step\":0.5}}"),
    ];
    for (s, json) in cases {
        assert_eq!(serde_json::to_string(&s).unwrap(), json);
        assert_eq!(serde_json::from_str::<Solver>(json).unwrap(), s);
    }
}

/// A slow state and a stiff one: `y0' = -y0`, `y1' = -k (y1 - cos t)`.
struct StiffPair {
    k: f64,
}

impl OdeSystem for StiffPair {
    fn dim(&self) -> usize {
        2
    }
    fn rhs(&self, t: f64, y: &[f64], dydt: &mut [f64]) {
        dydt[0] = -y[0];
        dydt[1] = -self.k * (y[1] - t.cos());
    }
}

#[test]
fn a_collapsed_step_size_ends_the_run_early_naming_the_stiff_state() {
    // Dopri5's stability bound is h < 3.3 / k: 100 s at k = 1e7 would take about 3e8 steps,
    // 300 times the budget; the run ends after a few thousand steps instead of 10^6
    let sys = StiffPair { k: 1e7 };
    let r = Integrator::new(Solver::Dopri5, 1e-6, 1e-9).integrate(
        &sys,
        0.0,
        &[1.0, 1.0],
        &[100.0],
        |_, _| Control::Continue,
    );
    match r {
        Err(OdeError::StepSizeCollapsed {
            t,
            h,
            projected_steps,
            max_steps,
            dominant_state,
            state,
        }) => {
            assert_eq!(dominant_state, 1);
            assert_eq!(max_steps, 1_000_000);
            assert!(projected_steps > 1e8, "{projected_steps}");
            assert!(h < 1e-6 && t < 0.01, "h = {h}, t = {t}");
            assert_eq!(state.len(), 2);
        }
        other => panic!("expected the collapse, got {other:?}"),
    }
    // the same problem with the linearly implicit method is not stiff for it: no collapse
    let mut end = 0.0;
    Integrator::new(Solver::Rosenbrock23, 1e-6, 1e-9)
        .integrate(&sys, 0.0, &[1.0, 1.0], &[100.0], |_, y| {
            end = y[1];
            Control::Continue
        })
        .unwrap();
    assert!((end - 100f64.cos()).abs() < 1e-4, "{end}");
}
