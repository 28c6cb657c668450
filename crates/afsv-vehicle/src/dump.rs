//! A description as commented TOML (`afsv params dump vehicle`): every field in schema
//! order with a comment above it. The vehicle's own fields are explained in words with
//! their source; the fields of the nested sets (tire, steering, strut, truck, yaw-plane)
//! carry their unit and plausible range from the set's parameter registry, the same range
//! [`crate::resolve`] enforces. Reading the dump back gives the description bit for bit.

use toml::{Table, Value};
use vehicle_components::{ParamSet, ParamSpec};

use crate::read::quoted_key;
use crate::schema::VehicleDescription;

/// Comments of the vehicle's own fields, by path (`[]` for any array index).
const COMMENTS: &[(&str, &str)] = &[
    ("format", "Description format; this afsv reads afsv-vehicle-1."),
    ("kind", "Model: \"articulated\" (two units, frame steering; Chapters 3 and 6) or \"rigid-truck\" (Chapter 2)."),
    ("name", "Name shown in reports."),
    ("source", "Where the data come from (free text, optional)."),
    ("gravity_m_s2", "Gravitational acceleration (m/s²)."),
    ("front_unit", "Front unit (engine, cab), wheel ends included. Table 6.1."),
    ("rear_unit", "Rear unit (dump body) without the payload, wheel ends included. Table 6.1."),
    ("payload", "Payload, fixed to the rear unit in the `loaded` load case; the `unloaded` case runs without it. Table 6.1."),
    ("[part].mass_kg", "Mass (kg)."),
    ("[part].cg_height_m", "Height of the cg above the ground at the static equilibrium (m)."),
    ("[part].cg_to_joint_m", "Distance of the cg from the articulation joint (m): ahead of it for the front unit, behind it for the rear unit and the payload."),
    ("[part].roll_inertia_kg_m2", "Principal moments of inertia about the part's cg (kg m²): roll, pitch, yaw. Each must be positive and no larger than the sum of the other two (a real body)."),
    ("[part].pitch_inertia_kg_m2", "Pitch moment of inertia (kg m²)."),
    ("[part].yaw_inertia_kg_m2", "Yaw moment of inertia (kg m²)."),
    ("joint", "The articulation joint (yaw) with the rear unit's roll joint at the same point."),
    ("joint.height_m", "Height of the joint above the ground (m). Assumption for the prototype: 1.0, about the wheel radius."),
    ("wheel_end", "One wheel end (tire, rim, hub drive), the same on every axle; part of its unit's mass."),
    ("wheel_end.mass_kg", "Mass (kg): the unsprung mass of a suspended corner. Assumption for the prototype: 2000."),
    ("wheel_end.spin_inertia_kg_m2", "Spin moment of inertia (kg m²)."),
    ("wheel_end.tilt_inertia_kg_m2", "Moment of inertia about a wheel diameter (kg m²)."),
    ("cab", "Where the ride (ISO 2631-1 a_wz) is read."),
    ("cab.point_m", "A point of the front unit [x ahead of the joint, y left, height above ground] (m)."),
    ("cab.body", "Optional, with [seat]: the cab as a rigid body on four elastomer mounts (bounce, roll, pitch about the mount-plane centre), driven by the front unit's motion; ISO 2631-1 is then also read on the cab floor and the seat, and SEAT reported (docs/layouts.md)."),
    ("cab.body.mass_kg", "Mass of the cab with its interior, without seat and operator (kg). Generic: 1100."),
    ("cab.body.roll_inertia_kg_m2", "Roll moment of inertia about the cab's cg (kg m²)."),
    ("cab.body.pitch_inertia_kg_m2", "Pitch moment of inertia about the cab's cg (kg m²)."),
    ("cab.body.cg_height_m", "Height of the cab's cg above the mount plane (m)."),
    ("cab.body.mount_centre_from_point_m", "Centre of the mount plane from cab.point_m, in the front unit's axes [x, y, z] (m)."),
    ("cab.body.mount", "The four mounts: vertical spring-dampers, horizontally stiff."),
    ("cab.body.mount[].x_m", "Ahead of the mount-plane centre (m)."),
    ("cab.body.mount[].y_m", "Left of the mount-plane centre (m)."),
    ("cab.body.mount[].stiffness_n_per_m", "Vertical stiffness (N/m)."),
    ("cab.body.mount[].damping_n_s_per_m", "Vertical damping (N s/m)."),
    ("seat", "Optional, with [cab.body]: the operator's suspension seat on the cab floor, spring and damper with elastic end stops, weight-adjusted to ride at mid-travel (docs/layouts.md)."),
    ("seat.suspended_mass_kg", "Mass on the suspension (kg): the seat top and, without a cushion, the operator's seated mass. Generic: 80."),
    ("seat.stiffness_n_per_m", "Suspension stiffness (N/m). Generic: 1.5 Hz with 80 kg."),
    ("seat.damping_n_s_per_m", "Suspension damping (N s/m). Generic: damping ratio 0.3."),
    ("seat.travel_m", "Travel between the end stops (m), centred on mid-travel."),
    ("seat.stop_stiffness_n_per_m", "Stiffness of each elastic end stop (N/m), at least the suspension's."),
    ("seat.x_m", "Seat ahead of the mount-plane centre (m)."),
    ("seat.y_m", "Seat left of the mount-plane centre (m)."),
    ("seat.height_m", "Height of the suspended mass above the mount plane (m)."),
    ("seat.cushion", "Optional: the operator's seated mass on a cushion spring-damper over the seat top."),
    ("seat.cushion.occupant_mass_kg", "Operator's mass on the cushion (kg)."),
    ("seat.cushion.stiffness_n_per_m", "Cushion stiffness (N/m)."),
    ("seat.cushion.damping_n_s_per_m", "Cushion damping (N s/m)."),
    ("axle", "The axles, front first: the articulated model has one on each unit."),
    ("axle[].name", "Name in messages."),
    ("axle[].unit", "The unit it hangs on: \"front\" or \"rear\"."),
    ("axle[].distance_from_joint_m", "Distance from the articulation joint (m): ahead of it on the front unit, behind it on the rear unit."),
    ("axle[].track_m", "Track: lateral distance between the tire centres (m)."),
    ("axle[].tire", "The tire: a key of the [tire] tables."),
    ("axle[].suspension", "\"rigid\" or \"hps\" (a hydro-pneumatic strut at each wheel, Chapter 5, on either axle; docs/layouts.md, \"HPS on any axle\")."),
    ("axle[].strut", "The strut of an \"hps\" axle, or the candidate strut of a rigid front axle that design studies try (--hps nominal): a built-in strut (front-axle, lab-1orifice, lab-2orifice), a strut file (JSON, `afsv params dump strut`; a relative path starts at this file's folder), or an inline [axle.strut] table. Optional on a rigid front axle; refused on a rigid rear axle; left out of an \"hps\" rear axle, the front strut scaled for the rear static load (docs/layouts.md)."),
    ("tire", "Tire sets by name (Fiala handling, vertical load-deflection and enveloping; Table 6.2)."),
    ("steering", "Hydraulic frame steering: strut geometry, valve, gerotor, fluid (Table 3.1, Eqs 3.1-3.12)."),
    ("drive", "Speed controller: one drive torque on all wheels, PI on the speed error with the rolling resistance as feed-forward."),
    ("drive.kp_n_m_per_m_s", "Proportional gain per wheel (N m per m/s)."),
    ("drive.ki_n_m_per_m", "Integral gain per wheel (N m per m)."),
    ("drive.max_torque_n_m", "Largest drive or braking torque per wheel (N m)."),
    ("yaw_plane", "Data of the yaw-plane model (Chapter 3) when they were measured apart from the 3-D data, as Table 3.1 was; without these tables they are derived from the units, axles and tire (docs/vehicles.md)."),
    ("yaw_plane.loaded", "Table 3.1, loaded column."),
    ("yaw_plane.unloaded", "Table 3.1, unloaded column."),
    ("truck", "Every parameter of the Chapter 2 truck model (Tables 2.1-2.3 and the assumptions of docs/roll-truck.md)."),
    ("tire.[name]", "One tire set."),
    ("axle[].strut.friction", "Seal friction of the strut."),
    ("axle[].bogie", "A walking-beam bogie (rear axle only, optional): the axle becomes a tandem centred at distance_from_joint_m, one beam per side pitching about its pivot, two wheel ends on each beam; with suspension = \"hps\" one strut per side at the pivot (docs/layouts.md, \"The walking-beam bogie\"). A field left out takes its default."),
    ("axle[].bogie.spacing_m", "Distance between the tandem axles (m), 0.8 to 4, more than the tire diameter. Default 2.1 (assumption: the 2.0 m tire plus 0.1 m)."),
    ("axle[].bogie.beam_mass_kg", "Mass of one beam (kg), 20 to 10000, cg at the pivot; part of the rear unit's mass. Default 800 (assumption for the 25-30 t class)."),
    ("axle[].bogie.beam_pitch_inertia_kg_m2", "Pitch moment of inertia of one beam about its pivot, wheel ends not included (kg m²), 1 to 20000. Default 300 (assumption: a slender 2.1 m bar of 800 kg)."),
    ("tire.[name].cornering_stiffness_table", "Load-dependent cornering stiffness rows [F_z (N), C_alpha (N/rad)], interpolated; when empty, cornering_stiffness_n_per_rad applies at every load. Table 6.2."),
    ("tire.[name].load_deflection", "Vertical load-deflection rows [deflection (m), load (N)], rising (Fig 6.4 replaced by an assumption for the 29.5R29)."),
    ("steering.inlet_check_valve", "Whether the valve's inlet check valve stops back flow into the supply (true or false)."),
];

/// The registry a nested set's fields take their unit and range from.
fn registry_of(path: &[String]) -> Option<&'static [ParamSpec]> {
    let head = path.first()?.as_str();
    match head {
        "tire" => Some(tire_fiala::TireParams::nominal().specs()),
        "steering" => Some(afs_hydraulics::AfsParams::nominal().specs()),
        "truck" => Some(roll_truck::TruckParams::nominal().specs()),
        "yaw_plane" => Some(afsv_dynamics::VehicleParams::loaded().specs()),
        "axle" if path.get(1).is_some_and(|k| k == "strut") => {
            Some(hps_emulsion::StrutParams::front_axle().specs())
        }
        _ => None,
    }
}

/// Comment of the field at `path` (keys; array indices left out).
fn comment(path: &[String]) -> Option<String> {
    let generic: Vec<String> = path
        .iter()
        .enumerate()
        .map(|(i, k)| match (i, path[0].as_str()) {
            (1, "tire") => "[name]".to_string(),
            _ => k.clone(),
        })
        .collect();
    let mut key = generic.join(".");
    if path[0] == "axle" && path.len() > 1 {
        key = format!("axle[].{}", generic[1..].join("."));
    }
    if matches!(path[0].as_str(), "front_unit" | "rear_unit" | "payload") && path.len() == 2 {
        key = format!("[part].{}", path[1]);
    }
    if let Some((_, c)) = COMMENTS.iter().find(|(k, _)| *k == key) {
        return Some(c.to_string());
    }
    // a nested set's field: unit and plausible range from its registry
    let specs = registry_of(path)?;
    let skip = match path[0].as_str() {
        "tire" | "yaw_plane" => 2,
        "axle" => 2,
        _ => 1,
    };
    let name = path.get(skip..)?.join(".");
    specs.iter().find(|s| s.name == name).map(|s| {
        format!(
            "{} ({}), plausible {} to {}.",
            s.name,
            s.unit,
            fmt_bound(s.lower),
            fmt_bound(s.upper)
        )
    })
}

fn fmt_bound(v: f64) -> String {
    if v != 0.0 && (v.abs() >= 1e5 || v.abs() < 1e-3) {
        format!("{v:e}")
    } else {
        format!("{v}")
    }
}

/// The description as commented TOML.
pub fn to_commented_toml(d: &VehicleDescription) -> Result<String, String> {
    let table = match d {
        VehicleDescription::Articulated(a) => Table::try_from(a),
        VehicleDescription::RigidTruck(t) => Table::try_from(t),
    }
    .map_err(|e| e.to_string())?;
    let mut out = String::from(
        "# afsv vehicle description (docs/vehicles.md). SI units; the unit is in each field name.\n\
         # Check it with `afsv params check vehicle FILE`; use it with `--vehicle FILE`.\n",
    );
    emit(&mut out, &[], &table);
    Ok(out)
}

/// `# text` lines, wrapped at about 92 columns.
fn comment_lines(out: &mut String, text: &str) {
    let mut line = String::from("#");
    for word in text.split_whitespace() {
        if line.len() + word.len() + 1 > 92 && line.len() > 1 {
            out.push_str(&line);
            out.push('\n');
            line = String::from("#");
        }
        line.push(' ');
        line.push_str(word);
    }
    if line.len() > 1 {
        out.push_str(&line);
        out.push('\n');
    }
}

fn is_table_array(v: &Value) -> bool {
    matches!(v, Value::Array(a) if !a.is_empty() && a.iter().all(Value::is_table))
}

fn header(path: &[String]) -> String {
    path.iter()
        .map(|k| quoted_key(k))
        .collect::<Vec<_>>()
        .join(".")
}

/// Write `table` at `path`: its plain keys, then its sub-tables and arrays of tables in
/// schema order.
fn emit(out: &mut String, path: &[String], table: &Table) {
    let child = |k: &str| {
        let mut p = path.to_vec();
        p.push(k.to_string());
        p
    };
    for (k, v) in table {
        if v.is_table() || is_table_array(v) {
            continue;
        }
        if let Some(c) = comment(&child(k)) {
            comment_lines(out, &c);
        }
        out.push_str(&format!("{} = {}\n", quoted_key(k), v));
    }
    for (k, v) in table {
        let p = child(k);
        match v {
            Value::Table(t) => {
                out.push('\n');
                if let Some(c) = comment(&p) {
                    comment_lines(out, &c);
                }
                // a table with only sub-tables needs no header of its own
                if t.values().any(|v| !(v.is_table() || is_table_array(v))) {
                    out.push_str(&format!("[{}]\n", header(&p)));
                }
                emit(out, &p, t);
            }
            Value::Array(items) if is_table_array(v) => {
                out.push('\n');
                if let Some(c) = comment(&p) {
                    comment_lines(out, &c);
                }
                for (i, item) in items.iter().enumerate() {
                    if let Value::Table(t) = item {
                        if i > 0 {
                            out.push('\n');
                        }
                        out.push_str(&format!("[[{}]]\n", header(&p)));
                        emit(out, &p, t);
                    }
                }
            }
            _ => {}
        }
    }
}
