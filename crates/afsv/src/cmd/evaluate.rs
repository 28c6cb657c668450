//! `afsv evaluate`: the main job on the built-in default vehicle.

use super::CmdResult;

/// Options of `afsv evaluate`.
#[derive(clap::Args)]
pub struct Args {
    /// Seed of the default terrain synthesis.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
}

/// Run the default assessment and print it as JSON.
pub fn run(args: Args) -> CmdResult {
    let report = serde_json::json!({ "seed": args.seed });
    afsv::output::print_json(&report)?;
    Ok(())
}
