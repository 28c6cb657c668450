//! The HPS sensitivity study of section 6.5.1 (Table 6.4) on the 3-D vehicle: A_hc, A_v and
//! A_b one at a time at -30, -15, +15 and +30 % of Table 6.3 ([`HpsDesign::apply`]: gas charge
//! pressure and rod area held, every column height held), with the ride (a_wz unloaded and
//! loaded, D1), roll (SP-DRT, D2) and yaw (omega_z, D3) measures of `vehicle-3d`. Every
//! variant runs on the same terrain seeds (common random numbers), so the differences between
//! variants are not masked by the terrain's scatter.

use serde::Serialize;
use std::sync::Arc;
use vehicle_3d::scenarios::{
    ride_on, ride_tracks, roll_on, roll_tracks, yaw, RideSpec, RollSpec, Spread, YawSpec,
};
use vehicle_3d::TireTracks;
use vehicle_3d::{FrontAxle, Load, VehicleParams};

use crate::error::DesignError;
use crate::hps_design::HpsDesign;

/// The changes of Table 6.4 (fractions).
pub const TABLE_6_4_CHANGES: [f64; 4] = [-0.30, -0.15, 0.15, 0.30];

/// Largest number of terrain seeds of one study.
pub const MAX_SEEDS: usize = 100;

/// One design variable of Eq 6.19.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum HpsVariable {
    /// A_hc, the piston area.
    PistonArea,
    /// A_v, the area of one check valve.
    CheckValveArea,
    /// A_b, the area of one bleed orifice.
    BleedArea,
}

impl HpsVariable {
    /// The three, in Table 6.4 order.
    pub const ALL: [Self; 3] = [Self::PistonArea, Self::CheckValveArea, Self::BleedArea];

    /// The symbol of Table 6.4.
    pub fn symbol(self) -> &'static str {
        match self {
            Self::PistonArea => "A_hc",
            Self::CheckValveArea => "A_v",
            Self::BleedArea => "A_b",
        }
    }

    /// `d` with this variable scaled by `1 + change`.
    pub fn scaled(self, d: HpsDesign, change: f64) -> Result<HpsDesign, DesignError> {
        let f = 1.0 + change;
        match self {
            Self::PistonArea => HpsDesign::new(d.a_hc * f, d.a_v, d.a_b),
            Self::CheckValveArea => HpsDesign::new(d.a_hc, d.a_v * f, d.a_b),
            Self::BleedArea => HpsDesign::new(d.a_hc, d.a_v, d.a_b * f),
        }
    }
}

/// The four measures of one design.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct HpsMeasures {
    /// a_wz unloaded (m/s²).
    pub a_wz_unloaded_m_s2: Spread,
    /// a_wz loaded (m/s²).
    pub a_wz_loaded_m_s2: Spread,
    /// SP-DRT, loaded (m/s²).
    pub sp_drt_m_s2: Spread,
    /// omega_z, loaded, smooth ground (Hz).
    pub omega_z_hz: f64,
}

/// One cell row of Table 6.4: a variable at a change.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SensitivityRow {
    /// The variable changed.
    pub variable: HpsVariable,
    /// The change (fraction; 0 for the nominal design).
    pub change: f64,
    /// The measures; a measure with a failed run is n/a (NaN, n = 0).
    pub measures: HpsMeasures,
    /// The runs of this design that failed, each with its error.
    pub failures: Vec<String>,
}

/// Which measures a study runs (the ride measures always).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct StudyScope {
    /// Run D2 for SP-DRT.
    pub roll: bool,
    /// Run D3 for omega_z.
    pub yaw: bool,
}

/// The study: the nominal design and every variant, over the same seeds.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HpsSensitivity {
    /// Terrain seeds.
    pub seeds: Vec<u64>,
    /// The nominal design's measures.
    pub nominal: HpsMeasures,
    /// Every variant, variable by variable in Table 6.4 order, changes ascending.
    pub rows: Vec<SensitivityRow>,
}

/// A run of the study: a design index and, for the rough-terrain runs, the index of its
/// terrain case (load and seed, with the enveloping cache).
#[derive(Debug, Clone, Copy)]
enum Run {
    Ride(usize, usize, Load),
    Roll(usize, usize),
    Yaw(usize),
}

impl Run {
    /// The design index of the run.
    fn design(self) -> usize {
        match self {
            Run::Ride(d, _, _) | Run::Roll(d, _) | Run::Yaw(d) => d,
        }
    }

    /// The run in words, with the terrain seed from `cases`.
    fn describe(self, cases: &[(Option<Load>, u64)]) -> String {
        match self {
            Run::Ride(_, c, load) => format!("D1 {load} seed {}", cases[c].1),
            Run::Roll(_, c) => format!("D2 seed {}", cases[c].1),
            Run::Yaw(_) => "D3".into(),
        }
    }
}

/// The vehicle runs of [`hps_sensitivity`] with `changes` changes per variable over `seeds`
/// seeds in `scope` (the progress total): per design (the nominal and three variables times
/// the changes) two rides and a roll run per seed, and one yaw run.
pub fn sensitivity_runs(changes: usize, seeds: usize, scope: StudyScope) -> usize {
    let designs = 1 + 3 * changes;
    designs * (seeds * (2 + usize::from(scope.roll)) + usize::from(scope.yaw))
}

/// The study of the module docs for `base` (its `hps` is the nominal design) over `seeds`
/// and `changes`; `progress` is called once per finished run. NaN marks a measure outside
/// `scope`.
pub fn hps_sensitivity(
    base: &VehicleParams,
    changes: &[f64],
    seeds: &[u64],
    scope: StudyScope,
    progress: &(dyn Fn(&str) + Sync),
) -> Result<HpsSensitivity, DesignError> {
    if seeds.is_empty() || seeds.len() > MAX_SEEDS {
        return Err(DesignError::Shape {
            field: "seeds",
            reason: format!("between 1 and {MAX_SEEDS} seeds, got {}", seeds.len()),
        });
    }
    let nominal = HpsDesign::of(&base.hps);
    // design 0 is the nominal one, then variable by variable
    let mut designs = vec![(HpsVariable::PistonArea, 0.0, base.clone())];
    for v in HpsVariable::ALL {
        for &c in changes {
            if !(c.is_finite() && c > -1.0) {
                return Err(DesignError::Invalid {
                    field: "changes",
                    value: c,
                    reason: "a change must be finite and above -100 %",
                });
            }
            let mut p = base.clone();
            p.hps = v.scaled(nominal, c)?.apply(&base.hps)?;
            designs.push((v, c, p));
        }
    }
    let sim = |e: vehicle_3d::VehicleError| DesignError::Simulation(e.to_string());
    // the terrain cases: per seed the unloaded and loaded ride and the roll run (None). Their
    // enveloping caches depend on the terrain and the load, not on the strut design: built
    // once per case, shared by every design
    let ride_spec = |load| RideSpec::d1(load, FrontAxle::Suspended);
    let roll_spec = RollSpec::d2(FrontAxle::Suspended);
    let mut cases: Vec<(Option<Load>, u64)> = Vec::new();
    for &s in seeds {
        cases.push((Some(Load::Unloaded), s));
        cases.push((Some(Load::Loaded), s));
        if scope.roll {
            cases.push((None, s));
        }
    }
    let mut runs = Vec::new();
    for d in 0..designs.len() {
        for (c, case) in cases.iter().enumerate() {
            runs.push(match case.0 {
                Some(load) => Run::Ride(d, c, load),
                None => Run::Roll(d, c),
            });
        }
        if scope.yaw {
            runs.push(Run::Yaw(d));
        }
    }
    // a run that fails (a design the integrator cannot carry through, e.g. a strut driven
    // into a stiff state) does not stop the study: its measure becomes n/a (NaN, n = 0) and
    // the failure is reported with the design
    let values: Vec<Result<f64, String>> = crate::fan_out::cached(
        &cases,
        |&(load, s)| match load {
            Some(load) => ride_tracks(base, &ride_spec(load), s),
            None => roll_tracks(base, &roll_spec, s),
        },
        &runs,
        |&r, tracks: &[Arc<TireTracks>]| {
            match r {
                Run::Ride(d, c, load) => {
                    ride_on(&designs[d].2, &ride_spec(load), Arc::clone(&tracks[c]))
                        .map(|(_, m)| m.a_wz_m_s2)
                }
                Run::Roll(d, c) => roll_on(&designs[d].2, &roll_spec, Arc::clone(&tracks[c]))
                    .map(|(_, m)| m.sp_drt_m_s2),
                Run::Yaw(d) => yaw(&designs[d].2, &YawSpec::d3(FrontAxle::Suspended), 0)
                    .map(|(_, m)| m.omega_z_hz),
            }
            .map_err(|e| e.to_string())
        },
        |r| progress(&format!("{r:?}")),
    )
    .map_err(sim)?;
    // the spread of one measure, n/a when any of its runs failed
    let spread = |v: &[Option<f64>]| {
        let ok: Option<Vec<f64>> = v.iter().copied().collect();
        Spread::of_measured(&ok.unwrap_or_default()).map_err(sim)
    };
    let measures = |d: usize| -> Result<(HpsMeasures, Vec<String>), DesignError> {
        let (mut u, mut l, mut sp, mut wz) = (vec![], vec![], vec![], f64::NAN);
        let mut failures = Vec::new();
        for (r, v) in runs.iter().zip(&values) {
            let x = match v {
                Ok(x) => Some(*x),
                Err(e) => {
                    if r.design() == d {
                        failures.push(format!("{}: {e}", r.describe(&cases)));
                    }
                    None
                }
            };
            match *r {
                Run::Ride(i, _, Load::Unloaded) if i == d => u.push(x),
                Run::Ride(i, _, Load::Loaded) if i == d => l.push(x),
                Run::Roll(i, _) if i == d => sp.push(x),
                Run::Yaw(i) if i == d => wz = x.unwrap_or(f64::NAN),
                _ => {}
            }
        }
        Ok((
            HpsMeasures {
                a_wz_unloaded_m_s2: spread(&u)?,
                a_wz_loaded_m_s2: spread(&l)?,
                sp_drt_m_s2: spread(&sp)?,
                omega_z_hz: wz,
            },
            failures,
        ))
    };
    let rows = (1..designs.len())
        .map(|d| {
            let (measures, failures) = measures(d)?;
            Ok(SensitivityRow {
                variable: designs[d].0,
                change: designs[d].1,
                measures,
                failures,
            })
        })
        .collect::<Result<_, DesignError>>()?;
    let (nominal, nominal_failures) = measures(0)?;
    if !nominal_failures.is_empty() {
        // without the nominal design there is no table to compare against
        return Err(DesignError::Simulation(format!(
            "the nominal design failed: {}",
            nominal_failures.join("; ")
        )));
    }
    Ok(HpsSensitivity {
        seeds: seeds.to_vec(),
        nominal,
        rows,
    })
}
