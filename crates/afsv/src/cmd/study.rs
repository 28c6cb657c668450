//! `afsv study`: design studies on the 3-D vehicle. `hps-sensitivity` is Table 6.4 (section
//! 6.5.1): A_hc, A_v and A_b of the front-axle HPS one at a time, with a_wz unloaded and
//! loaded (D1), SP-DRT (D2) and omega_z (D3) over common terrain seeds
//! (`afsv_design::hps_sensitivity`). `speed-sweep` is D4 (section 6.5.2, Fig 6.16): the
//! ride of one HPS design from 10 to 30 km/h against the 8 h health guidance caution zone
//! (`afsv_design::hps_speed_sweep`). `layouts` compares suspension layouts
//! (`afsv_design::layouts`, in `cmd/layouts.rs`).

use super::CmdResult;
use afsv::output::{OutputGuard, OutputKind};
use afsv_design::hps_sensitivity::{StudyScope, MAX_SEEDS};
use afsv_design::study_strut::study_vehicle;
use afsv_design::value_lists::list;
use std::path::PathBuf;

/// `afsv study` subcommands.
#[derive(clap::Subcommand)]
pub enum Command {
    /// Table 6.4: sensitivity of the ride, roll and yaw measures to A_hc, A_v and A_b.
    HpsSensitivity(HpsArgs),
    /// D4 (Fig 6.16): a_wz, unweighted RMS and HPS travel of one HPS design over forward
    /// speeds, both loads, and the speed at which a_wz crosses the 8 h caution zone.
    SpeedSweep(SweepArgs),
    /// Suspension layouts of one vehicle (rigid, front HPS, ...) through D1-D4 on common
    /// seeds, on the frame and at the seat: a_wz, SEAT, strut travel, SP-DRT, omega_z and
    /// the speed at which a_wz crosses the 8 h caution zone, differences inside the seed
    /// spread marked.
    Layouts(super::layouts::LayoutArgs),
}

/// Options of `afsv study speed-sweep`.
#[derive(clap::Args)]
pub struct SweepArgs {
    /// The strut: `nominal` (the description's front-axle strut; Table 6.3 for the
    /// prototype) or a strut parameter file (`afsv params dump strut`).
    #[arg(long, default_value = "nominal")]
    pub hps: String,
    #[arg(long, help = super::described::HELP)]
    pub vehicle: Option<PathBuf>,
    /// The Eq 6.19 design variables replacing the strut's: `A_HC,A_V,A_B` with A_hc in m²
    /// and A_v, A_b in mm² (as `afsv optimize hps` prints them), e.g. `0.0494,6.28,16.0`.
    #[arg(long)]
    pub design: Option<String>,
    /// Speeds (km/h), comma separated, strictly ascending, 5 to 100; D4: 10 to 30.
    #[arg(long, default_value = "10,15,20,25,30")]
    pub speeds: String,
    /// Terrain seeds per point, 1 to 100 (every point runs on the same seeds).
    #[arg(long, default_value_t = 10)]
    pub seeds: usize,
    /// First terrain seed.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Write an SVG of a_wz against the speed, one line per load, with the caution-zone bound.
    #[arg(long)]
    pub plot: Option<PathBuf>,
    /// Replace an existing plot file that afsv did not write.
    #[arg(long)]
    pub force: bool,
    #[command(flatten)]
    pub output: super::args::JsonOutput,
}

/// Options of `afsv study hps-sensitivity`.
#[derive(clap::Args)]
pub struct HpsArgs {
    /// Terrain seeds per measure, 1 to 100 (each variant runs on the same seeds). About
    /// 13 x (3 N + 1) vehicle runs with the HPS: minutes for 10 seeds on 2 cores.
    #[arg(long, default_value_t = 10)]
    pub seeds: usize,
    /// First terrain seed.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    #[arg(long, help = super::described::HELP)]
    pub vehicle: Option<PathBuf>,
    /// Changes in percent, comma separated (Table 6.4: -30,-15,15,30).
    #[arg(long, default_value = "-30,-15,15,30", allow_hyphen_values = true)]
    pub changes: String,
    /// Skip the D2 roll runs (SP-DRT), the costliest part.
    #[arg(long)]
    pub no_roll: bool,
    /// Skip the D3 yaw runs (omega_z).
    #[arg(long)]
    pub no_yaw: bool,
    /// Write an SVG of a_wz against the change, one line per variable and load.
    #[arg(long)]
    pub plot: Option<PathBuf>,
    /// Replace an existing plot file that afsv did not write.
    #[arg(long)]
    pub force: bool,
    #[command(flatten)]
    pub output: super::args::JsonOutput,
}

/// Run a study.
pub fn run(c: Command) -> CmdResult {
    match c {
        Command::HpsSensitivity(a) => hps(a),
        Command::SpeedSweep(a) => speed_sweep(a),
        Command::Layouts(a) => super::layouts::run(a),
    }
}

/// The vehicle of `--vehicle`, `--hps` and `--design` (`afsv_design::study_strut`), its
/// input files declared to `guard`.
fn sweep_vehicle(
    a: &SweepArgs,
    guard: &mut OutputGuard,
) -> Result<vehicle_3d::VehicleParams, String> {
    super::described::declare(guard, a.vehicle.as_deref())?;
    if a.hps != "nominal" {
        guard.input("--hps", std::path::Path::new(&a.hps))?;
    }
    study_vehicle(a.vehicle.as_deref(), &a.hps, a.design.as_deref())
}

fn speed_sweep(a: SweepArgs) -> CmdResult {
    use afsv_design::hps_speed_sweep::{hps_speed_sweep, MAX_SEEDS, MAX_SPEEDS};
    let seeds = super::args::seed_list(a.seed, a.seeds, MAX_SEEDS)?;
    let speeds = list("--speeds", &a.speeds, MAX_SPEEDS)?;
    let mut guard = OutputGuard::new(a.force);
    let p = sweep_vehicle(&a, &mut guard)?;
    guard.output_if("--plot", a.plot.as_deref(), OutputKind::Svg)?;
    let runs = afsv_design::hps_speed_sweep::speed_sweep_runs(speeds.len(), seeds.len());
    let progress = afsv::progress::Progress::new("afsv study speed-sweep", "runs", Some(runs));
    let s = hps_speed_sweep(&p, &speeds, &seeds, &|d| progress.step(d))?;
    progress.finish();
    if let Some(path) = &a.plot {
        super::write_chart(path, &afsv_design::figures::studies::speed_sweep(&s))?;
    }
    let text = || afsv_design::report::speed_sweep::text(&s);
    Ok(afsv::output::print_json_or_text(a.output.json, &s, text)?)
}

fn hps(a: HpsArgs) -> CmdResult {
    let seeds = super::args::seed_list(a.seed, a.seeds, MAX_SEEDS)?;
    let changes = afsv_design::value_lists::changes(&a.changes)?;
    let mut guard = OutputGuard::new(a.force);
    super::described::declare(&mut guard, a.vehicle.as_deref())?;
    guard.output_if("--plot", a.plot.as_deref(), OutputKind::Svg)?;
    let p = super::described::with_front_strut(a.vehicle.as_deref(), "study hps-sensitivity")?;
    let scope = StudyScope {
        roll: !a.no_roll,
        yaw: !a.no_yaw,
    };
    let runs = afsv_design::hps_sensitivity::sensitivity_runs(changes.len(), seeds.len(), scope);
    let progress = afsv::progress::Progress::new("afsv study hps-sensitivity", "runs", Some(runs));
    let s = afsv_design::hps_sensitivity(&p, &changes, &seeds, scope, &|d| progress.step(d))?;
    progress.finish();
    if let Some(path) = &a.plot {
        super::write_chart(path, &afsv_design::figures::studies::hps_sensitivity(&s))?;
    }
    let text = || afsv_design::report::hps_sensitivity::text(&s);
    Ok(afsv::output::print_json_or_text(a.output.json, &s, text)?)
}
