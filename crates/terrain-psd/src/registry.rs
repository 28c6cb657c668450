//! Named parameters of the terrain sets ([`vehicle_components::ParamSet`]): the synthesis
//! spec [`TwoTrackSpec`] (PSD, band and the coherence model's own parameters) and the
//! surface [`SurfaceParams`]. Names are the serde field paths (`psd.alpha_r`,
//! `band.n_min`, `coherence.m_c`, `track_width_m`), as in this crate's error messages.
//!
//! The coherence parameters present depend on the model: `coherence.m_c` (piecewise,
//! Eq 2.10), `coherence.rho` and `coherence.half_track_m` (Bogsjö, Eq 1.9),
//! `coherence.speed_m_s` (Zhang, Eq 1.8); the fully coherent and independent models have
//! none. Bounds are the physically meaningful ranges a fit or a design may explore.

use vehicle_components::{ParamSet, ParamSpec};

use crate::coherence::CoherenceModel;
use crate::surface::SurfaceParams;
use crate::synth::TwoTrackSpec;

/// PSD and band parameters, common to every coherence model (indices 0-3).
const FIXED: [ParamSpec; 4] = [
    ParamSpec::new("psd.alpha_r", "m^3 (w = 2)", 1e-10, 1e-2, 1e-4),
    ParamSpec::new("psd.waviness", "-", 0.0, 10.0, 2.0),
    ParamSpec::new("band.n_min", "cycle/m", 1e-4, 10.0, 0.02),
    ParamSpec::new("band.n_max", "cycle/m", 1e-3, 1e3, 5.0),
];

const PIECEWISE: [ParamSpec; 5] = [
    FIXED[0],
    FIXED[1],
    FIXED[2],
    FIXED[3],
    ParamSpec::new("coherence.m_c", "cycle/m", 1e-3, 100.0, 0.3),
];

const BOGSJO: [ParamSpec; 6] = [
    FIXED[0],
    FIXED[1],
    FIXED[2],
    FIXED[3],
    ParamSpec::new("coherence.rho", "-", 0.0, 100.0, 0.2),
    ParamSpec::new("coherence.half_track_m", "m", 0.05, 5.0, 1.14),
];

const ZHANG: [ParamSpec; 5] = [
    FIXED[0],
    FIXED[1],
    FIXED[2],
    FIXED[3],
    ParamSpec::new("coherence.speed_m_s", "m/s", 0.01, 100.0, 10.0),
];

impl ParamSet for TwoTrackSpec {
    fn set_name(&self) -> &'static str {
        "terrain synthesis"
    }

    fn specs(&self) -> &'static [ParamSpec] {
        match self.coherence {
            CoherenceModel::Piecewise { .. } => &PIECEWISE,
            CoherenceModel::Bogsjo { .. } => &BOGSJO,
            CoherenceModel::Zhang { .. } => &ZHANG,
            CoherenceModel::Full | CoherenceModel::Independent => &FIXED,
        }
    }

    fn value(&self, index: usize) -> f64 {
        match (index, self.coherence) {
            (0, _) => self.psd.alpha_r,
            (1, _) => self.psd.waviness,
            (2, _) => self.band.n_min,
            (3, _) => self.band.n_max,
            (4, CoherenceModel::Piecewise { m_c }) => m_c,
            (4, CoherenceModel::Bogsjo { rho, .. }) => rho,
            (5, CoherenceModel::Bogsjo { half_track_m, .. }) => half_track_m,
            (4, CoherenceModel::Zhang { speed_m_s }) => speed_m_s,
            _ => panic!("terrain synthesis parameter index {index} out of range"),
        }
    }

    fn assign(&mut self, index: usize, value: f64) {
        match (index, &mut self.coherence) {
            (0, _) => self.psd.alpha_r = value,
            (1, _) => self.psd.waviness = value,
            (2, _) => self.band.n_min = value,
            (3, _) => self.band.n_max = value,
            (4, CoherenceModel::Piecewise { m_c }) => *m_c = value,
            (4, CoherenceModel::Bogsjo { rho, .. }) => *rho = value,
            (5, CoherenceModel::Bogsjo { half_track_m, .. }) => *half_track_m = value,
            (4, CoherenceModel::Zhang { speed_m_s }) => *speed_m_s = value,
            _ => panic!("terrain synthesis parameter index {index} out of range"),
        }
    }

    fn check(&self) -> Result<(), String> {
        self.validate().map_err(|e| e.to_string())
    }
}

const SURFACE: [ParamSpec; 2] = [
    ParamSpec::new("track_width_m", "m", 0.1, 10.0, 2.28),
    ParamSpec::new("friction", "-", 0.0, 2.0, 0.8),
];

impl ParamSet for SurfaceParams {
    fn set_name(&self) -> &'static str {
        "terrain surface"
    }

    fn specs(&self) -> &'static [ParamSpec] {
        &SURFACE
    }

    fn value(&self, index: usize) -> f64 {
        match index {
            0 => self.track_width_m,
            1 => self.friction,
            _ => panic!("terrain surface parameter index {index} out of range"),
        }
    }

    fn assign(&mut self, index: usize, value: f64) {
        match index {
            0 => self.track_width_m = value,
            1 => self.friction = value,
            _ => panic!("terrain surface parameter index {index} out of range"),
        }
    }

    fn check(&self) -> Result<(), String> {
        self.validate().map_err(|e| e.to_string())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use vehicle_components::{check_specs, ParamError};

    fn all_models() -> [CoherenceModel; 5] {
        [
            CoherenceModel::PAPER,
            CoherenceModel::bogsjo(0.2, 1.14).unwrap(),
            CoherenceModel::zhang(10.0).unwrap(),
            CoherenceModel::Full,
            CoherenceModel::Independent,
        ]
    }

    #[test]
    fn specs_are_well_formed_and_hold_the_nominal_values() {
        check_specs(&SURFACE).unwrap();
        let s = SurfaceParams::nominal();
        for spec in s.specs() {
            spec.admit(s.get(spec.name).unwrap()).unwrap();
        }
        for coherence in all_models() {
            let mut t = TwoTrackSpec::paper_nominal();
            t.coherence = coherence;
            check_specs(t.specs()).unwrap();
            for spec in t.specs() {
                let v = t.get(spec.name).unwrap();
                spec.admit(v).unwrap();
                // Setting a parameter to its own value changes nothing.
                let before = t;
                t.set(spec.name, v).unwrap();
                assert_eq!(t, before);
            }
        }
    }

    #[test]
    fn each_name_reaches_its_field() {
        let mut t = TwoTrackSpec::paper_nominal();
        t.set("psd.alpha_r", 2e-4).unwrap();
        t.set("psd.waviness", 2.5).unwrap();
        t.set("band.n_min", 0.05).unwrap();
        t.set("band.n_max", 4.0).unwrap();
        t.set("coherence.m_c", 0.4).unwrap();
        assert_eq!((t.psd.alpha_r, t.psd.waviness), (2e-4, 2.5));
        assert_eq!((t.band.n_min, t.band.n_max), (0.05, 4.0));
        assert_eq!(t.coherence, CoherenceModel::Piecewise { m_c: 0.4 });
        t.coherence = CoherenceModel::bogsjo(0.2, 1.14).unwrap();
        t.set("coherence.rho", 0.3).unwrap();
        t.set("coherence.half_track_m", 1.0).unwrap();
        assert_eq!(
            t.coherence,
            CoherenceModel::Bogsjo {
                rho: 0.3,
                half_track_m: 1.0
            }
        );
        t.coherence = CoherenceModel::zhang(10.0).unwrap();
        t.set("coherence.speed_m_s", 5.0).unwrap();
        assert_eq!(t.get("coherence.speed_m_s").unwrap(), 5.0);
        let mut s = SurfaceParams::nominal();
        s.set("friction", 0.4).unwrap();
        s.set("track_width_m", 2.0).unwrap();
        assert_eq!((s.track_width_m, s.friction), (2.0, 0.4));
    }

    #[test]
    fn unknown_names_and_bad_values_are_typed_errors() {
        let mut t = TwoTrackSpec::paper_nominal();
        let before = t;
        // The piecewise model has no rho.
        assert!(matches!(
            t.get("coherence.rho"),
            Err(ParamError::Unknown { .. })
        ));
        t.coherence = CoherenceModel::Full;
        assert!(matches!(
            t.set("coherence.m_c", 0.3),
            Err(ParamError::Unknown { .. })
        ));
        t = before;
        assert!(matches!(
            t.set("psd.waviness", 11.0),
            Err(ParamError::OutOfBounds { .. })
        ));
        // In bounds but above n_max: the spec's validation refuses it.
        let e = t.set("band.n_min", 6.0).unwrap_err();
        assert!(
            matches!(
                e,
                ParamError::Rejected {
                    name: "band.n_min",
                    ..
                }
            ),
            "{e}"
        );
        assert_eq!(t, before);
        let mut s = SurfaceParams::nominal();
        assert!(matches!(
            s.set("friction", -0.1),
            Err(ParamError::OutOfBounds { .. })
        ));
        assert!(matches!(s.get("mu"), Err(ParamError::Unknown { .. })));
    }
}
