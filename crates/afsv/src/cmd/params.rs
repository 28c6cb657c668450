//! `afsv params`: dump the built-in parameter sets as JSON (to edit and load back with
//! `--params`), check a parameter file, and list a set's named parameters with units and
//! bounds. Every set rejects unknown fields and names the line and column of a bad value.

use super::hps::StrutChoice;
use super::CmdResult;
use afsv_design::param_files;
use afsv_design::report::params::list_text;
use serde_json::json;
use std::path::{Path, PathBuf};

/// Parameter sets that can be dumped, checked and listed.
#[derive(Clone, Copy, Debug, clap::ValueEnum)]
pub enum ParamSet {
    /// Yaw-plane vehicle (Table 3.1) with the hydraulic frame steering (Tables 3.1/4.1).
    #[value(name = "yaw-plane")]
    YawPlane,
    /// Hydro-pneumatic strut (Table 6.3 front axle, or the chapter 5 laboratory strut).
    Strut,
    /// Tire (Fiala handling, vertical contact, enveloping).
    Tire,
    /// Two-track terrain synthesis (PSD, band, coherence).
    Terrain,
    /// Terrain surface (track width, friction).
    Surface,
    /// The rigid mining truck of chapter 2 (Tables 2.1-2.3 and the documented assumptions).
    Truck,
    /// The 3-D articulated vehicle of chapter 6 (Table 6.1, tire, steering, front-axle
    /// strut, drive, and the documented assumptions; missing fields take the nominal value).
    #[value(name = "vehicle-3d")]
    Vehicle3d,
    /// The operator's suspension seat on the cab floor (the generic seat; docs/layouts.md
    /// "Cab and seat suspension"; the optional cushion is not a named parameter).
    Seat,
    /// The cab on its four elastomer mounts (the generic cab; docs/layouts.md).
    Cab,
    /// A whole vehicle description (TOML, docs/vehicles.md): units, joint, axles with
    /// tires and suspensions, steering, drive; the file every `--vehicle` option reads.
    Vehicle,
}

/// `afsv params` subcommands.
#[derive(clap::Subcommand, Debug)]
pub enum Command {
    /// Print the nominal parameter set as JSON (SI units; field names carry the unit).
    Dump {
        /// Which set.
        #[arg(value_enum)]
        set: ParamSet,
        /// Load condition of the vehicle columns (yaw-plane).
        #[arg(long, value_enum, default_value = "loaded")]
        load: super::yaw::LoadChoice,
        /// Which built-in strut (strut).
        #[arg(long, value_enum, default_value = "front-axle")]
        strut: StrutChoice,
        /// Which built-in vehicle (vehicle): prototype or chapter2-truck.
        #[arg(long, default_value = "prototype")]
        builtin: String,
        /// Write to this file instead of standard output; an existing file needs --force
        /// (a parameter file carries no afsv marker, so it may be the user's edited set).
        #[arg(short = 'o', long)]
        output: Option<PathBuf>,
        /// Replace an existing -o file.
        #[arg(long)]
        force: bool,
    },
    /// Read and validate a parameter file; prints `{"valid": true, ...}` or fails with
    /// the offending field (unknown fields are refused).
    Check {
        /// Which set.
        #[arg(value_enum)]
        set: ParamSet,
        /// The JSON file (TOML for a vehicle description).
        file: PathBuf,
    },
    /// List the named parameters of a set: name, unit, bounds, typical size and nominal
    /// value (the names that fits, sensitivity studies and designs use); for `vehicle`,
    /// the built-in vehicle descriptions.
    List {
        /// Which set.
        #[arg(value_enum)]
        set: ParamSet,
        /// Print JSON, also on a terminal (a pipe always gets JSON).
        #[arg(long)]
        json: bool,
    },
}

/// Run an `afsv params` subcommand.
pub fn run(cmd: Command) -> CmdResult {
    match cmd {
        Command::Dump {
            set,
            load,
            strut,
            builtin,
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
                ParamSet::Vehicle => return dump_vehicle(&builtin, output.as_deref()),
                _ => param_files::nominal(&set_name(set), load.into(), strut.name())?,
            };
            match output {
                Some(path) => {
                    afsv::output::write_json_file(&path, &value)?;
                    afsv::output::print_json(&json!({ "written": path }))?;
                }
                // a parameter file, read back as it is printed (`params dump strut > s.json`
                // then `--hps s.json`): no provenance key, which the reader would refuse
                None => println!("{}", serde_json::to_string_pretty(&value)?),
            }
        }
        Command::Check { set, file } => {
            let mut report = param_files::check(&set_name(set), &file)?;
            report["valid"] = json!(true);
            report["file"] = json!(file);
            afsv::output::print_json(&report)?;
        }
        Command::List { set, json } => {
            let list = param_files::list(&set_name(set))?;
            afsv::output::print_json_or_text(json, &list, || list_text(&list))?;
        }
    }
    Ok(())
}

/// `afsv params dump vehicle`: the built-in description `name` as commented TOML, to
/// standard output or (through a temporary file) to `output`.
fn dump_vehicle(name: &str, output: Option<&Path>) -> CmdResult {
    let text = param_files::builtin_vehicle_toml(name)?;
    match output {
        Some(path) => {
            afsv::output::write_file(path, text)?;
            afsv::output::print_json(&json!({ "written": path }))?;
        }
        None => print!("{text}"),
    }
    Ok(())
}

/// The name of `set` on the command line (its clap value), as `afsv_design::param_files`
/// takes it.
fn set_name(set: ParamSet) -> String {
    clap::ValueEnum::to_possible_value(&set).map_or_else(String::new, |v| v.get_name().into())
}
