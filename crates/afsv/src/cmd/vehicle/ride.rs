//! `afsv vehicle ride`: D1 over terrain seeds or one measured road, with the seat when the
//! vehicle has one.

use super::*;
use afsv_design::vehicle_case::{ride_seed, seat_of_run};

pub(super) fn ride_cmd(
    case: &CaseArgs,
    study: &StudyArgs,
    length_m: f64,
    road: Option<&Path>,
    seat: Option<&str>,
) -> CmdResult {
    if !(10.0..=5000.0).contains(&length_m) {
        return Err(format!("--length-m {}: must be 10 to 5000 m", args::show(length_m)).into());
    }
    if let (Some(_), Some(_)) = (road, &study.plot) {
        return Err(
            "--plot: the ride plot shows seed-mean PSDs of synthesised terrain; not with --road"
                .into(),
        );
    }
    let (p, axle, link) = prepare(case, study)?;
    let layout = vehicle_case::seat_layout(&case.source(), seat)?;
    let speed = case.speed_kmh.unwrap_or(20.0);
    let t_window = vehicle_case::ride_window_start(speed, length_m)?;
    if let Some(road) = road {
        let spec = RideSpec {
            speed_kmh: speed,
            length_m,
            ..RideSpec::d1(case.load, axle)
        };
        let (rec, m, ground) = afsv_design::measured_road::ride(&p, &spec, road, link.as_ref())?;
        let seats: Vec<_> = seat_of_run(&p, &rec, t_window, layout.as_ref())?
            .into_iter()
            .collect();
        return print_ride(
            case,
            study,
            (&spec, &p, link.as_ref()),
            &[m],
            &seats,
            ground,
        );
    }
    let (terrain, seeds) =
        case.terrain_and_seeds(study.seeds, study.seed, Some(TerrainSpec::default()))?;
    let Some(terrain) = terrain else {
        return Err("--terrain smooth: the ride run needs a terrain (class:...)".into());
    };
    let spec = RideSpec {
        speed_kmh: speed,
        length_m,
        terrain,
        ..RideSpec::d1(case.load, axle)
    };
    let want_psd = study.plot.is_some();
    let runs = over_seeds("afsv vehicle ride", &Some(terrain), &seeds, |_, s| {
        let run = (&p, &spec, link.as_ref());
        ride_seed(run, s, t_window, layout.as_ref(), want_psd)
    })?;
    let measures: Vec<RideMeasures> = runs.iter().map(|r| r.0).collect();
    let seats: Vec<SeatRideMeasures> = runs.iter().filter_map(|r| r.2).collect();
    if let Some(path) = &study.plot {
        let psds: Vec<RidePsd> = runs.into_iter().filter_map(|r| r.1).collect();
        let chart = figures::vehicle::ride(&psds, &spec, super::axle_name(axle, &p), &seeds)?;
        super::super::write_chart(path, &chart)?;
    }
    let ground = Ground::terrain(terrain, &seeds, &measures);
    print_ride(
        case,
        study,
        (&spec, &p, link.as_ref()),
        &measures,
        &seats,
        ground,
    )
}

/// The ride's report ([`ride_report`]) with its plot, printed as JSON or text.
fn print_ride(
    case: &CaseArgs,
    study: &StudyArgs,
    (spec, p, link): (&RideSpec, &VehicleParams, Option<&Link>),
    measures: &[RideMeasures],
    seats: &[SeatRideMeasures],
    ground: Ground,
) -> CmdResult {
    let report = ride_report(p, spec, case.paper_form, measures, seats, ground)?;
    print_linked(study.shown(), report, link)
}
