//! Unit tests of the figures: what each chart holds, on small synthetic results (one
//! short strut run; no vehicle run).

use super::*;
use crate::report::tire::sweep_rows;
use afsv_plot::Chart;
use vehicle_3d::scenarios::YawSpec;
use vehicle_3d::{FrontAxle, RunRecord};

fn curves(chart: &Chart) -> Vec<&afsv_plot::Curve> {
    match chart {
        Chart::Figure { curves, .. } | Chart::Lines { curves, .. } => curves.iter().collect(),
        Chart::Panels { panels, .. } => panels.iter().flat_map(|p| &p.curves).collect(),
    }
}

#[test]
fn the_ride_psds_are_averaged_over_seeds_weighted_by_wk_and_cut_at_15_hz() {
    let f = vec![0.5, 4.0, 15.0, 20.0];
    let psds = vec![
        (f.clone(), vec![1.0, 2.0, 3.0, 4.0], vec![0.0; 4]),
        (f.clone(), vec![3.0, 4.0, 5.0, 6.0], vec![2.0; 4]),
    ];
    let spec = vehicle_3d::scenarios::RideSpec::d1(vehicle_3d::Load::Loaded, FrontAxle::Rigid);
    let chart = vehicle::ride(&psds, &spec, "rigid", &[1, 2]).unwrap();
    let c = curves(&chart);
    assert_eq!(c[0].x, [0.5, 4.0, 15.0]);
    assert_eq!(c[0].y, [2.0, 3.0, 4.0]);
    let wk = perf_measures::Weighting::Wk.magnitude(4.0).powi(2);
    assert_eq!(c[1].y[1], wk * 3.0);
    assert_eq!(c[2].y, [1.0, 1.0, 1.0]);
    let uneven = vec![psds[0].clone(), (vec![1.0], vec![1.0], vec![1.0])];
    assert!(vehicle::ride(&uneven, &spec, "rigid", &[1, 2]).is_err());
    assert!(vehicle::ride(&[], &spec, "rigid", &[]).is_err());
}

#[test]
fn the_yaw_fit_follows_a_damped_articulation_over_its_window() {
    let spec = YawSpec::d3(FrontAxle::Rigid);
    let t: Vec<f64> = (0..=1000).map(|i| i as f64 * 0.005).collect();
    let start = spec.pulse_start_s + spec.pulse_s;
    let articulation_rad: Vec<f64> = t
        .iter()
        .map(|&x| {
            let tau = (x - start).max(0.0);
            0.05 * (-0.8 * tau).exp() * (2.0 * std::f64::consts::PI * 1.2 * tau).cos()
        })
        .collect();
    let rec = RunRecord {
        t_s: t,
        articulation_rad,
        ..RunRecord::default()
    };
    let chart = vehicle::yaw(&rec, &spec, "rigid", 1).unwrap();
    let c = curves(&chart);
    assert_eq!(c.len(), 3);
    let (fit, data) = (c[1], c[0]);
    let i0 = data.x.iter().position(|&x| x == fit.x[0]).unwrap();
    for (k, y) in fit.y.iter().enumerate() {
        assert!(
            (y - data.y[i0 + k]).abs() < 1e-3,
            "{y} vs {}",
            data.y[i0 + k]
        );
    }
    assert!(fit.x.last().unwrap() - fit.x[0] <= spec.fit_window_s);
    let flat = RunRecord {
        t_s: rec.t_s.clone(),
        articulation_rad: vec![0.0; rec.t_s.len()],
        ..RunRecord::default()
    };
    assert!(vehicle::yaw(&flat, &spec, "rigid", 1).is_err());
}

#[test]
fn the_strut_loops_are_drawn_in_mpa_kn_and_mm() {
    let p = hps_emulsion::StrutParams::front_axle();
    let test = hps_emulsion::HarmonicTest {
        frequency_hz: 2.0,
        amplitude_m: 0.01,
    };
    let opts = hps_emulsion::SimOptions {
        output_rate_hz: 400.0,
        ..hps_emulsion::SimOptions::default()
    };
    let exc = hps_emulsion::Excitation::harmonic(2.0, 0.01, 2.0);
    let rec =
        hps_emulsion::simulate_displacement(&p, &hps_emulsion::HpsExtensions::none(), &exc, &opts)
            .unwrap();
    let chart = strut::loops(&rec, &test, "c").unwrap();
    let c = curves(&chart);
    assert_eq!(c.len(), 5);
    let zmax = c[0].x.iter().fold(0.0f64, |m, z| m.max(z.abs()));
    assert!((zmax - 10.0).abs() < 0.5, "deflection {zmax} mm");
    let pmax = c[0].y.iter().fold(0.0f64, |m, p| m.max(*p));
    assert!(pmax > 0.1 && pmax < 100.0, "piston pressure {pmax} MPa");
    assert!(strut::loops(
        &rec,
        &hps_emulsion::HarmonicTest {
            frequency_hz: 0.1,
            amplitude_m: 0.01
        },
        "c"
    )
    .is_err());
}

#[test]
fn a_tire_sweep_draws_one_curve_per_load_and_other_slip() {
    let tire = tire_fiala::Fiala::new(&tire_fiala::TireParams::nominal()).unwrap();
    let (fzs, kappas, alphas) = ([5e4, 1e5], [0.0], [-5.0, 0.0, 5.0]);
    let rows = sweep_rows(&tire, &fzs, &kappas, &alphas);
    let c_lat = tire::sweep("t", &rows, &fzs, &kappas, &alphas).unwrap();
    let c = curves(&c_lat);
    assert_eq!(c.len(), 2);
    assert_eq!(c[1].x, alphas);
    assert_eq!(c[1].y[2], rows[5].fy_n / 1e3);
    assert_eq!(c[1].label, "Fz = 100 kN, kappa = 0");
    let (kappas, alphas) = ([0.0, 0.1, 0.2], [0.0]);
    let rows = sweep_rows(&tire, &fzs, &kappas, &alphas);
    let c_long = tire::sweep("t", &rows, &fzs, &kappas, &alphas).unwrap();
    assert_eq!(curves(&c_long)[0].x, kappas);
    let one = sweep_rows(&tire, &fzs, &[0.0], &[0.0]);
    assert!(tire::sweep("t", &one, &fzs, &[0.0], &[0.0]).is_err());
    let many: Vec<f64> = (1..=51).map(|i| i as f64 * 1e3).collect();
    let rows = sweep_rows(&tire, &many, &[0.0], &[0.0, 1.0]);
    let e = tire::sweep("t", &rows, &many, &[0.0], &[0.0, 1.0]).unwrap_err();
    assert!(e.contains("51 curves"), "{e}");
}
