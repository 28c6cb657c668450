//! The steering struts in 3-D: lengths and rates from the world positions of their mounts,
//! axial forces applied along the strut axis at both mounts (section 6.2.1).
//!
//! Each strut runs from its front-unit mount `A` to its hitch mount `B`; with
//! `u = (B - A) / |B - A|` the length is `l = |B - A|` and the extension rate
//! `l' = (v_B - v_A) . u`. The strut-space AFS component (Eqs 6.6-6.8) takes the extensions
//! `d = l - l_0` and rates of both struts and returns their axial forces `F` (positive
//! extending), applied as `+F u` at `B` and `-F u` at `A`: the power they deliver is `F l'`.
//! For the default layout at zero rear-unit roll these lengths are exactly Eq 3.8's
//! (`tests/steering.rs`).

use multibody::Workspace;
use nalgebra::Vector3;

use crate::model::{body, Layout};

/// Geometry of both struts at one instant (left, right).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StrutGeometry {
    /// Strut lengths l (m).
    pub length: [f64; 2],
    /// Extension rates l' (m/s).
    pub rate: [f64; 2],
    /// Unit axes from the front-unit mount to the hitch mount (world).
    pub axis: [Vector3<f64>; 2],
    /// Front-unit mounts (world, m).
    pub front_point: [Vector3<f64>; 2],
    /// Hitch mounts (world, m).
    pub hitch_point: [Vector3<f64>; 2],
}

/// Strut geometry from the current kinematics in `ws`.
#[inline]
pub fn strut_geometry(ws: &Workspace, layout: &Layout) -> StrutGeometry {
    let mut g = StrutGeometry {
        length: [0.0; 2],
        rate: [0.0; 2],
        axis: [Vector3::zeros(); 2],
        front_point: [Vector3::zeros(); 2],
        hitch_point: [Vector3::zeros(); 2],
    };
    for side in 0..2 {
        let a = ws.point_position(body::FRONT, &layout.strut_front[side]);
        let b = ws.point_position(body::HITCH, &layout.strut_hitch[side]);
        let va = ws.point_velocity(body::FRONT, &layout.strut_front[side]);
        let vb = ws.point_velocity(body::HITCH, &layout.strut_hitch[side]);
        let d = b - a;
        let l = d.norm();
        let u = d / l;
        g.length[side] = l;
        g.rate[side] = (vb - va).dot(&u);
        g.axis[side] = u;
        g.front_point[side] = a;
        g.hitch_point[side] = b;
    }
    g
}

/// Apply the axial forces `force = [F_L, F_R]` (N, positive extending) at both mounts.
#[inline]
pub fn apply_strut_forces(ws: &mut Workspace, g: &StrutGeometry, force: [f64; 2]) {
    for (side, &magnitude) in force.iter().enumerate() {
        let f = g.axis[side] * magnitude;
        ws.apply_force_world(body::HITCH, &f, &g.hitch_point[side]);
        ws.apply_force_world(body::FRONT, &(-f), &g.front_point[side]);
    }
}
