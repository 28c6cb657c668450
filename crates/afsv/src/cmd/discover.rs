//! `afsv discover` and `afsv synth`: the model-discrepancy workflow (docs/discovery.md).

use super::CmdResult;
use afsv_discovery::hps::HpsStrutModel;
use afsv_discovery::report::write_report;
use afsv_discovery::synth;
use afsv_discovery::vehicle3d::Vehicle3dModel;
use afsv_discovery::yaw::YawPlaneModel;
use afsv_discovery::{discover, DiscoveryModel, DiscoveryOptions, Progress};
use afsv_records::{ReadOptions, Record};
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

fn read_json<T: serde::de::DeserializeOwned>(path: &Path) -> Result<T, String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    serde_json::from_str(&text)
        .map_err(|e| format!("{}:{}:{}: {e}", path.display(), e.line(), e.column()))
}

fn hps_model(params: Option<&Path>) -> Result<HpsStrutModel, String> {
    match params {
        Some(path) => {
            let p: hps_emulsion::StrutParams = read_json(path)?;
            p.validate()
                .map_err(|e| format!("{}: {e}", path.display()))?;
            Ok(HpsStrutModel::new(p, None))
        }
        None => Ok(HpsStrutModel::nominal()),
    }
}

fn read_vehicle(path: &Path) -> Result<afsv_dynamics::YawPlaneParams, String> {
    let p: afsv_dynamics::YawPlaneParams = read_json(path)?;
    p.validate()
        .map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(p)
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
        let p: vehicle_3d::VehicleParams = read_json(path)?;
        p.validate()
            .map_err(|e| format!("{}: {e}", path.display()))?;
        super::params::vehicle_3d_in_ranges(&p).map_err(|e| format!("{}: {e}", path.display()))?;
        m.params = p;
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
        Some(path) => YawPlaneModel::with_vehicle(read_vehicle(path)?),
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
            .push((rec, read_vehicle(Path::new(file))?));
    }
    Ok(m)
}

/// Refuse, before any fit runs: an `-o` that is an existing file; an output folder that
/// holds any input record (the report's plots would land among them); and a record given
/// as both training and held-out (the held-out test would then measure nothing). Paths are
/// compared canonically, so `x`, `./x` and a link to `x` are the same.
fn check_output_folder(
    output: &Path,
    train: &[PathBuf],
    holdout: &[PathBuf],
) -> Result<(), String> {
    if output.exists() && !output.is_dir() {
        return Err(format!(
            "-o {}: exists and is not a folder; the report is a folder (report.md, report.json, plots)",
            output.display()
        ));
    }
    let out = afsv::output::canonical_path(output)?;
    let canon = |f: &PathBuf| afsv::output::canonical_path(f);
    let train_c = train.iter().map(canon).collect::<Result<Vec<_>, _>>()?;
    let hold_c = holdout.iter().map(canon).collect::<Result<Vec<_>, _>>()?;
    for (f, c) in train
        .iter()
        .zip(&train_c)
        .chain(holdout.iter().zip(&hold_c))
    {
        if c.parent() == Some(out.as_path()) {
            return Err(format!(
                "-o {}: holds the input record {}; choose a folder of its own for the report",
                output.display(),
                f.display()
            ));
        }
    }
    if let Some((f, _)) = holdout
        .iter()
        .zip(&hold_c)
        .find(|(_, c)| train_c.contains(c))
    {
        return Err(format!(
            "{} is both a training and a held-out record; the held-out records must be others",
            f.display()
        ));
    }
    Ok(())
}

/// CSV files of the given files and folders (folders: their `*.csv`, sorted).
fn csv_files(inputs: &[PathBuf]) -> Result<Vec<PathBuf>, String> {
    let mut out = Vec::new();
    for p in inputs {
        if p.is_dir() {
            let mut v: Vec<PathBuf> = std::fs::read_dir(p)
                .map_err(|e| format!("{}: {e}", p.display()))?
                .filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|f| f.extension().is_some_and(|x| x == "csv"))
                .collect();
            if v.is_empty() {
                return Err(format!("{}: no .csv records in this folder", p.display()));
            }
            v.sort();
            out.extend(v);
        } else if p.is_file() {
            out.push(p.clone());
        } else {
            return Err(format!("{}: no such file or folder", p.display()));
        }
    }
    Ok(out)
}

fn load(files: &[PathBuf], opts: &ReadOptions) -> Result<(Vec<Record>, Vec<String>), String> {
    let mut recs = Vec::new();
    let mut names = Vec::new();
    for f in files {
        recs.push(Record::read_with(f, opts).map_err(|e| e.to_string())?);
        names.push(
            f.file_stem()
                .map(|s| s.to_string_lossy().into_owned())
                .unwrap_or_default(),
        );
    }
    Ok((recs, names))
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
        afsv::output::print_json(&serde_json::json!({
            "model": model.name(),
            "baseline_params": model.baseline_params(),
            "catalogue": model.catalogue(),
        }))?;
        return Ok(0);
    }
    let output = args.output.as_deref().ok_or("-o/--output is required")?;
    let train_files = csv_files(&args.train)?;
    let hold_files = csv_files(&args.holdout)?;
    check_output_folder(output, &train_files, &hold_files)?;
    let read = ReadOptions {
        assume_convention: args.assume_convention.clone(),
    };
    read.validate()?;
    let (train, train_names) = load(&train_files, &read)?;
    let (hold, hold_names) = load(&hold_files, &read)?;
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
    afsv::output::print_json(&serde_json::json!({
        "model": d.model,
        "summary": afsv_discovery::report::headline(&d),
        "outcome": d.outcome,
        "exit_code": code,
        "excess_over_noise": d.excess_over_noise,
        "named": d.named,
        "effect_params": d.final_model.effect_params,
        "gap_shrink": d.gap_shrink,
        "best_unnamed": d.best_unnamed_shrink,
        "holdout_mse": {"calibrated": d.calibrated.holdout_mse, "final": d.final_model.holdout_mse, "noise": d.holdout_noise_mse},
        "channel_errors": d.channel_errors.iter().map(|(tb, ta, hb, ha)| serde_json::json!({
            "channel": tb.channel, "train_before": tb.nrmse, "train_after": ta.nrmse,
            "holdout_before": hb.nrmse, "holdout_after": ha.nrmse})).collect::<Vec<_>>(),
        "report": output.join("report.md"),
        "files_written": written.len(),
        "calibration_problems": d.calibration_problems,
        "accepted_despite_problems": args.accept_poor_fit && !d.calibration_problems.is_empty(),
    }))?;
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
    let replace = synth_folder_to_replace(&args.output, args.force)?;
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
    truth["written_by"] = SYNTH_WRITTEN_BY.into();
    for r in &mut records {
        if let Some(meta) = r.record.meta.as_object_mut() {
            meta.insert("written_by".into(), SYNTH_WRITTEN_BY.into());
        }
    }
    for f in &replace {
        std::fs::remove_file(f).map_err(|e| format!("{}: {e}", f.display()))?;
    }
    synth::write_records(&args.output, &records, &truth)?;
    afsv::output::print_json(&serde_json::json!({
        "output": args.output,
        "train": records.iter().filter(|r| !r.holdout).map(|r| &r.name).collect::<Vec<_>>(),
        "holdout": records.iter().filter(|r| r.holdout).map(|r| &r.name).collect::<Vec<_>>(),
        "truth": args.output.join("truth.json"),
    }))?;
    Ok(())
}

/// Default sample rate of `afsv synth`'s strut records (Hz): 45 samples per cycle of the
/// programme's fastest (8 Hz) test.
const STRUT_RATE_HZ: f64 = 360.0;

/// `"written_by"` of the `truth.json` that marks a folder `afsv synth` wrote.
const SYNTH_WRITTEN_BY: &str = "afsv synth";

/// The files to delete before `afsv synth` writes into `dir`: none when `dir` does not
/// exist or is empty. A non-empty `dir` is replaced only with `force` and only when afsv
/// wrote all of it: a `truth.json` with `"written_by": "afsv synth"`, and `train/` and
/// `holdout/` holding nothing but records (CSV) with afsv-written sidecars. Anything else
/// in it is refused, so no file afsv did not write is ever deleted.
fn synth_folder_to_replace(dir: &Path, force: bool) -> Result<Vec<PathBuf>, String> {
    if !dir.exists() {
        return Ok(Vec::new());
    }
    if !dir.is_dir() {
        return Err(format!(
            "-o {}: exists and is not a folder; synth writes a folder (train/, holdout/, truth.json)",
            dir.display()
        ));
    }
    let entries = list_dir(dir)?;
    if entries.is_empty() {
        return Ok(Vec::new());
    }
    let foreign = |what: &str| {
        format!(
            "-o {}: {what}; afsv synth did not write this folder, so it is never replaced (choose another folder)",
            dir.display()
        )
    };
    let truth = dir.join("truth.json");
    let text = std::fs::read_to_string(&truth).map_err(|_| foreign("has no truth.json"))?;
    let by_synth = serde_json::from_str::<serde_json::Value>(&text)
        .ok()
        .and_then(|v| v.get("written_by")?.as_str().map(|s| s == SYNTH_WRITTEN_BY))
        .unwrap_or(false);
    if !by_synth {
        return Err(foreign(
            "its truth.json does not say `\"written_by\": \"afsv synth\"`",
        ));
    }
    let mut files = vec![truth.clone()];
    for e in entries {
        if e == truth {
            continue;
        }
        let name = e.file_name().unwrap_or_default();
        if !(is_real_dir(&e) && (name == "train" || name == "holdout")) {
            return Err(foreign(&format!("holds {}", e.display())));
        }
        files.extend(synth_records(&e).map_err(|f| foreign(&format!("holds {}", f.display())))?);
    }
    if !force {
        return Err(format!(
            "-o {}: exists (written by an earlier afsv synth); add --force to replace it",
            dir.display()
        ));
    }
    Ok(files)
}

/// The records and sidecars in `sub` when all are afsv-written, else the first other file.
fn synth_records(sub: &Path) -> Result<Vec<PathBuf>, PathBuf> {
    let mut files = Vec::new();
    for f in list_dir(sub).map_err(|_| sub.to_path_buf())? {
        let ext = f.extension().and_then(|x| x.to_str());
        let afsv_json = |j: &Path| {
            j.is_file() && std::fs::read_to_string(j).is_ok_and(|t| afsv::output::is_afsv_json(&t))
        };
        let ours = !is_link(&f)
            && f.is_file()
            && match ext {
                Some("csv") => afsv_json(&f.with_extension("json")),
                Some("json") => afsv_json(&f) && f.with_extension("csv").is_file(),
                _ => false,
            };
        if !ours {
            return Err(f);
        }
        files.push(f);
    }
    Ok(files)
}

/// True when `p` is a symbolic link (never followed when replacing a folder).
fn is_link(p: &Path) -> bool {
    std::fs::symlink_metadata(p).map_or(true, |m| m.file_type().is_symlink())
}

/// True when `p` is a folder and not a link to one.
fn is_real_dir(p: &Path) -> bool {
    !is_link(p) && p.is_dir()
}

/// Entries of `dir`, sorted.
fn list_dir(dir: &Path) -> Result<Vec<PathBuf>, String> {
    let mut v = std::fs::read_dir(dir)
        .map_err(|e| format!("{}: {e}", dir.display()))?
        .map(|e| e.map(|e| e.path()))
        .collect::<Result<Vec<_>, _>>()
        .map_err(|e| format!("{}: {e}", dir.display()))?;
    v.sort();
    Ok(v)
}
