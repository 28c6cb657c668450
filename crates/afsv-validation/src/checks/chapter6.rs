//! Chapter 6: the integrated 3-D vehicle of `vehicle-3d` against sections 6.3-6.5
//! (fixtures `s6_*`). Rough-terrain numbers are means over [`VALIDATION_SEEDS`] terrain
//! seeds (`afsv vehicle` uses 10 or more), the same seeds for the unsuspended and the HPS
//! vehicle (common random numbers); with so few seeds they scatter by a few percent.

use super::Ctx;
use vehicle_3d::scenarios::{
    ride_over_seeds, roll_over_seeds, yaw, RideMeasures, RideSpec, RollSpec, Spread, TerrainSpec,
    YawSpec,
};
use vehicle_3d::{FrontAxle, Load, VehicleParams};

/// Terrain seeds per rough-terrain number (few, so that the validation stays fast).
pub(super) const VALIDATION_SEEDS: u64 = 3;

fn seeds() -> Vec<u64> {
    (1..=VALIDATION_SEEDS).collect()
}

fn spread(values: &[f64]) -> Result<Spread, String> {
    Spread::of(values).map_err(|e| e.to_string())
}

fn ride(p: &VehicleParams, spec: &RideSpec) -> Result<Vec<RideMeasures>, String> {
    ride_over_seeds(p, spec, &seeds()).map_err(|e| e.to_string())
}

fn mean_of(m: &[RideMeasures], f: fn(&RideMeasures) -> f64) -> Result<Spread, String> {
    spread(&m.iter().map(f).collect::<Vec<_>>())
}

fn note(s: &Spread, what: &str) -> String {
    format!(
        "{what}; mean ± SD over {} seeds: {:.3} ± {:.3}",
        s.n, s.mean, s.sd
    )
}

/// The vertical and pitch PSD peaks (mean over the seeds of `m`), with their keys.
fn peaks(m: &[RideMeasures]) -> Result<[(&'static str, Spread); 2], String> {
    Ok([
        ("vertical", mean_of(m, |m| m.vertical_peak_hz)?),
        ("pitch", mean_of(m, |m| m.pitch_peak_hz)?),
    ])
}

/// The chapter-6 rows (module docs).
pub(super) fn check_chapter6(ctx: &mut Ctx) -> Result<(), String> {
    let p = VehicleParams::nominal();
    // D1 ride, unsuspended and nominal HPS, both loads
    let mut awz = [[f64::NAN; 2]; 2];
    for (i, load) in [Load::Unloaded, Load::Loaded].into_iter().enumerate() {
        for (j, axle) in [FrontAxle::Rigid, FrontAxle::Suspended]
            .into_iter()
            .enumerate()
        {
            let m = ride(&p, &RideSpec::d1(load, axle))?;
            let a = mean_of(&m, |m| m.a_wz_m_s2)?;
            awz[i][j] = a.mean;
            if load == Load::Unloaded && axle == FrontAxle::Rigid {
                ctx.cache.rigid_awz_unloaded = Some(a.mean);
            }
            if axle == FrontAxle::Rigid {
                ctx.compare(
                    "s6_awz_unsuspended",
                    Some(&load.to_string()),
                    None,
                    a.mean,
                    note(
                        &a,
                        "D1: class E, m_c 0.3, 100 m at 20 km/h, W_k at the cab point",
                    ),
                );
            } else {
                for (key, s) in peaks(&m)? {
                    ctx.compare(
                        "s6_hps_dominant_frequencies",
                        Some(key),
                        Some(&load.to_string()),
                        s.mean,
                        note(
                            &s,
                            "D1 with the nominal HPS: Welch PSD peak within 0.5-10 Hz",
                        ),
                    );
                }
            }
        }
    }
    for (i, key) in ["unloaded", "loaded"].into_iter().enumerate() {
        ctx.compare(
            "s6_hps_awz_reduction",
            Some(key),
            None,
            100.0 * (awz[i][1] / awz[i][0] - 1.0),
            format!(
                "a_wz {:.3} (HPS) vs {:.3} m/s² (unsuspended), same seeds",
                awz[i][1], awz[i][0]
            ),
        );
    }
    // V1/V2: dominant frequencies on class C at the test speeds, 200 m
    for (load, speed, prefix) in [
        (Load::Loaded, 16.0, "loaded"),
        (Load::Unloaded, 18.0, "unloaded"),
    ] {
        let spec = RideSpec {
            speed_kmh: speed,
            length_m: 200.0,
            terrain: TerrainSpec {
                class: terrain_psd::IsoClass::C,
                ..TerrainSpec::default()
            },
            ..RideSpec::d1(load, FrontAxle::Rigid)
        };
        let m = ride(&p, &spec)?;
        for (key, s) in peaks(&m)? {
            ctx.compare(
                "s6_dominant_ride_frequencies_unsuspended",
                Some(&format!("{prefix}_{key}")),
                None,
                s.mean,
                note(
                    &s,
                    &format!("class C, 200 m at {speed} km/h, Welch PSD peak within 0.5-10 Hz"),
                ),
            );
        }
    }
    roll_and_yaw_rows(ctx, &p)
}

/// D2 and D3, unsuspended and with the nominal HPS.
fn roll_and_yaw_rows(ctx: &mut Ctx, p: &VehicleParams) -> Result<(), String> {
    let mut sp = [f64::NAN; 2];
    let mut wz = [f64::NAN; 2];
    for (j, axle) in [FrontAxle::Rigid, FrontAxle::Suspended]
        .into_iter()
        .enumerate()
    {
        let runs = roll_over_seeds(p, &RollSpec::d2(axle), &seeds()).map_err(|e| e.to_string())?;
        let s = spread(&runs.iter().map(|m| m.sp_drt_m_s2).collect::<Vec<_>>())?;
        sp[j] = s.mean;
        let (_, y) = yaw(p, &YawSpec::d3(axle), 0).map_err(|e| e.to_string())?;
        wz[j] = y.omega_z_hz;
        if axle == FrontAxle::Rigid {
            ctx.compare(
                "s6_sp_drt_unsuspended",
                None,
                None,
                s.mean,
                note(
                    &s,
                    "D2: ramp 5 deg/s at 50 km/h, loaded, class E, to rear-unit rollover",
                ),
            );
            for (key, f) in [
                (
                    "min",
                    (|m: &vehicle_3d::scenarios::RollMeasures| m.sustained_range_m_s2.0)
                        as fn(&vehicle_3d::scenarios::RollMeasures) -> f64,
                ),
                ("max", |m: &vehicle_3d::scenarios::RollMeasures| {
                    m.sustained_range_m_s2.1
                }),
            ] {
                let r = spread(&runs.iter().map(f).collect::<Vec<_>>())?;
                ctx.compare(
                    "s6_sp_lateral_acceleration_range",
                    Some(key),
                    None,
                    r.mean,
                    note(&r, "|a_y| of the rear unit in the sustained period"),
                );
            }
            ctx.compare(
                "s6_omega_z_unsuspended",
                None,
                Some("3-D vehicle"),
                y.omega_z_hz,
                "D3 on smooth ground, 30 deg pulse: the 3-D model's additions (rear roll, tire vertical and lateral compliance, relaxation) do not move the yaw mode towards 2.81 Hz (docs/vehicle-3d.md, Yaw mode)",
            );
        }
    }
    for (key, i) in [("sp_drt", 0), ("omega_z", 1)] {
        let (a, b) = if i == 0 {
            (sp[1], sp[0])
        } else {
            (wz[1], wz[0])
        };
        ctx.compare(
            "s6_hps_stability_reduction",
            Some(key),
            None,
            100.0 * (a / b - 1.0),
            format!("nominal HPS {a:.3} vs unsuspended {b:.3}"),
        );
    }
    Ok(())
}
