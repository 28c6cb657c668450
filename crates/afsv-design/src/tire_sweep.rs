//! The tire and the grid of `afsv tire sweep`: the Fiala tire of a parameter file (or the
//! nominal 29.5R29 of Table 6.2) with single values replaced ([`tire_params`]), and the
//! loads, slip ratios and slip angles swept ([`sweep_grid`]).

use std::path::Path;
use tire_fiala::TireParams;

/// Largest number of rows of one sweep.
pub const MAX_SWEEP_ROWS: usize = 2_000_000;

/// Values that replace the tire's own (`None`: keep it).
#[derive(Debug, Clone, Copy, Default)]
pub struct TireOverrides {
    /// Longitudinal slip stiffness C_slip (N per unit slip ratio).
    pub c_slip: Option<f64>,
    /// Constant cornering stiffness C_alpha (N/rad), replacing the load-dependent table.
    pub c_alpha_per_rad: Option<f64>,
    /// Static friction coefficient U_max.
    pub u_max: Option<f64>,
    /// Sliding friction coefficient U_min.
    pub u_min: Option<f64>,
    /// Tire width b (m).
    pub width_m: Option<f64>,
}

/// The tire of `file` (missing fields keep the nominal values; unknown ones are refused),
/// else the nominal tire, with `o` applied, validated and within the registry's ranges.
pub fn tire_params(file: Option<&Path>, o: &TireOverrides) -> Result<TireParams, String> {
    let mut p = match file {
        Some(path) => crate::param_files::read::<TireParams>(path)?,
        None => TireParams::nominal(),
    };
    if let Some(v) = o.c_slip {
        p.longitudinal_stiffness_n = v;
    }
    if let Some(v) = o.c_alpha_per_rad {
        p.cornering_stiffness_n_per_rad = v;
        p.cornering_stiffness_table.clear();
    }
    if let Some(v) = o.u_max {
        p.u_max = v;
    }
    if let Some(v) = o.u_min {
        p.u_min = v;
    }
    if let Some(v) = o.width_m {
        p.width_m = v;
    }
    p.validate().map_err(|e| e.to_string())?;
    // The file and the options together must lie in the registry's ranges.
    let source = file.map_or("the tire".to_string(), |f| f.display().to_string());
    vehicle_components::within_ranges(&p).map_err(|e| format!("{source}: {e}"))?;
    Ok(p)
}

/// The loads `fz` (N, each > 0), slip angles `alpha_deg` and slip ratios `kappa` of a
/// sweep (each a value or `start:stop:step`, [`crate::value_lists::range`]; neither
/// angle nor ratio: alpha -20:20:0.5 deg at kappa 0), at most [`MAX_SWEEP_ROWS`] rows.
#[allow(clippy::type_complexity)]
pub fn sweep_grid(
    fz: &str,
    alpha_deg: Option<&str>,
    kappa: Option<&str>,
) -> Result<(Vec<f64>, Vec<f64>, Vec<f64>), String> {
    use crate::value_lists::range;
    let fzs = range(fz, "--fz")?;
    if let Some(bad) = fzs.iter().find(|&&f| f <= 0.0) {
        return Err(format!(
            "--fz {fz}: normal loads must be > 0 N (got {bad}); a tire off the ground has no forces to sweep"
        ));
    }
    let (alphas, kappas) = match (alpha_deg, kappa) {
        (None, None) => (range("-20:20:0.5", "--alpha-deg")?, vec![0.0]),
        (a, k) => (
            a.map_or(Ok(vec![0.0]), |t| range(t, "--alpha-deg"))?,
            k.map_or(Ok(vec![0.0]), |t| range(t, "--kappa"))?,
        ),
    };
    let total = fzs.len() * alphas.len() * kappas.len();
    if total > MAX_SWEEP_ROWS {
        return Err(format!("the sweep has {total} rows (at most 2000000)"));
    }
    Ok((fzs, alphas, kappas))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_grid_defaults_to_an_angle_sweep() {
        let (f, a, k) = sweep_grid("1e5", None, None).unwrap();
        assert_eq!((f.len(), a.len(), k), (1, 81, vec![0.0]));
        let (_, a, k) = sweep_grid("1e5", None, Some("0:0.1:0.05")).unwrap();
        assert_eq!((a, k.len()), (vec![0.0], 3));
        assert!(sweep_grid("-1", None, None).unwrap_err().contains("> 0 N"));
        assert!(sweep_grid("1:2000:1", Some("0:10:0.01"), None)
            .unwrap_err()
            .contains("rows"));
    }

    #[test]
    fn overrides_replace_the_nominal_values() {
        let o = TireOverrides {
            c_alpha_per_rad: Some(2e5),
            u_max: Some(0.7),
            ..TireOverrides::default()
        };
        let p = tire_params(None, &o).unwrap();
        assert_eq!((p.cornering_stiffness_n_per_rad, p.u_max), (2e5, 0.7));
        assert!(p.cornering_stiffness_table.is_empty());
        assert_eq!(
            tire_params(None, &TireOverrides::default()).unwrap(),
            TireParams::nominal()
        );
    }
}
