//! The suspension layouts of `afsv study layouts` and `afsv optimize layout` by name: which
//! axles carry struts, which struts are interconnected, and the cab and seat they are read
//! at, built from one vehicle description (docs/layouts.md).

use crate::layouts::Layout;
use hps_emulsion::interconnect::LineParams;
use vehicle_3d::cab_ride::CabSeatLayout;
use vehicle_3d::interconnect::Link;
use vehicle_3d::FrontAxle;

/// The layouts `--layouts` can name, in the table's order.
pub const LAYOUT_NAMES: &[(&str, &str)] = &[
    ("rigid", "every axle rigid"),
    (
        "front-hps",
        "the description's front-axle strut (or its candidate strut), rigid rear",
    ),
    (
        "front-rear-hps",
        "front strut and the description's rear strut (or the front strut scaled for the rear static load)",
    ),
    (
        "front-roll",
        "front-hps with the front struts roll-interconnected (sealed pistons, two cross lines with accumulators)",
    ),
    (
        "front-rear-roll",
        "front-rear-hps with the front struts roll-interconnected",
    ),
    (
        "front-rear-pitch",
        "front-rear-hps with each side's front and rear struts pitch-interconnected (sealed pistons, two cross lines with accumulators per side)",
    ),
];

/// The layouts `text` names (comma separated, [`LAYOUT_NAMES`]), built from the described
/// vehicle `v`: its front strut, its rear strut (or the front strut scaled for the rear
/// static load, [`vehicle_3d::VehicleParams::default_rear_strut`]) and its `[link]` lines
/// (or the generic lines of their kind). Errors name the option `--layouts` and the layout.
pub fn build_layouts(
    v: &afsv_vehicle::ArticulatedVehicle,
    text: &str,
) -> Result<Vec<Layout>, String> {
    let mut out: Vec<Layout> = Vec::new();
    for name in text.split(',').map(str::trim) {
        if out.iter().any(|l| l.name == name) {
            return Err(format!("--layouts: `{name}` is named twice"));
        }
        if !LAYOUT_NAMES.iter().any(|(n, _)| *n == name) {
            let known: Vec<&str> = LAYOUT_NAMES.iter().map(|(n, _)| *n).collect();
            return Err(format!(
                "--layouts: unknown layout `{name}` (known: {})",
                known.join(", ")
            ));
        }
        let suspended = name != "rigid";
        let rear = name.starts_with("front-rear");
        let mut params = vehicle_3d::VehicleParams {
            rear_hps: None,
            ..v.params.clone()
        };
        if suspended {
            params.hps = v.front_strut.ok_or_else(|| {
                format!(
                    "--layouts {name}: the vehicle description `{}` gives the front axle no strut (add `strut = \"front-axle\"` or a strut file to its front [[axle]])",
                    v.name
                )
            })?;
        }
        if rear {
            params.rear_hps = Some(match v.params.rear_hps {
                Some(strut) => strut,
                None => params
                    .default_rear_strut()
                    .map_err(|e| format!("--layouts {name}: the default rear strut: {e}"))?,
            });
        }
        out.push(Layout {
            name: name.into(),
            front_axle: if suspended {
                FrontAxle::Suspended
            } else {
                FrontAxle::Rigid
            },
            // the linked layouts take the description's [link] lines when it has a link
            // of their kind, else the generic lines
            front_link: name.ends_with("-roll").then(|| match v.link {
                Some(Link::Roll(line)) => line,
                _ => LineParams::front_axle_roll(),
            }),
            pitch_link: match (name.ends_with("-pitch"), &params.rear_hps, v.link) {
                (true, _, Some(Link::Pitch(lines))) => Some(lines),
                (true, Some(rear), _) => Some(
                    LineParams::side_pitch(rear.a_hr / params.hps.a_hr)
                        .map_err(|e| format!("--layouts {name}: the pitch lines: {e}"))?,
                ),
                _ => None,
            },
            params,
        });
    }
    Ok(out)
}

/// The cab and seat `flag` names (`--seat`): `off` (none), `generic`
/// ([`CabSeatLayout::generic`]), `described` (the description's), or by default the
/// description's when it has one, else the generic one.
pub fn seat_of(
    v: &afsv_vehicle::ArticulatedVehicle,
    flag: Option<&str>,
) -> Result<Option<CabSeatLayout>, String> {
    match flag {
        Some("off") => Ok(None),
        Some("generic") => Ok(Some(CabSeatLayout::generic())),
        Some("described") => v.cab_seat.map(Some).ok_or_else(|| {
            format!(
                "--seat described: the vehicle description `{}` has no [cab.body] and [seat]",
                v.name
            )
        }),
        Some(other) => Err(format!(
            "--seat: `{other}` is not generic, off or described"
        )),
        None => Ok(Some(v.cab_seat.unwrap_or_else(CabSeatLayout::generic))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn layouts_and_seats_are_named_and_bad_names_refused() {
        let v = afsv_vehicle::load_builtin("prototype").unwrap();
        let afsv_vehicle::Vehicle::Articulated(v) = v.vehicle else {
            panic!("the prototype is articulated")
        };
        let l = build_layouts(
            &v,
            "rigid, front-hps,front-rear-hps,front-roll,front-rear-roll,front-rear-pitch",
        )
        .unwrap();
        assert_eq!(l.len(), 6);
        assert_eq!(l[0].front_axle, FrontAxle::Rigid);
        assert!(l[1..].iter().all(|l| l.front_axle == FrontAxle::Suspended));
        let rear: Vec<bool> = l.iter().map(|l| l.params.rear_hps.is_some()).collect();
        assert_eq!(rear, [false, false, true, false, true, true]);
        let link: Vec<bool> = l.iter().map(|l| l.front_link.is_some()).collect();
        assert_eq!(link, [false, false, false, true, true, false]);
        let pitch: Vec<bool> = l.iter().map(|l| l.pitch_link.is_some()).collect();
        assert_eq!(pitch, [false, false, false, false, false, true]);
        assert!(build_layouts(&v, "rigid,rigid")
            .unwrap_err()
            .contains("twice"));
        assert!(build_layouts(&v, "rigid,bogus")
            .unwrap_err()
            .contains("unknown layout `bogus`"));
        assert!(seat_of(&v, Some("off")).unwrap().is_none());
        assert!(seat_of(&v, None).unwrap().is_some());
        assert!(seat_of(&v, Some("soft")).unwrap_err().contains("--seat"));
    }

    #[test]
    fn a_described_link_gives_its_lines_to_the_layouts_of_its_kind() {
        let v = afsv_vehicle::load_builtin("prototype").unwrap();
        let afsv_vehicle::Vehicle::Articulated(mut v) = v.vehicle else {
            panic!("the prototype is articulated")
        };
        let names = "front-hps,front-roll,front-rear-pitch";
        let generic = build_layouts(&v, names).unwrap();
        let roll = LineParams {
            diameter_m: 0.02,
            ..LineParams::front_axle_roll()
        };
        v.link = Some(Link::Roll(roll));
        let l = build_layouts(&v, names).unwrap();
        assert_eq!(l[0].link(), None, "an unlinked layout stays unlinked");
        assert_eq!(l[1].front_link, Some(roll));
        assert_eq!(l[2].pitch_link, generic[2].pitch_link);
        let [front, rear] = generic[2].pitch_link.unwrap();
        let pitch = [
            LineParams {
                diameter_m: 0.03,
                ..front
            },
            rear,
        ];
        v.link = Some(Link::Pitch(pitch));
        let l = build_layouts(&v, names).unwrap();
        assert_eq!(l[1].front_link, generic[1].front_link);
        assert_eq!(l[2].pitch_link, Some(pitch));
    }
}
