//! `afsv terrain`: two-track terrain synthesis and spectral estimates (crate `terrain-psd`).

use super::{args, CmdResult};
use afsv::output::{OutputGuard, OutputKind};
use afsv::progress::Progress;
use afsv_design::report::terrain::{
    generated_record, generated_sidecar, generated_summary, psd_analysis, psd_summary, Generated,
};
use afsv_design::terrain_choice::{self, coherence_model, psd_model, psd_table, welch_config};
use afsv_records::Record;
use serde_json::json;
use std::path::{Path, PathBuf};
use terrain_psd::{synthesize, TwoTrackSpec};

/// Track width of the 35-t AFSV (Table 6.1), the default for the cross-slope PSD.
const DEFAULT_TRACK_WIDTH_M: f64 = terrain_psd::summary::AFSV_TRACK_WIDTH_M;

/// Subcommands of `afsv terrain`.
#[derive(clap::Subcommand)]
pub enum Command {
    /// Synthesize left/right terrain profiles whose PSD and coherence follow a model
    ///
    /// The displacement PSD is G_d(n) = alpha_r n^-w (Eq 2.8) on the band
    /// [n_min, n_max] (zero outside), chosen with one of --class, --terrain or
    /// --alpha/--waviness (default: ISO 8608 class E, the paper's nominal off-road terrain,
    /// section 6.2.3). The coherence of the two tracks follows --coherence. Profiles come
    /// from random-phase spectral synthesis (see docs/terrain-psd.md): their expected PSD and
    /// coherence equal the targets on every synthesized line. Same seed, same bytes.
    ///
    /// Output: with -o FILE, writes CSV columns x_m,left_m,right_m (x_i = i dx, elevations
    /// in m) plus a JSON sidecar beside it (FILE with extension .json) that records the model,
    /// and prints a short JSON summary on stdout. Without -o, prints one JSON object with
    /// the model and the arrays x_m, left_m, right_m on stdout.
    #[command(verbatim_doc_comment)]
    Generate(GenerateArgs),
    /// Estimate the PSDs, cross-spectrum, coherence and cross-slope PSD of a profile file
    ///
    /// Reads a CSV with columns x_m (uniformly spaced), left_m and optionally right_m (as
    /// written by `afsv terrain generate -o`) and reports (a table on a terminal, JSON on a
    /// pipe or with --json, every bin as CSV with -o) Welch one-sided PSDs
    /// (m^3 = m^2/(cycle/m)), and with right_m also the cross-spectral density (conj(L) R),
    /// the magnitude-squared coherence (Eq 2.9) and the PSD of the cross-slope angle
    /// (left - right)/B in rad^2/(cycle/m) (roll excitation, Fig 2.7), on frequencies
    /// n_cycles_per_m. When the file's sidecar records the model (generate -o writes it),
    /// the targets and the band-averaged errors are included under "target".
    #[command(verbatim_doc_comment)]
    Psd(PsdArgs),
}

/// Options of `afsv terrain generate`.
#[derive(clap::Args)]
#[command(allow_negative_numbers = true)]
pub struct GenerateArgs {
    /// ISO 8608 class A-H: G_d(n0 = 0.1 cycles/m) = 16e-6 * 4^k m^3 (A 16e-6, B 64e-6,
    /// C 256e-6, D 1024e-6, E 4096e-6, F 16384e-6, G 65536e-6, H 262144e-6), waviness 2,
    /// i.e. alpha_r = G_d(n0) * 0.01 (Table 2.4 for A-E). Default: E.
    #[arg(long, value_name = "A..H")]
    pub class: Option<String>,
    /// Off-road terrain of Tables 1.2/2.4: forestry (alpha_r 1.00e-4, w 1.76), pasture
    /// (3.00e-4, 1.60), mvee (3.16e-4, 2.27) or plowed (6.50e-4, 1.60).
    #[arg(long, value_name = "NAME")]
    pub terrain: Option<String>,
    /// Roughness coefficient alpha_r > 0 of G_d(n) = alpha_r n^-w (Eq 2.8), n in cycles/m,
    /// G_d in m^3 (4.096e-5 is class E); requires --waviness.
    #[arg(long, value_name = "ALPHA_R", allow_hyphen_values = true, value_parser = args::finite_f64)]
    pub alpha: Option<f64>,
    /// Waviness w of Eq 2.8, 0 <= w <= 10 (ISO 8608: 2); requires --alpha.
    #[arg(long, value_name = "W", allow_hyphen_values = true, value_parser = args::nonneg_f64)]
    pub waviness: Option<f64>,
    /// Spatial band N_MIN,N_MAX in cycles/m outside which the PSD is zero
    /// (0 < N_MIN < N_MAX <= 1/(2 dx)).
    #[arg(long, value_name = "N_MIN,N_MAX", default_value = "0.02,5")]
    pub band: String,
    /// Coherence of the two tracks: piecewise:M_C (Eq 2.10/6.5, gamma^2 = 1 - 0.9 n/M_C up
    /// to M_C cycles/m, 0.1 above), bogsjo:RHO (Eq 1.9, gamma = exp(-2 RHO T n), needs
    /// --half-track), zhang (Eq 1.8, 1 - 0.45 f up to f = n u = 2 Hz, 0.1 above, needs
    /// --speed), full (identical tracks) or none (independent tracks).
    #[arg(long, value_name = "MODEL", default_value = "piecewise:0.3")]
    pub coherence: String,
    /// Half-track width T in m for --coherence bogsjo:RHO (e.g. 1.14 for the 2.28 m track
    /// of Table 6.1).
    #[arg(long, value_name = "M", allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub half_track: Option<f64>,
    /// Forward speed u in m/s for --coherence zhang (50 km/h = 13.89 m/s).
    #[arg(long, value_name = "M_PER_S", allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub speed: Option<f64>,
    /// Profile length in m; samples x_i = i dx for i = 0..=round(length/dx), at most 1e7.
    #[arg(long, value_name = "M", default_value_t = 100.0, allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub length: f64,
    /// Sample spacing dx in m.
    #[arg(long, value_name = "M", default_value_t = 0.05, allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub dx: f64,
    /// Seed of the random phases (ChaCha8); the same seed gives the same profile.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Write the profile as CSV (x_m,left_m,right_m) to this file and the model to the
    /// sidecar FILE.json; stdout then gets a short JSON summary.
    #[arg(short, long, value_name = "FILE")]
    pub output: Option<PathBuf>,
    /// Replace an existing -o file afsv did not write (never a foreign JSON at the
    /// sidecar's name).
    #[arg(long)]
    pub force: bool,
}

/// Options of `afsv terrain psd`.
#[derive(clap::Args)]
#[command(allow_negative_numbers = true)]
pub struct PsdArgs {
    /// Profile CSV with columns x_m, left_m and optionally right_m.
    #[arg(short, long, value_name = "FILE")]
    pub input: PathBuf,
    /// Welch segment length in m (rounded to whole samples; frequency resolution is
    /// 1/segment). Default: the largest power-of-two number of samples <= 1/8 of the
    /// record (>= 15 half-overlapping segments).
    #[arg(long, value_name = "M", allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub segment_m: Option<f64>,
    /// Fractional overlap of consecutive segments, 0 <= overlap < 1.
    #[arg(long, value_name = "FRACTION", default_value_t = 0.5, allow_hyphen_values = true, value_parser = args::fraction_f64)]
    pub overlap: f64,
    /// Segment window: hann (periodic Hann) or rectangular.
    #[arg(long, value_name = "WINDOW", default_value = "hann")]
    pub window: String,
    /// Per-segment detrending: none, mean or linear.
    #[arg(long, value_name = "DETREND", default_value = "mean")]
    pub detrend: String,
    /// Track width B in m for the cross-slope angle (left - right)/B (default: the 2.28 m
    /// track of the 35-t AFSV, Table 6.1).
    #[arg(long, value_name = "M", default_value_t = DEFAULT_TRACK_WIDTH_M, allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub track_width: f64,
    /// Report only frequencies N_MIN <= n <= N_MAX (cycles/m); default: all bins from 0 to
    /// the Nyquist frequency 1/(2 dx).
    #[arg(long, value_name = "N_MIN,N_MAX")]
    pub band: Option<String>,
    /// Replace an existing -o file afsv did not write (never the input).
    #[arg(long)]
    pub force: bool,
    #[command(flatten)]
    pub table: afsv::table::TableOutput,
}

/// Run `afsv terrain ...`.
pub fn run(cmd: Command) -> CmdResult {
    match cmd {
        Command::Generate(a) => generate(a),
        Command::Psd(a) => psd(a),
    }
}

/// Profiles of at least this many samples report progress on stderr.
const LONG_PROFILE_SAMPLES: f64 = 1e6;

fn generate(a: GenerateArgs) -> CmdResult {
    args::check_profile(a.length, a.dx)?;
    if let Some(path) = &a.output {
        OutputGuard::new(a.force).output("-o", path, OutputKind::Record)?;
    }
    let power_law = (a.alpha, a.waviness);
    let (psd, model) = psd_model(a.class.as_deref(), a.terrain.as_deref(), power_law)?;
    let band = terrain_choice::band(&a.band)?;
    let coherence = coherence_model(&a.coherence, a.half_track, a.speed)?;
    let spec = TwoTrackSpec::new(psd, band, coherence)?;
    // A long profile takes seconds to synthesise and write: report the two stages.
    let progress = (a.length / a.dx >= LONG_PROFILE_SAMPLES)
        .then(|| Progress::new("afsv terrain generate", "stages", Some(2)));
    let prof = synthesize(&spec, a.length, a.dx, a.seed)?;
    if let Some(p) = &progress {
        p.step("synthesised");
    }
    let g = Generated {
        model: &model,
        spec: &spec,
        seed: a.seed,
        dx_m: a.dx,
        profile: &prof,
    };
    let meta = generated_sidecar(&g);
    if let Some(path) = &a.output {
        let mut rec = generated_record(&g, meta.clone())?;
        afsv::provenance::stamp_record(&mut rec);
        rec.write(path)?;
        if let Some(p) = &progress {
            p.step("written");
            p.finish();
        }
    }
    afsv::output::print_json(&generated_summary(&g, meta, a.output.as_deref()))?;
    if let (None, Some(p)) = (&a.output, &progress) {
        p.step("printed");
        p.finish();
    }
    Ok(())
}

/// Uniform spacing of the `x_m` column ([`terrain_psd::uniform_spacing`]).
fn spacing(x: &[f64], path: &Path) -> Result<f64, String> {
    terrain_psd::uniform_spacing(x).map_err(|e| format!("{}: x_m: {e}", path.display()))
}

fn psd(a: PsdArgs) -> CmdResult {
    let mut guard = OutputGuard::new(a.force);
    guard.record_input("--input", &a.input)?;
    let table_out = &a.table;
    table_out.declare(&mut guard)?;
    let rec = Record::read(&a.input)?;
    let x = rec.require("x_m", &a.input)?;
    let left = rec.require("left_m", &a.input)?;
    let right = rec.column("right_m");
    let dx = spacing(x, &a.input)?;
    let names = (&a.window[..], &a.detrend[..]);
    let cfg = welch_config((left.len(), dx, &a.input), a.segment_m, a.overlap, names)?;
    let band = a.band.as_deref().map(terrain_choice::band).transpose()?;
    let (mut out, spectrum) = psd_analysis(
        &a.input.display().to_string(),
        (left, right),
        dx,
        &cfg,
        band,
        a.track_width,
        &rec.meta,
    )?;
    let table = psd_table(&out, &spectrum)?;
    let summary = psd_summary(&out);
    out["spectrum"] = spectrum;
    table_out.emit(
        &table,
        &out,
        &summary,
        "afsv terrain psd",
        json!({ "input": a.input.display().to_string(), "welch": out["welch"] }),
    )?;
    Ok(())
}
