//! ROS34PW2 on stiff blocks: order 3 whatever the block Jacobian leaves out (the W
//! property), the stiff state handled implicitly beside explicit ones, a model's own block
//! Jacobian used as given, and bad blocks refused.

mod common;

use common::{loglog_slope, Oscillator, StiffFollower};
use odeint::{output_grid, Control, Integrator, OdeError, OdeSystem, Solver};

/// The oscillator with the position alone as its "stiff block": the block Jacobian
/// (∂x'/∂x = 0) leaves out the whole coupling, the case a W-method must survive at full order.
struct PartialBlock {
    blocks: Vec<Vec<usize>>,
}

impl OdeSystem for PartialBlock {
    fn dim(&self) -> usize {
        2
    }
    fn rhs(&self, t: f64, y: &[f64], d: &mut [f64]) {
        Oscillator { w: 1.0 }.rhs(t, y, d)
    }
    fn stiff_blocks(&self) -> &[Vec<usize>] {
        &self.blocks
    }
}

fn oscillator_error(sys: &dyn OdeSystem, tol: f64) -> (f64, f64) {
    let mut e = 0.0;
    let st = Integrator::new(Solver::Ros34pw2, tol, tol)
        .integrate(sys, 0.0, &[1.0, 0.0], &[20.0], |t, y| {
            e = (y[0] - t.cos()).abs() + (y[1] + t.sin()).abs();
            Control::Continue
        })
        .unwrap();
    (st.accepted as f64, e)
}

#[test]
fn third_order_with_no_block_a_partial_block_and_the_full_jacobian() {
    for blocks in [vec![], vec![vec![0]], vec![vec![1]], vec![vec![0, 1]]] {
        let sys = PartialBlock {
            blocks: blocks.clone(),
        };
        let pts: Vec<(f64, f64)> = [1e-4, 1e-5, 1e-6, 1e-7]
            .iter()
            .map(|&tol| oscillator_error(&sys, tol))
            .collect();
        let order = -loglog_slope(&pts);
        assert!(
            order > 2.5 && order < 4.0,
            "{blocks:?}: order {order} from {pts:?}"
        );
    }
}

/// Largest errors of `x` and `s` over the output grid (between steps: the dense output,
/// linear in the stiff state).
fn follower_run(sys: &StiffFollower, solver: Solver) -> (odeint::Stats, f64, f64) {
    let (mut err_x, mut err_s): (f64, f64) = (0.0, 0.0);
    let ts = output_grid(0.0, 10.0, 0.1);
    let st = Integrator::new(solver, 1e-6, 1e-9)
        .integrate(sys, 0.0, &[1.0, 0.0, 1.0], &ts, |t, y| {
            err_x = err_x.max((y[0] - t.cos()).abs());
            // s = x - x'/k + O(1/k^2) once the start-up layer has passed
            err_s = err_s.max((y[2] - t.cos() - t.sin() / sys.k).abs());
            Control::Continue
        })
        .unwrap();
    (st, err_x, err_s)
}

#[test]
fn the_stiff_block_is_implicit_and_the_rest_explicit() {
    let k = 1e6;
    for own_jacobian in [false, true] {
        let sys = StiffFollower::new(k, vec![vec![2]], own_jacobian);
        let (st, err_x, err_s) = follower_run(&sys, Solver::Ros34pw2);
        assert!(err_x < 1e-6 && err_s < 1e-5, "errors {err_x} {err_s}");
        assert!(st.accepted < 10_000, "{st:?}");
        // the model's own Jacobian saves the differencing call of each step
        if own_jacobian {
            assert!(
                st.rhs_evals <= 4 * st.accepted + 3 * st.rejected + 2,
                "{st:?}"
            );
        } else {
            assert!(st.rhs_evals > 5 * st.accepted, "{st:?}");
        }
    }
    // without the block the same method is explicit and the stiff state holds its steps
    // near the stability limit (about 2.5 / k each, more than 10x as many steps)
    let explicit = StiffFollower::new(k, vec![], false);
    let st = Integrator::new(Solver::Ros34pw2, 1e-6, 1e-9)
        .with_max_steps(200_000)
        .integrate(&explicit, 0.0, &[1.0, 0.0, 1.0], &[0.5], |_, _| {
            Control::Continue
        });
    match st {
        Ok(st) => assert!(st.accepted > 100_000, "{st:?}"),
        Err(e) => assert!(
            matches!(
                e,
                OdeError::TooManySteps { .. } | OdeError::StepSizeCollapsed { .. }
            ),
            "{e}"
        ),
    }
}

#[test]
fn bad_blocks_are_refused() {
    for blocks in [
        vec![vec![]],
        vec![vec![0, 0]],
        vec![vec![0], vec![2, 0]],
        vec![vec![3]],
    ] {
        let sys = StiffFollower::new(1.0, blocks.clone(), false);
        let r = Integrator::new(Solver::Ros34pw2, 1e-6, 1e-9).integrate(
            &sys,
            0.0,
            &[1.0, 0.0, 1.0],
            &[1.0],
            |_, _| Control::Continue,
        );
        assert!(
            matches!(&r, Err(OdeError::InvalidInput(m)) if m.contains("stiff block")),
            "{blocks:?}: {r:?}"
        );
    }
}

#[test]
fn spelled_ros34pw2() {
    assert_eq!(
        serde_json::to_string(&Solver::Ros34pw2).unwrap(),
        "\"ros34pw2\""
    );
    assert_eq!(Solver::Ros34pw2.name(), "ros34pw2");
    // Auto picks the additive Runge-Kutta method on a model with stiff blocks
    let sys = StiffFollower::new(1.0, vec![vec![2]], true);
    assert_eq!(Solver::Auto.resolve(&sys), Solver::Ark436);
}

/// `Auto` on a model with stiff blocks is the additive Runge-Kutta method, step for step:
/// on a stiff follower a fraction of Dormand-Prince's cost, at the same answer.
#[test]
fn auto_on_a_model_with_stiff_blocks_is_ark436() {
    let run = |k: f64, solver| {
        let sys = StiffFollower::new(k, vec![vec![2]], true);
        let mut last = vec![];
        let st = Integrator::new(solver, 1e-6, 1e-9)
            .integrate(&sys, 0.0, &[1.0, 0.0, 1.0], &[0.0, 5.0, 10.0], |_, y| {
                last = y.to_vec();
                Control::Continue
            })
            .unwrap();
        (st, last)
    };
    for k in [1.0, 1e5] {
        assert_eq!(run(k, Solver::Auto), run(k, Solver::Ark436), "k = {k}");
    }
    let (auto, y_auto) = run(1e5, Solver::Auto);
    let (explicit, y_explicit) = run(1e5, Solver::Dopri5);
    assert!(
        auto.rhs_evals * 10 < explicit.rhs_evals,
        "auto {auto:?} explicit {explicit:?}"
    );
    // the fourth-order method's global error after 10 s at rtol 1e-6: 1.2e-5 (measured)
    for (a, b) in y_auto.iter().zip(&y_explicit) {
        assert!((a - b).abs() < 3e-5, "{y_auto:?} {y_explicit:?}");
    }
}
