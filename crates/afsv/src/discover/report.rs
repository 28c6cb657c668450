//! Discovery reports: Markdown summary, full JSON, and SVG overlays/residuals of the
//! held-out records before (calibrated baseline) and after (named effects).

use super::{ActiveEffect, Discovery, DiscoveryModel};
use crate::plot::{line_plot, Series};
use crate::record::Record;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// Files a report writes into its folder (besides the SVG plots).
pub const REPORT_FILES: [&str; 2] = ["report.md", "report.json"];

/// Write `report.md`, `report.json` and SVG plots for `d` into `dir` (created if needed).
/// Returns the paths written.
pub fn write_report<M: DiscoveryModel + ?Sized>(
    model: &M,
    d: &Discovery,
    holdout: &[Record],
    holdout_names: &[String],
    dir: &Path,
) -> Result<Vec<PathBuf>, String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let mut written = Vec::new();
    let json = serde_json::to_string_pretty(d).map_err(|e| e.to_string())?;
    let p = dir.join("report.json");
    std::fs::write(&p, json + "\n").map_err(|e| format!("{}: {e}", p.display()))?;
    written.push(p);

    let catalogue = model.catalogue();
    let final_effects: Vec<(usize, Vec<f64>)> = d
        .final_model
        .effects
        .iter()
        .zip(&d.final_model.effect_params)
        .filter_map(|(name, params)| {
            let i = catalogue.iter().position(|e| &e.name == name)?;
            Some((i, params.iter().map(|p| p.1).collect()))
        })
        .collect();
    let active: Vec<ActiveEffect<'_>> = final_effects
        .iter()
        .map(|(index, values)| ActiveEffect {
            index: *index,
            values,
        })
        .collect();
    let mut plots = Vec::new();
    for (i, rec) in holdout.iter().enumerate() {
        let label = holdout_names
            .get(i)
            .cloned()
            .unwrap_or_else(|| format!("holdout_{i}"));
        let before = model.simulate(rec, &d.calibrated.baseline, &[])?;
        let after = model.simulate(rec, &d.final_model.baseline, &active)?;
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
            let p = dir.join(format!("overlay_{stem}.svg"));
            line_plot(
                &p,
                &format!("{label}: {ch}"),
                "time (s)",
                ch,
                &[
                    Series {
                        label: "measured",
                        x: &t,
                        y: meas,
                    },
                    Series {
                        label: "calibrated baseline",
                        x: &t,
                        y: b,
                    },
                    Series {
                        label: "with named effects",
                        x: &t,
                        y: a,
                    },
                ],
            )?;
            plots.push(p.clone());
            written.push(p);
            let rb: Vec<f64> = b.iter().zip(meas).map(|(x, y)| x - y).collect();
            let ra: Vec<f64> = a.iter().zip(meas).map(|(x, y)| x - y).collect();
            let p = dir.join(format!("residual_{stem}.svg"));
            line_plot(
                &p,
                &format!("{label}: {ch} residual (model - measured)"),
                "time (s)",
                ch,
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
            )?;
            written.push(p);
        }
    }
    let md = markdown(d, &plots, dir);
    let p = dir.join("report.md");
    std::fs::write(&p, md).map_err(|e| format!("{}: {e}", p.display()))?;
    written.push(p);
    Ok(written)
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

/// The Markdown summary of a discovery run.
pub fn markdown(d: &Discovery, plots: &[PathBuf], dir: &Path) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "# Model-discrepancy report: {}\n", d.model);
    if d.named.is_empty() {
        let _ = writeln!(s, "**No missing effect named.** The calibrated baseline explains the records as well as any candidate of the catalogue does, within the significance rule.");
        if let Some((name, shrink)) = &d.best_unnamed_shrink {
            let _ = writeln!(
                s,
                "\nThe best candidate, `{name}`, would explain only {:.0} % of the held-out gap; it was not significant.",
                100.0 * shrink
            );
        }
    } else {
        let _ = writeln!(
            s,
            "**Effects named, in order:** {}\n\n**Held-out gap shrink:** {:.1} % of the calibrated baseline's error above the estimated noise floor (normalised MSE {:.3e} -> {:.3e}, noise {:.3e}).",
            d.named.iter().map(|n| format!("`{n}`")).collect::<Vec<_>>().join(", "),
            100.0 * d.gap_shrink,
            d.calibrated.holdout_mse,
            d.final_model.holdout_mse,
            d.holdout_noise_mse
        );
        if d.gap_shrink < 0.7 {
            let _ = writeln!(s, "\nThe named effects explain only part of the gap: something outside the catalogue (or a different form of a named effect) remains.");
        }
        let _ = writeln!(s, "\n## Fitted effect parameters\n\n| effect | parameter | value | standard error |\n|---|---|---|---|");
        for (name, params) in d
            .final_model
            .effects
            .iter()
            .zip(&d.final_model.effect_params)
        {
            for (p, v, se) in params {
                let _ = writeln!(s, "| {name} | {p} | {v:.6e} | {se:.2e} |");
            }
        }
    }
    let _ = writeln!(s, "\n## Calibrated baseline parameters\n\n| parameter | nominal | calibrated | final | standard error (calibration) |\n|---|---|---|---|---|");
    for (i, n) in d.calibrated.baseline_names.iter().enumerate() {
        let _ = writeln!(
            s,
            "| {n} | {:.6e} | {:.6e} | {:.6e} | {:.2e} |",
            d.nominal.baseline[i],
            d.calibrated.baseline[i],
            d.final_model.baseline[i],
            d.calibrated.baseline_se[i]
        );
    }
    let _ = writeln!(s, "\n## Error per channel (NRMSE = RMS error / channel standard deviation)\n\n| channel | train before | train after | held-out before | held-out after |\n|---|---|---|---|---|");
    // A channel no record has is not compared: shown as "not recorded", not as NaN.
    let cell = |e: &super::ChannelError| {
        if e.samples == 0 {
            "not recorded".to_string()
        } else {
            format!("{:.4}", e.nrmse)
        }
    };
    for (tb, ta, hb, ha) in &d.channel_errors {
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} | {} |",
            tb.channel,
            cell(tb),
            cell(ta),
            cell(hb),
            cell(ha)
        );
    }
    let _ = writeln!(s, "\n## Where the calibrated baseline disagrees most\n\n| record | channel | NRMSE | bias | lag (s) | amplitude ratio | freq. shift (%) | low-band share | zero-crossing ratio | worst phase |\n|---|---|---|---|---|---|---|---|---|---|");
    let mut sig: Vec<_> = d.signatures.iter().collect();
    sig.sort_by(|a, b| b.1.nrmse.total_cmp(&a.1.nrmse));
    for (rec, g) in sig.iter().take(12) {
        let worst = g
            .phases
            .iter()
            .filter(|p| p.1.is_finite())
            .max_by(|a, b| a.1.total_cmp(&b.1))
            .map(|p| format!("{} ({:.3})", p.0, p.1))
            .unwrap_or_default();
        let _ = writeln!(
            s,
            "| {rec} | {} | {:.4} | {:+.3} | {:+.4} | {:.3} | {:+.1} | {:.2} | {:.2} | {worst} |",
            g.channel,
            g.nrmse,
            g.bias,
            g.lag_s,
            g.amplitude_ratio,
            g.frequency_shift_percent,
            g.low_band_fraction,
            g.zero_crossing_ratio
        );
    }
    let _ = writeln!(s, "\n## Candidates tried\n");
    for (k, st) in d.steps.iter().enumerate() {
        let _ = writeln!(
            s,
            "Round {} (named: {}):\n",
            k + 1,
            st.named.as_deref().unwrap_or("none")
        );
        if let Some(note) = &st.attribution {
            let _ = writeln!(s, "> {note}\n");
        }
        let _ = writeln!(
            s,
            "| candidate | held-out gain | BIC drop | train MSE | held-out MSE |\n|---|---|---|---|---|"
        );
        for c in &st.candidates {
            match &c.outcome {
                Ok(o) => {
                    let _ = writeln!(
                        s,
                        "| {} | {:+.1} % | {:.1} | {:.3e} | {:.3e} |",
                        c.effect,
                        100.0 * c.holdout_gain,
                        c.bic_drop,
                        o.train_mse,
                        o.holdout_mse
                    );
                }
                Err(e) => {
                    let _ = writeln!(s, "| {} | failed: {e} | | | |", c.effect);
                }
            }
        }
        let _ = writeln!(s);
    }
    if !plots.is_empty() {
        let _ = writeln!(s, "## Held-out overlays\n");
        for p in plots {
            let rel = p.strip_prefix(dir).unwrap_or(p);
            let _ = writeln!(s, "![{0}]({0})", rel.display());
        }
    }
    s
}
