//! The catalogue of the 3-D vehicle ([`crate::vehicle3d`]): what section 6.3 suspects behind
//! the field discrepancies of the paper's 3-D model, and how each one acts.
//!
//! Model-side effects change the replayed vehicle through existing hooks: the tires' lateral
//! relaxation length (tire lateral compliance), the PI drive's speed setpoint
//! ([`vehicle_3d::SpeedSetpoint`], driver throttle), the HPS strut's heat-transfer extension
//! ([`hps_emulsion::HeatTransfer`], gas temperature). Measurement-side effects act on the
//! predicted sensor channels only ([`SensorEffects::apply`]): a compliant sensor mount as a
//! second-order base-excitation filter, a misaligned sensor as a rotation of its axes.

use crate::{EffectSpec, ParamSpec};

/// Catalogue names, in catalogue order; `hps-gas-temperature` is in the catalogue of the
/// model with the front-axle HPS only (a rigid axle has no gas to heat).
pub const EFFECTS: [&str; 5] = [
    "tire-lateral-compliance",
    "mount-compliance",
    "driver-throttle",
    "sensor-misalignment",
    "hps-gas-temperature",
];

/// The sensor block's linear accelerations (body axes x forward, y left, z up; kinematic,
/// without gravity, as `afsv vehicle simulate -o` writes them).
pub const LINEAR_AXES: [&str; 3] = ["cab_accel_x_m_s2", "cab_accel_y_m_s2", "cab_accel_z_m_s2"];

/// The sensor block's angular accelerations, right-handed about the same axes.
pub const ANGULAR_AXES: [&str; 3] = [
    "front_roll_accel_rad_s2",
    "front_pitch_accel_rad_s2",
    "front_yaw_accel_rad_s2",
];

/// The catalogue entries (the first four, plus `hps-gas-temperature` when `hps`).
pub fn catalogue(hps: bool) -> Vec<EffectSpec> {
    let mut c = vec![
        EffectSpec {
            name: EFFECTS[0].into(),
            description: "lateral carcass compliance of the tires in series with the cornering stiffness: the side force builds up over an extra length C_alpha c_y beyond the relaxation length of Table 6.2 (its lag part; the lateral shift of the contact is not modelled)".into(),
            citation: "section 6.3 (lateral PSD mismatch blamed on the tires' lateral compliance); Pacejka (2012) ch. 7, relaxation length = C_alpha / lateral stiffness".into(),
            params: vec![ParamSpec::new("compliance_mm_per_kn", 1.0, 0.0, 5.0)],
        },
        EffectSpec {
            name: EFFECTS[1].into(),
            description: "a compliant mount of the cab or the sensor block: every axis of the 6-axis sensor reads the frame's motion through a second-order base-excitation filter (natural period, damping ratio)".into(),
            citation: "section 6.3 (cab and seat mounts not modelled; sensors on the cab); ISO 2631-1 transmissibility of resilient mounts".into(),
            params: vec![
                ParamSpec::new("period_s", 0.05, 0.005, 0.5),
                ParamSpec::new("damping_ratio", 0.2, 0.05, 1.0),
            ],
        },
        EffectSpec {
            name: EFFECTS[2].into(),
            description: "the driver's throttle moves the speed: the drive's setpoint is the one under which the model follows the recorded speed (the PI drive inverted, then corrected by one replay), its swing about the held speed scaled by a gain, where the paper's drive holds one speed".into(),
            citation: "section 6.3 (longitudinal excitation by the driver's throttle in the field runs)".into(),
            params: vec![ParamSpec::new("gain", 1.0, 0.0, 2.0)],
        },
        EffectSpec {
            name: EFFECTS[3].into(),
            description: "the sensor block is mounted rotated (roll, pitch, yaw about its x, y, z): its axes mix the body's accelerations, and gravity, subtracted along the assumed vertical, leaks into the horizontal channels".into(),
            citation: "section 6.3 (sensor placement and orientation on the field vehicle)".into(),
            params: vec![
                ParamSpec::new("roll_deg", 0.0, -5.0, 5.0),
                ParamSpec::new("pitch_deg", 0.0, -5.0, 5.0),
                ParamSpec::new("yaw_deg", 0.0, -5.0, 5.0),
            ],
        },
    ];
    if hps {
        c.push(EffectSpec {
            name: EFFECTS[4].into(),
            description: "the HPS gas exchanges heat with the strut body (a gas-temperature state): the gas law moves from adiabatic towards isothermal with a thermal time constant".into(),
            citation: "section 6.3 (HPS gas temperature in the field runs), section 5.4.2; Pourmovahed & Otis (1990)".into(),
            params: vec![ParamSpec::new("tau_s", 2.0, 0.05, 100.0)],
        });
    }
    c
}

/// The measurement-side effects on the 6-axis sensor channels.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SensorEffects {
    /// Mount: natural period (s) and damping ratio.
    pub mount: Option<(f64, f64)>,
    /// Misalignment: roll, pitch, yaw of the sensor axes (deg).
    pub misalignment: Option<[f64; 3]>,
}

impl SensorEffects {
    /// Apply to the six sensor channels of one record sampled at `dt_s`: `linear` in
    /// [`LINEAR_AXES`] order, `angular` in [`ANGULAR_AXES`] order (absent ones `None`;
    /// the rotation needs all three of a kind, else that kind is left unrotated).
    pub fn apply(
        &self,
        dt_s: f64,
        gravity_m_s2: f64,
        linear: &mut [Option<Vec<f64>>; 3],
        angular: &mut [Option<Vec<f64>>; 3],
    ) {
        if let Some(angles) = self.misalignment {
            let r = rotation(angles);
            rotate(&r, linear, Some(gravity_m_s2));
            rotate(&r, angular, None);
        }
        if let Some((period, zeta)) = self.mount {
            for ch in linear.iter_mut().chain(angular.iter_mut()).flatten() {
                mount_filter(ch, dt_s, period, zeta);
            }
        }
    }
}

/// Rotation matrix of the sensor axes: `Rz(yaw) Ry(pitch) Rx(roll)`, angles in degrees.
pub fn rotation([roll, pitch, yaw]: [f64; 3]) -> [[f64; 3]; 3] {
    let (sr, cr) = roll.to_radians().sin_cos();
    let (sp, cp) = pitch.to_radians().sin_cos();
    let (sy, cy) = yaw.to_radians().sin_cos();
    [
        [cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
        [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
        [-sp, cp * sr, cp * cr],
    ]
}

/// `v <- R v` sample by sample on three channels. With `gravity`, the accelerometer's
/// reading: the specific force `a + g e_z` seen in the rotated axes, less `g e_z` (the
/// gravity the record's convention subtracts along the assumed vertical).
fn rotate(r: &[[f64; 3]; 3], ch: &mut [Option<Vec<f64>>; 3], gravity: Option<f64>) {
    let [Some(x), Some(y), Some(z)] = ch else {
        return;
    };
    let g = gravity.unwrap_or(0.0);
    for i in 0..x.len().min(y.len()).min(z.len()) {
        let v = [x[i], y[i], z[i] + g];
        let w: Vec<f64> = r
            .iter()
            .map(|row| row[0] * v[0] + row[1] * v[1] + row[2] * v[2])
            .collect();
        x[i] = w[0];
        y[i] = w[1];
        z[i] = w[2] - g;
    }
}

/// A sensor on a mount of natural period `period_s` and damping ratio `zeta`: its absolute
/// acceleration follows the base's through `H(s) = (2 zeta w s + w^2) / (s^2 + 2 zeta w s +
/// w^2)`, discretised by the bilinear (Tustin) transform at `dt_s`, started at rest on the
/// first sample (unit gain at zero frequency).
pub fn mount_filter(x: &mut [f64], dt_s: f64, period_s: f64, zeta: f64) {
    let Some(&first) = x.first() else {
        return;
    };
    let w = std::f64::consts::TAU / period_s;
    let k = 2.0 / dt_s;
    let (k2, w2, d) = (k * k, w * w, 2.0 * zeta * w * k);
    let a0 = k2 + d + w2;
    let b = [(d + w2) / a0, 2.0 * w2 / a0, (w2 - d) / a0];
    let a = [(2.0 * w2 - 2.0 * k2) / a0, (k2 - d + w2) / a0];
    let (mut x1, mut x2, mut y1, mut y2) = (first, first, first, first);
    for v in x.iter_mut() {
        let x0 = *v;
        let y0 = b[0] * x0 + b[1] * x1 + b[2] * x2 - a[0] * y1 - a[1] * y2;
        (x2, x1, y2, y1) = (x1, x0, y1, y0);
        *v = y0;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_mount_passes_slow_motion_and_rings_at_its_period() {
        let dt = 0.01;
        let mut step = vec![0.0; 10];
        step.extend(vec![1.0; 400]);
        mount_filter(&mut step, dt, 0.1, 0.1);
        assert!((step[409] - 1.0).abs() < 1e-3, "unit gain at rest");
        let peak = step.iter().cloned().fold(0.0, f64::max);
        assert!(peak > 1.5, "a lightly damped mount overshoots: {peak}");
        let mut sine: Vec<f64> = (0..2000)
            .map(|i| (std::f64::consts::TAU * 0.5 * i as f64 * dt).sin())
            .collect();
        let orig = sine.clone();
        mount_filter(&mut sine, dt, 0.02, 0.3);
        let err = sine[1000..]
            .iter()
            .zip(&orig[1000..])
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        assert!(err < 0.01, "0.5 Hz through a 50 Hz mount: {err}");
    }

    #[test]
    fn misalignment_mixes_axes_and_leaks_gravity() {
        let r = rotation([0.0, 0.0, 0.0]);
        assert_eq!(r, [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]);
        let fx = SensorEffects {
            misalignment: Some([0.0, 2.0, 0.0]),
            mount: None,
        };
        let mut lin = [Some(vec![0.0]), Some(vec![0.0]), Some(vec![0.0])];
        let mut ang = [Some(vec![0.0]), Some(vec![1.0]), Some(vec![0.0])];
        fx.apply(0.01, 9.81, &mut lin, &mut ang);
        let x = lin[0].as_ref().unwrap()[0];
        assert!((x - 9.81 * 2f64.to_radians().sin()).abs() < 1e-12, "{x}");
        let z = lin[2].as_ref().unwrap()[0];
        assert!((z - 9.81 * (2f64.to_radians().cos() - 1.0)).abs() < 1e-12);
        assert_eq!(
            ang[1].as_ref().unwrap()[0],
            1.0,
            "pitch rate about the pitch axis"
        );
        assert_eq!(catalogue(false).len(), 4);
        assert_eq!(catalogue(true)[4].name, EFFECTS[4]);
    }
}
