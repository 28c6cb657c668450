//! `afsv vehicle simulate`: one run of the vehicle into a record (CSV + JSON sidecar,
//! docs/records.md) in the afsv-v1 sign convention, through the output guard.

use super::super::args;
use super::options::steer_input;
use super::CmdResult;
use super::{declare_inputs, described_link, terrain_and_seeds, vehicle_params, CaseArgs};
use afsv::output::{OutputGuard, OutputKind};
use afsv_design::report::vehicle_record::{
    simulate_record, simulate_sidecar, simulate_summary, SimulateRun,
};
use std::path::PathBuf;
use vehicle_3d::component_record::simulate_components;
use vehicle_3d::interconnect::LinkedVehicle;
use vehicle_3d::{RunOptions, Vehicle, VehicleOptions};
use vehicle_components::FlatTerrain;

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
    args::check_samples(
        &format!("--duration {}", args::show(duration)),
        &format!("duration/dt with --dt {}", args::show(dt)),
        duration / dt,
        vehicle_3d::simulate::MAX_SAMPLES as f64,
    )?;
    let input = steer_input(steer)?;
    let mut guard = OutputGuard::new(force);
    declare_inputs(case, &mut guard)?;
    guard.output("-o", output, OutputKind::Record)?;
    let (p, axle) = vehicle_params(case)?;
    let link = described_link(case, axle)?;
    let (terrain, seeds) = terrain_and_seeds(case, None, seed, None)?;
    // one run: the given seed, else the first of the default list (1)
    let seeds = &seeds[..1];
    let speed_kmh = case.speed_kmh.unwrap_or(20.0);
    let speed = speed_kmh / 3.6;
    let options = VehicleOptions {
        front_axle: axle,
        speed_m_s: speed,
        steer: input.clone(),
        path_length_m: speed * duration + 5.0,
        ..VehicleOptions::default()
    };
    let run = RunOptions {
        t_end_s: duration,
        output_dt_s: dt,
        ..RunOptions::default()
    };
    let half = 0.5 * p.front_track_m;
    let vehicle = match &terrain {
        None => {
            let flat = FlatTerrain::new(0.0, vehicle_components::DEFAULT_FRICTION)?;
            Vehicle::new(&p, case.load, options, &flat, half)?
        }
        Some(t) => {
            let length = options.start_s_m + options.path_length_m + 50.0;
            let ground = t.build(&p, length, seeds[0])?;
            Vehicle::new(&p, case.load, options, &ground, half)?
        }
    };
    let (rec, components) = match &link {
        None if out_args.components => {
            let (rec, c) = simulate_components(&vehicle, &run)?;
            (rec, Some(c))
        }
        None => (vehicle_3d::simulate(&vehicle, &run)?, None),
        Some(_) if out_args.components => {
            return Err(
                "--components: not with the description's [link] (the linked struts' lines are not components)"
                    .into(),
            )
        }
        Some(l) => {
            let linked = LinkedVehicle::new(vehicle, l)?;
            (
                linked.simulate_from(&linked.initial_state()?, &run)?.record,
                None,
            )
        }
    };
    let run = SimulateRun {
        params: &p,
        load: case.load,
        front_axle: axle,
        speed_kmh,
        steer: &input,
        terrain: &terrain,
        seeds,
        output_dt_s: dt,
        link: link.as_ref(),
    };
    let mut out = simulate_record(&rec, components.as_ref())?;
    out.meta = simulate_sidecar(&run, components.as_ref());
    afsv::provenance::stamp_record(&mut out);
    out.write(output)?;
    afsv::output::print_json(&simulate_summary(output, out.names(), &rec))?;
    Ok(())
}
