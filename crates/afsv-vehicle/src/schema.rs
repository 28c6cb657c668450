//! The vehicle description as a user writes it (`docs/vehicles.md`): plain serde structs
//! that refuse unknown fields. Two kinds of vehicle share the file's head (`format`,
//! `kind`, `name`):
//!
//! - `kind = "articulated"` ([`Articulated`]): two units joined by the articulation joint,
//!   frame steering between them, one axle on each unit, tires from a named set, the
//!   payload of the loaded case (Chapter 6, Table 6.1);
//! - `kind = "rigid-truck"` ([`RigidTruck`]): the two-axle rigid truck of Chapter 2
//!   (Tables 2.1-2.3) in one `[truck]` table.
//!
//! SI units inside, the unit in every field name.

use std::collections::BTreeMap;

use afs_hydraulics::AfsParams;
use hps_emulsion::interconnect::LineParams;
use hps_emulsion::StrutParams;
use roll_truck::TruckParams;
use serde::de::{self, MapAccess, Visitor};
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use tire_fiala::TireParams;
use vehicle_3d::DriveParams;

pub use crate::cab_seat::{CabBody, CushionSection, MountSection, SeatSection};

/// The `format` value of this version of the description.
pub const FORMAT: &str = "afsv-vehicle-1";

/// Which model a description is for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Kind {
    /// Two units and an articulation joint (the 3-D vehicle of Chapter 6; the yaw-plane
    /// model of Chapter 3).
    Articulated,
    /// One rigid body on two axles (the truck of Chapter 2).
    RigidTruck,
}

impl std::fmt::Display for Kind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Self::Articulated => "articulated",
            Self::RigidTruck => "rigid-truck",
        })
    }
}

/// The head every description starts with; read first to pick the schema.
#[derive(Debug, Clone, Deserialize)]
pub(crate) struct Head {
    /// Must be [`FORMAT`].
    pub format: String,
    /// The model.
    pub kind: Kind,
}

/// A vehicle description of either kind (read once per process, so the size difference of
/// the variants does not matter).
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone, PartialEq)]
pub enum VehicleDescription {
    /// An articulated frame-steered vehicle.
    Articulated(Articulated),
    /// A rigid two-axle truck.
    RigidTruck(RigidTruck),
}

impl VehicleDescription {
    /// The vehicle's name.
    pub fn name(&self) -> &str {
        match self {
            Self::Articulated(a) => &a.name,
            Self::RigidTruck(t) => &t.name,
        }
    }

    /// Its kind.
    pub fn kind(&self) -> Kind {
        match self {
            Self::Articulated(_) => Kind::Articulated,
            Self::RigidTruck(_) => Kind::RigidTruck,
        }
    }
}

/// Mass, cg and principal moments of inertia of one rigid part (Table 6.1 columns).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Part {
    /// Mass (kg); a unit includes its wheel ends.
    pub mass_kg: f64,
    /// Height of the cg above the ground at the static equilibrium (m).
    pub cg_height_m: f64,
    /// Distance of the cg from the articulation joint (m): ahead of it for the front unit,
    /// behind it for the rear unit and the payload.
    pub cg_to_joint_m: f64,
    /// Roll moment of inertia about the part's cg (kg m²).
    pub roll_inertia_kg_m2: f64,
    /// Pitch moment of inertia about the part's cg (kg m²).
    pub pitch_inertia_kg_m2: f64,
    /// Yaw moment of inertia about the part's cg (kg m²).
    pub yaw_inertia_kg_m2: f64,
}

/// The articulation joint.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Joint {
    /// Height of the joint above the ground (m).
    pub height_m: f64,
}

/// One wheel end: tire, rim and hub drive (the same on every axle).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WheelEnd {
    /// Mass (kg), part of its unit's mass; the unsprung mass of a suspended corner.
    pub mass_kg: f64,
    /// Spin moment of inertia (kg m²).
    pub spin_inertia_kg_m2: f64,
    /// Moment of inertia about a diameter (kg m²).
    pub tilt_inertia_kg_m2: f64,
}

/// Where the ride (ISO 2631-1) is read.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Cab {
    /// A point of the front unit: `[x ahead of the joint, y left, height above ground]` (m).
    pub point_m: [f64; 3],
    /// The cab as a body on mounts (with `[seat]`): ISO 2631-1 is then also read on the
    /// cab floor and the seat ([`crate::cab_seat`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub body: Option<CabBody>,
}

/// Which unit an axle hangs on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum UnitName {
    /// The front unit (engine and cab).
    Front,
    /// The rear unit (dump body).
    Rear,
}

/// How an axle is suspended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Suspension {
    /// Rigidly fixed to its unit (the prototype).
    Rigid,
    /// A hydro-pneumatic strut at each wheel (Chapter 5): `strut` names it.
    Hps,
}

/// A strut: a built-in name (`front-axle`, `lab-1orifice`, `lab-2orifice`), a strut file
/// (JSON as `afsv params dump strut` writes it; a relative path is taken from the
/// description's folder) or the strut's fields inline.
#[derive(Debug, Clone, PartialEq)]
pub enum StrutSource {
    /// A built-in strut or a file, as written.
    Named(String),
    /// The parameters themselves.
    Inline(Box<StrutParams>),
}

impl Serialize for StrutSource {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self {
            Self::Named(n) => s.serialize_str(n),
            Self::Inline(p) => p.serialize(s),
        }
    }
}

impl<'de> Deserialize<'de> for StrutSource {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct Source;
        impl<'de> Visitor<'de> for Source {
            type Value = StrutSource;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a strut name or file path (string), or a table of strut parameters")
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<StrutSource, E> {
                Ok(StrutSource::Named(v.to_string()))
            }
            fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<StrutSource, A::Error> {
                let p = StrutParams::deserialize(de::value::MapAccessDeserializer::new(map))?;
                Ok(StrutSource::Inline(Box::new(p)))
            }
        }
        d.deserialize_any(Source)
    }
}

/// One axle.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Axle {
    /// A name for messages (`front`, `rear`).
    pub name: String,
    /// The unit it hangs on.
    pub unit: UnitName,
    /// Distance from the articulation joint (m), ahead for the front unit, behind for the
    /// rear unit.
    pub distance_from_joint_m: f64,
    /// Track: lateral distance between the tire centres (m).
    pub track_m: f64,
    /// The tire, a key of the `[tire]` tables.
    pub tire: String,
    /// Rigid or HPS.
    pub suspension: Suspension,
    /// The strut of an `hps` axle; on a `rigid` axle the candidate strut that design
    /// studies try (`--hps nominal`). Optional on a rigid axle.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub strut: Option<StrutSource>,
    /// A walking-beam bogie (rear axle only): the axle becomes a tandem at
    /// `distance_from_joint_m`, one beam per side (`vehicle_3d::bogie`); a field left out
    /// takes its documented default.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bogie: Option<vehicle_3d::BogieParams>,
}

/// The yaw-plane model's own data for one load case (Chapter 3, Table 3.1 columns), when
/// they were measured apart from the 3-D data; otherwise they are derived from the units.
pub type YawPlaneData = afsv_dynamics::VehicleParams;

/// Table 3.1 data for both load cases.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct YawPlaneCases {
    /// With the payload.
    pub loaded: YawPlaneData,
    /// Without it.
    pub unloaded: YawPlaneData,
}

/// An articulated frame-steered vehicle.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Articulated {
    /// [`FORMAT`].
    pub format: String,
    /// `articulated`.
    pub kind: Kind,
    /// A name for reports.
    pub name: String,
    /// Where the data come from, free text.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub source: String,
    /// Gravitational acceleration (m/s²).
    pub gravity_m_s2: f64,
    /// Front unit, wheel ends included.
    pub front_unit: Part,
    /// Rear unit, wheel ends included, without the payload.
    pub rear_unit: Part,
    /// Payload, carried by the rear unit in the `loaded` case.
    pub payload: Part,
    /// The articulation joint.
    pub joint: Joint,
    /// The wheel ends.
    pub wheel_end: WheelEnd,
    /// Where the ride is read.
    pub cab: Cab,
    /// The axles, front first.
    pub axle: Vec<Axle>,
    /// The tires by name.
    pub tire: BTreeMap<String, TireParams>,
    /// Frame steering: strut geometry and hydraulics (Table 3.1, Eqs 3.1-3.12).
    pub steering: AfsParams,
    /// The speed controller.
    pub drive: DriveParams,
    /// Table 3.1 data of the yaw-plane model, when measured apart from the 3-D data.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub yaw_plane: Option<YawPlaneCases>,
    /// The operator's suspension seat on the cab (with `[cab.body]`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub seat: Option<SeatSection>,
    /// The struts' hydraulic interconnection (`[link]`); absent: none.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub link: Option<LinkSection>,
}

/// Which struts a `[link]` joins (`vehicle_3d::interconnect::Link`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum LinkKind {
    /// The two front struts, left-right (needs an `hps` front axle).
    Roll,
    /// On each side the front and the rear strut (needs `hps` on both axles).
    Pitch,
}

/// The struts' interconnection: cross-coupled pairs of sealed-piston struts joined by two
/// lines with accumulators each (docs/layouts.md, "Interconnected struts").
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LinkSection {
    /// `roll` or `pitch`.
    pub kind: LinkKind,
    /// Roll: the design of both lines (`[link.line]`); default
    /// `LineParams::front_axle_roll` (a 38 mm line, an 8.4 L accumulator at 2.4 MPa).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub line: Option<LineParams>,
    /// Pitch: `[[link.lines]]`, the line at the front strut's piston side, then the one at
    /// the rear strut's; default `LineParams::side_pitch` at the ratio of the rear strut's
    /// rod area to the front strut's.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub lines: Option<[LineParams; 2]>,
}

/// A rigid two-axle truck (Chapter 2).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RigidTruck {
    /// [`FORMAT`].
    pub format: String,
    /// `rigid-truck`.
    pub kind: Kind,
    /// A name for reports.
    pub name: String,
    /// Where the data come from, free text.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub source: String,
    /// Every parameter of the truck model (Tables 2.1-2.3 and the assumptions).
    pub truck: TruckParams,
}
