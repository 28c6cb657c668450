//! `afsv vehicle measures`: the three design measures of section 6.4 for one configuration
//! (parameter set, front axle, ride load case) over common terrain seeds, through the code
//! `afsv evaluate` uses (`afsv_design::design_3d::measure`): D1 a_wz with the 8 h
//! HGCZ verdict and the strut travel d_s (Eq 6.19), D2 SP-DRT, D3 omega_z and zeta. With
//! the front-axle HPS the struts run interconnected as the description's `[link]` says.

use super::{declare_inputs, vehicle_of, CaseArgs, CmdResult};
use afsv::output::OutputGuard;
use afsv::progress::Progress;
use afsv_design::design_3d::measure;
use afsv_design::report::vehicle::measures_report;
use afsv_design::vehicle_case::measure_seeds;

pub(super) fn measures_cmd(
    case: &CaseArgs,
    seeds: Option<usize>,
    seed: Option<u64>,
    json_out: bool,
) -> CmdResult {
    declare_inputs(case, &mut OutputGuard::new(false))?;
    let seeds = measure_seeds(seeds, seed)?;
    let (p, axle, link) = vehicle_of(case)?;
    let runs = seeds.len() * 2 + 1;
    let progress = Progress::new("afsv vehicle measures", "runs", Some(runs));
    let result = measure(&p, &[axle], &[case.load], &seeds, link, &|d| {
        progress.step(d)
    });
    progress.finish();
    let c = result?.pop().ok_or("no configuration was measured")?;
    let report = measures_report(&p, axle, case.load, case.paper_form, &seeds, &c)?;
    super::print_linked((json_out, None), report, link.as_ref())
}
