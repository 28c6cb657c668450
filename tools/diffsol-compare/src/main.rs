//! Work-precision comparison of odeint with diffsol (BDF, ESDIRK34, TR-BDF2) on the strut at
//! 8 Hz and 0.1 Hz and on the yaw-plane pulse. See README.md and docs/numerics.md.

mod runs;
mod scenario;

use odeint::{OdeSystem, Solver};
use runs::{measure, Method, Run};
use scenario::{strut, yaw, Scenario, YawParts};

/// Largest output error over all output times and states, per typical magnitude.
fn max_error(run: &Run, reference: &Run, typical: &[f64]) -> f64 {
    let n = typical.len();
    if run.out.len() != reference.out.len() {
        return f64::INFINITY;
    }
    run.out
        .iter()
        .zip(&reference.out)
        .enumerate()
        .map(|(k, (a, b))| (a - b).abs() / typical[k % n])
        .fold(0.0, f64::max)
}

fn compare<S: OdeSystem>(sc: &Scenario<S>) {
    let (rtol0, atol0) = sc.default_tol;
    let ratio = atol0 / rtol0;
    let reference =
        measure(sc, Method::Ours(Solver::Dopri5), 1e-12, 1e-12 * ratio).expect("reference run");
    println!("\n## {} ({} states)\n", sc.name, sc.y0.len());
    println!("| solver | rtol | max error / typical | RHS calls | steps | time per run |");
    println!("|---|---|---|---|---|---|");
    let ours_tols = [1e-4, 1e-5, 1e-6, 1e-7, 1e-8];
    let diffsol_tols = [1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8];
    let plan: Vec<(Method, &[f64])> = vec![
        (Method::Ours(Solver::Dopri5), &ours_tols),
        (Method::Ours(Solver::Rosenbrock23), &ours_tols),
        (Method::Bdf, &diffsol_tols),
        (Method::Esdirk34, &diffsol_tols),
        (Method::TrBdf2, &diffsol_tols),
    ];
    for (method, tols) in plan {
        for &rtol in tols {
            let mark = if method == Method::Ours(sc.auto) && rtol == rtol0 {
                " (default)"
            } else {
                ""
            };
            match measure(sc, method, rtol, rtol * ratio) {
                Ok(run) => println!(
                    "| {}{mark} | {rtol:.0e} | {:.1e} | {} | {} | {:.3} ms |",
                    method.name(),
                    max_error(&run, &reference, &sc.typical),
                    run.rhs,
                    run.steps,
                    run.seconds * 1e3
                ),
                Err(e) => println!("| {} | {rtol:.0e} | failed: {e} | | | |", method.name()),
            }
        }
    }
}

fn main() {
    compare(&strut("strut 8 Hz, 7.5 mm, 10 cycles", 8.0, 0.0075, 10.0));
    compare(&strut("strut 0.1 Hz, 25 mm, 1 cycle", 0.1, 0.025, 1.0));
    let parts = YawParts::pulse();
    compare(&yaw(&parts));
}
