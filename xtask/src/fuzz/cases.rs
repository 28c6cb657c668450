//! The fuzz cases: which subcommands are exercised how often ([`GROUPS`]) and, per
//! subcommand family, the bad options and files of one case.

use super::gen::*;

mod described;
mod optimize;
mod vehicles;

use optimize::{batch_case, optimize_layout_case};
use vehicles::{roll_case, sweep_case, vehicle_case};

/// The groups and their relative weights (slow successes weigh less).
pub(crate) const GROUPS: &[(&str, u32)] = &[
    ("yaw simulate", 10),
    ("yaw measures", 3),
    ("yaw sensitivity", 1),
    ("yaw leakage", 1),
    ("hps harmonic", 8),
    ("hps characterize", 2),
    ("hps identify", 6),
    ("hps thermal", 3),
    ("tire sweep", 8),
    ("tire envelope", 4),
    ("terrain generate", 8),
    ("terrain psd", 6),
    ("measures weighting", 4),
    ("measures wbv", 6),
    ("measures decay", 6),
    ("measures step", 6),
    ("measures check", 1),
    ("params check", 3),
    ("params dump", 1),
    ("params list", 1),
    ("evaluate", 1),
    ("check", 1),
    ("synth", 2),
    ("discover", 3),
    ("roll simulate", 3),
    ("roll measures", 4),
    ("roll study", 1),
    ("roll calibrate", 1),
    ("params check truck", 2),
    ("vehicle ride", 3),
    ("vehicle roll", 2),
    ("vehicle yaw", 3),
    ("vehicle simulate", 4),
    ("vehicle path-change", 2),
    ("vehicle measures", 1),
    ("params check vehicle-3d", 2),
    ("params check vehicle", 3),
    ("params check vehicle (link)", 2),
    ("batch evaluate", 3),
    ("study speed-sweep", 2),
    ("optimize layout", 3),
];

pub(crate) fn make_case(
    seed: u64,
    id: usize,
    groups: &[(&'static str, u32)],
    yaw_params: &str,
    truck_params: &str,
) -> Case {
    let mut g = Gen {
        rng: Rng::new(seed, id),
        args: Vec::new(),
        files: Vec::new(),
        yaw_params,
        truck_params,
        scale: 1.0,
    };
    g.scale = *g.rng.pick(&[&0.0, &0.3, &1.0, &1.5]);
    let total: u32 = groups.iter().map(|g| g.1).sum();
    let mut k = (g.rng.next() % total as u64) as u32;
    let mut group = groups[0].0;
    for (name, w) in groups {
        if k < *w {
            group = name;
            break;
        }
        k -= w;
    }
    // the words of the subcommand; a parenthesised tag tells groups of one subcommand apart
    for w in group.split(" (").next().unwrap_or(group).split(' ') {
        g.arg(w);
    }
    match group.split(' ').next().unwrap_or(group) {
        _ if group == "params check truck" => roll_case(&mut g, group),
        _ if group == "params check vehicle-3d" => vehicle_case(&mut g, group),
        _ if group == "params check vehicle" => described::check_case(&mut g),
        _ if group == "params check vehicle (link)" => described::link_case(&mut g),
        "vehicle" => vehicle_case(&mut g, group),
        "roll" => roll_case(&mut g, group),
        "yaw" => yaw_case(&mut g, group),
        "hps" => hps_case(&mut g, group),
        "tire" => tire_case(&mut g, group),
        "terrain" => terrain_case(&mut g, group),
        "measures" => measures_case(&mut g, group),
        "batch" => batch_case(&mut g),
        "study" => sweep_case(&mut g),
        "optimize" => optimize_layout_case(&mut g),
        _ => other_case(&mut g, group),
    }
    Case {
        group,
        args: g.args,
        files: g.files,
    }
}

/// The options and files of one `afsv yaw ...` case.
fn yaw_case(g: &mut Gen<'_>, group: &str) {
    match group {
        "yaw simulate" => {
            let spec = match g.rng.below(10) {
                0..=2 => "csv:in.csv:steer_wheel_deg".to_string(),
                3 => format!("pulse:{}", g.bad()),
                4 => format!("step:{}", g.bad()),
                5 => format!("ramp:{}:{}", g.bad(), g.bad()),
                6 => g
                    .rng
                    .pick(&[
                        "turn",
                        "path-change",
                        "",
                        "csv:in.csv",
                        "csv:in.csv:bogus_deg",
                        "csv:missing.csv:a_deg",
                        "csv:in.csv:time_s",
                    ])
                    .to_string(),
                _ => "pulse".to_string(),
            };
            if spec.contains("in.csv") {
                g.csv("in.csv", YAW_COLS, false);
            }
            g.push_opt("--input", &spec);
            if g.rng.chance(0.3) {
                g.yaw_params_file("p.json");
                g.push_opt("--params", "p.json");
            }
            g.num("--speed-kmh", "50", 0.15);
            g.num("--input-time", "0.5", 0.1);
            if g.rng.chance(0.3 * g.scale) {
                let v = g.bad();
                g.push_opt("--duration", &v);
            } else {
                g.push_opt("--duration", "1");
            }
            g.num("--dt", "0.005", 0.2);
            g.num("--rtol", "1e-5", 0.1);
            if g.rng.chance(0.2) {
                let s = g
                    .rng
                    .pick(&["dopri", "rosenbrock", "rk4", "bogus"])
                    .to_string();
                g.push_opt("--solver", &s);
            }
            if g.rng.chance(0.15) {
                let c = g
                    .rng
                    .pick(&[
                        "articulation_deg",
                        "time_s,bogus",
                        "articulation_deg,articulation_deg",
                        "",
                        ",,",
                        "steer_wheel_deg,p_c_pa",
                    ])
                    .to_string();
                g.push_opt("--columns", &c);
            }
            let o = g.output("out.csv", &["in.csv", "in.json", "p.json", "p.csv"]);
            g.push_opt("-o", &o);
        }
        "yaw measures" => {
            if g.rng.chance(0.5) {
                g.yaw_params_file("p.json");
                g.push_opt("--params", "p.json");
            }
            g.num("--speed-kmh", "50", 0.5);
        }
        "yaw sensitivity" => {
            let v = g.bad();
            g.push_opt("--speed-kmh", &v);
        }
        "yaw leakage" => {
            let v = g.bad();
            g.push_opt("--steer-wheel-deg", &v);
        }
        _ => unreachable!("group {group}"),
    }
}

/// The options and files of one `afsv hps ...` case.
fn hps_case(g: &mut Gen<'_>, group: &str) {
    match group {
        "hps harmonic" => {
            g.num("--freq", "2", 0.2);
            g.num("--amp-mm", "7.5", 0.15);
            if g.rng.chance(0.2 * g.scale) {
                let v = g.bad();
                g.push_opt("--cycles", &v);
            } else {
                g.push_opt("--cycles", "2");
            }
            g.num("--gamma0", "0.03", 0.15);
            g.num("--rate", "360", 0.15);
            if g.rng.chance(0.3) {
                g.file("in.json", b"{\"notes\": \"user file\"}\n".to_vec());
            }
            if g.rng.chance(0.5) {
                let o = g.output("out.csv", &["in.json", "in.csv", "plot.svg"]);
                g.push_opt("-o", &o);
            }
            if g.rng.chance(0.3) {
                let o = g.output("plot.svg", &["out.csv", "out.json", "in.json"]);
                g.push_opt("--plot", &o);
            }
        }
        "hps characterize" => {
            let v = g.bad();
            g.push_opt("--gamma0", &v);
        }
        "hps identify" => {
            g.csv("in.csv", HPS_COLS, true);
            g.push_opt("-i", "in.csv");
            if g.rng.chance(0.3) {
                let f = g
                    .rng
                    .pick(&[
                        "n,gamma0,cb",
                        "",
                        "bogus",
                        "n,n",
                        "n,fc,fs,muv,gamma0,cb,cv,kl",
                        "kl",
                    ])
                    .to_string();
                g.push_opt("--fit", &f);
            }
            g.num("--warmup", "0", 0.3);
            if g.rng.chance(0.3) {
                let s = g
                    .rng
                    .pick(&["front-axle", "lab-1orifice", "lab-2orifice", "bogus"])
                    .to_string();
                g.push_opt("--strut", &s);
            }
        }
        "hps thermal" => {
            // a success is cheap (a shift of hours on the slow thermal model)
            g.num("--ambient-c", "35", 0.2);
            g.num("--power-w", "500", 0.2);
            g.num("--hours", "8", 0.2);
            g.num("--step-min", "30", 0.2);
            g.num("--deadband-mm", "5", 0.15);
            g.num("--levelling-flow-l-min", "6", 0.15);
            if g.rng.chance(0.3) {
                let v = g.rng.pick(&["bogus", "", "chapter2-truck"]).to_string();
                g.push_opt("--vehicle", &v);
            }
            if g.rng.chance(0.4) {
                let o = g.output("shift.csv", &["in.json"]);
                g.push_opt("-o", &o);
            }
        }
        _ => unreachable!("group {group}"),
    }
}

/// The options and files of one `afsv tire ...` case.
fn tire_case(g: &mut Gen<'_>, group: &str) {
    match group {
        "tire sweep" => {
            let fz = match g.rng.below(6) {
                0 | 1 => g.bad(),
                2 => g
                    .rng
                    .pick(&[
                        "-10:10:5",
                        "1e5:1:1",
                        "1:1e9:1",
                        "1e5:2e5:0",
                        "1e5:2e5:nan",
                        "1:2",
                        "1e5:2e5:5e4",
                    ])
                    .to_string(),
                _ => "1e5".to_string(),
            };
            g.push_opt("--fz", &fz);
            if g.rng.chance(0.4) {
                let a = match g.rng.below(3) {
                    0 => g.bad(),
                    1 => g
                        .rng
                        .pick(&[
                            "-20:20:0.5",
                            "20:-20:1",
                            "0:1:0",
                            "-1e308:1e308:1e-308",
                            "0:1e-9:1e-12",
                        ])
                        .to_string(),
                    _ => "5".to_string(),
                };
                g.push_opt("--alpha-deg", &a);
            }
            if g.rng.chance(0.3) {
                let k = match g.rng.below(2) {
                    0 => g.bad(),
                    _ => g.rng.pick(&["-1:1:0.1", "-1e9:1e9:1", "0.1"]).to_string(),
                };
                g.push_opt("--kappa", &k);
            }
            if g.rng.chance(0.3) {
                let t = bad_tire_json(&mut g.rng);
                g.file("t.json", t.into_bytes());
                g.push_opt("--params", "t.json");
            }
            for (name, good) in [
                ("--c-slip", "5e5"),
                ("--c-alpha-per-rad", "3e5"),
                ("--u-max", "0.8"),
                ("--u-min", "0.6"),
                ("--width-m", "0.75"),
            ] {
                g.num(name, good, 0.06);
            }
            if g.rng.chance(0.3) {
                let o = g.output("plot.svg", &["t.json"]);
                g.push_opt("--plot", &o);
            }
        }
        "tire envelope" => {
            g.csv("prof.csv", PROFILE_COLS, false);
            g.push_opt("--profile", "prof.csv");
            g.num("--radius", "1", 0.25);
            g.num("--deflection-m", "0.1", 0.25);
            g.num("--spacing-m", "0.01", 0.25);
            if g.rng.chance(0.3) {
                let m = g.rng.pick(&["cams", "circle"]).to_string();
                g.push_opt("--method", &m);
            }
            if g.rng.chance(0.3) {
                g.push_opt("--track", "right");
            }
        }
        _ => unreachable!("group {group}"),
    }
}

/// The options and files of one `afsv terrain ...` case.
fn terrain_case(g: &mut Gen<'_>, group: &str) {
    match group {
        "terrain generate" => {
            match g.rng.below(5) {
                0 => {
                    let c = g.rng.pick(&["A", "H", "Z", "", "e"]).to_string();
                    g.push_opt("--class", &c);
                }
                1 => {
                    let t = g.rng.pick(&["forestry", "mvee", "moon", ""]).to_string();
                    g.push_opt("--terrain", &t);
                }
                2 => {
                    g.num("--alpha", "4e-5", 0.5);
                    g.num("--waviness", "2", 0.5);
                }
                _ => {}
            }
            if g.rng.chance(0.3) {
                let b = g
                    .rng
                    .pick(&[
                        "0.02,5",
                        "5,0.02",
                        "nan,5",
                        "1e-320,5",
                        "0,1",
                        "0.1",
                        "",
                        "0.02,1e308",
                    ])
                    .to_string();
                g.push_opt("--band", &b);
            }
            if g.rng.chance(0.3) {
                let c = match g.rng.below(3) {
                    0 => format!("piecewise:{}", g.bad()),
                    1 => format!("bogsjo:{}", g.bad()),
                    _ => g
                        .rng
                        .pick(&["zhang", "full", "none", "", "isotropic"])
                        .to_string(),
                };
                g.push_opt("--coherence", &c);
            }
            let coherence = g.args.join(" ");
            if coherence.contains("bogsjo") || g.rng.chance(0.03) {
                if g.rng.chance(0.3 * g.scale) {
                    let v = g.bad();
                    g.push_opt("--half-track", &v);
                } else {
                    g.push_opt("--half-track", "1.14");
                }
            }
            if coherence.contains("zhang") || g.rng.chance(0.03) {
                if g.rng.chance(0.3 * g.scale) {
                    let v = g.bad();
                    g.push_opt("--speed", &v);
                } else {
                    g.push_opt("--speed", "13.9");
                }
            }
            if g.rng.chance(0.3 * g.scale) {
                let v = g.bad();
                g.push_opt("--length", &v);
            } else {
                g.push_opt("--length", "20");
            }
            g.num("--dx", "0.05", 0.2);
            if g.rng.chance(0.1) {
                let s = g
                    .rng
                    .pick(&["-1", "18446744073709551616", "abc", "0"])
                    .to_string();
                g.push_opt("--seed", &s);
            }
            if g.rng.chance(0.5) {
                if g.rng.chance(0.3) {
                    g.file("in.csv", b"x_m,left_m\n0,0\n".to_vec());
                }
                let o = g.output("out.csv", &["in.csv", "out.json"]);
                g.push_opt("-o", &o);
            }
        }
        "terrain psd" => {
            g.csv("prof.csv", PROFILE_COLS, false);
            g.push_opt("-i", "prof.csv");
            g.num("--segment-m", "1", 0.2);
            g.num("--overlap", "0.5", 0.2);
            if g.rng.chance(0.1) {
                let w = g
                    .rng
                    .pick(&["hann", "rectangular", "kaiser", ""])
                    .to_string();
                g.push_opt("--window", &w);
            }
            if g.rng.chance(0.1) {
                let d = g.rng.pick(&["none", "mean", "linear", "cubic"]).to_string();
                g.push_opt("--detrend", &d);
            }
            g.num("--track-width", "2.28", 0.2);
            if g.rng.chance(0.2) {
                let b = g
                    .rng
                    .pick(&["0.02,5", "5,0.02", "nan,5", "0,1e308"])
                    .to_string();
                g.push_opt("--band", &b);
            }
        }
        _ => unreachable!("group {group}"),
    }
}

/// The options and files of one `afsv measures ...` case.
fn measures_case(g: &mut Gen<'_>, group: &str) {
    match group {
        "measures weighting" => {
            let w = g
                .rng
                .pick(&["wk", "wd", "wc", "we", "wj", "wf", "bogus", ""])
                .to_string();
            g.push_opt("-w", &w);
            let f = match g.rng.below(3) {
                0 => g.bad(),
                1 => format!("0.5,{},2", g.bad()),
                _ => "0.1,1,10,100,1000".to_string(),
            };
            g.push_opt("--freqs", &f);
            g.num("--fs", "1000", 0.4);
        }
        "measures wbv" => {
            g.csv("acc.csv", WBV_COLS, false);
            g.push_opt("-i", "acc.csv");
            g.num("--hours", "8", 0.2);
            if g.rng.chance(0.2) {
                let w = g
                    .rng
                    .pick(&["z=wk", "x=wd", "q=wk", "z=bogus", "", "zwk"])
                    .to_string();
                g.push_opt("--weighting", &w);
            }
            if g.rng.chance(0.2) {
                let k = match g.rng.below(2) {
                    0 => format!("1,{},1", g.bad()),
                    _ => g.rng.pick(&["1,1", "1,1,1,1", "", "1.4,1.4,1"]).to_string(),
                };
                g.push_opt("--k", &k);
            }
            if g.rng.chance(0.3) {
                let m = g.rng.pick(&["fft", "iir", "bogus"]).to_string();
                g.push_opt("--method", &m);
            }
            if g.rng.chance(0.2) {
                let c = g
                    .rng
                    .pick(&[
                        "y=ay_m_s2",
                        "z=az_g",
                        "q=ax_m_s2",
                        "y=",
                        "=ax_m_s2",
                        "zax",
                        "x=bogus_m_s2",
                    ])
                    .to_string();
                g.push_opt("--channel", &c);
            }
        }
        "measures decay" => {
            g.csv("in.csv", YAW_COLS, false);
            g.push_opt("-i", "in.csv");
            let c = g
                .rng
                .pick(&[
                    "articulation_deg",
                    "articulation_deg",
                    "time_s",
                    "bogus",
                    "",
                ])
                .to_string();
            g.push_opt("--column", &c);
            g.num("--start-s", "0.5", 0.3);
            g.num("--end-s", "1.5", 0.3);
        }
        "measures step" => {
            g.csv("in.csv", YAW_COLS, false);
            g.push_opt("-i", "in.csv");
            let i = g
                .rng
                .pick(&["steer_wheel_deg", "steer_wheel_deg", "bogus", "time_s"])
                .to_string();
            g.push_opt("--input", &i);
            let o = g
                .rng
                .pick(&["articulation_deg", "articulation_deg", "bogus", "time_s"])
                .to_string();
            g.push_opt("--output", &o);
            g.num("--t-step", "0.1", 0.3);
            g.num("--amplitude", "30", 0.3);
            g.num("--settle-fraction", "0.1", 0.3);
        }
        "measures check" => {
            let v = g.bad();
            g.push_opt("--iir-fs", &v);
        }
        _ => unreachable!("group {group}"),
    }
}

/// The options and files of one `afsv params ...`, `evaluate`, `check`, `synth` and `discover` case.
fn other_case(g: &mut Gen<'_>, group: &str) {
    match group {
        "params check" => {
            let set = g
                .rng
                .pick(&["yaw-plane", "strut", "tire", "terrain", "surface"]);
            if set == "yaw-plane" {
                g.yaw_params_file("p.json");
            } else {
                let text = g.rng.pick(&[
                    "{}",
                    "{\"bogus\": 1}",
                    "{\"a_hc\": \"x\"}",
                    "{\"u_max\": -1e400}",
                    "[]",
                    "{\"friction\": {\"mu_v\": ",
                    "{\"psd\": {\"alpha_r\": 0, \"waviness\": 2}}",
                    "{\"track_width_m\": 1e308, \"friction\": -1}",
                ]);
                g.file("p.json", text.as_bytes().to_vec());
            }
            g.arg(set);
            g.arg("p.json");
        }
        "params list" => {
            let set = g
                .rng
                .pick(&["yaw-plane", "strut", "tire", "terrain", "surface", "bogus"]);
            g.arg(set);
        }
        "params dump" => {
            let set = g
                .rng
                .pick(&["yaw-plane", "strut", "tire", "terrain", "surface"]);
            g.arg(set);
            if g.rng.chance(0.5) {
                g.file("p.json", b"{\"mine\": true}\n".to_vec());
            }
            let o = g.output("new.json", &["p.json"]);
            g.push_opt("-o", &o);
        }
        "evaluate" => {
            let v = g.bad();
            g.push_opt("--speed-kmh", &v);
            // a well-formed speed runs the whole assessment: one terrain seed keeps it short
            if g.rng.chance(0.5) {
                g.push_opt("--seeds", "1");
            } else {
                let n = g.bad();
                g.push_opt("--seeds", &n);
            }
        }
        "check" => {
            let v = g.bad();
            g.push_opt("--seed", &v);
        }
        "synth" => {
            let m = g.rng.pick(&["hps-strut", "yaw-plane", "bogus"]).to_string();
            g.push_opt("--model", &m);
            let e = match g.rng.below(3) {
                0 => format!("bogus={}", g.bad()),
                1 => g.rng.pick(&["none", "", "none,none"]).to_string(),
                _ => "none".to_string(),
            };
            g.push_opt("--effects", &e);
            if g.rng.chance(0.3) {
                let n = g.rng.pick(&["default", "none", "bogus"]).to_string();
                g.push_opt("--noise", &n);
            }
            if g.rng.chance(0.2) {
                let s = g
                    .rng
                    .pick(&["-1", "18446744073709551616", "abc"])
                    .to_string();
                g.push_opt("--seed", &s);
            }
            if g.rng.chance(0.4) {
                g.yaw_params_file("p.json");
                g.push_opt("--params", "p.json");
            }
            let o = g.output("out", &["p.json"]);
            g.push_opt("-o", &o);
        }
        "discover" => {
            let (m, cols) = if g.rng.chance(0.5) {
                ("hps-strut", HPS_COLS)
            } else {
                ("yaw-plane", YAW_COLS)
            };
            g.push_opt("--model", m);
            g.csv("train.csv", cols, true);
            g.push_opt("--train", "train.csv");
            if g.rng.chance(0.3) {
                g.csv("hold.csv", cols, true);
                g.push_opt("--holdout", "hold.csv");
            }
            if g.rng.chance(0.3) {
                g.yaw_params_file("p.json");
                g.push_opt("--params", "p.json");
            }
            if g.rng.chance(0.3) {
                let v = g.bad();
                g.push_opt("--max-effects", &v);
            }
            if g.rng.chance(0.2) {
                let e = g.rng.pick(&["bogus", "", "none"]).to_string();
                g.push_opt("--effects", &e);
            }
            if g.rng.chance(0.5) {
                let o = g.output("report", &["train.csv", "p.json"]);
                g.push_opt("-o", &o);
            }
        }
        _ => unreachable!("group {group}"),
    }
}
