//! Fuzz cases of the vehicle description (TOML, docs/vehicles.md): `afsv params check
//! vehicle` on a damaged description, and `afsv vehicle ...` / `afsv yaw measures` with
//! `--vehicle` on one. The templates are the built-in descriptions as `afsv params dump
//! vehicle` writes them.

use super::super::gen::*;

/// A built-in description as commented TOML: the prototype or the Chapter 2 truck.
fn template(rng: &mut Rng) -> String {
    template_of(rng.pick(&["prototype", "prototype", "chapter2-truck"]))
}

/// The built-in description `name` as commented TOML.
fn template_of(name: &str) -> String {
    let d = afsv_vehicle::builtin(name).expect("a built-in vehicle");
    afsv_vehicle::to_commented_toml(&d).expect("the built-in descriptions serialise")
}

/// `text` damaged in one or two ways a hand-edited file can be: a bad number, a value of
/// the wrong type, a missing or unknown key, a wrong format or kind, a cut file, a
/// strut file that is not there, a duplicated table.
pub(crate) fn mutate_toml(rng: &mut Rng, text: &str) -> String {
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    for _ in 0..1 + rng.below(2) {
        let values: Vec<usize> = (0..lines.len())
            .filter(|&i| !lines[i].starts_with('#') && lines[i].contains(" = "))
            .collect();
        if values.is_empty() {
            break;
        }
        let i = values[rng.below(values.len())];
        let key = lines[i].split(" = ").next().unwrap_or_default().to_string();
        match rng.below(12) {
            0 => lines.truncate(i),
            1 => {
                lines.remove(i);
            }
            2 => lines.insert(i, "unknown_key = 1.0".into()),
            3 => lines[i] = format!("{key} = \"x\""),
            4 => lines[i] = format!("{key} = nan"),
            5 => lines[i] = format!("{key} = inf"),
            6 => lines[i] = format!("{key} = -1.0"),
            7 => lines[i] = format!("{key} = 0.0"),
            8 => lines[i] = format!("{key} = 1e308"),
            9 => lines[i] = format!("{key} = 1e-320"),
            10 => {
                let bad = rng.pick(&[
                    "format = \"afsv-vehicle-9\"",
                    "kind = \"tank\"",
                    "strut = \"missing-strut.json\"",
                    "strut = \"s.json\"",
                    "suspension = \"air\"",
                    "tire = \"no-such-tire\"",
                    "unit = \"middle\"",
                ]);
                let k = bad.split(" = ").next().unwrap_or_default();
                match lines.iter().position(|l| l.starts_with(&format!("{k} = "))) {
                    Some(j) => lines[j] = bad.into(),
                    None => lines.push(bad.into()),
                }
            }
            _ => {
                if let Some(j) = lines.iter().position(|l| l.starts_with('[')) {
                    let table = lines[j].clone();
                    lines.push(table);
                }
            }
        }
    }
    lines.join("\n") + "\n"
}

/// A damaged description in `v.toml` (one case in five left whole), with a strut file
/// `s.json` beside it that may be damaged too.
pub(crate) fn description_file(g: &mut Gen<'_>) {
    let text = template(&mut g.rng);
    let text = if g.rng.chance(0.2) {
        text
    } else {
        mutate_toml(&mut g.rng, &text)
    };
    g.file("v.toml", text.into_bytes());
    let strut = afsv_vehicle::builtin_strut("front-axle").expect("a built-in strut");
    let strut = serde_json::to_string_pretty(&strut).expect("a strut serialises");
    let strut = mutate_json(&mut g.rng, &strut);
    g.file("s.json", strut.into_bytes());
}

/// `afsv params check vehicle v.toml`.
pub(super) fn check_case(g: &mut Gen<'_>) {
    description_file(g);
    g.arg("v.toml");
}

/// One interconnection line as TOML table lines (`LineParams::front_axle_roll`).
const LINE: &str = "diameter_m = 0.038\nviscosity_pa_s = 0.027\nport_cd = 0.7\n\
    accumulator_volume_m3 = 8.4e-3\nprecharge_pa = 2.4e6\n\
    piston_end = { length_m = 0.3, port_area_m2 = 3.3e-4 }\n\
    rod_end = { length_m = 2.5, port_area_m2 = 6.2e-5 }\n";

/// `afsv params check vehicle v.toml` on the prototype with a `[link]` (docs/vehicles.md):
/// a roll or pitch link (or another kind), its line tables given, mismatched or left out,
/// the axles suspended or not, then the link's lines damaged as a hand-edited file can be.
pub(super) fn link_case(g: &mut Gen<'_>) {
    let mut text = template_of("prototype");
    for _ in 0..g.rng.below(3) {
        text = text.replacen("suspension = \"rigid\"", "suspension = \"hps\"", 1);
    }
    let kind = g
        .rng
        .pick(&["roll", "roll", "pitch", "pitch", "yaw", ""])
        .to_string();
    let mut link = format!("[link]\nkind = \"{kind}\"\n");
    match g.rng.below(4) {
        0 => {}
        1 => link += &format!("[link.line]\n{LINE}"),
        2 => link += &format!("[[link.lines]]\n{LINE}[[link.lines]]\n{LINE}"),
        _ => link += &format!("[[link.lines]]\n{LINE}"),
    }
    let link = if g.rng.chance(0.2) {
        link
    } else {
        mutate_toml(&mut g.rng, &link)
    };
    g.file("v.toml", (text + "\n" + &link).into_bytes());
    g.arg("v.toml");
}
