//! The one calibrated parameter: the strut spacing ratio
//! ([`crate::TruckParams::strut_spacing_ratio`]), the roll compliance of both axles.
//!
//! Chapter 2 gives neither roll-centre heights, spring spacings nor bump-stop rates; its
//! smooth-road DRT of 0.279 g (L650) is about half the rigid-vehicle SSF, so the truck's
//! roll compliance must be large. The smooth DRT rises with the ratio. Below a ratio near
//! 0.25 the suspension's roll stiffness no longer carries the sprung mass's gravitational
//! roll moment: the upright truck is statically unstable in roll and falls onto its bump
//! stops on a straight, level road. The calibration therefore searches only the
//! statically stable ratios: [`calibrate_strut_spacing`] finds the stability floor
//! ([`is_roll_stable`], bisection) and then the ratio at which the smooth DRT equals the
//! target. If the DRT at the floor is already above the target, the floor is the result.
//!
//! For the nominal truck the floor decides. The smooth DRT at the floor is 0.28-0.29 g
//! against the paper's 0.279 g, so the target is not reached exactly. The ratio that gives
//! 0.279 g (0.242) tips a straight-running truck over to 20 deg roll. The constant
//! [`CALIBRATED_STRUT_SPACING_RATIO`] is the floor the search returns, rounded up to three
//! digits. `tests/calibration.rs` repeats the derivation. Every other number of the
//! chapter is a prediction.

use odeint::{Control, Integrator, Solver};

use crate::driver::SteerDirection;
use crate::error::TruckError;
use crate::measures::level_ground;
use crate::params::TruckParams;
use crate::vehicle::{ModelOptions, TruckVehicle};

/// Strut spacing ratio r (-): the smallest statically roll-stable ratio of
/// [`calibrate_strut_spacing`]`(&nominal, (0.15, 0.6), 0.279, 1e-4)`, rounded up to three
/// digits. Its smooth DRT (0.288 g) is the closest a stable truck of this model
/// comes to 0.279 g.
pub const CALIBRATED_STRUT_SPACING_RATIO: f64 = 0.254;

/// Smooth-road DRT the calibration aims at (g), section 2.3 (L650).
pub const TARGET_SMOOTH_DRT_G: f64 = 0.279;

/// Initial roll (rad) of the stability test.
pub const STABILITY_ROLL_RAD: f64 = 0.005;

/// Duration (s) of the stability test.
pub const STABILITY_TEST_S: f64 = 20.0;

/// Result of [`calibrate_strut_spacing`].
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Calibration {
    /// The calibrated ratio.
    pub strut_spacing_ratio: f64,
    /// Smooth-road DRT at that ratio (g).
    pub smooth_drt_g: f64,
    /// Smallest statically roll-stable ratio found (to 0.001).
    pub stability_floor: f64,
    /// Whether the stability floor, not the DRT target, fixed the result.
    pub limited_by_stability: bool,
    /// Runs made.
    pub runs: usize,
}

/// Whether the upright truck `p`, driving straight at its target speed on level ground
/// from a roll of [`STABILITY_ROLL_RAD`], has less roll than that after
/// [`STABILITY_TEST_S`].
pub fn is_roll_stable(p: &TruckParams) -> Result<bool, TruckError> {
    let options = ModelOptions {
        direction: SteerDirection::Straight,
        path_length_m: p.target_speed_m_s * STABILITY_TEST_S + 10.0,
        ..ModelOptions::default()
    };
    let v = TruckVehicle::new(p, &level_ground(), 1.0, options)?;
    let mut y = v.initial_state(p.target_speed_m_s);
    y[3] = (0.5 * STABILITY_ROLL_RAD).cos();
    y[4] = (0.5 * STABILITY_ROLL_RAD).sin();
    let mut roll = STABILITY_ROLL_RAD;
    Integrator::new(Solver::Dopri5, 1e-6, 1e-8).integrate(
        &v,
        0.0,
        &y,
        &[0.0, STABILITY_TEST_S],
        |_, s| {
            roll = 2.0 * s[4].asin();
            Control::Continue
        },
    )?;
    Ok(roll.abs() < STABILITY_ROLL_RAD)
}

/// The stable ratio in `[lower, upper]` whose smooth DRT is `target_g` within `tol_g`, or
/// the stability floor if every stable ratio gives more (module docs).
pub fn calibrate_strut_spacing(
    base: &TruckParams,
    (lower, upper): (f64, f64),
    target_g: f64,
    tol_g: f64,
) -> Result<Calibration, TruckError> {
    let with = |r: f64| {
        let mut p = *base;
        p.strut_spacing_ratio = r;
        p
    };
    let mut runs = 0;
    if !is_roll_stable(&with(upper))? {
        return Err(crate::error::rejected(
            "strut_spacing_ratio",
            upper,
            "the upper end of the calibration range is not roll-stable",
        ));
    }
    let (mut lo, mut hi) = (lower, upper);
    while hi - lo > 1e-3 {
        let mid = 0.5 * (lo + hi);
        runs += 1;
        if is_roll_stable(&with(mid))? {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    let floor = hi;
    let drt = |r: f64| crate::measures::smooth_drt_g(&with(r));
    let d_floor = drt(floor)?;
    runs += 1;
    if d_floor >= target_g - tol_g {
        return Ok(Calibration {
            strut_spacing_ratio: floor,
            smooth_drt_g: d_floor,
            stability_floor: floor,
            limited_by_stability: true,
            runs,
        });
    }
    let (mut lo, mut hi) = (floor, upper);
    loop {
        let mid = 0.5 * (lo + hi);
        let d = drt(mid)?;
        runs += 1;
        if (d - target_g).abs() <= tol_g || hi - lo < 1e-6 {
            return Ok(Calibration {
                strut_spacing_ratio: mid,
                smooth_drt_g: d,
                stability_floor: floor,
                limited_by_stability: false,
                runs,
            });
        }
        if d < target_g {
            lo = mid;
        } else {
            hi = mid;
        }
    }
}
