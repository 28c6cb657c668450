//! The optional cab-on-mounts and suspension-seat sections of an articulated vehicle's
//! description (`[cab.body]`, `[[cab.body.mount]]`, `[seat]`, `[seat.cushion]`;
//! `docs/vehicles.md`, model in `docs/layouts.md`), and their conversion to
//! `vehicle_3d::cab_ride::CabSeatLayout`. Without them ISO 2631-1 is read on the frame
//! only; with them also on the cab floor and the seat, and SEAT.

use serde::{Deserialize, Serialize};
use vehicle_3d::cab_ride::CabSeatLayout;
use vehicle_3d::VehicleParams;
use vehicle_components::{CabMount, CabParams, Cushion, SeatParams};

use crate::error::DescriptionError;
use crate::resolve::Origin;
use crate::schema::Articulated;

/// One cab mount (`[[cab.body.mount]]`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MountSection {
    /// Ahead of the mount-plane centre (m).
    pub x_m: f64,
    /// Left of the mount-plane centre (m).
    pub y_m: f64,
    /// Vertical stiffness (N/m).
    pub stiffness_n_per_m: f64,
    /// Vertical damping (N s/m).
    pub damping_n_s_per_m: f64,
}

/// The cab as a rigid body on four mounts (`[cab.body]`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CabBody {
    /// Mass of the cab with its interior, without seat and operator (kg).
    pub mass_kg: f64,
    /// Roll moment of inertia about the cab's cg (kg m²).
    pub roll_inertia_kg_m2: f64,
    /// Pitch moment of inertia about the cab's cg (kg m²).
    pub pitch_inertia_kg_m2: f64,
    /// Height of the cab's cg above the mount plane (m).
    pub cg_height_m: f64,
    /// Centre of the mount plane from `cab.point_m`, in the front unit's axes (m).
    pub mount_centre_from_point_m: [f64; 3],
    /// The four mounts, positions from the mount-plane centre (exactly four).
    pub mount: [MountSection; 4],
}

/// A seat cushion carrying the operator (`[seat.cushion]`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CushionSection {
    /// Operator's mass on the cushion (kg).
    pub occupant_mass_kg: f64,
    /// Stiffness (N/m).
    pub stiffness_n_per_m: f64,
    /// Damping (N s/m).
    pub damping_n_s_per_m: f64,
}

/// The suspension seat on the cab floor (`[seat]`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SeatSection {
    /// Mass on the suspension (kg): seat top and, without a cushion, the operator's seated
    /// mass.
    pub suspended_mass_kg: f64,
    /// Suspension stiffness (N/m).
    pub stiffness_n_per_m: f64,
    /// Suspension damping (N s/m).
    pub damping_n_s_per_m: f64,
    /// Travel between the end stops (m).
    pub travel_m: f64,
    /// Stiffness of each end stop (N/m).
    pub stop_stiffness_n_per_m: f64,
    /// Ahead of the mount-plane centre (m).
    pub x_m: f64,
    /// Left of the mount-plane centre (m).
    pub y_m: f64,
    /// Height of the suspended mass above the mount plane (m).
    pub height_m: f64,
    /// Optional cushion.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cushion: Option<CushionSection>,
}

impl CabBody {
    /// The generic cab of `vehicle_components::CabParams::generic`, centred on the a_wz point.
    pub fn generic() -> Self {
        let c = CabParams::generic();
        Self {
            mass_kg: c.mass_kg,
            roll_inertia_kg_m2: c.roll_inertia_kg_m2,
            pitch_inertia_kg_m2: c.pitch_inertia_kg_m2,
            cg_height_m: c.cg_height_m,
            mount_centre_from_point_m: [0.0; 3],
            mount: c.mounts.map(|m| MountSection {
                x_m: m.x_m,
                y_m: m.y_m,
                stiffness_n_per_m: m.stiffness_n_per_m,
                damping_n_s_per_m: m.damping_n_s_per_m,
            }),
        }
    }
}

impl SeatSection {
    /// The generic seat of `vehicle_components::SeatParams::generic`.
    pub fn generic() -> Self {
        let s = SeatParams::generic();
        Self {
            suspended_mass_kg: s.suspended_mass_kg,
            stiffness_n_per_m: s.stiffness_n_per_m,
            damping_n_s_per_m: s.damping_n_s_per_m,
            travel_m: s.travel_m,
            stop_stiffness_n_per_m: s.stop_stiffness_n_per_m,
            x_m: s.x_m,
            y_m: s.y_m,
            height_m: s.height_m,
            cushion: None,
        }
    }
}

/// The description path of a field the cab-and-seat model names.
fn path_of(field: &str) -> String {
    if let Some(rest) = field.strip_prefix("cab.mounts") {
        format!("cab.body.mount{rest}")
    } else if let Some(rest) = field.strip_prefix("cab.") {
        format!("cab.body.{rest}")
    } else if let Some(rest) = field.strip_prefix("mount_centre_from_cab_point_m") {
        format!("cab.body.mount_centre_from_point_m{rest}")
    } else {
        field.to_string()
    }
}

/// The cab and seat of `a`, checked against the model's ranges, or `None` when the
/// description has neither; `params` are the vehicle's converted parameters (gravity).
pub(crate) fn layout(
    a: &Articulated,
    params: &VehicleParams,
    o: &Origin<'_>,
) -> Result<Option<CabSeatLayout>, DescriptionError> {
    let (body, seat) = match (&a.cab.body, &a.seat) {
        (None, None) => return Ok(None),
        (Some(b), Some(s)) => (b, s),
        (Some(_), None) => {
            return Err(o.err(
                "cab.body",
                "a cab on mounts carries the operator's seat: add a [seat] table",
            ))
        }
        (None, Some(_)) => {
            return Err(o.err(
                "seat",
                "the seat sits on a cab on mounts: add a [cab.body] table with its four [[cab.body.mount]]s",
            ))
        }
    };
    let layout = CabSeatLayout {
        cab: CabParams {
            mass_kg: body.mass_kg,
            roll_inertia_kg_m2: body.roll_inertia_kg_m2,
            pitch_inertia_kg_m2: body.pitch_inertia_kg_m2,
            cg_height_m: body.cg_height_m,
            mounts: body.mount.map(|m| CabMount {
                x_m: m.x_m,
                y_m: m.y_m,
                stiffness_n_per_m: m.stiffness_n_per_m,
                damping_n_s_per_m: m.damping_n_s_per_m,
            }),
        },
        seat: SeatParams {
            suspended_mass_kg: seat.suspended_mass_kg,
            stiffness_n_per_m: seat.stiffness_n_per_m,
            damping_n_s_per_m: seat.damping_n_s_per_m,
            travel_m: seat.travel_m,
            stop_stiffness_n_per_m: seat.stop_stiffness_n_per_m,
            x_m: seat.x_m,
            y_m: seat.y_m,
            height_m: seat.height_m,
            cushion: seat.cushion.map(|c| Cushion {
                occupant_mass_kg: c.occupant_mass_kg,
                stiffness_n_per_m: c.stiffness_n_per_m,
                damping_n_s_per_m: c.damping_n_s_per_m,
            }),
        },
        mount_centre_from_cab_point_m: body.mount_centre_from_point_m,
    };
    layout.build(params).map_err(|e| match &e {
        vehicle_3d::VehicleError::InvalidParameter {
            field,
            value,
            reason,
        } => o.err(&path_of(field), format!("{value}: {reason}")),
        _ => o.err("cab.body", e.to_string()),
    })?;
    Ok(Some(layout))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{builtin, load_str, to_commented_toml, Vehicle};
    use std::path::Path;

    /// The prototype's description with `extra` TOML appended.
    fn prototype_with(extra: &str) -> String {
        let base = to_commented_toml(&builtin("prototype").unwrap()).unwrap();
        format!("{base}\n{extra}")
    }

    fn generic_tables() -> String {
        let mut t = toml::Table::new();
        let mut cab = toml::Table::new();
        cab.insert(
            "body".into(),
            toml::Value::try_from(CabBody::generic()).unwrap(),
        );
        t.insert(
            "seat".into(),
            toml::Value::try_from(SeatSection::generic()).unwrap(),
        );
        // `cab` is already a table of the prototype: add `body` under it by dotted headers
        let body = toml::to_string(&cab).unwrap().replace("[body", "[cab.body");
        format!("{body}\n{}", toml::to_string(&t).unwrap())
    }

    #[test]
    fn the_generic_cab_and_seat_read_back_as_the_generic_layout() {
        let text = prototype_with(&generic_tables());
        let d = load_str(&text, "v.toml", Path::new(".")).unwrap();
        let Vehicle::Articulated(a) = &d.vehicle else {
            panic!("articulated")
        };
        assert_eq!(a.cab_seat, Some(CabSeatLayout::generic()));
        // and the dump of that description reads back to the same description
        let again = to_commented_toml(&d.description).unwrap();
        let d2 = load_str(&again, "v2.toml", Path::new(".")).unwrap();
        assert_eq!(d2.description, d.description);
    }

    #[test]
    fn errors_name_the_field_path_with_its_line() {
        let bad = generic_tables().replacen(
            "stiffness_n_per_m = 550000.0",
            "stiffness_n_per_m = -1.0",
            1,
        );
        let text = prototype_with(&bad);
        let e = load_str(&text, "v.toml", Path::new("."))
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("`cab.body.mount[0].stiffness_n_per_m`: -1: must be finite and within [1000, 1e9] N/m"),
            "{e}"
        );
        let line = text
            .lines()
            .position(|l| l.contains("stiffness_n_per_m = -1.0"))
            .unwrap()
            + 1;
        assert!(e.starts_with(&format!("v.toml:{line}:")), "{e}");
        let seat_only = prototype_with(
            &toml::to_string(&{
                let mut t = toml::Table::new();
                t.insert(
                    "seat".into(),
                    toml::Value::try_from(SeatSection::generic()).unwrap(),
                );
                t
            })
            .unwrap(),
        );
        let e = load_str(&seat_only, "v.toml", Path::new("."))
            .unwrap_err()
            .to_string();
        assert!(e.contains("`seat`") && e.contains("[cab.body]"), "{e}");
        let travel = generic_tables().replace("travel_m = 0.1", "travel_m = 0.0");
        let e = load_str(&prototype_with(&travel), "v.toml", Path::new("."))
            .unwrap_err()
            .to_string();
        assert!(e.contains("`seat.travel_m`"), "{e}");
    }
}
