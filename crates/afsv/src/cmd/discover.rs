//! `afsv discover` and `afsv synth`: the model-discrepancy workflow (docs/discovery.md).

use super::CmdResult;
use afsv_discovery::hps::HpsStrutModel;
use afsv_discovery::report::write_report;
use afsv_discovery::synth;
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
}

/// Options of `afsv discover`.
#[derive(clap::Args)]
pub struct DiscoverArgs {
    /// Model to calibrate and extend.
    #[arg(long, value_enum)]
    pub model: ModelKind,
    /// Baseline parameters as JSON (strut: `StrutParams`; vehicle: `afsv params dump yaw-plane`
    /// format). Default: the paper's full model, the one `afsv hps harmonic` / `afsv yaw
    /// simulate` run: the front-axle strut of Table 6.3 / the vehicle of Table 3.1 for the
    /// load each record states. A vehicle file that states a load replaces that load's
    /// vehicle; one without a load is used for every record.
    #[arg(long)]
    pub params: Option<PathBuf>,
    /// Vehicle: the load of records whose sidecar states none.
    #[arg(long, value_parser = ["loaded", "unloaded"])]
    pub load: Option<String>,
    /// Vehicle: a record's own parameter file, `RECORD.csv=params.json` (repeatable).
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
    /// Baseline parameters as JSON (as for `afsv discover --params`).
    #[arg(long)]
    pub params: Option<PathBuf>,
    /// Output folder (must not exist or be empty): `train/`, `holdout/`, `truth.json`.
    #[arg(short = 'o', long = "output")]
    pub output: PathBuf,
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

/// Progress of the fits: a spinner on a terminal, otherwise one line per finished fit on
/// stderr (with the count and the time so far).
enum Spinner {
    Bar(indicatif::ProgressBar),
    Lines {
        start: std::time::Instant,
        done: std::sync::atomic::AtomicUsize,
    },
}

impl Spinner {
    fn new() -> Result<Self, String> {
        use std::io::IsTerminal;
        if !std::io::stderr().is_terminal() {
            return Ok(Spinner::Lines {
                start: std::time::Instant::now(),
                done: 0.into(),
            });
        }
        let bar = indicatif::ProgressBar::new_spinner();
        bar.set_style(
            indicatif::ProgressStyle::with_template("{spinner} {pos} fits done ({elapsed}) {msg}")
                .map_err(|e| e.to_string())?,
        );
        bar.enable_steady_tick(std::time::Duration::from_millis(200));
        Ok(Spinner::Bar(bar))
    }

    fn finish(&self) {
        if let Spinner::Bar(b) = self {
            b.finish_and_clear();
        }
    }
}

impl Progress for Spinner {
    fn fit_done(&self, what: &str) {
        match self {
            Spinner::Bar(b) => {
                b.inc(1);
                b.set_message(format!("last: {what}"));
            }
            Spinner::Lines { start, done } => {
                let n = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
                eprintln!(
                    "afsv discover: fit {n} done ({what}), {:.0} s",
                    start.elapsed().as_secs_f64()
                );
            }
        }
    }
}

fn run_discover<M: DiscoveryModel>(model: &M, args: &DiscoverArgs) -> CmdResult {
    if args.list_effects {
        afsv::output::print_json(&serde_json::json!({
            "model": model.name(),
            "baseline_params": model.baseline_params(),
            "catalogue": model.catalogue(),
        }))?;
        return Ok(());
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
    let spinner = Spinner::new()?;
    let d = discover(
        model,
        &train,
        &hold,
        &train_names,
        &hold_names,
        &opts,
        &spinner,
    )?;
    spinner.finish();
    let written = write_report(model, &d, &hold, &hold_names, output)?;
    afsv::output::print_json(&serde_json::json!({
        "model": d.model,
        "summary": afsv_discovery::report::headline(&d),
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
    }))?;
    Ok(())
}

/// Run `afsv discover`.
pub fn run_discover_cmd(args: DiscoverArgs) -> CmdResult {
    match args.model {
        ModelKind::HpsStrut => {
            if args.load.is_some() || !args.params_for.is_empty() {
                return Err("--load and --params-for apply to --model yaw-plane only".into());
            }
            run_discover(&hps_model(args.params.as_deref())?, &args)
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
    if args.output.exists()
        && std::fs::read_dir(&args.output)
            .map(|mut d| d.next().is_some())
            .unwrap_or(true)
    {
        return Err(format!(
            "{} exists and is not empty; synth writes only into a new or empty folder",
            args.output.display()
        )
        .into());
    }
    let noiseless = match args.noise.as_str() {
        "default" => false,
        "none" => true,
        other => return Err(format!("--noise must be `default` or `none`, got `{other}`").into()),
    };
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
            let recs = synth::hps_records(&m, &hidden, noise, args.seed, 360.0)?;
            (
                recs,
                serde_json::json!({"model": "hps-strut", "effects": hidden, "noise": noise, "seed": args.seed}),
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
    };
    synth::write_records(&args.output, &records, &truth)?;
    afsv::output::print_json(&serde_json::json!({
        "output": args.output,
        "train": records.iter().filter(|r| !r.holdout).map(|r| &r.name).collect::<Vec<_>>(),
        "holdout": records.iter().filter(|r| r.holdout).map(|r| &r.name).collect::<Vec<_>>(),
        "truth": args.output.join("truth.json"),
    }))?;
    Ok(())
}
