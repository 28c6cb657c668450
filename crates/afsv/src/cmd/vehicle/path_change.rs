//! `afsv vehicle path-change`: the V3 path change of section 6.3 (Fig 3.6(b), 4.5 m offset
//! over an 18 m gate) steered by the pure-pursuit driver of the yaw-plane model: the
//! peaks of the Fig 6.12 channels and the course deviation, optionally the record (CSV +
//! JSON sidecar, afsv-v1) and a four-panel SVG of the channels.

use super::{axle_name, declare_inputs, print_linked, vehicle_of, CaseArgs, CmdResult};
use afsv::output::{OutputGuard, OutputKind};
use afsv_design::design_3d::path_change_run;
use afsv_design::figures;
use afsv_design::report::vehicle::path_change_report;
use afsv_design::report::vehicle_record::path_change_sidecar;
use serde_json::json;
use std::path::PathBuf;
use vehicle_3d::scenarios::PathChangeSpec;

pub(super) fn path_change_cmd(
    case: &CaseArgs,
    seed: Option<u64>,
    offset: f64,
    duration: f64,
    out: &PathChangeFiles,
) -> CmdResult {
    let mut guard = OutputGuard::new(out.force);
    declare_inputs(case, &mut guard)?;
    if let Some(o) = out.output.as_deref() {
        guard.output("-o", o, OutputKind::Record)?;
    }
    if let Some(p) = out.plot.as_deref() {
        guard.output("--plot", p, OutputKind::Svg)?;
    }
    let (p, axle, link) = vehicle_of(case)?;
    let (terrain, seeds) = case.terrain_and_seeds(None, seed, None)?;
    let seeds = &seeds[..1];
    let v3 = PathChangeSpec::v3(case.load, axle);
    let spec = PathChangeSpec {
        speed_kmh: case.speed_kmh.unwrap_or(v3.speed_kmh),
        offset_m: offset,
        t_end_s: duration,
        terrain,
        ..v3
    };
    let (rec, m) = path_change_run(&p, &spec, seeds[0], link.as_ref())?;
    if let Some(path) = out.output.as_deref() {
        let meta = path_change_sidecar(&rec, &spec, seeds, &m, &p, link.as_ref());
        let columns = afsv_records::Record::from_columns(rec.afsv_v1_columns())?;
        afsv::provenance::write_record(path, columns, meta)?;
    }
    if let Some(path) = out.plot.as_deref() {
        let chart = figures::vehicle::path_change(&rec, &spec, axle_name(axle, &p), &m);
        super::super::write_chart(path, &chart)?;
    }
    let (mut v, text) = path_change_report(&p, &spec, seeds[0], &m);
    if let Some(o) = out.output.as_deref() {
        v["output"] = json!(o);
        v["sidecar"] = json!(o.with_extension("json"));
    }
    print_linked((out.json, out.plot.as_deref()), (v, text), link.as_ref())
}

/// Output options of `afsv vehicle path-change`.
#[derive(clap::Args, Debug)]
pub struct PathChangeFiles {
    /// Record CSV of the run (the sidecar goes beside it with extension .json); an
    /// existing file afsv did not write needs --force.
    #[arg(short = 'o', long)]
    pub output: Option<PathBuf>,
    /// SVG plot of articulation, left-strut displacement, yaw rate and lateral acceleration.
    #[arg(long)]
    pub plot: Option<PathBuf>,
    /// Replace existing output files afsv did not write.
    #[arg(long)]
    pub force: bool,
    /// Print JSON even on a terminal (JSON is the default when stdout is not a terminal).
    #[arg(long)]
    pub json: bool,
}
