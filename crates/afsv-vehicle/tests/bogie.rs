//! The `bogie` sub-table of the rear `[[axle]]` (docs/vehicles.md): the sample tandem
//! reads with its strut per side, a field left out takes its default, the dump shows the
//! table and reads back bit for bit, and bad input is a one-line error naming the field and
//! its allowed range.

use std::path::Path;

use afsv_vehicle::{builtin, load_file, load_str, to_commented_toml, Vehicle};
use vehicle_3d::{BogieParams, VehicleParams};

/// The prototype's dump with `extra` after its rear axle's `suspension = "rigid"` line
/// replaced by `rear`, and its rear unit's inertias raised for the tandem (roll, pitch, yaw
/// 26 000 / 40 000 / 44 000 kg m² for Table 6.1's 12 000 / 28 000 / 31 000): less four 2 t
/// wheel ends and two beams Table 6.1's are not positive definite unloaded (the
/// description's check says so at `rear_unit.roll_inertia_kg_m2`).
fn with_rear(rear: &str, extra: &str) -> String {
    let text = to_commented_toml(&builtin("prototype").unwrap())
        .unwrap()
        .replacen(
            "roll_inertia_kg_m2 = 12000.0",
            "roll_inertia_kg_m2 = 26000.0",
            1,
        )
        .replacen(
            "pitch_inertia_kg_m2 = 28000.0",
            "pitch_inertia_kg_m2 = 40000.0",
            1,
        )
        .replacen(
            "yaw_inertia_kg_m2 = 31000.0",
            "yaw_inertia_kg_m2 = 44000.0",
            1,
        );
    let at = text.rfind("suspension = \"rigid\"").unwrap();
    let end = at + "suspension = \"rigid\"".len();
    format!("{}{rear}\n{extra}{}", &text[..at], &text[end..])
}

fn params(text: &str) -> VehicleParams {
    match load_str(text, "v.toml", Path::new(".")).unwrap().vehicle {
        Vehicle::Articulated(a) => a.params,
        Vehicle::RigidTruck(_) => panic!("not articulated"),
    }
}

fn error(text: &str) -> String {
    let e = load_str(text, "v.toml", Path::new("."))
        .expect_err("a bad bogie was accepted")
        .to_string();
    assert!(!e.contains('\n'), "not one line: {e}");
    e
}

#[test]
fn the_sample_tandem_reads_with_one_strut_per_side_and_dumps_back() {
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../samples/vehicles/adt-28t-tandem.toml");
    let d = load_file(&path).unwrap();
    let Vehicle::Articulated(a) = &d.vehicle else {
        panic!("not articulated")
    };
    assert_eq!(a.params.bogie, Some(BogieParams::default()));
    let strut = a.params.rear_hps.expect("the tandem is suspended");
    // the default strut: the front strut scaled for a side's static strut load
    assert_eq!(strut, a.params.default_rear_strut().unwrap());
    assert!(a
        .rear_strut_source
        .as_deref()
        .unwrap()
        .contains("scaled by"));
    // the dump shows the table and reads back to the same vehicle
    let text = to_commented_toml(&d.description).unwrap();
    assert!(text.contains("[axle.bogie]\n"), "{text}");
    let back = load_str(&text, "dump.toml", path.parent().unwrap()).unwrap();
    assert_eq!(back.vehicle, d.vehicle);
}

#[test]
fn a_field_left_out_takes_its_default() {
    let p = params(&with_rear(
        "suspension = \"rigid\"",
        "[axle.bogie]\nspacing_m = 2.2\n",
    ));
    let b = p.bogie.unwrap();
    assert_eq!(b.spacing_m, 2.2);
    assert_eq!(b.beam_mass_kg, BogieParams::default().beam_mass_kg);
    assert_eq!(p.rear_hps, None);
    // without the table: the prototype's single rear axle
    let text = to_commented_toml(&builtin("prototype").unwrap()).unwrap();
    assert_eq!(params(&text).bogie, None);
}

#[test]
fn bad_bogies_name_the_field_and_the_range() {
    let e = error(&with_rear(
        "suspension = \"rigid\"",
        "[axle.bogie]\nspacing_m = 9.0\n",
    ));
    assert!(
        e.contains("axle[1].bogie.spacing_m") && e.contains("[0.8, 4]"),
        "{e}"
    );
    // tires 2.0 m across cannot stand 1.5 m apart
    let e = error(&with_rear(
        "suspension = \"rigid\"",
        "[axle.bogie]\nspacing_m = 1.5\n",
    ));
    assert!(
        e.contains("axle[1].bogie.spacing_m") && e.contains("overlap"),
        "{e}"
    );
    let e = error(&with_rear(
        "suspension = \"rigid\"",
        "[axle.bogie]\nbeam_mass_kg = -1.0\n",
    ));
    assert!(e.contains("axle[1].bogie.beam_mass_kg"), "{e}");
    let e = error(&with_rear(
        "suspension = \"rigid\"",
        "[axle.bogie]\npivot_height_m = 1.0\n",
    ));
    assert!(e.contains("pivot_height_m"), "{e}");
    // on the front axle (the table closes the front axle's entry)
    let text = with_rear("suspension = \"rigid\"", "");
    let second = text.rfind("[[axle]]").unwrap();
    let e = error(&format!(
        "{}[axle.bogie]\n\n{}",
        &text[..second],
        &text[second..]
    ));
    assert!(
        e.contains("`axle[0].bogie`") && e.contains("rear axle only"),
        "{e}"
    );
    // Table 6.1's rear unit cannot carry a tandem unloaded
    let text = to_commented_toml(&builtin("prototype").unwrap()).unwrap();
    let at = text.rfind("suspension = \"rigid\"").unwrap() + "suspension = \"rigid\"".len();
    let e = error(&format!("{}\n[axle.bogie]\n{}", &text[..at], &text[at..]));
    assert!(
        e.contains("rear_unit.roll_inertia_kg_m2") && e.contains("unloaded"),
        "{e}"
    );
}
