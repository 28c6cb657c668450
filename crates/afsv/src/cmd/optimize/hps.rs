//! `afsv optimize hps`: the chapter-6 HPS design optimisation (Eqs 6.19-6.20) on the 3-D
//! vehicle by a genetic algorithm (`afsv_design::hps_optimum`), then the optimum and the
//! nominal design re-evaluated over terrain seeds with SP-DRT and omega_z. In this
//! process, or ask/tell with `--state`: `--ask` writes the next batch of vehicle runs
//! (JSON Lines) for `afsv batch evaluate`, `--tell` reads the shards' results; once
//! finished `--ask` prints the report, the in-process one byte for byte
//! (`afsv_design::hps_ask_tell`).

use super::AskTellArgs;
use crate::cmd::CmdResult;
use afsv::output::OutputGuard;
use afsv_design::hps_optimum::{
    optimise_hps, optimum_speed_sweep, optimum_vehicle, HpsGaSettings, HpsOptimum, D4_SPEEDS_KMH,
};
use afsv_design::hps_speed_sweep::speed_sweep_runs;
use afsv_design::report::hps_optimum;
use afsv_design::{HpsAskTell, HpsAskTellState, HpsProblemDesc};
use afsv_records::lock::take_and_read;
use std::path::Path;

/// Options of `afsv optimize hps`.
#[derive(clap::Args)]
pub struct HpsArgs {
    /// GA population (even, 4 to 1000).
    #[arg(long, default_value_t = 20)]
    pub population: usize,
    /// GA generations (1 to 1000); each costs `population` vehicle runs.
    #[arg(long, default_value_t = 10)]
    pub generations: usize,
    /// Seed of the GA.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// The fixed terrain seed of the search (the first of the re-evaluation seeds).
    #[arg(long, default_value_t = 1)]
    pub terrain_seed: u64,
    /// Terrain seeds of the re-evaluation of the optimum and the nominal design (1 to 100).
    #[arg(long, default_value_t = 10)]
    pub reevaluation_seeds: usize,
    /// Skip the SP-DRT re-evaluation (D2, the costliest runs).
    #[arg(long)]
    pub no_roll: bool,
    /// Write the optimum's strut parameters to FILE (the `--hps FILE` of `afsv vehicle` and
    /// `afsv study speed-sweep`). An existing file afsv did not write needs --force.
    #[arg(long)]
    pub strut_out: Option<std::path::PathBuf>,
    /// Replace an existing --strut-out file.
    #[arg(long)]
    pub force: bool,
    /// Then run D4 on the optimum (Fig 6.16): both loads at 10, 15, 20, 25 and 30 km/h on the
    /// re-evaluation seeds, with the speed at which a_wz crosses the 8 h caution zone.
    #[arg(long)]
    pub speed_sweep: bool,
    #[arg(long, help = crate::cmd::described::HELP)]
    pub vehicle: Option<std::path::PathBuf>,
    #[command(flatten)]
    pub ask_tell: AskTellArgs,
    #[command(flatten)]
    pub output: crate::cmd::args::JsonOutput,
}

/// Run the optimisation and print the result.
pub fn run(a: &HpsArgs) -> CmdResult {
    let settings = HpsGaSettings {
        population: a.population,
        generations: a.generations,
        ga_seed: a.seed,
        terrain_seed: a.terrain_seed,
        reevaluation_seeds: a.reevaluation_seeds,
        reevaluate_roll: !a.no_roll,
        ..HpsGaSettings::default()
    };
    settings.check_options()?;
    a.ask_tell.check()?;
    let (_lock, stored) = take_and_read("--state", a.ask_tell.state.as_deref())?;
    let mut guard = OutputGuard::new(a.force);
    crate::cmd::described::declare(&mut guard, a.vehicle.as_deref())?;
    a.ask_tell.declare_inputs(&mut guard)?;
    guard.output_if(
        "--strut-out",
        a.strut_out.as_deref(),
        afsv::output::OutputKind::Other,
    )?;
    a.ask_tell.declare_outputs(&mut guard)?;
    let base = crate::cmd::described::with_front_strut(a.vehicle.as_deref(), "optimize hps")?;
    if let Some(state) = &a.ask_tell.state {
        let desc = HpsProblemDesc {
            vehicle: crate::cmd::described::articulated(a.vehicle.as_deref())?.name,
            params: base,
            settings,
        };
        return ask_tell(a, &desc, state, stored);
    }
    let progress = super::Generations::new("hps", a.generations, |b| format!("F {b:.4}"));
    let r = optimise_hps(&base, &settings, &progress)?;
    progress.0.finish();
    report(a, &base, &r)
}

/// The finished run's outputs: the optimum's strut file, the D4 sweep when asked, the
/// report on stdout (JSON, or text on a terminal); [`afsv::output::NotEarned`] when the
/// optimum misses the a_wz limit.
fn report(a: &HpsArgs, base: &vehicle_3d::VehicleParams, r: &HpsOptimum) -> CmdResult {
    let best = optimum_vehicle(base, r)?;
    if let Some(path) = &a.strut_out {
        afsv::output::write_json_file(path, &best.hps)?;
    }
    let sweep = if a.speed_sweep {
        let runs = speed_sweep_runs(D4_SPEEDS_KMH.len(), r.settings.reevaluation_seeds);
        let p = afsv::progress::Progress::new("afsv optimize hps: D4", "runs", Some(runs));
        let s = optimum_speed_sweep(&best, &r.settings, &|d| p.step(d))?;
        p.finish();
        Some(s)
    } else {
        None
    };
    let v = hps_optimum::to_json(r, sweep.as_ref())?;
    afsv::output::print_json_or_text(a.output.json, &v, || match &sweep {
        None => hps_optimum::text(r),
        Some(s) => format!(
            "{}\n{}",
            hps_optimum::text(r),
            afsv_design::report::speed_sweep::text(s)
        ),
    })?;
    hps_optimum::earned(r)
        .map_err(|why| afsv::output::NotEarned(format!("optimize hps: {why}")).into())
}

/// One `--ask` or `--tell` against the state file `path` (its text `stored`, read under
/// the run lock).
fn ask_tell(a: &HpsArgs, desc: &HpsProblemDesc, path: &Path, stored: Option<String>) -> CmdResult {
    let driver = HpsAskTell::new(desc)?;
    let mut state = HpsAskTellState::read(
        "--state",
        path,
        stored.as_deref(),
        a.ask_tell.ask.is_some(),
        desc,
    )?;
    let step = (&driver, &mut state, stored, path);
    if super::ask_or_tell(step, &a.ask_tell, a.output.json, "hps", "runs")? {
        return report(a, &desc.params, &driver.finish(&state.run)?);
    }
    Ok(())
}
