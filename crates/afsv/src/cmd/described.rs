//! `--vehicle`: which vehicle a command runs, a description file or a built-in name
//! (`afsv_design::described`, re-exported here), and the help line of the option.

pub use afsv_design::described::*;

/// The help line of every `--vehicle` option.
pub const HELP: &str = "Vehicle description (TOML, docs/vehicles.md; `afsv params dump vehicle` writes one to start from) or a built-in name (prototype, chapter2-truck)";
