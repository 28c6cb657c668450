//! SVG overlays and residuals of the held-out records in a discovery report (feature
//! `plots`): measured, calibrated baseline and model with the named effects, per channel,
//! each axis a readable quantity in engineering units (MPa, kN, mm;
//! `afsv_records::units::plot_axis`).

use crate::report::MAX_PLOTTED_RECORDS;
use crate::{ActiveEffect, Discovery, DiscoveryError, DiscoveryModel};
use afsv_plot::{line_plot, Series};
use afsv_records::Record;
use std::path::{Path, PathBuf};

/// Write an overlay and a residual SVG per plotted held-out record and channel into `dir`.
/// Returns (the overlays, every SVG written).
pub(crate) fn write_overlays<M: DiscoveryModel + ?Sized>(
    model: &M,
    d: &Discovery,
    holdout: &[Record],
    holdout_names: &[String],
    dir: &Path,
) -> Result<(Vec<PathBuf>, Vec<PathBuf>), DiscoveryError> {
    let mut written = Vec::new();
    let catalogue = model.catalogue();
    let final_effects: Vec<(usize, Vec<f64>)> = d
        .final_model
        .effects
        .iter()
        .zip(&d.final_model.effect_params)
        .filter_map(|(name, params)| {
            let i = catalogue.iter().position(|e| &e.name == name)?;
            Some((i, params.iter().map(|p| p.value).collect()))
        })
        .collect();
    let active: Vec<ActiveEffect<'_>> = final_effects
        .iter()
        .map(|(index, values)| ActiveEffect {
            index: *index,
            values,
        })
        .collect();
    // The replays run under the readings the calibration switches took.
    let readings: Vec<usize> = d.readings.iter().map(|r| r.index).collect();
    let mut plots = Vec::new();
    for i in plotted_records(d, holdout_names, holdout.len()) {
        let rec = &holdout[i];
        let label = holdout_names
            .get(i)
            .cloned()
            .unwrap_or_else(|| format!("holdout_{i}"));
        let prepared = model.prepare(rec)?;
        let before =
            model.simulate_with_readings(&prepared, &d.calibrated.baseline, &[], &readings)?;
        let after =
            model.simulate_with_readings(&prepared, &d.final_model.baseline, &active, &readings)?;
        let t: Vec<f64> = rec
            .column("time_s")
            .map(<[f64]>::to_vec)
            .unwrap_or_else(|| (0..rec.len()).map(|k| k as f64).collect());
        for (c, ch) in d.channels.iter().enumerate() {
            let (Some(meas), Some(Some(b)), Some(Some(a))) =
                (rec.column(ch), before.get(c), after.get(c))
            else {
                continue;
            };
            let stem = sanitize(&format!("{label}_{ch}"));
            let axis = afsv_records::units::plot_axis(ch);
            let scaled = |v: &[f64]| -> Vec<f64> { v.iter().map(|x| x * axis.scale).collect() };
            let (meas, b, a) = (scaled(meas), scaled(b), scaled(a));
            let quantity = axis.label.split(" (").next().unwrap_or(ch);
            let p = dir.join(format!("overlay_{stem}.svg"));
            line_plot(
                &p,
                &format!("{label}: {quantity} ({ch})"),
                "time (s)",
                &axis.label,
                &[
                    Series {
                        label: "measured",
                        x: &t,
                        y: &meas,
                    },
                    Series {
                        label: "calibrated baseline",
                        x: &t,
                        y: &b,
                    },
                    Series {
                        label: "with named effects",
                        x: &t,
                        y: &a,
                    },
                ],
            )
            .map_err(DiscoveryError::Plot)?;
            plots.push(p.clone());
            written.push(p);
            let rb: Vec<f64> = b.iter().zip(&meas).map(|(x, y)| x - y).collect();
            let ra: Vec<f64> = a.iter().zip(&meas).map(|(x, y)| x - y).collect();
            let p = dir.join(format!("residual_{stem}.svg"));
            line_plot(
                &p,
                &format!("{label}: {quantity} residual, model - measured ({ch})"),
                "time (s)",
                &format!("residual {}", axis.label),
                &[
                    Series {
                        label: "calibrated baseline",
                        x: &t,
                        y: &rb,
                    },
                    Series {
                        label: "with named effects",
                        x: &t,
                        y: &ra,
                    },
                ],
            )
            .map_err(DiscoveryError::Plot)?;
            written.push(p);
        }
    }
    Ok((plots, written))
}

/// Held-out records that get overlay plots: at most [`MAX_PLOTTED_RECORDS`], those carrying
/// the largest share of the first named effect's gain (or, when nothing was named, the
/// first ones), in record order. Every record stays in report.json.
fn plotted_records(d: &Discovery, names: &[String], n: usize) -> Vec<usize> {
    let mut picked: Vec<usize> = match d.evidence.first() {
        Some(ev) => ev
            .records
            .iter()
            .filter_map(|r| names.iter().position(|n| *n == r.record))
            .take(MAX_PLOTTED_RECORDS)
            .collect(),
        None => (0..n.min(MAX_PLOTTED_RECORDS)).collect(),
    };
    if picked.is_empty() {
        picked = (0..n.min(MAX_PLOTTED_RECORDS)).collect();
    }
    picked.sort_unstable();
    picked
}

fn sanitize(s: &str) -> String {
    s.chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' || c == '_' {
                c
            } else {
                '_'
            }
        })
        .collect()
}
