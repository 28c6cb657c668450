//! The vehicle description: the built-ins round-trip through their commented dump to the
//! models' nominal parameters bit for bit; malformed files get one-line errors naming the
//! field, its line and column and, for a value, its plausible range.

use std::path::Path;

use afsv_vehicle::{builtin, load_builtin, load_str, to_commented_toml, Vehicle};

fn dump(name: &str) -> String {
    to_commented_toml(&builtin(name).unwrap()).unwrap()
}

fn articulated(v: &Vehicle) -> &afsv_vehicle::ArticulatedVehicle {
    match v {
        Vehicle::Articulated(a) => a,
        Vehicle::RigidTruck(_) => panic!("not articulated"),
    }
}

#[test]
fn the_prototype_dump_reads_back_to_the_nominal_parameters_bit_for_bit() {
    let text = dump("prototype");
    let d = load_str(&text, "prototype.toml", Path::new(".")).unwrap();
    assert_eq!(d.description, builtin("prototype").unwrap());
    let a = articulated(&d.vehicle);
    assert_eq!(a.params, vehicle_3d::VehicleParams::nominal());
    assert_eq!(a.front_strut, Some(hps_emulsion::StrutParams::front_axle()));
    assert_eq!(a.front_suspension, afsv_vehicle::schema::Suspension::Rigid);
    assert_eq!(a.yaw_plane.loaded, afsv_dynamics::VehicleParams::loaded());
    assert_eq!(
        a.yaw_plane.unloaded,
        afsv_dynamics::VehicleParams::unloaded()
    );
    assert!(!a.yaw_plane_derived);
    assert_eq!(load_builtin("prototype").unwrap(), d);
}

#[test]
fn the_chapter2_truck_dump_reads_back_to_the_nominal_parameters() {
    let text = dump("chapter2-truck");
    let d = load_str(&text, "truck.toml", Path::new(".")).unwrap();
    match d.vehicle {
        Vehicle::RigidTruck(t) => assert_eq!(t.params, roll_truck::TruckParams::nominal()),
        Vehicle::Articulated(_) => panic!("not a truck"),
    }
}

#[test]
fn every_field_of_the_dump_has_a_comment() {
    for name in ["prototype", "chapter2-truck"] {
        let text = dump(name);
        let lines: Vec<&str> = text.lines().collect();
        for (i, l) in lines.iter().enumerate() {
            let is_key = !l.starts_with('#') && !l.starts_with('[') && l.contains(" = ");
            if is_key {
                assert!(
                    i > 0 && lines[i - 1].starts_with('#'),
                    "{name}: no comment above line {}: {l}",
                    i + 1
                );
            }
        }
    }
}

/// The error of the prototype's dump with `from` replaced by `to`.
fn error_of(from: &str, to: &str) -> String {
    let text = dump("prototype");
    assert!(text.contains(from), "{from:?} not in the dump");
    let bad = text.replacen(from, to, 1);
    let e = load_str(&bad, "v.toml", Path::new("."))
        .expect_err("a malformed description was accepted")
        .to_string();
    assert!(!e.contains('\n'), "not one line: {e}");
    e
}

#[test]
fn malformed_descriptions_name_the_field_line_and_column() {
    let e = error_of("mass_kg = 21000.0", "mass_kg = \"heavy\"");
    assert!(e.starts_with("v.toml:"), "{e}");
    assert!(
        e.contains("front_unit.mass_kg") && e.contains("invalid type"),
        "{e}"
    );

    let e = error_of("mass_kg = 21000.0", "mass_kg = -21000.0");
    assert!(
        e.contains("front_unit.mass_kg") && e.contains("plausible range"),
        "{e}"
    );

    let e = error_of("cg_height_m = 1.36\n", "");
    assert!(
        e.contains("front_unit") && e.contains("missing field `cg_height_m`"),
        "{e}"
    );

    let e = error_of("[joint]\n", "[joint]\nheigth_m = 1.0\n");
    assert!(
        e.contains("joint") && e.contains("unknown field `heigth_m`"),
        "{e}"
    );

    // a moment of inertia larger than the other two together: no real body
    let e = error_of(
        "roll_inertia_kg_m2 = 14000.0",
        "roll_inertia_kg_m2 = 140000.0",
    );
    assert!(
        e.contains("front_unit.roll_inertia_kg_m2") && e.contains("triangle"),
        "{e}"
    );

    // the rear axle ahead of the joint (a negative distance) is outside the wheelbase
    let e = error_of(
        "distance_from_joint_m = 3.44",
        "distance_from_joint_m = -3.44",
    );
    assert!(e.contains("axle[1].distance_from_joint_m"), "{e}");

    let e = error_of("tire = \"29.5R29\"", "tire = \"23.5R25\"");
    assert!(
        e.contains("axle[0].tire") && e.contains("no tire `23.5R25`"),
        "{e}"
    );

    // a field a tire set would otherwise default silently
    let e = error_of("u_min = 0.6\n", "");
    assert!(e.contains("missing field `u_min`"), "{e}");

    let e = error_of("format = \"afsv-vehicle-1\"", "format = \"afsv-vehicle-9\"");
    assert!(
        e.contains("`format`") && e.contains("afsv-vehicle-9"),
        "{e}"
    );

    // a 3 m tire radius puts the wheel ends so far from the unit's cg that the unit less
    // its wheels has no positive definite inertia: refused when read, not when run
    let e = error_of("unloaded_radius_m = 1.0", "unloaded_radius_m = 3.0");
    assert!(
        e.contains("front_unit.roll_inertia_kg_m2") && e.contains("not positive definite"),
        "{e}"
    );

    let e = error_of("strut = \"front-axle\"", "strut = \"no-such-strut.json\"");
    assert!(
        e.contains("axle[0].strut") && e.contains("built-in strut"),
        "{e}"
    );
}

#[test]
fn a_located_error_points_at_the_offending_line() {
    let text = dump("prototype");
    let line = text
        .lines()
        .position(|l| l.starts_with("track_m = 2.28"))
        .unwrap()
        + 1;
    let bad = text.replacen("track_m = 2.28", "track_m = 60.0", 1);
    let e = load_str(&bad, "v.toml", Path::new("."))
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with(&format!("v.toml:{line}:")),
        "{e} (line {line})"
    );
    assert!(
        e.contains("axle[0].track_m") && e.contains("[0.8, 6]"),
        "{e}"
    );
}

#[test]
fn without_yaw_plane_tables_the_yaw_plane_data_are_derived_from_the_units() {
    let text = dump("prototype");
    let cut = text.find("\n# Data of the yaw-plane model").unwrap();
    // drop everything from the yaw_plane comment on (the last section of the dump)
    let without = &text[..cut + 1];
    let d = load_str(without, "v.toml", Path::new(".")).unwrap();
    let a = articulated(&d.vehicle);
    assert!(a.yaw_plane_derived);
    let t31 = afsv_dynamics::VehicleParams::unloaded();
    let u = &a.yaw_plane.unloaded;
    // Table 3.1's unloaded masses and lengths are Table 6.1's
    for (x, y) in [
        (u.m_f_kg, t31.m_f_kg),
        (u.m_r_kg, t31.m_r_kg),
        (u.i_f_kg_m2, t31.i_f_kg_m2),
        (u.i_r_kg_m2, t31.i_r_kg_m2),
        (u.l_f1_m, t31.l_f1_m),
        (u.l_f2_m, t31.l_f2_m),
        (u.l_r1_m, t31.l_r1_m),
        (u.l_r2_m, t31.l_r2_m),
        (u.half_track_m, t31.half_track_m),
    ] {
        assert!((x - y).abs() < 1e-9 * y.abs().max(1.0), "{x} vs {y}");
    }
    // loaded: rear unit plus payload about their combined cg (hand calculation)
    let l = &a.yaw_plane.loaded;
    let x = (18_500.0 * 2.84 + 33_720.0 * 2.6) / 52_220.0;
    let i =
        31_000.0 + 76_000.0 + 18_500.0 * (2.84f64 - x).powi(2) + 33_720.0 * (2.6f64 - x).powi(2);
    assert!((l.m_r_kg - 52_220.0).abs() < 1e-9);
    assert!((l.l_r2_m - x).abs() < 1e-12 && (l.l_r1_m - (3.44 - x)).abs() < 1e-12);
    assert!((l.i_r_kg_m2 - i).abs() < 1e-6);
    // cornering stiffness of the Table 6.2 tire at the static loads: loaded above unloaded
    assert!(l.c_alpha_r_n_per_rad > u.c_alpha_r_n_per_rad);
    assert!(u.k_mz_f_nm_per_rad > 0.0);
}

/// The prototype's dump with both axles' suspension as given, and `link` appended.
fn with_link(front: &str, rear: &str, link: &str) -> String {
    let text = dump("prototype");
    let mut seen = 0;
    let lines: Vec<String> = text
        .lines()
        .map(|l| {
            if l.starts_with("suspension = ") {
                seen += 1;
                format!("suspension = \"{}\"", if seen == 1 { front } else { rear })
            } else {
                l.to_string()
            }
        })
        .collect();
    lines.join("\n") + "\n" + link
}

const LINE: &str = "diameter_m = 0.03\nviscosity_pa_s = 0.027\nport_cd = 0.7\n\
    accumulator_volume_m3 = 5e-3\nprecharge_pa = 2e6\npiston_end = { length_m = 0.3, port_area_m2 = 3e-4 }\n\
    rod_end = { length_m = 2.0, port_area_m2 = 6e-5 }\n";

#[test]
fn a_link_reads_with_its_default_or_given_lines_and_is_refused_with_its_field_path() {
    use hps_emulsion::interconnect::LineParams;
    use vehicle_3d::interconnect::Link;
    let read = |text: &str| load_str(text, "v.toml", Path::new("."));
    let link_of = |text: &str| articulated(&read(text).unwrap().vehicle).link;
    // no [link]: none, as before
    assert_eq!(link_of(&with_link("hps", "rigid", "")), None);
    assert_eq!(
        link_of(&with_link("hps", "rigid", "[link]\nkind = \"roll\"\n")),
        Some(Link::Roll(LineParams::front_axle_roll()))
    );
    let given = link_of(&with_link(
        "hps",
        "rigid",
        &format!("[link]\nkind = \"roll\"\n[link.line]\n{LINE}"),
    ));
    assert!(matches!(given, Some(Link::Roll(l)) if l.diameter_m == 0.03));
    // pitch: the default lines at the struts' rod-area ratio, or two given
    let d = read(&with_link("hps", "hps", "[link]\nkind = \"pitch\"\n")).unwrap();
    let a = articulated(&d.vehicle);
    assert_eq!(a.link, Some(Link::pitch_of(&a.params).unwrap()));
    let two = format!("[link]\nkind = \"pitch\"\n[[link.lines]]\n{LINE}[[link.lines]]\n{LINE}");
    assert!(matches!(
        link_of(&with_link("hps", "hps", &two)),
        Some(Link::Pitch(_))
    ));
    // refusals, one line each, naming the field
    for (front, rear, link, path, says) in [
        (
            "rigid",
            "rigid",
            "[link]\nkind = \"roll\"\n",
            "`link.kind`",
            "front [[axle]] needs",
        ),
        (
            "hps",
            "rigid",
            "[link]\nkind = \"pitch\"\n",
            "`link.kind`",
            "both [[axle]]",
        ),
        (
            "hps",
            "rigid",
            "[link]\nkind = \"yaw\"\n",
            "`link.kind`",
            "unknown variant",
        ),
        (
            "hps",
            "rigid",
            "[link]\nkind = \"roll\"\nlength_m = 1.0\n",
            "`link",
            "unknown field",
        ),
        (
            "hps",
            "hps",
            &format!("[link]\nkind = \"pitch\"\n[link.line]\n{LINE}"),
            "`link.line`",
            "pitch link takes two",
        ),
        (
            "hps",
            "rigid",
            &two.replace("pitch", "roll"),
            "`link.lines`",
            "roll link takes one",
        ),
        (
            "hps",
            "rigid",
            &format!(
                "[link]\nkind = \"roll\"\n[link.line]\n{}",
                LINE.replace("0.03", "-1.0")
            ),
            "`link.line`",
            "diameter_m",
        ),
        (
            "hps",
            "hps",
            &format!(
                "[link]\nkind = \"pitch\"\n[[link.lines]]\n{LINE}[[link.lines]]\n{}",
                LINE.replace("5e-3", "0.0")
            ),
            "`link.lines[1]`",
            "accumulator_volume_m3",
        ),
    ] {
        let e = read(&with_link(front, rear, link)).unwrap_err().to_string();
        assert!(e.contains(path) && e.contains(says), "{link}: {e}");
        assert_eq!(e.lines().count(), 1, "{e}");
    }
}
