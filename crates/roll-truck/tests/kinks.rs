//! Kinks located as events (`RunOptions::locate_kinks`, docs/numerics.md, "Kinks"): every
//! restart sits on the edge of the switch that crossed, and the runs agree with a
//! tight-tolerance run of the force laws as written.

use roll_truck::simulate::{simulate_with_stats, tire_state, RunStats};
use roll_truck::studies::{rough_terrain, truck_on};
use roll_truck::vehicle::{Pieces, SWITCHES, SWITCH_HYSTERESIS_M};
use roll_truck::{RunOptions, RunRecord, SteerDirection, TruckParams, TruckVehicle};
use terrain_psd::TwoTrackSpec;

/// The nominal truck on class E terrain (seed 1): bump stops and lift-offs from the first
/// seconds on.
fn rough_truck() -> TruckVehicle {
    let p = TruckParams::nominal();
    let terrain = rough_terrain(&p, &TwoTrackSpec::paper_nominal(), 200.0, 1).unwrap();
    truck_on(&p, &terrain, SteerDirection::Left, 150.0).unwrap()
}

fn options(rtol: f64, locate_kinks: bool) -> RunOptions {
    RunOptions {
        t_end_s: 8.0,
        rtol,
        locate_kinks,
        ..RunOptions::default()
    }
}

/// Switching function `i` of `pieces` at `(t, y)` without the hysteresis (m): the distance
/// inside the piece's range, recomputed from the public parts.
fn switch_value(v: &TruckVehicle, t: f64, y: &[f64], pieces: &Pieces, i: usize) -> f64 {
    if i < 4 {
        let s = v.suspension().compressions(&[y[7], y[8], y[9], y[10]]);
        v.suspension().strut(i).switching(s[i], pieces.stops[i])
    } else {
        let w = tire_state(v, t, y).unwrap().contact_margin[i - 4];
        if pieces.contact[i - 4] {
            w
        } else {
            -w
        }
    }
}

/// Largest differences of run `a` from the reference `b` over the common samples: roll
/// (rad), a_y (m/s²), tire load (N).
///
/// The tire load jumps at a touchdown by `c_t` times the impact speed (Eq 2.1: 9 kN at
/// 1.5 m/s), so a sample between the two runs' touchdown instants differs by the jump
/// however close the instants are. The load is compared where both runs have the tire in
/// the same contact state; where they differ, the reference must change state within one
/// sample of it (the touchdown or lift-off is at most one sample interval, 10 ms, apart).
fn differences(a: &RunRecord, b: &RunRecord) -> [f64; 3] {
    assert_eq!(a.t_s.len(), b.t_s.len());
    let n = a.t_s.len();
    let mut e = [0.0_f64; 3];
    for i in 0..n {
        e[0] = e[0].max((a.roll_rad[i] - b.roll_rad[i]).abs());
        e[1] = e[1].max((a.lateral_accel_m_s2[i] - b.lateral_accel_m_s2[i]).abs());
        for (fa, fb) in a.normal_force_n.iter().zip(&b.normal_force_n) {
            let contact = |f: &[f64], j: usize| f[j] > 0.0;
            if contact(fa, i) == contact(fb, i) {
                e[2] = e[2].max((fa[i] - fb[i]).abs());
            } else {
                let near = [i.saturating_sub(1), (i + 1).min(n - 1)];
                assert!(
                    near.iter().any(|&j| contact(fb, j) != contact(fb, i)),
                    "contact states differ at {} s, not beside a transition of the reference",
                    a.t_s[i]
                );
            }
        }
    }
    e
}

#[test]
fn every_restart_sits_on_the_edge_of_the_switch_that_crossed() {
    let v = rough_truck();
    let (_, stats): (_, RunStats) = simulate_with_stats(&v, &options(1e-4, true)).unwrap();
    let located: Vec<_> = stats
        .restarts
        .iter()
        .filter(|r| r.switch.is_some())
        .collect();
    let (mut struts, mut tires) = (0, 0);
    for r in &located {
        let i = r.switch.unwrap();
        assert!(i < SWITCHES);
        // the crossing is located to 1e-10 s where the switch is the hysteresis beyond its
        // edge; switching speeds are below 1 m/s
        let g = switch_value(&v, r.t_s, &r.state, &r.before, i);
        assert!(
            (g + SWITCH_HYSTERESIS_M).abs() < 1e-9,
            "switch {i} at {} s: {g:e} m from its edge",
            r.t_s
        );
        // the new pieces hold there, and the switch that crossed changed piece
        let on_new = switch_value(&v, r.t_s, &r.state, &r.after, i);
        assert!(on_new > 0.0, "switch {i} at {} s: {on_new:e}", r.t_s);
        assert_ne!(r.before, r.after);
        if i < 4 {
            assert_ne!(r.before.stops[i], r.after.stops[i]);
            struts += 1;
        } else {
            assert_ne!(r.before.contact[i - 4], r.after.contact[i - 4]);
            tires += 1;
        }
    }
    assert!(
        struts >= 10 && tires >= 10,
        "{struts} stop and {tires} tire kinks"
    );
    // crossings that came back inside one step, caught at the next output sample, are rare
    let caught = stats.restarts.len() - located.len();
    assert!(
        caught * 20 <= located.len(),
        "{caught} of {}",
        located.len()
    );
    assert_eq!(stats.integration.events, located.len());
}

#[test]
fn runs_between_kinks_agree_with_a_tight_run_of_the_laws_as_written() {
    let v = rough_truck();
    let (reference, _) = simulate_with_stats(&v, &options(1e-8, false)).unwrap();
    // at a tight tolerance the located kinks reproduce the laws as written
    let (tight, stats) = simulate_with_stats(&v, &options(1e-8, true)).unwrap();
    assert!(stats.restarts.len() > 20);
    let e = differences(&tight, &reference);
    assert!(e[0] < 1e-6 && e[1] < 1e-4 && e[2] < 20.0, "{e:?}");
    // at the default tolerance both ways stay within the same small errors
    for locate_kinks in [true, false] {
        let (run, _) = simulate_with_stats(&v, &options(1e-4, locate_kinks)).unwrap();
        let e = differences(&run, &reference);
        assert!(
            e[0] < 2e-3 && e[1] < 2e-2 && e[2] < 5e3,
            "locate_kinks {locate_kinks}: {e:?}"
        );
    }
    // a run with the kinks located leaves the laws as written behind it
    let fresh = simulate_with_stats(&rough_truck(), &options(1e-4, false)).unwrap();
    let again = simulate_with_stats(&v, &options(1e-4, false)).unwrap();
    assert_eq!(fresh, again);
}
