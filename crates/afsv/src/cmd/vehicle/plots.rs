//! The `--plot` figures of `afsv vehicle`: the ride PSDs (Welch), the roll LTR history with
//! the sustained period, the yaw articulation with its single-DOF decay fit.

use super::CmdResult;
use afsv_design::report::vehicle::RidePsd;
use std::path::Path;
use vehicle_3d::scenarios::{RideSpec, RollMeasures, RollSpec, YawSpec};
use vehicle_3d::RunRecord;

pub(super) fn plot_ride(
    path: &Path,
    psds: &[RidePsd],
    spec: &RideSpec,
    axles: &str,
    seeds: &[u64],
) -> CmdResult {
    let first = psds.first().ok_or("no PSD to plot")?;
    if psds.iter().any(|p| p.0.len() != first.0.len()) {
        return Err("the seeds' PSDs have different frequency grids".into());
    }
    let n = psds.len() as f64;
    let keep = first.0.iter().take_while(|&&f| f <= 15.0).count();
    let freq = &first.0[..keep];
    let mean = |k: usize| -> Vec<f64> {
        (0..keep)
            .map(|i| {
                psds.iter()
                    .map(|p| if k == 1 { p.1[i] } else { p.2[i] })
                    .sum::<f64>()
                    / n
            })
            .collect()
    };
    let (vert, pitch) = (mean(1), mean(2));
    // The ISO 2631-1 W_k-weighted PSD |W_k(f)|² G(f): its integral is a_wz² (the D1 measure).
    let weighted: Vec<f64> = freq
        .iter()
        .zip(&vert)
        .map(|(&f, &g)| perf_measures::Weighting::Wk.magnitude(f).powi(2) * g)
        .collect();
    let conditions = format!(
        "{}, {}, {} km/h, class {}, m_c {}, mean of {} seed(s) from {}",
        spec.load,
        axles,
        spec.speed_kmh,
        spec.terrain.class,
        spec.terrain.m_c,
        seeds.len(),
        seeds[0]
    );
    afsv_plot::panels(
        path,
        "front-unit acceleration PSDs (Welch), ride window",
        &conditions,
        2,
        &[
            afsv_plot::Panel {
                caption: "vertical acceleration at the cab point",
                x: afsv_plot::Axis::log("frequency", "Hz"),
                y: afsv_plot::Axis::log("PSD", "(m/s²)²/Hz"),
                series: vec![
                    afsv_plot::Series {
                        label: "a_z",
                        x: freq,
                        y: &vert,
                    },
                    afsv_plot::Series {
                        label: "a_z weighted by W_k (ISO 2631-1)",
                        x: freq,
                        y: &weighted,
                    },
                ],
            },
            afsv_plot::Panel {
                caption: "pitch acceleration",
                x: afsv_plot::Axis::log("frequency", "Hz"),
                y: afsv_plot::Axis::log("PSD", "(rad/s²)²/Hz"),
                series: vec![afsv_plot::Series {
                    label: "pitch",
                    x: freq,
                    y: &pitch,
                }],
            },
        ],
    )?;
    afsv::output::mark_svg(path)?;
    Ok(())
}

pub(super) fn plot_roll(
    path: &Path,
    rec: &RunRecord,
    m: &RollMeasures,
    spec: &RollSpec,
    axles: &str,
    seed: u64,
) -> CmdResult {
    let ltr: Vec<f64> = rec.rear_ltr.iter().map(|x| x.abs()).collect();
    let (a, b) = m.sustained_s;
    // afsv-plot draws lines only: the sustained period is outlined as a box.
    let box_x = [a, a, b, b, a];
    let box_y = [0.0, 1.05, 1.05, 0.0, 0.0];
    let ground = match spec.terrain {
        None => "smooth ground".to_string(),
        Some(t) => format!("class {}, m_c {}, seed {seed}", t.class, t.m_c),
    };
    let conditions = format!(
        "{}, {}, {} km/h, ramp {} deg/s, {ground}; SP-DRT {:.2} m/s²",
        spec.load, axles, spec.speed_kmh, spec.ramp_deg_s, m.sp_drt_m_s2
    );
    afsv_plot::figure(
        path,
        &afsv_plot::Figure {
            title: "rear-axle load transfer ratio, ramp steer (D2)",
            conditions: &conditions,
            x: afsv_plot::Axis::new("time", "s"),
            y: afsv_plot::Axis::new("|LTR|", "-"),
        },
        &[
            afsv_plot::Series {
                label: "|LTR| rear axle",
                x: &rec.t_s,
                y: &ltr,
            },
            afsv_plot::Series {
                label: "sustained period ΔT",
                x: &box_x,
                y: &box_y,
            },
        ],
    )?;
    afsv::output::mark_svg(path)?;
    Ok(())
}

pub(super) fn plot_yaw(
    path: &Path,
    rec: &RunRecord,
    spec: &YawSpec,
    axles: &str,
    seed: u64,
) -> CmdResult {
    let deg: Vec<f64> = rec
        .articulation_rad
        .iter()
        .map(|a| a.to_degrees())
        .collect();
    let t = &rec.t_s;
    // The window of vehicle_3d::scenarios::yaw_measures, and its fit drawn over it.
    let i0 = perf_measures::decay_onset(t, &deg, spec.pulse_start_s + spec.pulse_s)
        .ok_or("no free oscillation after the pulse")?;
    let i1 = t.partition_point(|&x| x < t[i0] + spec.fit_window_s);
    let fit = perf_measures::fit_free_decay(&t[i0..i1], &deg[i0..i1])?;
    let wd = 2.0 * std::f64::consts::PI * fit.damped_frequency_hz;
    let fitted: Vec<f64> = t[i0..i1]
        .iter()
        .map(|&x| {
            let tau = x - t[i0];
            fit.offset
                + fit.amplitude
                    * (-fit.decay_rate_1_s * tau).exp()
                    * (wd * tau + fit.phase_rad).cos()
        })
        .collect();
    let hi = deg.iter().fold(0.0f64, |m, v| m.max(v.abs())) * 1.05;
    let (a, b) = (t[i0], t[i1 - 1]);
    let edge_x = [a, a, f64::NAN, b, b];
    let edge_y = [-hi, hi, f64::NAN, hi, -hi];
    let ground = match spec.terrain {
        None => "smooth ground".to_string(),
        Some(g) => format!("class {}, m_c {}, seed {seed}", g.class, g.m_c),
    };
    let conditions = format!(
        "{}, {}, {} km/h, {} deg pulse, {ground}; omega_z {:.2} Hz, zeta {:.3}",
        spec.load,
        axles,
        spec.speed_kmh,
        spec.pulse_deg,
        fit.natural_frequency_hz,
        fit.damping_ratio
    );
    afsv_plot::figure(
        path,
        &afsv_plot::Figure {
            title: "articulation after a steering pulse (D3) and its single-DOF fit",
            conditions: &conditions,
            x: afsv_plot::Axis::new("time", "s"),
            y: afsv_plot::Axis::new("articulation", "deg"),
        },
        &[
            afsv_plot::Series {
                label: "articulation",
                x: t,
                y: &deg,
            },
            afsv_plot::Series {
                label: "single-DOF fit",
                x: &t[i0..i1],
                y: &fitted,
            },
            afsv_plot::Series {
                label: "fitted window",
                x: &edge_x,
                y: &edge_y,
            },
        ],
    )?;
    afsv::output::mark_svg(path)?;
    Ok(())
}
