//! `afsv yaw`: the yaw-plane AFSV model with hydraulic frame steering (chapters 3-4):
//! simulate a manoeuvre into a record, the yaw-plane measures, the sensitivity table and
//! the leakage analyses.

use super::{args, CmdResult};
use afsv::output::{OutputGuard, OutputKind};
use afsv::progress::Progress;
use afsv_design::report::yaw;
use afsv_dynamics::yaw_plane::analysis::{measures_for, sensitivity_of, MeasureSpec};
use afsv_dynamics::yaw_plane::simulate::Recording;
use afsv_dynamics::{
    simulate, Course, EquationForm, Load, Manoeuvre, PathDriver, SimOptions, Solver, SteerInput,
    YawPlaneParams,
};
use afsv_records::Record;
use std::path::{Path, PathBuf};

/// Load condition (Table 3.1 column).
#[derive(Clone, Copy, Debug, clap::ValueEnum)]
pub enum LoadChoice {
    /// Rated payload.
    Loaded,
    /// Empty.
    Unloaded,
}

impl From<LoadChoice> for Load {
    fn from(l: LoadChoice) -> Self {
        match l {
            LoadChoice::Loaded => Load::Loaded,
            LoadChoice::Unloaded => Load::Unloaded,
        }
    }
}

/// Form of the yaw equations.
#[derive(Clone, Copy, Debug, clap::ValueEnum)]
pub enum FormChoice {
    /// Newton-Euler about the joint, conserves energy (default).
    #[value(name = "energy-consistent")]
    EnergyConsistent,
    /// Eq 3.13 as printed (m L^2 counted twice in the yaw inertias).
    #[value(name = "paper-eq-3-13")]
    Paper,
}

impl From<FormChoice> for EquationForm {
    fn from(f: FormChoice) -> Self {
        match f {
            FormChoice::EnergyConsistent => EquationForm::EnergyConsistent,
            FormChoice::Paper => EquationForm::PaperEq313,
        }
    }
}

/// Integrator.
#[derive(Clone, Copy, Debug, clap::ValueEnum)]
pub enum SolverChoice {
    /// Adaptive Dormand-Prince 5(4) (default, fastest by measurement).
    Dopri,
    /// Adaptive linearly implicit Rosenbrock 2(3).
    Rosenbrock,
    /// Fixed-step RK4 (step 0.2 ms).
    Rk4,
}

/// Options shared by the subcommands that build a vehicle.
#[derive(clap::Args, Debug)]
pub struct VehicleArgs {
    /// Load condition (Table 3.1, or the description's `[yaw_plane]` case); ignored when
    /// --params is given.
    #[arg(long, value_enum, default_value = "loaded")]
    pub load: LoadChoice,
    /// Constant forward speed (km/h).
    #[arg(long, default_value_t = 50.0, allow_hyphen_values = true, value_parser = args::nonneg_f64)]
    pub speed_kmh: f64,
    /// The yaw-plane model's own parameter file (JSON, as written by `afsv params dump
    /// yaw-plane`), validated, instead of a vehicle description.
    #[arg(long)]
    pub params: Option<PathBuf>,
    #[arg(long, help = super::described::HELP, conflicts_with = "params")]
    pub vehicle: Option<PathBuf>,
    /// Form of the yaw equations.
    #[arg(long, value_enum, default_value = "energy-consistent")]
    pub form: FormChoice,
}

/// `afsv yaw` subcommands.
#[derive(clap::Subcommand, Debug)]
pub enum Command {
    /// Simulate one manoeuvre and write the record (CSV + JSON sidecar, docs/records.md format).
    Simulate {
        #[command(flatten)]
        vehicle: VehicleArgs,
        /// Steering input: `pulse[:PEAK_DEG]` (0.2 s half-sine, default 30 deg),
        /// `step:DEG`, `ramp:DEG_PER_S[:LIMIT_DEG]`, `csv:FILE:COLUMN` (a record's column in
        /// deg or rad, with `time_s`), `turn` (13.5 m steady-turn course with the driver,
        /// Fig 3.6a) or `path-change` (4.5 m / 18 m gate course, Fig 3.6b).
        #[arg(long, default_value = "pulse")]
        input: String,
        /// Input time of pulse, step and ramp (s).
        #[arg(long, default_value_t = 0.5, allow_hyphen_values = true, value_parser = args::nonneg_f64)]
        input_time: f64,
        /// Simulated time (s); at most 1e6 samples (duration/dt).
        #[arg(long, default_value_t = 10.0, allow_hyphen_values = true, value_parser = args::positive_f64)]
        duration: f64,
        /// Output sample interval (s).
        #[arg(long, default_value_t = 0.005, allow_hyphen_values = true, value_parser = args::positive_f64)]
        dt: f64,
        /// Integrator.
        #[arg(long, value_enum, default_value = "dopri")]
        solver: SolverChoice,
        /// Relative tolerance of the adaptive integrators.
        #[arg(long, default_value_t = 1e-5, allow_hyphen_values = true, value_parser = args::positive_f64)]
        rtol: f64,
        /// Output CSV file (the sidecar goes beside it with extension .json). It must not
        /// be an input; an existing file afsv did not write needs --force.
        #[arg(short = 'o', long)]
        output: PathBuf,
        /// Write only these columns, comma-separated (`time_s` always comes first), e.g.
        /// time_s,steer_wheel_deg,articulation_deg. Default: every channel and state (the
        /// names are listed in the printed `columns` of a run without this option).
        #[arg(long, value_name = "NAME,...", value_delimiter = ',')]
        columns: Vec<String>,
        /// Replace an existing output file that afsv did not write (never an input, never
        /// a foreign JSON at the sidecar's name).
        #[arg(long)]
        force: bool,
    },
    /// Yaw-mode frequency and damping (0.2 s pulse), steering gain, 0-100 % rise time,
    /// overshoot (30 deg step) and power efficiency (Eq 4.7), as JSON.
    Measures {
        #[command(flatten)]
        vehicle: VehicleArgs,
    },
    /// Sensitivity of the measures to A_0, B_eff, mu_v and k_l at -30, -15, +15, +30 %,
    /// loaded and unloaded (section 3.4.3), as JSON or a readable table.
    Sensitivity {
        /// Constant forward speed (km/h).
        #[arg(long, default_value_t = 50.0, allow_hyphen_values = true, value_parser = args::nonneg_f64)]
        speed_kmh: f64,
        /// Form of the yaw equations.
        #[arg(long, value_enum, default_value = "energy-consistent")]
        form: FormChoice,
        /// Print a readable table instead of JSON.
        #[arg(long)]
        table: bool,
        /// Vary the parameters about this vehicle description's yaw-plane data and steering
        /// (both loads) instead of Table 3.1's.
        #[arg(long, help = super::described::HELP)]
        vehicle: Option<PathBuf>,
    },
    /// Leakage effects: steady-turning articulation decay at the Table 3.2 speeds
    /// (section 3.4.1) and the gain-efficiency correlation over a leakage sweep (Fig 4.7).
    Leakage {
        /// Steering-wheel angle held in the steady turn (deg).
        #[arg(long, default_value_t = 300.0, value_parser = args::finite_f64, allow_hyphen_values = true)]
        steer_wheel_deg: f64,
        /// Run this vehicle description's yaw-plane data and steering instead of Table
        /// 3.1's (at the Table 3.2 speeds).
        #[arg(long, help = super::described::HELP)]
        vehicle: Option<PathBuf>,
    },
}

fn kmh(v: f64) -> Result<f64, String> {
    if v.is_finite() && v >= 0.0 {
        Ok(v / 3.6)
    } else {
        Err(format!("--speed-kmh must be finite and >= 0, got {v}"))
    }
}

/// Parameter set from `--params`, or the `--load` case of the `--vehicle` description (the
/// prototype's Table 3.1 columns by default).
fn load_params(v: &VehicleArgs) -> Result<YawPlaneParams, Box<dyn std::error::Error>> {
    if let Some(path) = &v.params {
        return Ok(afsv_design::param_files::read_yaw_plane(path)?);
    }
    let d = super::described::articulated(v.vehicle.as_deref())?;
    let load = match v.load {
        LoadChoice::Loaded => Load::Loaded,
        LoadChoice::Unloaded => Load::Unloaded,
    };
    let p = d.yaw_plane_params(load);
    p.validate()?;
    Ok(p)
}

fn parse_number(what: &str, s: &str) -> Result<f64, String> {
    s.parse::<f64>()
        .ok()
        .filter(|v| v.is_finite())
        .ok_or_else(|| format!("--input {what}: `{s}` is not a finite number"))
}

/// The file of a `csv:FILE:COLUMN` input specification.
fn csv_input_file(spec: &str) -> Option<&str> {
    let parts: Vec<&str> = spec.splitn(3, ':').collect();
    match parts.as_slice() {
        ["csv", file, _] => Some(file),
        _ => None,
    }
}

/// Parse the `--input` specification into a manoeuvre.
fn parse_input(
    spec: &str,
    speed: f64,
    t0: f64,
    duration: f64,
) -> Result<Manoeuvre, Box<dyn std::error::Error>> {
    let parts: Vec<&str> = spec.splitn(3, ':').collect();
    let open = |input: SteerInput, label: &str| Manoeuvre::open_loop(speed, duration, input, label);
    let m = match parts.as_slice() {
        ["pulse"] => open(SteerInput::pulse_deg(30.0, 0.2, t0), "pulse"),
        ["pulse", a] => open(
            SteerInput::pulse_deg(parse_number("pulse peak", a)?, 0.2, t0),
            "pulse",
        ),
        ["step", a] => open(SteerInput::step_deg(parse_number("step", a)?, t0), "step"),
        ["ramp", r] => open(
            SteerInput::Ramp {
                rate_rad_s: parse_number("ramp rate", r)?.to_radians(),
                start_s: t0,
                limit_rad: 720f64.to_radians(),
            },
            "ramp",
        ),
        ["ramp", r, l] => open(
            SteerInput::Ramp {
                rate_rad_s: parse_number("ramp rate", r)?.to_radians(),
                start_s: t0,
                limit_rad: parse_number("ramp limit", l)?.abs().to_radians(),
            },
            "ramp",
        ),
        ["csv", file, column] => {
            let path = Path::new(file);
            let rec = Record::read(path)?;
            let t = rec.require("time_s", path)?.to_vec();
            let col = rec.require(column, path)?;
            let scale = if column.ends_with("_deg") {
                std::f64::consts::PI / 180.0
            } else if column.ends_with("_rad") {
                1.0
            } else {
                return Err(format!(
                    "--input csv: column `{column}` must end in _deg or _rad to state its unit"
                )
                .into());
            };
            let input = SteerInput::Table {
                time_s: t,
                angle_rad: col.iter().map(|v| v * scale).collect(),
            };
            input.validate()?;
            open(input, "csv")
        }
        ["turn"] => Manoeuvre::course(
            speed,
            duration,
            PathDriver::new(Course::steady_turn_fig_3_6()),
            "steady_turn",
        ),
        ["path-change"] => Manoeuvre::course(
            speed,
            duration,
            PathDriver::new(Course::path_change_fig_3_6()),
            "path_change",
        ),
        _ => {
            return Err(format!(
                "--input `{spec}` not understood (expected pulse[:DEG], step:DEG, ramp:DEG_S[:LIMIT_DEG], csv:FILE:COLUMN, turn or path-change)"
            )
            .into())
        }
    };
    Ok(m)
}

/// The section 3.3 test definition in `form`, recording only the channels the measures
/// read (the same numbers as a full record, without the per-sample cost of the others).
fn measures_spec(form: FormChoice) -> MeasureSpec {
    let mut spec = MeasureSpec::default();
    spec.options.form = form.into();
    spec.options.recording = Recording::Measures;
    spec
}

/// Run an `afsv yaw` subcommand.
pub fn run(cmd: Command) -> CmdResult {
    match cmd {
        Command::Simulate {
            vehicle,
            input,
            input_time,
            duration,
            dt,
            solver,
            rtol,
            output,
            columns,
            force,
        } => {
            args::check_samples(
                &format!("--duration {}", args::show(duration)),
                &format!("duration/dt with --dt {}", args::show(dt)),
                duration / dt,
                args::MAX_YAW_SAMPLES,
            )?;
            let mut guard = OutputGuard::new(force);
            guard.input_if("--params", vehicle.params.as_deref())?;
            super::described::declare(&mut guard, vehicle.vehicle.as_deref())?;
            if let Some(file) = csv_input_file(&input) {
                guard.record_input("--input", Path::new(file))?;
            }
            guard.output("-o", &output, OutputKind::Record)?;
            let p = load_params(&vehicle)?;
            let speed = kmh(vehicle.speed_kmh)?;
            let sys = p.afs_system()?;
            let man = parse_input(&input, speed, input_time, duration)?;
            let opts = SimOptions {
                solver: match solver {
                    SolverChoice::Dopri => Solver::Dopri5,
                    SolverChoice::Rosenbrock => Solver::Rosenbrock23,
                    SolverChoice::Rk4 => Solver::Rk4 { step: 2e-4 },
                },
                rtol,
                atol: rtol * 0.1,
                output_dt_s: dt,
                form: vehicle.form.into(),
                ..SimOptions::default()
            };
            let rec = simulate(&p.vehicle, &sys, &man, &opts)?;
            let mut out = Record::from_selected(rec.columns(), &columns)?;
            out.meta = yaw::simulate_sidecar(&p, &man, &input, &opts, &rec);
            afsv::provenance::stamp_record(&mut out);
            out.write(&output)?;
            afsv::output::print_json(&yaw::simulate_summary(&output, out.names(), &rec))?;
        }
        Command::Measures { vehicle } => {
            let p = load_params(&vehicle)?;
            let speed = kmh(vehicle.speed_kmh)?;
            let spec = measures_spec(vehicle.form);
            let m = measures_for(&p.vehicle, &p.afs, p.load, speed, &spec)?;
            let mut v = serde_json::json!(m);
            if let Some(caveat) = m.decay_fit_caveat() {
                v["decay_fit_caveat"] = serde_json::json!(caveat);
            }
            afsv::output::print_json(&v)?;
        }
        Command::Sensitivity {
            speed_kmh,
            form,
            table,
            vehicle,
        } => {
            let spec = measures_spec(form);
            let d = super::described::articulated(vehicle.as_deref())?;
            let base = |load: Load| d.yaw_plane_params(load);
            let progress = Progress::new("afsv yaw sensitivity", "configurations", Some(34));
            let t = sensitivity_of(&base, kmh(speed_kmh)?, &spec, &|_, _| progress.step(""));
            progress.finish();
            let t = t?;
            if table {
                let form = match spec.options.form {
                    EquationForm::EnergyConsistent => "energy-consistent Eq 3.13",
                    EquationForm::PaperEq313 => "Eq 3.13 as printed",
                };
                println!(
                    "Percent change of the measures (section 3.4.3), {speed_kmh} km/h, {form}"
                );
                print!("{}", t.to_text());
            } else {
                afsv::output::print_json(&t)?;
            }
        }
        Command::Leakage {
            steer_wheel_deg,
            vehicle,
        } => {
            if !steer_wheel_deg.is_finite() {
                return Err("--steer-wheel-deg must be finite".into());
            }
            let d = super::described::articulated(vehicle.as_deref())?;
            afsv::output::print_json(&afsv_design::yaw_leakage::leakage(&d, steer_wheel_deg)?)?;
        }
    }
    Ok(())
}
