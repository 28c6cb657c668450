//! The report of `afsv hps thermal`: a vehicle's struts over a working shift
//! ([`crate::strut_shift::Shift`]) as rows per time step (gas and body temperatures, ride
//! height without and with the levelling valve, stiffness), per-strut results (statics,
//! thermal network, steady temperature, the end of the shift), and summary lines.

use super::show;
use crate::strut_shift::{HeatInput, Shift, ShiftSpec};
use afsv_records::Record;
use hps_emulsion::thermal::KELVIN_AT_0C;
use serde_json::{json, Value};
use vehicle_3d::Load;

/// The conditions of a shift as the user gave them (degC and h, reported as given).
pub struct ShiftConditions {
    /// Load case.
    pub load: Load,
    /// Ambient temperature (degC).
    pub ambient_c: f64,
    /// Temperature at which the struts were charged (degC).
    pub charge_c: f64,
    /// Strut temperature at the start of the shift (degC).
    pub start_c: f64,
    /// Length of the shift (h).
    pub hours: f64,
}

/// `k` (K) in degC.
fn celsius(k: f64) -> f64 {
    k - KELVIN_AT_0C
}

/// The shift `shift` of the vehicle `vehicle` run as `spec` under `c`: the table of rows, the
/// whole result as JSON (without provenance) and the summary lines. A strut whose unlevelled
/// drift passes the end of its travel is flagged (`within_travel`: the drift law no longer
/// holds there); struts resting on an end stop are listed with the reason.
pub fn shift_report(
    vehicle: &str,
    c: &ShiftConditions,
    spec: &ShiftSpec,
    shift: &Shift,
) -> Result<(Record, Value, String), String> {
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
    let t_ref = c.charge_c;
    let mut summary = format!(
        "{vehicle}, {}, ambient {} degC, charged at {} degC, start {} degC, {} h\n",
        match c.load {
            Load::Loaded => "loaded",
            Load::Unloaded => "unloaded",
        },
        show(c.ambient_c),
        show(t_ref),
        show(c.start_c),
        show(c.hours)
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
        let steady = s.steady_temperature_k(KELVIN_AT_0C + c.ambient_c, r.power_w);
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
            match spec.heat {
                HeatInput::Given(_) => "given",
                HeatInput::Ride { .. } => "D1 ride",
                HeatInput::Stroke { .. } => "stroke",
            },
            celsius(steady),
            slow / 3600.0,
            show(c.hours),
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
    let table = afsv_records::json::from_rows(&rows, &name_refs).map_err(|e| e.to_string())?;
    let conditions = json!({
        "load": c.load,
        "ambient_c": c.ambient_c,
        "charge_c": c.charge_c,
        "start_c": c.start_c,
        "hours": c.hours,
        "levelling_valve": spec.valve,
    });
    let full: Value = json!({
        "vehicle": vehicle,
        "conditions": conditions,
        "axles": axles,
        "axles_on_end_stop": skipped,
        "rows": rows,
        "ride_height_sign": "up positive (strut extended), from the static ride height at the charge temperature",

    });
    Ok((table, full, summary))
}
