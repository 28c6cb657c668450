//! The `--plot` figure of `afsv hps harmonic`: the strut's loops over the last period of
//! a harmonic test, drawn as in Figs 5.7, 5.9 and 5.10.

use afsv_plot::{Axis, Chart, ChartPanel, Curve};
use hps_emulsion::{HarmonicTest, HysteresisLoop, StrutRecord};

/// The four loops of the last period of `rec` under `test`: pressure-deflection (MPa,
/// mm), force-deflection (kN, mm), force-velocity and damping force-velocity (kN, m/s);
/// `conditions` is the figure's second title line. An error if the record holds no whole
/// last period.
pub fn loops(rec: &StrutRecord, test: &HarmonicTest, conditions: &str) -> Result<Chart, String> {
    let lp = HysteresisLoop::last_period(rec, test.frequency_hz).map_err(|e| e.to_string())?;
    let scaled = |v: &[f64], s: f64| v.iter().map(|x| x * s).collect::<Vec<f64>>();
    let z = scaled(&lp.displacement, 1e3);
    let f = scaled(&lp.force, 1e-3);
    let v = &lp.velocity;
    let deflection = Axis::new("deflection", "mm");
    let velocity = Axis::new("velocity", "m/s");
    let force = Axis::new("force", "kN");
    let panel = |caption: &str, x, y, curves| ChartPanel {
        caption: caption.into(),
        x,
        y,
        curves,
    };
    Ok(Chart::Panels {
        title: "strut loops, last period".into(),
        conditions: conditions.into(),
        columns: 2,
        panels: vec![
            panel(
                "pressure-deflection",
                deflection,
                Axis::new("pressure", "MPa"),
                vec![
                    Curve::new("P_hc piston side", z.clone(), scaled(&lp.p_piston, 1e-6)),
                    Curve::new("P_hr rod side", z.clone(), scaled(&lp.p_rod, 1e-6)),
                ],
            ),
            panel(
                "force-deflection",
                deflection,
                force,
                vec![Curve::new("F_h", z, f.clone())],
            ),
            panel(
                "force-velocity",
                velocity,
                force,
                vec![Curve::new("F_h", v.clone(), f)],
            ),
            panel(
                "damping force-velocity",
                velocity,
                Axis::new("damping force", "kN"),
                vec![Curve::new(
                    "F_h - spring",
                    v.clone(),
                    scaled(&lp.damping_force, 1e-3),
                )],
            ),
        ],
    })
}
