//! One vehicle description for every model and command (`docs/vehicles.md`).
//!
//! A description is a TOML file that declares a whole vehicle: its units (masses, cg,
//! inertias), the articulation joint, the frame steering, the axles (position, track, tire,
//! suspension), the tires and the payload of the loaded case; or, for the rigid truck of
//! Chapter 2, its one parameter table. Reading it ([`load_file`], [`load_str`]) checks every
//! field, names the field path with line and column on any error, and converts it to the
//! models' parameter sets ([`Vehicle`]): the 3-D vehicle (`vehicle_3d::VehicleParams`), the
//! yaw-plane model of the same vehicle (`afsv_dynamics::VehicleParams` per load case,
//! Table 3.1 data or derived), and the truck (`roll_truck::TruckParams`).
//!
//! - [`schema`]: the file's structure; [`read`]: TOML to a description with located errors;
//! - [`resolve`]: ranges from the parameter registries, the models' own checks, the
//!   conversion; [`mod@builtin`]: the Chapter 6 prototype (the default) and the Chapter 2
//!   truck; [`dump`]: a description as commented TOML.

pub mod builtin;
pub mod cab_seat;
pub mod dump;
pub mod error;
pub mod read;
pub mod resolve;
pub mod schema;

use std::path::Path;

pub use builtin::{builtin, BUILTIN};
pub use dump::to_commented_toml;
pub use error::DescriptionError;
pub use resolve::{
    builtin_strut, derived_yaw_plane, read_strut_file, ArticulatedVehicle, TruckVehicle, Vehicle,
    BUILTIN_STRUTS,
};
pub use schema::{Kind, VehicleDescription, FORMAT};

/// A description read and checked, with the models' parameters.
#[derive(Debug, Clone, PartialEq)]
pub struct Described {
    /// As written.
    pub description: VehicleDescription,
    /// Checked and converted.
    pub vehicle: Vehicle,
}

/// Read and check the description `text`; `origin` names it in messages and `dir` is the
/// folder relative strut paths start from.
pub fn load_str(text: &str, origin: &str, dir: &Path) -> Result<Described, DescriptionError> {
    let description = read::parse(text, origin)?;
    let vehicle = resolve::resolve(
        &description,
        &resolve::Origin {
            name: origin,
            text: Some(text),
            dir,
        },
    )?;
    Ok(Described {
        description,
        vehicle,
    })
}

/// Read and check the description file `path`.
pub fn load_file(path: &Path) -> Result<Described, DescriptionError> {
    let origin = path.display().to_string();
    let io = |reason: String| DescriptionError::Io {
        origin: origin.clone(),
        reason,
    };
    let meta = std::fs::metadata(path).map_err(|e| io(e.to_string()))?;
    if meta.len() > read::MAX_BYTES as u64 {
        return Err(DescriptionError::TooLarge {
            origin,
            bytes: meta.len() as usize,
            limit: read::MAX_BYTES,
        });
    }
    let text = afsv_records::provenance::read_input(path).map_err(|e| io(e.to_string()))?;
    load_str(&text, &origin, &resolve::folder_of(path))
}

/// A built-in description by name, checked and converted.
pub fn load_builtin(name: &str) -> Result<Described, DescriptionError> {
    let description = builtin(name).ok_or_else(|| DescriptionError::Io {
        origin: name.to_string(),
        reason: format!(
            "no built-in vehicle `{name}` (built in: {})",
            BUILTIN.map(|(n, _)| n).join(", ")
        ),
    })?;
    let vehicle = resolve::resolve(
        &description,
        &resolve::Origin {
            name,
            text: None,
            dir: Path::new("."),
        },
    )?;
    Ok(Described {
        description,
        vehicle,
    })
}
