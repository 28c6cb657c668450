//! Section 3.4.3: directions of the one-at-a-time design sensitivities.

use afs_hydraulics::AfsParams;
use afsv_dynamics::yaw_plane::analysis::{measures_for, SensitivityParam, SensitivityTable};
use afsv_dynamics::{sensitivity, Load, MeasureSpec, VehicleParams};

const U50: f64 = 50.0 / 3.6;

fn change(
    t: &SensitivityTable,
    load: Load,
    p: SensitivityParam,
    v: f64,
) -> afsv_dynamics::yaw_plane::analysis::MeasureChanges {
    t.rows
        .iter()
        .find(|r| r.load == load && r.parameter == p && r.variation_percent == v)
        .expect("row")
        .change
}

#[test]
fn directions_of_section_3_4_3() {
    let t = sensitivity(U50, &MeasureSpec::default()).unwrap();
    eprint!("{}", t.to_text());
    use SensitivityParam::*;
    for load in Load::ALL {
        // Higher B_eff: higher frequency, lower overshoot.
        for v in [15.0, 30.0] {
            assert!(change(&t, load, BulkModulus, v).frequency > 0.0);
            assert!(change(&t, load, BulkModulus, v).overshoot < 0.0);
            assert!(change(&t, load, BulkModulus, -v).frequency < 0.0);
            assert!(change(&t, load, BulkModulus, -v).overshoot > 0.0);
        }
        // Higher leakage or seal friction: higher damping, lower gain and response rate.
        for p in [LeakVelocity, SealViscous] {
            for v in [15.0, 30.0] {
                let up = change(&t, load, p, v);
                let down = change(&t, load, p, -v);
                assert!(up.damping > 0.0 && down.damping < 0.0, "{load:?} {p:?} {v}");
                assert!(up.gain < 0.0 && down.gain > 0.0, "{load:?} {p:?} {v}");
                assert!(
                    up.response_rate < 0.0 && down.response_rate > 0.0,
                    "{load:?} {p:?} {v}"
                );
            }
        }
        // Larger A_0: higher gain (the gain follows the inverse of the initial steering arm,
        // which is longest near -7.3 %, so below that the gain rises again).
        assert!(change(&t, load, A0, 15.0).gain > 0.0);
        assert!(change(&t, load, A0, 30.0).gain > change(&t, load, A0, 15.0).gain);
        assert!(change(&t, load, A0, -30.0).gain > change(&t, load, A0, -15.0).gain);
        // Frequency falls for +-30 % A_0 (peak in between).
        assert!(change(&t, load, A0, 30.0).frequency < 0.0);
        assert!(change(&t, load, A0, -30.0).frequency < 0.0);
    }
}

#[test]
fn frequency_peaks_about_7_5_percent_below_nominal_a0() {
    let v = VehicleParams::loaded();
    let spec = MeasureSpec::default();
    let base = AfsParams::nominal();
    let mut best = (f64::NEG_INFINITY, 0.0);
    for k in -8..=2 {
        let pct = 2.5 * k as f64;
        let a = SensitivityParam::A0.scaled(&base, 1.0 + pct / 100.0);
        let m = measures_for(&v, &a, None, U50, &spec).unwrap();
        eprintln!("A_0 {pct:+5.1}%: f = {:.4} Hz", m.natural_frequency_hz);
        if m.natural_frequency_hz > best.0 {
            best = (m.natural_frequency_hz, pct);
        }
    }
    // The initial steering arm is longest at cos A_0 = l_2/l_1 (-7.3 %).
    assert!(best.1 <= -2.5 && best.1 >= -12.5, "peak at {}%", best.1);
}
