//! From a description to the models' parameters, checked: every scalar against the range of
//! its parameter registry (`vehicle_3d::registry`, `tire_fiala`, `afs_hydraulics`,
//! `hps_emulsion`, `roll_truck`), then each model's own validation (relations between
//! fields), then what the models can run (one axle per unit, one tire set; HPS on either
//! axle). Every error names the description's field path.

use std::path::{Path, PathBuf};

use afs_hydraulics::AfsParams;
use afsv_dynamics::VehicleParams as YawParams;
use hps_emulsion::StrutParams;
use roll_truck::TruckParams;
use tire_fiala::{Fiala, TireParams};
use vehicle_3d::{FrontAxle, Load, Statics, VehicleParams};
use vehicle_components::ParamSet;

use crate::error::DescriptionError;
use crate::read::{at_path, quoted_key};
use crate::schema::{
    Articulated, Axle, LinkKind, LinkSection, RigidTruck, StrutSource, Suspension, UnitName,
    VehicleDescription, YawPlaneCases,
};
use hps_emulsion::interconnect::LineParams;
use vehicle_3d::interconnect::Link;

/// Largest strut file read (bytes).
const MAX_STRUT_BYTES: u64 = 1 << 20;

/// An articulated vehicle ready for the models.
#[derive(Debug, Clone, PartialEq)]
pub struct ArticulatedVehicle {
    /// Its name.
    pub name: String,
    /// The 3-D vehicle's parameters; `hps` is the front strut when one is given (the
    /// Table 6.3 strut otherwise, never used then).
    pub params: VehicleParams,
    /// How the front axle is described.
    pub front_suspension: Suspension,
    /// The front axle's strut: its suspension, or the candidate of a rigid axle.
    pub front_strut: Option<StrutParams>,
    /// Where the strut came from: a built-in name, a file, or `inline`.
    pub front_strut_source: Option<String>,
    /// How the rear axle is described; its strut is `params.rear_hps`.
    pub rear_suspension: Suspension,
    /// Where the rear strut came from: a built-in name, a file, `inline`, or the front
    /// strut scaled for the rear static load (the default when `strut` is left out).
    pub rear_strut_source: Option<String>,
    /// The yaw-plane model's data per load case.
    pub yaw_plane: YawPlaneCases,
    /// Whether `yaw_plane` was derived from the 3-D data (no `[yaw_plane]` tables).
    pub yaw_plane_derived: bool,
    /// The cab on mounts and the seat (`[cab.body]`, `[seat]`), when described.
    pub cab_seat: Option<vehicle_3d::cab_ride::CabSeatLayout>,
    /// The struts' interconnection (`[link]`), when described.
    pub link: Option<Link>,
}

impl ArticulatedVehicle {
    /// The yaw-plane data of `load`.
    pub fn yaw_plane(&self, load: Load) -> &YawParams {
        match load {
            Load::Loaded => &self.yaw_plane.loaded,
            Load::Unloaded => &self.yaw_plane.unloaded,
        }
    }

    /// The yaw-plane model's whole parameter set for its load `load`: this vehicle's
    /// yaw-plane data of that load and its steering.
    pub fn yaw_plane_params(&self, load: afsv_dynamics::Load) -> afsv_dynamics::YawPlaneParams {
        let case = match load {
            afsv_dynamics::Load::Loaded => Load::Loaded,
            afsv_dynamics::Load::Unloaded => Load::Unloaded,
        };
        afsv_dynamics::YawPlaneParams {
            load: Some(load),
            vehicle: self.yaw_plane(case).clone(),
            afs: self.steering().clone(),
        }
    }

    /// The steering system (the same in both models).
    pub fn steering(&self) -> &AfsParams {
        &self.params.steering
    }
}

/// A rigid truck ready for the model.
#[derive(Debug, Clone, PartialEq)]
pub struct TruckVehicle {
    /// Its name.
    pub name: String,
    /// The truck model's parameters.
    pub params: TruckParams,
}

/// A described vehicle, checked and converted (made once per process, so the size
/// difference of the variants does not matter).
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone, PartialEq)]
pub enum Vehicle {
    /// Articulated.
    Articulated(ArticulatedVehicle),
    /// Rigid truck.
    RigidTruck(TruckVehicle),
}

impl Vehicle {
    /// The vehicle's name.
    pub fn name(&self) -> &str {
        match self {
            Self::Articulated(a) => &a.name,
            Self::RigidTruck(t) => &t.name,
        }
    }
}

/// Where a description came from, for messages and relative strut paths.
pub(crate) struct Origin<'a> {
    /// The file name in messages.
    pub name: &'a str,
    /// The text, to locate fields (none for a built-in description).
    pub text: Option<&'a str>,
    /// The folder relative strut paths start from.
    pub dir: &'a Path,
}

impl Origin<'_> {
    pub(crate) fn err(&self, path: &str, message: impl Into<String>) -> DescriptionError {
        match self.text {
            Some(text) => at_path(text, self.name, path, message.into()),
            None => DescriptionError::Field {
                origin: self.name.to_string(),
                line: 1,
                column: 1,
                path: path.to_string(),
                message: message.into(),
            },
        }
    }
}

/// Check and convert a description.
pub(crate) fn resolve(
    d: &VehicleDescription,
    origin: &Origin<'_>,
) -> Result<Vehicle, DescriptionError> {
    match d {
        VehicleDescription::Articulated(a) => articulated(a, origin).map(Vehicle::Articulated),
        VehicleDescription::RigidTruck(t) => truck(t, origin).map(Vehicle::RigidTruck),
    }
}

/// Every scalar of `set` within its registry range; `path(name)` is its description path.
fn in_ranges(
    set: &dyn ParamSet,
    origin: &Origin<'_>,
    path: impl Fn(&str) -> String,
) -> Result<(), DescriptionError> {
    for (i, spec) in set.specs().iter().enumerate() {
        let v = set.value(i);
        if spec.admit(v).is_err() {
            return Err(origin.err(
                &path(spec.name),
                format!(
                    "{v} {unit} is outside the plausible range [{lo}, {hi}] {unit}",
                    unit = spec.unit,
                    lo = spec.lower,
                    hi = spec.upper
                ),
            ));
        }
    }
    Ok(())
}

/// The description path of a `vehicle_3d::registry` name.
fn articulated_path(name: &str) -> String {
    let mapped = match name {
        "front_axle_to_joint_m" => "axle[0].distance_from_joint_m",
        "rear_axle_to_joint_m" => "axle[1].distance_from_joint_m",
        "front_track_m" => "axle[0].track_m",
        "rear_track_m" => "axle[1].track_m",
        "joint_height_m" => "joint.height_m",
        "wheel_mass_kg" => "wheel_end.mass_kg",
        "wheel_spin_inertia_kg_m2" => "wheel_end.spin_inertia_kg_m2",
        "wheel_tilt_inertia_kg_m2" => "wheel_end.tilt_inertia_kg_m2",
        other if other.starts_with("bogie.") => return format!("axle[1].{other}"),
        other => return other.replace("cab_point_m", "cab.point_m"),
    };
    mapped.to_string()
}

fn articulated(a: &Articulated, o: &Origin<'_>) -> Result<ArticulatedVehicle, DescriptionError> {
    let [front, rear] = axles(a, o)?;
    let tire = tire_of(a, o)?;
    let (front_strut, front_strut_source) = match &front.strut {
        Some(s) => {
            let (p, src) = strut(s, "axle[0].strut", o)?;
            (Some(p), Some(src))
        }
        None => (None, None),
    };
    if front.suspension == Suspension::Hps && front_strut.is_none() {
        return Err(o.err(
            "axle[0].strut",
            "an `hps` axle needs its strut: a built-in name (front-axle, lab-1orifice, lab-2orifice), a strut file or an inline table",
        ));
    }
    let mut params = VehicleParams {
        gravity_m_s2: a.gravity_m_s2,
        front_axle_to_joint_m: front.distance_from_joint_m,
        rear_axle_to_joint_m: rear.distance_from_joint_m,
        front_track_m: front.track_m,
        rear_track_m: rear.track_m,
        front_unit: part(&a.front_unit),
        rear_unit: part(&a.rear_unit),
        payload: part(&a.payload),
        joint_height_m: a.joint.height_m,
        wheel_mass_kg: a.wheel_end.mass_kg,
        wheel_spin_inertia_kg_m2: a.wheel_end.spin_inertia_kg_m2,
        wheel_tilt_inertia_kg_m2: a.wheel_end.tilt_inertia_kg_m2,
        cab_point_m: a.cab.point_m,
        tire: tire.clone(),
        steering: a.steering.clone(),
        hps: front_strut.unwrap_or_else(StrutParams::front_axle),
        rear_hps: None,
        bogie: rear.bogie,
        drive: a.drive,
        // a description is a vehicle, not a model form: the CLI's --paper-form sets it
        yaw_inertia_form: vehicle_3d::YawInertiaForm::EnergyConsistent,
    };
    in_ranges(&params, o, articulated_path)?;
    let tire_path = format!("tire.{}", quoted_key(&front.tire));
    in_ranges(&params.tire, o, |n| format!("{tire_path}.{n}"))?;
    params
        .tire
        .validate()
        .map_err(|e| o.err(&tire_path, e.to_string()))?;
    in_ranges(&params.steering, o, |n| format!("steering.{n}"))?;
    params
        .steering
        .validate()
        .map_err(|e| o.err("steering", e.to_string()))?;
    if let Some(s) = &front_strut {
        let where_ = strut_path(front.strut.as_ref(), "axle[0].strut");
        in_ranges(s, o, |n| format!("{where_}.{n}"))?;
    }
    params.validate().map_err(|e| {
        let msg = e.to_string();
        match &e {
            vehicle_3d::VehicleError::InvalidParameter { field, .. } => {
                o.err(&articulated_path(field), msg)
            }
            _ => o.err("", msg),
        }
    })?;
    for load in [Load::Unloaded, Load::Loaded] {
        let statics = Statics::of(&params, load).map_err(|e| {
            let e = e.to_string();
            // The cg outside the axles is the axles' (or the parts') fault, a load beyond
            // the tire's table the tire's.
            let (path, hint) = if e.contains("wheel base") {
                ("axle", "the axles must straddle the combined cg: check each axle's distance_from_joint_m and the parts' cg_to_joint_m")
            } else {
                (tire_path.as_str(), "extend the tire's load_deflection table")
            };
            o.err(path, format!("no static equilibrium {load}: {e} ({hint})"))
        })?;
        // The bodies as the model builds them: a unit less its wheel ends (placed by the
        // tire radius and the static deflection) must keep a positive definite inertia.
        vehicle_3d::model::build_tree(&params, load, &statics, FrontAxle::Rigid, false)
            .map_err(|e| {
                let msg = format!("{load}: {e} (check the wheel ends' mass and the tire radius against the unit's inertias)");
                match &e {
                    vehicle_3d::VehicleError::InvalidParameter { field, .. } => {
                        o.err(&articulated_path(field), msg)
                    }
                    _ => o.err("", msg),
                }
            })?;
    }
    let (rear_hps, rear_strut_source) = rear_strut(rear, &params, o)?;
    params.rear_hps = rear_hps;
    let (yaw_plane, yaw_plane_derived) = match &a.yaw_plane {
        Some(y) => {
            for (case, p) in [("loaded", &y.loaded), ("unloaded", &y.unloaded)] {
                p.validate()
                    .map_err(|e| o.err(&format!("yaw_plane.{case}"), e.to_string()))?;
            }
            (y.clone(), false)
        }
        None => (
            YawPlaneCases {
                loaded: derived_yaw_plane(&params, Load::Loaded)
                    .map_err(|e| o.err("", format!("deriving the yaw-plane data: {e}")))?,
                unloaded: derived_yaw_plane(&params, Load::Unloaded)
                    .map_err(|e| o.err("", format!("deriving the yaw-plane data: {e}")))?,
            },
            true,
        ),
    };
    let cab_seat = crate::cab_seat::layout(a, &params, o)?;
    let link = match &a.link {
        Some(l) => Some(link(l, [front.suspension, rear.suspension], &params, o)?),
        None => None,
    };
    Ok(ArticulatedVehicle {
        cab_seat,
        link,
        name: a.name.clone(),
        params,
        front_suspension: front.suspension,
        front_strut,
        front_strut_source,
        rear_suspension: rear.suspension,
        rear_strut_source,
        yaw_plane,
        yaw_plane_derived,
    })
}

/// The interconnection `l` of a vehicle with axles suspended as `suspensions` (front, rear)
/// and parameters `params` (both struts resolved): the kind's struts must be there, the
/// lines given only as the kind takes them (`line` for roll, two `lines` for pitch; the
/// defaults otherwise), each line valid (`LineParams::validate`).
fn link(
    l: &LinkSection,
    suspensions: [Suspension; 2],
    params: &VehicleParams,
    o: &Origin<'_>,
) -> Result<Link, DescriptionError> {
    let check = |path: &str, line: &LineParams| {
        line.validate()
            .map_err(|e| o.err(path, format!("{e} (docs/vehicles.md, \"[link]\")")))
    };
    match l.kind {
        LinkKind::Roll => {
            if suspensions[0] != Suspension::Hps {
                return Err(o.err(
                    "link.kind",
                    "a roll link joins the two front struts: the front [[axle]] needs suspension = \"hps\"",
                ));
            }
            if l.lines.is_some() {
                return Err(o.err(
                    "link.lines",
                    "two lines per side are a pitch link's; a roll link takes one [link.line]",
                ));
            }
            let line = l.line.unwrap_or_else(LineParams::front_axle_roll);
            check("link.line", &line)?;
            Ok(Link::Roll(line))
        }
        LinkKind::Pitch => {
            if suspensions != [Suspension::Hps, Suspension::Hps] {
                return Err(o.err(
                    "link.kind",
                    "a pitch link joins the front and the rear strut on each side: both [[axle]] need suspension = \"hps\"",
                ));
            }
            if l.line.is_some() {
                return Err(o.err(
                    "link.line",
                    "one line is a roll link's; a pitch link takes two [[link.lines]] (front piston side, then rear) or none",
                ));
            }
            match l.lines {
                Some(lines) => {
                    for (i, line) in lines.iter().enumerate() {
                        check(&format!("link.lines[{i}]"), line)?;
                    }
                    Ok(Link::Pitch(lines))
                }
                None => Link::pitch_of(params).map_err(|e| o.err("link", e.to_string())),
            }
        }
    }
}

/// The two axles: front on the front unit, rear on the rear unit, the rear rigid.
fn axles<'a>(a: &'a Articulated, o: &Origin<'_>) -> Result<[&'a Axle; 2], DescriptionError> {
    let [front, rear] = a.axle.as_slice() else {
        return Err(o.err(
            "axle",
            format!(
                "{} axles given; the articulated model has two: [[axle]] front (unit = \"front\"), then rear (unit = \"rear\")",
                a.axle.len()
            ),
        ));
    };
    if front.unit != UnitName::Front {
        return Err(o.err("axle[0].unit", "the first axle must hang on the front unit"));
    }
    if rear.unit != UnitName::Rear {
        return Err(o.err("axle[1].unit", "the second axle must hang on the rear unit"));
    }
    if front.bogie.is_some() {
        return Err(o.err(
            "axle[0].bogie",
            "a walking-beam bogie carries the rear axle only (a rear tandem); remove it from the front axle",
        ));
    }
    if rear.suspension == Suspension::Rigid && rear.strut.is_some() {
        return Err(o.err(
            "axle[1].strut",
            "a strut on a rigid rear axle is never used (no command tries a rear candidate); remove it or set suspension = \"hps\"",
        ));
    }
    Ok([front, rear])
}

/// The rear axle's strut, checked, and where it came from: none on a rigid axle; on an
/// `hps` axle the strut given, or by default the front strut (`params.hps`) scaled for the
/// rear static load (`vehicle_3d::suspension::scaled_strut`). The strut must hold the
/// vehicle up in both load cases within its travel or topped out on its extension stop
/// (a passive strut scaled for the loaded truck does that unloaded), never bottomed out.
fn rear_strut(
    rear: &Axle,
    params: &VehicleParams,
    o: &Origin<'_>,
) -> Result<(Option<StrutParams>, Option<String>), DescriptionError> {
    const PATH: &str = "axle[1].strut";
    if rear.suspension == Suspension::Rigid {
        return Ok((None, None));
    }
    let (strut, source) = match &rear.strut {
        Some(s) => {
            let (p, src) = strut(s, PATH, o)?;
            let where_ = strut_path(Some(s), PATH);
            in_ranges(&p, o, |n| format!("{where_}.{n}"))?;
            (p, src)
        }
        None => {
            let ratio = params
                .rear_strut_load_ratio()
                .map_err(|e| o.err(PATH, e.to_string()))?;
            let p = vehicle_3d::suspension::scaled_strut(&params.hps, ratio).map_err(|e| {
                o.err(
                    PATH,
                    format!("the front strut scaled by {ratio:.3} for the rear load: {e}"),
                )
            })?;
            in_ranges(&p, o, |n| {
                format!("{PATH} (the front strut scaled by {ratio:.3}).{n}")
            })?;
            (
                p,
                format!("the front strut scaled by {ratio:.3} for the rear static load"),
            )
        }
    };
    let hps = hps_emulsion::HpsStrut::new(&strut, &hps_emulsion::HpsExtensions::default())
        .map_err(|e| o.err(PATH, e.to_string()))?;
    for load in [Load::Unloaded, Load::Loaded] {
        let statics = Statics::of(params, load).map_err(|e| o.err(PATH, e.to_string()))?;
        let force = statics.rear_strut_force_n(params);
        let z = vehicle_3d::suspension::static_travel(&hps, force)
            .map_err(|e| o.err(PATH, format!("{load}: {e}")))?;
        if z > strut.travel {
            return Err(o.err(
                PATH,
                format!(
                    "{load}: the strut rests on its compression stop under the static load of {:.1} kN (raise p_h0 or the areas)",
                    force / 1e3
                ),
            ));
        }
    }
    Ok((Some(strut), Some(source)))
}

/// The tire set both axles use.
fn tire_of<'a>(a: &'a Articulated, o: &Origin<'_>) -> Result<&'a TireParams, DescriptionError> {
    for (i, axle) in a.axle.iter().enumerate() {
        if !a.tire.contains_key(&axle.tire) {
            let known: Vec<&str> = a.tire.keys().map(String::as_str).collect();
            return Err(o.err(
                &format!("axle[{i}].tire"),
                format!(
                    "no tire `{}` in the [tire] tables (given: {})",
                    axle.tire,
                    if known.is_empty() {
                        "none".to_string()
                    } else {
                        known.join(", ")
                    }
                ),
            ));
        }
    }
    if a.axle[0].tire != a.axle[1].tire {
        return Err(o.err(
            "axle[1].tire",
            "the 3-D model runs one tire set on every axle; name the same tire on both axles",
        ));
    }
    Ok(&a.tire[&a.axle[0].tire])
}

/// Where a strut's fields stand in messages: the inline table, or the file.
fn strut_path(s: Option<&StrutSource>, path: &str) -> String {
    match s {
        Some(StrutSource::Named(n)) => format!("{path} ({n})"),
        _ => path.to_string(),
    }
}

/// A strut from its source, validated; and the source's name.
pub(crate) fn strut(
    s: &StrutSource,
    path: &str,
    o: &Origin<'_>,
) -> Result<(StrutParams, String), DescriptionError> {
    let (p, name) = match s {
        StrutSource::Inline(p) => (**p, "inline".to_string()),
        StrutSource::Named(n) => match builtin_strut(n) {
            Some(p) => (p, n.clone()),
            None => {
                let file = o.dir.join(n);
                (
                    read_strut_file(&file).map_err(|e| o.err(path, e))?,
                    file.display().to_string(),
                )
            }
        },
    };
    p.validate().map_err(|e| o.err(path, e.to_string()))?;
    Ok((p, name))
}

/// The built-in struts by name: `front-axle` (Table 6.3), `lab-1orifice` and
/// `lab-2orifice` (the laboratory strut of section 5.3).
pub fn builtin_strut(name: &str) -> Option<StrutParams> {
    use hps_emulsion::LabConfig;
    match name {
        "front-axle" => Some(StrutParams::front_axle()),
        "lab-1orifice" => Some(StrutParams::lab(LabConfig::OneOrifice)),
        "lab-2orifice" => Some(StrutParams::lab(LabConfig::TwoOrifices)),
        _ => None,
    }
}

/// Names of [`builtin_strut`].
pub const BUILTIN_STRUTS: [&str; 3] = ["front-axle", "lab-1orifice", "lab-2orifice"];

/// A strut parameter file (JSON, `afsv params dump strut`), with line and column on error.
pub fn read_strut_file(file: &Path) -> Result<StrutParams, String> {
    let shown = file.display();
    let meta = std::fs::metadata(file).map_err(|e| {
        format!(
            "`{shown}` is neither a built-in strut ({}) nor a readable file: {e}",
            BUILTIN_STRUTS.join(", ")
        )
    })?;
    if meta.len() > MAX_STRUT_BYTES {
        return Err(format!(
            "{shown}: {} bytes, too large for a strut file",
            meta.len()
        ));
    }
    let text = afsv_records::provenance::read_input(file).map_err(|e| format!("{shown}: {e}"))?;
    let mut de = serde_json::Deserializer::from_str(&text);
    let p = serde_path_to_error::deserialize::<_, StrutParams>(&mut de).map_err(|e| {
        let inner = e.inner();
        format!(
            "{shown}:{}:{}: `{}`: {inner}",
            inner.line(),
            inner.column(),
            e.path()
        )
    })?;
    vehicle_components::within_ranges(&p).map_err(|e| format!("{shown}: {e}"))?;
    Ok(p)
}

fn part(p: &crate::schema::Part) -> vehicle_3d::RigidPart {
    vehicle_3d::RigidPart {
        mass_kg: p.mass_kg,
        cg_height_m: p.cg_height_m,
        cg_to_joint_m: p.cg_to_joint_m,
        roll_inertia_kg_m2: p.roll_inertia_kg_m2,
        pitch_inertia_kg_m2: p.pitch_inertia_kg_m2,
        yaw_inertia_kg_m2: p.yaw_inertia_kg_m2,
    }
}

/// Small slip angle of the aligning-moment slope (rad).
const SLOPE_SLIP_RAD: f64 = 1e-4;

/// The yaw-plane data of `load` derived from the 3-D data (Fig 3.5, Eqs 3.13-3.17):
/// - front unit as given; the rear unit loaded is rear unit plus payload, with the
///   combined cg and the yaw inertia about it (parallel axes);
/// - `l_f1`, `l_r1`: axle distance from the joint minus the cg's;
/// - per-tire cornering stiffness of the tire set at its static load (`Statics`), the
///   aligning coefficient the small-slip slope of the same Fiala tire, the relaxation
///   length the tire's lateral one;
/// - half-track: the mean of both tracks over two.
pub fn derived_yaw_plane(p: &VehicleParams, load: Load) -> Result<YawParams, String> {
    let statics = Statics::of(p, load).map_err(|e| e.to_string())?;
    let fiala = Fiala::new(&p.tire).map_err(|e| e.to_string())?;
    let parts = p.rear_parts(load);
    let m_r: f64 = parts.iter().map(|q| q.mass_kg).sum();
    let x_r = parts
        .iter()
        .map(|q| q.mass_kg * q.cg_to_joint_m)
        .sum::<f64>()
        / m_r;
    let i_r: f64 = parts
        .iter()
        .map(|q| q.yaw_inertia_kg_m2 + q.mass_kg * (q.cg_to_joint_m - x_r).powi(2))
        .sum();
    let k_mz = |fz: f64| {
        let m = fiala.forces_on_surface(fz, 0.0, SLOPE_SLIP_RAD, 1.0);
        m.mz.abs() / SLOPE_SLIP_RAD
    };
    let y = YawParams {
        m_f_kg: p.front_unit.mass_kg,
        m_r_kg: m_r,
        i_f_kg_m2: p.front_unit.yaw_inertia_kg_m2,
        i_r_kg_m2: i_r,
        l_f1_m: p.front_axle_to_joint_m - p.front_unit.cg_to_joint_m,
        l_f2_m: p.front_unit.cg_to_joint_m,
        l_r1_m: p.rear_axle_to_joint_m - x_r,
        l_r2_m: x_r,
        c_alpha_f_n_per_rad: fiala.cornering_stiffness(statics.front_tire_load_n),
        c_alpha_r_n_per_rad: fiala.cornering_stiffness(statics.rear_tire_load_n),
        k_mz_f_nm_per_rad: k_mz(statics.front_tire_load_n),
        k_mz_r_nm_per_rad: k_mz(statics.rear_tire_load_n),
        relaxation_length_m: p.tire.lateral_relaxation_length_m,
        half_track_m: 0.25 * (p.front_track_m + p.rear_track_m),
    };
    y.validate().map_err(|e| e.to_string())?;
    Ok(y)
}

fn truck(t: &RigidTruck, o: &Origin<'_>) -> Result<TruckVehicle, DescriptionError> {
    in_ranges(&t.truck, o, |n| format!("truck.{n}"))?;
    t.truck.validate().map_err(|e| {
        let msg = e.to_string();
        match &e {
            roll_truck::TruckError::InvalidParameter { field, .. } => {
                o.err(&format!("truck.{field}"), msg)
            }
            _ => o.err("truck", msg),
        }
    })?;
    Ok(TruckVehicle {
        name: t.name.clone(),
        params: t.truck,
    })
}

/// The folder of a description file, for relative strut paths.
pub(crate) fn folder_of(file: &Path) -> PathBuf {
    file.parent()
        .filter(|p| !p.as_os_str().is_empty())
        .map_or_else(|| PathBuf::from("."), Path::to_path_buf)
}
