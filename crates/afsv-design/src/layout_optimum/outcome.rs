//! The result of a layout optimisation: the optimum's variables and constraints set against
//! the nominal layout's, and whether the optimum was earned.

use super::{LayoutGaSettings, LayoutMeasure, LayoutProblem, Measured, ON_BOUND};
use crate::error::DesignError;
use serde::Serialize;
use vehicle_3d::Load;

/// One variable of the result.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct VariableResult {
    /// Its name.
    pub name: String,
    /// Its bounds.
    pub lower: f64,
    /// Upper bound.
    pub upper: f64,
    /// The un-varied layout's value.
    pub nominal: f64,
    /// The optimum's value.
    pub optimum: f64,
    /// Within [`ON_BOUND`] of its range from a bound.
    pub on_bound: bool,
}

/// One constraint of the result.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ConstraintResult {
    /// As written, e.g. `sp_drt >= 0.96 * nominal`.
    pub constraint: String,
    /// The bound it resolves to.
    pub bound: f64,
    /// The nominal design's value of the measure.
    pub nominal: f64,
    /// The optimum's value.
    pub optimum: f64,
    /// Whether the optimum meets it.
    pub met: bool,
}

/// The result of a layout optimisation.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LayoutOptimum {
    /// The vehicle's name.
    pub vehicle: String,
    /// The layout's name.
    pub layout: String,
    /// Whether the layout has a cab and seat.
    pub seat: bool,
    /// Load of the rides.
    pub load: Load,
    /// Ride speed (km/h).
    pub speed_kmh: f64,
    /// Ride window (m).
    pub ride_length_m: f64,
    /// Terrain seeds.
    pub seeds: Vec<u64>,
    /// The GA's settings.
    pub ga: LayoutGaSettings,
    /// The objective measure.
    pub objective: LayoutMeasure,
    /// Whether it is maximised.
    pub maximise: bool,
    /// The variables.
    pub variables: Vec<VariableResult>,
    /// The constraints.
    pub constraints: Vec<ConstraintResult>,
    /// The nominal design's measures.
    pub nominal: Measured,
    /// The optimum's measures.
    pub optimum: Measured,
    /// Whether the optimum meets every constraint.
    pub feasible: bool,
    /// Designs evaluated by the GA (the nominal and the optimum's report not counted).
    pub evaluations: usize,
    /// Censored values the optimum's verdict rests on: the optimum's `d4_speed` or
    /// `d4_speed_seat` at an end of the D4 range, or the nominal's where a constraint scales
    /// it (empty otherwise).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub censored: Vec<String>,
}

impl LayoutOptimum {
    /// `Ok` when the optimum is earned: feasible, no variable on a bound; otherwise why not.
    pub fn earned(&self) -> Result<(), String> {
        let mut why = Vec::new();
        for c in self.constraints.iter().filter(|c| !c.met) {
            why.push(format!(
                "{} not met ({} against the bound {})",
                c.constraint, c.optimum, c.bound
            ));
        }
        why.extend(self.censored.iter().cloned());
        for v in self.variables.iter().filter(|v| v.on_bound) {
            why.push(format!(
                "{} = {} lies on a bound of {}..{} (widen it)",
                v.name, v.optimum, v.lower, v.upper
            ));
        }
        if why.is_empty() {
            Ok(())
        } else {
            Err(why.join("; "))
        }
    }
}

/// The result of a finished GA state: its best individual measured once more (a pure
/// function of the design) and set against the nominal measures.
pub(crate) fn result(
    problem: &LayoutProblem,
    ga: &LayoutGaSettings,
    nominal: &Measured,
    best_u: &[f64],
    best_x: &[f64],
    evaluations: usize,
) -> Result<LayoutOptimum, DesignError> {
    let d = &problem.desc;
    let optimum = problem
        .measure(Some(best_x))
        .map_err(|e| DesignError::Simulation(format!("the optimum: {e}")))?;
    let nominal_x = problem.nominal_x();
    let variables = d
        .variables
        .iter()
        .zip(best_u.iter().zip(best_x))
        .zip(nominal_x)
        .map(|((v, (u, x)), n)| VariableResult {
            name: v.name.clone(),
            lower: v.lower,
            upper: v.upper,
            nominal: n,
            optimum: *x,
            on_bound: *u <= ON_BOUND || *u >= 1.0 - ON_BOUND,
        })
        .collect();
    let constraints: Vec<ConstraintResult> = d
        .constraints
        .iter()
        .map(|c| ConstraintResult {
            constraint: c.to_string(),
            bound: c.bound(nominal),
            nominal: nominal.get(&c.measure).copied().unwrap_or(f64::NAN),
            optimum: optimum.get(&c.measure).copied().unwrap_or(f64::NAN),
            met: c.value_of(&optimum, nominal) <= 0.0,
        })
        .collect();
    let mut censored: Vec<String> = problem
        .d4_censored(&optimum)
        .into_iter()
        .map(|(_, text)| text)
        .collect();
    for (measure, n) in problem.d4_censored(nominal) {
        let scaled = d
            .constraints
            .iter()
            .any(|c| c.of_nominal && c.measure == measure);
        if scaled {
            censored.push(format!(
                "the nominal's {n}; a bound on `* nominal` rests on it"
            ));
        }
    }
    Ok(LayoutOptimum {
        censored,
        vehicle: d.vehicle.clone(),
        layout: d.layout.clone(),
        seat: d.seat.is_some(),
        load: d.load,
        speed_kmh: d.speed_kmh,
        ride_length_m: d.ride_length_m,
        seeds: d.seeds.clone(),
        ga: *ga,
        objective: d.objective,
        maximise: d.maximise,
        variables,
        feasible: constraints.iter().all(|c| c.met),
        constraints,
        nominal: nominal.clone(),
        optimum,
        evaluations,
    })
}
