//! `afsv hps identify` earns its success or says why not (exit 3): a fit at the record's
//! noise passes; a gauge pressure read as absolute, a residual far above the noise, and a
//! noisy displacement differentiated for want of a velocity channel are each named; and
//! `--accept-poor-fit` prints the same problems with exit 0.

mod cli_support;
use afsv_records::Record;
use cli_support::{afsv, json, scratch};
use std::path::Path;

/// Near-Gaussian noise of standard deviation `sd` (a sum of 12 uniforms), reproducible.
fn noise(n: usize, seed: u64, sd: f64) -> Vec<f64> {
    let mut s = seed;
    (0..n)
        .map(|_| {
            let u: f64 = (0..12)
                .map(|_| {
                    s = s
                        .wrapping_mul(6364136223846793005)
                        .wrapping_add(1442695040888963407);
                    (s >> 11) as f64 / (1u64 << 53) as f64
                })
                .sum();
            sd * (u - 6.0)
        })
        .collect()
}

/// The front-axle strut's harmonic test (3 cycles at 2 Hz), as `afsv hps harmonic` writes it.
fn bench_record(name: &str) -> Record {
    let path = scratch("identify", name);
    json(&afsv(&[
        "hps",
        "harmonic",
        "--strut",
        "front-axle",
        "--cycles",
        "3",
        "-o",
        path.to_str().unwrap(),
    ]));
    Record::read(&path).unwrap()
}

/// A copy of `rec` without its sidecar, each column passed through `edit` (`None` drops it).
fn variant(
    rec: &Record,
    name: &str,
    mut edit: impl FnMut(&str, &[f64]) -> Option<Vec<f64>>,
) -> std::path::PathBuf {
    let mut out = Record::new();
    for n in rec.names() {
        if let Some(v) = edit(n, rec.column(n).unwrap()) {
            out.push_column(n, v).unwrap();
        }
    }
    let path = scratch("identify", name);
    out.write(&path).unwrap();
    assert!(!Path::new(&path.with_extension("json")).exists());
    path
}

fn plus(v: &[f64], e: &[f64]) -> Vec<f64> {
    v.iter().zip(e).map(|(a, b)| a + b).collect()
}

fn identify(path: &Path, extra: &[&str]) -> std::process::Output {
    let mut args = vec![
        "hps",
        "identify",
        "-i",
        path.to_str().unwrap(),
        "--strut",
        "front-axle",
    ];
    args.extend_from_slice(extra);
    afsv(&args)
}

#[test]
fn a_fit_at_the_noise_passes_and_flawed_records_are_named() {
    let rec = bench_record("bench.csv");
    let n = rec.len();
    // 150 N on the load cell, 5 kPa on the pressure transducers: the model fits to the noise.
    let noisy = variant(&rec, "noisy.csv", |name, v| {
        Some(match name {
            "force_n" => plus(v, &noise(n, 1, 150.0)),
            "p_piston_pa" => plus(v, &noise(n, 2, 5e3)),
            "p_rod_pa" => plus(v, &noise(n, 3, 5e3)),
            _ => v.to_vec(),
        })
    });
    let v = json(&identify(&noisy, &[]));
    assert_eq!(v["problems"].as_array().unwrap().len(), 0, "{v}");
    let ratio = v["residual_checks"]["force_n"]["residual_to_noise"]
        .as_f64()
        .unwrap();
    assert!(ratio < 1.5, "{v}");
    assert_eq!(v["velocity"]["source"], "measured");

    // Gauge pressures in a file without a sidecar: read as absolute, one atmosphere off.
    let gauge = variant(&rec, "gauge.csv", |name, v| {
        Some(if name.starts_with("p_") {
            v.iter().map(|p| p - 101_325.0).collect()
        } else {
            v.to_vec()
        })
    });
    let out = identify(&gauge, &[]);
    assert_eq!(out.status.code(), Some(3), "{out:?}");
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("gauge pressure read as absolute"), "{err}");
    assert!(err.contains("times the noise the record shows"), "{err}");
    // The same with --accept-poor-fit: exit 0, the problems still printed.
    let v = json(&identify(&gauge, &["--accept-poor-fit"]));
    assert_eq!(v["accepted_despite_problems"], true);
    assert_eq!(v["converged"], false);
    assert!(v["problems"].to_string().contains("gauge"), "{v}");

    // No velocity channel, and 30 um of displacement noise to differentiate.
    let bare = variant(&rec, "novel.csv", |name, v| match name {
        "velocity_m_s" => None,
        "displacement_m" => Some(plus(v, &noise(n, 4, 3e-5))),
        _ => Some(v.to_vec()),
    });
    let out = identify(&bare, &[]);
    assert_eq!(out.status.code(), Some(3), "{out:?}");
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("no velocity_m_s"), "{err}");
}
