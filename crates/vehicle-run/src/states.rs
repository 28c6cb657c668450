//! The states both multibody vehicles share, as the component layer's [`StateInfo`]s: the
//! floating base of a tree (multibody's `Joint::Floating`: `q = [x, y, z, qw, qx, qy, qz]`,
//! `v = [omega; v_O]` in body axes) and the PI drive's two states. Each vehicle lays these
//! and its components' states into one [`vehicle_components::StateLayout`], whose typical
//! magnitudes set the run's absolute tolerances ([`crate::integrator`]) and whose names
//! name a state in an error ([`crate::run_error`]).

use vehicle_components::{StateInfo, StateLayout};

/// The floating base's configuration: the origin's world position (typical 1 m) and the
/// unit quaternion, scalar first (typical 1).
pub const FLOATING_Q: [StateInfo; 7] = [
    StateInfo::new("x_m", "m", 1.0),
    StateInfo::new("y_m", "m", 1.0),
    StateInfo::new("z_m", "m", 1.0),
    StateInfo::new("quat_w", "-", 1.0),
    StateInfo::new("quat_x", "-", 1.0),
    StateInfo::new("quat_y", "-", 1.0),
    StateInfo::new("quat_z", "-", 1.0),
];

/// The floating base's velocity in body axes: roll, pitch and yaw rates with the typical
/// magnitude `angular` (rad/s), the origin's velocity with `linear` (m/s).
pub const fn floating_v(angular: f64, linear: f64) -> [StateInfo; 6] {
    [
        StateInfo::new("roll_rate_rad_s", "rad/s", angular),
        StateInfo::new("pitch_rate_rad_s", "rad/s", angular),
        StateInfo::new("yaw_rate_rad_s", "rad/s", angular),
        StateInfo::new("vx_m_s", "m/s", linear),
        StateInfo::new("vy_m_s", "m/s", linear),
        StateInfo::new("vz_m_s", "m/s", linear),
    ]
}

/// The PI drive's states: the integral of the speed error and the path coordinate of the
/// vehicle's reference point (m, typical 1 m each).
pub const DRIVE: [StateInfo; 2] = [
    StateInfo::new("speed_error_integral_m", "m", 1.0),
    StateInfo::new("path_m", "m", 1.0),
];

/// Name of state `i` of `layout` in messages (a collapsing step names its state): its
/// name in the layout, `state i` past its end (a state an extension appends).
pub fn state_name(layout: &StateLayout, i: usize) -> String {
    layout
        .names()
        .get(i)
        .map_or_else(|| format!("state {i}"), Clone::clone)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_shared_states_lay_out_under_one_label() {
        let mut l = StateLayout::new();
        l.add("base", &FLOATING_Q).unwrap();
        l.add("base", &floating_v(0.1, 1.0)).unwrap();
        l.add("", &DRIVE).unwrap();
        assert_eq!(l.len(), 15);
        assert_eq!(l.names()[7], "base_roll_rate_rad_s");
        assert_eq!(l.typicals()[7..13], [0.1, 0.1, 0.1, 1.0, 1.0, 1.0]);
        assert_eq!(l.index_of("path_m"), Some(14));
        assert_eq!(state_name(&l, 14), "path_m");
        assert_eq!(state_name(&l, 15), "state 15");
    }
}
