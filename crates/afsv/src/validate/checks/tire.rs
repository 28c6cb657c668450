//! Table 6.2: the 29.5R29 tire.

use super::{Ctx, DEG};

/// Table 6.2 against `TireParams::nominal`, and its cornering stiffness evaluated at the
/// static tire loads derived from Table 6.1 (pitch-rigid articulation joint).
pub(super) fn check_tire(ctx: &mut Ctx) -> Result<(), String> {
    let p = tire_fiala::TireParams::nominal();
    let note = "TireParams::nominal";
    ctx.compare("t6_2_free_radius", None, None, p.unloaded_radius_m, note);
    ctx.compare("t6_2_width", None, None, p.width_m, note);
    ctx.compare(
        "t6_2_charge_pressure",
        None,
        None,
        p.charge_pressure_pa / 1e5,
        note,
    );
    let table = p.cornering_table().map_err(|e| e.to_string())?;
    let fx = ctx.fx();
    let n = |id: &str| fx.num(id, None);
    let g = 9.81;
    let x_front_cg = n("t6_1_front_axle_to_joint")? - n("t6_1_front_unit_cg_to_joint")?;
    let x_rear_cg = n("t6_1_front_axle_to_joint")? + n("t6_1_rear_unit_cg_to_joint")?;
    let x_payload = n("t6_1_front_axle_to_joint")? + n("t6_1_payload_cg_to_joint")?;
    let wheelbase = n("t6_1_wheel_base")?;
    for (key, payload) in [("loaded", n("t6_1_payload_mass")?), ("unloaded", 0.0)] {
        let masses = [
            (n("t6_1_front_unit_mass")?, x_front_cg),
            (n("t6_1_rear_unit_mass")?, x_rear_cg),
            (payload, x_payload),
        ];
        let total: f64 = masses.iter().map(|m| m.0).sum();
        let moment: f64 = masses.iter().map(|(m, x)| m * x).sum();
        let rear_tire = moment / wheelbase * g / 2.0;
        let front_tire = total * g / 2.0 - rear_tire;
        for (id, fz) in [
            ("t6_2_front_cornering_stiffness", front_tire),
            ("t6_2_rear_cornering_stiffness", rear_tire),
        ] {
            ctx.compare(
                id,
                Some(key),
                None,
                table.at(fz) * DEG / 1e3,
                format!(
                    "nominal C_alpha(F_z) table at the Table 6.1 static tire load {:.1} kN",
                    fz / 1e3
                ),
            );
        }
    }
    Ok(())
}
