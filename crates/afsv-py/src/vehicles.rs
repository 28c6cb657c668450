//! The rigid mining truck of Chapter 2 (ramp steer to rollover, Eqs 2.1-2.11) and the 3-D
//! articulated vehicle of Chapter 6, on the library calls of `afsv roll simulate` and
//! `afsv vehicle simulate`, with the same record channels and signs (afsv-v1).

use crate::desc::DescRef;
use crate::{py_err, record_out, to_json, value_err};
use afsv_dynamics::SteerInput;
use perf_measures::roll::SustainedPeriodParams;
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use roll_truck::studies::run_case;
use roll_truck::{BuiltinTruck, SteerDirection, TruckParams};
use serde_json::json;
use terrain_psd::{Band, CoherenceModel, IsoClass, PowerLawPsd, TwoTrackSpec};
use vehicle_3d::scenarios::TerrainSpec;
use vehicle_3d::{FrontAxle, Load, Vehicle, VehicleOptions};
use vehicle_components::FlatTerrain;

/// Largest steering-wheel angle of a 3-D run's steer input (deg), as the CLI.
const MAX_STEER_DEG: f64 = 1000.0;
/// Longest 3-D run (s), as the CLI.
const MAX_DURATION_S: f64 = 600.0;

/// A finite positive number, named in the error.
fn positive(name: &str, v: f64) -> PyResult<f64> {
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(value_err(format!(
            "{name} {v}: must be a finite number > 0"
        )))
    }
}

/// The truck: a rigid-truck description, else the built-in `truck` (`calibrated` or
/// `plausible`), with the CLI's overrides, validated.
fn truck_params(
    vehicle: Option<DescRef<'_>>,
    truck: &str,
    cg_height_m: Option<f64>,
    ramp_rate: Option<f64>,
    no_bump_stops: bool,
) -> PyResult<TruckParams> {
    let mut p = match vehicle {
        Some(r) => match crate::desc::load(r)?.vehicle {
            afsv_vehicle::Vehicle::RigidTruck(t) => t.params,
            afsv_vehicle::Vehicle::Articulated(a) => {
                return Err(value_err(format!(
                    "vehicle: `{}` is articulated; the truck model runs a rigid truck",
                    a.name
                )))
            }
        },
        None => truck
            .parse::<BuiltinTruck>()
            .map_err(|e| value_err(format!("truck: {e}")))?
            .params(),
    };
    if let Some(h) = cg_height_m {
        p.cg_height_m = positive("cg_height_m", h)?;
    }
    if let Some(r) = ramp_rate {
        p.steering_wheel_rate_deg_s = positive("ramp_rate", r)?;
    }
    if no_bump_stops {
        p = p.without_bump_stops();
    }
    p.validate().map_err(|e| value_err(e.to_string()))?;
    Ok(p)
}

/// A ramp-steer run of the truck to absolute rollover (Chapter 2) on level ground
/// (`terrain_class` None) or on the two-track terrain of Eqs 2.8-2.10: the record of
/// `afsv roll simulate` and its roll measures (DRT, SP-DRT, Eq 2.11) in the metadata.
#[pyfunction]
#[pyo3(signature = (vehicle, truck, cg_height_m, ramp_rate, no_bump_stops, direction, terrain_class, waviness, band, mc, seed, duration, dt, sp_threshold, sp_max_dip))]
#[allow(clippy::too_many_arguments)]
fn simulate_truck<'py>(
    py: Python<'py>,
    vehicle: Option<crate::desc::DescArg>,
    truck: &str,
    cg_height_m: Option<f64>,
    ramp_rate: Option<f64>,
    no_bump_stops: bool,
    direction: &str,
    terrain_class: Option<&str>,
    waviness: f64,
    band: (f64, f64),
    mc: f64,
    seed: u64,
    duration: Option<f64>,
    dt: f64,
    sp_threshold: Option<f64>,
    sp_max_dip: Option<f64>,
) -> PyResult<Bound<'py, PyTuple>> {
    let p = truck_params(
        crate::desc::as_ref(&vehicle),
        truck,
        cg_height_m,
        ramp_rate,
        no_bump_stops,
    )?;
    let direction: SteerDirection = direction
        .parse()
        .map_err(|e| value_err(format!("direction: {e}")))?;
    let duration = match duration {
        Some(d) => positive("duration", d)?,
        None => roll_truck::sensitivity::ramp_duration_s(&p),
    };
    if duration > 3600.0 {
        return Err(value_err(format!("duration {duration}: at most 3600 s")));
    }
    positive("dt", dt)?;
    let max = roll_truck::simulate::MAX_SAMPLES as f64;
    if duration / dt > max {
        return Err(value_err(format!(
            "duration/dt = {:.0} samples: at most {max:e}",
            duration / dt
        )));
    }
    let spec = match terrain_class {
        None => None,
        Some(c) => {
            let class: IsoClass = c
                .parse()
                .map_err(|e| value_err(format!("terrain_class: {e}")))?;
            let psd = PowerLawPsd::new(class.alpha_r(), positive("waviness", waviness)?)
                .map_err(|e| value_err(e.to_string()))?;
            let band = Band::new(band.0, band.1).map_err(|e| value_err(format!("band: {e}")))?;
            let coh = CoherenceModel::piecewise(mc).map_err(|e| value_err(format!("mc: {e}")))?;
            Some(TwoTrackSpec::new(psd, band, coh).map_err(|e| value_err(e.to_string()))?)
        }
    };
    let mut sp = SustainedPeriodParams::default();
    if let Some(t) = sp_threshold {
        sp.threshold = t;
    }
    if let Some(d) = sp_max_dip {
        sp.max_dip_s = d;
    }
    sp.validate()
        .map_err(|e| value_err(format!("sp_threshold/sp_max_dip: {e}")))?;
    let options = roll_truck::RunOptions {
        t_end_s: duration,
        output_dt_s: dt,
        acceleration_channels: true,
        ..roll_truck::RunOptions::default()
    };
    let run = py
        .detach(|| run_case(&p, spec.as_ref(), seed, direction, &options, &sp))
        .map_err(|e| py_err(py, &e))?;
    let r = &run.record;
    let meta = json!({
        "model": "roll-truck rigid mining truck (chapter 2)",
        "sample_rate_hz": 1.0 / dt,
        "manoeuvre": format!("ramp steer ({direction})"),
        "params": to_json(&p)?,
        "rollover_s": r.rollover_s,
        "measures": to_json(&run.measures)?,
        "sustained_period_rule": to_json(&sp)?,
    });
    record_out(py, &r.afsv_v1_columns(), &meta)
}

/// A steer input of the 3-D vehicle: `("none",)`, `("pulse", DEG, DUR_S, START_S)` or
/// `("ramp", DEG_PER_S, START_S[, LIMIT_DEG])`, within the CLI's bounds.
fn steer_input(kind: &str, values: &[f64]) -> PyResult<SteerInput> {
    let bounded = |what: &str, v: f64, max: f64| -> PyResult<f64> {
        if v.is_finite() && v.abs() <= max {
            Ok(v)
        } else {
            Err(value_err(format!(
                "steer {what} {v}: must be finite and at most {max} in magnitude"
            )))
        }
    };
    let input = match (kind, values) {
        ("none", []) => SteerInput::None,
        ("pulse", [a, d, t0]) => SteerInput::pulse_deg(
            bounded("pulse peak", *a, MAX_STEER_DEG)?,
            bounded("pulse duration", *d, MAX_DURATION_S)?,
            bounded("pulse start", *t0, MAX_DURATION_S)?,
        ),
        ("ramp", [r, t0, rest @ ..]) if rest.len() <= 1 => {
            let rate = bounded("ramp rate", *r, 1000.0)?;
            if rate.abs() < 0.01 {
                return Err(value_err(format!(
                    "steer ramp rate {rate}: must be at least 0.01 deg/s in magnitude"
                )));
            }
            SteerInput::Ramp {
                rate_rad_s: rate.to_radians(),
                start_s: bounded("ramp start", *t0, MAX_DURATION_S)?,
                limit_rad: match rest {
                    [l] => bounded("ramp limit", *l, MAX_STEER_DEG)?.abs().to_radians(),
                    _ => MAX_STEER_DEG.to_radians(),
                },
            }
        }
        _ => {
            return Err(value_err(format!(
                "steer ({kind}, {values:?}) not understood (expected (\"none\",), (\"pulse\", DEG, DUR_S, START_S) or (\"ramp\", DEG_PER_S, START_S[, LIMIT_DEG]))"
            )))
        }
    };
    input
        .validate()
        .map_err(|e| value_err(format!("steer: {e}")))?;
    Ok(input)
}

/// One run of the 3-D articulated vehicle (Chapter 6) on smooth ground or on the two-track
/// terrain of Eqs 6.4-6.5: the record of `afsv vehicle simulate`.
#[pyfunction]
#[pyo3(signature = (vehicle, load, speed_kmh, terrain_class, mc, seed, hps, steer_kind, steer_values, duration, dt))]
#[allow(clippy::too_many_arguments)]
fn simulate_vehicle<'py>(
    py: Python<'py>,
    vehicle: Option<crate::desc::DescArg>,
    load: &str,
    speed_kmh: f64,
    terrain_class: Option<&str>,
    mc: f64,
    seed: u64,
    hps: Option<&str>,
    steer_kind: &str,
    steer_values: Vec<f64>,
    duration: f64,
    dt: f64,
) -> PyResult<Bound<'py, PyTuple>> {
    if !(speed_kmh.is_finite() && speed_kmh > 0.0 && speed_kmh <= 80.0) {
        return Err(value_err(format!(
            "speed_kmh {speed_kmh}: must be in (0, 80] km/h"
        )));
    }
    if !(duration.is_finite() && duration > 0.0 && duration <= MAX_DURATION_S) {
        return Err(value_err(format!(
            "duration {duration}: must be in (0, {MAX_DURATION_S}] s"
        )));
    }
    positive("dt", dt)?;
    let max = vehicle_3d::simulate::MAX_SAMPLES as f64;
    if duration / dt > max {
        return Err(value_err(format!(
            "duration/dt = {:.0} samples: at most {max:e}",
            duration / dt
        )));
    }
    let load: Load = load.parse().map_err(|e| value_err(format!("load: {e}")))?;
    let input = steer_input(steer_kind, &steer_values)?;
    let v = crate::desc::articulated(crate::desc::as_ref(&vehicle))?;
    let mut p = v.params.clone();
    let axle = match hps {
        None => match v.front_suspension {
            afsv_vehicle::schema::Suspension::Hps => FrontAxle::Suspended,
            afsv_vehicle::schema::Suspension::Rigid => FrontAxle::Rigid,
        },
        Some("off") => FrontAxle::Rigid,
        Some("nominal") if v.front_strut.is_none() => {
            return Err(value_err(
                "hps nominal: the vehicle description gives the front axle no strut",
            ))
        }
        Some("nominal") => FrontAxle::Suspended,
        Some(file) => {
            p.hps = afsv_vehicle::read_strut_file(std::path::Path::new(file))
                .map_err(|e| value_err(format!("hps: {e}")))?;
            FrontAxle::Suspended
        }
    };
    p.validate().map_err(|e| value_err(e.to_string()))?;
    let terrain = match terrain_class {
        None => None,
        Some(c) => {
            let class: IsoClass = c.parse().map_err(|_| {
                value_err(format!(
                    "terrain_class `{c}`: expected an ISO 8608 class A to H"
                ))
            })?;
            Some(TerrainSpec {
                class,
                m_c: positive("mc", mc)?,
                ..TerrainSpec::default()
            })
        }
    };
    let speed = speed_kmh / 3.6;
    let options = VehicleOptions {
        front_axle: axle,
        speed_m_s: speed,
        steer: input.clone(),
        path_length_m: speed * duration + 5.0,
        ..VehicleOptions::default()
    };
    let run = vehicle_3d::RunOptions {
        t_end_s: duration,
        output_dt_s: dt,
        ..vehicle_3d::RunOptions::default()
    };
    let half = 0.5 * p.front_track_m;
    let flat =
        FlatTerrain::new(0.0, vehicle_components::DEFAULT_FRICTION).map_err(|e| py_err(py, &e))?;
    let rec = py
        .detach(|| match &terrain {
            None => vehicle_3d::simulate(&Vehicle::new(&p, load, options, &flat, half)?, &run),
            Some(t) => {
                let length = options.start_s_m + options.path_length_m + 50.0;
                let ground = t.build(&p, length, seed)?;
                vehicle_3d::simulate(&Vehicle::new(&p, load, options, &ground, half)?, &run)
            }
        })
        .map_err(|e| py_err(py, &e))?;
    let meta = json!({
        "model": "vehicle-3d integrated 3-D articulated dump truck (chapter 6)",
        "sample_rate_hz": 1.0 / dt,
        "load": to_json(&load)?,
        "front_axle": to_json(&axle)?,
        "speed_kmh": speed_kmh,
        "speed_m_s": speed,
        "steer": to_json(&input)?,
        "terrain": match &terrain {
            None => json!({ "kind": "smooth ground" }),
            Some(t) => json!({
                "kind": "two-track terrain (Eqs 6.4-6.5)",
                "class": t.class.to_string(),
                "m_c_cycles_per_m": t.m_c,
                "band_cycles_per_m": [t.band.0, t.band.1],
                "seed": seed,
            }),
        },
        "params": to_json(&p)?,
    });
    record_out(py, &rec.afsv_v1_columns(), &meta)
}

/// Register the truck and 3-D vehicle functions.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(simulate_truck, m)?)?;
    m.add_function(wrap_pyfunction!(simulate_vehicle, m)?)?;
    Ok(())
}
