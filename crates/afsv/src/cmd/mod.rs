//! One module per subcommand group. Each has a clap `Args` (or `Subcommand`) type and a
//! `run` function returning [`CmdResult`].

pub mod args;
pub mod batch;
pub mod check;
pub mod described;
pub mod discover;
pub mod evaluate;
pub mod hps;
pub mod hps_thermal;
pub mod layouts;
pub mod measures;
pub mod optimize;
pub mod params;
pub mod roll;
pub mod study;
pub mod terrain;
pub mod tire;
pub mod vehicle;
pub mod yaw;

/// Result of a subcommand: errors are printed as one line by `main`.
pub type CmdResult = Result<(), Box<dyn std::error::Error>>;

/// Write a `--plot` figure (built by `afsv_design::figures`) to `path`, marked as afsv's.
pub fn write_chart(path: &std::path::Path, chart: &afsv_plot::Chart) -> CmdResult {
    chart.write(path)?;
    afsv::output::mark_svg(path)?;
    Ok(())
}
