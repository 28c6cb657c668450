//! The built-in descriptions: the Chapter 6 prototype (the default vehicle of every
//! command) and the Chapter 2 truck. Each is exactly the models' nominal parameter sets,
//! so a run from the description is the run of the built-in path, bit for bit.

use std::collections::BTreeMap;

use roll_truck::TruckParams;
use tire_fiala::TireParams;
use vehicle_3d::{RigidPart, VehicleParams};

use crate::schema::{
    Articulated, Axle, Cab, Joint, Kind, Part, RigidTruck, StrutSource, Suspension, UnitName,
    VehicleDescription, WheelEnd, YawPlaneCases, FORMAT,
};

/// Name of the tire set of the prototype (Table 6.2).
pub const PROTOTYPE_TIRE: &str = "29.5R29";

/// The built-in descriptions by name.
pub const BUILTIN: [(&str, &str); 2] = [
    (
        "prototype",
        "Chapter 6: 35 t articulated dump truck (Tables 3.1, 6.1-6.3), rigid front axle with the Table 6.3 strut as candidate",
    ),
    (
        "chapter2-truck",
        "Chapter 2: 50 t rigid mining truck, loaded (Tables 2.1-2.3)",
    ),
];

/// A built-in description by name ([`BUILTIN`]).
pub fn builtin(name: &str) -> Option<VehicleDescription> {
    match name {
        "prototype" => Some(VehicleDescription::Articulated(prototype())),
        "chapter2-truck" => Some(VehicleDescription::RigidTruck(chapter2_truck())),
        _ => None,
    }
}

fn part(p: &RigidPart) -> Part {
    Part {
        mass_kg: p.mass_kg,
        cg_height_m: p.cg_height_m,
        cg_to_joint_m: p.cg_to_joint_m,
        roll_inertia_kg_m2: p.roll_inertia_kg_m2,
        pitch_inertia_kg_m2: p.pitch_inertia_kg_m2,
        yaw_inertia_kg_m2: p.yaw_inertia_kg_m2,
    }
}

/// The Chapter 6 prototype: `vehicle_3d::VehicleParams::nominal()` with the rigid front
/// axle and the Table 6.3 strut as its candidate, and the Table 3.1 yaw-plane data.
pub fn prototype() -> Articulated {
    let p = VehicleParams::nominal();
    let axle = |name: &str, unit, distance, track, strut| Axle {
        name: name.to_string(),
        unit,
        distance_from_joint_m: distance,
        track_m: track,
        tire: PROTOTYPE_TIRE.to_string(),
        suspension: Suspension::Rigid,
        strut,
        bogie: None,
    };
    let mut tire: BTreeMap<String, TireParams> = BTreeMap::new();
    tire.insert(PROTOTYPE_TIRE.to_string(), p.tire.clone());
    Articulated {
        format: FORMAT.to_string(),
        kind: Kind::Articulated,
        name: "Chapter 6 prototype: 35 t articulated dump truck".to_string(),
        source: "the dissertation: Table 6.1 (units, payload), Table 6.2 (29.5R29 tire), Table 3.1 (frame steering, yaw-plane data), Table 6.3 (front-axle strut); the rest are the assumptions of docs/vehicle-3d.md".to_string(),
        gravity_m_s2: p.gravity_m_s2,
        front_unit: part(&p.front_unit),
        rear_unit: part(&p.rear_unit),
        payload: part(&p.payload),
        joint: Joint {
            height_m: p.joint_height_m,
        },
        wheel_end: WheelEnd {
            mass_kg: p.wheel_mass_kg,
            spin_inertia_kg_m2: p.wheel_spin_inertia_kg_m2,
            tilt_inertia_kg_m2: p.wheel_tilt_inertia_kg_m2,
        },
        cab: Cab {
            point_m: p.cab_point_m,
            body: None,
        },
        axle: vec![
            axle(
                "front",
                UnitName::Front,
                p.front_axle_to_joint_m,
                p.front_track_m,
                Some(StrutSource::Named("front-axle".to_string())),
            ),
            axle(
                "rear",
                UnitName::Rear,
                p.rear_axle_to_joint_m,
                p.rear_track_m,
                None,
            ),
        ],
        tire,
        steering: p.steering.clone(),
        drive: p.drive,
        yaw_plane: Some(YawPlaneCases {
            loaded: afsv_dynamics::VehicleParams::loaded(),
            unloaded: afsv_dynamics::VehicleParams::unloaded(),
        }),
        seat: None,
        link: None,
    }
}

/// The Chapter 2 truck: `roll_truck::TruckParams::nominal()`.
pub fn chapter2_truck() -> RigidTruck {
    RigidTruck {
        format: FORMAT.to_string(),
        kind: Kind::RigidTruck,
        name: "Chapter 2 truck: 50 t rigid mining truck, loaded".to_string(),
        source: "the dissertation: Tables 2.1-2.3; the strut spacing is the one calibrated roll compliance (docs/roll-truck.md)".to_string(),
        truck: TruckParams::nominal(),
    }
}
