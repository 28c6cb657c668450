//! `afsv discover` and `afsv synth`: the model-discrepancy workflow (docs/discovery.md).

use super::CmdResult;
use afsv_design::param_files;
use afsv_discovery::hps::HpsStrutModel;
use afsv_discovery::report::{self, write_report};
use afsv_discovery::synth;
use afsv_discovery::vehicle3d::Vehicle3dModel;
use afsv_discovery::yaw::YawPlaneModel;
use afsv_discovery::{discover, DiscoveryModel, DiscoveryOptions, Progress};
use afsv_records::{folders, ReadOptions};
use std::path::{Path, PathBuf};

/// Which model the workflow works on.
#[derive(Clone, Copy, Debug, clap::ValueEnum)]
pub enum ModelKind {
    /// Hydro-pneumatic strut on a bench (records: time_s, displacement_m, [velocity_m_s],
    /// force_n, p_piston_pa, p_rod_pa).
    HpsStrut,
    /// Yaw-plane vehicle with hydraulic frame steering (records: time_s, steer_wheel_deg,
    /// speed_m_s, articulation_deg, strut_left_disp_m, p_c_pa, p_r_pa, yaw_rate_front_deg_s).
    YawPlane,
    /// The 3-D vehicle of Chapter 6 with a rigid front axle: ride records of `afsv vehicle
    /// simulate -o` (speed_m_s and the 6-axis sensor, cab_accel_{x,y,z}_m_s2,
    /// front_{roll,pitch,yaw}_accel_rad_s2) and V3 path changes of `afsv vehicle
    /// path-change -o` (also the steering channels).
    #[value(name = "vehicle-3d")]
    Vehicle3d,
    /// The same with the front-axle HPS (records whose sidecar says `front_axle: suspended`).
    #[value(name = "vehicle-3d-hps")]
    Vehicle3dHps,
}

/// Options of `afsv discover`.
#[derive(clap::Args)]
pub struct DiscoverArgs {
    /// Model to calibrate and extend.
    #[arg(long, value_enum)]
    pub model: ModelKind,
    /// Baseline parameters as JSON (strut: `StrutParams`; vehicle: `afsv params dump yaw-plane`
    /// format; 3-D vehicle: `afsv params dump vehicle-3d`). Default: the paper's full model,
    /// the one `afsv hps harmonic` / `afsv yaw simulate` / `afsv vehicle simulate` run: the
    /// front-axle strut of Table 6.3 / the vehicle of Table 3.1 for the load each record
    /// states / the vehicle of Table 6.1. A yaw-plane file that states a load replaces that
    /// load's vehicle; one without a load is used for every record.
    #[arg(long)]
    pub params: Option<PathBuf>,
    /// Vehicle (yaw-plane or 3-D): the load of records whose sidecar states none.
    #[arg(long, value_parser = ["loaded", "unloaded"])]
    pub load: Option<String>,
    /// Yaw-plane vehicle: a record's own parameter file, `RECORD.csv=params.json`
    /// (repeatable).
    #[arg(long = "params-for", value_name = "RECORD=PARAMS")]
    pub params_for: Vec<String>,
    /// Read records whose sidecar describes its sign convention in words as this convention
    /// (only `afsv-v1`, docs/records.md), after checking that the words mean it.
    #[arg(long = "assume-convention", value_parser = ["afsv-v1"])]
    pub assume_convention: Option<String>,
    /// Training records: CSV files or folders of them (repeatable).
    #[arg(long, num_args = 1.., required_unless_present = "list_effects")]
    pub train: Vec<PathBuf>,
    /// Held-out records: CSV files or folders of them (repeatable).
    #[arg(long, num_args = 1.., required_unless_present = "list_effects")]
    pub holdout: Vec<PathBuf>,
    /// Folder for report.md, report.json and SVG plots (created; input files are never written).
    #[arg(short = 'o', long = "output", required_unless_present = "list_effects")]
    pub output: Option<PathBuf>,
    /// Only try these catalogue effects (comma-separated names).
    #[arg(long, value_delimiter = ',')]
    pub effects: Option<Vec<String>>,
    /// Stop after naming this many effects.
    #[arg(long, default_value_t = 4)]
    pub max_effects: usize,
    /// Print the catalogue of the model and exit.
    #[arg(long)]
    pub list_effects: bool,
    /// Keep the outcome's exit code even when the final model did not earn its baseline (a
    /// baseline parameter still on its bound, a final fit that did not converge); the
    /// problems are still printed.
    #[arg(long)]
    pub accept_poor_fit: bool,
}

/// Options of `afsv synth`.
#[derive(clap::Args)]
pub struct SynthArgs {
    /// Truth model.
    #[arg(long, value_enum)]
    pub model: ModelKind,
    /// Effects hidden in the truth: `NAME` (realistic default size) or `NAME=v1:v2` with the
    /// parameter values in catalogue order, comma-separated; `none` for the baseline.
    #[arg(long, default_value = "none")]
    pub effects: String,
    /// Sensor noise: `default` (typical instrumentation) or `none`.
    #[arg(long, default_value = "default")]
    pub noise: String,
    /// Seed of the noise generator.
    #[arg(long, default_value_t = 7)]
    pub seed: u64,
    /// Strut: sample rate of the bench records (Hz), 50 to 2000; default 360 (the vehicle
    /// programme is sampled at 200 Hz).
    #[arg(long, allow_hyphen_values = true)]
    pub sample_rate_hz: Option<f64>,
    /// Baseline parameters as JSON (as for `afsv discover --params`).
    #[arg(long)]
    pub params: Option<PathBuf>,
    /// Output folder: `train/`, `holdout/`, `truth.json`. It must not exist or be empty,
    /// unless it is a folder `afsv synth` wrote and `--force` is given.
    #[arg(short = 'o', long = "output")]
    pub output: PathBuf,
    /// Replace an existing folder that `afsv synth` wrote (a folder afsv did not write is
    /// never replaced).
    #[arg(long)]
    pub force: bool,
}

fn hps_model(params: Option<&Path>) -> Result<HpsStrutModel, String> {
    match params {
        Some(path) => {
            let p: hps_emulsion::StrutParams = param_files::read(path)?;
            p.validate()
                .map_err(|e| format!("{}: {e}", path.display()))?;
            Ok(HpsStrutModel::new(p, None))
        }
        None => Ok(HpsStrutModel::nominal()),
    }
}

/// The 3-D vehicle with `front_axle`: Table 6.1's parameters or those of `params` (`afsv
/// params dump vehicle-3d` format, checked as `afsv params check` checks them), and the load
/// of records whose sidecar states none.
fn vehicle3d_model(
    front_axle: vehicle_3d::FrontAxle,
    params: Option<&Path>,
    load: Option<&str>,
) -> Result<Vehicle3dModel, String> {
    let mut m = Vehicle3dModel::nominal(front_axle);
    if let Some(path) = params {
        m.params = param_files::read_vehicle_3d(path)?;
    }
    m.default_load = load
        .map(|l| l.parse::<vehicle_3d::Load>())
        .transpose()
        .map_err(|e| format!("--load: {e}"))?;
    Ok(m)
}

fn yaw_model(
    params: Option<&Path>,
    load: Option<&str>,
    params_for: &[String],
) -> Result<YawPlaneModel, String> {
    let mut m = match params {
        Some(path) => YawPlaneModel::with_vehicle(param_files::read_yaw_plane(path)?),
        None => YawPlaneModel::nominal(),
    };
    m.conditions.default_load = load
        .map(|l| l.parse::<afsv_dynamics::Load>())
        .transpose()
        .map_err(|e| format!("--load: {e}"))?;
    for item in params_for {
        let (rec, file) = item
            .split_once('=')
            .ok_or_else(|| format!("--params-for {item}: expected RECORD.csv=params.json"))?;
        let rec = PathBuf::from(rec);
        if !rec.is_file() {
            return Err(format!(
                "--params-for {item}: no record file {}",
                rec.display()
            ));
        }
        m.conditions
            .per_record
            .push((rec, param_files::read_yaw_plane(Path::new(file))?));
    }
    Ok(m)
}

/// Progress of the fits on stderr ([`afsv::progress::Progress`]; the number of fits is
/// not known in advance).
struct FitProgress(afsv::progress::Progress);

impl Progress for FitProgress {
    fn fit_done(&self, what: &str) {
        self.0.step(what);
    }
}

/// The exit code of `afsv discover` on success: 0 effects named (or `--list-effects`), 3 a
/// model-form discrepancy or a calibration that did not earn its baseline (unless
/// `--accept-poor-fit`), 4 nothing missing (`afsv_discovery::Outcome::exit_code`,
/// docs/discovery.md); errors exit with 1 as for every command.
pub type DiscoverResult = Result<u8, Box<dyn std::error::Error>>;

fn run_discover<M: DiscoveryModel>(model: &M, args: &DiscoverArgs) -> DiscoverResult {
    if args.list_effects {
        afsv::output::print_json(&report::catalogue_json(model))?;
        return Ok(0);
    }
    let output = args.output.as_deref().ok_or("-o/--output is required")?;
    let train_files = folders::csv_files(&args.train)?;
    let hold_files = folders::csv_files(&args.holdout)?;
    folders::check_report_folder(output, &train_files, &hold_files)?;
    let read = ReadOptions {
        assume_convention: args.assume_convention.clone(),
    };
    read.validate()?;
    let (train, train_names) = folders::read_records(&train_files, &read)?;
    let (hold, hold_names) = folders::read_records(&hold_files, &read)?;
    let opts = DiscoveryOptions {
        candidates: args.effects.clone(),
        max_effects: args.max_effects,
        ..DiscoveryOptions::default()
    };
    let spinner = FitProgress(afsv::progress::Progress::new("afsv discover", "fits", None));
    let d = discover(
        model,
        &train,
        &hold,
        &train_names,
        &hold_names,
        &opts,
        &spinner,
    )?;
    spinner.0.finish();
    let provenance = afsv::provenance::stamp();
    let written = write_report(model, &d, &hold, &hold_names, output, &provenance)?;
    let earned = d.calibration_problems.is_empty() || args.accept_poor_fit;
    let code = if earned {
        d.outcome.exit_code()
    } else {
        afsv::output::EXIT_NOT_EARNED
    };
    let accepted = args.accept_poor_fit;
    let summary = report::summary_json(&d, output, written.len(), code, accepted);
    afsv::output::print_json(&summary)?;
    if !earned {
        eprintln!(
            "afsv: not earned: the final model's baseline: {} (the outcome stands in report.md; --accept-poor-fit keeps its exit code)",
            d.calibration_problems.join("; ")
        );
    }
    Ok(code)
}

/// Run `afsv discover`.
pub fn run_discover_cmd(args: DiscoverArgs) -> DiscoverResult {
    if !args.params_for.is_empty() && !matches!(args.model, ModelKind::YawPlane) {
        return Err("--params-for applies to --model yaw-plane only".into());
    }
    match args.model {
        ModelKind::HpsStrut => {
            if args.load.is_some() {
                return Err("--load applies to the vehicle models only".into());
            }
            run_discover(&hps_model(args.params.as_deref())?, &args)
        }
        ModelKind::Vehicle3d | ModelKind::Vehicle3dHps => {
            let axle = match args.model {
                ModelKind::Vehicle3dHps => vehicle_3d::FrontAxle::Suspended,
                _ => vehicle_3d::FrontAxle::Rigid,
            };
            let m = vehicle3d_model(axle, args.params.as_deref(), args.load.as_deref())?;
            run_discover(&m, &args)
        }
        ModelKind::YawPlane => run_discover(
            &yaw_model(
                args.params.as_deref(),
                args.load.as_deref(),
                &args.params_for,
            )?,
            &args,
        ),
    }
}

/// Run `afsv synth`.
pub fn run_synth(args: SynthArgs) -> CmdResult {
    let replace = folders::synth_folder_to_replace(&args.output, args.force)?;
    let noiseless = match args.noise.as_str() {
        "default" => false,
        "none" => true,
        other => return Err(format!("--noise must be `default` or `none`, got `{other}`").into()),
    };
    if args.sample_rate_hz.is_some() && !matches!(args.model, ModelKind::HpsStrut) {
        return Err("--sample-rate-hz applies to --model hps-strut only".into());
    }
    let rate = args.sample_rate_hz.unwrap_or(STRUT_RATE_HZ);
    if !(50.0..=2000.0).contains(&rate) {
        return Err(format!("--sample-rate-hz must be within 50 to 2000 Hz, got {rate}").into());
    }
    let (records, truth) = match args.model {
        ModelKind::HpsStrut => {
            let m = hps_model(args.params.as_deref())?;
            let hidden =
                synth::parse_effects(&args.effects, &m.catalogue(), synth::hps_default_size)?;
            let noise = if noiseless {
                synth::HpsNoise::none()
            } else {
                synth::HpsNoise::default_levels()
            };
            let recs = synth::hps_records(&m, &hidden, noise, args.seed, rate)?;
            (
                recs,
                serde_json::json!({"model": "hps-strut", "effects": hidden, "noise": noise, "seed": args.seed, "sample_rate_hz": rate}),
            )
        }
        ModelKind::YawPlane => {
            let m = yaw_model(args.params.as_deref(), None, &[])?;
            let hidden =
                synth::parse_effects(&args.effects, &m.catalogue(), synth::yaw_default_size)?;
            let noise = if noiseless {
                synth::YawNoise::none()
            } else {
                synth::YawNoise::default_levels()
            };
            let recs = synth::yaw_records(&m, &hidden, noise, args.seed)?;
            (
                recs,
                serde_json::json!({"model": "yaw-plane", "effects": hidden, "noise": noise, "seed": args.seed}),
            )
        }
        ModelKind::Vehicle3d | ModelKind::Vehicle3dHps => return Err(
            "afsv synth --model vehicle-3d: no record programme; write 3-D records with `afsv vehicle simulate -o` (ride) or `afsv vehicle path-change -o` (V3), docs/discovery.md"
                .into(),
        ),
    };
    let (mut records, mut truth) = (records, truth);
    truth["written_by"] = folders::SYNTH_WRITTEN_BY.into();
    for r in &mut records {
        if let Some(meta) = r.record.meta.as_object_mut() {
            meta.insert("written_by".into(), folders::SYNTH_WRITTEN_BY.into());
        }
    }
    for f in &replace {
        std::fs::remove_file(f).map_err(|e| format!("{}: {e}", f.display()))?;
    }
    synth::write_records(&args.output, &records, &truth)?;
    afsv::output::print_json(&report::synth_summary(&args.output, &records))?;
    Ok(())
}

/// Default sample rate of `afsv synth`'s strut records (Hz): 45 samples per cycle of the
/// programme's fastest (8 Hz) test.
const STRUT_RATE_HZ: f64 = 360.0;
