//! One tire of the 3-D vehicle at one instant (section 6.2.2): contact on its cached
//! tandem-cam track, normal force, slips, Fiala forces and moments, in world axes.
//!
//! Terrain: every left tire runs on the left track of the two-track terrain, every right
//! tire on the right track, read at the path coordinate `s` of the wheel centre along the
//! front unit's heading `h` (the road is laid along the path the vehicle drives, as in
//! the Chapter 2 truck). The contact comes from a [`tire_fiala::EffectiveTrack`] built once
//! per run at the tire's static deflection: penetration `delta` and slope `theta` of the
//! effective line P1P2 (Eqs 6.1-6.3).
//!
//! Per tire, with the carrier's heading `psi` (its x axis projected on the ground),
//! `e_x = (cos psi, sin psi, 0)`, `e_y = (-sin psi, cos psi, 0)`, the axle direction `a` (the
//! carrier's y axis), the wheel-centre velocity `v` and the wheel's spin `omega = w . a`:
//! 1. contact normal `n = -sin(theta) h + cos(theta) z`; deflection rate
//!    `delta' = (v . h) sin theta - v_z cos theta`; normal force
//!    `F_n = F_el(delta) + c_t delta' >= 0` with the nonlinear load curve (Fig 6.4 replaced by
//!    the labelled assumption of `tire_fiala::LoadDeflectionTable::default_29_5r29`);
//! 2. steady slips with the regularised speed `u = sqrt(v_x^2 + u_0^2)`, `v_x = v . e_x`:
//!    `kappa_s = (omega R_l - v_x) / u` (loaded radius `R_l = R - delta`),
//!    `alpha_s = -atan(v_y / u)`, `v_y = v . e_y` (Eq 3.17);
//! 3. Fiala forces from `F_n` and the lagged slips (the vehicle integrates the lags, Eq 3.16,
//!    with the longitudinal and lateral relaxation lengths of Table 6.2);
//! 4. force on the wheel `F = F_x t + F_y l + F_n n` with `t` the unit projection of `e_x` on
//!    the contact plane and `l = n x t`, applied at the contact point `c - (R - delta) n`; the
//!    aligning moment about `n`; the rolling-resistance moment about the axle, signed with
//!    the spin (`tanh(omega R / 0.1 m/s)`, smooth through standstill).

use nalgebra::{Matrix3, Vector3};
use tire_fiala::{regularised_speed, Fiala, HandlingModel, TrackContact, VerticalContact};

/// Speed (m/s) over which the rolling-resistance moment changes sign at standstill.
pub const ROLLING_SIGN_SPEED_M_S: f64 = 0.1;

/// What the vehicle hands a tire (world axes).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TireInput {
    /// Wheel centre (m).
    pub centre: Vector3<f64>,
    /// Wheel-centre velocity (m/s).
    pub velocity: Vector3<f64>,
    /// Rotation of the carrier (world = R body): x the wheel heading, y the axle.
    pub carrier_rotation: Matrix3<f64>,
    /// Angular velocity of the wheel (rad/s).
    pub wheel_angular_velocity: Vector3<f64>,
    /// Horizontal unit direction of the path coordinate (the front unit's heading).
    pub path_direction: Vector3<f64>,
    /// Contact on the tire's effective track.
    pub contact: TrackContact,
    /// Lagged slips `[kappa, alpha]` (the vehicle's states).
    pub lag: [f64; 2],
}

/// Contact quantities of one tire, for records and measures.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct TireContact {
    /// Normal force F_n (N).
    pub normal_force: f64,
    /// Penetration delta (m), positive in contact.
    pub deflection: f64,
    /// Slope theta of the effective line (rad).
    pub slope: f64,
    /// Forward velocity of the wheel centre v_x (m/s).
    pub forward_velocity: f64,
    /// Lateral velocity of the wheel centre v_y (m/s).
    pub lateral_velocity: f64,
    /// Steady-state slips `[kappa_s, alpha_s]`.
    pub slip_steady: [f64; 2],
    /// Longitudinal force F_x (N).
    pub fx: f64,
    /// Lateral force F_y (N).
    pub fy: f64,
    /// Wheel spin omega (rad/s), positive rolling forward.
    pub spin: f64,
}

/// Forces of one tire in world axes and its contact quantities.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TireOutput {
    /// Force on the wheel (N).
    pub force: Vector3<f64>,
    /// Where it acts (m).
    pub point: Vector3<f64>,
    /// Moment on the wheel (N m): aligning plus rolling resistance.
    pub moment: Vector3<f64>,
    /// Contact quantities.
    pub contact: TireContact,
}

/// The tire of the module docs. Allocation free.
#[inline]
pub fn tire_forces(
    input: &TireInput,
    radius: f64,
    vertical: &VerticalContact,
    fiala: &Fiala,
) -> TireOutput {
    let rot = &input.carrier_rotation;
    let psi = rot[(1, 0)].atan2(rot[(0, 0)]);
    let (sin_p, cos_p) = psi.sin_cos();
    let e_x = Vector3::new(cos_p, sin_p, 0.0);
    let e_y = Vector3::new(-sin_p, cos_p, 0.0);
    let axle = rot.column(1).into_owned();
    let h = &input.path_direction;
    let (delta, theta) = (input.contact.deflection, input.contact.slope);
    let (sin_t, cos_t) = theta.sin_cos();
    let n = Vector3::new(-sin_t * h.x, -sin_t * h.y, cos_t);
    let v = &input.velocity;
    let rate = v.dot(h) * sin_t - v.z * cos_t;
    let fz = vertical.normal_force(delta, rate);
    let (v_x, v_y) = (v.dot(&e_x), v.dot(&e_y));
    let u = regularised_speed(v_x);
    let spin = input.wheel_angular_velocity.dot(&axle);
    let loaded_radius = radius - delta.max(0.0);
    let slip_steady = [(spin * loaded_radius - v_x) / u, -(v_y / u).atan()];
    let f = fiala.forces(fz, input.lag[0], input.lag[1]);
    let t = (e_x - n * e_x.dot(&n)).normalize();
    let l = n.cross(&t);
    let force = t * f.fx + l * f.fy + n * fz;
    let point = input.centre - n * loaded_radius;
    let rolling_sign = (spin * radius / ROLLING_SIGN_SPEED_M_S).tanh();
    let moment = n * f.yaw_moment_z_up() + axle * (f.my * rolling_sign);
    TireOutput {
        force,
        point,
        moment,
        contact: TireContact {
            normal_force: fz,
            deflection: delta,
            slope: theta,
            forward_velocity: v_x,
            lateral_velocity: v_y,
            slip_steady,
            fx: f.fx,
            fy: f.fy,
            spin,
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use tire_fiala::{LoadDeflectionTable, TireParams};

    fn input(v: Vector3<f64>, spin: f64, lag: [f64; 2]) -> TireInput {
        TireInput {
            centre: Vector3::new(0.0, 0.0, 0.9),
            velocity: v,
            carrier_rotation: Matrix3::identity(),
            wheel_angular_velocity: Vector3::new(0.0, spin, 0.0),
            path_direction: Vector3::x(),
            contact: TrackContact {
                deflection: 0.1,
                slope: 0.0,
            },
            lag,
        }
    }

    fn parts() -> (VerticalContact, Fiala) {
        let p = TireParams::nominal();
        (
            VerticalContact::new(LoadDeflectionTable::new(&p.load_deflection).unwrap(), 35e3)
                .unwrap(),
            Fiala::new(&p).unwrap(),
        )
    }

    #[test]
    fn free_rolling_gives_no_slip_and_the_static_load() {
        let (vert, fiala) = parts();
        let out = tire_forces(
            &input(Vector3::new(10.0, 0.0, 0.0), 10.0 / 0.9, [0.0; 2]),
            1.0,
            &vert,
            &fiala,
        );
        assert!(out.contact.slip_steady[0].abs() < 1e-12);
        assert!((out.force.z - vert.load_deflection().load(0.1)).abs() < 1e-6);
        assert!(out.force.x.abs() < 1e-9 && out.force.y.abs() < 1e-9);
        // contact point one loaded radius below the centre
        assert!((out.point.z - 0.0).abs() < 1e-12);
        // rolling resistance opposes the forward spin
        assert!(out.moment.y < 0.0);
    }

    #[test]
    fn mirrored_motion_gives_mirrored_forces() {
        let (vert, fiala) = parts();
        let a = tire_forces(
            &input(Vector3::new(10.0, 0.3, -0.05), 11.0, [0.02, 0.03]),
            1.0,
            &vert,
            &fiala,
        );
        let b = tire_forces(
            &input(Vector3::new(10.0, -0.3, -0.05), 11.0, [0.02, -0.03]),
            1.0,
            &vert,
            &fiala,
        );
        assert!((a.force.x - b.force.x).abs() < 1e-9);
        assert!((a.force.y + b.force.y).abs() < 1e-9);
        assert!((a.force.z - b.force.z).abs() < 1e-9);
        assert!((a.moment.z + b.moment.z).abs() < 1e-9);
        assert!((a.contact.slip_steady[1] + b.contact.slip_steady[1]).abs() < 1e-15);
        // a wheel sliding left gets a force to the right
        assert!(a.contact.slip_steady[1] < 0.0);
    }

    #[test]
    fn lift_off_transmits_nothing() {
        let (vert, fiala) = parts();
        let mut i = input(Vector3::new(10.0, 0.3, 0.0), 12.0, [0.1, 0.1]);
        i.contact.deflection = -0.01;
        let out = tire_forces(&i, 1.0, &vert, &fiala);
        assert_eq!(out.force, Vector3::zeros());
        assert_eq!(out.moment, Vector3::zeros());
    }
}
