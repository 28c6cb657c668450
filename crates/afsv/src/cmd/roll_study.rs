//! `afsv roll study`: the section 2.4 studies, the comparison of the built-in trucks
//! (`trucks`) and the sensitivity of ΔT to the steering ramp and the detection rule
//! (`sensitivity`). Parses, calls, prints.

use super::{truck, CmdResult, RuleArgs, TruckArgs};
use afsv::output::{OutputGuard, OutputKind};
use afsv_design::report::roll::{self, sensitivity_text, study_text};
use afsv_design::truck_case::sensitivity_trucks;
use roll_truck::sensitivity::run_sensitivity;
use roll_truck::studies::{run_study, Study, MAX_SEEDS};
use roll_truck::RunOptions;
use std::path::PathBuf;

/// Which study `afsv roll study` runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StudyName {
    /// A study of `roll_truck::studies` (section 2.4, or `trucks`).
    Runs(Study),
    /// `sensitivity`: `roll_truck::sensitivity`.
    Sensitivity,
}

impl std::str::FromStr for StudyName {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "sensitivity" => Ok(Self::Sensitivity),
            _ => s
                .parse()
                .map(Self::Runs)
                .map_err(|e: String| e.replace("band, trucks)", "band, trucks, sensitivity)")),
        }
    }
}

/// Options of `afsv roll study`.
#[derive(clap::Args, Debug)]
pub struct StudyArgs {
    /// Which study: cg, roughness, waviness, band, trucks, sensitivity.
    pub study: StudyName,
    /// Number of terrain seeds (1 to 1000).
    #[arg(long, default_value_t = 10)]
    pub seeds: usize,
    #[command(flatten)]
    pub truck: TruckArgs,
    #[command(flatten)]
    pub rule: RuleArgs,
    /// SVG plot of the SP-DRT (mean ± SD) and, for `cg`, the smooth DRT and SSF (not for
    /// `sensitivity`).
    #[arg(long)]
    pub plot: Option<PathBuf>,
    /// Replace an existing plot afsv did not write.
    #[arg(long)]
    pub force: bool,
    #[command(flatten)]
    pub output: super::args::JsonOutput,
}

/// Run `afsv roll study`.
pub(super) fn run_study_cmd(a: &StudyArgs) -> CmdResult {
    let seeds = a.seeds;
    super::super::args::check_seeds(seeds, MAX_SEEDS)?;
    let t = &a.truck;
    let chosen = t.source().chosen();
    match a.study {
        StudyName::Runs(Study::Trucks) if chosen || t.ramp_rate.is_some() || t.no_bump_stops => {
            return Err("study trucks compares the built-in trucks with and without stops at their own ramp; --params, --truck, --vehicle, --ramp-rate and --no-bump-stops do not apply".into());
        }
        StudyName::Sensitivity if t.ramp_rate.is_some() || a.rule.given() => {
            return Err("study sensitivity sweeps the ramp rate and the detection rule itself; --ramp-rate, --sp-threshold and --sp-max-dip do not apply".into());
        }
        StudyName::Sensitivity if a.plot.is_some() => {
            return Err("--plot: study sensitivity has no plot (its table is the result)".into());
        }
        _ => {}
    }
    let mut guard = OutputGuard::new(a.force);
    t.declare_inputs(&mut guard)?;
    guard.output_if("--plot", a.plot.as_deref(), OutputKind::Svg)?;
    let seed_list: Vec<u64> = (1..=seeds as u64).collect();
    // The number of runs is known once the study has built its variants.
    let progress = std::sync::OnceLock::new();
    let report = |_done: usize, total: usize| {
        progress
            .get_or_init(|| afsv::progress::Progress::new("afsv roll study", "runs", Some(total)))
            .step("");
    };
    let study = match a.study {
        StudyName::Runs(s) => s,
        StudyName::Sensitivity => {
            let trucks = sensitivity_trucks(&t.source())?;
            let cells = run_sensitivity(&trucks, &seed_list, &report)?;
            if let Some(p) = progress.get() {
                p.finish();
            }
            let v = roll::sensitivity_json(&cells, &seed_list);
            return Ok(afsv::output::print_json_or_text(a.output.json, &v, || {
                sensitivity_text(&cells, seeds)
            })?);
        }
    };
    let p = truck(t, None)?;
    let options = RunOptions {
        t_end_s: roll_truck::sensitivity::ramp_duration_s(&p),
        // the truck comparison reports the peaks of every channel
        acceleration_channels: study == Study::Trucks,
        ..RunOptions::default()
    };
    let result = run_study(study, &p, &seed_list, &options, &a.rule.params()?, &report)?;
    if let Some(p) = progress.get() {
        p.finish();
    }
    if let Some(path) = &a.plot {
        crate::cmd::write_chart(path, &afsv_design::figures::studies::roll_study(&result))?;
    }
    let v = roll::study_json(&result)?;
    Ok(afsv::output::print_json_or_text(a.output.json, &v, || {
        study_text(&result)
    })?)
}
