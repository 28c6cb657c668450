//! The tires of Chapter 2: circle-line enveloping on the two-track terrain (Eqs 2.2-2.4),
//! vertical contact with loss of contact (Eq 2.1), linear cornering with the stiffness
//! interpolated against the instantaneous load (Eq 2.5) and lateral relaxation
//! (Eqs 2.6-2.7). The vehicle evaluates them through `tire_fiala::TireAssembly` with the
//! linear cornering law (`tire_fiala::LinearCorneringLaw`: `F_y = -k_ty(F_z) alpha`,
//! `alpha = atan(V_sy / |V_x|_eff)`, `k_ty = coefficient F_z` the line through the
//! Table 2.3 point, the lag of Eq 2.7 on the lateral contact velocity), the same assembly
//! as the 3-D vehicle's; this module builds its enveloping caches.
//!
//! Terrain: every left tire runs on the left track `q(s)` of the two-track terrain, every
//! right tire on the right track `p(s)` (the two tracks of Eq 2.10; the chapter gives no
//! track spacing for the coherence model, so front and rear wheels share the two
//! profiles). The profiles are read through [`vehicle_components::Terrain`] on the lines
//! `y = +-B/2` of the terrain, and `s` is the distance along the truck's path: the road is
//! laid along the path the truck drives (as a TruckSim road follows its reference path), so
//! a cornering truck stays on its two tracks.
//!
//! Enveloping cache (`tire_fiala::EffectiveTrack`): the circle-line contact of a tire under its static load is
//! precomputed once per run on a grid along each track ([`tire_fiala::EffectiveTrack`]), one cache per
//! side shared by the front and rear tires at the mean of their static deflections: the
//! wheel height `z_ref(s)` at which the circle-line deflection equals that deflection
//! `delta_ref`, and the slope `theta(s)` of P1P2 (Eq 2.4). During the run the deflection is
//! the normal penetration of the wheel into that effective line,
//! `delta = delta_ref + (z_ref(s) - z_c) cos theta(s)`, exact on a plane and to first order
//! in the load change on rough ground, and its rate is `v_s sin theta - v_z cos theta`.

use tire_fiala::{Envelope, EnvelopeMethod};

use crate::error::TruckError;

/// The circle-line enveloping of a tire of free radius `radius` on a profile sampled every
/// `sample_spacing` (m): what the truck's [`tire_fiala::EffectiveTrack`]s are built with,
/// at once or as a run reaches them ([`tire_fiala::EffectiveTrack::on_demand`]).
pub fn circle_line_envelope(radius: f64, sample_spacing: f64) -> Result<Envelope, TruckError> {
    Ok(Envelope::new(
        EnvelopeMethod::CircleLine,
        radius,
        sample_spacing,
    )?)
}
