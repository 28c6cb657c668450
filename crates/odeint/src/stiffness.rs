//! The stiffness test of the explicit 5(4) pairs (HNW I, section IV.2, the test of the code
//! DOPRI5), shared by Dormand-Prince and Tsitouras: both end a step with two stages at
//! `t + h`, the last one at the propagated solution (FSAL). After each accepted step
//! `h λ ≈ h ‖k7 − k6‖ / ‖y_new − y6‖` estimates the step times the dominant eigenvalue (at
//! about 3.3 the step sits on either method's stability boundary on the negative real
//! axis). Fifteen steps above [`STIFF_H_LAMBDA`] with no six ordinary ones between make the
//! problem stiff.

/// `h λ` above which a step counts as held by the stiff eigenvalue. DOPRI5 uses 3.25, the
/// stability boundary; on the suspended vehicle the error estimate already holds the steps
/// at `h λ` ≈ 0.5-1.8 (a rod-side pressure at 2.5·10⁴ s⁻¹, steps of 70 µs), so the test
/// here is looser. A false alarm costs one trial of the implicit method (`switching`).
const STIFF_H_LAMBDA: f64 = 1.0;
/// Steps on the boundary that make the problem stiff.
const STIFF_STEPS: usize = 15;
/// Ordinary steps that clear the count.
const NON_STIFF_STEPS: usize = 6;

/// Counts of the steps held at the stability boundary.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct StiffnessWatch {
    /// Steps on the stability boundary in a row.
    on_boundary: usize,
    /// Ordinary steps since the last one on it.
    ordinary: usize,
}

impl StiffnessWatch {
    /// Forget the counts (a restart).
    pub(crate) fn reset(&mut self) {
        *self = Self::default();
    }

    /// Count the accepted step of size `h` whose last two stages, both at `t + h`, are
    /// `k6 = f(y6)` and `k7 = f(y_new)`.
    pub(crate) fn observe(&mut self, h: f64, k6: &[f64], k7: &[f64], y6: &[f64], y_new: &[f64]) {
        let (mut num, mut den) = (0.0, 0.0);
        for i in 0..y_new.len() {
            num += (k7[i] - k6[i]).powi(2);
            den += (y_new[i] - y6[i]).powi(2);
        }
        if den > 0.0 && h * (num / den).sqrt() > STIFF_H_LAMBDA {
            self.ordinary = 0;
            self.on_boundary += 1;
        } else {
            self.ordinary += 1;
            if self.ordinary == NON_STIFF_STEPS {
                self.on_boundary = 0;
            }
        }
    }

    /// Has the test found the problem stiff?
    pub(crate) fn stiff(&self) -> bool {
        self.on_boundary >= STIFF_STEPS
    }
}
