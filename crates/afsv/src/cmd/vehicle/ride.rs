//! `afsv vehicle ride`: D1 over terrain seeds or one measured road, with the seat when the
//! vehicle has one.

use super::*;
use vehicle_3d::interconnect::ride_linked;

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
    let (p, axle) = prepare(case, study)?;
    let link = described_link(case, axle)?;
    let layout = seat::layout(case, seat)?;
    let speed = case.speed_kmh.unwrap_or(20.0);
    let t_window = RUN_IN_M / (speed / 3.6);
    let sim_s = (RUN_IN_M + length_m) / (speed / 3.6);
    if sim_s > MAX_DURATION_S {
        return Err(format!(
            "--length-m {}: the run-in and window take {} s at {speed} km/h, more than {MAX_DURATION_S} s",
            args::show(length_m),
            args::show(sim_s)
        )
        .into());
    }
    if let Some(road) = road {
        let spec = RideSpec {
            speed_kmh: speed,
            length_m,
            ..RideSpec::d1(case.load, axle)
        };
        let (rec, m, ground) = road::ride(&p, &spec, road, link.as_ref())?;
        let seats: Vec<_> = seat::of_run(&p, &rec, t_window, layout.as_ref())?
            .into_iter()
            .collect();
        return ride_report(
            case,
            study,
            (&spec, &p, link.as_ref()),
            &[m],
            &seats,
            ground,
        );
    }
    let (terrain, seeds) =
        terrain_and_seeds(case, study.seeds, study.seed, Some(TerrainSpec::default()))?;
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
    type RideRun = (RideMeasures, Option<RidePsd>, Option<SeatRideMeasures>);
    let runs: Vec<RideRun> = over_seeds("afsv vehicle ride", &Some(terrain), &seeds, |_, s| {
        let (rec, m) = match &link {
            Some(l) => ride_linked(&p, &spec, s, l).map(|(r, m)| (r.record, m)),
            None => scenarios::ride(&p, &spec, s),
        }
        .map_err(|e| e.to_string())?;
        let psd = if want_psd {
            Some(ride_psd(&rec, t_window)?)
        } else {
            None
        };
        Ok((m, psd, seat::of_run(&p, &rec, t_window, layout.as_ref())?))
    })?;
    let measures: Vec<RideMeasures> = runs.iter().map(|r| r.0).collect();
    let seats: Vec<SeatRideMeasures> = runs.iter().filter_map(|r| r.2).collect();
    if let Some(path) = &study.plot {
        let psds: Vec<RidePsd> = runs.into_iter().filter_map(|r| r.1).collect();
        plot_ride(path, &psds, &spec, super::axle_name(axle, &p), &seeds)?;
    }
    let ground = road::Ground {
        json: terrain_json(&Some(terrain), &seeds),
        text: format!(
            "terrain class {}, m_c {} cycles/m",
            terrain.class, terrain.m_c
        ),
        per_run: per_seed(&Some(terrain), &seeds, &measures, NO_STRUT),
    };
    ride_report(
        case,
        study,
        (&spec, &p, link.as_ref()),
        &measures,
        &seats,
        ground,
    )
}

/// The ride's measures over its runs (seeds, or one measured road) as JSON or text.
fn ride_report(
    case: &CaseArgs,
    study: &StudyArgs,
    (spec, p, link): (&RideSpec, &VehicleParams, Option<&Link>),
    measures: &[RideMeasures],
    seats: &[SeatRideMeasures],
    ground: road::Ground,
) -> CmdResult {
    let (axle, speed, length_m) = (spec.front_axle, spec.speed_kmh, spec.length_m);
    let a_wz = spread(measures, |m| m.a_wz_m_s2)?;
    let a_z = spread(measures, |m| m.a_z_rms_m_s2)?;
    let vertical = spread(measures, |m| m.vertical_peak_hz)?;
    let pitch = spread(measures, |m| m.pitch_peak_hz)?;
    let travel = match axle {
        FrontAxle::Rigid => None,
        FrontAxle::Suspended => Some(spread(measures, |m| {
            m.strut_travel_p2p_m.unwrap_or(f64::NAN)
        })?),
    };
    let rear_travel = if measures.iter().all(|m| m.rear_strut_travel_p2p_m.is_some()) {
        Some(spread(measures, |m| {
            m.rear_strut_travel_p2p_m.unwrap_or(f64::NAN)
        })?)
    } else {
        None
    };
    let zone = health_guidance_zone(HGCZ_HOURS, HgczRelation::SqrtTime)?;
    let verdict = zone.classify(a_wz.mean);
    let mut v = json!({
        "scenario": "ride (D1, section 6.4)",
        "load": case.load,
        "front_axle": axle,
        "rear_axle": super::rear_axle(p),
        "yaw_inertia_form": options::yaw_inertia_form(case.paper_form),
        "speed_kmh": speed,
        "run_in_m": RUN_IN_M,
        "length_m": length_m,
        "terrain": ground.json,
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
        "per_seed": ground.per_run,
    });
    if travel.is_none() {
        v["strut_travel_p2p_m_reason"] = json!(NO_STRUT);
    }
    if let Some(t) = &rear_travel {
        v["rear_strut_travel_p2p_m"] = json!(t);
    }
    if let Some(plot) = &study.plot {
        v["plot"] = json!(plot);
    }
    let verdict_text = match verdict {
        perf_measures::iso2631::HgczZone::Below => "below the zone",
        perf_measures::iso2631::HgczZone::Within => "within the zone (caution)",
        perf_measures::iso2631::HgczZone::Above => "above the zone (health risk likely)",
    };
    let mut text = header_text("ride D1", case, (axle, p), speed, measures.len());
    text += &format!(
        "{}, {length_m} m after a {RUN_IN_M} m run-in\n",
        ground.text
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
    if let Some(t) = &rear_travel {
        text += &spread_text("rear HPS travel peak-to-peak", t, "m");
    }
    text += &spread_text("dominant vertical frequency", &vertical, "Hz");
    text += &spread_text("dominant pitch frequency", &pitch, "Hz");
    seat::report(seats, &mut v, &mut text)?;
    print_linked(study.json, v, &text, link)
}
