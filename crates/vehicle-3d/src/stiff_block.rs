//! The stiff part of the suspended vehicle, for the integrators implicit in it
//! ([`odeint::Solver::Ros34pw2`], [`odeint::Solver::Ark436`]): each strut's own states,
//! front then rear axle (gas volume, rod-side pressure, velocity amplitude and any
//! extension states of Eqs 6.9-6.18).
//!
//! The rod-side pressure relaxes through the orifices with a rate `β/V_r · ∂Q/∂Δp` that
//! reaches about 3·10⁴ s⁻¹ near zero flow (nominal strut, loaded D1 ride; 150-700 s⁻¹
//! while the strut moves), while the rest of the vehicle's eigenvalues stay below about
//! 200 s⁻¹ (docs/vehicle-3d.md, "Speed"). An explicit method's steps are held to that
//! fast relaxation; the Rosenbrock-W method inverts `I/(hγ) − J` on these 3 × 3 blocks
//! only. Their Jacobian is differenced through the strut's own evaluate at the carrier's
//! current travel and rate: four strut evaluations per strut, no vehicle right-hand side.
//! The additive Runge-Kutta method's Newton iterations read the strut's rates alone the
//! same way.

use crate::suspension::AxleStruts;
use crate::vehicle::{Offsets, Vehicle};

/// One block per strut, its states in order: the front struts, then the rear; none on
/// rigid axles.
pub(crate) fn strut_blocks(offsets: &Offsets) -> Vec<Vec<usize>> {
    [
        (offsets.hps, offsets.hps_states),
        (offsets.rear_hps, offsets.rear_hps_states),
    ]
    .into_iter()
    .filter(|&(_, n)| n > 0)
    .flat_map(|(at, n)| (0..2).map(move |side| (at + side * n..at + (side + 1) * n).collect()))
    .collect()
}

impl Vehicle {
    /// The strut of stiff block `block` and its side: the front struts first, left then
    /// right, then the rear; `None` for a block that does not exist.
    fn block_strut(&self, block: usize) -> Option<(&AxleStruts, usize)> {
        self.axle_struts()
            .into_iter()
            .flatten()
            .flat_map(|a| [(a, 0), (a, 1)])
            .nth(block)
    }

    /// ∂(the rates of block `block`'s strut)/∂(its states) at `y`, row-major into `jac`,
    /// by forward differences of `HpsStrut::evaluate` with the carrier's travel and rate
    /// held. Blocks count the front struts first, left then right, then the rear. `false`
    /// for a block that does not exist.
    pub(crate) fn strut_block_jacobian(&self, y: &[f64], block: usize, jac: &mut [f64]) -> bool {
        const MAX_STATES: usize = 8;
        let Some((axle, side)) = self.block_strut(block) else {
            return false;
        };
        let strut = &axle.strut;
        let n = axle.n_states();
        if n > MAX_STATES {
            return false;
        }
        let (z, zdot) = axle.motion(y, self.offsets.v, side);
        let at = axle.states(side).start;
        let mut s = [0.0; MAX_STATES];
        s[..n].copy_from_slice(&y[at..at + n]);
        let (mut f0, mut f1) = ([0.0; MAX_STATES], [0.0; MAX_STATES]);
        strut.evaluate(z, zdot, &s[..n], &mut f0[..n]);
        for c in 0..n {
            let base = s[c];
            let d = f64::EPSILON.sqrt() * base.abs().max(strut.state_typical(c));
            s[c] = base + d;
            strut.evaluate(z, zdot, &s[..n], &mut f1[..n]);
            s[c] = base;
            for r in 0..n {
                jac[r * n + c] = (f1[r] - f0[r]) / d;
            }
        }
        true
    }

    /// The rates of block `block`'s strut at `y` into `out` (its states' length): the
    /// values the right-hand side writes in those rows (`AxleStruts::evaluate`, the same
    /// call). `false` for a block that does not exist.
    pub(crate) fn strut_block_rates(&self, y: &[f64], block: usize, out: &mut [f64]) -> bool {
        let Some((axle, side)) = self.block_strut(block) else {
            return false;
        };
        axle.evaluate(y, self.offsets.v, side, out);
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_block_per_strut_and_none_without() {
        let mut o = Offsets {
            q: 0,
            v: 16,
            afs: 30,
            tires: 33,
            hps: 41,
            hps_states: 3,
            rear_hps: 47,
            rear_hps_states: 0,
            pi: 47,
            path: 48,
            driver: None,
            dim: 49,
        };
        assert_eq!(strut_blocks(&o), vec![vec![41, 42, 43], vec![44, 45, 46]]);
        o.rear_hps_states = 3;
        assert_eq!(strut_blocks(&o)[2..], [vec![47, 48, 49], vec![50, 51, 52]]);
        o.hps_states = 0;
        o.rear_hps = 41;
        assert_eq!(strut_blocks(&o), vec![vec![41, 42, 43], vec![44, 45, 46]]);
        o.rear_hps_states = 0;
        assert!(strut_blocks(&o).is_empty());
    }
}
