//! Rigid-body equations of the two vehicle units in the yaw plane (Eqs 3.13/4.1, 3.14).
//!
//! Axes (SAE-like, mirrored consistently): x forward, y to the right, yaw positive for a
//! right-hand turn. The articulation angle is theta = psi_f - psi_r (Eq 3.14), positive in a
//! right-hand turn, and a positive steering torque T_s drives theta positive (docs/records.md).
//!
//! Unknown accelerations: (dv_f/dt, dphi_f/dt, dphi_r/dt) with the front forward speed u_f
//! held constant. The rear-unit velocities follow from the joint constraint (Eq 3.14) and
//! their derivatives are expanded analytically, so the three equations form a 3x3 linear
//! system that is solved by Cramer's rule (no allocation).
//!
//! **Energy-consistent form (default).** Newton-Euler for each unit with the joint
//! reaction eliminated gives exactly Eq 3.13 *without* the `m_f L_f2^2` and `m_r L_r2^2`
//! terms added to the yaw inertias: the moment of the cg's inertial force about the joint
//! (`m_f (dv_f/dt + u_f phi_f) L_f2`, `m_r (dv_r/dt + u_r phi_r) L_r2`) already contains
//! them, because v_f and v_r are cg velocities (see Eq 3.14 and 3.17). The printed form
//! ([`EquationForm::PaperEq313`]) counts them twice; it is kept as an option.

use serde::{Deserialize, Serialize};

/// Which yaw equations to integrate.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum EquationForm {
    /// Newton-Euler about the joint with cg velocities: conserves energy (default).
    #[default]
    EnergyConsistent,
    /// Eq 3.13/4.1 as printed: yaw inertias `I_f + m_f L_f2^2`, `I_r + m_r L_r2^2` in
    /// addition to the cg inertial-force moments (counts m L^2 twice).
    #[serde(rename = "paper_eq_3_13")]
    PaperEq313,
}

/// Inertial and geometric constants used by [`accelerations`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct UnitGeometry {
    /// m_f (kg).
    pub m_f: f64,
    /// m_r (kg).
    pub m_r: f64,
    /// Effective yaw inertia of the front unit in the chosen form (kg m^2).
    pub i_f: f64,
    /// Effective yaw inertia of the rear unit in the chosen form (kg m^2).
    pub i_r: f64,
    /// L_f1 (m).
    pub l_f1: f64,
    /// L_f2 (m).
    pub l_f2: f64,
    /// L_r1 (m).
    pub l_r1: f64,
    /// L_r2 (m).
    pub l_r2: f64,
}

impl UnitGeometry {
    /// Constants of `p` for the equation form `form`.
    pub fn new(p: &crate::VehicleParams, form: EquationForm) -> Self {
        let (di_f, di_r) = match form {
            EquationForm::EnergyConsistent => (0.0, 0.0),
            EquationForm::PaperEq313 => (
                p.m_f_kg * p.l_f2_m * p.l_f2_m,
                p.m_r_kg * p.l_r2_m * p.l_r2_m,
            ),
        };
        Self {
            m_f: p.m_f_kg,
            m_r: p.m_r_kg,
            i_f: p.i_f_kg_m2 + di_f,
            i_r: p.i_r_kg_m2 + di_r,
            l_f1: p.l_f1_m,
            l_f2: p.l_f2_m,
            l_r1: p.l_r1_m,
            l_r2: p.l_r2_m,
        }
    }
}

/// Velocity state of the two units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Motion {
    /// Articulation angle theta (rad).
    pub theta: f64,
    /// Front-unit forward speed u_f (m/s), constant.
    pub u_f: f64,
    /// Front-unit cg lateral velocity v_f (m/s).
    pub v_f: f64,
    /// Front-unit yaw rate phi_f (rad/s).
    pub r_f: f64,
    /// Rear-unit yaw rate phi_r (rad/s).
    pub r_r: f64,
}

/// Rear-unit cg velocities from the joint constraint, Eq 3.14: `(u_r, v_r)`.
#[inline]
pub fn rear_velocities(g: &UnitGeometry, m: &Motion) -> (f64, f64) {
    let (s, c) = m.theta.sin_cos();
    let w = m.v_f - g.l_f2 * m.r_f;
    (m.u_f * c - w * s, m.u_f * s + w * c - g.l_r2 * m.r_r)
}

/// External loads: lateral tire forces per axle (sum of the two tires, along each unit's
/// y axis), tire aligning moments per axle as in Eq 3.15 (`M_z = k_mz alpha`, entering
/// Eq 3.13 with a `+` sign), and the steering torque T_s.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Loads {
    /// Y_1 + Y_2 (N).
    pub y_front: f64,
    /// Y_3 + Y_4 (N).
    pub y_rear: f64,
    /// M_z1 + M_z2 (N m).
    pub mz_front: f64,
    /// M_z3 + M_z4 (N m).
    pub mz_rear: f64,
    /// T_s (N m), positive drives theta positive.
    pub steering_torque: f64,
}

/// Accelerations and the constraint force that holds u_f constant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Accelerations {
    /// dv_f/dt (m/s^2).
    pub dv_f: f64,
    /// dphi_f/dt (rad/s^2).
    pub dr_f: f64,
    /// dphi_r/dt (rad/s^2).
    pub dr_r: f64,
    /// Lateral acceleration of the front cg, dv_f/dt + u_f phi_f (m/s^2).
    pub a_y_front: f64,
    /// Lateral acceleration of the rear cg in the rear frame (m/s^2).
    pub a_y_rear: f64,
    /// Longitudinal force on the front unit (front x axis) needed to keep u_f constant
    /// (N); its power `F_x u_f` is the only work done on the system besides tires and
    /// steering torque.
    pub traction_force: f64,
}

/// Solve the three equations of motion (Eq 3.13 in the chosen form, with the constraint
/// Eq 3.14 differentiated) for the accelerations.
#[inline]
pub fn accelerations(g: &UnitGeometry, m: &Motion, f: &Loads) -> Accelerations {
    let sc = m.theta.sin_cos();
    let (s, c) = sc;
    let w = m.v_f - g.l_f2 * m.r_f;
    let rear = (m.u_f * c - w * s, m.u_f * s + w * c - g.l_r2 * m.r_r);
    accelerations_with(g, m, sc, rear, f)
}

/// [`accelerations`] with `sin_cos(theta)` and the rear velocities `(u_r, v_r)` of
/// [`rear_velocities`] already at hand (saves the trigonometry in the right-hand side).
#[inline]
pub fn accelerations_with(
    g: &UnitGeometry,
    m: &Motion,
    (s, c): (f64, f64),
    (u_r, v_r): (f64, f64),
    f: &Loads,
) -> Accelerations {
    let theta_dot = m.r_f - m.r_r;
    let (mf, mr, lf2, lr2) = (g.m_f, g.m_r, g.l_f2, g.l_r2);

    // Row 1: total lateral force in the front frame.
    let a11 = mf + mr;
    let a12 = -mr * lf2;
    let a13 = -mr * lr2 * c;
    let b1 = f.y_front + f.y_rear * c
        - mf * m.u_f * m.r_f
        - mr * (c * u_r * m.r_f + s * (v_r * m.r_f + lr2 * m.r_r * theta_dot));
    // Row 2: front-unit moments about the joint.
    let a21 = mf * lf2;
    let a22 = g.i_f;
    let a23 = 0.0;
    let b2 = f.y_front * (g.l_f1 + lf2) - f.mz_front + f.steering_torque - mf * lf2 * m.u_f * m.r_f;
    // Row 3: rear-unit moments about the joint.
    let a31 = -mr * lr2 * c;
    let a32 = mr * lr2 * lf2 * c;
    let a33 = g.i_r + mr * lr2 * lr2;
    let b3 = -f.y_rear * (g.l_r1 + lr2) - f.mz_rear - f.steering_torque + mr * lr2 * u_r * m.r_f;

    let det = a11 * (a22 * a33 - a23 * a32) - a12 * (a21 * a33 - a23 * a31)
        + a13 * (a21 * a32 - a22 * a31);
    let inv = 1.0 / det;
    let dv_f = (b1 * (a22 * a33 - a23 * a32) - a12 * (b2 * a33 - a23 * b3)
        + a13 * (b2 * a32 - a22 * b3))
        * inv;
    let dr_f = (a11 * (b2 * a33 - a23 * b3) - b1 * (a21 * a33 - a23 * a31)
        + a13 * (a21 * b3 - b2 * a31))
        * inv;
    let dr_r = (a11 * (a22 * b3 - b2 * a32) - a12 * (a21 * b3 - b2 * a31)
        + b1 * (a21 * a32 - a22 * a31))
        * inv;

    // Rear cg accelerations in the rear frame (differentiated Eq 3.14).
    let dw = dv_f - lf2 * dr_f;
    let du_r = -(v_r + lr2 * m.r_r) * theta_dot - s * dw;
    let dv_r = u_r * theta_dot + c * dw - lr2 * dr_r;
    let a_rx = du_r - v_r * m.r_r;
    let a_ry = dv_r + u_r * m.r_r;
    // Joint force on the rear unit (rear frame) is (m_r a_rx, m_r a_ry - Y_r); the front
    // unit feels the opposite. Front x balance gives the traction force.
    let p = mr * a_rx;
    let q = mr * a_ry - f.y_rear;
    let traction_force = -mf * m.v_f * m.r_f + p * c + q * s;
    Accelerations {
        dv_f,
        dr_f,
        dr_r,
        a_y_front: dv_f + m.u_f * m.r_f,
        a_y_rear: a_ry,
        traction_force,
    }
}

/// Kinetic energy of both units (J), with the rear velocities from Eq 3.14.
pub fn kinetic_energy(p: &crate::VehicleParams, m: &Motion) -> f64 {
    let g = UnitGeometry::new(p, EquationForm::EnergyConsistent);
    let (u_r, v_r) = rear_velocities(&g, m);
    0.5 * p.m_f_kg * (m.u_f * m.u_f + m.v_f * m.v_f)
        + 0.5 * p.i_f_kg_m2 * m.r_f * m.r_f
        + 0.5 * p.m_r_kg * (u_r * u_r + v_r * v_r)
        + 0.5 * p.i_r_kg_m2 * m.r_r * m.r_r
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::VehicleParams;

    fn motion() -> Motion {
        Motion {
            theta: 0.3,
            u_f: 5.0,
            v_f: 0.4,
            r_f: 0.2,
            r_r: -0.1,
        }
    }

    /// d(KE)/dt must equal the power of all external loads (energy-consistent form).
    #[test]
    fn power_balance_energy_consistent() {
        let p = VehicleParams::loaded();
        let g = UnitGeometry::new(&p, EquationForm::EnergyConsistent);
        let m = motion();
        let f = Loads {
            steering_torque: 2.0e5,
            ..Loads::default()
        };
        let a = accelerations(&g, &m, &f);
        let h = 1e-6;
        let m2 = Motion {
            theta: m.theta + h * (m.r_f - m.r_r),
            v_f: m.v_f + h * a.dv_f,
            r_f: m.r_f + h * a.dr_f,
            r_r: m.r_r + h * a.dr_r,
            ..m
        };
        let m0 = Motion {
            theta: m.theta - h * (m.r_f - m.r_r),
            v_f: m.v_f - h * a.dv_f,
            r_f: m.r_f - h * a.dr_f,
            r_r: m.r_r - h * a.dr_r,
            ..m
        };
        let dke = (kinetic_energy(&p, &m2) - kinetic_energy(&p, &m0)) / (2.0 * h);
        let power = f.steering_torque * (m.r_f - m.r_r) + a.traction_force * m.u_f;
        assert!(
            (dke - power).abs() < 1e-6 * power.abs().max(1.0),
            "dKE/dt {dke} vs power {power}"
        );
        // The printed form violates it.
        let gp = UnitGeometry::new(&p, EquationForm::PaperEq313);
        let ap = accelerations(&gp, &m, &f);
        assert!((ap.dr_f - a.dr_f).abs() > 1e-3 * a.dr_f.abs());
    }

    /// Straight running: no forces, no motion change; pure torque with u=0 gives opposite
    /// yaw accelerations whose angular momentum about the system cg is zero.
    #[test]
    fn equilibrium_and_symmetry() {
        let p = VehicleParams::unloaded();
        let g = UnitGeometry::new(&p, EquationForm::EnergyConsistent);
        let m = Motion {
            theta: 0.0,
            u_f: 10.0,
            v_f: 0.0,
            r_f: 0.0,
            r_r: 0.0,
        };
        let a = accelerations(&g, &m, &Loads::default());
        assert_eq!((a.dv_f, a.dr_f, a.dr_r), (0.0, 0.0, 0.0));
        let f = Loads {
            steering_torque: 1.0e4,
            ..Loads::default()
        };
        let a = accelerations(&g, &m, &f);
        assert!(a.dr_f > 0.0 && a.dr_r < 0.0, "{a:?}");
        // Mirror: negating the torque negates all accelerations.
        let fneg = Loads {
            steering_torque: -1.0e4,
            ..Loads::default()
        };
        let b = accelerations(&g, &m, &fneg);
        assert!((a.dv_f + b.dv_f).abs() < 1e-12 && (a.dr_f + b.dr_f).abs() < 1e-12);
        // Linear momentum: m_f a_f + m_r a_r = 0 laterally at theta = 0 (no external force).
        assert!((p.m_f_kg * a.a_y_front + p.m_r_kg * a.a_y_rear).abs() < 1e-6);
    }
}
