//! The rear unit's rollover margin (L1843, point C): the distance that ends a D2 run.

use multibody::Workspace;

use super::Vehicle;
use crate::model::body;

impl Vehicle {
    /// [`Vehicle::rear_rollover_margin`] at the state `y` (its first `dim` entries), from the
    /// kinematics alone: the rollover event's function, evaluated at every accepted step,
    /// needs no tire, strut or steering force. NaN where the kinematics fail.
    pub(crate) fn rear_rollover_margin_at(&self, y: &[f64]) -> f64 {
        let o = &self.offsets;
        let mut ws = self.ws.borrow_mut();
        match multibody::update_kinematics(&self.model, &mut ws, &y[o.q..o.v], &y[o.v..o.afs]) {
            Ok(()) => self.rear_rollover_margin(&ws),
            Err(_) => f64::NAN,
        }
    }

    /// Signed horizontal distance (m) of the rear unit's cg (with payload) inside the nearer
    /// of the two vertical planes through the articulation joint and a rear wheel's contact
    /// centre: absolute rollover of the rear unit when it reaches zero (L1843, point C).
    /// With the bogie the planes run through the pivots, each side's load centre (the
    /// tandem's tipping edge lies between its wheels as the load shifts). Needs current
    /// kinematics in `ws`.
    pub(crate) fn rear_rollover_margin(&self, ws: &Workspace) -> f64 {
        let cg = ws.point_position(body::REAR, &self.layout.rear_cg);
        let joint = ws.point_position(body::FRONT, &self.layout.joint_on_front);
        let side = |wheel: usize, inward: f64| {
            let w = ws.body_position(wheel);
            let (dx, dy) = (joint.x - w.x, joint.y - w.y);
            let len = dx.hypot(dy);
            // inward normal of the line wheel -> joint: right of it on the left side
            let (nx, ny) = (inward * dy / len, -inward * dx / len);
            (cg.x - w.x) * nx + (cg.y - w.y) * ny
        };
        let [left, right] = if self.params.bogie.is_some() {
            [body::BOGIE_CARRIER_RL, body::BOGIE_CARRIER_RR]
        } else {
            [body::WHEEL_RL, body::WHEEL_RR]
        };
        side(left, 1.0).min(side(right, -1.0))
    }
}
