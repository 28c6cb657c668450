//! A manoeuvre whose output grid would not fit in memory is an error naming the fields.

use afsv_dynamics::*;

#[test]
fn output_sample_count_is_bounded() {
    let p = YawPlaneParams::nominal(Load::Loaded);
    let sys = p.afs_system().unwrap();
    for (duration, dt) in [(1e308, 0.005), (9_999_999_999.0, 0.005), (10.0, 1e-320)] {
        let man = Manoeuvre::open_loop(
            13.9,
            duration,
            SteerInput::pulse_deg(30.0, 0.2, 0.5),
            "pulse",
        );
        let opts = SimOptions {
            output_dt_s: dt,
            ..SimOptions::default()
        };
        let e = simulate(&p.vehicle, &sys, &man, &opts).unwrap_err();
        let msg = e.to_string();
        assert!(
            msg.contains("duration_s") && msg.contains("output_dt_s"),
            "{msg}"
        );
    }
}
