//! `cargo xtask fuzz [--cases N] [--seed S] [--jobs J] [--timeout SECS] [--mem-mib MIB]
//! [--bin PATH] [--only GROUP,...] [--skip GROUP,...] [--keep]`: bad input across the CLI.
//!
//! Generates `N` (default 10,000) cases from the seed, each a command line of one `afsv`
//! subcommand that reads a file or a number plus the files it reads: bad CSVs (wrong
//! headers, NaN/inf cells, huge and tiny time steps, BOMs, ragged rows, 0 and 1 rows, ...),
//! bad sidecars, bad parameter JSONs and bad option values (nan, inf, -1, 0, 1e308,
//! 1e-320, 2^64, empty, ...), and output names that collide with inputs. Every case runs
//! the release binary in its own scratch folder (`target/fuzz/`) with a timeout (20 s; three
//! times that for the iterative fits of `SLOW_GROUPS`) and an
//! address-space limit (`ulimit -v` through `sh`), and is classified as
//!
//! - a clean rejection: exit 1 or 2 with one `afsv: error:` line on stderr;
//! - a success: exit 0, with no NaN/inf in stdout or the files written and no JSON `null`
//!   without a reason (`afsv::output::unexplained_nulls`);
//! - a failure: a panic, a hang (timeout), an abort (signal, allocation failure), a
//!   non-finite output, or an input file modified (inputs are hashed before and after).
//!
//! Prints the counts and per-group table, lists the failures with their command lines
//! (their folders are kept), and exits non-zero when there is any failure. The same seed
//! gives the same cases, whatever `--jobs`.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

struct Opts {
    cases: usize,
    seed: u64,
    jobs: usize,
    timeout: Duration,
    mem_mib: u64,
    bin: Option<PathBuf>,
    only: Vec<String>,
    skip: Vec<String>,
    keep: bool,
}

fn parse_opts(args: &[String]) -> Result<Opts, String> {
    let mut o = Opts {
        cases: 10_000,
        seed: 1,
        jobs: std::thread::available_parallelism().map_or(2, |n| n.get().min(4)),
        timeout: Duration::from_secs(20),
        mem_mib: 4096,
        bin: None,
        only: Vec::new(),
        skip: Vec::new(),
        keep: false,
    };
    let mut it = args.iter();
    while let Some(a) = it.next() {
        let mut val = || {
            it.next()
                .cloned()
                .ok_or_else(|| format!("fuzz: `{a}` needs a value"))
        };
        let num = |s: String| -> Result<u64, String> {
            s.parse::<u64>()
                .map_err(|_| format!("fuzz: `{a}`: `{s}` is not a whole number"))
        };
        match a.as_str() {
            "--cases" => o.cases = num(val()?)? as usize,
            "--seed" => o.seed = num(val()?)?,
            "--jobs" => o.jobs = (num(val()?)? as usize).max(1),
            "--timeout" => o.timeout = Duration::from_secs(num(val()?)?.max(1)),
            "--mem-mib" => o.mem_mib = num(val()?)?.max(64),
            "--bin" => o.bin = Some(PathBuf::from(val()?)),
            "--only" => o.only = val()?.split(',').map(str::to_string).collect(),
            "--skip" => o.skip = val()?.split(',').map(str::to_string).collect(),
            "--keep" => o.keep = true,
            other => return Err(format!("fuzz: unknown argument `{other}`")),
        }
    }
    Ok(o)
}

/// SplitMix64: small, seedable, the same everywhere.
struct Rng(u64);

impl Rng {
    fn new(seed: u64, case: usize) -> Self {
        let mut r = Rng(seed ^ (case as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15));
        r.next();
        r
    }
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
    fn chance(&mut self, p: f64) -> bool {
        ((self.next() >> 11) as f64 / (1u64 << 53) as f64) < p
    }
    fn pick<'a, T: ?Sized>(&mut self, v: &[&'a T]) -> &'a T {
        v[self.below(v.len())]
    }
}

/// Option values that must be refused or handled (never a panic, hang or NaN).
const BAD: &[&str] = &[
    "nan",
    "NaN",
    "inf",
    "-inf",
    "infinity",
    "-1",
    "0",
    "-0",
    "1e308",
    "-1e308",
    "1e-320",
    "18446744073709551616",
    "",
    "abc",
    "1e309",
    "9999999999",
    "1e7",
    "1e-9",
    " 3 ",
    "1,2",
    "0x10",
    "2^64",
];

/// One case: a command line (run in the case's folder) and the files it may read.
struct Case {
    group: &'static str,
    args: Vec<String>,
    files: Vec<(String, Vec<u8>)>,
}

/// Builds one case of a group.
struct Gen<'a> {
    rng: Rng,
    args: Vec<String>,
    files: Vec<(String, Vec<u8>)>,
    yaw_params: &'a str,
    /// Scales the probability of a bad option value: 0 leaves the damage to the files.
    scale: f64,
}

impl Gen<'_> {
    fn arg(&mut self, a: &str) {
        self.args.push(a.to_string());
    }
    fn bad(&mut self) -> String {
        self.rng.pick(BAD).to_string()
    }
    /// `--name` with a bad value (probability `p_bad`), its good value, or left out.
    fn num(&mut self, name: &str, good: &str, p_bad: f64) {
        if self.rng.chance(p_bad * self.scale) {
            let v = self.bad();
            self.push_opt(name, &v);
        } else if self.rng.chance(0.5) {
            self.push_opt(name, good);
        }
    }
    fn push_opt(&mut self, name: &str, v: &str) {
        // Half of the time `--name=value`, so values starting with '-' get through.
        if self.rng.chance(0.5) || v.starts_with('-') {
            self.args.push(format!("{name}={v}"));
        } else {
            self.args.push(name.to_string());
            self.args.push(v.to_string());
        }
    }
    fn file(&mut self, name: &str, bytes: Vec<u8>) {
        self.files.retain(|(n, _)| n != name);
        self.files.push((name.to_string(), bytes));
    }
    /// A CSV with `cols` (the first is the clock/abscissa), possibly broken, at `name`,
    /// and sometimes a sidecar beside it.
    fn csv(&mut self, name: &str, cols: &[&str], sidecar_strut: bool) {
        let bytes = bad_csv(&mut self.rng, cols);
        self.file(name, bytes);
        if self.rng.chance(0.4) {
            let side = Path::new(name).with_extension("json");
            let text = bad_sidecar(&mut self.rng, sidecar_strut);
            self.file(side.to_str().unwrap(), text.into_bytes());
        }
    }
    /// An output name: fresh, or colliding with an input/other output.
    fn output(&mut self, fresh: &str, others: &[&str]) -> String {
        let r = self.rng.below(10);
        if r < 6 || others.is_empty() {
            fresh.to_string()
        } else if r < 8 {
            self.rng.pick(others).to_string()
        } else if r < 9 {
            format!("./{}", self.rng.pick(others))
        } else {
            self.rng
                .pick(&["out.json", "", ".", "nodir/out.csv", "in.json", "p.json"])
                .to_string()
        }
    }
    fn yaw_params_file(&mut self, name: &str) {
        let text = mutate_json(&mut self.rng, self.yaw_params);
        self.file(name, text.into_bytes());
    }
}

/// Columns of the records the commands read.
const YAW_COLS: &[&str] = &[
    "time_s",
    "steer_wheel_deg",
    "articulation_deg",
    "speed_m_s",
    "yaw_rate_front_deg_s",
];
const HPS_COLS: &[&str] = &[
    "time_s",
    "displacement_m",
    "force_n",
    "p_piston_pa",
    "p_rod_pa",
    "velocity_m_s",
];
const WBV_COLS: &[&str] = &["time_s", "ax_m_s2", "ay_m_s2", "az_m_s2"];
const PROFILE_COLS: &[&str] = &["x_m", "left_m", "right_m"];

fn bad_csv(rng: &mut Rng, cols: &[&str]) -> Vec<u8> {
    let mut names: Vec<String> = cols.iter().map(|c| c.to_string()).collect();
    // Two in five files are well formed, so that the options and later stages are reached.
    if rng.chance(0.4) {
        let rows = *rng.pick(&[&40usize, &200, &400]);
        let step = *rng.pick(&[&0.005f64, &0.01, &0.05]);
        let mut text = names.join(",") + "\n";
        for i in 0..rows {
            let cells: Vec<String> = names
                .iter()
                .enumerate()
                .map(|(j, n)| {
                    let t = i as f64 * step;
                    let v = if j == 0 {
                        t
                    } else if n == "steer_wheel_deg" {
                        if t > 0.2 {
                            30.0
                        } else {
                            0.0
                        }
                    } else {
                        let a = if n.starts_with("p_") {
                            1e6
                        } else if n == "force_n" {
                            1e5
                        } else if n == "displacement_m" {
                            0.01
                        } else if n == "velocity_m_s" {
                            0.07
                        } else {
                            1.0
                        };
                        a * (-(0.5 * t)).exp() * (7.0 * t + j as f64).cos()
                    };
                    format!("{v}")
                })
                .collect();
            text += &cells.join(",");
            text.push('\n');
        }
        return text.into_bytes();
    }
    // Header damage.
    match rng.below(12) {
        0 => {
            let i = rng.below(names.len());
            names[i] = "bogus_x".into();
        }
        1 if names.len() > 1 => {
            let i = 1 + rng.below(names.len() - 1);
            names.remove(i);
        }
        2 => {
            let n = names[0].clone();
            names.push(n);
        }
        3 => names.push(String::new()),
        4 => {
            for i in 0..1000 {
                names.push(format!("extra{i}_x"));
            }
        }
        5 => names.insert(0, "time_s".into()),
        _ => {}
    }
    let rows = *rng.pick(&[&0usize, &1, &2, &3, &8, &40, &200, &400]);
    let step = *rng.pick(&[
        &0.005f64, &0.005, &0.005, &0.01, &1e-3, &1e-14, &1e10, &1e-320, &1e300, &0.0, &-0.01,
    ]);
    let mut lines = vec![names.join(",")];
    for i in 0..rows {
        let t = i as f64 * step;
        let mut cells: Vec<String> = Vec::with_capacity(names.len());
        for (j, n) in names.iter().enumerate() {
            let v = if j == 0 || n == "time_s" || n == "x_m" {
                t
            } else {
                let w = 1.0 + j as f64;
                let scale = match n.as_str() {
                    "p_piston_pa" | "p_rod_pa" => 1e6,
                    "force_n" => 1e5,
                    "displacement_m" => 0.01,
                    _ => 1.0,
                };
                scale * (w * i as f64 * 0.05).sin() * (-(i as f64) * 0.003).exp()
            };
            cells.push(format!("{v}"));
        }
        lines.push(cells.join(","));
    }
    // Cell and row damage.
    for _ in 0..rng.below(3) {
        if lines.len() < 2 {
            break;
        }
        let r = 1 + rng.below(lines.len() - 1);
        let mut cells: Vec<String> = lines[r].split(',').map(str::to_string).collect();
        let c = rng.below(cells.len());
        match rng.below(9) {
            0 => cells[c] = "NaN".into(),
            1 => cells[c] = "inf".into(),
            2 => cells[c] = "1e999".into(),
            3 => cells[c] = "abc".into(),
            4 => cells[c] = "1e308".into(),
            5 => {
                cells.pop();
            }
            6 => cells.push("1".into()),
            7 => cells[c] = String::new(),
            _ => cells[c] = "-1e-320".into(),
        }
        lines[r] = cells.join(",");
    }
    if lines.len() > 3 && rng.chance(0.1) {
        // Clock runs back.
        lines.swap(1, 2);
    }
    let sep = if rng.chance(0.15) { "\r\n" } else { "\n" };
    let mut text = lines.join(sep);
    if rng.chance(0.8) {
        text.push_str(sep);
    }
    match rng.below(20) {
        0 => text = format!("\u{feff}{text}"),
        1 => text = format!("# comment\n{text}"),
        2 => text = String::new(),
        3 => text = "\n\n\n".into(),
        4 => return vec![0xff, 0xfe, 0x00, 0x41, 0x80, 0x0a],
        5 => text = text.replace(',', ";"),
        6 => text = format!("\"{}\"", text.replace(',', "\",\"")),
        _ => {}
    }
    text.into_bytes()
}

fn bad_sidecar(rng: &mut Rng, strut: bool) -> String {
    let strut_val = if strut {
        *rng.pick(&[
            &"\"front-axle\"",
            &"\"lab-1orifice\"",
            &"\"lab-2orifice\"",
            &"\"bogus\"",
            &"3",
            &"null",
            &"[]",
        ])
    } else {
        "\"front-axle\""
    };
    match rng.below(12) {
        0 => "{".into(),
        1 => "[]".into(),
        2 => "null".into(),
        3 => String::new(),
        4 => "{\"sign_convention\": \"sae\"}".into(),
        5 => "{\"sign_convention\": 1}".into(),
        6 => format!("{}{}", "[".repeat(5000), "]".repeat(5000)),
        7 => "{\"sample_rate_hz\": \"nan\", \"terrain\": {\"psd\": 1}}".into(),
        8 => "{\"terrain\": {\"psd\": {\"alpha_r\": -1, \"waviness\": 2}, \"band\": {\"n_min\": 5, \"n_max\": 0.1}}}".into(),
        _ => format!(
            "{{\"sign_convention\": \"afsv-v1\", \"written_by\": \"afsv fuzz\", \"strut\": {strut_val}, \"sample_rate_hz\": 200}}"
        ),
    }
}

/// Replace one number of a JSON document by a bad value, or break the document.
fn mutate_json(rng: &mut Rng, text: &str) -> String {
    match rng.below(12) {
        0 => return String::new(),
        1 => return text[..text.len() / 2].to_string(),
        2 => return "{}".into(),
        3 => return "[1, 2]".into(),
        4 => return text.replacen(": ", ": NaN, \"x\": ", 1),
        5 => return text.replacen('{', "{\"unknown_field\": 1, ", 1),
        _ => {}
    }
    let Ok(mut v) = serde_json::from_str::<serde_json::Value>(text) else {
        return text.to_string();
    };
    let mut ptrs = Vec::new();
    numbers(&v, String::new(), &mut ptrs);
    if ptrs.is_empty() {
        return text.to_string();
    }
    for _ in 0..1 + rng.below(2) {
        let p = ptrs[rng.below(ptrs.len())].clone();
        let bad = match rng.below(8) {
            0 => serde_json::json!(-1.0),
            1 => serde_json::json!(0.0),
            2 => serde_json::json!(1e308),
            3 => serde_json::json!(1e-320),
            4 => serde_json::json!("x"),
            5 => serde_json::Value::Null,
            6 => serde_json::json!(-1e308),
            _ => serde_json::json!([]),
        };
        if let Some(slot) = v.pointer_mut(&p) {
            *slot = bad;
        }
    }
    serde_json::to_string_pretty(&v).unwrap_or_default()
}

fn numbers(v: &serde_json::Value, path: String, out: &mut Vec<String>) {
    match v {
        serde_json::Value::Number(_) => out.push(path),
        serde_json::Value::Object(m) => {
            for (k, c) in m {
                numbers(c, format!("{path}/{k}"), out);
            }
        }
        serde_json::Value::Array(a) => {
            for (i, c) in a.iter().enumerate() {
                numbers(c, format!("{path}/{i}"), out);
            }
        }
        _ => {}
    }
}

fn bad_tire_json(rng: &mut Rng) -> String {
    let fields = [
        "unloaded_radius_m",
        "width_m",
        "cornering_stiffness_n_per_rad",
        "longitudinal_stiffness_n",
        "u_max",
        "u_min",
        "rolling_resistance_coefficient",
        "bogus_field",
    ];
    let mut m = serde_json::Map::new();
    for _ in 0..rng.below(3) {
        let f = fields[rng.below(fields.len())];
        let v = match rng.below(6) {
            0 => serde_json::json!(-1.0),
            1 => serde_json::json!(0.0),
            2 => serde_json::json!(1e308),
            3 => serde_json::json!(1e-320),
            4 => serde_json::json!("x"),
            _ => serde_json::json!(0.5),
        };
        m.insert(f.into(), v);
    }
    if rng.chance(0.2) {
        m.insert(
            "cornering_stiffness_table".into(),
            serde_json::json!([[1e5, -1.0], [0.0, 1e308]]),
        );
    }
    let text = serde_json::Value::Object(m).to_string();
    mutate_json(rng, &text)
}

/// The groups and their relative weights (slow successes weigh less).
const GROUPS: &[(&str, u32)] = &[
    ("yaw simulate", 10),
    ("yaw measures", 3),
    ("yaw sensitivity", 1),
    ("yaw leakage", 1),
    ("hps harmonic", 8),
    ("hps characterize", 2),
    ("hps identify", 6),
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
];

fn make_case(seed: u64, id: usize, groups: &[(&'static str, u32)], yaw_params: &str) -> Case {
    let mut g = Gen {
        rng: Rng::new(seed, id),
        args: Vec::new(),
        files: Vec::new(),
        yaw_params,
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
    for w in group.split(' ') {
        g.arg(w);
    }
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
    Case {
        group,
        args: g.args,
        files: g.files,
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Outcome {
    Rejected,
    Success,
    Panic,
    Hang,
    Abort,
    NonFinite,
    Modified,
}

impl Outcome {
    fn failed(self) -> bool {
        !matches!(self, Outcome::Rejected | Outcome::Success)
    }
}

struct Result1 {
    id: usize,
    group: &'static str,
    outcome: Outcome,
    detail: String,
    args: Vec<String>,
    multi_line: bool,
    seconds: f64,
}

fn fnv(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325u64, |h, b| {
        (h ^ *b as u64).wrapping_mul(0x100_0000_01b3)
    })
}

/// `NaN`, `inf` or `infinity` as a word of `text` (not inside a longer word).
fn non_finite_token(text: &str) -> Option<String> {
    let lower = text.to_ascii_lowercase();
    for tok in ["nan", "inf"] {
        let mut from = 0;
        while let Some(i) = lower[from..].find(tok) {
            let s = from + i;
            let before = lower[..s].chars().next_back();
            let mut e = s + tok.len();
            if tok == "inf" && lower[e..].starts_with("inity") {
                e += 5;
            }
            let after = lower[e..].chars().next();
            let word = |c: Option<char>| c.is_some_and(|c| c.is_ascii_alphanumeric() || c == '_');
            if !word(before) && !word(after) {
                let lo = s.saturating_sub(30);
                return Some(text[lo..(e + 30).min(text.len())].to_string());
            }
            from = e;
        }
    }
    None
}

/// Groups whose successes are iterative fits (identification, discovery, sweeps of many
/// simulations): a well-formed but hard record may take several seconds, so they get
/// three times the timeout.
const SLOW_GROUPS: &[&str] = &[
    "hps identify",
    "discover",
    "synth",
    "yaw sensitivity",
    "evaluate",
];

fn timeout_of(group: &str, opts: &Opts) -> Duration {
    if SLOW_GROUPS.contains(&group) {
        opts.timeout * 3
    } else {
        opts.timeout
    }
}

fn run_case(bin: &Path, dir: &Path, case: &Case, opts: &Opts) -> (Outcome, String, bool) {
    let timeout = timeout_of(case.group, opts);
    let _ = std::fs::remove_dir_all(dir);
    std::fs::create_dir_all(dir).expect("scratch folder");
    let mut hashes = Vec::new();
    for (name, bytes) in &case.files {
        let p = dir.join(name);
        std::fs::write(&p, bytes).expect("write case file");
        hashes.push((name.clone(), fnv(bytes)));
    }
    let out_path = dir.join(".stdout");
    let err_path = dir.join(".stderr");
    let script = format!(
        "ulimit -v {} 2>/dev/null; exec \"$0\" \"$@\"",
        opts.mem_mib * 1024
    );
    let child = Command::new("sh")
        .arg("-c")
        .arg(script)
        .arg(bin)
        .args(&case.args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(std::fs::File::create(&out_path).expect("stdout file"))
        .stderr(std::fs::File::create(&err_path).expect("stderr file"))
        .spawn();
    let mut child = match child {
        Ok(c) => c,
        Err(e) => return (Outcome::Abort, format!("cannot start: {e}"), false),
    };
    let start = Instant::now();
    let mut nap = Duration::from_micros(500);
    let status = loop {
        match child.try_wait() {
            Ok(Some(s)) => break Some(s),
            Ok(None) if start.elapsed() > timeout => {
                let _ = child.kill();
                let _ = child.wait();
                break None;
            }
            Ok(None) => {
                std::thread::sleep(nap);
                nap = (nap * 2).min(Duration::from_millis(20));
            }
            Err(e) => return (Outcome::Abort, format!("wait: {e}"), false),
        }
    };
    let stdout = std::fs::read(&out_path).unwrap_or_default();
    let stderr =
        String::from_utf8_lossy(&std::fs::read(&err_path).unwrap_or_default()).into_owned();
    let first_err = stderr.lines().next().unwrap_or("").to_string();
    // Inputs must be as they were.
    for (name, h) in &hashes {
        match std::fs::read(dir.join(name)) {
            Ok(b) if fnv(&b) == *h => {}
            Ok(_) => {
                return (
                    Outcome::Modified,
                    format!("{name} was modified; {first_err}"),
                    false,
                )
            }
            Err(_) => {
                return (
                    Outcome::Modified,
                    format!("{name} was removed; {first_err}"),
                    false,
                )
            }
        }
    }
    let Some(status) = status else {
        return (Outcome::Hang, format!("no exit after {timeout:?}"), false);
    };
    if stderr.contains("panicked") || stderr.contains("internal error") {
        return (Outcome::Panic, first_err, false);
    }
    #[cfg(unix)]
    {
        use std::os::unix::process::ExitStatusExt;
        if let Some(sig) = status.signal() {
            return (Outcome::Abort, format!("signal {sig}; {first_err}"), false);
        }
    }
    match status.code() {
        Some(0) => {
            let text = String::from_utf8_lossy(&stdout);
            if let Some(t) = non_finite_token(&text) {
                return (Outcome::NonFinite, format!("stdout: ...{t}..."), false);
            }
            if let Ok(v) = serde_json::from_slice::<serde_json::Value>(&stdout) {
                let nulls = afsv::output::unexplained_nulls(&v);
                if !nulls.is_empty() {
                    return (
                        Outcome::NonFinite,
                        format!(
                            "null without reason at {}",
                            nulls[..nulls.len().min(3)].join(", ")
                        ),
                        false,
                    );
                }
            }
            // Files the command wrote (CSV, sidecars, reports) carry no NaN/inf either.
            if let Some(d) = written_non_finite(dir, &case.files) {
                return (Outcome::NonFinite, d, false);
            }
            (Outcome::Success, String::new(), false)
        }
        Some(1) | Some(2) if first_err.starts_with("afsv: error:") => {
            let multi = stderr.trim_end().lines().count() > 1;
            if multi {
                let all: String = stderr.chars().take(300).collect();
                (Outcome::Rejected, format!("{all:?}"), true)
            } else {
                (Outcome::Rejected, first_err, false)
            }
        }
        Some(c) => (Outcome::Abort, format!("exit {c}; {first_err}"), false),
        None => (Outcome::Abort, first_err, false),
    }
}

fn written_non_finite(dir: &Path, inputs: &[(String, Vec<u8>)]) -> Option<String> {
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).ok()?.flatten() {
            let p = e.path();
            if p.is_dir() {
                stack.push(p);
                continue;
            }
            let name = p.strip_prefix(dir).ok()?.to_string_lossy().into_owned();
            if name.starts_with(".std") || inputs.iter().any(|(n, _)| *n == name) {
                continue;
            }
            if !(name.ends_with(".csv") || name.ends_with(".json") || name.ends_with(".md")) {
                continue;
            }
            let text = std::fs::read_to_string(&p).unwrap_or_default();
            if let Some(t) = non_finite_token(&text) {
                return Some(format!("{name}: ...{t}..."));
            }
        }
    }
    None
}

fn quote(args: &[String]) -> String {
    args.iter()
        .map(|a| {
            if !a.is_empty()
                && a.chars()
                    .all(|c| c.is_ascii_alphanumeric() || "-_.,:=/+".contains(c))
            {
                a.clone()
            } else {
                format!("'{}'", a.replace('\'', "'\\''"))
            }
        })
        .collect::<Vec<_>>()
        .join(" ")
}

/// Run the fuzz suite (module documentation).
pub fn fuzz(args: &[String], root: &Path) -> Result<(), String> {
    let opts = parse_opts(args)?;
    let bin = match &opts.bin {
        Some(b) => b.clone(),
        None => {
            let status = Command::new(std::env::var("CARGO").unwrap_or_else(|_| "cargo".into()))
                .current_dir(root)
                .args(["build", "--quiet", "--release", "-p", "afsv"])
                .status()
                .map_err(|e| format!("cannot run cargo build: {e}"))?;
            if !status.success() {
                return Err(format!("cargo build -p afsv --release failed ({status})"));
            }
            root.join("target").join("release").join("afsv")
        }
    };
    let bin = std::fs::canonicalize(&bin).map_err(|e| format!("{}: {e}", bin.display()))?;
    let groups: Vec<(&'static str, u32)> = GROUPS
        .iter()
        .copied()
        .filter(|(g, _)| {
            let key = g.split(' ').next().unwrap_or(g);
            let hit = |list: &[String]| list.iter().any(|s| s == g || s == key);
            (opts.only.is_empty() || hit(&opts.only)) && !hit(&opts.skip)
        })
        .collect();
    if groups.is_empty() {
        return Err("fuzz: --only/--skip leave no group".into());
    }
    let yaw_params = Command::new(&bin)
        .args(["params", "dump", "yaw-plane"])
        .output()
        .map_err(|e| format!("cannot run {}: {e}", bin.display()))?;
    let yaw_params = String::from_utf8(yaw_params.stdout).map_err(|e| e.to_string())?;
    let scratch = root
        .join("target")
        .join("fuzz")
        .join(format!("seed-{}", opts.seed));
    let _ = std::fs::remove_dir_all(&scratch);
    std::fs::create_dir_all(&scratch).map_err(|e| format!("{}: {e}", scratch.display()))?;
    println!(
        "fuzz: {} cases, seed {}, {} jobs, timeout {:?} ({} x3), memory limit {} MiB, binary {}",
        opts.cases,
        opts.seed,
        opts.jobs,
        opts.timeout,
        SLOW_GROUPS.join(", "),
        opts.mem_mib,
        bin.display()
    );
    let t0 = Instant::now();
    let next = AtomicUsize::new(0);
    let done = AtomicUsize::new(0);
    let results = Mutex::new(Vec::with_capacity(opts.cases));
    std::thread::scope(|s| {
        for _ in 0..opts.jobs {
            s.spawn(|| loop {
                let id = next.fetch_add(1, Ordering::Relaxed);
                if id >= opts.cases {
                    break;
                }
                let case = make_case(opts.seed, id, &groups, &yaw_params);
                let dir = scratch.join(format!("case-{id:05}"));
                let started = Instant::now();
                let (outcome, detail, multi_line) = run_case(&bin, &dir, &case, &opts);
                let seconds = started.elapsed().as_secs_f64();
                if !outcome.failed() && !opts.keep {
                    let _ = std::fs::remove_dir_all(&dir);
                }
                results.lock().unwrap().push(Result1 {
                    id,
                    group: case.group,
                    outcome,
                    detail,
                    args: case.args,
                    multi_line,
                    seconds,
                });
                let n = done.fetch_add(1, Ordering::Relaxed) + 1;
                if n.checked_rem(1000) == Some(0) {
                    eprintln!(
                        "fuzz: {n}/{} cases, {:.0} s",
                        opts.cases,
                        t0.elapsed().as_secs_f64()
                    );
                }
            });
        }
    });
    let mut results = results.into_inner().unwrap();
    results.sort_by_key(|r| r.id);
    let elapsed = t0.elapsed();
    let count = |o: Outcome| results.iter().filter(|r| r.outcome == o).count();
    println!();
    println!("cases                 {}", results.len());
    println!("clean rejections      {}", count(Outcome::Rejected));
    println!("successes             {}", count(Outcome::Success));
    println!("panics                {}", count(Outcome::Panic));
    println!("hangs                 {}", count(Outcome::Hang));
    println!("aborts/crashes        {}", count(Outcome::Abort));
    println!("non-finite outputs    {}", count(Outcome::NonFinite));
    println!("input files modified  {}", count(Outcome::Modified));
    println!(
        "multi-line errors     {} (not a failure)",
        results.iter().filter(|r| r.multi_line).count()
    );
    for r in results.iter().filter(|r| r.multi_line).take(5) {
        println!(
            "    multi-line error, case {}: afsv {}\n        {}",
            r.id,
            quote(&r.args),
            r.detail
        );
    }
    if let Some(slow) = results
        .iter()
        .max_by(|a, b| a.seconds.total_cmp(&b.seconds))
    {
        println!(
            "slowest case          {:.1} s (case {}, {})",
            slow.seconds, slow.id, slow.group
        );
    }
    println!("time                  {:.1} s", elapsed.as_secs_f64());
    println!();
    let mut table: BTreeMap<&str, [usize; 3]> = BTreeMap::new();
    for r in &results {
        let row = table.entry(r.group).or_default();
        match r.outcome {
            Outcome::Rejected => row[0] += 1,
            Outcome::Success => row[1] += 1,
            _ => row[2] += 1,
        }
    }
    println!(
        "{:<20} {:>8} {:>8} {:>8}",
        "group", "rejected", "success", "FAILED"
    );
    for (g, [a, b, c]) in &table {
        println!("{g:<20} {a:>8} {b:>8} {c:>8}");
    }
    let failures: Vec<&Result1> = results.iter().filter(|r| r.outcome.failed()).collect();
    if failures.is_empty() {
        if !opts.keep {
            let _ = std::fs::remove_dir_all(&scratch);
        }
        return Ok(());
    }
    println!();
    for r in failures.iter().take(40) {
        println!(
            "{:?} case {} ({}): afsv {}\n    {}",
            r.outcome,
            r.id,
            scratch.join(format!("case-{:05}", r.id)).display(),
            quote(&r.args),
            r.detail
        );
    }
    if failures.len() > 40 {
        println!("... and {} more", failures.len() - 40);
    }
    Err(format!(
        "{} of {} cases failed",
        failures.len(),
        results.len()
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cases_are_reproducible_and_cover_every_group() {
        let p = "{\"a\": 1.5, \"b\": [2, 3]}";
        let a: Vec<String> = (0..300)
            .map(|i| make_case(7, i, GROUPS, p).args.join(" "))
            .collect();
        let b: Vec<String> = (0..300)
            .map(|i| make_case(7, i, GROUPS, p).args.join(" "))
            .collect();
        assert_eq!(a, b);
        let groups: std::collections::BTreeSet<&str> = (0..3000)
            .map(|i| make_case(1, i, GROUPS, p).group)
            .collect();
        assert_eq!(groups.len(), GROUPS.len());
    }

    #[test]
    fn finds_non_finite_words_only() {
        assert!(non_finite_token("x = NaN").is_some());
        assert!(non_finite_token("[1, inf]").is_some());
        assert!(non_finite_token("-infinity").is_some());
        assert!(non_finite_token("information, infer, nano, finance").is_none());
    }
}
