//! `afsv study layouts`: suspension layouts of one vehicle through D1-D4 on common seeds,
//! on the frame and at the seat (`afsv_design::layouts`, docs/layouts.md); the layouts by
//! name are `afsv_design::layout_names`, the table `afsv_design::report::layouts`.

use super::CmdResult;
use afsv::output::{OutputGuard, OutputKind};
use afsv_design::layout_names::{build_layouts, seat_of};
use afsv_design::layouts::{layout_runs, layouts, LayoutOptions};
use afsv_design::report::layouts::text;
use std::path::PathBuf;
use vehicle_3d::Load;

/// Options of `afsv study layouts`.
#[derive(clap::Args)]
pub struct LayoutArgs {
    #[arg(long, help = super::described::HELP)]
    pub vehicle: Option<PathBuf>,
    /// Layouts, comma separated, the first is the baseline: rigid (every axle rigid),
    /// front-hps (the description's front-axle strut, or its candidate strut),
    /// front-rear-hps (and the description's rear strut, or the front strut scaled for the
    /// rear static load), front-roll and front-rear-roll (those with the front struts
    /// roll-interconnected), front-rear-pitch (front-rear-hps with each side's front and
    /// rear struts pitch-interconnected; docs/layouts.md).
    #[arg(
        long,
        default_value = "rigid,front-hps,front-rear-hps,front-roll,front-rear-roll,front-rear-pitch"
    )]
    pub layouts: String,
    /// The cab and seat of the seat rows: `generic` (docs/layouts.md), `off` (frame rows
    /// only), or `described` (the description's [cab.body] and [seat]). Default: the
    /// description's when it has them, else generic.
    #[arg(long)]
    pub seat: Option<String>,
    /// Speed of the ride the table reports (km/h), 5 to 100; D1 is 20.
    #[arg(long, default_value_t = 20.0)]
    pub speed_kmh: f64,
    /// D4 speeds (km/h), comma separated, strictly ascending, 5 to 100.
    #[arg(long, default_value = "10,15,20,25,30")]
    pub speeds: String,
    /// Load case of the rides (D2 and D3 are loaded by definition).
    #[arg(long, default_value = "loaded")]
    pub load: Load,
    /// Terrain seeds, 1 to 100 (every layout runs on the same seeds).
    #[arg(long, default_value_t = 10)]
    pub seeds: usize,
    /// First terrain seed.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Write an SVG of the operator's a_wz against the speed (D4), one line per row,
    /// with the caution-zone bound.
    #[arg(long)]
    pub plot: Option<PathBuf>,
    /// Replace an existing plot file that afsv did not write.
    #[arg(long)]
    pub force: bool,
    #[command(flatten)]
    pub output: super::args::JsonOutput,
}

/// Run `afsv study layouts`.
pub fn run(a: LayoutArgs) -> CmdResult {
    use afsv_design::layouts::MAX_SEEDS;
    let seeds = super::args::seed_list(a.seed, a.seeds, MAX_SEEDS)?;
    let speeds = afsv_design::value_lists::list("--speeds", &a.speeds, 50)?;
    let mut guard = OutputGuard::new(a.force);
    super::described::declare(&mut guard, a.vehicle.as_deref())?;
    guard.output_if("--plot", a.plot.as_deref(), OutputKind::Svg)?;
    let v = super::described::articulated(a.vehicle.as_deref())?;
    let list = build_layouts(&v, &a.layouts)?;
    let options = LayoutOptions {
        load: a.load,
        ride_speed_kmh: a.speed_kmh,
        sweep_speeds_kmh: speeds,
        seeds,
        seat: seat_of(&v, a.seat.as_deref())?,
    };
    let runs = layout_runs(list.len(), &options);
    let progress = afsv::progress::Progress::new("afsv study layouts", "runs", Some(runs));
    let s = layouts(&list, &options, &|d| progress.step(d))?;
    progress.finish();
    if let Some(path) = &a.plot {
        super::write_chart(path, &afsv_design::figures::layouts::layouts(&s))?;
    }
    Ok(afsv::output::print_json_or_text(a.output.json, &s, || {
        text(&s)
    })?)
}
