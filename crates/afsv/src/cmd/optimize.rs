//! `afsv optimize afs`: the chapter-4 design optimisation of the frame-steering system
//! (section 4.3; `afsv_design::afs_optimum`). Text on a terminal, JSON with `--json` or
//! when piped; progress on stderr; resumable through `--checkpoint`. With `--state` the
//! same run goes ask/tell: `--ask` writes the next batch of design points (JSON Lines,
//! evaluated by `afsv batch evaluate`, possibly in shards on a cluster), `--tell` reads the
//! results and advances the state file; once finished `--ask` prints the report
//! (`afsv_design::afs_ask_tell`, formats in `afsv_design::afs_batch`). `afsv optimize hps`
//! and `afsv optimize layout` (both ask/tell too) are in their own modules.

use super::CmdResult;
use afsv::output::{NotEarned, OutputGuard, OutputKind};
use afsv_design::afs_batch::{chapter4_objective, Eq49Desc, ProblemDesc, MAX_SHARDS};
use afsv_design::afs_resume::AfsCheckpoint;
use afsv_design::afs_run::{self, run_here, solver_settings, vehicle_desc, AfsRunSpec, AfsStep};
use afsv_design::ga_ask_tell::{self, GaAskTell, GaStep};
use afsv_design::report::afs::asked_text;
use afsv_design::{AfsOptimum, AfsProblem, Objective};
use afsv_records::lock::take_and_read;
use serde_json::json;
use std::path::PathBuf;

mod hps;
mod layout;
mod report;

use afsv_design::report::afs::{earned, to_json, to_text, AfsRun as RunOutcome};
use report::{write_plots, Bar};

/// `afsv optimize` subcommands.
#[derive(clap::Subcommand)]
// One value per process, parsed once: the size difference between the variants is harmless.
#[allow(clippy::large_enum_variant)]
pub enum Command {
    /// Chapter 4: optimise the frame-steering design [A_0, l_1, l_2, a_v, B_eff] (Eq 4.8 with the AHP weights of Eq 4.17, Eq 4.10 and a minimum full-lock steering arm as constraints) by multi-start pattern search and SQP.
    Afs(AfsArgs),
    /// Chapter 6: optimise the front-axle HPS [A_hc, A_v, A_b] (Eq 6.19 with a_wz <= 0.85 m/s², Eq 6.20) on the 3-D vehicle by a genetic algorithm, then re-evaluate over terrain seeds; in-process or ask/tell (--state, --ask, --tell) for a cluster.
    Hps(hps::HpsArgs),
    /// Beyond the dissertation: optimise any suspension layout of `afsv study layouts` over parameters named in the registries (e.g. `front.a_b=5e-6..3e-5`), minimising one of its measures subject to constraints on any (e.g. 'awz_seat <= 0.5', 'sp_drt >= 0.96 * nominal'), by a genetic algorithm; in-process or ask/tell (--state, --ask, --tell) for a cluster.
    Layout(layout::LayoutArgs),
}

/// The ask/tell options of the optimisations that run across processes (`afs`, `hps`,
/// `layout`):
/// `--ask` writes the next batch for `afsv batch evaluate`, `--tell` reads its results.
#[derive(clap::Args)]
pub struct AskTellArgs {
    /// Ask/tell state file (JSON): created by the first --ask, advanced by each --tell; give the same options every time.
    #[arg(long)]
    pub state: Option<PathBuf>,
    /// With --state: write the next batch of points (JSON Lines) for `afsv batch evaluate`; once the run has finished, write a batch of no point (header "finished": true) and print the report.
    #[arg(long, requires = "state", conflicts_with = "tell")]
    pub ask: Option<PathBuf>,
    /// With --state: the results files of the asked batch (every shard's), to advance the state.
    #[arg(long, requires = "state", num_args = 1..)]
    pub tell: Vec<PathBuf>,
}

impl AskTellArgs {
    /// Refuse `--state` without `--ask` or `--tell`, and more than [`MAX_SHARDS`] results
    /// files.
    fn check(&self) -> Result<(), String> {
        if self.state.is_some() && self.ask.is_none() && self.tell.is_empty() {
            return Err("--state: give --ask FILE or --tell RESULTS...".into());
        }
        if self.tell.len() > MAX_SHARDS {
            return Err(format!("--tell: more than {MAX_SHARDS} results files"));
        }
        Ok(())
    }

    /// Declare the results files as inputs, each given once.
    fn declare_inputs(&self, guard: &mut OutputGuard) -> CmdResult {
        let mut told = Vec::with_capacity(self.tell.len());
        for f in &self.tell {
            let c = afsv::output::canonical_path(f)?;
            if told.contains(&c) {
                return Err(format!("--tell {}: given twice", f.display()).into());
            }
            told.push(c);
            guard.input("--tell", f)?;
        }
        Ok(())
    }

    /// Declare the state file and the asked batch as outputs.
    fn declare_outputs(&self, guard: &mut OutputGuard) -> CmdResult {
        guard.output_if("--state", self.state.as_deref(), OutputKind::Sidecar)?;
        guard.output_if("--ask", self.ask.as_deref(), OutputKind::JsonLines)?;
        Ok(())
    }
}

/// Progress of a GA run (`afsv optimize hps|layout`): one step per generation, with the
/// best objective as the run shows it.
struct Generations(afsv::progress::Progress, fn(f64) -> String);

impl Generations {
    fn new(command: &str, generations: usize, best: fn(f64) -> String) -> Self {
        let what = format!("afsv optimize {command}");
        Self(
            afsv::progress::Progress::new(&what, "generations", Some(generations)),
            best,
        )
    }
}

impl optimize::Progress for Generations {
    fn report(&self, _phase: &str, done: usize, _total: usize, best: f64) {
        self.0
            .step(&format!("generation {done}, best {}", (self.1)(best)));
    }
}

/// On stderr (unless quiet): `command`'s run has finished after `batches`, the report
/// follows.
fn finished_notice(command: &str, batches: usize, batch_path: &std::path::Path) {
    if !afsv::progress::is_quiet() {
        eprintln!(
            "afsv optimize {command}: the run has finished after {batches} batches; {} holds no point; the report follows",
            batch_path.display()
        );
    }
}

/// One `--ask` or `--tell` of a GA run (`command` `hps` or `layout`, its points counted
/// in `unit`) through `afsv_design::ga_ask_tell`, its status printed; `true` when the
/// run has finished and the caller prints the report.
fn ask_or_tell<D: GaAskTell>(
    (driver, state, stored, path): (&D, &mut D::State, Option<String>, &std::path::Path),
    args: &AskTellArgs,
    json: bool,
    command: &str,
    unit: &str,
) -> Result<bool, Box<dyn std::error::Error>> {
    let ask = args.ask.as_deref();
    match ga_ask_tell::ask_or_tell(driver, state, stored, path, ask, &args.tell)? {
        GaStep::Finished { batches } => {
            finished_notice(command, batches, ask.unwrap_or(path));
            return Ok(true);
        }
        GaStep::Asked {
            batch,
            phase,
            points,
        } => print_asked(json, batch, &phase, points, unit, ask.unwrap_or(path))?,
        GaStep::Told {
            batch,
            points,
            finished,
        } => print_told(json, batch, points, unit, finished)?,
    }
    Ok(false)
}

/// The status of an `--ask` that wrote batch `batch` (`points` of `unit`, `phase`) to
/// `batch_path`.
fn print_asked(
    json: bool,
    batch: usize,
    phase: &str,
    points: usize,
    unit: &str,
    batch_path: &std::path::Path,
) -> CmdResult {
    let status = json!({"batch": batch, "finished": false, "phase": phase,
        "points": points, "batch_file": batch_path.display().to_string()});
    afsv::output::print_json_or_text(json, &status, || {
        format!(
            "batch {batch} ({phase}): {points} {unit} written to {}\n",
            batch_path.display()
        )
    })?;
    Ok(())
}

/// The status of a `--tell` of batch `told` (`points` of `unit`).
fn print_told(json: bool, told: usize, points: usize, unit: &str, finished: bool) -> CmdResult {
    let status =
        json!({"told": told, "points": points, "next_batch": told + 1, "finished": finished});
    afsv::output::print_json_or_text(json, &status, || {
        format!(
            "batch {told} told ({points} {unit}); {}\n",
            if finished {
                "the run has finished: --ask prints the report"
            } else {
                "next: --ask"
            }
        )
    })?;
    Ok(())
}

/// Options of `afsv optimize afs`.
#[derive(clap::Args)]
pub struct AfsArgs {
    /// Optimise this vehicle description's steering on its loaded yaw-plane data: a
    /// description file (TOML, docs/vehicles.md) or a built-in name (prototype,
    /// chapter2-truck). It is stored whole in checkpoints, states and batches, so a resume or
    /// a shard needs no file.
    #[arg(long)]
    pub vehicle: Option<PathBuf>,
    /// Relax the upper B_eff bound to 2.08 GPa (Table 4.4) instead of 1.7 GPa (Table 4.3).
    #[arg(long)]
    pub relaxed: bool,
    /// Minimum steering arm at +-45 deg articulation (m); the printed compact optima have 0.25-0.27 m.
    #[arg(long, default_value_t = afsv_design::afs_problem::DEFAULT_MIN_STEERING_ARM_M, value_parser = super::args::positive_f64)]
    pub min_arm_m: f64,
    /// Leave out the second run without the steering-arm constraint.
    #[arg(long)]
    pub no_arm_comparison: bool,
    /// Pattern-search starts besides the current design (maximin Latin hypercube).
    #[arg(long, default_value_t = 4)]
    pub starts: usize,
    /// Seed of the starts and search hypercubes.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Points of each start's Latin-hypercube search step (0: none).
    #[arg(long, default_value_t = 75, value_parser = clap::value_parser!(u64).range(0..=100_000))]
    pub search_points: u64,
    /// Mesh (unit-cube coordinates) at which each start's screening search stops; in [--min-mesh, 0.25).
    #[arg(long, default_value_t = 1.0 / 32.0, value_parser = super::args::positive_f64)]
    pub screen_mesh: f64,
    /// Final mesh of the best start's pattern search; in (0, --screen-mesh].
    #[arg(long, default_value_t = 1.0 / 512.0, value_parser = super::args::positive_f64)]
    pub min_mesh: f64,
    /// Largest number of SLSQP calls of the SQP refinement.
    #[arg(long, default_value_t = 40, value_parser = clap::value_parser!(u64).range(1..=10_000))]
    pub sqp_calls: u64,
    /// Relative tolerance of the simulations (the noise of F grows above 1e-8).
    #[arg(long, default_value_t = 1e-8, value_parser = super::args::positive_f64)]
    pub rtol: f64,
    /// Form of the yaw equations.
    #[arg(long, value_enum, default_value_t = FormArg::EnergyConsistent)]
    pub form: FormArg,
    /// Eq 4.9: direction of the left front mount from the joint (deg from the x axis); give with --tire-point and --engine-point.
    #[arg(long, allow_hyphen_values = true, value_parser = super::args::finite_f64, requires_all = ["tire_point", "engine_point"])]
    pub front_mount_dir_deg: Option<f64>,
    /// Eq 4.9: inner extremity of the left front tire, "x,y" in m (front-unit frame, origin at the joint).
    #[arg(long, allow_hyphen_values = true, value_parser = afsv_design::value_lists::point, requires_all = ["front_mount_dir_deg", "engine_point"])]
    pub tire_point: Option<[f64; 2]>,
    /// Eq 4.9: extremity of the engine supporting structure, "x,y" in m.
    #[arg(long, allow_hyphen_values = true, value_parser = afsv_design::value_lists::point, requires_all = ["front_mount_dir_deg", "tire_point"])]
    pub engine_point: Option<[f64; 2]>,
    /// Write the step responses of the optimum and the current design (SVG, Fig 4.9).
    #[arg(long)]
    pub plot_step: Option<PathBuf>,
    /// Write the pulse responses of the optimum and the current design (SVG, Fig 4.9).
    #[arg(long)]
    pub plot_pulse: Option<PathBuf>,
    /// Checkpoint file: written after every iteration; an existing one is resumed.
    #[arg(long, conflicts_with = "state")]
    pub checkpoint: Option<PathBuf>,
    #[command(flatten)]
    pub ask_tell: AskTellArgs,
    /// Replace existing output files afsv did not write.
    #[arg(long)]
    pub force: bool,
    #[command(flatten)]
    pub output: super::args::JsonOutput,
}

/// Form of the yaw equations.
#[derive(Clone, Copy, clap::ValueEnum)]
pub enum FormArg {
    /// Newton-Euler about the joint, conserves energy (default).
    EnergyConsistent,
    /// Eq 3.13 as printed.
    PaperEq313,
}

/// Run `afsv optimize`.
pub fn run(cmd: Command) -> CmdResult {
    match cmd {
        Command::Afs(a) => run_afs(&a),
        Command::Hps(a) => hps::run(&a),
        Command::Layout(a) => layout::run(&a),
    }
}

/// The run `a` defines, its solver settings checked.
fn run_spec(a: &AfsArgs) -> Result<AfsRunSpec, Box<dyn std::error::Error>> {
    let search_points = a.search_points as usize;
    let meshes = (a.screen_mesh, a.min_mesh);
    let sqp_calls = a.sqp_calls as usize;
    let settings = solver_settings(a.starts, a.seed, search_points, meshes, sqp_calls)?;
    let eq_4_9 = match (a.front_mount_dir_deg, a.tire_point, a.engine_point) {
        (Some(dir), Some(t), Some(e)) => Some(Eq49Desc {
            front_mount_dir_deg: dir,
            tire_point: t,
            engine_point: e,
        }),
        _ => None,
    };
    Ok(AfsRunSpec {
        relaxed: a.relaxed,
        min_arm_m: a.min_arm_m,
        arm_comparison: !a.no_arm_comparison,
        starts: a.starts,
        seed: a.seed,
        rtol: a.rtol,
        form: match a.form {
            FormArg::EnergyConsistent => "energy_consistent",
            FormArg::PaperEq313 => "paper_eq_3_13",
        },
        eq_4_9,
        vehicle: None,
        settings,
    })
}

fn run_afs(a: &AfsArgs) -> CmdResult {
    let mut spec = run_spec(a)?;
    a.ask_tell.check()?;
    // One run at a time on a checkpoint or state file; the lock is held until the command
    // returns, and taken before the file is read.
    let (_lock, stored) = match &a.checkpoint {
        Some(p) => take_and_read("--checkpoint", Some(p))?,
        None => take_and_read("--state", a.ask_tell.state.as_deref())?,
    };
    let mut guard = OutputGuard::new(a.force);
    a.ask_tell.declare_inputs(&mut guard)?;
    guard.output_if("--plot-step", a.plot_step.as_deref(), OutputKind::Svg)?;
    guard.output_if("--plot-pulse", a.plot_pulse.as_deref(), OutputKind::Svg)?;
    guard.output_if("--checkpoint", a.checkpoint.as_deref(), OutputKind::Sidecar)?;
    a.ask_tell.declare_outputs(&mut guard)?;
    let objective = chapter4_objective()?;
    spec.vehicle = vehicle_desc(a.vehicle.as_deref())?;
    let descs = spec.descs();
    if let Some(state) = &a.ask_tell.state {
        let problems: Vec<AfsProblem> = descs
            .iter()
            .map(ProblemDesc::problem)
            .collect::<Result<_, _>>()?;
        let (ask, tell) = (a.ask_tell.ask.as_deref(), &a.ask_tell.tell[..]);
        let notice = |batches| finished_notice("afs", batches, ask.unwrap_or(state));
        let step = afs_run::ask_or_tell(&spec, &problems, (state, stored), (ask, tell), &notice)?;
        return match step {
            AfsStep::Finished { runs, .. } => report(a, &objective, &problems, &runs),
            AfsStep::Asked { batch, asked } => {
                let path = ask.unwrap_or(state);
                let status = json!({
                    "batch": batch, "finished": false, "points": asked.points.len(),
                    "batch_file": path.display().to_string(), "phases": asked.phases,
                });
                let text = || asked_text(batch, &asked, path) + "\n";
                Ok(afsv::output::print_json_or_text(
                    a.output.json,
                    &status,
                    text,
                )?)
            }
            AfsStep::Told {
                batch,
                points,
                finished,
            } => print_told(a.output.json, batch, points, "points", finished),
        };
    }
    let mut ck = match (&a.checkpoint, stored) {
        (Some(p), Some(text)) => {
            let configs = spec.configs().len();
            AfsCheckpoint::read("--checkpoint", p, &text, &spec.settings_json(), configs)?
        }
        _ => AfsCheckpoint::new("afsv optimize afs", spec.settings_json()),
    };
    let problems: Vec<AfsProblem> = descs
        .iter()
        .map(|d| AfsProblem::new(d.spec()?, objective).map_err(|e| e.to_string()))
        .collect::<Result<_, String>>()?;
    if let Some(p) = &a.checkpoint {
        ck.check_runs("--checkpoint", p, &problems, &spec.settings)?;
    }
    let progress = Bar::new()?;
    let checkpoint = (&mut ck, a.checkpoint.as_deref());
    let done = |label: &str, o: &AfsOptimum, seconds: f64| progress.done(label, o, seconds);
    let outcomes = run_here(&spec, &problems, checkpoint, &progress, &done)?;
    progress.finish();
    report(a, &objective, &problems, &outcomes)
}

/// Plots, then the report on stdout (JSON or text), of finished runs. A run whose best
/// point violates a constraint found no feasible design: the report is printed, and the
/// command is [`NotEarned`] (exit 3), naming the violated constraints and their values.
fn report(
    a: &AfsArgs,
    objective: &Objective,
    problems: &[AfsProblem],
    outcomes: &[RunOutcome],
) -> CmdResult {
    write_plots(a, &problems[0], &outcomes[0].optimum.ps_sqp.design)?;
    let current = problems[0].evaluate_design(&problems[0].current_design())?;
    let v = to_json(a.relaxed, a.rtol, objective, &current, outcomes);
    afsv::output::print_json_or_text(a.output.json, &v, || to_text(a.relaxed, &current, outcomes))?;
    earned(outcomes).map_err(|why| {
        NotEarned(format!(
            "optimize afs: no feasible design found ({why}); the least infeasible point is printed, not an optimum (check the Eq 4.9 points and --min-arm-m)"
        ))
        .into()
    })
}
