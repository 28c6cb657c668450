//! The numbers section 2.4 reports, derived from a study's points (targets R2.6-R2.12 of
//! the reading note): correlation of rough and smooth DRT over the cg heights, percent
//! changes of the SP-DRT and ratios of the sustained period between the ends of a sweep.

use serde::Serialize;

use crate::studies::{Study, StudyPoint, StudyResult};

/// One derived number with its name and meaning.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Finding {
    /// Name (stable, used by the validation).
    pub name: &'static str,
    /// Value (NaN if the points do not give it; printed as null).
    pub value: f64,
    /// What it is.
    pub meaning: &'static str,
}

fn finding(name: &'static str, value: f64, meaning: &'static str) -> Finding {
    Finding {
        name,
        value,
        meaning,
    }
}

/// Coefficient of determination r² of a least-squares line through `(x, y)`.
pub fn r_squared(x: &[f64], y: &[f64]) -> f64 {
    let n = x.len() as f64;
    let (mx, my) = (x.iter().sum::<f64>() / n, y.iter().sum::<f64>() / n);
    let sxy: f64 = x.iter().zip(y).map(|(a, b)| (a - mx) * (b - my)).sum();
    let sxx: f64 = x.iter().map(|a| (a - mx).powi(2)).sum();
    let syy: f64 = y.iter().map(|b| (b - my).powi(2)).sum();
    sxy * sxy / (sxx * syy)
}

fn pct(from: f64, to: f64) -> f64 {
    100.0 * (to / from - 1.0)
}

fn in_group<'a>(points: &'a [StudyPoint], group_prefix: &str) -> Vec<&'a StudyPoint> {
    points
        .iter()
        .filter(|p| p.group.starts_with(group_prefix))
        .collect()
}

/// The change between the points of `group` at `x_from` and `x_to`: SP-DRT in percent
/// and the ratio of the sustained periods.
fn change(points: &[StudyPoint], group: &str, x_from: f64, x_to: f64) -> (f64, f64) {
    let pts = in_group(points, group);
    let at = |x: f64| pts.iter().find(|p| (p.x / x - 1.0).abs() < 1e-9);
    match (at(x_from), at(x_to)) {
        (Some(a), Some(b)) => (
            pct(a.sp_drt_g.mean, b.sp_drt_g.mean),
            b.sustained_period_s.mean / a.sustained_period_s.mean,
        ),
        _ => (f64::NAN, f64::NAN),
    }
}

impl StudyResult {
    /// The derived numbers of this study (module docs).
    pub fn findings(&self) -> Vec<Finding> {
        let p = &self.points;
        match self.study {
            Study::CgHeight => cg_findings(p),
            Study::Roughness => {
                let e = terrain_psd::IsoClass::E.alpha_r();
                let a = terrain_psd::IsoClass::A.alpha_r();
                let (drt, dt) = change(p, "m_c = 0.3", a, e);
                let at_e = |g: &str| {
                    in_group(p, g)
                        .iter()
                        .find(|q| (q.x / e - 1.0).abs() < 1e-9)
                        .map_or(f64::NAN, |q| q.sp_drt_g.mean)
                };
                vec![
                    finding(
                        "drt_change_a_to_e_pct",
                        drt,
                        "SP-DRT change class A -> E at m_c = 0.3 (%)",
                    ),
                    finding(
                        "sustained_period_ratio_e_over_a",
                        dt,
                        "ΔT(E) / ΔT(A) at m_c = 0.3",
                    ),
                    finding(
                        "sp_drt_e_mc_0_3_g",
                        at_e("m_c = 0.3"),
                        "SP-DRT at class E, m_c = 0.3 (g)",
                    ),
                    finding(
                        "sp_drt_e_mc_0_9_g",
                        at_e("m_c = 0.9"),
                        "SP-DRT at class E, m_c = 0.9 (g)",
                    ),
                ]
            }
            Study::Waviness => {
                let (drt, dt) = change(p, "class E", 1.6, 2.4);
                vec![
                    finding(
                        "drt_change_w_1_6_to_2_4_pct",
                        drt,
                        "SP-DRT change w = 1.6 -> 2.4 (%)",
                    ),
                    finding("sustained_period_ratio_w", dt, "ΔT(w = 2.4) / ΔT(w = 1.6)"),
                ]
            }
            Study::Trucks => trucks_findings(p),
            Study::Band => {
                let (low, dt_low) = change(p, "lower", 0.25, 0.02);
                let (high, _) = change(p, "upper", 5.0, 10.0);
                vec![
                    finding(
                        "drt_change_low_frequency_pct",
                        low,
                        "SP-DRT of 0.02-5 against 0.25-5 cycles/m (%)",
                    ),
                    finding(
                        "sustained_period_ratio_low_frequency",
                        dt_low,
                        "ΔT(0.02-5) / ΔT(0.25-5)",
                    ),
                    finding(
                        "drt_change_high_frequency_pct",
                        high,
                        "SP-DRT of 0.02-10 against 0.02-5 cycles/m (%)",
                    ),
                ]
            }
        }
    }
}

fn trucks_findings(p: &[StudyPoint]) -> Vec<Finding> {
    let by = |group: &str| p.iter().find(|q| q.group == group);
    let ratio = |f: &dyn Fn(&StudyPoint) -> f64, num: &str, den: &str| match (by(num), by(den)) {
        (Some(a), Some(b)) => f(a) / f(b),
        _ => f64::NAN,
    };
    vec![
        finding(
            "smooth_drt_plausible_over_calibrated",
            ratio(
                &|q| q.smooth_drt_g.unwrap_or(f64::NAN),
                "plausible",
                "calibrated",
            ),
            "smooth DRT of the plausible truck / of the calibrated one",
        ),
        finding(
            "sp_drt_plausible_over_calibrated",
            ratio(&|q| q.sp_drt_g.mean, "plausible", "calibrated"),
            "SP-DRT (class E) of the plausible truck / of the calibrated one",
        ),
        finding(
            "sustained_period_plausible_over_calibrated",
            ratio(&|q| q.sustained_period_s.mean, "plausible", "calibrated"),
            "ΔT (class E) of the plausible truck / of the calibrated one",
        ),
        finding(
            "peak_ay_calibrated_stops_removed_over_engaged",
            ratio(&|q| q.peak_ay_g.mean, "calibrated, no stops", "calibrated"),
            "peak a_y (class E) of the calibrated truck with its stops out of reach / with them",
        ),
    ]
}

fn cg_findings(p: &[StudyPoint]) -> Vec<Finding> {
    let pairs: Vec<(f64, f64)> = p
        .iter()
        .filter_map(|q| q.smooth_drt_g.map(|s| (s, q.sp_drt_g.mean)))
        .filter(|(s, r)| s.is_finite() && r.is_finite())
        .collect();
    let (smooth, rough): (Vec<f64>, Vec<f64>) = pairs.iter().copied().unzip();
    let below = pairs.len() == p.len() && pairs.iter().all(|(s, r)| r < s);
    let gap = |q: Option<&StudyPoint>| {
        q.and_then(|q| q.smooth_drt_g.map(|s| pct(s, q.sp_drt_g.mean)))
            .unwrap_or(f64::NAN)
    };
    let nominal = p.get(p.len() / 2);
    let dt = |q: Option<&StudyPoint>| q.map_or(f64::NAN, |q| q.sustained_period_s.mean);
    let monotone = |f: &dyn Fn(&StudyPoint) -> f64| p.windows(2).all(|w| f(&w[1]) < f(&w[0]));
    let as_flag = |b: bool| if b { 1.0 } else { 0.0 };
    vec![
        finding(
            "drt_correlation_r2",
            r_squared(&smooth, &rough),
            "r² of rough SP-DRT against smooth DRT over the cg heights",
        ),
        finding(
            "rough_below_smooth_everywhere",
            as_flag(below),
            "1 if the rough SP-DRT is below the smooth DRT at every height",
        ),
        finding(
            "gap_lowest_cg_pct",
            gap(p.first()),
            "rough against smooth at the lowest cg (%)",
        ),
        finding(
            "gap_highest_cg_pct",
            gap(p.last()),
            "rough against smooth at the highest cg (%)",
        ),
        finding(
            "sustained_period_ratio_highest_over_nominal",
            dt(p.last()) / dt(nominal),
            "ΔT at the highest cg / ΔT at the nominal cg",
        ),
        finding(
            "smooth_drt_decreasing",
            as_flag(monotone(&|q| q.smooth_drt_g.unwrap_or(f64::NAN))),
            "1 if the smooth DRT falls with every cg step",
        ),
        finding(
            "rough_drt_decreasing",
            as_flag(monotone(&|q| q.sp_drt_g.mean)),
            "1 if the rough SP-DRT falls with every cg step",
        ),
        finding(
            "ssf_decreasing",
            as_flag(monotone(&|q| q.ssf)),
            "1 if the SSF falls with every cg step",
        ),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn r_squared_of_a_line_is_one_and_of_noise_small() {
        assert!((r_squared(&[1.0, 2.0, 3.0], &[2.0, 4.1, 6.0]) - 1.0).abs() < 1e-2);
        assert!(r_squared(&[1.0, 2.0, 3.0, 4.0], &[1.0, -1.0, -1.0, 1.0]) < 1e-12);
    }
}
