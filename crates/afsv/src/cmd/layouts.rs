//! `afsv study layouts`: suspension layouts of one vehicle through D1-D4 on common seeds,
//! on the frame and at the seat (`afsv_design::layouts`, docs/layouts.md).

use super::CmdResult;
use afsv::output::{OutputGuard, OutputKind};
use afsv_design::layouts::{layout_runs, layouts, Layout, LayoutOptions, LayoutRow, LayoutStudy};
use hps_emulsion::interconnect::LineParams;
use std::path::PathBuf;
use vehicle_3d::cab_ride::CabSeatLayout;
use vehicle_3d::interconnect::Link;
use vehicle_3d::{FrontAxle, Load};

/// The layouts `--layouts` can name, in the table's order.
pub const LAYOUT_NAMES: &[(&str, &str)] = &[
    ("rigid", "every axle rigid"),
    (
        "front-hps",
        "the description's front-axle strut (or its candidate strut), rigid rear",
    ),
    (
        "front-rear-hps",
        "front strut and the description's rear strut (or the front strut scaled for the rear static load)",
    ),
    (
        "front-roll",
        "front-hps with the front struts roll-interconnected (sealed pistons, two cross lines with accumulators)",
    ),
    (
        "front-rear-roll",
        "front-rear-hps with the front struts roll-interconnected",
    ),
    (
        "front-rear-pitch",
        "front-rear-hps with each side's front and rear struts pitch-interconnected (sealed pistons, two cross lines with accumulators per side)",
    ),
];

/// Options of `afsv study layouts`.
#[derive(clap::Args)]
pub struct LayoutArgs {
    #[arg(long, help = super::described::HELP)]
    pub vehicle: Option<PathBuf>,
    /// Layouts, comma separated, the first is the baseline: rigid (every axle rigid),
    /// front-hps (the description's front-axle strut, or its candidate strut),
    /// front-rear-hps (and the description's rear strut, or the front strut scaled for the
    /// rear static load), front-roll and front-rear-roll (those with the front struts
    /// roll-interconnected), front-rear-pitch (front-rear-hps with each side's front and
    /// rear struts pitch-interconnected; docs/layouts.md).
    #[arg(
        long,
        default_value = "rigid,front-hps,front-rear-hps,front-roll,front-rear-roll,front-rear-pitch"
    )]
    pub layouts: String,
    /// The cab and seat of the seat rows: `generic` (docs/layouts.md), `off` (frame rows
    /// only), or `described` (the description's [cab.body] and [seat]). Default: the
    /// description's when it has them, else generic.
    #[arg(long)]
    pub seat: Option<String>,
    /// Speed of the ride the table reports (km/h), 5 to 100; D1 is 20.
    #[arg(long, default_value_t = 20.0)]
    pub speed_kmh: f64,
    /// D4 speeds (km/h), comma separated, strictly ascending, 5 to 100.
    #[arg(long, default_value = "10,15,20,25,30")]
    pub speeds: String,
    /// Load case of the rides (D2 and D3 are loaded by definition).
    #[arg(long, default_value = "loaded")]
    pub load: Load,
    /// Terrain seeds, 1 to 100 (every layout runs on the same seeds).
    #[arg(long, default_value_t = 10)]
    pub seeds: usize,
    /// First terrain seed.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Write an SVG of the operator's a_wz against the speed (D4), one line per row,
    /// with the caution-zone bound.
    #[arg(long)]
    pub plot: Option<PathBuf>,
    /// Replace an existing plot file that afsv did not write.
    #[arg(long)]
    pub force: bool,
    /// Print JSON even on a terminal.
    #[arg(long)]
    pub json: bool,
}

/// The layouts `text` names, built from the described vehicle `v`.
pub(crate) fn build_layouts(
    v: &afsv_vehicle::ArticulatedVehicle,
    text: &str,
) -> Result<Vec<Layout>, String> {
    let mut out: Vec<Layout> = Vec::new();
    for name in text.split(',').map(str::trim) {
        if out.iter().any(|l| l.name == name) {
            return Err(format!("--layouts: `{name}` is named twice"));
        }
        if !LAYOUT_NAMES.iter().any(|(n, _)| *n == name) {
            let known: Vec<&str> = LAYOUT_NAMES.iter().map(|(n, _)| *n).collect();
            return Err(format!(
                "--layouts: unknown layout `{name}` (known: {})",
                known.join(", ")
            ));
        }
        let suspended = name != "rigid";
        let rear = name.starts_with("front-rear");
        let mut params = vehicle_3d::VehicleParams {
            rear_hps: None,
            ..v.params.clone()
        };
        if suspended {
            params.hps = v.front_strut.ok_or_else(|| {
                format!(
                    "--layouts {name}: the vehicle description `{}` gives the front axle no strut (add `strut = \"front-axle\"` or a strut file to its front [[axle]])",
                    v.name
                )
            })?;
        }
        if rear {
            params.rear_hps = Some(match v.params.rear_hps {
                Some(strut) => strut,
                None => params
                    .default_rear_strut()
                    .map_err(|e| format!("--layouts {name}: the default rear strut: {e}"))?,
            });
        }
        out.push(Layout {
            name: name.into(),
            front_axle: if suspended {
                FrontAxle::Suspended
            } else {
                FrontAxle::Rigid
            },
            // the linked layouts take the description's [link] lines when it has a link
            // of their kind, else the generic lines
            front_link: name.ends_with("-roll").then(|| match v.link {
                Some(Link::Roll(line)) => line,
                _ => LineParams::front_axle_roll(),
            }),
            pitch_link: match (name.ends_with("-pitch"), &params.rear_hps, v.link) {
                (true, _, Some(Link::Pitch(lines))) => Some(lines),
                (true, Some(rear), _) => Some(
                    LineParams::side_pitch(rear.a_hr / params.hps.a_hr)
                        .map_err(|e| format!("--layouts {name}: the pitch lines: {e}"))?,
                ),
                _ => None,
            },
            params,
        });
    }
    Ok(out)
}

/// The cab and seat of `--seat`.
pub(crate) fn seat_of(
    v: &afsv_vehicle::ArticulatedVehicle,
    flag: Option<&str>,
) -> Result<Option<CabSeatLayout>, String> {
    match flag {
        Some("off") => Ok(None),
        Some("generic") => Ok(Some(CabSeatLayout::generic())),
        Some("described") => v.cab_seat.map(Some).ok_or_else(|| {
            format!(
                "--seat described: the vehicle description `{}` has no [cab.body] and [seat]",
                v.name
            )
        }),
        Some(other) => Err(format!(
            "--seat: `{other}` is not generic, off or described"
        )),
        None => Ok(Some(v.cab_seat.unwrap_or_else(CabSeatLayout::generic))),
    }
}

/// Run `afsv study layouts`.
pub fn run(a: LayoutArgs) -> CmdResult {
    use afsv_design::layouts::MAX_SEEDS;
    if a.seeds == 0 || a.seeds > MAX_SEEDS {
        return Err(format!("--seeds {}: must be 1 to {MAX_SEEDS}", a.seeds).into());
    }
    let speeds = super::study::parse_list("--speeds", &a.speeds, 50)?;
    let mut guard = OutputGuard::new(a.force);
    if let Some(v) = a
        .vehicle
        .as_deref()
        .filter(|v| super::described::is_file(v))
    {
        guard.input("--vehicle", v)?;
    }
    if let Some(p) = &a.plot {
        guard.output("--plot", p, OutputKind::Svg)?;
    }
    let v = super::described::articulated(a.vehicle.as_deref())?;
    let list = build_layouts(&v, &a.layouts)?;
    let options = LayoutOptions {
        load: a.load,
        ride_speed_kmh: a.speed_kmh,
        sweep_speeds_kmh: speeds,
        seeds: (0..a.seeds as u64)
            .map(|i| a.seed.wrapping_add(i))
            .collect(),
        seat: seat_of(&v, a.seat.as_deref())?,
    };
    let runs = layout_runs(list.len(), &options);
    let progress = afsv::progress::Progress::new("afsv study layouts", "runs", Some(runs));
    let s = layouts(&list, &options, &|d| progress.step(d))?;
    progress.finish();
    if let Some(path) = &a.plot {
        plot(path, &s)?;
    }
    super::study::emit(a.json, &s, || text(&s))
}

/// `mean ± sd` with `d` decimals, `~` after it when the difference from the baseline lies
/// inside the seed spread, `-` when the row has no such measure.
fn cell(r: &LayoutRow, key: &str, v: Option<&vehicle_3d::scenarios::Spread>, d: usize) -> String {
    match v {
        None => "-".into(),
        Some(s) => {
            let mark = if r.inside_seed_spread.contains(&key) {
                "~"
            } else {
                ""
            };
            format!("{:.d$}±{:.d$}{mark}", s.mean, s.sd)
        }
    }
}

/// The study as a table: one row per layout and reading point.
pub(crate) fn text(s: &LayoutStudy) -> String {
    let mut out = format!(
        "Suspension layouts, {} ride at {} km/h on class E (m_c 0.3, 100 m), D2/D3 loaded; mean ± SD over {} terrain seeds\n\n",
        s.load, s.ride_speed_kmh, s.seeds.len()
    );
    out += &format!(
        "  {:<16} {:<5} {:>13} {:>13} {:>12} {:>15} {:>13} {:>7} {:>7} {:<10} {:>9}\n",
        "layout",
        "at",
        "a_wz frame",
        "a_wz seat",
        "SEAT",
        "d_s (m)",
        "SP-DRT",
        "change",
        "ω_z Hz",
        "8 h HGCZ",
        "D4 km/h"
    );
    for r in &s.rows {
        let zone = match r.hgcz_8h {
            perf_measures::iso2631::HgczZone::Below => "below",
            perf_measures::iso2631::HgczZone::Within => "within",
            perf_measures::iso2631::HgczZone::Above => "above",
        };
        let crossing = match (r.d4_crossing.speed_kmh, r.d4_crossing.above_at_lowest) {
            (Some(v), _) => format!("{v:.1}"),
            (None, true) => "below lowest".into(),
            (None, false) => "none".into(),
        };
        out += &format!(
            "  {:<16} {:<5} {:>13} {:>13} {:>12} {:>15} {:>13} {:>6.1}% {:>7.3} {:<10} {:>9}\n",
            r.layout,
            if r.at_seat { "seat" } else { "frame" },
            cell(r, "a_wz_frame", Some(&r.a_wz_frame_m_s2), 3),
            cell(r, "a_wz_seat", r.a_wz_seat_m_s2.as_ref(), 3),
            cell(r, "seat_ratio", r.seat_ratio.as_ref(), 2),
            cell(r, "strut_travel", r.strut_travel_m.as_ref(), 4),
            cell(r, "sp_drt", Some(&r.sp_drt_m_s2), 2),
            r.sp_drt_change_percent,
            r.omega_z_hz,
            zone,
            crossing
        );
    }
    out += &format!(
        "\na_wz in m/s², SP-DRT in m/s²; the HGCZ verdict and the D4 crossing read a_wz where the operator sits (the seat on a seat row, the frame otherwise).\n8 h caution zone {:.2}-{:.2} m/s² (ISO 2631-1 Eq B.1). `~`: the difference from the baseline (the first layout, read at the same point) lies inside the seed spread (less than twice its standard error). change: SP-DRT against the baseline.\n",
        s.hgcz_8h_m_s2.0, s.hgcz_8h_m_s2.1
    );
    out
}

/// The operator's a_wz of every row against the D4 speeds, with the zone's upper bound.
fn plot(path: &std::path::Path, s: &LayoutStudy) -> CmdResult {
    let mut columns: Vec<(String, Vec<f64>, Vec<f64>)> = s
        .rows
        .iter()
        .map(|r| {
            (
                format!(
                    "{} ({})",
                    r.layout,
                    if r.at_seat { "seat" } else { "frame" }
                ),
                s.sweep_speeds_kmh.clone(),
                r.d4_a_wz_m_s2.clone(),
            )
        })
        .collect();
    columns.push((
        "8 h HGCZ upper bound".into(),
        s.sweep_speeds_kmh.clone(),
        vec![s.hgcz_8h_m_s2.1; s.sweep_speeds_kmh.len()],
    ));
    super::study::line_svg(
        path,
        &format!(
            "Layouts: operator a_wz against speed ({}, class E), {} seeds",
            s.load,
            s.seeds.len()
        ),
        "forward speed (km/h)",
        "a_wz (m/s²)",
        &columns,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn layouts_and_seats_are_named_and_bad_names_refused() {
        let v = afsv_vehicle::load_builtin("prototype").unwrap();
        let afsv_vehicle::Vehicle::Articulated(v) = v.vehicle else {
            panic!("the prototype is articulated")
        };
        let l = build_layouts(
            &v,
            "rigid, front-hps,front-rear-hps,front-roll,front-rear-roll,front-rear-pitch",
        )
        .unwrap();
        assert_eq!(l.len(), 6);
        assert_eq!(l[0].front_axle, FrontAxle::Rigid);
        assert!(l[1..].iter().all(|l| l.front_axle == FrontAxle::Suspended));
        let rear: Vec<bool> = l.iter().map(|l| l.params.rear_hps.is_some()).collect();
        assert_eq!(rear, [false, false, true, false, true, true]);
        let link: Vec<bool> = l.iter().map(|l| l.front_link.is_some()).collect();
        assert_eq!(link, [false, false, false, true, true, false]);
        let pitch: Vec<bool> = l.iter().map(|l| l.pitch_link.is_some()).collect();
        assert_eq!(pitch, [false, false, false, false, false, true]);
        assert!(build_layouts(&v, "rigid,rigid")
            .unwrap_err()
            .contains("twice"));
        assert!(build_layouts(&v, "rigid,bogus")
            .unwrap_err()
            .contains("unknown layout `bogus`"));
        assert!(seat_of(&v, Some("off")).unwrap().is_none());
        assert!(seat_of(&v, None).unwrap().is_some());
        assert!(seat_of(&v, Some("soft")).unwrap_err().contains("--seat"));
    }

    #[test]
    fn a_described_link_gives_its_lines_to_the_layouts_of_its_kind() {
        let v = afsv_vehicle::load_builtin("prototype").unwrap();
        let afsv_vehicle::Vehicle::Articulated(mut v) = v.vehicle else {
            panic!("the prototype is articulated")
        };
        let names = "front-hps,front-roll,front-rear-pitch";
        let generic = build_layouts(&v, names).unwrap();
        let roll = LineParams {
            diameter_m: 0.02,
            ..LineParams::front_axle_roll()
        };
        v.link = Some(Link::Roll(roll));
        let l = build_layouts(&v, names).unwrap();
        assert_eq!(l[0].link(), None, "an unlinked layout stays unlinked");
        assert_eq!(l[1].front_link, Some(roll));
        assert_eq!(l[2].pitch_link, generic[2].pitch_link);
        let [front, rear] = generic[2].pitch_link.unwrap();
        let pitch = [
            LineParams {
                diameter_m: 0.03,
                ..front
            },
            rear,
        ];
        v.link = Some(Link::Pitch(pitch));
        let l = build_layouts(&v, names).unwrap();
        assert_eq!(l[1].front_link, generic[1].front_link);
        assert_eq!(l[2].pitch_link, Some(pitch));
    }
}
