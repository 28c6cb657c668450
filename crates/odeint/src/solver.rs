//! The one solver value every model and the CLI name.

use crate::OdeSystem;
use serde::{Deserialize, Serialize};

/// Integration method of a run.
///
/// Serialised in snake_case: `"dopri5"`, `"tsit5"`, `"rosenbrock23"`, `"ros34pw2"`,
/// `"ark436"`, `"auto"`,
/// `{"rk4": {"step": 2e-4}}`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Solver {
    /// Adaptive explicit Dormand-Prince 5(4) with 4th-order dense output (Hairer, Nørsett &
    /// Wanner, *Solving ODEs I*, II.5, code DOPRI5). For non-stiff models.
    Dopri5,
    /// Adaptive explicit Tsitouras 5(4) (Comput. Math. Appl. 62, 2011) with its 4th-order
    /// continuous extension: the same cost per step as [`Solver::Dopri5`] (7 stages, FSAL,
    /// 6 right-hand sides per step), smaller fifth-order error coefficients. For
    /// non-stiff models; outputs, breakpoints and events work as with Dormand-Prince.
    Tsit5,
    /// Adaptive linearly implicit Rosenbrock-W 2(3) (Shampine & Reichelt 1997, the MATLAB
    /// `ode23s` scheme), L-stable, finite-difference Jacobian every step. For stiff models
    /// with few states.
    Rosenbrock23,
    /// Adaptive Rosenbrock-W 3(2) of Rang & Angermann (ROS34PW2), linearly implicit in the
    /// model's stiff blocks only ([`OdeSystem::stiff_blocks`]) and explicit in every other
    /// state; of order 3 whatever coupling the blocks leave out. For models with a few stiff
    /// states beside many non-stiff ones: the suspended vehicles' HPS struts.
    Ros34pw2,
    /// Adaptive additive Runge-Kutta ARK4(3)6L\[2\]SA of Kennedy & Carpenter (2003), split
    /// by components: explicit (order 4) in every state outside the model's stiff blocks,
    /// singly diagonally implicit (L-stable, stiffly accurate) in the block states, whose
    /// stages are solved by Newton's method on the model's own block rates
    /// ([`OdeSystem::block_rhs`]). For models whose stiffness lives in a few states and whose
    /// other states move smoothly: the suspended vehicles' HPS struts.
    Ark436,
    /// Classical fixed-step Runge-Kutta 4: every interval between output times and
    /// breakpoints is split into `ceil(span / step)` equal steps, so outputs are hit exactly.
    Rk4 {
        /// Largest step (s).
        step: f64,
    },
    /// Let the model choose: [`Solver::Rosenbrock23`] when [`OdeSystem::is_stiff`] answers
    /// `true`; [`Solver::Ark436`] on a model with stiff blocks ([`OdeSystem::stiff_blocks`]:
    /// the suspended vehicles' struts); otherwise [`Solver::Dopri5`] (docs/numerics.md,
    /// "Choosing the method").
    Auto,
}

impl Solver {
    /// The concrete method of a run of `sys` ([`Solver::Auto`] asks
    /// [`OdeSystem::is_stiff`] and [`OdeSystem::stiff_blocks`]; the others are returned as
    /// they are).
    pub fn resolve<S: OdeSystem + ?Sized>(self, sys: &S) -> Solver {
        match self {
            Solver::Auto if sys.is_stiff() => Solver::Rosenbrock23,
            Solver::Auto if !sys.stiff_blocks().is_empty() => Solver::Ark436,
            Solver::Auto => Solver::Dopri5,
            s => s,
        }
    }

    /// Short lower-case name (`dopri5`, `tsit5`, `rosenbrock23`, `ros34pw2`, `ark436`, `rk4`,
    /// `auto`) for reports.
    pub fn name(&self) -> &'static str {
        match self {
            Solver::Dopri5 => "dopri5",
            Solver::Tsit5 => "tsit5",
            Solver::Rosenbrock23 => "rosenbrock23",
            Solver::Ros34pw2 => "ros34pw2",
            Solver::Ark436 => "ark436",
            Solver::Rk4 { .. } => "rk4",
            Solver::Auto => "auto",
        }
    }
}
