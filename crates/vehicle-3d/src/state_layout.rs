//! The vehicle's state vector as one [`StateLayout`] (docs/vehicle-3d.md, "States"): the
//! tree's configuration and velocities (the floating base of `vehicle_run::states`, then
//! the joints in tree order), the steering system's states (`AfsSystem` as a
//! `Component`), each tire's slip lags (`tire_fiala::relaxation::SLIP_LAG_STATES`), each
//! strut's states (`HpsStrut::states`), the PI drive's and the driver's. Every state has its
//! name with unit, its unit and the typical magnitude that sets its absolute tolerance.
//! The right-hand side reads the blocks at the plain indices of [`Offsets`], taken from
//! the layout once when the vehicle is built.

use vehicle_components::{StateInfo, StateLayout};

use crate::error::{rejected, VehicleError};
use crate::model::MAX_TIRES;
use crate::vehicle::Joints;

/// A joint after the floating base: its coordinate and its rate. Angles and travels are
/// small (typical 0.05 rad or m, rates 0.1 rad/s or m/s); wheel spins are not (10 rad,
/// 10 rad/s).
type JointStates = [StateInfo; 2];

const ARTICULATION: JointStates = [
    StateInfo::new("articulation_rad", "rad", 0.05),
    StateInfo::new("articulation_rate_rad_s", "rad/s", 0.1),
];

const REAR_ROLL: JointStates = [
    StateInfo::new("rear_roll_rad", "rad", 0.05),
    StateInfo::new("rear_roll_rate_rad_s", "rad/s", 0.1),
];

/// Per tire in [`crate::model::TIRE_NAMES`] order.
const SPIN: [JointStates; 4] = [
    [
        StateInfo::new("front_left_spin_rad", "rad", 10.0),
        StateInfo::new("front_left_spin_rate_rad_s", "rad/s", 10.0),
    ],
    [
        StateInfo::new("front_right_spin_rad", "rad", 10.0),
        StateInfo::new("front_right_spin_rate_rad_s", "rad/s", 10.0),
    ],
    [
        StateInfo::new("rear_left_spin_rad", "rad", 10.0),
        StateInfo::new("rear_left_spin_rate_rad_s", "rad/s", 10.0),
    ],
    [
        StateInfo::new("rear_right_spin_rad", "rad", 10.0),
        StateInfo::new("rear_right_spin_rate_rad_s", "rad/s", 10.0),
    ],
];

/// Per tire in [`crate::model::TANDEM_TIRE_NAMES`] order (with the rear bogie).
const TANDEM_SPIN: [JointStates; MAX_TIRES] = [
    SPIN[0],
    SPIN[1],
    [
        StateInfo::new("rear_left_lead_spin_rad", "rad", 10.0),
        StateInfo::new("rear_left_lead_spin_rate_rad_s", "rad/s", 10.0),
    ],
    [
        StateInfo::new("rear_right_lead_spin_rad", "rad", 10.0),
        StateInfo::new("rear_right_lead_spin_rate_rad_s", "rad/s", 10.0),
    ],
    [
        StateInfo::new("rear_left_trail_spin_rad", "rad", 10.0),
        StateInfo::new("rear_left_trail_spin_rate_rad_s", "rad/s", 10.0),
    ],
    [
        StateInfo::new("rear_right_trail_spin_rad", "rad", 10.0),
        StateInfo::new("rear_right_trail_spin_rate_rad_s", "rad/s", 10.0),
    ],
];

/// The bogie's beam pitches, left then right (small angles, typical 0.05 rad).
const BEAM_PITCH: [JointStates; 2] = [
    [
        StateInfo::new("rear_left_beam_pitch_rad", "rad", 0.05),
        StateInfo::new("rear_left_beam_pitch_rate_rad_s", "rad/s", 0.1),
    ],
    [
        StateInfo::new("rear_right_beam_pitch_rad", "rad", 0.05),
        StateInfo::new("rear_right_beam_pitch_rate_rad_s", "rad/s", 0.1),
    ],
];

/// The carriers of a suspended axle, left then right: front, then rear.
const CARRIER: [[JointStates; 2]; 2] = [
    [
        [
            StateInfo::new("front_left_carrier_m", "m", 0.05),
            StateInfo::new("front_left_carrier_rate_m_s", "m/s", 0.1),
        ],
        [
            StateInfo::new("front_right_carrier_m", "m", 0.05),
            StateInfo::new("front_right_carrier_rate_m_s", "m/s", 0.1),
        ],
    ],
    [
        [
            StateInfo::new("rear_left_carrier_m", "m", 0.05),
            StateInfo::new("rear_left_carrier_rate_m_s", "m/s", 0.1),
        ],
        [
            StateInfo::new("rear_right_carrier_m", "m", 0.05),
            StateInfo::new("rear_right_carrier_rate_m_s", "m/s", 0.1),
        ],
    ],
];

/// The path-following driver's steering-wheel angle (rad, typical 1).
const STEER_WHEEL: [StateInfo; 1] = [StateInfo::new("steer_wheel_rad", "rad", 1.0)];

/// The labels of the struts' blocks: front axle left and right, then rear.
pub(crate) const STRUT_LABELS: [[&str; 2]; 2] = [
    ["front_left_hps", "front_right_hps"],
    ["rear_left_hps", "rear_right_hps"],
];

/// Append the tree's configuration and velocity blocks (the floating base, then the joints
/// of `joints` in the tree's order) for a tree of `nq` coordinates and `nv` velocities.
pub(crate) fn add_tree_states(
    layout: &mut StateLayout,
    joints: &Joints,
    nq: usize,
    nv: usize,
) -> Result<(), VehicleError> {
    let mut by_joint: Vec<((usize, usize), &JointStates)> =
        vec![(joints.articulation, &ARTICULATION)];
    by_joint.extend(joints.rear_roll.map(|j| (j, &REAR_ROLL)));
    let spin_names: &[JointStates] = if joints.beam.is_some() {
        &TANDEM_SPIN
    } else {
        &SPIN
    };
    by_joint.extend(joints.spins().iter().copied().zip(spin_names));
    by_joint.extend(joints.beam.iter().flatten().copied().zip(&BEAM_PITCH));
    for (axle, carriers) in [joints.carrier, joints.rear_carrier].iter().enumerate() {
        by_joint.extend(carriers.iter().flatten().copied().zip(&CARRIER[axle]));
    }
    let ordered = |of: fn(&(usize, usize)) -> usize, k: usize| -> Vec<StateInfo> {
        let mut v: Vec<_> = by_joint.iter().map(|(j, s)| (of(j), s[k])).collect();
        v.sort_by_key(|&(i, _)| i);
        v.into_iter().map(|(_, s)| s).collect()
    };
    let (q, v) = (ordered(|j| j.0, 0), ordered(|j| j.1, 1));
    let base_v = vehicle_run::states::floating_v(0.1, 0.1);
    let named = vehicle_run::states::FLOATING_Q.len() + q.len() + base_v.len() + v.len();
    if named != nq + nv {
        return Err(rejected(
            "layout",
            named as f64,
            "the tree has coordinates the state layout does not name",
        ));
    }
    layout.add("base", &vehicle_run::states::FLOATING_Q)?;
    layout.add("", &q)?;
    layout.add("base", &base_v)?;
    layout.add("", &v)?;
    Ok(())
}

/// Append each tire's slip-lag block, in `names` order ([`crate::model::tire_names`]);
/// returns the first index.
pub(crate) fn add_tire_states(
    layout: &mut StateLayout,
    names: &[&str],
) -> Result<usize, VehicleError> {
    let at = layout.len();
    for name in names {
        layout.add(name, &tire_fiala::relaxation::SLIP_LAG_STATES)?;
    }
    Ok(at)
}

/// Append the drive's states and, with the path-following driver, the steering-wheel
/// angle; returns the index of the speed-error integral and of the steering-wheel angle.
pub(crate) fn add_drive_states(
    layout: &mut StateLayout,
    driver: bool,
) -> Result<(usize, Option<usize>), VehicleError> {
    let pi = layout.len();
    layout.add("", &vehicle_run::states::DRIVE)?;
    let wheel = if driver {
        let at = layout.len();
        layout.add("driver", &STEER_WHEEL)?;
        Some(at)
    } else {
        None
    };
    Ok((pi, wheel))
}
