//! The report of `afsv optimize layout` ([`crate::LayoutOptimum`]) as text: the variables
//! with their bounds, the measures, the constraints and whether the optimum is earned; its
//! JSON is the type's own serialisation.

use crate::layout_optimum::{LayoutMeasure, Measured};
use crate::LayoutOptimum;

/// A number with 4 significant digits, or "n/a".
fn num(x: f64) -> String {
    if !x.is_finite() {
        "n/a".into()
    } else if x != 0.0 && (x.abs() < 1e-2 || x.abs() >= 1e5) {
        format!("{x:.3e}")
    } else {
        format!("{x:.4}")
    }
}

/// The measure `k` of `m`, NaN when it was not measured.
fn value(m: &Measured, k: LayoutMeasure) -> f64 {
    m.get(&k).copied().unwrap_or(f64::NAN)
}

/// The report as text.
pub fn text(r: &LayoutOptimum) -> String {
    let mut s = format!(
        "Layout `{}` of `{}`{}: {} rides at {} km/h ({} m window, class E), {} terrain seed(s) from {}; GA {} x {} generations ({} designs)\n",
        r.layout,
        r.vehicle,
        if r.seat { " with cab and seat" } else { "" },
        r.load,
        r.speed_kmh,
        r.ride_length_m,
        r.seeds.len(),
        r.seeds[0],
        r.ga.population,
        r.ga.generations,
        r.evaluations
    );
    s += &format!(
        "{} {} ({})\n\n",
        if r.maximise { "Maximise" } else { "Minimise" },
        r.objective.name(),
        r.objective.unit()
    );
    s += &format!(
        "  {:<28} {:>11} {:>11} {:>11} {:>11}\n",
        "variable", "lower", "upper", "nominal", "optimum"
    );
    for v in &r.variables {
        s += &format!(
            "  {:<28} {:>11} {:>11} {:>11} {:>11}{}\n",
            v.name,
            num(v.lower),
            num(v.upper),
            num(v.nominal),
            num(v.optimum),
            if v.on_bound { "  ON A BOUND" } else { "" }
        );
    }
    s += &format!(
        "\n  {:<28} {:>11} {:>11}\n",
        "measure", "nominal", "optimum"
    );
    for (k, v) in &r.optimum {
        s += &format!(
            "  {:<28} {:>11} {:>11}\n",
            format!("{} ({})", k.name(), k.unit()),
            num(value(&r.nominal, *k)),
            num(*v)
        );
    }
    for c in &r.constraints {
        s += &format!(
            "  constraint {}: bound {}, optimum {} ({})\n",
            c.constraint,
            num(c.bound),
            num(c.optimum),
            if c.met { "met" } else { "NOT met" }
        );
    }
    s += &match r.earned() {
        Ok(()) => "The optimum is feasible and inside the bounds.\n".to_string(),
        Err(why) => format!("Not an optimum: {why}.\n"),
    };
    s
}
