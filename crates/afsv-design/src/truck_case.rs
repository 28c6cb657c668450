//! The rigid truck of chapter 2 that `afsv roll` runs, and where: the truck of a parameter
//! file, a built-in or a description, with the settings chapter 2 does not state (ramp
//! rate, bump stops, cg height) applied ([`truck`]); one ramp-steer run to rollover on the
//! ground of its report ([`run_on`]: level, synthesised rough terrain or a measured road).

use crate::report::roll::Ground;
use crate::report::show;
use perf_measures::roll::SustainedPeriodParams;
use roll_truck::calibration::{calibrate_strut_spacing, Calibration};
use roll_truck::studies::{run_case, run_case_on_road, Run};
use roll_truck::{BuiltinTruck, RunOptions, SteerDirection, TruckParams};
use std::path::Path;
use terrain_psd::{CoherenceModel, PowerLawPsd, TwoTrackSpec};

/// Which truck: a parameter file, else a built-in, else a description of a rigid truck
/// (the calibrated built-in by default); the ramp rate and the bump stops of the run.
#[derive(Debug, Clone, Copy, Default)]
pub struct TruckSource<'a> {
    /// Truck parameter file (JSON, `afsv params dump truck`).
    pub params: Option<&'a Path>,
    /// Built-in truck.
    pub builtin: Option<BuiltinTruck>,
    /// Vehicle description of a rigid truck, or a built-in name.
    pub vehicle: Option<&'a Path>,
    /// Steering-wheel ramp rate (deg/s), replacing the set's.
    pub ramp_rate_deg_s: Option<f64>,
    /// The bump stops out of reach.
    pub no_bump_stops: bool,
}

impl TruckSource<'_> {
    /// Whether a truck was chosen: a parameter file, a built-in or a description.
    pub fn chosen(&self) -> bool {
        self.params.is_some() || self.builtin.is_some() || self.vehicle.is_some()
    }

    /// The truck's name in reports: the parameter file, the description or the built-in.
    pub fn name(&self) -> String {
        match (self.params, self.vehicle, self.builtin) {
            (Some(p), _, _) | (None, Some(p), _) => p.display().to_string(),
            (None, None, t) => t.unwrap_or(BuiltinTruck::Calibrated).name().to_string(),
        }
    }
}

/// The truck of `source` with its ramp rate and stops and an optional sprung cg height
/// (m) applied, validated (errors of a parameter file name the file).
pub fn truck(source: &TruckSource, cg_height_m: Option<f64>) -> Result<TruckParams, String> {
    let mut p: TruckParams = match (source.params, source.builtin, source.vehicle) {
        (Some(path), _, _) => crate::param_files::read(path)?,
        (None, Some(t), _) => t.params(),
        (None, None, Some(v)) => crate::described::truck(v)?.params,
        (None, None, None) => TruckParams::nominal(),
    };
    if let Some(h) = cg_height_m {
        p.cg_height_m = h;
    }
    if let Some(r) = source.ramp_rate_deg_s {
        p.steering_wheel_rate_deg_s = r;
    }
    if source.no_bump_stops {
        p = p.without_bump_stops();
    }
    p.validate().map_err(|e| match source.params {
        Some(path) => format!("{}: {e}", path.display()),
        None => e.to_string(),
    })?;
    Ok(p)
}

/// The trucks of the ramp and rule sensitivity (`roll_truck::sensitivity`), named: the
/// [`truck`] of `source` when one was chosen ([`TruckSource::chosen`]), else the calibrated
/// and the plausible built-in, without their bump stops when `source` says so.
pub fn sensitivity_trucks(source: &TruckSource) -> Result<Vec<(String, TruckParams)>, String> {
    if source.chosen() {
        return Ok(vec![(source.name(), truck(source, None)?)]);
    }
    let builtins = [BuiltinTruck::Calibrated, BuiltinTruck::Plausible].map(|b| {
        let mut p = b.params();
        if source.no_bump_stops {
            p = p.without_bump_stops();
        }
        (b.name().to_string(), p)
    });
    Ok(builtins.to_vec())
}

/// Strut spacing ratios the calibration searches (the roll-stable floor and the smooth-road
/// DRT target lie inside).
pub const CALIBRATION_RATIOS: (f64, f64) = (0.15, 0.6);

/// Tolerance of the calibrated smooth-road DRT (g).
pub const CALIBRATION_TOL_G: f64 = 1e-4;

/// The strut spacing ratio of the truck of `source` whose smooth-road DRT is `target_g`,
/// among the roll-stable ratios in [`CALIBRATION_RATIOS`]
/// (`roll_truck::calibration::calibrate_strut_spacing`).
pub fn calibrate(source: &TruckSource, target_g: f64) -> Result<Calibration, String> {
    let p = truck(source, None)?;
    calibrate_strut_spacing(&p, CALIBRATION_RATIOS, target_g, CALIBRATION_TOL_G)
        .map_err(|e| e.to_string())
}

/// The detection rule of the sustained period (not given in chapter 2): the defaults
/// (`perf_measures::roll`) with the LTR `threshold` and the longest `max_dip_s` below it
/// replaced when given, validated.
pub fn sustained_period(
    threshold: Option<f64>,
    max_dip_s: Option<f64>,
) -> Result<SustainedPeriodParams, String> {
    let mut sp = SustainedPeriodParams::default();
    if let Some(t) = threshold {
        sp.threshold = t;
    }
    if let Some(d) = max_dip_s {
        sp.max_dip_s = d;
    }
    sp.validate()
        .map_err(|e| format!("--sp-threshold/--sp-max-dip: {e}"))?;
    Ok(sp)
}

/// Longest simulated time of one run (s).
pub const MAX_DURATION_S: f64 = 3600.0;

/// The settings of a run of `t_end_s` (s), at most [`MAX_DURATION_S`], sampled every
/// `dt` (s), with the acceleration channels its measures report.
pub fn run_options(t_end_s: f64, dt: f64) -> Result<RunOptions, String> {
    if t_end_s > MAX_DURATION_S {
        return Err(format!(
            "--duration {}: at most {MAX_DURATION_S} s",
            show(t_end_s)
        ));
    }
    Ok(RunOptions {
        t_end_s,
        output_dt_s: dt,
        acceleration_channels: true,
        ..RunOptions::default()
    })
}

/// One ramp-steer run of `p` to rollover in `direction` on `ground` (a measured road must
/// cover the run; errors name its file), with the sustained-period rule `sp`.
pub fn run_on(
    p: &TruckParams,
    ground: &Ground,
    direction: SteerDirection,
    options: &RunOptions,
    sp: &SustainedPeriodParams,
) -> Result<Run, String> {
    let spec = match *ground {
        Ground::Road(file) => {
            let half = roll_truck::studies::half_track_m(p);
            let (profile, _) = crate::measured_road::read(file, half)?;
            return run_case_on_road(p, profile, direction, options, sp)
                .map_err(|e| format!("{}: {e}", file.display()));
        }
        Ground::Level => {
            return run_case(p, None, 0, direction, options, sp).map_err(|e| e.to_string())
        }
        Ground::Rough {
            class,
            waviness,
            band,
            m_c,
            seed,
        } => {
            let psd = PowerLawPsd::new(class.alpha_r(), waviness).map_err(|e| e.to_string())?;
            let coherence = CoherenceModel::piecewise(m_c).map_err(|e| e.to_string())?;
            let spec = TwoTrackSpec::new(psd, band, coherence).map_err(|e| e.to_string())?;
            (spec, seed)
        }
    };
    run_case(p, Some(&spec.0), spec.1, direction, options, sp).map_err(|e| e.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_rule_takes_the_given_values() {
        let d = SustainedPeriodParams::default();
        assert_eq!(sustained_period(None, None).unwrap(), d);
        let sp = sustained_period(Some(0.9), Some(0.2)).unwrap();
        assert_eq!((sp.threshold, sp.max_dip_s), (0.9, 0.2));
        assert!(sustained_period(None, Some(-1.0)).is_err());
    }

    #[test]
    fn the_truck_is_chosen_and_adjusted() {
        let nominal = TruckSource::default();
        assert_eq!(nominal.name(), BuiltinTruck::Calibrated.name());
        assert_eq!(truck(&nominal, None).unwrap(), TruckParams::nominal());
        let adjusted = TruckSource {
            builtin: Some(BuiltinTruck::Plausible),
            ramp_rate_deg_s: Some(2.5),
            ..TruckSource::default()
        };
        let p = truck(&adjusted, Some(2.0)).unwrap();
        assert_eq!((p.cg_height_m, p.steering_wheel_rate_deg_s), (2.0, 2.5));
        assert!(truck(&nominal, Some(-1.0)).is_err());
        let described = TruckSource {
            vehicle: Some(Path::new("chapter2-truck")),
            ..TruckSource::default()
        };
        assert_eq!(described.name(), "chapter2-truck");
        assert!(truck(&described, None).is_ok());
        assert!(described.chosen() && adjusted.chosen() && !nominal.chosen());
    }

    #[test]
    fn a_run_lasts_at_most_an_hour() {
        let o = run_options(3600.0, 0.01).unwrap();
        assert_eq!(
            (o.t_end_s, o.output_dt_s, o.acceleration_channels),
            (3600.0, 0.01, true)
        );
        assert_eq!(
            run_options(3600.5, 0.01).unwrap_err(),
            "--duration 3600.5: at most 3600 s"
        );
    }

    /// The derivation of the built-in constant: the calibrated truck's own ratio.
    #[test]
    fn the_calibration_finds_the_builtin_ratio() {
        let c = calibrate(&TruckSource::default(), 0.279).unwrap();
        let builtin = roll_truck::calibration::CALIBRATED_STRUT_SPACING_RATIO;
        assert!((c.strut_spacing_ratio - builtin).abs() < 1e-3, "{c:?}");
        let missing = TruckSource {
            params: Some(Path::new("no-such-truck.json")),
            ..TruckSource::default()
        };
        assert!(calibrate(&missing, 0.279)
            .unwrap_err()
            .contains("no-such-truck.json"));
    }

    #[test]
    fn the_sensitivity_runs_the_chosen_truck_or_both_builtins() {
        let both = sensitivity_trucks(&TruckSource::default()).unwrap();
        let names: Vec<&str> = both.iter().map(|t| t.0.as_str()).collect();
        assert_eq!(names, ["calibrated", "plausible"]);
        assert_eq!(both[1].1, BuiltinTruck::Plausible.params());
        let stopless = TruckSource {
            no_bump_stops: true,
            ..TruckSource::default()
        };
        let free = sensitivity_trucks(&stopless).unwrap();
        assert_eq!(
            free[0].1,
            BuiltinTruck::Calibrated.params().without_bump_stops()
        );
        let one = TruckSource {
            builtin: Some(BuiltinTruck::Plausible),
            ..TruckSource::default()
        };
        let one = sensitivity_trucks(&one).unwrap();
        assert_eq!((one.len(), one[0].0.as_str()), (1, "plausible"));
    }
}
