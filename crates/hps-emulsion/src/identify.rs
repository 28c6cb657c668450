//! Parameter identification from a measured record (section 5.3.2): nonlinear least squares
//! on force and pressures over any subset of (n, F_c, F_s, mu_v, gamma_0, C_b, C_v, k_l).

use crate::error::HpsError;
use crate::extensions::HpsExtensions;
use crate::fit_checks::{ChannelCheck, ChannelChecks, VelocitySource};
use crate::params::StrutParams;
use crate::simulate::{simulate_displacement, Excitation, SimOptions};
use optimize::least_squares::{fit, FitOptions, Problem};
use serde::{Deserialize, Serialize};

/// A parameter that can be fitted.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum FitParam {
    /// Polytropic exponent n.
    N,
    /// Coulomb friction F_c.
    Fc,
    /// Stiction F_s.
    Fs,
    /// Viscous friction mu_v.
    MuV,
    /// Gas fraction gamma_0 (moved from the free gas, [`StrutParams::with_gamma0`]).
    Gamma0,
    /// Bleed discharge coefficient C_b.
    Cb,
    /// Check-valve discharge coefficient C_v.
    Cv,
    /// Leakage coefficient k_l.
    Kl,
}

impl FitParam {
    /// All fittable parameters.
    pub const ALL: [FitParam; 8] = [
        FitParam::N,
        FitParam::Fc,
        FitParam::Fs,
        FitParam::MuV,
        FitParam::Gamma0,
        FitParam::Cb,
        FitParam::Cv,
        FitParam::Kl,
    ];

    /// Short name (`n`, `fc`, `fs`, `muv`, `gamma0`, `cb`, `cv`, `kl`).
    pub fn name(self) -> &'static str {
        match self {
            FitParam::N => "n",
            FitParam::Fc => "fc",
            FitParam::Fs => "fs",
            FitParam::MuV => "muv",
            FitParam::Gamma0 => "gamma0",
            FitParam::Cb => "cb",
            FitParam::Cv => "cv",
            FitParam::Kl => "kl",
        }
    }

    /// Parse a short name (case-insensitive; `mu_v`, `f_c`, `k_l`, ... also accepted).
    pub fn parse(s: &str) -> Result<Self, HpsError> {
        let k = s.trim().to_ascii_lowercase().replace('_', "");
        FitParam::ALL
            .iter()
            .copied()
            .find(|p| p.name() == k)
            .ok_or_else(|| {
                HpsError::Identification(format!(
                    "unknown parameter `{s}` (choose from n, fc, fs, muv, gamma0, cb, cv, kl)"
                ))
            })
    }

    /// Parse a comma-separated list, rejecting duplicates and empty lists.
    pub fn parse_list(s: &str) -> Result<Vec<Self>, HpsError> {
        let mut v = Vec::new();
        for part in s.split(',').filter(|p| !p.trim().is_empty()) {
            let p = Self::parse(part)?;
            if v.contains(&p) {
                return Err(HpsError::Identification(format!(
                    "parameter `{}` listed twice",
                    p.name()
                )));
            }
            v.push(p);
        }
        if v.is_empty() {
            return Err(HpsError::Identification("no parameter to fit".into()));
        }
        Ok(v)
    }

    /// Current value in `p`.
    pub fn get(self, p: &StrutParams) -> f64 {
        match self {
            FitParam::N => p.n,
            FitParam::Fc => p.friction.f_c,
            FitParam::Fs => p.friction.f_s,
            FitParam::MuV => p.friction.mu_v,
            FitParam::Gamma0 => p.gamma0,
            FitParam::Cb => p.c_b,
            FitParam::Cv => p.c_v,
            FitParam::Kl => p.k_l,
        }
    }

    /// `p` with this parameter set to `value`.
    pub fn set(self, p: &StrutParams, value: f64) -> Result<StrutParams, HpsError> {
        let mut q = *p;
        match self {
            FitParam::N => q.n = value,
            FitParam::Fc => q.friction.f_c = value,
            FitParam::Fs => q.friction.f_s = value,
            FitParam::MuV => q.friction.mu_v = value,
            FitParam::Gamma0 => return p.with_gamma0(value),
            FitParam::Cb => q.c_b = value,
            FitParam::Cv => q.c_v = value,
            FitParam::Kl => q.k_l = value,
        }
        q.validate()?;
        Ok(q)
    }

    /// Typical magnitude (scales the fit variable when the start value is zero).
    fn typical(self) -> f64 {
        match self {
            FitParam::N => 1.0,
            FitParam::Fc | FitParam::Fs => 100.0,
            FitParam::MuV => 50.0,
            FitParam::Gamma0 => 0.03,
            FitParam::Cb | FitParam::Cv => 0.5,
            FitParam::Kl => 5e-12,
        }
    }

    /// Bounds of the physical range searched (in the parameter's own unit).
    pub fn bounds(self) -> (f64, f64) {
        match self {
            FitParam::N => (1.0, 1.7),
            FitParam::Fc | FitParam::Fs => (0.0, 1e5),
            FitParam::MuV => (0.0, 1e6),
            FitParam::Gamma0 => (0.0, 0.45),
            FitParam::Cb | FitParam::Cv => (0.05, 1.0),
            FitParam::Kl => (0.0, 1e-8),
        }
    }
}

/// A measured strut record (columns of the HPS bench test of docs/records.md). Channels that are
/// `None` are not compared.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Measured {
    /// Time (s).
    pub time: Vec<f64>,
    /// Deflection z_s (m, + compression).
    pub displacement: Vec<f64>,
    /// Velocity (m/s); differentiated from the displacement when absent.
    pub velocity: Option<Vec<f64>>,
    /// Strut force (N, + compressive).
    pub force: Option<Vec<f64>>,
    /// Piston-side pressure (Pa, absolute).
    pub p_piston: Option<Vec<f64>>,
    /// Rod-side pressure (Pa, absolute).
    pub p_rod: Option<Vec<f64>>,
}

/// Settings of [`identify`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IdentifyOptions {
    /// Simulation settings (tight tolerances keep the finite-difference Jacobian clean).
    pub sim: SimOptions,
    /// Samples before this time (s after the first sample) are simulated but not compared
    /// (start-up transient when the record does not begin at static equilibrium).
    pub warmup_s: f64,
    /// Iteration limit of Levenberg-Marquardt.
    pub max_iter: usize,
}

impl Default for IdentifyOptions {
    fn default() -> Self {
        Self {
            sim: SimOptions {
                rtol: 1e-8,
                atol: 1e-10,
                ..SimOptions::default()
            },
            warmup_s: 0.0,
            max_iter: 50,
        }
    }
}

/// Normalised RMS error of each compared channel: `rms(sim - meas) / (max(meas) - min(meas))`.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct ChannelNrmse {
    /// Force channel.
    pub force: Option<f64>,
    /// Piston-side pressure channel.
    pub p_piston: Option<f64>,
    /// Rod-side pressure channel.
    pub p_rod: Option<f64>,
}

/// One fitted parameter.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct FittedValue {
    /// Which parameter.
    pub param: FitParam,
    /// Start value.
    pub initial: f64,
    /// Fitted value.
    pub value: f64,
    /// Standard error from the Jacobian at the solution (NaN when not determined).
    pub std_error: f64,
}

/// Outcome of [`identify`].
#[derive(Debug, Clone, PartialEq)]
pub struct IdentifyResult {
    /// Strut with the fitted values.
    pub params: StrutParams,
    /// Fitted values and standard errors.
    pub fitted: Vec<FittedValue>,
    /// NRMSE per channel before the fit.
    pub nrmse_initial: ChannelNrmse,
    /// NRMSE per channel after the fit.
    pub nrmse: ChannelNrmse,
    /// Levenberg-Marquardt iterations.
    pub iterations: usize,
    /// Whether a convergence test was met.
    pub converged: bool,
    /// The fitted model's residual against the record's noise, per channel.
    pub checks: ChannelChecks,
    /// Where the velocity came from (measured, or differentiated from the displacement).
    pub velocity: VelocitySource,
}

struct Channel<'a> {
    meas: &'a [f64],
    scale: f64,
}

struct IdProblem<'a> {
    base: StrutParams,
    ext: HpsExtensions,
    which: &'a [FitParam],
    typ: Vec<f64>,
    exc: Excitation,
    opts: IdentifyOptions,
    channels: [Option<Channel<'a>>; 3],
    first: usize,
    n_used: usize,
}

impl IdProblem<'_> {
    fn params_at(&self, x: &[f64]) -> Result<StrutParams, HpsError> {
        let mut p = self.base;
        for (k, fp) in self.which.iter().enumerate() {
            p = fp.set(&p, x[k] * self.typ[k])?;
        }
        Ok(p)
    }

    /// Simulated channels (force, p_piston, p_rod).
    fn simulate(&self, p: &StrutParams) -> Result<[Vec<f64>; 3], HpsError> {
        let r = simulate_displacement(p, &self.ext, &self.exc, &self.opts.sim)?;
        Ok([r.force, r.p_piston, r.p_rod])
    }

    fn checks(&self, sim: &[Vec<f64>; 3]) -> ChannelChecks {
        let check = |c: usize| {
            self.channels[c]
                .as_ref()
                .map(|ch| ChannelCheck::of(&ch.meas[self.first..], &sim[c][self.first..]))
        };
        ChannelChecks {
            force: check(0),
            p_piston: check(1),
            p_rod: check(2),
        }
    }

    fn nrmse(&self, sim: &[Vec<f64>; 3]) -> ChannelNrmse {
        let mut out = [None; 3];
        for (c, ch) in self.channels.iter().enumerate() {
            if let Some(ch) = ch {
                let m = &ch.meas[self.first..];
                let s = &sim[c][self.first..];
                let rms = (m.iter().zip(s).map(|(a, b)| (a - b) * (a - b)).sum::<f64>()
                    / m.len() as f64)
                    .sqrt();
                let range = m.iter().cloned().fold(f64::NEG_INFINITY, f64::max)
                    - m.iter().cloned().fold(f64::INFINITY, f64::min);
                out[c] = Some(if range > 0.0 { rms / range } else { rms });
            }
        }
        ChannelNrmse {
            force: out[0],
            p_piston: out[1],
            p_rod: out[2],
        }
    }
}

impl Problem for IdProblem<'_> {
    fn n_params(&self) -> usize {
        self.which.len()
    }
    fn n_residuals(&self) -> usize {
        self.n_used
    }
    fn residuals(&self, x: &[f64], r: &mut [f64]) -> Result<(), String> {
        let p = self.params_at(x).map_err(|e| e.to_string())?;
        let sim = self.simulate(&p).map_err(|e| e.to_string())?;
        let mut k = 0;
        for (c, ch) in self.channels.iter().enumerate() {
            if let Some(ch) = ch {
                for i in self.first..ch.meas.len() {
                    r[k] = (sim[c][i] - ch.meas[i]) / ch.scale;
                    k += 1;
                }
            }
        }
        Ok(())
    }
}

/// The options and the parameter list of [`identify`]: a finite, non-negative warm-up and
/// at least one parameter, none listed twice.
fn check_request(which: &[FitParam], opts: &IdentifyOptions) -> Result<(), HpsError> {
    if !(opts.warmup_s.is_finite() && opts.warmup_s >= 0.0) {
        return Err(HpsError::Identification(format!(
            "`warmup_s` must be finite and >= 0, got {}",
            opts.warmup_s
        )));
    }
    if which.is_empty() {
        return Err(HpsError::Identification("no parameter to fit".into()));
    }
    for (i, a) in which.iter().enumerate() {
        if which[..i].contains(a) {
            return Err(HpsError::Identification(format!(
                "parameter `{}` listed twice",
                a.name()
            )));
        }
    }
    Ok(())
}

/// Fit the parameters `which` of `start` (other parameters fixed) to the measured record by
/// bounded Levenberg-Marquardt. Each channel's residuals are divided by that channel's
/// standard deviation so force and pressures weigh alike; standard errors come from the
/// Jacobian at the solution (`s^2 (J^T J)^-1`).
pub fn identify(
    measured: &Measured,
    start: &StrutParams,
    ext: &HpsExtensions,
    which: &[FitParam],
    opts: &IdentifyOptions,
) -> Result<IdentifyResult, HpsError> {
    start.validate()?;
    check_request(which, opts)?;
    let n = measured.time.len();
    let exc = Excitation::Samples {
        time_s: measured.time.clone(),
        displacement_m: measured.displacement.clone(),
        velocity_m_s: measured.velocity.clone(),
    };
    exc.validate(start.travel)?;
    let mk = |v: &'_ Option<Vec<f64>>, name: &str| -> Result<Option<Vec<f64>>, HpsError> {
        match v {
            Some(x) if x.len() != n => Err(HpsError::Identification(format!(
                "channel {name} has {} samples, time has {n}",
                x.len()
            ))),
            Some(x) if x.iter().any(|a| !a.is_finite()) => Err(HpsError::Identification(format!(
                "channel {name} has non-finite samples"
            ))),
            _ => Ok(v.clone()),
        }
    };
    let force = mk(&measured.force, "force")?;
    let pc = mk(&measured.p_piston, "p_piston")?;
    let pr = mk(&measured.p_rod, "p_rod")?;
    let t0 = measured.time[0];
    let first = measured
        .time
        .iter()
        .position(|&t| t - t0 >= opts.warmup_s)
        .unwrap_or(n);
    let used = n - first;
    let chan = |v: &'_ Option<Vec<f64>>| -> Option<(f64, usize)> {
        v.as_ref().map(|x| {
            let m = &x[first..];
            let mean = m.iter().sum::<f64>() / m.len().max(1) as f64;
            let sd = (m.iter().map(|a| (a - mean) * (a - mean)).sum::<f64>()
                / m.len().max(1) as f64)
                .sqrt();
            (if sd > 0.0 { sd } else { 1.0 }, m.len())
        })
    };
    let specs = [chan(&force), chan(&pc), chan(&pr)];
    let n_used: usize = specs.iter().flatten().map(|s| s.1).sum();
    if n_used == 0 {
        return Err(HpsError::Identification(
            "no force or pressure channel to compare (need force_n, p_piston_pa or p_rod_pa)"
                .into(),
        ));
    }
    if used < 2 * which.len() {
        return Err(HpsError::Identification(format!(
            "only {used} samples after the warm-up for {} parameters",
            which.len()
        )));
    }
    let datas = [force, pc, pr];
    let channels: [Option<Channel>; 3] = std::array::from_fn(|c| match (&datas[c], specs[c]) {
        (Some(d), Some((scale, _))) => Some(Channel {
            meas: d.as_slice(),
            scale,
        }),
        _ => None,
    });
    let typ: Vec<f64> = which
        .iter()
        .map(|p| {
            let v = p.get(start).abs();
            if v > 0.0 {
                v
            } else {
                p.typical()
            }
        })
        .collect();
    let problem = IdProblem {
        base: *start,
        ext: *ext,
        which,
        typ: typ.clone(),
        exc,
        opts: *opts,
        channels,
        first,
        n_used,
    };
    let x0: Vec<f64> = which
        .iter()
        .zip(&typ)
        .map(|(p, t)| p.get(start) / t)
        .collect();
    let sim0 = problem.simulate(start)?;
    let nrmse_initial = problem.nrmse(&sim0);
    let lower: Vec<f64> = which
        .iter()
        .zip(&typ)
        .map(|(p, t)| p.bounds().0 / t)
        .collect();
    let upper: Vec<f64> = which
        .iter()
        .zip(&typ)
        .map(|(p, t)| p.bounds().1 / t)
        .collect();
    let fo = FitOptions {
        max_iter: opts.max_iter,
        ftol: 1e-10,
        xtol: 1e-8,
        lower: Some(lower),
        upper: Some(upper),
        diff_step: 1e-4,
        typical: Some(vec![1.0; which.len()]),
        ..FitOptions::default()
    };
    let res = fit(&problem, &x0, &fo).map_err(|e| HpsError::Identification(e.to_string()))?;
    let params = problem.params_at(&res.params)?;
    let sim = problem.simulate(&params)?;
    let fitted = which
        .iter()
        .enumerate()
        .map(|(k, p)| FittedValue {
            param: *p,
            initial: p.get(start),
            value: res.params[k] * typ[k],
            std_error: res.std_errors[k] * typ[k],
        })
        .collect();
    Ok(IdentifyResult {
        params,
        fitted,
        nrmse_initial,
        nrmse: problem.nrmse(&sim),
        iterations: res.iterations,
        converged: res.converged,
        checks: problem.checks(&sim),
        velocity: VelocitySource::of(
            &measured.time[first..],
            &measured.displacement[first..],
            measured.velocity.as_deref().map(|v| &v[first..]),
        ),
    })
}
