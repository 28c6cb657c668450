//! One tire of the 3-D vehicle at one instant (section 6.2.2): contact on its cached
//! tandem-cam track, normal force, slips, Fiala forces and moments, in world axes.
//!
//! Terrain: every left tire runs on the left track of the two-track terrain, every right
//! tire on the right track, read at the path coordinate `s` of the wheel centre along the
//! front unit's heading `h` (the road is laid along the path the vehicle drives, as in
//! the Chapter 2 truck). The contact comes from a [`tire_fiala::EffectiveTrack`] built once
//! per run at the tire's static deflection: penetration `delta` and slope `theta` of the
//! effective line P1P2 (Eqs 6.1-6.3). Section 6.2.2 makes the cams' spacing (the contact
//! length P1P2) depend on the deflection, and does not say whether the static or the
//! instantaneous one: [`CamSpacing`] offers both, the static one by default (then a
//! [`tire_fiala::InstantaneousTrack`] per tire).
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
use tire_fiala::{
    regularised_speed, EffectiveTrack, Envelope, EnvelopeMethod, Fiala, HandlingModel,
    InstantaneousTrack, Track, TrackContact, VerticalContact,
};
use vehicle_components::Terrain;

use crate::error::{positive, rejected, VehicleError};
use crate::params::{Load, VehicleParams};
use crate::statics::Statics;
use crate::vehicle::VehicleOptions;

/// Where the tandem cams of a tire stand (section 6.2.2, Eqs 6.1-6.3): at `x_c -+ a`, `a`
/// the half contact length of the deflected tire, `sqrt(2 R delta - delta^2)`. The paper
/// ties the contact length P1P2 to the deflection without saying which: a calibration
/// switch of the discovery workflow (docs/discovery.md, "Calibration switches").
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum CamSpacing {
    /// At the tire's static deflection, cached along each track
    /// ([`tire_fiala::EffectiveTrack`]; the penetration linearised about it). The default.
    #[default]
    Static,
    /// At the tire's instantaneous deflection, found on line from the cams' base cached
    /// along each track ([`tire_fiala::InstantaneousTrack`], on a grid
    /// [`CAM_BASE_GRID_DIVISOR`] times finer than the static cache's). Tandem cams only.
    Instantaneous,
}

impl std::str::FromStr for CamSpacing {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "static" => Ok(Self::Static),
            "instantaneous" => Ok(Self::Instantaneous),
            _ => Err(format!(
                "unknown cam spacing `{s}` (use `static` or `instantaneous`)"
            )),
        }
    }
}

/// Grid of the cams' base with [`CamSpacing::Instantaneous`], in steps per grid step of
/// the static cache (`VehicleOptions::track_grid_m`): 0.0125 m at the default. The base has
/// cusps in the profile's valleys, where the spacing's fixed point is unstable and the
/// cams' three steps amplify an interpolation error (`tire_fiala::InstantaneousTrack`).
pub const CAM_BASE_GRID_DIVISOR: f64 = 4.0;

/// One tire's contact cache.
#[derive(Debug, Clone, PartialEq)]
enum TireTrack {
    Static(EffectiveTrack),
    Instantaneous(InstantaneousTrack),
}

/// The four tires' effective tracks (in [`crate::model::TIRE_NAMES`] order), each at its
/// static deflection or following the instantaneous one ([`CamSpacing`]), covering the
/// path of a run: the enveloping cache, built once per terrain, load case and tire and
/// shared by every vehicle built on it ([`crate::Vehicle::on_tracks`]).
#[derive(Debug, Clone, PartialEq)]
pub struct TireTracks {
    tracks: [TireTrack; 4],
    reference: [f64; 2],
    range: (f64, f64),
    settings: (EnvelopeMethod, f64, f64, f64, CamSpacing),
}

impl TireTracks {
    /// The tracks of `params`' tire under `load` on `terrain` for a run with `options`, the
    /// left tires on `y = +half_width`, the right ones on `y = -half_width`.
    pub fn build<T: Terrain>(
        params: &VehicleParams,
        load: Load,
        options: &VehicleOptions,
        terrain: &T,
        half_width: f64,
    ) -> Result<Self, VehicleError> {
        params.validate()?;
        positive("half_width", half_width)?;
        positive("path_length_m", options.path_length_m)?;
        positive("track_grid_m", options.track_grid_m)?;
        positive("envelope_sample_m", options.envelope_sample_m)?;
        let statics = Statics::of(params, load)?;
        let radius = params.tire.unloaded_radius_m;
        let envelope = Envelope::new(options.envelope, radius, options.envelope_sample_m)?;
        let range = Self::range_of(params, options);
        let reference = [
            statics.front_tire_deflection_m,
            statics.rear_tire_deflection_m,
        ];
        if options.cam_spacing == CamSpacing::Instantaneous
            && options.envelope != EnvelopeMethod::TandemCams
        {
            return Err(rejected(
                "cam_spacing",
                f64::NAN,
                "instantaneous needs the tandem cams (envelope = TandemCams)",
            ));
        }
        let track = |left: bool, front: bool| -> Result<TireTrack, VehicleError> {
            let y = if left { half_width } else { -half_width };
            let profile = Track { terrain, y };
            let d = reference[usize::from(!front)];
            Ok(match options.cam_spacing {
                CamSpacing::Static => TireTrack::Static(EffectiveTrack::build(
                    &profile,
                    range,
                    options.track_grid_m,
                    &envelope,
                    d,
                )?),
                CamSpacing::Instantaneous => TireTrack::Instantaneous(InstantaneousTrack::build(
                    &profile,
                    range,
                    options.track_grid_m / CAM_BASE_GRID_DIVISOR,
                    &envelope,
                )?),
            })
        };
        Ok(Self {
            tracks: [
                track(true, true)?,
                track(false, true)?,
                track(true, false)?,
                track(false, false)?,
            ],
            reference,
            range,
            settings: (
                options.envelope,
                options.envelope_sample_m,
                options.track_grid_m,
                radius,
                options.cam_spacing,
            ),
        })
    }

    /// Path range a run with `options` needs: the path plus a vehicle length each side.
    fn range_of(params: &VehicleParams, options: &VehicleOptions) -> (f64, f64) {
        let margin = params.wheelbase_m()
            + params.front_unit.cg_to_joint_m
            + 2.0 * params.tire.unloaded_radius_m;
        (
            options.start_s_m - margin,
            options.start_s_m + options.path_length_m + margin,
        )
    }

    /// Whether these tracks serve a vehicle of `params` with `statics` and `options`: the
    /// same reference deflections, enveloping settings and tire radius, and a range that
    /// covers the run.
    pub fn check(
        &self,
        params: &VehicleParams,
        statics: &Statics,
        options: &VehicleOptions,
    ) -> Result<(), VehicleError> {
        let same = |a: f64, b: f64| (a - b).abs() <= 1e-12 * (1.0 + a.abs());
        let settings = (
            options.envelope,
            options.envelope_sample_m,
            options.track_grid_m,
            params.tire.unloaded_radius_m,
            options.cam_spacing,
        );
        if !(same(self.reference[0], statics.front_tire_deflection_m)
            && same(self.reference[1], statics.rear_tire_deflection_m))
        {
            return Err(rejected(
                "tracks",
                statics.front_tire_deflection_m,
                "built for other static tire deflections (another tire or load case)",
            ));
        }
        if self.settings != settings {
            return Err(rejected(
                "tracks",
                options.track_grid_m,
                "built with other enveloping settings, tire radius or cam spacing",
            ));
        }
        let need = Self::range_of(params, options);
        if need.0 < self.range.0 || need.1 > self.range.1 {
            return Err(rejected(
                "tracks",
                options.path_length_m,
                "do not cover the run's path",
            ));
        }
        Ok(())
    }

    /// Contact of tire `i` with centre height `z_c` at path coordinate `s`.
    #[inline]
    pub fn contact(&self, i: usize, s: f64, z_c: f64) -> TrackContact {
        match &self.tracks[i] {
            TireTrack::Static(t) => t.contact(s, z_c),
            TireTrack::Instantaneous(t) => t.contact(s, z_c),
        }
    }

    /// The cam spacing these tracks were built with.
    pub fn cam_spacing(&self) -> CamSpacing {
        self.settings.4
    }
}

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
    let delta = input.contact.deflection;
    let (sin_t, cos_t) = (input.contact.sin_slope, input.contact.cos_slope);
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
            slope: input.contact.slope,
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
                sin_slope: 0.0,
                cos_slope: 1.0,
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
    fn the_cam_spacing_is_built_checked_and_exact_on_a_plane() {
        use vehicle_components::FlatTerrain;
        let p = VehicleParams::nominal();
        let flat = FlatTerrain::new(0.2, 0.8).unwrap();
        let options = |cam_spacing| VehicleOptions {
            path_length_m: 20.0,
            cam_spacing,
            ..VehicleOptions::default()
        };
        let fixed = options(CamSpacing::Static);
        let inst = options(CamSpacing::Instantaneous);
        let a = TireTracks::build(&p, Load::Loaded, &fixed, &flat, 1.3).unwrap();
        let b = TireTracks::build(&p, Load::Loaded, &inst, &flat, 1.3).unwrap();
        assert_eq!(
            (a.cam_spacing(), b.cam_spacing()),
            (fixed.cam_spacing, inst.cam_spacing)
        );
        // on a plane both readings give the exact penetration, lift-off included
        for i in 0..4 {
            for z in [1.25, 1.15, 1.12, 1.05, 0.98] {
                let (ca, cb) = (a.contact(i, 17.3, z), b.contact(i, 17.3, z));
                assert!((ca.deflection - (1.2 - z)).abs() < 1e-9, "{ca:?}");
                assert!((cb.deflection - ca.deflection).abs() < 1e-9, "{cb:?}");
                assert!(ca.slope == 0.0 && cb.slope == 0.0);
            }
        }
        // a vehicle refuses the tracks of the other spacing
        let st = Statics::of(&p, Load::Loaded).unwrap();
        assert!(b.check(&p, &st, &inst).is_ok());
        let e = a.check(&p, &st, &inst).unwrap_err().to_string();
        assert!(e.contains("cam spacing"), "{e}");
        // the circle-line enveloping has no cams to space
        let circle = VehicleOptions {
            envelope: EnvelopeMethod::CircleLine,
            ..inst
        };
        let e = TireTracks::build(&p, Load::Loaded, &circle, &flat, 1.3)
            .unwrap_err()
            .to_string();
        assert!(e.contains("cam_spacing"), "{e}");
        assert_eq!("instantaneous".parse(), Ok(CamSpacing::Instantaneous));
        assert_eq!("static".parse(), Ok(CamSpacing::Static));
        assert!("dynamic".parse::<CamSpacing>().is_err());
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
