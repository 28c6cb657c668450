//! The cab's and the seat's parameters by name ([`ParamSet`] for [`SeatParams`] and
//! [`CabParams`]): every scalar by its serde name (the cab's mounts as `mounts[0].x_m` ..
//! `mounts[3].damping_n_s_per_m`), with SI unit, the range a design may explore and a
//! typical magnitude (the generic cab and seat, `docs/layouts.md` "Cab and seat
//! suspension"). The ranges lie inside the validation's ([`SeatParams::validate`],
//! [`CabParams::validate`]), which still applies on every set (e.g. the end stops at least
//! as stiff as the suspension). The seat's optional cushion is not listed: a name must
//! address a value every seat has.

use super::params::{CabParams, SeatParams};
use crate::params::{ParamSet, ParamSpec};

/// The scalar parameters of [`SeatParams`] (cushion excepted), in field order.
pub const SEAT_PARAMS: [ParamSpec; 8] = [
    // suspended part plus, without a cushion, the operator's seated mass (generic 80 kg)
    ParamSpec::new("suspended_mass_kg", "kg", 30.0, 200.0, 80.0),
    // suspension stiffness about mid-travel (generic: 80 kg tuned to 1.5 Hz)
    ParamSpec::new("stiffness_n_per_m", "N/m", 1000.0, 100000.0, 7106.0),
    // suspension damping (generic: damping ratio 0.3)
    ParamSpec::new("damping_n_s_per_m", "N·s/m", 0.0, 20000.0, 452.0),
    // total travel between the end stops
    ParamSpec::new("travel_m", "m", 0.02, 0.3, 0.1),
    // each end stop's stiffness (>= the suspension's, checked by the set)
    ParamSpec::new(
        "stop_stiffness_n_per_m",
        "N/m",
        10000.0,
        10000000.0,
        150000.0,
    ),
    // position ahead of the mount-plane centre O
    ParamSpec::new("x_m", "m", -3.0, 3.0, 0.2),
    // position left of O
    ParamSpec::new("y_m", "m", -2.0, 2.0, 0.5),
    // height of the suspended mass above the mount plane
    ParamSpec::new("height_m", "m", 0.0, 2.0, 0.5),
];

/// The scalar parameters of [`CabParams`], in field order (each mount's four after the
/// cab's own four).
pub const CAB_PARAMS: [ParamSpec; 20] = [
    ParamSpec::new("mass_kg", "kg", 200.0, 5000.0, 1100.0),
    ParamSpec::new("roll_inertia_kg_m2", "kg·m²", 20.0, 10000.0, 601.0),
    ParamSpec::new("pitch_inertia_kg_m2", "kg·m²", 20.0, 10000.0, 664.0),
    ParamSpec::new("cg_height_m", "m", 0.0, 3.0, 0.9),
    ParamSpec::new("mounts[0].x_m", "m", -3.0, 3.0, 0.8),
    ParamSpec::new("mounts[0].y_m", "m", -2.0, 2.0, 0.65),
    ParamSpec::new(
        "mounts[0].stiffness_n_per_m",
        "N/m",
        10000.0,
        1.0e8,
        550000.0,
    ),
    ParamSpec::new(
        "mounts[0].damping_n_s_per_m",
        "N·s/m",
        0.0,
        100000.0,
        3500.0,
    ),
    ParamSpec::new("mounts[1].x_m", "m", -3.0, 3.0, 0.8),
    ParamSpec::new("mounts[1].y_m", "m", -2.0, 2.0, 0.65),
    ParamSpec::new(
        "mounts[1].stiffness_n_per_m",
        "N/m",
        10000.0,
        1.0e8,
        550000.0,
    ),
    ParamSpec::new(
        "mounts[1].damping_n_s_per_m",
        "N·s/m",
        0.0,
        100000.0,
        3500.0,
    ),
    ParamSpec::new("mounts[2].x_m", "m", -3.0, 3.0, 0.8),
    ParamSpec::new("mounts[2].y_m", "m", -2.0, 2.0, 0.65),
    ParamSpec::new(
        "mounts[2].stiffness_n_per_m",
        "N/m",
        10000.0,
        1.0e8,
        550000.0,
    ),
    ParamSpec::new(
        "mounts[2].damping_n_s_per_m",
        "N·s/m",
        0.0,
        100000.0,
        3500.0,
    ),
    ParamSpec::new("mounts[3].x_m", "m", -3.0, 3.0, 0.8),
    ParamSpec::new("mounts[3].y_m", "m", -2.0, 2.0, 0.65),
    ParamSpec::new(
        "mounts[3].stiffness_n_per_m",
        "N/m",
        10000.0,
        1.0e8,
        550000.0,
    ),
    ParamSpec::new(
        "mounts[3].damping_n_s_per_m",
        "N·s/m",
        0.0,
        100000.0,
        3500.0,
    ),
];

impl ParamSet for SeatParams {
    fn set_name(&self) -> &'static str {
        "seat"
    }

    fn specs(&self) -> &'static [ParamSpec] {
        &SEAT_PARAMS
    }

    fn value(&self, index: usize) -> f64 {
        match index {
            0 => self.suspended_mass_kg,
            1 => self.stiffness_n_per_m,
            2 => self.damping_n_s_per_m,
            3 => self.travel_m,
            4 => self.stop_stiffness_n_per_m,
            5 => self.x_m,
            6 => self.y_m,
            7 => self.height_m,
            _ => panic!("seat parameter index {index} out of range"),
        }
    }

    fn assign(&mut self, index: usize, value: f64) {
        let slot = match index {
            0 => &mut self.suspended_mass_kg,
            1 => &mut self.stiffness_n_per_m,
            2 => &mut self.damping_n_s_per_m,
            3 => &mut self.travel_m,
            4 => &mut self.stop_stiffness_n_per_m,
            5 => &mut self.x_m,
            6 => &mut self.y_m,
            7 => &mut self.height_m,
            _ => panic!("seat parameter index {index} out of range"),
        };
        *slot = value;
    }

    fn check(&self) -> Result<(), String> {
        self.validate().map_err(|e| e.to_string())
    }
}

impl ParamSet for CabParams {
    fn set_name(&self) -> &'static str {
        "cab"
    }

    fn specs(&self) -> &'static [ParamSpec] {
        &CAB_PARAMS
    }

    fn value(&self, index: usize) -> f64 {
        match index {
            0 => self.mass_kg,
            1 => self.roll_inertia_kg_m2,
            2 => self.pitch_inertia_kg_m2,
            3 => self.cg_height_m,
            4..=19 => {
                let m = &self.mounts[(index - 4) / 4];
                [m.x_m, m.y_m, m.stiffness_n_per_m, m.damping_n_s_per_m][(index - 4) % 4]
            }
            _ => panic!("cab parameter index {index} out of range"),
        }
    }

    fn assign(&mut self, index: usize, value: f64) {
        let slot = match index {
            0 => &mut self.mass_kg,
            1 => &mut self.roll_inertia_kg_m2,
            2 => &mut self.pitch_inertia_kg_m2,
            3 => &mut self.cg_height_m,
            4..=19 => {
                let m = &mut self.mounts[(index - 4) / 4];
                match (index - 4) % 4 {
                    0 => &mut m.x_m,
                    1 => &mut m.y_m,
                    2 => &mut m.stiffness_n_per_m,
                    _ => &mut m.damping_n_s_per_m,
                }
            }
            _ => panic!("cab parameter index {index} out of range"),
        };
        *slot = value;
    }

    fn check(&self) -> Result<(), String> {
        self.validate().map_err(|e| e.to_string())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::check_specs;

    #[test]
    fn specs_are_well_formed_and_the_generic_sets_lie_in_their_ranges() {
        check_specs(&SEAT_PARAMS).unwrap();
        check_specs(&CAB_PARAMS).unwrap();
        assert!(SeatParams::generic().out_of_range().is_empty());
        assert!(CabParams::generic().out_of_range().is_empty());
    }

    #[test]
    fn every_name_reads_and_writes_its_own_field() {
        let mut s = SeatParams::generic();
        for (i, spec) in SEAT_PARAMS.iter().enumerate() {
            let v = s.value(i) + 0.125;
            let mut t = s;
            t.assign(i, v);
            assert_eq!(t.value(i), v, "{}", spec.name);
            let changed = (0..SEAT_PARAMS.len()).filter(|&j| t.value(j) != s.value(j));
            assert_eq!(changed.count(), 1, "{}", spec.name);
        }
        let mut c = CabParams::generic();
        for (i, spec) in CAB_PARAMS.iter().enumerate() {
            let v = c.value(i) + 0.125;
            let mut t = c;
            t.assign(i, v);
            assert_eq!(t.value(i), v, "{}", spec.name);
            let changed = (0..CAB_PARAMS.len()).filter(|&j| t.value(j) != c.value(j));
            assert_eq!(changed.count(), 1, "{}", spec.name);
        }
        // by name, through the set's check: stops softer than the suspension are refused
        s.set("stiffness_n_per_m", 20000.0).unwrap();
        assert_eq!(s.stiffness_n_per_m, 20000.0);
        let e = s.set("stop_stiffness_n_per_m", 10000.0).unwrap_err();
        assert!(e.to_string().contains("stop_stiffness_n_per_m"), "{e}");
        assert_eq!(s.stop_stiffness_n_per_m, 150e3);
        c.set("mounts[2].stiffness_n_per_m", 4e5).unwrap();
        assert_eq!(c.mounts[2].stiffness_n_per_m, 4e5);
        assert_eq!(c.mounts[1].stiffness_n_per_m, 550e3);
    }
}
