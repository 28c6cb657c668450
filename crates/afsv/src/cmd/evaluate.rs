//! `afsv evaluate [VEHICLE]`: the main job, on the built-in default vehicle or on a vehicle
//! description (`VEHICLE` or `--vehicle`, docs/vehicles.md).
//!
//! The default vehicle is the 35 t articulated dump truck of the dissertation (Table 3.1
//! steering and yaw-plane parameters, Table 6.1 3-D vehicle, Table 6.3 front-axle strut) on
//! the nominal off-road terrain (ISO 8608 class E, piecewise coherence m_c = 0.3 cycles/m,
//! sections 2.2.2 and 6.2.3). First come the three design measures of Chapter 6 (ride, roll,
//! yaw of the 3-D vehicle with a rigid front axle and with the description's front-axle
//! strut, over `--seeds` terrain seeds, `afsv_design::design_3d`), then the yaw-plane
//! steering measures of Chapter 3 (the description's yaw-plane data and steering), the
//! strut and the terrain.
//!
//! The assessment and its report are the library's (`afsv_design::evaluate`,
//! `afsv_design::report::evaluate`, shared with the Python package's `afsv.evaluate()`).
//! On a terminal it prints a readable summary; with `--json`, or when stdout is a pipe or a
//! file, it prints the same assessment as JSON. The toolkit's own self-checks (ISO 2631-1
//! weighting table, terrain synthesis fidelity) are `afsv check`.

use super::CmdResult;
use afsv_design::evaluate::{assess, check_speed};
use afsv_design::report::evaluate::{to_json, to_text};
use std::path::PathBuf;

/// Options of `afsv evaluate`.
#[derive(clap::Args)]
pub struct Args {
    /// Seed of the default terrain synthesis, and the first of the 3-D vehicle's terrain
    /// seeds.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Terrain seeds per rough-terrain measure of the 3-D vehicle (1 to 100).
    #[arg(long, default_value_t = 10, value_parser = clap::value_parser!(u64).range(1..=afsv_design::design_3d::MAX_SEEDS))]
    pub seeds: u64,
    /// Forward speed for the yaw-plane measures (km/h; section 3.3 uses 50).
    #[arg(long, default_value_t = 50.0, allow_hyphen_values = true, value_parser = super::args::positive_f64)]
    pub speed_kmh: f64,
    #[arg(long, help = super::described::HELP)]
    pub vehicle: Option<PathBuf>,
    /// The vehicle to assess, as `--vehicle` takes it (`afsv evaluate my-truck.toml`).
    #[arg(value_name = "VEHICLE", conflicts_with = "vehicle")]
    pub vehicle_positional: Option<PathBuf>,
    #[arg(long, help = super::vehicle::PAPER_FORM_HELP)]
    pub paper_form: bool,
    /// Print JSON even on a terminal (JSON is the default when stdout is not a terminal).
    #[arg(long)]
    pub json: bool,
}

/// Run the assessment and print it (text on a terminal, JSON otherwise).
pub fn run(args: Args) -> CmdResult {
    check_speed(args.speed_kmh)?;
    let vehicle = args.vehicle.or(args.vehicle_positional);
    let v = super::described::articulated(vehicle.as_deref())?;
    let seeds = afsv_design::fan_out::seed_range(args.seed, args.seeds);
    let runs = afsv_design::design_3d::assess_runs(v.front_strut.is_some(), seeds.len());
    let progress = afsv::progress::Progress::new("afsv evaluate", "vehicle runs", Some(runs));
    let a = assess(
        &v,
        args.speed_kmh,
        args.seed,
        &seeds,
        args.paper_form,
        &|detail| progress.step(detail),
    )?;
    progress.finish();
    afsv::output::print_json_or_text(args.json, &to_json(&a), || to_text(&a))?;
    Ok(())
}
