//! The report of `afsv study speed-sweep` ([`crate::SpeedSweep`], D4) as text; its JSON is
//! the type's own serialisation.

/// The sweep as text: one row per speed and load, then the crossing speeds.
pub fn text(s: &crate::SpeedSweep) -> String {
    let mut out = format!(
        "HPS speed sweep (D4), class E, m_c 0.3, 100 m per run, mean ± SD over {} terrain seeds\n\n  {:<9} {:>6} {:>16} {:>16} {:>16}\n",
        s.seeds.len(),
        "load",
        "km/h",
        "a_wz (m/s²)",
        "a_z RMS (m/s²)",
        "d_s (m)"
    );
    let pm = |x: &vehicle_3d::scenarios::Spread, d: usize| format!("{:.d$} ± {:.d$}", x.mean, x.sd);
    for p in &s.points {
        out += &format!(
            "  {:<9} {:>6.1} {:>16} {:>16} {:>16}\n",
            p.load.to_string(),
            p.speed_kmh,
            pm(&p.a_wz_m_s2, 3),
            pm(&p.a_z_rms_m_s2, 3),
            pm(&p.d_s_m, 4)
        );
    }
    out += &format!(
        "\n8 h health guidance caution zone, upper bound {:.3} m/s² (ISO 2631-1 Eq B.1)\n",
        s.hgcz_upper_m_s2
    );
    for c in &s.crossings {
        let what = match (c.speed_kmh, c.above_at_lowest) {
            (Some(v), _) => format!("a_wz crosses it at {v:.1} km/h"),
            (None, true) => "a_wz is above it at every swept speed".into(),
            (None, false) => "a_wz stays below it over the sweep".into(),
        };
        out += &format!("  {:<9} {what}\n", c.load.to_string());
    }
    out
}
