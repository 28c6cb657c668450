//! `afsv params`: dump the built-in parameter sets as JSON (to edit and load back with
//! `--params`) and check a parameter file.

use super::CmdResult;
use afsv_dynamics::YawPlaneParams;
use std::path::PathBuf;

/// Parameter sets that can be dumped and checked.
#[derive(Clone, Copy, Debug, clap::ValueEnum)]
pub enum ParamSet {
    /// Yaw-plane vehicle (Table 3.1) with the hydraulic frame steering (Tables 3.1/4.1).
    #[value(name = "yaw-plane")]
    YawPlane,
}

/// `afsv params` subcommands.
#[derive(clap::Subcommand, Debug)]
pub enum Command {
    /// Print the nominal parameter set as JSON (SI units; field names carry the unit).
    Dump {
        /// Which set.
        #[arg(value_enum)]
        set: ParamSet,
        /// Load condition of the vehicle columns.
        #[arg(long, value_enum, default_value = "loaded")]
        load: super::yaw::LoadChoice,
        /// Write to this file instead of standard output; an existing file needs --force
        /// (a parameter file carries no afsv marker, so it may be the user's edited set).
        #[arg(short = 'o', long)]
        output: Option<PathBuf>,
        /// Replace an existing -o file.
        #[arg(long)]
        force: bool,
    },
    /// Read and validate a parameter file; prints `{"valid": true, ...}` or fails with
    /// the offending field.
    Check {
        /// Which set.
        #[arg(value_enum)]
        set: ParamSet,
        /// The JSON file.
        file: PathBuf,
    },
}

/// Run an `afsv params` subcommand.
pub fn run(cmd: Command) -> CmdResult {
    match cmd {
        Command::Dump {
            set,
            load,
            output,
            force,
        } => {
            if let Some(path) = &output {
                afsv::output::OutputGuard::new(force).output(
                    "-o",
                    path,
                    afsv::output::OutputKind::Other,
                )?;
            }
            let value = match set {
                ParamSet::YawPlane => serde_json::to_value(YawPlaneParams::nominal(load.into()))?,
            };
            match output {
                Some(path) => {
                    let text = serde_json::to_string_pretty(&value)? + "\n";
                    std::fs::write(&path, text).map_err(|e| format!("{}: {e}", path.display()))?;
                    afsv::output::print_json(&serde_json::json!({ "written": path }))?;
                }
                None => afsv::output::print_json(&value)?,
            }
        }
        Command::Check { set, file } => match set {
            ParamSet::YawPlane => {
                let p = super::yaw::read_params(&file)?;
                afsv::output::print_json(&serde_json::json!({
                    "valid": true,
                    "file": file,
                    "load": p.load,
                }))?;
            }
        },
    }
    Ok(())
}
