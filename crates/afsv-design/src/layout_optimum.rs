//! `afsv optimize layout`: the optimisation of any suspension layout of `afsv study layouts`
//! (section 7.3's future work, docs/layouts.md "Optimising a layout") over parameters named
//! in the registries, with constraints on any of its measures.
//!
//! A problem ([`LayoutProblemDesc`]) is one layout of one vehicle (its 3-D parameters, front
//! axle, roll interconnection and cab and seat, stored whole), the variables (registry names
//! with bounds, [`LayoutVariable`]), an objective measure to minimise (or maximise) and
//! constraints ([`LayoutConstraint`], `awz_seat <= 0.5`, `sp_drt >= 0.96 * nominal`, where
//! `nominal` is the un-varied layout's value). A design is evaluated by the runs its
//! measures need, each on every terrain seed of the problem, the measure being the mean
//! over the seeds:
//! - the ride (D1 style, class E, m_c 0.3, after the 20 m run-in) at the problem's speed
//!   and load for `awz_frame`, `awz_seat`, `seat`, `strut_travel`, `rear_strut_travel`;
//! - D2 (loaded, ramp steer to rollover) for `sp_drt`;
//! - D3 (loaded, smooth ground, one run) for `omega_z`;
//! - D4 for `d4_speed`: the ride (frame a_wz, the problem's load and window) at every one
//!   of the problem's D4 speeds, the mean a_wz's first upward crossing of the ISO 2631-1
//!   8 h caution-zone bound ([`crate::hps_speed_sweep::first_upward_crossing`]), censored
//!   at the ends of the swept range ([`LayoutMeasure::D4Speed`]); `d4_speed_seat` the same
//!   on the seat pan's a_wz of the same runs ([`LayoutMeasure::D4SpeedSeat`]).
//!
//! The search is the real-coded GA of `optimize::ga` (Deb's feasibility rules, seeded, so
//! a run is reproducible bit for bit), its initial population the nominal design projected
//! onto the bounds and a Latin hypercube. The objective is the measure itself (negated to
//! maximise); constraint `m <= b` is `(m - b) / |b|` and `m >= b` is `(b - m) / |b|`
//! (feasible where <= 0), so constraints in different units weigh alike in Deb's rules.
//! The same search runs ask/tell ([`crate::layout_ask_tell`]) for a cluster.

use crate::error::DesignError;
use crate::hps_speed_sweep::{first_upward_crossing, HGCZ_HOURS};
use optimize::ga::{GaOptions, GeneticAlgorithm};
use optimize::{Bounds, ConstrainedProblem, Evaluation, Progress};
use perf_measures::iso2631::{health_guidance_zone, HgczRelation};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::collections::{BTreeMap, BTreeSet};
use std::sync::{Arc, OnceLock};
use vehicle_3d::cab_ride::{seat_ride_measures, CabSeatLayout};
use vehicle_3d::interconnect::{ride_linked_on, roll_linked_on, yaw_linked, Link};
use vehicle_3d::scenarios::{
    ride_on, ride_tracks, roll_on, roll_tracks, yaw, RideSpec, RollSpec, YawSpec, RUN_IN_M,
};
use vehicle_3d::{FrontAxle, Load, TireTracks, VehicleParams};
use vehicle_components::ParamSet;

mod measures;
mod outcome;
mod variables;

use measures::Run;
pub use measures::{LayoutConstraint, LayoutMeasure, Measured, Relation};
pub(crate) use outcome::result;
pub use outcome::{ConstraintResult, LayoutOptimum, VariableResult};
pub use variables::LayoutVariable;
use variables::{near, Target};

/// Largest number of terrain seeds of one problem.
pub const MAX_SEEDS: usize = 100;
/// Largest number of variables.
pub const MAX_VARIABLES: usize = 32;
/// Largest number of constraints.
pub const MAX_CONSTRAINTS: usize = 16;
/// Largest number of D4 speeds.
pub const MAX_D4_SPEEDS: usize = 20;
/// A variable within this share of its range from a bound (unit-cube coordinate) is on it.
pub const ON_BOUND: f64 = 1e-3;

/// What defines a layout optimisation: the layout (stored whole, so a shard or a resume
/// needs no file), the runs' settings, the variables, objective and constraints.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LayoutProblemDesc {
    /// The vehicle description's name.
    pub vehicle: String,
    /// The layout's name (`afsv study layouts`).
    pub layout: String,
    /// The layout's 3-D parameters (front strut in `hps`, rear strut in `rear_hps`).
    pub params: VehicleParams,
    /// The front axle.
    pub front_axle: FrontAxle,
    /// The layout's strut interconnection (the front struts' roll link or each side's
    /// pitch link), if any.
    pub link: Option<Link>,
    /// The cab and seat (needed by `awz_seat` and `seat`).
    pub seat: Option<CabSeatLayout>,
    /// Load case of the rides (D2 and D3 are loaded).
    pub load: Load,
    /// Speed of the rides (km/h).
    pub speed_kmh: f64,
    /// Measured window of the rides (m; D1: 100).
    pub ride_length_m: f64,
    /// Terrain seeds of every run.
    pub seeds: Vec<u64>,
    /// The D4 speeds of `d4_speed` (km/h, strictly ascending, at least two, 5 to 100);
    /// empty when no measure needs them.
    #[serde(default)]
    pub d4_speeds_kmh: Vec<f64>,
    /// The design variables.
    pub variables: Vec<LayoutVariable>,
    /// The objective measure.
    pub objective: LayoutMeasure,
    /// Maximise the objective instead of minimising it.
    pub maximise: bool,
    /// The constraints.
    pub constraints: Vec<LayoutConstraint>,
}

impl LayoutProblemDesc {
    /// Every name a variable may take for this layout.
    pub fn variable_names(&self) -> Vec<String> {
        let mut v: Vec<String> = Vec::new();
        if self.front_axle == FrontAxle::Suspended {
            v.extend(
                self.params
                    .hps
                    .specs()
                    .iter()
                    .map(|s| format!("front.{}", s.name)),
            );
        }
        if let Some(r) = &self.params.rear_hps {
            v.extend(r.specs().iter().map(|s| format!("rear.{}", s.name)));
        }
        v.extend(self.params.specs().iter().map(|s| s.name.to_string()));
        if let Some(s) = &self.seat {
            v.extend(s.seat.specs().iter().map(|p| format!("seat.{}", p.name)));
            v.extend(s.cab.specs().iter().map(|p| format!("cab.{}", p.name)));
        }
        v
    }

    /// Where variable `name` lives and its registry range; an unknown name lists the near
    /// names.
    fn target(&self, name: &str) -> Result<(Target, f64, f64), String> {
        let found = if let Some(n) = name.strip_prefix("front.") {
            (self.front_axle == FrontAxle::Suspended)
                .then(|| self.params.hps.find(n).ok())
                .flatten()
                .map(|(i, s)| (Target::Front(i), s.lower, s.upper))
        } else if let Some(n) = name.strip_prefix("rear.") {
            self.params
                .rear_hps
                .as_ref()
                .and_then(|r| r.find(n).ok())
                .map(|(i, s)| (Target::Rear(i), s.lower, s.upper))
        } else if let Some(n) = name.strip_prefix("seat.") {
            self.seat
                .as_ref()
                .and_then(|s| s.seat.find(n).ok())
                .map(|(i, s)| (Target::Seat(i), s.lower, s.upper))
        } else if let Some(n) = name.strip_prefix("cab.") {
            self.seat
                .as_ref()
                .and_then(|s| s.cab.find(n).ok())
                .map(|(i, s)| (Target::Cab(i), s.lower, s.upper))
        } else {
            self.params
                .find(name)
                .ok()
                .map(|(i, s)| (Target::Vehicle(i), s.lower, s.upper))
        };
        found.ok_or_else(|| {
            let names = self.variable_names();
            let close = near(name, names.iter().map(String::as_str));
            let hint = if close.is_empty() {
                "`afsv params list strut|vehicle-3d|seat|cab` list the names; a strut parameter takes `front.` or `rear.`, the seat's `seat.`, the cab's `cab.`".to_string()
            } else {
                format!("did you mean {}?", close.join(", "))
            };
            let axle = match name.split_once('.') {
                Some(("front", _)) if self.front_axle != FrontAxle::Suspended => {
                    format!(" (layout `{}` has no front strut)", self.layout)
                }
                Some(("rear", _)) if self.params.rear_hps.is_none() => {
                    format!(" (layout `{}` has no rear strut)", self.layout)
                }
                Some(("seat" | "cab", _)) if self.seat.is_none() => {
                    format!(" (layout `{}` has no cab and seat: --seat off?)", self.layout)
                }
                _ => String::new(),
            };
            if !axle.is_empty() {
                return format!("variable `{name}`{axle}");
            }
            format!("unknown variable `{name}`; {hint}")
        })
    }

    /// The problem, every field checked.
    pub fn problem(&self) -> Result<LayoutProblem, DesignError> {
        LayoutProblem::new(self.clone())
    }
}

fn shape(field: &'static str, reason: String) -> DesignError {
    DesignError::Shape { field, reason }
}

/// A checked problem with its enveloping caches.
pub struct LayoutProblem {
    desc: LayoutProblemDesc,
    targets: Vec<Target>,
    bounds: Bounds,
    /// Whether a vehicle parameter varies (then the caches, built on the nominal, do not
    /// apply: the tracks depend on the vehicle, not on the struts).
    vehicle_varies: bool,
    ride: Vec<OnceLock<Result<Arc<TireTracks>, String>>>,
    roll: Vec<OnceLock<Result<Arc<TireTracks>, String>>>,
}

impl LayoutProblem {
    /// Checks `desc`: seeds, speed, ride length, the layout (validated, the link needs the
    /// front HPS), the variables (known, distinct, `lower < upper` inside the registry's
    /// range), the measures (a seat measure needs a seat, a strut travel its strut), the
    /// constraint bounds.
    pub fn new(desc: LayoutProblemDesc) -> Result<Self, DesignError> {
        let d = &desc;
        if d.seeds.is_empty() || d.seeds.len() > MAX_SEEDS {
            return Err(shape(
                "seeds",
                format!("between 1 and {MAX_SEEDS} seeds, got {}", d.seeds.len()),
            ));
        }
        if !(d.speed_kmh.is_finite() && (5.0..=100.0).contains(&d.speed_kmh)) {
            return Err(DesignError::Invalid {
                field: "speed_kmh",
                value: d.speed_kmh,
                reason: "a speed must lie within 5-100 km/h",
            });
        }
        if !(d.ride_length_m.is_finite() && (10.0..=1000.0).contains(&d.ride_length_m)) {
            return Err(DesignError::Invalid {
                field: "ride_length_m",
                value: d.ride_length_m,
                reason: "the ride window must lie within 10-1000 m",
            });
        }
        let sim = |e: String| DesignError::Simulation(format!("layout `{}`: {e}", d.layout));
        d.params.validate().map_err(|e| sim(e.to_string()))?;
        if let Some(link) = &d.link {
            if d.front_axle != FrontAxle::Suspended {
                return Err(sim(
                    "the strut interconnection needs the front-axle HPS".into()
                ));
            }
            if matches!(link, Link::Pitch(_)) && d.params.rear_hps.is_none() {
                return Err(sim(
                    "the pitch interconnection needs struts on the rear axle".into(),
                ));
            }
            link.validate().map_err(|e| sim(e.to_string()))?;
        }
        if let Some(s) = &d.seat {
            s.build(&d.params)
                .map_err(|e| DesignError::Simulation(format!("the cab and seat: {e}")))?;
        }
        if d.variables.is_empty() || d.variables.len() > MAX_VARIABLES {
            return Err(shape(
                "variables",
                format!(
                    "between 1 and {MAX_VARIABLES} variables, got {}",
                    d.variables.len()
                ),
            ));
        }
        let mut targets = Vec::new();
        for (i, v) in d.variables.iter().enumerate() {
            if d.variables[..i].iter().any(|w| w.name == v.name) {
                return Err(shape("variables", format!("`{}` is named twice", v.name)));
            }
            let (t, lo, hi) = d.target(&v.name).map_err(|e| shape("variables", e))?;
            if v.lower >= v.upper || v.lower.is_nan() || v.upper.is_nan() {
                return Err(shape(
                    "variables",
                    format!(
                        "`{}`: the bounds {}..{} must have lower < upper",
                        v.name, v.lower, v.upper
                    ),
                ));
            }
            if v.lower < lo || v.upper > hi {
                return Err(shape(
                    "variables",
                    format!(
                        "`{}`: the bounds {}..{} leave the registry's range {lo}..{hi}",
                        v.name, v.lower, v.upper
                    ),
                ));
            }
            targets.push(t);
        }
        if d.constraints.len() > MAX_CONSTRAINTS {
            return Err(shape(
                "constraints",
                format!("at most {MAX_CONSTRAINTS}, got {}", d.constraints.len()),
            ));
        }
        for c in &d.constraints {
            if !c.value.is_finite() || (c.of_nominal && c.value <= 0.0) {
                return Err(DesignError::Invalid {
                    field: "constraints",
                    value: c.value,
                    reason: "a bound is finite; a factor on nominal is > 0",
                });
            }
        }
        let problem_measures =
            std::iter::once(d.objective).chain(d.constraints.iter().map(|c| c.measure));
        if problem_measures.clone().any(|m| m.run() == Run::Sweep) {
            let s = &d.d4_speeds_kmh;
            let ok = (2..=MAX_D4_SPEEDS).contains(&s.len())
                && s.iter().all(|v| v.is_finite() && (5.0..=100.0).contains(v))
                && s.windows(2).all(|w| w[0] < w[1]);
            if !ok {
                return Err(shape(
                    "d4_speeds_kmh",
                    format!(
                        "`d4_speed` and `d4_speed_seat` need 2 to {MAX_D4_SPEEDS} strictly ascending speeds within 5-100 km/h, got {s:?}"
                    ),
                ));
            }
        }
        for m in problem_measures {
            let why = match m {
                LayoutMeasure::AwzSeat | LayoutMeasure::Seat | LayoutMeasure::D4SpeedSeat
                    if d.seat.is_none() =>
                {
                    Some("needs a cab and seat")
                }
                LayoutMeasure::StrutTravel if d.front_axle != FrontAxle::Suspended => {
                    Some("needs the front-axle HPS")
                }
                LayoutMeasure::RearStrutTravel if d.params.rear_hps.is_none() => {
                    Some("needs a rear strut")
                }
                _ => None,
            };
            if let Some(why) = why {
                return Err(shape(
                    "measures",
                    format!("`{}` {why}; layout `{}` has none", m.name(), d.layout),
                ));
            }
        }
        let bounds = Bounds::new(
            d.variables.iter().map(|v| v.lower).collect(),
            d.variables.iter().map(|v| v.upper).collect(),
        )
        .map_err(|e| shape("variables", e.to_string()))?;
        let n = d.seeds.len();
        Ok(Self {
            vehicle_varies: targets.iter().any(|t| matches!(t, Target::Vehicle(_))),
            targets,
            bounds,
            ride: (0..n).map(|_| OnceLock::new()).collect(),
            roll: (0..n).map(|_| OnceLock::new()).collect(),
            desc,
        })
    }

    /// The description.
    pub fn desc(&self) -> &LayoutProblemDesc {
        &self.desc
    }

    /// The variables' bounds.
    pub fn variable_bounds(&self) -> &Bounds {
        &self.bounds
    }

    /// The measures the objective and the constraints need, each once.
    pub fn needed(&self) -> BTreeSet<LayoutMeasure> {
        std::iter::once(self.desc.objective)
            .chain(self.desc.constraints.iter().map(|c| c.measure))
            .collect()
    }

    /// The variables' values in the un-varied layout.
    pub fn nominal_x(&self) -> Vec<f64> {
        let p = &self.desc.params;
        self.targets
            .iter()
            .map(|t| match *t {
                Target::Front(i) => p.hps.value(i),
                Target::Rear(i) => p.rear_hps.map_or(f64::NAN, |r| r.value(i)),
                Target::Vehicle(i) => p.value(i),
                Target::Seat(i) => self.desc.seat.map_or(f64::NAN, |s| s.seat.value(i)),
                Target::Cab(i) => self.desc.seat.map_or(f64::NAN, |s| s.cab.value(i)),
            })
            .collect()
    }

    /// The layout's parameters with the variables at `x` (each set through its registry:
    /// in range, and the whole set valid afterwards).
    pub fn params_at(&self, x: &[f64]) -> Result<VehicleParams, String> {
        self.design_at(x).map(|(p, _)| p)
    }

    /// The layout's parameters and its cab and seat with the variables at `x` (each set
    /// through its registry: in range, and the whole set valid afterwards; the cab and
    /// seat must build under the vehicle's gravity).
    pub fn design_at(&self, x: &[f64]) -> Result<(VehicleParams, Option<CabSeatLayout>), String> {
        if x.len() != self.targets.len() {
            return Err(format!(
                "{} values for {} variables",
                x.len(),
                self.targets.len()
            ));
        }
        let mut p = self.desc.params.clone();
        let mut seat = self.desc.seat;
        for ((t, v), var) in self.targets.iter().zip(x).zip(&self.desc.variables) {
            let named = |e: vehicle_components::ParamError| format!("{}: {e}", var.name);
            match *t {
                Target::Front(i) => {
                    let name = p.hps.specs()[i].name;
                    p.hps.set(name, *v).map_err(named)?;
                }
                Target::Rear(i) => {
                    let r = p.rear_hps.as_mut().ok_or("the layout has no rear strut")?;
                    let name = r.specs()[i].name;
                    r.set(name, *v).map_err(named)?;
                }
                Target::Vehicle(i) => {
                    let name = p.specs()[i].name;
                    p.set(name, *v).map_err(named)?;
                }
                Target::Seat(i) => {
                    let s = &mut seat.as_mut().ok_or("the layout has no seat")?.seat;
                    let name = s.specs()[i].name;
                    s.set(name, *v).map_err(named)?;
                }
                Target::Cab(i) => {
                    let c = &mut seat.as_mut().ok_or("the layout has no cab")?.cab;
                    let name = c.specs()[i].name;
                    c.set(name, *v).map_err(named)?;
                }
            }
        }
        p.validate().map_err(|e| e.to_string())?;
        if let Some(s) = &seat {
            s.build(&p).map_err(|e| format!("the cab and seat: {e}"))?;
        }
        Ok((p, seat))
    }

    fn cached(
        &self,
        cache: &OnceLock<Result<Arc<TireTracks>, String>>,
        p: &VehicleParams,
        build: &dyn Fn(&VehicleParams) -> Result<Arc<TireTracks>, String>,
    ) -> Result<Arc<TireTracks>, String> {
        if self.vehicle_varies {
            return build(p);
        }
        cache.get_or_init(|| build(&self.desc.params)).clone()
    }

    /// The needed measures of the design at `x` (`None`: the un-varied layout), each the
    /// mean over the seeds; an error names the failed run.
    pub fn measure(&self, x: Option<&[f64]>) -> Result<Measured, String> {
        let d = &self.desc;
        let (p, seat) = match x {
            Some(x) => self.design_at(x)?,
            None => (d.params.clone(), d.seat),
        };
        let needed = self.needed();
        let needs = |r: Run| needed.iter().any(|m| m.run() == r);
        let (need_ride, need_roll) = (needs(Run::Ride), needs(Run::Roll));
        let sim = |e: vehicle_3d::VehicleError| e.to_string();
        let ride_spec = RideSpec {
            speed_kmh: d.speed_kmh,
            length_m: d.ride_length_m,
            ..RideSpec::d1(d.load, d.front_axle)
        };
        let roll_spec = RollSpec::d2(d.front_axle);
        let mut sums: Measured = BTreeMap::new();
        let per_seed: Vec<Result<Vec<(LayoutMeasure, f64)>, String>> = (0..d.seeds.len())
            .into_par_iter()
            .map(|k| {
                let seed = d.seeds[k];
                let mut out = Vec::new();
                if need_ride {
                    let t = self.cached(&self.ride[k], &p, &|q| {
                        ride_tracks(q, &ride_spec, seed).map_err(sim)
                    })?;
                    let (rec, m) = match &d.link {
                        None => ride_on(&p, &ride_spec, t).map_err(sim)?,
                        Some(link) => {
                            let (run, m) = ride_linked_on(&p, &ride_spec, t, link).map_err(sim)?;
                            (run.record, m)
                        }
                    };
                    out.push((LayoutMeasure::AwzFrame, m.a_wz_m_s2));
                    if let Some(v) = m.strut_travel_p2p_m {
                        out.push((LayoutMeasure::StrutTravel, v));
                    }
                    if let Some(v) = m.rear_strut_travel_p2p_m {
                        out.push((LayoutMeasure::RearStrutTravel, v));
                    }
                    if let Some(s) = &seat {
                        let t0 = RUN_IN_M / (d.speed_kmh / 3.6);
                        let r = seat_ride_measures(&p, &rec, t0, s).map_err(sim)?;
                        out.push((LayoutMeasure::AwzSeat, r.a_wz_seat_m_s2));
                        out.push((LayoutMeasure::Seat, r.seat.seat));
                    }
                }
                if need_roll {
                    let t = self.cached(&self.roll[k], &p, &|q| {
                        roll_tracks(q, &roll_spec, seed).map_err(sim)
                    })?;
                    let m = match &d.link {
                        None => roll_on(&p, &roll_spec, t).map_err(sim)?.1,
                        Some(link) => roll_linked_on(&p, &roll_spec, t, link).map_err(sim)?.1,
                    };
                    out.push((LayoutMeasure::SpDrt, m.sp_drt_m_s2));
                }
                Ok(out)
            })
            .collect();
        for r in per_seed {
            for (m, v) in r? {
                if needed.contains(&m) {
                    *sums.entry(m).or_insert(0.0) += v;
                }
            }
        }
        let n = d.seeds.len() as f64;
        for v in sums.values_mut() {
            *v /= n;
        }
        if needs(Run::Yaw) {
            let spec = YawSpec::d3(d.front_axle);
            let m = match &d.link {
                None => yaw(&p, &spec, 0).map_err(sim)?.1,
                Some(link) => yaw_linked(&p, &spec, link).map_err(sim)?.1,
            };
            sums.insert(LayoutMeasure::OmegaZ, m.omega_z_hz);
        }
        if needs(Run::Sweep) {
            let at_seat = needed.contains(&LayoutMeasure::D4SpeedSeat);
            let (frame, on_seat) = self.d4_speed(&p, seat.as_ref().filter(|_| at_seat))?;
            if needed.contains(&LayoutMeasure::D4Speed) {
                sums.insert(LayoutMeasure::D4Speed, frame);
            }
            if let Some(v) = on_seat {
                sums.insert(LayoutMeasure::D4SpeedSeat, v);
            }
        }
        for m in &needed {
            match sums.get(m) {
                Some(v) if v.is_finite() => {}
                Some(v) => return Err(format!("{} = {v}: not a finite number", m.name())),
                None => return Err(format!("{}: the runs gave no value", m.name())),
            }
        }
        Ok(sums)
    }

    /// `d4_speed` of the layout `p` ([`LayoutMeasure::D4Speed`]): the ride at every D4
    /// speed on every seed (its own tracks: they depend on the speed), the frame's a_wz
    /// averaged over the seeds, its first upward crossing of the 8 h caution-zone bound,
    /// censored at the ends of the range; with `seat`, also `d4_speed_seat`
    /// ([`LayoutMeasure::D4SpeedSeat`]) from the seat pan's a_wz on the same runs.
    fn d4_speed(
        &self,
        p: &VehicleParams,
        seat: Option<&CabSeatLayout>,
    ) -> Result<(f64, Option<f64>), String> {
        let d = &self.desc;
        let sim = |e: vehicle_3d::VehicleError| e.to_string();
        let speeds = &d.d4_speeds_kmh;
        let runs: Vec<(usize, u64)> = (0..speeds.len())
            .flat_map(|i| d.seeds.iter().map(move |&s| (i, s)))
            .collect();
        // per run: the frame's a_wz and, with a seat, the seat pan's
        let awz: Vec<Result<(usize, f64, f64), String>> = runs
            .into_par_iter()
            .map(|(i, seed)| {
                let spec = RideSpec {
                    speed_kmh: speeds[i],
                    length_m: d.ride_length_m,
                    ..RideSpec::d1(d.load, d.front_axle)
                };
                let t = ride_tracks(p, &spec, seed).map_err(sim)?;
                let (rec, m) = match &d.link {
                    None => ride_on(p, &spec, t).map_err(sim)?,
                    Some(link) => {
                        let (run, m) = ride_linked_on(p, &spec, t, link).map_err(sim)?;
                        (run.record, m)
                    }
                };
                let on_seat = match seat {
                    Some(s) => {
                        let t0 = RUN_IN_M / (speeds[i] / 3.6);
                        seat_ride_measures(p, &rec, t0, s)
                            .map_err(sim)?
                            .a_wz_seat_m_s2
                    }
                    None => f64::NAN,
                };
                Ok((i, m.a_wz_m_s2, on_seat))
            })
            .collect();
        let (mut frame, mut on_seat) = (vec![0.0; speeds.len()], vec![0.0; speeds.len()]);
        for r in awz {
            let (i, a, s) = r.map_err(|e| format!("d4_speed: {e}"))?;
            frame[i] += a / d.seeds.len() as f64;
            on_seat[i] += s / d.seeds.len() as f64;
        }
        let upper = health_guidance_zone(HGCZ_HOURS, HgczRelation::SqrtTime)
            .map_err(|e| e.to_string())?
            .upper_m_s2;
        Ok((
            d4_crossing(speeds, &frame, upper),
            seat.map(|_| d4_crossing(speeds, &on_seat, upper)),
        ))
    }

    /// The D4 measures of `m` (`d4_speed`, `d4_speed_seat`, those measured) that lie at an
    /// end of the swept D4 range, where they are censored ([`LayoutMeasure::D4Speed`]),
    /// each with the sentence that says so.
    pub fn d4_censored(&self, m: &Measured) -> Vec<(LayoutMeasure, String)> {
        let s = &self.desc.d4_speeds_kmh;
        let (Some(&lo), Some(&hi)) = (s.first(), s.last()) else {
            return Vec::new();
        };
        [
            (LayoutMeasure::D4Speed, "the frame's"),
            (LayoutMeasure::D4SpeedSeat, "the seat pan's"),
        ]
        .into_iter()
        .filter_map(|(measure, whose)| {
            let v = *m.get(&measure)?;
            let name = measure.name();
            let text = if v >= hi {
                format!("{name}: {whose} a_wz stays below the 8 h caution zone up to {hi} km/h, the top of the D4 speeds (the crossing lies beyond: raise the top speed)")
            } else if v <= lo {
                format!("{name}: {whose} a_wz is in the 8 h caution zone already at {lo} km/h, the lowest D4 speed (the crossing lies at or below it: lower the lowest speed)")
            } else {
                return None;
            };
            Some((measure, text))
        })
        .collect()
    }

    /// The GA's evaluation of measures `m` given the nominal ones (module docs).
    pub fn evaluation(&self, m: &Measured, nominal: &Measured) -> Evaluation {
        let obj = m.get(&self.desc.objective).copied().unwrap_or(f64::NAN);
        let constraints: Vec<f64> = self
            .desc
            .constraints
            .iter()
            .map(|c| c.value_of(m, nominal))
            .collect();
        if !obj.is_finite() || constraints.iter().any(|c| !c.is_finite()) {
            return Evaluation::failed(constraints.len());
        }
        Evaluation {
            f: if self.desc.maximise { -obj } else { obj },
            constraints,
        }
    }
}

/// The D4 crossing speed of the mean a_wz `awz` over ascending `speeds` against the bound
/// `upper`: the first upward crossing, linearly interpolated; the highest speed when the
/// a_wz never rises above the bound, the lowest when it is above it at the lowest speed
/// (censored values, [`LayoutMeasure::D4Speed`]).
pub fn d4_crossing(speeds: &[f64], awz: &[f64], upper: f64) -> f64 {
    match first_upward_crossing(speeds, awz, upper) {
        Some(v) => v,
        None if awz.first().is_some_and(|a| *a > upper) => speeds[0],
        None => speeds[speeds.len() - 1],
    }
}

/// The problem as the GA sees it: the bounds, and each point measured and scored against
/// the nominal measures.
pub(crate) struct Scored<'a> {
    pub(crate) problem: &'a LayoutProblem,
    pub(crate) nominal: &'a Measured,
}

impl ConstrainedProblem for Scored<'_> {
    fn bounds(&self) -> &Bounds {
        &self.problem.bounds
    }
    fn n_constraints(&self) -> usize {
        self.problem.desc.constraints.len()
    }
    fn evaluate(&self, x: &[f64]) -> Evaluation {
        match self.problem.measure(Some(x)) {
            Ok(m) => self.problem.evaluation(&m, self.nominal),
            Err(_) => Evaluation::failed(self.n_constraints()),
        }
    }
}

/// Settings of the GA.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LayoutGaSettings {
    /// Individuals per generation (even, 4 to 1000).
    pub population: usize,
    /// Generations after the initial one (1 to 1000).
    pub generations: usize,
    /// Seed of the GA's random numbers.
    pub seed: u64,
}

impl LayoutGaSettings {
    /// The GA options (checked).
    pub fn options(&self) -> Result<GaOptions, DesignError> {
        if !(4..=1000).contains(&self.population) || self.population % 2 == 1 {
            return Err(shape(
                "population",
                format!("even, 4 to 1000, got {}", self.population),
            ));
        }
        if !(1..=1000).contains(&self.generations) {
            return Err(shape(
                "generations",
                format!("1 to 1000, got {}", self.generations),
            ));
        }
        let o = GaOptions {
            population: self.population,
            generations: self.generations,
            seed: self.seed,
            ..GaOptions::default()
        };
        o.validate().map_err(|e| shape("ga", e.to_string()))?;
        Ok(o)
    }
}

/// The optimisation of the module docs, in this process: the nominal measured, the GA run
/// (`progress` once per generation), the optimum measured.
pub fn optimise_layout(
    problem: &LayoutProblem,
    ga: &LayoutGaSettings,
    progress: &dyn Progress,
) -> Result<LayoutOptimum, DesignError> {
    let options = ga.options()?;
    let nominal = problem
        .measure(None)
        .map_err(|e| DesignError::Simulation(format!("the nominal layout: {e}")))?;
    let scored = Scored {
        problem,
        nominal: &nominal,
    };
    let opt = |e: optimize::OptimizeError| shape("ga", e.to_string());
    let algo = GeneticAlgorithm::new(&scored, options).map_err(opt)?;
    let start = algo.start(&[problem.nominal_x()]).map_err(opt)?;
    let end = algo.run(start, progress, &mut |_| Ok(())).map_err(opt)?;
    let best = end.best();
    result(problem, ga, &nominal, &best.u, &best.x, end.evaluations)
}

#[cfg(test)]
pub(crate) mod tests;
