//! The strut a design study on the 3-D vehicle runs (`afsv study speed-sweep`): the
//! described vehicle's front-axle strut or a strut file's, its Eq 6.19 design variables
//! [A_hc, A_v, A_b] replaced by a design ([`crate::HpsDesign`], Table 6.5).

use std::path::Path;
use vehicle_3d::VehicleParams;

/// The vehicle of `vehicle` (the prototype by default) with the front-axle strut of `hps`
/// (`nominal`: the description's; else a strut file, which a description with a `[link]`
/// refuses), the strut's areas replaced by `design` (`A_HC,A_V,A_B`, A_hc in m², A_v and
/// A_b in mm², as `afsv optimize hps` prints them), validated.
pub fn study_vehicle(
    vehicle: Option<&Path>,
    hps: &str,
    design: Option<&str>,
) -> Result<VehicleParams, String> {
    let mut p = if hps == "nominal" {
        crate::described::with_front_strut(vehicle, "--hps nominal")?
    } else {
        let v = crate::described::articulated(vehicle)?;
        crate::described::refuse_link(&v, "--hps FILE")?;
        let mut p = v.params;
        p.hps = crate::param_files::read_hps_strut(Path::new(hps), "nominal or a strut file")?;
        p
    };
    if let Some(text) = design {
        let v = crate::value_lists::list("--design", text, 3)?;
        let [a_hc, a_v, a_b] = v[..] else {
            return Err(format!(
                "--design: three values A_HC,A_V,A_B, got {}",
                v.len()
            ));
        };
        let d = crate::HpsDesign::new(a_hc, a_v * 1e-6, a_b * 1e-6)
            .map_err(|e| format!("--design: {e}"))?;
        p.hps = d.apply(&p.hps).map_err(|e| format!("--design: {e}"))?;
    }
    p.validate().map_err(|e| e.to_string())?;
    Ok(p)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_design_replaces_the_areas() {
        let nominal = study_vehicle(None, "nominal", None).unwrap();
        let designed = study_vehicle(None, "nominal", Some("0.05,6,16")).unwrap();
        assert_ne!(nominal.hps, designed.hps);
        assert!(study_vehicle(None, "nominal", Some("0.05,6"))
            .unwrap_err()
            .contains("three values"));
        assert!(study_vehicle(None, "no-such-strut.json", None).is_err());
    }
}
