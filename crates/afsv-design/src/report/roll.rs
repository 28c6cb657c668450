//! The reports of `afsv roll` (the rigid truck of Chapter 2, crate `roll-truck`): the roll
//! measures of one run as JSON (with the ground, the truck and the detection rule) and as
//! text, the section 2.4 studies and the sensitivity of ΔT as text and JSON.

use super::table::number;
use perf_measures::roll::SustainedPeriodParams;
use roll_truck::measures::RollMeasures;
use roll_truck::sensitivity::SensitivityCell;
use roll_truck::studies::{Stat, Study, StudyResult};
use serde_json::{json, Value};
use std::path::Path;
use terrain_psd::{Band, IsoClass};

/// The ground a truck run drove on, as its report and record sidecar name it.
#[derive(Debug, Clone, Copy)]
pub enum Ground<'a> {
    /// A measured two-track road, read from this file.
    Road(&'a Path),
    /// Level ground.
    Level,
    /// Synthesised two-track rough terrain: G_d(n) = alpha_r n^-w (Eq 2.8) of the ISO 8608
    /// class, within the band, with the coherence cut-off m_c of Eq 2.10, from the seed.
    Rough {
        /// ISO 8608 class (Table 2.4).
        class: IsoClass,
        /// Waviness w of Eq 2.8.
        waviness: f64,
        /// Spatial band (cycles/m).
        band: Band,
        /// Coherence cut-off m_c (cycles/m).
        m_c: f64,
        /// Terrain seed.
        seed: u64,
    },
}

impl Ground<'_> {
    /// The ground as JSON: its kind and the file or the terrain's spectrum and seed.
    pub fn to_json(&self) -> Value {
        match *self {
            Ground::Road(file) => json!({ "kind": "measured two-track road", "file": file }),
            Ground::Level => json!({ "kind": "level ground" }),
            Ground::Rough {
                class,
                waviness,
                band,
                m_c,
                seed,
            } => json!({
                "kind": "two-track rough terrain",
                "class": class.to_string(),
                "alpha_r": class.alpha_r(),
                "waviness": waviness,
                "band_cycles_per_m": [band.n_min, band.n_max],
                "m_c_cycles_per_m": m_c,
                "seed": seed,
            }),
        }
    }
}

/// The sidecar of `afsv roll simulate`'s record: the model, the ramp steer in its
/// `direction`, the `ground`, the truck `p`, the sample rate (1 / `output_dt_s`) and the
/// rollover time (`None`: no rollover).
pub fn simulate_sidecar(
    p: &roll_truck::TruckParams,
    direction: impl std::fmt::Display,
    ground: &Ground,
    output_dt_s: f64,
    rollover_s: Option<f64>,
) -> Value {
    json!({
        "written_by": "afsv roll simulate",
        "sample_rate_hz": 1.0 / output_dt_s,
        "model": "roll-truck rigid mining truck (chapter 2)",
        "manoeuvre": format!("ramp steer ({direction})"),
        "terrain": ground.to_json(),
        "params": p,
        "rollover_s": rollover_s,
    })
}

/// A section 2.4 study as JSON: the result's own serialisation with its `findings`.
pub fn study_json(r: &StudyResult) -> Result<Value, serde_json::Error> {
    let mut v = serde_json::to_value(r)?;
    v["findings"] = serde_json::to_value(r.findings())?;
    Ok(v)
}

/// The sensitivity study as JSON: its terrain `seeds` and its `cells`.
pub fn sensitivity_json(cells: &[SensitivityCell], seeds: &[u64]) -> Value {
    json!({
        "study": "sensitivity",
        "seeds": seeds,
        "cells": cells,
    })
}

/// The roll measures of one run as JSON: the measures, the `ground`, the `truck` by name,
/// whether its bump stops are in reach, the sustained-period `rule` (`None` when it is
/// invalid) and the g the accelerations are reported in; each `null` measure explained.
pub fn measures_json(
    m: &RollMeasures,
    ground: &Ground,
    truck: &str,
    bump_stops: bool,
    rule: Option<SustainedPeriodParams>,
) -> Value {
    let mut v = serde_json::to_value(m).unwrap_or_default();
    v["terrain"] = ground.to_json();
    v["truck"] = json!(truck);
    v["bump_stops"] = json!(bump_stops);
    v["sustained_period_rule"] = json!(rule);
    v["g_for_reporting_m_s2"] = json!(roll_truck::measures::G_REPORT);
    afsv_records::json::explain_nulls(
        v,
        "not found in this run (no LTR of 1, no sustained period, or no rollover)",
    )
}

/// `v` with 3 decimals and its unit, or "n/a".
fn show(v: Option<f64>, unit: &str) -> String {
    v.map_or("n/a".into(), |x| format!("{x:.3} {unit}"))
}

/// The roll measures of one run (DRT, SP-DRT, ΔT, a_y at A4 and B', peaks, SSF), one per
/// line.
pub fn measures_text(m: &RollMeasures) -> String {
    let range = m
        .sustained_range_g
        .map_or("n/a".into(), |(a, b)| format!("{a:.3}-{b:.3} g"));
    format!(
        "DRT (first LTR = 1)      {}\nSP-DRT                   {}\nsustained period ΔT      {} ({} to {})\na_y range in ΔT          {range}\na_y at A4                {}\na_y at rollover B'       {}\npeak a_y                 {:.3} g (whole vehicle, tire forces; sprung cg {}, sprung-fixed sensor {})\npeak a_y before stops    {:.3} g (first stop contact {})\nall wheels off ground    {}\nabsolute rollover        {}\nSSF                      {:.3}\n",
        show(m.drt_g, "g"),
        show(m.sp_drt_g, "g"),
        show(m.sustained_period_s, "s"),
        show(m.sustained_start_s, "s"),
        show(m.sustained_end_s, "s"),
        show(m.ay_at_a4_g, "g"),
        show(m.ay_at_rollover_g, "g"),
        m.peak_ay_g,
        show(m.peak_sprung_ay_g, "g"),
        show(m.peak_sensor_ay_g, "g"),
        m.peak_ay_before_stop_g,
        show(m.first_bump_stop_s, "s"),
        airborne_text(m),
        show(m.rollover_s, "s"),
        m.ssf,
    )
}

/// When the truck jumped: the LTR (Eq 2.11) reads 0 on those samples.
fn airborne_text(m: &RollMeasures) -> String {
    match m.first_airborne_s {
        None => "never".into(),
        Some(t) => format!(
            "{:.3} s in all, first at {t:.3} s (LTR reads 0 there: no load to transfer)",
            m.airborne_time_s
        ),
    }
}

/// `mean ± sd` with `digits` decimals, or "n/a" without samples.
fn pm(s: &Stat, digits: usize) -> String {
    if s.n == 0 {
        return "n/a".into();
    }
    format!("{:.d$} ± {:.d$}", s.mean, s.sd, d = digits)
}

/// A section 2.4 study (or `trucks`): one row per point, the peaks of the truck comparison,
/// then the findings.
pub fn study_text(r: &StudyResult) -> String {
    let mut s = format!(
        "{:<22} {:>10} {:>10} {:>16} {:>14} {:>16} {:>7}\n",
        "group", "x", "smooth g", "SP-DRT g", "ΔT s", "peak a_y g", "SSF"
    );
    for p in &r.points {
        s += &format!(
            "{:<22} {:>10} {:>10} {:>16} {:>14} {:>16} {:>7.3}\n",
            p.group,
            number(p.x),
            p.smooth_drt_g.map_or("n/a".into(), |v| format!("{v:.3}")),
            pm(&p.sp_drt_g, 3),
            pm(&p.sustained_period_s, 2),
            pm(&p.peak_ay_g, 3),
            p.ssf,
        );
    }
    if r.study == Study::Trucks {
        s += &format!(
            "\n{:<22} {:>16} {:>16} {:>16} {:>16}\n",
            "peak a_y (class E)",
            "whole vehicle g",
            "sprung cg g",
            "sprung sensor g",
            "before stops g"
        );
        for p in &r.points {
            s += &format!(
                "{:<22} {:>16} {:>16} {:>16} {:>16}\n",
                p.group,
                pm(&p.peak_ay_g, 3),
                pm(&p.peak_sprung_ay_g, 3),
                pm(&p.peak_sensor_ay_g, 3),
                pm(&p.peak_ay_before_stop_g, 3),
            );
        }
        s += "\n";
    }
    for f in r.findings() {
        s += &format!("{:<44} {:>9.4}  {}\n", f.name, f.value, f.meaning);
    }
    s
}

/// The sensitivity of ΔT to the ramp rate and the detection rule: one row per cell.
pub fn sensitivity_text(cells: &[SensitivityCell], seeds: usize) -> String {
    let mut s = format!(
        "ΔT over {seeds} seeds (class A and E, w = 2, 0.02-5 cycles/m, m_c = 0.3)\n{:<12} {:>9} {:<8} {:>7} {:>7} {:>15} {:>15} {:>9} {:>15}\n",
        "truck", "ramp °/s", "rule", "LTR ≥", "dip s", "ΔT class A s", "ΔT class E s", "E / A", "SP-DRT E g"
    );
    for c in cells {
        s += &format!(
            "{:<12} {:>9.1} {:<8} {:>7.2} {:>7.2} {:>15} {:>15} {:>9.2} {:>15}\n",
            c.truck,
            c.ramp_rate_deg_s,
            c.rule.name(),
            c.threshold,
            c.max_dip_s,
            pm(&c.class_a_s, 2),
            pm(&c.class_e_s, 2),
            c.ratio_e_over_a,
            pm(&c.sp_drt_e_g, 3),
        );
    }
    s
}
