//! Tolerances of the fixtures and the status of a compared row.

use super::fixtures::descend;
use super::report::fmt_num;
use serde::Serialize;
use serde_json::Value;

/// Tolerance of one fixture value, in the fixture's printed unit.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Tolerance {
    /// |simulated - reported| <= r |reported|.
    Relative(f64),
    /// |simulated - reported| <= a.
    Absolute(f64),
    /// simulated >= bound (a number printed as "> x").
    LowerBound(f64),
    /// simulated <= bound (a number printed as "< x").
    UpperBound(f64),
}

/// Slack for round-off when a tolerance is exactly zero or a value sits on its limit.
const ROUND_OFF: f64 = 1e-9;

impl Tolerance {
    /// The tolerance of the value at `key` (a `.`-separated path into `values`, or `None`)
    /// from a fixture's `tolerance` field: `{"relative": r}`, `{"absolute": a}`, per-key
    /// objects or arrays of either, `{"lower_bound": x}`, `{"upper_bound": x}`, or an object
    /// keyed by value key whose entries are such tolerances. `None` when there is none.
    pub fn from_fixture(tol: &Value, key: Option<&str>) -> Option<Tolerance> {
        let path: Vec<&str> = key.map(|k| k.split('.').collect()).unwrap_or_default();
        Self::lookup(tol, &path)
    }

    fn lookup(tol: &Value, path: &[&str]) -> Option<Tolerance> {
        let obj = tol.as_object()?;
        for (name, make) in [
            ("relative", Tolerance::Relative as fn(f64) -> Tolerance),
            ("absolute", Tolerance::Absolute),
            ("lower_bound", Tolerance::LowerBound),
            ("upper_bound", Tolerance::UpperBound),
        ] {
            if let Some(v) = obj.get(name) {
                return descend(v, path).and_then(Value::as_f64).map(make);
            }
        }
        let (first, rest) = path.split_first()?;
        Self::lookup(obj.get(*first)?, rest)
    }

    /// Signed error of `simulated` against `reported`: relative `(sim - rep)/|rep|`, absolute
    /// `sim - rep`, and for bounds the margin `sim - bound` (positive = above the bound).
    pub fn error(&self, reported: f64, simulated: f64) -> f64 {
        match *self {
            Tolerance::Relative(_) => (simulated - reported) / reported.abs(),
            Tolerance::Absolute(_) => simulated - reported,
            Tolerance::LowerBound(b) | Tolerance::UpperBound(b) => simulated - b,
        }
    }

    /// Whether `simulated` is within this tolerance of `reported` (non-finite: never).
    pub fn within(&self, reported: f64, simulated: f64) -> bool {
        if !simulated.is_finite() || !reported.is_finite() {
            return false;
        }
        let e = self.error(reported, simulated);
        let slack = ROUND_OFF * reported.abs().max(1e-300);
        match *self {
            Tolerance::Relative(r) => e.abs() <= r + ROUND_OFF,
            Tolerance::Absolute(a) => e.abs() <= a + slack,
            Tolerance::LowerBound(_) => e >= -slack,
            Tolerance::UpperBound(_) => e <= slack,
        }
    }

    /// Short text for tables: `rel 5%`, `abs 0.5`, `>= 0.99`, `<= 4`.
    pub fn describe(&self) -> String {
        match *self {
            Tolerance::Relative(r) => format!("rel {}%", fmt_num(100.0 * r)),
            Tolerance::Absolute(a) => format!("abs {}", fmt_num(a)),
            Tolerance::LowerBound(b) => format!(">= {}", fmt_num(b)),
            Tolerance::UpperBound(b) => format!("<= {}", fmt_num(b)),
        }
    }

    /// Describe a signed error in this tolerance's terms (`+3.1%` or `-0.02`).
    pub fn describe_error(&self, error: f64) -> String {
        match self {
            Tolerance::Relative(_) => format!("{:+.2}%", 100.0 * error),
            _ => format!("{:+}", fmt_num(error)),
        }
    }
}

/// Outcome of one comparison.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Status {
    /// Computed by a model and within tolerance (a qualitative check passed).
    Reproduced,
    /// Computed, outside tolerance (the reason is in the note).
    Differs,
    /// Needs a model or data we do not have (the reason is in the note).
    NotReproducible,
    /// Computed, but the paper's data cannot pin the number down: it depends on inputs the
    /// paper does not state (a steering ramp, a detection rule), and the note says which
    /// and by how much. Shown with its error and tolerance; never agrees.
    NotReproducibleFromPaperData,
    /// Echoes an input: the number is a parameter our parameter set carries (a nominal
    /// value, a design bound, the current design), within tolerance. Not a model result.
    Input,
    /// Holds by construction: the number was used to build the model (an identification
    /// target, a table the model interpolates at its own rows, a structural zero), within
    /// tolerance. Not a model result.
    ByConstruction,
}

impl Status {
    /// Text as printed.
    pub fn as_str(self) -> &'static str {
        match self {
            Status::Reproduced => "reproduced",
            Status::Differs => "differs",
            Status::NotReproducible => "not-reproducible",
            Status::NotReproducibleFromPaperData => "not-reproducible-from-paper-data",
            Status::Input => "input",
            Status::ByConstruction => "by-construction",
        }
    }

    /// Whether the row agrees with the fixture: reproduced, or an echo within tolerance
    /// (the regression rule accepts all three).
    pub fn agrees(self) -> bool {
        matches!(
            self,
            Status::Reproduced | Status::Input | Status::ByConstruction
        )
    }
}

/// Why a row's number matches the fixture without being a model result (the status an
/// echo gets when it is within tolerance; outside it the row `differs`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Echo {
    /// The number is an input parameter ([`Status::Input`]).
    Input,
    /// The number holds by construction ([`Status::ByConstruction`]).
    ByConstruction,
}

impl Echo {
    /// The status of a row within tolerance.
    pub fn status(self) -> Status {
        match self {
            Echo::Input => Status::Input,
            Echo::ByConstruction => Status::ByConstruction,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn echoes_agree_but_are_not_reproduced() {
        assert!(Status::Input.agrees() && Status::ByConstruction.agrees());
        assert!(!Status::Differs.agrees() && !Status::NotReproducible.agrees());
        assert!(!Status::NotReproducibleFromPaperData.agrees());
        assert_eq!(
            serde_json::to_value(Status::NotReproducibleFromPaperData).unwrap(),
            json!(Status::NotReproducibleFromPaperData.as_str())
        );
        assert_eq!(Echo::ByConstruction.status().as_str(), "by-construction");
        assert_eq!(serde_json::to_value(Status::Input).unwrap(), json!("input"));
    }

    #[test]
    fn relative_tolerance_inside_and_outside() {
        let t = Tolerance::from_fixture(&json!({"relative": 0.05}), None).unwrap();
        assert!(t.within(2.81, 2.9));
        assert!(!t.within(2.81, 3.0));
        assert!((t.error(2.0, 2.1) - 0.05).abs() < 1e-12);
        assert!(!t.within(2.81, f64::NAN));
    }

    #[test]
    fn absolute_zero_tolerance_allows_round_off_only() {
        let t = Tolerance::from_fixture(&json!({"absolute": 0}), None).unwrap();
        assert!(t.within(1.0 / 3.0, 0.333_333_333_333_333_3));
        assert!(!t.within(0.3333, 1.0 / 3.0));
    }

    #[test]
    fn bounds() {
        let lo = Tolerance::from_fixture(&json!({"lower_bound": 0.99}), None).unwrap();
        assert!(lo.within(0.99, 0.995));
        assert!(!lo.within(0.99, 0.98));
        let hi = Tolerance::from_fixture(&json!({"upper_bound": 4}), None).unwrap();
        assert!(hi.within(4.0, 3.9));
        assert!(!hi.within(4.0, 4.1));
    }

    #[test]
    fn per_key_and_nested_tolerances() {
        let tol = json!({"absolute": {"loaded": 0.5, "unloaded": 0.005}});
        assert_eq!(
            Tolerance::from_fixture(&tol, Some("unloaded")),
            Some(Tolerance::Absolute(0.005))
        );
        let tol = json!({"drt": {"absolute": 5}, "ratio": {"relative": 0.3}});
        assert_eq!(
            Tolerance::from_fixture(&tol, Some("ratio")),
            Some(Tolerance::Relative(0.3))
        );
        let tol = json!({"absolute": [[0.005, 0.5], [0.005, 0.5]]});
        assert_eq!(
            Tolerance::from_fixture(&tol, Some("1.1")),
            Some(Tolerance::Absolute(0.5))
        );
        // A scalar tolerance applies to every key of a matrix.
        assert_eq!(
            Tolerance::from_fixture(&json!({"absolute": 0.006}), Some("3.1")),
            Some(Tolerance::Absolute(0.006))
        );
        assert_eq!(Tolerance::from_fixture(&Value::Null, None), None);
        assert_eq!(
            Tolerance::from_fixture(&json!({"absolute": {"a": 1}}), Some("b")),
            None
        );
    }
}
