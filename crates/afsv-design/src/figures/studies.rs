//! The `--plot` line figures of the design studies: the roll studies of section 2.4
//! (`afsv roll study`), the D4 speed sweep (`afsv study speed-sweep`), the Table 6.4 HPS
//! sensitivity (`afsv study hps-sensitivity`) and the Fig 4.9 responses of the Chapter 4
//! optimum against the current design (`afsv optimize afs --plot-step|--plot-pulse`).

use crate::hps_sensitivity::{HpsMeasures, HpsSensitivity, HpsVariable};
use crate::SpeedSweep;
use afsv_dynamics::YawRecord;
use afsv_plot::{Chart, Curve};
use roll_truck::studies::{Study, StudyPoint, StudyResult};
use vehicle_3d::Load;

/// A line figure of `curves` with the axis labels as text.
fn lines(title: String, x_label: &str, y_label: &str, log_x: bool, curves: Vec<Curve>) -> Chart {
    Chart::Lines {
        title,
        x_label: x_label.into(),
        y_label: y_label.into(),
        log_x,
        curves,
    }
}

/// Ratio of the largest to the smallest abscissa above which a study's variable is drawn
/// on a logarithmic axis (α_r goes in ×4 steps).
pub const LOG_X_SPAN: f64 = 20.0;

/// The SP-DRT of a roll study as mean, mean - SD and mean + SD per group of points, and
/// for the cg study the smooth-road DRT and the SSF; on a logarithmic abscissa when the
/// study variable spans more than [`LOG_X_SPAN`].
pub fn roll_study(r: &StudyResult) -> Chart {
    let mut groups: Vec<&str> = r.points.iter().map(|p| p.group.as_str()).collect();
    groups.dedup();
    let mut curves = Vec::new();
    for g in &groups {
        let pts: Vec<&StudyPoint> = r.points.iter().filter(|p| p.group == *g).collect();
        let x: Vec<f64> = pts.iter().map(|p| p.x).collect();
        let y = |f: &dyn Fn(&StudyPoint) -> f64| pts.iter().map(|p| f(p)).collect();
        curves.push(Curve::new(
            format!("SP-DRT {g}"),
            x.clone(),
            y(&|p| p.sp_drt_g.mean),
        ));
        curves.push(Curve::new(
            format!("- SD {g}"),
            x.clone(),
            y(&|p| p.sp_drt_g.mean - p.sp_drt_g.sd),
        ));
        curves.push(Curve::new(
            format!("+ SD {g}"),
            x.clone(),
            y(&|p| p.sp_drt_g.mean + p.sp_drt_g.sd),
        ));
        if r.study == Study::CgHeight {
            curves.push(Curve::new(
                "smooth DRT",
                x.clone(),
                y(&|p| p.smooth_drt_g.unwrap_or(f64::NAN)),
            ));
            curves.push(Curve::new("SSF", x, y(&|p| p.ssf)));
        }
    }
    let (lo, hi) = r.points.iter().fold((f64::INFINITY, 0.0_f64), |(a, b), p| {
        (a.min(p.x), b.max(p.x))
    });
    lines(
        format!("rough-terrain SP-DRT over {} seeds", r.seeds.len()),
        r.study.x_label(),
        "lateral acceleration (g) / SSF",
        lo > 0.0 && hi / lo > LOG_X_SPAN,
        curves,
    )
}

/// The D4 sweep: a_wz against speed unloaded and loaded, with the 8 h upper bound of the
/// health guidance caution zone.
pub fn speed_sweep(s: &SpeedSweep) -> Chart {
    let mut curves: Vec<Curve> = [Load::Unloaded, Load::Loaded]
        .iter()
        .map(|&load| {
            Curve::new(
                format!("a_wz {load}"),
                s.of_load(load).map(|p| p.speed_kmh).collect(),
                s.of_load(load).map(|p| p.a_wz_m_s2.mean).collect(),
            )
        })
        .collect();
    let xs: Vec<f64> = s.of_load(Load::Unloaded).map(|p| p.speed_kmh).collect();
    let bound = vec![s.hgcz_upper_m_s2; xs.len()];
    curves.push(Curve::new("8 h HGCZ upper bound", xs, bound));
    lines(
        format!(
            "D4 speed sweep of a_wz (class E, HPS), {} seeds",
            s.seeds.len()
        ),
        "forward speed (km/h)",
        "a_wz (m/s²)",
        false,
        curves,
    )
}

/// One measure of a sensitivity row.
type Pick = fn(&HpsMeasures) -> f64;

/// Table 6.4 as curves: a_wz unloaded and loaded against the change of each area (%),
/// the nominal design at 0 %.
pub fn hps_sensitivity(s: &HpsSensitivity) -> Chart {
    let mut curves = Vec::new();
    for v in HpsVariable::ALL {
        let picks: [(&str, Pick); 2] = [
            ("unloaded", |m| m.a_wz_unloaded_m_s2.mean),
            ("loaded", |m| m.a_wz_loaded_m_s2.mean),
        ];
        for (load, pick) in picks {
            let mut pts: Vec<(f64, f64)> = s
                .rows
                .iter()
                .filter(|r| r.variable == v)
                .map(|r| (100.0 * r.change, pick(&r.measures)))
                .collect();
            pts.push((0.0, pick(&s.nominal)));
            pts.sort_by(|a, b| a.0.total_cmp(&b.0));
            curves.push(Curve::new(
                format!("{} {load}", v.symbol()),
                pts.iter().map(|p| p.0).collect(),
                pts.iter().map(|p| p.1).collect(),
            ));
        }
    }
    lines(
        format!(
            "HPS sensitivity of a_wz (D1, class E, 20 km/h), {} seeds",
            s.seeds.len()
        ),
        "change of the area (%)",
        "a_wz (m/s²)",
        false,
        curves,
    )
}

/// The articulation of the optimum and the current design in one test of Fig 4.9
/// (`title` names it).
pub fn afs_response(title: &str, optimum: &YawRecord, current: &YawRecord) -> Chart {
    lines(
        title.into(),
        "time (s)",
        "articulation angle (deg)",
        false,
        vec![
            Curve::new(
                "optimum (PS/SQP)",
                optimum.time_s.clone(),
                optimum.articulation_deg.clone(),
            ),
            Curve::new(
                "current design",
                current.time_s.clone(),
                current.articulation_deg.clone(),
            ),
        ],
    )
}
