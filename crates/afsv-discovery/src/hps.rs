//! The hydro-pneumatic strut as a [`DiscoveryModel`]: prescribed displacement in, force and
//! chamber pressures out (bench records of docs/records.md).
//!
//! Baseline: the paper's full model, the one `afsv hps harmonic` runs: the front-axle strut of
//! Table 6.3 with its gas-oil emulsion (gamma_0 = 2 %), or the user's parameter file.
//! Calibrated first: polytropic exponent `n`, static pressure `P_h0`, gas volume `V_g0`,
//! Coulomb friction `F_c`, viscous friction `mu_v`, the friction band's ratio to the peak
//! velocity, bleed-orifice discharge coefficient `C_b`, the chamber split of the oil
//! (rod-side volume `V_r0`, which sets the rod-side dead volume) and the emulsion's gas
//! fraction `gamma_0`; and two calibration switches ([`SWITCHES`]): the density of the
//! orifice laws and the orifice law near zero pressure drop (Eq 5.12). Catalogue (each a switchable extension of
//! `hps-emulsion`, none of them in the paper's model): gas heat transfer, growth of the gas
//! fraction with strut velocity, asymmetric seal friction, check-valve opening lag.

use super::{
    ActiveEffect, DiscoveryError, DiscoveryModel, EffectSpec, LawSwitch, ParamSpec, Phase,
};
use afsv_records::Record;
use hps_emulsion::{
    simulate_strut_from, AsymmetricFriction, Excitation, GasFractionGrowth, HeatTransfer,
    HpsExtensions, HpsStrut, OrificeDensity, OrificeTransition, SimOptions, StrutLaws, StrutParams,
    ValveLag,
};
use vehicle_components::ParamSet;

/// Channels the strut model predicts (bench-record names of docs/records.md).
pub const CHANNELS: [&str; 3] = ["force_n", "p_piston_pa", "p_rod_pa"];

/// Catalogue names, in catalogue order.
pub const EFFECTS: [&str; 4] = [
    "gas-heat-transfer",
    "gas-fraction-growth",
    "asymmetric-friction",
    "check-valve-lag",
];

/// The strut model for the discovery workflow.
#[derive(Debug, Clone)]
pub struct HpsStrutModel {
    /// Baseline parameters (calibrated parameters start from these values).
    pub params: StrutParams,
    /// Name of the strut the parameters describe (`front-axle`, a file name): a record whose
    /// sidecar names another strut is refused.
    pub strut: Option<String>,
    /// Integrator settings.
    pub sim: SimOptions,
}

/// A bench record prepared for replay: its prescribed motion.
#[derive(Debug, Clone)]
pub struct StrutReplay {
    /// The recorded displacement with a velocity consistent with it ([`velocity_of`]).
    pub excitation: Excitation,
    /// Peak strut velocity of the motion (m/s): sets the friction band and the
    /// velocity-dependent gas fraction (section 5.3.1), worked out once per record.
    pub peak_velocity_m_s: f64,
    /// Conditions in words.
    pub condition: String,
    /// Condition group of the constancy test: `quasi-static` below 0.5 Hz, else `dynamic`.
    pub group: String,
}

impl HpsStrutModel {
    /// Model around `params`, describing the strut `strut` (if known).
    pub fn new(params: StrutParams, strut: Option<&str>) -> Self {
        Self {
            params,
            strut: strut.map(str::to_string),
            sim: SimOptions::default(),
        }
    }

    /// The default discovery baseline: the front-axle strut of Table 6.3 as published,
    /// with its gas-oil emulsion.
    pub fn nominal() -> Self {
        Self::new(StrutParams::front_axle(), Some("front-axle"))
    }

    /// Parameters with the baseline vector applied: value `i` to the registry parameter
    /// [`CALIBRATED`]`[i]`; the last two with their own rules, the rod-side volume `v_r0`
    /// with [`StrutParams::with_rod_volume`] (the oil it takes comes from the piston side:
    /// the total stays Table 6.3's) and the gas fraction last with
    /// [`StrutParams::with_gamma0`].
    pub fn apply_baseline(&self, v: &[f64]) -> Result<StrutParams, DiscoveryError> {
        if v.len() != CALIBRATED.len() {
            return Err(DiscoveryError::BaselineLength {
                expected: CALIBRATED.len(),
                got: v.len(),
            });
        }
        let (fields, split) = v.split_at(CALIBRATED.len() - 2);
        let mut p = self.params;
        for (name, &x) in CALIBRATED.iter().zip(fields) {
            let (i, _) = p.find(name)?;
            p.assign(i, x);
        }
        p.validate()?;
        Ok(p.with_rod_volume(split[0])?.with_gamma0(split[1])?)
    }

    /// The strut's readings for the switch positions `readings` (an index per entry of
    /// [`SWITCHES`], missing entries at the default 0).
    pub fn laws(readings: &[usize]) -> Result<StrutLaws, DiscoveryError> {
        let at = |k: usize| readings.get(k).copied().unwrap_or(0);
        let bad = |k: usize| DiscoveryError::NoSuchReading {
            switch: SWITCHES[k].0,
            index: at(k),
        };
        Ok(StrutLaws {
            orifice_density: match at(0) {
                0 => OrificeDensity::Mean,
                1 => OrificeDensity::Upstream,
                _ => return Err(bad(0)),
            },
            orifice_transition: match at(1) {
                0 => OrificeTransition::Turbulent,
                1 => OrificeTransition::Laminar,
                _ => return Err(bad(1)),
            },
        })
    }

    /// Extensions for the active effects.
    pub fn apply_effects(
        &self,
        effects: &[ActiveEffect<'_>],
    ) -> Result<HpsExtensions, DiscoveryError> {
        let mut ext = HpsExtensions::none();
        for e in effects {
            let v = e.values;
            match e.index {
                0 => {
                    ext.heat_transfer = Some(HeatTransfer {
                        tau: v[0],
                        kappa: 1.4,
                    })
                }
                1 => ext.gas_fraction_growth = Some(GasFractionGrowth { k_gamma: v[0] }),
                2 => {
                    ext.asymmetric_friction = Some(AsymmetricFriction {
                        compression: 1.0 + v[0],
                        extension: 1.0 - v[0],
                    })
                }
                3 => ext.valve_lag = Some(ValveLag { tau: v[0] }),
                index => {
                    return Err(DiscoveryError::NoSuchEffect {
                        index,
                        model: "strut",
                    })
                }
            }
        }
        Ok(ext)
    }
}

/// Strut velocity for replaying a record, consistent with its displacement.
///
/// The displacement is differentiated by a local cubic least-squares fit (Savitzky-Golay)
/// over about +-10 ms. When the record also has a measured `velocity_m_s`, that signal is
/// kept for its low noise but its slow part is replaced by the displacement's (a
/// complementary filter with a 0.25 s moving average): an offset or drift in a measured
/// velocity would otherwise integrate into a gas-volume error that grows over the record
/// (0.5 mm/s over 20 s shifts the static pressure by tens of kPa).
pub fn velocity_of(rec: &Record) -> Option<Vec<f64>> {
    let t = rec.column("time_s")?;
    let z = rec.column("displacement_m")?;
    let n = t.len();
    if n < 9 {
        return None;
    }
    let dt = (t[n - 1] - t[0]) / (n - 1) as f64;
    if dt.is_nan() || dt <= 0.0 {
        return None;
    }
    let m = ((0.010 / dt).round() as usize).clamp(3, (n - 1) / 2);
    let w = cubic_derivative_weights(m);
    let from_z: Vec<f64> = (0..n)
        .map(|i| {
            if i >= m && i + m < n {
                w.iter()
                    .enumerate()
                    .map(|(j, wj)| wj * z[i + j - m])
                    .sum::<f64>()
                    / dt
            } else {
                // Near the ends: slope of a local line through the available points.
                let a = i.saturating_sub(m);
                let b = (i + m).min(n - 1);
                let k = (b - a + 1) as f64;
                let tm = t[a..=b].iter().sum::<f64>() / k;
                let zm = z[a..=b].iter().sum::<f64>() / k;
                let (mut num, mut den) = (0.0, 0.0);
                for j in a..=b {
                    num += (t[j] - tm) * (z[j] - zm);
                    den += (t[j] - tm) * (t[j] - tm);
                }
                num / den
            }
        })
        .collect();
    let Some(measured) = rec.column("velocity_m_s") else {
        return Some(from_z);
    };
    // Complementary filter: measured velocity plus the slow part of (dz/dt - measured).
    let half = ((0.125 / dt).round() as usize).max(1);
    let diff: Vec<f64> = from_z.iter().zip(measured).map(|(a, b)| a - b).collect();
    let mut prefix = vec![0.0; n + 1];
    for i in 0..n {
        prefix[i + 1] = prefix[i] + diff[i];
    }
    Some(
        (0..n)
            .map(|i| {
                let a = i.saturating_sub(half);
                let b = (i + half + 1).min(n);
                measured[i] + (prefix[b] - prefix[a]) / (b - a) as f64
            })
            .collect(),
    )
}

/// Weights `w_j` (j = 0..2m) such that `sum w_j z[i - m + j]` is the first derivative (per
/// sample) of the cubic least-squares fit to the window at its centre.
fn cubic_derivative_weights(m: usize) -> Vec<f64> {
    // Normal equations of the Vandermonde matrix with powers 0..3 of x = j - m.
    let xs: Vec<f64> = (0..=2 * m).map(|j| j as f64 - m as f64).collect();
    let mut a = [[0.0f64; 4]; 4];
    for x in &xs {
        for (r, row) in a.iter_mut().enumerate() {
            for (c, v) in row.iter_mut().enumerate() {
                *v += x.powi((r + c) as i32);
            }
        }
    }
    // Row 1 of A^-1 (the derivative coefficient) by Gauss-Jordan elimination.
    let mut inv = [[0.0f64; 4]; 4];
    for (i, row) in inv.iter_mut().enumerate() {
        row[i] = 1.0;
    }
    for col in 0..4 {
        let piv = (col..4)
            .max_by(|&p, &q| a[p][col].abs().total_cmp(&a[q][col].abs()))
            .unwrap_or(col);
        a.swap(col, piv);
        inv.swap(col, piv);
        let d = a[col][col];
        a[col].iter_mut().for_each(|v| *v /= d);
        inv[col].iter_mut().for_each(|v| *v /= d);
        let (pivot_a, pivot_inv) = (a[col], inv[col]);
        for r in (0..4).filter(|&r| r != col) {
            let f = a[r][col];
            for c in 0..4 {
                a[r][c] -= f * pivot_a[c];
                inv[r][c] -= f * pivot_inv[c];
            }
        }
    }
    xs.iter()
        .map(|x| (0..4).map(|k| inv[1][k] * x.powi(k as i32)).sum())
        .collect()
}

/// The calibrated baseline of the strut, by the names of the strut registry
/// ([`hps_emulsion::STRUT_PARAMS`], which gives each one's unit, bounds and typical size), in
/// the order of [`DiscoveryModel::baseline_params`]. The last two have their own rules:
/// `v_r0` (the chamber split of Table 6.3's 11.4 L, which sets the rod-side dead volume;
/// window [`ROD_DEAD_LENGTH_WINDOW_M`]) is applied with [`StrutParams::with_rod_volume`],
/// which takes the oil from the piston side, and `gamma0` last with
/// [`StrutParams::with_gamma0`], which moves gas between the free volume and the emulsion.
pub const CALIBRATED: [&str; 9] = [
    "n",
    "p_h0",
    "v_g0",
    "friction.f_c",
    "friction.mu_v",
    "friction.vh_ratio",
    "c_b",
    "v_r0",
    "gamma0",
];

/// The strut's calibration switches ([`DiscoveryModel::switches`]): name, readings (the
/// crate's first, `hps_emulsion::StrutLaws::default`) and where the paper is ambiguous.
pub const SWITCHES: [(&str, [&str; 2], &str); 2] = [
    (
        "orifice-density",
        ["mean", "upstream"],
        "Eq 5.12: one density rho_bar for the orifice laws in both flow directions (hps_emulsion::OrificeDensity)",
    ),
    (
        "orifice-transition",
        ["turbulent", "laminar"],
        "Eq 5.12 gives the turbulent square-root law only; below a few tens of kPa the bleed jet's Reynolds number falls under ~1000 (hps_emulsion::OrificeTransition)",
    ),
];

/// Rod-side oil left at full extension (m) at the ends of the calibration window of
/// `v_r0`: the rod-side volume ranges over `A_ann (travel + l) (1 + gamma_0)` for `l` in
/// this window. The crate's choice is 10 mm (`hps_emulsion::params::ROD_DEAD_LENGTH`); the
/// paper gives none.
pub const ROD_DEAD_LENGTH_WINDOW_M: (f64, f64) = (0.002, 0.100);

/// The calibration window of registry parameter `name` around its value in `p`: narrower
/// than the registry's bounds (a calibration moves a parameter near its nominal value), the
/// friction levels with a floor that lets a zero nominal grow.
fn calibration_window(p: &StrutParams, name: &str) -> ParamSpec {
    let x = p.get(name).unwrap_or(f64::NAN);
    match name {
        "n" => ParamSpec::new(name, x, 1.0, 1.8),
        "p_h0" | "v_g0" => ParamSpec::new(name, x, 0.5 * x, 1.5 * x),
        "friction.f_c" => ParamSpec {
            typical: x.abs().max(100.0),
            ..ParamSpec::new(name, x, 0.0, 20.0 * x.max(100.0))
        },
        "friction.mu_v" => ParamSpec {
            typical: x.abs().max(100.0),
            ..ParamSpec::new(name, x, 0.0, 50.0 * x.max(100.0))
        },
        "c_b" => ParamSpec::new(name, x, 0.2, 1.0),
        // The band's width is unstated (section 5.3.1: it grows with the peak velocity):
        // from a sharp reversal to half the peak velocity.
        "friction.vh_ratio" => ParamSpec {
            typical: x.abs().max(0.05),
            ..ParamSpec::new(name, x, 0.02, 0.5)
        },
        // The chamber split: the rod-side volume with the window of its dead length.
        "v_r0" => {
            let per_m = p.a_ann() * (1.0 + p.gamma0);
            let (lo, hi) = ROD_DEAD_LENGTH_WINDOW_M;
            ParamSpec {
                typical: (per_m * 0.01).max(1e-9),
                ..ParamSpec::new(
                    name,
                    x,
                    (per_m * (p.travel + lo)).min(x),
                    (per_m * (p.travel + hi)).max(x),
                )
            }
        }
        "gamma0" => ParamSpec {
            typical: x.max(0.01),
            ..ParamSpec::new(name, x, 0.0, 0.3)
        },
        // Any other registry parameter: the registry's own bounds and typical size.
        _ => match p.find(name) {
            Ok((_, s)) => ParamSpec {
                typical: s.typical,
                ..ParamSpec::new(name, x, s.lower, s.upper)
            },
            Err(_) => ParamSpec::new(name, f64::NAN, f64::NAN, f64::NAN),
        },
    }
}

impl DiscoveryModel for HpsStrutModel {
    type Prepared = StrutReplay;

    fn name(&self) -> &str {
        "hps-strut"
    }

    fn channels(&self) -> Vec<String> {
        CHANNELS.iter().map(|s| s.to_string()).collect()
    }

    fn baseline_params(&self) -> Vec<ParamSpec> {
        CALIBRATED
            .iter()
            .map(|&name| calibration_window(&self.params, name))
            .collect()
    }

    fn switches(&self) -> Vec<LawSwitch> {
        SWITCHES
            .iter()
            .map(|(name, readings, citation)| LawSwitch {
                name: name.to_string(),
                readings: readings.iter().map(|r| r.to_string()).collect(),
                citation: citation.to_string(),
            })
            .collect()
    }

    fn catalogue(&self) -> Vec<EffectSpec> {
        vec![
            EffectSpec {
                name: EFFECTS[0].into(),
                description: "heat exchange between the gas and the strut body: the gas law moves from adiabatic (fast) towards isothermal (slow) with a thermal time constant, which opens a hysteresis loop at low frequency".into(),
                citation: "section 5.4.2 (low-frequency hysteresis attributed to gas heat transfer); thermal time-constant model of Pourmovahed & Otis (1990)".into(),
                params: vec![ParamSpec::new("tau_s", 2.0, 0.05, 100.0)],
            },
            EffectSpec {
                name: EFFECTS[1].into(),
                description: "a gas fraction of the emulsion that grows with the strut's peak velocity (more gas entrained by faster flow), beyond the fixed gamma_0 of Eqs 5.8-5.11".into(),
                citation: "Fig 5.4b (identified gamma_0 rising with peak velocity), section 5.4.3".into(),
                params: vec![ParamSpec {
                    typical: 0.1,
                    ..ParamSpec::new("k_gamma_s_m", 0.05, 0.0, 2.0)
                }],
            },
            EffectSpec {
                name: EFFECTS[2].into(),
                description: "seal friction that differs between compression and extension (structural asymmetry of the seals): the friction levels times (1 + a) in compression and (1 - a) in extension; their mean level is the calibrated F_c and mu_v".into(),
                citation: "section 5.4.2 (model underestimates compression friction)".into(),
                params: vec![ParamSpec {
                    typical: 0.2,
                    ..ParamSpec::new("asymmetry", 0.0, -0.9, 0.9)
                }],
            },
            EffectSpec {
                name: EFFECTS[3].into(),
                description: "check valves that open and close with a first-order lag (valve inertia and spring)".into(),
                citation: "section 5.3.2 (valve construction and dynamics), Eq 5.12".into(),
                params: vec![ParamSpec::new("tau_s", 0.01, 1e-4, 0.5)],
            },
        ]
    }

    fn prepare(&self, record: &Record) -> Result<StrutReplay, DiscoveryError> {
        let t = record
            .column("time_s")
            .ok_or(DiscoveryError::MissingColumn { column: "time_s" })?;
        let z = record
            .column("displacement_m")
            .ok_or(DiscoveryError::MissingColumn {
                column: "displacement_m",
            })?;
        if let (Some(mine), Some(theirs)) = (
            &self.strut,
            record.meta.get("strut").and_then(serde_json::Value::as_str),
        ) {
            if mine != theirs {
                return Err(DiscoveryError::OtherStrut {
                    record: theirs.to_string(),
                    model: mine.clone(),
                });
            }
        }
        let v = velocity_of(record).ok_or(DiscoveryError::NoStrutVelocity)?;
        let meta = |k: &str| record.meta.get(k).and_then(serde_json::Value::as_f64);
        let f = meta("frequency_hz").map_or(String::new(), |f| format!(", {f} Hz"));
        let amp = meta("amplitude_m").map_or(String::new(), |a| format!(", {:.0} mm", 1000.0 * a));
        let excitation = Excitation::Samples {
            time_s: t.to_vec(),
            displacement_m: z.to_vec(),
            velocity_m_s: Some(v),
        };
        // The motion's frequency from its peak velocity and amplitude (harmonic tests).
        let mean = z.iter().sum::<f64>() / z.len().max(1) as f64;
        let amplitude = z.iter().map(|v| (v - mean).abs()).fold(0.0, f64::max);
        let peak_velocity_m_s = excitation.peak_velocity();
        let freq = peak_velocity_m_s / (2.0 * std::f64::consts::PI * amplitude.max(1e-9));
        Ok(StrutReplay {
            group: if freq < 0.5 {
                "quasi-static"
            } else {
                "dynamic"
            }
            .to_string(),
            peak_velocity_m_s,
            excitation,
            condition: format!("{} strut{f}{amp}", self.strut.as_deref().unwrap_or("user")),
        })
    }

    fn condition(&self, prepared: &StrutReplay) -> String {
        prepared.condition.clone()
    }

    fn group(&self, prepared: &StrutReplay) -> Option<String> {
        Some(prepared.group.clone())
    }

    fn simulate(
        &self,
        prepared: &StrutReplay,
        baseline: &[f64],
        effects: &[ActiveEffect<'_>],
    ) -> Result<Vec<Option<Vec<f64>>>, DiscoveryError> {
        self.simulate_with_readings(prepared, baseline, effects, &[])
    }

    fn simulate_with_readings(
        &self,
        prepared: &StrutReplay,
        baseline: &[f64],
        effects: &[ActiveEffect<'_>],
        readings: &[usize],
    ) -> Result<Vec<Option<Vec<f64>>>, DiscoveryError> {
        let p = self.apply_baseline(baseline)?;
        let ext = self.apply_effects(effects)?;
        let strut = HpsStrut::new(&p, &ext)?.with_laws(Self::laws(readings)?);
        let out = simulate_strut_from(
            &strut,
            &prepared.excitation,
            prepared.peak_velocity_m_s,
            &self.sim,
        )?;
        Ok(vec![Some(out.force), Some(out.p_piston), Some(out.p_rod)])
    }

    fn phases(&self, record: &Record) -> Vec<Phase> {
        let Some(v) = velocity_of(record) else {
            return Vec::new();
        };
        vec![
            Phase {
                name: "compression".into(),
                mask: v.iter().map(|x| *x > 0.0).collect(),
            },
            Phase {
                name: "extension".into(),
                mask: v.iter().map(|x| *x < 0.0).collect(),
            },
        ]
    }

    fn skip_samples(&self, record: &Record) -> usize {
        record.len() / 4
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cubic_derivative_is_exact_for_cubics() {
        let w = cubic_derivative_weights(4);
        let f = |x: f64| 0.3 - 1.2 * x + 0.5 * x * x - 0.07 * x * x * x;
        let d: f64 = w
            .iter()
            .enumerate()
            .map(|(j, wj)| wj * f(j as f64 - 4.0))
            .sum();
        assert!((d - -1.2).abs() < 1e-10, "{d}");
    }

    #[test]
    fn velocity_of_a_sine_record() {
        let mut r = Record::new();
        let t: Vec<f64> = (0..3600).map(|i| i as f64 / 360.0).collect();
        let w = 2.0 * std::f64::consts::PI * 4.0;
        r.push_column("time_s", t.clone()).unwrap();
        r.push_column(
            "displacement_m",
            t.iter().map(|t| 0.01 * (w * t).sin()).collect(),
        )
        .unwrap();
        let v = velocity_of(&r).unwrap();
        for i in 10..3590 {
            assert!((v[i] - 0.01 * w * (w * t[i]).cos()).abs() < 2e-4, "{i}");
        }
    }

    #[test]
    fn the_calibration_set_is_named_by_the_strut_registry() {
        let m = HpsStrutModel::nominal();
        let specs = m.baseline_params();
        let names: Vec<&str> = specs.iter().map(|s| s.name.as_str()).collect();
        assert_eq!(names, CALIBRATED);
        for s in &specs {
            let (_, reg) = m.params.find(&s.name).unwrap();
            assert_eq!(s.initial, m.params.get(&s.name).unwrap(), "{}", s.name);
            assert!(s.lower <= s.initial && s.initial <= s.upper, "{}", s.name);
            assert!(s.lower >= reg.lower, "{}", s.name);
        }
        // The nominal vector gives back the nominal strut; a changed value lands on its field.
        let mut v: Vec<f64> = specs.iter().map(|s| s.initial).collect();
        assert_eq!(m.apply_baseline(&v).unwrap(), m.params);
        v[1] *= 1.1;
        v[3] = 123.0;
        let p = m.apply_baseline(&v).unwrap();
        assert_eq!((p.p_h0, p.friction.f_c), (1.1 * m.params.p_h0, 123.0));
        assert!(matches!(
            m.apply_baseline(&v[..6]),
            Err(DiscoveryError::BaselineLength {
                expected: 9,
                got: 6
            })
        ));
        // The chamber split moves oil between the chambers and keeps the total; the
        // window's ends are rod-side dead lengths of 2 and 100 mm.
        let k = CALIBRATED.iter().position(|&n| n == "v_r0").unwrap();
        let mut v: Vec<f64> = specs.iter().map(|s| s.initial).collect();
        v[k] = specs[k].upper;
        let p = m.apply_baseline(&v).unwrap();
        let total = |p: &StrutParams| p.v_c0 + p.v_r0;
        assert!((total(&p) - total(&m.params)).abs() < 1e-15);
        let dead = p.v_r0 / (1.0 + p.gamma0) - p.a_ann() * p.travel;
        assert!((dead - p.a_ann() * 0.1).abs() < 1e-12, "{dead}");
        v[k] = specs[k].lower;
        v[CALIBRATED.len() - 1] = 0.0; // no gas in the emulsion: the rod side still holds
        assert!(m.apply_baseline(&v).is_ok());
    }
}
