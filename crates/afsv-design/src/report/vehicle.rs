//! The reports of `afsv vehicle` (the 3-D vehicle of Chapter 6, crate `vehicle-3d`): the
//! D1 ride, D2 roll and D3 yaw runs over terrain seeds (or one measured road) summarised
//! as mean ± SD with their verdicts, as JSON and as text (docs/vehicle-3d.md). The runs are
//! the library's (`vehicle_3d::scenarios`); the CLI runs them, adds its plot and the
//! vehicle's interconnection, and prints.

use super::design_3d::yaw_fit_caveat;
use crate::design_3d::{hgcz_8h_band, ConfigMeasures};
use perf_measures::iso2631::{health_guidance_zone, HgczRelation, HgczZone};
use serde_json::{json, Value};
use terrain_psd::{welch_psd, WelchConfig};
use vehicle_3d::cab_ride::SeatRideMeasures;
use vehicle_3d::interconnect::Link;
use vehicle_3d::scenarios::{PathChangeMeasures, PathChangeSpec};
use vehicle_3d::scenarios::{
    RideMeasures, RideSpec, RollMeasures, RollSpec, Spread, TerrainSpec, YawMeasures, YawSpec,
    RUN_IN_M,
};
use vehicle_3d::{FrontAxle, Load, RunRecord, VehicleParams, YawInertiaForm};

/// Why a rigid front axle has no strut travel.
pub const NO_STRUT: &str = "rigid front axle (--hps off): no strut";

/// Exposure duration of the ISO 2631-1 health guidance caution zone verdict (h).
pub const HGCZ_HOURS: f64 = 8.0;

/// Why a ride has no seat measures.
pub const NO_SEAT: &str =
    "no cab and seat: give --seat generic, or [cab.body] and [seat] in the vehicle description";

/// The yaw-inertia form of `--paper-form`.
pub fn yaw_inertia_form(paper_form: bool) -> YawInertiaForm {
    if paper_form {
        YawInertiaForm::PaperEq313
    } else {
        YawInertiaForm::EnergyConsistent
    }
}

/// What the ride ran on, for its report.
pub struct Ground {
    /// The ground as JSON (`"terrain"` of the report).
    pub json: Value,
    /// The ground in words (one line of the text report).
    pub text: String,
    /// The measures of each run with what tells the runs apart (`"per_seed"`).
    pub per_run: Value,
}

impl Ground {
    /// The two-track terrain `t` run on `seeds`, with each seed's ride `measures`.
    pub fn terrain(t: TerrainSpec, seeds: &[u64], measures: &[RideMeasures]) -> Self {
        Ground {
            json: terrain_json(&Some(t), seeds),
            text: format!("terrain class {}, m_c {} cycles/m", t.class, t.m_c),
            per_run: per_seed(&Some(t), seeds, measures, NO_STRUT),
        }
    }
}

/// The ground of a run as JSON: smooth, or the two-track terrain with its seeds.
pub fn terrain_json(spec: &Option<TerrainSpec>, seeds: &[u64]) -> Value {
    match spec {
        None => json!({ "kind": "smooth ground" }),
        Some(t) => json!({
            "kind": "two-track terrain (Eqs 6.4-6.5)",
            "class": t.class.to_string(),
            "m_c_cycles_per_m": t.m_c,
            "band_cycles_per_m": [t.band.0, t.band.1],
            "seeds": seeds,
        }),
    }
}

/// The per-seed measures; on smooth ground the seed is null with its reason; a null measure
/// gets `null_reason`.
pub fn per_seed<T: serde::Serialize>(
    terrain: &Option<TerrainSpec>,
    seeds: &[u64],
    measures: &[T],
    null_reason: &str,
) -> Value {
    let rows: Vec<Value> = seeds
        .iter()
        .zip(measures)
        .map(|(s, m)| {
            let m = afsv_records::json::explain_nulls(json!(m), null_reason);
            match terrain {
                Some(_) => json!({ "seed": s, "measures": m }),
                None => json!({ "seed": null, "seed_reason": "smooth ground", "measures": m }),
            }
        })
        .collect();
    Value::Array(rows)
}

/// The suspended axles of the vehicle `p` run with the front axle `front`, for headers and
/// plot titles.
pub fn axle_name(front: FrontAxle, p: &VehicleParams) -> &'static str {
    match (front, p.rear_hps.is_some()) {
        (FrontAxle::Rigid, false) => "rigid (no HPS)",
        (FrontAxle::Suspended, false) => "front-axle HPS",
        (FrontAxle::Rigid, true) => "rear-axle HPS, rigid front axle",
        (FrontAxle::Suspended, true) => "HPS on both axles",
    }
}

/// The rear axle of `p` in JSON: `rigid` or `suspended` (as `front_axle`); a rear
/// walking-beam tandem is `rigid tandem` or `suspended tandem` (one strut per side).
pub fn rear_axle(p: &VehicleParams) -> Value {
    json!(match (p.rear_hps.is_some(), p.bogie.is_some()) {
        (true, false) => "suspended",
        (false, false) => "rigid",
        (true, true) => "suspended tandem",
        (false, true) => "rigid tandem",
    })
}

/// Mean ± SD of `f` over `values`.
pub fn spread<T>(values: &[T], f: impl Fn(&T) -> f64) -> Result<Spread, String> {
    let v: Vec<f64> = values.iter().map(f).collect();
    Spread::of(&v).map_err(|e| e.to_string())
}

/// One text row: `label`, mean ± SD over several runs (the mean alone over one), unit.
pub fn spread_text(label: &str, s: &Spread, unit: &str) -> String {
    if s.n > 1 {
        format!("{label:<32} {:>9.3} ± {:<7.3} {unit}\n", s.mean, s.sd)
    } else {
        format!("{label:<32} {:>9.3}           {unit}\n", s.mean)
    }
}

/// The first line of a scenario report: the scenario, load, axles, speed, seed count and
/// the yaw-inertia form.
pub fn header_text(
    title: &str,
    (load, paper_form): (Load, bool),
    (axle, p): (FrontAxle, &VehicleParams),
    speed: f64,
    seeds: usize,
) -> String {
    let runs = if seeds > 1 {
        format!(", mean ± SD over {seeds} seeds")
    } else {
        String::new()
    };
    let form = if paper_form {
        "; yaw inertias of the printed Eq 3.13 (--paper-form: m L² counted twice, not for design)"
    } else {
        ""
    };
    format!(
        "{title}: {}, {}, {speed} km/h{runs}{form}\n",
        load,
        axle_name(axle, p)
    )
}

/// What the report says of `link`: a JSON value and a text line.
pub fn link_note(link: &Link) -> (Value, String) {
    let text = match link {
        Link::Roll(_) => "front struts interconnected left-right (roll link, [link])",
        Link::Pitch(_) => "front and rear struts interconnected on each side (pitch link, [link])",
    };
    (json!(link), format!("{text}\n"))
}

/// The D1 ride report of `p` run as `spec` (`paper_form`: the printed Eq 3.13 yaw inertias)
/// over its runs' `measures` on `ground`, with the seat measures of the runs that have a
/// seat: mean ± SD, the ISO 2631-1 8 h caution-zone verdict of the mean a_wz, strut
/// travels, dominant frequencies. Returns the JSON and the text.
pub fn ride_report(
    p: &VehicleParams,
    spec: &RideSpec,
    paper_form: bool,
    measures: &[RideMeasures],
    seats: &[SeatRideMeasures],
    ground: Ground,
) -> Result<(Value, String), String> {
    let (axle, speed, length_m) = (spec.front_axle, spec.speed_kmh, spec.length_m);
    let a_wz = spread(measures, |m| m.a_wz_m_s2)?;
    let a_z = spread(measures, |m| m.a_z_rms_m_s2)?;
    let vertical = spread(measures, |m| m.vertical_peak_hz)?;
    let pitch = spread(measures, |m| m.pitch_peak_hz)?;
    let travel = match axle {
        FrontAxle::Rigid => None,
        FrontAxle::Suspended => Some(spread(measures, |m| {
            m.strut_travel_p2p_m.unwrap_or(f64::NAN)
        })?),
    };
    let rear_travel = if measures.iter().all(|m| m.rear_strut_travel_p2p_m.is_some()) {
        Some(spread(measures, |m| {
            m.rear_strut_travel_p2p_m.unwrap_or(f64::NAN)
        })?)
    } else {
        None
    };
    let zone =
        health_guidance_zone(HGCZ_HOURS, HgczRelation::SqrtTime).map_err(|e| e.to_string())?;
    let verdict = zone.classify(a_wz.mean);
    let mut v = json!({
        "scenario": "ride (D1, section 6.4)",
        "load": spec.load,
        "front_axle": axle,
        "rear_axle": rear_axle(p),
        "yaw_inertia_form": yaw_inertia_form(paper_form),
        "speed_kmh": speed,
        "run_in_m": RUN_IN_M,
        "length_m": length_m,
        "terrain": ground.json,
        "a_wz_m_s2": a_wz,
        "a_z_rms_m_s2": a_z,
        "strut_travel_p2p_m": travel,
        "vertical_peak_hz": vertical,
        "pitch_peak_hz": pitch,
        "hgcz": {
            "duration_h": HGCZ_HOURS,
            "relation": zone.relation,
            "lower_m_s2": zone.lower_m_s2,
            "upper_m_s2": zone.upper_m_s2,
            "a_wz_mean_zone": verdict,
        },
        "per_seed": ground.per_run,
    });
    if travel.is_none() {
        v["strut_travel_p2p_m_reason"] = json!(NO_STRUT);
    }
    if let Some(t) = &rear_travel {
        v["rear_strut_travel_p2p_m"] = json!(t);
    }
    let verdict_text = match verdict {
        perf_measures::iso2631::HgczZone::Below => "below the zone",
        perf_measures::iso2631::HgczZone::Within => "within the zone (caution)",
        perf_measures::iso2631::HgczZone::Above => "above the zone (health risk likely)",
    };
    let mut text = header_text(
        "ride D1",
        (spec.load, paper_form),
        (axle, p),
        speed,
        measures.len(),
    );
    text += &format!(
        "{}, {length_m} m after a {RUN_IN_M} m run-in\n",
        ground.text
    );
    text += &spread_text("a_wz (W_k weighted RMS)", &a_wz, "m/s²");
    text += &format!(
        "{:<32} {verdict_text} ({:.2}-{:.2} m/s² at {HGCZ_HOURS} h)\n",
        "ISO 2631-1 HGCZ verdict", zone.lower_m_s2, zone.upper_m_s2
    );
    text += &spread_text("vertical acceleration RMS", &a_z, "m/s²");
    match &travel {
        Some(t) => text += &spread_text("HPS travel peak-to-peak d_s", t, "m"),
        None => {
            text += &format!(
                "{:<32} n/a (rigid front axle)\n",
                "HPS travel peak-to-peak d_s"
            )
        }
    }
    if let Some(t) = &rear_travel {
        text += &spread_text("rear HPS travel peak-to-peak", t, "m");
    }
    text += &spread_text("dominant vertical frequency", &vertical, "Hz");
    text += &spread_text("dominant pitch frequency", &pitch, "Hz");
    seat_report(seats, &mut v, &mut text)?;
    Ok((v, text))
}

/// Add the seat measures over the runs to the ride report: `"seat"` in `v` (null with a
/// reason when the ride has none) and their lines in `text`.
fn seat_report(seats: &[SeatRideMeasures], v: &mut Value, text: &mut String) -> Result<(), String> {
    if seats.is_empty() {
        v["seat"] = Value::Null;
        v["seat_reason"] = json!(NO_SEAT);
        return Ok(());
    }
    let floor = spread(seats, |s| s.a_wz_floor_m_s2)?;
    let seat = spread(seats, |s| s.a_wz_seat_m_s2)?;
    let ratio = spread(seats, |s| s.seat.seat)?;
    let travel = spread(seats, |s| s.seat_travel_p2p_m)?;
    let stops = spread(seats, |s| s.stop_fraction)?;
    let zone =
        health_guidance_zone(HGCZ_HOURS, HgczRelation::SqrtTime).map_err(|e| e.to_string())?;
    let verdict = zone.classify(seat.mean);
    v["seat"] = json!({
        "a_wz_floor_m_s2": floor,
        "a_wz_seat_m_s2": seat,
        "a_wz_seat_mean_zone": verdict,
        "seat_ratio": ratio,
        "seat_travel_p2p_m": travel,
        "stop_fraction": stops,
        "per_run": seats,
    });
    let verdict = match verdict {
        HgczZone::Below => "below the zone",
        HgczZone::Within => "within the zone (caution)",
        HgczZone::Above => "above the zone (health risk likely)",
    };
    *text += &spread_text("a_wz on the cab floor", &floor, "m/s²");
    *text += &spread_text("a_wz at the seat", &seat, "m/s²");
    *text += &format!("{:<32} {verdict}\n", "HGCZ verdict at the seat");
    *text += &spread_text("SEAT (seat / floor, ISO 10326-1)", &ratio, "");
    *text += &spread_text("seat travel peak-to-peak", &travel, "m");
    *text += &spread_text("share of time on seat stops", &stops, "");
    Ok(())
}

/// The D2 roll report of `p` run as `spec` over `seeds` with `measures` (one per seed):
/// SP-DRT, the sustained period, peak a_y and the rollover time as mean ± SD. Returns the
/// JSON and the text.
pub fn roll_report(
    p: &VehicleParams,
    spec: &RollSpec,
    paper_form: bool,
    seeds: &[u64],
    measures: &[RollMeasures],
) -> Result<(Value, String), String> {
    let sp_drt = spread(measures, |m| m.sp_drt_m_s2)?;
    let period = spread(measures, |m| m.sustained_s.1 - m.sustained_s.0)?;
    let peak = spread(measures, |m| m.peak_ay_m_s2)?;
    let rolled: Vec<f64> = measures.iter().filter_map(|m| m.rollover_s).collect();
    let rollover = if rolled.is_empty() {
        None
    } else {
        Some(Spread::of(&rolled).map_err(|e| e.to_string())?)
    };
    let mut v = json!({
        "scenario": "roll (D2, section 6.4)",
        "load": spec.load,
        "front_axle": spec.front_axle,
        "rear_axle": rear_axle(p),
        "yaw_inertia_form": yaw_inertia_form(paper_form),
        "speed_kmh": spec.speed_kmh,
        "ramp_deg_s": spec.ramp_deg_s,
        "ramp_start_s": spec.ramp_start_s,
        "terrain": terrain_json(&spec.terrain, seeds),
        "sp_drt_m_s2": sp_drt,
        "sustained_period_s": period,
        "peak_ay_m_s2": peak,
        "rollover_s": rollover,
        "rolled_over": rolled.len(),
        "per_seed": per_seed(&spec.terrain, seeds, measures, "no absolute rollover of the rear unit in this run"),
    });
    if rollover.is_none() {
        v["rollover_s_reason"] = json!("no run reached the rear unit's absolute rollover");
    }
    let mut text = header_text(
        "roll D2",
        (spec.load, paper_form),
        (spec.front_axle, p),
        spec.speed_kmh,
        seeds.len(),
    );
    text += &format!(
        "ramp steer {} deg/s from t = {} s\n",
        spec.ramp_deg_s, spec.ramp_start_s
    );
    text += &spread_text("SP-DRT of the rear unit", &sp_drt, "m/s²");
    text += &spread_text("sustained period ΔT", &period, "s");
    text += &spread_text("peak |a_y| of the rear unit", &peak, "m/s²");
    match &rollover {
        Some(r) => {
            text += &spread_text("absolute rollover at", r, "s");
            text += &format!(
                "{:<32} {:>9}\n",
                "runs that rolled over",
                format!("{}/{}", rolled.len(), seeds.len())
            );
        }
        None => {
            text += &format!(
                "{:<32} n/a (no rollover within {} s)\n",
                "absolute rollover at", spec.t_end_s
            )
        }
    }
    Ok((v, text))
}

/// The D3 yaw report of `p` run as `spec` over `seeds` with `measures` (one per seed):
/// omega_z, the damped frequency, zeta and the peak articulation as mean ± SD, with the
/// caveat of the single-mode fit. Returns the JSON and the text.
pub fn yaw_report(
    p: &VehicleParams,
    spec: &YawSpec,
    paper_form: bool,
    seeds: &[u64],
    measures: &[YawMeasures],
) -> Result<(Value, String), String> {
    let omega = spread(measures, |m| m.omega_z_hz)?;
    let damped = spread(measures, |m| m.damped_frequency_hz)?;
    let zeta = spread(measures, |m| m.damping_ratio)?;
    let peak = spread(measures, |m| m.peak_articulation_deg)?;
    let mut v = json!({
        "scenario": "yaw (D3, section 6.4)",
        "load": spec.load,
        "front_axle": spec.front_axle,
        "rear_axle": rear_axle(p),
        "yaw_inertia_form": yaw_inertia_form(paper_form),
        "speed_kmh": spec.speed_kmh,
        "pulse_deg": spec.pulse_deg,
        "pulse_s": spec.pulse_s,
        "pulse_start_s": spec.pulse_start_s,
        "fit_window_s": spec.fit_window_s,
        "terrain": terrain_json(&spec.terrain, seeds),
        "omega_z_hz": omega,
        "damped_frequency_hz": damped,
        "damping_ratio": zeta,
        "peak_articulation_deg": peak,
        "per_seed": per_seed(&spec.terrain, seeds, measures, "not computed"),
    });
    let mut text = header_text(
        "yaw D3",
        (spec.load, paper_form),
        (spec.front_axle, p),
        spec.speed_kmh,
        seeds.len(),
    );
    text += &format!(
        "steering-wheel pulse {} deg, {} s, at t = {} s\n",
        spec.pulse_deg, spec.pulse_s, spec.pulse_start_s
    );
    text += &spread_text("omega_z (natural frequency)", &omega, "Hz");
    text += &spread_text("damped frequency", &damped, "Hz");
    text += &spread_text("damping ratio zeta", &zeta, "-");
    text += &spread_text("peak articulation", &peak, "deg");
    if let Some(caveat) = yaw_fit_caveat(measures) {
        text += &format!("note: {caveat}\n");
        v["fit_caveat"] = json!(caveat);
    }
    Ok((v, text))
}

/// The report of `afsv vehicle measures`: D1-D3 of one configuration (`p` with the front
/// axle `axle`, the D1 ride at `load`) over `seeds` from [`crate::design_3d::measure`], with
/// the 8 h caution-zone verdict of the ride (`paper_form`: the printed Eq 3.13 yaw
/// inertias). Returns the JSON and the text.
pub fn measures_report(
    p: &VehicleParams,
    axle: FrontAxle,
    load: Load,
    paper_form: bool,
    seeds: &[u64],
    c: &ConfigMeasures,
) -> Result<(Value, String), String> {
    let ride = c
        .ride_of(load)
        .ok_or_else(|| format!("the {load} ride is missing"))?;
    let band = hgcz_8h_band()?;
    let no_strut = "rigid front axle (--hps off): no strut";
    let mut v = json!({
        "measures": "design measures D1-D3 (section 6.4)",
        "front_axle": axle,
        "rear_axle": rear_axle(p),
        "yaw_inertia_form": p.yaw_inertia_form,
        "ride_load": load,
        "seeds": seeds,
        "terrain": "class E, m_c 0.3 (D1, D2); smooth ground (D3)",
        "d1_ride": {
            "load": load,
            "speed_kmh": 20.0,
            "a_wz_m_s2": ride.a_wz_m_s2,
            "strut_travel_p2p_m": ride.strut_travel_m,
            "hgcz_8h": ride.hgcz_8h,
            "hgcz_8h_m_s2": band,
        },
        "d2_roll": { "load": Load::Loaded, "speed_kmh": 50.0, "sp_drt_m_s2": c.sp_drt_m_s2 },
        "d3_yaw": {
            "load": Load::Loaded,
            "speed_kmh": 50.0,
            "omega_z_hz": c.yaw.omega_z_hz,
            "damping_ratio": c.yaw.damping_ratio,
            "damped_frequency_hz": c.yaw.damped_frequency_hz,
            "peak_articulation_deg": c.yaw.peak_articulation_deg,
            "damping_ratio_std": c.yaw.damping_ratio_std,
            "fit_residual_to_noise": c.yaw.fit_residual_to_noise,
        },
    });
    if let Some(caveat) = c.yaw.fit_caveat() {
        v["d3_yaw"]["fit_caveat"] = json!(caveat);
    }
    if ride.strut_travel_m.is_none() {
        v["d1_ride"]["strut_travel_p2p_m_reason"] = json!(no_strut);
    }
    let pm = |s: &vehicle_3d::scenarios::Spread, d: usize| {
        if s.n > 1 {
            format!("{:.d$} ± {:.d$}", s.mean, s.sd)
        } else {
            format!("{:.d$}", s.mean)
        }
    };
    let row = |label: &str, value: String, unit: &str| format!("{label:<36} {value:>16} {unit}\n");
    let mut text = format!(
        "design measures: {}, ride {}, {} terrain seed(s){}\n",
        axle_name(axle, p),
        load,
        seeds.len(),
        if seeds.len() > 1 { ", mean ± SD" } else { "" }
    );
    text += &row(
        "a_wz (D1, 20 km/h, class E)",
        pm(&ride.a_wz_m_s2, 3),
        "m/s²",
    );
    text += &row(
        "  8 h HGCZ verdict",
        measures_zone_text(ride.hgcz_8h).into(),
        &format!("({:.2}-{:.2} m/s²)", band.0, band.1),
    );
    text += &row(
        "strut travel d_s (Eq 6.19)",
        ride.strut_travel_m
            .as_ref()
            .map_or("n/a".into(), |t| pm(t, 3)),
        "m",
    );
    text += &row(
        "SP-DRT (D2, 50 km/h, loaded)",
        pm(&c.sp_drt_m_s2, 2),
        "m/s²",
    );
    text += &row(
        "omega_z (D3, 50 km/h, loaded)",
        format!("{:.2}", c.yaw.omega_z_hz),
        "Hz",
    );
    text += &row(
        "yaw damping ratio zeta",
        format!("{:.3}", c.yaw.damping_ratio),
        "-",
    );
    if paper_form {
        text += "(--paper-form: yaw inertias of the printed Eq 3.13, m L² counted twice; not for design)\n";
    }
    if let Some(caveat) = c.yaw.fit_caveat() {
        text += &format!("note on omega_z and zeta: {caveat}\n");
    }
    Ok((v, text))
}

/// The zone of the 8 h caution zone in words (`afsv vehicle measures`).
fn measures_zone_text(z: HgczZone) -> &'static str {
    match z {
        HgczZone::Below => "below the zone",
        HgczZone::Within => "within the zone (caution)",
        HgczZone::Above => "above the zone (health risk likely)",
    }
}

/// The report of `afsv vehicle path-change` (V3, section 6.3): the run of `p` as `spec` on
/// the terrain seed `seed` with its measures `m`, afsv-v1 signs. Returns the JSON and the
/// text.
pub fn path_change_report(
    p: &VehicleParams,
    spec: &PathChangeSpec,
    seed: u64,
    m: &PathChangeMeasures,
) -> (Value, String) {
    let v = json!({
        "scenario": "path change (V3, section 6.3, Fig 3.6(b))",
        "load": spec.load,
        "front_axle": spec.front_axle,
        "rear_axle": rear_axle(p),
        "speed_kmh": spec.speed_kmh,
        "course": {
            "offset_m": spec.offset_m,
            "gate_m": spec.gate_m,
            "approach_m": spec.approach_m,
        },
        "duration_s": spec.t_end_s,
        "terrain": terrain_json(&spec.terrain, &[seed]),
        "sign_convention": "afsv-v1: positive in a right-hand turn; offset positive to the right",
        "measures": m,
    });
    let ground = match &spec.terrain {
        None => "smooth ground".to_string(),
        Some(t) => format!("class {}, m_c {}, seed {}", t.class, t.m_c, seed),
    };
    let mut text = format!(
        "path change V3: {}, {}, {} km/h, {} m offset over an {} m gate, {ground}\n",
        spec.load,
        axle_name(spec.front_axle, p),
        spec.speed_kmh,
        spec.offset_m,
        spec.gate_m
    );
    let row = |label: &str, value: String, unit: &str| format!("{label:<36} {value:>16} {unit}\n");
    text += &row(
        "peak articulation",
        format!("{:.2}", m.peak_articulation_deg),
        "deg",
    );
    text += &row(
        "left-strut displacement min / max",
        format!(
            "{:.3} / {:.3}",
            m.strut_left_range_m.0, m.strut_left_range_m.1
        ),
        "m",
    );
    text += &row(
        "peak front-unit yaw rate",
        format!("{:.2}", m.peak_yaw_rate_deg_s),
        "deg/s",
    );
    text += &row(
        "peak front-unit lateral acceleration",
        format!("{:.3}", m.peak_lateral_accel_m_s2),
        "m/s²",
    );
    text += &row(
        "largest deviation from the course",
        format!("{:.3}", m.max_deviation_m),
        "m",
    );
    text += &row(
        "final lateral position",
        format!("{:.3}", m.final_offset_m),
        "m",
    );
    text += "signs: positive in a right-hand turn (afsv-v1)\n";
    (v, text)
}

/// The seed-mean Welch PSDs of the cab's vertical acceleration and the front unit's pitch
/// acceleration over the ride window: frequencies and the two densities.
pub type RidePsd = (Vec<f64>, Vec<f64>, Vec<f64>);

/// The PSDs of one ride record from `t_start_s` on, with the Welch settings of
/// `vehicle_3d::scenarios::psd_peak` (segments of up to 8 s, at least two, Hann, 50 %).
pub fn ride_psd(rec: &RunRecord, t_start_s: f64) -> Result<RidePsd, String> {
    let i0 = rec.t_s.partition_point(|&t| t < t_start_s);
    let dt = rec.t_s[1] - rec.t_s[0];
    let az = &rec.cab_accel_m_s2[2][i0..];
    let pitch = &rec.front_angular_accel_rad_s2[1][i0..];
    let seg = ((8.0 / dt) as usize).min(az.len() / 2).max(32);
    let cfg = WelchConfig::new(seg);
    let v = welch_psd(az, dt, &cfg).map_err(|e| format!("vertical PSD: {e}"))?;
    let p = welch_psd(pitch, dt, &cfg).map_err(|e| format!("pitch PSD: {e}"))?;
    Ok((v.freq, v.psd, p.psd))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_rows_show_the_spread_only_over_several_seeds() {
        let two = Spread::of(&[1.0, 3.0]).unwrap();
        let row = spread_text("a_wz", &two, "m/s²");
        assert!(
            row.contains("2.000 ± 1.414") && row.ends_with("m/s²\n"),
            "{row}"
        );
        let one = Spread::of(&[1.25]).unwrap();
        let row = spread_text("a_wz", &one, "m/s²");
        assert!(row.contains("1.250") && !row.contains('±'), "{row}");
    }
}
