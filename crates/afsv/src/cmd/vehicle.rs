//! `afsv vehicle`: the integrated 3-D articulated vehicle of Chapter 6 (crate `vehicle-3d`):
//! the design runs of section 6.4 over terrain seeds with their measures as mean ± SD
//! (`ride` D1, `roll` D2, `yaw` D3), the three measures of one configuration (`measures`),
//! the V3 path change with the path-following driver (`path-change`), and one recorded run
//! (`simulate`) in the record format of docs/records.md. Parses, calls, prints.

mod measures;
mod path_change;
mod ride;
mod simulate;

use super::{args, CmdResult};
use afsv::output::{OutputGuard, OutputKind};
use afsv::progress::Progress;
use afsv_design::design_3d::{roll_run, yaw_run};
use afsv_design::figures;
use afsv_design::report::vehicle::{
    axle_name, link_note, ride_report, roll_report, yaw_report, Ground, RidePsd,
};
use afsv_design::vehicle_case::{self, parse_terrain, CaseSource, TerrainChoice as TerrainArg};
use afsv_design::vehicle_options::{
    duration_s, offset_m, ramp_rate, seed_count, speed_kmh, steer_peak,
};
use measures::measures_cmd;
use path_change::{path_change_cmd, PathChangeFiles};
use serde_json::{json, Value};
use simulate::simulate_cmd;
use std::path::{Path, PathBuf};
use vehicle_3d::cab_ride::SeatRideMeasures;
use vehicle_3d::interconnect::Link;
use vehicle_3d::scenarios::{
    RideMeasures, RideSpec, RollMeasures, RollSpec, TerrainSpec, YawMeasures, YawSpec,
};
use vehicle_3d::{FrontAxle, Load, RunRecord, VehicleParams};

/// Help of `--paper-form` (the vehicle commands and `afsv evaluate`).
pub(crate) const PAPER_FORM_HELP: &str = "Use the printed Eq 3.13 yaw inertias (m L² counted twice) instead of the energy-consistent equations, to reproduce the dissertation's lower yaw frequency; for comparison with the paper, never for design (docs/vehicle-3d.md)";

/// The vehicle and where it runs, shared by every subcommand.
#[derive(clap::Args, Debug)]
pub struct CaseArgs {
    /// Load case (Table 6.1): `loaded` (with the payload) or `unloaded`.
    #[arg(long, default_value = "loaded")]
    pub load: Load,
    /// Target speed of the drive (km/h), in (0, 80]. Default: the scenario's (ride 20,
    /// roll and yaw 50, simulate 20).
    #[arg(long, allow_hyphen_values = true, value_parser = speed_kmh)]
    pub speed_kmh: Option<f64>,
    /// Ground: `smooth` (or `flat`), or the two-track terrain `class:C,mc:0.3[,seed:N]`
    /// (ISO 8608 class A-H, coherence cut-off m_c in cycles/m, Eqs 6.4-6.5). Default:
    /// `class:E,mc:0.3` for ride and roll, smooth for yaw and simulate.
    #[arg(long, allow_hyphen_values = true, value_parser = parse_terrain)]
    pub terrain: Option<TerrainArg>,
    /// Front axle: `off` (rigid), `nominal` (the strut the vehicle description gives the
    /// front axle: Table 6.3 for the prototype) or a strut parameter file (JSON, as written
    /// by `afsv params dump strut`). Default: as the description says (the prototype:
    /// rigid).
    #[arg(long)]
    pub hps: Option<String>,
    #[arg(long, help = super::described::HELP, conflicts_with = "params")]
    pub vehicle: Option<PathBuf>,
    /// The 3-D model's raw parameter set (JSON, `afsv params dump vehicle-3d`) instead of a
    /// description; its front axle is rigid unless `--hps` says otherwise.
    #[arg(long)]
    pub params: Option<PathBuf>,
    #[arg(long, help = PAPER_FORM_HELP)]
    pub paper_form: bool,
}

/// Seeds, output format and plot of the scenario subcommands.
#[derive(clap::Args, Debug)]
pub struct StudyArgs {
    /// Run the terrain seeds 1..=N (1 to 1000) and report mean ± SD (default 10 on a
    /// terrain).
    #[arg(long, value_parser = seed_count, conflicts_with = "seed")]
    pub seeds: Option<usize>,
    /// Run this one terrain seed.
    #[arg(long)]
    pub seed: Option<u64>,
    /// Print JSON even on a terminal (JSON is the default when stdout is not a terminal).
    #[arg(long)]
    pub json: bool,
    /// SVG plot of the run (the first seed's for roll and yaw, the seed-mean PSDs for ride).
    #[arg(long)]
    pub plot: Option<PathBuf>,
    /// Replace an existing plot afsv did not write.
    #[arg(long)]
    pub force: bool,
}

impl StudyArgs {
    /// `--json` and `--plot`, for [`print_linked`].
    fn shown(&self) -> (bool, Option<&Path>) {
        (self.json, self.plot.as_deref())
    }
}

/// `afsv vehicle` subcommands.
#[derive(clap::Subcommand, Debug)]
pub enum Command {
    /// D1 ride: straight run over the terrain after a 20 m run-in; a_wz (W_k, ISO 2631-1)
    /// and its 8 h health guidance caution zone verdict, unweighted RMS, HPS travel, the
    /// dominant vertical and pitch frequencies, as mean ± SD over the seeds.
    Ride {
        #[command(flatten)]
        case: CaseArgs,
        #[command(flatten)]
        study: StudyArgs,
        /// Length of the measured window after the run-in (m), 10 to 5000; D1: 100.
        #[arg(long, default_value_t = 100.0, allow_hyphen_values = true, value_parser = args::positive_f64)]
        length_m: f64,
        /// A measured road instead of synthesised terrain: a two-track CSV with columns
        /// x_m (uniformly spaced), left_m and right_m (other length units such as left_mm
        /// are converted on read; docs/records.md), or an ASAM OpenCRG ASCII file (`.crg`,
        /// straight reference line; read along plus and minus half the front track,
        /// docs/terrain-psd.md). One run; no seeds.
        #[arg(long, conflicts_with_all = ["terrain", "seeds", "seed"])]
        road: Option<PathBuf>,
        /// The operator's cab and seat (docs/layouts.md): `generic` adds the generic cab on
        /// mounts and suspension seat, `off` leaves out the description's; default: as the
        /// vehicle description says (the prototype has none). With one, ISO 2631-1 is also
        /// read on the cab floor and the seat pan, with SEAT (ISO 10326-1).
        #[arg(long, value_parser = ["generic", "off"])]
        seat: Option<String>,
    },
    /// D2 roll: ramp steer to the rear unit's absolute rollover; SP-DRT (RMS |a_y| over the
    /// sustained period of |LTR| = 1), the sustained period, rollover time, peak a_y.
    Roll {
        #[command(flatten)]
        case: CaseArgs,
        #[command(flatten)]
        study: StudyArgs,
        /// Steering-wheel rate of the ramp from t = 1 s (deg/s), 0.01 to 1000; D2: 5.
        #[arg(long, default_value_t = 5.0, allow_hyphen_values = true, value_parser = ramp_rate)]
        ramp_deg_s: f64,
        /// Longest run if the rear unit does not roll over (s), at most 600; D2: 45. The
        /// terrain is synthesised over the whole run's path, so another duration (or speed)
        /// reads another terrain under the same seed; at the default a seed's terrain is the
        /// one `afsv evaluate` runs.
        #[arg(long, default_value_t = vehicle_3d::scenarios::D2_DURATION_S, allow_hyphen_values = true, value_parser = duration_s)]
        duration: f64,
    },
    /// D3 yaw: a 0.2 s half-sine steering-wheel pulse at t = 1 s; omega_z and zeta of the
    /// single-DOF fit to the articulation's free decay, peak articulation.
    Yaw {
        #[command(flatten)]
        case: CaseArgs,
        #[command(flatten)]
        study: StudyArgs,
        /// Peak of the steering-wheel pulse (deg), at most 1000; D3 assumption: 30.
        #[arg(long, default_value_t = 30.0, allow_hyphen_values = true, value_parser = steer_peak)]
        pulse_deg: f64,
    },
    /// V3 path change (section 6.3, Fig 3.6(b)): the pure-pursuit driver of the yaw-plane
    /// model steers the front axle through a lateral offset over an 18 m gate after a 20 m
    /// approach; peaks of articulation, left-strut displacement, front-unit yaw rate and
    /// lateral acceleration, and the largest deviation from the course. Default speed: the
    /// Table 3.2 mean, 15.3 km/h loaded, 19.2 km/h unloaded; default ground smooth
    /// (`--terrain class:C` for the paved field course).
    PathChange {
        #[command(flatten)]
        case: CaseArgs,
        /// Terrain seed (with a terrain; default 1).
        #[arg(long)]
        seed: Option<u64>,
        /// Lateral offset of the course (m), positive to the right, at most 20 in magnitude.
        #[arg(long, default_value_t = 4.5, allow_hyphen_values = true, value_parser = offset_m)]
        offset_m: f64,
        /// Simulated time (s), at most 600.
        #[arg(long, default_value_t = 20.0, allow_hyphen_values = true, value_parser = duration_s)]
        duration: f64,
        #[command(flatten)]
        files: PathChangeFiles,
    },
    /// The three design measures of section 6.4 for one configuration (the code of `afsv
    /// evaluate`): D1 a_wz (W_k) with the 8 h HGCZ verdict and the strut travel d_s for
    /// `--load` at 20 km/h on class E, D2 SP-DRT and D3 omega_z / zeta (both loaded, 50
    /// km/h) with the front axle of `--hps` and the set of `--params`.
    Measures {
        /// Load case of the D1 ride (D2 and D3 are loaded by definition).
        #[arg(long, default_value = "loaded")]
        load: Load,
        /// Front axle: `off`, `nominal` or a strut parameter file (as for the other
        /// subcommands); default: as the description says.
        #[arg(long)]
        hps: Option<String>,
        #[arg(long, help = super::described::HELP, conflicts_with = "params")]
        vehicle: Option<PathBuf>,
        /// The 3-D model's raw parameter set (JSON, `afsv params dump vehicle-3d`).
        #[arg(long)]
        params: Option<PathBuf>,
        #[arg(long, help = PAPER_FORM_HELP)]
        paper_form: bool,
        /// Run the terrain seeds 1..=N (1 to 100; default 10).
        #[arg(long, conflicts_with = "seed")]
        seeds: Option<usize>,
        /// Run this one terrain seed.
        #[arg(long)]
        seed: Option<u64>,
        /// Print JSON even on a terminal (JSON is the default when stdout is not a terminal).
        #[arg(long)]
        json: bool,
    },
    /// One run into a record (CSV + JSON sidecar, docs/records.md, sign convention
    /// afsv-v1): the steering channels of a vehicle steering test plus the ride channels.
    Simulate {
        #[command(flatten)]
        case: CaseArgs,
        /// Terrain seed (with a terrain; default 1).
        #[arg(long)]
        seed: Option<u64>,
        /// Steering-wheel input: `pulse:DEG,DUR_S,START_S` (half sine),
        /// `ramp:DEG_PER_S,START_S[,LIMIT_DEG]` (held at LIMIT_DEG, default 1000) or `none`.
        #[arg(long, default_value = "none")]
        steer: String,
        /// Simulated time (s), at most 600.
        #[arg(long, default_value_t = 10.0, allow_hyphen_values = true, value_parser = duration_s)]
        duration: f64,
        /// Output sample interval (s).
        #[arg(long, default_value_t = 0.005, allow_hyphen_values = true, value_parser = args::positive_f64)]
        dt: f64,
        #[command(flatten)]
        output: simulate::RecordOutput,
    },
}

/// Run an `afsv vehicle` subcommand.
pub fn run(cmd: Command) -> CmdResult {
    match cmd {
        Command::Ride {
            case,
            study,
            length_m,
            road,
            seat,
        } => ride::ride_cmd(&case, &study, length_m, road.as_deref(), seat.as_deref()),
        Command::Roll {
            case,
            study,
            ramp_deg_s,
            duration,
        } => roll_cmd(&case, &study, ramp_deg_s, duration),
        Command::Yaw {
            case,
            study,
            pulse_deg,
        } => yaw_cmd(&case, &study, pulse_deg),
        Command::Simulate {
            case,
            seed,
            steer,
            duration,
            dt,
            output,
        } => simulate_cmd(&case, seed, &steer, duration, dt, &output),
        Command::PathChange {
            case,
            seed,
            offset_m,
            duration,
            files,
        } => path_change_cmd(&case, seed, offset_m, duration, &files),
        Command::Measures {
            load,
            hps,
            vehicle,
            params,
            paper_form,
            seeds,
            seed,
            json,
        } => {
            let case = CaseArgs {
                load,
                speed_kmh: None,
                terrain: None,
                hps,
                vehicle,
                params,
                paper_form,
            };
            measures_cmd(&case, seeds, seed, json)
        }
    }
}

impl CaseArgs {
    /// Where the vehicle comes from, as `afsv_design::vehicle_case` takes it.
    fn source(&self) -> CaseSource<'_> {
        CaseSource {
            params: self.params.as_deref(),
            vehicle: self.vehicle.as_deref(),
            hps: self.hps.as_deref(),
            paper_form: self.paper_form,
        }
    }

    /// The ground (`default` without `--terrain`) and the seeds to run
    /// (`afsv_design::vehicle_case::terrain_and_seeds`).
    fn terrain_and_seeds(
        &self,
        seeds: Option<usize>,
        seed: Option<u64>,
        default: Option<TerrainSpec>,
    ) -> Result<(Option<TerrainSpec>, Vec<u64>), String> {
        vehicle_case::terrain_and_seeds(self.terrain, seeds, seed, default)
    }
}

/// Declare the input files of `case` to `guard`.
fn declare_inputs(case: &CaseArgs, guard: &mut OutputGuard) -> Result<(), String> {
    vehicle_case::declare_inputs(&case.source(), guard)
}

/// [`CaseArgs`]'s vehicle, validated, its front axle and its struts' interconnection.
fn vehicle_of(case: &CaseArgs) -> Result<(VehicleParams, FrontAxle, Option<Link>), String> {
    let source = case.source();
    let (p, axle) = vehicle_case::vehicle_params(&source)?;
    let link = vehicle_case::described_link(&source, axle)?;
    Ok((p, axle, link))
}

/// The report `(value, text)` of a run of a vehicle whose struts `link` interconnects (the
/// report of a vehicle without one unchanged), with its `--plot` file: JSON with `--json`
/// (`json`) or on a pipe, else the text.
fn print_linked(
    (json, plot): (bool, Option<&Path>),
    report: (Value, String),
    link: Option<&Link>,
) -> CmdResult {
    let (mut value, mut text) = report;
    if let Some(plot) = plot {
        value["plot"] = json!(plot);
    }
    if let Some(l) = link {
        let (v, line) = link_note(l);
        value["link"] = v;
        text = line + &text;
    }
    Ok(afsv::output::print_json_or_text(json, &value, || text)?)
}

/// Run `one` for every seed in parallel (`afsv_design::fan_out::over_seeds`), with progress
/// when there are several; the results in seed order; an error names its seed on a terrain.
fn over_seeds<T: Send>(
    what: &str,
    terrain: &Option<TerrainSpec>,
    seeds: &[u64],
    one: impl Fn(usize, u64) -> Result<T, String> + Sync,
) -> Result<Vec<T>, String> {
    let progress = (seeds.len() > 1).then(|| Progress::new(what, "runs", Some(seeds.len())));
    let out = afsv_design::fan_out::over_seeds(
        seeds,
        |i, s| {
            one(i, s).map_err(|e| match terrain {
                Some(_) => format!("seed {s}: {e}"),
                None => e,
            })
        },
        |s| {
            if let Some(p) = &progress {
                p.step(&format!("seed {s}"));
            }
        },
    );
    if let Some(p) = &progress {
        p.finish();
    }
    out
}

/// Common start of the scenario commands: guard the inputs and the plot, read the vehicle.
fn prepare(
    case: &CaseArgs,
    study: &StudyArgs,
) -> Result<(VehicleParams, FrontAxle, Option<Link>), String> {
    let mut guard = OutputGuard::new(study.force);
    declare_inputs(case, &mut guard)?;
    guard.output_if("--plot", study.plot.as_deref(), OutputKind::Svg)?;
    vehicle_of(case)
}

fn roll_cmd(case: &CaseArgs, study: &StudyArgs, ramp_deg_s: f64, duration: f64) -> CmdResult {
    let (p, axle, link) = prepare(case, study)?;
    let (terrain, seeds) =
        case.terrain_and_seeds(study.seeds, study.seed, Some(TerrainSpec::default()))?;
    let spec = RollSpec {
        load: case.load,
        speed_kmh: case.speed_kmh.unwrap_or(50.0),
        ramp_deg_s,
        t_end_s: duration,
        terrain,
        ..RollSpec::d2(axle)
    };
    let axles = axle_name(axle, &p);
    scenario_cmd(
        study,
        ("afsv vehicle roll", &terrain, &seeds),
        link.as_ref(),
        |s| roll_run(&p, &spec, s, link.as_ref()).map_err(|e| e.to_string()),
        |rec, m: &RollMeasures| Ok(figures::vehicle::roll(rec, m, &spec, axles, seeds[0])),
        |m| roll_report(&p, &spec, case.paper_form, &seeds, m),
    )
}

fn yaw_cmd(case: &CaseArgs, study: &StudyArgs, pulse_deg: f64) -> CmdResult {
    let (p, axle, link) = prepare(case, study)?;
    let (terrain, seeds) = case.terrain_and_seeds(study.seeds, study.seed, None)?;
    let spec = YawSpec {
        load: case.load,
        speed_kmh: case.speed_kmh.unwrap_or(50.0),
        pulse_deg,
        terrain,
        ..YawSpec::d3(axle)
    };
    let axles = axle_name(axle, &p);
    scenario_cmd(
        study,
        ("afsv vehicle yaw", &terrain, &seeds),
        link.as_ref(),
        |s| yaw_run(&p, &spec, s, link.as_ref()).map_err(|e| e.to_string()),
        |rec, _: &YawMeasures| figures::vehicle::yaw(rec, &spec, axles, seeds[0]),
        |m| yaw_report(&p, &spec, case.paper_form, &seeds, m),
    )
}

/// What `vehicle roll` and `vehicle yaw` share once their scenario is set: `run` every seed
/// (the first seed's record kept for the plot), draw the `chart` of the first seed, print
/// the `report` of every seed's measures.
fn scenario_cmd<M: Send>(
    study: &StudyArgs,
    (what, terrain, seeds): (&str, &Option<TerrainSpec>, &[u64]),
    link: Option<&Link>,
    run: impl Fn(u64) -> Result<(RunRecord, M), String> + Sync,
    chart: impl Fn(&RunRecord, &M) -> Result<afsv_plot::Chart, String>,
    report: impl Fn(&[M]) -> Result<(Value, String), String>,
) -> CmdResult {
    let want_record = study.plot.is_some();
    let runs: Vec<(M, Option<RunRecord>)> = over_seeds(what, terrain, seeds, |i, s| {
        let (rec, m) = run(s)?;
        Ok((m, (want_record && i == 0).then_some(rec)))
    })?;
    if let (Some(path), Some((m, Some(rec)))) = (&study.plot, runs.first()) {
        super::write_chart(path, &chart(rec, m)?)?;
    }
    let measures: Vec<M> = runs.into_iter().map(|r| r.0).collect();
    print_linked(study.shown(), report(&measures)?, link)
}
