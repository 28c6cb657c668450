//! `afsv hps thermal`: the struts of a vehicle over a working shift, their gas and body
//! temperatures and the ride height these set, with and without a levelling valve
//! (`hps_emulsion::thermal`, docs/layouts.md "HPS temperature and ride height").
//!
//! The vehicle part: each suspended axle's strut carries its static load from the hand
//! statics of `vehicle_3d::Statics` (tire load less the wheel end); the strut's thermal data
//! are `ThermalParams::for_strut`'s; the dissipation is given (`--power-w`), read from a D1
//! ride of the vehicle (`--ride`: each strut's travel replayed through it) or from a
//! simulated harmonic stroke of that strut (`--stroke-hz`, `--stroke-mm`).

use super::{args, CmdResult};
use afsv::output::OutputGuard;
use hps_emulsion::thermal::KELVIN_AT_0C;
use hps_emulsion::{
    mean_dissipation_w, run_harmonic, HarmonicTest, HpsError, HpsExtensions, LevellingValve,
    SimOptions, StrutParams, ThermalConditions, ThermalParams, ThermalRecord, ThermalStrut,
};
use serde_json::{json, Value};
use std::path::PathBuf;
use vehicle_3d::scenarios::{RideSpec, RUN_IN_M};
use vehicle_3d::{FrontAxle, Load, Statics, VehicleParams};

/// Longest shift (h).
const MAX_HOURS: f64 = 72.0;

/// Options of `afsv hps thermal`.
#[derive(clap::Args)]
pub struct ThermalArgs {
    #[arg(long, help = super::described::HELP)]
    pub vehicle: Option<PathBuf>,
    /// Load case whose static strut loads are carried.
    #[arg(long, default_value = "loaded")]
    pub load: Load,
    /// Also a rear strut when the description's rear axle is rigid: the front strut scaled
    /// for the rear static load (the designer's default rear strut, docs/layouts.md).
    #[arg(long)]
    pub with_rear: bool,
    /// Ambient temperature (degC).
    #[arg(long = "ambient-c", default_value_t = 20.0, allow_hyphen_values = true, value_parser = args::finite_f64)]
    pub ambient_c: f64,
    /// Temperature at which the gas was charged and the ride height set (degC).
    #[arg(long = "charge-c", default_value_t = 20.0, allow_hyphen_values = true, value_parser = args::finite_f64)]
    pub charge_c: f64,
    /// Strut temperature at the start of the shift (degC); default: the ambient (parked
    /// overnight).
    #[arg(long = "start-c", allow_hyphen_values = true, value_parser = args::finite_f64)]
    pub start_c: Option<f64>,
    /// Mean damping dissipation of each strut (W). Without it, each strut's dissipation is
    /// read from a simulated harmonic stroke (--stroke-hz, --stroke-mm).
    #[arg(long = "power-w", allow_hyphen_values = true, value_parser = args::nonneg_f64)]
    pub power_w: Option<f64>,
    /// Read each strut's dissipation from a D1 ride of the vehicle (class E terrain, the
    /// struts' recorded travel replayed through the strut) instead of a harmonic stroke.
    #[arg(long, conflicts_with = "power_w")]
    pub ride: bool,
    /// Speed of that ride (km/h), in (0, 80].
    #[arg(long = "speed-kmh", default_value_t = 20.0, allow_hyphen_values = true, value_parser = args::positive_f64, requires = "ride")]
    pub speed_kmh: f64,
    /// Terrain seed of that ride.
    #[arg(long, default_value_t = 1, requires = "ride")]
    pub seed: u64,
    /// Frequency of the harmonic stroke that sets the dissipation (Hz).
    #[arg(long = "stroke-hz", default_value_t = 1.0, allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub stroke_hz: f64,
    /// Amplitude of that stroke (mm); the default 1 Hz, 10 mm (63 mm/s peak) is an
    /// assumed moderate working ride, not a measured one.
    #[arg(long = "stroke-mm", default_value_t = 10.0, allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub stroke_mm: f64,
    /// Length of the shift (h), at most 72.
    #[arg(long, default_value_t = 8.0, allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub hours: f64,
    /// Time between table rows (min).
    #[arg(long = "step-min", default_value_t = 30.0, allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub step_min: f64,
    /// Levelling valve deadband, half width (mm).
    #[arg(long = "deadband-mm", default_value_t = 5.0, allow_hyphen_values = true, value_parser = args::nonneg_f64)]
    pub deadband_mm: f64,
    /// Levelling valve time constant (s).
    #[arg(long = "levelling-tau-s", default_value_t = 30.0, allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub levelling_tau_s: f64,
    /// Levelling valve's largest flow (L/min).
    #[arg(long = "levelling-flow-l-min", default_value_t = 6.0, allow_hyphen_values = true, value_parser = args::positive_f64)]
    pub levelling_flow_l_min: f64,
    /// Replace an existing -o file afsv did not write (never the --vehicle file).
    #[arg(long)]
    pub force: bool,
    #[command(flatten)]
    pub table: afsv::table::TableOutput,
}

/// One suspended axle's strut over the shift, without and with levelling.
struct AxleRun {
    name: &'static str,
    strut: ThermalStrut,
    power_w: f64,
    power_source: String,
    drift: ThermalRecord,
    levelled: ThermalRecord,
}

/// Run `afsv hps thermal`.
pub fn run(a: ThermalArgs) -> CmdResult {
    if a.hours > MAX_HOURS {
        return Err(format!("--hours {}: at most {MAX_HOURS}", args::show(a.hours)).into());
    }
    let step_s = a.step_min * 60.0;
    args::check_samples(
        &format!("--step-min {}", args::show(a.step_min)),
        &format!("--hours {} * 60 / --step-min", args::show(a.hours)),
        a.hours * 3600.0 / step_s,
        args::MAX_HPS_SAMPLES,
    )?;
    let mut guard = OutputGuard::new(a.force);
    if let Some(v) = a
        .vehicle
        .as_deref()
        .filter(|v| super::described::is_file(v))
    {
        guard.input("--vehicle", v)?;
    }
    a.table.declare(&mut guard)?;
    let v = super::described::articulated(a.vehicle.as_deref())?;
    let mut params = v.params.clone();
    let front = v.front_strut.ok_or_else(|| {
        format!(
            "--vehicle: `{}` gives the front axle no strut (add `strut = \"front-axle\"` or a strut file to its front [[axle]])",
            v.name
        )
    })?;
    params.hps = front;
    let statics = Statics::of(&params, a.load)?;
    let rear = match (&params.rear_hps, a.with_rear) {
        (Some(r), _) => Some(*r),
        (None, true) => Some(params.default_rear_strut()?),
        (None, false) => None,
    };
    let valve = LevellingValve {
        deadband_m: a.deadband_mm * 1e-3,
        time_constant_s: a.levelling_tau_s,
        max_flow_m3_s: a.levelling_flow_l_min * 1e-3 / 60.0,
    };
    valve
        .validate()
        .map_err(|e| format!("--deadband-mm, --levelling-tau-s, --levelling-flow-l-min: {e}"))?;
    let ambient_k = KELVIN_AT_0C + a.ambient_c;
    let start_k = KELVIN_AT_0C + a.start_c.unwrap_or(a.ambient_c);
    let duration = a.hours * 3600.0;
    let mut axles = vec![("front", front, statics.front_strut_force_n(&params))];
    if let Some(r) = rear {
        axles.push(("rear", r, statics.rear_strut_force_n(&params)));
    }
    let ride = if a.ride {
        if a.speed_kmh > 80.0 {
            return Err(format!("--speed-kmh {}: at most 80", args::show(a.speed_kmh)).into());
        }
        let mut p = params.clone();
        p.rear_hps = rear;
        Some(ride_powers(&p, a.load, a.speed_kmh, a.seed)?)
    } else {
        None
    };
    let mut runs = Vec::with_capacity(axles.len());
    let mut skipped = Vec::new();
    for (name, strut_params, load_n) in axles {
        let mut thermal = ThermalParams::for_strut(&strut_params)?;
        thermal.charge_temperature_k = KELVIN_AT_0C + a.charge_c;
        let strut = match ThermalStrut::new(&strut_params, &thermal, load_n) {
            Ok(s) => s,
            // A strut scaled for the loaded rear axle tops out unloaded (docs/layouts.md,
            // "HPS on any axle"): on its end stop the ride height cannot drift.
            Err(HpsError::InvalidParameter {
                field: "load_n", ..
            }) => {
                skipped.push(json!({
                    "axle": name,
                    "strut_load_n": load_n,
                    "reason": "the strut cannot carry this static load within its travel: it rests on an end stop, where the ride height does not drift",
                }));
                continue;
            }
            Err(e) => return Err(format!("{name} strut: {e}").into()),
        };
        let (power_w, power_source) = match (a.power_w, &ride) {
            (Some(p), _) => (p, "--power-w".to_string()),
            (None, Some(r)) => (
                if name == "front" { r[0] } else { r[1] },
                format!(
                    "D1 ride, class E, {} km/h, seed {}: the strut travel replayed through the strut, mean of left and right",
                    args::show(a.speed_kmh),
                    a.seed
                ),
            ),
            (None, None) => (
                stroke_power(&strut_params, a.stroke_hz, a.stroke_mm)?,
                format!(
                    "simulated harmonic stroke {} Hz, {} mm about mid-stroke (mean dissipated power)",
                    args::show(a.stroke_hz),
                    args::show(a.stroke_mm)
                ),
            ),
        };
        let cond = ThermalConditions {
            ambient_k,
            power_w,
            initial_gas_k: start_k,
            initial_body_k: start_k,
        };
        let drift = strut.run(&cond, duration, step_s)?;
        let levelled_strut = strut.clone().with_levelling(valve)?;
        let levelled = levelled_strut.run(&cond, duration, step_s)?;
        runs.push(AxleRun {
            name,
            strut,
            power_w,
            power_source,
            drift,
            levelled,
        });
    }
    if runs.is_empty() {
        return Err(format!(
            "no strut of `{}` carries its static load within its travel",
            v.name
        )
        .into());
    }
    emit(&a, &v.name, &runs, &skipped, &valve)
}

/// Mean dissipated power (W) per strut, front then rear (0 without rear struts), in one D1
/// ride of `p` (front axle suspended) at `speed_kmh` on terrain `seed`: each strut's
/// recorded travel after the run-in replayed through it
/// ([`hps_emulsion::mean_dissipation_w`]), left and right averaged.
fn ride_powers(
    p: &VehicleParams,
    load: Load,
    speed_kmh: f64,
    seed: u64,
) -> Result<[f64; 2], String> {
    let spec = RideSpec {
        speed_kmh,
        ..RideSpec::d1(load, FrontAxle::Suspended)
    };
    let (rec, _) =
        vehicle_3d::scenarios::ride(p, &spec, seed).map_err(|e| format!("--ride: {e}"))?;
    let i0 = rec
        .t_s
        .partition_point(|&t| t < RUN_IN_M / (speed_kmh / 3.6));
    let time = &rec.t_s[i0..];
    let mean = |strut: &StrutParams, travel: &[Vec<f64>; 2]| -> Result<f64, String> {
        let mut sum = 0.0;
        for side in travel {
            sum += mean_dissipation_w(strut, time, &side[i0..])
                .map_err(|e| format!("--ride: replaying the strut travel: {e}"))?;
        }
        Ok(0.5 * sum)
    };
    let front = mean(&p.hps, &rec.hps_travel_m)?;
    let rear = match &p.rear_hps {
        Some(r) => mean(r, &rec.rear_hps_travel_m)?,
        None => 0.0,
    };
    Ok([front, rear])
}

/// Mean dissipated power (W) of `strut` in a harmonic stroke about mid-stroke: the last of
/// three cycles' `closed integral F dz` times the frequency.
fn stroke_power(strut: &StrutParams, hz: f64, mm: f64) -> Result<f64, String> {
    let test = HarmonicTest {
        frequency_hz: hz,
        amplitude_m: mm * 1e-3,
    };
    let (_, m) = run_harmonic(
        strut,
        &HpsExtensions::none(),
        &test,
        3.0,
        &SimOptions::default(),
    )
    .map_err(|e| format!("--stroke-hz/--stroke-mm: {e}"))?;
    Ok(m.dissipated_energy_j * hz)
}

fn celsius(k: f64) -> f64 {
    k - KELVIN_AT_0C
}

fn emit(
    a: &ThermalArgs,
    vehicle: &str,
    runs: &[AxleRun],
    skipped: &[Value],
    valve: &LevellingValve,
) -> CmdResult {
    let t_ref = a.charge_c;
    let mut summary = format!(
        "{vehicle}, {}, ambient {} degC, charged at {} degC, start {} degC, {} h\n",
        match a.load {
            Load::Loaded => "loaded",
            Load::Unloaded => "unloaded",
        },
        args::show(a.ambient_c),
        args::show(t_ref),
        args::show(a.start_c.unwrap_or(a.ambient_c)),
        args::show(a.hours)
    );
    let mut axles = Vec::with_capacity(runs.len());
    for r in runs {
        let s = &r.strut;
        let n = r.drift.time_s.len() - 1;
        let k0 = s.stiffness_n_m(
            s.thermal().charge_temperature_k,
            s.thermal().charge_temperature_k,
            0.0,
        );
        let [fast, slow] = s.time_constants_s();
        let steady = s.steady_temperature_k(KELVIN_AT_0C + a.ambient_c, r.power_w);
        // the largest drift of the shift against the travel: past it the strut is on its
        // stop and the drift law no longer holds
        let within = r
            .drift
            .ride_height_m
            .iter()
            .all(|h| (s.static_travel_m() - h).abs() <= s.params().travel);
        let end = json!({
            "gas_c": celsius(r.drift.gas_k[n]),
            "body_c": celsius(r.drift.body_k[n]),
            "ride_height_mm": r.drift.ride_height_m[n] * 1e3,
            "levelled_ride_height_mm": r.levelled.ride_height_m[n] * 1e3,
            "levelled_oil_l": r.levelled.levelled_m3[n] * 1e3,
            "stiffness_ratio": r.drift.stiffness_n_m[n] / k0,
            "within_travel": within,
            "levelled_stiffness_ratio": r.levelled.stiffness_n_m[n] / k0,
        });
        summary += &format!(
            "{} strut: load {:.1} kN at {:.2} MPa, {:.0} W ({}); steady {:.1} degC (body time constant {:.2} h); after {} h: body {:.1} degC, ride height {:+.1} mm ({:+.1} mm levelled), stiffness x{:.3}; {:.2} mm/K\n",
            r.name,
            s.load_n() * 1e-3,
            s.pressure_pa() * 1e-6,
            r.power_w,
            match (a.power_w, a.ride) {
                (Some(_), _) => "given",
                (None, true) => "D1 ride",
                (None, false) => "stroke",
            },
            celsius(steady),
            slow / 3600.0,
            args::show(a.hours),
            celsius(r.drift.body_k[n]),
            r.drift.ride_height_m[n] * 1e3,
            r.levelled.ride_height_m[n] * 1e3,
            r.drift.stiffness_n_m[n] / k0,
            s.ride_height_per_kelvin() * 1e3,
        );
        if !within {
            summary += &format!(
                "  {} strut: the unlevelled drift passes the end of the travel (static travel {:.1} mm of +-{:.0} mm): past it the strut rests on its stop and the drift law does not hold\n",
                r.name,
                s.static_travel_m() * 1e3,
                s.params().travel * 1e3
            );
        }
        let (cg, cb) = s.capacities_j_k();
        let (ggb, gba) = s.conductances_w_k();
        axles.push(json!({
            "axle": r.name,
            "strut_load_n": s.load_n(),
            "pressure_pa": s.pressure_pa(),
            "static_travel_m": s.static_travel_m(),
            "gas_volume_m3": s.gas_volume_m3(),
            "gas_mass_kg": s.gas_mass_kg(),
            "thermal": s.thermal(),
            "gas_capacity_j_k": cg,
            "body_capacity_j_k": cb,
            "gas_body_conductance_w_k": ggb,
            "body_ambient_conductance_w_k": gba,
            "time_constants_s": [fast, slow],
            "power_w": r.power_w,
            "power_source": r.power_source,
            "steady_temperature_c": celsius(steady),
            "ride_height_per_kelvin_m": s.ride_height_per_kelvin(),
            "stiffness_at_charge_n_m": k0,
            "end": end,
        }));
    }
    for k in skipped {
        summary += &format!(
            "{} strut: {}\n",
            k["axle"].as_str().unwrap_or("?"),
            k["reason"].as_str().unwrap_or("?")
        );
    }
    let front = &runs[0];
    let mut rows = Vec::with_capacity(front.drift.time_s.len());
    for i in 0..front.drift.time_s.len() {
        let mut row = json!({ "time_h": front.drift.time_s[i] / 3600.0 });
        for r in runs {
            let p = r.name;
            row[format!("{p}_gas_c")] = json!(celsius(r.drift.gas_k[i]));
            row[format!("{p}_body_c")] = json!(celsius(r.drift.body_k[i]));
            row[format!("{p}_ride_height_mm")] = json!(r.drift.ride_height_m[i] * 1e3);
            row[format!("{p}_levelled_mm")] = json!(r.levelled.ride_height_m[i] * 1e3);
            row[format!("{p}_stiffness_ratio")] = json!(
                r.drift.stiffness_n_m[i]
                    / r.strut.stiffness_n_m(
                        r.strut.thermal().charge_temperature_k,
                        r.strut.thermal().charge_temperature_k,
                        0.0
                    )
            );
        }
        rows.push(row);
    }
    let mut names = vec!["time_h".to_string()];
    for r in runs {
        for c in [
            "gas_c",
            "body_c",
            "ride_height_mm",
            "levelled_mm",
            "stiffness_ratio",
        ] {
            names.push(format!("{}_{c}", r.name));
        }
    }
    let name_refs: Vec<&str> = names.iter().map(String::as_str).collect();
    let table = afsv::table::from_rows(&rows, &name_refs)?;
    let conditions = json!({
        "load": a.load,
        "ambient_c": a.ambient_c,
        "charge_c": a.charge_c,
        "start_c": a.start_c.unwrap_or(a.ambient_c),
        "hours": a.hours,
        "levelling_valve": valve,
    });
    let full: Value = json!({
        "vehicle": vehicle,
        "conditions": conditions,
        "axles": axles,
        "axles_on_end_stop": skipped,
        "rows": rows,
        "ride_height_sign": "up positive (strut extended), from the static ride height at the charge temperature",
        "provenance": afsv::provenance::stamp(),
    });
    a.table.emit(
        &table,
        &full,
        &summary,
        "afsv hps thermal",
        json!({ "vehicle": vehicle, "conditions": conditions }),
    )?;
    Ok(())
}
