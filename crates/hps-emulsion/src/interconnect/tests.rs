//! Physics tests of the interconnection (docs/layouts.md, "Interconnected struts" and
//! "Pitch interconnection"): statics, the quasi-static bounce, roll and pitch stiffness
//! against the hand-derived formula, energy, mirror symmetry, parameter checks. Together
//! about a second in release.

use super::*;
use crate::extensions::HpsExtensions;
use odeint::{Integrator, OdeSystem, Solver};

fn table_6_3_pair() -> CrossCoupledPair {
    let sealed = sealed_piston(&StrutParams::front_axle());
    let s = HpsStrut::ported(&sealed, &HpsExtensions::default()).unwrap();
    CrossCoupledPair::new([s.clone(), s], &LineParams::front_axle_roll()).unwrap()
}

/// Area ratio of the prototype's rear strut to its front strut (the loaded rear-to-front
/// strut load ratio, docs/layouts.md "HPS on any axle").
const REAR_RATIO: f64 = 1.457;

/// The Table 6.3 strut and the rear strut similar to it at `REAR_RATIO` (areas and volumes
/// scaled, pressures and oil kept: the similitude of `vehicle_3d::suspension::scaled_strut`
/// without its friction, which the stiffness leaves out).
fn front_and_rear() -> [StrutParams; 2] {
    let f = StrutParams::front_axle();
    let r = REAR_RATIO;
    let rear = StrutParams {
        a_hc: r * f.a_hc,
        a_hr: r * f.a_hr,
        a_b: r * f.a_b,
        a_v: r * f.a_v,
        v_g0: r * f.v_g0,
        v_c0: r * f.v_c0,
        v_r0: r * f.v_r0,
        ..f
    };
    [f, rear]
}

/// One side's pitch pair: the sealed front strut (strut 0) and the sealed rear strut
/// (strut 1), cross-connected by the generic pitch lines.
fn pitch_pair() -> CrossCoupledPair {
    let ext = HpsExtensions::default();
    let struts = front_and_rear().map(|p| HpsStrut::ported(&sealed_piston(&p), &ext).unwrap());
    let lines = LineParams::side_pitch(REAR_RATIO).unwrap();
    CrossCoupledPair::with_lines(struts, [&lines[0], &lines[1]]).unwrap()
}

/// Two struts driven by prescribed deflections `z_i(t) = dz_i (1 - cos(pi t / T)) / 2` for
/// `t < T`, then held: a slow ramp from rest.
enum Driven<'a> {
    /// The cross-coupled pair.
    Coupled(&'a CrossCoupledPair),
    /// Two independent struts (plain, without lines).
    Independent([&'a HpsStrut; 2]),
}

struct Ramp<'a> {
    pair: Driven<'a>,
    dz: [f64; 2],
    t_ramp: f64,
}

impl Ramp<'_> {
    fn motion(&self, t: f64) -> ([f64; 2], [f64; 2]) {
        let w = std::f64::consts::PI / self.t_ramp;
        let (s, sd) = if t < self.t_ramp {
            (0.5 * (1.0 - (w * t).cos()), 0.5 * w * (w * t).sin())
        } else {
            (1.0, 0.0)
        };
        (self.dz.map(|d| d * s), self.dz.map(|d| d * sd))
    }

    /// Pressure forces (Eq 5.1 without the seal friction) of both struts.
    fn forces(&self, t: f64, y: &[f64]) -> [f64; 2] {
        let mut d = vec![0.0; y.len()];
        let (z, zd) = self.motion(t);
        match self.pair {
            Driven::Coupled(p) => p
                .evaluate(z, zd, y, &mut d)
                .struts
                .map(|o| o.force - o.friction),
            Driven::Independent(s) => {
                let n0 = s[0].n_states();
                let o0 = s[0].evaluate(z[0], zd[0], &y[..n0], &mut d[..n0]);
                let o1 = s[1].evaluate(z[1], zd[1], &y[n0..], &mut d[n0..]);
                [o0.force - o0.friction, o1.force - o1.friction]
            }
        }
    }
}

impl OdeSystem for Ramp<'_> {
    fn dim(&self) -> usize {
        match self.pair {
            Driven::Coupled(p) => p.n_states(),
            Driven::Independent(s) => s[0].n_states() + s[1].n_states(),
        }
    }
    fn rhs(&self, t: f64, y: &[f64], dydt: &mut [f64]) {
        let (z, zd) = self.motion(t);
        match self.pair {
            Driven::Coupled(p) => {
                p.evaluate(z, zd, y, dydt);
            }
            Driven::Independent(s) => {
                let n0 = s[0].n_states();
                s[0].evaluate(z[0], zd[0], &y[..n0], &mut dydt[..n0]);
                s[1].evaluate(z[1], zd[1], &y[n0..], &mut dydt[n0..]);
            }
        }
    }
    fn is_stiff(&self) -> bool {
        true
    }
}

/// Pressure forces of both struts after the ramp to `dz` from the rest state `y0`.
fn force_after(pair: Driven<'_>, y0: &[f64], dz: [f64; 2]) -> [f64; 2] {
    let ramp = Ramp {
        pair,
        dz,
        t_ramp: 2.0,
    };
    let t_end = 2.5;
    let mut last = vec![0.0; y0.len()];
    Integrator::new(Solver::Rosenbrock23, 1e-9, 1e-12)
        .integrate(&ramp, 0.0, y0, &[t_end], |_, y| {
            last.copy_from_slice(y);
            odeint::Control::Continue
        })
        .unwrap();
    ramp.forces(t_end, &last)
}

/// Quasi-static stiffness per strut (N/m) of the motion `shape` (bounce `[1, 1]`, roll or
/// pitch `[1, -1]`), the Rayleigh quotient `u^T dF / (u^T u dz)` of both struts' forces by
/// a central difference over +-0.5 mm ramps.
fn stiffness(pair: impl Fn() -> Driven<'static>, y0: &[f64], shape: [f64; 2]) -> f64 {
    let d = 5e-4;
    let up = force_after(pair(), y0, shape.map(|s| s * d));
    let down = force_after(pair(), y0, shape.map(|s| -s * d));
    let work: f64 = (0..2).map(|k| shape[k] * (up[k] - down[k])).sum();
    work / (2.0 * d * (shape[0] * shape[0] + shape[1] * shape[1]))
}

#[test]
fn at_rest_every_pressure_is_equal_and_nothing_moves() {
    let pair = table_6_3_pair();
    let p_s = 5.6e6;
    let mut y = vec![0.0; pair.n_states()];
    pair.rest_state(p_s, &mut y).unwrap();
    let mut d = vec![1.0; y.len()];
    let out = pair.evaluate([0.01, 0.01], [0.0, 0.0], &y, &mut d);
    for o in out.struts {
        assert!((o.p_piston - p_s).abs() < 1e-6 * p_s, "{o:?}");
        assert_eq!(o.p_rod, p_s);
        // Eq 5.1 at one pressure: (P - p_amb) A_hr
        let sp = pair.struts()[0].params();
        assert!((o.force - (p_s - sp.p_amb) * sp.a_hr).abs() < 1e-6 * o.force);
    }
    for l in out.lines {
        assert!((l.p_node - p_s).abs() < 1e-6 * p_s, "{l:?}");
        assert!(l.q_piston.abs() < 1e-9 && l.q_rod.abs() < 1e-9 && l.dissipation_w.abs() < 1e-3);
    }
    // zero up to round-off (the stiff rod side turns a 1e-16 pressure error into 1e-4 Pa/s)
    let typical = pair.struts()[0].states().iter().map(|s| s.typical);
    let typical: Vec<f64> = typical.clone().chain(typical).chain([1e-3, 1e-3]).collect();
    for (r, t) in d.iter().zip(&typical) {
        assert!(r.abs() < 1e-9 * t, "{d:?}");
    }
    // the accumulator holds its precharged gas compressed to the static pressure
    let lp = LineParams::front_axle_roll();
    let v = y[pair.line_state(0)];
    let hand = lp.accumulator_volume_m3 * (lp.precharge_pa / p_s).powf(1.0 / 1.4);
    assert!((v - hand).abs() < 1e-12 * hand, "{v} {hand}");
    // at or below the precharge there is no static state with oil in the accumulator
    assert!(pair.rest_state(lp.precharge_pa, &mut y).is_err());
}

#[test]
fn without_line_flow_the_ported_strut_is_the_strut_bit_for_bit() {
    // a strut with lines whose flows are zero evaluates exactly as the strut alone
    let s = HpsStrut::new(&StrutParams::front_axle(), &HpsExtensions::default()).unwrap();
    let mut y = vec![0.0; s.n_states()];
    for (k, (z, zd)) in [(0.02, 0.3), (-0.05, -0.7), (0.0, 0.0), (0.1, -0.01)]
        .into_iter()
        .enumerate()
    {
        s.initial_state(z * 0.5, &mut y).unwrap();
        y[1] *= 1.0 + 0.01 * k as f64;
        y[2] = 0.05 * k as f64;
        let (mut a, mut b) = (vec![0.0; y.len()], vec![0.0; y.len()]);
        let oa = s.evaluate(z, zd, &y, &mut a);
        let ob = s.evaluate_with_inflow(z, zd, ChamberInflow::NONE, &y, &mut b);
        assert_eq!(oa, ob);
        assert_eq!(
            a.iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
            b.iter().map(|v| v.to_bits()).collect::<Vec<_>>()
        );
        // and an inflow moves exactly the two continuity equations
        let oc = s.evaluate_with_inflow(
            z,
            zd,
            ChamberInflow {
                piston: 1e-4,
                rod: 0.0,
            },
            &y,
            &mut b,
        );
        assert_eq!(oa.force, oc.force);
        assert!(b[0] < a[0] && b[1] == a[1]);
    }
}

#[test]
fn the_end_law_is_laminar_plus_turbulent_in_series() {
    let line = table_6_3_pair().line(0).rod_end;
    for dp in [-3e6, -2e4, -1.0, 0.0, 1e-3, 50.0, 7e5, 4e6] {
        let q = line.flow(dp);
        let back = line.laminar * q + line.turbulent * q * q.abs();
        assert!(
            (back - dp).abs() <= 1e-12 * dp.abs().max(1.0),
            "{dp}: {back}"
        );
        assert_eq!(line.flow(-dp), -q);
    }
    // Hagen-Poiseuille and the orifice law by hand: 128 mu L / (pi d^4), rho / (2 (C A)^2)
    let lp = LineParams::front_axle_roll();
    let r = 128.0 * 0.027 * 2.5 / (std::f64::consts::PI * 0.038f64.powi(4));
    assert!((line.laminar - r).abs() < 1e-9 * r);
    let a = 850.0 / (2.0 * (0.7 * lp.rod_end.port_area_m2).powi(2));
    assert!((line.turbulent - a).abs() < 1e-9 * a);
}

#[test]
fn bounce_and_roll_stiffness_match_the_hand_formula() {
    let sp = StrutParams::front_axle();
    let pair: &'static CrossCoupledPair = Box::leak(Box::new(table_6_3_pair()));
    let strut: &'static HpsStrut = Box::leak(Box::new(
        HpsStrut::new(&sp, &HpsExtensions::default()).unwrap(),
    ));
    // both at the reference state, z = 0 and P_h0 in every chamber
    let mut y_pair = vec![0.0; pair.n_states()];
    pair.rest_state(sp.p_h0, &mut y_pair).unwrap();
    let mut y1 = vec![0.0; strut.n_states()];
    strut.initial_state(0.0, &mut y1).unwrap();
    let y_ind: Vec<f64> = y1.iter().chain(y1.iter()).copied().collect();

    let c0 = strut.chamber_compliances(0.0, &y1);
    let k0_hand = sp.a_hr * sp.a_hr / (c0.piston + c0.rod);
    let at_rest = |shape| pair.mode_stiffness([sp.p_h0; 2], [0.0; 2], shape).unwrap();
    let (kb_hand, kr_hand) = (at_rest([1.0, 1.0]), at_rest([1.0, -1.0]));
    // for equal struts the Rayleigh quotients are A_hr^2 / C and (A_hc + A_ann)^2 / C
    let mut y_rest = vec![0.0; pair.n_states()];
    pair.rest_state(sp.p_h0, &mut y_rest).unwrap();
    let cs = pair.struts()[0].chamber_compliances(0.0, &y_rest[..pair.struts()[0].n_states()]);
    let c = cs.piston + cs.rod + pair.line(0).compliance(y_rest[pair.line_state(0)]);
    assert!((kb_hand * c / (sp.a_hr * sp.a_hr) - 1.0).abs() < 1e-12);
    assert!((kr_hand * c / (sp.a_hc + sp.a_ann()).powi(2) - 1.0).abs() < 1e-12);

    let bounce0 = stiffness(|| Driven::Independent([strut, strut]), &y_ind, [1.0, 1.0]);
    let roll0 = stiffness(|| Driven::Independent([strut, strut]), &y_ind, [1.0, -1.0]);
    let bounce = stiffness(|| Driven::Coupled(pair), &y_pair, [1.0, 1.0]);
    let roll = stiffness(|| Driven::Coupled(pair), &y_pair, [1.0, -1.0]);
    println!(
        "k per strut (kN/m): without line bounce {:.1} roll {:.1} (hand {:.1}); with line \
         bounce {:.1} (hand {:.1}) roll {:.1} (hand {:.1}); roll/bounce {:.3}, \
         bounce with/without {:.3}, roll with/without {:.3}; relative to hand {:.1e} {:.1e} \
         {:.1e} {:.1e}",
        bounce0 / 1e3,
        roll0 / 1e3,
        k0_hand / 1e3,
        bounce / 1e3,
        kb_hand / 1e3,
        roll / 1e3,
        kr_hand / 1e3,
        roll / bounce,
        bounce / bounce0,
        roll / roll0,
        bounce0 / k0_hand - 1.0,
        roll0 / k0_hand - 1.0,
        bounce / kb_hand - 1.0,
        roll / kr_hand - 1.0,
    );
    let close = |a: f64, b: f64, tol: f64| (a / b - 1.0).abs() < tol;
    assert!(close(bounce0, k0_hand, 2e-3), "{bounce0} {k0_hand}");
    assert!(close(roll0, k0_hand, 2e-3), "{roll0} {k0_hand}");
    assert!(close(bounce, kb_hand, 2e-3), "{bounce} {kb_hand}");
    assert!(close(roll, kr_hand, 2e-3), "{roll} {kr_hand}");
    // the ratio is the area ratio ((2 A_hc - A_hr) / A_hr)^2, whatever the compliances
    let area = ((2.0 * sp.a_hc - sp.a_hr) / sp.a_hr).powi(2);
    assert!(close(kr_hand / kb_hand, area, 1e-12));
    assert!(close(roll / bounce, area, 3e-3), "{}", roll / bounce);
    // the point of the layout: softer in bounce, stiffer in roll than the plain strut
    assert!(bounce < 0.7 * bounce0 && roll > 1.5 * roll0);
}

/// The pair at fixed deflections (no external work) with the dissipated energy as an extra
/// state.
struct Closed<'a> {
    pair: &'a CrossCoupledPair,
    z: [f64; 2],
}

impl OdeSystem for Closed<'_> {
    fn dim(&self) -> usize {
        self.pair.n_states() + 1
    }
    fn rhs(&self, _t: f64, y: &[f64], dydt: &mut [f64]) {
        let n = self.pair.n_states();
        let o = self
            .pair
            .evaluate(self.z, [0.0; 2], &y[..n], &mut dydt[..n]);
        dydt[n] = o.lines[0].dissipation_w + o.lines[1].dissipation_w;
    }
    fn is_stiff(&self) -> bool {
        true
    }
}

/// `int_{p0}^{p} s c(s) ds` by Simpson's rule: the energy stored in a chamber of
/// compliance `c` when it is charged from `p0` to `p` (`dE = P dV = P C dP`).
fn charge_energy(c: impl Fn(f64) -> f64, p0: f64, p: f64) -> f64 {
    let n = 400;
    let h = (p - p0) / n as f64;
    (0..=n)
        .map(|i| {
            let s = p0 + h * i as f64;
            let w = if i == 0 || i == n {
                1.0
            } else if i % 2 == 1 {
                4.0
            } else {
                2.0
            };
            w * s * c(s)
        })
        .sum::<f64>()
        * h
        / 3.0
}

/// Stored energy of the pair at fixed deflections `z` (J, from every chamber at `p0`).
fn stored(pair: &CrossCoupledPair, z: [f64; 2], y: &[f64]) -> f64 {
    let p0 = 5.0e6;
    let mut e = 0.0;
    let mut off = 0;
    for (i, s) in pair.struts().iter().enumerate() {
        let n = s.n_states();
        let (pc, pr) = s.chamber_pressures(&y[off..off + n]);
        let c = |p: f64| {
            let mut buf = vec![0.0; n];
            s.rest_state_at_pressure(p, &mut buf).unwrap();
            s.chamber_compliances(z[i], &buf)
        };
        e += charge_energy(|p| c(p).piston, p0, pc);
        e += charge_energy(|p| c(p).rod, p0, pr);
        off += n;
    }
    e + (0..2)
        .map(|k| pair.line(k).stored_energy(y[pair.line_state(k)]))
        .sum::<f64>()
}

#[test]
fn the_lines_dissipate_and_never_create_energy() {
    let pair = table_6_3_pair();
    let l = pair.line(0);
    // pointwise: the power the chambers push into a line is the node's storage rate plus
    // a dissipation that is never negative
    let v_rest = l.gas_volume_at(5.6e6).unwrap();
    for (dv, pc, pr) in [
        (0.0, 5.6e6, 5.6e6),
        (0.05, 6.1e6, 5.0e6),
        (-0.08, 4.9e6, 7.2e6),
        (0.02, 5.61e6, 5.5999e6),
    ] {
        let v = v_rest * (1.0 + dv);
        let f = l.evaluate(v, pc, pr);
        let h = 1e-9 * v;
        let de = (l.stored_energy(v + h) - l.stored_energy(v - h)) / (2.0 * h) * f.gas_volume_rate;
        let p_in = -(pc * f.q_piston + pr * f.q_rod);
        assert!(f.dissipation_w >= 0.0);
        assert!(
            (p_in - de - f.dissipation_w).abs() <= 1e-6 * p_in.abs().max(1.0),
            "{p_in} {de} {}",
            f.dissipation_w
        );
    }
    // a run of the roll pair and of the pitch pair
    released_pair_loses_energy(&pair);
    released_pair_loses_energy(&pitch_pair());
}

/// The pair held at fixed deflections, released from unequal pressures: the stored energy
/// never rises, `E(t) + int D = E(0)`, and each circuit settles to one pressure.
fn released_pair_loses_energy(pair: &CrossCoupledPair) {
    let z = [0.01, -0.02];
    let sys = Closed { pair, z };
    let n = pair.n_states();
    let mut y0 = vec![0.0; n + 1];
    pair.rest_state(5.6e6, &mut y0[..n]).unwrap();
    y0[pair.line_state(0)] *= 0.97;
    y0[pair.struts()[0].n_states() + 1] += 3e5;
    let e0 = stored(pair, z, &y0);
    let times: Vec<f64> = (1..=20).map(|i| 0.01 * i as f64).collect();
    let mut last_e = e0;
    let mut samples = Vec::new();
    Integrator::new(Solver::Rosenbrock23, 1e-10, 1e-14)
        .integrate(&sys, 0.0, &y0, &times, |_, y| {
            samples.push(y.to_vec());
            odeint::Control::Continue
        })
        .unwrap();
    for y in &samples {
        let e = stored(pair, z, y);
        let dissipated = y[n];
        assert!(
            e <= last_e + 1e-9 * e0.abs(),
            "stored energy rose: {last_e} -> {e}"
        );
        assert!(
            (e + dissipated - e0).abs() < 1e-4 * dissipated,
            "E {e} + D {dissipated} != E0 {e0}"
        );
        last_e = e;
    }
    // and the pressures settled to one per circuit
    let y = samples.last().unwrap();
    let mut d = vec![0.0; n];
    let o = pair.evaluate(z, [0.0; 2], &y[..n], &mut d);
    assert!((o.struts[0].p_piston / o.struts[1].p_rod - 1.0).abs() < 1e-6);
    assert!((o.struts[1].p_piston / o.struts[0].p_rod - 1.0).abs() < 1e-6);
    println!(
        "released: dissipated {:.3} J, stored change {:.3} J",
        y[n],
        e0 - stored(pair, z, y)
    );
}

#[test]
fn swapping_the_struts_swaps_the_response() {
    let pair = table_6_3_pair();
    let (n0, n) = (pair.struts()[0].n_states(), pair.n_states());
    let mut y = vec![0.0; n];
    pair.rest_state(5.6e6, &mut y).unwrap();
    // an unsymmetric state: each strut and each line at its own pressure
    y[0] *= 0.98;
    y[1] += 2e5;
    y[n0 + 1] -= 1e5;
    y[pair.line_state(1)] *= 1.01;
    let mirror = |y: &[f64]| -> Vec<f64> {
        let mut m = Vec::with_capacity(n);
        m.extend_from_slice(&y[n0..2 * n0]);
        m.extend_from_slice(&y[..n0]);
        m.push(y[pair.line_state(1)]);
        m.push(y[pair.line_state(0)]);
        m
    };
    let (z, zd) = ([0.02, -0.01], [0.3, -0.1]);
    let (mut d, mut dm) = (vec![0.0; n], vec![0.0; n]);
    let o = pair.evaluate(z, zd, &y, &mut d);
    let om = pair.evaluate([z[1], z[0]], [zd[1], zd[0]], &mirror(&y), &mut dm);
    assert_eq!(mirror(&d), dm);
    assert_eq!(o.struts[0], om.struts[1]);
    assert_eq!(o.struts[1], om.struts[0]);
    assert_eq!(o.lines[0], om.lines[1]);
}

#[test]
fn bad_parameters_are_refused_by_name() {
    let good = LineParams::front_axle_roll();
    good.validate().unwrap();
    let field = |p: LineParams| match p.validate() {
        Err(HpsError::InvalidParameter { field, .. }) => field,
        other => panic!("{other:?}"),
    };
    assert_eq!(
        field(LineParams {
            diameter_m: 0.5,
            ..good
        }),
        "diameter_m"
    );
    assert_eq!(
        field(LineParams {
            diameter_m: f64::NAN,
            ..good
        }),
        "diameter_m"
    );
    assert_eq!(
        field(LineParams {
            viscosity_pa_s: 0.0,
            ..good
        }),
        "viscosity_pa_s"
    );
    assert_eq!(
        field(LineParams {
            port_cd: 1.5,
            ..good
        }),
        "port_cd"
    );
    let mut p = good;
    p.rod_end.port_area_m2 = -1e-5;
    assert_eq!(field(p), "rod_end.port_area_m2");
    p = good;
    p.piston_end.port_area_m2 = 0.01;
    assert_eq!(field(p), "piston_end.port_area_m2");
    p = good;
    p.piston_end.length_m = 100.0;
    assert_eq!(field(p), "piston_end.length_m");
    assert_eq!(
        field(LineParams {
            accumulator_volume_m3: 1.0,
            ..good
        }),
        "accumulator_volume_m3"
    );
    assert_eq!(
        field(LineParams {
            precharge_pa: -1.0,
            ..good
        }),
        "precharge_pa"
    );
    // struts of different oil cannot share a line
    let a = StrutParams::front_axle();
    let b = StrutParams { rho_h: 900.0, ..a };
    let ext = HpsExtensions::default();
    let s = [
        HpsStrut::ported(&a, &ext).unwrap(),
        HpsStrut::ported(&b, &ext).unwrap(),
    ];
    assert!(CrossCoupledPair::new(s, &good).is_err());
    // a sealed piston needs ports: the plain strut refuses it, the ported one takes it
    let sealed = sealed_piston(&a);
    assert!(HpsStrut::new(&sealed, &ext).is_err());
    assert!(HpsStrut::ported(&sealed, &ext).is_ok());
}

#[test]
fn the_pitch_pair_rests_at_the_hand_circuit_pressures() {
    let pair = pitch_pair();
    let [f, r] = front_and_rear();
    // loaded, the similar struts rest at one pressure (5.228 MPa): the circuits keep it,
    // bit for bit
    let p_s = 5.228e6;
    assert_eq!(pair.circuit_pressures([p_s, p_s]), [p_s, p_s]);
    // unloaded the front strut rests at 4.159 MPa, the rear one on its extension stop with
    // 2.897 MPa in its chambers: by hand (Eq 5.1 for both struts, D = A_hc,f A_hc,r -
    // A_ann,f A_ann,r)
    let p = [4.159e6, 2.897e6];
    let d = f.a_hc * r.a_hc - f.a_ann() * r.a_ann();
    let hand = [
        p[0] + (p[1] - p[0]) * f.a_ann() * r.a_hr / d,
        p[1] - (p[1] - p[0]) * r.a_ann() * f.a_hr / d,
    ];
    let q = pair.circuit_pressures(p);
    println!(
        "unloaded circuit pressures: front piston / rear rod {:.4} MPa, rear piston / front rod {:.4} MPa",
        q[0] / 1e6,
        q[1] / 1e6
    );
    for k in 0..2 {
        assert!((q[k] / hand[k] - 1.0).abs() < 1e-12, "{q:?} {hand:?}");
    }
    // at those pressures each strut carries the force it carries alone, every line rests,
    // nothing moves
    let mut y = vec![0.0; pair.n_states()];
    pair.rest_state_at(q, &mut y).unwrap();
    let mut dy = vec![1.0; y.len()];
    let z = [-0.05, -0.12];
    let out = pair.evaluate(z, [0.0; 2], &y, &mut dy);
    for (k, sp) in [f, r].iter().enumerate() {
        let alone = (p[k] - sp.p_amb) * sp.a_hr;
        let o = out.struts[k];
        assert!(
            ((o.force - o.friction) / alone - 1.0).abs() < 1e-9,
            "{k}: {} {alone}",
            o.force
        );
    }
    assert!((out.struts[0].p_piston / q[0] - 1.0).abs() < 1e-9);
    assert_eq!([out.struts[0].p_rod, out.struts[1].p_rod], [q[1], q[0]]);
    for (k, l) in out.lines.iter().enumerate() {
        assert!((l.p_node / q[k] - 1.0).abs() < 1e-12, "{l:?}");
        assert!(l.q_piston.abs() < 1e-12 && l.q_rod.abs() < 1e-12);
    }
    let typical: Vec<f64> = pair
        .struts()
        .iter()
        .flat_map(|s| s.states().iter().map(|i| i.typical))
        .chain([1e-3, 1e-3])
        .collect();
    for (rate, t) in dy.iter().zip(&typical) {
        assert!(rate.abs() < 1e-9 * t, "{dy:?}");
    }
    // the accumulators hold their gas at the circuit pressures
    let lines = LineParams::side_pitch(REAR_RATIO).unwrap();
    for k in 0..2 {
        let v = lines[k].accumulator_volume_m3 * (lines[k].precharge_pa / q[k]).powf(1.0 / f.n);
        assert!((y[pair.line_state(k)] / v - 1.0).abs() < 1e-12);
    }
    // a circuit at its precharge has no static state
    assert!(pair.rest_state_at([q[0], 2.4e6], &mut y).is_err());
}

#[test]
fn pitch_is_stiffer_than_bounce_by_the_hand_ratio() {
    let [fp, rp] = front_and_rear();
    let pair: &'static CrossCoupledPair = Box::leak(Box::new(pitch_pair()));
    let ext = HpsExtensions::default();
    let plain: &'static [HpsStrut; 2] =
        Box::leak(Box::new([fp, rp].map(|p| HpsStrut::new(&p, &ext).unwrap())));
    let p = fp.p_h0;
    let mut y_pair = vec![0.0; pair.n_states()];
    pair.rest_state(p, &mut y_pair).unwrap();
    let mut y_plain = Vec::new();
    for s in plain.iter() {
        let mut y = vec![0.0; s.n_states()];
        s.initial_state(0.0, &mut y).unwrap();
        y_plain.extend(y);
    }
    let (bounce, pitch) = ([1.0, 1.0], [1.0, -1.0]);
    let measured = |shape| stiffness(|| Driven::Coupled(pair), &y_pair, shape);
    let measured_plain = |shape| {
        stiffness(
            || Driven::Independent([&plain[0], &plain[1]]),
            &y_plain,
            shape,
        )
    };
    let hand = |shape| pair.mode_stiffness([p; 2], [0.0; 2], shape).unwrap();
    let (kb, kp) = (measured(bounce), measured(pitch));
    let (kb0, kp0) = (measured_plain(bounce), measured_plain(pitch));
    let (hb, hp) = (hand(bounce), hand(pitch));
    // the plain struts by hand: each A_hr^2 / (C_piston + C_rod), the Rayleigh quotient
    // their mean for either shape
    let plain_hand: f64 = (0..2)
        .map(|k| {
            let n = plain[k].n_states();
            let c = plain[k].chamber_compliances(0.0, &y_plain[k * plain[0].n_states()..][..n]);
            plain[k].params().a_hr.powi(2) / (c.piston + c.rod)
        })
        .sum::<f64>()
        / 2.0;
    // the closed form of the hand ratio with the circuits' compliances C_0, C_1
    let c = [0, 1].map(|k| {
        let at = |j: usize| pair.strut_state(j);
        let cc = |j: usize| {
            pair.struts()[j]
                .chamber_compliances(0.0, &y_pair[at(j)..at(j) + pair.struts()[j].n_states()])
        };
        cc(k).piston + cc(1 - k).rod + pair.line(k).compliance(y_pair[pair.line_state(k)])
    });
    let r = REAR_RATIO;
    let (ac, an) = (fp.a_hc, fp.a_ann());
    let closed = ((ac + r * an).powi(2) / c[0] + (r * ac + an).powi(2) / c[1])
        / ((ac - r * an).powi(2) / c[0] + (r * ac - an).powi(2) / c[1]);
    println!(
        "pitch pair per strut (kN/m): plain bounce {:.1} pitch {:.1} (hand {:.1}); linked \
         bounce {:.1} (hand {:.1}) pitch {:.1} (hand {:.1}); pitch/bounce {:.3} (hand {:.3}, \
         closed form {:.3}); bounce linked/plain {:.3}, pitch linked/plain {:.3}; circuit \
         compliances {:.3e} {:.3e} m^3/Pa",
        kb0 / 1e3,
        kp0 / 1e3,
        plain_hand / 1e3,
        kb / 1e3,
        hb / 1e3,
        kp / 1e3,
        hp / 1e3,
        kp / kb,
        hp / hb,
        closed,
        kb / kb0,
        kp / kp0,
        c[0],
        c[1]
    );
    // the hand model at the loaded static state of the prototype (5.228 MPa, -14.49 mm):
    // the matrix, and bounce, pitch and their coupling u_b^T K u_p / 2
    let (p_s, z_s) = (5.2276e6, -0.01449);
    let k = pair.stiffness_matrix([p_s; 2], [z_s; 2]).unwrap();
    let at_static = |u| pair.mode_stiffness([p_s; 2], [z_s; 2], u).unwrap();
    println!(
        "hand at the loaded static state (kN/m): K = [[{:.1}, {:.1}], [{:.1}, {:.1}]], bounce \
         {:.1}, pitch {:.1}, pitch/bounce {:.3}, coupling {:.1}",
        k[0][0] / 1e3,
        k[0][1] / 1e3,
        k[1][0] / 1e3,
        k[1][1] / 1e3,
        at_static(bounce) / 1e3,
        at_static(pitch) / 1e3,
        at_static(pitch) / at_static(bounce),
        (k[0][0] - k[1][1]) / 2e3
    );
    assert_eq!(k[0][1], k[1][0], "a passive spring's matrix is symmetric");
    let close = |a: f64, b: f64, tol: f64| (a / b - 1.0).abs() < tol;
    assert!(close(kb0, plain_hand, 2e-3) && close(kp0, plain_hand, 2e-3));
    assert!(close(kb, hb, 2e-3), "{kb} {hb}");
    assert!(close(kp, hp, 2e-3), "{kp} {hp}");
    assert!(close(hp / hb, closed, 1e-12));
    assert!(close(kp / kb, hp / hb, 3e-3), "{}", kp / kb);
    // the point of the layout: softer in bounce, stiffer in pitch than the plain struts
    assert!(kb < 0.8 * kb0 && kp > 1.5 * kp0, "{kb} {kb0} {kp} {kp0}");
}

#[test]
fn the_pitch_lines_are_the_roll_line_scaled_and_checked() {
    let roll = LineParams::front_axle_roll();
    let [at_front, at_rear] = LineParams::side_pitch(REAR_RATIO).unwrap();
    assert_eq!(at_front.piston_end, roll.piston_end);
    assert_eq!(at_front.rod_end.length_m, PITCH_LINE_M);
    assert!((at_front.rod_end.port_area_m2 / roll.rod_end.port_area_m2 - REAR_RATIO).abs() < 1e-12);
    assert_eq!(at_front.accumulator_volume_m3, roll.accumulator_volume_m3);
    assert!(
        (at_rear.piston_end.port_area_m2 / roll.piston_end.port_area_m2 - REAR_RATIO).abs() < 1e-12
    );
    assert_eq!(at_rear.rod_end.port_area_m2, roll.rod_end.port_area_m2);
    assert!(
        (at_rear.accumulator_volume_m3 / roll.accumulator_volume_m3 - REAR_RATIO).abs() < 1e-12
    );
    for bad in [0.0, f64::NAN, 10.0] {
        match LineParams::side_pitch(bad) {
            Err(HpsError::InvalidParameter { field, .. }) => assert_eq!(field, "ratio"),
            other => panic!("{other:?}"),
        }
    }
    // a ratio whose rear port outgrows the line's bore is refused by that field
    match LineParams::side_pitch(3.9) {
        Err(HpsError::InvalidParameter { field, .. }) => {
            assert_eq!(field, "piston_end.port_area_m2")
        }
        other => panic!("{other:?}"),
    }
}
