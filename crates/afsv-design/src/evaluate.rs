//! The assessment of `afsv evaluate` (and its Python twin `afsv.evaluate`) on one
//! articulated vehicle description: the three design measures of Chapter 6 on the 3-D
//! vehicle over terrain seeds ([`crate::design_3d::assess`]), the yaw-plane steering
//! measures of Chapter 3 per load case (section 3.3), the front-axle strut's summary
//! (Chapter 5) and the nominal terrain's synthesis summary (section 6.2.3).

use afsv_dynamics::{measures_for, EquationForm, Load, MeasureSpec, YawMeasures};
use afsv_vehicle::ArticulatedVehicle;
use hps_emulsion::StrutSummary;

/// The assessment of one vehicle.
pub struct Assessment {
    /// The vehicle's name.
    pub name: String,
    /// Whether it is the built-in prototype (the dissertation's numbers apply).
    pub is_prototype: bool,
    /// Whether both models use the printed Eq 3.13 (`--paper-form`).
    pub paper_form: bool,
    /// Where the front strut comes from (the description's strut file or table).
    pub strut_source: Option<String>,
    /// The Chapter 6 design measures D1-D3.
    pub vehicle: crate::design_3d::DesignMeasures,
    /// Speed of the yaw-plane measures (km/h).
    pub speed_kmh: f64,
    /// The nominal terrain's synthesis summary (first seed).
    pub terrain: terrain_psd::Summary,
    /// Yaw-plane measures, loaded.
    pub yaw_loaded: YawMeasures,
    /// Yaw-plane measures, unloaded.
    pub yaw_unloaded: YawMeasures,
    /// The front strut's summary (Chapter 5), if the vehicle has one.
    pub strut: Option<StrutSummary>,
}

/// Lowest forward speed of the yaw-plane measures (km/h): below it the tire slip angles of
/// Eq 3.13 lose meaning.
pub const MIN_SPEED_KMH: f64 = 1.0;

/// `speed_kmh` (`--speed-kmh`) is at least [`MIN_SPEED_KMH`].
pub fn check_speed(speed_kmh: f64) -> Result<(), String> {
    if speed_kmh.is_finite() && speed_kmh >= MIN_SPEED_KMH {
        Ok(())
    } else {
        Err(format!(
            "--speed-kmh must be at least {MIN_SPEED_KMH} km/h (the yaw-plane measures need forward speed), got {speed_kmh}"
        ))
    }
}

/// The yaw-plane measures of `v` at `load` and `speed` (m/s) in the equation `form`.
pub fn yaw_of(
    v: &ArticulatedVehicle,
    load: Load,
    speed: f64,
    form: EquationForm,
) -> Result<YawMeasures, String> {
    let p = v.yaw_plane_params(load);
    let mut spec = MeasureSpec::default();
    spec.options.form = form;
    measures_for(&p.vehicle, &p.afs, Some(load), speed, &spec)
        .map_err(|e| format!("yaw-plane measures, {load:?} case: {e}").to_lowercase())
}

/// Everything `afsv evaluate` measures on the vehicle `v`: the design measures over
/// `seeds` (`progress` after each run), the yaw-plane measures at `speed_kmh`, the strut and
/// the terrain of `seed`; `paper_form` puts both models on the printed Eq 3.13.
pub fn assess(
    v: &ArticulatedVehicle,
    speed_kmh: f64,
    seed: u64,
    seeds: &[u64],
    paper_form: bool,
    progress: &(dyn Fn(&str) + Sync),
) -> Result<Assessment, String> {
    let speed = speed_kmh / 3.6;
    let mut p = v.params.clone();
    if let Some(s) = &v.front_strut {
        p.hps = *s;
    }
    let form = if paper_form {
        p.yaw_inertia_form = vehicle_3d::YawInertiaForm::PaperEq313;
        EquationForm::PaperEq313
    } else {
        EquationForm::EnergyConsistent
    };
    let vehicle = crate::design_3d::assess(&p, v.front_strut.is_some(), seeds, v.link, progress)?;
    let strut = match &v.front_strut {
        Some(s) => Some(hps_emulsion::characterize::summary(s, 0.025).map_err(|e| e.to_string())?),
        None => None,
    };
    let prototype = afsv_vehicle::load_builtin("prototype").map_err(|e| e.to_string())?;
    let is_prototype =
        matches!(&prototype.vehicle, afsv_vehicle::Vehicle::Articulated(p) if p == v);
    Ok(Assessment {
        is_prototype,
        paper_form,
        name: v.name.clone(),
        strut_source: v.front_strut_source.clone(),
        vehicle,
        speed_kmh,
        terrain: terrain_psd::default_terrain_summary(seed),
        yaw_loaded: yaw_of(v, Load::Loaded, speed, form)?,
        yaw_unloaded: yaw_of(v, Load::Unloaded, speed, form)?,
        strut,
    })
}

/// A yaw mode is stable when its free oscillation decays: a positive fitted damping ratio.
pub fn yaw_stable(m: &YawMeasures) -> bool {
    m.damping_ratio.is_finite() && m.damping_ratio > 0.0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_yaw_plane_measures_need_forward_speed() {
        assert!(check_speed(MIN_SPEED_KMH).is_ok() && check_speed(50.0).is_ok());
        let e = check_speed(0.5).unwrap_err();
        assert!(e.starts_with("--speed-kmh must be at least 1 km/h") && e.ends_with("got 0.5"));
        assert!(check_speed(f64::NAN).is_err());
    }

    #[test]
    fn a_yaw_mode_is_stable_only_with_positive_finite_damping() {
        let mut v = serde_json::json!({
            "load": null,
            "form": serde_json::to_value(EquationForm::EnergyConsistent).unwrap(),
        });
        for f in [
            "speed_m_s",
            "natural_frequency_hz",
            "damped_frequency_hz",
            "damping_ratio",
            "decay_fit_rmse_deg",
            "decay_fit_r_squared",
            "pulse_peak_articulation_deg",
            "steering_gain",
            "steady_articulation_deg",
            "rise_time_s",
            "response_rate_deg_s",
            "overshoot_percent",
            "power_efficiency",
            "strut_length_m",
        ] {
            v[f] = 0.2.into();
        }
        let mut m: YawMeasures = serde_json::from_value(v).unwrap();
        assert!(yaw_stable(&m));
        for z in [0.0, -0.1, f64::NAN] {
            m.damping_ratio = z;
            assert!(!yaw_stable(&m), "{z}");
        }
    }
}
