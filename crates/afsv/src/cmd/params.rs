//! `afsv params`: dump the built-in parameter sets as JSON (to edit and load back with
//! `--params`), check a parameter file, and list a set's named parameters with units and
//! bounds. Every set rejects unknown fields and names the line and column of a bad value.

use super::hps::StrutChoice;
use super::CmdResult;
pub(super) use afsv_design::report::params::vehicle_3d_in_ranges;
use afsv_design::report::params::{check_vehicle, list_text, named, specs};
use afsv_dynamics::YawPlaneParams;
use hps_emulsion::StrutParams;
use roll_truck::TruckParams;
use serde_json::{json, Value};
use std::path::{Path, PathBuf};
use terrain_psd::{SurfaceParams, TwoTrackSpec};
use tire_fiala::TireParams;
use vehicle_3d::VehicleParams;
use vehicle_components::ParamSet as Named;
use vehicle_components::{CabParams, SeatParams};

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
                ParamSet::YawPlane => serde_json::to_value(YawPlaneParams::nominal(load.into()))?,
                ParamSet::Strut => serde_json::to_value(strut.params())?,
                ParamSet::Tire => serde_json::to_value(TireParams::nominal())?,
                ParamSet::Terrain => serde_json::to_value(TwoTrackSpec::paper_nominal())?,
                ParamSet::Surface => serde_json::to_value(SurfaceParams::default())?,
                ParamSet::Truck => serde_json::to_value(TruckParams::nominal())?,
                ParamSet::Vehicle3d => serde_json::to_value(VehicleParams::nominal())?,
                ParamSet::Seat => serde_json::to_value(SeatParams::generic())?,
                ParamSet::Cab => serde_json::to_value(CabParams::generic())?,
            };
            match output {
                Some(path) => {
                    let text = serde_json::to_string_pretty(&value)? + "\n";
                    afsv_records::atomic::write(&path, text)
                        .map_err(|e| format!("{}: {e}", path.display()))?;
                    afsv::output::print_json(&json!({ "written": path }))?;
                }
                // a parameter file, read back as it is printed (`params dump strut > s.json`
                // then `--hps s.json`): no provenance key, which the reader would refuse
                None => println!("{}", serde_json::to_string_pretty(&value)?),
            }
        }
        Command::Check { set, file } => {
            let mut report = match set {
                ParamSet::YawPlane => {
                    let p = super::yaw::read_params(&file)?;
                    json!({ "load": p.load, "parameters": named(&p) })
                }
                ParamSet::Strut => json!({ "parameters": checked::<StrutParams>(&file)? }),
                ParamSet::Tire => json!({ "parameters": checked::<TireParams>(&file)? }),
                ParamSet::Terrain => json!({ "parameters": checked::<TwoTrackSpec>(&file)? }),
                ParamSet::Surface => json!({ "parameters": checked::<SurfaceParams>(&file)? }),
                ParamSet::Truck => json!({ "parameters": checked::<TruckParams>(&file)? }),
                ParamSet::Vehicle3d => {
                    let p: VehicleParams = read(&file)?;
                    p.validate()
                        .map_err(|e| format!("{}: {e}", file.display()))?;
                    vehicle_3d_in_ranges(&p).map_err(|e| format!("{}: {e}", file.display()))?;
                    json!({ "parameters": p })
                }
                ParamSet::Seat => json!({ "parameters": checked::<SeatParams>(&file)? }),
                ParamSet::Cab => json!({ "parameters": checked::<CabParams>(&file)? }),
                ParamSet::Vehicle => check_vehicle(&file)?,
            };
            report["valid"] = json!(true);
            report["file"] = json!(file);
            afsv::output::print_json(&report)?;
        }
        Command::List { set, json } => {
            let list = match set {
                ParamSet::YawPlane => specs(&YawPlaneParams::nominal(afsv_dynamics::Load::Loaded)),
                ParamSet::Strut => specs(&StrutParams::front_axle()),
                ParamSet::Tire => specs(&TireParams::nominal()),
                ParamSet::Terrain => specs(&TwoTrackSpec::paper_nominal()),
                ParamSet::Surface => specs(&SurfaceParams::default()),
                ParamSet::Truck => specs(&TruckParams::nominal()),
                ParamSet::Vehicle3d => specs(&VehicleParams::nominal()),
                ParamSet::Seat => specs(&SeatParams::generic()),
                ParamSet::Cab => specs(&CabParams::generic()),
                ParamSet::Vehicle => {
                    let rows: Vec<Value> = afsv_vehicle::BUILTIN
                        .iter()
                        .map(|(name, about)| json!({ "name": name, "description": about }))
                        .collect();
                    json!({ "set": "vehicle", "builtin": rows })
                }
            };
            afsv::output::print_json_or_text(json, &list, || list_text(&list))?;
        }
    }
    Ok(())
}

/// `afsv params dump vehicle`: the built-in description `name` as commented TOML, to
/// standard output or (through a temporary file) to `output`.
fn dump_vehicle(name: &str, output: Option<&Path>) -> CmdResult {
    let d = afsv_vehicle::builtin(name).ok_or_else(|| {
        let names: Vec<&str> = afsv_vehicle::BUILTIN.iter().map(|b| b.0).collect();
        format!(
            "--builtin {name}: no such built-in vehicle (one of: {})",
            names.join(", ")
        )
    })?;
    let text = afsv_vehicle::to_commented_toml(&d)?;
    match output {
        Some(path) => {
            afsv_records::atomic::write(path, text)
                .map_err(|e| format!("{}: {e}", path.display()))?;
            afsv::output::print_json(&json!({ "written": path }))?;
        }
        None => print!("{text}"),
    }
    Ok(())
}

/// A parameter file as `T`, refusing unknown fields; errors name the file, line and column.
pub(super) fn read<T: serde::de::DeserializeOwned>(path: &Path) -> Result<T, String> {
    let text = afsv_records::provenance::read_input(path)
        .map_err(|e| format!("{}: {e}", path.display()))?;
    serde_json::from_str(&text).map_err(|e| format!("{}: {e}", path.display()))
}

/// The parameter file `path` read as `T` and validated by the set's own check; its named
/// parameters with their values.
fn checked<T: serde::de::DeserializeOwned + Named>(path: &Path) -> Result<Value, String> {
    let p: T = read(path)?;
    p.check().map_err(|e| format!("{}: {e}", path.display()))?;
    vehicle_components::within_ranges(&p).map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(named(&p))
}
