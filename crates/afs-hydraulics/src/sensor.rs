//! Measurement effects (not part of the hydraulic state): articulation-sensor backlash.
//!
//! Section 3.4.1 / 4.2.2 report that the unloaded path-change articulation record was
//! corrupted by loosened link rods of the articulation potentiometer. A loose link is a
//! play (backlash) element between the true articulation and the sensor shaft.

/// One step of a play (backlash) element of total width `2 * half_width`.
///
/// The output stays at `prev_output` while the input moves inside the play band
/// `[prev_output - half_width, prev_output + half_width]`; once the input pushes against
/// either side, the output follows it at a distance `half_width`. Apply it sample by sample
/// to a true articulation history to get what a loose-link sensor reads. A non-positive or
/// NaN `half_width` means no play (the input is returned).
#[inline]
pub fn backlash(prev_output: f64, input: f64, half_width: f64) -> f64 {
    if half_width.is_nan() || half_width <= 0.0 {
        return input;
    }
    if input - prev_output > half_width {
        input - half_width
    } else if prev_output - input > half_width {
        input + half_width
    } else {
        prev_output
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn play_element_holds_then_follows() {
        let hw = 0.5;
        let mut y = 0.0;
        let mut out = Vec::new();
        for x in [0.2, 0.4, 1.0, 2.0, 1.8, 1.2, 0.0] {
            y = backlash(y, x, hw);
            out.push(y);
        }
        assert_eq!(out, vec![0.0, 0.0, 0.5, 1.5, 1.5, 1.5, 0.5]);
        assert_eq!(backlash(3.0, 7.0, 0.0), 7.0);
        assert_eq!(backlash(3.0, 7.0, f64::NAN), 7.0);
    }
}
