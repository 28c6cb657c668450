//! Parameter files and the named parameter sets by name: a set read from its JSON file
//! (unknown fields refused, errors naming file, line and column) and checked against its
//! own rules and the registry's ranges; the nominal set, the named parameters and the check
//! of a file for each set `afsv params dump|list|check SET` names ([`SETS`]); the strut a
//! command names, built-in or file ([`StrutSource`]).

use crate::report::params::{check_vehicle, named, specs, vehicle_3d_in_ranges};
use afsv_dynamics::{Load, YawPlaneParams};
use hps_emulsion::StrutParams;
use roll_truck::TruckParams;
use serde::de::DeserializeOwned;
use serde_json::Value;
use std::path::Path;
use terrain_psd::{SurfaceParams, TwoTrackSpec};
use tire_fiala::TireParams;
use vehicle_3d::VehicleParams;
use vehicle_components::{CabParams, ParamSet, SeatParams};

/// The parameter sets by name, besides the whole vehicle description (`vehicle`).
pub const SETS: [&str; 9] = [
    "yaw-plane",
    "strut",
    "tire",
    "terrain",
    "surface",
    "truck",
    "vehicle-3d",
    "seat",
    "cab",
];

/// A parameter file as `T`, refusing unknown fields; errors name the file, line and column.
/// The file is listed in the run's provenance with its SHA-256.
pub fn read<T: DeserializeOwned>(path: &Path) -> Result<T, String> {
    let text = afsv_records::provenance::read_input(path)
        .map_err(|e| format!("{}: {e}", path.display()))?;
    serde_json::from_str(&text).map_err(|e| format!("{}: {e}", path.display()))
}

/// The parameter file `path` read as `T`, validated by the set's own check and within the
/// registry's ranges.
pub fn read_checked<T: DeserializeOwned + ParamSet>(path: &Path) -> Result<T, String> {
    let p: T = read(path)?;
    p.check().map_err(|e| format!("{}: {e}", path.display()))?;
    vehicle_components::within_ranges(&p).map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(p)
}

/// A yaw-plane parameter file (`afsv params dump yaw-plane`), validated and within the
/// registry's ranges.
pub fn read_yaw_plane(path: &Path) -> Result<YawPlaneParams, String> {
    let p: YawPlaneParams = read(path)?;
    p.validate()
        .map_err(|e| format!("{}: {e}", path.display()))?;
    vehicle_components::within_ranges(&p).map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(p)
}

/// A 3-D vehicle parameter file (`afsv params dump vehicle-3d`), validated and within the
/// registry's ranges.
pub fn read_vehicle_3d(path: &Path) -> Result<VehicleParams, String> {
    let p: VehicleParams = read(path)?;
    p.validate()
        .map_err(|e| format!("{}: {e}", path.display()))?;
    vehicle_3d_in_ranges(&p).map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(p)
}

/// The strut parameter file of an `--hps FILE` option, validated; `expected` names the
/// option's accepted values in the error of an unreadable file.
pub fn read_hps_strut(file: &Path, expected: &str) -> Result<StrutParams, String> {
    let strut: StrutParams = read(file).map_err(|e| format!("--hps: {e} (expected {expected})"))?;
    strut
        .validate()
        .map_err(|e| format!("--hps {}: {e}", file.display()))?;
    Ok(strut)
}

/// The nominal set `set` ([`SETS`]) as JSON: the yaw-plane set for `load`, the built-in
/// strut `strut` (`front-axle`, `lab-1orifice`, `lab-2orifice`).
pub fn nominal(set: &str, load: Load, strut: &str) -> Result<Value, String> {
    let json = |v: Result<Value, serde_json::Error>| v.map_err(|e| e.to_string());
    match set {
        "yaw-plane" => json(serde_json::to_value(YawPlaneParams::nominal(load))),
        "strut" => {
            let p = afsv_vehicle::builtin_strut(strut)
                .ok_or_else(|| format!("--strut {strut}: no such built-in strut"))?;
            json(serde_json::to_value(p))
        }
        "tire" => json(serde_json::to_value(TireParams::nominal())),
        "terrain" => json(serde_json::to_value(TwoTrackSpec::paper_nominal())),
        "surface" => json(serde_json::to_value(SurfaceParams::default())),
        "truck" => json(serde_json::to_value(TruckParams::nominal())),
        "vehicle-3d" => json(serde_json::to_value(VehicleParams::nominal())),
        "seat" => json(serde_json::to_value(SeatParams::generic())),
        "cab" => json(serde_json::to_value(CabParams::generic())),
        other => Err(unknown(other)),
    }
}

/// The named parameters of `set` with unit, bounds, typical size and nominal value; for
/// `vehicle`, the built-in vehicle descriptions.
pub fn list(set: &str) -> Result<Value, String> {
    Ok(match set {
        "yaw-plane" => specs(&YawPlaneParams::nominal(Load::Loaded)),
        "strut" => specs(&StrutParams::front_axle()),
        "tire" => specs(&TireParams::nominal()),
        "terrain" => specs(&TwoTrackSpec::paper_nominal()),
        "surface" => specs(&SurfaceParams::default()),
        "truck" => specs(&TruckParams::nominal()),
        "vehicle-3d" => specs(&VehicleParams::nominal()),
        "seat" => specs(&SeatParams::generic()),
        "cab" => specs(&CabParams::generic()),
        "vehicle" => {
            let rows: Vec<Value> = afsv_vehicle::BUILTIN
                .iter()
                .map(|(name, about)| serde_json::json!({ "name": name, "description": about }))
                .collect();
            serde_json::json!({ "set": "vehicle", "builtin": rows })
        }
        other => return Err(unknown(other)),
    })
}

/// The check of a parameter file of `set` (a description TOML for `vehicle`): what it
/// holds, named, or the first problem naming file and field.
pub fn check(set: &str, file: &Path) -> Result<Value, String> {
    let parameters = match set {
        "yaw-plane" => {
            let p = read_yaw_plane(file)?;
            return Ok(serde_json::json!({ "load": p.load, "parameters": named(&p) }));
        }
        "strut" => named(&read_checked::<StrutParams>(file)?),
        "tire" => named(&read_checked::<TireParams>(file)?),
        "terrain" => named(&read_checked::<TwoTrackSpec>(file)?),
        "surface" => named(&read_checked::<SurfaceParams>(file)?),
        "truck" => named(&read_checked::<TruckParams>(file)?),
        "vehicle-3d" => serde_json::json!(read_vehicle_3d(file)?),
        "seat" => named(&read_checked::<SeatParams>(file)?),
        "cab" => named(&read_checked::<CabParams>(file)?),
        "vehicle" => return check_vehicle(file),
        other => return Err(unknown(other)),
    };
    Ok(serde_json::json!({ "parameters": parameters }))
}

fn unknown(set: &str) -> String {
    format!(
        "no parameter set `{set}` (one of: {}, vehicle)",
        SETS.join(", ")
    )
}

/// The built-in vehicle description `name` as commented TOML (`afsv params dump vehicle
/// --builtin`); an unknown name lists the built-ins.
pub fn builtin_vehicle_toml(name: &str) -> Result<String, String> {
    let d = afsv_vehicle::builtin(name).ok_or_else(|| {
        let names: Vec<&str> = afsv_vehicle::BUILTIN.iter().map(|b| b.0).collect();
        format!(
            "--builtin {name}: no such built-in vehicle (one of: {})",
            names.join(", ")
        )
    })?;
    afsv_vehicle::to_commented_toml(&d).map_err(|e| e.to_string())
}

/// A strut named on the command line: a built-in set (`front-axle`, `lab-1orifice`,
/// `lab-2orifice`; `afsv_vehicle::builtin_strut`) or a strut parameter file (JSON, `afsv
/// params dump strut`); a file of a built-in's name wins.
#[derive(Clone, Debug)]
pub struct StrutSource {
    /// The built-in set, when the argument names one.
    builtin: Option<StrutParams>,
    /// The argument as given.
    given: String,
}

impl StrutSource {
    /// Any non-empty text (a file is read when used); the error says what to give.
    pub fn parse(s: &str) -> Result<Self, String> {
        if s.trim().is_empty() {
            return Err(
                "give a built-in strut (front-axle, lab-1orifice, lab-2orifice) or a strut file"
                    .into(),
            );
        }
        Ok(Self {
            builtin: afsv_vehicle::builtin_strut(s).filter(|_| !Path::new(s).exists()),
            given: s.into(),
        })
    }

    /// The built-in strut `name`, if there is one.
    pub fn builtin(name: &str) -> Option<Self> {
        Some(Self {
            builtin: Some(afsv_vehicle::builtin_strut(name)?),
            given: name.into(),
        })
    }

    /// Whether the argument names a built-in set.
    pub fn is_builtin(&self) -> bool {
        self.builtin.is_some()
    }

    /// The strut file, when the argument names one.
    pub fn file(&self) -> Option<&Path> {
        self.builtin.is_none().then(|| Path::new(&self.given))
    }

    /// The strut's parameters (a file is read and checked).
    pub fn params(&self) -> Result<StrutParams, String> {
        match self.builtin {
            Some(p) => Ok(p),
            None => afsv_vehicle::read_strut_file(Path::new(&self.given))
                .map_err(|e| format!("--strut: {e}")),
        }
    }

    /// The strut's parameters ([`StrutSource::params`]) with the emulsion's gas volume
    /// fraction `gamma0` when given (`StrutParams::with_gamma0`, gas moved from the free
    /// gas volume).
    pub fn params_with_gamma0(&self, gamma0: Option<f64>) -> Result<StrutParams, String> {
        let p = self.params()?;
        match gamma0 {
            Some(g) => p.with_gamma0(g).map_err(|e| e.to_string()),
            None => Ok(p),
        }
    }

    /// The name shown in outputs: the built-in name or the file as given.
    pub fn name(&self) -> &str {
        &self.given
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_set_has_a_nominal_and_a_list() {
        for set in SETS {
            let v = nominal(set, Load::Unloaded, "lab-1orifice").unwrap();
            assert!(v.is_object(), "{set}");
            assert!(list(set).unwrap()["parameters"].is_array(), "{set}");
        }
        assert!(list("vehicle").unwrap()["builtin"].is_array());
        for (name, ..) in afsv_vehicle::BUILTIN {
            let text = builtin_vehicle_toml(name).unwrap();
            assert!(text.starts_with('#'), "{name}");
            assert!(text.contains("format = \"afsv-vehicle-1\""), "{name}");
        }
        let e = builtin_vehicle_toml("nope").unwrap_err();
        assert!(
            e.contains("--builtin nope") && e.contains("prototype"),
            "{e}"
        );
        assert!(nominal("strut", Load::Loaded, "nope").is_err());
        assert!(nominal("nope", Load::Loaded, "front-axle").is_err());
    }

    #[test]
    fn a_strut_is_a_builtin_unless_a_file_of_that_name_exists() {
        let s = StrutSource::parse("lab-2orifice").unwrap();
        assert!(s.is_builtin() && s.file().is_none());
        assert_eq!(
            s.params().unwrap(),
            afsv_vehicle::builtin_strut("lab-2orifice").unwrap()
        );
        let f = StrutSource::parse("no-such-strut.json").unwrap();
        assert_eq!(f.file(), Some(Path::new("no-such-strut.json")));
        assert!(f.params().unwrap_err().starts_with("--strut: "));
        assert!(StrutSource::parse(" ").is_err());
        assert!(StrutSource::builtin("nope").is_none());
        assert_eq!(s.params_with_gamma0(None).unwrap(), s.params().unwrap());
        let emulsion = s.params_with_gamma0(Some(0.03)).unwrap();
        assert_eq!(emulsion, s.params().unwrap().with_gamma0(0.03).unwrap());
        assert!(s.params_with_gamma0(Some(2.0)).is_err());
    }
}
