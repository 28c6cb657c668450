//! Measurement-like records from a truth model with hidden effects plus sensor noise
//! (`afsv synth`), for testing the discovery workflow on data whose answer is known.
//!
//! Effects are given as `NAME` (realistic default size) or `NAME=v1:v2` (parameter values in
//! catalogue order). Records are written as CSV + JSON sidecar (docs/records.md) into
//! `DIR/train/` and `DIR/holdout/`; the truth (effects and values) goes to `DIR/truth.json`,
//! never into the records' sidecars.

use crate::hps::HpsStrutModel;
use crate::yaw::{apply_play, YawPlaneModel};
use crate::{ActiveEffect, DiscoveryError, DiscoveryModel, EffectSpec};
use afsv_records::Record;
use hps_emulsion::{simulate_displacement, Excitation, HarmonicTest};
use rand_chacha::rand_core::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::path::Path;

/// An effect hidden in the truth model: catalogue index and parameter values.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct HiddenEffect {
    /// Catalogue index.
    pub index: usize,
    /// Effect name.
    pub name: String,
    /// Parameter values in catalogue order.
    pub values: Vec<f64>,
}

/// A named record with its role.
pub struct SynthRecord {
    /// File stem.
    pub name: String,
    /// Whether it belongs to the held-out set.
    pub holdout: bool,
    /// The record.
    pub record: Record,
}

/// Parse `NAME[=v1:v2...],...` against a catalogue; `default_size(name)` supplies the
/// realistic size when no values are given.
pub fn parse_effects(
    spec: &str,
    catalogue: &[EffectSpec],
    default_size: impl Fn(&str) -> Vec<f64>,
) -> Result<Vec<HiddenEffect>, DiscoveryError> {
    let mut out: Vec<HiddenEffect> = Vec::new();
    for item in spec.split(',').map(str::trim).filter(|s| !s.is_empty()) {
        if item == "none" {
            continue;
        }
        let (name, vals) = match item.split_once('=') {
            Some((n, v)) => (n.trim(), Some(v)),
            None => (item, None),
        };
        let index = catalogue
            .iter()
            .position(|e| e.name == name)
            .ok_or_else(|| DiscoveryError::UnknownHiddenEffect {
                effect: name.to_string(),
                known: catalogue
                    .iter()
                    .map(|e| e.name.as_str())
                    .collect::<Vec<_>>()
                    .join(", "),
            })?;
        if out.iter().any(|e| e.index == index) {
            return Err(DiscoveryError::EffectTwice {
                effect: name.to_string(),
            });
        }
        let spec = &catalogue[index];
        let values = match vals {
            None => default_size(name),
            Some(v) => v
                .split(':')
                .map(|x| {
                    x.trim()
                        .parse::<f64>()
                        .map_err(|_| DiscoveryError::NotANumber {
                            effect: name.to_string(),
                            text: x.to_string(),
                        })
                })
                .collect::<Result<Vec<f64>, DiscoveryError>>()?,
        };
        if values.len() != spec.params.len() {
            return Err(DiscoveryError::WrongValueCount {
                effect: name.to_string(),
                expected: spec.params.len(),
                names: spec
                    .params
                    .iter()
                    .map(|p| p.name.as_str())
                    .collect::<Vec<_>>()
                    .join(":"),
                got: values.len(),
            });
        }
        for (p, v) in spec.params.iter().zip(&values) {
            if !(v.is_finite() && *v >= p.lower && *v <= p.upper) {
                return Err(DiscoveryError::OutOfRange {
                    effect: name.to_string(),
                    param: p.name.clone(),
                    value: *v,
                    lower: p.lower,
                    upper: p.upper,
                });
            }
        }
        out.push(HiddenEffect {
            index,
            name: name.to_string(),
            values,
        });
    }
    Ok(out)
}

/// Standard normal deviates from a seeded generator (Box-Muller).
pub struct Gaussian {
    rng: ChaCha8Rng,
    spare: Option<f64>,
}

impl Gaussian {
    /// Generator with `seed`.
    pub fn new(seed: u64) -> Self {
        Self {
            rng: ChaCha8Rng::seed_from_u64(seed),
            spare: None,
        }
    }

    fn uniform(&mut self) -> f64 {
        ((self.rng.next_u64() >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    }

    /// Next N(0, 1) deviate.
    pub fn sample(&mut self) -> f64 {
        if let Some(s) = self.spare.take() {
            return s;
        }
        let (u1, u2) = (self.uniform(), self.uniform());
        let r = (-2.0 * u1.ln()).sqrt();
        let a = 2.0 * std::f64::consts::PI * u2;
        self.spare = Some(r * a.sin());
        r * a.cos()
    }

    /// Add N(0, sigma^2) white noise to every sample.
    pub fn add(&mut self, x: &mut [f64], sigma: f64) {
        for v in x {
            *v += sigma * self.sample();
        }
    }

    /// Add low-pass noise of standard deviation `sigma`: white noise through a first-order
    /// filter with corner `corner_hz` at sample rate `rate_hz` (the error of a signal that a
    /// conditioning amplifier or a differentiating filter produced).
    pub fn add_lowpass(&mut self, x: &mut [f64], sigma: f64, corner_hz: f64, rate_hz: f64) {
        let a = (-2.0 * std::f64::consts::PI * corner_hz / rate_hz).exp();
        // Stationary variance of e[k] = a e[k-1] + w[k] is 1/(1-a^2): scale w to get sigma.
        let gain = sigma * (1.0 - a * a).sqrt();
        let mut e = sigma * self.sample();
        for v in x {
            *v += e;
            e = a * e + gain * self.sample();
        }
    }
}

/// Sensor noise of strut bench records (standard deviations).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct HpsNoise {
    /// Displacement (m).
    pub displacement_m: f64,
    /// Velocity (m/s), band-limited to 10 Hz (velocity derived from a filtered LVDT signal).
    pub velocity_m_s: f64,
    /// Force (N).
    pub force_n: f64,
    /// Pressures (Pa).
    pub pressure_pa: f64,
}

impl HpsNoise {
    /// Typical bench instrumentation: LVDT 0.02 mm, derived velocity 0.5 mm/s (band-limited),
    /// load cell 150 N, pressure transducers 5 kPa.
    pub fn default_levels() -> Self {
        Self {
            displacement_m: 2e-5,
            velocity_m_s: 5e-4,
            force_n: 150.0,
            pressure_pa: 5e3,
        }
    }

    /// No noise.
    pub fn none() -> Self {
        Self {
            displacement_m: 0.0,
            velocity_m_s: 0.0,
            force_n: 0.0,
            pressure_pa: 0.0,
        }
    }
}

/// Realistic size of each strut effect when `afsv synth` is given only its name.
pub fn hps_default_size(name: &str) -> Vec<f64> {
    match name {
        "gas-heat-transfer" => vec![3.0],
        "gas-fraction-growth" => vec![0.15],
        "asymmetric-friction" => vec![0.6],
        "check-valve-lag" => vec![0.03],
        _ => Vec::new(),
    }
}

/// The bench programme `afsv synth` records for the strut: a subset of the chapter 5
/// programme (0.1 Hz at 25/50 mm, 1-8 Hz at constant peak velocity). Three records are held
/// out, chosen inside the range the training records span (amplitude and frequency), so that
/// the held-out error measures the model rather than an extrapolation.
pub fn hps_programme() -> Vec<(HarmonicTest, f64, bool)> {
    let t = HarmonicTest::at_peak_velocity;
    vec![
        (
            HarmonicTest {
                frequency_hz: 0.1,
                amplitude_m: 0.025,
            },
            2.0,
            true,
        ),
        (
            HarmonicTest {
                frequency_hz: 0.1,
                amplitude_m: 0.050,
            },
            2.0,
            false,
        ),
        (t(1.0, 0.15), 4.0, false),
        (t(2.0, 0.2), 4.0, false),
        (t(3.0, 0.1), 4.0, true),
        (t(4.0, 0.2356), 4.0, false),
        (t(5.0, 0.15), 4.0, true),
        (t(8.0, 0.2), 4.0, false),
    ]
}

/// The truth configuration: the model's nominal baseline values and the hidden effects.
fn truth_of<'a, M: DiscoveryModel>(
    model: &M,
    hidden: &'a [HiddenEffect],
) -> (Vec<f64>, Vec<ActiveEffect<'a>>) {
    let base = model.baseline_params().iter().map(|s| s.initial).collect();
    let active = hidden
        .iter()
        .map(|h| ActiveEffect {
            index: h.index,
            values: &h.values,
        })
        .collect();
    (base, active)
}

/// Strut bench records from the truth model `model` + `hidden`, sampled at `rate_hz`, with noise.
pub fn hps_records(
    model: &HpsStrutModel,
    hidden: &[HiddenEffect],
    noise: HpsNoise,
    seed: u64,
    rate_hz: f64,
) -> Result<Vec<SynthRecord>, DiscoveryError> {
    let (base, active) = truth_of(model, hidden);
    let params = model.apply_baseline(&base)?;
    let ext = model.apply_effects(&active)?;
    let mut gauss = Gaussian::new(seed);
    let mut out = Vec::new();
    for (k, (test, cycles, holdout)) in hps_programme().into_iter().enumerate() {
        let mut opts = model.sim;
        opts.output_rate_hz = rate_hz;
        let rec = simulate_displacement(
            &params,
            &ext,
            &Excitation::harmonic(test.frequency_hz, test.amplitude_m, cycles),
            &opts,
        )?;
        let mut z = rec.displacement.clone();
        let mut v = rec.velocity.clone();
        let mut f = rec.force.clone();
        let mut pc = rec.p_piston.clone();
        let mut pr = rec.p_rod.clone();
        gauss.add(&mut z, noise.displacement_m);
        gauss.add_lowpass(&mut v, noise.velocity_m_s, 10.0, rate_hz);
        gauss.add(&mut f, noise.force_n);
        gauss.add(&mut pc, noise.pressure_pa);
        gauss.add(&mut pr, noise.pressure_pa);
        let mut r = Record::new();
        let push = |r: &mut Record, n: &str, v: Vec<f64>| r.push_column(n, v);
        push(&mut r, "time_s", rec.time.clone())?;
        push(&mut r, "displacement_m", z)?;
        push(&mut r, "velocity_m_s", v)?;
        push(&mut r, "force_n", f)?;
        push(&mut r, "p_piston_pa", pc)?;
        push(&mut r, "p_rod_pa", pr)?;
        r.meta = serde_json::json!({
            "model": "hps-strut",
            "strut": model.strut,
            "excitation": "harmonic",
            "frequency_hz": test.frequency_hz,
            "amplitude_m": test.amplitude_m,
            "sample_rate_hz": rate_hz,
            "units": {"time_s": "s", "displacement_m": "m", "velocity_m_s": "m/s", "force_n": "N", "p_piston_pa": "Pa", "p_rod_pa": "Pa"},
        });
        let name = format!(
            "hps_{:02}_{}hz_{}mm",
            k,
            format!("{}", test.frequency_hz).replace('.', "p"),
            (test.amplitude_m * 1000.0).round()
        );
        out.push(SynthRecord {
            name,
            holdout,
            record: r,
        });
    }
    Ok(out)
}

/// Sensor noise of vehicle steering records (standard deviations, white).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct YawNoise {
    /// Steering-wheel angle (deg).
    pub steer_deg: f64,
    /// Forward speed (m/s).
    pub speed_m_s: f64,
    /// Articulation angle (deg).
    pub articulation_deg: f64,
    /// Strut displacement (m).
    pub strut_m: f64,
    /// Chamber pressures (Pa).
    pub pressure_pa: f64,
    /// Yaw rate (deg/s).
    pub yaw_rate_deg_s: f64,
}

impl YawNoise {
    /// Typical field instrumentation: steering encoder 0.02 deg (an optical encoder's
    /// quantisation, not an analog jitter), potentiometer 0.05 deg, string pot 0.1 mm,
    /// transducers 20 kPa, gyro 0.2 deg/s, speed 0.05 m/s.
    pub fn default_levels() -> Self {
        Self {
            steer_deg: 0.02,
            speed_m_s: 0.05,
            articulation_deg: 0.05,
            strut_m: 1e-4,
            pressure_pa: 2e4,
            yaw_rate_deg_s: 0.2,
        }
    }

    /// No noise.
    pub fn none() -> Self {
        Self {
            steer_deg: 0.0,
            speed_m_s: 0.0,
            articulation_deg: 0.0,
            strut_m: 0.0,
            pressure_pa: 0.0,
            yaw_rate_deg_s: 0.0,
        }
    }
}

/// Realistic size of each vehicle effect when `afsv synth` is given only its name.
pub fn yaw_default_size(name: &str) -> Vec<f64> {
    match name {
        "sensor-backlash" => vec![0.5],
        "supply-droop" => vec![1.5e9],
        "strut-coulomb-friction" => vec![4000.0],
        "entrained-air" => vec![0.03],
        "valve-lag" => vec![0.04],
        _ => Vec::new(),
    }
}

/// The manoeuvres `afsv synth` records for the vehicle (section 3.3 inputs and the Fig 3.6
/// field courses), with the load and the hold-out role of each. Both loads appear in
/// training and in the held-out records, as in field data (Table 3.2).
pub fn yaw_programme() -> Vec<(afsv_dynamics::Manoeuvre, afsv_dynamics::Load, bool)> {
    use afsv_dynamics::{
        table_3_2_speeds_kmh, yaw_plane::driver::Course, FieldCourse, Load, Manoeuvre, PathDriver,
        SteerInput,
    };
    let kmh = |v: f64| v / 3.6;
    let steady = table_3_2_speeds_kmh(FieldCourse::SteadyTurn, Load::Loaded)[0];
    let change = table_3_2_speeds_kmh(FieldCourse::PathChange, Load::Loaded)[0];
    vec![
        (Manoeuvre::pulse(kmh(50.0), 30.0), Load::Loaded, false),
        // A driver's "step" takes about 0.1 s: an ideal step would make the recorded
        // (sampled) input differ from the truth's between two samples.
        (
            Manoeuvre::open_loop(kmh(50.0), 10.0, fast_step(30.0), "step"),
            Load::Loaded,
            false,
        ),
        (
            Manoeuvre::open_loop(
                kmh(30.0),
                8.0,
                SteerInput::pulse_deg(-20.0, 0.2, 0.5),
                "pulse",
            ),
            Load::Unloaded,
            true,
        ),
        // The field path change (held out below) is large, slow steering at high pressure
        // and flow; without a record of that kind in training, seal friction's Coulomb and
        // viscous parts cannot be told apart and the held-out path change extrapolates.
        (
            Manoeuvre::course(
                kmh(0.8 * change),
                14.0,
                PathDriver::new(Course::path_change_fig_3_6()),
                "path-change",
            ),
            Load::Loaded,
            false,
        ),
        (
            Manoeuvre::open_loop(
                kmh(30.0),
                8.0,
                SteerInput::Ramp {
                    rate_rad_s: 20f64.to_radians(),
                    start_s: 0.5,
                    limit_rad: 40f64.to_radians(),
                },
                "ramp",
            ),
            Load::Loaded,
            true,
        ),
        (
            Manoeuvre::course(
                kmh(steady),
                20.0,
                PathDriver::new(Course::steady_turn_fig_3_6()),
                "steady-turn",
            ),
            Load::Loaded,
            false,
        ),
        (
            Manoeuvre::course(
                kmh(change),
                12.0,
                PathDriver::new(Course::path_change_fig_3_6()),
                "path-change",
            ),
            Load::Loaded,
            true,
        ),
        (
            Manoeuvre::open_loop(
                kmh(40.0),
                8.0,
                SteerInput::pulse_deg(40.0, 0.2, 0.5),
                "pulse",
            ),
            Load::Unloaded,
            false,
        ),
    ]
}

/// A steering step of `amplitude_deg` applied at 300 deg/s from t = 0.5 s.
fn fast_step(amplitude_deg: f64) -> afsv_dynamics::SteerInput {
    afsv_dynamics::SteerInput::Ramp {
        rate_rad_s: 300f64.to_radians() * amplitude_deg.signum(),
        start_s: 0.5,
        limit_rad: amplitude_deg.abs().to_radians(),
    }
}

/// Vehicle steering records from the truth model `model` + `hidden`, with noise.
pub fn yaw_records(
    model: &YawPlaneModel,
    hidden: &[HiddenEffect],
    noise: YawNoise,
    seed: u64,
) -> Result<Vec<SynthRecord>, DiscoveryError> {
    let (base, active) = truth_of(model, hidden);
    let (ext, play) = model.apply_effects(&active)?;
    let mut gauss = Gaussian::new(seed);
    let mut out = Vec::new();
    for (k, (man, load, holdout)) in yaw_programme().into_iter().enumerate() {
        let vehicle = match load {
            afsv_dynamics::Load::Loaded => &model.loaded,
            afsv_dynamics::Load::Unloaded => &model.unloaded,
        };
        let params = model.apply_baseline(vehicle, &base)?;
        let sys = afs_hydraulics::AfsSystem::new(params.afs.clone())
            .and_then(|s| s.with_extensions(ext))?;
        let rec = afsv_dynamics::simulate(&params.vehicle, &sys, &man, &model.sim)?;
        let mut art = rec.articulation_deg.clone();
        apply_play(&mut art, play);
        let mut cols = [
            (
                "steer_wheel_deg",
                rec.steer_wheel_deg.clone(),
                noise.steer_deg,
            ),
            ("speed_m_s", rec.speed_m_s.clone(), noise.speed_m_s),
            ("articulation_deg", art, noise.articulation_deg),
            (
                "strut_left_disp_m",
                rec.strut_left_disp_m.clone(),
                noise.strut_m,
            ),
            ("p_c_pa", rec.p_c_pa.clone(), noise.pressure_pa),
            ("p_r_pa", rec.p_r_pa.clone(), noise.pressure_pa),
            (
                "yaw_rate_front_deg_s",
                rec.yaw_rate_front_deg_s.clone(),
                noise.yaw_rate_deg_s,
            ),
        ];
        let mut r = Record::new();
        r.push_column("time_s", rec.time_s.clone())?;
        for (name, values, sigma) in cols.iter_mut() {
            gauss.add(values, *sigma);
            r.push_column(name, std::mem::take(values))?;
        }
        r.meta = serde_json::json!({
            "model": "yaw-plane",
            "manoeuvre": man.label,
            "speed_m_s": man.speed_m_s,
            "load": load.name(),
            "sample_rate_hz": 1.0 / model.sim.output_dt_s,
        });
        out.push(SynthRecord {
            name: format!("yaw_{k:02}_{}", man.label),
            holdout,
            record: r,
        });
    }
    Ok(out)
}

/// Write records into `dir/train` and `dir/holdout`, and the truth into `dir/truth.json`.
pub fn write_records(
    dir: &Path,
    records: &[SynthRecord],
    truth: &serde_json::Value,
) -> Result<(), DiscoveryError> {
    for sub in ["train", "holdout"] {
        let folder = dir.join(sub);
        std::fs::create_dir_all(&folder).map_err(|e| DiscoveryError::io(folder, e))?;
    }
    for r in records {
        let sub = if r.holdout { "holdout" } else { "train" };
        let path = dir.join(sub).join(format!("{}.csv", r.name));
        r.record.write(&path)?;
    }
    let text = serde_json::to_string_pretty(truth)?;
    let path = dir.join("truth.json");
    afsv_records::atomic::write(&path, text + "\n").map_err(|e| DiscoveryError::io(path, e))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_effect_lists() {
        let m = HpsStrutModel::nominal();
        let cat = m.catalogue();
        let e = parse_effects(
            "gas-heat-transfer, asymmetric-friction=0.3",
            &cat,
            hps_default_size,
        )
        .unwrap();
        assert_eq!(e.len(), 2);
        assert_eq!(e[0].values, vec![3.0]);
        assert_eq!(e[1].values, vec![0.3]);
        assert!(parse_effects("nope", &cat, hps_default_size).is_err());
        assert!(parse_effects("gas-heat-transfer=1:2", &cat, hps_default_size).is_err());
        assert!(parse_effects("gas-heat-transfer=x", &cat, hps_default_size).is_err());
        assert!(parse_effects("gas-heat-transfer=-1", &cat, hps_default_size).is_err());
        assert!(parse_effects("none", &cat, hps_default_size)
            .unwrap()
            .is_empty());
    }

    #[test]
    fn gaussian_is_standard_and_deterministic() {
        let mut g = Gaussian::new(5);
        let x: Vec<f64> = (0..20000).map(|_| g.sample()).collect();
        let m = x.iter().sum::<f64>() / x.len() as f64;
        let v = x.iter().map(|a| (a - m) * (a - m)).sum::<f64>() / x.len() as f64;
        assert!(m.abs() < 0.03 && (v - 1.0).abs() < 0.03, "{m} {v}");
        assert_eq!(Gaussian::new(5).sample(), x[0]);
    }
}
