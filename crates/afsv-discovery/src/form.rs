//! Naming tests: tell a missing effect from a model-form difference before naming anything.
//!
//! A catalogue effect that passes the significance rule ([`crate::stats`]) may still only
//! absorb a difference of form between the baseline and the records (another friction band,
//! chamber split, density upwinding, cavitation floor, ...): the closest effect then takes
//! up what it can. Before an effect is named, three tests use evidence the records hold
//! (docs/discovery.md, "Naming tests"):
//!
//! 1. **Bounds.** A fitted effect parameter on a bound of its range fails: the data push it
//!    beyond any physical value, as a proxy does.
//! 2. **Placebos.** The generic corrections of [`crate::placebo`] with the same number of
//!    parameters are scouted exactly as the candidate was (same start points, short fits
//!    with the baseline freed), then get [`crate::DiscoveryOptions::polish_iterations`]
//!    more iterations on all training records (not the candidate's fit to convergence,
//!    which costs as much as a whole candidate). The candidate's held-out gain
//!    `G_e = MSE_ref - MSE_e` must beat the best placebo's `G_p` by a clear margin:
//!    `G_p <= (1 - m) G_e` with `m` = [`FormRule::placebo_margin`].
//! 3. **Constancy.** A real effect has one parameter value across conditions. With the
//!    baseline held at the candidate's fit, the effect's parameters are fitted again on each
//!    condition group of the training records ([`crate::DiscoveryModel::group`]). Two groups
//!    agree when `|a - b| <= max(z sqrt(s_a^2 + s_b^2), r max(|a|, |b|))`, with the standard
//!    errors `s` inflated by `sqrt(n / n_eff)` for serially correlated residuals
//!    ([`crate::stats::effective_samples`]), `z` = [`FormRule::constancy_z`] and `r` =
//!    [`FormRule::constancy_rel`]. A group whose fit sits on a bound, or has no finite
//!    standard error, cannot identify the parameter and is left out; with fewer than two
//!    informative groups the test is not applicable.
//!
//! The outcome ([`Outcome`]) is one of: effects named; a model-form discrepancy (a
//! significant candidate failed a test, or nothing was significant but the calibrated
//! baseline leaves more than [`FormRule::noise_ratio`] times the noise floor); nothing
//! missing.

use super::fitting::{Config, Context, Fitted};
use super::layout::RecordSet;
use super::stats;
use super::{DiscoveryError, DiscoveryModel};
use optimize::least_squares::{fit, FitOptions, Problem};
use rayon::prelude::*;

/// Thresholds of the naming tests.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct FormRule {
    /// A named effect's held-out gain must exceed the best placebo's by this fraction of
    /// its own gain (`G_p <= (1 - m) G_e`).
    pub placebo_margin: f64,
    /// Agreement of condition groups: standard errors (inflated for correlation) allowed.
    pub constancy_z: f64,
    /// Agreement of condition groups: relative difference always allowed.
    pub constancy_rel: f64,
    /// Nothing significant and the calibrated baseline's held-out error above this many
    /// times the noise floor: a model-form discrepancy instead of "nothing missing".
    pub noise_ratio: f64,
    /// Run the naming tests at all (off: every significant candidate is named, as before
    /// the tests existed).
    pub enabled: bool,
}

impl Default for FormRule {
    fn default() -> Self {
        Self {
            placebo_margin: 0.3,
            constancy_z: 3.0,
            constancy_rel: 0.1,
            noise_ratio: 4.0,
            enabled: true,
        }
    }
}

/// One condition group's fit of a candidate's parameters (baseline held).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct GroupFit {
    /// Group label.
    pub group: String,
    /// Training records in it.
    pub records: usize,
    /// Fitted values of the candidate's parameters.
    pub values: Vec<f64>,
    /// Their standard errors, inflated by `sqrt(n / n_eff)` (`None`: not estimable).
    pub std_errors: Vec<Option<f64>>,
    /// Some value sits on a bound: the group cannot identify the parameter.
    pub at_bound: bool,
}

/// The naming tests of one significant candidate.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct NamingTests {
    /// The candidate.
    pub effect: String,
    /// Its parameters that sit on a bound.
    pub at_bound: Vec<String>,
    /// The candidate's held-out gain (normalised MSE removed against the round's model).
    pub effect_gain: f64,
    /// The best placebo with as many parameters and its held-out gain (`None`: no placebo
    /// could be fitted).
    pub best_placebo: Option<(String, f64)>,
    /// Per condition group: the candidate's parameters fitted there.
    pub groups: Vec<GroupFit>,
    /// Whether the informative groups agree (`None`: fewer than two informative groups).
    pub constant: Option<bool>,
    /// Each failed test in words (empty: the candidate may be named).
    pub failed: Vec<String>,
}

impl NamingTests {
    /// No test failed.
    pub fn passed(&self) -> bool {
        self.failed.is_empty()
    }
}

/// What a discovery run found.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum Outcome {
    /// Effects named (and passed every naming test).
    Named {
        /// In naming order.
        effects: Vec<String>,
        /// After them, a significant candidate that failed a naming test, in words.
        #[serde(skip_serializing_if = "Option::is_none")]
        remainder: Option<String>,
    },
    /// The calibrated baseline differs from the records in a way no catalogue effect
    /// explains as a real effect would.
    ModelFormDiscrepancy {
        /// Calibrated baseline's held-out error over the noise floor.
        excess_over_noise: f64,
        /// The closest candidate.
        #[serde(skip_serializing_if = "Option::is_none")]
        closest: Option<String>,
        /// Its share of the reducible held-out gap.
        explains: f64,
        /// The tests it failed, in words.
        failed: Vec<String>,
    },
    /// Nothing is missing: no candidate is significant and the calibrated baseline is
    /// near the noise floor.
    NothingMissing {
        /// Calibrated baseline's held-out error over the noise floor.
        excess_over_noise: f64,
    },
}

/// Exit code of `afsv discover` for a named effect.
pub const EXIT_NAMED: u8 = 0;
/// Exit code of `afsv discover` for a model-form discrepancy.
pub const EXIT_DISCREPANCY: u8 = 3;
/// Exit code of `afsv discover` when nothing is missing.
pub const EXIT_NOTHING_MISSING: u8 = 4;

impl Outcome {
    /// The exit code `afsv discover` returns for it ([`EXIT_NAMED`],
    /// [`EXIT_DISCREPANCY`], [`EXIT_NOTHING_MISSING`]).
    pub fn exit_code(&self) -> u8 {
        match self {
            Outcome::Named { .. } => EXIT_NAMED,
            Outcome::ModelFormDiscrepancy { .. } => EXIT_DISCREPANCY,
            Outcome::NothingMissing { .. } => EXIT_NOTHING_MISSING,
        }
    }

    /// One line in words.
    pub fn describe(&self) -> String {
        match self {
            Outcome::Named { effects, remainder } => format!(
                "named: {}{}",
                effects.join(", "),
                remainder
                    .as_ref()
                    .map_or(String::new(), |r| format!("; then {r}"))
            ),
            Outcome::ModelFormDiscrepancy {
                excess_over_noise,
                closest,
                explains,
                failed,
            } => match closest {
                Some(c) => format!(
                    "model-form discrepancy: the calibrated baseline leaves {excess_over_noise:.1}x the noise; closest candidate {c} explains {:.0} % but fails: {}",
                    100.0 * explains,
                    failed.join("; ")
                ),
                None => format!(
                    "model-form discrepancy: the calibrated baseline leaves {excess_over_noise:.1}x the noise and no candidate explains it"
                ),
            },
            Outcome::NothingMissing { excess_over_noise } => format!(
                "nothing missing: no candidate is significant and the calibrated baseline leaves {excess_over_noise:.1}x the noise"
            ),
        }
    }
}

/// Run the naming tests of `cand` (the round's best, significant) against `current`.
/// `real` is the length of the model's own catalogue (placebos follow it).
pub(crate) fn naming_tests<M: DiscoveryModel + ?Sized>(
    ctx: &Context<'_, M>,
    current: &Fitted,
    cand: &Fitted,
    nominal_base: &[f64],
    real: usize,
) -> Result<NamingTests, DiscoveryError> {
    let rule = ctx.opts.form;
    let (e, values) = cand
        .1
        .effects
        .last()
        .cloned()
        .ok_or(DiscoveryError::NoStartPoint { effect: "?".into() })?;
    let spec = &ctx.catalogue[e];
    let k = values.len();
    let last = cand.0.effect_params.last().cloned().unwrap_or_default();
    let at_bound: Vec<String> = last
        .iter()
        .filter(|p| p.at_bound)
        .map(|p| p.name.clone())
        .collect();
    let effect_gain = current.0.holdout_mse - cand.0.holdout_mse;

    // Placebos with as many parameters, fitted as the candidate was.
    let placebos: Vec<usize> = (0..super::placebo::PLACEBOS.len())
        .map(|f| real + 2 * f + (k.clamp(1, 2) - 1))
        .filter(|&i| i < ctx.catalogue.len() && ctx.catalogue[i].params.len() == k)
        .collect();
    let fitted: Vec<(String, f64)> = placebos
        .par_iter()
        .filter_map(|&p| {
            let (c, _) = ctx.scout_candidate(&current.1, nominal_base, p).ok()?;
            let f = ctx.polish_short(c, current.2).ok()?;
            Some((
                ctx.catalogue[p].name.clone(),
                current.0.holdout_mse - f.0.holdout_mse,
            ))
        })
        .collect();
    let best_placebo = fitted.into_iter().max_by(|a, b| a.1.total_cmp(&b.1));

    let groups = group_fits(ctx, &cand.1, e)?;
    let informative: Vec<&GroupFit> = groups
        .iter()
        .filter(|g| !g.at_bound && g.std_errors.iter().all(Option::is_some))
        .collect();
    let constant = (informative.len() >= 2).then(|| {
        informative.iter().enumerate().all(|(i, a)| {
            informative[i + 1..]
                .iter()
                .all(|b| agree(a, b, rule.constancy_z, rule.constancy_rel))
        })
    });

    let mut failed = Vec::new();
    if !at_bound.is_empty() {
        failed.push(format!(
            "bounds: {} on a bound of its range",
            at_bound.join(", ")
        ));
    }
    if let Some((name, g)) = &best_placebo {
        if *g > (1.0 - rule.placebo_margin) * effect_gain {
            failed.push(format!(
                "placebo: {name} removes {:.0} % of the held-out error the effect removes (at most {:.0} % allowed)",
                100.0 * g / effect_gain.max(f64::MIN_POSITIVE),
                100.0 * (1.0 - rule.placebo_margin)
            ));
        }
    }
    if constant == Some(false) {
        let shown: Vec<String> = informative
            .iter()
            .map(|g| {
                let v: Vec<String> = g
                    .values
                    .iter()
                    .zip(&g.std_errors)
                    .map(|(v, s)| format!("{v:.3e} +- {:.1e}", s.unwrap_or(f64::NAN)))
                    .collect();
                format!("{} {}", g.group, v.join(", "))
            })
            .collect();
        failed.push(format!(
            "constancy: {} differs between condition groups ({})",
            spec.params
                .iter()
                .map(|p| p.name.as_str())
                .collect::<Vec<_>>()
                .join(", "),
            shown.join("; ")
        ));
    }
    Ok(NamingTests {
        effect: spec.name.clone(),
        at_bound,
        effect_gain,
        best_placebo,
        groups,
        constant,
        failed,
    })
}

/// What the outcome of a search depends on.
pub(crate) struct SearchSummary<'a> {
    /// Effects named, in order.
    pub named: &'a [String],
    /// The rounds.
    pub steps: &'a [super::Step],
    /// Held-out error of a significant candidate that failed a naming test.
    pub rejected_mse: Option<f64>,
    /// With nothing named: the best candidate and its held-out error.
    pub best_unnamed: Option<&'a (String, f64)>,
}

/// The outcome of a search (see [`Outcome`]).
pub(crate) fn outcome(
    s: &SearchSummary<'_>,
    calibrated_mse: f64,
    noise: f64,
    excess: f64,
    rule: &FormRule,
) -> Outcome {
    let failed = s
        .steps
        .iter()
        .filter_map(|st| st.naming_tests.as_ref())
        .find(|t| !t.passed());
    if !s.named.is_empty() {
        return Outcome::Named {
            effects: s.named.to_vec(),
            remainder: failed.map(|t| {
                format!(
                    "model-form discrepancy: the closest candidate {} fails: {}",
                    t.effect,
                    t.failed.join("; ")
                )
            }),
        };
    }
    if let Some(t) = failed {
        let explains = s
            .rejected_mse
            .map_or(0.0, |mse| stats::gap_shrink(calibrated_mse, mse, noise));
        return Outcome::ModelFormDiscrepancy {
            excess_over_noise: excess,
            closest: Some(t.effect.clone()),
            explains,
            failed: t.failed.clone(),
        };
    }
    if rule.enabled && excess > rule.noise_ratio {
        let best = s.best_unnamed;
        return Outcome::ModelFormDiscrepancy {
            excess_over_noise: excess,
            closest: best.map(|(n, _)| n.clone()),
            explains: best.map_or(0.0, |(_, mse)| {
                stats::gap_shrink(calibrated_mse, *mse, noise)
            }),
            failed: vec![if s.steps.is_empty() {
                format!(
                    "no candidate was tried (the effect limit or the candidate list), and the calibrated baseline leaves more than {} times the noise",
                    rule.noise_ratio
                )
            } else {
                format!(
                    "significance: no candidate passes the significance rule, yet the calibrated baseline leaves more than {} times the noise",
                    rule.noise_ratio
                )
            }],
        };
    }
    Outcome::NothingMissing {
        excess_over_noise: excess,
    }
}

/// Whether two groups' values agree (see the module docs).
fn agree(a: &GroupFit, b: &GroupFit, z: f64, rel: f64) -> bool {
    a.values
        .iter()
        .zip(&b.values)
        .zip(a.std_errors.iter().zip(&b.std_errors))
        .all(|((va, vb), (sa, sb))| {
            let s = (sa.unwrap_or(0.0).powi(2) + sb.unwrap_or(0.0).powi(2)).sqrt();
            (va - vb).abs() <= (z * s).max(rel * va.abs().max(vb.abs()))
        })
}

/// Refit the last effect's parameters of `config` on each condition group of the training
/// records, the baseline and earlier effects held.
fn group_fits<M: DiscoveryModel + ?Sized>(
    ctx: &Context<'_, M>,
    config: &Config,
    e: usize,
) -> Result<Vec<GroupFit>, DiscoveryError> {
    let train = &ctx.train;
    let mut labels: Vec<(String, Vec<usize>)> = Vec::new();
    for (i, p) in train.prepared.iter().enumerate() {
        if let Some(g) = ctx.model.group(p) {
            match labels.iter_mut().find(|(l, _)| *l == g) {
                Some((_, v)) => v.push(i),
                None => labels.push((g, vec![i])),
            }
        }
    }
    if labels.len() < 2 {
        return Ok(Vec::new());
    }
    let specs = &ctx.catalogue[e].params;
    let mut out = Vec::new();
    for (group, idx) in labels {
        let set = RecordSet::new(
            ctx.model,
            idx.iter().map(|&i| train.records[i]).collect(),
            idx.iter().map(|&i| train.prepared[i]).collect(),
            &train.channels,
            &train.scales,
            &config.baseline,
        )?;
        let obj = GroupObjective {
            model: ctx.model,
            set: &set,
            config,
        };
        let p0 = config
            .effects
            .last()
            .map(|(_, v)| v.clone())
            .unwrap_or_default();
        let res = fit(
            &obj,
            &p0,
            &FitOptions {
                max_iter: 15,
                ftol: 1e-8,
                xtol: 1e-8,
                lower: Some(specs.iter().map(|s| s.lower).collect()),
                upper: Some(specs.iter().map(|s| s.upper).collect()),
                diff_step: 1e-3,
                typical: Some(specs.iter().map(|s| s.typical).collect()),
                ..FitOptions::default()
            },
        )?;
        let mut r = vec![0.0; set.n];
        obj.residuals(&res.params, &mut r)
            .map_err(|_| DiscoveryError::NoStartPoint {
                effect: ctx.catalogue[e].name.clone(),
            })?;
        let n_eff = stats::effective_samples(&set.segment_slices(&r));
        let inflate = (set.n as f64 / n_eff.max(1.0)).sqrt();
        out.push(GroupFit {
            group,
            records: idx.len(),
            std_errors: res
                .std_errors
                .iter()
                .map(|s| Some(s * inflate).filter(|v| v.is_finite()))
                .collect(),
            at_bound: res
                .params
                .iter()
                .zip(specs)
                .any(|(v, s)| super::fitting::at_bound(*v, s)),
            values: res.params,
        });
    }
    Ok(out)
}

struct GroupObjective<'a, M: DiscoveryModel + ?Sized> {
    model: &'a M,
    set: &'a RecordSet<'a, M::Prepared>,
    config: &'a Config,
}

impl<M: DiscoveryModel + ?Sized> Problem for GroupObjective<'_, M> {
    fn n_params(&self) -> usize {
        self.config.effects.last().map_or(0, |(_, v)| v.len())
    }
    fn n_residuals(&self) -> usize {
        self.set.n
    }
    fn residuals(&self, p: &[f64], r: &mut [f64]) -> Result<(), String> {
        let mut c = self.config.clone();
        if let Some((_, v)) = c.effects.last_mut() {
            v.copy_from_slice(p);
        }
        self.set
            .residuals(self.model, &c.baseline, &c.active(), r)
            .map_err(|e| e.to_string())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn g(v: f64, s: Option<f64>) -> GroupFit {
        GroupFit {
            group: "g".into(),
            records: 1,
            values: vec![v],
            std_errors: vec![s],
            at_bound: false,
        }
    }

    #[test]
    fn groups_agree_within_errors_or_the_relative_tolerance() {
        // 1.0 +- 0.1 and 1.5 +- 0.1: 3.5 sigma apart, 33 % apart: disagree.
        assert!(!agree(&g(1.0, Some(0.1)), &g(1.5, Some(0.1)), 3.0, 0.3));
        // Within 3 sigma.
        assert!(agree(&g(1.0, Some(0.2)), &g(1.5, Some(0.1)), 3.0, 0.3));
        // Tiny errors, 10 % apart: the relative tolerance.
        assert!(agree(&g(1.0, Some(1e-6)), &g(1.1, Some(1e-6)), 3.0, 0.3));
    }

    #[test]
    fn outcomes_have_distinct_documented_exit_codes() {
        let named = Outcome::Named {
            effects: vec!["a".into()],
            remainder: None,
        };
        let disc = Outcome::ModelFormDiscrepancy {
            excess_over_noise: 8.6,
            closest: Some("a".into()),
            explains: 0.9,
            failed: vec!["bounds: x on a bound of its range".into()],
        };
        let none = Outcome::NothingMissing {
            excess_over_noise: 1.1,
        };
        assert_eq!(
            [named.exit_code(), disc.exit_code(), none.exit_code()],
            [0, 3, 4]
        );
        assert!(disc.describe().starts_with("model-form discrepancy: the calibrated baseline leaves 8.6x the noise; closest candidate a explains 90 % but fails: bounds"));
        assert!(none.describe().starts_with("nothing missing"));
        let json = serde_json::to_value(&disc).unwrap();
        assert_eq!(json["kind"], "model-form-discrepancy");
    }
}
