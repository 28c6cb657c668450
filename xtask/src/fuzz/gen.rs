//! The generator of bad inputs: a small deterministic RNG, bad option values, and bad CSVs,
//! sidecars and JSON files.

use std::path::Path;

/// SplitMix64: small, seedable, the same everywhere.
pub(crate) struct Rng(u64);

impl Rng {
    pub(crate) fn new(seed: u64, case: usize) -> Self {
        let mut r = Rng(seed ^ (case as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15));
        r.next();
        r
    }
    pub(crate) fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    pub(crate) fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
    pub(crate) fn chance(&mut self, p: f64) -> bool {
        ((self.next() >> 11) as f64 / (1u64 << 53) as f64) < p
    }
    pub(crate) fn pick<'a, T: ?Sized>(&mut self, v: &[&'a T]) -> &'a T {
        v[self.below(v.len())]
    }
}

/// Option values that must be refused or handled (never a panic, hang or NaN).
pub(crate) const BAD: &[&str] = &[
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
pub(crate) struct Case {
    pub(crate) group: &'static str,
    pub(crate) args: Vec<String>,
    pub(crate) files: Vec<(String, Vec<u8>)>,
}

/// Builds one case of a group.
pub(crate) struct Gen<'a> {
    pub(crate) rng: Rng,
    pub(crate) args: Vec<String>,
    pub(crate) files: Vec<(String, Vec<u8>)>,
    pub(crate) yaw_params: &'a str,
    /// `afsv params dump truck`, the template of the truck parameter files.
    pub(crate) truck_params: &'a str,
    /// Scales the probability of a bad option value: 0 leaves the damage to the files.
    pub(crate) scale: f64,
}

impl Gen<'_> {
    pub(crate) fn arg(&mut self, a: &str) {
        self.args.push(a.to_string());
    }
    pub(crate) fn bad(&mut self) -> String {
        self.rng.pick(BAD).to_string()
    }
    /// `--name` with a bad value (probability `p_bad`), its good value, or left out.
    pub(crate) fn num(&mut self, name: &str, good: &str, p_bad: f64) {
        if self.rng.chance(p_bad * self.scale) {
            let v = self.bad();
            self.push_opt(name, &v);
        } else if self.rng.chance(0.5) {
            self.push_opt(name, good);
        }
    }
    pub(crate) fn push_opt(&mut self, name: &str, v: &str) {
        // Half of the time `--name=value`, so values starting with '-' get through.
        if self.rng.chance(0.5) || v.starts_with('-') {
            self.args.push(format!("{name}={v}"));
        } else {
            self.args.push(name.to_string());
            self.args.push(v.to_string());
        }
    }
    pub(crate) fn file(&mut self, name: &str, bytes: Vec<u8>) {
        self.files.retain(|(n, _)| n != name);
        self.files.push((name.to_string(), bytes));
    }
    /// A CSV with `cols` (the first is the clock/abscissa), possibly broken, at `name`,
    /// and sometimes a sidecar beside it.
    pub(crate) fn csv(&mut self, name: &str, cols: &[&str], sidecar_strut: bool) {
        let bytes = bad_csv(&mut self.rng, cols);
        self.file(name, bytes);
        if self.rng.chance(0.4) {
            let side = Path::new(name).with_extension("json");
            let text = bad_sidecar(&mut self.rng, sidecar_strut);
            self.file(side.to_str().unwrap(), text.into_bytes());
        }
    }
    /// An output name: fresh, or colliding with an input/other output.
    pub(crate) fn output(&mut self, fresh: &str, others: &[&str]) -> String {
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
    pub(crate) fn yaw_params_file(&mut self, name: &str) {
        let text = mutate_json(&mut self.rng, self.yaw_params);
        self.file(name, text.into_bytes());
    }
    pub(crate) fn truck_params_file(&mut self, name: &str) {
        let text = mutate_json(&mut self.rng, self.truck_params);
        self.file(name, text.into_bytes());
    }
}

/// Columns of the records the commands read.
pub(crate) const YAW_COLS: &[&str] = &[
    "time_s",
    "steer_wheel_deg",
    "articulation_deg",
    "speed_m_s",
    "yaw_rate_front_deg_s",
];
pub(crate) const HPS_COLS: &[&str] = &[
    "time_s",
    "displacement_m",
    "force_n",
    "p_piston_pa",
    "p_rod_pa",
    "velocity_m_s",
];
pub(crate) const WBV_COLS: &[&str] = &["time_s", "ax_m_s2", "ay_m_s2", "az_m_s2"];
pub(crate) const PROFILE_COLS: &[&str] = &["x_m", "left_m", "right_m"];

pub(crate) fn bad_csv(rng: &mut Rng, cols: &[&str]) -> Vec<u8> {
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
            // An unknown column, or a known quantity in another unit (converted or refused).
            let i = rng.below(names.len());
            names[i] = rng
                .pick(&[
                    "bogus_x",
                    "az_g",
                    "az_ft_s2",
                    "force_kn",
                    "p_rod_bar",
                    "time_ms",
                ])
                .to_string();
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

pub(crate) fn bad_sidecar(rng: &mut Rng, strut: bool) -> String {
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
pub(crate) fn mutate_json(rng: &mut Rng, text: &str) -> String {
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

pub(crate) fn numbers(v: &serde_json::Value, path: String, out: &mut Vec<String>) {
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

pub(crate) fn bad_tire_json(rng: &mut Rng) -> String {
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
