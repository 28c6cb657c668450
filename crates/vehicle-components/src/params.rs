//! Named parameters: a parameter set lists its scalar parameters ([`ParamSpec`]: name with
//! unit, bounds, typical size) and is read and written by name ([`ParamSet::get`],
//! [`ParamSet::set`]), so fits, sensitivities and design vectors address parameters by name
//! instead of by position.
//!
//! An implementation supplies the list and positional access ([`ParamSet::value`],
//! [`ParamSet::assign`]) plus its own whole-set validation ([`ParamSet::check`]); the trait
//! supplies the name lookup and the checks: an unknown name is
//! [`ParamError::Unknown`], a NaN or out-of-bounds value [`ParamError::OutOfBounds`], and a
//! value the set's validation refuses [`ParamError::Rejected`], with the set left unchanged.

use crate::error::ParamError;

/// One scalar parameter: name (the serde field path, unit in the name where it has one),
/// SI unit, the physical range `[lower, upper]` a fit or a design may explore, and a typical
/// magnitude (> 0) that scales it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ParamSpec {
    /// Name, e.g. `u_max` or `band.n_min`.
    pub name: &'static str,
    /// SI unit (`-` for dimensionless).
    pub unit: &'static str,
    /// Lower bound (inclusive, finite).
    pub lower: f64,
    /// Upper bound (inclusive, finite, >= lower).
    pub upper: f64,
    /// Typical magnitude (finite, > 0).
    pub typical: f64,
}

impl ParamSpec {
    /// A specification (checked by [`check_specs`]).
    pub const fn new(
        name: &'static str,
        unit: &'static str,
        lower: f64,
        upper: f64,
        typical: f64,
    ) -> Self {
        Self {
            name,
            unit,
            lower,
            upper,
            typical,
        }
    }

    /// `value` if it lies in `[lower, upper]` (NaN never does).
    pub fn admit(&self, value: f64) -> Result<f64, ParamError> {
        if value >= self.lower && value <= self.upper {
            Ok(value)
        } else {
            Err(ParamError::OutOfBounds {
                name: self.name,
                value,
                lower: self.lower,
                upper: self.upper,
                unit: self.unit,
            })
        }
    }
}

/// Check a list of specifications: names distinct and non-empty, bounds finite with
/// `lower <= upper`, typical magnitude finite and > 0.
pub fn check_specs(specs: &[ParamSpec]) -> Result<(), ParamError> {
    for (i, s) in specs.iter().enumerate() {
        let bad = |reason| {
            Err(ParamError::Spec {
                name: s.name,
                reason,
            })
        };
        if s.name.is_empty() {
            return bad("empty name");
        }
        if specs[..i].iter().any(|t| t.name == s.name) {
            return bad("name listed twice");
        }
        if !(s.lower.is_finite() && s.upper.is_finite() && s.lower <= s.upper) {
            return bad("bounds must be finite with lower <= upper");
        }
        if !(s.typical.is_finite() && s.typical > 0.0) {
            return bad("typical magnitude must be finite and > 0");
        }
    }
    Ok(())
}

/// `Ok` when every parameter of `p` lies in its registry range; otherwise one message
/// naming each parameter outside it with the range and unit (see
/// [`ParamSet::out_of_range`]).
pub fn within_ranges(p: &dyn ParamSet) -> Result<(), String> {
    let out = p.out_of_range();
    if out.is_empty() {
        return Ok(());
    }
    let list: Vec<String> = out.iter().map(ToString::to_string).collect();
    Err(format!(
        "{} outside the plausible range of the {} registry (`afsv params list` shows the ranges): {}",
        if out.len() == 1 {
            "a parameter lies".to_string()
        } else {
            format!("{} parameters lie", out.len())
        },
        p.set_name(),
        list.join("; ")
    ))
}

/// A parameter set addressed by name.
pub trait ParamSet {
    /// Name of the set in messages (e.g. `tire`).
    fn set_name(&self) -> &'static str;

    /// The scalar parameters, in a fixed order (the index of [`ParamSet::value`]).
    fn specs(&self) -> &'static [ParamSpec];

    /// Current value of parameter `index` of [`ParamSet::specs`]. Implementations panic
    /// for `index >= specs().len()`, like slice indexing.
    fn value(&self, index: usize) -> f64;

    /// Store `value` in parameter `index` without any check (panics like
    /// [`ParamSet::value`]).
    fn assign(&mut self, index: usize, value: f64);

    /// The set's own validation of the whole set, as a message naming the bad field.
    fn check(&self) -> Result<(), String>;

    /// Index and specification of parameter `name`.
    fn find(&self, name: &str) -> Result<(usize, &'static ParamSpec), ParamError> {
        let specs = self.specs();
        specs
            .iter()
            .position(|s| s.name == name)
            .map(|i| (i, &specs[i]))
            .ok_or_else(|| ParamError::Unknown {
                set: self.set_name(),
                name: name.to_string(),
                known: specs.iter().map(|s| s.name).collect::<Vec<_>>().join(", "),
            })
    }

    /// Value of parameter `name`.
    fn get(&self, name: &str) -> Result<f64, ParamError> {
        let (i, _) = self.find(name)?;
        Ok(self.value(i))
    }

    /// Every parameter whose value lies outside its `[lower, upper]` (or is NaN), in list
    /// order: a file that passes the set's own validation may still hold a value no fit or
    /// design would explore, e.g. an orifice area scaled by 1e6, which makes a run stiff
    /// and slow instead of failing at once.
    fn out_of_range(&self) -> Vec<ParamError> {
        self.specs()
            .iter()
            .enumerate()
            .filter_map(|(i, s)| s.admit(self.value(i)).err())
            .collect()
    }

    /// Set parameter `name` to `value`: the value must lie within the bounds and the whole
    /// set must pass [`ParamSet::check`] afterwards; otherwise the set is left unchanged.
    fn set(&mut self, name: &str, value: f64) -> Result<(), ParamError> {
        let (i, spec) = self.find(name)?;
        spec.admit(value)?;
        let old = self.value(i);
        self.assign(i, value);
        if let Err(reason) = self.check() {
            self.assign(i, old);
            return Err(ParamError::Rejected {
                name: spec.name,
                value,
                reason,
            });
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A two-parameter friction pair with the rule `u_min <= u_max`.
    #[derive(Debug, Clone, PartialEq)]
    struct Friction {
        u_max: f64,
        u_min: f64,
    }

    const SPECS: [ParamSpec; 2] = [
        ParamSpec::new("u_max", "-", 0.05, 2.0, 0.8),
        ParamSpec::new("u_min", "-", 0.05, 2.0, 0.6),
    ];

    impl ParamSet for Friction {
        fn set_name(&self) -> &'static str {
            "friction"
        }
        fn specs(&self) -> &'static [ParamSpec] {
            &SPECS
        }
        fn value(&self, index: usize) -> f64 {
            [self.u_max, self.u_min][index]
        }
        fn assign(&mut self, index: usize, value: f64) {
            match index {
                0 => self.u_max = value,
                _ => self.u_min = value,
            }
        }
        fn check(&self) -> Result<(), String> {
            if self.u_min <= self.u_max {
                Ok(())
            } else {
                Err(format!(
                    "u_min = {} above u_max = {}",
                    self.u_min, self.u_max
                ))
            }
        }
    }

    #[test]
    fn values_outside_their_ranges_are_all_listed() {
        let f = Friction {
            u_max: 8e5,
            u_min: 0.0,
        };
        let out = f.out_of_range();
        assert_eq!(out.len(), 2);
        assert!(out[0].to_string().contains("u_max"), "{}", out[0]);
        let ok = Friction {
            u_max: 0.8,
            u_min: 0.6,
        };
        assert!(ok.out_of_range().is_empty());
        let e = within_ranges(&f).unwrap_err();
        assert!(e.starts_with("2 parameters lie outside"), "{e}");
        assert!(within_ranges(&ok).is_ok());
    }

    #[test]
    fn get_and_set_by_name() {
        let mut f = Friction {
            u_max: 0.8,
            u_min: 0.6,
        };
        assert_eq!(f.get("u_min").unwrap(), 0.6);
        f.set("u_max", 0.9).unwrap();
        assert_eq!(f.u_max, 0.9);
        check_specs(f.specs()).unwrap();
    }

    #[test]
    fn errors_are_typed_and_leave_the_set_unchanged() {
        let mut f = Friction {
            u_max: 0.8,
            u_min: 0.6,
        };
        let before = f.clone();
        match f.get("mu").unwrap_err() {
            ParamError::Unknown { set, name, known } => {
                assert_eq!(
                    (set, name.as_str(), known.as_str()),
                    ("friction", "mu", "u_max, u_min")
                );
            }
            e => panic!("{e}"),
        }
        assert!(matches!(
            f.set("u_max", 3.0),
            Err(ParamError::OutOfBounds { name: "u_max", .. })
        ));
        assert!(matches!(
            f.set("u_max", f64::NAN),
            Err(ParamError::OutOfBounds { .. })
        ));
        let e = f.set("u_min", 0.9).unwrap_err();
        assert!(
            matches!(e, ParamError::Rejected { name: "u_min", .. }),
            "{e}"
        );
        assert!(e.to_string().contains("above u_max"), "{e}");
        assert_eq!(f, before);
    }

    #[test]
    fn malformed_specs_are_found() {
        let dup = [SPECS[0], SPECS[0]];
        assert!(check_specs(&dup).is_err());
        let inverted = [ParamSpec::new("a", "m", 1.0, 0.0, 1.0)];
        assert!(check_specs(&inverted).is_err());
        let open = [ParamSpec::new("a", "m", 0.0, f64::INFINITY, 1.0)];
        assert!(check_specs(&open).is_err());
        let zero = [ParamSpec::new("a", "m", 0.0, 1.0, 0.0)];
        assert!(check_specs(&zero).is_err());
        assert!(check_specs(&[ParamSpec::new("", "m", 0.0, 1.0, 1.0)]).is_err());
    }
}
