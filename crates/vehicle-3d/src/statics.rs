//! Static tire loads by hand (note 2.11) and the static deflections they give.
//!
//! The articulation joint's two revolutes (yaw about z, roll about x) are rigid in pitch,
//! so in the vertical plane the truck is one rigid body on two axles. With the combined cg
//! `x_cg` (from the joint, forward positive) of the front unit, rear unit and payload and the
//! axles at `+a` and `-b`, the front axle carries `W (x_cg + b) / (a + b)`, the rear axle the
//! rest; each tire half of its axle. Table 6.1 gives unloaded 122.69 / 71.06 kN and loaded
//! 149.83 / 209.32 kN per front / rear tire.
//!
//! With the rear walking-beam bogie ([`crate::bogie`]) the pivots sit where the single rear
//! axle sat, so the axle loads are the same; each centred beam shares its pivot's load
//! equally between its wheels, so each of the four rear tires carries a quarter of the rear
//! axle.

use hps_emulsion::HpsStrut;
use tire_fiala::LoadDeflectionTable;

use crate::error::{rejected, VehicleError};
use crate::params::{Load, VehicleParams};

/// Static loads and deflections of one load case.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Statics {
    /// Total mass (kg).
    pub total_mass_kg: f64,
    /// Combined cg from the joint (m, forward positive).
    pub cg_x_m: f64,
    /// Load of one front tire (N).
    pub front_tire_load_n: f64,
    /// Load of one rear tire (N); with the bogie, of one of its four tires.
    pub rear_tire_load_n: f64,
    /// Deflection of a front tire under its load (m), from the load-deflection table.
    pub front_tire_deflection_m: f64,
    /// Deflection of a rear tire (m).
    pub rear_tire_deflection_m: f64,
}

impl Statics {
    /// The hand calculation of the module docs for `load` (parameters validated by the
    /// caller). Fails when a load lies beyond the tire's load-deflection table.
    pub fn of(p: &VehicleParams, load: Load) -> Result<Self, VehicleError> {
        let g = p.gravity_m_s2;
        let front = &p.front_unit;
        let mut mass = front.mass_kg;
        let mut moment = front.mass_kg * front.cg_to_joint_m;
        for part in p.rear_parts(load) {
            mass += part.mass_kg;
            moment -= part.mass_kg * part.cg_to_joint_m;
        }
        let cg_x = moment / mass;
        let (a, b) = (p.front_axle_to_joint_m, p.rear_axle_to_joint_m);
        let weight = mass * g;
        let front_axle = weight * (cg_x + b) / (a + b);
        let rear_axle = weight - front_axle;
        if front_axle <= 0.0 || rear_axle <= 0.0 {
            return Err(rejected(
                "front_unit.cg_to_joint_m",
                front.cg_to_joint_m,
                "the combined cg lies outside the wheel base",
            ));
        }
        let table = LoadDeflectionTable::new(&p.tire.load_deflection)?;
        let deflection = |load: f64| -> Result<f64, VehicleError> {
            let d = table.deflection_at(load);
            if d.is_finite() && d > 0.0 && d < p.tire.unloaded_radius_m {
                Ok(d)
            } else {
                Err(rejected(
                    "tire.load_deflection",
                    load,
                    "no static deflection for this tire load",
                ))
            }
        };
        let rear_share = if p.bogie.is_some() { 0.25 } else { 0.5 };
        Ok(Self {
            total_mass_kg: mass,
            cg_x_m: cg_x,
            front_tire_load_n: 0.5 * front_axle,
            rear_tire_load_n: rear_share * rear_axle,
            front_tire_deflection_m: deflection(0.5 * front_axle)?,
            rear_tire_deflection_m: deflection(rear_share * rear_axle)?,
        })
    }

    /// Static force of one front strut (N): the tire load less the weight of the wheel end
    /// below the strut.
    pub fn front_strut_force_n(&self, p: &VehicleParams) -> f64 {
        self.front_tire_load_n - p.wheel_mass_kg * p.gravity_m_s2
    }

    /// Static force of one rear strut (N): the tire load less the weight of the wheel end
    /// below the strut; with the bogie, the side's two tire loads less the weight of its
    /// beam and two wheel ends, `W_r / 2 - (2 m_w + m_b) g`.
    pub fn rear_strut_force_n(&self, p: &VehicleParams) -> f64 {
        match &p.bogie {
            None => self.rear_tire_load_n - p.wheel_mass_kg * p.gravity_m_s2,
            Some(b) => {
                2.0 * self.rear_tire_load_n
                    - (2.0 * p.wheel_mass_kg + b.beam_mass_kg) * p.gravity_m_s2
            }
        }
    }

    /// Mean static tire load (N) and deflection (m) over the vehicle's tires (two front, two
    /// or, with the bogie, four rear): the rolling-resistance feed-forward of the drive.
    pub fn mean_tire_load_and_deflection(&self, p: &VehicleParams) -> (f64, f64) {
        let (f, r) = (self.front_tire_load_n, self.rear_tire_load_n);
        let (df, dr) = (self.front_tire_deflection_m, self.rear_tire_deflection_m);
        match p.bogie {
            None => (0.5 * (f + r), 0.5 * (df + dr)),
            Some(_) => ((f + 2.0 * r) / 3.0, (df + 2.0 * dr) / 3.0),
        }
    }
}

/// Static deflection z_s (m, compression positive from mid-stroke) at which `strut`
/// carries `force` (N), by bisection on its static force over the travel.
pub fn strut_static_deflection(strut: &HpsStrut, force: f64) -> Result<f64, VehicleError> {
    let travel = strut.params().travel;
    let f = |z: f64| strut.static_force(z).map(|s| s - force);
    let (mut lo, mut hi) = (-travel, travel);
    let (f_lo, f_hi) = (f(lo)?, f(hi)?);
    if !(f_lo <= 0.0 && f_hi >= 0.0) {
        return Err(rejected(
            "hps",
            force,
            "the strut cannot carry this static load within its travel",
        ));
    }
    for _ in 0..80 {
        let mid = 0.5 * (lo + hi);
        if f(mid)? < 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(0.5 * (lo + hi))
}

#[cfg(test)]
mod tests {
    use super::*;
    use hps_emulsion::HpsExtensions;

    #[test]
    fn table_6_1_gives_the_hand_loads_of_note_2_11() {
        let p = VehicleParams::nominal();
        let u = Statics::of(&p, Load::Unloaded).unwrap();
        assert!((u.front_tire_load_n - 122.69e3).abs() < 10.0, "{u:?}");
        assert!((u.rear_tire_load_n - 71.06e3).abs() < 10.0, "{u:?}");
        let l = Statics::of(&p, Load::Loaded).unwrap();
        assert!((l.front_tire_load_n - 149.83e3).abs() < 10.0, "{l:?}");
        assert!((l.rear_tire_load_n - 209.32e3).abs() < 10.0, "{l:?}");
        // the load-deflection table is progressive: the loaded rear tire deflects most
        assert!(l.rear_tire_deflection_m > l.front_tire_deflection_m);
        assert!(l.rear_tire_deflection_m < 0.13 && u.rear_tire_deflection_m > 0.04);
    }

    #[test]
    fn front_struts_settle_within_their_travel() {
        let p = VehicleParams::nominal();
        let strut = HpsStrut::new(&p.hps, &HpsExtensions::default()).unwrap();
        for load in [Load::Loaded, Load::Unloaded] {
            let s = Statics::of(&p, load).unwrap();
            let force = s.front_strut_force_n(&p);
            let z = strut_static_deflection(&strut, force).unwrap();
            assert!((strut.static_force(z).unwrap() - force).abs() < 1e-3 * force);
            // note 2.10: loaded near mid-stroke, unloaded extended by a few cm
            match load {
                Load::Loaded => assert!(z.abs() < 0.03, "{z}"),
                Load::Unloaded => assert!((-0.08..-0.01).contains(&z), "{z}"),
            }
        }
    }
}
