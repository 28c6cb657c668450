//! One `afsv optimize afs` run as its options define it (section 4.3): its identity, which a
//! checkpoint or an ask/tell state is checked against ([`AfsRunSpec::settings_json`]), the
//! problem of each configuration (with and without the steering-arm constraint), the
//! configurations run in this process and resumable from a checkpoint ([`run_here`]), and
//! one `--ask` or `--tell` of the same run across processes ([`ask_or_tell`]).

use crate::afs_batch::{BatchHeader, Eq49Desc, ProblemDesc, VehicleDesc, AFS_KIND};
use crate::afs_resume::AfsCheckpoint;
use crate::afs_state::{AskTellState, Asked};
use crate::error::DesignError;
use crate::ga_ask_tell::AskTellError;
use crate::report::afs::AfsRun;
use crate::{optimise, AfsAskTell, AfsOptimisationSettings, AfsOptimum, AfsProblem};
use afsv_records::jsonl::write_jsonl;
use afsv_records::stored::{write_json, StateIdentity};
use serde_json::{json, Value};
use std::path::{Path, PathBuf};

/// An `optimize afs` run: the options that define its problems and its solver settings.
#[derive(Debug, Clone)]
pub struct AfsRunSpec {
    /// The relaxed B_eff bound of Table 4.4.
    pub relaxed: bool,
    /// Minimum steering arm at ±45 deg articulation (m) of the constrained configuration.
    pub min_arm_m: f64,
    /// Also the configuration without the steering-arm constraint.
    pub arm_comparison: bool,
    /// Pattern-search starts besides the current design.
    pub starts: usize,
    /// Seed of the starts and search hypercubes.
    pub seed: u64,
    /// Relative tolerance of the simulations.
    pub rtol: f64,
    /// `energy_consistent` or `paper_eq_3_13`.
    pub form: &'static str,
    /// The Eq 4.9 geometry, if given.
    pub eq_4_9: Option<Eq49Desc>,
    /// The described vehicle, if one was given (the built-in prototype otherwise).
    pub vehicle: Option<VehicleDesc>,
    /// The solver settings.
    pub settings: AfsOptimisationSettings,
}

impl AfsRunSpec {
    /// The configurations: their labels and minimum steering arms (m).
    pub fn configs(&self) -> Vec<(&'static str, Option<f64>)> {
        let mut configs = vec![("with the steering-arm constraint", Some(self.min_arm_m))];
        if self.arm_comparison {
            configs.push(("without the steering-arm constraint", None));
        }
        configs
    }

    /// The run's identity as JSON, stored in its checkpoint and state (the vehicle only
    /// when one was given, so a checkpoint of the built-in vehicle still resumes).
    pub fn settings_json(&self) -> Value {
        let eq_4_9 = match &self.eq_4_9 {
            Some(g) => json!(g),
            None => json!({"front_mount_dir_deg": null, "tire_point": null, "engine_point": null}),
        };
        let mut v = json!({
            "relaxed": self.relaxed, "min_arm_m": self.min_arm_m,
            "arm_comparison": self.arm_comparison, "starts": self.starts, "seed": self.seed,
            "rtol": self.rtol, "form": self.form, "eq_4_9": eq_4_9, "solver": self.settings,
        });
        if let Some(vehicle) = &self.vehicle {
            v["vehicle"] = json!(vehicle);
        }
        v
    }

    /// The problem description of every configuration.
    pub fn descs(&self) -> Vec<ProblemDesc> {
        self.configs()
            .into_iter()
            .map(|(label, min_arm)| ProblemDesc {
                kind: AFS_KIND.into(),
                label: label.into(),
                relaxed: self.relaxed,
                min_steering_arm_m: min_arm,
                rtol: self.rtol,
                form: self.form.into(),
                eq_4_9: self.eq_4_9,
                vehicle: self.vehicle.clone(),
            })
            .collect()
    }
}

/// The solver settings of the options: `starts` pattern-search starts besides the current
/// design (below [`crate::afs_optimum::MAX_STARTS`]) from `seed`, `search_points` per
/// search step, every start screened to `screen_mesh`, the best refined to `min_mesh`
/// (`min_mesh <= screen_mesh < 0.25`, the initial mesh), at most `sqp_calls` SLSQP calls.
/// Errors name the options.
pub fn solver_settings(
    starts: usize,
    seed: u64,
    search_points: usize,
    (screen_mesh, min_mesh): (f64, f64),
    sqp_calls: usize,
) -> Result<AfsOptimisationSettings, String> {
    use crate::afs_optimum::MAX_STARTS;
    if starts >= MAX_STARTS {
        return Err(format!("--starts must be below {MAX_STARTS}"));
    }
    if !(min_mesh <= screen_mesh && screen_mesh < 0.25) {
        return Err(format!(
            "--screen-mesh {screen_mesh} and --min-mesh {min_mesh}: need --min-mesh <= --screen-mesh < 0.25 (the initial mesh)"
        ));
    }
    Ok(settings(
        starts,
        seed,
        search_points,
        (screen_mesh, min_mesh),
        sqp_calls,
    ))
}

/// The solver settings of [`solver_settings`], for values a caller has checked with its own
/// names (the Python package).
pub fn settings(
    starts: usize,
    seed: u64,
    search_points: usize,
    (screen_mesh, min_mesh): (f64, f64),
    sqp_calls: usize,
) -> AfsOptimisationSettings {
    let mut settings = AfsOptimisationSettings {
        extra_starts: starts,
        seed,
        screen_min_mesh: screen_mesh,
        ..AfsOptimisationSettings::default()
    };
    settings.pattern.search_points = search_points;
    settings.pattern.min_mesh = min_mesh;
    settings.sqp.max_calls = sqp_calls;
    settings
}

/// The vehicle description `path` names (`crate::described`) as a problem stores it: its
/// name, loaded yaw-plane data and steering; `None` without one.
pub fn vehicle_desc(path: Option<&Path>) -> Result<Option<VehicleDesc>, String> {
    let Some(path) = path else {
        return Ok(None);
    };
    let v = crate::described::articulated(Some(path))?;
    Ok(Some(VehicleDesc {
        name: v.name.clone(),
        yaw_plane: v.yaw_plane(vehicle_3d::Load::Loaded).clone(),
        steering: v.steering().clone(),
    }))
}

/// Every configuration of `spec` (its `problems`) optimised in this process, resumed from
/// `ck`'s stored runs; with a `checkpoint` file, `ck` is written to it after every
/// iteration. `done` hears of each finished run (its label, optimum and seconds).
pub fn run_here(
    spec: &AfsRunSpec,
    problems: &[AfsProblem],
    (ck, checkpoint): (&mut AfsCheckpoint, Option<&Path>),
    progress: &dyn optimize::Progress,
    done: &dyn Fn(&str, &AfsOptimum, f64),
) -> Result<Vec<AfsRun>, DesignError> {
    let mut outcomes = Vec::new();
    for (i, ((label, arm), problem)) in spec.configs().into_iter().zip(problems).enumerate() {
        let t = std::time::Instant::now();
        let resume = ck.runs.get(i).cloned().unwrap_or_default();
        let optimum = optimise(problem, &spec.settings, resume, progress, &mut |st| {
            let Some(path) = checkpoint else {
                return Ok(());
            };
            ck.record(i, st);
            write_json(path, &*ck)
        })?;
        done(label, &optimum, t.elapsed().as_secs_f64());
        outcomes.push(AfsRun {
            label: label.to_string(),
            min_arm_m: arm,
            optimum,
            seconds: t.elapsed().as_secs_f64(),
        });
    }
    Ok(outcomes)
}

/// What one `--ask` or `--tell` of an ask/tell run did.
pub enum AfsStep {
    /// `--ask` wrote batch `batch` ([`Asked`]) to its file.
    Asked {
        /// The batch's number.
        batch: usize,
        /// Its points and phases.
        asked: Asked,
    },
    /// `--ask` found the run finished after `batches` (it wrote a batch of no point): the
    /// finished runs.
    Finished {
        /// Batches of the run.
        batches: usize,
        /// The finished configurations.
        runs: Vec<AfsRun>,
    },
    /// `--tell` advanced the state by batch `batch` (`points` points).
    Told {
        /// The batch told.
        batch: usize,
        /// Its points.
        points: usize,
        /// Whether the run has finished (the next `--ask` prints the report).
        finished: bool,
    },
}

/// One `--ask` (to the batch file `ask`) or `--tell` (of the results files `tell`) of the
/// run `spec` (its `problems`) against the state file `path`, whose text `stored` was read
/// under the run lock (`None`: no state yet). `finished` hears of a finished run's batch
/// count before its configurations are finished.
pub fn ask_or_tell(
    spec: &AfsRunSpec,
    problems: &[AfsProblem],
    (path, stored): (&Path, Option<String>),
    (ask, tell): (Option<&Path>, &[PathBuf]),
    finished: &dyn Fn(usize),
) -> Result<AfsStep, AskTellError> {
    let descs = spec.descs();
    let drivers: Vec<AfsAskTell> = problems
        .iter()
        .map(|p| AfsAskTell::new(p, spec.settings))
        .collect::<Result<_, _>>()?;
    let (settings, settings_json) = (&spec.settings, spec.settings_json());
    let read_state = |stored: Option<&str>| {
        AskTellState::read(
            "--state",
            path,
            stored,
            ask.is_some(),
            settings,
            &settings_json,
            problems,
        )
    };
    let mut state = read_state(stored.as_deref())?;
    let id = StateIdentity::of(stored, &state)?;
    if let Some(batch_path) = ask {
        let asked = state.asked(&drivers, &descs)?;
        let points = asked.as_ref().map_or(&[][..], |a| &a.points[..]);
        let header =
            BatchHeader::asked(state.batch, &id.sha, asked.is_none(), points.len(), &descs);
        write_jsonl(batch_path, &header, points)?;
        id.write_if_new(path)?;
        return Ok(match asked {
            Some(asked) => AfsStep::Asked {
                batch: state.batch,
                asked,
            },
            None => {
                finished(state.batch);
                AfsStep::Finished {
                    batches: state.batch,
                    runs: state.finish(&drivers, &descs)?,
                }
            }
        });
    }
    let asked = state.asked(&drivers, &descs)?.ok_or_else(|| {
        format!(
            "--state {}: the run has finished; --ask prints its report",
            path.display()
        )
    })?;
    let evals = state.results(tell, &id.sha, &asked, &descs, problems)?;
    state.tell(&drivers, &asked, evals)?;
    write_json(path, &state)?;
    Ok(AfsStep::Told {
        batch: state.batch - 1,
        points: asked.points.len(),
        finished: state.asked(&drivers, &descs)?.is_none(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spec(arm_comparison: bool) -> AfsRunSpec {
        AfsRunSpec {
            relaxed: false,
            min_arm_m: 0.25,
            arm_comparison,
            starts: 1,
            seed: 1,
            rtol: 1e-8,
            form: "energy_consistent",
            eq_4_9: None,
            vehicle: None,
            settings: AfsOptimisationSettings::default(),
        }
    }

    #[test]
    fn solver_settings_keep_the_defaults_and_refuse_bad_meshes() {
        let d = AfsOptimisationSettings::default();
        let s = solver_settings(4, 1, 75, (1.0 / 32.0, 1.0 / 512.0), 40).unwrap();
        assert_eq!(json!(s), json!(d));
        let s = solver_settings(1, 7, 4, (0.1, 0.1), 2).unwrap();
        assert_eq!((s.extra_starts, s.seed, s.sqp.max_calls), (1, 7, 2));
        assert_eq!((s.pattern.search_points, s.pattern.min_mesh), (4, 0.1));
        assert!(solver_settings(1000, 1, 4, (0.1, 0.01), 2)
            .unwrap_err()
            .contains("--starts must be below 1000"));
        for meshes in [(0.25, 0.01), (0.01, 0.1)] {
            let e = solver_settings(1, 1, 4, meshes, 2).unwrap_err();
            assert!(e.contains("need --min-mesh <= --screen-mesh < 0.25"), "{e}");
        }
    }

    #[test]
    fn the_identity_names_every_configuration_and_no_vehicle_by_default() {
        let s = spec(true);
        assert_eq!(s.configs().len(), 2);
        assert_eq!(spec(false).descs().len(), 1);
        let d = s.descs();
        assert_eq!(d[0].min_steering_arm_m, Some(0.25));
        assert_eq!(d[1].min_steering_arm_m, None);
        let v = s.settings_json();
        assert!(v.get("vehicle").is_none());
        assert!(v["eq_4_9"]["tire_point"].is_null());
        assert_eq!(v["form"], "energy_consistent");
        assert_eq!(vehicle_desc(None).unwrap(), None);
        let proto = vehicle_desc(Some(Path::new("prototype"))).unwrap().unwrap();
        assert_eq!(
            proto.name,
            crate::described::articulated(None).unwrap().name
        );
    }
}
