//! `suspension = "hps"` on the rear axle: the strut by default (the front strut scaled for
//! the rear static load), by built-in name, file or inline table; the dump shows it and
//! reads back bit for bit; bad input is a one-line error naming the field.

use std::path::Path;

use afsv_vehicle::{builtin, load_str, to_commented_toml, Vehicle};
use hps_emulsion::StrutParams;
use vehicle_3d::VehicleParams;

/// The prototype's dump with its rigid rear axle turned into `rear` (the lines after
/// `suspension = ` of the rear axle).
fn with_rear(rear: &str) -> String {
    let text = to_commented_toml(&builtin("prototype").unwrap()).unwrap();
    let at = text.rfind("suspension = \"rigid\"").unwrap();
    let end = at + "suspension = \"rigid\"".len();
    format!("{}{rear}{}", &text[..at], &text[end..])
}

fn rear_strut(text: &str) -> (Option<StrutParams>, Option<String>) {
    let d = load_str(text, "v.toml", Path::new(".")).unwrap();
    match d.vehicle {
        Vehicle::Articulated(a) => (a.params.rear_hps, a.rear_strut_source),
        Vehicle::RigidTruck(_) => panic!("not articulated"),
    }
}

/// A strut's fields as the body of an inline `[axle.strut]` table.
fn inline_strut(s: &StrutParams) -> String {
    toml::to_string(s)
        .unwrap()
        .replace("[friction]", "[axle.strut.friction]")
}

fn error(text: &str) -> String {
    let e = load_str(text, "v.toml", Path::new("."))
        .expect_err("a bad rear strut was accepted")
        .to_string();
    assert!(!e.contains('\n'), "not one line: {e}");
    e
}

#[test]
fn an_hps_rear_axle_takes_its_strut_from_every_source() {
    let nominal = VehicleParams::nominal();
    // left out: the front strut scaled for the rear static load
    let (strut, source) = rear_strut(&with_rear("suspension = \"hps\""));
    assert_eq!(strut, Some(nominal.default_rear_strut().unwrap()));
    assert!(source.unwrap().contains("scaled by 1.457"));
    // a built-in name
    let (strut, source) = rear_strut(&with_rear("suspension = \"hps\"\nstrut = \"front-axle\""));
    assert_eq!(strut, Some(StrutParams::front_axle()));
    assert_eq!(source.as_deref(), Some("front-axle"));
    // a strut file, relative to the description's folder
    let dir = std::env::temp_dir().join(format!("afsv-rear-hps-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let rear = nominal.default_rear_strut().unwrap();
    std::fs::write(dir.join("rear.json"), serde_json::to_string(&rear).unwrap()).unwrap();
    let text = with_rear("suspension = \"hps\"\nstrut = \"rear.json\"");
    let d = load_str(&text, "v.toml", &dir).unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
    match d.vehicle {
        Vehicle::Articulated(a) => assert_eq!(a.params.rear_hps, Some(rear)),
        Vehicle::RigidTruck(_) => panic!("not articulated"),
    }
    // inline, and the dump of that description reads back to the same vehicle
    let mut described = match builtin("prototype").unwrap() {
        afsv_vehicle::VehicleDescription::Articulated(a) => a,
        afsv_vehicle::VehicleDescription::RigidTruck(_) => unreachable!(),
    };
    described.axle[1].suspension = afsv_vehicle::schema::Suspension::Hps;
    described.axle[1].strut = Some(afsv_vehicle::schema::StrutSource::Inline(Box::new(rear)));
    let text =
        to_commented_toml(&afsv_vehicle::VehicleDescription::Articulated(described)).unwrap();
    assert!(
        text.contains("[axle.strut]") && text.contains("suspension = \"hps\""),
        "{text}"
    );
    let (strut, source) = rear_strut(&text);
    assert_eq!(strut, Some(rear));
    assert_eq!(source.as_deref(), Some("inline"));
}

#[test]
fn a_bad_rear_strut_is_a_one_line_error_naming_the_field() {
    let e = error(&with_rear(
        "suspension = \"hps\"\nstrut = \"no-such-strut.json\"",
    ));
    assert!(
        e.contains("axle[1].strut") && e.contains("built-in strut"),
        "{e}"
    );
    // a strut on a rigid rear axle would be silently unused
    let e = error(&with_rear("suspension = \"rigid\"\nstrut = \"front-axle\""));
    assert!(
        e.contains("axle[1].strut") && e.contains("never used"),
        "{e}"
    );
    // an inline strut with a rod larger than its piston
    let mut bad = StrutParams::front_axle();
    bad.a_hr = 0.05;
    let inline = inline_strut(&bad);
    let e = error(&with_rear(&format!(
        "suspension = \"hps\"\n\n[axle.strut]\n{inline}"
    )));
    assert!(e.contains("axle[1].strut") && e.contains("a_hr"), "{e}");
    // a strut too weak to hold the loaded rear axle up: it would sit on its bump stops
    let mut weak = StrutParams::front_axle();
    weak.p_h0 = 1.0e6;
    let inline = inline_strut(&weak);
    let e = error(&with_rear(&format!(
        "suspension = \"hps\"\n\n[axle.strut]\n{inline}"
    )));
    assert!(
        e.contains("axle[1].strut") && e.contains("loaded") && e.contains("compression stop"),
        "{e}"
    );
}
