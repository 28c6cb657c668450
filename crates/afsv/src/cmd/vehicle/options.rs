//! The options of `afsv vehicle` and their bounds: speeds, seed counts, durations, the
//! `--terrain` and `--steer` specifications. Every value is checked when it is parsed, so
//! a bad one is a one-line error naming the option.

use super::super::args;
use afsv_design::vehicle_case::TerrainChoice;
use afsv_dynamics::SteerInput;
use terrain_psd::IsoClass;
use vehicle_3d::scenarios::TerrainSpec;

/// Help of `--paper-form` (the vehicle commands and `afsv evaluate`).
pub(crate) const PAPER_FORM_HELP: &str = "Use the printed Eq 3.13 yaw inertias (m L² counted twice) instead of the energy-consistent equations, to reproduce the dissertation's lower yaw frequency; for comparison with the paper, never for design (docs/vehicle-3d.md)";

/// Largest number of terrain seeds of one command.
pub(super) const MAX_SEEDS: usize = 1000;

/// Highest speed the options accept (km/h): above the truck's top speed.
pub(super) const MAX_SPEED_KMH: f64 = 80.0;

/// Longest simulated time of one run (s).
pub(super) const MAX_DURATION_S: f64 = 600.0;

/// Largest steering-wheel angle of the options (deg), also where a `--steer ramp` without
/// a limit holds: the roll scenario's hold angle, far beyond the rear unit's rollover.
const MAX_STEER_DEG: f64 = 1000.0;

/// Range of steering-wheel ramp rates (deg/s): slower ramps do not reach rollover within
/// the longest run, faster ones are steps.
const RAMP_RATE_DEG_S: (f64, f64) = (0.01, 1000.0);

/// A speed in km/h within (0, [`MAX_SPEED_KMH`]].
pub(super) fn speed_kmh(s: &str) -> Result<f64, String> {
    let v = args::positive_f64(s)?;
    if v <= MAX_SPEED_KMH {
        Ok(v)
    } else {
        Err(format!("must be at most {MAX_SPEED_KMH} km/h"))
    }
}

/// A seed count within 1..=[`MAX_SEEDS`].
pub(super) fn seed_count(s: &str) -> Result<usize, String> {
    let n: usize = s
        .trim()
        .parse()
        .map_err(|_| format!("`{}` is not a whole number", s.trim()))?;
    if (1..=MAX_SEEDS).contains(&n) {
        Ok(n)
    } else {
        Err(format!("must be 1 to {MAX_SEEDS}"))
    }
}

/// A steering-wheel ramp rate within [`RAMP_RATE_DEG_S`] (deg/s).
pub(super) fn ramp_rate(s: &str) -> Result<f64, String> {
    let v = args::positive_f64(s)?;
    let (lo, hi) = RAMP_RATE_DEG_S;
    if (lo..=hi).contains(&v) {
        Ok(v)
    } else {
        Err(format!("must be {lo} to {hi} deg/s"))
    }
}

/// A steering-wheel angle within (0, [`MAX_STEER_DEG`]] (deg).
pub(super) fn steer_peak(s: &str) -> Result<f64, String> {
    let v = args::positive_f64(s)?;
    if v <= MAX_STEER_DEG {
        Ok(v)
    } else {
        Err(format!("must be at most {MAX_STEER_DEG} deg"))
    }
}

/// A duration within (0, [`MAX_DURATION_S`]] s.
pub(super) fn duration_s(s: &str) -> Result<f64, String> {
    let v = args::positive_f64(s)?;
    if v <= MAX_DURATION_S {
        Ok(v)
    } else {
        Err(format!("must be at most {MAX_DURATION_S} s"))
    }
}

/// Parse `smooth`, `flat` or `class:E,mc:0.3[,seed:N]` (keys in any order; a missing class
/// is E, a missing m_c 0.3, the section 6.4 terrain).
pub(super) fn terrain_arg(s: &str) -> Result<TerrainChoice, String> {
    let s = s.trim();
    if s == "smooth" || s == "flat" {
        return Ok(TerrainChoice {
            spec: None,
            seed: None,
        });
    }
    let mut spec = TerrainSpec::default();
    let (mut class, mut mc, mut seed) = (None, None, None);
    for part in s.split(',') {
        let (key, value) = part.split_once(':').ok_or_else(|| {
            format!("`{part}` is not KEY:VALUE (expected smooth, flat or class:E,mc:0.3[,seed:N])")
        })?;
        let (key, value) = (key.trim(), value.trim());
        let twice = |k: &str| format!("`{k}` is given twice");
        match key {
            "class" => {
                if class.is_some() {
                    return Err(twice(key));
                }
                class =
                    Some(value.parse::<IsoClass>().map_err(|_| {
                        format!("class `{value}`: expected an ISO 8608 class A to H")
                    })?);
            }
            "mc" => {
                if mc.is_some() {
                    return Err(twice(key));
                }
                mc = Some(args::positive_f64(value).map_err(|e| format!("mc `{value}`: {e}"))?);
            }
            "seed" => {
                if seed.is_some() {
                    return Err(twice(key));
                }
                seed = Some(
                    value
                        .parse::<u64>()
                        .map_err(|_| format!("seed `{value}`: expected a whole number"))?,
                );
            }
            _ => return Err(format!("unknown key `{key}` (known: class, mc, seed)")),
        }
    }
    if let Some(c) = class {
        spec.class = c;
    }
    if let Some(m) = mc {
        spec.m_c = m;
    }
    Ok(TerrainChoice {
        spec: Some(spec),
        seed,
    })
}

/// Parse a `--steer` number whose magnitude is at most `max`.
fn steer_number(what: &str, s: &str, max: f64) -> Result<f64, String> {
    let v = args::finite_f64(s).map_err(|e| format!("--steer {what} `{}`: {e}", s.trim()))?;
    if v.abs() <= max {
        Ok(v)
    } else {
        Err(format!(
            "--steer {what} `{}`: must be at most {max} in magnitude",
            s.trim()
        ))
    }
}

/// Parse `--steer`: `pulse:DEG,DUR_S,START_S`, `ramp:DEG_PER_S,START_S[,LIMIT_DEG]`, `none`.
pub(super) fn steer_input(spec: &str) -> Result<SteerInput, String> {
    let spec = spec.trim();
    let usage = || {
        format!(
            "--steer `{spec}` not understood (expected pulse:DEG,DUR_S,START_S, ramp:DEG_PER_S,START_S[,LIMIT_DEG] or none)"
        )
    };
    if spec == "none" {
        return Ok(SteerInput::None);
    }
    let (kind, rest) = spec.split_once(':').ok_or_else(usage)?;
    let parts: Vec<&str> = rest.split(',').collect();
    let input = match (kind, parts.as_slice()) {
        ("pulse", [a, d, t0]) => SteerInput::pulse_deg(
            steer_number("pulse peak", a, MAX_STEER_DEG)?,
            steer_number("pulse duration", d, MAX_DURATION_S)?,
            steer_number("pulse start", t0, MAX_DURATION_S)?,
        ),
        ("ramp", [r, t0, rest @ ..]) if rest.len() <= 1 => {
            let rate = steer_number("ramp rate", r, RAMP_RATE_DEG_S.1)?;
            if rate.abs() < RAMP_RATE_DEG_S.0 {
                return Err(format!(
                    "--steer ramp rate `{r}`: must be at least {} deg/s in magnitude",
                    RAMP_RATE_DEG_S.0
                ));
            }
            SteerInput::Ramp {
                rate_rad_s: rate.to_radians(),
                start_s: steer_number("ramp start", t0, MAX_DURATION_S)?,
                limit_rad: match rest {
                    [l] => steer_number("ramp limit", l, MAX_STEER_DEG)?
                        .abs()
                        .to_radians(),
                    _ => MAX_STEER_DEG.to_radians(),
                },
            }
        }
        _ => return Err(usage()),
    };
    input.validate().map_err(|e| format!("--steer: {e}"))?;
    Ok(input)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The largest accepted values (a run at each would take minutes; the refusals just
    /// above them are checked through the binary, tests/cli_vehicle.rs).
    #[test]
    fn bounded_options_accept_their_limits() {
        assert_eq!(seed_count("1000").unwrap(), 1000);
        assert!(duration_s("600").is_ok());
        assert!(ramp_rate("0.01").is_ok() && ramp_rate("1000").is_ok());
        assert!(steer_peak("1000").is_ok());
    }
}
