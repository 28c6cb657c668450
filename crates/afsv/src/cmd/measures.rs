//! `afsv measures`: ISO 2631-1 weightings and whole-body vibration exposure, free-decay
//! (yaw-mode) fit, step-response metrics and the weighting check (crate `perf-measures`).

use super::{args, CmdResult};
use afsv_design::record_measures;
use afsv_records::Record;
use perf_measures::iso2631::{IirWeighting, Weighting};
use std::path::PathBuf;

/// Subcommands of `afsv measures`.
#[derive(clap::Subcommand)]
pub enum Command {
    /// Print the magnitude (factor and dB) and phase of an ISO 2631-1 frequency weighting
    /// (Annex A analog transfer function) at the given frequencies, and, with --fs, the
    /// magnitude of its bilinear IIR realisation at that sampling rate.
    Weighting(WeightingArgs),
    /// Whole-body vibration assessment of a seat acceleration record (CSV with `time_s`
    /// and any of `ax_m_s2`, `ay_m_s2`, `az_m_s2`, uniformly sampled, unweighted m/s^2):
    /// per-axis weighted RMS a_w, crest factor, MTVV (1-s running RMS), VDV, the combined
    /// a_v (Eq 1.1), daily exposure A(8) for --hours against the EU 2002/44/EC action
    /// (0.5 m/s^2) and limit (1.15 m/s^2) values, and the ISO 2631-1 Annex B health
    /// guidance caution zone for that duration.
    Wbv(WbvArgs),
    /// Fit a single-DOF free decay y = c + A exp(-zeta wn t) cos(wd t + phi) to one column
    /// of a record (e.g. the articulation angle after a steering pulse) and print the
    /// natural frequency (Hz), damping ratio and fit quality. The fit starts at --start-s,
    /// or, without it, at the largest deviation from the final value.
    Decay(DecayArgs),
    /// Step-response metrics of an output column to a step in an input column (e.g.
    /// articulation_deg to steer_wheel_deg): steady gain (steady output / input step),
    /// 0-100 % rise time, percent overshoot, peak.
    Step(StepArgs),
    /// Compare every ISO 2631-1 weighting (analog, IIR at --iir-fs, frequency-domain
    /// method) with the standard's tabulated factors from 0.1 to 100 Hz (2 % tolerance).
    Check(CheckArgs),
}

/// Options of `afsv measures weighting`.
#[derive(clap::Args)]
pub struct WeightingArgs {
    /// Weighting: wk, wd, wc, we, wj or wf.
    #[arg(long, short = 'w', value_name = "W")]
    pub weighting: Weighting,
    /// Frequencies in Hz, comma separated (e.g. 0.5,1,2).
    #[arg(
        long,
        value_name = "HZ,...",
        value_delimiter = ',',
        required = true,
        allow_hyphen_values = true,
        value_parser = args::positive_f64
    )]
    pub freqs: Vec<f64>,
    /// Also report the IIR filter's magnitude at this sampling rate (Hz).
    #[arg(long, value_name = "HZ", allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub fs: Option<f64>,
}

/// Options of `afsv measures wbv`.
#[derive(clap::Args)]
pub struct WbvArgs {
    /// Input record (CSV with `time_s` and any of `ax_m_s2`, `ay_m_s2`, `az_m_s2`).
    #[arg(long, short = 'i', value_name = "CSV")]
    pub input: PathBuf,
    /// Daily exposure duration in hours for A(8) and the caution zone.
    #[arg(long, value_name = "H", default_value_t = 8.0, allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub hours: f64,
    /// Weighting of an axis, AXIS=W (repeatable), e.g. --weighting z=wk --weighting x=wd.
    /// Defaults are the seat-pan health weightings: x=wd, y=wd, z=wk.
    #[arg(long, value_name = "AXIS=W")]
    pub weighting: Vec<String>,
    /// Multiplying factors k_x,k_y,k_z of Eq 1.1 (health, seated: 1.4,1.4,1; comfort: 1,1,1).
    #[arg(
        long,
        value_name = "KX,KY,KZ",
        value_delimiter = ',',
        default_value = "1.4,1.4,1",
        allow_hyphen_values = true, value_parser = args::nonneg_f64
    )]
    pub k: Vec<f64>,
    /// Weighting method: fft (exact analog response, default) or iir (bilinear filter;
    /// accurate only well below the Nyquist frequency).
    #[arg(long, value_name = "METHOD", default_value = "fft", value_parser = ["fft", "iir"])]
    pub method: String,
    /// Column of an axis, AXIS=COLUMN (repeatable), for records whose channels have other
    /// names, e.g. --channel y=lateral_accel_front_m_s2 (a column in m/s^2, name ending
    /// in _m_s2). Default: ax_m_s2, ay_m_s2, az_m_s2.
    #[arg(long, value_name = "AXIS=COLUMN")]
    pub channel: Vec<String>,
}

/// Options of `afsv measures decay`.
#[derive(clap::Args)]
pub struct DecayArgs {
    /// Input record (CSV with `time_s`).
    #[arg(long, short = 'i', value_name = "CSV")]
    pub input: PathBuf,
    /// Column holding the decaying signal (e.g. articulation_deg).
    #[arg(long, value_name = "NAME")]
    pub column: String,
    /// Start of the free decay (s); default: the time of the largest deviation from the
    /// final value (mean of the last 10 % of the record).
    #[arg(long, value_name = "S", allow_hyphen_values = true, value_parser = args::finite_f64)]
    pub start_s: Option<f64>,
    /// End of the fitted window (s); default: end of the record.
    #[arg(long, value_name = "S", allow_hyphen_values = true, value_parser = args::finite_f64)]
    pub end_s: Option<f64>,
    /// Exit 0 even when the fit did not earn its numbers (no convergence, a residual far
    /// above the record's noise, under 1.5 cycles, an undetermined damping ratio). The
    /// problems are still printed.
    #[arg(long)]
    pub accept_poor_fit: bool,
}

/// Options of `afsv measures step`.
#[derive(clap::Args)]
pub struct StepArgs {
    /// Input record (CSV with `time_s`).
    #[arg(long, short = 'i', value_name = "CSV")]
    pub input_file: PathBuf,
    /// Input (steering) column, e.g. steer_wheel_deg.
    #[arg(long, value_name = "NAME")]
    pub input: String,
    /// Output (response) column, e.g. articulation_deg.
    #[arg(long, value_name = "NAME")]
    pub output: String,
    /// Step time (s); default: the first time the input departs from its initial value by
    /// 2 % of the step.
    #[arg(long, value_name = "S", allow_hyphen_values = true, value_parser = args::finite_f64)]
    pub t_step: Option<f64>,
    /// Step amplitude in the input column's unit; default: the mean of the input over
    /// the final --settle-fraction minus its initial value.
    #[arg(long, value_name = "X", allow_hyphen_values = true, value_parser = args::finite_f64)]
    pub amplitude: Option<f64>,
    /// Final fraction of the post-step record averaged for the steady values.
    #[arg(long, value_name = "F", default_value_t = 0.1, allow_hyphen_values = true, value_parser = args::open_fraction_f64)]
    pub settle_fraction: f64,
}

/// Options of `afsv measures check`.
#[derive(clap::Args)]
pub struct CheckArgs {
    /// Sampling rate (Hz) of the IIR filters compared.
    #[arg(long, value_name = "HZ", default_value_t = perf_measures::iso2631::check::CHECK_IIR_FS_HZ, allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub iir_fs: f64,
}

/// Run an `afsv measures` subcommand.
pub fn run(cmd: Command) -> CmdResult {
    match cmd {
        Command::Weighting(a) => weighting(a),
        Command::Wbv(a) => wbv(a),
        Command::Decay(a) => decay(a),
        Command::Step(a) => step(a),
        Command::Check(a) => {
            let c = perf_measures::weighting_check_at(a.iir_fs)?;
            afsv::output::print_json(&c)?;
            Ok(())
        }
    }
}

fn weighting(a: WeightingArgs) -> CmdResult {
    let iir = match a.fs {
        Some(fs) => Some(IirWeighting::new(a.weighting, fs)?),
        None => None,
    };
    let out =
        afsv_design::report::weighting::weighting_report(a.weighting, &a.freqs, iir.as_ref(), a.fs);
    afsv::output::print_json(&out)?;
    Ok(())
}

fn wbv(a: WbvArgs) -> CmdResult {
    let rec = Record::read(&a.input)?;
    let names = (&a.weighting[..], &a.channel[..]);
    let v = record_measures::wbv((&rec, &a.input), names, &a.k, &a.method, a.hours)?;
    afsv::output::print_json(&v)?;
    Ok(())
}

fn decay(a: DecayArgs) -> CmdResult {
    let rec = Record::read(&a.input)?;
    let window = (a.start_s, a.end_s);
    let accepted = a.accept_poor_fit;
    let (v, problems) = record_measures::decay((&rec, &a.input), &a.column, window, accepted)?;
    afsv::output::print_json(&v)?;
    Ok(afsv::output::fit_earned(
        "measures decay",
        &problems,
        accepted,
    )?)
}

fn step(a: StepArgs) -> CmdResult {
    let rec = Record::read(&a.input_file)?;
    let columns = (&a.input[..], &a.output[..]);
    let given = (a.t_step, a.amplitude);
    let file = (&rec, a.input_file.as_path());
    let v = record_measures::step(file, columns, given, a.settle_fraction)?;
    afsv::output::print_json(&v)?;
    Ok(())
}
