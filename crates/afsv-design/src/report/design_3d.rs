//! The report of the D1-D3 design measures of the 3-D vehicle
//! ([`crate::design_3d::DesignMeasures`]) as a terminal table, one column per front axle
//! (`afsv evaluate`); their JSON is the type's own serialisation with
//! [`crate::design_3d::hps_changes`].

use super::wrap_note;
use crate::design_3d::{settled, AxleSummary, DesignMeasures, RideSummary};
use perf_measures::iso2631::HgczZone;
use vehicle_3d::scenarios::Spread;

/// The relative change from `base` to `with` in percent, marked when it lies within the
/// seed spread ([`settled`]).
fn change(with: &Spread, base: &Spread) -> String {
    let pct = 100.0 * (with.mean / base.mean - 1.0);
    if settled(with, base) {
        format!("{pct:+.1} %")
    } else {
        format!("{pct:+.1} % (within the seed spread)")
    }
}

/// `mean ± sd` with `digits` decimals.
fn pm(s: &Spread, digits: usize) -> String {
    format!("{:.digits$} ± {:.digits$}", s.mean, s.sd)
}

fn zone_text(z: HgczZone) -> &'static str {
    match z {
        HgczZone::Below => "below the HGCZ",
        HgczZone::Within => "within the HGCZ (caution)",
        HgczZone::Above => "above the HGCZ (health risk likely)",
    }
}

/// The assessment as a terminal table with units and verdicts: one column per front axle.
pub fn to_text(d: &DesignMeasures) -> String {
    let mut s = format!(
        "3-D vehicle (Chapter 6): design measures, mean ± SD over {} terrain seeds (class E, m_c 0.3)\n",
        d.seeds.len()
    );
    let mut cols = vec![("rigid front axle", &d.unsuspended)];
    if let Some(h) = &d.nominal_hps {
        let head = match d.link {
            None => "front-axle HPS",
            Some(vehicle_3d::interconnect::Link::Roll(_)) => "HPS + roll link",
            Some(vehicle_3d::interconnect::Link::Pitch(_)) => "HPS + pitch link",
        };
        cols.push((head, h));
    }
    let row = |name: &str, f: &dyn Fn(&AxleSummary) -> String, unit: &str| {
        let cells: String = cols.iter().map(|(_, a)| format!(" {:>18}", f(a))).collect();
        format!("  {name:<36}{cells}  {unit}\n")
    };
    let heads: String = cols.iter().map(|(h, _)| format!(" {h:>18}")).collect();
    s += &format!("  {:<36}{heads}  unit\n", "measure");
    s += &row(
        "a_wz unloaded (D1, 20 km/h)",
        &|a| pm(&a.ride_unloaded.a_wz_m_s2, 3),
        "m/s²",
    );
    s += &row(
        "a_wz loaded (D1, 20 km/h)",
        &|a| pm(&a.ride_loaded.a_wz_m_s2, 3),
        "m/s²",
    );
    let travel = |r: &RideSummary| r.strut_travel_m.as_ref().map_or("-".into(), |t| pm(t, 3));
    if d.nominal_hps.is_some() {
        s += &row(
            "strut travel d_s unloaded",
            &|a| travel(&a.ride_unloaded),
            "m",
        );
        s += &row("strut travel d_s loaded", &|a| travel(&a.ride_loaded), "m");
    }
    s += &row(
        "SP-DRT (D2, 50 km/h, loaded)",
        &|a| pm(&a.sp_drt_m_s2, 2),
        "m/s²",
    );
    s += &row(
        "omega_z (D3, 50 km/h, loaded)",
        &|a| format!("{:.2}", a.yaw.omega_z_hz),
        "Hz",
    );
    s += &row(
        "yaw damping ratio (D3 decay fit)",
        &|a| format!("{:.3}", a.yaw.damping_ratio),
        "-",
    );
    s += &format!(
        "  ride verdict, 8 h HGCZ {:.2}-{:.2} m/s²:\n",
        d.hgcz_8h_m_s2.0, d.hgcz_8h_m_s2.1
    );
    for (name, a) in &cols {
        s += &format!(
            "    {name}: {} unloaded, {} loaded\n",
            zone_text(a.ride_unloaded.hgcz_8h),
            zone_text(a.ride_loaded.hgcz_8h),
        );
    }
    if let Some(h) = &d.nominal_hps {
        let u = &d.unsuspended;
        s += &format!(
            "  HPS change: a_wz {} unloaded, {} loaded; SP-DRT {}; omega_z {:+.1} %\n",
            change(&h.ride_unloaded.a_wz_m_s2, &u.ride_unloaded.a_wz_m_s2),
            change(&h.ride_loaded.a_wz_m_s2, &u.ride_loaded.a_wz_m_s2),
            change(&h.sp_drt_m_s2, &u.sp_drt_m_s2),
            100.0 * (h.yaw.omega_z_hz / u.yaw.omega_z_hz - 1.0),
        );
        s += "  (\"within the seed spread\": the change is less than twice its standard error over\n   the seeds, so its sign is not settled; run more --seeds. D3 runs once, on smooth\n   ground: omega_z and zeta have no seed spread)\n";
    } else {
        s += "  (the description gives the front axle no strut: no HPS column)\n";
    }
    let yaws: Vec<_> = cols.iter().map(|(_, a)| a.yaw).collect();
    if let Some(c) = yaw_fit_caveat(&yaws) {
        s += &wrap_note(&format!("note on omega_z and zeta (D3): {c}"));
    }
    s + "\n"
}

/// The caveat of the runs' single-mode yaw fits: the worst seed's ([`vehicle_3d::scenarios::YawMeasures::fit_caveat`]).
pub fn yaw_fit_caveat(measures: &[vehicle_3d::scenarios::YawMeasures]) -> Option<String> {
    measures
        .iter()
        .max_by(|a, b| a.fit_residual_to_noise.total_cmp(&b.fit_residual_to_noise))
        .and_then(vehicle_3d::scenarios::YawMeasures::fit_caveat)
}
