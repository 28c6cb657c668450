//! Numerical optimisation. Now: bounded nonlinear least squares (Levenberg-Marquardt) with
//! parameter standard errors, used by the free-decay fit, strut identification and model
//! discovery. Later: AHP weights, pattern search, SQP and GA for AFS/HPS design (Chapters 4, 6).

pub mod least_squares;

pub use least_squares::{fit, FitOptions, FitResult, LeastSquaresError, Problem};
