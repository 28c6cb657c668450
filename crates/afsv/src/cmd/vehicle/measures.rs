//! `afsv vehicle measures`: the three design measures of section 6.4 for one configuration
//! (parameter set, front axle, ride load case) over common terrain seeds, through the code
//! `afsv evaluate` uses (`afsv_design::design_3d::measure`): D1 a_wz with the 8 h
//! HGCZ verdict and the strut travel d_s (Eq 6.19), D2 SP-DRT, D3 omega_z and zeta. With
//! the front-axle HPS the struts run interconnected as the description's `[link]` says.

use super::{declare_inputs, vehicle_params, CaseArgs, CmdResult};
use afsv::output::OutputGuard;
use afsv::progress::Progress;
use afsv_design::design_3d::{measure, MAX_SEEDS};
use afsv_design::report::vehicle::measures_report;

/// The seeds of `--seeds N` (1..=N) or `--seed S` (default 1..=10), at most [`MAX_SEEDS`].
pub(super) fn measure_seeds(seeds: Option<usize>, seed: Option<u64>) -> Result<Vec<u64>, String> {
    match (seeds, seed) {
        (Some(_), Some(_)) => Err("--seeds and --seed both give the seeds; give one".into()),
        (None, Some(s)) => Ok(vec![s]),
        (n, None) => {
            let n = n.unwrap_or(10);
            if n == 0 || n as u64 > MAX_SEEDS {
                return Err(format!("--seeds {n}: must be 1 to {MAX_SEEDS}"));
            }
            Ok((1..=n as u64).collect())
        }
    }
}

pub(super) fn measures_cmd(
    case: &CaseArgs,
    seeds: Option<usize>,
    seed: Option<u64>,
    json_out: bool,
) -> CmdResult {
    let mut guard = OutputGuard::new(false);
    declare_inputs(case, &mut guard)?;
    let seeds = measure_seeds(seeds, seed)?;
    let (p, axle) = vehicle_params(case)?;
    let link = super::described_link(case, axle)?;
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn seeds_come_from_one_option() {
        assert_eq!(
            measure_seeds(None, None).unwrap(),
            (1..=10).collect::<Vec<_>>()
        );
        assert_eq!(measure_seeds(Some(2), None).unwrap(), vec![1, 2]);
        assert_eq!(measure_seeds(None, Some(7)).unwrap(), vec![7]);
        assert!(measure_seeds(Some(2), Some(7)).is_err());
        assert!(measure_seeds(Some(0), None).is_err());
        assert!(measure_seeds(Some(101), None).is_err());
    }
}
