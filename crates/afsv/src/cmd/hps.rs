//! `afsv hps`: the hydro-pneumatic suspension strut with gas-oil emulsion (chapter 5):
//! harmonic runs with loops, the laboratory characterisation programme, parameter
//! identification from a measured record, and the struts' temperatures and ride height over a
//! shift (`thermal`, in `hps_thermal`).

use super::{args, CmdResult};
use afsv::output::{OutputGuard, OutputKind};
use afsv::progress::Progress;
use afsv_design::param_files::StrutSource;
use afsv_design::report::hps_identify::identify_report;
use afsv_design::report::strut;
use afsv_design::strut_lab::harmonic as harmonic_run;
use afsv_design::strut_lab::{characterize_each, characterize_report, identify_strut};
use afsv_records::Record;
use hps_emulsion::{
    identify, lab_programme, FitParam, HarmonicTest, HpsExtensions, IdentifyOptions, SimOptions,
    Solver,
};
use std::path::PathBuf;

/// Built-in strut parameter sets.
#[derive(Clone, Copy, Debug, clap::ValueEnum)]
pub enum StrutChoice {
    /// Front-axle strut of the articulated dump truck (Table 6.3).
    FrontAxle,
    /// Laboratory strut of chapter 5 with one bleed orifice (identified, see docs/hps-emulsion.md).
    #[value(name = "lab-1orifice")]
    Lab1Orifice,
    /// Laboratory strut of chapter 5 with two bleed orifices.
    #[value(name = "lab-2orifice")]
    Lab2Orifice,
}

impl StrutChoice {
    /// The built-in's name (`afsv_vehicle::builtin_strut`).
    pub(crate) fn name(self) -> &'static str {
        match self {
            StrutChoice::FrontAxle => "front-axle",
            StrutChoice::Lab1Orifice => "lab-1orifice",
            StrutChoice::Lab2Orifice => "lab-2orifice",
        }
    }
}

/// Integrator choice.
#[derive(Clone, Copy, Debug, clap::ValueEnum)]
pub enum SolverChoice {
    /// Dopri5 at 0.5 Hz and above, Rosenbrock23 below (measured fastest).
    Auto,
    /// Linearly implicit Rosenbrock 2(3).
    Rosenbrock,
    /// Explicit Dormand-Prince 5(4).
    Dopri,
}

impl SolverChoice {
    fn solver(self) -> Solver {
        match self {
            SolverChoice::Auto => Solver::Auto,
            SolverChoice::Rosenbrock => Solver::Rosenbrock23,
            SolverChoice::Dopri => Solver::Dopri5,
        }
    }
}

/// Subcommands of `afsv hps`.
#[derive(clap::Subcommand)]
pub enum Command {
    /// Simulate a harmonic displacement test; print the last cycle's loop metrics as JSON,
    /// optionally write the record (CSV + JSON sidecar) and an SVG of the loops.
    Harmonic(HarmonicArgs),
    /// Run the laboratory programme (0.1 Hz at 5/25/50 mm; 1-8 Hz at peak velocities
    /// 0.05-0.2356 m/s, amplitude capped at 45 mm): stiffness, damping and energy per test
    /// (a table on a terminal, JSON on a pipe or with --json, CSV with -o).
    Characterize(CharacterizeArgs),
    /// Fit model parameters to a measured strut record (CSV with time_s, displacement_m and
    /// any of force_n, p_piston_pa, p_rod_pa); print fitted values, standard errors and NRMSE.
    Identify(IdentifyArgs),
    /// Gas and strut-body temperatures of a vehicle's struts over a working shift and the
    /// ride-height drift they set, without and with a levelling valve (a table on a
    /// terminal, JSON on a pipe or with --json, CSV with -o; docs/layouts.md).
    Thermal(super::hps_thermal::ThermalArgs),
}

/// Options of `afsv hps harmonic`.
#[derive(clap::Args)]
pub struct HarmonicArgs {
    /// The strut: front-axle (Table 6.3), lab-1orifice, lab-2orifice, or a strut
    /// parameter file (JSON, `afsv params dump strut`).
    #[arg(long, default_value = "front-axle", value_parser = StrutSource::parse)]
    pub strut: StrutSource,
    /// Excitation frequency (Hz).
    #[arg(long, default_value_t = 2.0, allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub freq: f64,
    /// Excitation amplitude (mm), > 0; deflection positive in compression.
    #[arg(long = "amp-mm", default_value_t = 7.5, allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub amp_mm: f64,
    /// Number of cycles simulated (metrics are from the last); at most 1e6 samples
    /// (cycles / freq * rate).
    #[arg(long, default_value_t = 5.0, allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub cycles: f64,
    /// Gas volume fraction of the emulsion, e.g. 0.03 (gas moved from the free gas volume).
    #[arg(long, allow_hyphen_values = true, value_parser = args::nonneg_f64)]
    pub gamma0: Option<f64>,
    /// Output sample rate of the record (Hz).
    #[arg(long, default_value_t = 360.0, allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub rate: f64,
    /// Integrator.
    #[arg(long, value_enum, default_value = "auto")]
    pub solver: SolverChoice,
    /// Write the record here (CSV; a JSON sidecar is written beside it).
    #[arg(short = 'o', long = "output")]
    pub output: Option<PathBuf>,
    /// Draw pressure-deflection, force-deflection, force-velocity and damping-force loops (SVG).
    #[arg(long)]
    pub plot: Option<PathBuf>,
    /// Replace existing output files afsv did not write (never a foreign JSON at the
    /// sidecar's name).
    #[arg(long)]
    pub force: bool,
}

/// Options of `afsv hps characterize`.
#[derive(clap::Args)]
pub struct CharacterizeArgs {
    /// The strut: lab-1orifice (chapter 5), lab-2orifice, front-axle (Table 6.3), or a
    /// strut parameter file (JSON, `afsv params dump strut`).
    #[arg(long, default_value = "lab-1orifice", value_parser = StrutSource::parse)]
    pub strut: StrutSource,
    /// Gas volume fraction of the emulsion, e.g. 0.03.
    #[arg(long, allow_hyphen_values = true, value_parser = args::nonneg_f64)]
    pub gamma0: Option<f64>,
    /// Replace an existing -o file afsv did not write (never the --strut file).
    #[arg(long)]
    pub force: bool,
    #[command(flatten)]
    pub table: afsv::table::TableOutput,
}

/// Options of `afsv hps identify`.
#[derive(clap::Args)]
pub struct IdentifyArgs {
    /// Measured record (CSV; sidecar `.json` beside it is honoured).
    #[arg(short = 'i', long = "input")]
    pub input: PathBuf,
    /// Parameters to fit, comma-separated, from: n, fc, fs, muv, gamma0, cb, cv, kl.
    #[arg(long, default_value = "n,gamma0,cb")]
    pub fit: String,
    /// Strut whose other parameters are taken as known (and start values): a built-in
    /// (front-axle, lab-1orifice, lab-2orifice) or a strut parameter file. Default: the
    /// `"strut"` named in the record's sidecar; without either it is an error (a guessed
    /// strut fits nothing). A built-in --strut that differs from the sidecar's is an error.
    #[arg(long, value_parser = StrutSource::parse)]
    pub strut: Option<StrutSource>,
    /// Simulate but do not compare the first seconds (start-up transient), >= 0.
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true, value_parser = args::nonneg_f64)]
    pub warmup: f64,
    /// Exit 0 even when the fit did not earn its result (a parameter on its bound, a fit
    /// worse than its start, no convergence, a residual far above the record's noise, a
    /// pressure one atmosphere off, a noisy differentiated velocity). The problems are
    /// still printed.
    #[arg(long)]
    pub accept_poor_fit: bool,
}

/// Run `afsv hps ...`.
pub fn run(cmd: Command) -> CmdResult {
    match cmd {
        Command::Harmonic(a) => harmonic(a),
        Command::Characterize(a) => characterize_cmd(a),
        Command::Identify(a) => identify_cmd(a),
        Command::Thermal(a) => super::hps_thermal::run(a),
    }
}

fn harmonic(a: HarmonicArgs) -> CmdResult {
    args::check_cycles(a.cycles, a.freq, a.rate)?;
    let mut guard = OutputGuard::new(a.force);
    guard.input_if("--strut", a.strut.file())?;
    guard.output_if("-o", a.output.as_deref(), OutputKind::Record)?;
    guard.output_if("--plot", a.plot.as_deref(), OutputKind::Svg)?;
    let params = a.strut.params_with_gamma0(a.gamma0)?;
    let test = HarmonicTest {
        frequency_hz: a.freq,
        amplitude_m: a.amp_mm * 1e-3,
    };
    let opts = SimOptions {
        output_rate_hz: a.rate,
        solver: a.solver.solver(),
        ..SimOptions::default()
    };
    let (rec, metrics) = harmonic_run(&params, &test, a.cycles, &opts)?;
    if let Some(path) = &a.output {
        let meta = strut::harmonic_sidecar(&strut::HarmonicRun {
            strut: a.strut.name(),
            gamma0: params.gamma0,
            sample_rate_hz: a.rate,
            frequency_hz: a.freq,
            amplitude_m: test.amplitude_m,
            cycles: a.cycles,
        });
        afsv::provenance::write_record(path, Record::from_columns(rec.columns())?, meta)?;
    }
    if let Some(path) = &a.plot {
        let record = match &a.output {
            Some(csv) => format!("record {}", csv.display()),
            None => "simulated (no record written)".to_string(),
        };
        let conditions = format!(
            "{record}, {} strut, gamma0 {:.3}, {} Hz, {} mm amplitude",
            a.strut.name(),
            params.gamma0,
            args::show(a.freq),
            args::show(a.amp_mm)
        );
        let chart = afsv_design::figures::strut::loops(&rec, &test, &conditions)
            .map_err(|e| format!("{}: {e}", path.display()))?;
        super::write_chart(path, &chart)?;
    }
    afsv::output::print_json(&serde_json::json!({
        "strut": a.strut.name(),
        "gamma0": params.gamma0,
        "last_cycle": metrics,
    }))?;
    Ok(())
}

fn characterize_cmd(a: CharacterizeArgs) -> CmdResult {
    let mut guard = afsv::output::OutputGuard::new(a.force);
    guard.input_if("--strut", a.strut.file())?;
    a.table.declare(&mut guard)?;
    let params = a.strut.params_with_gamma0(a.gamma0)?;
    let tests = lab_programme(params.travel);
    let progress = Progress::new("afsv hps characterize", "tests", Some(tests.len()));
    let rows = characterize_each(&params, &tests, &|t| {
        let (f, amp_mm) = (args::show(t.frequency_hz), t.amplitude_m * 1e3);
        progress.step(&format!("{f} Hz, {amp_mm:.1} mm"));
    })?;
    progress.finish();
    let (table, full, summary, meta) = characterize_report(a.strut.name(), params.gamma0, &rows)?;
    let written_by = "afsv hps characterize";
    a.table.emit(&table, &full, &summary, written_by, meta)
}

fn identify_cmd(a: IdentifyArgs) -> CmdResult {
    let which = FitParam::parse_list(&a.fit)?;
    let progress = Progress::new("afsv hps identify", "steps", Some(2));
    let rec = Record::read(&a.input)?;
    let meas = strut::measured(&rec, &a.input)?;
    let opts = IdentifyOptions {
        warmup_s: a.warmup,
        ..IdentifyOptions::default()
    };
    let (strut, strut_source) = identify_strut(a.strut.as_ref(), &a.input, &rec.meta)?;
    let start = strut.params()?;
    progress.step(&format!("read {} samples", meas.time.len()));
    let res = identify(&meas, &start, &HpsExtensions::none(), &which, &opts)
        .map_err(|e| format!("{}: {e}", a.input.display()))?;
    progress.step(&format!("fitted in {} iterations", res.iterations));
    progress.finish();
    let (report, problems) = identify_report(
        &res,
        &a.input.display().to_string(),
        strut.name(),
        strut_source,
        a.accept_poor_fit,
    );
    afsv::output::print_json(&report)?;
    Ok(afsv::output::fit_earned(
        "hps identify",
        &problems,
        a.accept_poor_fit,
    )?)
}
