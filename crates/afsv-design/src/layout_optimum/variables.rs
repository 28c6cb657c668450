//! The design variables of a layout optimisation: registry names with bounds.

use serde::{Deserialize, Serialize};

/// One design variable: a registry name and its bounds. `front.NAME` and `rear.NAME` name
/// a parameter of the front or rear strut (`afsv params list strut`), `seat.NAME` and
/// `cab.NAME` one of the suspension seat or the cab on its mounts (`afsv params list seat`,
/// `afsv params list cab`; a layout with a cab and seat only), any other name one of the
/// 3-D vehicle (`afsv params list vehicle-3d`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LayoutVariable {
    /// The name.
    pub name: String,
    /// Lower bound (SI).
    pub lower: f64,
    /// Upper bound (SI).
    pub upper: f64,
}

impl LayoutVariable {
    /// Parses `NAME=LO..HI`.
    pub fn parse(text: &str) -> Result<Self, String> {
        let bad = |why: &str| format!("variable `{text}`: {why}");
        let (name, range) = text
            .split_once('=')
            .ok_or_else(|| bad("expected NAME=LO..HI, e.g. front.a_b=5e-6..2e-5"))?;
        let (lo, hi) = range
            .split_once("..")
            .ok_or_else(|| bad("expected NAME=LO..HI, e.g. front.a_b=5e-6..2e-5"))?;
        let num = |t: &str| match t.trim().parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(v),
            _ => Err(bad(&format!("`{}` is not a finite number", t.trim()))),
        };
        Ok(Self {
            name: name.trim().to_string(),
            lower: num(lo)?,
            upper: num(hi)?,
        })
    }
}

/// Where a variable lives: the front strut, the rear strut, the vehicle, the seat or the
/// cab, by index of its registry.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Target {
    Front(usize),
    Rear(usize),
    Vehicle(usize),
    Seat(usize),
    Cab(usize),
}

/// The nearest names of `known` to `name` (Levenshtein distance at most a third of its
/// length, or sharing its last dotted part), at most five.
pub(super) fn near<'a>(name: &str, known: impl Iterator<Item = &'a str>) -> Vec<&'a str> {
    let tail = name.rsplit('.').next().unwrap_or(name);
    let mut scored: Vec<(usize, &str)> = known
        .map(|k| (strsim::levenshtein(name, k), k))
        .filter(|(d, k)| *d <= name.len().max(3) / 3 || k.rsplit('.').next() == Some(tail))
        .collect();
    scored.sort();
    scored.into_iter().take(5).map(|(_, k)| k).collect()
}
