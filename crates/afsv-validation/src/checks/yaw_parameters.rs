//! Tables 3.1, 4.1, 4.2 (design bounds), 4.3/4.4 ("current" column) and 3.2 (test speeds)
//! against the nominal parameter sets of the yaw-plane vehicle and the AFS and the design
//! bounds of `afsv_design`. Every row echoes an input ([`Echo::Input`]): these numbers are
//! what the parameter sets carry, not model results.

use super::{Ctx, DEG};
use crate::Echo;
use afs_hydraulics::params::{
    MU_V_TABLE_UNIT, VALVE_A0_TABLE_UNIT, VALVE_AM_TABLE_UNIT, VALVE_AV_TABLE_UNIT,
};
use afs_hydraulics::AfsParams;
use afsv_design::{AfsDesign, AfsDesignBounds};
use afsv_dynamics::{table_3_2_speeds_kmh, FieldCourse, Load, VehicleParams};

/// Table 3.1 / 4.1 / 4.2 and Table 3.2 against our nominal parameter sets and bounds.
pub(super) fn check_yaw_parameters(ctx: &mut Ctx) -> Result<(), String> {
    vehicle_rows(ctx);
    afs_rows(ctx);
    design_rows(ctx);
    relaxed_bound_row(ctx);
    speed_rows(ctx);
    Ok(())
}

/// Tables 3.1 and 4.1: the yaw-plane vehicle of each load (`VehicleParams::nominal`).
fn vehicle_rows(ctx: &mut Ctx) {
    let kn_deg = |v: f64| v * DEG / 1e3;
    let note = "VehicleParams::nominal";
    for load in Load::ALL {
        let v = VehicleParams::nominal(load);
        let k = Some(load.name());
        for t in ["t3_1", "t4_1"] {
            for (name, val) in [
                ("m_f", v.m_f_kg),
                ("m_r", v.m_r_kg),
                ("i_f", v.i_f_kg_m2),
                ("i_r", v.i_r_kg_m2),
                ("l_f1", v.l_f1_m),
                ("l_f2", v.l_f2_m),
                ("l_r1", v.l_r1_m),
                ("l_r2", v.l_r2_m),
            ] {
                ctx.echo(Echo::Input, &format!("{t}_{name}"), k, None, val, note);
            }
        }
        for (name, val) in [
            ("c_alpha_f", kn_deg(v.c_alpha_f_n_per_rad)),
            ("c_alpha_r", kn_deg(v.c_alpha_r_n_per_rad)),
            ("k_mzf", kn_deg(v.k_mz_f_nm_per_rad)),
            ("k_mzr", kn_deg(v.k_mz_r_nm_per_rad)),
            ("sigma_y", v.relaxation_length_m),
            ("half_track", v.half_track_m),
        ] {
            ctx.echo(Echo::Input, &format!("t3_1_{name}"), k, None, val, note);
        }
    }
}

/// Tables 3.1 and 4.1: the AFS (`AfsParams::nominal`).
fn afs_rows(ctx: &mut Ctx) {
    let a = AfsParams::nominal();
    let note = "AfsParams::nominal (table units for the unstated ones, docs/afs-hydraulics.md)";
    let common = [
        ("a0", a.a0_rad / DEG),
        ("l1", a.l1_m),
        ("l2", a.l2_m),
        ("a_c", a.piston_area_m2 * 1e4),
        ("a_r", a.annulus_area_m2 * 1e4),
        ("b_eff", a.bulk_modulus_pa / 1e9),
    ];
    for t in ["t3_1", "t4_1"] {
        for (name, val) in common {
            ctx.echo(Echo::Input, &format!("{t}_{name}"), None, None, val, note);
        }
    }
    for (name, val) in [
        ("x0", a.dead_band_rad / DEG),
        ("v0", a.dead_volume_m3 * 1e3),
        ("p_s", a.supply_pressure_pa / 1e6),
        ("p0", a.reservoir_pressure_pa / 1e6),
        ("mu_v", a.seal_viscous_n_s_m / MU_V_TABLE_UNIT),
        ("k_l0", a.leak_const),
        ("k_l", a.leak_velocity),
        ("k_theta", a.gerotor_displacement * DEG * 1e6),
        ("k_v", a.return_factor),
        ("eta_g", a.gerotor_efficiency),
    ] {
        ctx.echo(Echo::Input, &format!("t3_1_{name}"), None, None, val, note);
    }
    for (name, val) in [
        ("a_0", a.valve_a0_per_pa / VALVE_A0_TABLE_UNIT),
        ("a_m", a.valve_am / VALVE_AM_TABLE_UNIT),
        ("a_v", a.valve_av / VALVE_AV_TABLE_UNIT),
    ] {
        ctx.echo(Echo::Input, &format!("t4_1_{name}"), None, None, val, note);
    }
}

/// Table 4.2 (nominal column) and the "current" column of Tables 4.3/4.4: the design vector
/// of `AfsParams::nominal` (`afsv_design::AfsDesign`).
fn design_rows(ctx: &mut Ctx) {
    let current = AfsDesign::of(&AfsParams::nominal()).table_units();
    let bounds = AfsDesignBounds::table_4_2();
    let (lower, upper) = (bounds.lower.table_units(), bounds.upper.table_units());
    let note = "AfsParams::nominal (table units for the unstated ones, docs/afs-hydraulics.md)";
    let bound_note = "afsv_design::AfsDesignBounds::table_4_2";
    for (i, name) in ["a0", "l1", "l2", "a_v", "b_eff"].into_iter().enumerate() {
        let id = format!("t4_2_{name}_bounds");
        let val = current[i];
        ctx.echo(Echo::Input, &id, Some("nominal"), None, val, note);
        ctx.echo(Echo::Input, &id, Some("lower"), None, lower[i], bound_note);
        ctx.echo(Echo::Input, &id, Some("upper"), None, upper[i], bound_note);
        for t in ["t4_3", "t4_4"] {
            ctx.echo(
                Echo::Input,
                &format!("{t}_opt_{name}"),
                Some("current"),
                None,
                val,
                "current design = AfsParams::nominal",
            );
        }
    }
}

/// Section 4.4: the relaxed B_eff bound of Table 4.4's runs.
fn relaxed_bound_row(ctx: &mut Ctx) {
    ctx.echo(
        Echo::Input,
        "s4_relaxed_b_eff_bound",
        None,
        None,
        AfsDesignBounds::table_4_2_relaxed().upper.table_units()[4],
        "afsv_design::AfsDesignBounds::table_4_2_relaxed (1.3 x the nominal 1.6 GPa)",
    );
}

/// Table 3.2: mean test speeds.
fn speed_rows(ctx: &mut Ctx) {
    let note = "afsv_dynamics::table_3_2_speeds_kmh (mean speeds)";
    for (id, course, load, i) in [
        (
            "t3_2_speed_steady_turn_loaded",
            FieldCourse::SteadyTurn,
            Load::Loaded,
            0,
        ),
        (
            "t3_2_speed_steady_turn_unloaded_a",
            FieldCourse::SteadyTurn,
            Load::Unloaded,
            0,
        ),
        (
            "t3_2_speed_steady_turn_unloaded_b",
            FieldCourse::SteadyTurn,
            Load::Unloaded,
            1,
        ),
        (
            "t3_2_speed_path_change_loaded",
            FieldCourse::PathChange,
            Load::Loaded,
            0,
        ),
        (
            "t3_2_speed_path_change_unloaded_a",
            FieldCourse::PathChange,
            Load::Unloaded,
            0,
        ),
        (
            "t3_2_speed_path_change_unloaded_b",
            FieldCourse::PathChange,
            Load::Unloaded,
            1,
        ),
    ] {
        let s = table_3_2_speeds_kmh(course, load)
            .get(i)
            .copied()
            .unwrap_or(f64::NAN);
        ctx.echo(Echo::Input, id, Some("mean"), None, s, note);
    }
}
