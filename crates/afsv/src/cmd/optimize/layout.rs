//! `afsv optimize layout`: a GA over registry-named parameters of one suspension layout of
//! `afsv study layouts`, with constraints on its measures (`afsv_design::layout_optimum`,
//! docs/layouts.md "Optimising a layout"). In this process, or ask/tell with `--state`:
//! `--ask` writes the next batch (JSON Lines) for `afsv batch evaluate`, `--tell` reads the
//! shards' results; once finished `--ask` prints the report, the in-process one byte for
//! byte (`afsv_design::layout_ask_tell`).

use super::AskTellArgs;
use crate::cmd::CmdResult;
use afsv::output::{NotEarned, OutputGuard};
use afsv_design::layout_problem::{self, LayoutOptions};
use afsv_design::report::layout_optimum::text;
use afsv_design::{
    optimise_layout, LayoutAskTell, LayoutAskTellState, LayoutGaSettings, LayoutOptimum,
    LayoutProblem, LayoutProblemDesc,
};
use afsv_records::lock::take_and_read;
use std::path::{Path, PathBuf};
use vehicle_3d::Load;

/// Options of `afsv optimize layout`.
#[derive(clap::Args)]
pub struct LayoutArgs {
    #[arg(long, help = crate::cmd::described::HELP)]
    pub vehicle: Option<PathBuf>,
    /// The layout (as `afsv study layouts --layouts` names it): rigid, front-hps,
    /// front-rear-hps, front-roll, front-rear-roll, front-rear-pitch.
    #[arg(long, default_value = "front-rear-hps")]
    pub layout: String,
    /// The cab and seat: `generic`, `off`, or `described` (the description's); default:
    /// the description's when it has them, else generic.
    #[arg(long)]
    pub seat: Option<String>,
    /// A design variable NAME=LO..HI (repeat): `front.NAME` or `rear.NAME` of the strut
    /// registry (`afsv params list strut`), `seat.NAME` or `cab.NAME` of the cab and seat
    /// (`afsv params list seat|cab`; not with `--seat off`), or a 3-D vehicle name (`afsv
    /// params list vehicle-3d`), e.g. `front.a_b=5e-6..3e-5`, `seat.damping_n_s_per_m=200..2000`.
    #[arg(long = "vary", required = true)]
    pub vary: Vec<String>,
    /// The measure to minimise: awz_frame, awz_seat, seat, strut_travel,
    /// rear_strut_travel, sp_drt, omega_z, d4_speed (the frame's 8 h caution-zone crossing
    /// speed over --d4-speeds: one ride per D4 speed and seed per design), d4_speed_seat
    /// (the same on the seat pan's a_wz; needs the seat).
    #[arg(long)]
    pub objective: String,
    /// Maximise the objective instead.
    #[arg(long)]
    pub maximise: bool,
    /// A constraint (repeat): `MEASURE <= BOUND` or `MEASURE >= BOUND`, BOUND a number or
    /// `F * nominal` (the un-varied layout's value), e.g. 'sp_drt >= 0.96 * nominal'.
    #[arg(long = "constraint")]
    pub constraints: Vec<String>,
    /// Speed of the rides (km/h), 5 to 100.
    #[arg(long, default_value_t = 20.0)]
    pub speed_kmh: f64,
    /// Measured window of the rides (m), 10 to 1000 (D1: 100).
    #[arg(long, default_value_t = 100.0)]
    pub ride_length_m: f64,
    /// Load case of the rides (D2 and D3 are loaded by definition).
    #[arg(long, default_value = "loaded")]
    pub load: Load,
    /// The D4 speeds of `d4_speed` and `d4_speed_seat` (km/h), comma separated, strictly
    /// ascending, 2 to 20 of them within 5 to 100; read only when one of them is the
    /// objective or constrained.
    #[arg(long, default_value = "10,15,20,25,30,35,40")]
    pub d4_speeds: String,
    /// Terrain seeds of every design, 1 to 100 (each measure is the mean over them).
    #[arg(long, default_value_t = 1)]
    pub seeds: usize,
    /// First terrain seed.
    #[arg(long, default_value_t = 1)]
    pub terrain_seed: u64,
    /// GA population (even, 4 to 1000).
    #[arg(long, default_value_t = 20)]
    pub population: usize,
    /// GA generations (1 to 1000); each costs `population` designs.
    #[arg(long, default_value_t = 10)]
    pub generations: usize,
    /// Seed of the GA.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    #[command(flatten)]
    pub ask_tell: AskTellArgs,
    /// Replace existing output files afsv did not write.
    #[arg(long)]
    pub force: bool,
    #[command(flatten)]
    pub output: crate::cmd::args::JsonOutput,
}

/// The problem the options define (`afsv_design::layout_problem`).
fn problem_desc(a: &LayoutArgs) -> Result<LayoutProblemDesc, String> {
    layout_problem::problem_desc(&LayoutOptions {
        vehicle: a.vehicle.as_deref(),
        layout: &a.layout,
        seat: a.seat.as_deref(),
        vary: &a.vary,
        objective: &a.objective,
        maximise: a.maximise,
        constraints: &a.constraints,
        load: a.load,
        speed_kmh: a.speed_kmh,
        ride_length_m: a.ride_length_m,
        d4_speeds: &a.d4_speeds,
        seeds: a.seeds,
        terrain_seed: a.terrain_seed,
    })
}

/// Run `afsv optimize layout`.
pub fn run(a: &LayoutArgs) -> CmdResult {
    a.ask_tell.check()?;
    let ga = LayoutGaSettings {
        population: a.population,
        generations: a.generations,
        seed: a.seed,
    };
    ga.options()?;
    let (_lock, stored) = take_and_read("--state", a.ask_tell.state.as_deref())?;
    let mut guard = OutputGuard::new(a.force);
    crate::cmd::described::declare(&mut guard, a.vehicle.as_deref())?;
    a.ask_tell.declare_inputs(&mut guard)?;
    a.ask_tell.declare_outputs(&mut guard)?;
    let desc = problem_desc(a)?;
    let problem = desc.problem()?;
    if let Some(state) = &a.ask_tell.state {
        return ask_tell(a, &problem, &ga, state, stored);
    }
    let progress = super::Generations::new("layout", a.generations, |b| format!("{b:.5}"));
    let r = optimise_layout(&problem, &ga, &progress)?;
    progress.0.finish();
    report(a, &r)
}

/// The report on stdout (JSON, or text on a terminal); [`NotEarned`] when the optimum is
/// infeasible or a variable lies on a bound.
fn report(a: &LayoutArgs, r: &LayoutOptimum) -> CmdResult {
    afsv::output::print_json_or_text(a.output.json, r, || text(r))?;
    r.earned().map_err(|why| {
        NotEarned(format!(
            "optimize layout: the best design found is printed, not an optimum: {why}"
        ))
        .into()
    })
}

/// One `--ask` or `--tell` against the state file `path` (its text `stored`, read under
/// the run lock).
fn ask_tell(
    a: &LayoutArgs,
    problem: &LayoutProblem,
    ga: &LayoutGaSettings,
    path: &Path,
    stored: Option<String>,
) -> CmdResult {
    let driver = LayoutAskTell::new(problem, *ga)?;
    let mut state = LayoutAskTellState::read(
        "--state",
        path,
        stored.as_deref(),
        a.ask_tell.ask.is_some(),
        problem.desc(),
        ga,
    )?;
    let step = (&driver, &mut state, stored, path);
    if super::ask_or_tell(step, &a.ask_tell, a.output.json, "layout", "points")? {
        return report(a, &driver.finish(&state.run)?);
    }
    Ok(())
}
