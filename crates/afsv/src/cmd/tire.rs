//! `afsv tire`: Fiala tire force sweeps and terrain enveloping (crate `tire-fiala`).

use super::{args, CmdResult};
use afsv::output::{OutputGuard, OutputKind};
use afsv_design::report::tire::{envelope_track, sweep_rows, ENVELOPE_COLUMNS, SWEEP_COLUMNS};
use afsv_design::tire_sweep::{sweep_grid, tire_params, TireOverrides};
use std::path::PathBuf;
use tire_fiala::{EnvelopeMethod, Fiala};

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

fn sweep(args: SweepArgs) -> CmdResult {
    let mut guard = OutputGuard::new(args.force);
    guard.input_if("--params", args.params.as_deref())?;
    guard.output_if("--plot", args.plot.as_deref(), OutputKind::Svg)?;
    let out = &args.table;
    out.declare(&mut guard)?;
    let (alpha, kappa) = (args.alpha_deg.as_deref(), args.kappa.as_deref());
    let (fzs, alphas, kappas) = sweep_grid(&args.fz, alpha, kappa)?;
    let overrides = TireOverrides {
        c_slip: args.c_slip,
        c_alpha_per_rad: args.c_alpha_per_rad,
        u_max: args.u_max,
        u_min: args.u_min,
        width_m: args.width_m,
    };
    let tire = Fiala::new(&tire_params(args.params.as_deref(), &overrides)?)?;
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
    let col = match args.track {
        TrackSide::Left => "left_m",
        TrackSide::Right => "right_m",
    };
    let method = match args.method {
        MethodArg::Cams => EnvelopeMethod::TandemCams,
        MethodArg::Circle => EnvelopeMethod::CircleLine,
    };
    let tire = (method, args.radius, args.spacing_m);
    let rows = envelope_track((&rec, &args.profile), col, tire, args.deflection_m)?;
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
