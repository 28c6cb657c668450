//! Harmonic characterisation (sections 5.4.2-5.4.3): the laboratory programme, loop metrics
//! per test, and the summary `afsv evaluate` prints.

use crate::error::HpsError;
use crate::extensions::HpsExtensions;
use crate::params::StrutParams;
use crate::simulate::{simulate_displacement, Excitation, SimOptions, StrutRecord};
use crate::strut::HpsStrut;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// One harmonic test: `z_s = A sin(2 pi f t)`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct HarmonicTest {
    /// Frequency (Hz).
    pub frequency_hz: f64,
    /// Amplitude (m).
    pub amplitude_m: f64,
}

/// Largest amplitude of the dynamic tests (section 5.2: "limited to 45 mm").
pub const AMPLITUDE_CAP: f64 = 0.045;

impl HarmonicTest {
    /// Test at constant peak velocity `v_peak` (m/s), amplitude `v_peak / (2 pi f)` capped at 45 mm.
    pub fn at_peak_velocity(frequency_hz: f64, v_peak: f64) -> Self {
        Self {
            frequency_hz,
            amplitude_m: (v_peak / (2.0 * PI * frequency_hz)).min(AMPLITUDE_CAP),
        }
    }
}

/// The laboratory programme of section 5.2: 0.1 Hz at 5, 25, 50 mm, then 1-8 Hz (1 Hz steps)
/// at peak velocities 0.05, 0.1, 0.15, 0.2 and 0.2356 m/s with amplitudes capped at 45 mm.
/// Tests that exceed `travel` are left out.
pub fn lab_programme(travel: f64) -> Vec<HarmonicTest> {
    let mut v: Vec<HarmonicTest> = [0.005, 0.025, 0.050]
        .iter()
        .map(|&a| HarmonicTest {
            frequency_hz: 0.1,
            amplitude_m: a,
        })
        .collect();
    for f in 1..=8 {
        for &vp in &[0.05, 0.1, 0.15, 0.2, 0.2356] {
            v.push(HarmonicTest::at_peak_velocity(f as f64, vp));
        }
    }
    v.retain(|t| t.amplitude_m <= travel);
    v
}

/// Metrics of one steady cycle (the last simulated period).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct LoopMetrics {
    /// Frequency (Hz).
    pub frequency_hz: f64,
    /// Amplitude (m).
    pub amplitude_m: f64,
    /// Peak velocity (m/s).
    pub peak_velocity_m_s: f64,
    /// Effective stiffness: least-squares slope of the gas-spring force
    /// `(P_hc - p_amb) A_hr` against deflection over the cycle (N/m).
    pub effective_stiffness_n_m: f64,
    /// Largest damping force (total minus gas-spring force) in compression (N, > 0).
    pub peak_damping_compression_n: f64,
    /// Largest damping force magnitude in extension (N, > 0).
    pub peak_damping_extension_n: f64,
    /// Energy dissipated per cycle: area of the force-deflection loop, `closed integral F dz` (J).
    pub dissipated_energy_j: f64,
    /// Area of the gas-spring force-deflection loop (J): its hysteresis.
    pub spring_loop_area_j: f64,
    /// Area of the damping force-velocity loop `|closed integral F_d dv|` (N m/s): its hysteresis.
    pub damping_loop_area_n_m_s: f64,
    /// Equivalent viscous damping `E / (pi omega A^2)` (N s/m).
    pub equivalent_damping_n_s_m: f64,
    /// Lowest rod-side pressure over the cycle (Pa).
    pub p_rod_min_pa: f64,
    /// Highest rod-side pressure over the cycle (Pa).
    pub p_rod_max_pa: f64,
    /// Highest piston-side pressure over the cycle (Pa).
    pub p_piston_max_pa: f64,
    /// Lowest piston-side pressure over the cycle (Pa).
    pub p_piston_min_pa: f64,
}

fn loop_integral(x: &[f64], y: &[f64]) -> f64 {
    // Trapezoidal closed integral of y dx over the samples (first and last close the loop).
    let n = x.len();
    let mut s = 0.0;
    for i in 0..n {
        let j = (i + 1) % n;
        s += 0.5 * (y[i] + y[j]) * (x[j] - x[i]);
    }
    s
}

/// Loop metrics of the last full period `1/frequency_hz` of a harmonic record.
pub fn loop_metrics(rec: &StrutRecord, test: &HarmonicTest) -> Result<LoopMetrics, HpsError> {
    let t_end = *rec
        .time
        .last()
        .ok_or_else(|| HpsError::InvalidExcitation("empty record".into()))?;
    let period = 1.0 / test.frequency_hz;
    let t_start = t_end - period;
    // The last period, without its duplicated closing sample.
    let idx: Vec<usize> = (0..rec.time.len())
        .filter(|&i| rec.time[i] >= t_start - 1e-9 && rec.time[i] < t_end - 1e-9)
        .collect();
    if idx.len() < 16 || t_start < -1e-9 {
        return Err(HpsError::InvalidExcitation(
            "record shorter than one period or too coarse (need 16 samples per period)".into(),
        ));
    }
    let g = |v: &Vec<f64>| idx.iter().map(|&i| v[i]).collect::<Vec<f64>>();
    let z = g(&rec.displacement);
    let v = g(&rec.velocity);
    let f = g(&rec.force);
    let fs = g(&rec.spring_force);
    let pr = g(&rec.p_rod);
    let pc = g(&rec.p_piston);
    let fd: Vec<f64> = f.iter().zip(&fs).map(|(a, b)| a - b).collect();
    let n = z.len() as f64;
    let zm = z.iter().sum::<f64>() / n;
    let fm = fs.iter().sum::<f64>() / n;
    let szz: f64 = z.iter().map(|a| (a - zm) * (a - zm)).sum();
    let szf: f64 = z.iter().zip(&fs).map(|(a, b)| (a - zm) * (b - fm)).sum();
    let stiffness = if szz > 0.0 { szf / szz } else { 0.0 };
    let energy = loop_integral(&z, &f);
    let w = 2.0 * PI * test.frequency_hz;
    let min = |x: &[f64]| x.iter().cloned().fold(f64::INFINITY, f64::min);
    let max = |x: &[f64]| x.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
    Ok(LoopMetrics {
        frequency_hz: test.frequency_hz,
        amplitude_m: test.amplitude_m,
        peak_velocity_m_s: w * test.amplitude_m,
        effective_stiffness_n_m: stiffness,
        peak_damping_compression_n: max(&fd).max(0.0),
        peak_damping_extension_n: (-min(&fd)).max(0.0),
        dissipated_energy_j: energy,
        spring_loop_area_j: loop_integral(&z, &fs).abs(),
        damping_loop_area_n_m_s: loop_integral(&v, &fd).abs(),
        equivalent_damping_n_s_m: if test.amplitude_m > 0.0 {
            energy / (PI * w * test.amplitude_m * test.amplitude_m)
        } else {
            0.0
        },
        p_rod_min_pa: min(&pr),
        p_rod_max_pa: max(&pr),
        p_piston_max_pa: max(&pc),
        p_piston_min_pa: min(&pc),
    })
}

/// Simulate one harmonic test for `cycles` periods and return the record and the metrics of
/// the last period.
pub fn run_harmonic(
    params: &StrutParams,
    ext: &HpsExtensions,
    test: &HarmonicTest,
    cycles: f64,
    opts: &SimOptions,
) -> Result<(StrutRecord, LoopMetrics), HpsError> {
    let exc = Excitation::harmonic(test.frequency_hz, test.amplitude_m, cycles);
    let mut o = *opts;
    // At least 64 samples per period for the loop integrals.
    o.output_rate_hz = o.output_rate_hz.max(64.0 * test.frequency_hz);
    let rec = simulate_displacement(params, ext, &exc, &o)?;
    let m = loop_metrics(&rec, test)?;
    Ok((rec, m))
}

/// Run every test of `tests` (3 periods each, metrics of the last) and return their metrics.
pub fn characterize(
    params: &StrutParams,
    ext: &HpsExtensions,
    tests: &[HarmonicTest],
    opts: &SimOptions,
) -> Result<Vec<LoopMetrics>, HpsError> {
    tests
        .iter()
        .map(|t| run_harmonic(params, ext, t, 3.0, opts).map(|(_, m)| m))
        .collect()
}

/// Headline numbers of a strut for `afsv evaluate`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct StrutSummary {
    /// Static force at mid-stroke (N).
    pub static_force_n: f64,
    /// Static stiffness dF/dz at mid-stroke (N/m), polytropic gas (Eq 5.4) with emulsion.
    pub static_stiffness_n_m: f64,
    /// Metrics of the 1 Hz test.
    pub at_1hz: LoopMetrics,
}

/// Summary of a strut: static stiffness at mid-stroke and damping under a 1 Hz harmonic test
/// of amplitude `amplitude_m`.
pub fn summary(params: &StrutParams, amplitude_m: f64) -> Result<StrutSummary, HpsError> {
    let ext = HpsExtensions::none();
    let s = HpsStrut::new(params, &ext)?;
    let test = HarmonicTest {
        frequency_hz: 1.0,
        amplitude_m,
    };
    let (_, m) = run_harmonic(params, &ext, &test, 3.0, &SimOptions::default())?;
    Ok(StrutSummary {
        static_force_n: s.static_force(0.0)?,
        static_stiffness_n_m: s.static_stiffness(0.0)?,
        at_1hz: m,
    })
}

/// The front-axle strut (Table 6.3) summary at +-25 mm, 1 Hz: what `afsv evaluate` prints.
pub fn front_axle_summary() -> Result<StrutSummary, HpsError> {
    summary(&StrutParams::front_axle(), 0.025)
}
