//! Helpers shared by the discovery tests.

use afsv::discover::Discovery;

/// One line per candidate and round: what a failing assertion should show.
pub fn summary(d: &Discovery) -> String {
    let mut s = format!("named {:?}, shrink {:.3}\n", d.named, d.gap_shrink);
    for st in &d.steps {
        for c in &st.candidates {
            s += &format!(
                "  {} gain {:.4} bic_drop {:.1} {:?}\n",
                c.effect,
                c.holdout_gain,
                c.bic_drop,
                c.outcome
                    .as_ref()
                    .map(|o| o.effect_params.clone())
                    .map_err(|e| e.clone())
            );
        }
    }
    s
}
