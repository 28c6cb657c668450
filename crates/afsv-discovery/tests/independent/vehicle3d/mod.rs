//! Independent implementation of the integrated 3-D articulated vehicle of Chapter 6 (rigid
//! front axle, or the front-axle HPS of section 6.2.3 with the Chapter 5 strut of
//! `super::strut`, Table 6.3: [`Data::nominal_hps`]), written from the dissertation (sections 6.2-6.3, Tables 6.1-6.2; the frame
//! steering of Chapter 3, Eqs 3.5-3.12 and Table 3.1, in the strut form of Eqs 6.6-6.8;
//! the driver of section 3.4.1), the close reading of the chapters and, for values the paper
//! does not give, the project's list of assumptions (docs/vehicle-3d.md). It calls no model
//! code of the toolkit (no vehicle-3d, multibody, tire-fiala, afs-hydraulics, afsv-dynamics,
//! vehicle-components, vehicle-run). The one exception is the road: ride records run on
//! the two-track ground the adapter rebuilds from the sidecar, so the heights come from the
//! same generator (`vehicle_3d::scenarios::TerrainSpec::build`, the road as an input, like a
//! measured profile); everything the tires do with it (the cams) is ours.
//!
//! Formulation ([`model`]): ten coordinates, the front cg position, the front unit's yaw,
//! pitch and roll (Z-Y-X Euler angles), the articulation theta (rear unit about the front
//! unit's z, positive in a right-hand turn), the rear unit's roll about its own x axis
//! at the joint and the two front wheel carriers' travels (HPS only; held at zero by the
//! rigid axle), plus four wheel spins. Equations of motion in Kane's form, `M(q) q'' =
//! sum J^T (F - m a_bias) + J_w^T (tau - I alpha_bias - w x I w)`, with the Jacobians of every
//! point and rotation by central differences of the pose in the five angles and the
//! velocity-product accelerations by second differences along the angle rates; the 10 x 10
//! system (the rigid axle's carrier rows the identity, which leaves the other eight rows'
//! elimination as it was) solved by Gaussian elimination at each evaluation. Integrator: classic RK4, fixed
//! 0.5 ms steps.
//!
//! The HPS front axle ([`HpsAxle`]): two more coordinates, the front wheel carriers' travels
//! along the front unit's z at the wheel centres (ratio 1; held at zero by the rigid axle),
//! each carrying a wheel end of 1 950 kg as a point mass; the Table 6.1 front unit keeps its
//! mass and inertia with the wheel ends at their static places, so each wheel end's mass is
//! taken out there and put in on its carrier (Kane's sums exact for the combination). Each
//! strut is `super::strut::VehicleStrut` (Eqs 5.1-5.12, its own chamber states) at travel
//! `z_static + c`; its force (plus a 1e8 N/m end stop beyond the 120 mm travel) acts on the
//! carrier's coordinate only. The struts carry the front tire load less the wheel end's
//! weight at rest (`VehicleStrut::static_state`), so the static pose and tire loads are the
//! rigid axle's. RK4 at the strut's own step bound, 0.1 ms (`model::STEP_HPS_S`; a 6 s ride
//! in 0.8 s; at 0.5 ms the class C ride of the cross-check also ran, its sensor axes within
//! 0.02 % NRMSE of the 0.1 ms run, but the strut file's bound was kept). The hidden gas
//! effect is the strut's own heat transfer (`StrutHidden::GasHeatTransfer`: the gas
//! temperature ratio relaxing to the wall's with time constant tau, kappa 1.4 between); the
//! struts then rest at the isothermal static travel.
//!
//! Channels written (afsv-v1, docs/records.md): the steering-wheel angle, the speed (mean
//! forward speed of the four wheel centres), the articulation, the left strut's extension,
//! P_c and P_r, the front unit's yaw rate (right-turn positive), the front cg's horizontal
//! lateral acceleration (left positive), the cab point's kinematic acceleration in the
//! front unit's axes and the front unit's angular accelerations about its axes.
//!
//! Choices where the paper is silent or ambiguous, with the crate's value beside each:
//!
//! | choice | the crate (vehicle-3d) | this implementation |
//! |---|---|---|
//! | formulation | tree multibody in minimal coordinates (quaternion base), CRBA + sparse LDL | Euler angles, Kane's equations with finite-difference Jacobians, dense solve |
//! | wheel ends | 2 000 kg bodies on revolutes, spin 600 kg m², tilt 350 kg m² | lumped into the units (Table 6.1 masses and inertias as printed); a spin DOF of 600 kg m² per wheel (its state the absolute rate about the axle), whose angular momentum's gyroscopic reaction acts on its unit |
//! | joint height, revolute order | 1.0 m; yaw then roll at one point | the same (the note's recommendation) |
//! | steering mount points | Table 3.1 planar layout at the joint height | the same |
//! | tire load-deflection (Fig 6.4 absent) | `1.2e6 d + 4.306e6 d²` N | `1.25e6 d + 4.0e6 d²` N (1.4 % stiffer at the loaded front tire's deflection) |
//! | Eq 6.1 deflection | normal distance to the cams' line, `delta_ref + (z_ref - z_c) cos theta` | as printed, `(z_oi - z_u) / cos theta` with `z_u = z_c - R` |
//! | cam spacing | three fixed-point steps of the half contact length, once per grid point at the static deflection (a cache along the track) | half-length `sqrt(R² - (R - delta_0)²)` from the central cam's instantaneous deflection, at every evaluation (section 6.2.2: P1P2 depends on the deflection). On class E ground this is the largest difference from the crate (docs/discovery.md) |
//! | cam base | a cam of the free radius on the profile's 0.05 m vertices and segments | a circle of the free radius on the terrain's 0.05 m samples (vertices only), linear between |
//! | cornering stiffness vs load | piecewise linear through the four Table 6.2 points, extrapolated beyond (floored at 0) | piecewise linear through them, held constant beyond |
//! | Fiala U_max / U_min, C_slip | 0.8 / 0.6, 1e6 N | the same (docs) |
//! | rolling resistance moment | `f_r R F_z` (free radius), f_r 0.03 | the same |
//! | effective rolling radius | loaded radius `R - delta` | the same |
//! | slip definitions at low speed | `sqrt(v_x² + u_0²)` | `|V_x|` floored at 0.5 m/s |
//! | the drive's speed signal | mean horizontal forward speed of the wheel centres | mean forward speed of the wheel centres in their contact planes (the cams' lines) |
//! | Eq 6.1 deflection rate | `v_s sin theta - v_z cos theta` (the cams' line held fixed) | the same reading |
//! | relaxation | lateral 1.2 m (Table 6.2), longitudinal equal | the same |
//! | PI drive | 9 kN m/(m/s), 2 kN m/m, ±60 kN m, feed-forward `f_r (R - delta)` times the mean static tire load | the same gains and limit; the same feed-forward (the rolling-resistance force times the contact force's lever arm about the axle, the loaded radius). Note: the rolling-resistance moment uses the free radius in both, so the feed-forward starts 9 % short and the PI's integral lets the vehicle fall about 0.2 m behind in the first seconds; with the feed-forward at the free radius (`Data::feed_forward_free_radius`) the independent rides run 0.2 m ahead of the crate's after 6 s and the sensor axes' NRMSE against the crate grows from 4.5-8.4 % to 26-66 % at 20 km/h (`ride_channels_by_speed_and_feed_forward`) |
//! | steering valve, leakage, cavitation | Tables 3.1, 4.1; standby 1 MPa, cavitation floor 10 kPa with a 40 kPa band, orifice regularised over 10 kPa | the independent yaw-plane model's laws (`super::yaw`): standby 1 MPa, floor 20 kPa with a 30 kPa taper, sqrt regularised over 0.02 bar (2 kPa) |
//! | driver | pure pursuit, look-ahead `max(4 m, 1.2 s u)` along the course's arc, K = 40 1/s, 2 turns/s | the same gains; look-ahead point taken at `x + l_d` along the course axis |
//! | sensor (cab) point | `[1.68, 0, 2.0]` m (from the joint, height) | the same |
//! | start | static pose at speed, cg at 1.36 m | the same; front cg at path coordinate 10 m |
//! | hidden tire lateral compliance | relaxation length + c x C_alpha (6.8 kN/deg, constant) | relaxation length + c x C_alpha(F_z) at the tire's current load |
//! | hidden mount | Tustin-discretised filter on the 100 Hz channels | a sprung sensor integrated by RK4 in 1 ms steps on the linearly interpolated 100 Hz acceleration |
//! | HPS: unsprung mass per front wheel | 2 000 kg wheel-end body on a massless carrier, the unit's cg and inertia corrected | 1 950 kg point mass on the carrier (Table 2.1's front unsprung mass, 3 900 kg, halved; Table 6.1 gives none), taken out of the Table 6.1 unit at its static place |
//! | HPS: strut model | `hps_emulsion::HpsStrut` (Eqs 5.1-5.12, Eq 6.9) | `tests/independent/strut.rs` (written from Chapter 5; gas pressure integrated instead of the gas volume, its own square-root regularisation (2 kPa) and rod-side cavitation taper) |
//! | HPS: strut friction | the laboratory friction scaled by the piston perimeter | the same scaling (mu_v 119 N s/m, F_c 357 N, F_s 238 N), Eq 5.3 band at v_h = 1 mm/s |
//! | HPS: static travel | bisection on the strut's static force | quasi-static compliance of both chambers integrated from the charge position (loaded -13.96 mm, the crate -14.49 mm; unloaded -49.55 / -50.34 mm) |
//! | HPS: end stops | 2e8 N/m, 2e4 N s/m beyond ±120 mm | 1e8 N/m, 2e4 N s/m, pushing only |
//! | HPS: hidden gas temperature | `hps_emulsion::HeatTransfer { tau, kappa: 1.4 }` | the strut file's gas energy balance with wall exchange (temperature-ratio state), kappa 1.4 |
//!
//! Used by `tests/independent_vehicle3d.rs` (cross-checks against the crate) and
//! `tests/discover_independent_vehicle3d.rs` (the discovery matrix on these records).

pub mod model;

use super::rng::Noise;
use super::strut::StrutData;
use super::yaw::{YawLoad, YawParams};
use afsv_records::Record;
use model::{simulate, CamTrack, Model, Outputs, RunInput, Steering};
use serde_json::json;
use terrain_psd::IsoClass;

/// Path coordinate of the front cg at the start (m), as the commands lay out a run.
pub const START_S_M: f64 = 10.0;

/// Who wrote the records (the sidecar's `written_by`).
pub const WRITTEN_BY: &str =
    "afsv-discovery tests/independent/vehicle3d (independent implementation of Chapter 6)";

/// Steering data (Table 3.1), SI units except where named.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteeringData {
    pub a0_deg: f64,
    pub x0_deg: f64,
    pub xlim_deg: f64,
    pub l1: f64,
    pub l2: f64,
    pub ac: f64,
    pub ar: f64,
    pub v0: f64,
    pub ps: f64,
    pub p0: f64,
    pub bulk: f64,
    pub mu_v: f64,
    pub kl0: f64,
    pub kl: f64,
    pub ktheta_ml_deg: f64,
    pub kv: f64,
    pub eta_g: f64,
    pub a0_per_bar: f64,
    pub am: f64,
    pub av: f64,
    pub standby: f64,
}

impl SteeringData {
    /// Table 3.1's steering columns in SI units: the independent yaw-plane model's table
    /// (`independent::yaw`, in the table's units; the same for both loads), converted.
    pub fn table_3_1() -> Self {
        let t = YawParams::table_3_1(YawLoad::Loaded).steering;
        Self {
            a0_deg: t.a0_deg,
            x0_deg: t.x0_deg,
            xlim_deg: t.xlim_deg,
            l1: t.l1_m,
            l2: t.l2_m,
            ac: t.ac_cm2 / 1e4,
            ar: t.ar_cm2 / 1e4,
            v0: t.v0_l / 1e3,
            ps: t.ps_mpa * 1e6,
            p0: t.p0_mpa * 1e6,
            bulk: t.b_gpa * 1e9,
            mu_v: t.mu_v_kn_s_mm * 1e6,
            kl0: t.kl0,
            kl: t.kl,
            ktheta_ml_deg: t.ktheta_ml_deg,
            kv: t.kv,
            eta_g: t.eta_g,
            a0_per_bar: t.a0_per_bar,
            am: t.am,
            av: t.av,
            standby: t.standby_mpa * 1e6,
        }
    }
}

/// The vehicle's data (Tables 6.1, 6.2, 3.1 and the assumptions of the module table).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Data {
    pub loaded: bool,
    pub gravity: f64,
    pub front_mass: f64,
    pub front_cg_height: f64,
    pub front_cg_to_joint: f64,
    pub front_inertia: [f64; 3],
    pub rear_mass: f64,
    pub rear_cg_height: f64,
    pub rear_cg_to_joint: f64,
    pub rear_inertia: [f64; 3],
    pub payload_mass: f64,
    pub payload_cg_height: f64,
    pub payload_cg_to_joint: f64,
    pub payload_inertia: [f64; 3],
    pub front_axle_to_joint: f64,
    pub rear_axle_to_joint: f64,
    pub track: f64,
    pub joint_height: f64,
    pub cab_point: [f64; 3],
    pub radius: f64,
    pub half_width: f64,
    pub tire_damping: f64,
    pub relax_y: f64,
    pub relax_x: f64,
    pub u_max: f64,
    pub u_min: f64,
    pub c_slip: f64,
    pub rolling_resistance: f64,
    pub spin_inertia: f64,
    /// Load-deflection curve `k1 d + k2 d²` (N).
    pub k1: f64,
    pub k2: f64,
    pub kp: f64,
    pub ki: f64,
    pub max_torque: f64,
    pub steering: SteeringData,
    pub preview_time: f64,
    pub min_preview: f64,
    pub driver_gain: f64,
    pub driver_max_rate: f64,
    /// Cavitation floor of the steering circuit (off for the energy check).
    pub cavitation: bool,
    /// Fiala's horizontal forces and the aligning moment (off for the energy check).
    pub horizontal_forces: bool,
    /// The drive's feed-forward with the free radius (the rolling-resistance moment's
    /// lever) instead of the loaded radius (module table).
    pub feed_forward_free_radius: bool,
    /// The front axle's HPS (two Chapter 5 struts on wheel carriers), `None` for the rigid
    /// front axle of the paper's base model.
    pub hps: Option<HpsAxle>,
}

/// The front-axle HPS: the strut of Table 6.3 (`independent::strut`, Chapter 5) at each
/// front wheel, between the front unit and a wheel carrier sliding along the unit's z at
/// the wheel centre (ratio 1); the wheel end's mass rides on the carrier.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HpsAxle {
    /// The strut (both sides alike).
    pub strut: StrutData,
    /// Mass moving with each carrier (kg): the wheel end, taken out of the Table 6.1 front
    /// unit at its static place.
    pub wheel_end_mass: f64,
    /// The hidden gas heat transfer's thermal time constant (s), `None` for Eq 5.4's
    /// polytropic gas.
    pub gas_tau_s: Option<f64>,
    /// End stops beyond the strut's travel: stiffness (N/m) and damping (N s/m), pushing
    /// only.
    pub stop_stiffness: f64,
    pub stop_damping: f64,
}

impl HpsAxle {
    /// Table 6.3's strut with the strut file's completions; 1 950 kg per wheel end (the
    /// front axle's unsprung mass of Table 2.1, 3 900 kg, shared by the two sides: Table
    /// 6.1 gives none); end stops of 1e8 N/m and 2e4 N s/m.
    pub fn nominal(gas_tau_s: Option<f64>) -> Self {
        Self {
            strut: StrutData::table_6_3(),
            wheel_end_mass: 1_950.0,
            gas_tau_s,
            stop_stiffness: 1.0e8,
            stop_damping: 2.0e4,
        }
    }

    /// The end stop's force (N, compressive positive) at travel `z` and rate `zd` of a
    /// strut of half travel `travel`.
    pub fn end_stop(&self, z: f64, zd: f64, travel: f64) -> f64 {
        if z > travel {
            (self.stop_stiffness * (z - travel) + self.stop_damping * zd).max(0.0)
        } else if z < -travel {
            (self.stop_stiffness * (z + travel) + self.stop_damping * zd).min(0.0)
        } else {
            0.0
        }
    }
}

impl Data {
    /// The paper's data and the assumptions of the module table.
    pub fn nominal(loaded: bool) -> Self {
        Self {
            loaded,
            gravity: 9.81,
            front_mass: 21_000.0,
            front_cg_height: 1.36,
            front_cg_to_joint: 2.13,
            front_inertia: [14_000.0, 41_000.0, 42_000.0],
            rear_mass: 18_500.0,
            rear_cg_height: 1.55,
            rear_cg_to_joint: 2.84,
            rear_inertia: [12_000.0, 28_000.0, 31_000.0],
            payload_mass: 33_720.0,
            payload_cg_height: 2.4,
            payload_cg_to_joint: 2.6,
            payload_inertia: [27_000.0, 72_000.0, 76_000.0],
            front_axle_to_joint: 1.68,
            rear_axle_to_joint: 3.44,
            track: 2.28,
            joint_height: 1.0,
            cab_point: [1.68, 0.0, 2.0],
            radius: 1.0,
            half_width: 0.35,
            tire_damping: 35.0e3,
            relax_y: 1.2,
            relax_x: 1.2,
            u_max: 0.8,
            u_min: 0.6,
            c_slip: 1.0e6,
            rolling_resistance: 0.03,
            spin_inertia: 600.0,
            k1: 1.25e6,
            k2: 4.0e6,
            kp: 9_000.0,
            ki: 2_000.0,
            max_torque: 60_000.0,
            steering: SteeringData::table_3_1(),
            preview_time: 1.2,
            min_preview: 4.0,
            driver_gain: 40.0,
            driver_max_rate: 2.0 * std::f64::consts::TAU,
            cavitation: true,
            horizontal_forces: true,
            feed_forward_free_radius: false,
            hps: None,
        }
    }

    /// [`Data::nominal`] with the front-axle HPS ([`HpsAxle::nominal`]).
    pub fn nominal_hps(loaded: bool, gas_tau_s: Option<f64>) -> Self {
        Self {
            hps: Some(HpsAxle::nominal(gas_tau_s)),
            ..Self::nominal(loaded)
        }
    }

    /// The rear unit with its payload when loaded, as one body: mass, cg distance behind
    /// the joint, cg height, inertia tensor about the cg (rear axes; parallel-axis terms
    /// including the x-z product).
    pub fn rear_body(&self) -> (f64, f64, f64, [[f64; 3]; 3]) {
        let mut parts = vec![(
            self.rear_mass,
            self.rear_cg_to_joint,
            self.rear_cg_height,
            self.rear_inertia,
        )];
        if self.loaded {
            parts.push((
                self.payload_mass,
                self.payload_cg_to_joint,
                self.payload_cg_height,
                self.payload_inertia,
            ));
        }
        let m: f64 = parts.iter().map(|p| p.0).sum();
        let x = parts.iter().map(|p| p.0 * p.1).sum::<f64>() / m;
        let z = parts.iter().map(|p| p.0 * p.2).sum::<f64>() / m;
        let mut i = [[0.0; 3]; 3];
        for (mp, xp, zp, ip) in parts {
            // offsets from the combined cg in rear axes: x backwards is negative
            let (dx, dz) = (-(xp - x), zp - z);
            i[0][0] += ip[0] + mp * dz * dz;
            i[1][1] += ip[1] + mp * (dx * dx + dz * dz);
            i[2][2] += ip[2] + mp * dx * dx;
            i[0][2] -= mp * dx * dz;
            i[2][0] -= mp * dx * dz;
        }
        (m, x, z, i)
    }

    /// Static load of one front and one rear tire (N): the vehicle rigid in pitch on its
    /// two axles.
    pub fn static_tire_loads(&self, m_r: f64, x_r: f64) -> [f64; 2] {
        let g = self.gravity;
        let wb = self.front_axle_to_joint + self.rear_axle_to_joint;
        // moments about the rear axle (distances forward of it)
        let front = self.front_mass * (self.rear_axle_to_joint + self.front_cg_to_joint)
            + m_r * (self.rear_axle_to_joint - x_r);
        let front_axle = g * front / wb;
        let total = g * (self.front_mass + m_r);
        [0.5 * front_axle, 0.5 * (total - front_axle)]
    }

    /// Tire normal force at deflection `d` (m), the spring part.
    pub fn load_curve(&self, d: f64) -> f64 {
        self.k1 * d + self.k2 * d * d
    }

    /// Spring energy stored at deflection `d`.
    pub fn load_energy(&self, d: f64) -> f64 {
        0.5 * self.k1 * d * d + self.k2 * d * d * d / 3.0
    }

    /// Deflection under the static load `f`.
    pub fn deflection(&self, f: f64) -> f64 {
        (-self.k1 + (self.k1 * self.k1 + 4.0 * self.k2 * f).sqrt()) / (2.0 * self.k2)
    }

    /// Cornering stiffness (N/rad) at load `fz`: piecewise linear through Table 6.2's four
    /// values at the static loads they were measured at (derived from Table 6.1).
    pub fn cornering_stiffness(&self, fz: f64) -> f64 {
        const PTS: [[f64; 2]; 4] = [
            [71.06e3, 3.7],
            [122.69e3, 6.1],
            [149.83e3, 6.8],
            [209.32e3, 7.5],
        ];
        let kn_deg = 1.0e3 * 180.0 / std::f64::consts::PI;
        if fz <= PTS[0][0] {
            return PTS[0][1] * kn_deg;
        }
        for w in PTS.windows(2) {
            if fz <= w[1][0] {
                let t = (fz - w[0][0]) / (w[1][0] - w[0][0]);
                return (w[0][1] + t * (w[1][1] - w[0][1])) * kn_deg;
            }
        }
        PTS[3][1] * kn_deg
    }

    /// Fiala forces at load `fz`, slip ratio `kappa`, slip angle `alpha` (sliding left
    /// positive): longitudinal force, the size of the lateral force (signed with alpha; it
    /// acts against the sliding) and the aligning moment (signed with alpha).
    pub fn fiala(&self, fz: f64, kappa: f64, alpha: f64, c_alpha: f64) -> (f64, f64, f64) {
        if fz <= 0.0 {
            return (0.0, 0.0, 0.0);
        }
        let alpha = alpha.clamp(-1.4, 1.4);
        let ta = alpha.tan();
        let s = (kappa * kappa + ta * ta).sqrt().min(1.0);
        let ufz = (self.u_max - (self.u_max - self.u_min) * s) * fz;
        let kc = ufz / (2.0 * self.c_slip);
        let fx = if kappa.abs() <= kc {
            self.c_slip * kappa
        } else {
            kappa.signum() * (ufz - ufz * ufz / (4.0 * kappa.abs() * self.c_slip))
        };
        let h = 1.0 - c_alpha * ta.abs() / (3.0 * ufz);
        let sg = if alpha > 0.0 {
            1.0
        } else if alpha < 0.0 {
            -1.0
        } else {
            0.0
        };
        let (fy, mz) = if h > 0.0 {
            let h3 = h * h * h;
            (
                sg * ufz * (1.0 - h3),
                sg * 2.0 * ufz * self.half_width * (1.0 - h) * h3,
            )
        } else {
            (sg * ufz, 0.0)
        };
        (fx, fy, mz)
    }
}

/// A hidden effect of the records, written here in its physical form.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Hidden3d {
    /// Nothing.
    None,
    /// Lateral carcass compliance (mm/kN) in series with the cornering stiffness.
    TireCompliance(f64),
    /// Sensor on a mount: natural period (s), damping ratio.
    Mount(f64, f64),
    /// The driver's throttle: setpoint swing (m/s), period (s).
    Throttle(f64, f64),
    /// Sensor axes rotated by roll, pitch, yaw (deg).
    Misalignment([f64; 3]),
}

/// One record's run (the layout of `tests/vehicle3d::runs`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Run3d {
    /// Loaded (with the payload) or empty.
    pub loaded: bool,
    /// Ride on (class, terrain seed), or the V3 path change on smooth ground.
    pub ride: Option<(IsoClass, u64)>,
    /// Speed (km/h).
    pub speed_kmh: f64,
    /// Duration (s).
    pub duration_s: f64,
}

/// `rides` ride records (alternating class C and E and both loads, 15-24 km/h, 6 s) and
/// `changes` V3 path changes (alternating loads, 12 s), from `seed`: the same conditions
/// as `tests/vehicle3d::runs`.
pub fn runs(rides: usize, changes: usize, seed: u64) -> Vec<Run3d> {
    let mut v: Vec<Run3d> = (0..rides)
        .map(|i| Run3d {
            loaded: (i / 2) % 2 == 0,
            ride: Some((
                if i % 2 == 0 { IsoClass::C } else { IsoClass::E },
                seed * 100 + i as u64,
            )),
            speed_kmh: 15.0 + (i * 7 % 10) as f64,
            duration_s: 6.0,
        })
        .collect();
    v.extend((0..changes).map(|i| Run3d {
        loaded: i % 2 == 0,
        ride: None,
        speed_kmh: if i % 2 == 0 { 15.3 } else { 19.2 },
        duration_s: 12.0,
    }));
    v
}

/// The cam bases of the left and right tracks of the ground the adapter rebuilds for a
/// ride of `run` (the road heights from the shared generator, module docs).
pub fn ground(run: &Run3d) -> Option<[CamTrack; 2]> {
    let (class, seed) = run.ride?;
    let speed = run.speed_kmh / 3.6;
    let length = START_S_M + (speed * run.duration_s + 5.0) + 50.0;
    let spec = vehicle_3d::scenarios::TerrainSpec {
        class,
        ..Default::default()
    };
    let terrain = spec
        .build(&vehicle_3d::VehicleParams::nominal(), length, seed)
        .expect("terrain");
    let p = terrain.profile();
    let r = Data::nominal(true).radius;
    Some([
        CamTrack::new(&p.left_m, p.dx_m, r),
        CamTrack::new(&p.right_m, p.dx_m, r),
    ])
}

/// Simulate `run` on `data` with the model-side part of `hidden` and `steer` (for a path
/// change, `None` means the driver on the V3 course, 4.5 m to the right); outputs at
/// 100 Hz.
pub fn simulate_run(
    data: Data,
    run: &Run3d,
    hidden: Hidden3d,
    steer: Option<Steering>,
) -> (Vec<f64>, Vec<Outputs>) {
    let speed = run.speed_kmh / 3.6;
    let steer = steer.unwrap_or(match run.ride {
        Some(_) => Steering::None,
        None => Steering::Driver(4.5),
    });
    let input = RunInput {
        speed,
        throttle: match hidden {
            Hidden3d::Throttle(a, p) => Some((a, p)),
            _ => None,
        },
        compliance_m_per_n: match hidden {
            Hidden3d::TireCompliance(c) => c * 1e-6,
            _ => 0.0,
        },
        steer,
        ground: ground(run),
    };
    let m = Model::new(data, input);
    let y0 = m.initial();
    let (t, o, _) = simulate(&m, y0, run.duration_s, 100.0);
    (t, o)
}

/// The recorded channels (afsv-v1 names) of a run's outputs, before sensor effects and
/// noise.
pub fn channels(outs: &[Outputs]) -> Vec<(&'static str, Vec<f64>)> {
    let col = |f: &dyn Fn(&Outputs) -> f64| outs.iter().map(f).collect::<Vec<f64>>();
    vec![
        ("steer_wheel_deg", col(&|o| o.steer_rad.to_degrees())),
        ("speed_m_s", col(&|o| o.speed)),
        ("articulation_deg", col(&|o| o.theta.to_degrees())),
        ("strut_left_disp_m", col(&|o| o.d_left)),
        ("p_c_pa", col(&|o| o.pc)),
        ("p_r_pa", col(&|o| o.pr)),
        (
            "yaw_rate_front_deg_s",
            col(&|o| -o.rate_body[2].to_degrees()),
        ),
        ("front_lateral_accel_m_s2", col(&|o| o.front_lat)),
        ("cab_accel_x_m_s2", col(&|o| o.cab_acc_body[0])),
        ("cab_accel_y_m_s2", col(&|o| o.cab_acc_body[1])),
        ("cab_accel_z_m_s2", col(&|o| o.cab_acc_body[2])),
        ("front_roll_accel_rad_s2", col(&|o| o.ang_acc_body[0])),
        ("front_pitch_accel_rad_s2", col(&|o| o.ang_acc_body[1])),
        ("front_yaw_accel_rad_s2", col(&|o| o.ang_acc_body[2])),
    ]
}

/// A sensor on a mount of natural period `period` and damping `zeta`: the sensor mass's
/// deflection `e` obeys `e'' + 2 zeta w e' + w² e = -a_base`, its absolute acceleration is
/// `a_base + e''`; RK4 in 1 ms steps with the base acceleration linear between samples,
/// started at rest relative to the base.
pub fn mount(x: &mut [f64], dt: f64, period: f64, zeta: f64) {
    let w = std::f64::consts::TAU / period;
    let sub = (dt / 1e-3).round().max(1.0) as usize;
    let h = dt / sub as f64;
    let f = |s: [f64; 2], a: f64| -> [f64; 2] { [s[1], -a - 2.0 * zeta * w * s[1] - w * w * s[0]] };
    let mut s = [0.0, 0.0];
    let orig = x.to_vec();
    for k in 0..x.len() {
        x[k] = orig[k] + f(s, orig[k])[1];
        if k + 1 == x.len() {
            break;
        }
        let (a0, a1) = (orig[k], orig[k + 1]);
        for j in 0..sub {
            let at = |u: f64| a0 + (a1 - a0) * (j as f64 + u) / sub as f64;
            let k1 = f(s, at(0.0));
            let k2 = f([s[0] + 0.5 * h * k1[0], s[1] + 0.5 * h * k1[1]], at(0.5));
            let k3 = f([s[0] + 0.5 * h * k2[0], s[1] + 0.5 * h * k2[1]], at(0.5));
            let k4 = f([s[0] + h * k3[0], s[1] + h * k3[1]], at(1.0));
            for i in 0..2 {
                s[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
            }
        }
    }
}

/// A sensor block rotated by roll, pitch, yaw (deg; `Rz Ry Rx`, the catalogue's
/// convention): it reads the specific force `a + g e_z` and the angular acceleration in
/// its own axes, and the record's convention subtracts `g` along the assumed vertical.
pub fn misalign(lin: &mut [Vec<f64>; 3], ang: &mut [Vec<f64>; 3], deg: [f64; 3], g: f64) {
    let [r, p, y] = deg.map(f64::to_radians);
    let m = {
        let (sr, cr) = r.sin_cos();
        let (sp, cp) = p.sin_cos();
        let (sy, cy) = y.sin_cos();
        // Rz(y) Ry(p) Rx(r), multiplied out
        [
            [cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
            [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
            [-sp, cp * sr, cp * cr],
        ]
    };
    let turn = |v: [f64; 3]| -> [f64; 3] {
        [
            m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2],
            m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
            m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2],
        ]
    };
    for i in 0..lin[0].len() {
        let w = turn([lin[0][i], lin[1][i], lin[2][i] + g]);
        lin[0][i] = w[0];
        lin[1][i] = w[1];
        lin[2][i] = w[2] - g;
        let w = turn([ang[0][i], ang[1][i], ang[2][i]]);
        ang[0][i] = w[0];
        ang[1][i] = w[1];
        ang[2][i] = w[2];
    }
}

/// The record of `run` with `hidden` and noise `noise` (share of each channel's SD).
pub fn record(run: &Run3d, hidden: Hidden3d, noise: f64, seed: u64) -> Record {
    record_of(Data::nominal(run.loaded), run, hidden, noise, seed)
}

/// The record of `run` on the vehicle with the front-axle HPS, its gas with the heat
/// transfer of time constant `gas_tau_s` (s) or polytropic (`None`), noise `noise`.
pub fn record_hps(run: &Run3d, gas_tau_s: Option<f64>, noise: f64, seed: u64) -> Record {
    let data = Data::nominal_hps(run.loaded, gas_tau_s);
    record_of(data, run, Hidden3d::None, noise, seed)
}

/// The record of `run` on `data` (its load must be the run's) with `hidden` and noise
/// `noise`.
pub fn record_of(data: Data, run: &Run3d, hidden: Hidden3d, noise: f64, seed: u64) -> Record {
    assert_eq!(data.loaded, run.loaded, "the data's load is the run's");
    let (t, outs) = simulate_run(data, run, hidden, None);
    let mut ch = channels(&outs);
    // sensor-side effects on the six sensor channels (indices 8..14)
    if let Hidden3d::Misalignment(deg) = hidden {
        let mut lin = [ch[8].1.clone(), ch[9].1.clone(), ch[10].1.clone()];
        let mut ang = [ch[11].1.clone(), ch[12].1.clone(), ch[13].1.clone()];
        misalign(&mut lin, &mut ang, deg, data.gravity);
        for k in 0..3 {
            ch[8 + k].1 = lin[k].clone();
            ch[11 + k].1 = ang[k].clone();
        }
    }
    if let Hidden3d::Mount(period, zeta) = hidden {
        for c in ch[8..14].iter_mut() {
            mount(&mut c.1, 0.01, period, zeta);
        }
    }
    let mut rec = Record::new();
    rec.push_column("time_s", t).unwrap();
    for (k, (name, mut x)) in ch.into_iter().enumerate() {
        if k > 0 {
            let mut rng = Noise::new(seed, 11 + k as u64);
            rng.add_share(&mut x, noise);
        }
        rec.push_column(name, x).unwrap();
    }
    let speed = run.speed_kmh / 3.6;
    let terrain = match run.ride {
        None => json!({"kind": "smooth ground"}),
        Some((class, seed)) => json!({
            "kind": "two-track terrain (Eqs 6.4-6.5)",
            "class": class.to_string(),
            "m_c_cycles_per_m": 0.3,
            "band_cycles_per_m": [0.02, 5.0],
            "seeds": [seed],
        }),
    };
    rec.meta = json!({
        "written_by": WRITTEN_BY,
        "load": if run.loaded { "loaded" } else { "unloaded" },
        "front_axle": if data.hps.is_some() { "suspended" } else { "rigid" },
        "speed_kmh": run.speed_kmh,
        "speed_m_s": speed,
        "manoeuvre": if run.ride.is_some() { "ride" } else { "path_change" },
        "t_end_s": run.duration_s,
        "terrain": terrain,
    });
    rec
}

/// Records of `runs` with `hidden`, noise 3 % of each channel's SD, in parallel.
pub fn records(runs: &[Run3d], hidden: Hidden3d, seed: u64) -> Vec<Record> {
    use rayon::prelude::*;
    runs.par_iter()
        .enumerate()
        .map(|(i, r)| record(r, hidden, 0.03, seed * 1000 + i as u64))
        .collect()
}

/// Records of `runs` on the vehicle with the front-axle HPS ([`record_hps`]), noise 3 %
/// of each channel's SD, in parallel.
pub fn records_hps(runs: &[Run3d], gas_tau_s: Option<f64>, seed: u64) -> Vec<Record> {
    use rayon::prelude::*;
    runs.par_iter()
        .enumerate()
        .map(|(i, r)| record_hps(r, gas_tau_s, 0.03, seed * 1000 + i as u64))
        .collect()
}
