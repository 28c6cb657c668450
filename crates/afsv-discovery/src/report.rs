//! Discovery reports: Markdown summary, full JSON, and SVG overlays/residuals of the
//! held-out records before (calibrated baseline) and after (named effects).

use super::{Discovery, DiscoveryError, DiscoveryModel};
use afsv_records::Record;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// Files a report writes into its folder (besides the SVG plots of the `plots` feature).
pub const REPORT_FILES: [&str; 2] = ["report.md", "report.json"];

/// Write `report.md`, `report.json` and (with the `plots` feature) SVG overlays and
/// residuals of the held-out records for `d` into `dir` (created if needed). `provenance`
/// (what made the report: tool, version, commit, the input files with their SHA-256) goes
/// into both as it is given. Returns the paths written.
pub fn write_report<M: DiscoveryModel + ?Sized>(
    model: &M,
    d: &Discovery,
    holdout: &[Record],
    holdout_names: &[String],
    dir: &Path,
    provenance: &serde_json::Value,
) -> Result<Vec<PathBuf>, DiscoveryError> {
    std::fs::create_dir_all(dir).map_err(|e| DiscoveryError::io(dir, e))?;
    let mut written = Vec::new();
    let mut value = serde_json::to_value(d)?;
    value["provenance"] = provenance.clone();
    let json = serde_json::to_string_pretty(&value)?;
    let p = dir.join("report.json");
    afsv_records::atomic::write(&p, json + "\n").map_err(|e| DiscoveryError::io(&p, e))?;
    written.push(p);

    #[cfg(feature = "plots")]
    let plots = {
        let (overlays, svgs) =
            crate::overlay::write_overlays(model, d, holdout, holdout_names, dir)?;
        written.extend(svgs);
        overlays
    };
    #[cfg(not(feature = "plots"))]
    let plots: Vec<PathBuf> = {
        // Without the `plots` feature the report is report.md and report.json only.
        let _ = (model, holdout, holdout_names);
        Vec::new()
    };
    let mut md = markdown(d, &plots, dir);
    provenance_section(&mut md, provenance);
    let p = dir.join("report.md");
    afsv_records::atomic::write(&p, md).map_err(|e| DiscoveryError::io(&p, e))?;
    written.push(p);
    Ok(written)
}

/// The report's last section: what made it, as `provenance` states it.
fn provenance_section(s: &mut String, provenance: &serde_json::Value) {
    let text = |k: &str| provenance[k].as_str().unwrap_or("not stated").to_string();
    let _ = writeln!(
        s,
        "\n## Provenance\n\n{} {}, commit {}.\n",
        text("tool"),
        text("version"),
        text("commit")
    );
    if let Some(inputs) = provenance["inputs"].as_array().filter(|a| !a.is_empty()) {
        let _ = writeln!(s, "| input file | SHA-256 |\n|---|---|");
        for i in inputs {
            let _ = writeln!(
                s,
                "| `{}` | `{}` |",
                i["file"].as_str().unwrap_or("?"),
                i["sha256"].as_str().unwrap_or("?")
            );
        }
    }
}

/// Most held-out records plotted (two SVGs per record and channel).
pub const MAX_PLOTTED_RECORDS: usize = 8;

/// A number with three significant digits, in plain or scientific notation as fits.
fn sig3(v: f64) -> String {
    let a = v.abs();
    if a == 0.0 {
        "0".into()
    } else if (1e-3..1e4).contains(&a) {
        let decimals = (2 - a.log10().floor() as i32).max(0) as usize;
        format!("{v:.decimals$}")
    } else {
        format!("{v:.2e}")
    }
}

/// The Markdown summary of a discovery run.
pub fn markdown(d: &Discovery, plots: &[PathBuf], dir: &Path) -> String {
    let mut s = String::new();
    summary(&mut s, d);
    naming_tests(&mut s, d);
    if !d.named.is_empty() {
        fitted_effects(&mut s, d);
        evidence(&mut s, d);
    }
    conditions(&mut s, d);
    readings_table(&mut s, d);
    baseline_table(&mut s, d);
    channel_table(&mut s, d);
    disagreement(&mut s, d);
    candidates(&mut s, d);
    overlays(&mut s, plots, dir);
    s
}

/// Title, headline and what was named (or why nothing was).
fn summary(s: &mut String, d: &Discovery) {
    let _ = writeln!(s, "# Model-discrepancy report: {}\n", d.model);
    let _ = writeln!(s, "{}\n", headline(d));
    let _ = writeln!(
        s,
        "**Outcome:** {} (exit code {}).\n",
        d.outcome.describe(),
        d.outcome.exit_code()
    );
    if !d.calibration_problems.is_empty() {
        let _ = writeln!(
            s,
            "**The final model did not earn its baseline** (`afsv discover` exits 3 unless `--accept-poor-fit`):\n"
        );
        for p in &d.calibration_problems {
            let _ = writeln!(s, "- {p}");
        }
        let _ = writeln!(s);
    }
    for n in &d.calibration_notes {
        let _ = writeln!(s, "**Note on the calibration:** {n}.\n");
    }
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
    }
}

/// The naming tests of each significant candidate ([`crate::form`]).
fn naming_tests(s: &mut String, d: &Discovery) {
    let tested: Vec<_> = d
        .steps
        .iter()
        .filter_map(|st| st.naming_tests.as_ref())
        .collect();
    let _ = writeln!(
        s,
        "\n## Naming tests\n\nThe calibrated baseline leaves {:.2}x the estimated noise floor on the held-out records.\n",
        d.excess_over_noise
    );
    if tested.is_empty() {
        let _ = writeln!(s, "No candidate was significant, so none was tested.");
        return;
    }
    let _ = writeln!(s, "| candidate | on a bound | held-out gain | best placebo (gain) | condition groups | constant | verdict |\n|---|---|---|---|---|---|---|");
    for t in tested {
        let groups: Vec<String> = t
            .groups
            .iter()
            .map(|g| {
                let v: Vec<String> = g
                    .values
                    .iter()
                    .zip(&g.std_errors)
                    .map(|(v, e)| format!("{} ± {}", sig3(*v), opt(*e, sig3)))
                    .collect();
                let b = if g.at_bound { " (at a bound)" } else { "" };
                format!("{} [{}]: {}{b}", g.group, g.records, v.join(", "))
            })
            .collect();
        let _ = writeln!(
            s,
            "| {} | {} | {:.3e} | {} | {} | {} | {} |",
            t.effect,
            if t.at_bound.is_empty() {
                "no".to_string()
            } else {
                t.at_bound.join(", ")
            },
            t.effect_gain,
            t.best_placebo
                .as_ref()
                .map_or("n/a".to_string(), |(n, g)| format!("{n} ({g:.3e})")),
            if groups.is_empty() {
                "n/a".to_string()
            } else {
                groups.join("; ")
            },
            match t.constant {
                Some(true) => "yes",
                Some(false) => "no",
                None => "not testable",
            },
            if t.passed() {
                "named".to_string()
            } else {
                format!("fails: {}", t.failed.join("; "))
            }
        );
    }
}

/// The fitted parameters of the named effects.
fn fitted_effects(s: &mut String, d: &Discovery) {
    let _ = writeln!(s, "\n## Fitted effect parameters\n\n| effect | parameter | value | standard error | note |\n|---|---|---|---|---|");
    for (name, params) in d
        .final_model
        .effects
        .iter()
        .zip(&d.final_model.effect_params)
    {
        for p in params {
            let note = if p.at_bound {
                "at a bound of its range"
            } else {
                ""
            };
            let _ = writeln!(
                s,
                "| {name} | {} | {:.6e} | {} | {note} |",
                p.name,
                p.value,
                opt(p.std_error, |v| format!("{v:.2e}"))
            );
        }
    }
}

/// Per named effect: the held-out records and phases that carried its gain.
fn evidence(s: &mut String, d: &Discovery) {
    let _ = writeln!(
        s,
        "\n## Evidence: where each effect's held-out gain comes from\n"
    );
    for ev in &d.evidence {
        let phases = ev
            .phases
            .iter()
            .map(|(p, share)| format!("{p} {:.0} %", 100.0 * share))
            .collect::<Vec<_>>()
            .join(", ");
        let _ = writeln!(s, "`{}` (by phase: {phases}):\n\n| held-out record | condition | MSE before | MSE after | share of gain |\n|---|---|---|---|---|", ev.effect);
        for r in ev.records.iter().take(10) {
            let _ = writeln!(
                s,
                "| {} | {} | {:.3e} | {:.3e} | {:+.1} % |",
                r.record,
                r.condition,
                r.mse_before,
                r.mse_after,
                100.0 * r.share
            );
        }
        if ev.records.len() > 10 {
            let _ = writeln!(
                s,
                "\n({} more records in report.json)",
                ev.records.len() - 10
            );
        }
        let _ = writeln!(s);
    }
}

/// The conditions each record was replayed under.
fn conditions(s: &mut String, d: &Discovery) {
    let _ = writeln!(s, "\n## Conditions each record was replayed under\n\n| record | set | condition |\n|---|---|---|");
    for c in &d.conditions {
        let _ = writeln!(s, "| {} | {} | {} |", c.record, c.set, c.condition);
    }
}

/// The reading each calibration switch took, and what each reading tried scored.
fn readings_table(s: &mut String, d: &Discovery) {
    if d.readings.is_empty() {
        return;
    }
    let _ = writeln!(s, "\n## Calibration switches\n\nLaws the paper states ambiguously, calibrated in each reading; a reading replaces the default only when it fits the training records better and lowers the held-out error by at least the rule's share of the gap.\n\n| switch | reading kept | reading tried: normalised MSE training / held-out |\n|---|---|---|");
    for r in &d.readings {
        let tried: Vec<String> = r
            .tried
            .iter()
            .map(|t| {
                format!(
                    "{}: {} / {}",
                    t.reading,
                    sig3(t.train_mse),
                    sig3(t.holdout_mse)
                )
            })
            .collect();
        let _ = writeln!(s, "| {} | {} | {} |", r.switch, r.chosen, tried.join("; "));
    }
}

/// Nominal, calibrated and final baseline parameters.
fn baseline_table(s: &mut String, d: &Discovery) {
    let _ = writeln!(s, "\n## Calibrated baseline parameters\n\n| parameter | nominal | calibrated | final | standard error (calibration) |\n|---|---|---|---|---|");
    for (i, n) in d.calibrated.baseline_names.iter().enumerate() {
        let _ = writeln!(
            s,
            "| {n} | {:.6e} | {:.6e} | {:.6e} | {} |",
            d.nominal.baseline[i],
            d.calibrated.baseline[i],
            d.final_model.baseline[i],
            opt(d.calibrated.baseline_se[i], |v| format!("{v:.2e}"))
        );
    }
}

/// Per-channel NRMSE before and after, training and held-out.
fn channel_table(s: &mut String, d: &Discovery) {
    let _ = writeln!(s, "\n## Error per channel (NRMSE = RMS error / channel standard deviation)\n\n| channel | train before | train after | held-out before | held-out after |\n|---|---|---|---|---|");
    // A channel no record has is not compared: shown as "not recorded", not as NaN.
    let cell = |e: &super::ChannelError| {
        if e.samples == 0 {
            "not recorded".to_string()
        } else {
            opt(e.nrmse, |v| format!("{v:.4}"))
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
}

/// The worst channel signatures of the calibrated baseline.
fn disagreement(s: &mut String, d: &Discovery) {
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
}

/// Every round's candidates with their scores or failures.
fn candidates(s: &mut String, d: &Discovery) {
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
                        "| {} | {} | {} | {:.3e} | {:.3e} |",
                        c.effect,
                        opt(c.holdout_gain, |g| format!("{:+.1} %", 100.0 * g)),
                        opt(c.bic_drop, |b| format!("{b:.1}")),
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
}

/// Links to the overlay plots (feature `plots`).
fn overlays(s: &mut String, plots: &[PathBuf], dir: &Path) {
    if !plots.is_empty() {
        let _ = writeln!(s, "## Held-out overlays\n");
        for p in plots {
            let rel = p.strip_prefix(dir).unwrap_or(p);
            let _ = writeln!(s, "![{0}]({0})", rel.display());
        }
    }
}

/// `n/a` for a quantity that could not be computed.
fn opt(v: Option<f64>, f: impl Fn(f64) -> String) -> String {
    v.filter(|x| x.is_finite())
        .map_or_else(|| "n/a".to_string(), f)
}

/// One plain sentence a vehicle engineer can act on: what is missing, how big, how much of
/// the gap it closes, and where the evidence is.
pub fn headline(d: &Discovery) -> String {
    let subject = if d.model == "hps-strut" {
        "strut"
    } else {
        "steering"
    };
    if let super::Outcome::ModelFormDiscrepancy {
        excess_over_noise,
        closest,
        ..
    } = &d.outcome
    {
        return format!(
            "The calibrated paper model leaves {excess_over_noise:.1} times the noise on these {subject} records, and no effect of the catalogue explains it as a real effect would{}: the model's form differs from the records' (laws or parameters the paper does not state), so calibrate or revise the baseline before naming physics.",
            closest
                .as_ref()
                .map_or(String::new(), |c| format!(" (the closest, {c}, fails a naming test)"))
        );
    }
    if d.named.is_empty() {
        return match &d.best_unnamed_shrink {
            Some((name, shrink)) if *shrink > 0.0 => format!(
                "The calibrated paper model explains these {subject} records as well as any effect of the catalogue: the best candidate, {name}, would close only {:.0} % of the remaining held-out gap and is not significant, so look outside the catalogue (sensors, inputs) if the gap matters.",
                100.0 * shrink
            ),
            _ => format!(
                "The calibrated paper model explains these {subject} records; no effect of the catalogue improves the held-out records significantly."
            ),
        };
    }
    let effects: Vec<String> = d
        .final_model
        .effects
        .iter()
        .zip(&d.final_model.effect_params)
        .map(|(name, params)| {
            let vals: Vec<String> = params
                .iter()
                .map(|p| match p.std_error {
                    Some(se) if !p.at_bound => {
                        format!("{} = {} ± {}", p.name, sig3(p.value), sig3(se))
                    }
                    _ if p.at_bound => format!("{} = {} (at a bound)", p.name, sig3(p.value)),
                    _ => format!("{} = {}", p.name, sig3(p.value)),
                })
                .collect();
            format!("{name} ({})", vals.join(", "))
        })
        .collect();
    let where_ = d
        .evidence
        .first()
        .and_then(|ev| {
            let top: Vec<String> = ev
                .records
                .iter()
                .take(2)
                .filter(|r| r.share > 0.0)
                .map(|r| format!("{} [{}]", r.record, r.condition))
                .collect();
            (!top.is_empty())
                .then(|| format!("; the evidence is strongest in {}", top.join(" and ")))
        })
        .unwrap_or_default();
    let partial = if d.gap_shrink < 0.7 {
        " Part of the gap remains unexplained."
    } else {
        ""
    };
    format!(
        "The {subject} records show what the paper model lacks: add {} — it closes {:.1} % of the held-out gap above the noise{where_}.{partial}",
        effects.join(" and "),
        100.0 * d.gap_shrink
    )
}

/// What `afsv discover --list-effects` prints: the model's name, its baseline parameters
/// and its catalogue of effects.
pub fn catalogue_json<M: DiscoveryModel + ?Sized>(model: &M) -> serde_json::Value {
    serde_json::json!({
        "model": model.name(),
        "baseline_params": model.baseline_params(),
        "catalogue": model.catalogue(),
    })
}

/// What `afsv discover` prints of a finished discovery `d` whose report went to
/// `report_dir` (`files_written` files): the [`headline`], the outcome and its `exit_code`,
/// the named effects and the gap they close, the held-out errors per channel and the
/// calibration's problems (`accepted`: printed despite them, `--accept-poor-fit`).
pub fn summary_json(
    d: &Discovery,
    report_dir: &Path,
    files_written: usize,
    exit_code: u8,
    accepted: bool,
) -> serde_json::Value {
    serde_json::json!({
        "model": d.model,
        "summary": headline(d),
        "outcome": d.outcome,
        "exit_code": exit_code,
        "excess_over_noise": d.excess_over_noise,
        "named": d.named,
        "effect_params": d.final_model.effect_params,
        "gap_shrink": d.gap_shrink,
        "best_unnamed": d.best_unnamed_shrink,
        "holdout_mse": {"calibrated": d.calibrated.holdout_mse, "final": d.final_model.holdout_mse, "noise": d.holdout_noise_mse},
        "channel_errors": d.channel_errors.iter().map(|(tb, ta, hb, ha)| serde_json::json!({
            "channel": tb.channel, "train_before": tb.nrmse, "train_after": ta.nrmse,
            "holdout_before": hb.nrmse, "holdout_after": ha.nrmse})).collect::<Vec<_>>(),
        "report": report_dir.join("report.md"),
        "files_written": files_written,
        "calibration_problems": d.calibration_problems,
        "calibration_notes": d.calibration_notes,
        "accepted_despite_problems": accepted && !d.calibration_problems.is_empty(),
    })
}

/// What `afsv synth` prints after writing `records` to `output`: the training and held-out
/// record names and the truth file.
pub fn synth_summary(output: &Path, records: &[crate::synth::SynthRecord]) -> serde_json::Value {
    let names = |holdout: bool| -> Vec<&String> {
        records
            .iter()
            .filter(|r| r.holdout == holdout)
            .map(|r| &r.name)
            .collect()
    };
    serde_json::json!({
        "output": output,
        "train": names(false),
        "holdout": names(true),
        "truth": output.join("truth.json"),
    })
}

#[cfg(test)]
mod tests {
    use super::{catalogue_json, provenance_section, sig3, synth_summary};
    use crate::synth::SynthRecord;
    use crate::DiscoveryModel;

    #[test]
    fn the_provenance_names_the_tool_and_every_input() {
        let mut s = String::new();
        provenance_section(
            &mut s,
            &serde_json::json!({
                "tool": "afsv", "version": "0.1.0", "commit": "abc123",
                "inputs": [{"file": "train/a.csv", "sha256": "00ff"}],
            }),
        );
        assert!(s.contains("## Provenance") && s.contains("afsv 0.1.0, commit abc123."));
        assert!(s.contains("| `train/a.csv` | `00ff` |"));
        let mut bare = String::new();
        provenance_section(&mut bare, &serde_json::json!({}));
        assert!(bare.contains("not stated") && !bare.contains("SHA-256"));
    }

    #[test]
    fn three_significant_digits() {
        assert_eq!(sig3(0.040126), "0.0401");
        assert_eq!(sig3(2.62e-6), "2.62e-6");
        assert_eq!(sig3(3689.95), "3690");
        assert_eq!(sig3(12.345), "12.3");
        assert_eq!(sig3(-0.5), "-0.500");
        assert_eq!(sig3(0.0), "0");
    }

    #[test]
    fn synth_summary_splits_train_and_holdout() {
        let rec = |name: &str, holdout| SynthRecord {
            name: name.into(),
            holdout,
            record: afsv_records::Record::new(),
        };
        let v = synth_summary(
            std::path::Path::new("out"),
            &[rec("a", false), rec("b", true), rec("c", false)],
        );
        assert_eq!(v["train"], serde_json::json!(["a", "c"]));
        assert_eq!(v["holdout"], serde_json::json!(["b"]));
        assert_eq!(v["truth"], "out/truth.json");
    }

    #[test]
    fn the_catalogue_lists_the_models_effects() {
        let m = crate::hps::HpsStrutModel::nominal();
        let v = catalogue_json(&m);
        assert_eq!(v["model"], m.name());
        assert_eq!(
            v["catalogue"].as_array().unwrap().len(),
            m.catalogue().len()
        );
    }
}
