//! Static equilibrium of the loaded truck on level ground, by hand (note 1.9): axle loads
//! from the sprung-mass cg position (Table 2.1), tire loads, tire and strut deflections.
//! The model is built so that this state is its equilibrium; `tests/statics.rs` checks
//! that a perturbed truck settles back to these tire loads.

use crate::params::TruckParams;

/// Static loads and deflections of the truck on level ground.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Statics {
    /// Load on one front tire (N): `(m_s g b / L + m_uf g) / 2`.
    pub front_tire_load_n: f64,
    /// Load on one of the four rear tires (N): `(m_s g a / L + m_ur g) / 4`.
    pub rear_tire_load_n: f64,
    /// Force in one front strut (N): the sprung weight share `m_s g b / (2 L)`.
    pub front_strut_force_n: f64,
    /// Force in one rear strut (N): `m_s g a / (2 L)`.
    pub rear_strut_force_n: f64,
    /// Static front tire deflection (m).
    pub front_tire_deflection_m: f64,
    /// Static rear tire deflection (m).
    pub rear_tire_deflection_m: f64,
    /// Static front strut deflection from its free length (m), for the travel check.
    pub front_strut_deflection_m: f64,
    /// Static rear strut deflection from its free length (m).
    pub rear_strut_deflection_m: f64,
}

impl Statics {
    /// The hand calculation for `p` (any parameter set; not validated here).
    pub fn of(p: &TruckParams) -> Self {
        let g = p.gravity_m_s2;
        let sprung_front = p.sprung_mass_kg * g * p.cg_to_rear_axle_m() / p.wheelbase_m;
        let sprung_rear = p.sprung_mass_kg * g * p.cg_to_front_axle_m / p.wheelbase_m;
        let front_tire_load_n = 0.5 * (sprung_front + p.front_unsprung_mass_kg * g);
        let rear_tire_load_n = 0.25 * (sprung_rear + p.rear_unsprung_mass_kg * g);
        let front_strut_force_n = 0.5 * sprung_front;
        let rear_strut_force_n = 0.5 * sprung_rear;
        Self {
            front_tire_load_n,
            rear_tire_load_n,
            front_strut_force_n,
            rear_strut_force_n,
            front_tire_deflection_m: front_tire_load_n / p.tire_vertical_stiffness_n_per_m,
            rear_tire_deflection_m: rear_tire_load_n / p.tire_vertical_stiffness_n_per_m,
            front_strut_deflection_m: front_strut_force_n / p.front_spring_n_per_m,
            rear_strut_deflection_m: rear_strut_force_n / p.rear_spring_n_per_m,
        }
    }
}

/// Quasi-static roll stiffness (N m/rad) of the upright truck `p` on level ground, by hand:
/// the second derivative of its potential energy in the sprung roll angle `phi`, the
/// axle-line rolls `theta_f`, `theta_r` minimised out, lateral translation free (no
/// lateral tire stiffness at rest), small angles:
///
/// ```text
/// V = K_sf (theta_f - phi)^2 / 2 + K_tf theta_f^2 / 2 + K_sr (theta_r - phi)^2 / 2
///   + (K_tr + S_r (h_r - c_r)) theta_r^2 / 2
///   - (S_f (H - h_f) + 2 W_f (h_f - c_f) + S_r (H - c_r)) phi^2 / 2
/// K = K_sf K_tf / (K_sf + K_tf) + K_sr K'_tr / (K_sr + K'_tr) - D
/// ```
///
/// with strut roll rates `K_s = k (r T)^2 / 2` (Table 2.2 per station, `r` the strut
/// spacing ratio), tire roll rates `K_t = k_t sum y_i^2` (front at `±T_f/2`, rear duals at
/// `±(T_r ± d)/2`), sprung weights on the axles `S_f`, `S_r`, static front tire load
/// `W_f`, sprung cg height `H`, wheel-centre heights `h`, roll-centre heights `c`
/// ([`TruckParams::front_roll_centre_height_m`], `rear_roll_centre_height_m`). The front
/// term: the sprung mass and carriers tip over tires that hang from the carriers at `c_f`,
/// so the whole front weight `2 W_f` rises with `(h_f - c_f)` besides the sprung weight's
/// `(H - h_f)`. The truck is statically roll-stable when `K > 0`.
pub fn roll_stiffness_n_m_per_rad(p: &TruckParams) -> f64 {
    let s = Statics::of(p);
    let (h_f, h_r) = p.wheel_centre_heights_m();
    let (c_f, c_r) = (p.front_roll_centre_height_m, p.rear_roll_centre_height_m);
    let h = p.cg_height_m;
    let r = p.strut_spacing_ratio;
    let k_t = p.tire_vertical_stiffness_n_per_m;
    let k_sf = p.front_spring_n_per_m * (r * p.front_track_m).powi(2) / 2.0;
    let k_sr = p.rear_spring_n_per_m * (r * p.rear_track_m).powi(2) / 2.0;
    let k_tf = k_t * p.front_track_m.powi(2) / 2.0;
    let (outer, inner) = (
        0.5 * (p.rear_track_m + p.dual_spacing_m),
        0.5 * (p.rear_track_m - p.dual_spacing_m),
    );
    let s_f = 2.0 * s.front_strut_force_n;
    let s_r = 2.0 * s.rear_strut_force_n;
    let k_tr = 2.0 * k_t * (outer * outer + inner * inner) + s_r * (h_r - c_r);
    let series = |a: f64, b: f64| a * b / (a + b);
    let destabilising = s_f * (h - h_f) + 2.0 * s.front_tire_load_n * (h_f - c_f) + s_r * (h - c_r);
    series(k_sf, k_tf) + series(k_sr, k_tr) - destabilising
}

/// The smallest strut spacing ratio in `(0, 1]` at which [`roll_stiffness_n_m_per_rad`]
/// is positive (bisection to 1e-9; the stiffness rises with the ratio), or `None` if the
/// truck is unstable even at 1. The hand value of the stability floor that
/// [`crate::calibration::calibrate_strut_spacing`] finds by simulation.
pub fn hand_stability_floor(p: &TruckParams) -> Option<f64> {
    let at = |r: f64| {
        let mut q = *p;
        q.strut_spacing_ratio = r;
        roll_stiffness_n_m_per_rad(&q)
    };
    if at(1.0) <= 0.0 {
        return None;
    }
    let (mut lo, mut hi) = (0.0, 1.0);
    while hi - lo > 1e-9 {
        let mid = 0.5 * (lo + hi);
        if at(mid) > 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Some(hi)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn loaded_truck_matches_note_1_9() {
        let s = Statics::of(&TruckParams::nominal());
        // note 1.9 (derived): 149.8 kN per front tire, 134.9 kN per rear tire
        assert!((s.front_tire_load_n / 1e3 - 149.8).abs() < 0.1, "{s:?}");
        assert!((s.rear_tire_load_n / 1e3 - 134.9).abs() < 0.1, "{s:?}");
        // per wheel station: 119 mm front, 45 mm rear static strut deflection
        assert!((s.front_strut_deflection_m - 0.119).abs() < 1e-3);
        assert!((s.rear_strut_deflection_m - 0.0445).abs() < 1e-3);
    }

    #[test]
    fn hand_floor_rises_when_the_front_tires_hang_lower() {
        let p = TruckParams::nominal();
        let wheel_centre = hand_stability_floor(&p).unwrap();
        let mut ground = p;
        ground.front_roll_centre_height_m = 0.0;
        let ground = hand_stability_floor(&ground).unwrap();
        // numbers of docs/roll-truck.md
        assert!((wheel_centre - 0.2531).abs() < 2e-4, "{wheel_centre}");
        assert!((ground - 0.2776).abs() < 2e-4, "{ground}");
        // a stiff suspension is stable, a very soft one not
        let mut q = p;
        q.strut_spacing_ratio = 0.5;
        assert!(roll_stiffness_n_m_per_rad(&q) > 0.0);
        q.strut_spacing_ratio = 0.1;
        assert!(roll_stiffness_n_m_per_rad(&q) < 0.0);
    }
}
