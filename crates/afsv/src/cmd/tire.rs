//! `afsv tire`: Fiala tire force sweeps and terrain enveloping (crate `tire-fiala`).

use super::{args, CmdResult};
use afsv::output::{OutputGuard, OutputKind};
use afsv_design::report::tire::{envelope_rows, sweep_rows, ENVELOPE_COLUMNS, SWEEP_COLUMNS};
use std::path::PathBuf;
use tire_fiala::{Envelope, EnvelopeMethod, Fiala, PolylineProfile, TireParams};

/// Subcommands of `afsv tire`.
#[derive(clap::Subcommand)]
pub enum Command {
    /// Sweep slip angle and/or slip ratio at one or more loads: the Fiala forces as rows
    /// {fz_n, kappa, alpha_deg, fx_n, fy_n, mz_nm, my_nm} (a table on a terminal, JSON on a
    /// pipe or with --json, CSV with -o).
    ///
    /// Signs: x forward, y left; alpha has the sign of Eq 3.17 (positive alpha gives
    /// positive F_y); kappa > 0 in traction; M_z with the paper's sign (same as alpha);
    /// M_y < 0 opposes forward rolling. Without --alpha-deg and --kappa the sweep is
    /// alpha -20:20:0.5 deg at kappa 0. Tire: the 29.5R29 of Table 6.2 (see
    /// docs/tire-fiala.md for the assumed values), changed by --params and the options.
    Sweep(SweepArgs),
    /// Envelope a terrain profile with the tire: at every profile point, the effective
    /// elevation z_oi and slope (Eqs 2.3-2.4 / 6.2-6.3) seen by a wheel held at a constant
    /// deflection, as rows {x_m, z_profile_m, z_eff_m, slope_rad, contact_length_m,
    /// wheel_z_m} (a table on a terminal, JSON on a pipe or with --json, CSV with -o).
    Envelope(EnvelopeArgs),
}

/// Options of `afsv tire sweep`.
#[derive(clap::Args)]
#[command(allow_negative_numbers = true)]
pub struct SweepArgs {
    /// Normal load(s) F_z in N: a value (100000) or a range start:stop:step.
    #[arg(long, value_name = "N|RANGE", allow_hyphen_values = true)]
    pub fz: String,
    /// Slip angle(s) in degrees: a value or a range start:stop:step (e.g. -20:20:0.5).
    #[arg(long, value_name = "DEG|RANGE", allow_hyphen_values = true)]
    pub alpha_deg: Option<String>,
    /// Longitudinal slip ratio(s): a value or a range start:stop:step (e.g. -0.5:0.5:0.01).
    #[arg(long, value_name = "X|RANGE", allow_hyphen_values = true)]
    pub kappa: Option<String>,
    /// Tire parameter file (JSON, fields of TireParams; missing fields keep the nominal
    /// 29.5R29 values).
    #[arg(long, value_name = "FILE")]
    pub params: Option<PathBuf>,
    /// Longitudinal slip stiffness C_slip (N per unit slip ratio).
    #[arg(long, value_name = "N", allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub c_slip: Option<f64>,
    /// Constant cornering stiffness C_alpha (N/rad); replaces the load-dependent table.
    #[arg(long, value_name = "N", allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub c_alpha_per_rad: Option<f64>,
    /// Static friction coefficient U_max.
    #[arg(long, value_name = "X", allow_hyphen_values = true, value_parser = args::nonneg_f64)]
    pub u_max: Option<f64>,
    /// Sliding friction coefficient U_min.
    #[arg(long, value_name = "X", allow_hyphen_values = true, value_parser = args::nonneg_f64)]
    pub u_min: Option<f64>,
    /// Tire width b in m (Fiala's R2 is half of it).
    #[arg(long, value_name = "M", allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub width_m: Option<f64>,
    /// Also draw the curves into this SVG file: F_y vs alpha when alpha is swept,
    /// otherwise F_x vs kappa; one curve per (F_z, kappa) or (F_z, alpha).
    #[arg(long, value_name = "SVG")]
    pub plot: Option<PathBuf>,
    /// Replace an existing --plot or -o file afsv did not write (never the --params file).
    #[arg(long)]
    pub force: bool,
    #[command(flatten)]
    pub table: afsv::table::TableOutput,
}

/// Which profile column a wheel runs on.
#[derive(Clone, Copy, clap::ValueEnum)]
pub enum TrackSide {
    /// Column `left_m`.
    Left,
    /// Column `right_m`.
    Right,
}

/// Enveloping method on the command line.
#[derive(Clone, Copy, clap::ValueEnum)]
pub enum MethodArg {
    /// Two tandem cams (section 6.2.2, Eqs 6.1-6.3).
    Cams,
    /// Circle-line intersection (section 2.2.1, Eqs 2.2-2.4).
    Circle,
}

/// Options of `afsv tire envelope`.
#[derive(clap::Args)]
#[command(allow_negative_numbers = true)]
pub struct EnvelopeArgs {
    /// Terrain profile CSV with columns x_m,left_m,right_m (x strictly increasing).
    #[arg(long, value_name = "CSV")]
    pub profile: PathBuf,
    /// Free tire radius R in m (Table 6.2: 1.0).
    #[arg(long, default_value_t = 1.0, value_name = "M", allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub radius: f64,
    /// Enveloping method.
    #[arg(long, value_enum, default_value = "cams")]
    pub method: MethodArg,
    /// Profile track under the wheel.
    #[arg(long, value_enum, default_value = "left")]
    pub track: TrackSide,
    /// Tire deflection held constant along the profile, m (0.1 m is the default
    /// 29.5R29 table at about 160 kN).
    #[arg(long, default_value_t = 0.1, value_name = "M", allow_hyphen_values = true, value_parser = args::nonneg_f64)]
    pub deflection_m: f64,
    /// Sampling step of the profile under the tire, m.
    #[arg(long, default_value_t = 0.01, value_name = "M", allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub spacing_m: f64,
    /// Replace an existing -o file afsv did not write (never the --profile file).
    #[arg(long)]
    pub force: bool,
    #[command(flatten)]
    pub table: afsv::table::TableOutput,
}

/// Run `afsv tire ...`.
pub fn run(cmd: Command) -> CmdResult {
    match cmd {
        Command::Sweep(a) => sweep(a),
        Command::Envelope(a) => envelope(a),
    }
}

/// Parse `v` or `start:stop:step` (inclusive end) into values.
fn parse_range(text: &str, option: &str) -> Result<Vec<f64>, String> {
    let num = |s: &str, what: &str| -> Result<f64, String> {
        let v: f64 = s.trim().parse().map_err(|_| {
            format!(
                "{option}: {what} `{}` is not a number (in `{text}`)",
                s.trim()
            )
        })?;
        if v.is_finite() {
            Ok(v)
        } else {
            Err(format!("{option}: {what} `{}` is not finite", s.trim()))
        }
    };
    let parts: Vec<&str> = text.split(':').collect();
    match parts.as_slice() {
        [v] => Ok(vec![num(v, "value")?]),
        [a, b, s] => {
            let (a, b, s) = (num(a, "start")?, num(b, "stop")?, num(s, "step")?);
            if s <= 0.0 {
                return Err(format!("{option}: step must be > 0 in `{text}`"));
            }
            if b < a {
                return Err(format!("{option}: stop {b} is below start {a} in `{text}`"));
            }
            let n = ((b - a) / s + 1e-9).floor() + 1.0;
            if n > 1e6 {
                return Err(format!(
                    "{option}: `{text}` gives {n} values (at most 1000000)"
                ));
            }
            Ok((0..n as usize).map(|i| a + i as f64 * s).collect())
        }
        _ => Err(format!(
            "{option}: expected a value or start:stop:step, got `{text}`"
        )),
    }
}

fn load_params(args: &SweepArgs) -> Result<TireParams, Box<dyn std::error::Error>> {
    let mut p = match &args.params {
        Some(path) => {
            let text = afsv_records::provenance::read_input(path)
                .map_err(|e| format!("{}: {e}", path.display()))?;
            serde_json::from_str::<TireParams>(&text)
                .map_err(|e| format!("{}: {e}", path.display()))?
        }
        None => TireParams::nominal(),
    };
    if let Some(v) = args.c_slip {
        p.longitudinal_stiffness_n = v;
    }
    if let Some(v) = args.c_alpha_per_rad {
        p.cornering_stiffness_n_per_rad = v;
        p.cornering_stiffness_table.clear();
    }
    if let Some(v) = args.u_max {
        p.u_max = v;
    }
    if let Some(v) = args.u_min {
        p.u_min = v;
    }
    if let Some(v) = args.width_m {
        p.width_m = v;
    }
    p.validate()?;
    // The file and the options together must lie in the registry's ranges.
    let source = args
        .params
        .as_ref()
        .map_or("the tire".to_string(), |f| f.display().to_string());
    vehicle_components::within_ranges(&p).map_err(|e| format!("{source}: {e}"))?;
    Ok(p)
}

fn sweep(args: SweepArgs) -> CmdResult {
    let mut guard = OutputGuard::new(args.force);
    guard.input_if("--params", args.params.as_deref())?;
    guard.output_if("--plot", args.plot.as_deref(), OutputKind::Svg)?;
    let out = &args.table;
    out.declare(&mut guard)?;
    let fzs = parse_range(&args.fz, "--fz")?;
    if let Some(bad) = fzs.iter().find(|&&f| f <= 0.0) {
        return Err(format!(
            "--fz {}: normal loads must be > 0 N (got {bad}); a tire off the ground has no forces to sweep",
            args.fz
        )
        .into());
    }
    let (alphas, kappas) = match (&args.alpha_deg, &args.kappa) {
        (None, None) => (parse_range("-20:20:0.5", "--alpha-deg")?, vec![0.0]),
        (a, k) => (
            match a {
                Some(t) => parse_range(t, "--alpha-deg")?,
                None => vec![0.0],
            },
            match k {
                Some(t) => parse_range(t, "--kappa")?,
                None => vec![0.0],
            },
        ),
    };
    let total = fzs.len() * alphas.len() * kappas.len();
    if total > 2_000_000 {
        return Err(format!("the sweep has {total} rows (at most 2000000)").into());
    }
    let tire = Fiala::new(&load_params(&args)?)?;
    let rows = sweep_rows(&tire, &fzs, &kappas, &alphas);
    if let Some(path) = &args.plot {
        let tire_name = match &args.params {
            Some(f) => format!("tire {}", f.display()),
            None => "nominal 29.5R29 tire".to_string(),
        };
        let chart = afsv_design::figures::tire::sweep(&tire_name, &rows, &fzs, &kappas, &alphas)?;
        super::write_chart(path, &chart)?;
    }
    let full = serde_json::to_value(&rows)?;
    let table = afsv::table::from_rows(full.as_array().map_or(&[], Vec::as_slice), &SWEEP_COLUMNS)?;
    let tire = match &args.params {
        Some(f) => f.display().to_string(),
        None => "nominal 29.5R29 (Table 6.2)".into(),
    };
    out.emit(
        &table,
        &full,
        &format!("Fiala forces of the {tire} tire (N, N·m; alpha in deg)\n"),
        "afsv tire sweep",
        serde_json::json!({ "tire": tire }),
    )?;
    Ok(())
}

fn envelope(args: EnvelopeArgs) -> CmdResult {
    let mut guard = OutputGuard::new(args.force);
    guard.record_input("--profile", &args.profile)?;
    let out = &args.table;
    out.declare(&mut guard)?;
    let rec = afsv_records::Record::read(&args.profile)?;
    let xs = rec.require("x_m", &args.profile)?.to_vec();
    let col = match args.track {
        TrackSide::Left => "left_m",
        TrackSide::Right => "right_m",
    };
    let zs = rec.require(col, &args.profile)?.to_vec();
    let profile = PolylineProfile::new(xs.clone(), zs.clone())
        .map_err(|e| format!("{}: {e}", args.profile.display()))?;
    let method = match args.method {
        MethodArg::Cams => EnvelopeMethod::TandemCams,
        MethodArg::Circle => EnvelopeMethod::CircleLine,
    };
    let env = Envelope::new(method, args.radius, args.spacing_m)?;
    let rows = envelope_rows(&env, &profile, (&xs, &zs), args.deflection_m)?;
    let full = serde_json::to_value(&rows)?;
    let table = afsv::table::from_rows(
        full.as_array().map_or(&[], Vec::as_slice),
        &ENVELOPE_COLUMNS,
    )?;
    out.emit(
        &table,
        &full,
        &format!(
            "terrain enveloped by a {} m tire at {} m deflection, {} track of {}\n",
            args.radius,
            args.deflection_m,
            col,
            args.profile.display()
        ),
        "afsv tire envelope",
        serde_json::json!({
            "profile": args.profile.display().to_string(),
            "track": col,
            "radius_m": args.radius,
            "deflection_m": args.deflection_m,
        }),
    )?;
    Ok(())
}
