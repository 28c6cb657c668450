//! The `--plot` figure of `afsv tire sweep`: one Fiala force curve per normal load and
//! other slip, F_y against the slip angle when it is swept, else F_x against the slip
//! ratio.

use crate::report::tire::SweepRow;
use afsv_plot::{Axis, Chart, Curve};

/// The most curves a sweep figure draws (more cannot be told apart).
pub const MAX_CURVES: usize = 50;

/// The figure of `rows`, the sweep over `fzs` × `kappas` × `alphas` in that nesting
/// (slip angle innermost) of the tire named `tire_name`. Refused when neither slip is a
/// range, or with more than [`MAX_CURVES`] curves.
pub fn sweep(
    tire_name: &str,
    rows: &[SweepRow],
    fzs: &[f64],
    kappas: &[f64],
    alphas: &[f64],
) -> Result<Chart, String> {
    let lateral = alphas.len() > 1;
    if !lateral && kappas.len() < 2 {
        return Err("--plot needs a swept --alpha-deg or --kappa (a range)".into());
    }
    if rows.len() != fzs.len() * kappas.len() * alphas.len() {
        return Err(format!(
            "{} sweep rows for {} x {} x {} points",
            rows.len(),
            fzs.len(),
            kappas.len(),
            alphas.len()
        ));
    }
    let mut curves = Vec::new();
    for (i, &fz) in fzs.iter().enumerate() {
        if lateral {
            for (j, &k) in kappas.iter().enumerate() {
                let start = (i * kappas.len() + j) * alphas.len();
                let run = &rows[start..start + alphas.len()];
                curves.push(Curve::new(
                    format!("Fz = {:.0} kN, kappa = {k}", fz / 1e3),
                    run.iter().map(|r| r.alpha_deg).collect(),
                    run.iter().map(|r| r.fy_n / 1e3).collect(),
                ));
            }
        } else {
            for (j, &a) in alphas.iter().enumerate() {
                let run: Vec<&SweepRow> = (0..kappas.len())
                    .map(|m| &rows[(i * kappas.len() + m) * alphas.len() + j])
                    .collect();
                curves.push(Curve::new(
                    format!("Fz = {:.0} kN, alpha = {a} deg", fz / 1e3),
                    run.iter().map(|r| r.kappa).collect(),
                    run.iter().map(|r| r.fx_n / 1e3).collect(),
                ));
            }
        }
    }
    if curves.len() > MAX_CURVES {
        return Err(format!(
            "--plot: {} curves is too many to read (at most {MAX_CURVES})",
            curves.len()
        ));
    }
    let (title, x, y) = if lateral {
        (
            "Fiala lateral force F_y versus slip angle",
            Axis::new("slip angle alpha", "deg"),
            Axis::new("lateral force F_y", "kN"),
        )
    } else {
        (
            "Fiala longitudinal force F_x versus slip ratio",
            Axis::new("slip ratio kappa", "-"),
            Axis::new("longitudinal force F_x", "kN"),
        )
    };
    let conditions = format!(
        "{tire_name}; F_z = {} kN; {}",
        values(fzs, 1e-3),
        if lateral {
            format!("kappa = {}", values(kappas, 1.0))
        } else {
            format!("alpha = {} deg", values(alphas, 1.0))
        }
    );
    Ok(Chart::Figure {
        title: title.into(),
        conditions,
        x,
        y,
        curves,
    })
}

/// The values `v` scaled by `s` for a conditions line: listed when few, else the range
/// and count.
fn values(v: &[f64], s: f64) -> String {
    match v {
        [a, .., b] if v.len() > 6 => format!("{} to {} ({} values)", a * s, b * s, v.len()),
        _ => {
            let parts: Vec<String> = v.iter().map(|x| format!("{}", x * s)).collect();
            parts.join(", ")
        }
    }
}
