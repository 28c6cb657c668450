//! The vehicle as a tree of rigid bodies on the multibody core (note 2.2):
//!
//! | body | joint | DOF |
//! |---|---|---|
//! | 0 front unit (origin at its Table 6.1 cg) | floating | X, Y, Z, roll, pitch, yaw |
//! | 1, 3 front-left / front-right wheel carrier (massless) | prismatic along the front unit's z (HPS), else fixed | strut travel |
//! | 2, 4 front-left / front-right wheel end | revolute about y | spin |
//! | 5 hitch (massless, at the joint) | revolute about z | articulation theta |
//! | 6 rear unit + payload (origin at the joint) | revolute about x | rear-unit roll |
//! | 7, 9 rear-left / rear-right wheel carrier (massless) | prismatic along the rear unit's z (rear HPS), else fixed | strut travel |
//! | 8, 10 rear-left / rear-right wheel end | revolute about y | spin |
//!
//! With the rear walking-beam bogie ([`crate::bogie`], `VehicleParams::bogie`) the rear
//! bodies are instead:
//!
//! | body | joint | DOF |
//! |---|---|---|
//! | 7, 11 rear-left / rear-right bogie carrier (massless, at the pivot) | prismatic along the rear unit's z (rear HPS), else fixed | strut travel |
//! | 8, 12 rear-left / rear-right beam (cg at the pivot) | revolute about the carrier's y | beam pitch |
//! | 9, 13 leading wheel end, `+s/2` along the beam | revolute about y | spin |
//! | 10, 14 trailing wheel end, `-s/2` along the beam | revolute about y | spin |
//!
//! 14 DOF unsuspended, 16 with the front-axle HPS (Table "s6_model_dof"), 18 with HPS on
//! both axles: the rear struts are mounted as the front ones, at the wheel centres along
//! the carrying unit's z, ratio 1 (`docs/layouts.md`, "HPS on any axle"). The bogie adds
//! two beam pitches and two spins (18, 20, 22); its struts sit at the pivots, one per side.
//! The two steering struts are massless force elements between the front unit and the
//! hitch, so their spins about their own axes (Fig 6.2) do not appear.
//!
//! The bogie's pivot lies at the rear axle position (`rear_axle_to_joint_m`) at the wheel
//! centres' height (assumption: the drive torque reacted on the beam then balances the
//! tires' longitudinal forces about the pivot, so driving does not pitch the beam).
//!
//! The geometry is laid out in the static pose: every body level, the cgs at their Table 6.1
//! heights, the wheel centres at the free radius minus the static tire deflection
//! ([`crate::statics`]). With the static tire loads this pose is an exact equilibrium, so
//! every joint coordinate is zero there (the struts' static travel is a constant offset).
//! The wheel ends are bodies of their own; the unit bodies carry the Table 6.1 mass less
//! their wheel ends, with cg and inertia corrected so that unit plus wheels is exactly the
//! Table 6.1 part.
//!
//! With [`YawInertiaForm::PaperEq313`] each unit's yaw inertia about its cg (the rear
//! unit's with the payload of the load case) grows by its mass times its cg's squared
//! distance from the joint: the printed Eq 3.13, kept to show the gap to the paper.
//!
//! Articulation sign: the hitch joint turns the rear unit about the front unit's +z, which
//! is the paper's positive theta (right-hand turn: the front unit yawed clockwise relative to
//! the rear), in which the left strut extends (Eq 3.8).

use multibody::{Body, Joint, Model, ModelBuilder};
use nalgebra::{Isometry3, Matrix3, Vector3};

use crate::bogie::BogieParams;
use crate::error::{rejected, VehicleError};
use crate::params::{Load, RigidPart, VehicleParams, YawInertiaForm};
use crate::statics::Statics;

/// Body indices of the tree.
pub mod body {
    /// Front unit (floating base).
    pub const FRONT: usize = 0;
    /// Front-left wheel carrier.
    pub const CARRIER_FL: usize = 1;
    /// Front-left wheel end.
    pub const WHEEL_FL: usize = 2;
    /// Front-right wheel carrier.
    pub const CARRIER_FR: usize = 3;
    /// Front-right wheel end.
    pub const WHEEL_FR: usize = 4;
    /// Massless hitch between the articulation yaw and roll revolutes.
    pub const HITCH: usize = 5;
    /// Rear unit with its payload.
    pub const REAR: usize = 6;
    /// Rear-left wheel carrier.
    pub const CARRIER_RL: usize = 7;
    /// Rear-left wheel end.
    pub const WHEEL_RL: usize = 8;
    /// Rear-right wheel carrier.
    pub const CARRIER_RR: usize = 9;
    /// Rear-right wheel end.
    pub const WHEEL_RR: usize = 10;
    /// With the bogie: rear-left carrier at the pivot.
    pub const BOGIE_CARRIER_RL: usize = 7;
    /// With the bogie: rear-left beam.
    pub const BEAM_RL: usize = 8;
    /// With the bogie: rear-left leading wheel end.
    pub const WHEEL_RL_LEAD: usize = 9;
    /// With the bogie: rear-left trailing wheel end.
    pub const WHEEL_RL_TRAIL: usize = 10;
    /// With the bogie: rear-right carrier at the pivot.
    pub const BOGIE_CARRIER_RR: usize = 11;
    /// With the bogie: rear-right beam.
    pub const BEAM_RR: usize = 12;
    /// With the bogie: rear-right leading wheel end.
    pub const WHEEL_RR_LEAD: usize = 13;
    /// With the bogie: rear-right trailing wheel end.
    pub const WHEEL_RR_TRAIL: usize = 14;
}

/// Largest number of tires (the rear tandem's six).
pub const MAX_TIRES: usize = 6;

/// Tire names in state and record order.
pub const TIRE_NAMES: [&str; 4] = ["front_left", "front_right", "rear_left", "rear_right"];

/// Tire names with the rear bogie, in state and record order: the front pair, the leading
/// rear pair, the trailing rear pair.
pub const TANDEM_TIRE_NAMES: [&str; MAX_TIRES] = [
    "front_left",
    "front_right",
    "rear_left_lead",
    "rear_right_lead",
    "rear_left_trail",
    "rear_right_trail",
];

/// The tire names of a vehicle with or without the rear bogie.
pub fn tire_names(bogie: bool) -> &'static [&'static str] {
    if bogie {
        &TANDEM_TIRE_NAMES
    } else {
        &TIRE_NAMES
    }
}

/// The tire mounts of a vehicle with or without the rear bogie, in [`tire_names`] order.
pub fn tire_mounts(bogie: bool) -> &'static [TireMount] {
    if bogie {
        &TANDEM_MOUNTS
    } else {
        &TIRE_MOUNTS
    }
}

/// Where a tire sits: its wheel body, the non-spinning body that carries it (its heading
/// and axle direction), its side and axle.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TireMount {
    /// Wheel body (origin at the wheel centre).
    pub wheel: usize,
    /// Carrier body (front carriers, rear unit), whose x axis is the wheel heading.
    pub carrier: usize,
    /// Left side (runs on the left track).
    pub left: bool,
    /// Front axle.
    pub front: bool,
}

impl TireMount {
    /// Index of the effective track the tire runs on ([`crate::tires::TireTracks`]: front
    /// left, front right, rear left, rear right): the tandem's two wheels of a side share
    /// their side's rear track, read at their own path coordinate.
    pub fn track(&self) -> usize {
        2 * usize::from(!self.front) + usize::from(!self.left)
    }
}

/// The four tire mounts in [`TIRE_NAMES`] order.
pub const TIRE_MOUNTS: [TireMount; 4] = [
    TireMount {
        wheel: body::WHEEL_FL,
        carrier: body::CARRIER_FL,
        left: true,
        front: true,
    },
    TireMount {
        wheel: body::WHEEL_FR,
        carrier: body::CARRIER_FR,
        left: false,
        front: true,
    },
    TireMount {
        wheel: body::WHEEL_RL,
        carrier: body::CARRIER_RL,
        left: true,
        front: false,
    },
    TireMount {
        wheel: body::WHEEL_RR,
        carrier: body::CARRIER_RR,
        left: false,
        front: false,
    },
];

/// The six tire mounts with the rear bogie in [`TANDEM_TIRE_NAMES`] order: the rear
/// wheels' carrier is their side's bogie carrier (its x axis the heading; the beam pitches).
pub const TANDEM_MOUNTS: [TireMount; MAX_TIRES] = [
    TIRE_MOUNTS[0],
    TIRE_MOUNTS[1],
    TireMount {
        wheel: body::WHEEL_RL_LEAD,
        carrier: body::BOGIE_CARRIER_RL,
        left: true,
        front: false,
    },
    TireMount {
        wheel: body::WHEEL_RR_LEAD,
        carrier: body::BOGIE_CARRIER_RR,
        left: false,
        front: false,
    },
    TireMount {
        wheel: body::WHEEL_RL_TRAIL,
        carrier: body::BOGIE_CARRIER_RL,
        left: true,
        front: false,
    },
    TireMount {
        wheel: body::WHEEL_RR_TRAIL,
        carrier: body::BOGIE_CARRIER_RR,
        left: false,
        front: false,
    },
];

/// Points the vehicle needs, in body coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Layout {
    /// Steering-strut mounts on the front unit, left and right.
    pub strut_front: [Vector3<f64>; 2],
    /// Steering-strut mounts on the hitch, left and right.
    pub strut_hitch: [Vector3<f64>; 2],
    /// The a_wz point on the front unit.
    pub cab: Vector3<f64>,
    /// The articulation joint centre on the front unit.
    pub joint_on_front: Vector3<f64>,
    /// The rear unit's (with payload and rear wheels) combined cg in the rear frame.
    pub rear_cg: Vector3<f64>,
    /// Mass of the rear unit with payload and rear wheels (kg).
    pub rear_mass_kg: f64,
}

/// Mass, cg and inertia about the cg of a rigid set of parts.
#[derive(Debug, Clone, Copy, PartialEq)]
struct MassProps {
    mass: f64,
    com: Vector3<f64>,
    inertia: Matrix3<f64>,
}

impl MassProps {
    fn new(mass: f64, com: Vector3<f64>, inertia: Matrix3<f64>) -> Self {
        Self { mass, com, inertia }
    }

    fn of_part(part: &RigidPart, at: Vector3<f64>) -> Self {
        Self::new(
            part.mass_kg,
            at,
            Matrix3::from_diagonal(&Vector3::new(
                part.roll_inertia_kg_m2,
                part.pitch_inertia_kg_m2,
                part.yaw_inertia_kg_m2,
            )),
        )
    }

    /// Inertia about the point `p` (parallel axis theorem).
    fn about(&self, p: &Vector3<f64>) -> Matrix3<f64> {
        let d = self.com - p;
        self.inertia + self.mass * (Matrix3::identity() * d.dot(&d) - d * d.transpose())
    }

    /// `self` plus `sign` times `other` (sign -1 removes a part).
    fn combine(&self, other: &Self, sign: f64) -> Self {
        let mass = self.mass + sign * other.mass;
        let com = (self.com * self.mass + sign * other.com * other.mass) / mass;
        let about_com = self.about(&com) + sign * other.about(&com);
        Self::new(mass, com, about_com)
    }
}

/// One beam of the bogie at the origin: its mass, and its inertia about the pivot with the
/// roll part of [`crate::bogie::BEAM_ROLL_TO_PITCH`] and yaw equal to pitch.
fn beam_props(bogie: &BogieParams) -> MassProps {
    let pitch = bogie.beam_pitch_inertia_kg_m2;
    MassProps::new(
        bogie.beam_mass_kg,
        Vector3::zeros(),
        Matrix3::from_diagonal(&Vector3::new(
            crate::bogie::BEAM_ROLL_TO_PITCH * pitch,
            pitch,
            pitch,
        )),
    )
}

/// The two wheel centres of a beam from its pivot, leading then trailing.
fn tandem_ends(bogie: &BogieParams) -> [Vector3<f64>; 2] {
    let h = bogie.half_spacing_m();
    [Vector3::new(h, 0.0, 0.0), Vector3::new(-h, 0.0, 0.0)]
}

/// Whether the front wheel carriers slide (front-axle HPS) or are fixed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FrontAxle {
    /// Wheels fixed to the front unit (the prototype, L1568).
    Rigid,
    /// Prismatic carriers with one HPS strut each.
    Suspended,
}

/// The multibody tree and the layout of `p` for `load` (parameters validated by the
/// caller); `lock_rear_roll` fixes the rear-unit roll joint (the yaw-mode analysis). The
/// rear carriers slide when `p.rear_hps` holds a strut.
pub fn build_tree(
    p: &VehicleParams,
    load: Load,
    statics: &Statics,
    front_axle: FrontAxle,
    lock_rear_roll: bool,
) -> Result<(Model, Layout), VehicleError> {
    let r = p.tire.unloaded_radius_m;
    let f = &p.front_unit;
    let (d_f, h_f, h_j) = (f.cg_to_joint_m, f.cg_height_m, p.joint_height_m);
    let joint = Vector3::new(-d_f, 0.0, h_j - h_f);
    let wheel = MassProps::new(
        p.wheel_mass_kg,
        Vector3::zeros(),
        Matrix3::from_diagonal(&Vector3::new(
            p.wheel_tilt_inertia_kg_m2,
            p.wheel_spin_inertia_kg_m2,
            p.wheel_tilt_inertia_kg_m2,
        )),
    );
    let at = |c: Vector3<f64>| MassProps { com: c, ..wheel };

    // front unit: Table 6.1 part at the origin, less its two wheel ends
    let z_fw = r - statics.front_tire_deflection_m - h_f;
    let x_fw = p.front_axle_x_m();
    let half_f = 0.5 * p.front_track_m;
    let front_wheels = [
        Vector3::new(x_fw, half_f, z_fw),
        Vector3::new(x_fw, -half_f, z_fw),
    ];
    let mut front = MassProps::of_part(f, Vector3::zeros());
    let paper_form = p.yaw_inertia_form == YawInertiaForm::PaperEq313;
    if paper_form {
        front.inertia[(2, 2)] += f.mass_kg * d_f * d_f;
    }
    for c in front_wheels {
        front = front.combine(&at(c), -1.0);
    }
    // rear unit (+ payload), frame at the joint, less its two wheel ends
    let rear_parts: Vec<MassProps> = p
        .rear_parts(load)
        .iter()
        .map(|part| {
            MassProps::of_part(
                part,
                Vector3::new(-part.cg_to_joint_m, 0.0, part.cg_height_m - h_j),
            )
        })
        .collect();
    let mut rear_all = rear_parts[0];
    for part in &rear_parts[1..] {
        rear_all = rear_all.combine(part, 1.0);
    }
    if paper_form {
        // the horizontal distance of the combined cg from the joint is |x| (y = 0)
        rear_all.inertia[(2, 2)] += rear_all.mass * rear_all.com.x * rear_all.com.x;
    }
    let z_rw = r - statics.rear_tire_deflection_m - h_j;
    let half_r = 0.5 * p.rear_track_m;
    // the single rear axle's wheel centres, or the bogie's pivots
    let rear_wheels = [
        Vector3::new(-p.rear_axle_to_joint_m, half_r, z_rw),
        Vector3::new(-p.rear_axle_to_joint_m, -half_r, z_rw),
    ];
    let mut rear = rear_all;
    match &p.bogie {
        None => {
            for c in rear_wheels {
                rear = rear.combine(&at(c), -1.0);
            }
        }
        Some(bogie) => {
            let beam = beam_props(bogie);
            let ends = tandem_ends(bogie);
            for pivot in rear_wheels {
                rear = rear.combine(&MassProps { com: pivot, ..beam }, -1.0);
                for e in ends {
                    rear = rear.combine(&at(pivot + e), -1.0);
                }
            }
        }
    }
    for (field, m) in [
        ("front_unit.roll_inertia_kg_m2", &front),
        ("rear_unit.roll_inertia_kg_m2", &rear),
    ] {
        let eig = m.inertia.symmetric_eigenvalues();
        if eig.iter().any(|&e| e <= 0.0) {
            return Err(rejected(
                field,
                m.inertia[(0, 0)],
                "the unit's inertia less its wheel ends is not positive definite",
            ));
        }
    }

    let mut b = ModelBuilder::new(Vector3::new(0.0, 0.0, -p.gravity_m_s2));
    let place = |c: Vector3<f64>| Isometry3::translation(c.x, c.y, c.z);
    let spin = Joint::Revolute { axis: Vector3::y() };
    let slide = |suspended: bool| {
        if suspended {
            Joint::Prismatic { axis: Vector3::z() }
        } else {
            Joint::Fixed
        }
    };
    let carrier_joint = slide(front_axle == FrontAxle::Suspended);
    b.add_body(Body {
        name: "front_unit".into(),
        parent: None,
        joint: Joint::Floating,
        placement: Isometry3::identity(),
        mass: front.mass,
        com: front.com,
        inertia: front.inertia,
    });
    let wheel_body = |name: &str, parent: usize, placement: Isometry3<f64>| Body {
        name: name.into(),
        parent: Some(parent),
        joint: spin,
        placement,
        mass: wheel.mass,
        com: Vector3::zeros(),
        inertia: wheel.inertia,
    };
    let carrier_body = |name: String, parent: usize, joint: Joint, c: Vector3<f64>| Body {
        name,
        parent: Some(parent),
        joint,
        placement: place(c),
        mass: 0.0,
        com: Vector3::zeros(),
        inertia: Matrix3::zeros(),
    };
    for (side, c) in ["left", "right"].into_iter().zip(front_wheels) {
        let carrier = b.add_body(carrier_body(
            format!("carrier_front_{side}"),
            body::FRONT,
            carrier_joint,
            c,
        ));
        b.add_body(wheel_body(
            &format!("wheel_front_{side}"),
            carrier,
            Isometry3::identity(),
        ));
    }
    b.add_body(Body {
        name: "hitch".into(),
        parent: Some(body::FRONT),
        joint: Joint::Revolute { axis: Vector3::z() },
        placement: place(joint),
        mass: 0.0,
        com: Vector3::zeros(),
        inertia: Matrix3::zeros(),
    });
    b.add_body(Body {
        name: "rear_unit".into(),
        parent: Some(body::HITCH),
        joint: if lock_rear_roll {
            Joint::Fixed
        } else {
            Joint::Revolute { axis: Vector3::x() }
        },
        placement: Isometry3::identity(),
        mass: rear.mass,
        com: rear.com,
        inertia: rear.inertia,
    });
    let rear_joint = slide(p.rear_hps.is_some());
    for (side, c) in ["left", "right"].into_iter().zip(rear_wheels) {
        let carrier = b.add_body(carrier_body(
            format!("carrier_rear_{side}"),
            body::REAR,
            rear_joint,
            c,
        ));
        match &p.bogie {
            None => {
                b.add_body(wheel_body(
                    &format!("wheel_rear_{side}"),
                    carrier,
                    Isometry3::identity(),
                ));
            }
            Some(bogie) => {
                let beam = beam_props(bogie);
                let beam_body = b.add_body(Body {
                    name: format!("beam_rear_{side}"),
                    parent: Some(carrier),
                    joint: spin,
                    placement: Isometry3::identity(),
                    mass: beam.mass,
                    com: Vector3::zeros(),
                    inertia: beam.inertia,
                });
                for (end, e) in ["lead", "trail"].into_iter().zip(tandem_ends(bogie)) {
                    b.add_body(wheel_body(
                        &format!("wheel_rear_{side}_{end}"),
                        beam_body,
                        place(e),
                    ));
                }
            }
        }
    }
    let model = b.build()?;

    let s = &p.steering;
    let phi = std::f64::consts::FRAC_PI_2 - s.a0_rad;
    let front_mount =
        |side: f64| joint + Vector3::new(s.l1_m * phi.cos(), side * s.l1_m * phi.sin(), 0.0);
    let cab = Vector3::new(
        p.cab_point_m[0] - d_f,
        p.cab_point_m[1],
        p.cab_point_m[2] - h_f,
    );
    let layout = Layout {
        strut_front: [front_mount(1.0), front_mount(-1.0)],
        strut_hitch: [
            Vector3::new(0.0, s.l2_m, 0.0),
            Vector3::new(0.0, -s.l2_m, 0.0),
        ],
        cab,
        joint_on_front: joint,
        rear_cg: rear_all.com,
        rear_mass_kg: rear_all.mass,
    };
    Ok((model, layout))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tree(load: Load, axle: FrontAxle) -> (Model, Layout) {
        let p = VehicleParams::nominal();
        let s = Statics::of(&p, load).unwrap();
        build_tree(&p, load, &s, axle, false).unwrap()
    }

    #[test]
    fn dof_count_is_14_unsuspended_16_with_the_front_hps_18_with_both() {
        let (m, _) = tree(Load::Loaded, FrontAxle::Rigid);
        assert_eq!(m.nv(), 6 + 4 + 2);
        // the issue counts the 2 idle strut spins of Fig 6.2 among the 14
        assert_eq!(m.nv() + 2, 14);
        let (m, _) = tree(Load::Loaded, FrontAxle::Suspended);
        assert_eq!(m.nv() + 2, 16);
        let mut p = VehicleParams::nominal();
        p.rear_hps = Some(p.hps);
        let s = Statics::of(&p, Load::Loaded).unwrap();
        let (m, _) = build_tree(&p, Load::Loaded, &s, FrontAxle::Suspended, false).unwrap();
        assert_eq!(m.nv() + 2, 18);
    }

    #[test]
    fn the_bogie_adds_two_beam_pitches_and_two_spins_and_keeps_the_masses() {
        let mut p = VehicleParams::nominal();
        p.bogie = Some(BogieParams::default());
        for (rear_hps, dof) in [(false, 18), (true, 20)] {
            if rear_hps {
                p.rear_hps = Some(p.default_rear_strut().unwrap());
            }
            let s = Statics::of(&p, Load::Loaded).unwrap();
            let (m, l) = build_tree(&p, Load::Loaded, &s, FrontAxle::Rigid, false).unwrap();
            assert_eq!(m.nv() + 2, dof);
            assert!((m.total_mass() - 73_220.0).abs() < 1e-6);
            assert!((l.rear_mass_kg - 52_220.0).abs() < 1e-6);
            assert!((l.rear_cg.x + 2.6852).abs() < 1e-3, "{:?}", l.rear_cg);
        }
        // the mounts name the bodies the tree builds
        let s = Statics::of(&p, Load::Loaded).unwrap();
        let (m, _) = build_tree(&p, Load::Loaded, &s, FrontAxle::Rigid, false).unwrap();
        assert_eq!(m.body_index("beam_rear_left"), Some(body::BEAM_RL));
        assert_eq!(
            m.body_index("wheel_rear_right_trail"),
            Some(body::WHEEL_RR_TRAIL)
        );
        assert_eq!(
            m.body_index("carrier_rear_right"),
            Some(body::BOGIE_CARRIER_RR)
        );
        for (i, mount) in TANDEM_MOUNTS.iter().enumerate() {
            assert_eq!(mount.track(), TIRE_MOUNTS[i.min(2 + i % 2)].track());
        }
    }

    #[test]
    fn masses_are_the_table_6_1_totals() {
        let (m, l) = tree(Load::Loaded, FrontAxle::Rigid);
        assert!((m.total_mass() - 73_220.0).abs() < 1e-6);
        assert!((l.rear_mass_kg - 52_220.0).abs() < 1e-6);
        // rear unit + payload cg 2.685 m behind the joint at 2.099 m height (note 2.10)
        assert!((l.rear_cg.x + 2.6852).abs() < 1e-3, "{:?}", l.rear_cg);
        assert!((l.rear_cg.z + 1.0 - 2.099).abs() < 1e-3, "{:?}", l.rear_cg);
        let (m, _) = tree(Load::Unloaded, FrontAxle::Suspended);
        assert!((m.total_mass() - 39_500.0).abs() < 1e-6);
    }

    #[test]
    fn strut_mounts_reproduce_the_planar_layout() {
        let p = VehicleParams::nominal();
        let (_, l) = tree(Load::Loaded, FrontAxle::Rigid);
        for side in 0..2 {
            let (a, b) = (l.strut_front[side] - l.joint_on_front, l.strut_hitch[side]);
            assert!((a.norm() - p.steering.l1_m).abs() < 1e-12);
            assert!((b.norm() - p.steering.l2_m).abs() < 1e-12);
            let angle = (a.dot(&b) / (a.norm() * b.norm())).acos();
            assert!((angle - p.steering.a0_rad).abs() < 1e-12);
        }
    }
}
