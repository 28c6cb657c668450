//! `afsv roll`: roll stability of the rigid mining truck of chapter 2 (crate `roll-truck`):
//! a ramp-steer run to absolute rollover into a record, its roll measures (DRT, SP-DRT,
//! ΔT, a_y at A⁴ and B′, peak, SSF), the section 2.4 studies over terrain seeds with a
//! plot, and the calibration of the strut spacing ratio. Parses, calls, prints.

use super::{args, CmdResult};
use afsv::output::{OutputGuard, OutputKind};
use afsv_records::Record;
use perf_measures::roll::SustainedPeriodParams;
use roll_truck::measures::RollMeasures;
use roll_truck::model::TIRE_NAMES;
use roll_truck::studies::{run_case, run_study, Study, StudyResult, MAX_SEEDS};
use roll_truck::{RunOptions, RunRecord, SteerDirection, TruckParams};
use serde_json::json;
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use terrain_psd::{Band, CoherenceModel, IsoClass, PowerLawPsd, TwoTrackSpec};

/// The truck, its terrain and the run settings.
#[derive(clap::Args, Debug)]
pub struct CaseArgs {
    /// Truck parameter file (JSON, as written by `afsv params dump truck`), validated.
    #[arg(long)]
    pub params: Option<PathBuf>,
    /// Sprung cg height (m), replacing the parameter set's.
    #[arg(long, allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub cg_height_m: Option<f64>,
    /// Ramp direction: `left` (rolls to the right) or `right`.
    #[arg(long, default_value = "left")]
    pub direction: SteerDirection,
    /// Level ground instead of the synthesized rough terrain.
    #[arg(long)]
    pub smooth: bool,
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
    /// Simulated time if the truck does not roll over (s), at most 3600. The rough terrain
    /// is 800 m long (72 s at 40 km/h); beyond it the ground keeps its end height.
    #[arg(long, default_value_t = 60.0, allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub duration: f64,
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
        /// Print JSON even on a terminal.
        #[arg(long)]
        json: bool,
    },
    /// A study of section 2.4 over terrain seeds 1..=N (common to every variant): `cg`
    /// (Figs 2.10-2.11), `roughness` (Fig 2.12), `waviness` (Fig 2.13), `band` (Fig 2.14).
    Study {
        /// Which study.
        study: Study,
        /// Number of terrain seeds (1 to 1000).
        #[arg(long, default_value_t = 10)]
        seeds: usize,
        /// Truck parameter file (JSON), validated.
        #[arg(long)]
        params: Option<PathBuf>,
        /// SVG plot of the SP-DRT (mean ± SD) and, for `cg`, the smooth DRT and SSF.
        #[arg(long)]
        plot: Option<PathBuf>,
        /// Replace an existing plot afsv did not write.
        #[arg(long)]
        force: bool,
        /// Print JSON even on a terminal.
        #[arg(long)]
        json: bool,
    },
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
        Command::Measures { case, json } => {
            let p = truck(case.params.as_deref(), case.cg_height_m)?;
            let run = one_run(&case, &p, 0.01)?;
            if json || !std::io::stdout().is_terminal() {
                afsv::output::print_json(&measures_json(&run.measures, &case))?;
            } else {
                print!("{}", measures_text(&run.measures));
            }
            Ok(())
        }
        Command::Study {
            study,
            seeds,
            params,
            plot,
            force,
            json,
        } => run_study_cmd(
            study,
            seeds,
            params.as_deref(),
            plot.as_deref(),
            force,
            json,
        ),
        Command::Calibrate { params, target_g } => {
            let p = truck(params.as_deref(), None)?;
            let c =
                roll_truck::calibration::calibrate_strut_spacing(&p, (0.15, 0.6), target_g, 1e-4)?;
            afsv::output::print_json(&c)?;
            Ok(())
        }
    }
}

/// The truck of `--params` (or nominal) with an optional cg height, validated.
fn truck(params: Option<&Path>, cg_height_m: Option<f64>) -> Result<TruckParams, String> {
    let mut p: TruckParams = match params {
        Some(path) => super::params::read(path)?,
        None => TruckParams::nominal(),
    };
    if let Some(h) = cg_height_m {
        p.cg_height_m = h;
    }
    p.validate().map_err(|e| match params {
        Some(path) => format!("{}: {e}", path.display()),
        None => e.to_string(),
    })?;
    Ok(p)
}

fn spec(case: &CaseArgs) -> Result<TwoTrackSpec, Box<dyn std::error::Error>> {
    Ok(TwoTrackSpec::new(
        PowerLawPsd::new(case.class.alpha_r(), case.waviness)?,
        case.band,
        CoherenceModel::piecewise(case.mc)?,
    )?)
}

fn one_run(
    case: &CaseArgs,
    p: &TruckParams,
    dt: f64,
) -> Result<roll_truck::studies::Run, Box<dyn std::error::Error>> {
    if case.duration > 3600.0 {
        return Err(format!("--duration {}: at most 3600 s", args::show(case.duration)).into());
    }
    let options = RunOptions {
        t_end_s: case.duration,
        output_dt_s: dt,
        ..RunOptions::default()
    };
    let spec = if case.smooth { None } else { Some(spec(case)?) };
    let sp = SustainedPeriodParams::default();
    Ok(run_case(
        p,
        spec.as_ref(),
        case.seed,
        case.direction,
        &options,
        &sp,
    )?)
}

fn simulate(case: &CaseArgs, dt: f64, output: &Path, force: bool) -> CmdResult {
    args::check_samples(
        &format!("--duration {}", args::show(case.duration)),
        &format!("duration/dt with --dt {}", args::show(dt)),
        case.duration / dt,
        roll_truck::simulate::MAX_SAMPLES as f64,
    )?;
    let mut guard = OutputGuard::new(force);
    if let Some(p) = &case.params {
        guard.input("--params", p)?;
    }
    guard.output("-o", output, OutputKind::Record)?;
    let p = truck(case.params.as_deref(), case.cg_height_m)?;
    let run = one_run(case, &p, dt)?;
    let out = record(&run.record)?;
    let mut out = out;
    out.meta = json!({
        "written_by": "afsv roll simulate",
        "sample_rate_hz": 1.0 / dt,
        "model": "roll-truck rigid mining truck (chapter 2)",
        "manoeuvre": format!("ramp steer ({:?})", case.direction),
        "terrain": terrain_json(case),
        "params": p,
        "rollover_s": run.record.rollover_s,
    });
    out.write(output)?;
    let mut summary = measures_json(&run.measures, case);
    summary["output"] = json!(output);
    summary["sidecar"] = json!(output.with_extension("json"));
    summary["samples"] = json!(run.record.t_s.len());
    summary["columns"] = json!(out.names());
    afsv::output::print_json(&summary)?;
    Ok(())
}

/// The run's channels, named with their units.
fn record(r: &RunRecord) -> Result<Record, afsv_records::RecordError> {
    let mut out = Record::new();
    out.push_column("time_s", r.t_s.clone())?;
    out.push_column("steer_rad", r.steer_rad.clone())?;
    out.push_column("speed_m_s", r.speed_m_s.clone())?;
    out.push_column("lateral_accel_m_s2", r.lateral_accel_m_s2.clone())?;
    out.push_column("ltr", r.ltr.clone())?;
    out.push_column("roll_rad", r.roll_rad.clone())?;
    out.push_column("rollover_margin_m", r.rollover_margin_m.clone())?;
    out.push_column("drive_force_n", r.drive_force_n.clone())?;
    let stop = r
        .on_bump_stop
        .iter()
        .map(|b| f64::from(u8::from(*b)))
        .collect();
    out.push_column("on_bump_stop", stop)?;
    for (name, values) in TIRE_NAMES.iter().zip(&r.normal_force_n) {
        out.push_column(&format!("normal_force_{name}_n"), values.clone())?;
    }
    Ok(out)
}

fn terrain_json(case: &CaseArgs) -> serde_json::Value {
    if case.smooth {
        json!({ "kind": "level ground" })
    } else {
        json!({
            "kind": "two-track rough terrain",
            "class": case.class.to_string(),
            "alpha_r": case.class.alpha_r(),
            "waviness": case.waviness,
            "band_cycles_per_m": [case.band.n_min, case.band.n_max],
            "m_c_cycles_per_m": case.mc,
            "seed": case.seed,
        })
    }
}

fn measures_json(m: &RollMeasures, case: &CaseArgs) -> serde_json::Value {
    let mut v = serde_json::to_value(m).unwrap_or_default();
    v["terrain"] = terrain_json(case);
    v["g_for_reporting_m_s2"] = json!(roll_truck::measures::G_REPORT);
    afsv::output::explain_nulls(
        v,
        "not found in this run (no LTR of 1, no sustained period, or no rollover)",
    )
}

fn show(v: Option<f64>, unit: &str) -> String {
    v.map_or("n/a".into(), |x| format!("{x:.3} {unit}"))
}

fn measures_text(m: &RollMeasures) -> String {
    let range = m
        .sustained_range_g
        .map_or("n/a".into(), |(a, b)| format!("{a:.3}-{b:.3} g"));
    format!(
        "DRT (first LTR = 1)      {}\nSP-DRT                   {}\nsustained period ΔT      {} ({} to {})\na_y range in ΔT          {range}\na_y at A4                {}\na_y at rollover B'       {}\npeak a_y                 {:.3} g\nabsolute rollover        {}\nSSF                      {:.3}\n",
        show(m.drt_g, "g"),
        show(m.sp_drt_g, "g"),
        show(m.sustained_period_s, "s"),
        show(m.sustained_start_s, "s"),
        show(m.sustained_end_s, "s"),
        show(m.ay_at_a4_g, "g"),
        show(m.ay_at_rollover_g, "g"),
        m.peak_ay_g,
        show(m.rollover_s, "s"),
        m.ssf,
    )
}

fn run_study_cmd(
    study: Study,
    seeds: usize,
    params: Option<&Path>,
    plot: Option<&Path>,
    force: bool,
    json: bool,
) -> CmdResult {
    if seeds == 0 || seeds > MAX_SEEDS {
        return Err(format!("--seeds {seeds}: must be 1 to {MAX_SEEDS}").into());
    }
    let mut guard = OutputGuard::new(force);
    if let Some(p) = params {
        guard.input("--params", p)?;
    }
    if let Some(p) = plot {
        guard.output("--plot", p, OutputKind::Svg)?;
    }
    let p = truck(params, None)?;
    let seed_list: Vec<u64> = (1..=seeds as u64).collect();
    // The number of runs is known once the study has built its variants.
    let progress = std::sync::OnceLock::new();
    let report = |_done: usize, total: usize| {
        progress
            .get_or_init(|| afsv::progress::Progress::new("afsv roll study", "runs", Some(total)))
            .step("");
    };
    let result = run_study(
        study,
        &p,
        &seed_list,
        &RunOptions::default(),
        &SustainedPeriodParams::default(),
        &report,
    )?;
    if let Some(p) = progress.get() {
        p.finish();
    }
    if let Some(path) = plot {
        plot_study(path, &result)?;
    }
    if json || !std::io::stdout().is_terminal() {
        let mut v = serde_json::to_value(&result)?;
        v["findings"] = serde_json::to_value(result.findings())?;
        afsv::output::print_json(&v)?;
    } else {
        print!("{}", study_text(&result));
    }
    Ok(())
}

fn study_text(r: &StudyResult) -> String {
    let mut s = format!(
        "{:<22} {:>10} {:>10} {:>16} {:>14} {:>7}\n",
        "group", "x", "smooth g", "SP-DRT g", "ΔT s", "SSF"
    );
    for p in &r.points {
        s += &format!(
            "{:<22} {:>10.4} {:>10} {:>7.3} ± {:<6.3} {:>6.2} ± {:<5.2} {:>7.3}\n",
            p.group,
            p.x,
            p.smooth_drt_g.map_or("n/a".into(), |v| format!("{v:.3}")),
            p.sp_drt_g.mean,
            p.sp_drt_g.sd,
            p.sustained_period_s.mean,
            p.sustained_period_s.sd,
            p.ssf,
        );
    }
    for f in r.findings() {
        s += &format!("{:<44} {:>9.4}  {}\n", f.name, f.value, f.meaning);
    }
    s
}

fn plot_study(path: &Path, r: &StudyResult) -> CmdResult {
    let mut groups: Vec<&str> = r.points.iter().map(|p| p.group.as_str()).collect();
    groups.dedup();
    let mut columns: Vec<(String, Vec<f64>, Vec<f64>)> = Vec::new();
    for g in &groups {
        let pts: Vec<_> = r.points.iter().filter(|p| p.group == *g).collect();
        let x: Vec<f64> = pts.iter().map(|p| p.x).collect();
        let y = |f: &dyn Fn(&roll_truck::studies::StudyPoint) -> f64| {
            pts.iter().map(|p| f(p)).collect()
        };
        columns.push((format!("SP-DRT {g}"), x.clone(), y(&|p| p.sp_drt_g.mean)));
        columns.push((
            format!("- SD {g}"),
            x.clone(),
            y(&|p| p.sp_drt_g.mean - p.sp_drt_g.sd),
        ));
        columns.push((
            format!("+ SD {g}"),
            x.clone(),
            y(&|p| p.sp_drt_g.mean + p.sp_drt_g.sd),
        ));
        if r.study == Study::CgHeight {
            columns.push((
                "smooth DRT".into(),
                x.clone(),
                y(&|p| p.smooth_drt_g.unwrap_or(f64::NAN)),
            ));
            columns.push(("SSF".into(), x, y(&|p| p.ssf)));
        }
    }
    let series: Vec<afsv_plot::Series> = columns
        .iter()
        .map(|(label, x, y)| afsv_plot::Series { label, x, y })
        .collect();
    afsv_plot::line_plot(
        path,
        &format!("rough-terrain SP-DRT over {} seeds", r.seeds.len()),
        r.study.x_label(),
        "lateral acceleration (g) / SSF",
        &series,
    )?;
    afsv::output::mark_svg(path)?;
    Ok(())
}
