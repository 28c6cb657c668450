//! Statistical acceptance tests of the synthesis against its targets (issue 2, section 2):
//! Welch PSD within +-1.5 dB of the target averaged over the band and 20 seeds, coherence
//! within +-0.1, Parseval within 5 %, cross-slope PSD (Fig 2.7), determinism.

use terrain_psd::*;

const SEEDS: u64 = 20;
const LENGTH_M: f64 = 2000.0;
const DX_M: f64 = 0.05;
const SEGMENT: usize = 2048; // 102.4 m: resolution 0.0098 cycles/m, 38 segments

fn specs() -> Vec<(&'static str, TwoTrackSpec)> {
    let band = Band::PAPER;
    vec![
        (
            "class E, piecewise 0.3 (paper nominal)",
            TwoTrackSpec::paper_nominal(),
        ),
        (
            "forestry, bogsjo rho=0.2 T=1.14",
            TwoTrackSpec::new(
                PowerLawPsd::off_road(OffRoadTerrain::Forestry),
                band,
                CoherenceModel::bogsjo(0.2, 1.14).unwrap(),
            )
            .unwrap(),
        ),
        (
            "MVEE, zhang 50 km/h",
            TwoTrackSpec::new(
                PowerLawPsd::off_road(OffRoadTerrain::Mvee),
                band,
                CoherenceModel::zhang(50.0 / 3.6).unwrap(),
            )
            .unwrap(),
        ),
        (
            "plowed, independent",
            TwoTrackSpec::new(
                PowerLawPsd::off_road(OffRoadTerrain::Plowed),
                band,
                CoherenceModel::Independent,
            )
            .unwrap(),
        ),
        (
            "user alpha=4.096e-5 w=2.4, piecewise 0.9, band 0.05-3",
            TwoTrackSpec::new(
                PowerLawPsd::new(4.096e-5, 2.4).unwrap(),
                Band::new(0.05, 3.0).unwrap(),
                CoherenceModel::piecewise(0.9).unwrap(),
            )
            .unwrap(),
        ),
        (
            "class H, full",
            TwoTrackSpec::new(PowerLawPsd::iso(IsoClass::H), band, CoherenceModel::Full).unwrap(),
        ),
    ]
}

/// Seed-averaged Welch estimates of one spec.
struct Averaged {
    freq: Vec<f64>,
    pxx: Vec<f64>,
    pyy: Vec<f64>,
    coh: Vec<f64>,
    slope: Vec<f64>,
    var_ratio: f64,
    parseval_ratio: f64,
}

fn averaged(spec: &TwoTrackSpec, track_width: f64) -> Averaged {
    let cfg = WelchConfig::new(SEGMENT);
    let mut acc: Option<Averaged> = None;
    for seed in 0..SEEDS {
        let p = synthesize(spec, LENGTH_M, DX_M, seed).unwrap();
        let cs = cross_spectrum(&p.left_m, &p.right_m, DX_M, &cfg).unwrap();
        let sl = cross_slope_psd(&p.left_m, &p.right_m, DX_M, track_width, &cfg).unwrap();
        let var = |v: &[f64]| {
            let m = v.iter().sum::<f64>() / v.len() as f64;
            v.iter().map(|x| (x - m) * (x - m)).sum::<f64>() / v.len() as f64
        };
        let (vl, vr) = (var(&p.left_m), var(&p.right_m));
        let wl = welch_psd(&p.left_m, DX_M, &cfg).unwrap();
        let a = acc.get_or_insert_with(|| Averaged {
            freq: cs.freq.clone(),
            pxx: vec![0.0; cs.freq.len()],
            pyy: vec![0.0; cs.freq.len()],
            coh: vec![0.0; cs.freq.len()],
            slope: vec![0.0; cs.freq.len()],
            var_ratio: 0.0,
            parseval_ratio: 0.0,
        });
        let w = 1.0 / SEEDS as f64;
        for k in 0..cs.freq.len() {
            a.pxx[k] += w * cs.pxx[k];
            a.pyy[k] += w * cs.pyy[k];
            a.coh[k] += w * cs.coherence[k];
            a.slope[k] += w * sl.psd[k];
        }
        a.var_ratio += w * 0.5 * (vl + vr) / spec.variance();
        a.parseval_ratio += w * wl.integral() / vl;
    }
    acc.unwrap()
}

fn band_bins(spec: &TwoTrackSpec, freq: &[f64]) -> Vec<usize> {
    (0..freq.len())
        .filter(|&k| spec.band.contains(freq[k]))
        .collect()
}

fn db(a: f64, b: f64) -> f64 {
    10.0 * (a / b).log10()
}

#[test]
fn welch_psd_within_1_5_db_coherence_within_0_1_parseval_within_5_percent() {
    for (name, spec) in specs() {
        let a = averaged(&spec, 2.28);
        let bins = band_bins(&spec, &a.freq);
        assert!(bins.len() > 100, "{name}");
        let mut mean_db = 0.0;
        let mut worst_db: f64 = 0.0;
        let mut mean_coh = 0.0;
        let mut worst_coh: f64 = 0.0;
        let mut worst_inner_db: f64 = 0.0;
        let df = a.freq[1];
        for &k in &bins {
            let n = a.freq[k];
            let g = spec.target_psd(n);
            let e = 0.5 * (db(a.pxx[k], g) + db(a.pyy[k], g));
            mean_db += e / bins.len() as f64;
            worst_db = worst_db.max(e.abs());
            // Away from the band edges by more than the Hann main-lobe half-width (2 bins),
            // where the estimate is not smeared across the PSD's cut-off.
            if n > spec.band.n_min + 2.0 * df && n < spec.band.n_max - 2.0 * df {
                worst_inner_db = worst_inner_db.max(e.abs());
            }
            let c = a.coh[k] - spec.target_msc(n);
            mean_coh += c / bins.len() as f64;
            worst_coh = worst_coh.max(c.abs());
        }
        println!(
            "{name}: PSD mean {mean_db:+.3} dB (worst bin {worst_db:.2} dB, inside {worst_inner_db:.2} dB), coherence mean {mean_coh:+.4} (worst bin {worst_coh:.3}), variance/integral {:.4}, welch/variance {:.4}",
            a.var_ratio, a.parseval_ratio
        );
        assert!(mean_db.abs() < 1.5, "{name}: mean PSD error {mean_db} dB");
        assert!(
            worst_inner_db < 1.5,
            "{name}: worst inner-bin PSD error {worst_inner_db} dB"
        );
        assert!(
            mean_coh.abs() < 0.1,
            "{name}: mean coherence error {mean_coh}"
        );
        assert!(
            worst_coh < 0.1,
            "{name}: worst-bin coherence error {worst_coh}"
        );
        assert!(
            (a.var_ratio - 1.0).abs() < 0.05,
            "{name}: variance / integral = {}",
            a.var_ratio
        );
        assert!(
            (a.parseval_ratio - 1.0).abs() < 0.05,
            "{name}: Welch integral / variance = {}",
            a.parseval_ratio
        );
    }
}

#[test]
fn same_seed_same_bytes_other_seed_other_profile() {
    for (name, spec) in specs() {
        let a = synthesize(&spec, 100.0, 0.05, 42).unwrap();
        let b = synthesize(&spec, 100.0, 0.05, 42).unwrap();
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<u64>>();
        assert_eq!(bits(&a.left_m), bits(&b.left_m), "{name}");
        assert_eq!(bits(&a.right_m), bits(&b.right_m), "{name}");
        let c = synthesize(&spec, 100.0, 0.05, 43).unwrap();
        assert_ne!(a.left_m, c.left_m, "{name}");
    }
}

#[test]
fn pinned_values_of_seed_1_catch_algorithm_changes() {
    // Paper nominal terrain, 100 m at 0.05 m, seed 1. A change here changes every profile a
    // user generated with a given seed: update only deliberately (and say so in the changelog).
    let p = synthesize(&TwoTrackSpec::paper_nominal(), 100.0, 0.05, 1).unwrap();
    let pinned = [
        (p.left_m[0], 8.998619204708391e-2),
        (p.left_m[1000], -1.094838051776929e-2),
        (p.right_m[0], 5.608224862279967e-2),
        (p.right_m[2000], -4.739333707940355e-2),
    ];
    for (got, want) in pinned {
        assert!((got - want).abs() < 1e-12, "{got:e} vs {want:e}");
    }
}

#[test]
fn zhang_equals_piecewise_with_cutoff_2hz_over_speed() {
    let u = 10.0;
    let psd = PowerLawPsd::paper_nominal();
    let z = TwoTrackSpec::new(psd, Band::PAPER, CoherenceModel::zhang(u).unwrap()).unwrap();
    let p = TwoTrackSpec::new(
        psd,
        Band::PAPER,
        CoherenceModel::piecewise(2.0 / u).unwrap(),
    )
    .unwrap();
    let a = synthesize(&z, 200.0, 0.05, 5).unwrap();
    let b = synthesize(&p, 200.0, 0.05, 5).unwrap();
    for (x, y) in a.right_m.iter().zip(&b.right_m) {
        assert!((x - y).abs() < 1e-12);
    }
}

#[test]
fn cross_slope_psd_follows_target_and_fig_2_7_ordering() {
    // Fig 2.7: a higher cut-off m_c gives lower roll excitation at low spatial frequency.
    let track = 2.28;
    let mut low_band_level = Vec::new();
    for m_c in [0.3, 0.6, 0.9] {
        let spec = TwoTrackSpec::new(
            PowerLawPsd::paper_nominal(),
            Band::PAPER,
            CoherenceModel::piecewise(m_c).unwrap(),
        )
        .unwrap();
        let a = averaged(&spec, track);
        let bins = band_bins(&spec, &a.freq);
        let mean_db = bins
            .iter()
            .map(|&k| db(a.slope[k], spec.target_cross_slope_psd(a.freq[k], track)))
            .sum::<f64>()
            / bins.len() as f64;
        println!("m_c = {m_c}: cross-slope PSD mean error {mean_db:+.3} dB");
        assert!(mean_db.abs() < 1.5, "m_c = {m_c}: {mean_db} dB");
        let low: Vec<usize> = bins.iter().copied().filter(|&k| a.freq[k] < 0.3).collect();
        low_band_level.push(low.iter().map(|&k| a.slope[k]).sum::<f64>());
        // The target itself is 2 G (1 - gamma) / B^2.
        let n = 0.15;
        let g = spec.coherence.msc(n).sqrt();
        let want = 2.0 * spec.psd.gd(n) * (1.0 - g) / (track * track);
        assert!((spec.target_cross_slope_psd(n, track) - want).abs() < 1e-18);
    }
    assert!(low_band_level[0] > low_band_level[1] && low_band_level[1] > low_band_level[2]);
}

#[test]
fn coherence_models_are_distinguishable_in_the_estimates() {
    // Full coherence: identical tracks and zero cross-slope; independence: coherence ~ 0.
    let full = TwoTrackSpec::new(
        PowerLawPsd::paper_nominal(),
        Band::PAPER,
        CoherenceModel::Full,
    )
    .unwrap();
    let p = synthesize(&full, 500.0, 0.05, 3).unwrap();
    assert!(p.cross_slope_rad(2.28).iter().all(|v| *v == 0.0));
    let none = TwoTrackSpec::new(
        PowerLawPsd::paper_nominal(),
        Band::PAPER,
        CoherenceModel::Independent,
    )
    .unwrap();
    let a = averaged(&none, 2.28);
    let bins = band_bins(&none, &a.freq);
    let mean = bins.iter().map(|&k| a.coh[k]).sum::<f64>() / bins.len() as f64;
    assert!(mean < 0.05, "{mean}");
}

#[test]
fn default_summary_is_within_tolerances() {
    let s = default_terrain_summary(1);
    assert_eq!(s.spec, TwoTrackSpec::paper_nominal());
    assert_eq!(s.samples, 40001);
    assert!(s.psd_mean_error_db.abs() < 1.5, "{}", s.psd_mean_error_db);
    assert!(s.coherence_mean_error.abs() < 0.1);
    assert!((s.variance_ratio - 1.0).abs() < 0.25);
    assert!((s.welch_parseval_ratio - 1.0).abs() < 0.1);
    assert!((s.rms_target_m - (4.096e-5f64 * 49.8).sqrt()).abs() < 1e-12);
    assert_eq!(s.octave_bands.len(), 8);
    assert_eq!(s, default_terrain_summary(1));
}

#[test]
fn fidelity_passes_for_the_default_and_fails_on_a_wrong_estimate() {
    let s = default_terrain_summary(1);
    let f = s.fidelity();
    assert!(f.pass, "{f:?}");
    assert_eq!(f.criteria.len(), 4);
    let mut bad = s.clone();
    bad.psd_mean_error_db = 3.0;
    assert!(!bad.fidelity().pass);
    bad.psd_mean_error_db = f64::NAN;
    assert!(!bad.fidelity().pass, "a non-finite deviation must fail");
}
