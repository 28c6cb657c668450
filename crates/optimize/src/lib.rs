//! Numerical optimisation: bounded nonlinear least squares (Levenberg-Marquardt) with
//! parameter standard errors, used by the free-decay fit, strut identification and model
//! discovery; and the Analytic Hierarchy Process weights of section 4.3.4. Pattern search,
//! SQP and GA for AFS/HPS design (Chapters 4, 6) belong here too.

pub mod ahp;
pub mod least_squares;

pub use least_squares::{fit, FitOptions, FitResult, LeastSquaresError, Problem};
