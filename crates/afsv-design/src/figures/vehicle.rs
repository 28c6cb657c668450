//! The `--plot` figures of `afsv vehicle`: the ride PSDs (Welch) with the ISO 2631-1
//! W_k-weighted one (D1), the rear-axle LTR history with the sustained period (D2), the
//! articulation after a pulse with its single-DOF decay fit (D3), and the four Fig 6.12
//! channels of the V3 path change.

use crate::report::vehicle::RidePsd;
use afsv_plot::{Axis, Chart, ChartPanel, Curve};
use vehicle_3d::scenarios::{
    PathChangeMeasures, PathChangeSpec, RideSpec, RollMeasures, RollSpec, TerrainSpec, YawSpec,
};
use vehicle_3d::RunRecord;

/// Highest frequency drawn of the ride PSDs (Hz).
pub const RIDE_PSD_MAX_HZ: f64 = 15.0;

/// The mean over seeds of the ride PSDs `psds` up to [`RIDE_PSD_MAX_HZ`]: the vertical
/// cab-point acceleration, its W_k-weighted PSD |W_k(f)|² G(f) (whose integral is a_wz²,
/// the D1 measure) and the pitch acceleration, in two log-log panels. `axles` names the
/// suspended axles, `seeds` the seeds the PSDs come from (in order).
pub fn ride(
    psds: &[RidePsd],
    spec: &RideSpec,
    axles: &str,
    seeds: &[u64],
) -> Result<Chart, String> {
    let first = psds.first().ok_or("no PSD to plot")?;
    if psds.iter().any(|p| p.0.len() != first.0.len()) {
        return Err("the seeds' PSDs have different frequency grids".into());
    }
    let n = psds.len() as f64;
    let keep = first
        .0
        .iter()
        .take_while(|&&f| f <= RIDE_PSD_MAX_HZ)
        .count();
    let freq = first.0[..keep].to_vec();
    let mean = |pick: fn(&RidePsd) -> &Vec<f64>| -> Vec<f64> {
        (0..keep)
            .map(|i| psds.iter().map(|p| pick(p)[i]).sum::<f64>() / n)
            .collect()
    };
    let (vert, pitch) = (mean(|p| &p.1), mean(|p| &p.2));
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
        seeds.first().ok_or("no seed")?
    );
    Ok(Chart::Panels {
        title: "front-unit acceleration PSDs (Welch), ride window".into(),
        conditions,
        columns: 2,
        panels: vec![
            ChartPanel {
                caption: "vertical acceleration at the cab point".into(),
                x: Axis::log("frequency", "Hz"),
                y: Axis::log("PSD", "(m/s²)²/Hz"),
                curves: vec![
                    Curve::new("a_z", freq.clone(), vert),
                    Curve::new("a_z weighted by W_k (ISO 2631-1)", freq.clone(), weighted),
                ],
            },
            ChartPanel {
                caption: "pitch acceleration".into(),
                x: Axis::log("frequency", "Hz"),
                y: Axis::log("PSD", "(rad/s²)²/Hz"),
                curves: vec![Curve::new("pitch", freq, pitch)],
            },
        ],
    })
}

/// The ground of a roll or yaw run for a conditions line.
fn ground(terrain: Option<&TerrainSpec>, seed: u64) -> String {
    match terrain {
        None => "smooth ground".to_string(),
        Some(t) => format!("class {}, m_c {}, seed {seed}", t.class, t.m_c),
    }
}

/// The rear-axle |LTR| of a D2 ramp-steer run with its sustained period outlined as a box
/// from 0 to 1.05 (afsv-plot draws lines only).
pub fn roll(rec: &RunRecord, m: &RollMeasures, spec: &RollSpec, axles: &str, seed: u64) -> Chart {
    let ltr: Vec<f64> = rec.rear_ltr.iter().map(|x| x.abs()).collect();
    let (a, b) = m.sustained_s;
    let conditions = format!(
        "{}, {}, {} km/h, ramp {} deg/s, {}; SP-DRT {:.2} m/s²",
        spec.load,
        axles,
        spec.speed_kmh,
        spec.ramp_deg_s,
        ground(spec.terrain.as_ref(), seed),
        m.sp_drt_m_s2
    );
    Chart::Figure {
        title: "rear-axle load transfer ratio, ramp steer (D2)".into(),
        conditions,
        x: Axis::new("time", "s"),
        y: Axis::new("|LTR|", "-"),
        curves: vec![
            Curve::new("|LTR| rear axle", rec.t_s.clone(), ltr),
            Curve::new(
                "sustained period ΔT",
                vec![a, a, b, b, a],
                vec![0.0, 1.05, 1.05, 0.0, 0.0],
            ),
        ],
    }
}

/// The articulation of a D3 run after its pulse, the single-DOF decay fit over the window
/// of `vehicle_3d::scenarios::yaw_measures` drawn over it, and the window's edges.
pub fn yaw(rec: &RunRecord, spec: &YawSpec, axles: &str, seed: u64) -> Result<Chart, String> {
    let (deg, window) = vehicle_3d::scenarios::yaw_decay_window(
        rec,
        spec.pulse_start_s + spec.pulse_s,
        spec.fit_window_s,
    )
    .map_err(|e| e.to_string())?;
    let (t, i0, i1) = (&rec.t_s, window.start, window.end);
    let fit = perf_measures::fit_free_decay(&t[i0..i1], &deg[i0..i1]).map_err(|e| e.to_string())?;
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
    let conditions = format!(
        "{}, {}, {} km/h, {} deg pulse, {}; omega_z {:.2} Hz, zeta {:.3}",
        spec.load,
        axles,
        spec.speed_kmh,
        spec.pulse_deg,
        ground(spec.terrain.as_ref(), seed),
        fit.natural_frequency_hz,
        fit.damping_ratio
    );
    Ok(Chart::Figure {
        title: "articulation after a steering pulse (D3) and its single-DOF fit".into(),
        conditions,
        x: Axis::new("time", "s"),
        y: Axis::new("articulation", "deg"),
        curves: vec![
            Curve::new("articulation", t.clone(), deg),
            Curve::new("single-DOF fit", t[i0..i1].to_vec(), fitted),
            Curve::new(
                "fitted window",
                vec![a, a, f64::NAN, b, b],
                vec![-hi, hi, f64::NAN, hi, -hi],
            ),
        ],
    })
}

/// The four Fig 6.12 channels of a V3 path change in a 2 × 2 grid, in the afsv-v1 signs
/// (positive in a right-hand turn: the yaw rate and the lateral acceleration of the
/// record's left-handed axes are negated).
pub fn path_change(
    rec: &RunRecord,
    spec: &PathChangeSpec,
    axles: &str,
    m: &PathChangeMeasures,
) -> Chart {
    let deg =
        |v: &[f64], sign: f64| -> Vec<f64> { v.iter().map(|x| sign * x.to_degrees()).collect() };
    let panel = |caption: &str, label: &'static str, unit: &'static str, y: Vec<f64>| ChartPanel {
        caption: caption.into(),
        x: Axis::new("time", "s"),
        y: Axis::new(label, unit),
        curves: vec![Curve::new(label, rec.t_s.clone(), y)],
    };
    let conditions = format!(
        "{}, {}, {} km/h, {} m offset, {} m gate; max deviation {:.2} m",
        spec.load, axles, spec.speed_kmh, spec.offset_m, spec.gate_m, m.max_deviation_m
    );
    Chart::Panels {
        title: "path change (V3): the Fig 6.12 channels, positive in a right-hand turn".into(),
        conditions,
        columns: 2,
        panels: vec![
            panel(
                "articulation angle",
                "articulation",
                "deg",
                deg(&rec.articulation_rad, 1.0),
            ),
            panel(
                "left-strut displacement",
                "d_L",
                "m",
                rec.strut_disp_m[0].clone(),
            ),
            panel(
                "front-unit yaw rate",
                "yaw rate",
                "deg/s",
                deg(&rec.front_rate_rad_s[2], -1.0),
            ),
            panel(
                "front-unit lateral acceleration",
                "a_y",
                "m/s²",
                rec.front_lateral_accel_m_s2.iter().map(|a| -a).collect(),
            ),
        ],
    }
}
