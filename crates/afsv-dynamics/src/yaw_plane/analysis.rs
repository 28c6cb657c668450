//! Analyses of sections 3.3, 3.4.1-3.4.3 and 4.3.1: yaw-mode frequency and damping from
//! the pulse response, steering gain / rise time / overshoot / power efficiency from the
//! step response, the one-at-a-time sensitivity table, the steady-turning decay due to
//! leakage, and the gain-efficiency correlation over a leakage sweep (Fig 4.7).

use crate::error::DynError;
use crate::yaw_plane::params::{Load, VehicleParams, YawPlaneParams};
use crate::yaw_plane::simulate::{simulate, Manoeuvre, SimOptions, YawRecord};
use crate::{EquationForm, SteerInput};
use afs_hydraulics::{AfsParams, AfsSystem};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::sync::atomic::{AtomicUsize, Ordering};
use vehicle_components::ParamSet;

/// Test definition of the measures (section 3.3).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct MeasureSpec {
    /// Peak of the 0.2 s half-sine pulse (deg of steering wheel). Not stated in the
    /// paper; 30 deg makes the pulse and the 30 deg step give comparable articulation
    /// peaks, as section 3.3 says they do.
    pub pulse_amplitude_deg: f64,
    /// Pulse duration (s), 0.2 in section 3.3.
    pub pulse_duration_s: f64,
    /// Step height (deg of steering wheel), 30 in section 3.3.
    pub step_amplitude_deg: f64,
    /// Input time (s).
    pub input_time_s: f64,
    /// Simulated time of each run (s).
    pub duration_s: f64,
    /// Length of the free-decay window fitted after the pulse (s).
    pub decay_window_s: f64,
    /// Numerical options.
    pub options: SimOptions,
}

impl Default for MeasureSpec {
    fn default() -> Self {
        Self {
            pulse_amplitude_deg: 30.0,
            pulse_duration_s: 0.2,
            step_amplitude_deg: 30.0,
            input_time_s: 0.5,
            duration_s: 10.0,
            decay_window_s: 3.0,
            options: SimOptions::default(),
        }
    }
}

/// The yaw-plane performance measures of one configuration.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct YawMeasures {
    /// Load condition (`None` for a user parameter set).
    pub load: Option<Load>,
    /// Forward speed (m/s).
    pub speed_m_s: f64,
    /// Equation form used.
    pub form: EquationForm,
    /// Yaw-mode natural frequency from the single-DOF fit of the post-pulse articulation (Hz).
    pub natural_frequency_hz: f64,
    /// Damped frequency of that fit (Hz).
    pub damped_frequency_hz: f64,
    /// Yaw damping ratio (-).
    pub damping_ratio: f64,
    /// RMS residual of the decay fit (deg) and its coefficient of determination.
    pub decay_fit_rmse_deg: f64,
    /// Coefficient of determination of the decay fit.
    pub decay_fit_r_squared: f64,
    /// Noise RMS the decay window shows (deg; floored at 0.1 % of its range,
    /// `perf_measures::DecayFit::noise_rms`); 0 in states written before it was recorded.
    #[serde(default)]
    pub decay_fit_noise_rms_deg: f64,
    /// Peak articulation after the pulse (deg).
    pub pulse_peak_articulation_deg: f64,
    /// Steering gain Gamma: steady articulation / steering-wheel step (deg/deg).
    pub steering_gain: f64,
    /// Steady articulation after the step (deg).
    pub steady_articulation_deg: f64,
    /// 0-100 % rise time of the step response (s).
    pub rise_time_s: f64,
    /// Response rate psi: steady articulation / rise time (deg/s).
    pub response_rate_deg_s: f64,
    /// Overshoot of the step response (%).
    pub overshoot_percent: f64,
    /// Steering power efficiency eta over the step run, Eq 4.7 (-).
    pub power_efficiency: f64,
    /// Initial strut length L (m), the sixth objective of section 4.3.2.
    pub strut_length_m: f64,
}

impl YawMeasures {
    /// Why the single-mode decay fit's frequency and damping need a caveat (None when its
    /// residual lies within [`perf_measures::DECAY_RESIDUAL_NOISE_LIMIT`] times the noise):
    /// the hydraulic steering's damping is not linear, so the free response is not one
    /// decaying mode and the fitted numbers depend on the window.
    pub fn decay_fit_caveat(&self) -> Option<String> {
        perf_measures::not_one_mode(self.decay_fit_rmse_deg / self.decay_fit_noise_rms_deg)
    }
}

fn measure_err(measure: &'static str) -> impl Fn(perf_measures::MeasureError) -> DynError {
    move |e| DynError::Measure {
        measure,
        reason: e.to_string(),
    }
}

/// Index of the first sample at or after `t`.
fn index_at(time: &[f64], t: f64) -> usize {
    time.partition_point(|&x| x < t - 1e-12)
}

/// Pulse measures from a pulse run: `(fit, peak articulation deg)`.
pub fn pulse_measures(
    rec: &YawRecord,
    pulse_end_s: f64,
    window_s: f64,
) -> Result<(perf_measures::DecayFit, f64), DynError> {
    let y = &rec.articulation_deg;
    let t = &rec.time_s;
    let peak = y
        .iter()
        .fold(0.0f64, |m, v| if v.abs() > m.abs() { *v } else { m });
    let i0 = perf_measures::decay_onset(t, y, pulse_end_s).ok_or_else(|| DynError::Measure {
        measure: "yaw-mode frequency",
        reason: "no free oscillation after the pulse (fewer than two extrema)".into(),
    })?;
    let i1 = index_at(t, t[i0] + window_s).min(t.len());
    let fit = perf_measures::fit_free_decay(&t[i0..i1], &y[i0..i1])
        .map_err(measure_err("yaw-mode frequency"))?;
    Ok((fit, peak))
}

/// Step measures from a step run: `(metrics, efficiency)`.
pub fn step_measures(
    rec: &YawRecord,
    step_time_s: f64,
    amplitude_deg: f64,
) -> Result<(perf_measures::StepMetrics, f64), DynError> {
    let m = perf_measures::step_metrics(
        &rec.time_s,
        &rec.articulation_deg,
        step_time_s,
        amplitude_deg,
    )
    .map_err(measure_err("step response"))?;
    let i0 = index_at(&rec.time_s, step_time_s);
    let q: Vec<f64> = rec.q_supply_m3_s[i0..].iter().map(|q| q.abs()).collect();
    let eta = perf_measures::steering_power_efficiency(
        &rec.time_s[i0..],
        &rec.steering_torque_nm[i0..],
        &rec.articulation_rate_rad_s()[i0..],
        &rec.supply_pressure_pa[i0..],
        &q,
    )
    .map_err(measure_err("power efficiency"))?;
    Ok((m, eta))
}

/// All measures of one configuration (vehicle, steering parameters) at `speed_m_s`.
pub fn measures_for(
    vehicle: &VehicleParams,
    afs: &AfsParams,
    load: Option<Load>,
    speed_m_s: f64,
    spec: &MeasureSpec,
) -> Result<YawMeasures, DynError> {
    let sys = AfsSystem::new(afs.clone()).map_err(|e| DynError::Steering(e.to_string()))?;
    // The measures use neither energy channel; recording them costs a quadrature per sample.
    let options = SimOptions {
        record_energy: false,
        ..spec.options
    };
    let pulse = Manoeuvre::open_loop(
        speed_m_s,
        spec.duration_s,
        SteerInput::pulse_deg(
            spec.pulse_amplitude_deg,
            spec.pulse_duration_s,
            spec.input_time_s,
        ),
        "pulse",
    );
    let step = Manoeuvre::open_loop(
        speed_m_s,
        spec.duration_s,
        SteerInput::step_deg(spec.step_amplitude_deg, spec.input_time_s),
        "step",
    );
    let rp = simulate(vehicle, &sys, &pulse, &options)?;
    let (fit, peak) = pulse_measures(
        &rp,
        spec.input_time_s + spec.pulse_duration_s,
        spec.decay_window_s,
    )?;
    let rs = simulate(vehicle, &sys, &step, &options)?;
    let (sm, eta) = step_measures(&rs, spec.input_time_s, spec.step_amplitude_deg)?;
    Ok(YawMeasures {
        load,
        speed_m_s,
        form: spec.options.form,
        natural_frequency_hz: fit.natural_frequency_hz,
        damped_frequency_hz: fit.damped_frequency_hz,
        damping_ratio: fit.damping_ratio,
        decay_fit_rmse_deg: fit.rmse,
        decay_fit_r_squared: fit.r_squared,
        decay_fit_noise_rms_deg: fit.noise_rms,
        pulse_peak_articulation_deg: peak,
        steering_gain: sm.gain,
        steady_articulation_deg: sm.steady_value,
        rise_time_s: sm.rise_time_s,
        response_rate_deg_s: sm.steady_value / sm.rise_time_s,
        overshoot_percent: sm.overshoot_percent,
        power_efficiency: eta,
        strut_length_m: sys.initial_strut_length(),
    })
}

/// The measures of the nominal vehicle (Table 3.1) for `load` at `speed_m_s` with the
/// default test definition and the energy-consistent equations. This is what
/// `afsv evaluate` and `afsv yaw measures` report.
pub fn yaw_measures(load: Load, speed_m_s: f64) -> Result<YawMeasures, DynError> {
    measures_for(
        &VehicleParams::nominal(load),
        &AfsParams::nominal(),
        Some(load),
        speed_m_s,
        &MeasureSpec::default(),
    )
}

/// Design parameters of the sensitivity study (section 3.4.3).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SensitivityParam {
    /// Kinematic angle A_0.
    A0,
    /// Effective bulk modulus B_eff.
    BulkModulus,
    /// Viscous seal-friction coefficient mu_v.
    SealViscous,
    /// Velocity-related leakage coefficient k_l.
    LeakVelocity,
}

impl SensitivityParam {
    /// The four parameters in the paper's order.
    pub const ALL: [SensitivityParam; 4] = [
        SensitivityParam::A0,
        SensitivityParam::BulkModulus,
        SensitivityParam::SealViscous,
        SensitivityParam::LeakVelocity,
    ];

    /// Paper symbol.
    pub fn symbol(self) -> &'static str {
        match self {
            SensitivityParam::A0 => "A_0",
            SensitivityParam::BulkModulus => "B_eff",
            SensitivityParam::SealViscous => "mu_v",
            SensitivityParam::LeakVelocity => "k_l",
        }
    }

    /// The parameter's name in the yaw-plane registry
    /// ([`crate::yaw_plane::registry::YAW_PLANE_PARAMS`], the steering system's part:
    /// [`afs_hydraulics::AFS_PARAMS`]), as `afsv params list yaw-plane` prints it.
    pub fn name(self) -> &'static str {
        match self {
            SensitivityParam::A0 => "a0_rad",
            SensitivityParam::BulkModulus => "bulk_modulus_pa",
            SensitivityParam::SealViscous => "seal_viscous_n_s_m",
            SensitivityParam::LeakVelocity => "leak_velocity",
        }
    }

    /// `p` with this parameter, addressed by [`Self::name`], scaled by `factor`, without
    /// the registry's bounds (an exploration may leave them). Every name is in the
    /// registry (tested); the set is returned unchanged otherwise.
    pub fn scaled(self, p: &AfsParams, factor: f64) -> AfsParams {
        let mut q = p.clone();
        if let Ok((i, _)) = q.find(self.name()) {
            let v = q.value(i);
            q.assign(i, v * factor);
        }
        q
    }

    /// The whole yaw-plane set `p` with this parameter scaled by `factor` through
    /// [`ParamSet::set`]: the value must stay inside the registry's bounds and pass the
    /// set's validation, else the error names the parameter.
    pub fn try_scaled(self, p: &YawPlaneParams, factor: f64) -> Result<YawPlaneParams, DynError> {
        let mut q = p.clone();
        let name = self.name();
        let scaled = q
            .get(name)
            .and_then(|v| q.set(name, v * factor))
            .map_err(|e| DynError::InvalidInput(format!("sensitivity study: {e}")));
        scaled.map(|()| q)
    }
}

/// Percent changes of the measures relative to nominal.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct MeasureChanges {
    /// Natural frequency (%).
    pub frequency: f64,
    /// Damping ratio (%).
    pub damping: f64,
    /// Steering gain (%).
    pub gain: f64,
    /// Response rate = steady articulation / rise time (%).
    pub response_rate: f64,
    /// Overshoot (%), relative change of the overshoot percentage.
    pub overshoot: f64,
    /// Power efficiency (%).
    pub efficiency: f64,
}

fn pct(a: f64, b: f64) -> f64 {
    100.0 * (a - b) / b
}

impl MeasureChanges {
    /// Changes of `m` relative to `nominal`.
    pub fn between(m: &YawMeasures, nominal: &YawMeasures) -> Self {
        Self {
            frequency: pct(m.natural_frequency_hz, nominal.natural_frequency_hz),
            damping: pct(m.damping_ratio, nominal.damping_ratio),
            gain: pct(m.steering_gain, nominal.steering_gain),
            response_rate: pct(m.response_rate_deg_s, nominal.response_rate_deg_s),
            overshoot: pct(m.overshoot_percent, nominal.overshoot_percent),
            efficiency: pct(m.power_efficiency, nominal.power_efficiency),
        }
    }
}

/// One row of the sensitivity table.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SensitivityRow {
    /// Load condition.
    pub load: Load,
    /// Parameter varied.
    pub parameter: SensitivityParam,
    /// Variation (%), e.g. -30.
    pub variation_percent: f64,
    /// Percent changes of the measures.
    pub change: MeasureChanges,
    /// The measures themselves.
    pub measures: YawMeasures,
}

/// The full one-at-a-time study.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SensitivityTable {
    /// Speed (m/s).
    pub speed_m_s: f64,
    /// Nominal measures, loaded then unloaded.
    pub nominal: Vec<YawMeasures>,
    /// Rows: load x parameter x variation.
    pub rows: Vec<SensitivityRow>,
}

impl SensitivityTable {
    /// Plain-text table: a header, one line per row (percent change of each measure), and
    /// the nominal measures per load.
    pub fn to_text(&self) -> String {
        use std::fmt::Write as _;
        let mut s = format!(
            "{:<9} {:<6} {:>5}  {:>9} {:>9} {:>9} {:>9} {:>9} {:>9}\n",
            "load", "param", "var%", "freq", "damping", "gain", "rate", "overshoot", "effic."
        );
        for r in &self.rows {
            let c = r.change;
            let _ = writeln!(
                s,
                "{:<9} {:<6} {:>+5.0}  {:>9} {:>9} {:>9} {:>9} {:>9} {:>9}",
                r.load.name(),
                r.parameter.symbol(),
                r.variation_percent,
                na(c.frequency, 2, true),
                na(c.damping, 2, true),
                na(c.gain, 2, true),
                na(c.response_rate, 2, true),
                na(c.overshoot, 2, true),
                na(c.efficiency, 2, true)
            );
        }
        for n in &self.nominal {
            let _ = writeln!(
                s,
                "nominal {:<9}: f = {} Hz, zeta = {}, gain = {}, rise = {} s, OS = {} %, eta = {}",
                n.load.map(|l| l.name()).unwrap_or("-"),
                na(n.natural_frequency_hz, 3, false),
                na(n.damping_ratio, 4, false),
                na(n.steering_gain, 4, false),
                na(n.rise_time_s, 3, false),
                na(n.overshoot_percent, 1, false),
                na(n.power_efficiency, 4, false)
            );
        }
        s
    }
}

/// `v` with `prec` decimals (and a sign when `signed`), or `n/a` when it is not finite.
fn na(v: f64, prec: usize, signed: bool) -> String {
    match (v.is_finite(), signed) {
        (false, _) => "n/a".into(),
        (true, true) => format!("{v:+.prec$}"),
        (true, false) => format!("{v:.prec$}"),
    }
}

/// Variations of section 3.4.3 (%).
pub const VARIATIONS_PERCENT: [f64; 4] = [-30.0, -15.0, 15.0, 30.0];

/// Section 3.4.3: each of A_0, B_eff, mu_v, k_l at -30, -15, +15, +30 % for both loads.
/// Same as [`sensitivity_with_progress`] without a progress report.
pub fn sensitivity(speed_m_s: f64, spec: &MeasureSpec) -> Result<SensitivityTable, DynError> {
    sensitivity_with_progress(speed_m_s, spec, &|_, _| {})
}

/// One configuration of the sensitivity study: a load, and the parameter varied with its
/// variation (%), or `None` for the nominal vehicle.
type StudyCase = (Load, Option<(SensitivityParam, f64)>);

/// Section 3.4.3, with the 34 configurations (nominal plus 4 parameters x 4 variations, per
/// load) measured in parallel on the rayon thread pool. Each configuration is an
/// independent pair of runs, so the table does not depend on the number of threads
/// (tested). `progress(done, total)` is called once per finished configuration, from
/// whichever thread finished it.
pub fn sensitivity_with_progress(
    speed_m_s: f64,
    spec: &MeasureSpec,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<SensitivityTable, DynError> {
    sensitivity_of(&YawPlaneParams::nominal, speed_m_s, spec, progress)
}

/// [`sensitivity_with_progress`] about the parameters `base(load)` of each load (a
/// vehicle description's yaw-plane data and steering) instead of Table 3.1's.
pub fn sensitivity_of(
    base: &(dyn Fn(Load) -> YawPlaneParams + Sync),
    speed_m_s: f64,
    spec: &MeasureSpec,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<SensitivityTable, DynError> {
    let mut cases: Vec<StudyCase> = Vec::new();
    for load in Load::ALL {
        cases.push((load, None));
        for p in SensitivityParam::ALL {
            for pctv in VARIATIONS_PERCENT {
                cases.push((load, Some((p, pctv))));
            }
        }
    }
    let total = cases.len();
    let done = AtomicUsize::new(0);
    let measured: Vec<YawMeasures> = cases
        .par_iter()
        .map(|&(load, variation)| {
            let nominal = base(load);
            let p = match variation {
                None => nominal,
                Some((param, pctv)) => param.try_scaled(&nominal, 1.0 + pctv / 100.0)?,
            };
            let m = measures_for(&p.vehicle, &p.afs, Some(load), speed_m_s, spec);
            progress(done.fetch_add(1, Ordering::Relaxed) + 1, total);
            m
        })
        .collect::<Result<_, _>>()?;
    let mut nominal = Vec::new();
    let mut rows = Vec::new();
    for (&(load, variation), m) in cases.iter().zip(measured) {
        match variation {
            None => nominal.push(m),
            Some((parameter, variation_percent)) => {
                let nom = nominal.last().expect("a load's nominal case comes first");
                rows.push(SensitivityRow {
                    load,
                    parameter,
                    variation_percent,
                    change: MeasureChanges::between(&m, nom),
                    measures: m,
                });
            }
        }
    }
    Ok(SensitivityTable {
        speed_m_s,
        nominal,
        rows,
    })
}

/// Steady-turning decay of the articulation due to leakage (section 3.4.1).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SteadyTurnDecay {
    /// Load condition.
    pub load: Load,
    /// Speed (m/s).
    pub speed_m_s: f64,
    /// Steering-wheel angle held (deg).
    pub steer_wheel_deg: f64,
    /// Articulation at the start of the hold window (deg).
    pub articulation_start_deg: f64,
    /// Articulation at the end of the hold window (deg).
    pub articulation_end_deg: f64,
    /// Mean drift rate over the window (deg/s, negative = decaying).
    pub drift_deg_s: f64,
    /// Length of the window (s).
    pub window_s: f64,
}

/// Hold a steering-wheel angle (ramped in over 1 s) at the Table 3.2 speed and report
/// how much the articulation decays over `window_s` seconds once settled (from 10 s on).
pub fn steady_turn_decay(
    load: Load,
    speed_m_s: f64,
    steer_wheel_deg: f64,
    window_s: f64,
    options: &SimOptions,
) -> Result<SteadyTurnDecay, DynError> {
    let p = YawPlaneParams::nominal(load);
    steady_turn_decay_of(&p, load, speed_m_s, steer_wheel_deg, window_s, options)
}

/// [`steady_turn_decay`] of the vehicle and steering `p` (a description's), reported as
/// `load`.
pub fn steady_turn_decay_of(
    p: &YawPlaneParams,
    load: Load,
    speed_m_s: f64,
    steer_wheel_deg: f64,
    window_s: f64,
    options: &SimOptions,
) -> Result<SteadyTurnDecay, DynError> {
    let sys = AfsSystem::new(p.afs.clone()).map_err(|e| DynError::Steering(e.to_string()))?;
    let v = &p.vehicle;
    let t_settle = 10.0;
    let man = Manoeuvre::open_loop(
        speed_m_s,
        t_settle + window_s,
        SteerInput::Ramp {
            rate_rad_s: steer_wheel_deg.to_radians(),
            start_s: 0.0,
            limit_rad: steer_wheel_deg.abs().to_radians(),
        },
        "steady_turn",
    );
    let r = simulate(v, &sys, &man, options)?;
    let i0 = index_at(&r.time_s, t_settle);
    let n = r.time_s.len() - 1;
    let (a0, a1) = (r.articulation_deg[i0], r.articulation_deg[n]);
    let w = r.time_s[n] - r.time_s[i0];
    Ok(SteadyTurnDecay {
        load,
        speed_m_s,
        steer_wheel_deg,
        articulation_start_deg: a0,
        articulation_end_deg: a1,
        drift_deg_s: (a1 - a0) / w,
        window_s: w,
    })
}

/// Gain-efficiency correlation over a leakage sweep (Fig 4.7).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct GainEfficiency {
    /// Leakage-coefficient variations (%).
    pub variation_percent: Vec<f64>,
    /// Steering gain at each (deg/deg).
    pub steering_gain: Vec<f64>,
    /// Power efficiency at each (-).
    pub power_efficiency: Vec<f64>,
    /// Coefficient of determination of the linear fit efficiency ~ gain.
    pub r_squared: f64,
}

/// Coefficient of determination of a straight-line fit of `y` on `x`.
pub fn r_squared(x: &[f64], y: &[f64]) -> f64 {
    let n = x.len() as f64;
    let mx = x.iter().sum::<f64>() / n;
    let my = y.iter().sum::<f64>() / n;
    let (mut sxy, mut sxx, mut syy) = (0.0, 0.0, 0.0);
    for (a, b) in x.iter().zip(y) {
        sxy += (a - mx) * (b - my);
        sxx += (a - mx) * (a - mx);
        syy += (b - my) * (b - my);
    }
    if sxx == 0.0 || syy == 0.0 {
        return 0.0;
    }
    sxy * sxy / (sxx * syy)
}

/// Fig 4.7: step-response gain and efficiency with both leakage coefficients (k_l0 and
/// k_l) scaled by -30, -15, 0, +15, +30 %, loaded vehicle.
pub fn gain_efficiency_correlation(
    load: Load,
    speed_m_s: f64,
    spec: &MeasureSpec,
) -> Result<GainEfficiency, DynError> {
    gain_efficiency_correlation_of(&YawPlaneParams::nominal(load), speed_m_s, spec)
}

/// [`gain_efficiency_correlation`] of the vehicle and steering `p` (a description's).
pub fn gain_efficiency_correlation_of(
    p: &YawPlaneParams,
    speed_m_s: f64,
    spec: &MeasureSpec,
) -> Result<GainEfficiency, DynError> {
    let v = &p.vehicle;
    let base = &p.afs;
    let vars = [-30.0, -15.0, 0.0, 15.0, 30.0];
    let mut gains = Vec::new();
    let mut effs = Vec::new();
    for pv in vars {
        let mut a = base.clone();
        a.leak_const *= 1.0 + pv / 100.0;
        a.leak_velocity *= 1.0 + pv / 100.0;
        let sys = AfsSystem::new(a).map_err(|e| DynError::Steering(e.to_string()))?;
        let step = Manoeuvre::open_loop(
            speed_m_s,
            spec.duration_s,
            SteerInput::step_deg(spec.step_amplitude_deg, spec.input_time_s),
            "step",
        );
        let r = simulate(v, &sys, &step, &spec.options)?;
        let (m, eta) = step_measures(&r, spec.input_time_s, spec.step_amplitude_deg)?;
        gains.push(m.gain);
        effs.push(eta);
    }
    Ok(GainEfficiency {
        r_squared: r_squared(&gains, &effs),
        variation_percent: vars.to_vec(),
        steering_gain: gains,
        power_efficiency: effs,
    })
}

#[cfg(test)]
mod na_tests {
    use super::na;

    #[test]
    fn non_finite_cells_read_n_a() {
        assert_eq!(na(f64::NAN, 2, true), "n/a");
        assert_eq!(na(f64::INFINITY, 2, false), "n/a");
        assert_eq!(na(1.234, 2, true), "+1.23");
        assert_eq!(na(-1.0, 1, false), "-1.0");
    }
}

#[cfg(test)]
mod study_tests {
    use super::*;
    use afs_hydraulics::AFS_PARAMS;

    #[test]
    fn parameters_are_addressed_by_their_registry_names() {
        let base = YawPlaneParams::nominal(Load::Loaded);
        for p in SensitivityParam::ALL {
            assert!(
                AFS_PARAMS.iter().any(|s| s.name == p.name()),
                "{}",
                p.name()
            );
            let by_name = p.try_scaled(&base, 1.15).unwrap();
            assert_eq!(by_name.afs, p.scaled(&base.afs, 1.15));
            let v0 = base.get(p.name()).unwrap();
            assert!((by_name.get(p.name()).unwrap() / v0 - 1.15).abs() < 1e-12);
            // only that parameter changed
            let mut back = by_name.clone();
            back.set(p.name(), v0).unwrap();
            assert_eq!(back, base);
        }
        // out of the registry's bounds: an error naming the parameter, not a silent run
        let err = SensitivityParam::A0.try_scaled(&base, 10.0).unwrap_err();
        assert!(err.to_string().contains("a0_rad"), "{err}");
    }

    #[test]
    fn the_parallel_study_does_not_depend_on_the_thread_count() {
        let spec = MeasureSpec::default();
        let run = |threads: usize| {
            let calls = AtomicUsize::new(0);
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            let t = pool
                .install(|| {
                    sensitivity_with_progress(50.0 / 3.6, &spec, &|done, total| {
                        assert!(done >= 1 && done <= total && total == 34);
                        calls.fetch_add(1, Ordering::Relaxed);
                    })
                })
                .unwrap();
            assert_eq!(calls.into_inner(), 34);
            t
        };
        let one = run(1);
        let three = run(3);
        assert_eq!(one, three);
        assert_eq!(one.rows.len(), 32);
        assert_eq!(one.nominal[0].load, Some(Load::Loaded));
        assert_eq!(one.nominal[1].load, Some(Load::Unloaded));
        // rows in the paper's order: load, parameter, variation
        assert_eq!(one.rows[0].parameter, SensitivityParam::A0);
        assert_eq!(one.rows[0].variation_percent, -30.0);
        assert_eq!(one.rows[31].load, Load::Unloaded);
        assert_eq!(one.rows[31].parameter, SensitivityParam::LeakVelocity);
    }
}
