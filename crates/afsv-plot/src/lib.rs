//! SVG line plots (plotters) for reports and `--plot` options of the afsv toolkit: the
//! discovery report's overlays and residuals, validation figures and CLI plots.
//!
//! Non-finite points are left out of a curve; a plot with no finite point is an error.
//!
//! ```no_run
//! use afsv_plot::{line_plot, Series};
//! use std::path::Path;
//!
//! let t = [0.0, 0.5, 1.0];
//! let measured = [0.0, 1.2, 0.9];
//! let model = [0.0, 1.0, 1.0];
//! line_plot(
//!     Path::new("force.svg"),
//!     "strut force",
//!     "time (s)",
//!     "force (N)",
//!     &[
//!         Series { label: "measured", x: &t, y: &measured },
//!         Series { label: "model", x: &t, y: &model },
//!     ],
//! )
//! .unwrap();
//! ```

use plotters::prelude::*;
use std::path::Path;

/// One curve: legend label, x values, y values.
pub struct Series<'a> {
    /// Legend label.
    pub label: &'a str,
    /// Abscissa.
    pub x: &'a [f64],
    /// Ordinate.
    pub y: &'a [f64],
}

const COLORS: [RGBColor; 6] = [
    RGBColor(0, 0, 0),
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
];

/// Draw `series` into an 900x520 SVG at `path`.
pub fn line_plot(
    path: &Path,
    title: &str,
    x_label: &str,
    y_label: &str,
    series: &[Series<'_>],
) -> Result<(), String> {
    let finite = |v: &&f64| v.is_finite();
    let (mut x0, mut x1, mut y0, mut y1) = (
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    );
    for s in series {
        for &v in s.x.iter().filter(finite) {
            x0 = x0.min(v);
            x1 = x1.max(v);
        }
        for &v in s.y.iter().filter(finite) {
            y0 = y0.min(v);
            y1 = y1.max(v);
        }
    }
    if x0 >= x1 {
        x1 = x0 + 1.0;
    }
    if y0 >= y1 {
        y0 -= 0.5;
        y1 += 0.5;
    }
    if !x0.is_finite() || !y0.is_finite() {
        return Err(format!("nothing to plot in {}", path.display()));
    }
    let pad = 0.05 * (y1 - y0);
    let err = |e: &dyn std::fmt::Display| format!("{}: {e}", path.display());
    let root = SVGBackend::new(path, (900, 520)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(&e))?;
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d(x0..x1, (y0 - pad)..(y1 + pad))
        .map_err(|e| err(&e))?;
    chart
        .configure_mesh()
        .x_desc(x_label)
        .y_desc(y_label)
        .draw()
        .map_err(|e| err(&e))?;
    for (i, s) in series.iter().enumerate() {
        let color = COLORS[i % COLORS.len()];
        let pts: Vec<(f64, f64)> =
            s.x.iter()
                .zip(s.y)
                .filter(|(a, b)| a.is_finite() && b.is_finite())
                .map(|(a, b)| (*a, *b))
                .collect();
        chart
            .draw_series(LineSeries::new(pts, color.stroke_width(2)))
            .map_err(|e| err(&e))?
            .label(s.label)
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 18, y)], color.stroke_width(2))
            });
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()
        .map_err(|e| err(&e))?;
    root.present().map_err(|e| err(&e))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn writes_an_svg() {
        let dir = std::env::temp_dir().join(format!("afsv-plot-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let p = dir.join("a.svg");
        let x = [0.0, 1.0, 2.0];
        let y = [1.0, 0.0, 1.0];
        line_plot(
            &p,
            "t",
            "x",
            "y",
            &[Series {
                label: "a",
                x: &x,
                y: &y,
            }],
        )
        .unwrap();
        let text = std::fs::read_to_string(&p).unwrap();
        assert!(text.starts_with("<svg"));
        assert!(line_plot(&p, "t", "x", "y", &[]).is_err());
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
