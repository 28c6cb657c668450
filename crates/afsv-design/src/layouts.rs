//! `afsv study layouts`: several suspension layouts of one vehicle through D1-D4 on common
//! terrain seeds (section 6.4; the layouts of section 7.3's future work, docs/layouts.md).
//!
//! Each [`Layout`] is a parameter set of the 3-D vehicle (its rear strut, if any, in
//! `rear_hps`) with its front axle and, optionally, the front struts' roll interconnection
//! or the front-rear (pitch) interconnection of each side's struts.
//! On the same seeds, each layout runs
//! - the ride (class E, m_c 0.3, 100 m after the run-in) at the question's speed and at
//!   every D4 speed: a_wz on the frame (W_k, ISO 2631-1) and the strut travel d_s;
//! - D2 (SP-DRT, loaded) and D3 (omega_z, loaded, smooth ground).
//!
//! With a cab and seat ([`LayoutOptions::seat`]) every layout gets a second row read at the
//! seat: the cab and seat are driven by the same ride records (one-way coupled,
//! `vehicle_3d::cab_ride`), so the seat costs no vehicle run. A row's operator measure is
//! a_wz where the operator's body meets the vehicle: the seat pan on a seat row, the frame
//! otherwise. Its D4 crossing is the speed at which that measure's mean first rises above
//! the 8 h upper bound of the health guidance caution zone (Eq B.1, linear interpolation,
//! [`first_upward_crossing`]).
//!
//! The first layout is the baseline. A difference from the baseline's row read at the same
//! point (frame or seat) that lies inside the seed spread (not [`settled`]: less than twice
//! the standard error of the difference) is listed in the row's `inside_seed_spread`, so a
//! table never reads noise as a ranking.

use crate::design_3d::{hgcz_8h_band, settled};
use crate::error::DesignError;
use crate::hps_speed_sweep::{first_upward_crossing, MAX_SPEEDS, MAX_SPEED_KMH, MIN_SPEED_KMH};
use hps_emulsion::interconnect::LineParams;
use perf_measures::iso2631::{health_guidance_zone, HgczRelation, HgczZone};
use serde::Serialize;
use std::sync::Arc;
use vehicle_3d::cab_ride::{seat_ride_measures, CabSeatLayout};
use vehicle_3d::interconnect::{ride_linked_on, roll_linked_on, yaw_linked, Link};
use vehicle_3d::scenarios::{
    ride_on, ride_tracks, roll_on, roll_tracks, yaw, RideSpec, RollSpec, Spread, YawSpec, RUN_IN_M,
};
use vehicle_3d::{FrontAxle, Load, TireTracks, VehicleParams};

/// Largest number of layouts of one study.
pub const MAX_LAYOUTS: usize = 16;
/// Largest number of terrain seeds of one study.
pub const MAX_SEEDS: usize = 100;

/// One suspension layout of the vehicle.
#[derive(Debug, Clone)]
pub struct Layout {
    /// Its name in the table (e.g. `front HPS`).
    pub name: String,
    /// The vehicle's parameters with this layout's suspension.
    pub params: VehicleParams,
    /// The front axle.
    pub front_axle: FrontAxle,
    /// The roll interconnection of the front struts (`vehicle_3d::interconnect`), if any;
    /// it needs the front-axle HPS.
    pub front_link: Option<LineParams>,
    /// The pitch interconnection of each side's front and rear struts
    /// (`vehicle_3d::interconnect::Link::Pitch`: the line at the front strut's piston side,
    /// the line at the rear strut's), if any; it needs struts on both axles, and a layout
    /// has at most one of the two links.
    pub pitch_link: Option<[LineParams; 2]>,
}

impl Layout {
    /// The layout's strut interconnection, if any.
    pub fn link(&self) -> Option<Link> {
        match (self.front_link, self.pitch_link) {
            (Some(line), _) => Some(Link::Roll(line)),
            (None, Some(lines)) => Some(Link::Pitch(lines)),
            (None, None) => None,
        }
    }
}

/// What the study runs.
#[derive(Debug, Clone)]
pub struct LayoutOptions {
    /// Load case of the rides (D2 and D3 are loaded, as in section 6.4).
    pub load: Load,
    /// Speed of the ride the question asks about (km/h; D1 is 20).
    pub ride_speed_kmh: f64,
    /// The D4 speeds (km/h), strictly ascending.
    pub sweep_speeds_kmh: Vec<f64>,
    /// Terrain seeds, common to every layout and measure.
    pub seeds: Vec<u64>,
    /// The cab and seat of the seat rows; `None`: frame rows only.
    pub seat: Option<CabSeatLayout>,
}

/// Where one row's operator a_wz crosses the caution zone over the D4 speeds.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LayoutCrossing {
    /// The interpolated speed (km/h); `None` when the mean stays on one side of the bound.
    pub speed_kmh: Option<f64>,
    /// The mean is above the bound already at the lowest D4 speed.
    pub above_at_lowest: bool,
}

/// One row of the study: a layout, read on the frame or at the seat.
#[derive(Debug, Clone, Serialize)]
pub struct LayoutRow {
    /// The layout's name.
    pub layout: String,
    /// Read at the seat (with the study's cab and seat) rather than on the frame.
    pub at_seat: bool,
    /// a_wz on the frame at the a_wz point, at the ride speed (m/s²).
    pub a_wz_frame_m_s2: Spread,
    /// a_wz on the seat pan at the ride speed (m/s²); seat rows only.
    pub a_wz_seat_m_s2: Option<Spread>,
    /// SEAT, seat over floor (ISO 10326-1), at the ride speed; seat rows only.
    pub seat_ratio: Option<Spread>,
    /// Peak-to-peak travel of the front struts at the ride speed (m); HPS rows only.
    pub strut_travel_m: Option<Spread>,
    /// D2 SP-DRT, loaded (m/s²).
    pub sp_drt_m_s2: Spread,
    /// SP-DRT against the first row's (percent).
    pub sp_drt_change_percent: f64,
    /// D3 omega_z, loaded (Hz).
    pub omega_z_hz: f64,
    /// The operator's a_wz at the ride speed against the 8 h caution zone.
    pub hgcz_8h: HgczZone,
    /// D4: where the operator's a_wz crosses the zone's upper bound.
    pub d4_crossing: LayoutCrossing,
    /// The operator's mean a_wz at each D4 speed (m/s²), in sweep order.
    pub d4_a_wz_m_s2: Vec<f64>,
    /// Measures whose difference from the first row lies inside the seed spread.
    pub inside_seed_spread: Vec<&'static str>,
}

impl LayoutRow {
    /// a_wz where the operator meets the vehicle: the seat pan on a seat row, else the frame.
    pub fn operator_a_wz(&self) -> &Spread {
        self.a_wz_seat_m_s2
            .as_ref()
            .unwrap_or(&self.a_wz_frame_m_s2)
    }
}

/// The study.
#[derive(Debug, Clone, Serialize)]
pub struct LayoutStudy {
    /// Terrain seeds.
    pub seeds: Vec<u64>,
    /// Load case of the rides.
    pub load: Load,
    /// Speed of the ride (km/h).
    pub ride_speed_kmh: f64,
    /// D4 speeds (km/h).
    pub sweep_speeds_kmh: Vec<f64>,
    /// The 8 h caution zone (m/s²).
    pub hgcz_8h_m_s2: (f64, f64),
    /// Rows in the layouts' order, each layout's frame row before its seat row.
    pub rows: Vec<LayoutRow>,
}

/// One run of the study, by layout index.
#[derive(Debug, Clone, Copy)]
enum Job {
    Ride {
        layout: usize,
        speed: usize,
        seed: usize,
    },
    Roll {
        layout: usize,
        seed: usize,
    },
    Yaw {
        layout: usize,
    },
}

/// What one ride measured: frame a_wz, strut travel, and (seat a_wz, SEAT) with a seat.
struct RideOut {
    a_wz_frame: f64,
    strut_travel: Option<f64>,
    seat: Option<(f64, f64)>,
}

enum Outcome {
    Ride(RideOut),
    Roll(f64),
    Yaw(f64),
}

/// The enveloping caches of one layout and seed: the ride's and the roll's.
struct Tracks {
    ride: Arc<TireTracks>,
    roll: Arc<TireTracks>,
}

/// Vehicle runs of [`layouts`] for `layouts` layouts with options `o`: per layout one yaw
/// run and, per seed, one roll run and one ride at each distinct speed (the ride speed and
/// the D4 speeds together).
pub fn layout_runs(layouts: usize, o: &LayoutOptions) -> usize {
    layouts * (1 + o.seeds.len() * (1 + all_speeds(o).len()))
}

/// The ride speed and the D4 speeds, ascending, each once.
fn all_speeds(o: &LayoutOptions) -> Vec<f64> {
    let mut v = o.sweep_speeds_kmh.clone();
    v.push(o.ride_speed_kmh);
    v.sort_by(f64::total_cmp);
    v.dedup();
    v
}

fn check(layouts: &[Layout], o: &LayoutOptions) -> Result<(), DesignError> {
    if layouts.is_empty() || layouts.len() > MAX_LAYOUTS {
        return Err(DesignError::Shape {
            field: "layouts",
            reason: format!("between 1 and {MAX_LAYOUTS} layouts, got {}", layouts.len()),
        });
    }
    if o.seeds.is_empty() || o.seeds.len() > MAX_SEEDS {
        return Err(DesignError::Shape {
            field: "seeds",
            reason: format!("between 1 and {MAX_SEEDS} seeds, got {}", o.seeds.len()),
        });
    }
    if o.sweep_speeds_kmh.len() < 2 || o.sweep_speeds_kmh.len() > MAX_SPEEDS {
        return Err(DesignError::Shape {
            field: "sweep_speeds_kmh",
            reason: format!(
                "between 2 and {MAX_SPEEDS} D4 speeds, got {}",
                o.sweep_speeds_kmh.len()
            ),
        });
    }
    let in_range = |v: f64| v.is_finite() && (MIN_SPEED_KMH..=MAX_SPEED_KMH).contains(&v);
    if !in_range(o.ride_speed_kmh) {
        return Err(DesignError::Invalid {
            field: "ride_speed_kmh",
            value: o.ride_speed_kmh,
            reason: "a speed must lie within 5-100 km/h",
        });
    }
    for (i, &v) in o.sweep_speeds_kmh.iter().enumerate() {
        if !in_range(v) || (i > 0 && v <= o.sweep_speeds_kmh[i - 1]) {
            return Err(DesignError::Invalid {
                field: "sweep_speeds_kmh",
                value: v,
                reason: "D4 speeds lie within 5-100 km/h, strictly ascending",
            });
        }
    }
    for l in layouts {
        l.params
            .validate()
            .map_err(|e| DesignError::Simulation(format!("layout `{}`: {e}", l.name)))?;
        if let Some(line) = &l.front_link {
            if l.front_axle != FrontAxle::Suspended {
                return Err(DesignError::Simulation(format!(
                    "layout `{}`: the roll interconnection needs the front-axle HPS",
                    l.name
                )));
            }
            line.validate()
                .map_err(|e| DesignError::Simulation(format!("layout `{}`: {e}", l.name)))?;
        }
        if let Some(lines) = &l.pitch_link {
            if l.front_link.is_some() {
                return Err(DesignError::Simulation(format!(
                    "layout `{}`: a layout takes the roll or the pitch interconnection, not both",
                    l.name
                )));
            }
            if l.front_axle != FrontAxle::Suspended || l.params.rear_hps.is_none() {
                return Err(DesignError::Simulation(format!(
                    "layout `{}`: the pitch interconnection needs struts on both axles",
                    l.name
                )));
            }
            for line in lines {
                line.validate()
                    .map_err(|e| DesignError::Simulation(format!("layout `{}`: {e}", l.name)))?;
            }
        }
    }
    if let (Some(s), Some(l)) = (&o.seat, layouts.first()) {
        s.build(&l.params)
            .map_err(|e| DesignError::Simulation(format!("the cab and seat: {e}")))?;
    }
    Ok(())
}

/// Run the study of the module docs; `progress` is called once per finished run with a
/// short description. Every run of every layout is on the same seeds.
pub fn layouts(
    layouts: &[Layout],
    o: &LayoutOptions,
    progress: &(dyn Fn(&str) + Sync),
) -> Result<LayoutStudy, DesignError> {
    check(layouts, o)?;
    let speeds = all_speeds(o);
    let mut jobs = Vec::new();
    for layout in 0..layouts.len() {
        jobs.push(Job::Yaw { layout });
        for seed in 0..o.seeds.len() {
            jobs.push(Job::Roll { layout, seed });
            for speed in 0..speeds.len() {
                jobs.push(Job::Ride {
                    layout,
                    speed,
                    seed,
                });
            }
        }
    }
    let cases: Vec<(usize, u64)> = (0..layouts.len())
        .flat_map(|l| o.seeds.iter().map(move |&s| (l, s)))
        .collect();
    let ride_spec = |l: &Layout, speed_kmh: f64| RideSpec {
        speed_kmh,
        ..RideSpec::d1(o.load, l.front_axle)
    };
    let sim = |e: vehicle_3d::VehicleError| e.to_string();
    let outcomes = crate::fan_out::cached(
        &cases,
        |&(l, seed)| -> Result<Tracks, String> {
            let layout = &layouts[l];
            Ok(Tracks {
                ride: ride_tracks(&layout.params, &ride_spec(layout, speeds[0]), seed)
                    .map_err(sim)?,
                roll: roll_tracks(&layout.params, &RollSpec::d2(layout.front_axle), seed)
                    .map_err(sim)?,
            })
        },
        &jobs,
        |&job, tracks: &[Tracks]| -> Result<Outcome, String> {
            let cache = |l: usize, seed: usize| &tracks[l * o.seeds.len() + seed];
            match job {
                Job::Ride {
                    layout,
                    speed,
                    seed,
                } => {
                    let l = &layouts[layout];
                    let spec = ride_spec(l, speeds[speed]);
                    let t = Arc::clone(&cache(layout, seed).ride);
                    let (rec, m) = match &l.link() {
                        None => ride_on(&l.params, &spec, t).map_err(sim)?,
                        Some(link) => {
                            let (run, m) =
                                ride_linked_on(&l.params, &spec, t, link).map_err(sim)?;
                            (run.record, m)
                        }
                    };
                    let seat = o
                        .seat
                        .as_ref()
                        .map(|s| {
                            seat_ride_measures(&l.params, &rec, RUN_IN_M / (speeds[speed] / 3.6), s)
                                .map(|r| (r.a_wz_seat_m_s2, r.seat.seat))
                        })
                        .transpose()
                        .map_err(sim)?;
                    Ok(Outcome::Ride(RideOut {
                        a_wz_frame: m.a_wz_m_s2,
                        strut_travel: m.strut_travel_p2p_m,
                        seat,
                    }))
                }
                Job::Roll { layout, seed } => {
                    let l = &layouts[layout];
                    let t = Arc::clone(&cache(layout, seed).roll);
                    let spec = RollSpec::d2(l.front_axle);
                    let m = match &l.link() {
                        None => roll_on(&l.params, &spec, t).map_err(sim)?.1,
                        Some(link) => roll_linked_on(&l.params, &spec, t, link).map_err(sim)?.1,
                    };
                    Ok(Outcome::Roll(m.sp_drt_m_s2))
                }
                Job::Yaw { layout } => {
                    let l = &layouts[layout];
                    let spec = YawSpec::d3(l.front_axle);
                    let m = match &l.link() {
                        None => yaw(&l.params, &spec, 0).map_err(sim)?.1,
                        Some(link) => yaw_linked(&l.params, &spec, link).map_err(sim)?.1,
                    };
                    Ok(Outcome::Yaw(m.omega_z_hz))
                }
            }
        },
        |&job| progress(&job_text(layouts, o, &speeds, job)),
    )
    .map_err(DesignError::Simulation)?;
    let mut per_layout: Vec<Collected> = (0..layouts.len())
        .map(|_| Collected::new(speeds.len()))
        .collect();
    for (job, out) in jobs.iter().zip(outcomes) {
        let out = out.map_err(DesignError::Simulation)?;
        match (*job, out) {
            (Job::Ride { layout, speed, .. }, Outcome::Ride(r)) => {
                per_layout[layout].rides[speed].push(r)
            }
            (Job::Roll { layout, .. }, Outcome::Roll(v)) => per_layout[layout].sp_drt.push(v),
            (Job::Yaw { layout }, Outcome::Yaw(v)) => per_layout[layout].omega_z = v,
            _ => unreachable!("every job gives its own kind of outcome"),
        }
    }
    let band = hgcz_8h_band().map_err(DesignError::Simulation)?;
    let mut rows = Vec::new();
    for (l, c) in layouts.iter().zip(&per_layout) {
        rows.push(c.row(l, o, &speeds, false)?);
        if o.seat.is_some() {
            rows.push(c.row(l, o, &speeds, true)?);
        }
    }
    compare_with_baseline(&mut rows);
    Ok(LayoutStudy {
        seeds: o.seeds.clone(),
        load: o.load,
        ride_speed_kmh: o.ride_speed_kmh,
        sweep_speeds_kmh: o.sweep_speeds_kmh.clone(),
        hgcz_8h_m_s2: band,
        rows,
    })
}

/// A run in words for the progress line, e.g. `front HPS: ride 30 km/h, seed 3`.
fn job_text(layouts: &[Layout], o: &LayoutOptions, speeds: &[f64], job: Job) -> String {
    match job {
        Job::Ride {
            layout,
            speed,
            seed,
        } => format!(
            "{}: ride {} km/h, seed {}",
            layouts[layout].name, speeds[speed], o.seeds[seed]
        ),
        Job::Roll { layout, seed } => {
            format!("{}: D2 roll, seed {}", layouts[layout].name, o.seeds[seed])
        }
        Job::Yaw { layout } => format!("{}: D3 yaw", layouts[layout].name),
    }
}

/// The runs of one layout, by speed index then seed.
struct Collected {
    rides: Vec<Vec<RideOut>>,
    sp_drt: Vec<f64>,
    omega_z: f64,
}

impl Collected {
    fn new(speeds: usize) -> Self {
        Self {
            rides: (0..speeds).map(|_| Vec::new()).collect(),
            sp_drt: Vec::new(),
            omega_z: f64::NAN,
        }
    }

    /// The layout's frame row, or its seat row when `at_seat`.
    fn row(
        &self,
        l: &Layout,
        o: &LayoutOptions,
        speeds: &[f64],
        at_seat: bool,
    ) -> Result<LayoutRow, DesignError> {
        let spread =
            |v: Vec<f64>| Spread::of(&v).map_err(|e| DesignError::Simulation(e.to_string()));
        let at = |v: f64| speeds.iter().position(|&s| s == v).unwrap_or(0);
        let ride = &self.rides[at(o.ride_speed_kmh)];
        let seat = |pick: fn((f64, f64)) -> f64| -> Result<Option<Spread>, DesignError> {
            if !at_seat {
                return Ok(None);
            }
            let v: Option<Vec<f64>> = ride.iter().map(|r| r.seat.map(pick)).collect();
            v.map(spread).transpose()
        };
        let travel: Vec<f64> = ride.iter().filter_map(|r| r.strut_travel).collect();
        let operator = |r: &RideOut| match (at_seat, r.seat) {
            (true, Some((a, _))) => a,
            _ => r.a_wz_frame,
        };
        let zone = health_guidance_zone(8.0, HgczRelation::SqrtTime)
            .map_err(|e| DesignError::Simulation(e.to_string()))?;
        let d4: Vec<f64> = o
            .sweep_speeds_kmh
            .iter()
            .map(|&v| {
                let runs = &self.rides[at(v)];
                runs.iter().map(operator).sum::<f64>() / runs.len() as f64
            })
            .collect();
        let operator_ride = if at_seat { seat(|s| s.0)? } else { None };
        let frame = spread(ride.iter().map(|r| r.a_wz_frame).collect())?;
        let operator_mean = operator_ride.as_ref().unwrap_or(&frame).mean;
        Ok(LayoutRow {
            layout: l.name.clone(),
            at_seat,
            a_wz_frame_m_s2: frame,
            a_wz_seat_m_s2: operator_ride,
            seat_ratio: seat(|s| s.1)?,
            strut_travel_m: if travel.is_empty() {
                None
            } else {
                Some(spread(travel)?)
            },
            sp_drt_m_s2: spread(self.sp_drt.clone())?,
            sp_drt_change_percent: 0.0,
            omega_z_hz: self.omega_z,
            hgcz_8h: zone.classify(operator_mean),
            d4_crossing: LayoutCrossing {
                speed_kmh: first_upward_crossing(&o.sweep_speeds_kmh, &d4, zone.upper_m_s2),
                above_at_lowest: d4[0] > zone.upper_m_s2,
            },
            d4_a_wz_m_s2: d4,
            inside_seed_spread: Vec::new(),
        })
    }
}

/// SP-DRT changes against the first row, and the measures whose difference from the
/// baseline layout (the first row's) lies inside the seed spread: each row against the
/// baseline's row read at the same point (frame or seat), measures both rows have.
fn compare_with_baseline(rows: &mut [LayoutRow]) {
    type Pick = fn(&LayoutRow) -> Option<Spread>;
    let measures: [(&'static str, Pick); 5] = [
        ("a_wz_frame", |r| Some(r.a_wz_frame_m_s2)),
        ("a_wz_seat", |r| r.a_wz_seat_m_s2),
        ("seat_ratio", |r| r.seat_ratio),
        ("strut_travel", |r| r.strut_travel_m),
        ("sp_drt", |r| Some(r.sp_drt_m_s2)),
    ];
    let Some(first) = rows.first() else { return };
    let sp0 = first.sp_drt_m_s2.mean;
    let baseline = first.layout.clone();
    let base_rows: Vec<LayoutRow> = rows
        .iter()
        .filter(|r| r.layout == baseline)
        .cloned()
        .collect();
    for row in rows.iter_mut() {
        row.sp_drt_change_percent = 100.0 * (row.sp_drt_m_s2.mean / sp0 - 1.0);
        if row.layout == baseline {
            continue;
        }
        let Some(base) = base_rows.iter().find(|b| b.at_seat == row.at_seat) else {
            continue;
        };
        for (name, pick) in &measures {
            if let (Some(b), Some(v)) = (pick(base), pick(row)) {
                if !settled(&v, &b) {
                    row.inside_seed_spread.push(name);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spread(mean: f64, sd: f64, n: usize) -> Spread {
        Spread { mean, sd, n }
    }

    fn row(name: &str, awz: Spread, seat: Option<Spread>, sp: Spread) -> LayoutRow {
        LayoutRow {
            layout: name.into(),
            at_seat: seat.is_some(),
            a_wz_frame_m_s2: awz,
            a_wz_seat_m_s2: seat,
            seat_ratio: None,
            strut_travel_m: None,
            sp_drt_m_s2: sp,
            sp_drt_change_percent: f64::NAN,
            omega_z_hz: 1.0,
            hgcz_8h: HgczZone::Below,
            d4_crossing: LayoutCrossing {
                speed_kmh: None,
                above_at_lowest: false,
            },
            d4_a_wz_m_s2: Vec::new(),
            inside_seed_spread: Vec::new(),
        }
    }

    #[test]
    fn differences_inside_the_seed_spread_are_listed_against_the_baseline_layout() {
        let n = 10;
        // standard error of a difference of two SD-0.1 means over 10 seeds: 0.0447
        let seat = |mean| Some(spread(mean, 0.1, n));
        let mut rows = vec![
            row("rigid", spread(1.0, 0.1, n), None, spread(4.0, 0.1, n)),
            row("rigid", spread(1.0, 0.1, n), seat(1.5), spread(4.0, 0.1, n)),
            // frame 0.05 from the baseline: inside; SP-DRT 0.2 below: settled, -5 %
            row("a", spread(1.05, 0.1, n), None, spread(3.8, 0.1, n)),
            // seat 0.05 from the baseline's seat row: inside; frame 0.2 away: settled
            row("b", spread(0.8, 0.1, n), seat(1.45), spread(4.0, 0.1, n)),
        ];
        rows[3].strut_travel_m = Some(spread(0.05, 0.001, n));
        compare_with_baseline(&mut rows);
        assert!(rows[0].inside_seed_spread.is_empty() && rows[1].inside_seed_spread.is_empty());
        assert_eq!(rows[1].sp_drt_change_percent, 0.0);
        assert_eq!(rows[2].inside_seed_spread, vec!["a_wz_frame"]);
        assert!((rows[2].sp_drt_change_percent + 5.0).abs() < 1e-12);
        assert_eq!(
            rows[3].inside_seed_spread,
            vec!["a_wz_seat", "sp_drt"],
            "no strut travel on the baseline: nothing to compare"
        );
    }

    #[test]
    fn bad_studies_are_refused_before_any_run() {
        let p = VehicleParams::nominal();
        let one = vec![Layout {
            name: "rigid".into(),
            params: p.clone(),
            front_axle: FrontAxle::Rigid,
            front_link: None,
            pitch_link: None,
        }];
        let good = LayoutOptions {
            load: Load::Loaded,
            ride_speed_kmh: 30.0,
            sweep_speeds_kmh: vec![10.0, 20.0, 30.0],
            seeds: vec![1, 2],
            seat: None,
        };
        let none = |_: &str| panic!("no run may start");
        let bad = [
            LayoutOptions {
                seeds: vec![],
                ..good.clone()
            },
            LayoutOptions {
                ride_speed_kmh: 200.0,
                ..good.clone()
            },
            LayoutOptions {
                sweep_speeds_kmh: vec![20.0],
                ..good.clone()
            },
            LayoutOptions {
                sweep_speeds_kmh: vec![20.0, 10.0],
                ..good.clone()
            },
            LayoutOptions {
                sweep_speeds_kmh: vec![10.0, f64::NAN],
                ..good.clone()
            },
        ];
        for o in &bad {
            assert!(layouts(&one, o, &none).is_err(), "{o:?}");
        }
        assert!(layouts(&[], &good, &none).is_err());
        // a pitch link without rear struts, or with the roll link, is refused by name
        let lines = LineParams::side_pitch(1.457).unwrap();
        let pitch = Layout {
            name: "front-pitch".into(),
            front_axle: FrontAxle::Suspended,
            pitch_link: Some(lines),
            ..one[0].clone()
        };
        let e = layouts(std::slice::from_ref(&pitch), &good, &none).unwrap_err();
        assert!(e.to_string().contains("both axles"), "{e}");
        let mut both = pitch;
        both.params.rear_hps = Some(p.default_rear_strut().unwrap());
        assert!(both.link() == Some(Link::Pitch(lines)));
        both.front_link = Some(LineParams::front_axle_roll());
        let e = layouts(&[both], &good, &none).unwrap_err();
        assert!(e.to_string().contains("not both"), "{e}");
        assert_eq!(all_speeds(&good), vec![10.0, 20.0, 30.0]);
        let extra = LayoutOptions {
            ride_speed_kmh: 25.0,
            ..good
        };
        assert_eq!(all_speeds(&extra), vec![10.0, 20.0, 25.0, 30.0]);
        // two seeds, four speeds: per layout a yaw run, and per seed a roll and four rides
        assert_eq!(layout_runs(3, &extra), 3 * (1 + 2 * (1 + 4)));
    }
}
