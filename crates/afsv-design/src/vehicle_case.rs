//! The 3-D vehicle a command of `afsv vehicle` runs, and where: the described vehicle (the
//! prototype by default) or a raw parameter set, with the front axle the command chose
//! (`off`, `nominal`, a strut file), the struts' interconnection of the description, the
//! terrain and its seeds (`class:E,mc:0.3[,seed:N]`, [`parse_terrain`]), the
//! steering-wheel input (`pulse:...`, `ramp:...`, [`parse_steer`]), the cab and seat, and
//! one recorded run of it ([`simulate_run`]).

use crate::report::show;
use crate::report::vehicle::{ride_psd, yaw_inertia_form, RidePsd};
use crate::report::vehicle_record::SimulateRun;
use crate::value_lists::{finite_f64, positive_f64};
use afsv_dynamics::SteerInput;
use afsv_records::guard::OutputGuard;
use std::path::Path;
use terrain_psd::IsoClass;
use vehicle_3d::cab_ride::{seat_ride_measures, CabSeatLayout, SeatRideMeasures};
use vehicle_3d::component_record::simulate_components;
use vehicle_3d::interconnect::{Link, LinkedVehicle};
use vehicle_3d::scenarios::{RideMeasures, RideSpec, TerrainSpec, RUN_IN_M};
use vehicle_3d::{FrontAxle, RunOptions, RunRecord, Vehicle, VehicleOptions, VehicleParams};
use vehicle_components::recorder::Recorder;
use vehicle_components::FlatTerrain;

/// Longest simulated time of one run (s).
pub const MAX_DURATION_S: f64 = 600.0;

/// Largest steering-wheel angle of the options (deg), also where a `--steer ramp` without
/// a limit holds: the roll scenario's hold angle, far beyond the rear unit's rollover.
pub const MAX_STEER_DEG: f64 = 1000.0;

/// Range of steering-wheel ramp rates (deg/s): slower ramps do not reach rollover within
/// the longest run, faster ones are steps.
pub const RAMP_RATE_DEG_S: (f64, f64) = (0.01, 1000.0);

/// Where a command's vehicle comes from: `--params` (a raw 3-D parameter set), else
/// `--vehicle` (a description; the prototype when `None`); the front axle of `--hps`
/// (`off`, `nominal` or a strut file; default: as the description says) and the yaw
/// inertias of `--paper-form`.
#[derive(Debug, Clone, Copy)]
pub struct CaseSource<'a> {
    /// The raw parameter set file.
    pub params: Option<&'a Path>,
    /// The description file or built-in name.
    pub vehicle: Option<&'a Path>,
    /// The front axle: `off`, `nominal` or a strut file.
    pub hps: Option<&'a str>,
    /// The printed Eq 3.13 yaw inertias.
    pub paper_form: bool,
}

/// The ground of a run as a command names it: smooth (`spec` `None`) or a two-track
/// terrain, with the seed given with it (`seed:N`), if any.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TerrainChoice {
    /// None: smooth (flat) ground.
    pub spec: Option<TerrainSpec>,
    /// A seed given with the terrain.
    pub seed: Option<u64>,
}

/// Parse `smooth`, `flat` or `class:E,mc:0.3[,seed:N]` (keys in any order; a missing class
/// is E, a missing m_c 0.3, the section 6.4 terrain).
pub fn parse_terrain(s: &str) -> Result<TerrainChoice, String> {
    let s = s.trim();
    if s == "smooth" || s == "flat" {
        return Ok(TerrainChoice {
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
                mc = Some(positive_f64(value).map_err(|e| format!("mc `{value}`: {e}"))?);
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
    Ok(TerrainChoice {
        spec: Some(spec),
        seed,
    })
}

/// Parse a `--steer` number whose magnitude is at most `max`.
fn steer_number(what: &str, s: &str, max: f64) -> Result<f64, String> {
    let v = finite_f64(s).map_err(|e| format!("--steer {what} `{}`: {e}", s.trim()))?;
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
pub fn parse_steer(spec: &str) -> Result<SteerInput, String> {
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

/// The strut file `--hps` names, if it names one (not `off` or `nominal`).
pub fn hps_file(hps: Option<&str>) -> Option<&Path> {
    match hps {
        None | Some("off" | "nominal") => None,
        Some(file) => Some(Path::new(file)),
    }
}

/// Declare the input files of `case` to `guard`.
pub fn declare_inputs(case: &CaseSource, guard: &mut OutputGuard) -> Result<(), String> {
    guard.input_if("--params", case.params)?;
    crate::described::declare(guard, case.vehicle)?;
    guard.input_if("--hps", hps_file(case.hps))?;
    Ok(())
}

/// The vehicle of `case`, validated, and its front axle (default: as the description says;
/// rigid for a raw parameter set). A strut file replaces the set's strut before the set is
/// checked; a raw set is also checked against the registry's ranges.
pub fn vehicle_params(case: &CaseSource) -> Result<(VehicleParams, FrontAxle), String> {
    let (mut p, described, has_strut) = match case.params {
        Some(path) => (crate::param_files::read(path)?, FrontAxle::Rigid, true),
        None => {
            let v = crate::described::articulated(case.vehicle)?;
            let axle = match v.front_suspension {
                afsv_vehicle::schema::Suspension::Hps => FrontAxle::Suspended,
                afsv_vehicle::schema::Suspension::Rigid => FrontAxle::Rigid,
            };
            (v.params, axle, v.front_strut.is_some())
        }
    };
    let axle = match case.hps {
        None => described,
        Some("off") => FrontAxle::Rigid,
        Some("nominal") if !has_strut => {
            return Err("--hps nominal: the vehicle description gives the front axle no strut (add `strut` to its [[axle]], or give --hps FILE)".into())
        }
        Some("nominal") => FrontAxle::Suspended,
        Some(file) => {
            p.hps = crate::param_files::read_hps_strut(Path::new(file), "off, nominal or a strut file")?;
            FrontAxle::Suspended
        }
    };
    p.yaw_inertia_form = yaw_inertia_form(case.paper_form);
    p.validate().map_err(|e| match case.params {
        Some(path) => format!("{}: {e}", path.display()),
        None => e.to_string(),
    })?;
    if let Some(path) = case.params {
        crate::report::params::vehicle_3d_in_ranges(&p)
            .map_err(|e| format!("{}: {e}", path.display()))?;
    }
    Ok((p, axle))
}

/// The struts' interconnection of the description (`[link]`, docs/vehicles.md) the runs
/// use: `None` without one, and for a raw parameter set; refused with the front axle made
/// rigid (`--hps off`), which leaves the link no front struts.
pub fn described_link(case: &CaseSource, axle: FrontAxle) -> Result<Option<Link>, String> {
    if case.params.is_some() {
        return Ok(None);
    }
    let Some(link) = crate::described::articulated(case.vehicle)?.link else {
        return Ok(None);
    };
    if axle == FrontAxle::Rigid {
        return Err(
            "--hps off: the vehicle description's [link] interconnects the front struts; leave --hps out or give a strut file"
                .into(),
        );
    }
    Ok(Some(link))
}

/// The terrain of `terrain` (`default` when it is `None`) and the seeds to run: one run on
/// smooth ground (its seed, 0, is not used), else `seed`, the terrain's own seed, or
/// 1..=`seeds` (default 10).
pub fn terrain_and_seeds(
    terrain: Option<TerrainChoice>,
    seeds: Option<usize>,
    seed: Option<u64>,
    default: Option<TerrainSpec>,
) -> Result<(Option<TerrainSpec>, Vec<u64>), String> {
    let t = terrain.unwrap_or(TerrainChoice {
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

/// When the measured window of a D1 ride at `speed_kmh` starts (s): after the
/// [`RUN_IN_M`] run-in; the run-in and the `length_m` window together take at most
/// [`MAX_DURATION_S`].
pub fn ride_window_start(speed_kmh: f64, length_m: f64) -> Result<f64, String> {
    let speed = speed_kmh / 3.6;
    let sim_s = (RUN_IN_M + length_m) / speed;
    if sim_s > MAX_DURATION_S {
        return Err(format!(
            "--length-m {}: the run-in and window take {} s at {speed_kmh} km/h, more than {MAX_DURATION_S} s",
            show(length_m),
            show(sim_s)
        ));
    }
    Ok(RUN_IN_M / speed)
}

/// The seeds of `afsv vehicle measures`: 1..=`seeds` or `seed` (default 1..=10), at most
/// [`crate::design_3d::MAX_SEEDS`].
pub fn measure_seeds(seeds: Option<usize>, seed: Option<u64>) -> Result<Vec<u64>, String> {
    use crate::design_3d::MAX_SEEDS;
    match (seeds, seed) {
        (Some(_), Some(_)) => Err("--seeds and --seed both give the seeds; give one".into()),
        (None, Some(s)) => Ok(vec![s]),
        (n, None) => {
            let n = n.unwrap_or(10);
            if n == 0 || n as u64 > MAX_SEEDS {
                return Err(format!("--seeds {n}: must be 1 to {MAX_SEEDS}"));
            }
            Ok((1..=n as u64).collect())
        }
    }
}

/// The cab and seat of a ride: `flag` `generic` or `off`, else the description's (none for
/// a raw parameter set or a description without them).
pub fn seat_layout(case: &CaseSource, flag: Option<&str>) -> Result<Option<CabSeatLayout>, String> {
    match flag {
        Some("off") => Ok(None),
        Some(_) => Ok(Some(CabSeatLayout::generic())),
        None if case.params.is_some() => Ok(None),
        None => Ok(crate::described::articulated(case.vehicle)?.cab_seat),
    }
}

/// The seat measures of one ride record from `t_window` (s) on, when there is a seat.
pub fn seat_of_run(
    p: &VehicleParams,
    rec: &RunRecord,
    t_window: f64,
    layout: Option<&CabSeatLayout>,
) -> Result<Option<SeatRideMeasures>, String> {
    layout
        .map(|l| seat_ride_measures(p, rec, t_window, l).map_err(|e| e.to_string()))
        .transpose()
}

/// What the report of one seed's D1 ride needs: its measures, the cab's PSDs when a plot
/// asks for them, the seat's measures when there is a seat.
pub type RideSeed = (RideMeasures, Option<RidePsd>, Option<SeatRideMeasures>);

/// One seed's D1 ride of `p` (`crate::design_3d::ride_run`, the struts linked as `link`
/// says) measured from `t_window` (s): the [`RideSeed`], its PSDs only `with_psd`, the
/// seat's measures with a cab and seat `layout` ([`seat_of_run`]).
pub fn ride_seed(
    (p, spec, link): (&VehicleParams, &RideSpec, Option<&Link>),
    seed: u64,
    t_window: f64,
    layout: Option<&CabSeatLayout>,
    with_psd: bool,
) -> Result<RideSeed, String> {
    let (rec, m) = crate::design_3d::ride_run(p, spec, seed, link).map_err(|e| e.to_string())?;
    let psd = if with_psd {
        Some(ride_psd(&rec, t_window)?)
    } else {
        None
    };
    Ok((m, psd, seat_of_run(p, &rec, t_window, layout)?))
}

/// One run of `run.params` for `duration_s` (s) on its ground (the first seed of a
/// terrain), its struts interconnected as `run.link` says; with `components`, also every
/// component's own channels (not with a link: the linked struts' lines are not components).
pub fn simulate_run(
    run: &SimulateRun,
    duration_s: f64,
    components: bool,
) -> Result<(RunRecord, Option<Recorder>), String> {
    let p = run.params;
    let speed = run.speed_kmh / 3.6;
    let options = VehicleOptions {
        front_axle: run.front_axle,
        speed_m_s: speed,
        steer: run.steer.clone(),
        path_length_m: speed * duration_s + 5.0,
        ..VehicleOptions::default()
    };
    let opts = RunOptions {
        t_end_s: duration_s,
        output_dt_s: run.output_dt_s,
        ..RunOptions::default()
    };
    let half = 0.5 * p.front_track_m;
    let err = |e: vehicle_3d::VehicleError| e.to_string();
    let vehicle = match run.terrain {
        None => {
            let flat = FlatTerrain::new(0.0, vehicle_components::DEFAULT_FRICTION)
                .map_err(|e| e.to_string())?;
            Vehicle::new(p, run.load, options, &flat, half).map_err(err)?
        }
        Some(t) => {
            let length = options.start_s_m + options.path_length_m + 50.0;
            let ground = t.build(p, length, run.seeds[0]).map_err(err)?;
            Vehicle::new(p, run.load, options, &ground, half).map_err(err)?
        }
    };
    match run.link {
        None if components => {
            let (rec, c) = simulate_components(&vehicle, &opts).map_err(err)?;
            Ok((rec, Some(c)))
        }
        None => Ok((vehicle_3d::simulate(&vehicle, &opts).map_err(err)?, None)),
        Some(_) if components => Err(
            "--components: not with the description's [link] (the linked struts' lines are not components)"
                .into(),
        ),
        Some(l) => {
            let linked = LinkedVehicle::new(vehicle, l).map_err(err)?;
            let state = linked.initial_state().map_err(err)?;
            Ok((linked.simulate_from(&state, &opts).map_err(err)?.record, None))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A short ride: the measures are the ride's, the PSDs and the seat only when asked.
    #[test]
    fn a_ride_seed_carries_what_its_report_asks_for() {
        let p = VehicleParams::nominal();
        let spec = RideSpec {
            length_m: 10.0,
            ..RideSpec::d1(vehicle_3d::Load::Loaded, FrontAxle::Rigid)
        };
        let t_window = ride_window_start(spec.speed_kmh, spec.length_m).unwrap();
        let (_, m) = crate::design_3d::ride_run(&p, &spec, 1, None).unwrap();
        let (bare, psd, seat) = ride_seed((&p, &spec, None), 1, t_window, None, false).unwrap();
        assert_eq!(
            (bare.a_wz_m_s2, psd.is_none(), seat.is_none()),
            (m.a_wz_m_s2, true, true)
        );
        let seat_layout = CabSeatLayout::generic();
        let (_, psd, seat) =
            ride_seed((&p, &spec, None), 1, t_window, Some(&seat_layout), true).unwrap();
        assert!(psd.is_some() && seat.is_some());
    }

    #[test]
    fn seeds_come_from_one_option() {
        assert_eq!(
            measure_seeds(None, None).unwrap(),
            (1..=10).collect::<Vec<_>>()
        );
        assert_eq!(measure_seeds(Some(2), None).unwrap(), vec![1, 2]);
        assert_eq!(measure_seeds(None, Some(7)).unwrap(), vec![7]);
        assert!(measure_seeds(Some(2), Some(7)).is_err());
        assert!(measure_seeds(Some(0), None).is_err());
        assert!(measure_seeds(Some(101), None).is_err());
    }

    #[test]
    fn smooth_ground_has_one_run_and_a_terrain_its_seeds() {
        assert_eq!(
            terrain_and_seeds(None, None, None, None).unwrap(),
            (None, vec![0])
        );
        assert!(terrain_and_seeds(None, Some(2), None, None).is_err());
        let e = TerrainSpec::default();
        let (t, s) = terrain_and_seeds(None, Some(3), None, Some(e)).unwrap();
        assert_eq!((t, s), (Some(e), vec![1, 2, 3]));
        let own = TerrainChoice {
            spec: Some(e),
            seed: Some(5),
        };
        assert_eq!(
            terrain_and_seeds(Some(own), None, None, None).unwrap().1,
            vec![5]
        );
        assert!(terrain_and_seeds(Some(own), None, Some(4), None).is_err());
    }

    #[test]
    fn the_front_axle_follows_hps() {
        let case = |hps| CaseSource {
            params: None,
            vehicle: None,
            hps,
            paper_form: false,
        };
        assert_eq!(
            vehicle_params(&case(Some("off"))).unwrap().1,
            FrontAxle::Rigid
        );
        assert_eq!(
            vehicle_params(&case(Some("nominal"))).unwrap().1,
            FrontAxle::Suspended
        );
        assert_eq!(hps_file(Some("s.json")), Some(Path::new("s.json")));
        assert_eq!(hps_file(Some("nominal")), None);
        assert!(vehicle_params(&case(Some("no-such-strut.json")))
            .unwrap_err()
            .starts_with("--hps: "));
    }

    #[test]
    fn the_ride_window_follows_the_run_in() {
        let t = ride_window_start(36.0, 100.0).unwrap();
        assert_eq!(t, RUN_IN_M / 10.0);
        assert!(ride_window_start(1.0, 5000.0)
            .unwrap_err()
            .contains("more than 600 s"));
    }

    #[test]
    fn terrain_and_steer_texts() {
        assert_eq!(parse_terrain("smooth").unwrap().spec, None);
        let t = parse_terrain("mc:0.5, class:C, seed:4").unwrap();
        let spec = t.spec.unwrap();
        assert_eq!((spec.class, spec.m_c, t.seed), (IsoClass::C, 0.5, Some(4)));
        assert!(parse_terrain("class:C,class:D")
            .unwrap_err()
            .contains("twice"));
        assert!(parse_terrain("colour:red")
            .unwrap_err()
            .contains("unknown key"));
        assert_eq!(parse_steer("none").unwrap(), SteerInput::None);
        assert!(matches!(
            parse_steer("ramp:5,1").unwrap(),
            SteerInput::Ramp { .. }
        ));
        assert!(parse_steer("ramp:0.001,1")
            .unwrap_err()
            .contains("at least"));
        assert!(parse_steer("pulse:30,0.2")
            .unwrap_err()
            .contains("not understood"));
        assert!(parse_steer("pulse:2000,0.2,1")
            .unwrap_err()
            .contains("at most"));
    }
}
