//! Fuzz cases of the vehicle models that run simulations on success: the Chapter 2
//! truck (`afsv roll`) and the Chapter 6 3-D vehicle (`afsv vehicle`).

use super::super::gen::*;

/// The options and files of one `afsv roll ...` (and `afsv params check truck`) case.
/// Successes are kept short (a few simulated seconds); the study and the calibration get
/// only values they must refuse, since a valid one runs many simulations.
pub(super) fn roll_case(g: &mut Gen<'_>, group: &str) {
    match group {
        "roll simulate" | "roll measures" => {
            roll_case_args(g);
            if group == "roll simulate" {
                g.num("--dt", "0.01", 0.3);
                let o = g.output("run.csv", &["p.json", "run.json", "in.csv"]);
                g.push_opt("-o", &o);
            } else if g.rng.chance(0.3) {
                g.arg("--json");
            }
        }
        "roll study" => {
            let s = g
                .rng
                .pick(&[
                    "cg",
                    "roughness",
                    "waviness",
                    "band",
                    "trucks",
                    "sensitivity",
                    "bogus",
                    "",
                ])
                .to_string();
            g.arg(&s);
            let v = g.bad();
            g.push_opt("--seeds", &v);
            if g.rng.chance(0.3) {
                let o = g.output("plot.svg", &["p.json"]);
                g.push_opt("--plot", &o);
            }
        }
        "roll calibrate" => {
            if g.rng.chance(0.5) {
                let v = g
                    .rng
                    .pick(&["-1", "0", "nan", "inf", "abc", ""])
                    .to_string();
                g.push_opt("--target-g", &v);
            } else {
                let t = g.rng.pick(&["", "{}", "[1]", "{\"bogus\": 1}"]).to_string();
                g.file("p.json", t.into_bytes());
                g.push_opt("--params", "p.json");
            }
        }
        "params check truck" => {
            g.truck_params_file("p.json");
            g.arg("p.json");
        }
        _ => unreachable!("group {group}"),
    }
}

/// The truck and terrain options shared by `afsv roll simulate` and `afsv roll measures`.
fn roll_case_args(g: &mut Gen<'_>) {
    if g.rng.chance(0.4) {
        g.truck_params_file("p.json");
        g.push_opt("--params", "p.json");
    }
    g.num("--cg-height-m", "3.15", 0.15);
    if g.rng.chance(0.3) {
        g.arg("--smooth");
    }
    if g.rng.chance(0.3) {
        let c = g.rng.pick(&["A", "C", "E", "F", "", "e"]).to_string();
        g.push_opt("--class", &c);
    }
    if g.rng.chance(0.2) {
        let d = g.rng.pick(&["left", "right", "up", ""]).to_string();
        g.push_opt("--direction", &d);
    }
    g.num("--waviness", "2", 0.15);
    g.num("--mc", "0.3", 0.15);
    if g.rng.chance(0.2) {
        let b = g
            .rng
            .pick(&["0.02,5", "5,0.02", "nan,5", "0.02,11", "0,1", "0.1", ""])
            .to_string();
        g.push_opt("--band", &b);
    }
    if g.rng.chance(0.1) {
        let s = g
            .rng
            .pick(&["-1", "18446744073709551616", "abc"])
            .to_string();
        g.push_opt("--seed", &s);
    }
    if g.rng.chance(0.2) {
        let t = g
            .rng
            .pick(&["calibrated", "plausible", "stiff", ""])
            .to_string();
        g.push_opt("--truck", &t);
    }
    g.num("--ramp-rate", "10", 0.1);
    if g.rng.chance(0.2) {
        g.arg("--no-bump-stops");
    }
    g.num("--sp-threshold", "0.9", 0.1);
    g.num("--sp-max-dip", "1", 0.1);
    if g.rng.chance(0.3 * g.scale) {
        let v = g.bad();
        g.push_opt("--duration", &v);
    } else {
        g.push_opt("--duration", "3");
    }
}

/// A partial 3-D vehicle parameter file (missing fields take the nominal values), the
/// template of the mutated `--params` files of `afsv vehicle`.
const VEHICLE_PARAMS: &str = r#"{
  "front_axle_to_joint_m": 1.68,
  "rear_track_m": 2.28,
  "joint_height_m": 1.0,
  "wheel_mass_kg": 2000.0,
  "wheel_spin_inertia_kg_m2": 600.0,
  "cab_point_m": [1.68, 0.0, 2.0],
  "payload": {
    "mass_kg": 33720.0,
    "cg_height_m": 2.4,
    "cg_to_joint_m": 2.6,
    "roll_inertia_kg_m2": 27000.0,
    "pitch_inertia_kg_m2": 72000.0,
    "yaw_inertia_kg_m2": 76000.0
  },
  "drive": {"kp_n_m_per_m_s": 9000.0, "ki_n_m_per_m": 2000.0, "max_torque_n_m": 60000.0}
}"#;

/// The options and files of one `afsv vehicle ...` (and `afsv params check vehicle-3d`)
/// case. Successes are kept short: one or two seeds, 20 m ride windows, a fast ramp to
/// rollover within 12 s, one simulated second.
pub(super) fn vehicle_case(g: &mut Gen<'_>, group: &str) {
    if group == "params check vehicle-3d" {
        let text = mutate_json(&mut g.rng, VEHICLE_PARAMS);
        g.file("p.json", text.into_bytes());
        g.arg("p.json");
        return;
    }
    if g.rng.chance(0.3) {
        let text = mutate_json(&mut g.rng, VEHICLE_PARAMS);
        g.file("p.json", text.into_bytes());
        g.push_opt("--params", "p.json");
    } else if g.rng.chance(0.3) {
        super::described::description_file(g);
        let v = g
            .rng
            .pick(&[
                "v.toml",
                "v.toml",
                "prototype",
                "chapter2-truck",
                "missing.toml",
            ])
            .to_string();
        g.push_opt("--vehicle", &v);
    }
    if g.rng.chance(0.3) {
        let l = g.rng.pick(&["loaded", "unloaded", "heavy", ""]).to_string();
        g.push_opt("--load", &l);
    }
    // `vehicle measures` runs the fixed D1-D3 scenarios: no speed, terrain or plot
    let measures = group == "vehicle measures";
    if !measures {
        g.num("--speed-kmh", "20", 0.2);
    }
    hps_opt(
        g,
        &["off", "nominal", "s.json", "missing.json", "p.json", ""],
    );
    let simulate = group == "vehicle simulate";
    let single_run = simulate || group == "vehicle path-change";
    let terrain = !measures && g.rng.chance(0.4);
    if terrain {
        let bad = g.bad();
        let t = g
            .rng
            .pick(&[
                "smooth",
                "flat",
                "class:C",
                "class:E,mc:0.3",
                "class:C,seed:2",
                "mc:0.1,class:A",
                "class:Z",
                "class:E,class:C",
                "slope:3",
                "E",
                "",
                "class:C,seed:-1",
            ])
            .to_string();
        let t = if g.rng.chance(0.3 * g.scale) {
            format!("class:C,mc:{bad}")
        } else {
            t
        };
        g.push_opt("--terrain", &t);
    }
    if single_run {
        if g.rng.chance(0.2) {
            g.push_opt("--seed", "2");
        }
    } else {
        if g.rng.chance(0.3 * g.scale) {
            let v = g.bad();
            g.push_opt("--seeds", &v);
        } else if group == "vehicle yaw" && !terrain {
            // smooth ground by default: no seeds
        } else if g.rng.chance(0.5) {
            let n = g.rng.pick(&["1", "2"]).to_string();
            g.push_opt("--seeds", &n);
        } else {
            g.push_opt("--seed", "3");
        }
        if g.rng.chance(0.3) {
            g.arg("--json");
        }
        if !measures && g.rng.chance(0.2) {
            let o = g.output("plot.svg", &["p.json", "s.json"]);
            g.push_opt("--plot", &o);
        }
    }
    match group {
        "vehicle measures" => {}
        "vehicle path-change" => {
            g.num("--offset-m", "4.5", 0.3);
            if g.rng.chance(0.3 * g.scale) {
                let v = g.bad();
                g.push_opt("--duration", &v);
            } else {
                g.push_opt("--duration", "8");
            }
            if g.rng.chance(0.3) {
                g.arg("--json");
            }
            if g.rng.chance(0.2) {
                let o = g.output("plot.svg", &["p.json", "s.json"]);
                g.push_opt("--plot", &o);
            }
            if g.rng.chance(0.3) {
                let o = g.output("run.csv", &["p.json", "s.json", "run.json"]);
                g.push_opt("-o", &o);
            }
        }
        "vehicle ride" => {
            if g.rng.chance(0.3 * g.scale) {
                let v = g.bad();
                g.push_opt("--length-m", &v);
            } else {
                g.push_opt("--length-m", "20");
            }
        }
        "vehicle roll" => {
            g.num("--ramp-deg-s", "40", 0.3);
            if g.rng.chance(0.3 * g.scale) {
                let v = g.bad();
                g.push_opt("--duration", &v);
            } else {
                g.push_opt("--duration", "12");
            }
        }
        "vehicle yaw" => g.num("--pulse-deg", "30", 0.3),
        "vehicle simulate" => {
            let bad = g.bad();
            let steer = match g.rng.below(6) {
                0 => format!("pulse:{bad},0.2,0.5"),
                1 => format!("pulse:30,{bad},0.5"),
                2 => format!("ramp:{bad},0.2"),
                3 => g
                    .rng
                    .pick(&["none", "", "pulse:30", "ramp:5", "step:3,1", "sine:1,2,3"])
                    .to_string(),
                _ => "pulse:30,0.2,0.3".to_string(),
            };
            g.push_opt("--steer", &steer);
            if g.rng.chance(0.3 * g.scale) {
                let v = g.bad();
                g.push_opt("--duration", &v);
            } else {
                g.push_opt("--duration", "1");
            }
            g.num("--dt", "0.01", 0.2);
            let o = g.output("run.csv", &["p.json", "s.json", "run.json"]);
            g.push_opt("-o", &o);
        }
        _ => unreachable!("group {group}"),
    }
}

/// The options of one `afsv study speed-sweep` case: short sweeps (one or two speeds, one
/// seed) with bad lists, designs and strut files mixed in.
pub(super) fn sweep_case(g: &mut Gen<'_>) {
    let bad = g.bad();
    let speeds = match g.rng.below(6) {
        0 => bad.to_string(),
        1 => format!("20,{bad}"),
        2 => g
            .rng
            .pick(&[
                "30,20", "20,20", "", "0.5", "1,2", "1e400", "20;30", "10,20,30",
            ])
            .to_string(),
        _ => g.rng.pick(&["30", "20,30"]).to_string(),
    };
    g.push_opt("--speeds", &speeds);
    if g.rng.chance(0.3 * g.scale) {
        let v = g.bad();
        g.push_opt("--seeds", &v);
    } else {
        g.push_opt("--seeds", "1");
    }
    if g.rng.chance(0.3) {
        let d = match g.rng.below(3) {
            0 => format!("0.038,{bad},11"),
            1 => g
                .rng
                .pick(&["0.0494,6.28,16.0", "0.038,8", "1,2,3", "0,0,0", "", "a,b,c"])
                .to_string(),
            _ => "0.045,6,14".to_string(),
        };
        g.push_opt("--design", &d);
    }
    hps_opt(g, &["nominal", "s.json", "missing.json", ""]);
    if g.rng.chance(0.3) {
        g.arg("--json");
    }
    if g.rng.chance(0.2) {
        let o = g.output("plot.svg", &["s.json"]);
        g.push_opt("--plot", &o);
    }
}

/// With probability 1/4, `--hps` with one of `choices`; `s.json` is written as a broken
/// strut file.
fn hps_opt(g: &mut Gen<'_>, choices: &[&str]) {
    if g.rng.chance(0.25) {
        let h = g.rng.pick(choices).to_string();
        if h == "s.json" {
            let t = g
                .rng
                .pick(&["", "{}", "[1]", "{\"a_hc\": -1}", "{\"bogus\": 1}"])
                .to_string();
            g.file("s.json", t.into_bytes());
        }
        g.push_opt("--hps", &h);
    }
}
