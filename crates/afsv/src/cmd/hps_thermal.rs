//! `afsv hps thermal`: the struts of a vehicle over a working shift, their gas and body
//! temperatures and the ride height these set, with and without a levelling valve
//! (`hps_emulsion::thermal`, docs/layouts.md "HPS temperature and ride height").
//!
//! The shift is `afsv_design::strut_shift`'s; the dissipation is given (`--power-w`), read
//! from a D1 ride of the vehicle (`--ride`: each strut's travel replayed through it) or from
//! a simulated harmonic stroke of that strut (`--stroke-hz`, `--stroke-mm`).

use super::{args, CmdResult};
use afsv::output::OutputGuard;
use afsv_design::strut_shift::{strut_shift, HeatInput, Shift, ShiftSpec};
use hps_emulsion::thermal::KELVIN_AT_0C;
use hps_emulsion::LevellingValve;
use serde_json::{json, Value};
use std::path::PathBuf;
use vehicle_3d::Load;

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

/// Run `afsv hps thermal`.
pub fn run(a: ThermalArgs) -> CmdResult {
    if a.hours > MAX_HOURS {
        return Err(format!("--hours {}: at most {MAX_HOURS}", args::show(a.hours)).into());
    }
    if a.ride && a.speed_kmh > 80.0 {
        return Err(format!("--speed-kmh {}: at most 80", args::show(a.speed_kmh)).into());
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
    params.hps = v.front_strut.ok_or_else(|| {
        format!(
            "--vehicle: `{}` gives the front axle no strut (add `strut = \"front-axle\"` or a strut file to its front [[axle]])",
            v.name
        )
    })?;
    let valve = LevellingValve {
        deadband_m: a.deadband_mm * 1e-3,
        time_constant_s: a.levelling_tau_s,
        max_flow_m3_s: a.levelling_flow_l_min * 1e-3 / 60.0,
    };
    valve
        .validate()
        .map_err(|e| format!("--deadband-mm, --levelling-tau-s, --levelling-flow-l-min: {e}"))?;
    let heat = match (a.power_w, a.ride) {
        (Some(p), _) => HeatInput::Given(p),
        (None, true) => HeatInput::Ride {
            speed_kmh: a.speed_kmh,
            seed: a.seed,
        },
        (None, false) => HeatInput::Stroke {
            frequency_hz: a.stroke_hz,
            amplitude_m: a.stroke_mm * 1e-3,
        },
    };
    let spec = ShiftSpec {
        load: a.load,
        with_rear: a.with_rear,
        ambient_k: KELVIN_AT_0C + a.ambient_c,
        charge_k: KELVIN_AT_0C + a.charge_c,
        start_k: KELVIN_AT_0C + a.start_c.unwrap_or(a.ambient_c),
        duration_s: a.hours * 3600.0,
        step_s,
        valve,
        heat,
    };
    let shift = strut_shift(&params, &spec).map_err(|e| format!("`{}`: {e}", v.name))?;
    emit(&a, &v.name, &shift, &valve)
}

fn celsius(k: f64) -> f64 {
    k - KELVIN_AT_0C
}

fn emit(a: &ThermalArgs, vehicle: &str, shift: &Shift, valve: &LevellingValve) -> CmdResult {
    let runs = &shift.axles;
    let skipped: Vec<Value> = shift
        .on_stop
        .iter()
        .map(|k| {
            json!({
                "axle": k.axle,
                "strut_load_n": k.load_n,
                "reason": "the strut cannot carry this static load within its travel: it rests on an end stop, where the ride height does not drift",
            })
        })
        .collect();
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
            r.axle,
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
                r.axle,
                s.static_travel_m() * 1e3,
                s.params().travel * 1e3
            );
        }
        let (cg, cb) = s.capacities_j_k();
        let (ggb, gba) = s.conductances_w_k();
        axles.push(json!({
            "axle": r.axle,
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
    for k in &skipped {
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
            let p = r.axle;
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
            names.push(format!("{}_{c}", r.axle));
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
