//! Parameters of the cab on mounts and the suspension seat, with their validation and the
//! documented generic values (`docs/layouts.md` gives every source and assumption).

use crate::error::ComponentError;

/// One elastomer cab mount: where it sits and its vertical stiffness and damping.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CabMount {
    /// Position ahead of the mount-plane centre O (m), in the frame's x.
    pub x_m: f64,
    /// Position left of O (m), in the frame's y.
    pub y_m: f64,
    /// Vertical stiffness (N/m).
    pub stiffness_n_per_m: f64,
    /// Vertical viscous damping (N s/m).
    pub damping_n_s_per_m: f64,
}

/// The cab: a rigid body whose centre of mass lies `cg_height_m` above the centre O of the
/// plane of its mounts, on four vertical elastomer mounts (horizontally stiff: the cab
/// rotates about O and moves vertically, it does not slide on the frame).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CabParams {
    /// Mass of the cab with its interior, without seat and operator (kg).
    pub mass_kg: f64,
    /// Roll moment of inertia about the cab's own centre of mass (kg m²).
    pub roll_inertia_kg_m2: f64,
    /// Pitch moment of inertia about the cab's own centre of mass (kg m²).
    pub pitch_inertia_kg_m2: f64,
    /// Height of the centre of mass above the mount plane (m).
    pub cg_height_m: f64,
    /// The four mounts.
    pub mounts: [CabMount; 4],
}

impl CabParams {
    /// The generic cab (assumptions, `docs/layouts.md`): 1 100 kg, a 1.8 m long, 1.6 m
    /// wide, 2.0 m high uniform box for the inertias (`m (b² + c²) / 12`: roll 601 kg m²,
    /// pitch 664 kg m²), centre of mass 0.9 m above the mounts, four mounts at
    /// x = ±0.8 m, y = ±0.65 m of 550 kN/m and 3.5 kN s/m each: a 7.1 Hz bounce (the seat
    /// on its soft suspension hardly adds to it), 5.3 mm static deflection under cab and
    /// seat, and a bounce damping ratio near 0.14 (an elastomer loss factor of about 0.3).
    pub fn generic() -> Self {
        let m = 1_100.0;
        let mount = |x_m, y_m| CabMount {
            x_m,
            y_m,
            stiffness_n_per_m: 550e3,
            damping_n_s_per_m: 3.5e3,
        };
        Self {
            mass_kg: m,
            roll_inertia_kg_m2: m * (1.6f64.powi(2) + 2.0f64.powi(2)) / 12.0,
            pitch_inertia_kg_m2: m * (1.8f64.powi(2) + 2.0f64.powi(2)) / 12.0,
            cg_height_m: 0.9,
            mounts: [
                mount(0.8, 0.65),
                mount(0.8, -0.65),
                mount(-0.8, 0.65),
                mount(-0.8, -0.65),
            ],
        }
    }

    /// Every field finite and in its plausible range; the field is named in the error.
    pub fn validate(&self) -> Result<(), ComponentError> {
        in_range(
            "cab.mass_kg",
            self.mass_kg,
            50.0,
            20_000.0,
            "must be finite and within [50, 20000] kg",
        )?;
        in_range(
            "cab.roll_inertia_kg_m2",
            self.roll_inertia_kg_m2,
            1.0,
            1e5,
            "must be finite and within [1, 1e5] kg m²",
        )?;
        in_range(
            "cab.pitch_inertia_kg_m2",
            self.pitch_inertia_kg_m2,
            1.0,
            1e5,
            "must be finite and within [1, 1e5] kg m²",
        )?;
        in_range(
            "cab.cg_height_m",
            self.cg_height_m,
            0.0,
            5.0,
            "must be finite and within [0, 5] m",
        )?;
        for (m, names) in self.mounts.iter().zip(MOUNT_FIELDS) {
            in_range(
                names[0],
                m.x_m,
                -5.0,
                5.0,
                "must be finite and within [-5, 5] m",
            )?;
            in_range(
                names[1],
                m.y_m,
                -5.0,
                5.0,
                "must be finite and within [-5, 5] m",
            )?;
            in_range(
                names[2],
                m.stiffness_n_per_m,
                1e3,
                1e9,
                "must be finite and within [1000, 1e9] N/m",
            )?;
            in_range(
                names[3],
                m.damping_n_s_per_m,
                0.0,
                1e7,
                "must be finite and within [0, 1e7] N s/m",
            )?;
        }
        Ok(())
    }
}

const MOUNT_FIELDS: [[&str; 4]; 4] = [
    [
        "cab.mounts[0].x_m",
        "cab.mounts[0].y_m",
        "cab.mounts[0].stiffness_n_per_m",
        "cab.mounts[0].damping_n_s_per_m",
    ],
    [
        "cab.mounts[1].x_m",
        "cab.mounts[1].y_m",
        "cab.mounts[1].stiffness_n_per_m",
        "cab.mounts[1].damping_n_s_per_m",
    ],
    [
        "cab.mounts[2].x_m",
        "cab.mounts[2].y_m",
        "cab.mounts[2].stiffness_n_per_m",
        "cab.mounts[2].damping_n_s_per_m",
    ],
    [
        "cab.mounts[3].x_m",
        "cab.mounts[3].y_m",
        "cab.mounts[3].stiffness_n_per_m",
        "cab.mounts[3].damping_n_s_per_m",
    ],
];

/// An optional seat cushion between the seat's suspended frame and the operator: the
/// operator's seated mass on a spring and damper.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Cushion {
    /// The operator's mass carried by the cushion (kg).
    pub occupant_mass_kg: f64,
    /// Cushion stiffness (N/m).
    pub stiffness_n_per_m: f64,
    /// Cushion damping (N s/m).
    pub damping_n_s_per_m: f64,
}

impl Cushion {
    /// A cushion of natural frequency `f_hz` and damping ratio `zeta` under `occupant_mass_kg`:
    /// `k = m (2 pi f)²`, `c = 2 zeta sqrt(k m)`.
    pub fn tuned(occupant_mass_kg: f64, f_hz: f64, zeta: f64) -> Self {
        let (k, c) = spring_damper(occupant_mass_kg, f_hz, zeta);
        Self {
            occupant_mass_kg,
            stiffness_n_per_m: k,
            damping_n_s_per_m: c,
        }
    }
}

/// The suspension seat on the cab floor: a suspended mass on a spring and a damper with
/// elastic end stops, the spring preloaded by the weight adjustment so that the seat rides
/// at mid-travel under its static load (ISO 10326-1 tests with the suspension adjusted to
/// the occupant's weight), and an optional cushion.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SeatParams {
    /// Mass on the suspension (kg): the seat's suspended part plus, without a cushion, the
    /// operator's seated mass; with a cushion, the seat's suspended part only.
    pub suspended_mass_kg: f64,
    /// Suspension stiffness about mid-travel (N/m).
    pub stiffness_n_per_m: f64,
    /// Suspension damping (N s/m).
    pub damping_n_s_per_m: f64,
    /// Total suspension travel between the end stops (m), centred on mid-travel.
    pub travel_m: f64,
    /// Stiffness of each elastic end stop beyond the travel (N/m).
    pub stop_stiffness_n_per_m: f64,
    /// Seat position ahead of the mount-plane centre O (m).
    pub x_m: f64,
    /// Seat position left of O (m).
    pub y_m: f64,
    /// Height of the suspended mass above the mount plane (m).
    pub height_m: f64,
    /// Optional cushion carrying the operator.
    pub cushion: Option<Cushion>,
}

impl SeatParams {
    /// The generic suspension seat (assumptions, `docs/layouts.md`): 80 kg on the
    /// suspension (about three quarters of a 75 kg operator and the seat's suspended
    /// part), tuned to 1.5 Hz with a damping ratio of 0.3, 100 mm travel (±50 mm) between
    /// elastic stops of 150 kN/m, no cushion, on the cab's centreline 0.2 m behind O and
    /// 0.5 m above the mount plane.
    pub fn generic() -> Self {
        let m = 80.0;
        let (k, c) = spring_damper(m, 1.5, 0.3);
        Self {
            suspended_mass_kg: m,
            stiffness_n_per_m: k,
            damping_n_s_per_m: c,
            travel_m: 0.1,
            stop_stiffness_n_per_m: 150e3,
            x_m: -0.2,
            y_m: 0.0,
            height_m: 0.5,
            cushion: None,
        }
    }

    /// The mass above the suspension: suspended part plus the cushion's occupant (kg).
    pub fn total_mass_kg(&self) -> f64 {
        self.suspended_mass_kg + self.cushion.map_or(0.0, |c| c.occupant_mass_kg)
    }

    /// Every field finite and in its plausible range; the field is named in the error.
    pub fn validate(&self) -> Result<(), ComponentError> {
        in_range(
            "seat.suspended_mass_kg",
            self.suspended_mass_kg,
            10.0,
            500.0,
            "must be finite and within [10, 500] kg",
        )?;
        in_range(
            "seat.stiffness_n_per_m",
            self.stiffness_n_per_m,
            100.0,
            1e7,
            "must be finite and within [100, 1e7] N/m",
        )?;
        in_range(
            "seat.damping_n_s_per_m",
            self.damping_n_s_per_m,
            0.0,
            1e6,
            "must be finite and within [0, 1e6] N s/m",
        )?;
        in_range(
            "seat.travel_m",
            self.travel_m,
            0.01,
            0.5,
            "must be finite and within [0.01, 0.5] m",
        )?;
        in_range(
            "seat.stop_stiffness_n_per_m",
            self.stop_stiffness_n_per_m,
            self.stiffness_n_per_m,
            1e9,
            "must be finite, at least the seat's stiffness_n_per_m and at most 1e9 N/m",
        )?;
        in_range(
            "seat.x_m",
            self.x_m,
            -5.0,
            5.0,
            "must be finite and within [-5, 5] m",
        )?;
        in_range(
            "seat.y_m",
            self.y_m,
            -5.0,
            5.0,
            "must be finite and within [-5, 5] m",
        )?;
        in_range(
            "seat.height_m",
            self.height_m,
            0.0,
            5.0,
            "must be finite and within [0, 5] m",
        )?;
        if let Some(c) = &self.cushion {
            in_range(
                "seat.cushion.occupant_mass_kg",
                c.occupant_mass_kg,
                10.0,
                300.0,
                "must be finite and within [10, 300] kg",
            )?;
            in_range(
                "seat.cushion.stiffness_n_per_m",
                c.stiffness_n_per_m,
                1e3,
                1e7,
                "must be finite and within [1000, 1e7] N/m",
            )?;
            in_range(
                "seat.cushion.damping_n_s_per_m",
                c.damping_n_s_per_m,
                0.0,
                1e6,
                "must be finite and within [0, 1e6] N s/m",
            )?;
        }
        Ok(())
    }
}

/// Stiffness and damping of mass `m` tuned to `f_hz` with damping ratio `zeta`.
fn spring_damper(m: f64, f_hz: f64, zeta: f64) -> (f64, f64) {
    let k = m * (2.0 * std::f64::consts::PI * f_hz).powi(2);
    (k, 2.0 * zeta * (k * m).sqrt())
}

/// `value` finite and within `[lo, hi]`, else an error naming `field` with `reason` (the
/// range in words).
pub(crate) fn in_range(
    field: &'static str,
    value: f64,
    lo: f64,
    hi: f64,
    reason: &'static str,
) -> Result<(), ComponentError> {
    if value.is_finite() && (lo..=hi).contains(&value) {
        Ok(())
    } else {
        Err(ComponentError::InvalidParameter {
            field,
            value,
            reason,
        })
    }
}
