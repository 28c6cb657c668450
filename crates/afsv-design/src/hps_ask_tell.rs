//! The chapter-6 HPS optimisation of [`crate::hps_optimum`] split into ask (the next batch
//! of vehicle runs) and tell (advance by their measures), so that its runs go anywhere:
//! other processes, a cluster's array tasks (`afsv optimize hps --state --ask/--tell`,
//! `afsv batch evaluate --shard I/N`; docs/optimisation.md "Running on a cluster").
//!
//! A run asks, in order:
//!
//! 1. `initial`: the nominal design's search ride (the a_wzn and d_sn of Eq 6.19), then the
//!    GA's initial population ([`optimize::ga::GeneticAlgorithm::initial`]): the nominal's
//!    measures are one more point of the first batch, since the initial population does
//!    not depend on them;
//! 2. `generation N`: each generation's children;
//! 3. `reevaluation`: the optimum's search ride once more, then for the nominal design and
//!    the optimum each re-evaluation seed's D1 ride, each seed's D2 roll (unless
//!    `reevaluate_roll` is off) and the D3 yaw run, one point each.
//!
//! A shard returns each point's raw measures ([`HpsValues`]); tell scores the search rides
//! against the stored nominal ([`crate::hps_optimum`]'s Eq 6.19) and advances the GA as the
//! in-process [`crate::optimise_hps`] does, and the finished run assembles the same
//! [`HpsOptimum`], bit for bit (the JSON numbers round-trip exactly).
//!
//! The files: a batch (header [`HpsBatchHeader`], one [`HpsBatchPoint`] a line), a results
//! file (header [`HpsResultsHeader`], one [`HpsPointResult`] a line) and the state
//! ([`HpsAskTellState`]). Every header carries the whole problem ([`HpsProblemDesc`]: the
//! vehicle and the settings), so a shard needs nothing but its batch file.

use crate::batch_files::{check_results_header, collect_results, BatchKind};
use crate::error::DesignError;
use crate::hps_optimum::{
    assessment, check_settings, evaluation, ga_options, nominal_x, reevaluation_seeds, result,
    search_bounds, Found, HpsGaSettings, HpsOptimum, RideValues,
};
use optimize::ga::{GaOptions, GaState, GeneticAlgorithm};
use optimize::{Bounds, ConstrainedProblem, Evaluation, OptimizeError};
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};
use vehicle_3d::VehicleParams;

mod shard;

pub use shard::{
    batch_file, batch_points, evaluate_hps_shard, read_hps_batch, HpsBatchHeader, HpsBatchPoint,
    HpsPointResult, HpsResultsHeader,
};

/// Version of the HPS batch, results and state formats.
pub const HPS_FORMAT_VERSION: u32 = 1;
/// `format` of an HPS batch file's header.
pub const HPS_BATCH_FORMAT: &str = "afsv-hps-batch";
/// `format` of an HPS results file's header.
pub const HPS_RESULTS_FORMAT: &str = "afsv-hps-results";
/// `format` of the HPS ask/tell state file.
pub const HPS_STATE_FORMAT: &str = "afsv-hps-state";

/// The problem, whole: what a shard needs to run its points.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HpsProblemDesc {
    /// The vehicle's name.
    pub vehicle: String,
    /// The vehicle (its `hps` is the nominal design).
    pub params: VehicleParams,
    /// The settings.
    pub settings: HpsGaSettings,
}

/// The run a point asks for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum HpsTask {
    /// D1 on the search seed: a_wz and d_s.
    Search,
    /// D1 (unloaded, 20 km/h, class E) on `seed`: a_wz.
    Ride,
    /// D2 to rollover on `seed`: SP-DRT.
    Roll,
    /// D3 on smooth ground: omega_z.
    Yaw,
}

/// One point of a batch: a run of one design.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HpsPoint {
    /// The run.
    pub task: HpsTask,
    /// Its terrain seed (the search seed for [`HpsTask::Search`], 0 for [`HpsTask::Yaw`]).
    pub seed: u64,
    /// The design [A_hc, A_v, A_b] (m²); `None`: the vehicle's own struts.
    pub x: Option<[f64; 3]>,
}

/// The measures of one point (absent: not measured by its run, or not a finite number).
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HpsValues {
    /// a_wz (m/s²): search and ride runs.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub a_wz_m_s2: Option<f64>,
    /// d_s (m): search runs.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub d_s_m: Option<f64>,
    /// SP-DRT (m/s²): roll runs.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sp_drt_m_s2: Option<f64>,
    /// omega_z (Hz): yaw runs.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub omega_z_hz: Option<f64>,
}

/// A finite value, else `None` (what JSON can carry).
fn finite(x: f64) -> Option<f64> {
    x.is_finite().then_some(x)
}

/// A stored value back (`None` to NaN).
fn back(x: Option<f64>) -> f64 {
    x.unwrap_or(f64::NAN)
}

impl HpsValues {
    /// The search ride of these values.
    fn ride(&self) -> RideValues {
        RideValues {
            a_wz_m_s2: back(self.a_wz_m_s2),
            d_s_m: back(self.d_s_m),
        }
    }
}

/// Where an HPS run stands: the nominal's search ride once told, the GA's state, then the
/// re-evaluation's values (in the order of its batch).
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HpsRunState {
    /// The nominal design's search ride.
    pub nominal: Option<HpsValues>,
    /// The GA after its initial population and each generation told.
    pub ga: Option<GaState>,
    /// The re-evaluation batch's values.
    pub reevaluated: Option<Vec<HpsValues>>,
}

/// The phase of a batch.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum HpsPhase {
    /// The nominal design and the GA's initial population.
    Initial,
    /// The children of generation `n` (1-based).
    Generation(usize),
    /// The optimum's search ride and both designs over the re-evaluation seeds.
    Reevaluation,
}

impl HpsPhase {
    /// `initial`, `generation N` or `reevaluation`.
    pub fn name(self) -> String {
        match self {
            HpsPhase::Initial => "initial".into(),
            HpsPhase::Generation(n) => format!("generation {n}"),
            HpsPhase::Reevaluation => "reevaluation".into(),
        }
    }
}

/// The next batch of a run.
#[derive(Debug, Clone, PartialEq)]
pub struct HpsBatch {
    /// Its phase.
    pub phase: HpsPhase,
    /// The points.
    pub points: Vec<HpsPoint>,
}

/// What [`HpsAskTell::ask`] found.
#[derive(Debug, Clone, PartialEq)]
pub enum HpsAsk {
    /// Run these points and tell their values.
    Evaluate(HpsBatch),
    /// Search and re-evaluation are done; [`HpsAskTell::finish`] gives the result.
    Finished,
}

/// The GA's view of the problem when the evaluations come from elsewhere: its bounds and
/// its one constraint (a_wz <= the limit). Ask/tell never evaluates through it (the GA's
/// `initial`, `start_told`, `ask` and `tell` take evaluations made elsewhere); an
/// evaluation asked of it is a failed one.
struct Told {
    bounds: Bounds,
}

impl ConstrainedProblem for Told {
    fn bounds(&self) -> &Bounds {
        &self.bounds
    }
    fn n_constraints(&self) -> usize {
        1
    }
    fn evaluate(&self, _x: &[f64]) -> Evaluation {
        Evaluation::failed(1)
    }
}

fn opt(e: OptimizeError) -> DesignError {
    DesignError::Shape {
        field: "ga",
        reason: e.to_string(),
    }
}

/// The ask/tell driver of one problem.
pub struct HpsAskTell<'a> {
    desc: &'a HpsProblemDesc,
    problem: Told,
    options: GaOptions,
}

/// `x` as a design array.
fn design(x: &[f64]) -> [f64; 3] {
    [x[0], x[1], x[2]]
}

impl<'a> HpsAskTell<'a> {
    /// The driver of `desc` (its settings checked).
    pub fn new(desc: &'a HpsProblemDesc) -> Result<Self, DesignError> {
        check_settings(&desc.settings)?;
        let problem = Told {
            bounds: search_bounds(&desc.settings)?,
        };
        let options = ga_options(&desc.settings);
        GeneticAlgorithm::new(&problem, options).map_err(opt)?;
        Ok(Self {
            desc,
            problem,
            options,
        })
    }

    fn ga(&self) -> GeneticAlgorithm<'_, Told> {
        GeneticAlgorithm::new(&self.problem, self.options).expect("options checked in new")
    }

    /// The initial population in unit-cube coordinates.
    fn initial(&self) -> Result<Vec<Vec<f64>>, DesignError> {
        self.ga()
            .initial(&[nominal_x(&self.desc.params)])
            .map_err(opt)
    }

    /// The search ride of `x`.
    fn search(&self, x: &[f64]) -> HpsPoint {
        HpsPoint {
            task: HpsTask::Search,
            seed: self.desc.settings.terrain_seed,
            x: Some(design(x)),
        }
    }

    /// The re-evaluation runs of one design (`None`: the vehicle's own struts).
    fn reevaluation(&self, x: Option<[f64; 3]>) -> Vec<HpsPoint> {
        let seeds = reevaluation_seeds(&self.desc.settings);
        let mut points: Vec<HpsPoint> = seeds
            .iter()
            .map(|&seed| HpsPoint {
                task: HpsTask::Ride,
                seed,
                x,
            })
            .collect();
        if self.desc.settings.reevaluate_roll {
            points.extend(seeds.iter().map(|&seed| HpsPoint {
                task: HpsTask::Roll,
                seed,
                x,
            }));
        }
        points.push(HpsPoint {
            task: HpsTask::Yaw,
            seed: 0,
            x,
        });
        points
    }

    /// The GA's state, checked.
    fn state<'s>(&self, run: &'s HpsRunState) -> Result<Option<&'s GaState>, DesignError> {
        if let Some(st) = &run.ga {
            self.ga().check_state(st).map_err(opt)?;
        }
        Ok(run.ga.as_ref())
    }

    /// The next batch of `run` (a pure function of the state), or [`HpsAsk::Finished`].
    pub fn ask(&self, run: &HpsRunState) -> Result<HpsAsk, DesignError> {
        let b = &self.problem.bounds;
        let Some(st) = self.state(run)? else {
            let mut points = vec![self.search(&nominal_x(&self.desc.params))];
            points.extend(self.initial()?.iter().map(|u| self.search(&b.from_unit(u))));
            return Ok(HpsAsk::Evaluate(HpsBatch {
                phase: HpsPhase::Initial,
                points,
            }));
        };
        if st.generation < self.options.generations {
            if run.reevaluated.is_some() {
                return Err(DesignError::Shape {
                    field: "state",
                    reason: "a re-evaluation stored before the GA's last generation".into(),
                });
            }
            return Ok(HpsAsk::Evaluate(HpsBatch {
                phase: HpsPhase::Generation(st.generation + 1),
                points: self
                    .ga()
                    .ask(st)
                    .iter()
                    .map(|u| self.search(&b.from_unit(u)))
                    .collect(),
            }));
        }
        if run.reevaluated.is_some() {
            return Ok(HpsAsk::Finished);
        }
        let best = design(&st.best().x);
        let mut points = vec![self.search(&best)];
        points.extend(self.reevaluation(None));
        points.extend(self.reevaluation(Some(best)));
        Ok(HpsAsk::Evaluate(HpsBatch {
            phase: HpsPhase::Reevaluation,
            points,
        }))
    }

    /// Advances `run` by the values of the batch [`HpsAskTell::ask`] gives for it, in its
    /// order (an `Err` is a run that failed: a GA design scores as failed, as in-process; a
    /// failed nominal or re-evaluation run is refused, as in-process it ends the run). A
    /// refused tell leaves `run` unchanged.
    pub fn tell(
        &self,
        run: &mut HpsRunState,
        values: Vec<Result<HpsValues, String>>,
    ) -> Result<(), DesignError> {
        let HpsAsk::Evaluate(asked) = self.ask(run)? else {
            return Err(DesignError::Shape {
                field: "state",
                reason: "the run has finished; nothing to tell".into(),
            });
        };
        if values.len() != asked.points.len() {
            return Err(DesignError::Shape {
                field: "values",
                reason: format!(
                    "expected {} points' values, got {}",
                    asked.points.len(),
                    values.len()
                ),
            });
        }
        let limit = self.desc.settings.a_wz_limit_m_s2;
        let score = |v: &Result<HpsValues, String>, nominal: &RideValues| {
            let r = v
                .as_ref()
                .map(HpsValues::ride)
                .map_err(|e| DesignError::Simulation(e.clone()));
            evaluation(r, nominal, limit)
        };
        match asked.phase {
            HpsPhase::Initial => {
                let nominal = values[0]
                    .clone()
                    .map_err(|e| DesignError::Simulation(format!("the nominal design: {e}")))?;
                let evals = values[1..]
                    .iter()
                    .map(|v| score(v, &nominal.ride()))
                    .collect();
                let units = self.initial()?;
                run.ga = Some(self.ga().start_told(units, evals).map_err(opt)?);
                run.nominal = Some(nominal);
            }
            HpsPhase::Generation(_) => {
                let nominal = run.nominal.ok_or_else(|| DesignError::Shape {
                    field: "state",
                    reason: "a GA state without the nominal design's ride".into(),
                })?;
                let evals = values.iter().map(|v| score(v, &nominal.ride())).collect();
                let mut st = run.ga.clone().expect("a generation is asked of a GA state");
                self.ga().tell(&mut st, evals).map_err(opt)?;
                run.ga = Some(st);
            }
            HpsPhase::Reevaluation => {
                let told = values
                    .into_iter()
                    .zip(&asked.points)
                    .map(|(v, p)| {
                        v.map_err(|e| {
                            DesignError::Simulation(format!(
                                "the re-evaluation's {:?} run on seed {}: {e}",
                                p.task, p.seed
                            ))
                        })
                    })
                    .collect::<Result<Vec<HpsValues>, DesignError>>()?;
                run.reevaluated = Some(told);
            }
        }
        Ok(())
    }

    /// The result of a finished run.
    pub fn finish(&self, run: &HpsRunState) -> Result<HpsOptimum, DesignError> {
        let (Some(nominal), Some(st), Some(values), HpsAsk::Finished) =
            (&run.nominal, &run.ga, &run.reevaluated, self.ask(run)?)
        else {
            return Err(DesignError::Shape {
                field: "state",
                reason: "the run has not finished; ask for the next batch".into(),
            });
        };
        let settings = &self.desc.settings;
        let n = settings.reevaluation_seeds;
        let per_design = n * if settings.reevaluate_roll { 2 } else { 1 } + 1;
        if values.len() != 1 + 2 * per_design {
            return Err(DesignError::Shape {
                field: "reevaluated",
                reason: format!(
                    "{} values, the re-evaluation has {}",
                    values.len(),
                    1 + 2 * per_design
                ),
            });
        }
        let assess = |v: &[HpsValues]| {
            let a_wz: Vec<f64> = v[..n].iter().map(|v| back(v.a_wz_m_s2)).collect();
            let sp_drt: Vec<f64> = v[n..per_design - 1]
                .iter()
                .map(|v| back(v.sp_drt_m_s2))
                .collect();
            assessment(&a_wz, &sp_drt, back(v[per_design - 1].omega_z_hz))
        };
        let best = st.best();
        result(
            &self.desc.params,
            settings,
            Found {
                best,
                evaluations: st.evaluations,
                nominal_ride: nominal.ride(),
                optimum_ride: values[0].ride(),
                nominal_over_seeds: assess(&values[1..1 + per_design])?,
                optimum_over_seeds: assess(&values[1 + per_design..])?,
            },
        )
    }
}

impl crate::ga_ask_tell::GaAskTell for HpsAskTell<'_> {
    type State = HpsAskTellState;
    type Header = HpsBatchHeader;
    type Point = HpsBatchPoint;

    fn batch(state: &HpsAskTellState) -> usize {
        state.batch
    }

    fn batch_file(
        &self,
        state: &HpsAskTellState,
        sha: &str,
    ) -> Result<(HpsBatchHeader, Vec<HpsBatchPoint>, Option<String>), DesignError> {
        let asked = self.ask(&state.run)?;
        let (header, points) = batch_file(self.desc, state.batch, sha, &asked);
        let phase = (asked != HpsAsk::Finished).then(|| header.phase.clone());
        Ok((header, points, phase))
    }

    fn tell_results(
        &self,
        state: &mut HpsAskTellState,
        tell: &[PathBuf],
        sha: &str,
    ) -> Result<Option<usize>, crate::ga_ask_tell::AskTellError> {
        let HpsAsk::Evaluate(b) = self.ask(&state.run)? else {
            return Ok(None);
        };
        let points = batch_points(state.batch, &b);
        let results = state.results(tell, sha, &points)?;
        self.tell(&mut state.run, results)?;
        state.batch += 1;
        Ok(Some(points.len()))
    }

    fn finished(&self, state: &HpsAskTellState) -> Result<bool, DesignError> {
        Ok(self.ask(&state.run)? == HpsAsk::Finished)
    }
}

/// The HPS ask/tell state file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HpsAskTellState {
    /// The command that wrote it.
    pub written_by: String,
    /// `afsv-v1`.
    pub sign_convention: String,
    /// [`HPS_STATE_FORMAT`].
    pub format: String,
    /// [`HPS_FORMAT_VERSION`].
    pub version: u32,
    /// The problem the state belongs to.
    pub problem: HpsProblemDesc,
    /// Batches told so far: the number of the next batch.
    pub batch: usize,
    /// The run.
    pub run: HpsRunState,
}

/// What a state's problem is compared by, short enough for a message: the vehicle's name,
/// the SHA-256 of its parameters' JSON and the settings.
fn identity(p: &HpsProblemDesc) -> serde_json::Value {
    let params = serde_json::to_string(&p.params).unwrap_or_default();
    serde_json::json!({
        "vehicle": p.vehicle,
        "params_sha256": afsv_records::provenance::sha256_hex(params.as_bytes()),
        "settings": p.settings,
    })
}

impl HpsAskTellState {
    /// The state `flag` `path` holds in `stored` (read under the run lock), which must
    /// belong to `problem`; a new state when there is none and `create` allows one.
    pub fn read(
        flag: &str,
        path: &Path,
        stored: Option<&str>,
        create: bool,
        problem: &HpsProblemDesc,
    ) -> Result<Self, String> {
        match stored {
            Some(text) => {
                let st: HpsAskTellState = afsv_records::stored::parse_stored(flag, path, text)?;
                if st.format != HPS_STATE_FORMAT || st.version != HPS_FORMAT_VERSION {
                    return Err(format!(
                        "{flag} {}: not an HPS ask/tell state of version {HPS_FORMAT_VERSION}",
                        path.display()
                    ));
                }
                afsv_records::stored::same_settings(
                    flag,
                    path,
                    &identity(&st.problem),
                    &identity(problem),
                )?;
                Ok(st)
            }
            None if !create => Err(format!(
                "{flag} {}: does not exist; start the run with --ask",
                path.display()
            )),
            None => Ok(Self {
                written_by: "afsv optimize hps".into(),
                sign_convention: afsv_records::SIGN_CONVENTION.into(),
                format: HPS_STATE_FORMAT.into(),
                version: HPS_FORMAT_VERSION,
                problem: problem.clone(),
                batch: 0,
                run: HpsRunState::default(),
            }),
        }
    }

    /// Reads every results file (`--tell`) and returns the outcomes in the batch's order,
    /// checking that every asked id comes exactly once, no other id comes, and every file
    /// belongs to this state's batch (`sha`: the state's SHA-256) and problem.
    pub fn results(
        &self,
        tell: &[PathBuf],
        sha: &str,
        asked: &[HpsBatchPoint],
    ) -> Result<Vec<Result<HpsValues, String>>, String> {
        let kind = BatchKind {
            what: "an HPS results file",
            format: HPS_RESULTS_FORMAT,
            version: HPS_FORMAT_VERSION,
        };
        let check = |h: &HpsResultsHeader, file: &str| {
            check_results_header(
                file,
                &kind,
                (&h.format, h.version),
                h.problem == self.problem,
                (h.batch, &h.state_sha256),
                (self.batch, sha),
            )
        };
        let ids: Vec<&str> = asked.iter().map(|p| p.id.as_str()).collect();
        collect_results(tell, self.batch, &ids, &check, &|r: &HpsPointResult, _| {
            Ok(r.outcome())
        })
    }
}
