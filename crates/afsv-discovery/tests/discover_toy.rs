//! The discovery engine on a toy first-order system with a catalogue of three effects:
//! it must name a hidden effect, name nothing when none is hidden, and find two at once.

use afsv_discovery::{
    discover, ActiveEffect, DiscoveryError, DiscoveryModel, DiscoveryOptions, EffectSpec,
    ParamSpec, Phase,
};
use afsv_records::Record;

/// tau y' + y = K * g(u), with optional dead zone in g, output saturation, and Coulomb-like
/// offset (sign(u) * c added to the output).
struct Toy;

#[derive(Clone, Copy, Default)]
struct Truth {
    k: f64,
    tau: f64,
    dead: f64,
    sat: f64,
    coul: f64,
}

fn simulate(t: &[f64], u: &[f64], p: Truth) -> Vec<f64> {
    let mut y = 0.0;
    let mut out = Vec::with_capacity(t.len());
    for i in 0..t.len() {
        out.push(y);
        if i + 1 < t.len() {
            let dt = t[i + 1] - t[i];
            let ui = u[i];
            let g = if p.dead > 0.0 {
                if ui.abs() <= p.dead {
                    0.0
                } else {
                    ui - p.dead * ui.signum()
                }
            } else {
                ui
            };
            let sub = 10;
            let h = dt / sub as f64;
            for _ in 0..sub {
                y += h * (p.k * g - y) / p.tau;
            }
            if p.sat > 0.0 {
                y = y.clamp(-p.sat, p.sat);
            }
        }
    }
    if p.coul != 0.0 {
        for (o, ui) in out.iter_mut().zip(u) {
            *o += p.coul * ui.signum();
        }
    }
    out
}

impl DiscoveryModel for Toy {
    type Prepared = Record;
    fn prepare(&self, rec: &Record) -> Result<Record, DiscoveryError> {
        Ok(rec.clone())
    }
    fn condition(&self, _: &Record) -> String {
        "toy".into()
    }
    fn name(&self) -> &str {
        "toy"
    }
    fn channels(&self) -> Vec<String> {
        vec!["y_x".into()]
    }
    fn baseline_params(&self) -> Vec<ParamSpec> {
        vec![
            ParamSpec::new("gain", 1.0, 0.1, 10.0),
            ParamSpec::new("tau_s", 0.3, 0.01, 5.0),
        ]
    }
    fn catalogue(&self) -> Vec<EffectSpec> {
        let e = |name: &str, p: ParamSpec| EffectSpec {
            name: name.into(),
            description: format!("toy {name}"),
            citation: "test".into(),
            params: vec![p],
        };
        vec![
            e("dead-zone", ParamSpec::new("width", 0.05, 0.0, 1.0)),
            e("saturation", ParamSpec::new("limit", 3.0, 0.1, 10.0)),
            e("offset", ParamSpec::new("level", 0.01, -1.0, 1.0)),
        ]
    }
    fn simulate(
        &self,
        rec: &Record,
        baseline: &[f64],
        effects: &[ActiveEffect<'_>],
    ) -> Result<Vec<Option<Vec<f64>>>, DiscoveryError> {
        let missing = |column| DiscoveryError::MissingColumn { column };
        let t = rec.column("time_s").ok_or(missing("time_s"))?;
        let u = rec.column("u_x").ok_or(missing("u_x"))?;
        let mut p = Truth {
            k: baseline[0],
            tau: baseline[1],
            ..Truth::default()
        };
        for e in effects {
            match e.index {
                0 => p.dead = e.values[0],
                1 => p.sat = e.values[0],
                _ => p.coul = e.values[0],
            }
        }
        Ok(vec![Some(simulate(t, u, p))])
    }
    fn phases(&self, rec: &Record) -> Vec<Phase> {
        let u = rec.column("u_x").unwrap_or(&[]);
        vec![
            Phase {
                name: "positive input".into(),
                mask: u.iter().map(|v| *v > 0.0).collect(),
            },
            Phase {
                name: "negative input".into(),
                mask: u.iter().map(|v| *v <= 0.0).collect(),
            },
        ]
    }
}

fn records(truth: Truth, seeds: &[u64]) -> Vec<Record> {
    seeds
        .iter()
        .map(|&seed| {
            let n = 2000;
            let t: Vec<f64> = (0..n).map(|i| i as f64 * 0.005).collect();
            let f = 0.2 + 0.2 * seed as f64;
            let u: Vec<f64> = t
                .iter()
                .map(|t| 1.5 * (2.0 * std::f64::consts::PI * f * t).sin())
                .collect();
            let mut y = simulate(&t, &u, truth);
            let mut s = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1;
            for v in y.iter_mut() {
                s ^= s << 13;
                s ^= s >> 7;
                s ^= s << 17;
                *v += 0.01 * ((s >> 11) as f64 / (1u64 << 53) as f64 - 0.5);
            }
            let mut r = Record::new();
            r.push_column("time_s", t).unwrap();
            r.push_column("u_x", u).unwrap();
            r.push_column("y_x", y).unwrap();
            r
        })
        .collect()
}

fn run(truth: Truth) -> afsv_discovery::Discovery {
    let train = records(truth, &[1, 3, 5]);
    let hold = records(truth, &[2, 4]);
    discover(
        &Toy,
        &train,
        &hold,
        &[],
        &[],
        &DiscoveryOptions::default(),
        &(),
    )
    .unwrap()
}

const BASE: Truth = Truth {
    k: 1.3,
    tau: 0.25,
    dead: 0.0,
    sat: 0.0,
    coul: 0.0,
};

#[test]
fn names_a_hidden_dead_zone_and_shrinks_the_gap() {
    let d = run(Truth { dead: 0.3, ..BASE });
    assert_eq!(d.named, vec!["dead-zone".to_string()], "{:#?}", d.steps);
    assert!(d.gap_shrink > 0.7, "shrink {}", d.gap_shrink);
    let w = d.final_model.effect_params[0][0].value;
    assert!((w - 0.3).abs() < 0.02, "width {w}");
}

#[test]
fn names_nothing_when_nothing_is_hidden_but_calibrates() {
    let d = run(BASE);
    assert!(d.named.is_empty(), "{:#?}", d.steps);
    assert!((d.calibrated.baseline[0] - 1.3).abs() < 0.01);
    assert!((d.calibrated.baseline[1] - 0.25).abs() < 0.01);
}

#[test]
fn names_two_hidden_effects() {
    let d = run(Truth {
        dead: 0.3,
        sat: 1.0,
        ..BASE
    });
    let mut named = d.named.clone();
    named.sort();
    assert_eq!(
        named,
        vec!["dead-zone".to_string(), "saturation".to_string()],
        "{:#?}",
        d.steps
    );
}
