//! The figure of `afsv study layouts --plot`: the operator's a_wz of every layout against
//! the D4 speeds, with the 8 h caution zone's upper bound.

use crate::layouts::LayoutStudy;
use afsv_plot::{Chart, Curve};

/// One curve per row of `s` (its layout, on the frame or at the seat) of a_wz against the
/// D4 speeds, and the zone's upper bound.
pub fn layouts(s: &LayoutStudy) -> Chart {
    let speeds = &s.sweep_speeds_kmh;
    let mut curves: Vec<Curve> = s
        .rows
        .iter()
        .map(|r| {
            let at = if r.at_seat { "seat" } else { "frame" };
            let label = format!("{} ({at})", r.layout);
            Curve::new(label, speeds.clone(), r.d4_a_wz_m_s2.clone())
        })
        .collect();
    let bound = vec![s.hgcz_8h_m_s2.1; speeds.len()];
    curves.push(Curve::new("8 h HGCZ upper bound", speeds.clone(), bound));
    Chart::Lines {
        title: format!(
            "Layouts: operator a_wz against speed ({}, class E), {} seeds",
            s.load,
            s.seeds.len()
        ),
        x_label: "forward speed (km/h)".into(),
        y_label: "a_wz (m/s²)".into(),
        log_x: false,
        curves,
    }
}
