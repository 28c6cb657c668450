//! Cross-checks of the independent yaw-plane implementation (tests/independent/yaw.rs)
//! against the toolkit's model, hidden-effect visibility, and the record-set generator.

mod independent;

use afsv_dynamics::{simulate, Load, Manoeuvre, SimOptions, SteerInput, YawPlaneParams};
use independent::yaw::{simulate_yaw, Steer, YawHidden, YawLoad, YawParams, YawRun};

fn nrmse(a: &[f64], b: &[f64]) -> f64 {
    let n = a.len().min(b.len());
    let mean = b[..n].iter().sum::<f64>() / n as f64;
    let var = b[..n].iter().map(|x| (x - mean).powi(2)).sum::<f64>() / n as f64;
    let mse = (0..n).map(|i| (a[i] - b[i]).powi(2)).sum::<f64>() / n as f64;
    (mse / var.max(1e-300)).sqrt()
}

fn crate_run(load: Load, steer: &Steer, speed: f64, duration: f64) -> YawRun {
    let params = YawPlaneParams::nominal(load);
    let afs = params.afs_system().unwrap();
    let input = match *steer {
        Steer::Pulse { amp_deg, dur_s, start_s } => SteerInput::pulse_deg(amp_deg, dur_s, start_s),
        Steer::Step { amp_deg, start_s } => SteerInput::step_deg(amp_deg, start_s),
        Steer::Ramp { rate_deg_s, start_s, limit_deg } => SteerInput::Ramp {
            rate_rad_s: rate_deg_s.to_radians(),
            start_s,
            limit_rad: limit_deg.to_radians(),
        },
        Steer::Sine { .. } => {
            let t: Vec<f64> = (0..=(duration * 1000.0) as usize).map(|k| k as f64 * 1e-3).collect();
            let a = t.iter().map(|&x| steer.deg(x).to_radians()).collect();
            SteerInput::Table { time_s: t, angle_rad: a }
        }
    };
    let m = Manoeuvre::open_loop(speed, duration, input, steer.kind());
    let opts = SimOptions { rtol: 1e-8, atol: 1e-10, output_dt_s: 0.01, max_step_s: 0.002, record_energy: false, ..SimOptions::default() };
    let r = simulate(&params.vehicle, &afs, &m, &opts).unwrap();
    YawRun {
        time_s: r.time_s,
        steer_wheel_deg: r.steer_wheel_deg,
        speed_m_s: r.speed_m_s,
        articulation_deg: r.articulation_deg,
        strut_left_disp_m: r.strut_left_disp_m,
        p_c_pa: r.p_c_pa,
        p_r_pa: r.p_r_pa,
        yaw_rate_front_deg_s: r.yaw_rate_front_deg_s,
    }
}

#[test]
fn cross_check_print() {
    let cases = [
        Steer::Pulse { amp_deg: 30.0, dur_s: 0.2, start_s: 0.5 },
        Steer::Step { amp_deg: 30.0, start_s: 0.5 },
        Steer::Sine { amp_deg: 60.0, freq_hz: 0.5, start_s: 0.5, cycles: 2.0 },
    ];
    for (load, yl) in [(Load::Loaded, YawLoad::Loaded), (Load::Unloaded, YawLoad::Unloaded)] {
        for s in &cases {
            let speed = 50.0 / 3.6;
            let t0 = std::time::Instant::now();
            let mine = simulate_yaw(&YawParams::table_3_1(yl), YawHidden::None, s, speed, 10.0, 100.0);
            let tm = t0.elapsed();
            let theirs = crate_run(load, s, speed, 10.0);
            println!("{:?} {} n {} {} mine {:?}", load, s.kind(), mine.time_s.len(), theirs.time_s.len(), tm);
            for ((name, a), (_, b)) in mine.channels().iter().zip(theirs.channels().iter()) {
                println!("   {name:24} nrmse {:.5}  max_mine {:.4e} max_theirs {:.4e}", nrmse(a, b),
                    a.iter().cloned().fold(f64::MIN, f64::max), b.iter().cloned().fold(f64::MIN, f64::max));
            }
        }
    }
}
