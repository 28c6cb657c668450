//! `afsv vehicle simulate`: one run of the vehicle into a record (CSV + JSON sidecar,
//! docs/records.md) in the afsv-v1 sign convention, through the output guard.

use super::super::args;
use super::CmdResult;
use super::{declare_inputs, vehicle_of, CaseArgs};
use afsv::output::{OutputGuard, OutputKind};
use afsv_design::report::vehicle_record::{
    simulate_record, simulate_sidecar, simulate_summary, SimulateRun,
};
use afsv_design::vehicle_case::{parse_steer, simulate_run};
use std::path::PathBuf;

/// Where `afsv vehicle simulate` writes its record, and what goes in it.
#[derive(clap::Args, Debug)]
pub struct RecordOutput {
    /// Output CSV file (the sidecar goes beside it with extension .json). It must not be an
    /// input; an existing file afsv did not write needs --force.
    #[arg(short = 'o', long)]
    pub output: PathBuf,
    /// Also record every component's own channels: the steering hydraulics' (steering_*)
    /// and each axle strut's (hps_<axle>_<side>_*: force, pressures, friction, gas volume,
    /// flow, ...), in the model's signs (docs/vehicle-3d.md, "Component channels"). Not
    /// with the description's [link].
    #[arg(long)]
    pub components: bool,
    /// Replace an existing output file that afsv did not write.
    #[arg(long)]
    pub force: bool,
}

pub(super) fn simulate_cmd(
    case: &CaseArgs,
    seed: Option<u64>,
    steer: &str,
    duration: f64,
    dt: f64,
    out_args: &RecordOutput,
) -> CmdResult {
    let (output, force) = (out_args.output.as_path(), out_args.force);
    args::check_duration(duration, dt, vehicle_3d::simulate::MAX_SAMPLES as f64)?;
    let input = parse_steer(steer)?;
    let mut guard = OutputGuard::new(force);
    declare_inputs(case, &mut guard)?;
    guard.output("-o", output, OutputKind::Record)?;
    let (p, axle, link) = vehicle_of(case)?;
    let (terrain, seeds) = case.terrain_and_seeds(None, seed, None)?;
    // one run: the given seed, else the first of the default list (1)
    let run = SimulateRun {
        params: &p,
        load: case.load,
        front_axle: axle,
        speed_kmh: case.speed_kmh.unwrap_or(20.0),
        steer: &input,
        terrain: &terrain,
        seeds: &seeds[..1],
        output_dt_s: dt,
        link: link.as_ref(),
    };
    let (rec, components) = simulate_run(&run, duration, out_args.components)?;
    let meta = simulate_sidecar(&run, components.as_ref());
    let columns = simulate_record(&rec, components.as_ref())?;
    let out = afsv::provenance::write_record(output, columns, meta)?;
    afsv::output::print_json(&simulate_summary(output, out.names(), &rec))?;
    Ok(())
}
