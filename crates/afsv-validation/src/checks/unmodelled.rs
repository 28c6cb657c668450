//! Fixtures that need models we do not have (chapter 6 vehicle, optimisations), listed
//! with the reason. The chapter 2 truck is modelled (`roll-truck`, `checks/chapter2.rs`).

use super::Ctx;

/// Fixtures that need models we do not have, with the reason.
pub(super) fn list_not_reproducible(ctx: &mut Ctx) -> Result<(), String> {
    let ch6 = "needs a chapter-6 scenario the 3-D vehicle (vehicle-3d) does not run yet (field measurements, the path change, the speed sweep)";
    let ch6_hps = "needs the chapter-6 HPS sensitivity study on the 3-D vehicle (vehicle-3d); not implemented yet";
    let ch6_opt = "needs the chapter-6 HPS optimisation on the 3-D vehicle; not implemented";
    let ch4_opt = "needs the chapter-4 design optimisation; not implemented";
    let fx = ctx.fx();
    // Table 6.5: the nominal column is the nominal HPS vehicle, the optimal one the optimum.
    for id in [
        "t6_5_awz",
        "t6_5_sp_drt",
        "t6_5_omega_z",
        "t6_5_d_s",
        "t6_5_objective_f",
    ] {
        ctx.not_reproducible(id, Some("nominal"), ch6_hps);
        ctx.not_reproducible(id, Some("optimal"), ch6_opt);
    }
    let ids: Vec<(String, &str)> = fx
        .by_id
        .values()
        .filter(|f| f.kind == "result" || f.kind == "qualitative")
        .filter_map(|f| {
            let id = f.id.as_str();
            let reason = if id.starts_with("s6_hps_opt") || id.starts_with("t6_5_") {
                ch6_opt
            } else if id.starts_with("t6_4_") || id.starts_with("s6_hps_") {
                ch6_hps
            } else if id.starts_with("s6_") {
                ch6
            } else if id.starts_with("s4_") || id.starts_with("t4_") {
                ch4_opt
            } else {
                return None;
            };
            Some((f.id.clone(), reason))
        })
        .collect();
    for (id, reason) in ids {
        // Fixtures (or keys) computed by another check stay as they are.
        if !ctx.results.iter().any(|r| r.id == id) {
            ctx.not_reproducible(&id, None, reason);
        }
    }
    Ok(())
}
