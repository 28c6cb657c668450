//! The four struts (Table 2.2, per wheel station): linear spring about the static preload,
//! linear damper and a bump stop, acting on the joint coordinates of the wheel carriers and
//! the rear axle.
//!
//! Strut compressions from static, linear in the joint coordinates (`q_fl`, `q_fr` the
//! front carrier travels, `q_b`, `q_phi` the rear axle bounce and roll relative to the
//! sprung body, all positive for a compressing left strut), with `r` the strut spacing
//! ratio ([`crate::TruckParams::strut_spacing_ratio`]):
//!
//! ```text
//! s_fl = (q_fl + q_fr)/2 + r (q_fl - q_fr)/2      s_rl = q_b + (r T_r / 2) q_phi
//! s_fr = (q_fl + q_fr)/2 - r (q_fl - q_fr)/2      s_rr = q_b - (r T_r / 2) q_phi
//! ```
//!
//! so the heave rate of each wheel station is the Table 2.2 rate `k` whatever `r`, and the
//! roll rate of an axle is `k (r T)^2 / 2`: the struts act as if mounted at `r` times the
//! track. The strut force (compression positive) is
//! `F = F_0 + k s + c ds/dt + k_b (s - clamp(s, -travel/2, travel/2))`, `F_0` the static
//! preload and `k_b = bump_stop_ratio k` the clearance spring; its joint-space force is
//! `tau_j = -sum_i F_i d(s_i)/d(q_j)`. With the dampers off the struts have the potential
//! [`Suspension::energy`].

use crate::params::TruckParams;
use crate::statics::Statics;

/// One strut: rate, damping, half travel, bump-stop rate, static preload.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Strut {
    /// Spring rate k (N/m).
    pub rate: f64,
    /// Damping c (N s/m).
    pub damping: f64,
    /// Half travel (m): the bump stop engages beyond +- this compression from static.
    pub half_travel: f64,
    /// Bump-stop rate k_b (N/m).
    pub bump_rate: f64,
    /// Static preload F_0 (N).
    pub preload: f64,
}

impl Strut {
    /// Compression force (N) at compression `s` (m from static) and rate `ds` (m/s).
    #[inline]
    pub fn force(&self, s: f64, ds: f64) -> f64 {
        self.force_on(s, ds, self.piece(s))
    }

    /// Which piece of the force law holds at compression `s`: `1` on the compression stop
    /// (`s > half_travel`), `-1` on the extension stop (`s < -half_travel`), else `0`.
    #[inline]
    pub fn piece(&self, s: f64) -> i8 {
        if s > self.half_travel {
            1
        } else if s < -self.half_travel {
            -1
        } else {
            0
        }
    }

    /// The force of piece `piece` ([`Strut::piece`]) extended beyond its range: the clearance
    /// term is `s - half_travel` on piece 1, `s + half_travel` on piece -1, 0 on piece 0, so
    /// the force is linear in `s` and `ds` (a smooth law inside one integration step;
    /// docs/numerics.md, "Kinks").
    #[inline]
    pub fn force_on(&self, s: f64, ds: f64, piece: i8) -> f64 {
        let clear = match piece {
            1 => s - self.half_travel,
            -1 => s + self.half_travel,
            _ => 0.0,
        };
        self.preload + self.rate * s + self.damping * ds + self.bump_rate * clear
    }

    /// Switching function of piece `piece` at compression `s` (m): the distance of `s`
    /// inside that piece's range, positive inside, zero on its edge, negative beyond it.
    #[inline]
    pub fn switching(&self, s: f64, piece: i8) -> f64 {
        match piece {
            1 => s - self.half_travel,
            -1 => -self.half_travel - s,
            _ => (self.half_travel - s).min(s + self.half_travel),
        }
    }

    /// Stored energy (J) relative to static of the conservative part (preload, spring, stop).
    pub fn energy(&self, s: f64) -> f64 {
        let clear = s - s.clamp(-self.half_travel, self.half_travel);
        self.preload * s + 0.5 * self.rate * s * s + 0.5 * self.bump_rate * clear * clear
    }

    /// Whether the bump stop is engaged at compression `s`.
    pub fn on_stop(&self, s: f64) -> bool {
        s.abs() > self.half_travel
    }
}

/// The four struts and their geometry (module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Suspension {
    /// Front struts (left and right are equal).
    pub front: Strut,
    /// Rear struts.
    pub rear: Strut,
    /// Strut spacing ratio r (-).
    pub ratio: f64,
    /// Half spacing of the rear struts, `r T_r / 2` (m).
    pub rear_half_spacing: f64,
}

/// Joint coordinates (or velocities) the struts act on: `[q_fl, q_fr, q_b, q_phi]`.
pub type StrutJoints = [f64; 4];

impl Suspension {
    /// From the parameters, with preloads from the hand statics.
    pub fn new(p: &TruckParams) -> Self {
        let s = Statics::of(p);
        let strut = |rate: f64, damping: f64, travel: f64, preload: f64| Strut {
            rate,
            damping,
            half_travel: 0.5 * travel,
            bump_rate: p.bump_stop_ratio * rate,
            preload,
        };
        Self {
            front: strut(
                p.front_spring_n_per_m,
                p.front_damping_n_s_per_m,
                p.front_travel_m,
                s.front_strut_force_n,
            ),
            rear: strut(
                p.rear_spring_n_per_m,
                p.rear_damping_n_s_per_m,
                p.rear_travel_m,
                s.rear_strut_force_n,
            ),
            ratio: p.strut_spacing_ratio,
            rear_half_spacing: 0.5 * p.strut_spacing_ratio * p.rear_track_m,
        }
    }

    /// Strut compressions `[s_fl, s_fr, s_rl, s_rr]` (or their rates from joint rates).
    #[inline]
    pub fn compressions(&self, q: &StrutJoints) -> [f64; 4] {
        let heave = 0.5 * (q[0] + q[1]);
        let roll = 0.5 * self.ratio * (q[0] - q[1]);
        let rear_roll = self.rear_half_spacing * q[3];
        [
            heave + roll,
            heave - roll,
            q[2] + rear_roll,
            q[2] - rear_roll,
        ]
    }

    /// Strut forces `[F_fl, F_fr, F_rl, F_rr]` (N, compression positive).
    #[inline]
    pub fn forces(&self, q: &StrutJoints, dq: &StrutJoints) -> [f64; 4] {
        self.forces_on(q, dq, &self.pieces(q))
    }

    /// The pieces ([`Strut::piece`]) of the four struts at joint coordinates `q`.
    #[inline]
    pub fn pieces(&self, q: &StrutJoints) -> [i8; 4] {
        let s = self.compressions(q);
        std::array::from_fn(|i| self.strut(i).piece(s[i]))
    }

    /// Strut forces of the pieces `pieces` ([`Strut::force_on`]), in
    /// [`Suspension::forces`] order.
    #[inline]
    pub fn forces_on(&self, q: &StrutJoints, dq: &StrutJoints, pieces: &[i8; 4]) -> [f64; 4] {
        let s = self.compressions(q);
        let ds = self.compressions(dq);
        [
            self.front.force_on(s[0], ds[0], pieces[0]),
            self.front.force_on(s[1], ds[1], pieces[1]),
            self.rear.force_on(s[2], ds[2], pieces[2]),
            self.rear.force_on(s[3], ds[3], pieces[3]),
        ]
    }

    /// The strut of compression `i` ([`Suspension::compressions`] order).
    #[inline]
    pub fn strut(&self, i: usize) -> &Strut {
        if i < 2 {
            &self.front
        } else {
            &self.rear
        }
    }

    /// Joint-space forces `tau` on `[q_fl, q_fr, q_b, q_phi]` of strut forces `f`.
    #[inline]
    pub fn joint_forces(&self, f: &[f64; 4]) -> StrutJoints {
        let (a, b) = (0.5 * (1.0 + self.ratio), 0.5 * (1.0 - self.ratio));
        [
            -(a * f[0] + b * f[1]),
            -(b * f[0] + a * f[1]),
            -(f[2] + f[3]),
            -self.rear_half_spacing * (f[2] - f[3]),
        ]
    }

    /// Stored energy (J) of the four struts' conservative parts at joint coordinates `q`.
    pub fn energy(&self, q: &StrutJoints) -> f64 {
        let s = self.compressions(q);
        self.front.energy(s[0])
            + self.front.energy(s[1])
            + self.rear.energy(s[2])
            + self.rear.energy(s[3])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    proptest::proptest! {
        /// With the dampers at rest the struts are conservative: tau = -grad(energy), on and
        /// off the bump stops, for any spacing ratio.
        #[test]
        fn joint_forces_are_the_gradient_of_the_energy(
            ratio in 0.05..1.0_f64,
            q in proptest::array::uniform4(-0.3..0.3_f64),
        ) {
            let mut p = TruckParams::nominal();
            p.strut_spacing_ratio = ratio;
            let s = Suspension::new(&p);
            let tau = s.joint_forces(&s.forces(&q, &[0.0; 4]));
            for j in 0..4 {
                let h = 1e-7;
                let (mut a, mut b) = (q, q);
                a[j] += h;
                b[j] -= h;
                let grad = (s.energy(&a) - s.energy(&b)) / (2.0 * h);
                // a bump stop's kink inside the difference step costs at most k_b h (about
                // 6 N with the lever of the rear roll joint)
                let tol = 10.0 + 1e-7 * grad.abs();
                proptest::prop_assert!((tau[j] + grad).abs() < tol, "{} {} {}", j, tau[j], grad);
            }
        }
    }

    #[test]
    fn each_piece_extends_the_law_linearly_and_its_switch_marks_its_range() {
        let strut = Suspension::new(&TruckParams::nominal()).rear;
        let h = strut.half_travel;
        for s in [-1.5 * h, -h, -0.5 * h, 0.0, 0.7 * h, h, 1.2 * h] {
            // the law as written is its own piece's force
            assert_eq!(strut.force(s, 0.1), strut.force_on(s, 0.1, strut.piece(s)));
            // inside a piece its switch is positive, at the edge zero, beyond it negative
            for piece in [-1, 0, 1] {
                let g = strut.switching(s, piece);
                let inside = strut.piece(s) == piece;
                assert!(inside == (g > 0.0) || g == 0.0, "{s} {piece} {g}");
            }
        }
        assert_eq!(strut.switching(h, 0), 0.0);
        assert_eq!(strut.switching(h, 1), 0.0);
        // a stop's piece extended back into free travel keeps the stop's spring
        let on_stop = strut.force_on(0.5 * h, 0.0, 1);
        let free = strut.force_on(0.5 * h, 0.0, 0);
        assert!((on_stop - free + strut.bump_rate * 0.5 * h).abs() < 1e-6 * free.abs());
    }

    #[test]
    fn heave_rate_per_station_and_roll_rate_scale_with_the_ratio() {
        let mut p = TruckParams::nominal();
        p.strut_spacing_ratio = 0.5;
        let s = Suspension::new(&p);
        let f0 = s.forces(&[0.0; 4], &[0.0; 4]);
        let f1 = s.forces(&[0.01, 0.01, 0.0, 0.0], &[0.0; 4]);
        assert!((f1[0] - f0[0] - 0.01 * p.front_spring_n_per_m).abs() < 1e-6);
        // rear roll rate k (r T)^2 / 2
        let dphi = 1e-3;
        let tau = s.joint_forces(&s.forces(&[0.0, 0.0, 0.0, dphi], &[0.0; 4]));
        let expected = p.rear_spring_n_per_m * (0.5 * p.rear_track_m).powi(2) * 0.5 * dphi;
        assert!((-tau[3] - expected).abs() < 1e-6 * expected);
    }
}
