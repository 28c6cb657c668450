//! The report of `afsv study hps-sensitivity` ([`crate::HpsSensitivity`], Table 6.4) as
//! text; its JSON is the type's own serialisation.

use crate::hps_sensitivity::SensitivityRow;
use crate::{HpsSensitivity, HpsVariable};

/// A measure's mean with 3 decimals, or "n/a" when it was not run.
fn cell(v: f64) -> String {
    if v.is_finite() {
        format!("{v:.3}")
    } else {
        "n/a".into()
    }
}

/// Table 6.4 as text: one block per measure, rows = changes, columns = variables.
pub fn text(s: &HpsSensitivity) -> String {
    let mut changes: Vec<f64> = s.rows.iter().map(|r| r.change).collect();
    changes.push(0.0);
    changes.sort_by(f64::total_cmp);
    changes.dedup();
    let find = |v: HpsVariable, c: f64| -> Option<&SensitivityRow> {
        s.rows.iter().find(|r| r.variable == v && r.change == c)
    };
    type Pick = fn(&crate::hps_sensitivity::HpsMeasures) -> f64;
    let blocks: [(&str, Pick); 4] = [
        ("a_wz unloaded (m/s²)", |m| m.a_wz_unloaded_m_s2.mean),
        ("a_wz loaded (m/s²)", |m| m.a_wz_loaded_m_s2.mean),
        ("SP-DRT loaded (m/s²)", |m| m.sp_drt_m_s2.mean),
        ("omega_z loaded (Hz)", |m| m.omega_z_hz),
    ];
    let mut out = format!(
        "HPS sensitivity (Table 6.4), 3-D vehicle with the front-axle HPS, mean over {} terrain seeds\n",
        s.seeds.len()
    );
    for (name, pick) in blocks {
        out += &format!(
            "\n{name}\n  {:>9} {:>9} {:>9} {:>9}\n",
            "change", "A_hc", "A_v", "A_b"
        );
        for &c in &changes {
            let col = |v| {
                if c == 0.0 {
                    cell(pick(&s.nominal))
                } else {
                    find(v, c).map_or("-".into(), |r| cell(pick(&r.measures)))
                }
            };
            out += &format!(
                "  {:>8.0}% {:>9} {:>9} {:>9}\n",
                100.0 * c,
                col(HpsVariable::PistonArea),
                col(HpsVariable::CheckValveArea),
                col(HpsVariable::BleedArea)
            );
        }
    }
    let failed: Vec<&SensitivityRow> = s.rows.iter().filter(|r| !r.failures.is_empty()).collect();
    if !failed.is_empty() {
        out += "\nfailed runs (their cells are n/a):\n";
        for r in failed {
            for f in &r.failures {
                out += &format!("  {} {:+.0}%: {f}\n", r.variable.symbol(), 100.0 * r.change);
            }
        }
    }
    out
}
