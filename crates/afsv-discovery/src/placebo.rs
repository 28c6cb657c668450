//! Placebo candidates: generic corrections of the predicted channels with no physical
//! meaning, fitted exactly as a catalogue effect is (same start points, scouting, baseline
//! refit, held-out score). A named effect must beat the best placebo with the same number of
//! parameters by a clear held-out margin ([`crate::form`]); a catalogue effect that only
//! absorbs a model-form difference does about as well as a placebo does.
//!
//! [`WithPlacebos`] wraps a [`DiscoveryModel`]: its catalogue is the model's followed by the
//! placebos, and its simulation runs the model with the catalogue effects, then applies the
//! placebo transforms to every predicted channel. Two families, each with `k` = 1 or 2
//! parameters (the catalogue's effects have one or two):
//!
//! - `placebo-output-lag`: a first-order low-pass filter on every predicted channel,
//!   `y_f' = (y - y_f) / tau` (discretised exactly per sample with the record's time step),
//!   `tau` in [0, 0.2] s; with `k = 2` also a gain `(1 + g)` on the filtered channel's
//!   deviation from its record mean, `g` in [-0.5, 0.5].
//! - `placebo-output-polynomial`: each predicted channel `y` plus `c2 (y - m)^2 / s` (and,
//!   with `k = 2`, `c3 (y - m)^3 / s^2`), with `m` and `s` the mean and standard deviation
//!   of that prediction over the record; the coefficients are dimensionless, in [-1, 1].

use super::{ActiveEffect, DiscoveryError, DiscoveryModel, EffectSpec, ParamSpec, Phase};
use afsv_records::Record;

/// Names of the placebo families.
pub const PLACEBOS: [&str; 2] = ["placebo-output-lag", "placebo-output-polynomial"];

/// A model whose catalogue ends with the placebo candidates (see the module docs).
pub struct WithPlacebos<'a, M: DiscoveryModel + ?Sized> {
    /// The model.
    pub inner: &'a M,
    /// Its catalogue length: catalogue indices from here on are placebos.
    pub real: usize,
}

/// A record prepared by the inner model, with its time step for the placebo filters.
pub struct PlaceboPrepared<P> {
    /// The inner model's preparation.
    pub inner: P,
    /// Sample times of the record (s; sample index when the record has no time).
    pub time_s: Vec<f64>,
}

impl<'a, M: DiscoveryModel + ?Sized> WithPlacebos<'a, M> {
    /// Wrap `inner`.
    pub fn new(inner: &'a M) -> Self {
        Self {
            real: inner.catalogue().len(),
            inner,
        }
    }

    /// Catalogue index of placebo family `family` (index into [`PLACEBOS`]) with `k`
    /// parameters (1 or 2).
    pub fn placebo_index(&self, family: usize, k: usize) -> usize {
        self.real + 2 * family + (k.clamp(1, 2) - 1)
    }
}

fn placebo_specs() -> Vec<EffectSpec> {
    let lag = || ParamSpec {
        typical: 0.01,
        ..ParamSpec::new("tau_s", 0.01, 0.0, 0.2)
    };
    let gain = || ParamSpec {
        typical: 0.1,
        ..ParamSpec::new("gain", 0.0, -0.5, 0.5)
    };
    let coef = |name: &str| ParamSpec {
        typical: 0.1,
        ..ParamSpec::new(name, 0.0, -1.0, 1.0)
    };
    let spec = |name: &str, params: Vec<ParamSpec>| {
        EffectSpec {
        name: name.to_string(),
        description: "placebo: a generic correction of every predicted channel with no physical meaning (docs/discovery.md, \"Naming tests\")".into(),
        citation: "-".into(),
        params,
    }
    };
    vec![
        spec(PLACEBOS[0], vec![lag()]),
        spec(PLACEBOS[0], vec![lag(), gain()]),
        spec(PLACEBOS[1], vec![coef("c2")]),
        spec(PLACEBOS[1], vec![coef("c2"), coef("c3")]),
    ]
}

/// Apply placebo `which` (index into [`placebo_specs`]) with `values` to one predicted
/// channel `y` sampled at `t`.
fn apply(which: usize, values: &[f64], t: &[f64], y: &mut [f64]) {
    if y.is_empty() {
        return;
    }
    let mean_sd = |y: &[f64]| {
        let m = y.iter().sum::<f64>() / y.len() as f64;
        let v = y.iter().map(|x| (x - m) * (x - m)).sum::<f64>() / y.len() as f64;
        (m, v.sqrt().max(f64::MIN_POSITIVE))
    };
    match which {
        0 | 1 => {
            let tau = values[0].max(0.0);
            if tau > 0.0 {
                let mut f = y[0];
                for i in 1..y.len() {
                    let dt = (t[i] - t[i - 1]).max(0.0);
                    f += (1.0 - (-dt / tau).exp()) * (y[i] - f);
                    y[i] = f;
                }
            }
            if which == 1 {
                let (m, _) = mean_sd(y);
                y.iter_mut()
                    .for_each(|v| *v = m + (1.0 + values[1]) * (*v - m));
            }
        }
        _ => {
            let (m, s) = mean_sd(y);
            let c3 = if which == 3 { values[1] } else { 0.0 };
            y.iter_mut().for_each(|v| {
                let d = *v - m;
                *v += values[0] * d * d / s + c3 * d * d * d / (s * s);
            });
        }
    }
}

impl<M: DiscoveryModel + ?Sized> DiscoveryModel for WithPlacebos<'_, M> {
    type Prepared = PlaceboPrepared<M::Prepared>;

    fn name(&self) -> &str {
        self.inner.name()
    }
    fn channels(&self) -> Vec<String> {
        self.inner.channels()
    }
    fn baseline_params(&self) -> Vec<ParamSpec> {
        self.inner.baseline_params()
    }
    fn catalogue(&self) -> Vec<EffectSpec> {
        let mut c = self.inner.catalogue();
        c.extend(placebo_specs());
        c
    }
    fn prepare(&self, record: &Record) -> Result<Self::Prepared, DiscoveryError> {
        let time_s = record
            .column("time_s")
            .map(<[f64]>::to_vec)
            .unwrap_or_else(|| (0..record.len()).map(|i| i as f64).collect());
        Ok(PlaceboPrepared {
            inner: self.inner.prepare(record)?,
            time_s,
        })
    }
    fn condition(&self, prepared: &Self::Prepared) -> String {
        self.inner.condition(&prepared.inner)
    }
    fn group(&self, prepared: &Self::Prepared) -> Option<String> {
        self.inner.group(&prepared.inner)
    }
    fn scaling_group(&self, prepared: &Self::Prepared) -> Option<String> {
        self.inner.scaling_group(&prepared.inner)
    }
    fn simulate(
        &self,
        prepared: &Self::Prepared,
        baseline: &[f64],
        effects: &[ActiveEffect<'_>],
    ) -> Result<Vec<Option<Vec<f64>>>, DiscoveryError> {
        let (real, placebo): (Vec<ActiveEffect<'_>>, Vec<ActiveEffect<'_>>) =
            effects.iter().partition(|e| e.index < self.real);
        let mut out = self.inner.simulate(&prepared.inner, baseline, &real)?;
        for p in &placebo {
            let which = p.index - self.real;
            if which >= 4 {
                return Err(DiscoveryError::NoSuchEffect {
                    index: p.index,
                    model: "placebo",
                });
            }
            for y in out.iter_mut().flatten() {
                let n = y.len().min(prepared.time_s.len());
                apply(which, p.values, &prepared.time_s[..n], &mut y[..n]);
            }
        }
        Ok(out)
    }
    fn phases(&self, record: &Record) -> Vec<Phase> {
        self.inner.phases(record)
    }
    fn skip_samples(&self, record: &Record) -> usize {
        self.inner.skip_samples(record)
    }
    fn broadband_channels(&self) -> bool {
        self.inner.broadband_channels()
    }
    fn coarse(&self, prepared: &Self::Prepared) -> Option<Self::Prepared> {
        Some(PlaceboPrepared {
            inner: self.inner.coarse(&prepared.inner)?,
            time_s: prepared.time_s.clone(),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lag_placebo_filters_a_step_and_is_off_at_zero() {
        let t: Vec<f64> = (0..101).map(|i| i as f64 * 0.01).collect();
        let step: Vec<f64> = (0..101).map(|i| if i >= 1 { 1.0 } else { 0.0 }).collect();
        let mut y = step.clone();
        apply(0, &[0.0], &t, &mut y);
        assert_eq!(y, step);
        apply(0, &[0.1], &t, &mut y);
        // After one time constant (10 samples) the filter has risen to 1 - 1/e.
        assert!((y[10] - (1.0 - (-1.0f64).exp())).abs() < 1e-12, "{}", y[10]);
    }

    #[test]
    fn polynomial_placebo_bends_about_the_mean_and_is_off_at_zero() {
        let t: Vec<f64> = (0..4).map(f64::from).collect();
        let y0 = vec![-1.0, 1.0, -1.0, 1.0];
        let mut y = y0.clone();
        apply(2, &[0.0], &t, &mut y);
        assert_eq!(y, y0);
        apply(2, &[0.5], &t, &mut y);
        // mean 0, sd 1: every sample moves up by 0.5.
        assert_eq!(y, vec![-0.5, 1.5, -0.5, 1.5]);
        let mut y = y0.clone();
        apply(3, &[0.0, 0.5], &t, &mut y);
        assert_eq!(y, vec![-1.5, 1.5, -1.5, 1.5]);
    }

    #[test]
    fn families_have_one_and_two_parameters() {
        let specs = placebo_specs();
        for (i, s) in specs.iter().enumerate() {
            assert_eq!(s.params.len(), 1 + i % 2, "{}", s.name);
            assert_eq!(s.name, PLACEBOS[i / 2]);
        }
    }
}
