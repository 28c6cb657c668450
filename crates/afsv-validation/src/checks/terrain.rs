//! Table 2.4: terrain roughness. The ISO 8608 alpha_r are computed from the standard's
//! class values (G_d(n0) n0^2); the waviness w = 2 of the classes and both parameters of the
//! measured off-road terrains are inputs the crate carries.

use super::Ctx;
use crate::Echo;

/// Table 2.4 roughness parameters against `terrain_psd`.
pub(super) fn check_terrain(ctx: &mut Ctx) -> Result<(), String> {
    use terrain_psd::{IsoClass, OffRoadTerrain, PowerLawPsd};
    for (id, c) in [
        ("t2_4_iso_class_a", IsoClass::A),
        ("t2_4_iso_class_b", IsoClass::B),
        ("t2_4_iso_class_c", IsoClass::C),
        ("t2_4_iso_class_d", IsoClass::D),
        ("t2_4_iso_class_e", IsoClass::E),
    ] {
        let p = PowerLawPsd::iso(c);
        let note = "PowerLawPsd::iso (ISO 8608 G_d(n0) n0^2)";
        ctx.compare(id, Some("alpha_r"), None, p.alpha_r, note);
        ctx.echo(Echo::Input, id, Some("w"), None, p.waviness, note);
    }
    for (id, t) in [
        ("t2_4_offroad_forestry", OffRoadTerrain::Forestry),
        ("t2_4_offroad_pasture", OffRoadTerrain::Pasture),
        ("t2_4_offroad_mvee", OffRoadTerrain::Mvee),
        ("t2_4_offroad_plowed", OffRoadTerrain::Plowed),
    ] {
        let p = PowerLawPsd::off_road(t);
        ctx.echo(
            Echo::Input,
            id,
            Some("alpha_r"),
            None,
            p.alpha_r,
            "PowerLawPsd::off_road",
        );
        ctx.echo(
            Echo::Input,
            id,
            Some("w"),
            None,
            p.waviness,
            "PowerLawPsd::off_road",
        );
    }
    Ok(())
}
