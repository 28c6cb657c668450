//! Each method on problems with known solutions.

mod common;

use common::{BlowUp, Oscillator, StiffCos};
use odeint::{output_grid, Control, Integrator, OdeError, Solver};

fn dopri5(rtol: f64, atol: f64) -> Integrator {
    Integrator::new(Solver::Dopri5, rtol, atol)
}

fn rosenbrock23(rtol: f64, atol: f64) -> Integrator {
    Integrator::new(Solver::Rosenbrock23, rtol, atol)
}

#[test]
fn oscillator_matches_closed_form() {
    let sys = Oscillator {
        w: 2.0 * std::f64::consts::PI,
    };
    let ts = output_grid(0.0, 3.0, 0.01);
    let mut max_err: f64 = 0.0;
    let stats = dopri5(1e-9, 1e-12)
        .integrate(&sys, 0.0, &[1.0, 0.0], &ts, |t, y| {
            max_err = max_err.max((y[0] - (sys.w * t).cos()).abs());
            Control::Continue
        })
        .unwrap();
    assert!(max_err < 1e-7, "max error {max_err}");
    assert!(stats.accepted > 10);
}

#[test]
fn error_shrinks_with_tolerance() {
    let sys = Oscillator { w: 3.0 };
    let run = |rtol: f64| {
        let mut e: f64 = 0.0;
        dopri5(rtol, rtol * 1e-3)
            .integrate(&sys, 0.0, &[1.0, 0.0], &[5.0], |t, y| {
                e = (y[0] - (3.0 * t).cos()).abs();
                Control::Continue
            })
            .unwrap();
        e
    };
    assert!(run(1e-8) < run(1e-4) / 100.0);
}

#[test]
fn blow_up_is_an_error_with_time_and_state() {
    let r = dopri5(1e-6, 1e-9).integrate(&BlowUp, 0.0, &[1.0], &[2.0], |_, _| Control::Continue);
    match r {
        Err(OdeError::Diverged { t, state, .. }) | Err(OdeError::TooManySteps { t, state, .. }) => {
            assert!(t > 0.9 && t < 1.01, "t = {t}");
            assert!(state[0].is_finite());
        }
        other => panic!("expected an error, got {other:?}"),
    }
}

#[test]
fn stop_ends_run() {
    let sys = Oscillator { w: 1.0 };
    let ts = output_grid(0.0, 10.0, 0.1);
    let mut seen = 0;
    dopri5(1e-6, 1e-9)
        .integrate(&sys, 0.0, &[1.0, 0.0], &ts, |t, _| {
            seen += 1;
            if t >= 1.0 {
                Control::Stop
            } else {
                Control::Continue
            }
        })
        .unwrap();
    assert_eq!(seen, 11);
}

#[test]
fn rejects_bad_requests() {
    let sys = Oscillator { w: 1.0 };
    let d = dopri5(1e-6, 1e-9);
    assert!(d
        .integrate(&sys, 0.0, &[1.0], &[1.0], |_, _| Control::Continue)
        .is_err());
    assert!(d
        .integrate(&sys, 0.0, &[f64::NAN, 0.0], &[1.0], |_, _| {
            Control::Continue
        })
        .is_err());
    assert!(d
        .integrate(&sys, 0.0, &[1.0, 0.0], &[1.0, 0.5], |_, _| {
            Control::Continue
        })
        .is_err());
    assert!(dopri5(-1.0, 1e-9)
        .integrate(&sys, 0.0, &[1.0, 0.0], &[1.0], |_, _| Control::Continue)
        .is_err());
}

#[test]
fn rk4_fourth_order_convergence() {
    let sys = Oscillator { w: 1.0 };
    let err = |h: f64| {
        let mut e = 0.0;
        Integrator::new(Solver::Rk4 { step: h }, 1e-6, 1e-9)
            .integrate(&sys, 0.0, &[1.0, 0.0], &[2.0], |t, y| {
                e = (y[0] - t.cos()).abs();
                Control::Continue
            })
            .unwrap();
        e
    };
    let ratio = err(0.1) / err(0.05);
    assert!((ratio - 16.0).abs() < 2.0, "ratio {ratio}");
}

#[test]
fn stiff_problem_solved_in_few_steps() {
    let sys = StiffCos { k: 1e6 };
    let mut max_err: f64 = 0.0;
    let ts = output_grid(0.0, 2.0, 0.1);
    let st = rosenbrock23(1e-5, 1e-8)
        .integrate(&sys, 0.0, &[1.0], &ts, |t, y| {
            max_err = max_err.max((y[0] - t.cos()).abs());
            Control::Continue
        })
        .unwrap();
    assert!(max_err < 1e-4, "max err {max_err}");
    // The explicit method needs ~k*T/3 steps here; the implicit one a few hundred at most.
    assert!(st.accepted < 500, "{st:?}");
    let ex = dopri5(1e-5, 1e-8)
        .integrate(&sys, 0.0, &[1.0], &ts, |_, _| Control::Continue)
        .unwrap();
    assert!(
        ex.accepted > 10 * st.accepted,
        "explicit {ex:?} vs implicit {st:?}"
    );
}

#[test]
fn rosenbrock_oscillator_second_order_accuracy() {
    let sys = Oscillator { w: 1.0 };
    let mut e = 0.0;
    rosenbrock23(1e-7, 1e-10)
        .integrate(&sys, 0.0, &[1.0, 0.0], &[3.0], |t, y| {
            e = (y[0] - t.cos()).abs();
            Control::Continue
        })
        .unwrap();
    assert!(e < 1e-5, "err {e}");
}

#[test]
fn rosenbrock_blow_up_is_an_error() {
    let r =
        rosenbrock23(1e-4, 1e-8).integrate(&BlowUp, 0.0, &[1.0], &[2.0], |_, _| Control::Continue);
    assert!(r.is_err());
}
