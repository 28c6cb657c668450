//! The report of `afsv study layouts` ([`crate::layouts::LayoutStudy`]) as a table: one row
//! per layout and reading point; its JSON is the type's own serialisation.

use crate::layouts::{LayoutRow, LayoutStudy};

/// `mean ± sd` with `d` decimals, `~` after it when the difference from the baseline lies
/// inside the seed spread, `-` when the row has no such measure.
fn cell(r: &LayoutRow, key: &str, v: Option<&vehicle_3d::scenarios::Spread>, d: usize) -> String {
    match v {
        None => "-".into(),
        Some(s) => {
            let mark = if r.inside_seed_spread.contains(&key) {
                "~"
            } else {
                ""
            };
            format!("{:.d$}±{:.d$}{mark}", s.mean, s.sd)
        }
    }
}

/// The study as a table: one row per layout and reading point.
pub fn text(s: &LayoutStudy) -> String {
    let mut out = format!(
        "Suspension layouts, {} ride at {} km/h on class E (m_c 0.3, 100 m), D2/D3 loaded; mean ± SD over {} terrain seeds\n\n",
        s.load, s.ride_speed_kmh, s.seeds.len()
    );
    out += &format!(
        "  {:<16} {:<5} {:>13} {:>13} {:>12} {:>15} {:>13} {:>7} {:>7} {:<10} {:>9}\n",
        "layout",
        "at",
        "a_wz frame",
        "a_wz seat",
        "SEAT",
        "d_s (m)",
        "SP-DRT",
        "change",
        "ω_z Hz",
        "8 h HGCZ",
        "D4 km/h"
    );
    for r in &s.rows {
        let zone = match r.hgcz_8h {
            perf_measures::iso2631::HgczZone::Below => "below",
            perf_measures::iso2631::HgczZone::Within => "within",
            perf_measures::iso2631::HgczZone::Above => "above",
        };
        let crossing = match (r.d4_crossing.speed_kmh, r.d4_crossing.above_at_lowest) {
            (Some(v), _) => format!("{v:.1}"),
            (None, true) => "below lowest".into(),
            (None, false) => "none".into(),
        };
        out += &format!(
            "  {:<16} {:<5} {:>13} {:>13} {:>12} {:>15} {:>13} {:>6.1}% {:>7.3} {:<10} {:>9}\n",
            r.layout,
            if r.at_seat { "seat" } else { "frame" },
            cell(r, "a_wz_frame", Some(&r.a_wz_frame_m_s2), 3),
            cell(r, "a_wz_seat", r.a_wz_seat_m_s2.as_ref(), 3),
            cell(r, "seat_ratio", r.seat_ratio.as_ref(), 2),
            cell(r, "strut_travel", r.strut_travel_m.as_ref(), 4),
            cell(r, "sp_drt", Some(&r.sp_drt_m_s2), 2),
            r.sp_drt_change_percent,
            r.omega_z_hz,
            zone,
            crossing
        );
    }
    out += &format!(
        "\na_wz in m/s², SP-DRT in m/s²; the HGCZ verdict and the D4 crossing read a_wz where the operator sits (the seat on a seat row, the frame otherwise).\n8 h caution zone {:.2}-{:.2} m/s² (ISO 2631-1 Eq B.1). `~`: the difference from the baseline (the first layout, read at the same point) lies inside the seed spread (less than twice its standard error). change: SP-DRT against the baseline.\n",
        s.hgcz_8h_m_s2.0, s.hgcz_8h_m_s2.1
    );
    out
}
