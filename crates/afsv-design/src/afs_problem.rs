//! The chapter-4 design problem (section 4.3): minimise F(chi) of Eq 4.8 with the AHP
//! weights of Eq 4.17 over chi = [A_0, l_1, l_2, a_v, B_eff] inside the Table 4.2 bounds
//! (the relaxed B_eff bound of Table 4.4 as an option), the measures from the loaded
//! 50 km/h pulse and step ([`afsv_dynamics::measures_for`]) as ratios to the current
//! design, subject to
//!
//! - **Eq 4.10**, `L > (L_max - L) + 2 (L - L_min)`, which reduces exactly to
//!   `L_max < 2 L_min` with `L_max = L(A_0 + 45 deg)`, `L_min = L(A_0 - 45 deg)` (the closed
//!   strut longer than its stroke); written `(L_max - 2 L_min) / L_0 <= 0`, `L_0` the
//!   current design's strut length;
//! - **a minimum steering arm at full lock** (not in the dissertation): the smaller of the
//!   two arms h(A_0 +- 45 deg) (Eq 3.2) at least `min_steering_arm_m`, written
//!   `(h_req - h_min) / h_req <= 0`. Without it the optimum slides to A_0 = 45 deg, where
//!   the short-side strut passes through the joint at full lock (zero arm: the vehicle
//!   cannot steer out of full lock); the printed compact optima have 0.25-0.27 m;
//! - **Eq 4.9** only when the user gives the geometry ([`InterferenceGeometry`]): the strut
//!   axis seen from the front mount stays between the engine-structure and tire
//!   extremities over the steering range.
//!
//! Every point is addressed by name ([`AfsVariable`]); the solver vector is
//! [`AfsVariable::ALL`]'s order in SI units.

use crate::afs_design::{AfsDesign, AfsDesignBounds, AfsVariable};
use crate::error::{positive, DesignError};
use crate::measures::{DesignMeasures, MeasureRatios};
use crate::objective::Objective;
use afs_hydraulics::kinematics::strut_kinematics;
use afs_hydraulics::{AfsParams, AfsSystem};
use afsv_dynamics::{
    measures_for, simulate, Load, Manoeuvre, MeasureSpec, SteerInput, VehicleParams, YawMeasures,
    YawRecord,
};
use optimize::{Bounds, ConstrainedProblem, Evaluation, BARRIER};
use serde::Serialize;

const DEG: f64 = std::f64::consts::PI / 180.0;

/// Default minimum steering arm at +-45 deg (m): the printed compact optima have 0.25-0.27 m.
pub const DEFAULT_MIN_STEERING_ARM_M: f64 = 0.25;

/// Articulation samples over the steering range for Eq 4.9.
const EQ_4_9_SAMPLES: usize = 19;

/// The Eq 4.9 geometry in the front-unit frame (origin at the joint O, x forward, y left):
/// the direction of the left front mount L_1 from O (L_1 = l_1 (cos, sin) of it), the inner
/// extremity T_L of the left front tire and the extremity E_L of the engine structure.
/// The right side is the mirror image.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct InterferenceGeometry {
    /// Direction of O->L_1 from the x axis (rad).
    pub front_mount_direction_rad: f64,
    /// T_L (m).
    pub tire_point_m: [f64; 2],
    /// E_L (m).
    pub engine_point_m: [f64; 2],
}

impl InterferenceGeometry {
    /// A geometry with finite entries and both points away from the joint.
    pub fn new(
        front_mount_direction_rad: f64,
        tire_point_m: [f64; 2],
        engine_point_m: [f64; 2],
    ) -> Result<Self, DesignError> {
        let finite = |field: &'static str, v: f64| {
            if v.is_finite() {
                Ok(v)
            } else {
                Err(DesignError::Invalid {
                    field,
                    value: v,
                    reason: "must be finite",
                })
            }
        };
        finite("front_mount_direction_rad", front_mount_direction_rad)?;
        for (field, p) in [
            ("tire_point_m", tire_point_m),
            ("engine_point_m", engine_point_m),
        ] {
            finite(field, p[0])?;
            finite(field, p[1])?;
            positive(field, p[0].hypot(p[1]))?;
        }
        Ok(Self {
            front_mount_direction_rad,
            tire_point_m,
            engine_point_m,
        })
    }

    /// `(beta_E, beta_T)`: the angles at L_1 between L_1->O and L_1->E_L, L_1->T_L (rad).
    fn limits(&self, l1: f64) -> (f64, f64) {
        let (s, c) = self.front_mount_direction_rad.sin_cos();
        let m = [l1 * c, l1 * s];
        let angle = |p: [f64; 2]| {
            let (a, b) = ([-m[0], -m[1]], [p[0] - m[0], p[1] - m[1]]);
            let cos = (a[0] * b[0] + a[1] * b[1]) / (a[0].hypot(a[1]) * b[0].hypot(b[1]));
            cos.clamp(-1.0, 1.0).acos()
        };
        (angle(self.engine_point_m), angle(self.tire_point_m))
    }
}

/// Settings of the chapter-4 problem.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AfsProblemSpec {
    /// Design bounds: [`AfsDesignBounds::table_4_2`] or its relaxed B_eff form.
    pub bounds: AfsDesignBounds,
    /// Minimum steering arm at full lock (m); `None` leaves the constraint out.
    pub min_steering_arm_m: Option<f64>,
    /// Full-lock articulation of Eq 4.10 and of the arm constraint (rad), 45 deg.
    pub max_articulation_rad: f64,
    /// Eq 4.9 geometry; `None` leaves Eq 4.9 out.
    pub interference: Option<InterferenceGeometry>,
    /// Test definition and numerics of the measures.
    pub measure: MeasureSpec,
    /// Forward speed (m/s), 50 km/h.
    pub speed_m_s: f64,
    /// The loaded vehicle the measures run on: Table 3.1's, or a vehicle description's
    /// yaw-plane data.
    pub vehicle: VehicleParams,
    /// The current steering system, whose five design variables are varied: Table 3.1's, or
    /// a description's.
    pub steering: AfsParams,
}

impl Default for AfsProblemSpec {
    /// Table 4.2 bounds, a 0.25 m minimum arm, 45 deg, no Eq 4.9, loaded at 50 km/h with
    /// the default test definition at rtol 1e-8 (the noise of F falls from 1e-4 at
    /// rtol 1e-6 to 2e-5, at no extra cost: the 0.05 s step limit sets the steps) and without the energy channels.
    fn default() -> Self {
        let mut measure = MeasureSpec::default();
        measure.options.rtol = 1e-8;
        measure.options.record_energy = false;
        Self {
            bounds: AfsDesignBounds::table_4_2(),
            min_steering_arm_m: Some(DEFAULT_MIN_STEERING_ARM_M),
            max_articulation_rad: 45.0 * DEG,
            interference: None,
            measure,
            speed_m_s: 50.0 / 3.6,
            vehicle: VehicleParams::nominal(Load::Loaded),
            steering: AfsParams::nominal(),
        }
    }
}

/// One constraint of the problem, by name.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum AfsConstraint {
    /// Eq 4.10: L_max < 2 L_min.
    Eq410,
    /// Smallest full-lock arm at least the minimum.
    MinSteeringArm,
    /// Eq 4.9, tire side: the strut axis angle at L_1 stays below beta_T.
    Eq49Tire,
    /// Eq 4.9, engine side: it stays above beta_E.
    Eq49Engine,
}

impl AfsConstraint {
    /// Snake-case name.
    pub fn name(self) -> &'static str {
        match self {
            AfsConstraint::Eq410 => "eq_4_10",
            AfsConstraint::MinSteeringArm => "min_steering_arm",
            AfsConstraint::Eq49Tire => "eq_4_9_tire",
            AfsConstraint::Eq49Engine => "eq_4_9_engine",
        }
    }
}

/// Strut geometry of a design at full lock (Eqs 3.2, 3.7, 4.3).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FullLockGeometry {
    /// Initial strut length L = l_0 (m), Eq 3.7.
    pub strut_length_m: f64,
    /// L_max = L(A_0 + theta_max) (m).
    pub l_max_m: f64,
    /// L_min = L(A_0 - theta_max) (m).
    pub l_min_m: f64,
    /// L_max / L_min; Eq 4.10 holds below 2.
    pub stroke_ratio: f64,
    /// The smaller of the two full-lock arms h(A_0 - theta_max), h(A_0 + theta_max) (m).
    pub min_arm_m: f64,
    /// l_2 / l_1.
    pub l2_over_l1: f64,
}

/// Full-lock geometry of `d` at articulation `theta_max` (rad).
pub fn full_lock_geometry(d: &AfsDesign, theta_max: f64) -> FullLockGeometry {
    let l0 = d.initial_strut_length();
    let k = strut_kinematics(d.l1_m, d.l2_m, d.a0_rad, l0, theta_max);
    FullLockGeometry {
        strut_length_m: l0,
        l_max_m: k.length_left,
        l_min_m: k.length_right,
        stroke_ratio: k.length_left / k.length_right,
        min_arm_m: k.arm_left.min(k.arm_right),
        l2_over_l1: d.l2_m / d.l1_m,
    }
}

/// A design evaluated against the current one.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DesignEvaluation {
    /// The design.
    pub design: AfsDesign,
    /// Its measures.
    pub measures: YawMeasures,
    /// Plain ratios design / current, as Tables 4.3/4.4 print them.
    pub ratios: MeasureRatios,
    /// V of Eq 4.8 (the larger-is-better ratios inverted).
    pub objective_vector: [f64; 6],
    /// F = W . V (Eq 4.8).
    pub f: f64,
    /// Full-lock geometry.
    pub geometry: FullLockGeometry,
    /// Constraint values (feasible where <= 0), in [`AfsProblem::constraints`]' order.
    pub constraints: Vec<(AfsConstraint, f64)>,
}

impl DesignEvaluation {
    /// The constraints the design violates (value > 0, or not a number), with their values,
    /// in [`AfsProblem::constraints`]' order; empty when the design is feasible.
    pub fn violated(&self) -> Vec<(AfsConstraint, f64)> {
        self.constraints
            .iter()
            .copied()
            .filter(|(_, v)| v.is_nan() || *v > 0.0)
            .collect()
    }

    /// Whether every constraint holds (value <= 0), as the solvers count feasibility.
    pub fn is_feasible(&self) -> bool {
        self.violated().is_empty()
    }
}

/// The chapter-4 problem with the current design's measures computed once.
#[derive(Debug, Clone)]
pub struct AfsProblem {
    spec: AfsProblemSpec,
    vehicle: VehicleParams,
    base: AfsParams,
    current: YawMeasures,
    current_measures: DesignMeasures,
    objective: Objective,
    bounds: Bounds,
    constraints: Vec<AfsConstraint>,
    l0_current: f64,
}

impl AfsProblem {
    /// The problem of `spec` with the objective `objective` (e.g. the Eq 4.17 weights of
    /// [`crate::AhpHierarchy::chapter4`]); simulates the current design (`spec.steering` on
    /// the loaded `spec.vehicle`) once.
    pub fn new(spec: AfsProblemSpec, objective: Objective) -> Result<Self, DesignError> {
        positive("speed_m_s", spec.speed_m_s)?;
        if !(spec.max_articulation_rad > 0.0 && spec.max_articulation_rad < 90.0 * DEG) {
            return Err(DesignError::Invalid {
                field: "max_articulation_rad",
                value: spec.max_articulation_rad,
                reason: "must be in (0, 90 deg)",
            });
        }
        if let Some(h) = spec.min_steering_arm_m {
            positive("min_steering_arm_m", h)?;
        }
        if spec.bounds.upper.a0_rad + spec.max_articulation_rad >= std::f64::consts::PI {
            return Err(DesignError::Invalid {
                field: "bounds.upper.a0_rad",
                value: spec.bounds.upper.a0_rad,
                reason: "A_0 + theta_max must stay below 180 deg",
            });
        }
        spec.vehicle
            .validate()
            .map_err(|e| DesignError::Simulation(format!("vehicle: {e}")))?;
        let base = spec.steering.clone();
        AfsSystem::new(base.clone())
            .map_err(|e| DesignError::Simulation(format!("steering: {e}")))?;
        let vehicle = spec.vehicle.clone();
        let current = measures_for(
            &vehicle,
            &base,
            Some(Load::Loaded),
            spec.speed_m_s,
            &spec.measure,
        )
        .map_err(|e| DesignError::Simulation(format!("current design: {e}")))?;
        let current_measures = DesignMeasures::from_yaw(&current)?;
        let lo = AfsVariable::ALL.map(|v| spec.bounds.lower.get(v)).to_vec();
        let hi = AfsVariable::ALL.map(|v| spec.bounds.upper.get(v)).to_vec();
        let bounds = Bounds::new(lo, hi).map_err(|e| DesignError::Shape {
            field: "bounds",
            reason: e.to_string(),
        })?;
        let mut constraints = vec![AfsConstraint::Eq410];
        if spec.min_steering_arm_m.is_some() {
            constraints.push(AfsConstraint::MinSteeringArm);
        }
        if spec.interference.is_some() {
            constraints.extend([AfsConstraint::Eq49Tire, AfsConstraint::Eq49Engine]);
        }
        Ok(Self {
            l0_current: AfsDesign::of(&base).initial_strut_length(),
            spec,
            vehicle,
            base,
            current,
            current_measures,
            objective,
            bounds,
            constraints,
        })
    }

    /// The settings.
    pub fn spec(&self) -> &AfsProblemSpec {
        &self.spec
    }

    /// The current design's measures.
    pub fn current(&self) -> &YawMeasures {
        &self.current
    }

    /// The current design.
    pub fn current_design(&self) -> AfsDesign {
        AfsDesign::of(&self.base)
    }

    /// The objective (weights of Eq 4.8).
    pub fn objective(&self) -> &Objective {
        &self.objective
    }

    /// The active constraints, in the order of [`Evaluation::constraints`].
    pub fn constraints(&self) -> &[AfsConstraint] {
        &self.constraints
    }

    /// The design of a solver vector (SI, [`AfsVariable::ALL`]'s order).
    pub fn design_of(&self, x: &[f64]) -> Result<AfsDesign, DesignError> {
        let x: [f64; 5] = x.try_into().map_err(|_| DesignError::Shape {
            field: "x",
            reason: format!("expected 5 design variables, got {}", x.len()),
        })?;
        AfsDesign::from_vector(x)
    }

    /// The solver vector of a design.
    pub fn vector_of(&self, d: &AfsDesign) -> Vec<f64> {
        AfsVariable::ALL.map(|v| d.get(v)).to_vec()
    }

    /// Constraint values of `d` (feasible where <= 0), no simulation needed.
    pub fn constraint_values(&self, d: &AfsDesign) -> Vec<f64> {
        let g = full_lock_geometry(d, self.spec.max_articulation_rad);
        let mut c = Vec::with_capacity(self.constraints.len());
        c.push((g.l_max_m - 2.0 * g.l_min_m) / self.l0_current);
        if let Some(h) = self.spec.min_steering_arm_m {
            c.push((h - g.min_arm_m) / h);
        }
        if let Some(geo) = &self.spec.interference {
            let (beta_e, beta_t) = geo.limits(d.l1_m);
            let (lo, hi) = strut_angle_range(d, self.spec.max_articulation_rad);
            c.push(hi - beta_t);
            c.push(beta_e - lo);
        }
        c
    }

    /// The full evaluation of a design: measures, ratios, V, F, geometry, constraints.
    pub fn evaluate_design(&self, d: &AfsDesign) -> Result<DesignEvaluation, DesignError> {
        let p = d.apply(&self.base)?;
        let measures = measures_for(
            &self.vehicle,
            &p,
            Some(Load::Loaded),
            self.spec.speed_m_s,
            &self.spec.measure,
        )
        .map_err(|e| DesignError::Simulation(e.to_string()))?;
        let ratios = MeasureRatios::new(
            &DesignMeasures::from_yaw(&measures)?,
            &self.current_measures,
        )?;
        let constraints = self
            .constraints
            .iter()
            .copied()
            .zip(self.constraint_values(d))
            .collect();
        Ok(DesignEvaluation {
            design: *d,
            objective_vector: ratios.objective_vector(),
            f: self.objective.value(&ratios),
            geometry: full_lock_geometry(d, self.spec.max_articulation_rad),
            measures,
            ratios,
            constraints,
        })
    }

    /// The pulse and step responses of `d` under the problem's test definition (Fig 4.9):
    /// `(pulse, step)` records.
    pub fn responses(&self, d: &AfsDesign) -> Result<(YawRecord, YawRecord), DesignError> {
        let sys = AfsSystem::new(d.apply(&self.base)?)?;
        let m = &self.spec.measure;
        let run = |input: SteerInput, label: &str| {
            let man = Manoeuvre::open_loop(self.spec.speed_m_s, m.duration_s, input, label);
            simulate(&self.vehicle, &sys, &man, &m.options)
                .map_err(|e| DesignError::Simulation(e.to_string()))
        };
        Ok((
            run(
                SteerInput::pulse_deg(m.pulse_amplitude_deg, m.pulse_duration_s, m.input_time_s),
                "pulse",
            )?,
            run(
                SteerInput::step_deg(m.step_amplitude_deg, m.input_time_s),
                "step",
            )?,
        ))
    }

    /// `x` evaluated for a solver; with `screen`, a point that violates a constraint is not
    /// simulated (its objective is [`BARRIER`]), which is all an extreme barrier or Deb's
    /// rules need.
    pub fn evaluate_point(&self, x: &[f64], screen: bool) -> Evaluation {
        let Ok(d) = self.design_of(x) else {
            return Evaluation::failed(self.constraints.len());
        };
        let constraints = self.constraint_values(&d);
        if screen && constraints.iter().any(|c| *c > 0.0) {
            return Evaluation {
                f: BARRIER,
                constraints,
            };
        }
        match self.evaluate_design(&d) {
            Ok(e) => Evaluation {
                f: e.f,
                constraints,
            },
            Err(_) => Evaluation::failed(self.constraints.len()),
        }
    }

    /// The view that screens infeasible points (for pattern search and GA; SQP needs the
    /// objective just outside the boundary and uses the problem itself).
    pub fn screened(&self) -> Screened<'_> {
        Screened(self)
    }
}

impl ConstrainedProblem for AfsProblem {
    fn bounds(&self) -> &Bounds {
        &self.bounds
    }
    fn n_constraints(&self) -> usize {
        self.constraints.len()
    }
    fn evaluate(&self, x: &[f64]) -> Evaluation {
        self.evaluate_point(x, false)
    }
}

/// [`AfsProblem`] with infeasible points left unsimulated ([`AfsProblem::evaluate_point`]).
#[derive(Debug, Clone, Copy)]
pub struct Screened<'a>(pub &'a AfsProblem);

impl ConstrainedProblem for Screened<'_> {
    fn bounds(&self) -> &Bounds {
        &self.0.bounds
    }
    fn n_constraints(&self) -> usize {
        self.0.constraints.len()
    }
    fn evaluate(&self, x: &[f64]) -> Evaluation {
        self.0.evaluate_point(x, true)
    }
}

/// Range of the angle at L_1 between L_1->O and the strut axis over the steering range
/// (law of cosines in triangle O L_1 L_2; the left strut at A_0 + theta).
fn strut_angle_range(d: &AfsDesign, theta_max: f64) -> (f64, f64) {
    let (mut lo, mut hi) = (f64::MAX, f64::MIN);
    for i in 0..EQ_4_9_SAMPLES {
        let theta = theta_max * (2.0 * i as f64 / (EQ_4_9_SAMPLES - 1) as f64 - 1.0);
        let len = afs_hydraulics::kinematics::strut_length(d.l1_m, d.l2_m, d.a0_rad + theta);
        let cos = (d.l1_m * d.l1_m + len * len - d.l2_m * d.l2_m) / (2.0 * d.l1_m * len);
        let beta = cos.clamp(-1.0, 1.0).acos();
        lo = lo.min(beta);
        hi = hi.max(beta);
    }
    (lo, hi)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::AhpHierarchy;

    fn weights() -> Objective {
        Objective::new(AhpHierarchy::chapter4().weights().unwrap().composite).unwrap()
    }

    #[test]
    fn eq_4_10_at_the_printed_optima() {
        // Reading notes, section 3.4: L_max / L_min of the current design and the four
        // printed optima at +-45 deg.
        for (a0, l1, l2, ratio) in [
            (76.5, 1.96, 0.64, 1.623),
            (74.4, 1.86, 0.85, 2.004),
            (56.4, 1.79, 0.77, 1.992),
            (55.7, 1.95, 0.84, 1.992),
            (56.9, 1.67, 0.72, 1.996),
        ] {
            let d = AfsDesign::from_table_units(a0, l1, l2, 4.8, 1.6).unwrap();
            let g = full_lock_geometry(&d, 45.0 * DEG);
            assert!((g.stroke_ratio - ratio).abs() < 1.5e-3, "{a0}: {g:?}");
            // Eq 4.10 as printed, L > (L_max - L) + 2 (L - L_min), is L_max < 2 L_min.
            let l = g.strut_length_m;
            let printed = l > (g.l_max_m - l) + 2.0 * (l - g.l_min_m);
            assert_eq!(printed, g.l_max_m < 2.0 * g.l_min_m);
        }
        // The compact optima's short-side arm at full lock is 0.25-0.27 m, nominal 0.45 m.
        let d = AfsDesign::from_table_units(56.4, 1.79, 0.77, 7.2, 1.7).unwrap();
        let g = full_lock_geometry(&d, 45.0 * DEG);
        assert!((0.24..0.28).contains(&g.min_arm_m), "{g:?}");
        let nominal = full_lock_geometry(&AfsDesign::of(&AfsParams::nominal()), 45.0 * DEG);
        assert!((nominal.min_arm_m - 0.45).abs() < 0.01, "{nominal:?}");
    }

    #[test]
    fn current_design_scores_one_and_constraints_have_the_right_sign() {
        let p = AfsProblem::new(AfsProblemSpec::default(), weights()).unwrap();
        let cur = p.current_design();
        let e = p.evaluate_design(&cur).unwrap();
        assert!((e.f - 1.0).abs() < 1e-12, "{}", e.f);
        assert!(e.constraints.iter().all(|(_, c)| *c < 0.0), "{e:?}");
        // A_0 = 45 deg: zero arm on the short side at full lock (L_min = l_1 - l_2, so
        // Eq 4.10 still holds: 2.058 < 2 x 1.32).
        let mut d = cur;
        d.set(AfsVariable::A0, 45.0 * DEG);
        let c = p.constraint_values(&d);
        assert!(c[0] < 0.0 && (c[1] - 1.0).abs() < 1e-9, "{c:?}");
        // l_2 = l_1 at A_0 = 60 deg: L_min = 2 l sin 7.5 deg, L_max = 2 l sin 52.5 deg.
        let mut d = cur;
        d.set(AfsVariable::A0, 60.0 * DEG);
        d.set(AfsVariable::L2, d.l1_m);
        let c = p.constraint_values(&d);
        let want = 2.0 * d.l1_m * ((52.5 * DEG).sin() - 2.0 * (7.5 * DEG).sin());
        assert!(
            (c[0] - want / p.l0_current).abs() < 1e-12 && c[0] > 0.0,
            "{c:?}"
        );
        let screened = p.screened().evaluate(&p.vector_of(&d));
        assert_eq!(screened.f, BARRIER);
        assert_eq!(
            p.constraints(),
            &[AfsConstraint::Eq410, AfsConstraint::MinSteeringArm]
        );
    }

    #[test]
    fn optional_constraints_and_invalid_settings() {
        let spec = AfsProblemSpec {
            min_steering_arm_m: None,
            interference: Some(
                InterferenceGeometry::new(60.0 * DEG, [0.68, 0.79], [0.2, 0.3]).unwrap(),
            ),
            ..AfsProblemSpec::default()
        };
        let p = AfsProblem::new(spec, weights()).unwrap();
        assert_eq!(
            p.constraints(),
            &[
                AfsConstraint::Eq410,
                AfsConstraint::Eq49Tire,
                AfsConstraint::Eq49Engine
            ]
        );
        // The strut-axis angle of the current design sweeps 13.3-19.1 deg (notes, 3.4).
        let (lo, hi) = strut_angle_range(&p.current_design(), 45.0 * DEG);
        assert!(
            (lo / DEG - 13.3).abs() < 0.1 && (hi / DEG - 19.1).abs() < 0.1,
            "{lo} {hi}"
        );
        let e = InterferenceGeometry::new(0.0, [0.0, 0.0], [1.0, 1.0]).unwrap_err();
        assert!(e.to_string().contains("tire_point_m"), "{e}");
        let bad = AfsProblemSpec {
            min_steering_arm_m: Some(-1.0),
            ..AfsProblemSpec::default()
        };
        let e = AfsProblem::new(bad, weights()).unwrap_err();
        assert!(e.to_string().contains("min_steering_arm_m"), "{e}");
    }
}
