//! A vehicle's HPS struts over a working shift: their gas and body temperatures and the ride
//! height and stiffness these set, without and with a levelling valve
//! (`hps_emulsion::thermal`, docs/layouts.md "HPS temperature and ride height"; `afsv hps
//! thermal`).
//!
//! Each suspended axle's strut carries its static load from the hand statics of
//! [`vehicle_3d::Statics`] (tire load less the wheel end); the strut's thermal data are
//! [`ThermalParams::for_strut`]'s; the heat input is given, read from a D1 ride of the vehicle
//! (each strut's recorded travel replayed through it) or from a simulated harmonic stroke of
//! the strut.

use hps_emulsion::{
    mean_dissipation_w, run_harmonic, HarmonicTest, HpsError, HpsExtensions, LevellingValve,
    SimOptions, StrutParams, ThermalConditions, ThermalParams, ThermalRecord, ThermalStrut,
};
use vehicle_3d::scenarios::{RideSpec, RUN_IN_M};
use vehicle_3d::{FrontAxle, Load, Statics, VehicleParams};

use crate::DesignError;

/// Where each strut's mean damping dissipation comes from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum HeatInput {
    /// Given (W), the same for every strut.
    Given(f64),
    /// A D1 ride of the vehicle (class E) at this speed (km/h) on this terrain seed: each
    /// strut's recorded travel after the run-in replayed through it, left and right averaged.
    Ride {
        /// Speed (km/h), in (0, 80].
        speed_kmh: f64,
        /// Terrain seed.
        seed: u64,
    },
    /// A simulated harmonic stroke of each strut about mid-stroke.
    Stroke {
        /// Frequency (Hz).
        frequency_hz: f64,
        /// Amplitude (m).
        amplitude_m: f64,
    },
}

/// The shift: conditions, length, the levelling valve and the heat input.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShiftSpec {
    /// Load case whose static strut loads are carried.
    pub load: Load,
    /// Also a rear strut when the vehicle's rear axle is rigid: the front strut scaled for
    /// the rear static load ([`VehicleParams::default_rear_strut`]).
    pub with_rear: bool,
    /// Ambient temperature (K).
    pub ambient_k: f64,
    /// Temperature at which the gas was charged and the ride height set (K).
    pub charge_k: f64,
    /// Strut temperature at the start of the shift (K).
    pub start_k: f64,
    /// Length of the shift (s).
    pub duration_s: f64,
    /// Output interval (s).
    pub step_s: f64,
    /// The levelling valve of the levelled runs.
    pub valve: LevellingValve,
    /// The heat input.
    pub heat: HeatInput,
}

/// One suspended axle's strut over the shift, without and with levelling.
#[derive(Debug, Clone)]
pub struct AxleShift {
    /// `front` or `rear`.
    pub axle: &'static str,
    /// The loaded strut.
    pub strut: ThermalStrut,
    /// Its mean damping dissipation (W).
    pub power_w: f64,
    /// Where that came from, in words.
    pub power_source: String,
    /// The shift without levelling.
    pub drift: ThermalRecord,
    /// The shift with the levelling valve.
    pub levelled: ThermalRecord,
}

impl AxleShift {
    /// The strut's parameter set at the end of the shift, without levelling or (`levelled`)
    /// with the valve: [`ThermalStrut::strut_at`] at the last gas and body temperatures and
    /// levelled oil volume of that run (the strut file of `afsv hps thermal --strut-out`
    /// and `--strut-out-levelled`).
    pub fn end_strut(&self, levelled: bool) -> Result<StrutParams, HpsError> {
        let rec = if levelled {
            &self.levelled
        } else {
            &self.drift
        };
        let n = rec.time_s.len() - 1;
        self.strut
            .strut_at(rec.gas_k[n], rec.body_k[n], rec.levelled_m3[n])
    }
}

/// A strut that cannot carry its axle's static load within its travel: it rests on an end
/// stop, where the ride height does not drift.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AxleOnStop {
    /// `front` or `rear`.
    pub axle: &'static str,
    /// The static load it would carry (N).
    pub load_n: f64,
}

/// The shift of every suspended axle.
#[derive(Debug, Clone)]
pub struct Shift {
    /// The axles whose strut carries its load, front first.
    pub axles: Vec<AxleShift>,
    /// The axles whose strut rests on an end stop.
    pub on_stop: Vec<AxleOnStop>,
}

/// The shift of `params`' struts: its front strut `params.hps`, its rear strut if the rear
/// axle is suspended (or with [`ShiftSpec::with_rear`]). An error if no strut carries its
/// load.
pub fn strut_shift(params: &VehicleParams, spec: &ShiftSpec) -> Result<Shift, DesignError> {
    let sim = |e: String| DesignError::Simulation(e);
    let statics = Statics::of(params, spec.load).map_err(|e| sim(e.to_string()))?;
    let rear = match (&params.rear_hps, spec.with_rear) {
        (Some(r), _) => Some(*r),
        (None, true) => Some(
            params
                .default_rear_strut()
                .map_err(|e| sim(e.to_string()))?,
        ),
        (None, false) => None,
    };
    let mut axles = vec![("front", params.hps, statics.front_strut_force_n(params))];
    if let Some(r) = rear {
        axles.push(("rear", r, statics.rear_strut_force_n(params)));
    }
    // the ride's dissipation per strut, front then rear (read once for both axles)
    let ride = match spec.heat {
        HeatInput::Ride { speed_kmh, seed } => {
            let mut p = params.clone();
            p.rear_hps = rear;
            ride_powers(&p, spec.load, speed_kmh, seed)?
        }
        _ => [0.0; 2],
    };
    let mut shift = Shift {
        axles: Vec::with_capacity(axles.len()),
        on_stop: Vec::new(),
    };
    for (k, (axle, strut_params, load_n)) in axles.into_iter().enumerate() {
        let mut thermal = ThermalParams::for_strut(&strut_params)?;
        thermal.charge_temperature_k = spec.charge_k;
        let strut = match ThermalStrut::new(&strut_params, &thermal, load_n) {
            Ok(s) => s,
            // A strut scaled for the loaded rear axle tops out unloaded (docs/layouts.md,
            // "HPS on any axle"): on its end stop the ride height cannot drift.
            Err(HpsError::InvalidParameter {
                field: "load_n", ..
            }) => {
                shift.on_stop.push(AxleOnStop { axle, load_n });
                continue;
            }
            Err(e) => return Err(sim(format!("{axle} strut: {e}"))),
        };
        let (power_w, power_source) = match spec.heat {
            HeatInput::Given(p) => (p, "given".to_string()),
            HeatInput::Ride { speed_kmh, seed } => (
                ride[k],
                format!(
                    "D1 ride, class E, {speed_kmh} km/h, seed {seed}: the strut travel replayed through the strut, mean of left and right"
                ),
            ),
            HeatInput::Stroke {
                frequency_hz,
                amplitude_m,
            } => (
                stroke_power(&strut_params, frequency_hz, amplitude_m)?,
                format!(
                    "simulated harmonic stroke {frequency_hz} Hz, {} mm about mid-stroke (mean dissipated power)",
                    amplitude_m * 1e3
                ),
            ),
        };
        let cond = ThermalConditions {
            ambient_k: spec.ambient_k,
            power_w,
            initial_gas_k: spec.start_k,
            initial_body_k: spec.start_k,
        };
        let drift = strut.run(&cond, spec.duration_s, spec.step_s)?;
        let levelled =
            strut
                .clone()
                .with_levelling(spec.valve)?
                .run(&cond, spec.duration_s, spec.step_s)?;
        shift.axles.push(AxleShift {
            axle,
            strut,
            power_w,
            power_source,
            drift,
            levelled,
        });
    }
    if shift.axles.is_empty() {
        return Err(sim(
            "no strut of the vehicle carries its static load within its travel".into(),
        ));
    }
    Ok(shift)
}

/// Mean dissipated power (W) per strut, front then rear (0 without rear struts), in one D1
/// ride of `p` (front axle suspended) at `speed_kmh` on terrain `seed`: each strut's
/// recorded travel after the run-in replayed through it ([`mean_dissipation_w`]), left and
/// right averaged.
fn ride_powers(
    p: &VehicleParams,
    load: Load,
    speed_kmh: f64,
    seed: u64,
) -> Result<[f64; 2], DesignError> {
    let sim = |what: &str, e: String| DesignError::Simulation(format!("{what}: {e}"));
    if !(speed_kmh > 0.0 && speed_kmh <= 80.0) {
        return Err(DesignError::Invalid {
            field: "speed_kmh",
            value: speed_kmh,
            reason: "the ride's speed must lie in (0, 80] km/h",
        });
    }
    let spec = RideSpec {
        speed_kmh,
        ..RideSpec::d1(load, FrontAxle::Suspended)
    };
    let (rec, _) = vehicle_3d::scenarios::ride(p, &spec, seed)
        .map_err(|e| sim("the D1 ride", e.to_string()))?;
    let i0 = rec
        .t_s
        .partition_point(|&t| t < RUN_IN_M / (speed_kmh / 3.6));
    let time = &rec.t_s[i0..];
    let mean = |strut: &StrutParams, travel: &[Vec<f64>; 2]| -> Result<f64, DesignError> {
        let mut sum = 0.0;
        for side in travel {
            sum += mean_dissipation_w(strut, time, &side[i0..])
                .map_err(|e| sim("replaying the ride's strut travel", e.to_string()))?;
        }
        Ok(0.5 * sum)
    };
    let front = mean(&p.hps, &rec.hps_travel_m)?;
    let rear = match &p.rear_hps {
        Some(r) => mean(r, &rec.rear_hps_travel_m)?,
        None => 0.0,
    };
    Ok([front, rear])
}

/// Mean dissipated power (W) of `strut` in a harmonic stroke about mid-stroke: the last of
/// three cycles' `closed integral F dz` times the frequency.
fn stroke_power(strut: &StrutParams, hz: f64, amplitude_m: f64) -> Result<f64, DesignError> {
    let test = HarmonicTest {
        frequency_hz: hz,
        amplitude_m,
    };
    let (_, m) = run_harmonic(
        strut,
        &HpsExtensions::none(),
        &test,
        3.0,
        &SimOptions::default(),
    )
    .map_err(|e| DesignError::Simulation(format!("the harmonic stroke: {e}")))?;
    Ok(m.dissipated_energy_j * hz)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// With no heat, the struts at the charge temperature throughout and nothing to level,
    /// the front strut ends the shift as it began (to round-off).
    #[test]
    fn a_shift_without_heat_ends_with_the_strut_it_began_with() {
        let mut params = VehicleParams::nominal();
        params.hps = StrutParams::front_axle();
        let t = 300.0;
        let spec = ShiftSpec {
            load: Load::Loaded,
            with_rear: false,
            ambient_k: t,
            charge_k: t,
            start_k: t,
            duration_s: 3600.0,
            step_s: 60.0,
            valve: LevellingValve {
                deadband_m: 5e-3,
                time_constant_s: 30.0,
                max_flow_m3_s: 1e-4,
            },
            heat: HeatInput::Given(0.0),
        };
        let shift = strut_shift(&params, &spec).unwrap();
        let front = &shift.axles[0];
        assert_eq!(front.axle, "front");
        for levelled in [false, true] {
            let end = front.end_strut(levelled).unwrap();
            assert!(
                (end.p_h0 / params.hps.p_h0 - 1.0).abs() < 1e-9,
                "{levelled}"
            );
            assert!(
                (end.v_g0 / params.hps.v_g0 - 1.0).abs() < 1e-9,
                "{levelled}"
            );
        }
    }
}
