//! The registry of checks, one module per chapter's quantities. A check calls the models and
//! the design layer (`afsv_design`) and compares their numbers with the fixtures; it
//! computes no physics itself.

mod ahp;
mod chapter2;
mod chapter4;
mod chapter6;
mod hps;
mod hps_design;
mod sensitivity;
mod terrain;
mod tire;
mod unmodelled;
mod yaw_parameters;
mod yaw_plane;

use super::Ctx;

/// One check: computes rows into the context.
type CheckFn = fn(&mut Ctx) -> Result<(), String>;

/// The registry: (name, fixture ids it covers, computation). The ids let [`super::run`] list the
/// fixtures of a failed check as not reproduced with the error as reason.
pub const CHECKS: &[(&str, &[&str], CheckFn)] = &[
    (
        "ahp_weights",
        &["s4_ahp_w_ii_i", "s4_ahp_w_iii_ii", "s4_ahp_w"],
        ahp::check_ahp,
    ),
    (
        "table_3_1_4_1_parameters",
        &[],
        yaw_parameters::check_yaw_parameters,
    ),
    ("table_6_2_tire", &[], tire::check_tire),
    ("table_2_4_terrain", &[], terrain::check_terrain),
    ("table_6_3_hps_front_axle", &[], hps::check_hps_front),
    (
        "hps_lab",
        &[
            "static_pressure_75mm",
            "static_pressure_100mm",
            "static_pressure_115mm",
            "mid_position_pressure",
            "p_rod_min_compression",
            "s5_min_rod_side_pressure",
            "s5_saturation_pressures",
            "s5_dynamic_qualitative",
        ],
        hps::check_hps_lab,
    ),
    (
        "sensitivity_3_4_3",
        &[
            "s3_sens_a0_arm_length_peak",
            "s3_sens_kl_damping_loaded",
            "s3_sens_muv_damping_loaded",
            "s3_sens_muv_damping_unloaded",
            "s3_sens_kl_minus30_damping",
            "s3_sens_beff_damping",
            "s3_sens_a0_gain",
            "s3_sens_beff_overshoot",
            "s3_sens_beff_minus30_overshoot",
            "s3_sens_kl_muv_overshoot",
            "s3_sens_qualitative_trends",
        ],
        sensitivity::check_sensitivity,
    ),
    (
        "a0_frequency_peak",
        &["s3_sens_a0_frequency_peak"],
        sensitivity::check_a0_peak,
    ),
    (
        "yaw_frequency",
        &["s6_omega_z_unsuspended"],
        yaw_plane::check_yaw_frequency,
    ),
    (
        "yaw_plane_qualitative",
        &[
            "s3_leakage_decay_steady_turn",
            "s3_nonzero_final_articulation_after_pulse",
        ],
        yaw_plane::check_yaw_qualitative,
    ),
    (
        "gain_efficiency",
        &["s4_gain_efficiency_r2"],
        yaw_plane::check_gain_efficiency,
    ),
    ("chapter_4_designs", &[], chapter4::check_chapter4),
    (
        "chapter_2_truck",
        &[
            "s2_drt_smooth",
            "s2_smooth_oscillation_time",
            "s2_drt_rough",
            "s2_sustained_period",
            "s2_t_lift_a4",
            "s2_ay_at_a4_b_prime",
            "s2_ay_range_sustained",
            "s2_drt_rough_vs_smooth_cg",
            "s2_drt_correlation_r2",
            "s2_drt_change_class_a_to_e",
            "s2_drt_change_waviness",
            "s2_drt_change_low_frequency_content",
        ],
        chapter2::check_chapter2,
    ),
    (
        "chapter_6_vehicle",
        &[
            "s6_awz_unsuspended",
            "s6_hps_dominant_frequencies",
            "s6_hps_awz_reduction",
            "s6_dominant_ride_frequencies_unsuspended",
            "s6_sp_drt_unsuspended",
            "s6_sp_lateral_acceleration_range",
            "s6_hps_stability_reduction",
        ],
        chapter6::check_chapter6,
    ),
    (
        "table_6_4_hps_sensitivity",
        &[
            "t6_4_awz_unloaded_a_hc",
            "t6_4_awz_unloaded_a_v",
            "t6_4_awz_unloaded_a_b",
            "t6_4_awz_loaded_a_hc",
            "t6_4_awz_loaded_a_v",
            "t6_4_awz_loaded_a_b",
            "t6_4_sp_drt_loaded_a_hc",
            "t6_4_sp_drt_loaded_a_v",
            "t6_4_sp_drt_loaded_a_b",
            "t6_4_omega_z_loaded_a_hc",
            "t6_4_omega_z_loaded_a_v",
            "t6_4_omega_z_loaded_a_b",
            "s6_hps_a_hc_sensitivity_awz",
            "s6_hps_directional_sensitivity_bound",
            "s6_hps_a_b_trend",
        ],
        hps_design::check_table_6_4,
    ),
    (
        "table_6_5_hps_optimum",
        &[
            "t6_5_a_hc[optimal]",
            "t6_5_a_v[optimal]",
            "t6_5_a_b[optimal]",
            "t6_5_awz",
            "t6_5_sp_drt",
            "t6_5_omega_z",
            "t6_5_d_s",
            "t6_5_objective_f",
            "s6_hps_opt_outcome",
            "s6_hps_opt_hcgz_speed",
            "s6_hps_opt_speed_trends",
        ],
        hps_design::check_hps_optimum,
    ),
    ("not_reproducible", &[], unmodelled::list_not_reproducible),
];

/// One degree in radians.
pub(super) const DEG: f64 = std::f64::consts::PI / 180.0;
/// Speed of the section 3.3/3.4 and chapter 4 tests (50 km/h) in m/s.
pub(super) const TEST_SPEED_M_S: f64 = 50.0 / 3.6;
