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
}
