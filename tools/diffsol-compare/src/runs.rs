//! One run of a solver on a scenario: outputs, RHS calls, steps, wall time.

use crate::scenario::Scenario;
use diffsol::{NalgebraLU, NalgebraMat, OdeBuilder, OdeSolverMethod, OdeSolverStopReason, Vector};
use odeint::{Atol, Control, Integrator, OdeSystem, Problem, Solver, Workspace};
use std::cell::RefCell;
use std::time::Instant;

/// The methods compared.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Method {
    Ours(Solver),
    Bdf,
    Esdirk34,
    TrBdf2,
}

impl Method {
    pub fn name(&self) -> String {
        match self {
            Method::Ours(s) => format!("odeint {}", s.name()),
            Method::Bdf => "diffsol BDF".into(),
            Method::Esdirk34 => "diffsol ESDIRK34".into(),
            Method::TrBdf2 => "diffsol TR-BDF2".into(),
        }
    }
}

/// What a run produced.
pub struct Run {
    /// Outputs, one state vector per output time, concatenated.
    pub out: Vec<f64>,
    pub rhs: usize,
    pub steps: usize,
    /// Mean wall time per run (s).
    pub seconds: f64,
}

/// Run `method` at `rtol` (atol = `atol_per_typical * typical_i`), repeated until 0.3 s of
/// wall time have passed (at least 3 runs), and report the last run and the mean time.
pub fn measure<S: OdeSystem>(
    sc: &Scenario<S>,
    method: Method,
    rtol: f64,
    atol_per_typical: f64,
) -> Result<Run, String> {
    let atol: Vec<f64> = sc.typical.iter().map(|s| atol_per_typical * s).collect();
    let start = Instant::now();
    let mut n = 0;
    loop {
        sc.sys.calls.set(0);
        let (out, steps) = match method {
            Method::Ours(s) => ours(sc, s, rtol, &atol)?,
            m => diffsol_run(sc, m, rtol, &atol)?,
        };
        n += 1;
        let elapsed = start.elapsed().as_secs_f64();
        if n >= 3 && elapsed > 0.3 {
            return Ok(Run {
                out,
                rhs: sc.sys.calls.get(),
                steps,
                seconds: elapsed / n as f64,
            });
        }
    }
}

fn ours<S: OdeSystem>(
    sc: &Scenario<S>,
    solver: Solver,
    rtol: f64,
    atol: &[f64],
) -> Result<(Vec<f64>, usize), String> {
    let mut out = Vec::with_capacity(sc.t_out.len() * sc.y0.len());
    let problem = Problem::new(0.0, &sc.y0, &sc.t_out).with_breakpoints(&sc.breakpoints);
    let st = Integrator::new(solver, rtol, Atol::PerState(atol.to_vec()))
        .with_max_step(sc.max_step)
        .run(&sc.sys, &problem, &mut Workspace::new(sc.y0.len()), |s| {
            out.extend_from_slice(s.y);
            Control::Continue
        })
        .map_err(|e| e.to_string())?;
    Ok((out, st.accepted + st.rejected))
}

/// Forward-difference Jacobian-vector product with a per-state relative perturbation
/// (the same rule as odeint's Rosenbrock Jacobian), reusing f(t, x) while x and t repeat.
struct JacVec<'a, S> {
    sc: &'a Scenario<S>,
    cache: RefCell<(f64, Vec<f64>, Vec<f64>, Vec<f64>)>,
}

impl<S: OdeSystem> JacVec<'_, S> {
    fn apply(&self, x: &[f64], t: f64, v: &[f64], y: &mut [f64]) {
        let mut c = self.cache.borrow_mut();
        let (t_c, x_c, f_c, scratch) = &mut *c;
        if *t_c != t || x_c.as_slice() != x {
            *t_c = t;
            x_c.copy_from_slice(x);
            self.sc.sys.rhs(t, x, f_c);
        }
        let mut eps = f64::INFINITY;
        for j in 0..x.len() {
            if v[j] != 0.0 {
                let step = f64::EPSILON.sqrt() * x[j].abs().max(self.sc.typical[j] * 1e-3);
                eps = eps.min(step / v[j].abs());
            }
        }
        if !eps.is_finite() {
            y.fill(0.0);
            return;
        }
        for j in 0..x.len() {
            scratch[j] = x[j] + eps * v[j];
        }
        self.sc.sys.rhs(t, scratch, y);
        for j in 0..x.len() {
            y[j] = (y[j] - f_c[j]) / eps;
        }
    }
}

fn diffsol_run<S: OdeSystem>(
    sc: &Scenario<S>,
    method: Method,
    rtol: f64,
    atol: &[f64],
) -> Result<(Vec<f64>, usize), String> {
    let n = sc.y0.len();
    let jv = JacVec {
        sc,
        cache: RefCell::new((f64::NAN, vec![0.0; n], vec![0.0; n], vec![0.0; n])),
    };
    let problem = OdeBuilder::<NalgebraMat<f64>>::new()
        .rtol(rtol)
        .atol(atol.iter().copied())
        .h0(1e-5)
        .rhs_implicit(
            |x: &[f64], _p: &[f64], t: f64, y: &mut [f64]| sc.sys.rhs(t, x, y),
            |x: &[f64], _p: &[f64], t: f64, v: &[f64], y: &mut [f64]| jv.apply(x, t, v, y),
        )
        .init(
            |_p: &[f64], _t: f64, y: &mut [f64]| y.copy_from_slice(&sc.y0),
            n,
        )
        .build()
        .map_err(|e| e.to_string())?;
    let err = |e: diffsol::DiffsolError| e.to_string();
    match method {
        Method::Bdf => step_through(sc, problem.bdf::<NalgebraLU<f64>>().map_err(err)?),
        Method::Esdirk34 => step_through(sc, problem.esdirk34::<NalgebraLU<f64>>().map_err(err)?),
        Method::TrBdf2 => step_through(sc, problem.tr_bdf2::<NalgebraLU<f64>>().map_err(err)?),
        Method::Ours(_) => unreachable!("odeint runs are not diffsol runs"),
    }
}

/// Step a diffsol solver to each breakpoint and the end, interpolating the output times.
fn step_through<'a, S, M, Eqn>(sc: &Scenario<S>, mut solver: M) -> Result<(Vec<f64>, usize), String>
where
    Eqn: diffsol::OdeEquations<T = f64> + 'a,
    M: OdeSolverMethod<'a, Eqn>,
{
    let err = |e: diffsol::DiffsolError| e.to_string();
    let mut out = Vec::with_capacity(sc.t_out.len() * sc.y0.len());
    let mut y = solver.state().y.clone();
    let mut next = 0;
    while next < sc.t_out.len() && sc.t_out[next] <= 0.0 {
        out.extend_from_slice(&sc.y0);
        next += 1;
    }
    let t_end = sc.t_out[sc.t_out.len() - 1];
    let stops = sc.breakpoints.iter().copied().chain(std::iter::once(t_end));
    for stop in stops {
        solver.set_stop_time(stop).map_err(err)?;
        loop {
            let reason = solver.step().map_err(err)?;
            let t = solver.state().t;
            while next < sc.t_out.len() && sc.t_out[next] <= t {
                solver
                    .interpolate_inplace(sc.t_out[next], &mut y)
                    .map_err(err)?;
                out.extend((0..sc.y0.len()).map(|i| y.get_index(i)));
                next += 1;
            }
            if matches!(reason, OdeSolverStopReason::TstopReached) {
                break;
            }
        }
    }
    let st = solver.get_statistics();
    Ok((out, st.number_of_steps + st.number_of_error_test_failures))
}
