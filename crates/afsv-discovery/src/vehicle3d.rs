//! The integrated 3-D vehicle of Chapter 6 (crate `vehicle-3d`) as a [`DiscoveryModel`]:
//! ride runs with the 6-axis sensor (the D1 set-up, straight on two-track class C or E
//! ground) and the V3 path change (steering, articulation, strut, pressure and yaw-rate
//! channels), in the afsv-v1 records `afsv vehicle simulate -o` and `afsv vehicle
//! path-change -o` write (docs/records.md, docs/vehicle-3d.md).
//!
//! Baseline: the paper's 3-D model as those commands run it. Each record is replayed on its
//! own conditions: the load and front axle of its sidecar, the terrain its sidecar names
//! (class, coherence, band and seed: the same road, rebuilt), its speed, and for a path
//! change its recorded steering-wheel angle (open loop: the replay does not re-drive the
//! course). Calibrated: parameters the paper leaves unstated for the 3-D vehicle
//! ([`CALIBRATED`], named by the vehicle-3d registry and the tire and strut registries).
//! One calibration switch ([`SWITCHES`]): where the tandem cams stand (section 6.2.2). The
//! catalogue ([`crate::vehicle3d_effects`]) holds section 6.3's suspects.

use super::{
    ActiveEffect, DiscoveryError, DiscoveryModel, EffectSpec, LawSwitch, ParamSpec, Phase,
};
use crate::vehicle3d_effects::{catalogue, SensorEffects, ANGULAR_AXES, EFFECTS, LINEAR_AXES};
use afsv_dynamics::SteerInput;
use afsv_records::Record;
use hps_emulsion::HeatTransfer;
use serde_json::Value;
use std::sync::{Arc, Mutex};
use vehicle_3d::scenarios::TerrainSpec;
use vehicle_3d::{
    CamSpacing, FieldEffects, FrontAxle, Load, RunOptions, SpeedSetpoint, TireTracks, Vehicle,
    VehicleOptions, VehicleParams,
};
use vehicle_components::FlatTerrain;

mod cache;
mod registry_paths;
mod sidecar;
mod throttle;
use cache::{Channels, FOLLOW_KEY, GAIN_KEY, READING_KEY};
pub use cache::{ReplayCache, CACHE_ENTRIES};
pub use registry_paths::{assign, value};
use sidecar::{meta, terrain_of};
pub use throttle::{drive_error, local_quadratic, throttle_setpoint, throttle_target};

/// Channels the 3-D model predicts (afsv-v1 names). Ride records are compared on the speed
/// and the six sensor axes; path changes also on the steering channels.
pub const CHANNELS: [&str; 13] = [
    "speed_m_s",
    "articulation_deg",
    "strut_left_disp_m",
    "p_c_pa",
    "p_r_pa",
    "yaw_rate_front_deg_s",
    "front_lateral_accel_m_s2",
    LINEAR_AXES[0],
    LINEAR_AXES[1],
    LINEAR_AXES[2],
    ANGULAR_AXES[0],
    ANGULAR_AXES[1],
    ANGULAR_AXES[2],
];

/// Channels of [`CHANNELS`] compared on ride records only: the speed and the six axes.
const RIDE_CHANNELS: usize = 0b1_1111_1000_0001;

/// The calibrated parameters: registry paths (`tire.` and `hps.` prefix the tire's and the
/// strut's own registries), each one's calibration window and why it is uncertain. The
/// last one only with the front-axle HPS. Every entry is a value the paper does not state
/// (Chapter 6, Tables 6.1-6.3; the project's assumptions of docs/vehicle-3d.md).
pub const CALIBRATED: [(&str, f64, f64, &str); 8] = [
    ("joint_height_m", 0.6, 1.6, "not in Table 6.1; 1.0 m assumed (docs/vehicle-3d.md)"),
    ("drive.kp_n_m_per_m_s", 3_000.0, 27_000.0, "the PI speed gains are not given; 9 kN m/(m/s) assumed"),
    ("tire.vertical_damping_n_s_per_m", 1.0e4, 1.0e5, "Table 6.2 gives no tire damping; 35 kN s/m assumed"),
    ("tire.longitudinal_relaxation_length_m", 0.3, 3.0, "only the lateral relaxation length is stated (1.2 m); the longitudinal one is assumed equal"),
    ("drive.ki_n_m_per_m", 0.0, 8_000.0, "the PI speed gains are not given; 2 kN m/m assumed"),
    ("tire.rolling_resistance_coefficient", 0.005, 0.06, "not in Table 6.2; 0.03 assumed"),
    ("wheel_spin_inertia_kg_m2", 300.0, 1_200.0, "wheel ends are not in Table 6.1; 600 kg m² assumed (tire, rim and in-wheel drive)"),
    ("hps.friction.f_c", 0.0, 5_000.0, "Table 5.1's friction constants are missing (HPS only)"),
];

/// The 3-D vehicle's calibration switches ([`DiscoveryModel::switches`]): name, readings
/// (the crate's default first) and where the paper is ambiguous.
pub const SWITCHES: [(&str, [&str; 2], &str); 1] = [(
    "cam-spacing",
    ["static", "instantaneous"],
    "section 6.2.2, Eqs 6.1-6.3: the tandem cams stand at the half contact length of the deflected tire, which depends on the deflection; the paper does not say whether at the static or the instantaneous one (vehicle_3d::CamSpacing)",
)];

/// The cam spacing of reading `index` of `cam-spacing` ([`SWITCHES`]).
pub fn cam_spacing(index: usize) -> Result<CamSpacing, DiscoveryError> {
    match index {
        0 => Ok(CamSpacing::Static),
        1 => Ok(CamSpacing::Instantaneous),
        _ => Err(DiscoveryError::NoSuchReading {
            switch: SWITCHES[0].0,
            index,
        }),
    }
}

/// Entries of [`CALIBRATED`] a rigid front axle calibrates (all but the HPS friction).
const RIGID_CALIBRATED: usize = 7;

/// Relative tolerance of the replays: the fits difference outputs over parameter steps of
/// 1e-3, so the integrator's jitter must stay well below what such a step changes
/// (docs/discovery.md "Integration tolerance"); the scenario default is 3e-5.
pub const REPLAY_RTOL: f64 = 1e-6;

/// Relative tolerance of the replays with the front-axle HPS: the strut's gas law moves the
/// compared channels so little that at 1e-6 the integrator's jitter is of the size of what a
/// 1e-3 step of the gas time constant changes (docs/discovery.md, "The 3-D vehicle"), and
/// the fits of `hps-gas-temperature` stop where they start.
pub const REPLAY_RTOL_HPS: f64 = 1e-7;

/// Scouting replays ([`DiscoveryModel::coarse`]) run at this multiple of the model's
/// tolerance ([`Vehicle3dModel::rtol`]): 1e-5 for the rigid axle, 1e-6 with the HPS, about
/// half the cost of a replay. Scouting only ranks start points and candidates and takes six
/// iterations from each; every fit to convergence, polish and score replays at the model's
/// tolerance, from the scouted point (a continuation in tolerance). At 1e-5 a calibration
/// from the nominal values stalled far from the optimum (docs/discovery.md, "The 3-D
/// vehicle"), which is why the fits themselves do not run there.
pub const SCOUT_RTOL_FACTOR: f64 = 10.0;

/// Half width of the local quadratic fit ([`local_quadratic`]) of the recorded speed that
/// `driver-throttle` follows (s): a driver's throttle moves the speed over seconds; the
/// faster fluctuations are the terrain's, which the replay produces itself (and which the
/// correction replay of [`Vehicle3dModel::following_setpoint`] takes out of what is followed).
pub const THROTTLE_SMOOTH_S: f64 = 0.5;

/// Leading samples left out of every comparison (s): the replay starts at the static
/// equilibrium at speed, a measured run does not.
pub const SKIP_S: f64 = 0.5;

/// The 3-D vehicle for the discovery workflow.
#[derive(Debug, Clone)]
pub struct Vehicle3dModel {
    /// Reference parameters (Table 6.1 and the documented assumptions).
    pub params: VehicleParams,
    /// Front axle of every record (a record whose sidecar names the other one is refused).
    pub front_axle: FrontAxle,
    /// Load of records whose sidecar states none.
    pub default_load: Option<Load>,
    /// Relative tolerance of the replays.
    pub rtol: f64,
}

/// What a record is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RunKind {
    /// Straight run on the record's ground.
    Ride,
    /// The V3 path change, replayed with its recorded steering-wheel angle.
    PathChange,
}

/// A record prepared for replay.
#[derive(Debug, Clone)]
pub struct Replay3d {
    /// Ride or path change.
    pub kind: RunKind,
    /// Load case.
    pub load: Load,
    /// The drive's setpoint (m/s): the sidecar's target speed, else the mean of the record.
    pub speed_m_s: f64,
    /// Steering-wheel input (path change), `SteerInput::None` for a ride.
    pub steer: SteerInput,
    /// Path length of the run (m), as the commands lay it out.
    pub path_length_m: f64,
    /// The enveloping cache of the record's ground, the cams at the static deflection.
    pub tracks: Arc<TireTracks>,
    /// The record's ground (class and seed; `None` for smooth ground), for the caches of
    /// the other cam spacing.
    pub ground: Option<(TerrainSpec, u64)>,
    /// The enveloping cache with the cams at the instantaneous deflection (reading
    /// `instantaneous` of `cam-spacing`), built on first use and shared with the scouting
    /// copy.
    pub instantaneous: Arc<Mutex<Option<Arc<TireTracks>>>>,
    /// Samples (from 0) and spacing (s).
    pub time_s: Vec<f64>,
    /// Sample spacing (s).
    pub dt_s: f64,
    /// Recorded speed smoothed over +-[`THROTTLE_SMOOTH_S`] and its rate (for
    /// `driver-throttle`).
    pub speed_smooth: (Vec<f64>, Vec<f64>),
    /// Conditions in words and the constancy-test group.
    pub condition: String,
    /// Constancy group: the run kind and the ground class.
    pub group: String,
    /// The last replays' vehicle-side channels by their vehicle-side inputs ([`ReplayCache`]).
    pub cache: ReplayCache,
    /// A scouting copy: replayed at [`SCOUT_RTOL_FACTOR`] times the model's tolerance.
    pub coarse: bool,
}

impl Vehicle3dModel {
    /// The paper's vehicle with a rigid front axle (the prototype) or the front-axle HPS.
    pub fn nominal(front_axle: FrontAxle) -> Self {
        Self {
            params: VehicleParams::nominal(),
            front_axle,
            default_load: None,
            rtol: match front_axle {
                FrontAxle::Rigid => REPLAY_RTOL,
                FrontAxle::Suspended => REPLAY_RTOL_HPS,
            },
        }
    }

    /// `vehicle-3d` (rigid front axle) or `vehicle-3d-hps`.
    pub fn model_name(&self) -> &'static str {
        match self.front_axle {
            FrontAxle::Rigid => "vehicle-3d",
            FrontAxle::Suspended => "vehicle-3d-hps",
        }
    }

    /// The entries of [`CALIBRATED`] this model calibrates.
    fn calibrated(&self) -> &'static [(&'static str, f64, f64, &'static str)] {
        match self.front_axle {
            FrontAxle::Rigid => &CALIBRATED[..RIGID_CALIBRATED],
            FrontAxle::Suspended => &CALIBRATED[..],
        }
    }

    /// `params` with the baseline vector applied by registry path.
    pub fn apply_baseline(&self, v: &[f64]) -> Result<VehicleParams, DiscoveryError> {
        let names = self.calibrated();
        if v.len() != names.len() {
            return Err(DiscoveryError::BaselineLength {
                expected: names.len(),
                got: v.len(),
            });
        }
        let mut p = self.params.clone();
        for (&(name, ..), &x) in names.iter().zip(v) {
            assign(&mut p, name, x)?;
        }
        Ok(p)
    }

    /// The vehicle options of a run, laid out as `afsv vehicle simulate` and `path-change`
    /// do (start at 10 m, path `speed * duration + 5 m`), with the field mechanisms `field`.
    pub fn layout(
        &self,
        speed_m_s: f64,
        steer: SteerInput,
        path_length_m: f64,
        field: FieldEffects,
    ) -> VehicleOptions {
        VehicleOptions {
            front_axle: self.front_axle,
            speed_m_s,
            steer,
            path_length_m,
            field,
            ..VehicleOptions::default()
        }
    }

    /// The vehicle options of a prepared record's run ([`Self::layout`]).
    pub fn options(&self, rec: &Replay3d, field: FieldEffects) -> VehicleOptions {
        self.layout(rec.speed_m_s, rec.steer.clone(), rec.path_length_m, field)
    }

    /// The enveloping cache of `load` on `ground` (`None`: smooth ground) for a run with
    /// `options`.
    fn build_tracks(
        &self,
        load: Load,
        options: &VehicleOptions,
        ground: Option<&(TerrainSpec, u64)>,
    ) -> Result<TireTracks, DiscoveryError> {
        let half = 0.5 * self.params.front_track_m;
        Ok(match ground {
            None => {
                let flat =
                    FlatTerrain::new(0.0, vehicle_components::DEFAULT_FRICTION).map_err(|e| {
                        DiscoveryError::Sidecar {
                            field: "terrain",
                            reason: e.to_string(),
                        }
                    })?;
                TireTracks::build(&self.params, load, options, &flat, half)?
            }
            Some((spec, seed)) => {
                let length = options.start_s_m + options.path_length_m + 50.0;
                let terrain = spec.build(&self.params, length, *seed)?;
                TireTracks::build(&self.params, load, options, &terrain, half)?
            }
        })
    }

    /// The enveloping cache of a prepared record with the cams at `spacing`: the static one
    /// prepared with the record, the instantaneous one built on first use.
    pub fn tracks(
        &self,
        rec: &Replay3d,
        spacing: CamSpacing,
    ) -> Result<Arc<TireTracks>, DiscoveryError> {
        if spacing == CamSpacing::Static {
            return Ok(rec.tracks.clone());
        }
        let mut slot = rec.instantaneous.lock().unwrap_or_else(|e| e.into_inner());
        if let Some(t) = slot.as_ref() {
            return Ok(t.clone());
        }
        let options = VehicleOptions {
            cam_spacing: spacing,
            ..self.options(rec, FieldEffects::default())
        };
        let t = Arc::new(self.build_tracks(rec.load, &options, rec.ground.as_ref())?);
        *slot = Some(t.clone());
        Ok(t)
    }

    /// Simulate a prepared record with full parameters, field mechanisms and the cams at
    /// `spacing`: one series per entry of [`CHANNELS`] (`None` where the kind is not
    /// compared), before the sensor effects ([`Self::apply_sensor`]).
    pub fn replay(
        &self,
        rec: &Replay3d,
        params: &VehicleParams,
        field: FieldEffects,
        spacing: CamSpacing,
    ) -> Result<Channels, DiscoveryError> {
        let v = Vehicle::on_tracks(
            params,
            rec.load,
            VehicleOptions {
                cam_spacing: spacing,
                ..self.options(rec, field)
            },
            self.tracks(rec, spacing)?,
        )?;
        let n = rec.time_s.len();
        let run = RunOptions {
            t_end_s: (n as f64 - 0.75) * rec.dt_s,
            output_dt_s: rec.dt_s,
            rtol: if rec.coarse {
                SCOUT_RTOL_FACTOR * self.rtol
            } else {
                self.rtol
            },
            ..RunOptions::default()
        };
        let out = vehicle_3d::simulate(&v, &run)?;
        let ch: Channels = CHANNELS
            .iter()
            .enumerate()
            .map(|(i, name)| {
                (rec.kind == RunKind::PathChange || RIDE_CHANNELS & (1 << i) != 0)
                    .then(|| out.afsv_v1_channel(name))
                    .flatten()
            })
            .collect();
        Ok(ch)
    }

    /// The setpoint under which the model follows the recorded speed of `rec`
    /// (`driver-throttle` at gain 1): [`throttle_setpoint`], corrected once by what a replay
    /// with it (`field` and that setpoint; cached under `key`) misses: with `d = w - y_s`
    /// (`w` the target of [`throttle_target`], `y_s` that replay's speed smoothed as the
    /// record's is), the setpoint becomes `set + d + e(d)` (`e` of [`drive_error`] for `d`'s
    /// rate). The correction takes out what the inversion does not know: the tires' slip
    /// lag, and the terrain's own speed fluctuations, which are in the record and in the
    /// replay alike. The replay's cams stand at `spacing`.
    pub fn following_setpoint(
        &self,
        rec: &Replay3d,
        params: &VehicleParams,
        mut field: FieldEffects,
        spacing: CamSpacing,
        key: Vec<u64>,
    ) -> Result<Vec<f64>, DiscoveryError> {
        let set = throttle_setpoint(params, rec);
        field.speed_setpoint = Some(SpeedSetpoint::new(rec.time_s.clone(), set.clone())?);
        let first = rec
            .cache
            .get_or(key, || self.replay(rec, params, field, spacing))?;
        let Some(Some(speed)) = first.first() else {
            return Ok(set);
        };
        let half = (THROTTLE_SMOOTH_S / rec.dt_s).round() as usize;
        let (y, y_rate) = local_quadratic(speed, half, rec.dt_s);
        let (w, w_rate) = throttle_target(rec);
        let d_rate: Vec<f64> = w_rate.iter().zip(&y_rate).map(|(a, b)| a - b).collect();
        let e = drive_error(params, rec.load, rec.dt_s, &d_rate);
        Ok((0..set.len())
            .map(|i| set[i] + (w[i] - y[i]) + e[i])
            .collect())
    }

    /// The sensor effects on replayed channels of `rec` (sampled at its spacing).
    pub fn apply_sensor(
        &self,
        rec: &Replay3d,
        gravity_m_s2: f64,
        sensor: SensorEffects,
        mut ch: Channels,
    ) -> Channels {
        let (lin, ang) = ch.split_at_mut(10);
        let mut linear = [lin[7].take(), lin[8].take(), lin[9].take()];
        let mut angular = [ang[0].take(), ang[1].take(), ang[2].take()];
        sensor.apply(rec.dt_s, gravity_m_s2, &mut linear, &mut angular);
        [lin[7], lin[8], lin[9]] = linear;
        [ang[0], ang[1], ang[2]] = angular;
        ch
    }

    /// The field mechanisms, the sensor effects and the lateral compliance (mm/kN) of the
    /// active effects (`driver-throttle`'s setpoint is not among them: it needs a replay,
    /// [`Self::following_setpoint`]).
    pub fn apply_effects(
        &self,
        effects: &[ActiveEffect<'_>],
    ) -> Result<(FieldEffects, SensorEffects, f64), DiscoveryError> {
        let (mut field, mut sensor, mut compliance) =
            (FieldEffects::default(), SensorEffects::default(), 0.0);
        for e in effects {
            let v = e.values;
            match EFFECTS.get(e.index).copied() {
                Some("tire-lateral-compliance") => compliance = v[0],
                Some("mount-compliance") => sensor.mount = Some((v[0], v[1])),
                Some("driver-throttle") => {}
                Some("sensor-misalignment") => sensor.misalignment = Some([v[0], v[1], v[2]]),
                Some("hps-gas-temperature") => {
                    field.hps.heat_transfer = Some(HeatTransfer {
                        tau: v[0],
                        kappa: 1.4,
                    })
                }
                _ => {
                    return Err(DiscoveryError::NoSuchEffect {
                        index: e.index,
                        model: self.model_name(),
                    })
                }
            }
        }
        Ok((field, sensor, compliance))
    }
}

impl DiscoveryModel for Vehicle3dModel {
    type Prepared = Replay3d;

    fn name(&self) -> &str {
        self.model_name()
    }

    fn channels(&self) -> Vec<String> {
        CHANNELS.iter().map(|s| s.to_string()).collect()
    }

    fn baseline_params(&self) -> Vec<ParamSpec> {
        self.calibrated()
            .iter()
            .map(|&(name, lo, hi, _)| {
                let x = value(&self.params, name).unwrap_or(f64::NAN);
                ParamSpec {
                    typical: x.max(0.1 * hi),
                    ..ParamSpec::new(name, x, lo, hi)
                }
            })
            .collect()
    }

    fn catalogue(&self) -> Vec<EffectSpec> {
        catalogue(self.front_axle == FrontAxle::Suspended)
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

    fn prepare(&self, record: &Record) -> Result<Replay3d, DiscoveryError> {
        let t = record
            .column("time_s")
            .ok_or(DiscoveryError::MissingColumn { column: "time_s" })?;
        let n = t.len();
        if n < 2 {
            return Err(DiscoveryError::TooFewSamples);
        }
        let load = match meta(record, "load") {
            Some(Value::String(s)) => s
                .parse::<Load>()
                .map_err(|_| DiscoveryError::UnknownLoad { load: s.clone() })?,
            Some(v) => {
                return Err(DiscoveryError::LoadNotText {
                    value: v.to_string(),
                })
            }
            None => self.default_load.ok_or(DiscoveryError::NoLoad)?,
        };
        if let Some(axle) = meta(record, "front_axle") {
            let want = serde_json::to_value(self.front_axle)?;
            if *axle != want {
                return Err(DiscoveryError::Sidecar {
                    field: "front_axle",
                    reason: format!("the record was run with {axle}, the model is {want}"),
                });
            }
        }
        let kind = match meta(record, "manoeuvre").and_then(Value::as_str) {
            Some("path_change") => RunKind::PathChange,
            _ => RunKind::Ride,
        };
        let time_s: Vec<f64> = t.iter().map(|v| v - t[0]).collect();
        let dt_s = time_s[n - 1] / (n - 1) as f64;
        let speed_col = record
            .column("speed_m_s")
            .ok_or(DiscoveryError::MissingColumn {
                column: "speed_m_s",
            })?;
        let target = meta(record, "speed_m_s")
            .and_then(Value::as_f64)
            .or_else(|| {
                meta(record, "speed_kmh")
                    .and_then(Value::as_f64)
                    .map(|v| v / 3.6)
            });
        let speed_m_s = target.unwrap_or(speed_col.iter().sum::<f64>() / n as f64);
        let steer = match kind {
            RunKind::Ride => SteerInput::None,
            RunKind::PathChange => {
                let sw = record
                    .column("steer_wheel_deg")
                    .ok_or(DiscoveryError::MissingColumn {
                        column: "steer_wheel_deg",
                    })?;
                SteerInput::Table {
                    time_s: time_s.clone(),
                    angle_rad: sw.iter().map(|d| d.to_radians()).collect(),
                }
            }
        };
        let duration = match kind {
            RunKind::PathChange => meta(record, "t_end_s").and_then(Value::as_f64),
            RunKind::Ride => None,
        }
        .unwrap_or(time_s[n - 1]);
        let path_length_m = speed_m_s * duration + 5.0;
        let options = self.layout(
            speed_m_s,
            steer.clone(),
            path_length_m,
            FieldEffects::default(),
        );
        let ground = terrain_of(record)?;
        let tracks = Arc::new(self.build_tracks(load, &options, ground.as_ref())?);
        let ground_name = ground.map_or("smooth ground".to_string(), |(s, seed)| {
            format!("class {} seed {seed}", s.class)
        });
        let kind_name = match kind {
            RunKind::Ride => "ride",
            RunKind::PathChange => "path change",
        };
        let group = match ground_name.split(" seed").next() {
            Some(g) => format!("{kind_name}, {g}"),
            None => kind_name.to_string(),
        };
        Ok(Replay3d {
            kind,
            load,
            speed_m_s,
            steer,
            path_length_m,
            tracks,
            ground,
            instantaneous: Arc::default(),
            dt_s,
            speed_smooth: local_quadratic(
                speed_col,
                (THROTTLE_SMOOTH_S / dt_s).round() as usize,
                dt_s,
            ),
            condition: format!(
                "{load}, {kind_name}, {:.1} km/h, {ground_name}",
                speed_m_s * 3.6
            ),
            group,
            time_s,
            cache: ReplayCache::default(),
            coarse: false,
        })
    }

    /// The record replayed at [`SCOUT_RTOL_FACTOR`] times the tolerance (its own cache).
    fn coarse(&self, prepared: &Replay3d) -> Option<Replay3d> {
        Some(Replay3d {
            coarse: true,
            ..prepared.clone()
        })
    }

    fn condition(&self, prepared: &Replay3d) -> String {
        prepared.condition.clone()
    }

    fn group(&self, prepared: &Replay3d) -> Option<String> {
        Some(prepared.group.clone())
    }

    /// Ride runs and V3 path changes are separate experiments: each is scaled by the spread
    /// of its own kind's training records (docs/discovery.md, "Each experiment's own
    /// scale").
    fn scaling_group(&self, prepared: &Replay3d) -> Option<String> {
        Some(
            match prepared.kind {
                RunKind::Ride => "ride",
                RunKind::PathChange => "path change",
            }
            .to_string(),
        )
    }

    fn simulate(
        &self,
        prepared: &Replay3d,
        baseline: &[f64],
        effects: &[ActiveEffect<'_>],
    ) -> Result<Vec<Option<Vec<f64>>>, DiscoveryError> {
        self.simulate_with_readings(prepared, baseline, effects, &[])
    }

    fn simulate_with_readings(
        &self,
        prepared: &Replay3d,
        baseline: &[f64],
        effects: &[ActiveEffect<'_>],
        readings: &[usize],
    ) -> Result<Vec<Option<Vec<f64>>>, DiscoveryError> {
        let reading = readings.first().copied().unwrap_or(0);
        let spacing = cam_spacing(reading)?;
        let mut p = self.apply_baseline(baseline)?;
        let (mut field, sensor, compliance) = self.apply_effects(effects)?;
        p.tire.lateral_relaxation_length_m +=
            compliance * 1e-6 * p.tire.cornering_stiffness_n_per_rad;
        // the vehicle-side inputs: the baseline and every model-side effect's values but
        // the throttle's gain
        let mut key: Vec<u64> = baseline.iter().map(|x| x.to_bits()).collect();
        if reading != 0 {
            key.extend([READING_KEY, reading as u64]);
        }
        let mut throttle = None;
        for e in effects {
            match EFFECTS.get(e.index) {
                Some(&"mount-compliance") | Some(&"sensor-misalignment") => {}
                Some(&"driver-throttle") => throttle = Some(e.values[0]),
                _ => {
                    key.push(e.index as u64);
                    key.extend(e.values.iter().map(|x| x.to_bits()));
                }
            }
        }
        let ch = match throttle {
            None => prepared
                .cache
                .get_or(key, || self.replay(prepared, &p, field, spacing))?,
            Some(gain) => {
                // the setpoint that follows the record (one replay, shared by every gain),
                // its swing about the drive's setpoint scaled by the gain
                let mut follow_key = key.clone();
                follow_key.push(FOLLOW_KEY);
                let set =
                    self.following_setpoint(prepared, &p, field.clone(), spacing, follow_key)?;
                let v0 = prepared.speed_m_s;
                let scaled = set.iter().map(|s| v0 + gain * (s - v0)).collect();
                field.speed_setpoint = Some(SpeedSetpoint::new(prepared.time_s.clone(), scaled)?);
                key.push(GAIN_KEY);
                key.push(gain.to_bits());
                prepared
                    .cache
                    .get_or(key, || self.replay(prepared, &p, field, spacing))?
            }
        };
        Ok(self.apply_sensor(prepared, p.gravity_m_s2, sensor, ch))
    }

    fn phases(&self, record: &Record) -> Vec<Phase> {
        let Some(sw) = record.column("steer_wheel_deg") else {
            return Vec::new();
        };
        let steering: Vec<bool> = sw.iter().map(|d| d.abs() > 1.0).collect();
        vec![
            Phase {
                name: "steering".into(),
                mask: steering.clone(),
            },
            Phase {
                name: "straight".into(),
                mask: steering.iter().map(|s| !s).collect(),
            },
        ]
    }

    /// Ride accelerations have content up to the sampling rate (the terrain's band and the
    /// tires' enveloping reach tens of Hz at ride speeds).
    fn broadband_channels(&self) -> bool {
        true
    }

    fn skip_samples(&self, record: &Record) -> usize {
        match record.column("time_s") {
            Some(t) if t.len() > 1 => {
                let dt = (t[t.len() - 1] - t[0]) / (t.len() - 1) as f64;
                (SKIP_S / dt).round() as usize
            }
            _ => 0,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_calibration_set_is_named_by_the_registries() {
        for axle in [FrontAxle::Rigid, FrontAxle::Suspended] {
            let m = Vehicle3dModel::nominal(axle);
            let specs = m.baseline_params();
            assert_eq!(specs.len(), m.calibrated().len());
            for s in &specs {
                assert!(s.lower <= s.initial && s.initial <= s.upper, "{}", s.name);
            }
            let v: Vec<f64> = specs.iter().map(|s| s.initial).collect();
            assert_eq!(m.apply_baseline(&v).unwrap(), m.params);
            let mut w = v.clone();
            w[0] = 1.3;
            w[3] = 0.7;
            let p = m.apply_baseline(&w).unwrap();
            assert_eq!(p.joint_height_m, 1.3);
            assert_eq!(p.tire.longitudinal_relaxation_length_m, 0.7);
            assert!(m.apply_baseline(&v[1..]).is_err());
        }
        let mut p = VehicleParams::nominal();
        assign(&mut p, "hps.friction.f_c", 800.0).unwrap();
        assert_eq!(value(&p, "hps.friction.f_c").unwrap(), 800.0);
        assert!(assign(&mut p, "tire.no_such", 1.0).is_err());
    }

    #[test]
    fn the_cam_spacing_switch_replays_both_readings() {
        let m = Vehicle3dModel::nominal(FrontAxle::Rigid);
        let sw = m.switches();
        assert_eq!(sw.len(), 1);
        assert_eq!(sw[0].name, "cam-spacing");
        assert_eq!(sw[0].readings, ["static", "instantaneous"]);
        // a 1.5 s loaded ride on class E ground
        let n = 151;
        let mut r = Record::new();
        r.push_column("time_s", (0..n).map(|i| 0.01 * i as f64).collect())
            .unwrap();
        r.push_column("speed_m_s", vec![5.5; n]).unwrap();
        r.meta = serde_json::json!({"load": "loaded", "terrain": {"class": "E", "seeds": [3]}});
        let rec = m.prepare(&r).unwrap();
        let base: Vec<f64> = m.baseline_params().iter().map(|s| s.initial).collect();
        let plain = m.simulate(&rec, &base, &[]).unwrap();
        let fixed = m.simulate_with_readings(&rec, &base, &[], &[0]).unwrap();
        let inst = m.simulate_with_readings(&rec, &base, &[], &[1]).unwrap();
        assert_eq!(plain, fixed);
        // the cams follow the deflection: the ride's vertical acceleration moves, by less
        // than its own size
        let z = CHANNELS.iter().position(|c| *c == LINEAR_AXES[2]).unwrap();
        let (a, b) = (fixed[z].as_ref().unwrap(), inst[z].as_ref().unwrap());
        let rel = (a.iter().zip(b).map(|(x, y)| (x - y).powi(2)).sum::<f64>()
            / a.iter().map(|x| x * x).sum::<f64>())
        .sqrt();
        assert!(rel > 0.01 && rel < 0.5, "{rel}");
        assert_eq!(
            m.tracks(&rec, CamSpacing::Instantaneous)
                .unwrap()
                .cam_spacing(),
            CamSpacing::Instantaneous
        );
        let e = m
            .simulate_with_readings(&rec, &base, &[], &[2])
            .unwrap_err();
        assert!(e.to_string().contains("cam-spacing"), "{e}");
    }

    #[test]
    fn a_record_of_the_other_front_axle_or_without_a_load_is_refused() {
        let mut r = Record::new();
        r.push_column("time_s", vec![0.0, 0.01, 0.02]).unwrap();
        r.push_column("speed_m_s", vec![5.0; 3]).unwrap();
        let m = Vehicle3dModel::nominal(FrontAxle::Rigid);
        assert!(matches!(m.prepare(&r), Err(DiscoveryError::NoLoad)));
        r.meta = serde_json::json!({"load": "loaded", "front_axle": "suspended"});
        let e = m.prepare(&r).unwrap_err().to_string();
        assert!(e.contains("front_axle"), "{e}");
    }
}
