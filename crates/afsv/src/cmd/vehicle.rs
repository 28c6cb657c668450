//! `afsv vehicle`: the integrated 3-D articulated vehicle of Chapter 6 (crate `vehicle-3d`):
//! the design runs of section 6.4 over terrain seeds with their measures as mean ± SD
//! (`ride` D1, `roll` D2, `yaw` D3), and one recorded run (`simulate`) in the record format
//! of docs/records.md. Parses, calls, prints.

use super::{args, CmdResult};
use afsv::output::{OutputGuard, OutputKind};
use afsv::progress::Progress;
use afsv_dynamics::SteerInput;
use afsv_records::Record;
use hps_emulsion::StrutParams;
use perf_measures::iso2631::{health_guidance_zone, HgczRelation};
use rayon::prelude::*;
use serde_json::{json, Value};
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use terrain_psd::{welch_psd, IsoClass, WelchConfig};
use vehicle_3d::model::TIRE_NAMES;
use vehicle_3d::scenarios::{
    self, RideMeasures, RideSpec, RollMeasures, RollSpec, Spread, TerrainSpec, YawMeasures,
    YawSpec, RUN_IN_M,
};
use vehicle_3d::{FrontAxle, Load, RunOptions, RunRecord, Vehicle, VehicleOptions, VehicleParams};
use vehicle_components::FlatTerrain;

/// Largest number of terrain seeds of one command.
pub const MAX_SEEDS: usize = 1000;

/// Highest speed the options accept (km/h): above the truck's top speed.
pub const MAX_SPEED_KMH: f64 = 80.0;

/// Longest simulated time of one run (s).
pub const MAX_DURATION_S: f64 = 600.0;

/// Largest steering-wheel angle of the options (deg), also where a `--steer ramp` without
/// a limit holds: the roll scenario's hold angle, far beyond the rear unit's rollover.
const MAX_STEER_DEG: f64 = 1000.0;

/// Range of steering-wheel ramp rates (deg/s): slower ramps do not reach rollover within
/// the longest run, faster ones are steps.
const RAMP_RATE_DEG_S: (f64, f64) = (0.01, 1000.0);

/// Why a rigid front axle has no strut travel.
const NO_STRUT: &str = "rigid front axle (--hps off): no strut";

/// Exposure duration of the ISO 2631-1 health guidance caution zone verdict (h).
const HGCZ_HOURS: f64 = 8.0;

/// A speed in km/h within (0, [`MAX_SPEED_KMH`]].
fn speed_kmh(s: &str) -> Result<f64, String> {
    let v = args::positive_f64(s)?;
    if v <= MAX_SPEED_KMH {
        Ok(v)
    } else {
        Err(format!("must be at most {MAX_SPEED_KMH} km/h"))
    }
}

/// A seed count within 1..=[`MAX_SEEDS`].
fn seed_count(s: &str) -> Result<usize, String> {
    let n: usize = s
        .trim()
        .parse()
        .map_err(|_| format!("`{}` is not a whole number", s.trim()))?;
    if (1..=MAX_SEEDS).contains(&n) {
        Ok(n)
    } else {
        Err(format!("must be 1 to {MAX_SEEDS}"))
    }
}

/// A steering-wheel ramp rate within [`RAMP_RATE_DEG_S`] (deg/s).
fn ramp_rate(s: &str) -> Result<f64, String> {
    let v = args::positive_f64(s)?;
    let (lo, hi) = RAMP_RATE_DEG_S;
    if (lo..=hi).contains(&v) {
        Ok(v)
    } else {
        Err(format!("must be {lo} to {hi} deg/s"))
    }
}

/// A steering-wheel angle within (0, [`MAX_STEER_DEG`]] (deg).
fn steer_peak(s: &str) -> Result<f64, String> {
    let v = args::positive_f64(s)?;
    if v <= MAX_STEER_DEG {
        Ok(v)
    } else {
        Err(format!("must be at most {MAX_STEER_DEG} deg"))
    }
}

/// A duration within (0, [`MAX_DURATION_S`]] s.
fn duration_s(s: &str) -> Result<f64, String> {
    let v = args::positive_f64(s)?;
    if v <= MAX_DURATION_S {
        Ok(v)
    } else {
        Err(format!("must be at most {MAX_DURATION_S} s"))
    }
}

/// The `--terrain` option: smooth ground or a two-track terrain, with an optional seed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TerrainArg {
    /// None: smooth (flat) ground.
    pub spec: Option<TerrainSpec>,
    /// A seed given as `seed:N`.
    pub seed: Option<u64>,
}

/// Parse `smooth`, `flat` or `class:E,mc:0.3[,seed:N]` (keys in any order; a missing class
/// is E, a missing m_c 0.3, the section 6.4 terrain).
fn terrain_arg(s: &str) -> Result<TerrainArg, String> {
    let s = s.trim();
    if s == "smooth" || s == "flat" {
        return Ok(TerrainArg {
            spec: None,
            seed: None,
        });
    }
    let mut spec = TerrainSpec::default();
    let (mut class, mut mc, mut seed) = (None, None, None);
    for part in s.split(',') {
        let (key, value) = part.split_once(':').ok_or_else(|| {
            format!("`{part}` is not KEY:VALUE (expected smooth, flat or class:E,mc:0.3[,seed:N])")
        })?;
        let (key, value) = (key.trim(), value.trim());
        let twice = |k: &str| format!("`{k}` is given twice");
        match key {
            "class" => {
                if class.is_some() {
                    return Err(twice(key));
                }
                class =
                    Some(value.parse::<IsoClass>().map_err(|_| {
                        format!("class `{value}`: expected an ISO 8608 class A to H")
                    })?);
            }
            "mc" => {
                if mc.is_some() {
                    return Err(twice(key));
                }
                mc = Some(args::positive_f64(value).map_err(|e| format!("mc `{value}`: {e}"))?);
            }
            "seed" => {
                if seed.is_some() {
                    return Err(twice(key));
                }
                seed = Some(
                    value
                        .parse::<u64>()
                        .map_err(|_| format!("seed `{value}`: expected a whole number"))?,
                );
            }
            _ => return Err(format!("unknown key `{key}` (known: class, mc, seed)")),
        }
    }
    if let Some(c) = class {
        spec.class = c;
    }
    if let Some(m) = mc {
        spec.m_c = m;
    }
    Ok(TerrainArg {
        spec: Some(spec),
        seed,
    })
}

/// The vehicle and where it runs, shared by every subcommand.
#[derive(clap::Args, Debug)]
pub struct CaseArgs {
    /// Load case (Table 6.1): `loaded` (with the payload) or `unloaded`.
    #[arg(long, default_value = "loaded")]
    pub load: Load,
    /// Target speed of the drive (km/h), in (0, 80]. Default: the scenario's (ride 20,
    /// roll and yaw 50, simulate 20).
    #[arg(long, allow_hyphen_values = true, value_parser = speed_kmh)]
    pub speed_kmh: Option<f64>,
    /// Ground: `smooth` (or `flat`), or the two-track terrain `class:C,mc:0.3[,seed:N]`
    /// (ISO 8608 class A-H, coherence cut-off m_c in cycles/m, Eqs 6.4-6.5). Default:
    /// `class:E,mc:0.3` for ride and roll, smooth for yaw and simulate.
    #[arg(long, allow_hyphen_values = true, value_parser = terrain_arg)]
    pub terrain: Option<TerrainArg>,
    /// Front axle: `off` (rigid, the prototype), `nominal` (the Table 6.3 HPS strut of the
    /// parameter set) or a strut parameter file (JSON, as written by `afsv params dump
    /// strut`) replacing the set's strut.
    #[arg(long, default_value = "off")]
    pub hps: String,
    /// Vehicle parameter file (JSON, as written by `afsv params dump vehicle-3d`), validated.
    #[arg(long)]
    pub params: Option<PathBuf>,
}

/// Seeds, output format and plot of the scenario subcommands.
#[derive(clap::Args, Debug)]
pub struct StudyArgs {
    /// Run the terrain seeds 1..=N (1 to 1000) and report mean ± SD (default 10 on a
    /// terrain).
    #[arg(long, value_parser = seed_count, conflicts_with = "seed")]
    pub seeds: Option<usize>,
    /// Run this one terrain seed.
    #[arg(long)]
    pub seed: Option<u64>,
    /// Print JSON even on a terminal (JSON is the default when stdout is not a terminal).
    #[arg(long)]
    pub json: bool,
    /// SVG plot of the run (the first seed's for roll and yaw, the seed-mean PSDs for ride).
    #[arg(long)]
    pub plot: Option<PathBuf>,
    /// Replace an existing plot afsv did not write.
    #[arg(long)]
    pub force: bool,
}

/// `afsv vehicle` subcommands.
#[derive(clap::Subcommand, Debug)]
pub enum Command {
    /// D1 ride: straight run over the terrain after a 20 m run-in; a_wz (W_k, ISO 2631-1)
    /// and its 8 h health guidance caution zone verdict, unweighted RMS, HPS travel, the
    /// dominant vertical and pitch frequencies, as mean ± SD over the seeds.
    Ride {
        #[command(flatten)]
        case: CaseArgs,
        #[command(flatten)]
        study: StudyArgs,
        /// Length of the measured window after the run-in (m), 10 to 5000; D1: 100.
        #[arg(long, default_value_t = 100.0, allow_hyphen_values = true, value_parser = args::positive_f64)]
        length_m: f64,
    },
    /// D2 roll: ramp steer to the rear unit's absolute rollover; SP-DRT (RMS |a_y| over the
    /// sustained period of |LTR| = 1), the sustained period, rollover time, peak a_y.
    Roll {
        #[command(flatten)]
        case: CaseArgs,
        #[command(flatten)]
        study: StudyArgs,
        /// Steering-wheel rate of the ramp from t = 1 s (deg/s), 0.01 to 1000; D2: 5.
        #[arg(long, default_value_t = 5.0, allow_hyphen_values = true, value_parser = ramp_rate)]
        ramp_deg_s: f64,
        /// Longest run if the rear unit does not roll over (s), at most 600.
        #[arg(long, default_value_t = 90.0, allow_hyphen_values = true, value_parser = duration_s)]
        duration: f64,
    },
    /// D3 yaw: a 0.2 s half-sine steering-wheel pulse at t = 1 s; omega_z and zeta of the
    /// single-DOF fit to the articulation's free decay, peak articulation.
    Yaw {
        #[command(flatten)]
        case: CaseArgs,
        #[command(flatten)]
        study: StudyArgs,
        /// Peak of the steering-wheel pulse (deg), at most 1000; D3 assumption: 30.
        #[arg(long, default_value_t = 30.0, allow_hyphen_values = true, value_parser = steer_peak)]
        pulse_deg: f64,
    },
    /// One run into a record (CSV + JSON sidecar, docs/records.md, sign convention
    /// afsv-v1): the steering channels of a vehicle steering test plus the ride channels.
    Simulate {
        #[command(flatten)]
        case: CaseArgs,
        /// Terrain seed (with a terrain; default 1).
        #[arg(long)]
        seed: Option<u64>,
        /// Steering-wheel input: `pulse:DEG,DUR_S,START_S` (half sine),
        /// `ramp:DEG_PER_S,START_S[,LIMIT_DEG]` (held at LIMIT_DEG, default 1000) or `none`.
        #[arg(long, default_value = "none")]
        steer: String,
        /// Simulated time (s), at most 600.
        #[arg(long, default_value_t = 10.0, allow_hyphen_values = true, value_parser = duration_s)]
        duration: f64,
        /// Output sample interval (s).
        #[arg(long, default_value_t = 0.005, allow_hyphen_values = true, value_parser = args::positive_f64)]
        dt: f64,
        /// Output CSV file (the sidecar goes beside it with extension .json). It must not
        /// be an input; an existing file afsv did not write needs --force.
        #[arg(short = 'o', long)]
        output: PathBuf,
        /// Replace an existing output file that afsv did not write.
        #[arg(long)]
        force: bool,
    },
}

/// Run an `afsv vehicle` subcommand.
pub fn run(cmd: Command) -> CmdResult {
    match cmd {
        Command::Ride {
            case,
            study,
            length_m,
        } => ride_cmd(&case, &study, length_m),
        Command::Roll {
            case,
            study,
            ramp_deg_s,
            duration,
        } => roll_cmd(&case, &study, ramp_deg_s, duration),
        Command::Yaw {
            case,
            study,
            pulse_deg,
        } => yaw_cmd(&case, &study, pulse_deg),
        Command::Simulate {
            case,
            seed,
            steer,
            duration,
            dt,
            output,
            force,
        } => simulate_cmd(&case, seed, &steer, duration, dt, &output, force),
    }
}

/// The front axle and the strut file of `--hps`, if it names one.
fn front_axle(hps: &str) -> (FrontAxle, Option<&Path>) {
    match hps {
        "off" => (FrontAxle::Rigid, None),
        "nominal" => (FrontAxle::Suspended, None),
        file => (FrontAxle::Suspended, Some(Path::new(file))),
    }
}

/// Declare the input files of `case` to `guard`.
fn declare_inputs(case: &CaseArgs, guard: &mut OutputGuard) -> Result<(), String> {
    if let Some(p) = &case.params {
        guard.input("--params", p)?;
    }
    if let (_, Some(file)) = front_axle(&case.hps) {
        guard.input("--hps", file)?;
    }
    Ok(())
}

/// The vehicle of `--params` (or nominal) with the strut of `--hps`, validated; and its
/// front axle.
fn vehicle_params(case: &CaseArgs) -> Result<(VehicleParams, FrontAxle), String> {
    let mut p: VehicleParams = match &case.params {
        Some(path) => super::params::read(path)?,
        None => VehicleParams::nominal(),
    };
    p.validate().map_err(|e| match &case.params {
        Some(path) => format!("{}: {e}", path.display()),
        None => e.to_string(),
    })?;
    let (axle, file) = front_axle(&case.hps);
    if let Some(file) = file {
        let strut: StrutParams = super::params::read(file)
            .map_err(|e| format!("--hps: {e} (expected off, nominal or a strut file)"))?;
        strut
            .validate()
            .map_err(|e| format!("--hps {}: {e}", file.display()))?;
        p.hps = strut;
    }
    Ok((p, axle))
}

/// The terrain of `case` (`default` when `--terrain` is not given) and the seeds to run:
/// none on smooth ground, else `--seed`, the terrain's `seed:N`, or 1..=`--seeds`
/// (default 10).
fn terrain_and_seeds(
    case: &CaseArgs,
    seeds: Option<usize>,
    seed: Option<u64>,
    default: Option<TerrainSpec>,
) -> Result<(Option<TerrainSpec>, Vec<u64>), String> {
    let t = case.terrain.unwrap_or(TerrainArg {
        spec: default,
        seed: None,
    });
    let Some(spec) = t.spec else {
        if seeds.is_some() || seed.is_some() {
            return Err(
                "--seed/--seeds: smooth ground has no terrain seeds (give --terrain class:...)"
                    .into(),
            );
        }
        return Ok((None, vec![0]));
    };
    let list = match (t.seed, seed, seeds) {
        (Some(_), Some(_), _) | (Some(_), _, Some(_)) => {
            return Err("--terrain seed:N and --seed/--seeds both give the seeds; give one".into())
        }
        (Some(s), None, None) | (None, Some(s), _) => vec![s],
        (None, None, n) => (1..=n.unwrap_or(10) as u64).collect(),
    };
    Ok((Some(spec), list))
}

fn terrain_json(spec: &Option<TerrainSpec>, seeds: &[u64]) -> Value {
    match spec {
        None => json!({ "kind": "smooth ground" }),
        Some(t) => json!({
            "kind": "two-track terrain (Eqs 6.4-6.5)",
            "class": t.class.to_string(),
            "m_c_cycles_per_m": t.m_c,
            "band_cycles_per_m": [t.band.0, t.band.1],
            "seeds": seeds,
        }),
    }
}

/// The per-seed measures; on smooth ground the seed is null with its reason; a null measure
/// gets `null_reason`.
fn per_seed<T: serde::Serialize>(
    terrain: &Option<TerrainSpec>,
    seeds: &[u64],
    measures: &[T],
    null_reason: &str,
) -> Value {
    let rows: Vec<Value> = seeds
        .iter()
        .zip(measures)
        .map(|(s, m)| {
            let m = afsv::output::explain_nulls(json!(m), null_reason);
            match terrain {
                Some(_) => json!({ "seed": s, "measures": m }),
                None => json!({ "seed": null, "seed_reason": "smooth ground", "measures": m }),
            }
        })
        .collect();
    Value::Array(rows)
}

fn axle_name(axle: FrontAxle) -> &'static str {
    match axle {
        FrontAxle::Rigid => "rigid (no HPS)",
        FrontAxle::Suspended => "front-axle HPS",
    }
}

/// Run `one` for every seed in parallel, with progress when there are several; the
/// results in seed order; an error names its seed on a terrain.
fn over_seeds<T: Send>(
    what: &str,
    terrain: &Option<TerrainSpec>,
    seeds: &[u64],
    one: impl Fn(usize, u64) -> Result<T, String> + Sync,
) -> Result<Vec<T>, String> {
    let progress = (seeds.len() > 1).then(|| Progress::new(what, "runs", Some(seeds.len())));
    let out = seeds
        .par_iter()
        .enumerate()
        .map(|(i, &s)| {
            let r = one(i, s).map_err(|e| match terrain {
                Some(_) => format!("seed {s}: {e}"),
                None => e,
            });
            if let Some(p) = &progress {
                p.step(&format!("seed {s}"));
            }
            r
        })
        .collect();
    if let Some(p) = &progress {
        p.finish();
    }
    out
}

/// Mean ± SD of `f` over `values`.
fn spread<T>(values: &[T], f: impl Fn(&T) -> f64) -> Result<Spread, String> {
    let v: Vec<f64> = values.iter().map(f).collect();
    Spread::of(&v).map_err(|e| e.to_string())
}

fn spread_text(label: &str, s: &Spread, unit: &str) -> String {
    if s.n > 1 {
        format!("{label:<32} {:>9.3} ± {:<7.3} {unit}\n", s.mean, s.sd)
    } else {
        format!("{label:<32} {:>9.3}           {unit}\n", s.mean)
    }
}

fn header_text(title: &str, load: Load, axle: FrontAxle, speed: f64, seeds: usize) -> String {
    let runs = if seeds > 1 {
        format!(", mean ± SD over {seeds} seeds")
    } else {
        String::new()
    };
    format!("{title}: {load}, {}, {speed} km/h{runs}\n", axle_name(axle))
}

fn print_result(json_out: bool, value: &Value, text: &str) -> CmdResult {
    if json_out || !std::io::stdout().is_terminal() {
        afsv::output::print_json(value)?;
    } else {
        print!("{text}");
    }
    Ok(())
}

/// Common start of the scenario commands: guard the inputs and the plot, read the vehicle.
fn prepare(case: &CaseArgs, study: &StudyArgs) -> Result<(VehicleParams, FrontAxle), String> {
    let mut guard = OutputGuard::new(study.force);
    declare_inputs(case, &mut guard)?;
    if let Some(plot) = &study.plot {
        guard.output("--plot", plot, OutputKind::Svg)?;
    }
    vehicle_params(case)
}

/// The seed-mean Welch PSDs of the cab's vertical acceleration and the front unit's pitch
/// acceleration over the ride window: frequencies and the two densities.
type RidePsd = (Vec<f64>, Vec<f64>, Vec<f64>);

/// The PSDs of one ride record from `t_start_s` on, with the Welch settings of
/// `vehicle_3d::scenarios::psd_peak` (segments of up to 8 s, at least two, Hann, 50 %).
fn ride_psd(rec: &RunRecord, t_start_s: f64) -> Result<RidePsd, String> {
    let i0 = rec.t_s.partition_point(|&t| t < t_start_s);
    let dt = rec.t_s[1] - rec.t_s[0];
    let az = &rec.cab_accel_m_s2[2][i0..];
    let pitch = &rec.front_angular_accel_rad_s2[1][i0..];
    let seg = ((8.0 / dt) as usize).min(az.len() / 2).max(32);
    let cfg = WelchConfig::new(seg);
    let v = welch_psd(az, dt, &cfg).map_err(|e| format!("vertical PSD: {e}"))?;
    let p = welch_psd(pitch, dt, &cfg).map_err(|e| format!("pitch PSD: {e}"))?;
    Ok((v.freq, v.psd, p.psd))
}

fn ride_cmd(case: &CaseArgs, study: &StudyArgs, length_m: f64) -> CmdResult {
    if !(10.0..=5000.0).contains(&length_m) {
        return Err(format!("--length-m {}: must be 10 to 5000 m", args::show(length_m)).into());
    }
    let (p, axle) = prepare(case, study)?;
    let (terrain, seeds) =
        terrain_and_seeds(case, study.seeds, study.seed, Some(TerrainSpec::default()))?;
    let Some(terrain) = terrain else {
        return Err("--terrain smooth: the ride run needs a terrain (class:...)".into());
    };
    let speed = case.speed_kmh.unwrap_or(20.0);
    let sim_s = (RUN_IN_M + length_m) / (speed / 3.6);
    if sim_s > MAX_DURATION_S {
        return Err(format!(
            "--length-m {}: the run-in and window take {} s at {speed} km/h, more than {MAX_DURATION_S} s",
            args::show(length_m),
            args::show(sim_s)
        )
        .into());
    }
    let spec = RideSpec {
        speed_kmh: speed,
        length_m,
        terrain,
        ..RideSpec::d1(case.load, axle)
    };
    let t_window = RUN_IN_M / (speed / 3.6);
    let want_psd = study.plot.is_some();
    let runs: Vec<(RideMeasures, Option<RidePsd>)> =
        over_seeds("afsv vehicle ride", &Some(terrain), &seeds, |_, s| {
            let (rec, m) = scenarios::ride(&p, &spec, s).map_err(|e| e.to_string())?;
            let psd = if want_psd {
                Some(ride_psd(&rec, t_window)?)
            } else {
                None
            };
            Ok((m, psd))
        })?;
    let measures: Vec<RideMeasures> = runs.iter().map(|r| r.0).collect();
    let a_wz = spread(&measures, |m| m.a_wz_m_s2)?;
    let a_z = spread(&measures, |m| m.a_z_rms_m_s2)?;
    let vertical = spread(&measures, |m| m.vertical_peak_hz)?;
    let pitch = spread(&measures, |m| m.pitch_peak_hz)?;
    let travel = match axle {
        FrontAxle::Rigid => None,
        FrontAxle::Suspended => Some(spread(&measures, |m| {
            m.strut_travel_p2p_m.unwrap_or(f64::NAN)
        })?),
    };
    let zone = health_guidance_zone(HGCZ_HOURS, HgczRelation::SqrtTime)?;
    let verdict = zone.classify(a_wz.mean);
    if let Some(path) = &study.plot {
        let psds: Vec<RidePsd> = runs.into_iter().filter_map(|r| r.1).collect();
        plot_ride(path, &psds, &spec, &seeds)?;
    }
    let mut v = json!({
        "scenario": "ride (D1, section 6.4)",
        "load": case.load,
        "front_axle": axle,
        "speed_kmh": speed,
        "run_in_m": RUN_IN_M,
        "length_m": length_m,
        "terrain": terrain_json(&Some(terrain), &seeds),
        "a_wz_m_s2": a_wz,
        "a_z_rms_m_s2": a_z,
        "strut_travel_p2p_m": travel,
        "vertical_peak_hz": vertical,
        "pitch_peak_hz": pitch,
        "hgcz": {
            "duration_h": HGCZ_HOURS,
            "relation": zone.relation,
            "lower_m_s2": zone.lower_m_s2,
            "upper_m_s2": zone.upper_m_s2,
            "a_wz_mean_zone": verdict,
        },
        "per_seed": per_seed(&Some(terrain), &seeds, &measures, NO_STRUT),
    });
    if travel.is_none() {
        v["strut_travel_p2p_m_reason"] = json!(NO_STRUT);
    }
    if let Some(plot) = &study.plot {
        v["plot"] = json!(plot);
    }
    let verdict_text = match verdict {
        perf_measures::iso2631::HgczZone::Below => "below the zone",
        perf_measures::iso2631::HgczZone::Within => "within the zone (caution)",
        perf_measures::iso2631::HgczZone::Above => "above the zone (health risk likely)",
    };
    let mut text = header_text("ride D1", case.load, axle, speed, seeds.len());
    text += &format!(
        "terrain class {}, m_c {} cycles/m, {length_m} m after a {RUN_IN_M} m run-in\n",
        terrain.class, terrain.m_c
    );
    text += &spread_text("a_wz (W_k weighted RMS)", &a_wz, "m/s²");
    text += &format!(
        "{:<32} {verdict_text} ({:.2}-{:.2} m/s² at {HGCZ_HOURS} h)\n",
        "ISO 2631-1 HGCZ verdict", zone.lower_m_s2, zone.upper_m_s2
    );
    text += &spread_text("vertical acceleration RMS", &a_z, "m/s²");
    match &travel {
        Some(t) => text += &spread_text("HPS travel peak-to-peak d_s", t, "m"),
        None => {
            text += &format!(
                "{:<32} n/a (rigid front axle)\n",
                "HPS travel peak-to-peak d_s"
            )
        }
    }
    text += &spread_text("dominant vertical frequency", &vertical, "Hz");
    text += &spread_text("dominant pitch frequency", &pitch, "Hz");
    print_result(study.json, &v, &text)
}

fn plot_ride(path: &Path, psds: &[RidePsd], spec: &RideSpec, seeds: &[u64]) -> CmdResult {
    let first = psds.first().ok_or("no PSD to plot")?;
    if psds.iter().any(|p| p.0.len() != first.0.len()) {
        return Err("the seeds' PSDs have different frequency grids".into());
    }
    let n = psds.len() as f64;
    let keep = first.0.iter().take_while(|&&f| f <= 15.0).count();
    let freq = &first.0[..keep];
    let mean = |k: usize| -> Vec<f64> {
        (0..keep)
            .map(|i| {
                psds.iter()
                    .map(|p| if k == 1 { p.1[i] } else { p.2[i] })
                    .sum::<f64>()
                    / n
            })
            .collect()
    };
    let (vert, pitch) = (mean(1), mean(2));
    let conditions = format!(
        "{}, {}, {} km/h, class {}, m_c {}, mean of {} seed(s) from {}",
        spec.load,
        axle_name(spec.front_axle),
        spec.speed_kmh,
        spec.terrain.class,
        spec.terrain.m_c,
        seeds.len(),
        seeds[0]
    );
    afsv_plot::panels(
        path,
        "front-unit acceleration PSDs (Welch), ride window",
        &conditions,
        2,
        &[
            afsv_plot::Panel {
                caption: "vertical acceleration at the cab point",
                x: afsv_plot::Axis::new("frequency", "Hz"),
                y: afsv_plot::Axis::new("PSD", "(m/s²)²/Hz"),
                series: vec![afsv_plot::Series {
                    label: "a_z",
                    x: freq,
                    y: &vert,
                }],
            },
            afsv_plot::Panel {
                caption: "pitch acceleration",
                x: afsv_plot::Axis::new("frequency", "Hz"),
                y: afsv_plot::Axis::new("PSD", "(rad/s²)²/Hz"),
                series: vec![afsv_plot::Series {
                    label: "pitch",
                    x: freq,
                    y: &pitch,
                }],
            },
        ],
    )?;
    afsv::output::mark_svg(path)?;
    Ok(())
}

fn roll_cmd(case: &CaseArgs, study: &StudyArgs, ramp_deg_s: f64, duration: f64) -> CmdResult {
    let (p, axle) = prepare(case, study)?;
    let (terrain, seeds) =
        terrain_and_seeds(case, study.seeds, study.seed, Some(TerrainSpec::default()))?;
    let speed = case.speed_kmh.unwrap_or(50.0);
    let spec = RollSpec {
        load: case.load,
        speed_kmh: speed,
        ramp_deg_s,
        t_end_s: duration,
        terrain,
        ..RollSpec::d2(axle)
    };
    let want_record = study.plot.is_some();
    let runs: Vec<(RollMeasures, Option<RunRecord>)> =
        over_seeds("afsv vehicle roll", &terrain, &seeds, |i, s| {
            let (rec, m) = scenarios::roll(&p, &spec, s).map_err(|e| e.to_string())?;
            Ok((m, (want_record && i == 0).then_some(rec)))
        })?;
    let measures: Vec<RollMeasures> = runs.iter().map(|r| r.0).collect();
    let sp_drt = spread(&measures, |m| m.sp_drt_m_s2)?;
    let period = spread(&measures, |m| m.sustained_s.1 - m.sustained_s.0)?;
    let peak = spread(&measures, |m| m.peak_ay_m_s2)?;
    let rolled: Vec<f64> = measures.iter().filter_map(|m| m.rollover_s).collect();
    let rollover = if rolled.is_empty() {
        None
    } else {
        Some(Spread::of(&rolled)?)
    };
    if let (Some(path), Some((m, Some(rec)))) = (&study.plot, runs.first()) {
        plot_roll(path, rec, m, &spec, seeds[0])?;
    }
    let mut v = json!({
        "scenario": "roll (D2, section 6.4)",
        "load": case.load,
        "front_axle": axle,
        "speed_kmh": speed,
        "ramp_deg_s": ramp_deg_s,
        "ramp_start_s": spec.ramp_start_s,
        "terrain": terrain_json(&terrain, &seeds),
        "sp_drt_m_s2": sp_drt,
        "sustained_period_s": period,
        "peak_ay_m_s2": peak,
        "rollover_s": rollover,
        "rolled_over": rolled.len(),
        "per_seed": per_seed(&terrain, &seeds, &measures, "no absolute rollover of the rear unit in this run"),
    });
    if rollover.is_none() {
        v["rollover_s_reason"] = json!("no run reached the rear unit's absolute rollover");
    }
    if let Some(plot) = &study.plot {
        v["plot"] = json!(plot);
    }
    let mut text = header_text("roll D2", case.load, axle, speed, seeds.len());
    text += &format!(
        "ramp steer {ramp_deg_s} deg/s from t = {} s\n",
        spec.ramp_start_s
    );
    text += &spread_text("SP-DRT of the rear unit", &sp_drt, "m/s²");
    text += &spread_text("sustained period ΔT", &period, "s");
    text += &spread_text("peak |a_y| of the rear unit", &peak, "m/s²");
    match &rollover {
        Some(r) => {
            text += &spread_text("absolute rollover at", r, "s");
            text += &format!(
                "{:<32} {:>9}\n",
                "runs that rolled over",
                format!("{}/{}", rolled.len(), seeds.len())
            );
        }
        None => {
            text += &format!(
                "{:<32} n/a (no rollover within {duration} s)\n",
                "absolute rollover at"
            )
        }
    }
    print_result(study.json, &v, &text)
}

fn plot_roll(
    path: &Path,
    rec: &RunRecord,
    m: &RollMeasures,
    spec: &RollSpec,
    seed: u64,
) -> CmdResult {
    let ltr: Vec<f64> = rec.rear_ltr.iter().map(|x| x.abs()).collect();
    let (a, b) = m.sustained_s;
    // afsv-plot draws lines only: the sustained period is outlined as a box.
    let box_x = [a, a, b, b, a];
    let box_y = [0.0, 1.05, 1.05, 0.0, 0.0];
    let ground = match spec.terrain {
        None => "smooth ground".to_string(),
        Some(t) => format!("class {}, m_c {}, seed {seed}", t.class, t.m_c),
    };
    let conditions = format!(
        "{}, {}, {} km/h, ramp {} deg/s, {ground}; SP-DRT {:.2} m/s²",
        spec.load,
        axle_name(spec.front_axle),
        spec.speed_kmh,
        spec.ramp_deg_s,
        m.sp_drt_m_s2
    );
    afsv_plot::figure(
        path,
        &afsv_plot::Figure {
            title: "rear-axle load transfer ratio, ramp steer (D2)",
            conditions: &conditions,
            x: afsv_plot::Axis::new("time", "s"),
            y: afsv_plot::Axis::new("|LTR|", "-"),
        },
        &[
            afsv_plot::Series {
                label: "|LTR| rear axle",
                x: &rec.t_s,
                y: &ltr,
            },
            afsv_plot::Series {
                label: "sustained period ΔT",
                x: &box_x,
                y: &box_y,
            },
        ],
    )?;
    afsv::output::mark_svg(path)?;
    Ok(())
}

fn yaw_cmd(case: &CaseArgs, study: &StudyArgs, pulse_deg: f64) -> CmdResult {
    let (p, axle) = prepare(case, study)?;
    let (terrain, seeds) = terrain_and_seeds(case, study.seeds, study.seed, None)?;
    let speed = case.speed_kmh.unwrap_or(50.0);
    let spec = YawSpec {
        load: case.load,
        speed_kmh: speed,
        pulse_deg,
        terrain,
        ..YawSpec::d3(axle)
    };
    let want_record = study.plot.is_some();
    let runs: Vec<(YawMeasures, Option<RunRecord>)> =
        over_seeds("afsv vehicle yaw", &terrain, &seeds, |i, s| {
            let (rec, m) = scenarios::yaw(&p, &spec, s).map_err(|e| e.to_string())?;
            Ok((m, (want_record && i == 0).then_some(rec)))
        })?;
    let measures: Vec<YawMeasures> = runs.iter().map(|r| r.0).collect();
    let omega = spread(&measures, |m| m.omega_z_hz)?;
    let damped = spread(&measures, |m| m.damped_frequency_hz)?;
    let zeta = spread(&measures, |m| m.damping_ratio)?;
    let peak = spread(&measures, |m| m.peak_articulation_deg)?;
    if let (Some(path), Some((_, Some(rec)))) = (&study.plot, runs.first()) {
        plot_yaw(path, rec, &spec, seeds[0])?;
    }
    let mut v = json!({
        "scenario": "yaw (D3, section 6.4)",
        "load": case.load,
        "front_axle": axle,
        "speed_kmh": speed,
        "pulse_deg": pulse_deg,
        "pulse_s": spec.pulse_s,
        "pulse_start_s": spec.pulse_start_s,
        "fit_window_s": spec.fit_window_s,
        "terrain": terrain_json(&terrain, &seeds),
        "omega_z_hz": omega,
        "damped_frequency_hz": damped,
        "damping_ratio": zeta,
        "peak_articulation_deg": peak,
        "per_seed": per_seed(&terrain, &seeds, &measures, "not computed"),
    });
    if let Some(plot) = &study.plot {
        v["plot"] = json!(plot);
    }
    let mut text = header_text("yaw D3", case.load, axle, speed, seeds.len());
    text += &format!(
        "steering-wheel pulse {pulse_deg} deg, {} s, at t = {} s\n",
        spec.pulse_s, spec.pulse_start_s
    );
    text += &spread_text("omega_z (natural frequency)", &omega, "Hz");
    text += &spread_text("damped frequency", &damped, "Hz");
    text += &spread_text("damping ratio zeta", &zeta, "-");
    text += &spread_text("peak articulation", &peak, "deg");
    print_result(study.json, &v, &text)
}

fn plot_yaw(path: &Path, rec: &RunRecord, spec: &YawSpec, seed: u64) -> CmdResult {
    let deg: Vec<f64> = rec
        .articulation_rad
        .iter()
        .map(|a| a.to_degrees())
        .collect();
    let t = &rec.t_s;
    // The window of vehicle_3d::scenarios::yaw_measures, and its fit drawn over it.
    let i0 =
        afsv_dynamics::yaw_plane::analysis::decay_onset(t, &deg, spec.pulse_start_s + spec.pulse_s)
            .ok_or("no free oscillation after the pulse")?;
    let i1 = t.partition_point(|&x| x < t[i0] + spec.fit_window_s);
    let fit = perf_measures::fit_free_decay(&t[i0..i1], &deg[i0..i1])?;
    let wd = 2.0 * std::f64::consts::PI * fit.damped_frequency_hz;
    let fitted: Vec<f64> = t[i0..i1]
        .iter()
        .map(|&x| {
            let tau = x - t[i0];
            fit.offset
                + fit.amplitude
                    * (-fit.decay_rate_1_s * tau).exp()
                    * (wd * tau + fit.phase_rad).cos()
        })
        .collect();
    let hi = deg.iter().fold(0.0f64, |m, v| m.max(v.abs())) * 1.05;
    let (a, b) = (t[i0], t[i1 - 1]);
    let edge_x = [a, a, f64::NAN, b, b];
    let edge_y = [-hi, hi, f64::NAN, hi, -hi];
    let ground = match spec.terrain {
        None => "smooth ground".to_string(),
        Some(g) => format!("class {}, m_c {}, seed {seed}", g.class, g.m_c),
    };
    let conditions = format!(
        "{}, {}, {} km/h, {} deg pulse, {ground}; omega_z {:.2} Hz, zeta {:.3}",
        spec.load,
        axle_name(spec.front_axle),
        spec.speed_kmh,
        spec.pulse_deg,
        fit.natural_frequency_hz,
        fit.damping_ratio
    );
    afsv_plot::figure(
        path,
        &afsv_plot::Figure {
            title: "articulation after a steering pulse (D3) and its single-DOF fit",
            conditions: &conditions,
            x: afsv_plot::Axis::new("time", "s"),
            y: afsv_plot::Axis::new("articulation", "deg"),
        },
        &[
            afsv_plot::Series {
                label: "articulation",
                x: t,
                y: &deg,
            },
            afsv_plot::Series {
                label: "single-DOF fit",
                x: &t[i0..i1],
                y: &fitted,
            },
            afsv_plot::Series {
                label: "fitted window",
                x: &edge_x,
                y: &edge_y,
            },
        ],
    )?;
    afsv::output::mark_svg(path)?;
    Ok(())
}

/// Parse a `--steer` number whose magnitude is at most `max`.
fn steer_number(what: &str, s: &str, max: f64) -> Result<f64, String> {
    let v = args::finite_f64(s).map_err(|e| format!("--steer {what} `{}`: {e}", s.trim()))?;
    if v.abs() <= max {
        Ok(v)
    } else {
        Err(format!(
            "--steer {what} `{}`: must be at most {max} in magnitude",
            s.trim()
        ))
    }
}

/// Parse `--steer`: `pulse:DEG,DUR_S,START_S`, `ramp:DEG_PER_S,START_S[,LIMIT_DEG]`, `none`.
fn steer_input(spec: &str) -> Result<SteerInput, String> {
    let spec = spec.trim();
    let usage = || {
        format!(
            "--steer `{spec}` not understood (expected pulse:DEG,DUR_S,START_S, ramp:DEG_PER_S,START_S[,LIMIT_DEG] or none)"
        )
    };
    if spec == "none" {
        return Ok(SteerInput::None);
    }
    let (kind, rest) = spec.split_once(':').ok_or_else(usage)?;
    let parts: Vec<&str> = rest.split(',').collect();
    let input = match (kind, parts.as_slice()) {
        ("pulse", [a, d, t0]) => SteerInput::pulse_deg(
            steer_number("pulse peak", a, MAX_STEER_DEG)?,
            steer_number("pulse duration", d, MAX_DURATION_S)?,
            steer_number("pulse start", t0, MAX_DURATION_S)?,
        ),
        ("ramp", [r, t0, rest @ ..]) if rest.len() <= 1 => {
            let rate = steer_number("ramp rate", r, RAMP_RATE_DEG_S.1)?;
            if rate.abs() < RAMP_RATE_DEG_S.0 {
                return Err(format!(
                    "--steer ramp rate `{r}`: must be at least {} deg/s in magnitude",
                    RAMP_RATE_DEG_S.0
                ));
            }
            SteerInput::Ramp {
                rate_rad_s: rate.to_radians(),
                start_s: steer_number("ramp start", t0, MAX_DURATION_S)?,
                limit_rad: match rest {
                    [l] => steer_number("ramp limit", l, MAX_STEER_DEG)?
                        .abs()
                        .to_radians(),
                    _ => MAX_STEER_DEG.to_radians(),
                },
            }
        }
        _ => return Err(usage()),
    };
    input.validate().map_err(|e| format!("--steer: {e}"))?;
    Ok(input)
}

fn steer_label(input: &SteerInput) -> &'static str {
    match input {
        SteerInput::None => "straight",
        SteerInput::Pulse { .. } => "pulse",
        SteerInput::Ramp { .. } => "ramp",
        SteerInput::Step { .. } => "step",
        SteerInput::Table { .. } => "table",
    }
}

fn simulate_cmd(
    case: &CaseArgs,
    seed: Option<u64>,
    steer: &str,
    duration: f64,
    dt: f64,
    output: &Path,
    force: bool,
) -> CmdResult {
    args::check_samples(
        &format!("--duration {}", args::show(duration)),
        &format!("duration/dt with --dt {}", args::show(dt)),
        duration / dt,
        vehicle_3d::simulate::MAX_SAMPLES as f64,
    )?;
    let input = steer_input(steer)?;
    let mut guard = OutputGuard::new(force);
    declare_inputs(case, &mut guard)?;
    guard.output("-o", output, OutputKind::Record)?;
    let (p, axle) = vehicle_params(case)?;
    let (terrain, seeds) = terrain_and_seeds(case, None, seed, None)?;
    let speed_kmh = case.speed_kmh.unwrap_or(20.0);
    let speed = speed_kmh / 3.6;
    let options = VehicleOptions {
        front_axle: axle,
        speed_m_s: speed,
        steer: input.clone(),
        path_length_m: speed * duration + 5.0,
        ..VehicleOptions::default()
    };
    let run = RunOptions {
        t_end_s: duration,
        output_dt_s: dt,
        ..RunOptions::default()
    };
    let half = 0.5 * p.front_track_m;
    let rec = match &terrain {
        None => {
            let flat = FlatTerrain::new(0.0, vehicle_components::DEFAULT_FRICTION)?;
            vehicle_3d::simulate(&Vehicle::new(&p, case.load, options, &flat, half)?, &run)?
        }
        Some(t) => {
            let length = options.start_s_m + options.path_length_m + 50.0;
            let ground = t.build(&p, length, seeds[0])?;
            vehicle_3d::simulate(&Vehicle::new(&p, case.load, options, &ground, half)?, &run)?
        }
    };
    let mut out = record(&rec)?;
    out.meta = json!({
        "written_by": "afsv vehicle simulate",
        "sample_rate_hz": 1.0 / dt,
        "model": "vehicle-3d integrated 3-D articulated dump truck (chapter 6)",
        "load": case.load,
        "front_axle": axle,
        "speed_kmh": speed_kmh,
        "speed_m_s": speed,
        "manoeuvre": steer_label(&input),
        "steer": input,
        "terrain": terrain_json(&terrain, &seeds),
        "axes": "cab_accel_*, front_pitch_accel: the front unit's body axes (x forward, y left, z up), kinematic acceleration without gravity at the a_wz point; front_pitch_accel right-handed about y (nose down positive); rear_lateral_accel left positive; rear_ltr = (F_zL - F_zR)/(F_zL + F_zR) of the rear axle; hps_travel compression positive",
        "params": p,
    });
    afsv::output::check_finite_record(&out)?;
    out.write(output)?;
    afsv::output::print_json(&json!({
        "output": output,
        "sidecar": output.with_extension("json"),
        "samples": rec.len(),
        "columns": out.names(),
        "peak_articulation_deg": rec.articulation_rad.iter().fold(0.0f64, |m, v| if v.abs() > m.abs() { *v } else { m }).to_degrees(),
    }))?;
    Ok(())
}

/// The run's channels in the afsv-v1 convention (docs/records.md): the steering channels of
/// a vehicle steering test, then the ride channels.
fn record(r: &RunRecord) -> Result<Record, afsv_records::RecordError> {
    let deg = |v: &[f64], sign: f64| v.iter().map(|x| sign * x.to_degrees()).collect();
    let mut out = Record::new();
    out.push_column("time_s", r.t_s.clone())?;
    out.push_column("steer_wheel_deg", deg(&r.steer_wheel_rad, 1.0))?;
    out.push_column("speed_m_s", r.speed_m_s.clone())?;
    out.push_column("articulation_deg", deg(&r.articulation_rad, 1.0))?;
    out.push_column("strut_left_disp_m", r.strut_disp_m[0].clone())?;
    out.push_column("strut_right_disp_m", r.strut_disp_m[1].clone())?;
    out.push_column("p_c_pa", r.pressure_pa[0].clone())?;
    out.push_column("p_r_pa", r.pressure_pa[1].clone())?;
    // The model's yaw rate is left-turn positive about +z; afsv-v1 is right-turn positive.
    out.push_column("yaw_rate_front_deg_s", deg(&r.front_rate_rad_s[2], -1.0))?;
    for (axis, values) in ["x", "y", "z"].iter().zip(&r.cab_accel_m_s2) {
        out.push_column(&format!("cab_accel_{axis}_m_s2"), values.clone())?;
    }
    out.push_column(
        "front_pitch_accel_rad_s2",
        r.front_angular_accel_rad_s2[1].clone(),
    )?;
    out.push_column(
        "front_lateral_accel_m_s2",
        r.front_lateral_accel_m_s2.clone(),
    )?;
    out.push_column("rear_lateral_accel_m_s2", r.rear_lateral_accel_m_s2.clone())?;
    out.push_column("rear_ltr", r.rear_ltr.clone())?;
    out.push_column("rear_roll_deg", deg(&r.rear_roll_rad, 1.0))?;
    out.push_column("hps_travel_left_m", r.hps_travel_m[0].clone())?;
    out.push_column("hps_travel_right_m", r.hps_travel_m[1].clone())?;
    for (name, values) in TIRE_NAMES.iter().zip(&r.normal_force_n) {
        out.push_column(&format!("normal_force_{name}_n"), values.clone())?;
    }
    out.push_column("drive_torque_n_m", r.drive_torque_n_m.clone())?;
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn terrain_option_parses_keys_in_any_order() {
        let t = terrain_arg("mc:0.2,class:c").unwrap();
        let s = t.spec.unwrap();
        assert_eq!((s.class, s.m_c, t.seed), (IsoClass::C, 0.2, None));
        let t = terrain_arg("class:H,seed:7").unwrap();
        assert_eq!((t.spec.unwrap().m_c, t.seed), (0.3, Some(7)));
        assert_eq!(terrain_arg("flat").unwrap().spec, None);
        for (bad, needle) in [
            ("class:Z", "class `Z`"),
            ("class:E,class:C", "twice"),
            ("mc:nan", "mc `nan`"),
            ("mc:-1", "mc `-1`"),
            ("slope:3", "unknown key `slope`"),
            ("E", "KEY:VALUE"),
            ("seed:-1", "seed `-1`"),
        ] {
            let e = terrain_arg(bad).unwrap_err();
            assert!(e.contains(needle), "{bad}: {e}");
        }
    }

    #[test]
    fn steer_option_parses_pulse_ramp_and_none() {
        assert_eq!(steer_input("none").unwrap(), SteerInput::None);
        assert_eq!(
            steer_input("pulse:30,0.2,1").unwrap(),
            SteerInput::pulse_deg(30.0, 0.2, 1.0)
        );
        match steer_input("ramp:5,1").unwrap() {
            SteerInput::Ramp {
                rate_rad_s,
                start_s,
                limit_rad,
            } => {
                assert!((rate_rad_s - 5f64.to_radians()).abs() < 1e-15);
                assert_eq!(start_s, 1.0);
                assert!((limit_rad - MAX_STEER_DEG.to_radians()).abs() < 1e-12);
            }
            other => panic!("{other:?}"),
        }
        for bad in [
            "pulse:30,0.2",
            "pulse:30,nan,1",
            "pulse:30,-0.2,1",
            "ramp:5",
            "sine:1",
            "step:3,1",
            "pulse:1001,0.2,1",
            "ramp:1e-320,1",
            "ramp:-2000,1",
            "ramp:5,1,1e6",
        ] {
            assert!(steer_input(bad).unwrap_err().contains("--steer"), "{bad}");
        }
    }

    #[test]
    fn bounded_options_refuse_out_of_range_values() {
        assert!(speed_kmh("80").is_ok());
        assert!(speed_kmh("80.01").is_err());
        assert!(speed_kmh("0").is_err());
        assert_eq!(seed_count("1000").unwrap(), 1000);
        assert!(seed_count("1001").is_err());
        assert!(seed_count("0").is_err());
        assert!(seed_count("1e3").is_err());
        assert!(duration_s("600").is_ok());
        assert!(duration_s("600.5").is_err());
        assert!(ramp_rate("0.01").is_ok() && ramp_rate("1000").is_ok());
        assert!(ramp_rate("0.009").is_err() && ramp_rate("1000.1").is_err());
        assert!(steer_peak("1000").is_ok() && steer_peak("1000.1").is_err());
        assert!(steer_input("ramp:-5,1").is_ok(), "a left-hand ramp");
    }
}
