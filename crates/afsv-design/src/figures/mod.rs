//! The figures of the commands' `--plot` options as [`afsv_plot::Chart`] values: pure
//! functions of a library result, like the reports ([`crate::report`]) they draw beside.
//! A figure decides its curves, units, scales and conditions line; it runs no model and
//! writes nothing (the caller writes the chart with [`afsv_plot::Chart::write`] under its
//! output guard).
//!
//! - [`vehicle`]: `afsv vehicle ride|roll|yaw|path-change`;
//! - [`layouts`]: `afsv study layouts`;
//! - [`strut`]: the loops of `afsv hps harmonic`;
//! - [`tire`]: the force curves of `afsv tire sweep`;
//! - [`studies`]: `afsv roll study`, `afsv study speed-sweep|hps-sensitivity` and the
//!   Fig 4.9 responses of `afsv optimize afs`.

pub mod layouts;
pub mod strut;
pub mod studies;
pub mod tire;
pub mod vehicle;

#[cfg(test)]
mod tests;
