//! Value parsers for numeric options, shared by every subcommand (the number rules are
//! `afsv_design::value_lists`'s, re-exported): a number that is not finite (nan, inf), or
//! out of the option's range, is refused when the command line is parsed, with a one-line
//! message naming the value and the rule; sample bounds of a run
//! (`afsv_design::sample_bounds`, re-exported).
//!
//! Use as `#[arg(long, allow_hyphen_values = true, value_parser = args::positive_f64)]`.

pub use afsv_design::report::show;
pub use afsv_design::sample_bounds::*;
pub use afsv_design::value_lists::{
    finite_f64, fraction_f64, nonneg_f64, open_fraction_f64, positive_f64,
};

/// `--json` of the commands whose JSON a terminal asks for explicitly (a pipe always gets
/// JSON).
#[derive(clap::Args, Debug, Clone, Copy, Default)]
pub struct JsonOutput {
    /// Print JSON even on a terminal.
    #[arg(long)]
    pub json: bool,
}
