//! The shift `afsv hps thermal` runs, from its options in the units a user gives them
//! (degC, hours, minutes, mm, L/min): the described vehicle with its front-axle strut, the
//! levelling valve, where the struts' heat comes from, and the conditions the report
//! states (`crate::strut_shift`, docs/layouts.md "HPS temperature and ride height").

use crate::report::show;
use crate::report::strut_shift::ShiftConditions;
use crate::sample_bounds::{check_samples, MAX_HPS_SAMPLES};
use crate::strut_shift::{HeatInput, ShiftSpec};
use afsv_vehicle::ArticulatedVehicle;
use hps_emulsion::thermal::KELVIN_AT_0C;
use hps_emulsion::LevellingValve;
use vehicle_3d::{Load, VehicleParams};

/// The options of a shift, as given.
#[derive(Debug, Clone, Copy)]
pub struct ShiftOptions {
    /// Load case whose static strut loads are carried.
    pub load: Load,
    /// Also a rear strut when the rear axle is rigid (the front strut scaled).
    pub with_rear: bool,
    /// Ambient temperature (degC).
    pub ambient_c: f64,
    /// Temperature at which the gas was charged and the ride height set (degC).
    pub charge_c: f64,
    /// Strut temperature at the start (degC); default the ambient.
    pub start_c: Option<f64>,
    /// Mean damping dissipation of each strut (W), if given.
    pub power_w: Option<f64>,
    /// The dissipation from a D1 ride at this speed (km/h) on this terrain seed.
    pub ride: Option<(f64, u64)>,
    /// Else from a harmonic stroke of this frequency (Hz) and amplitude (mm).
    pub stroke: (f64, f64),
    /// Length of the shift (h).
    pub hours: f64,
    /// Time between table rows (min).
    pub step_min: f64,
    /// The levelling valve: deadband half width (mm), time constant (s), largest flow
    /// (L/min).
    pub valve: (f64, f64, f64),
}

/// Longest shift (h).
pub const MAX_HOURS: f64 = 72.0;

/// Highest speed of the ride that sets the dissipation (km/h).
pub const MAX_RIDE_SPEED_KMH: f64 = 80.0;

impl ShiftOptions {
    /// The shift's size before anything runs: at most [`MAX_HOURS`], a ride of at most
    /// [`MAX_RIDE_SPEED_KMH`], at most [`MAX_HPS_SAMPLES`] table rows; errors name the
    /// options.
    pub fn check_size(&self) -> Result<(), String> {
        if self.hours > MAX_HOURS {
            return Err(format!("--hours {}: at most {MAX_HOURS}", show(self.hours)));
        }
        if let Some((speed_kmh, _)) = self.ride.filter(|r| r.0 > MAX_RIDE_SPEED_KMH) {
            return Err(format!("--speed-kmh {}: at most 80", show(speed_kmh)));
        }
        check_samples(
            &format!("--step-min {}", show(self.step_min)),
            &format!("--hours {} * 60 / --step-min", show(self.hours)),
            self.hours * 3600.0 / (self.step_min * 60.0),
            MAX_HPS_SAMPLES,
        )
    }
}

/// The vehicle `v` with its front-axle strut (a description without one is refused), the
/// shift `o` defines in SI units, and the conditions its report states; the valve is
/// checked.
pub fn shift_case(
    v: &ArticulatedVehicle,
    o: &ShiftOptions,
) -> Result<(VehicleParams, ShiftSpec, ShiftConditions), String> {
    let mut params = v.params.clone();
    params.hps = v.front_strut.ok_or_else(|| {
        format!(
            "--vehicle: `{}` gives the front axle no strut (add `strut = \"front-axle\"` or a strut file to its front [[axle]])",
            v.name
        )
    })?;
    let (deadband_mm, tau_s, flow_l_min) = o.valve;
    let valve = LevellingValve {
        deadband_m: deadband_mm * 1e-3,
        time_constant_s: tau_s,
        max_flow_m3_s: flow_l_min * 1e-3 / 60.0,
    };
    valve
        .validate()
        .map_err(|e| format!("--deadband-mm, --levelling-tau-s, --levelling-flow-l-min: {e}"))?;
    let heat = match (o.power_w, o.ride) {
        (Some(p), _) => HeatInput::Given(p),
        (None, Some((speed_kmh, seed))) => HeatInput::Ride { speed_kmh, seed },
        (None, None) => HeatInput::Stroke {
            frequency_hz: o.stroke.0,
            amplitude_m: o.stroke.1 * 1e-3,
        },
    };
    let start_c = o.start_c.unwrap_or(o.ambient_c);
    let spec = ShiftSpec {
        load: o.load,
        with_rear: o.with_rear,
        ambient_k: KELVIN_AT_0C + o.ambient_c,
        charge_k: KELVIN_AT_0C + o.charge_c,
        start_k: KELVIN_AT_0C + start_c,
        duration_s: o.hours * 3600.0,
        step_s: o.step_min * 60.0,
        valve,
        heat,
    };
    let conditions = ShiftConditions {
        load: o.load,
        ambient_c: o.ambient_c,
        charge_c: o.charge_c,
        start_c,
        hours: o.hours,
    };
    Ok((params, spec, conditions))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_size_of_a_shift_is_bounded() {
        let o = ShiftOptions {
            load: Load::Loaded,
            with_rear: false,
            ambient_c: 20.0,
            charge_c: 20.0,
            start_c: None,
            power_w: None,
            ride: Some((80.0, 1)),
            stroke: (1.0, 10.0),
            hours: 72.0,
            step_min: 30.0,
            valve: (5.0, 30.0, 6.0),
        };
        assert!(o.check_size().is_ok());
        let long = ShiftOptions { hours: 72.5, ..o };
        assert_eq!(long.check_size().unwrap_err(), "--hours 72.5: at most 72");
        let fast = ShiftOptions {
            ride: Some((81.0, 1)),
            ..o
        };
        assert_eq!(fast.check_size().unwrap_err(), "--speed-kmh 81: at most 80");
        let fine = ShiftOptions {
            step_min: 1e-4,
            ..o
        };
        assert!(fine
            .check_size()
            .unwrap_err()
            .starts_with("--step-min 0.0001"));
    }

    #[test]
    fn the_options_in_si_units() {
        let v = crate::described::articulated(None).unwrap();
        let o = ShiftOptions {
            load: Load::Loaded,
            with_rear: false,
            ambient_c: 20.0,
            charge_c: 10.0,
            start_c: None,
            power_w: None,
            ride: None,
            stroke: (1.0, 10.0),
            hours: 2.0,
            step_min: 30.0,
            valve: (5.0, 30.0, 6.0),
        };
        let (p, spec, c) = shift_case(&v, &o).unwrap();
        assert_eq!(p.hps, v.front_strut.unwrap());
        assert_eq!((spec.duration_s, spec.step_s), (7200.0, 1800.0));
        assert_eq!(spec.start_k, KELVIN_AT_0C + 20.0);
        assert_eq!(c.start_c, 20.0);
        assert!(matches!(spec.heat, HeatInput::Stroke { amplitude_m, .. } if amplitude_m == 0.01));
        let ride = ShiftOptions {
            ride: Some((20.0, 3)),
            ..o
        };
        assert!(matches!(
            shift_case(&v, &ride).unwrap().1.heat,
            HeatInput::Ride { seed: 3, .. }
        ));
        let bad_valve = ShiftOptions {
            valve: (5.0, -1.0, 6.0),
            ..o
        };
        let Err(e) = shift_case(&v, &bad_valve) else {
            panic!("a valve with a negative time constant was accepted");
        };
        assert!(e.starts_with("--deadband-mm"), "{e}");
    }
}
