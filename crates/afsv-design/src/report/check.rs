//! The report of `afsv check`, the toolkit's self-checks: the ISO 2631-1 weightings against
//! the standard's tables and the terrain synthesis against its targets, as text.

/// `pass` or `FAIL`.
fn verdict(pass: bool) -> &'static str {
    if pass {
        "pass"
    } else {
        "FAIL"
    }
}

/// The self-checks as text: each weighting's largest errors, each fidelity criterion of
/// the terrain of `seed`, with their verdicts.
pub fn to_text(w: &perf_measures::WeightingCheck, f: &terrain_psd::Fidelity, seed: u64) -> String {
    let mut s = format!(
        "ISO 2631-1 weightings against {} (limit {} %): {}\n",
        w.reference,
        w.tolerance_percent,
        verdict(w.pass)
    );
    s += &format!(
        "  {:<10} {:>6} {:>12} {:>12} {:>12}\n",
        "weighting", "bands", "analog (%)", "IIR (%)", "FFT (%)"
    );
    for e in &w.weightings {
        s += &format!(
            "  {:<10} {:>6} {:>12.2} {:>12.2} {:>12.2}  {}\n",
            format!("{:?}", e.weighting).to_lowercase(),
            e.bands,
            e.max_analog_error_percent,
            e.max_iir_error_percent,
            e.max_fft_error_percent,
            verdict(e.pass)
        );
    }
    s += &format!(
        "\nTerrain synthesis (default terrain, seed {seed}): {}\n",
        verdict(f.pass)
    );
    for c in &f.criteria {
        let dev = if c.deviation.is_finite() {
            format!("{:+.3}", c.deviation)
        } else {
            "n/a".to_string()
        };
        s += &format!(
            "  {:<36} {:>9}  (limit ±{})  {}\n",
            c.name,
            dev,
            c.limit,
            verdict(c.pass)
        );
    }
    s
}
