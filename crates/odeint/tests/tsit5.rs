//! Tsitouras 5(4) (`Solver::Tsit5`): convergence order on a nonlinear problem with a closed
//! form, dense output between steps, events located as with Dormand-Prince, breakpoints,
//! and a run that allocates nothing once its workspace exists (counted by a global
//! allocator wrapper, per thread).

mod common;
mod counting;

use common::{loglog_slope, Logistic, Oscillator};
use odeint::{
    Control, Direction, Event, Integrator, OdeSystem, Problem, SampleKind, Solver, Workspace,
};

const T_END: f64 = 8.0;

/// Steps of exactly `h` (a tolerance no step can miss, `first_step = max_step = h`, and
/// `T_END / h` whole): the largest error at the step ends and at 7 dense outputs inside
/// every step, against the closed form.
fn fixed_step_errors(solver: Solver, h: f64) -> (f64, f64) {
    let mut integ = Integrator::new(solver, 1e6, 1e6).with_max_step(h);
    integ.first_step = Some(h);
    let n = (T_END / h).round() as usize;
    let t_out: Vec<f64> = (0..=8 * n).map(|i| i as f64 * h / 8.0).collect();
    let (mut at_steps, mut between) = (0.0f64, 0.0f64);
    let mut ws = Workspace::new(2);
    let st = integ
        .run(
            &Logistic,
            &Problem::new(0.0, &[0.1, 1.0], &t_out),
            &mut ws,
            |s| {
                let e = Logistic::exact(s.t);
                let err = (s.y[0] - e[0]).abs().max((s.y[1] - e[1]).abs());
                if let SampleKind::Output(i) = s.kind {
                    if i % 8 == 0 {
                        at_steps = at_steps.max(err);
                    } else {
                        between = between.max(err);
                    }
                }
                Control::Continue
            },
        )
        .unwrap();
    assert_eq!(
        (st.accepted, st.rejected),
        (n, 0),
        "h = {h}: not fixed steps"
    );
    (at_steps, between)
}

#[test]
fn converges_at_fifth_order_with_a_fourth_order_dense_output() {
    let hs = [0.2, 0.1, 0.05, 0.025];
    let errs: Vec<(f64, f64)> = hs
        .iter()
        .map(|&h| fixed_step_errors(Solver::Tsit5, h))
        .collect();
    let steps: Vec<f64> = hs.iter().map(|h| T_END / h).collect();
    let at: Vec<(f64, f64)> = steps.iter().zip(&errs).map(|(&n, e)| (n, e.0)).collect();
    let dense: Vec<(f64, f64)> = steps.iter().zip(&errs).map(|(&n, e)| (n, e.1)).collect();
    let order = -loglog_slope(&at);
    // the local slopes fall towards 5 as h shrinks (5.7, 5.5, 5.3 here)
    assert!(order > 4.7 && order < 5.8, "order {order} from {at:?}");
    // a continuous extension of order 4 leaves O(h^5) local errors between the steps
    let dense_order = -loglog_slope(&dense);
    let dopri = fixed_step_errors(Solver::Dopri5, 0.1);
    assert!(
        dense_order > 3.8 && dense_order < 6.0,
        "dense order {dense_order} from {dense:?}"
    );
    // between the steps it is as accurate as Dormand-Prince's (7.9e-8 against 8.1e-8 here)
    assert!(
        errs[1].1 < 1e-7 && errs[1].1 < 1.5 * dopri.1,
        "dense error at h = 0.1: {:e} (Dopri5 {:e})",
        errs[1].1,
        dopri.1
    );
    // on this problem the smaller fifth-order error coefficients show at equal steps
    // (3.2e-9 against 1.2e-8 at the step ends)
    assert!(
        errs[1].0 < dopri.0,
        "Tsit5 {:e} against Dopri5 {:e} at h = 0.1",
        errs[1].0,
        dopri.0
    );
}

#[test]
fn adaptive_error_follows_the_tolerance() {
    let mut last = f64::INFINITY;
    for tol in [1e-4, 1e-6, 1e-8, 1e-10] {
        let mut err = 0.0f64;
        Integrator::new(Solver::Tsit5, tol, tol)
            .integrate(&Logistic, 0.0, &[0.1, 1.0], &[2.0, 4.0, 8.0], |t, y| {
                let e = Logistic::exact(t);
                err = err.max((y[0] - e[0]).abs().max((y[1] - e[1]).abs()));
                Control::Continue
            })
            .unwrap();
        assert!(
            err < 100.0 * tol && err < last,
            "tol {tol:e}: error {err:e}"
        );
        last = err;
    }
}

#[test]
fn oscillator_zeros_are_located_as_with_dopri5() {
    let w = 2.0;
    let g = |_t: f64, y: &[f64]| y[0];
    let mut found = Vec::new();
    for solver in [Solver::Dopri5, Solver::Tsit5] {
        for direction in [Direction::Either, Direction::Rising] {
            let events = [Event::new(&g, direction)];
            let mut times = Vec::new();
            let mut ws = Workspace::with_events(2, 1);
            let st = Integrator::new(solver, 1e-8, 1e-10)
                .run(
                    &Oscillator { w },
                    &Problem::new(0.0, &[1.0, 0.0], &[10.0]).with_events(&events),
                    &mut ws,
                    |s| {
                        if s.kind == SampleKind::Event(0) {
                            times.push(s.t);
                        }
                        Control::Continue
                    },
                )
                .unwrap();
            assert_eq!(st.events, times.len());
            // zeros of cos(w t) at (k + 1/2) pi / w; rising (x' > 0 ... x from - to +) at odd k
            let want: Vec<f64> = (0..)
                .map(|k| (k as f64 + 0.5) * std::f64::consts::PI / w)
                .take_while(|&t| t < 10.0)
                .enumerate()
                .filter(|(k, _)| direction == Direction::Either || k % 2 == 1)
                .map(|(_, t)| t)
                .collect();
            assert_eq!(times.len(), want.len(), "{solver:?} {direction:?}");
            for (t, tw) in times.iter().zip(&want) {
                assert!((t - tw).abs() < 1e-7, "{solver:?}: {t} against {tw}");
            }
            found.push(times);
        }
    }
    for (d, t) in found[..2].iter().zip(&found[2..]) {
        for (a, b) in d.iter().zip(t) {
            assert!((a - b).abs() < 1e-7, "Dopri5 {a} against Tsit5 {b}");
        }
    }
}

#[test]
fn a_terminal_event_ends_the_run_at_the_crossing() {
    // y1 = 1 / (1 + t²) falls through 0.2 at t = 2
    let g = |_t: f64, y: &[f64]| y[1] - 0.2;
    let events = [Event::new(&g, Direction::Falling).terminal()];
    let mut last = (0.0, 0.0);
    let t_out: Vec<f64> = (0..=100).map(|i| i as f64 * 0.1).collect();
    let mut ws = Workspace::with_events(2, 1);
    Integrator::new(Solver::Tsit5, 1e-9, 1e-11)
        .run(
            &Logistic,
            &Problem::new(0.0, &[0.1, 1.0], &t_out).with_events(&events),
            &mut ws,
            |s| {
                last = (s.t, s.y[1]);
                Control::Continue
            },
        )
        .unwrap();
    assert!((last.0 - 2.0).abs() < 1e-9, "ended at {}", last.0);
    assert!((last.1 - 0.2).abs() < 1e-9);
}

/// y' = max(0, t - 1): a kink at t = 1.
struct Ramp;

impl OdeSystem for Ramp {
    fn dim(&self) -> usize {
        1
    }
    fn rhs(&self, t: f64, _y: &[f64], d: &mut [f64]) {
        d[0] = (t - 1.0).max(0.0);
    }
}

#[test]
fn a_breakpoint_is_landed_on() {
    let mut ws = Workspace::new(1);
    let mut end = 0.0;
    Integrator::new(Solver::Tsit5, 1e-6, 1e-9)
        .run(
            &Ramp,
            &Problem::new(0.0, &[0.0], &[3.0]).with_breakpoints(&[1.0]),
            &mut ws,
            |s| {
                end = s.y[0];
                Control::Continue
            },
        )
        .unwrap();
    assert!((end - 2.0).abs() < 1e-12, "y(3) = {end}, want 2");
}

#[test]
fn a_run_with_its_workspace_allocates_nothing() {
    let g = |_t: f64, y: &[f64]| y[0] - 0.5;
    let events = [Event::new(&g, Direction::Rising)];
    let t_out: Vec<f64> = (0..=400).map(|i| i as f64 * 0.02).collect();
    let integ = Integrator::new(Solver::Tsit5, 1e-8, 1e-10);
    let mut ws = Workspace::with_events(2, 1);
    let problem = Problem::new(0.0, &[0.1, 1.0], &t_out).with_events(&events);
    let mut sum = 0.0;
    integ
        .run(&Logistic, &problem, &mut ws, |s| {
            sum += s.y[0];
            Control::Continue
        })
        .unwrap();
    let before = counting::allocations();
    let st = integ
        .run(&Logistic, &problem, &mut ws, |s| {
            sum += s.y[0];
            Control::Continue
        })
        .unwrap();
    let allocated = counting::allocations() - before;
    assert_eq!(allocated, 0, "{allocated} allocations in a run of {st:?}");
    assert_eq!(st.events, 1);
    assert!(sum.is_finite());
}
