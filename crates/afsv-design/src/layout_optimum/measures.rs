//! The measures of a layout design and the constraints on them
//! ([`super::LayoutProblemDesc`]).

use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// A measure of a layout (the measures of `afsv study layouts` at one speed).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum LayoutMeasure {
    /// a_wz on the frame at the a_wz point (W_k, ISO 2631-1), m/s².
    AwzFrame,
    /// a_wz on the seat pan, m/s² (needs a cab and seat).
    AwzSeat,
    /// SEAT, seat pan over floor (ISO 10326-1), - (needs a cab and seat).
    Seat,
    /// Peak-to-peak travel of the front struts, m (needs the front-axle HPS).
    StrutTravel,
    /// Peak-to-peak travel of the rear struts, m (needs a rear strut).
    RearStrutTravel,
    /// D2 SP-DRT, loaded, m/s².
    SpDrt,
    /// D3 omega_z, loaded, Hz.
    OmegaZ,
    /// D4: the speed (km/h) at which the frame's a_wz (mean over the seeds) first rises
    /// above the 8 h upper bound of the ISO 2631-1 health guidance caution zone, linearly
    /// interpolated between the problem's D4 speeds. Censored at the ends of the swept
    /// range: a design that never enters the zone takes the highest speed (its crossing
    /// lies at or above it), one already in it at the lowest speed the lowest (at or
    /// below it); such a value at the optimum is reported and not earned.
    D4Speed,
    /// D4 read where the operator sits: [`LayoutMeasure::D4Speed`] of the seat pan's a_wz
    /// (needs a cab and seat), censored alike.
    D4SpeedSeat,
}

/// The run a measure needs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Run {
    Ride,
    Roll,
    Yaw,
    Sweep,
}

impl LayoutMeasure {
    /// Every measure.
    pub const ALL: [LayoutMeasure; 9] = [
        LayoutMeasure::AwzFrame,
        LayoutMeasure::AwzSeat,
        LayoutMeasure::Seat,
        LayoutMeasure::StrutTravel,
        LayoutMeasure::RearStrutTravel,
        LayoutMeasure::SpDrt,
        LayoutMeasure::OmegaZ,
        LayoutMeasure::D4Speed,
        LayoutMeasure::D4SpeedSeat,
    ];

    /// Its name on the command line and in reports.
    pub fn name(self) -> &'static str {
        match self {
            LayoutMeasure::AwzFrame => "awz_frame",
            LayoutMeasure::AwzSeat => "awz_seat",
            LayoutMeasure::Seat => "seat",
            LayoutMeasure::StrutTravel => "strut_travel",
            LayoutMeasure::RearStrutTravel => "rear_strut_travel",
            LayoutMeasure::SpDrt => "sp_drt",
            LayoutMeasure::OmegaZ => "omega_z",
            LayoutMeasure::D4Speed => "d4_speed",
            LayoutMeasure::D4SpeedSeat => "d4_speed_seat",
        }
    }

    /// Its SI unit.
    pub fn unit(self) -> &'static str {
        match self {
            LayoutMeasure::AwzFrame | LayoutMeasure::AwzSeat | LayoutMeasure::SpDrt => "m/s²",
            LayoutMeasure::Seat => "-",
            LayoutMeasure::StrutTravel | LayoutMeasure::RearStrutTravel => "m",
            LayoutMeasure::OmegaZ => "Hz",
            LayoutMeasure::D4Speed | LayoutMeasure::D4SpeedSeat => "km/h",
        }
    }

    /// The measure named `name`; an unknown name lists the known ones.
    pub fn parse(name: &str) -> Result<Self, String> {
        let name = name.trim();
        Self::ALL
            .into_iter()
            .find(|m| m.name() == name)
            .ok_or_else(|| {
                let known: Vec<&str> = Self::ALL.iter().map(|m| m.name()).collect();
                format!("unknown measure `{name}` (known: {})", known.join(", "))
            })
    }

    pub(super) fn run(self) -> Run {
        match self {
            LayoutMeasure::SpDrt => Run::Roll,
            LayoutMeasure::OmegaZ => Run::Yaw,
            LayoutMeasure::D4Speed | LayoutMeasure::D4SpeedSeat => Run::Sweep,
            _ => Run::Ride,
        }
    }
}

/// Measures of one design, each the mean over the problem's seeds.
pub type Measured = BTreeMap<LayoutMeasure, f64>;

/// `<=` or `>=`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Relation {
    /// The measure at most the bound.
    AtMost,
    /// The measure at least the bound.
    AtLeast,
}

/// A constraint `MEASURE <= VALUE` or `MEASURE >= VALUE`; with `of_nominal`, the bound is
/// `VALUE` times the un-varied layout's value of the measure.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LayoutConstraint {
    /// The measure.
    pub measure: LayoutMeasure,
    /// `<=` or `>=`.
    pub relation: Relation,
    /// The bound, or its factor on the nominal value.
    pub value: f64,
    /// Whether `value` multiplies the nominal value.
    pub of_nominal: bool,
}

impl LayoutConstraint {
    /// Parses `MEASURE <= BOUND` or `MEASURE >= BOUND`, where BOUND is a number, `nominal`,
    /// `F * nominal` or `nominal * F` (spaces optional), e.g. `sp_drt >= 0.96 * nominal`.
    pub fn parse(text: &str) -> Result<Self, String> {
        let bad = |why: &str| format!("constraint `{text}`: {why}");
        let (lhs, relation, rhs) = if let Some((l, r)) = text.split_once("<=") {
            (l, Relation::AtMost, r)
        } else if let Some((l, r)) = text.split_once(">=") {
            (l, Relation::AtLeast, r)
        } else {
            return Err(bad(
                "expected `MEASURE <= BOUND` or `MEASURE >= BOUND` (BOUND: a number, nominal or F * nominal)",
            ));
        };
        let measure = LayoutMeasure::parse(lhs).map_err(|e| bad(&e))?;
        let number = |t: &str| -> Result<f64, String> {
            let t = t.trim();
            match t.parse::<f64>() {
                Ok(v) if v.is_finite() => Ok(v),
                _ => Err(bad(&format!("`{t}` is not a finite number"))),
            }
        };
        let rhs = rhs.trim();
        let (value, of_nominal) = match rhs.split_once('*') {
            Some((a, b)) if b.trim() == "nominal" => (number(a)?, true),
            Some((a, b)) if a.trim() == "nominal" => (number(b)?, true),
            Some(_) => return Err(bad("a product must be `F * nominal`")),
            None if rhs == "nominal" => (1.0, true),
            None => (number(rhs)?, false),
        };
        if of_nominal && value <= 0.0 {
            return Err(bad("the factor on nominal must be > 0"));
        }
        Ok(Self {
            measure,
            relation,
            value,
            of_nominal,
        })
    }

    /// The bound given the nominal measures.
    pub fn bound(&self, nominal: &Measured) -> f64 {
        if self.of_nominal {
            self.value * nominal.get(&self.measure).copied().unwrap_or(f64::NAN)
        } else {
            self.value
        }
    }

    /// The constraint value of `m` (feasible where <= 0): the excess over the bound as a
    /// share of the bound's magnitude (of 1 for a zero bound).
    pub fn value_of(&self, m: &Measured, nominal: &Measured) -> f64 {
        let b = self.bound(nominal);
        let v = m.get(&self.measure).copied().unwrap_or(f64::NAN);
        let scale = if b != 0.0 { b.abs() } else { 1.0 };
        match self.relation {
            Relation::AtMost => (v - b) / scale,
            Relation::AtLeast => (b - v) / scale,
        }
    }
}

impl std::fmt::Display for LayoutConstraint {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        let rel = match self.relation {
            Relation::AtMost => "<=",
            Relation::AtLeast => ">=",
        };
        if self.of_nominal {
            write!(f, "{} {rel} {} * nominal", self.measure.name(), self.value)
        } else {
            write!(f, "{} {rel} {}", self.measure.name(), self.value)
        }
    }
}
