//! V3, the path change of section 6.3 (Fig 3.6(b)): the field course steered by the
//! yaw-plane model's pure-pursuit `PathDriver`, its record and the Fig 6.12 channels' peaks
//! ([`crate::scenarios`] re-exports it with the design scenarios).

use serde::Serialize;
use vehicle_components::FlatTerrain;
use vehicle_components::{Course, PathDriver};

use crate::error::{measure, positive, VehicleError};
use crate::interconnect::{Link, LinkedRun, LinkedVehicle};
use crate::model::FrontAxle;
use crate::params::{Load, VehicleParams};
use crate::scenarios::{TerrainSpec, OUTPUT_DT_S};
use crate::simulate::{simulate, RunOptions, RunRecord};
use crate::vehicle::{course_frame, Vehicle, VehicleOptions};

/// Settings of a path-change run (V3 of section 6.3, Fig 3.6(b)).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PathChangeSpec {
    /// Load case.
    pub load: Load,
    /// Front axle.
    pub front_axle: FrontAxle,
    /// Target speed of the drive (km/h): the Table 3.2 means, 15.3 loaded, 19.2 unloaded.
    pub speed_kmh: f64,
    /// Lateral offset of the course (m), positive to the right (Fig 3.6(b): 4.5).
    pub offset_m: f64,
    /// Gate length of the half-cosine transition (m): 18.
    pub gate_m: f64,
    /// Straight approach before the gate (m): 20 (the yaw-plane course's).
    pub approach_m: f64,
    /// Run length (s): 20, the yaw-plane path change's, about 40 m beyond the gate.
    pub t_end_s: f64,
    /// Terrain: None for smooth ground (the default: the yaw-plane model it is compared
    /// with runs on flat ground); class C for the paved field course (note table, V3).
    pub terrain: Option<TerrainSpec>,
}

impl PathChangeSpec {
    /// V3 of section 6.3 for `load` at its Table 3.2 mean speed, on smooth ground, offset to
    /// the right.
    pub fn v3(load: Load, front_axle: FrontAxle) -> Self {
        Self {
            load,
            front_axle,
            speed_kmh: match load {
                Load::Loaded => 15.3,
                Load::Unloaded => 19.2,
            },
            offset_m: 4.5,
            gate_m: 18.0,
            approach_m: 20.0,
            t_end_s: 20.0,
            terrain: None,
        }
    }

    /// The course of the spec (the yaw-plane driver's frame: y to the right).
    pub fn course(&self) -> Course {
        Course::PathChange {
            offset_m: self.offset_m,
            gate_m: self.gate_m,
            approach_m: self.approach_m,
        }
    }
}

/// Measures of one path-change run. Signs: the afsv-v1 record convention (docs/records.md),
/// positive in a right-hand turn, so a path change to the right starts with positive
/// articulation, yaw rate and lateral acceleration.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PathChangeMeasures {
    /// Articulation angle of largest magnitude, with its sign (deg).
    pub peak_articulation_deg: f64,
    /// Largest extension and shortening of the left strut from its initial length, d_L
    /// (m): `(min, max)`.
    pub strut_left_range_m: (f64, f64),
    /// Front-unit yaw rate of largest magnitude, with its sign (deg/s).
    pub peak_yaw_rate_deg_s: f64,
    /// Horizontal lateral acceleration of the front unit's cg of largest magnitude, with
    /// its sign (m/s²).
    pub peak_lateral_accel_m_s2: f64,
    /// Largest lateral deviation of the front-axle centre from the course (m, magnitude).
    pub max_deviation_m: f64,
    /// Lateral position of the front-axle centre at the end of the run, in the course
    /// frame (m, right positive): the offset reached.
    pub final_offset_m: f64,
}

/// The vehicle options of a path-change run.
fn path_change_options(spec: &PathChangeSpec) -> VehicleOptions {
    let speed = spec.speed_kmh / 3.6;
    VehicleOptions {
        front_axle: spec.front_axle,
        speed_m_s: speed,
        driver: Some(PathDriver::new(spec.course())),
        path_length_m: speed * spec.t_end_s + 5.0,
        ..VehicleOptions::default()
    }
}

/// The vehicle of a path-change run: on smooth ground, or on the terrain of `seed` when the
/// spec has one.
fn path_change_vehicle(
    p: &VehicleParams,
    spec: &PathChangeSpec,
    seed: u64,
) -> Result<Vehicle, VehicleError> {
    positive("speed_kmh", spec.speed_kmh)?;
    positive("t_end_s", spec.t_end_s)?;
    let options = path_change_options(spec);
    let half = 0.5 * p.front_track_m;
    match &spec.terrain {
        None => {
            let flat = FlatTerrain::new(0.0, vehicle_components::DEFAULT_FRICTION)
                .map_err(|e| measure("terrain", e))?;
            Vehicle::new(p, spec.load, options, &flat, half)
        }
        Some(t) => {
            let terrain = t.build(p, options.start_s_m + options.path_length_m + 50.0, seed)?;
            Vehicle::new(p, spec.load, options, &terrain, half)
        }
    }
}

/// The integration settings of a path-change run.
fn path_change_run(spec: &PathChangeSpec) -> RunOptions {
    RunOptions {
        t_end_s: spec.t_end_s,
        output_dt_s: OUTPUT_DT_S,
        ..RunOptions::default()
    }
}

/// One path-change run (on terrain `seed` when the spec has a terrain): the record and its
/// measures.
pub fn path_change(
    p: &VehicleParams,
    spec: &PathChangeSpec,
    seed: u64,
) -> Result<(RunRecord, PathChangeMeasures), VehicleError> {
    let rec = simulate(&path_change_vehicle(p, spec, seed)?, &path_change_run(spec))?;
    let m = path_change_measures(p, &rec, &spec.course())?;
    Ok((rec, m))
}

/// [`path_change`] with the struts interconnected by `link` ([`LinkedVehicle`]): the run
/// with its line pressures, and the measures of its vehicle record.
pub fn path_change_linked(
    p: &VehicleParams,
    spec: &PathChangeSpec,
    seed: u64,
    link: impl Into<Link>,
) -> Result<(LinkedRun, PathChangeMeasures), VehicleError> {
    let linked = LinkedVehicle::new(path_change_vehicle(p, spec, seed)?, &link.into())?;
    let run = linked.simulate_from(&linked.initial_state()?, &path_change_run(spec))?;
    let m = path_change_measures(p, &run.record, &spec.course())?;
    Ok((run, m))
}

/// The value of largest magnitude of `x`, with its sign (0 for an empty slice).
fn signed_peak(x: impl Iterator<Item = f64>) -> f64 {
    x.fold(0.0, |m: f64, v| if v.abs() > m.abs() { v } else { m })
}

/// Path-change measures of `rec` on `course` (the vehicle of `p` started with its front
/// axle at the course start, [`crate::vehicle::course_frame`]).
pub fn path_change_measures(
    p: &VehicleParams,
    rec: &RunRecord,
    course: &Course,
) -> Result<PathChangeMeasures, VehicleError> {
    if rec.is_empty() {
        return Err(measure("path change", "the record is empty"));
    }
    let x0 = p.front_axle_x_m();
    let mut worst: f64 = 0.0;
    let mut last = 0.0;
    for i in 0..rec.len() {
        let (x, y, psi) = course_frame(
            course,
            x0,
            rec.front_axle_m[0][i],
            rec.front_axle_m[1][i],
            rec.heading_rad[i],
        );
        worst = worst.max(course.deviation(x, y, psi).abs());
        last = y;
    }
    let d_l = &rec.strut_disp_m[0];
    Ok(PathChangeMeasures {
        peak_articulation_deg: signed_peak(rec.articulation_rad.iter().map(|a| a.to_degrees())),
        strut_left_range_m: (
            d_l.iter().fold(0.0, |m: f64, v| m.min(*v)),
            d_l.iter().fold(0.0, |m: f64, v| m.max(*v)),
        ),
        // the record's rates and accelerations are left-turn positive
        peak_yaw_rate_deg_s: signed_peak(rec.front_rate_rad_s[2].iter().map(|r| -r.to_degrees())),
        peak_lateral_accel_m_s2: signed_peak(rec.front_lateral_accel_m_s2.iter().map(|a| -a)),
        max_deviation_m: worst,
        final_offset_m: last,
    })
}
