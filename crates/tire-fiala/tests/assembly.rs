//! The tire assembly against hand calculations: the static load on a plane, free rolling,
//! mirror symmetry, lift-off, the two handling laws term by term, an incline, the path
//! coordinate on its track, and the constructors' checks.

use std::sync::Arc;

use nalgebra::Vector3;
use tire_fiala::{
    Contact, EffectiveTrack, Envelope, EnvelopeMethod, Fiala, FialaLaw, HandlingLaw, HandlingModel,
    LinearCorneringLaw, LoadDeflectionTable, PathFrame, Profile, Relaxation, TireAssembly,
    TireInput, TireParams, TireTrack, VerticalContact, Wheel,
};
use vehicle_components::Component;

/// Static deflection (m) the tracks are built at.
const REFERENCE: f64 = 0.1;
/// Linear spring and damper of the Chapter 2 law's tests (N/m, N s/m).
const K_T: f64 = 1.8e6;
const C_T: f64 = 6.0e3;
/// Chapter 2 coefficient (1/rad) and relaxation length (m).
const COEFFICIENT: f64 = 0.4;
const SIGMA: f64 = 0.6;

fn track<P: Profile>(profile: &P, method: EnvelopeMethod) -> TireTrack {
    let envelope = Envelope::new(method, 1.0, 0.01).unwrap();
    TireTrack::Static(
        EffectiveTrack::build(profile, (-5.0, 30.0), 0.05, &envelope, REFERENCE).unwrap(),
    )
}

fn fiala_tires(tracks: Arc<[TireTrack]>) -> TireAssembly {
    let p = TireParams::nominal();
    let law = HandlingLaw::Fiala(FialaLaw::new(&p).unwrap());
    TireAssembly::new(
        tracks,
        &[0],
        1.0,
        VerticalContact::from_params(&p).unwrap(),
        law,
    )
    .unwrap()
}

fn linear_tires(tracks: Arc<[TireTrack]>) -> TireAssembly {
    let vertical = VerticalContact::new(LoadDeflectionTable::linear(K_T).unwrap(), C_T).unwrap();
    let law = HandlingLaw::LinearCornering(LinearCorneringLaw::new(COEFFICIENT, SIGMA).unwrap());
    TireAssembly::new(tracks, &[0], 1.0, vertical, law).unwrap()
}

/// Both laws on level ground at height `ground` (m).
fn on_level(ground: f64) -> [TireAssembly; 2] {
    let tracks: Arc<[TireTrack]> = Arc::new([track(&|_: f64| ground, EnvelopeMethod::TandemCams)]);
    [fiala_tires(tracks.clone()), linear_tires(tracks)]
}

/// The path along +x from the origin, coordinate 0 there.
const PATH: PathFrame = PathFrame {
    direction: Vector3::new(1.0, 0.0, 0.0),
    origin: Vector3::new(0.0, 0.0, 0.0),
    coordinate: 0.0,
};

fn wheel(x: f64, z: f64, v: [f64; 3], psi: f64, spin: f64) -> Wheel {
    Wheel {
        centre: Vector3::new(x, 0.7, z),
        velocity: Vector3::from(v),
        heading: psi.sin_cos(),
        axle: Vector3::new(-psi.sin(), psi.cos(), 0.0),
        spin,
    }
}

/// Contact and handling of tire 0 with lag states `state`.
fn run(
    tires: &TireAssembly,
    w: Wheel,
    state: &[f64],
    drive_force: f64,
) -> (Contact, tire_fiala::TireOutput, Vec<f64>) {
    let contact = tires.contact(0, &w, &PATH, None);
    let mut d = vec![0.0; state.len()];
    let input = TireInput {
        wheel: w,
        contact,
        drive_force,
    };
    let out = tires.evaluate(&input, state, &mut d);
    (contact, out, d)
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * (1.0 + a.abs().max(b.abs()))
}

#[test]
fn a_wheel_at_rest_on_a_plane_carries_its_static_load_straight_down() {
    for tires in on_level(0.3) {
        let n = tires.n_states();
        // centre one loaded radius above the ground: deflection exactly the reference
        let (c, out, d) = run(
            &tires,
            wheel(4.0, 1.2, [0.0; 3], 0.0, 0.0),
            &[0.0; 2][..n],
            0.0,
        );
        let load = tires.vertical().load_deflection().load(REFERENCE);
        assert!(close(c.track.deflection, REFERENCE, 1e-12), "{c:?}");
        assert_eq!((c.track.slope, c.deflection_rate), (0.0, 0.0));
        assert!(close(out.force.z, load, 1e-9) && load > 0.0, "{out:?}");
        assert_eq!((out.force.x, out.force.y), (0.0, 0.0));
        // applied on the ground under the centre, no moment at rest
        assert!(close(out.point.z, 0.3, 1e-12) && out.point.x == 4.0 && out.point.y == 0.7);
        assert!(out.moment.iter().all(|m| *m == 0.0));
        assert!(d.iter().all(|r| *r == 0.0), "{d:?}");
    }
}

#[test]
fn free_rolling_has_no_slip_and_resists_the_spin() {
    let [fiala, linear] = on_level(0.0);
    let v = [10.0, 0.0, 0.0];
    let (_, out, d) = run(
        &fiala,
        wheel(6.0, 0.9, v, 0.0, 10.0 / 0.9),
        &[0.0, 0.0],
        0.0,
    );
    assert!(
        out.contact.slip_steady[0].abs() < 1e-12,
        "{:?}",
        out.contact
    );
    assert_eq!(out.contact.slip_steady[1], 0.0);
    assert!(out.force.x.abs() < 1e-9 && out.force.y.abs() < 1e-9);
    assert!(d.iter().all(|r| r.abs() < 1e-10), "{d:?}");
    // rolling resistance: about the axle (+y), against the forward spin
    assert!(
        out.moment.y < 0.0 && out.moment.x == 0.0,
        "{:?}",
        out.moment
    );
    let (_, out, d) = run(&linear, wheel(6.0, 0.9, v, 0.0, 0.0), &[0.0], 0.0);
    assert_eq!((out.force.x, out.force.y, d[0]), (0.0, 0.0, 0.0));
    assert!(out.force.z > 0.0);
}

#[test]
fn mirrored_motion_gives_mirrored_forces_under_both_laws() {
    for tires in on_level(0.0) {
        let fiala = tires.n_states() == 2;
        let state = if fiala { vec![0.02, 0.03] } else { vec![0.25] };
        let mirror: Vec<f64> = if fiala {
            vec![0.02, -0.03]
        } else {
            vec![-0.25]
        };
        for (vy, vz) in [(0.3, -0.05), (1.7, 0.2), (-0.4, 0.0)] {
            let (_, a, da) = run(
                &tires,
                wheel(3.0, 0.88, [9.0, vy, vz], 0.0, 10.5),
                &state,
                2e3,
            );
            let (_, b, db) = run(
                &tires,
                wheel(3.0, 0.88, [9.0, -vy, vz], 0.0, 10.5),
                &mirror,
                2e3,
            );
            assert_eq!(b.force.x, a.force.x);
            assert_eq!(b.force.y, -a.force.y);
            assert_eq!(b.force.z, a.force.z);
            assert_eq!(b.moment.z, -a.moment.z);
            assert_eq!(b.contact.slip_steady[1], -a.contact.slip_steady[1]);
            let sign = if fiala { [1.0, -1.0] } else { [-1.0, 0.0] };
            for k in 0..da.len() {
                assert_eq!(db[k], sign[k] * da[k]);
            }
            assert!(a.force.iter().chain(&a.moment).all(|f| f.is_finite()));
        }
    }
    // a wheel sliding left gets a force to the right
    let [fiala, linear] = on_level(0.0);
    let (_, f, _) = run(
        &fiala,
        wheel(3.0, 0.88, [9.0, 0.5, 0.0], 0.0, 10.0),
        &[0.0, -0.05],
        0.0,
    );
    let (_, l, _) = run(
        &linear,
        wheel(3.0, 0.88, [9.0, 0.5, 0.0], 0.0, 0.0),
        &[0.5],
        0.0,
    );
    assert!(f.force.y < 0.0 && l.force.y < 0.0);
}

#[test]
fn a_lifted_tire_transmits_nothing() {
    for tires in on_level(0.0) {
        let n = tires.n_states();
        let w = wheel(2.0, 1.05, [8.0, 0.6, 1.0], 0.2, 9.0);
        let (c, out, d) = run(&tires, w, &[0.1, 0.1][..n], 0.0);
        assert!(c.track.deflection < 0.0 && c.normal_force == 0.0, "{c:?}");
        assert_eq!(out.force, Vector3::zeros());
        assert_eq!(out.moment, Vector3::zeros());
        assert!(d.iter().all(|r| r.is_finite()));
        // off the ground by the margin too; the frozen lifted piece is zero
        assert!(tires.contact_margin(&c) <= c.track.deflection);
        assert_eq!(tires.contact(0, &w, &PATH, Some(false)).normal_force, 0.0);
    }
    // Eq 2.1's in-contact piece extended past lift-off: k delta + c delta', negative here
    let [_, linear] = on_level(0.0);
    let w = wheel(2.0, 0.905, [8.0, 0.0, -0.5], 0.0, 0.0);
    let free = linear.contact(0, &w, &PATH, None);
    let frozen = linear.contact(0, &w, &PATH, Some(true));
    let delta = free.track.deflection;
    assert!(close(delta, 0.095, 1e-12) && free.deflection_rate == 0.5);
    assert_eq!(frozen.normal_force, K_T * delta + C_T * 0.5);
    assert!(close(free.normal_force, frozen.normal_force, 1e-12));
    let lifted = linear.contact(
        0,
        &wheel(2.0, 1.2, [8.0, 0.0, 0.5], 0.0, 0.0),
        &PATH,
        Some(true),
    );
    assert_eq!(
        lifted.normal_force,
        K_T * lifted.track.deflection + C_T * -0.5
    );
    assert!(lifted.normal_force < 0.0);
    // the margin: min(delta, delta + (c/k) delta')
    let m = linear.contact_margin(&free);
    assert_eq!(m, delta.min(delta + (C_T / K_T) * 0.5));
}

#[test]
fn the_linear_cornering_law_is_eqs_2_5_to_2_7() {
    let [_, tires] = on_level(0.0);
    let (v, lag, drive) = ([7.0, 0.35, 0.0], 0.2, 3.0e3);
    let (c, out, d) = run(&tires, wheel(1.0, 0.92, v, 0.0, 0.0), &[lag], drive);
    let u = 7.0_f64.hypot(0.1);
    let fz = c.normal_force;
    assert!(close(fz, K_T * 0.08, 1e-9), "{fz}");
    let fy = -COEFFICIENT * fz * (lag / u).atan();
    assert_eq!(out.contact.fy, fy);
    assert_eq!(out.contact.fx, drive);
    assert_eq!(d[0], (0.35 - lag) * u / SIGMA);
    assert_eq!(out.force, Vector3::new(drive, fy, fz));
    // at rest at the lateral velocity: the initial state
    let mut s0 = [0.0];
    let input = TireInput {
        wheel: wheel(1.0, 0.92, v, 0.0, 0.0),
        contact: c,
        drive_force: drive,
    };
    tires.initial_state(&input, &mut s0);
    assert_eq!(s0, [0.35]);
}

#[test]
fn the_fiala_law_is_section_6_2_2_with_the_lags_of_eq_3_16() {
    let [tires, _] = on_level(0.0);
    let p = TireParams::nominal();
    let (fiala, relax) = (
        Fiala::new(&p).unwrap(),
        Relaxation::from_params(&p).unwrap(),
    );
    let (v, spin, state) = ([8.0, 0.4, -0.05], 8.5, [0.02, -0.01]);
    let (c, out, d) = run(&tires, wheel(12.3, 0.93, v, 0.0, spin), &state, 0.0);
    let delta = c.track.deflection;
    assert!(close(delta, 0.07, 1e-12), "{delta}");
    // Eq 2.1 with the load curve; the rate with the line fixed: -v_z
    assert_eq!(c.deflection_rate, 0.05);
    let fz = tires.vertical().normal_force(delta, 0.05);
    assert_eq!(c.normal_force, fz);
    let u = 8.0_f64.hypot(0.1);
    let steady = [(8.5 * (1.0 - delta) - 8.0) / u, -(0.4 / u).atan()];
    assert_eq!(out.contact.slip_steady, steady);
    assert_eq!(d, relax.rates(state, steady, 8.0));
    let f = fiala.forces(fz, 0.02, -0.01);
    assert_eq!((out.contact.fx, out.contact.fy), (f.fx, f.fy));
    assert_eq!(out.force, Vector3::new(f.fx, f.fy, fz));
    let rolling = (8.5f64 / 0.1).tanh();
    assert_eq!(out.moment, Vector3::new(0.0, f.my * rolling, -f.mz));
    assert!(close(out.point.z, 0.0, 1e-12));
    let mut s0 = [0.0; 2];
    let input = TireInput {
        wheel: wheel(12.3, 0.93, v, 0.0, spin),
        contact: c,
        drive_force: 0.0,
    };
    tires.initial_state(&input, &mut s0);
    assert_eq!(s0, steady);
}

#[test]
fn the_heading_rotates_the_wheel_axes() {
    for tires in on_level(0.0) {
        let n = tires.n_states();
        let state = [0.01, 0.03];
        let (_, straight, d0) = run(
            &tires,
            wheel(5.0, 0.92, [6.0, -0.3, 0.0], 0.0, 6.2),
            &state[..n],
            1e3,
        );
        let psi: f64 = 0.7;
        let (s, c) = psi.sin_cos();
        let v = [6.0 * c + 0.3 * s, 6.0 * s - 0.3 * c, 0.0];
        let (_, turned, d1) = run(&tires, wheel(5.0, 0.92, v, psi, 6.2), &state[..n], 1e3);
        let (fx, fy) = (straight.force.x, straight.force.y);
        assert!(close(turned.force.x, fx * c - fy * s, 1e-9));
        assert!(close(turned.force.y, fx * s + fy * c, 1e-9));
        assert!(close(turned.force.z, straight.force.z, 1e-12));
        for k in 0..n {
            assert!(close(d1[k], d0[k], 1e-9));
        }
    }
}

#[test]
fn on_an_incline_both_laws_push_along_the_slope() {
    // ground z = 0.1 x: slope atan(0.1), normal (-sin, 0, cos)
    let grade = |x: f64| 0.1 * x;
    let tracks: Arc<[TireTrack]> = Arc::new([track(&grade, EnvelopeMethod::CircleLine)]);
    let theta = 0.1_f64.atan();
    let (sin, cos) = theta.sin_cos();
    for tires in [fiala_tires(tracks.clone()), linear_tires(tracks.clone())] {
        let n = tires.n_states();
        let (x, lift) = (10.0, 1.0 - 0.06);
        // the centre one loaded radius above the ground, along the normal
        let w = wheel(
            x - sin * lift,
            grade(x) + cos * lift,
            [5.0, 0.0, 0.5],
            0.0,
            5.0 / lift,
        );
        let (c, out, _) = run(&tires, w, &[0.05, 0.0][..n], 4e3);
        assert!(close(c.track.slope, theta, 1e-6), "{c:?}");
        assert!(close(c.track.deflection, 0.06, 1e-6), "{c:?}");
        // moving along the slope: no deflection rate
        assert!(c.deflection_rate.abs() < 1e-6, "{c:?}");
        let along = out.force.x * cos + out.force.z * sin;
        let normal = -out.force.x * sin + out.force.z * cos;
        assert!(close(normal, c.normal_force, 1e-9), "{out:?}");
        assert!(close(along, out.contact.fx, 1e-9), "{out:?}");
        assert!(out.contact.fx > 0.0);
        assert!(close(out.point.z, grade(out.point.x), 1e-6));
    }
}

#[test]
fn the_contact_is_the_tracks_at_the_wheels_path_coordinate() {
    // a 0.1 m step at s = 10 under a path along (0.6, 0.8), coordinate 3 at (1, 2)
    let step = |s: f64| if s >= 10.0 { 0.1 } else { 0.0 };
    let tracks: Arc<[TireTrack]> = Arc::new([
        track(&|_: f64| 0.0, EnvelopeMethod::TandemCams),
        track(&step, EnvelopeMethod::TandemCams),
    ]);
    let cached = &tracks[1];
    let p = TireParams::nominal();
    let law = HandlingLaw::Fiala(FialaLaw::new(&p).unwrap());
    let tires = TireAssembly::new(
        Arc::clone(&tracks),
        &[0, 1, 1],
        1.0,
        VerticalContact::from_params(&p).unwrap(),
        law,
    )
    .unwrap();
    let path = PathFrame {
        direction: Vector3::new(0.6, 0.8, 0.0),
        origin: Vector3::new(1.0, 2.0, 0.4),
        coordinate: 3.0,
    };
    for k in 0..40 {
        let along = 4.0 + 0.1 * k as f64;
        let centre = Vector3::new(1.0 + 0.6 * along, 2.0 + 0.8 * along, 0.95);
        let w = Wheel {
            centre,
            ..wheel(0.0, 0.0, [3.0, 4.0, 0.0], 0.9, 5.0)
        };
        let s = 3.0 + along;
        let c = tires.contact(2, &w, &path, None);
        let expected = cached.contact(s, 0.95);
        assert!(
            close(c.track.deflection, expected.deflection, 1e-12),
            "{c:?}"
        );
        assert!(close(c.track.slope, expected.slope, 1e-12), "{c:?}");
        // tire 0 reads the level track
        assert!(close(
            tires.contact(0, &w, &path, None).track.deflection,
            0.05,
            1e-12
        ));
    }
}

#[test]
fn the_constructors_name_the_bad_field() {
    let p = TireParams::nominal();
    let tracks: Arc<[TireTrack]> = Arc::new([track(&|_: f64| 0.0, EnvelopeMethod::CircleLine)]);
    let law = || HandlingLaw::Fiala(FialaLaw::new(&p).unwrap());
    let vertical = || VerticalContact::from_params(&p).unwrap();
    let refused = |track_of: &[usize], radius: f64| {
        TireAssembly::new(tracks.clone(), track_of, radius, vertical(), law())
            .unwrap_err()
            .to_string()
    };
    // no tire, more than MAX_TIRES, a track that is not there, a radius of zero
    for track_of in [&[][..], &[0; 9], &[0, 1]] {
        let e = refused(track_of, 1.0);
        assert!(e.contains("track_of"), "{e}");
    }
    let e = refused(&[0], 0.0);
    assert!(e.contains("unloaded_radius_m"), "{e}");
    let e = LinearCorneringLaw::new(-1.0, 0.6).unwrap_err().to_string();
    assert!(e.contains("cornering_coefficient_per_rad"), "{e}");
    let e = LinearCorneringLaw::new(0.4, f64::NAN)
        .unwrap_err()
        .to_string();
    assert!(e.contains("relaxation_length_m"), "{e}");
    let bad = TireParams {
        lateral_relaxation_length_m: 0.0,
        ..TireParams::nominal()
    };
    assert!(FialaLaw::new(&bad)
        .unwrap_err()
        .to_string()
        .contains("lateral_relaxation_length_m"));
    // the component's states and channels
    let tires = TireAssembly::new(tracks.clone(), &[0, 0, 0, 0], 1.0, vertical(), law()).unwrap();
    assert_eq!((tires.len(), tires.n_states()), (4, 2));
    assert_eq!(linear_tires(tracks).n_states(), 1);
    let (_, out, _) = run(
        &tires,
        wheel(1.0, 0.9, [5.0, 0.1, 0.0], 0.0, 5.0),
        &[0.0, 0.0],
        0.0,
    );
    let mut row = vec![f64::NAN; tires.channels().len()];
    tires.record(&out, &mut row);
    assert_eq!(row[..3], [out.force.x, out.force.y, out.force.z]);
    assert!(row.iter().all(|v| v.is_finite()));
}
