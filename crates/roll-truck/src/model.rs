//! The truck as a tree of rigid bodies on the multibody core (note 1.2, 10 DOF):
//!
//! | body | joint | DOF |
//! |---|---|---|
//! | 0 sprung mass (origin at its cg) | floating | X, Y, Z, roll, pitch, yaw |
//! | 1, 2 front-left / front-right wheel carrier | prismatic along the sprung z axis | travel |
//! | 3 rear bounce (massless) | prismatic along the sprung z axis | axle bounce |
//! | 4 rear axle (dual tires) | revolute about x at the rear roll centre | axle roll |
//!
//! Roll centres ([`TruckParams::front_roll_centre_height_m`], `rear_roll_centre_height_m`,
//! heights above ground at static equilibrium): each front tire hangs from its carrier at
//! the carrier-fixed point at the front roll-centre height, a vertical column of the static
//! length from there to the wheel-centre height ([`TireMount::column_m`]); the rear axle's roll
//! joint sits at the rear roll-centre height above the axle's centre line. At the nominal
//! heights (the static wheel centres) the columns have zero length and the joint is at the
//! axle centre.
//!
//! Joint coordinates are zero at the static equilibrium of [`crate::statics`] (sprung cg
//! at `cg_height_m`, wheel centres at the free radius minus the static tire deflection),
//! positive for a compressing left strut. Wheel spins are left out: no longitudinal tire
//! slip is modelled and the PI drive force acts directly at the rear contact patches
//! (note 1.2, the minimal option). Unsprung masses have their cg at the wheel centres.

use multibody::{Body, Joint, Model, ModelBuilder};
use nalgebra::{Isometry3, Matrix3, Translation3, UnitQuaternion, Vector3};

use crate::error::TruckError;
use crate::params::TruckParams;
use crate::statics::Statics;

/// Body indices of the tree.
pub mod body {
    /// Sprung mass (floating base).
    pub const SPRUNG: usize = 0;
    /// Front-left wheel carrier.
    pub const FRONT_LEFT: usize = 1;
    /// Front-right wheel carrier.
    pub const FRONT_RIGHT: usize = 2;
    /// Massless rear bounce slider.
    pub const REAR_BOUNCE: usize = 3;
    /// Rear solid axle.
    pub const REAR_AXLE: usize = 4;
}

/// Number of configuration coordinates (7 floating + 4 joints).
pub const NQ: usize = 11;
/// Number of degrees of freedom.
pub const NV: usize = 10;

/// Tire names in state and record order.
pub const TIRE_NAMES: [&str; 6] = [
    "front_left",
    "front_right",
    "rear_left_outer",
    "rear_left_inner",
    "rear_right_inner",
    "rear_right_outer",
];

/// Where a tire sits: its body, the point it hangs from in body coordinates, the column
/// down to its wheel centre, side and axle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TireMount {
    /// Body index carrying the wheel.
    pub body: usize,
    /// Point the tire hangs from, in body coordinates (m): the wheel centre, or for a front
    /// tire the carrier-fixed point at the front roll-centre height.
    pub point: Vector3<f64>,
    /// Height (world z) of the effective wheel centre above `point` (m): the wheel-centre
    /// height minus the roll-centre height for a front tire, else 0. The tire's deflection
    /// and contact are those of a wheel centred `column_m` above `point` (below it for a
    /// roll centre above the wheel centre), its slip velocity is the velocity of `point`, its forces act on `body` along lines
    /// through the contact below that centre.
    pub column_m: f64,
    /// Left side (runs on the left track).
    pub left: bool,
    /// Front axle (steered).
    pub front: bool,
}

/// The multibody tree and the tire mounts of `p` (validated by the caller).
pub fn build_tree(p: &TruckParams) -> Result<(Model, [TireMount; 6]), TruckError> {
    let s = Statics::of(p);
    let r = p.tire_free_radius_m;
    let z_front = r - s.front_tire_deflection_m - p.cg_height_m;
    let z_rear = r - s.rear_tire_deflection_m - p.cg_height_m;
    // rear roll joint and front tire columns at the roll-centre heights (module docs)
    let z_joint = p.rear_roll_centre_height_m - p.cg_height_m;
    let axle_below_joint = z_rear - z_joint;
    let front_column = (r - s.front_tire_deflection_m) - p.front_roll_centre_height_m;
    let (a, b) = (p.cg_to_front_axle_m, p.cg_to_rear_axle_m());
    let mut builder = ModelBuilder::new(Vector3::new(0.0, 0.0, -p.gravity_m_s2));
    let place = |x: f64, y: f64, z: f64| {
        Isometry3::from_parts(Translation3::new(x, y, z), UnitQuaternion::identity())
    };
    let diag = |x: f64, y: f64, z: f64| Matrix3::from_diagonal(&Vector3::new(x, y, z));
    let slider = Joint::Prismatic { axis: Vector3::z() };
    builder.add_body(Body {
        name: "sprung".into(),
        parent: None,
        joint: Joint::Floating,
        placement: Isometry3::identity(),
        mass: p.sprung_mass_kg,
        com: Vector3::zeros(),
        inertia: diag(
            p.sprung_roll_inertia_kg_m2,
            p.sprung_pitch_inertia_kg_m2,
            p.sprung_yaw_inertia_kg_m2,
        ),
    });
    // A wheel carrier: a wheel-like inertia, m R^2 / 4 about x and z, m R^2 / 2 about y.
    let m_c = p.front_carrier_mass_kg();
    let carrier = diag(0.25 * m_c * r * r, 0.5 * m_c * r * r, 0.25 * m_c * r * r);
    for (name, y) in [("front_left", 0.5), ("front_right", -0.5)] {
        builder.add_body(Body {
            name: name.into(),
            parent: Some(body::SPRUNG),
            joint: slider,
            placement: place(a, y * p.front_track_m, z_front),
            mass: m_c,
            com: Vector3::zeros(),
            inertia: carrier,
        });
    }
    builder.add_body(Body {
        name: "rear_bounce".into(),
        parent: Some(body::SPRUNG),
        joint: slider,
        placement: place(-b, 0.0, z_joint),
        mass: 0.0,
        com: Vector3::zeros(),
        inertia: Matrix3::zeros(),
    });
    // Rear axle: Table 2.1 roll inertia; yaw as roll (a beam along y), pitch of the wheels.
    let m_r = p.rear_unsprung_mass_kg;
    builder.add_body(Body {
        name: "rear_axle".into(),
        parent: Some(body::REAR_BOUNCE),
        joint: Joint::Revolute { axis: Vector3::x() },
        placement: Isometry3::identity(),
        mass: m_r,
        com: Vector3::new(0.0, 0.0, axle_below_joint),
        inertia: diag(
            p.rear_axle_roll_inertia_kg_m2,
            0.5 * m_r * r * r,
            p.rear_axle_roll_inertia_kg_m2,
        ),
    });
    let model = builder.build()?;
    let (outer, inner) = (
        0.5 * (p.rear_track_m + p.dual_spacing_m),
        0.5 * (p.rear_track_m - p.dual_spacing_m),
    );
    let mount = |body: usize, y: f64, left: bool, front: bool| TireMount {
        body,
        point: if front {
            Vector3::new(0.0, y, -front_column)
        } else {
            Vector3::new(0.0, y, axle_below_joint)
        },
        column_m: if front { front_column } else { 0.0 },
        left,
        front,
    };
    let mounts = [
        mount(body::FRONT_LEFT, 0.0, true, true),
        mount(body::FRONT_RIGHT, 0.0, false, true),
        mount(body::REAR_AXLE, outer, true, false),
        mount(body::REAR_AXLE, inner, true, false),
        mount(body::REAR_AXLE, -inner, false, false),
        mount(body::REAR_AXLE, -outer, false, false),
    ];
    Ok((model, mounts))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tree_has_ten_dof_and_the_table_2_1_masses() {
        let p = TruckParams::nominal();
        let (m, mounts) = build_tree(&p).unwrap();
        assert_eq!((m.nq(), m.nv()), (NQ, NV));
        assert!((m.total_mass() - 85_540.0).abs() < 1e-9);
        // outer duals at 1.745 m (note 1.5)
        assert!((mounts[2].point.y - 1.745).abs() < 1e-12);
    }
}
