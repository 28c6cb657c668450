//! `afsv roll`: roll stability of the rigid mining truck of chapter 2 (crate `roll-truck`):
//! a ramp-steer run to absolute rollover into a record, its roll measures (DRT, SP-DRT,
//! ΔT, a_y at A⁴ and B′, peak, SSF), the section 2.4 studies over terrain seeds with a
//! plot, the comparison of the calibrated and the plausible truck, the sensitivity of ΔT
//! to the steering ramp and the detection rule (`roll_study.rs`), and the calibration of
//! the strut spacing ratio. Parses, calls, prints.

use super::{args, CmdResult};
use afsv::output::{OutputGuard, OutputKind};
use afsv_design::report::roll::{self, measures_text, Ground};
use afsv_design::truck_case::{self, TruckSource};
use afsv_records::Record;
use perf_measures::roll::SustainedPeriodParams;
use roll_truck::measures::RollMeasures;
use roll_truck::{BuiltinTruck, SteerDirection, TruckParams};
use serde_json::json;
use std::path::{Path, PathBuf};

#[path = "roll_study.rs"]
mod roll_study;
use terrain_psd::{Band, IsoClass};

/// Which truck, and the settings chapter 2 does not state: the steering ramp rate and the
/// bump stops.
#[derive(clap::Args, Debug, Clone)]
pub struct TruckArgs {
    /// Truck parameter file (JSON, as written by `afsv params dump truck`), validated.
    #[arg(long)]
    pub params: Option<PathBuf>,
    /// Built-in truck: `calibrated` (strut spacing ratio 0.254, the default) or
    /// `plausible` (struts at half the track, 0.5); not with --params.
    #[arg(long, conflicts_with = "params")]
    pub truck: Option<BuiltinTruck>,
    /// Vehicle description of a rigid truck (TOML, docs/vehicles.md; `afsv params dump
    /// vehicle --builtin chapter2-truck` writes one to start from) or a built-in name
    /// (chapter2-truck); not with --params or --truck.
    #[arg(long, conflicts_with_all = ["params", "truck"])]
    pub vehicle: Option<PathBuf>,
    /// Steering-wheel ramp rate (deg/s), replacing the parameter set's (5 deg/s, not given
    /// in chapter 2).
    #[arg(long, allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub ramp_rate: Option<f64>,
    /// Put the bump stops out of reach (both strut travels 2 m).
    #[arg(long)]
    pub no_bump_stops: bool,
}

/// The detection rule of the sustained period (not given in chapter 2).
#[derive(clap::Args, Debug, Clone, Copy)]
pub struct RuleArgs {
    /// LTR threshold of the sustained period, in (0, 1) (default 0.95).
    #[arg(long, allow_hyphen_values = true, value_parser = args::open_fraction_f64)]
    pub sp_threshold: Option<f64>,
    /// Longest dip below the threshold that does not end the sustained period (s, default
    /// 0.5).
    #[arg(long, allow_hyphen_values = true, value_parser = args::nonneg_f64)]
    pub sp_max_dip: Option<f64>,
}

impl RuleArgs {
    /// The rule: the defaults with the given options replaced, validated.
    pub fn params(&self) -> Result<SustainedPeriodParams, String> {
        truck_case::sustained_period(self.sp_threshold, self.sp_max_dip)
    }

    fn given(&self) -> bool {
        self.sp_threshold.is_some() || self.sp_max_dip.is_some()
    }
}

/// The truck, its terrain and the run settings.
#[derive(clap::Args, Debug)]
pub struct CaseArgs {
    #[command(flatten)]
    pub truck: TruckArgs,
    #[command(flatten)]
    pub rule: RuleArgs,
    /// Sprung cg height (m), replacing the parameter set's.
    #[arg(long, allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub cg_height_m: Option<f64>,
    /// Ramp direction: `left` (rolls to the right) or `right`.
    #[arg(long, default_value = "left")]
    pub direction: SteerDirection,
    /// Level ground instead of the synthesized rough terrain (the terrain options then
    /// have nothing to act on and are refused).
    #[arg(long, conflicts_with_all = ["class", "waviness", "band", "mc", "seed"])]
    pub smooth: bool,
    /// A measured road instead of synthesized terrain: a two-track CSV with columns x_m
    /// (uniformly spaced), left_m and right_m (other length units such as left_mm are
    /// converted on read; docs/records.md), or an ASAM OpenCRG ASCII file (`.crg`, read at
    /// plus and minus half the mean track). It must cover the run; a shorter road is
    /// refused with the length it needs.
    #[arg(long, conflicts_with_all = ["smooth", "class", "waviness", "band", "mc", "seed"])]
    pub road: Option<PathBuf>,
    /// ISO 8608 class of the rough terrain (Table 2.4), A to E.
    #[arg(long, default_value = "E")]
    pub class: IsoClass,
    /// Waviness w of the rough terrain (Eq 2.8).
    #[arg(long, default_value_t = 2.0, allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub waviness: f64,
    /// Spatial band `N_MIN,N_MAX` (cycles/m) of the rough terrain, at most 10 cycles/m.
    #[arg(long, default_value = "0.02,5")]
    pub band: Band,
    /// Coherence cut-off m_c (cycles/m) of Eq 2.10.
    #[arg(long, default_value_t = 0.3, allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub mc: f64,
    /// Terrain seed.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Simulated time if the truck does not roll over (s), at most 3600. Default: the ramp
    /// start plus 290 deg of steering-wheel angle at the ramp rate (60 s at 5 deg/s). The
    /// rough terrain is 800 m long, or longer for runs beyond 60 s.
    #[arg(long, allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub duration: Option<f64>,
}

/// `afsv roll` subcommands.
#[derive(clap::Subcommand, Debug)]
pub enum Command {
    /// Ramp-steer run to absolute rollover; writes the record (CSV + JSON sidecar) and
    /// prints its measures as JSON.
    Simulate {
        #[command(flatten)]
        case: CaseArgs,
        /// Output sample interval (s).
        #[arg(long, default_value_t = 0.01, allow_hyphen_values = true, value_parser = args::positive_f64)]
        dt: f64,
        /// Output CSV file (the sidecar goes beside it with extension .json). It must not
        /// be an input; an existing file afsv did not write needs --force.
        #[arg(short = 'o', long)]
        output: PathBuf,
        /// Replace an existing output file that afsv did not write.
        #[arg(long)]
        force: bool,
    },
    /// Roll measures of one run: readable text on a terminal, JSON when piped or with --json.
    Measures {
        #[command(flatten)]
        case: CaseArgs,
        #[command(flatten)]
        output: super::args::JsonOutput,
    },
    /// A study over terrain seeds 1..=N (common to every variant): of section 2.4, `cg`
    /// (Figs 2.10-2.11), `roughness` (Fig 2.12), `waviness` (Fig 2.13), `band`
    /// (Fig 2.14); `trucks`, the calibrated and the plausible truck with and without their
    /// bump stops; `sensitivity`, ΔT and the class A -> E ratio against the ramp rate
    /// (2.5, 5, 10 deg/s) and the detection rule (default, strict, loose).
    Study(roll_study::StudyArgs),
    /// Find the strut spacing ratio of the smooth-road DRT target among the roll-stable
    /// ratios (the derivation of the built-in constant), as JSON.
    Calibrate {
        /// Truck parameter file (JSON), validated.
        #[arg(long)]
        params: Option<PathBuf>,
        /// Target smooth-road DRT (g).
        #[arg(long, default_value_t = 0.279, allow_hyphen_values = true, value_parser = args::positive_f64)]
        target_g: f64,
    },
}

/// Run an `afsv roll` subcommand.
pub fn run(cmd: Command) -> CmdResult {
    match cmd {
        Command::Simulate {
            case,
            dt,
            output,
            force,
        } => simulate(&case, dt, &output, force),
        Command::Measures { case, output } => {
            let p = truck(&case.truck, case.cg_height_m)?;
            let run = one_run(&case, &p, 0.01)?;
            let v = measures_json(&run.measures, &case);
            afsv::output::print_json_or_text(output.json, &v, || measures_text(&run.measures))?;
            Ok(())
        }
        Command::Study(a) => roll_study::run_study_cmd(&a),
        Command::Calibrate { params, target_g } => {
            let source = TruckSource {
                params: params.as_deref(),
                ..TruckSource::default()
            };
            afsv::output::print_json(&truck_case::calibrate(&source, target_g)?)?;
            Ok(())
        }
    }
}

impl TruckArgs {
    /// The truck's source, as `afsv_design::truck_case` takes it.
    pub fn source(&self) -> TruckSource<'_> {
        TruckSource {
            params: self.params.as_deref(),
            builtin: self.truck,
            vehicle: self.vehicle.as_deref(),
            ramp_rate_deg_s: self.ramp_rate,
            no_bump_stops: self.no_bump_stops,
        }
    }

    /// The truck's name in reports: the parameter file, the description or the built-in.
    pub fn name(&self) -> String {
        self.source().name()
    }

    /// Declare the files the truck is read from as inputs.
    pub fn declare_inputs(&self, guard: &mut OutputGuard) -> Result<(), String> {
        guard.input_if("--params", self.params.as_deref())?;
        super::described::declare(guard, self.vehicle.as_deref())?;
        Ok(())
    }
}

/// The truck of `--params`, `--truck` or `--vehicle` (default calibrated) with the ramp
/// rate, the stops and an optional cg height applied, validated.
fn truck(a: &TruckArgs, cg_height_m: Option<f64>) -> Result<TruckParams, String> {
    truck_case::truck(&a.source(), cg_height_m)
}

fn one_run(
    case: &CaseArgs,
    p: &TruckParams,
    dt: f64,
) -> Result<roll_truck::studies::Run, Box<dyn std::error::Error>> {
    let options = truck_case::run_options(duration(case, p), dt)?;
    let sp = case.rule.params()?;
    Ok(truck_case::run_on(
        p,
        &ground(case),
        case.direction,
        &options,
        &sp,
    )?)
}

/// `--duration`, or the ramp start plus [`roll_truck::sensitivity::RAMP_SPAN_DEG`] at the
/// truck's ramp rate.
fn duration(case: &CaseArgs, p: &TruckParams) -> f64 {
    case.duration
        .unwrap_or_else(|| roll_truck::sensitivity::ramp_duration_s(p))
}

fn simulate(case: &CaseArgs, dt: f64, output: &Path, force: bool) -> CmdResult {
    let mut guard = OutputGuard::new(force);
    case.truck.declare_inputs(&mut guard)?;
    guard.input_if("--road", case.road.as_deref())?;
    guard.output("-o", output, OutputKind::Record)?;
    let p = truck(&case.truck, case.cg_height_m)?;
    let duration = duration(case, &p);
    args::check_duration(duration, dt, roll_truck::simulate::MAX_SAMPLES as f64)?;
    let run = one_run(case, &p, dt)?;
    let rollover_s = run.record.rollover_s;
    let meta = roll::simulate_sidecar(&p, case.direction, &ground(case), dt, rollover_s);
    let columns = Record::from_columns(run.record.afsv_v1_columns())?;
    let out = afsv::provenance::write_record(output, columns, meta)?;
    let mut summary = measures_json(&run.measures, case);
    summary["output"] = json!(output);
    summary["sidecar"] = json!(output.with_extension("json"));
    summary["samples"] = json!(run.record.t_s.len());
    summary["columns"] = json!(out.names());
    afsv::output::print_json(&summary)?;
    Ok(())
}

/// The ground of `case` for its report and sidecar.
fn ground(case: &CaseArgs) -> Ground<'_> {
    match &case.road {
        Some(road) => Ground::Road(road),
        None if case.smooth => Ground::Level,
        None => Ground::Rough {
            class: case.class,
            waviness: case.waviness,
            band: case.band,
            m_c: case.mc,
            seed: case.seed,
        },
    }
}

fn measures_json(m: &RollMeasures, case: &CaseArgs) -> serde_json::Value {
    let truck = case.truck.name();
    let rule = case.rule.params().ok();
    roll::measures_json(m, &ground(case), &truck, !case.truck.no_bump_stops, rule)
}
