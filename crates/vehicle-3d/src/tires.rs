//! The 3-D vehicle's tire tracks (section 6.2.2): the enveloping caches its tires read,
//! evaluated per tire by `tire_fiala::TireAssembly` with the Fiala law (the same assembly as
//! the Chapter 2 truck's, docs/tire-fiala.md).
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
//! Per tire the vehicle hands the assembly the wheel centre and velocity, the carrier's
//! heading `psi` (its x axis projected on the ground, from `atan2`), the axle direction `a`
//! (the carrier's y axis) and the wheel's spin `omega = w . a`; the assembly returns the
//! normal force `F_n = F_el(delta) + c_t delta' >= 0` with the nonlinear load curve (Fig 6.4
//! replaced by the labelled assumption of `tire_fiala::LoadDeflectionTable::default_29_5r29`),
//! the Fiala forces from the lagged slips (Eqs 3.16-3.17, the relaxation lengths of
//! Table 6.2) along the contact plane, the aligning and rolling-resistance moments, and the
//! lags' rates.

use std::sync::Arc;

use tire_fiala::{
    EffectiveTrack, Envelope, EnvelopeMethod, InstantaneousTrack, TireTrack, Track, TrackContact,
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

/// The four tires' effective tracks (in [`crate::model::TIRE_NAMES`] order), each at its
/// static deflection or following the instantaneous one ([`CamSpacing`]), covering the
/// path of a run: the enveloping cache, built once per terrain, load case and tire and
/// shared by every vehicle built on it ([`crate::Vehicle::on_tracks`]).
#[derive(Debug, Clone, PartialEq)]
pub struct TireTracks {
    tracks: Arc<[TireTrack]>,
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
        Self::assemble(
            params,
            load,
            options,
            half_width,
            |y, d, range, envelope| {
                let profile = Track { terrain, y };
                built_at_once(options, &profile, d, range, envelope)
            },
        )
    }

    /// [`TireTracks::build`] for a run that may stop early (a roll run ends at rollover):
    /// with the static cam spacing each track is built in order, a chunk at a time, as the
    /// run first reads it ([`tire_fiala::EffectiveTrack::on_demand`]), the same values to
    /// the bit. The tracks hold `terrain` until they are built to the end. With the
    /// instantaneous spacing they are built at once, as [`TireTracks::build`] builds them.
    pub fn on_demand<T: Terrain + Send + Sync + 'static>(
        params: &VehicleParams,
        load: Load,
        options: &VehicleOptions,
        terrain: Arc<T>,
        half_width: f64,
    ) -> Result<Self, VehicleError> {
        Self::assemble(
            params,
            load,
            options,
            half_width,
            |y, d, range, envelope| {
                let profile = Track {
                    terrain: Arc::clone(&terrain),
                    y,
                };
                match options.cam_spacing {
                    CamSpacing::Static => Ok(TireTrack::Static(EffectiveTrack::on_demand(
                        profile,
                        range,
                        options.track_grid_m,
                        envelope,
                        d,
                    )?)),
                    CamSpacing::Instantaneous => {
                        built_at_once(options, &profile, d, range, envelope)
                    }
                }
            },
        )
    }

    /// The four tracks, each from `track(y, reference deflection, path range, envelope)`,
    /// after the settings are checked.
    fn assemble(
        params: &VehicleParams,
        load: Load,
        options: &VehicleOptions,
        half_width: f64,
        track: impl Fn(f64, f64, (f64, f64), &Envelope) -> Result<TireTrack, VehicleError>,
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
        let tire = |left: bool, front: bool| {
            let y = if left { half_width } else { -half_width };
            track(y, reference[usize::from(!front)], range, &envelope)
        };
        Ok(Self {
            tracks: Arc::new([
                tire(true, true)?,
                tire(false, true)?,
                tire(true, false)?,
                tire(false, false)?,
            ]),
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

    /// Contact on track `i` (front left, front right, rear left, rear right) with centre
    /// height `z_c` at path coordinate `s`.
    #[inline]
    pub fn contact(&self, i: usize, s: f64, z_c: f64) -> TrackContact {
        self.tracks[i].contact(s, z_c)
    }

    /// The four tracks, to share with a vehicle's `tire_fiala::TireAssembly`.
    pub fn shared(&self) -> Arc<[TireTrack]> {
        Arc::clone(&self.tracks)
    }

    /// The cam spacing these tracks were built with.
    pub fn cam_spacing(&self) -> CamSpacing {
        self.settings.4
    }
}

/// One tire's track built at once: the contact at the reference deflection `d`
/// ([`EffectiveTrack`]) or the cams' base for the instantaneous spacing
/// ([`InstantaneousTrack`], on the finer grid of [`CAM_BASE_GRID_DIVISOR`]).
fn built_at_once<T: Terrain>(
    options: &VehicleOptions,
    profile: &Track<T>,
    d: f64,
    range: (f64, f64),
    envelope: &Envelope,
) -> Result<TireTrack, VehicleError> {
    Ok(match options.cam_spacing {
        CamSpacing::Static => TireTrack::Static(EffectiveTrack::build(
            profile,
            range,
            options.track_grid_m,
            envelope,
            d,
        )?),
        CamSpacing::Instantaneous => TireTrack::Instantaneous(InstantaneousTrack::build(
            profile,
            range,
            options.track_grid_m / CAM_BASE_GRID_DIVISOR,
            envelope,
        )?),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

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

    /// Tracks built on demand (a roll run's) give the contacts of tracks built at once to
    /// the bit, whatever the order the run reads them in.
    #[test]
    fn tracks_built_on_demand_are_the_tracks_built_at_once() {
        let p = VehicleParams::nominal();
        let terrain = crate::scenarios::TerrainSpec::default()
            .build(&p, 120.0, 7)
            .unwrap();
        let options = VehicleOptions {
            path_length_m: 60.0,
            ..VehicleOptions::default()
        };
        let half = 0.5 * p.front_track_m;
        let at_once = TireTracks::build(&p, Load::Loaded, &options, &terrain, half).unwrap();
        let shared = Arc::new(terrain);
        let later = TireTracks::on_demand(&p, Load::Loaded, &options, shared, half).unwrap();
        let (lo, hi) = at_once.range;
        assert_eq!(later.range, at_once.range);
        // far along first, then back to the start, then the whole range
        for k in [0.9, 0.05, 0.5, 0.0, 1.0, 0.31] {
            let s = lo + k * (hi - lo);
            for (i, z) in [(0, 1.2), (1, 1.3), (2, 1.25), (3, 1.1)] {
                let (a, b) = (at_once.contact(i, s, z), later.contact(i, s, z));
                assert_eq!(a.deflection.to_bits(), b.deflection.to_bits(), "{i} {s}");
                assert_eq!(a.slope.to_bits(), b.slope.to_bits(), "{i} {s}");
            }
        }
        assert_eq!(later, at_once);
    }
}
