//! The files of an HPS batch (the batch a shard reads, the results it writes) and the
//! evaluation of one shard: each point's vehicle run ([`HpsTask`]) in parallel, the search
//! seed's enveloping cache built once.

use super::{finite, HpsAsk, HpsBatch, HpsProblemDesc, HpsTask, HpsValues};
use super::{HPS_BATCH_FORMAT, HPS_FORMAT_VERSION};
use crate::afs_batch::{in_shard, point_id};
use crate::batch_files::{read_batch_file, BatchHeaderFields, BatchKind, PointId};
use crate::error::DesignError;
use crate::hps_optimum::{search_ride, search_spec, with_design};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::path::Path;
use std::sync::Arc;
use vehicle_3d::scenarios::{ride, ride_tracks, roll, yaw, RollSpec, YawSpec};
use vehicle_3d::{FrontAxle, TireTracks};

/// First line of an HPS batch file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HpsBatchHeader {
    /// [`HPS_BATCH_FORMAT`].
    pub format: String,
    /// [`HPS_FORMAT_VERSION`].
    pub version: u32,
    /// `afsv optimize hps --ask`.
    pub written_by: String,
    /// `afsv-v1`.
    pub sign_convention: String,
    /// Number of the batch (batches told before it).
    pub batch: usize,
    /// SHA-256 (hex) of the state file's content when it asked this batch.
    pub state_sha256: String,
    /// Whether the run has finished (then the batch holds no point).
    pub finished: bool,
    /// The phase (`initial`, `generation N`, `reevaluation`; empty when finished).
    pub phase: String,
    /// Number of point lines that follow.
    pub points: usize,
    /// The problem, whole.
    pub problem: HpsProblemDesc,
}

/// One run of an HPS batch.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HpsBatchPoint {
    /// Identifier, `b<batch>-<index>`.
    pub id: String,
    /// The run: `search`, `ride`, `roll` or `yaw`.
    pub task: HpsTask,
    /// Its terrain seed.
    pub seed: u64,
    /// The design [A_hc, A_v, A_b] (m²); absent: the vehicle's own struts.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub x: Option<[f64; 3]>,
}

/// First line of an HPS results file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HpsResultsHeader {
    /// [`HPS_RESULTS_FORMAT`](super::HPS_RESULTS_FORMAT).
    pub format: String,
    /// [`HPS_FORMAT_VERSION`].
    pub version: u32,
    /// `afsv batch evaluate`.
    pub written_by: String,
    /// `afsv-v1`.
    pub sign_convention: String,
    /// The batch's number.
    pub batch: usize,
    /// The batch's state SHA-256, carried over.
    pub state_sha256: String,
    /// The shard, "I/N".
    pub shard: String,
    /// Number of result lines that follow.
    pub points: usize,
    /// The batch's problem.
    pub problem: HpsProblemDesc,
}

impl HpsResultsHeader {
    /// The header of the results of the shard `shard` (I, N) of the batch `header`, with
    /// `points` result lines, written by `afsv batch evaluate`.
    pub fn of_shard(header: &HpsBatchHeader, shard: (usize, usize), points: usize) -> Self {
        Self {
            format: super::HPS_RESULTS_FORMAT.into(),
            version: HPS_FORMAT_VERSION,
            written_by: "afsv batch evaluate".into(),
            sign_convention: afsv_records::SIGN_CONVENTION.into(),
            batch: header.batch,
            state_sha256: header.state_sha256.clone(),
            shard: format!("{}/{}", shard.0, shard.1),
            points,
            problem: header.problem.clone(),
        }
    }
}

/// One run's result.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HpsPointResult {
    /// The point's id.
    pub id: String,
    /// `evaluated` or `failed`.
    pub status: String,
    /// The measures (none when failed).
    pub values: HpsValues,
    /// Why the run failed.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub reason: Option<String>,
}

impl HpsPointResult {
    /// The values, or why the run failed.
    pub fn outcome(&self) -> Result<HpsValues, String> {
        match self.status.as_str() {
            "evaluated" => Ok(self.values),
            _ => Err(self
                .reason
                .clone()
                .unwrap_or_else(|| "the run failed".into())),
        }
    }
}

impl BatchHeaderFields for HpsBatchHeader {
    fn format(&self) -> &str {
        &self.format
    }
    fn version(&self) -> u32 {
        self.version
    }
    fn state_sha256(&self) -> &str {
        &self.state_sha256
    }
    fn batch(&self) -> usize {
        self.batch
    }
    fn points(&self) -> usize {
        self.points
    }
}

impl PointId for HpsBatchPoint {
    fn id(&self) -> &str {
        &self.id
    }
}

impl PointId for HpsPointResult {
    fn id(&self) -> &str {
        &self.id
    }
}

/// The points of `batch` number `number` in file form.
pub fn batch_points(number: usize, batch: &HpsBatch) -> Vec<HpsBatchPoint> {
    batch
        .points
        .iter()
        .enumerate()
        .map(|(i, p)| HpsBatchPoint {
            id: point_id(number, i),
            task: p.task,
            seed: p.seed,
            x: p.x,
        })
        .collect()
}

/// What an `--ask` of batch `number` writes for `asked`: the header, identified by the
/// asking state's SHA-256 `state_sha256`, and the points (none once the run has finished,
/// with the header's `finished` set).
pub fn batch_file(
    desc: &HpsProblemDesc,
    number: usize,
    state_sha256: &str,
    asked: &HpsAsk,
) -> (HpsBatchHeader, Vec<HpsBatchPoint>) {
    let (phase, points) = match asked {
        HpsAsk::Evaluate(b) => (b.phase.name(), batch_points(number, b)),
        HpsAsk::Finished => (String::new(), Vec::new()),
    };
    let header = HpsBatchHeader {
        format: HPS_BATCH_FORMAT.into(),
        version: HPS_FORMAT_VERSION,
        written_by: "afsv optimize hps --ask".into(),
        sign_convention: afsv_records::SIGN_CONVENTION.into(),
        batch: number,
        state_sha256: state_sha256.into(),
        finished: *asked == HpsAsk::Finished,
        phase,
        points: points.len(),
        problem: desc.clone(),
    };
    (header, points)
}

/// Reads and checks an HPS batch file: format, version, SHA-256, point count and ids.
pub fn read_hps_batch(
    label: &str,
    path: &Path,
) -> Result<(HpsBatchHeader, Vec<HpsBatchPoint>), String> {
    let kind = BatchKind {
        what: "HPS batch file",
        format: HPS_BATCH_FORMAT,
        version: HPS_FORMAT_VERSION,
    };
    let (h, lines) = read_batch_file(label, path, &kind, &|_: &HpsBatchHeader| Ok(()))?;
    Ok((h, lines.into_iter().map(|(_, p)| p).collect()))
}

/// The values of one run of `p` for the problem `desc` (`tracks`: the search seed's
/// enveloping cache, shared by the search rides).
fn run_point(
    desc: &HpsProblemDesc,
    tracks: &dyn Fn() -> Result<Arc<TireTracks>, String>,
    p: &HpsBatchPoint,
) -> Result<HpsValues, String> {
    let err = |e: DesignError| e.to_string();
    let sim = |e: vehicle_3d::VehicleError| e.to_string();
    let base = &desc.params;
    let vehicle = match &p.x {
        Some(x) => with_design(base, x).map_err(err)?,
        None => base.clone(),
    };
    Ok(match p.task {
        HpsTask::Search => {
            let x = p.x.ok_or("a search run needs a design x")?;
            let r = search_ride(base, tracks()?, &x).map_err(err)?;
            HpsValues {
                a_wz_m_s2: finite(r.a_wz_m_s2),
                d_s_m: finite(r.d_s_m),
                ..HpsValues::default()
            }
        }
        HpsTask::Ride => HpsValues {
            a_wz_m_s2: finite(
                ride(&vehicle, &search_spec(), p.seed)
                    .map_err(sim)?
                    .1
                    .a_wz_m_s2,
            ),
            ..HpsValues::default()
        },
        HpsTask::Roll => {
            let spec = RollSpec::d2(FrontAxle::Suspended);
            HpsValues {
                sp_drt_m_s2: finite(roll(&vehicle, &spec, p.seed).map_err(sim)?.1.sp_drt_m_s2),
                ..HpsValues::default()
            }
        }
        HpsTask::Yaw => {
            let spec = YawSpec::d3(FrontAxle::Suspended);
            HpsValues {
                omega_z_hz: finite(yaw(&vehicle, &spec, 0).map_err(sim)?.1.omega_z_hz),
                ..HpsValues::default()
            }
        }
    })
}

/// Runs the points of shard `shard` of an HPS batch in parallel, in the batch's order;
/// `step` is called after each point. The search seed's enveloping cache is built once, and
/// only when the shard has a search ride.
pub fn evaluate_hps_shard(
    header: &HpsBatchHeader,
    points: &[HpsBatchPoint],
    shard: (usize, usize),
    step: &(dyn Fn() + Sync),
) -> Vec<HpsPointResult> {
    let desc = &header.problem;
    let mine: Vec<&HpsBatchPoint> = points
        .iter()
        .enumerate()
        .filter(|(i, _)| in_shard(*i, shard))
        .map(|(_, p)| p)
        .collect();
    let cache: std::sync::OnceLock<Result<Arc<TireTracks>, String>> = std::sync::OnceLock::new();
    let tracks = || {
        cache
            .get_or_init(|| {
                ride_tracks(&desc.params, &search_spec(), desc.settings.terrain_seed)
                    .map_err(|e| e.to_string())
            })
            .clone()
    };
    mine.par_iter()
        .map(|p| {
            let out = run_point(desc, &tracks, p);
            step();
            match out {
                Ok(values) => HpsPointResult {
                    id: p.id.clone(),
                    status: "evaluated".into(),
                    values,
                    reason: None,
                },
                Err(e) => HpsPointResult {
                    id: p.id.clone(),
                    status: "failed".into(),
                    values: HpsValues::default(),
                    reason: Some(e),
                },
            }
        })
        .collect()
}
