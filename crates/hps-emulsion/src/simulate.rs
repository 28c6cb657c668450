//! Drive the strut by a prescribed displacement history (harmonic, or samples from a record).

use crate::error::HpsError;
use crate::extensions::HpsExtensions;
use crate::params::StrutParams;
use crate::strut::HpsStrut;
pub use odeint::Solver;
use odeint::{Atol, Control, Integrator, OdeSystem};
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// A prescribed strut deflection history (z_s positive in compression, from the static position).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub enum Excitation {
    /// `z_s(t) = A sin(2 pi f t)` from t = 0 for `cycles` periods (starts at the static position).
    Harmonic {
        /// Frequency f (Hz).
        frequency_hz: f64,
        /// Amplitude A (m).
        amplitude_m: f64,
        /// Number of periods simulated.
        cycles: f64,
    },
    /// Sampled displacement (and optionally velocity), linearly interpolated; outputs are
    /// produced at the sample times. Without velocities, they are taken from central
    /// differences of the displacement.
    Samples {
        /// Sample times (s), strictly increasing.
        time_s: Vec<f64>,
        /// Displacement z_s (m).
        displacement_m: Vec<f64>,
        /// Velocity (m/s), optional.
        velocity_m_s: Option<Vec<f64>>,
    },
}

impl Excitation {
    /// Harmonic excitation.
    pub fn harmonic(frequency_hz: f64, amplitude_m: f64, cycles: f64) -> Self {
        Self::Harmonic {
            frequency_hz,
            amplitude_m,
            cycles,
        }
    }

    /// Check the excitation against the strut's travel.
    pub fn validate(&self, travel: f64) -> Result<(), HpsError> {
        match self {
            Self::Harmonic {
                frequency_hz,
                amplitude_m,
                cycles,
            } => {
                if !(frequency_hz.is_finite() && *frequency_hz > 0.0) {
                    return Err(HpsError::InvalidExcitation(format!(
                        "frequency must be > 0 Hz, got {frequency_hz}"
                    )));
                }
                if !(amplitude_m.is_finite() && *amplitude_m >= 0.0) {
                    return Err(HpsError::InvalidExcitation(format!(
                        "amplitude must be >= 0, got {amplitude_m}"
                    )));
                }
                if *amplitude_m > travel {
                    return Err(HpsError::InvalidExcitation(format!(
                        "amplitude {:.1} mm exceeds the strut travel of +-{:.1} mm",
                        amplitude_m * 1e3,
                        travel * 1e3
                    )));
                }
                if !(cycles.is_finite() && *cycles > 0.0) {
                    return Err(HpsError::InvalidExcitation(format!(
                        "cycles must be > 0, got {cycles}"
                    )));
                }
            }
            Self::Samples {
                time_s,
                displacement_m,
                velocity_m_s,
            } => {
                if time_s.len() < 2 || time_s.len() != displacement_m.len() {
                    return Err(HpsError::InvalidExcitation(format!(
                        "need at least 2 samples and equal lengths (time {}, displacement {})",
                        time_s.len(),
                        displacement_m.len()
                    )));
                }
                if let Some(v) = velocity_m_s {
                    if v.len() != time_s.len() {
                        return Err(HpsError::InvalidExcitation(format!(
                            "velocity has {} samples, time has {}",
                            v.len(),
                            time_s.len()
                        )));
                    }
                    if let Some(i) = v.iter().position(|x| !x.is_finite()) {
                        return Err(HpsError::InvalidExcitation(format!(
                            "velocity sample {i} is not finite"
                        )));
                    }
                }
                for i in 0..time_s.len() {
                    if !time_s[i].is_finite() || !displacement_m[i].is_finite() {
                        return Err(HpsError::InvalidExcitation(format!(
                            "sample {i} is not finite"
                        )));
                    }
                    if i > 0 && time_s[i] <= time_s[i - 1] {
                        return Err(HpsError::InvalidExcitation(format!(
                            "time must increase strictly (sample {i}: {} after {})",
                            time_s[i],
                            time_s[i - 1]
                        )));
                    }
                    if displacement_m[i].abs() > travel {
                        return Err(HpsError::InvalidExcitation(format!(
                            "displacement {:.1} mm at sample {i} exceeds the strut travel of +-{:.1} mm",
                            displacement_m[i] * 1e3,
                            travel * 1e3
                        )));
                    }
                }
            }
        }
        Ok(())
    }

    /// Peak absolute velocity of the motion (m/s).
    pub fn peak_velocity(&self) -> f64 {
        match self {
            Self::Harmonic {
                frequency_hz,
                amplitude_m,
                ..
            } => 2.0 * PI * frequency_hz * amplitude_m,
            Self::Samples {
                time_s,
                displacement_m,
                velocity_m_s,
            } => match velocity_m_s {
                Some(v) => v.iter().fold(0.0, |m, x| m.max(x.abs())),
                None => central_differences(time_s, displacement_m)
                    .iter()
                    .fold(0.0, |m, x| m.max(x.abs())),
            },
        }
    }

    /// Characteristic frequency `v_peak / (2 pi z_amp)` (Hz), `z_amp` half the displacement
    /// range; the frequency itself for a harmonic excitation, 0 for no motion.
    pub fn characteristic_frequency(&self) -> f64 {
        match self {
            Self::Harmonic { frequency_hz, .. } => *frequency_hz,
            Self::Samples { displacement_m, .. } => {
                let hi = displacement_m
                    .iter()
                    .cloned()
                    .fold(f64::NEG_INFINITY, f64::max);
                let lo = displacement_m.iter().cloned().fold(f64::INFINITY, f64::min);
                let amp = 0.5 * (hi - lo);
                if amp > 0.0 {
                    self.peak_velocity() / (2.0 * PI * amp)
                } else {
                    0.0
                }
            }
        }
    }

    /// Duration (s).
    pub fn duration(&self) -> f64 {
        match self {
            Self::Harmonic {
                frequency_hz,
                cycles,
                ..
            } => cycles / frequency_hz,
            Self::Samples { time_s, .. } => time_s[time_s.len() - 1] - time_s[0],
        }
    }
}

fn central_differences(t: &[f64], z: &[f64]) -> Vec<f64> {
    let n = t.len();
    (0..n)
        .map(|i| {
            let (a, b) = (i.saturating_sub(1), (i + 1).min(n - 1));
            (z[b] - z[a]) / (t[b] - t[a])
        })
        .collect()
}

/// Prepared displacement input: z(t), z'(t) without allocation.
enum Input<'a> {
    Harmonic {
        w: f64,
        a: f64,
    },
    Samples {
        t: &'a [f64],
        z: &'a [f64],
        v: &'a [f64],
        /// Samples per second on the mean grid, to guess where `t` falls.
        rate: f64,
    },
}

/// The number of samples of `ts` (strictly increasing) before `t`: what a binary search
/// finds, looked for first within a few samples of `guess` (the index on the mean grid), so
/// that a uniformly sampled record needs two or three comparisons instead of a dozen.
#[inline]
fn samples_before(ts: &[f64], t: f64, guess: f64) -> usize {
    vehicle_components::sampled::partition_point_near(ts, guess, |x| {
        x.total_cmp(&t) == std::cmp::Ordering::Less
    })
}

impl Input<'_> {
    #[inline]
    fn eval(&self, t: f64) -> (f64, f64) {
        match self {
            Input::Harmonic { w, a } => {
                let (s, c) = (w * t).sin_cos();
                (a * s, a * w * c)
            }
            Input::Samples { t: ts, z, v, rate } => {
                let n = ts.len();
                // The interval of a binary search: [i, i + 1] at a sample hit, else the one
                // holding t (clamped to the record).
                let i = samples_before(ts, t, (t - ts[0]) * rate);
                let k = if i < n && ts[i].total_cmp(&t) == std::cmp::Ordering::Equal {
                    i.min(n - 2)
                } else {
                    i.clamp(1, n - 1) - 1
                };
                let r = ((t - ts[k]) / (ts[k + 1] - ts[k])).clamp(0.0, 1.0);
                (z[k] + r * (z[k + 1] - z[k]), v[k] + r * (v[k + 1] - v[k]))
            }
        }
    }
}

struct Driven<'a> {
    strut: &'a HpsStrut,
    input: Input<'a>,
    /// The [`Solver::Auto`] rule for this motion (see [`AUTO_SWITCH_HZ`]).
    stiff: bool,
}

impl OdeSystem for Driven<'_> {
    fn dim(&self) -> usize {
        self.strut.n_states()
    }
    fn rhs(&self, t: f64, y: &[f64], dydt: &mut [f64]) {
        let (z, zd) = self.input.eval(t);
        self.strut.derivatives(z, zd, y, dydt);
    }
    /// Slow motion keeps the orifice pressure drops small, where the strut is stiffest.
    fn is_stiff(&self) -> bool {
        self.stiff
    }
}

/// Characteristic frequency (Hz) at which [`Solver::Auto`] switches from Rosenbrock23 to
/// Dopri5, measured (docs/hps-emulsion.md): a strut run answers [`OdeSystem::is_stiff`]
/// with `true` when the motion's characteristic frequency `v_peak / (2 pi z_amp)`
/// ([`Excitation::characteristic_frequency`]) is below it.
pub const AUTO_SWITCH_HZ: f64 = 0.5;

/// Settings of a displacement-driven run.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct SimOptions {
    /// Output rate for harmonic runs (Hz); sampled excitations output at their own times.
    pub output_rate_hz: f64,
    /// Integrator ([`Solver::Auto`]: by the frequency rule of [`AUTO_SWITCH_HZ`]).
    pub solver: Solver,
    /// Relative tolerance.
    pub rtol: f64,
    /// Absolute tolerance per typical magnitude: state `i` gets
    /// `atol * HpsStrut::state_typical(i)` (e.g. `atol * P_h0` for the rod-side pressure).
    pub atol: f64,
}

impl Default for SimOptions {
    fn default() -> Self {
        Self {
            output_rate_hz: 360.0,
            solver: Solver::Auto,
            rtol: 1e-6,
            atol: 1e-9,
        }
    }
}

/// Time histories of a run, in the record convention of docs/records.md.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct StrutRecord {
    /// Time (s).
    pub time: Vec<f64>,
    /// Deflection z_s (m, + compression).
    pub displacement: Vec<f64>,
    /// Velocity z_s' (m/s).
    pub velocity: Vec<f64>,
    /// Strut force F_h (N, + compressive).
    pub force: Vec<f64>,
    /// Piston-side pressure P_hc (Pa, absolute).
    pub p_piston: Vec<f64>,
    /// Rod-side pressure P_hr (Pa, absolute).
    pub p_rod: Vec<f64>,
    /// Seal friction F_f (N).
    pub friction: Vec<f64>,
    /// Gas-spring force (P_hc - p_amb) A_hr (N).
    pub spring_force: Vec<f64>,
    /// Free gas volume V_g (m^3).
    pub gas_volume: Vec<f64>,
}

impl StrutRecord {
    /// Damping force: total minus gas-spring force (section 5.4.2), N.
    pub fn damping_force(&self) -> Vec<f64> {
        self.force
            .iter()
            .zip(&self.spring_force)
            .map(|(f, s)| f - s)
            .collect()
    }

    /// Columns as `(name_unit, values)` in the record format of docs/records.md (the first six are
    /// the standard HPS bench-test columns).
    pub fn columns(&self) -> Vec<(&'static str, Vec<f64>)> {
        vec![
            ("time_s", self.time.clone()),
            ("displacement_m", self.displacement.clone()),
            ("velocity_m_s", self.velocity.clone()),
            ("force_n", self.force.clone()),
            ("p_piston_pa", self.p_piston.clone()),
            ("p_rod_pa", self.p_rod.clone()),
            ("friction_n", self.friction.clone()),
            ("spring_force_n", self.spring_force.clone()),
            ("damping_force_n", self.damping_force()),
            ("gas_volume_m3", self.gas_volume.clone()),
        ]
    }

    fn with_capacity(n: usize) -> Self {
        let v = || Vec::with_capacity(n);
        Self {
            time: v(),
            displacement: v(),
            velocity: v(),
            force: v(),
            p_piston: v(),
            p_rod: v(),
            friction: v(),
            spring_force: v(),
            gas_volume: v(),
        }
    }
}

/// Simulate the strut under a prescribed displacement, starting from static equilibrium at
/// the first displacement with the velocity amplitude at the excitation's peak velocity, so
/// the peak-velocity laws (friction band `v_h`, gas-fraction growth when that extension is
/// on) start in their steady state.
pub fn simulate_displacement(
    params: &StrutParams,
    ext: &HpsExtensions,
    excitation: &Excitation,
    opts: &SimOptions,
) -> Result<StrutRecord, HpsError> {
    params.validate()?;
    excitation.validate(params.travel)?;
    let strut = HpsStrut::new(params, ext)?;
    simulate_strut(&strut, excitation, opts)
}

/// Most output samples one harmonic run produces (duration times output rate).
pub const MAX_OUTPUT_SAMPLES: f64 = 1e7;

/// As [`simulate_displacement`] for an already built strut: the velocity amplitude starts at
/// [`Excitation::peak_velocity`].
pub fn simulate_strut(
    strut: &HpsStrut,
    excitation: &Excitation,
    opts: &SimOptions,
) -> Result<StrutRecord, HpsError> {
    simulate_strut_from(strut, excitation, excitation.peak_velocity(), opts)
}

/// As [`simulate_strut`] with the initial velocity amplitude `u0` (m/s) given: a caller that
/// replays one excitation many times computes its peak once; `u0 = 0` starts at rest.
pub fn simulate_strut_from(
    strut: &HpsStrut,
    excitation: &Excitation,
    u0: f64,
    opts: &SimOptions,
) -> Result<StrutRecord, HpsError> {
    excitation.validate(strut.params().travel)?;
    if !(opts.output_rate_hz.is_finite() && opts.output_rate_hz > 0.0) {
        return Err(HpsError::InvalidExcitation(format!(
            "output rate must be > 0 Hz, got {}",
            opts.output_rate_hz
        )));
    }
    let vel_storage;
    let (input, t0, t_out, max_step) = match excitation {
        Excitation::Harmonic {
            frequency_hz,
            amplitude_m,
            ..
        } => {
            let t_end = excitation.duration();
            let samples = t_end * opts.output_rate_hz;
            if samples.is_nan() || samples > MAX_OUTPUT_SAMPLES {
                return Err(HpsError::InvalidExcitation(format!(
                    "`cycles` / `frequency_hz` * `output_rate_hz` = {samples:e} output samples, at most {MAX_OUTPUT_SAMPLES:e}"
                )));
            }
            let dt = 1.0 / opts.output_rate_hz;
            let mut ts = odeint::output_grid(0.0, t_end, dt);
            if t_end - ts[ts.len() - 1] > 1e-9 * t_end.max(1.0) {
                ts.push(t_end);
            }
            (
                Input::Harmonic {
                    w: 2.0 * PI * frequency_hz,
                    a: *amplitude_m,
                },
                0.0,
                ts,
                1.0 / (20.0 * frequency_hz),
            )
        }
        Excitation::Samples {
            time_s,
            displacement_m,
            velocity_m_s,
        } => {
            vel_storage = match velocity_m_s {
                Some(v) => v.clone(),
                None => central_differences(time_s, displacement_m),
            };
            let min_dt = time_s
                .windows(2)
                .map(|w| w[1] - w[0])
                .fold(f64::INFINITY, f64::min);
            (
                Input::Samples {
                    t: time_s,
                    z: displacement_m,
                    v: &vel_storage,
                    rate: (time_s.len() - 1) as f64 / (time_s[time_s.len() - 1] - time_s[0]),
                },
                time_s[0],
                time_s.clone(),
                min_dt,
            )
        }
    };
    let sys = Driven {
        strut,
        input,
        stiff: excitation.characteristic_frequency() < AUTO_SWITCH_HZ,
    };
    let (z0, _) = sys.input.eval(t0);
    let mut y0 = vec![0.0; strut.n_states()];
    strut.initial_state_at(z0, u0, &mut y0)?;
    let mut rec = StrutRecord::with_capacity(t_out.len());
    let mut observe = |t: f64, y: &[f64]| {
        let (z, zd) = sys.input.eval(t);
        let o = strut.outputs(z, zd, y);
        rec.time.push(t);
        rec.displacement.push(z);
        rec.velocity.push(zd);
        rec.force.push(o.force);
        rec.p_piston.push(o.p_piston);
        rec.p_rod.push(o.p_rod);
        rec.friction.push(o.friction);
        rec.spring_force.push(o.spring_force);
        rec.gas_volume.push(o.gas_volume);
        Control::Continue
    };
    let atol = Atol::scaled(opts.atol, (0..y0.len()).map(|i| strut.state_typical(i)));
    Integrator::new(opts.solver, opts.rtol, atol)
        .with_max_step(max_step)
        .integrate(&sys, t0, &y0, &t_out, &mut observe)?;
    if let Some(i) = rec.gas_volume.iter().position(|v| v.is_nan() || *v <= 0.0) {
        return Err(HpsError::OutOfRange {
            t: rec.time[i],
            reason: "free gas volume vanished".into(),
        });
    }
    Ok(rec)
}
