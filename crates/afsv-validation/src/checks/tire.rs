//! Table 6.2: the 29.5R29 tire.

use super::{Ctx, DEG};
use crate::Echo;
use tire_fiala::cornering::TABLE_6_2_STATIC_LOADS_N;

/// Table 6.2 against `TireParams::nominal`, and its cornering-stiffness table evaluated at
/// the static tire loads the table was built from.
pub(super) fn check_tire(ctx: &mut Ctx) -> Result<(), String> {
    let p = tire_fiala::TireParams::nominal();
    let note = "TireParams::nominal";
    for (id, variant, v) in [
        ("t6_2_free_radius", None, p.unloaded_radius_m),
        ("t6_2_width", None, p.width_m),
        ("t6_2_charge_pressure", None, p.charge_pressure_pa / 1e5),
        (
            "t6_2_vertical_damping",
            None,
            p.vertical_damping_n_s_per_m / 1e3,
        ),
        (
            "t6_2_relaxation_length",
            Some("lateral"),
            p.lateral_relaxation_length_m,
        ),
        (
            "t6_2_relaxation_length",
            Some("longitudinal"),
            p.longitudinal_relaxation_length_m,
        ),
    ] {
        ctx.echo(Echo::Input, id, None, variant, v, note);
    }
    let table = p.cornering_table().map_err(|e| e.to_string())?;
    let [front_unloaded, front_loaded, rear_unloaded, rear_loaded] = TABLE_6_2_STATIC_LOADS_N;
    for (id, key, fz) in [
        ("t6_2_front_cornering_stiffness", "loaded", front_loaded),
        ("t6_2_front_cornering_stiffness", "unloaded", front_unloaded),
        ("t6_2_rear_cornering_stiffness", "loaded", rear_loaded),
        ("t6_2_rear_cornering_stiffness", "unloaded", rear_unloaded),
    ] {
        ctx.echo(
            Echo::ByConstruction,
            id,
            Some(key),
            None,
            table.at(fz) * DEG / 1e3,
            format!(
                "nominal C_alpha(F_z) table at the static tire load {:.1} kN derived from Table 6.1 (tire_fiala::cornering::TABLE_6_2_STATIC_LOADS_N): the table holds Table 6.2's values at these loads",
                fz / 1e3
            ),
        );
    }
    Ok(())
}
