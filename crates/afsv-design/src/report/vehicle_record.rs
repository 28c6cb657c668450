//! The records of `afsv vehicle simulate` and `afsv vehicle path-change` (the 3-D vehicle
//! of Chapter 6, crate `vehicle-3d`) in the afsv-v1 sign convention (docs/records.md):
//! the record with the components' own channels when asked, its sidecar, and the summary
//! printed once it is written.

use super::vehicle::{rear_axle, terrain_json};
use afsv_records::{Record, RecordError};
use serde_json::{json, Value};
use std::path::Path;
use vehicle_3d::interconnect::Link;
use vehicle_3d::scenarios::{PathChangeMeasures, PathChangeSpec, TerrainSpec};
use vehicle_3d::{FrontAxle, Load, RunRecord, VehicleParams};
use vehicle_components::{Recorder, SteerInput};

/// The axes and signs of the record's ride channels (the sidecar's `axes`).
pub const AXES: &str = "cab_accel_*, front_pitch_accel: the front unit's body axes (x forward, y left, z up), kinematic acceleration without gravity at the a_wz point; front_pitch_accel right-handed about y (nose down positive); front_lateral_accel and rear_lateral_accel left positive; rear_ltr = (F_zL - F_zR)/(F_zL + F_zR) of the rear axle; hps_travel compression positive";

/// The model every record of the 3-D vehicle names.
const MODEL: &str = "vehicle-3d integrated 3-D articulated dump truck (chapter 6)";

/// The manoeuvre's name of a steering-wheel input (`straight` without one).
pub fn steer_label(input: &SteerInput) -> &'static str {
    match input {
        SteerInput::None => "straight",
        SteerInput::Pulse { .. } => "pulse",
        SteerInput::Ramp { .. } => "ramp",
        SteerInput::Step { .. } => "step",
        SteerInput::Table { .. } => "table",
    }
}

/// A run of `afsv vehicle simulate`, as its sidecar describes it.
#[derive(Debug, Clone, Copy)]
pub struct SimulateRun<'a> {
    /// The vehicle (validated).
    pub params: &'a VehicleParams,
    /// Its load case.
    pub load: Load,
    /// Its front axle.
    pub front_axle: FrontAxle,
    /// Target speed (km/h).
    pub speed_kmh: f64,
    /// The steering-wheel input.
    pub steer: &'a SteerInput,
    /// The ground: smooth (`None`) or the two-track terrain.
    pub terrain: &'a Option<TerrainSpec>,
    /// The run's terrain seed (one).
    pub seeds: &'a [u64],
    /// Output sample interval (s).
    pub output_dt_s: f64,
    /// The struts' interconnection of the vehicle description, if any.
    pub link: Option<&'a Link>,
}

/// The record of a run: the afsv-v1 columns of `rec`, then, when recorded, every
/// component's own channels (`components`, model signs; its time column is the record's).
pub fn simulate_record(
    rec: &RunRecord,
    components: Option<&Recorder>,
) -> Result<Record, RecordError> {
    let mut out = Record::from_columns(rec.afsv_v1_columns())?;
    if let Some(c) = components {
        // the first column is the time, which the record has
        for (i, name) in c.channels().names().iter().enumerate().skip(1) {
            let column = c.column_at(i).unwrap_or_default().to_vec();
            out.push_column(name, column)?;
        }
    }
    Ok(out)
}

/// The sidecar of `afsv vehicle simulate`'s record: the model, the run (load, axles,
/// speed, manoeuvre, ground, parameters), the axes and signs of the channels ([`AXES`]),
/// the interconnection when there is one, and the units of the component channels when
/// they were recorded.
pub fn simulate_sidecar(run: &SimulateRun, components: Option<&Recorder>) -> Value {
    let p = run.params;
    let mut meta = json!({
        "written_by": "afsv vehicle simulate",
        "sample_rate_hz": 1.0 / run.output_dt_s,
        "model": MODEL,
        "load": run.load,
        "front_axle": run.front_axle,
        "rear_axle": rear_axle(p),
        "speed_kmh": run.speed_kmh,
        "speed_m_s": run.speed_kmh / 3.6,
        "manoeuvre": steer_label(run.steer),
        "steer": run.steer,
        "terrain": terrain_json(run.terrain, run.seeds),
        "axes": AXES,
        "params": p,
    });
    if let Some(l) = run.link {
        meta["link"] = json!(l);
    }
    if let Some(c) = components {
        let ch = c.channels();
        meta["component_channels"] = json!({
            "signs": "each component's own (model signs, SI): strut forces of the steering positive extending, axle strut forces and travel compression positive",
            "units": ch.names().iter().zip(ch.units()).skip(1).map(|(n, u)| (n.clone(), json!(u))).collect::<serde_json::Map<_, _>>(),
        });
    }
    meta
}

/// The sidecar of `afsv vehicle path-change`'s record `rec`: the model, the course `spec`
/// on its ground and seed, the measures `m`, the axes and signs ([`AXES`]), the vehicle
/// `p` and its interconnection `link` when there is one.
pub fn path_change_sidecar(
    rec: &RunRecord,
    spec: &PathChangeSpec,
    seeds: &[u64],
    m: &PathChangeMeasures,
    p: &VehicleParams,
    link: Option<&Link>,
) -> Value {
    let mut meta = json!({
        "written_by": "afsv vehicle path-change",
        "sample_rate_hz": 1.0 / (rec.t_s[1] - rec.t_s[0]),
        "model": MODEL,
        "manoeuvre": "path_change",
        "spec": spec,
        "terrain": terrain_json(&spec.terrain, seeds),
        "measures": m,
        "axes": AXES,
        "params": p,
    });
    if let Some(l) = link {
        meta["link"] = json!(l);
    }
    meta
}

/// What `afsv vehicle simulate` prints once the record `output` is written with
/// `columns`: the files, the sample count and the signed peak articulation
/// ([`super::signed_peak`], deg).
pub fn simulate_summary(output: &Path, columns: &[String], rec: &RunRecord) -> Value {
    json!({
        "output": output,
        "sidecar": output.with_extension("json"),
        "samples": rec.len(),
        "columns": columns,
        "peak_articulation_deg": super::signed_peak(&rec.articulation_rad).to_degrees(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The sidecar carries the run's speed in both units and its manoeuvre's name, the
    /// link only when there is one, and the component units only when recorded.
    #[test]
    fn the_simulate_sidecar_describes_the_run() {
        let p = VehicleParams::nominal();
        let steer = SteerInput::None;
        let run = SimulateRun {
            params: &p,
            load: Load::Loaded,
            front_axle: FrontAxle::Rigid,
            speed_kmh: 18.0,
            steer: &steer,
            terrain: &None,
            seeds: &[0],
            output_dt_s: 0.005,
            link: None,
        };
        let meta = simulate_sidecar(&run, None);
        assert_eq!(meta["manoeuvre"], "straight");
        assert_eq!(meta["speed_m_s"], 5.0);
        assert_eq!(meta["sample_rate_hz"], 200.0);
        assert_eq!(meta["terrain"]["kind"], "smooth ground");
        assert!(meta.get("link").is_none() && meta.get("component_channels").is_none());
        assert_eq!(steer_label(&SteerInput::pulse_deg(10.0, 1.0, 0.0)), "pulse");
    }
}
