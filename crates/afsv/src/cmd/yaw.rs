//! `afsv yaw`: the yaw-plane AFSV model with hydraulic frame steering (chapters 3-4):
//! simulate a manoeuvre into a record, the yaw-plane measures, the sensitivity table and
//! the leakage analyses.

use super::{args, CmdResult};
use afsv::output::{OutputGuard, OutputKind};
use afsv::progress::Progress;
use afsv_design::report::yaw;
use afsv_design::yaw_manoeuvre::{self, measures_spec, speed_m_s, yaw_plane_params, RK4_STEP_S};
use afsv_dynamics::yaw_plane::analysis::{measures_for, sensitivity_of};
use afsv_dynamics::{simulate, EquationForm, Load, Solver, YawPlaneParams};
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
        /// (both loads) instead of Table 3.1's: a description file (TOML, docs/vehicles.md) or
        /// a built-in name (prototype, chapter2-truck).
        #[arg(long)]
        vehicle: Option<PathBuf>,
    },
    /// Leakage effects: steady-turning articulation decay at the Table 3.2 speeds
    /// (section 3.4.1) and the gain-efficiency correlation over a leakage sweep (Fig 4.7).
    Leakage {
        /// Steering-wheel angle held in the steady turn (deg).
        #[arg(long, default_value_t = 300.0, value_parser = args::finite_f64, allow_hyphen_values = true)]
        steer_wheel_deg: f64,
        /// Run this vehicle description's yaw-plane data and steering instead of Table
        /// 3.1's (at the Table 3.2 speeds): a description file (TOML, docs/vehicles.md) or a
        /// built-in name (prototype, chapter2-truck).
        #[arg(long)]
        vehicle: Option<PathBuf>,
    },
}

/// Parameter set from `--params`, or the `--load` case of the `--vehicle` description.
fn load_params(v: &VehicleArgs) -> Result<YawPlaneParams, String> {
    yaw_plane_params(v.params.as_deref(), v.vehicle.as_deref(), v.load.into())
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
            args::check_duration(duration, dt, args::MAX_YAW_SAMPLES)?;
            let mut guard = OutputGuard::new(force);
            guard.input_if("--params", vehicle.params.as_deref())?;
            super::described::declare(&mut guard, vehicle.vehicle.as_deref())?;
            if let Some(file) = yaw_manoeuvre::csv_input_file(&input) {
                guard.record_input("--input", Path::new(file))?;
            }
            guard.output("-o", &output, OutputKind::Record)?;
            let p = load_params(&vehicle)?;
            let speed = speed_m_s(vehicle.speed_kmh)?;
            let sys = p.afs_system()?;
            let man = yaw_manoeuvre::manoeuvre(&input, speed, input_time, duration)?;
            let solver = match solver {
                SolverChoice::Dopri => Solver::Dopri5,
                SolverChoice::Rosenbrock => Solver::Rosenbrock23,
                SolverChoice::Rk4 => Solver::Rk4 { step: RK4_STEP_S },
            };
            let opts = yaw_manoeuvre::sim_options(solver, rtol, dt, vehicle.form.into());
            let rec = simulate(&p.vehicle, &sys, &man, &opts)?;
            let meta = yaw::simulate_sidecar(&p, &man, &input, &opts, &rec);
            let selected = Record::from_selected(rec.columns(), &columns)?;
            let out = afsv::provenance::write_record(&output, selected, meta)?;
            afsv::output::print_json(&yaw::simulate_summary(&output, out.names(), &rec))?;
        }
        Command::Measures { vehicle } => {
            let p = load_params(&vehicle)?;
            let speed = speed_m_s(vehicle.speed_kmh)?;
            let spec = measures_spec(vehicle.form.into());
            let m = measures_for(&p.vehicle, &p.afs, p.load, speed, &spec)?;
            afsv::output::print_json(&yaw::measures_json(&m))?;
        }
        Command::Sensitivity {
            speed_kmh,
            form,
            table,
            vehicle,
        } => {
            let spec = measures_spec(form.into());
            let d = super::described::articulated(vehicle.as_deref())?;
            let base = |load: Load| d.yaw_plane_params(load);
            let progress = Progress::new("afsv yaw sensitivity", "configurations", Some(34));
            let t = sensitivity_of(&base, speed_m_s(speed_kmh)?, &spec, &|_, _| {
                progress.step("")
            });
            progress.finish();
            let t = t?;
            if table {
                let form = yaw_manoeuvre::form_text(spec.options.form);
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
            let d = super::described::articulated(vehicle.as_deref())?;
            afsv::output::print_json(&afsv_design::yaw_leakage::leakage(&d, steer_wheel_deg)?)?;
        }
    }
    Ok(())
}
