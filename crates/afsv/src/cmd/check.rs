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

/// Options of `afsv check`.
#[derive(clap::Args)]
pub struct Args {
    /// Seed of the terrain synthesis that is checked.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    #[command(flatten)]
    pub output: super::args::JsonOutput,
}

/// Run the self-checks and print them.
pub fn run(args: Args) -> CmdResult {
    let weighting = perf_measures::weighting_check();
    let terrain = terrain_psd::default_terrain_summary(args.seed);
    let fidelity = terrain.fidelity();
    let pass = weighting.pass && fidelity.pass;
    let v = json!({
        "pass": pass,
        "iso2631_weighting": weighting,
        "terrain_synthesis": { "fidelity": fidelity, "summary": terrain },
    });
    afsv::output::print_json_or_text(args.output.json, &v, || {
        afsv_design::report::check::to_text(&weighting, &fidelity, args.seed)
    })?;
    if pass {
        Ok(())
    } else {
        Err("a self-check failed (see the report above)".into())
    }
}
