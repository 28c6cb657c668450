//! The rear walking-beam bogie (`docs/layouts.md`, "The walking-beam bogie"): a rear tandem
//! whose two wheels on each side turn on the ends of one beam, the beam pitching about a
//! pivot at the rear axle position of [`crate::VehicleParams`] (`rear_axle_to_joint_m`) at the
//! wheel-centre height. Each side's pivot sits on the side's wheel carrier, which slides
//! along the rear unit's z on one HPS strut when the rear axle is suspended
//! (`VehicleParams::rear_hps`), else is fixed ([`crate::model`]).
//!
//! Statics: the beam is centred on its pivot and symmetric, so the pivot's vertical load
//! splits equally between its two wheels whatever the wheels weigh: each tandem tire carries
//! a quarter of the rear-axle load of [`crate::statics`] (the rear axle's load moves to the
//! pivots unchanged, since the pivot sits where the single axle sat). The strut of a side
//! carries the side's half of the axle load less the unsprung weight below it, two wheel
//! ends and the beam: `F_s = W_r / 2 - (2 m_w + m_b) g`.
//!
//! Beam pitch: with the pivot held, the beam and its wheels pitch against the two tires'
//! vertical stiffness `k_t` at `+- s/2`: `omega^2 = 2 k_t (s/2)^2 / I_p`, with
//! `I_p = I_b + 2 m_w (s/2)^2` about the pivot: the wheel ends turn on their spin joints,
//! so their own inertia about the axle does not follow the beam (`tests/bogie.rs`).

use serde::{Deserialize, Serialize};

use crate::error::{rejected, VehicleError};

/// Tandem axle spacing (m): assumption 2.1 m. ADT tandems of the 25-40 t class put the
/// axles one tire diameter plus a small clearance apart; the model's tire (unloaded radius
/// 1.0 m) is 2.0 m across, so 2.1 m leaves 0.1 m between the treads. Not from the
/// dissertation, whose prototype has a single rear axle.
pub const DEFAULT_SPACING_M: f64 = 2.1;

/// Mass of one beam (kg): assumption 800 kg, a cast bogie beam (with its drop-gear housing)
/// of a 25-30 t ADT class machine, about a tenth of that class's rear-unit mass without
/// its wheel ends. Not from a source.
pub const DEFAULT_BEAM_MASS_KG: f64 = 800.0;

/// Pitch moment of inertia of one beam about its pivot (kg m²): assumption 300 kg m², the
/// slender bar `m L² / 12` of the default mass over a length of 2.1 m (the axle spacing)
/// rounded up for the housing's ends. Not from a source.
pub const DEFAULT_BEAM_PITCH_INERTIA_KG_M2: f64 = 300.0;

/// Plausible tandem spacing (m): from a small forwarder bogie to the largest haulers.
pub const SPACING_RANGE_M: (f64, f64) = (0.8, 4.0);

/// Plausible beam mass (kg).
pub const BEAM_MASS_RANGE_KG: (f64, f64) = (20.0, 10_000.0);

/// Plausible beam pitch inertia about its pivot (kg m²).
pub const BEAM_PITCH_INERTIA_RANGE_KG_M2: (f64, f64) = (1.0, 20_000.0);

/// Ratio of a beam's roll inertia to its pitch inertia (assumption 0.1: a slender beam
/// along x; its yaw inertia equals its pitch inertia). The rear unit carries both rigidly
/// (only the pitch turns), so they only add to the rear unit's roll and yaw inertia.
pub const BEAM_ROLL_TO_PITCH: f64 = 0.1;

/// The walking-beam bogie of the rear axle (module docs). Both sides alike.
/// A field left out of a file takes its default.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct BogieParams {
    /// Distance between the tandem axles (m), the pivot midway. [`DEFAULT_SPACING_M`].
    pub spacing_m: f64,
    /// Mass of one beam (kg), its cg at the pivot. [`DEFAULT_BEAM_MASS_KG`].
    pub beam_mass_kg: f64,
    /// Pitch moment of inertia of one beam about its pivot (kg m²), wheel ends not
    /// included. [`DEFAULT_BEAM_PITCH_INERTIA_KG_M2`].
    pub beam_pitch_inertia_kg_m2: f64,
}

impl Default for BogieParams {
    fn default() -> Self {
        Self {
            spacing_m: DEFAULT_SPACING_M,
            beam_mass_kg: DEFAULT_BEAM_MASS_KG,
            beam_pitch_inertia_kg_m2: DEFAULT_BEAM_PITCH_INERTIA_KG_M2,
        }
    }
}

impl BogieParams {
    /// A validated bogie ([`BogieParams::validate`]).
    pub fn new(
        spacing_m: f64,
        beam_mass_kg: f64,
        beam_pitch_inertia_kg_m2: f64,
    ) -> Result<Self, VehicleError> {
        let b = Self {
            spacing_m,
            beam_mass_kg,
            beam_pitch_inertia_kg_m2,
        };
        b.validate()?;
        Ok(b)
    }

    /// Each field inside its plausible range; the error names the field (`bogie.…`).
    pub fn validate(&self) -> Result<(), VehicleError> {
        in_range("bogie.spacing_m", self.spacing_m, SPACING_RANGE_M)?;
        in_range("bogie.beam_mass_kg", self.beam_mass_kg, BEAM_MASS_RANGE_KG)?;
        in_range(
            "bogie.beam_pitch_inertia_kg_m2",
            self.beam_pitch_inertia_kg_m2,
            BEAM_PITCH_INERTIA_RANGE_KG_M2,
        )?;
        Ok(())
    }

    /// Half the spacing: each wheel's distance from the pivot (m).
    pub fn half_spacing_m(&self) -> f64 {
        0.5 * self.spacing_m
    }

    /// Pitch moment of inertia about the pivot of one beam with its two wheel ends
    /// (kg m²): `I_b + 2 m_w (s/2)²`, the wheel ends' own rotation about their axle free
    /// on the spin joints.
    pub fn pitch_inertia_with_wheels(&self, wheel_mass_kg: f64) -> f64 {
        let h = self.half_spacing_m();
        self.beam_pitch_inertia_kg_m2 + 2.0 * wheel_mass_kg * h * h
    }

    /// Natural frequency of the beam pitch with the pivot held (Hz): two tires of tangent
    /// stiffness `k_t` (N/m) at `+- s/2`, `omega^2 = 2 k_t (s/2)^2 / I_p` (module docs).
    pub fn pitch_frequency_hz(&self, wheel_mass_kg: f64, tire_stiffness_n_m: f64) -> f64 {
        let h = self.half_spacing_m();
        let omega2 =
            2.0 * tire_stiffness_n_m * h * h / self.pitch_inertia_with_wheels(wheel_mass_kg);
        omega2.sqrt() / (2.0 * std::f64::consts::PI)
    }
}

fn in_range(field: &'static str, v: f64, (lo, hi): (f64, f64)) -> Result<(), VehicleError> {
    if v.is_finite() && (lo..=hi).contains(&v) {
        Ok(())
    } else {
        Err(rejected(field, v, range_reason(field)))
    }
}

/// The error text of each field (static: the error type holds `&'static str`).
fn range_reason(field: &str) -> &'static str {
    match field {
        "bogie.spacing_m" => "must lie in [0.8, 4] m",
        "bogie.beam_mass_kg" => "must lie in [20, 10000] kg",
        _ => "must lie in [1, 20000] kg m²",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_is_valid_and_bad_fields_are_named_with_their_range() {
        BogieParams::default().validate().unwrap();
        let e = BogieParams::new(0.5, 800.0, 300.0).unwrap_err().to_string();
        assert!(
            e.contains("bogie.spacing_m") && e.contains("[0.8, 4]"),
            "{e}"
        );
        let e = BogieParams::new(2.0, f64::NAN, 300.0)
            .unwrap_err()
            .to_string();
        assert!(e.contains("bogie.beam_mass_kg"), "{e}");
        let e = BogieParams::new(2.0, 800.0, 0.0).unwrap_err().to_string();
        assert!(e.contains("bogie.beam_pitch_inertia_kg_m2"), "{e}");
    }

    #[test]
    fn the_pitch_inertia_with_wheels_is_the_parallel_axis_sum() {
        let b = BogieParams::new(2.0, 800.0, 300.0).unwrap();
        // 300 + 2 * 2000 * 1² = 4300
        assert_eq!(b.pitch_inertia_with_wheels(2_000.0), 4_300.0);
        // omega² = 2 * 4300 * 1² / 4300 = 2
        let f = b.pitch_frequency_hz(2_000.0, 4_300.0);
        assert!((f - 2f64.sqrt() / (2.0 * std::f64::consts::PI)).abs() < 1e-15);
    }
}
