//! The chapter-4 design vector chi = [A_0, l_1, l_2, a_v, B_eff] (section 4.3.2, Table 4.2)
//! and its application to the AFS parameters. Everything else (a_m, a_0, leakage, seal
//! friction, the vehicle) stays at the base set: the paper holds them at nominal because
//! they "directly relate to the power consumption".

use crate::error::{positive, DesignError};
use afs_hydraulics::params::VALVE_AV_TABLE_UNIT;
use afs_hydraulics::AfsParams;
use serde::Serialize;

const DEG: f64 = std::f64::consts::PI / 180.0;

/// One entry of the chapter-4 design vector chi, by name (Table 4.2's rows, in order).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum AfsVariable {
    /// A_0, angle between the strut mounts at zero articulation.
    A0,
    /// l_1, front mount distance from the joint.
    L1,
    /// l_2, rear mount distance from the joint.
    L2,
    /// a_v, valve flow gain.
    ValveAv,
    /// B_eff, effective bulk modulus.
    BulkModulus,
}

impl AfsVariable {
    /// The five variables in Table 4.2's order.
    pub const ALL: [AfsVariable; 5] = [
        AfsVariable::A0,
        AfsVariable::L1,
        AfsVariable::L2,
        AfsVariable::ValveAv,
        AfsVariable::BulkModulus,
    ];

    /// Field name of the SI value in [`AfsDesign`] (`a0_rad`, ...).
    pub fn name(self) -> &'static str {
        match self {
            AfsVariable::A0 => "a0_rad",
            AfsVariable::L1 => "l1_m",
            AfsVariable::L2 => "l2_m",
            AfsVariable::ValveAv => "valve_av",
            AfsVariable::BulkModulus => "bulk_modulus_pa",
        }
    }

    /// Symbol and unit of Table 4.2 (`A_0 (deg)`, ...; a_v in the table unit, L/min per
    /// bar per unit opening, docs/afs-hydraulics.md).
    pub fn table_label(self) -> &'static str {
        match self {
            AfsVariable::A0 => "A_0 (deg)",
            AfsVariable::L1 => "l_1 (m)",
            AfsVariable::L2 => "l_2 (m)",
            AfsVariable::ValveAv => "a_v (L/min/bar)",
            AfsVariable::BulkModulus => "B_eff (GPa)",
        }
    }

    /// SI value per Table 4.2 unit (rad per deg, 1, 1, SI per table unit, Pa per GPa).
    pub fn table_unit(self) -> f64 {
        match self {
            AfsVariable::A0 => DEG,
            AfsVariable::L1 | AfsVariable::L2 => 1.0,
            AfsVariable::ValveAv => VALVE_AV_TABLE_UNIT,
            AfsVariable::BulkModulus => 1e9,
        }
    }
}

/// One chapter-4 design chi (SI units, as in [`AfsParams`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct AfsDesign {
    /// A_0: angle between the strut mounts at zero articulation (rad), Eq 3.7.
    pub a0_rad: f64,
    /// l_1: front mount distance from the joint (m).
    pub l1_m: f64,
    /// l_2: rear mount distance from the joint (m).
    pub l2_m: f64,
    /// a_v: valve flow gain (SI, the unit of [`AfsParams::valve_av`]).
    pub valve_av: f64,
    /// B_eff: effective bulk modulus (Pa).
    pub bulk_modulus_pa: f64,
}

impl AfsDesign {
    /// Names of the entries of [`AfsDesign::to_vector`], in Table 4.2's order.
    pub const NAMES: [&'static str; 5] = ["a0_rad", "l1_m", "l2_m", "valve_av", "bulk_modulus_pa"];

    /// The SI value of variable `v`.
    pub fn get(&self, v: AfsVariable) -> f64 {
        match v {
            AfsVariable::A0 => self.a0_rad,
            AfsVariable::L1 => self.l1_m,
            AfsVariable::L2 => self.l2_m,
            AfsVariable::ValveAv => self.valve_av,
            AfsVariable::BulkModulus => self.bulk_modulus_pa,
        }
    }

    /// Sets variable `v` to the SI value `value` (unchecked; [`AfsDesign::apply`] and
    /// [`AfsDesign::from_vector`] validate).
    pub fn set(&mut self, v: AfsVariable, value: f64) {
        match v {
            AfsVariable::A0 => self.a0_rad = value,
            AfsVariable::L1 => self.l1_m = value,
            AfsVariable::L2 => self.l2_m = value,
            AfsVariable::ValveAv => self.valve_av = value,
            AfsVariable::BulkModulus => self.bulk_modulus_pa = value,
        }
    }

    /// A design with every entry finite and positive, A_0 below 180 deg.
    pub fn new(
        a0_rad: f64,
        l1_m: f64,
        l2_m: f64,
        valve_av: f64,
        bulk_modulus_pa: f64,
    ) -> Result<Self, DesignError> {
        positive("a0_rad", a0_rad)?;
        if a0_rad >= std::f64::consts::PI {
            return Err(DesignError::Invalid {
                field: "a0_rad",
                value: a0_rad,
                reason: "must be below pi (the mounts would cross the joint)",
            });
        }
        Ok(Self {
            a0_rad,
            l1_m: positive("l1_m", l1_m)?,
            l2_m: positive("l2_m", l2_m)?,
            valve_av: positive("valve_av", valve_av)?,
            bulk_modulus_pa: positive("bulk_modulus_pa", bulk_modulus_pa)?,
        })
    }

    /// A design in Table 4.2's units: A_0 (deg), l_1, l_2 (m), a_v (table unit, L/min per
    /// bar, docs/afs-hydraulics.md), B_eff (GPa).
    pub fn from_table_units(
        a0_deg: f64,
        l1_m: f64,
        l2_m: f64,
        a_v: f64,
        b_eff_gpa: f64,
    ) -> Result<Self, DesignError> {
        Self::new(
            a0_deg * DEG,
            l1_m,
            l2_m,
            a_v * VALVE_AV_TABLE_UNIT,
            b_eff_gpa * 1e9,
        )
    }

    /// The design a parameter set carries (the "current" design for [`AfsParams::nominal`]).
    pub fn of(p: &AfsParams) -> Self {
        Self {
            a0_rad: p.a0_rad,
            l1_m: p.l1_m,
            l2_m: p.l2_m,
            valve_av: p.valve_av,
            bulk_modulus_pa: p.bulk_modulus_pa,
        }
    }

    /// `base` with this design's five entries; the result is validated
    /// ([`AfsParams::validate`]).
    pub fn apply(&self, base: &AfsParams) -> Result<AfsParams, DesignError> {
        let mut p = base.clone();
        p.a0_rad = self.a0_rad;
        p.l1_m = self.l1_m;
        p.l2_m = self.l2_m;
        p.valve_av = self.valve_av;
        p.bulk_modulus_pa = self.bulk_modulus_pa;
        p.validate()?;
        Ok(p)
    }

    /// The entries in Table 4.2's units: A_0 (deg), l_1, l_2 (m), a_v (table unit), B_eff (GPa).
    pub fn table_units(&self) -> [f64; 5] {
        AfsVariable::ALL.map(|v| self.get(v) / v.table_unit())
    }

    /// chi as a vector in SI units, in the order of [`AfsDesign::NAMES`].
    pub fn to_vector(&self) -> [f64; 5] {
        AfsVariable::ALL.map(|v| self.get(v))
    }

    /// [`AfsDesign::new`] from a vector in the order of [`AfsDesign::NAMES`].
    pub fn from_vector(x: [f64; 5]) -> Result<Self, DesignError> {
        let mut d = Self::of(&AfsParams::nominal());
        for (v, value) in AfsVariable::ALL.into_iter().zip(x) {
            d.set(v, value);
        }
        Self::new(d.a0_rad, d.l1_m, d.l2_m, d.valve_av, d.bulk_modulus_pa)
    }

    /// Initial strut length l_0 = sqrt(l_1^2 + l_2^2 - 2 l_1 l_2 cos A_0) (m), Eq 3.7: the
    /// measure L of Eq 4.8.
    pub fn initial_strut_length(&self) -> f64 {
        afs_hydraulics::kinematics::strut_length(self.l1_m, self.l2_m, self.a0_rad)
    }
}

/// Lower and upper bounds of the design space.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct AfsDesignBounds {
    /// Lower bounds.
    pub lower: AfsDesign,
    /// Upper bounds.
    pub upper: AfsDesign,
}

impl AfsDesignBounds {
    /// Bounds with `lower < upper` in every entry.
    pub fn new(lower: AfsDesign, upper: AfsDesign) -> Result<Self, DesignError> {
        for v in AfsVariable::ALL {
            if lower.get(v) >= upper.get(v) {
                return Err(DesignError::Invalid {
                    field: v.name(),
                    value: lower.get(v),
                    reason: "lower bound must be below the upper bound",
                });
            }
        }
        Ok(Self { lower, upper })
    }

    /// Table 4.2: A_0 45-130 deg, l_1 0.8-3.0 m, l_2 0.35-0.95 m, a_v 2.4-7.2 (+-50 %),
    /// B_eff 0.6-1.7 GPa (the saturation near 1.7 GPa, section 4.3.2; Table 4.3's runs).
    pub fn table_4_2() -> Self {
        Self {
            lower: Self::table(45.0, 0.8, 0.35, 2.4, 0.6),
            upper: Self::table(130.0, 3.0, 0.95, 7.2, 1.7),
        }
    }

    /// Table 4.2 with the upper B_eff bound relaxed by 30 % of the nominal 1.6 GPa to 2.08 GPa
    /// (section 4.3.5, Table 4.4's runs).
    pub fn table_4_2_relaxed() -> Self {
        let mut b = Self::table_4_2();
        b.upper.bulk_modulus_pa = 2.08e9;
        b
    }

    fn table(a0_deg: f64, l1: f64, l2: f64, a_v: f64, b_gpa: f64) -> AfsDesign {
        let mut d = AfsDesign::of(&AfsParams::nominal());
        for (v, value) in AfsVariable::ALL
            .into_iter()
            .zip([a0_deg, l1, l2, a_v, b_gpa])
        {
            d.set(v, value * v.table_unit());
        }
        d
    }

    /// Whether `d` lies inside the bounds (bounds included).
    pub fn contains(&self, d: &AfsDesign) -> bool {
        AfsVariable::ALL
            .iter()
            .all(|&v| self.lower.get(v) <= d.get(v) && d.get(v) <= self.upper.get(v))
    }
}

/// The A_0 that maximises the initial steering arm h(0) = l_1 l_2 sin A_0 / l_0 (Eqs 3.2,
/// 3.7) for mount distances `l1_m`, `l2_m` (section 3.4.3): setting dh/dA_0 = 0 gives
/// `cos A_0 = min(l_1, l_2) / max(l_1, l_2)`, the strut perpendicular to the shorter mount
/// radius, where h(0) equals that radius.
pub fn a0_of_longest_initial_arm(l1_m: f64, l2_m: f64) -> Result<f64, DesignError> {
    positive("l1_m", l1_m)?;
    positive("l2_m", l2_m)?;
    Ok((l1_m.min(l2_m) / l1_m.max(l2_m)).acos())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn zero_design_change_returns_the_nominal_set() {
        let p = AfsParams::nominal();
        let d = AfsDesign::of(&p);
        assert_eq!(d.apply(&p).unwrap(), p);
        let back = AfsDesign::from_vector(d.to_vector()).unwrap();
        assert_eq!(back.apply(&p).unwrap(), p);
    }

    #[test]
    fn table_units_round_trip_and_apply() {
        let d = AfsDesign::from_table_units(56.4, 1.79, 0.77, 7.2, 1.7).unwrap();
        let t = d.table_units();
        for (a, b) in t.iter().zip([56.4, 1.79, 0.77, 7.2, 1.7]) {
            assert!((a - b).abs() < 1e-12 * b, "{t:?}");
        }
        let p = d.apply(&AfsParams::nominal()).unwrap();
        assert_eq!(p.l2_m, 0.77);
        assert_eq!(p.leak_velocity, AfsParams::nominal().leak_velocity);
        // Eq 3.7 at the nominal layout: 1.9146 m (docs note).
        let l0 = AfsDesign::of(&AfsParams::nominal()).initial_strut_length();
        assert!((l0 - 1.9146).abs() < 1e-4);
    }

    #[test]
    fn invalid_designs_name_the_field() {
        let e = AfsDesign::new(1.0, 1.0, f64::NAN, 1.0, 1.0).unwrap_err();
        assert!(e.to_string().contains("l2_m"), "{e}");
        assert!(AfsDesign::new(4.0, 1.0, 1.0, 1.0, 1.0).is_err());
        assert!(AfsDesign::new(1.0, 1.0, 1.0, -1.0, 1.0).is_err());
    }

    #[test]
    fn bounds_of_table_4_2() {
        let b = AfsDesignBounds::table_4_2();
        let nominal = AfsDesign::of(&AfsParams::nominal());
        assert!(b.contains(&nominal));
        let t43 = AfsDesign::from_table_units(74.4, 1.86, 0.85, 7.189, 1.7).unwrap();
        assert!(b.contains(&t43));
        let t44 = AfsDesign::from_table_units(56.9, 1.67, 0.72, 7.198, 2.08).unwrap();
        assert!(!b.contains(&t44));
        assert!(AfsDesignBounds::table_4_2_relaxed().contains(&t44));
        assert!(AfsDesignBounds::new(b.upper, b.lower).is_err());
    }

    #[test]
    fn longest_arm_is_the_numeric_maximum() {
        let (l1, l2) = (1.96, 0.64);
        let arm = |a: f64| l1 * l2 * a.sin() / (l1 * l1 + l2 * l2 - 2.0 * l1 * l2 * a.cos()).sqrt();
        let a = a0_of_longest_initial_arm(l1, l2).unwrap();
        assert!((arm(a) - l2).abs() < 1e-12);
        for da in [-1e-3, 1e-3] {
            assert!(arm(a + da) < arm(a));
        }
        assert!(a0_of_longest_initial_arm(0.0, 1.0).is_err());
    }
}
