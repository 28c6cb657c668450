//! `afsv check`: the toolkit's self-checks, apart from the vehicle assessment.
//!
//! - ISO 2631-1 frequency weightings (analog, IIR and FFT realisations) against the
//!   standard's Tables 3 and 4 within 2 %;
//! - the terrain synthesis of the default vehicle's terrain: PSD, coherence, variance and
//!   Parseval against their targets (`terrain_psd::Summary::fidelity`).
//!
//! Text on a terminal, JSON with `--json` or when stdout is not a terminal. The exit code is
//! non-zero when a check fails.

use super::CmdResult;
use serde_json::json;
use std::io::IsTerminal;

/// Options of `afsv check`.
#[derive(clap::Args)]
pub struct Args {
    /// Seed of the terrain synthesis that is checked.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Print JSON even on a terminal.
    #[arg(long)]
    pub json: bool,
}

/// Run the self-checks and print them.
pub fn run(args: Args) -> CmdResult {
    let weighting = perf_measures::weighting_check();
    let terrain = terrain_psd::default_terrain_summary(args.seed);
    let fidelity = terrain.fidelity();
    let pass = weighting.pass && fidelity.pass;
    if args.json || !std::io::stdout().is_terminal() {
        afsv::output::print_json(&json!({
            "pass": pass,
            "iso2631_weighting": weighting,
            "terrain_synthesis": { "fidelity": fidelity, "summary": terrain },
        }))?;
    } else {
        print!("{}", to_text(&weighting, &fidelity, args.seed));
    }
    if pass {
        Ok(())
    } else {
        Err("a self-check failed (see the report above)".into())
    }
}

fn verdict(pass: bool) -> &'static str {
    if pass {
        "pass"
    } else {
        "FAIL"
    }
}

fn to_text(w: &perf_measures::WeightingCheck, f: &terrain_psd::Fidelity, seed: u64) -> String {
    let mut s = format!(
        "ISO 2631-1 weightings against {} (limit {} %): {}\n",
        w.reference,
        w.tolerance_percent,
        verdict(w.pass)
    );
    s += &format!(
        "  {:<10} {:>6} {:>12} {:>12} {:>12}\n",
        "weighting", "bands", "analog (%)", "IIR (%)", "FFT (%)"
    );
    for e in &w.weightings {
        s += &format!(
            "  {:<10} {:>6} {:>12.2} {:>12.2} {:>12.2}  {}\n",
            format!("{:?}", e.weighting).to_lowercase(),
            e.bands,
            e.max_analog_error_percent,
            e.max_iir_error_percent,
            e.max_fft_error_percent,
            verdict(e.pass)
        );
    }
    s += &format!(
        "\nTerrain synthesis (default terrain, seed {seed}): {}\n",
        verdict(f.pass)
    );
    for c in &f.criteria {
        let dev = if c.deviation.is_finite() {
            format!("{:+.3}", c.deviation)
        } else {
            "n/a".to_string()
        };
        s += &format!(
            "  {:<36} {:>9}  (limit ±{})  {}\n",
            c.name,
            dev,
            c.limit,
            verdict(c.pass)
        );
    }
    s
}
