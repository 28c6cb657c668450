//! The driver's throttle of the `driver-throttle` effect: the recorded speed smoothed by a
//! local quadratic fit, and the PI drive's speed error under which the model's drive
//! follows it (docs/discovery.md, "The 3-D vehicle").

use super::Replay3d;
use vehicle_3d::{Load, VehicleParams};

/// The recorded speed of `rec` smoothed over +-[`super::THROTTLE_SMOOTH_S`] ([`local_quadratic`])
/// and its rate: what the drive follows under `driver-throttle`.
pub fn throttle_target(rec: &Replay3d) -> (&[f64], &[f64]) {
    (&rec.speed_smooth.0, &rec.speed_smooth.1)
}

/// The PI drive's speed error `e` (m/s) along a record of spacing `dt_s` under which the
/// drive gives the torque that accelerates `params`' vehicle (loaded as `load`) at `rate`:
/// with the lumped longitudinal inertia per wheel torque `M = (m + 4 J / r^2) r / 4` (m the
/// vehicle's mass, J the wheel spin inertia, r the unloaded radius), the drive law
/// `kp e + ki E = M dv/dt` (E the integral of e, 0 at the start, as the replay's) is solved
/// exactly over each sample for the torque held. Rolling resistance is the drive's
/// feed-forward; the tires' slip lag between torque and force is left to the correction
/// replay of [`super::Vehicle3dModel::following_setpoint`].
pub fn drive_error(params: &VehicleParams, load: Load, dt_s: f64, rate: &[f64]) -> Vec<f64> {
    let mass = params.front_unit.mass_kg
        + params
            .rear_parts(load)
            .iter()
            .map(|p| p.mass_kg)
            .sum::<f64>();
    let r = params.tire.unloaded_radius_m;
    let inertia = (mass + 4.0 * params.wheel_spin_inertia_kg_m2 / (r * r)) * r / 4.0;
    let (kp, ki) = (params.drive.kp_n_m_per_m_s, params.drive.ki_n_m_per_m);
    let decay = (-ki / kp * dt_s).exp();
    let mut big_e = 0.0;
    rate.iter()
        .map(|a| {
            let u = inertia * a;
            let e = (u - ki * big_e) / kp;
            big_e = if ki > 0.0 {
                u / ki + (big_e - u / ki) * decay
            } else {
                big_e + e * dt_s
            };
            e
        })
        .collect()
}

/// The drive's setpoint under which `params`' PI drive reproduces the target `w` of
/// [`throttle_target`] on `rec`: `w + e` with `e` of [`drive_error`] for `w`'s rate.
pub fn throttle_setpoint(params: &VehicleParams, rec: &Replay3d) -> Vec<f64> {
    let (w, rate) = throttle_target(rec);
    let e = drive_error(params, rec.load, rec.dt_s, rate);
    w.iter().zip(&e).map(|(w, e)| w + e).collect()
}

/// Local quadratic least-squares fit of `x` (spacing `dt`) over `2 half + 1` samples about
/// each sample (a Savitzky-Golay smoother; the window is shifted inside the record at its
/// ends, so the ends are not biased as a truncated average is): the fitted value and slope
/// at each sample.
pub fn local_quadratic(x: &[f64], half: usize, dt: f64) -> (Vec<f64>, Vec<f64>) {
    let n = x.len();
    let width = (2 * half + 1).min(n);
    if width < 3 {
        return (x.to_vec(), vec![0.0; n]);
    }
    let mut value = Vec::with_capacity(n);
    let mut slope = Vec::with_capacity(n);
    for i in 0..n {
        let a = i.saturating_sub(half).min(n - width);
        // normal equations of y = c0 + c1 tau + c2 tau^2, tau = (j - i) dt
        let (mut m, mut r) = ([[0.0; 3]; 3], [0.0; 3]);
        for (j, y) in x.iter().enumerate().skip(a).take(width) {
            let tau = (j as f64 - i as f64) * dt;
            let basis = [1.0, tau, tau * tau];
            for (k, bk) in basis.iter().enumerate() {
                r[k] += bk * y;
                for (l, bl) in basis.iter().enumerate() {
                    m[k][l] += bk * bl;
                }
            }
        }
        let c = solve3(m, r).unwrap_or([x[i], 0.0, 0.0]);
        value.push(c[0]);
        slope.push(c[1]);
    }
    (value, slope)
}

/// Solution of the 3 x 3 system `m c = r` by Cramer's rule (`None` when singular: a window
/// of fewer than three samples).
fn solve3(m: [[f64; 3]; 3], r: [f64; 3]) -> Option<[f64; 3]> {
    let det = |a: [[f64; 3]; 3]| {
        a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
            - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
            + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0])
    };
    let d = det(m);
    if d == 0.0 || !d.is_finite() {
        return None;
    }
    let mut c = [0.0; 3];
    for (k, ck) in c.iter_mut().enumerate() {
        let mut a = m;
        for (row, rv) in a.iter_mut().zip(r) {
            row[k] = rv;
        }
        *ck = det(a) / d;
    }
    Some(c)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_local_quadratic_fit_reproduces_a_parabola_to_its_ends() {
        let dt = 0.01;
        let x: Vec<f64> = (0..300)
            .map(|i| {
                let t = i as f64 * dt;
                2.0 + 0.5 * t - 0.3 * t * t
            })
            .collect();
        let (v, r) = local_quadratic(&x, 50, dt);
        for (i, (v, r)) in v.iter().zip(&r).enumerate() {
            let t = i as f64 * dt;
            assert!((v - x[i]).abs() < 1e-9, "{i}: {v}");
            assert!((r - (0.5 - 0.6 * t)).abs() < 1e-9, "{i}: {r}");
        }
        // too short to fit: the samples back, no slope
        assert_eq!(
            local_quadratic(&[1.0, 2.0], 5, dt),
            (vec![1.0, 2.0], vec![0.0; 2])
        );
    }

    #[test]
    fn the_drive_error_solves_the_pi_law() {
        // kp e + ki E = M a for a constant rate a: e = (M a / kp) exp(-ki t / kp)
        let p = VehicleParams::nominal();
        let (dt, a) = (0.01, 0.4);
        let e = drive_error(&p, Load::Loaded, dt, &vec![a; 500]);
        let mass = p.front_unit.mass_kg
            + p.rear_parts(Load::Loaded)
                .iter()
                .map(|q| q.mass_kg)
                .sum::<f64>();
        let r = p.tire.unloaded_radius_m;
        let m = (mass + 4.0 * p.wheel_spin_inertia_kg_m2 / (r * r)) * r / 4.0;
        let (kp, ki) = (p.drive.kp_n_m_per_m_s, p.drive.ki_n_m_per_m);
        for (i, e) in e.iter().enumerate() {
            let want = m * a / kp * (-ki / kp * i as f64 * dt).exp();
            assert!(
                (e - want).abs() < 1e-9 * want.abs().max(1.0),
                "{i}: {e} vs {want}"
            );
        }
    }
}
