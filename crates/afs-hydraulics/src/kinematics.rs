//! Strut kinematics: lengths, steering arms, displacements (Eqs 3.2, 3.8 / 4.3, 6.7).
//!
//! Sign convention: positive articulation theta is the paper's right-hand turn, in which
//! the valve feeds the P_c group and the left strut extends. With Eq 3.8,
//! `dl_L/dtheta = +h_L` and `dl_R/dtheta = -h_R` (h_L, h_R of Eq 3.2 are positive for
//! |theta| < A_0), so the left strut lengthens and the right strut shortens as theta grows.

/// Strut geometry at one articulation angle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StrutKinematics {
    /// l_L(theta), left strut length (m), Eq 3.8.
    pub length_left: f64,
    /// l_R(theta), right strut length (m), Eq 3.8.
    pub length_right: f64,
    /// h_L(theta) = dl_L/dtheta, left steering arm (m), Eq 3.2.
    pub arm_left: f64,
    /// h_R(theta) = -dl_R/dtheta, right steering arm (m), Eq 3.2.
    pub arm_right: f64,
    /// d_L = l_L - l_0, left strut displacement (m, + = extension), Eq 6.7.
    pub disp_left: f64,
    /// d_R = l_R - l_0, right strut displacement (m, + = extension), Eq 6.7.
    pub disp_right: f64,
}

/// Length of a strut whose mounts are `l1`, `l2` from the joint with included angle `angle`
/// (law of cosines, Eq 3.8): sqrt(l1² + l2² - 2 l1 l2 cos(angle)).
#[inline]
pub fn strut_length(l1: f64, l2: f64, angle: f64) -> f64 {
    (l1 * l1 + l2 * l2 - 2.0 * l1 * l2 * angle.cos()).sqrt()
}

/// Strut lengths, arms and displacements at articulation `theta` (rad) for the layout
/// `l1`, `l2` (m), `a0` (rad); `l0` is the initial strut length (Eq 3.7).
///
/// Eq 3.8: l_L = sqrt(l1²+l2²-2 l1 l2 cos(A0+theta)), l_R with (A0-theta);
/// Eq 3.2 / 4.3: h_L = l1 l2 sin(A0+theta)/l_L, h_R = l1 l2 sin(A0-theta)/l_R.
#[inline]
pub fn strut_kinematics(l1: f64, l2: f64, a0: f64, l0: f64, theta: f64) -> StrutKinematics {
    let (s_l, c_l) = (a0 + theta).sin_cos();
    let (s_r, c_r) = (a0 - theta).sin_cos();
    let base = l1 * l1 + l2 * l2;
    let p = l1 * l2;
    let length_left = (base - 2.0 * p * c_l).sqrt();
    let length_right = (base - 2.0 * p * c_r).sqrt();
    StrutKinematics {
        length_left,
        length_right,
        arm_left: p * s_l / length_left,
        arm_right: p * s_r / length_right,
        disp_left: length_left - l0,
        disp_right: length_right - l0,
    }
}
