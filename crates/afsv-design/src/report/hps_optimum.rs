//! The report of `afsv optimize hps` (Chapter 6, [`crate::HpsOptimum`]) as text: the
//! nominal and the optimum design with their rides and re-evaluation; its JSON is the type's
//! own serialisation (with the D4 sweep of the optimum when it was run), and whether the
//! optimum earned its name.

use super::num;
use crate::HpsOptimum;

/// The report as JSON: the result's own serialisation, with the D4 `sweep` of the optimum
/// under `speed_sweep` when it was run.
pub fn to_json(
    r: &HpsOptimum,
    sweep: Option<&crate::SpeedSweep>,
) -> Result<serde_json::Value, serde_json::Error> {
    let mut v = serde_json::to_value(r)?;
    if let Some(s) = sweep {
        v["speed_sweep"] = serde_json::to_value(s)?;
    }
    Ok(v)
}

/// Whether the optimum is one: an error naming the best a_wz when no design met the a_wz
/// limit of Eq 6.20 on the search seed (the best found is then not an optimum).
pub fn earned(r: &HpsOptimum) -> Result<(), String> {
    if r.feasible {
        return Ok(());
    }
    Err(format!(
        "no design met the a_wz limit of Eq 6.20 on the search seed (best a_wz {} m/s²); the best found is printed, not an optimum (more generations or another vehicle)",
        num(r.optimum_ride.a_wz_m_s2, 1.0, 3)
    ))
}

/// The optimum against the nominal design: the Eq 6.19 areas, a_wz and d_s on the search
/// seed, F, and the measures over the re-evaluation seeds.
pub fn text(r: &HpsOptimum) -> String {
    let (n, o) = (&r.nominal_design, &r.design);
    let (an, ao) = (&r.nominal_over_seeds, &r.optimum_over_seeds);
    // (row, nominal, optimum, decimals)
    let rows = [
        ("A_hc (m²)".to_string(), n.a_hc, o.a_hc, 4),
        ("A_v (mm²)".into(), n.a_v * 1e6, o.a_v * 1e6, 2),
        ("A_b (mm²)".into(), n.a_b * 1e6, o.a_b * 1e6, 2),
        (
            "a_wz, search seed (m/s²)".into(),
            r.nominal_ride.a_wz_m_s2,
            r.optimum_ride.a_wz_m_s2,
            3,
        ),
        (
            "d_s, search seed (m)".into(),
            r.nominal_ride.d_s_m,
            r.optimum_ride.d_s_m,
            4,
        ),
        ("F (Eq 6.19)".into(), 2.0, r.objective, 3),
        (
            format!("a_wz, {} seeds (m/s²)", an.a_wz_m_s2.n),
            an.a_wz_m_s2.mean,
            ao.a_wz_m_s2.mean,
            3,
        ),
        (
            "SP-DRT loaded (m/s²)".into(),
            an.sp_drt_m_s2.mean,
            ao.sp_drt_m_s2.mean,
            2,
        ),
        (
            "omega_z loaded (Hz)".into(),
            an.omega_z_hz,
            ao.omega_z_hz,
            2,
        ),
    ];
    let mut s = format!(
        "HPS design (Eq 6.19: F = a_wz/a_wzn + d_s/d_sn, a_wz <= {} m/s²), unloaded, 20 km/h, class E, terrain seed {}\n",
        r.settings.a_wz_limit_m_s2, r.settings.terrain_seed
    );
    s += &format!("  {:<26} {:>12} {:>12}\n", "", "nominal", "optimum");
    for (name, a, b, digits) in rows {
        s += &format!(
            "  {name:<26} {:>12} {:>12}\n",
            num(a, 1.0, digits),
            num(b, 1.0, digits)
        );
    }
    s += &format!(
        "  {} vehicle runs in the search; the optimum is {}\n",
        r.evaluations,
        if r.feasible {
            "feasible"
        } else {
            "NOT feasible (a_wz above the limit)"
        }
    );
    s
}
