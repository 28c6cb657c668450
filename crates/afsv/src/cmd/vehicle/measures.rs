//! `afsv vehicle measures`: the three design measures of section 6.4 for one configuration
//! (parameter set, front axle, ride load case) over common terrain seeds, through the code
//! `afsv evaluate` uses (`afsv_design::design_3d::measure`): D1 a_wz with the 8 h
//! HGCZ verdict and the strut travel d_s (Eq 6.19), D2 SP-DRT, D3 omega_z and zeta.

use super::{axle_name, declare_inputs, print_result, vehicle_params, CaseArgs, CmdResult};
use afsv::output::OutputGuard;
use afsv::progress::Progress;
use afsv_design::design_3d::{hgcz_8h_band, measure, MAX_SEEDS};
use perf_measures::iso2631::HgczZone;
use serde_json::json;
use vehicle_3d::Load;

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

fn zone_text(z: HgczZone) -> &'static str {
    match z {
        HgczZone::Below => "below the zone",
        HgczZone::Within => "within the zone (caution)",
        HgczZone::Above => "above the zone (health risk likely)",
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
    super::unlinked(case, "measures")?;
    let (p, axle) = vehicle_params(case)?;
    let runs = seeds.len() * 2 + 1;
    let progress = Progress::new("afsv vehicle measures", "runs", Some(runs));
    let result = measure(&p, &[axle], &[case.load], &seeds, &|d| progress.step(d));
    progress.finish();
    let c = result?.pop().ok_or("no configuration was measured")?;
    let ride = c
        .ride_of(case.load)
        .ok_or_else(|| format!("the {} ride is missing", case.load))?;
    let band = hgcz_8h_band()?;
    let no_strut = "rigid front axle (--hps off): no strut";
    let mut v = json!({
        "measures": "design measures D1-D3 (section 6.4)",
        "front_axle": axle,
        "rear_axle": super::rear_axle(&p),
        "yaw_inertia_form": p.yaw_inertia_form,
        "ride_load": case.load,
        "seeds": seeds,
        "terrain": "class E, m_c 0.3 (D1, D2); smooth ground (D3)",
        "d1_ride": {
            "load": case.load,
            "speed_kmh": 20.0,
            "a_wz_m_s2": ride.a_wz_m_s2,
            "strut_travel_p2p_m": ride.strut_travel_m,
            "hgcz_8h": ride.hgcz_8h,
            "hgcz_8h_m_s2": band,
        },
        "d2_roll": { "load": Load::Loaded, "speed_kmh": 50.0, "sp_drt_m_s2": c.sp_drt_m_s2 },
        "d3_yaw": {
            "load": Load::Loaded,
            "speed_kmh": 50.0,
            "omega_z_hz": c.yaw.omega_z_hz,
            "damping_ratio": c.yaw.damping_ratio,
            "damped_frequency_hz": c.yaw.damped_frequency_hz,
            "peak_articulation_deg": c.yaw.peak_articulation_deg,
            "damping_ratio_std": c.yaw.damping_ratio_std,
            "fit_residual_to_noise": c.yaw.fit_residual_to_noise,
        },
    });
    if let Some(caveat) = c.yaw.fit_caveat() {
        v["d3_yaw"]["fit_caveat"] = json!(caveat);
    }
    if ride.strut_travel_m.is_none() {
        v["d1_ride"]["strut_travel_p2p_m_reason"] = json!(no_strut);
    }
    let pm = |s: &vehicle_3d::scenarios::Spread, d: usize| {
        if s.n > 1 {
            format!("{:.d$} ± {:.d$}", s.mean, s.sd)
        } else {
            format!("{:.d$}", s.mean)
        }
    };
    let row = |label: &str, value: String, unit: &str| format!("{label:<36} {value:>16} {unit}\n");
    let mut text = format!(
        "design measures: {}, ride {}, {} terrain seed(s){}\n",
        axle_name(axle, &p),
        case.load,
        seeds.len(),
        if seeds.len() > 1 { ", mean ± SD" } else { "" }
    );
    text += &row(
        "a_wz (D1, 20 km/h, class E)",
        pm(&ride.a_wz_m_s2, 3),
        "m/s²",
    );
    text += &row(
        "  8 h HGCZ verdict",
        zone_text(ride.hgcz_8h).into(),
        &format!("({:.2}-{:.2} m/s²)", band.0, band.1),
    );
    text += &row(
        "strut travel d_s (Eq 6.19)",
        ride.strut_travel_m
            .as_ref()
            .map_or("n/a".into(), |t| pm(t, 3)),
        "m",
    );
    text += &row(
        "SP-DRT (D2, 50 km/h, loaded)",
        pm(&c.sp_drt_m_s2, 2),
        "m/s²",
    );
    text += &row(
        "omega_z (D3, 50 km/h, loaded)",
        format!("{:.2}", c.yaw.omega_z_hz),
        "Hz",
    );
    text += &row(
        "yaw damping ratio zeta",
        format!("{:.3}", c.yaw.damping_ratio),
        "-",
    );
    if case.paper_form {
        text += "(--paper-form: yaw inertias of the printed Eq 3.13, m L² counted twice; not for design)\n";
    }
    if let Some(caveat) = c.yaw.fit_caveat() {
        text += &format!("note on omega_z and zeta: {caveat}\n");
    }
    print_result(json_out, &v, &text)
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
