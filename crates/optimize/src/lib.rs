//! Numerical optimisation: bounded nonlinear least squares (Levenberg-Marquardt) with
//! parameter standard errors, used by the free-decay fit, strut identification and model
//! discovery; the Analytic Hierarchy Process weights of section 4.3.4; and the design
//! optimisers of Chapters 4 and 6, generic over a [`ConstrainedProblem`]: Latin hypercube
//! sampling ([`lhs`]), generalized pattern search ([`pattern_search`]), SQP from a given
//! point with finite-difference gradients ([`sqp`]), a real-coded genetic algorithm with
//! Deb's feasibility rules ([`ga`]), the noise level of an objective ([`noise`]), and
//! parallel batch evaluation ([`batch`]). Every random choice comes from a seeded stream
//! ([`rng`]) and every solver state can be saved and resumed with identical results.

pub mod ahp;
pub mod batch;
pub mod ga;
pub mod least_squares;
pub mod lhs;
pub mod noise;
pub mod pattern_search;
pub mod problem;
pub mod rng;
pub mod sqp;

pub use batch::{evaluate_batch, Progress, Silent};
pub use least_squares::{fit, FitOptions, FitResult, LeastSquaresError, Problem};
pub use problem::{Bounds, ConstrainedProblem, Evaluation, OptimizeError, BARRIER};
