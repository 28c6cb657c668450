//! Energy and momentum of the tree at the state of the last kinematics update, for
//! conservation checks (Featherstone, "Rigid Body Dynamics Algorithms", 2008: kinetic
//! energy, spatial momentum and force transforms, ch. 2).

use crate::error::DynamicsError;
use crate::model::Model;
use crate::workspace::Workspace;
use nalgebra::{Vector3, Vector6};

/// Kinetic energy `sum 1/2 v_i . I_i v_i` (J), equal to `1/2 v^T H v`.
pub fn kinetic_energy(model: &Model, ws: &Workspace) -> Result<f64, DynamicsError> {
    ws.check(model)?;
    Ok(model
        .links
        .iter()
        .zip(&ws.vel)
        .map(|(l, v)| 0.5 * v.dot(&(l.inertia * v)))
        .sum())
}

/// Gravitational potential energy `-sum m_i g . p_ci` (J), zero at the world origin.
pub fn potential_energy(model: &Model, ws: &Workspace) -> Result<f64, DynamicsError> {
    ws.check(model)?;
    let g = model.gravity();
    Ok(model
        .bodies()
        .iter()
        .enumerate()
        .map(|(i, b)| -b.mass * g.dot(&ws.point_position(i, &b.com)))
        .sum())
}

/// Total spatial momentum `[angular momentum about the world origin; linear momentum]`
/// in world coordinates: `sum (i X 0)^T I_i v_i`.
pub fn spatial_momentum(model: &Model, ws: &Workspace) -> Result<Vector6<f64>, DynamicsError> {
    ws.check(model)?;
    Ok(model
        .links
        .iter()
        .zip(ws.vel.iter().zip(&ws.x_world))
        .map(|(l, (v, x))| x.transpose_apply_force(&(l.inertia * v)))
        .sum())
}

/// World position of the centre of mass of the whole tree, m.
pub fn centre_of_mass(model: &Model, ws: &Workspace) -> Result<Vector3<f64>, DynamicsError> {
    ws.check(model)?;
    let weighted: Vector3<f64> = model
        .bodies()
        .iter()
        .enumerate()
        .map(|(i, b)| b.mass * ws.point_position(i, &b.com))
        .sum();
    Ok(weighted / model.total_mass())
}
