//! SVG line plots (plotters) for reports and `--plot` options of the afsv toolkit: the
//! discovery report's overlays and residuals, validation figures and CLI plots.
//!
//! Every figure has a title naming what is plotted and, on a second line, the conditions
//! (record, load, speed, strut, ...); axes are labelled `quantity (unit)` in the engineering
//! unit the caller chose (MPa, kN, mm, deg); the legend sits in its own column to the
//! right of the plot area, so it never covers data. Non-finite points are left out of a
//! curve; a plot with no finite point is an error.
//!
//! ```no_run
//! use afsv_plot::{figure, Axis, Figure, Series};
//! use std::path::Path;
//!
//! let t = [0.0, 0.5, 1.0];
//! let measured = [0.0, 1.2, 0.9];
//! let model = [0.0, 1.0, 1.0];
//! figure(
//!     Path::new("force.svg"),
//!     &Figure {
//!         title: "strut force",
//!         conditions: "record run3.csv, front-axle strut, 1 Hz, 24 mm",
//!         x: Axis::new("time", "s"),
//!         y: Axis::new("force", "kN"),
//!     },
//!     &[
//!         Series { label: "measured", x: &t, y: &measured },
//!         Series { label: "model", x: &t, y: &model },
//!     ],
//! )
//! .unwrap();
//! ```

mod chart;

pub use chart::{Chart, ChartPanel, Curve};

use plotters::coord::ranged1d::ValueFormatter;
use plotters::coord::Shift;
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

/// An axis: the quantity and its unit, shown as `quantity (unit)`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Axis<'a> {
    /// Quantity, e.g. `strut force`.
    pub quantity: &'a str,
    /// Unit, e.g. `kN`; `-` for a dimensionless quantity.
    pub unit: &'a str,
    /// Logarithmic scale (for quantities that span decades: PSDs, frequencies, α_r); only
    /// the positive values are drawn.
    pub log: bool,
}

impl<'a> Axis<'a> {
    /// A linear axis, `quantity (unit)`.
    pub const fn new(quantity: &'a str, unit: &'a str) -> Self {
        Self {
            quantity,
            unit,
            log: false,
        }
    }

    /// A logarithmic axis, `quantity (unit)`.
    pub const fn log(quantity: &'a str, unit: &'a str) -> Self {
        Self {
            quantity,
            unit,
            log: true,
        }
    }

    /// The axis label, `quantity (unit)`.
    pub fn label(&self) -> String {
        format!("{} ({})", self.quantity, self.unit)
    }
}

/// What a figure shows: title, conditions, axes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Figure<'a> {
    /// First title line: what is plotted.
    pub title: &'a str,
    /// Second title line: the record and conditions (may be empty).
    pub conditions: &'a str,
    /// Abscissa.
    pub x: Axis<'a>,
    /// Ordinate.
    pub y: Axis<'a>,
}

const COLORS: [RGBColor; 6] = [
    RGBColor(0, 0, 0),
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
];

/// Width of the figure (px).
const WIDTH: u32 = 1000;
/// Height of the figure (px).
const HEIGHT: u32 = 560;

/// Draw `series` into a 1000x560 SVG at `path`: title and conditions on top, the plot
/// area, and the legend in a column on the right.
pub fn figure(path: &Path, fig: &Figure<'_>, series: &[Series<'_>]) -> Result<(), String> {
    render(
        path,
        fig.title,
        fig.conditions,
        (&fig.x.label(), fig.x.log),
        (&fig.y.label(), fig.y.log),
        series,
    )
}

/// [`figure`] with the axis labels as text (with whether each is logarithmic) and the
/// conditions line `conditions` (may be empty).
fn render(
    path: &Path,
    title: &str,
    conditions: &str,
    x_label: (&str, bool),
    y_label: (&str, bool),
    series: &[Series<'_>],
) -> Result<(), String> {
    let err = |e: &dyn std::fmt::Display| format!("{}: {e}", path.display());
    let ranges = ranges(series, x_label.1, y_label.1)
        .ok_or_else(|| format!("nothing to plot in {}", path.display()))?;
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (WIDTH, HEIGHT)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| err(&e))?;
        let area = titled(&root, title, conditions).map_err(|e| err(&e))?;
        let (plot, legend) = area.split_horizontally(WIDTH - legend_width(series));
        draw_labelled(&plot, None, x_label, y_label, ranges, series).map_err(|e| err(&e))?;
        draw_legend(&legend, series).map_err(|e| err(&e))?;
        root.present().map_err(|e| err(&e))?;
    }
    afsv_records::atomic::write(path, svg).map_err(|e| err(&e))
}

/// `area` below a title line and, when not empty, a conditions line.
fn titled<'b>(
    area: &DrawingArea<SVGBackend<'b>, Shift>,
    title: &str,
    conditions: &str,
) -> Result<DrawingArea<SVGBackend<'b>, Shift>, String> {
    let e = |e: &dyn std::fmt::Display| e.to_string();
    let below = area.titled(title, ("sans-serif", 20)).map_err(|x| e(&x))?;
    if conditions.is_empty() {
        Ok(below)
    } else {
        below
            .titled(conditions, ("sans-serif", 14))
            .map_err(|x| e(&x))
    }
}

/// One panel of a [`panels`] figure: its caption, axes and curves.
pub struct Panel<'a> {
    /// Caption of the panel.
    pub caption: &'a str,
    /// Abscissa.
    pub x: Axis<'a>,
    /// Ordinate.
    pub y: Axis<'a>,
    /// Curves.
    pub series: Vec<Series<'a>>,
}

/// Several panels in a grid of `columns` columns (e.g. the four loops of a strut test),
/// with one title and conditions line on top; each panel has its legend in a column on
/// its right.
pub fn panels(
    path: &Path,
    title: &str,
    conditions: &str,
    columns: usize,
    panels: &[Panel<'_>],
) -> Result<(), String> {
    let err = |e: &dyn std::fmt::Display| format!("{}: {e}", path.display());
    if panels.is_empty() || columns == 0 {
        return Err(format!("nothing to plot in {}", path.display()));
    }
    let rows = panels.len().div_ceil(columns);
    let (w, h) = (600 * columns as u32, 450 * rows as u32 + 60);
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (w, h)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| err(&e))?;
        let area = titled(&root, title, conditions).map_err(|e| err(&e))?;
        for (cell, p) in area.split_evenly((rows, columns)).iter().zip(panels) {
            let ranges = ranges(&p.series, p.x.log, p.y.log).ok_or_else(|| {
                format!(
                    "nothing to plot in panel `{}` of {}",
                    p.caption,
                    path.display()
                )
            })?;
            let (cw, _) = cell.dim_in_pixel();
            let (plot, legend) =
                cell.split_horizontally(cw.saturating_sub(legend_width(&p.series)));
            draw_panel(&plot, Some(p.caption), p.x, p.y, ranges, &p.series).map_err(|e| err(&e))?;
            draw_legend(&legend, &p.series).map_err(|e| err(&e))?;
        }
        root.present().map_err(|e| err(&e))?;
    }
    afsv_records::atomic::write(path, svg).map_err(|e| err(&e))
}

/// Draw `series` into an SVG at `path` with the axis labels given as text (the caller
/// writes the unit into them, `time (s)`); no conditions line. See [`figure`].
pub fn line_plot(
    path: &Path,
    title: &str,
    x_label: &str,
    y_label: &str,
    series: &[Series<'_>],
) -> Result<(), String> {
    render(path, title, "", (x_label, false), (y_label, false), series)
}

/// [`line_plot`] with a logarithmic abscissa, for a study variable that spans decades
/// (e.g. the road roughness α_r); points with x <= 0 are left out.
pub fn line_plot_log_x(
    path: &Path,
    title: &str,
    x_label: &str,
    y_label: &str,
    series: &[Series<'_>],
) -> Result<(), String> {
    render(path, title, "", (x_label, true), (y_label, false), series)
}

/// Whether the point `(a, b)` is drawn on axes with these scales: finite, and positive on
/// a logarithmic axis.
fn drawable(a: f64, b: f64, x_log: bool, y_log: bool) -> bool {
    a.is_finite() && b.is_finite() && (!x_log || a > 0.0) && (!y_log || b > 0.0)
}

/// (x0, x1, y0, y1) over the drawable points of `series` (padded on a linear ordinate), or
/// `None` without any.
fn ranges(series: &[Series<'_>], x_log: bool, y_log: bool) -> Option<(f64, f64, f64, f64)> {
    let (mut x0, mut x1, mut y0, mut y1) = (
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    );
    for s in series {
        for (&a, &b) in s.x.iter().zip(s.y) {
            if drawable(a, b, x_log, y_log) {
                x0 = x0.min(a);
                x1 = x1.max(a);
                y0 = y0.min(b);
                y1 = y1.max(b);
            }
        }
    }
    if !x0.is_finite() || !y0.is_finite() {
        return None;
    }
    if x0 >= x1 {
        x1 = if x_log { 10.0 * x0 } else { x0 + 1.0 };
    }
    if y_log {
        if y0 >= y1 {
            y1 = 10.0 * y0;
        }
        return Some((x0, x1, y0, y1));
    }
    if y0 >= y1 {
        y0 -= 0.5;
        y1 += 0.5;
    }
    let pad = 0.05 * (y1 - y0);
    Some((x0, x1, y0 - pad, y1 + pad))
}

/// Width of the legend column: the longest label at ~7.5 px a character, plus the line
/// sample and margins.
fn legend_width(series: &[Series<'_>]) -> u32 {
    let chars = series
        .iter()
        .map(|s| s.label.chars().count())
        .max()
        .unwrap_or(0);
    (chars as u32 * 15 / 2 + 50).clamp(80, 360)
}

fn draw_panel(
    area: &DrawingArea<SVGBackend<'_>, Shift>,
    caption: Option<&str>,
    x: Axis<'_>,
    y: Axis<'_>,
    ranges: (f64, f64, f64, f64),
    series: &[Series<'_>],
) -> Result<(), String> {
    draw_labelled(
        area,
        caption,
        (&x.label(), x.log),
        (&y.label(), y.log),
        ranges,
        series,
    )
}

fn draw_labelled(
    area: &DrawingArea<SVGBackend<'_>, Shift>,
    caption: Option<&str>,
    (x_label, x_log): (&str, bool),
    (y_label, y_log): (&str, bool),
    (x0, x1, y0, y1): (f64, f64, f64, f64),
    series: &[Series<'_>],
) -> Result<(), String> {
    let e = |e: &dyn std::fmt::Display| e.to_string();
    let mut builder = ChartBuilder::on(area);
    if let Some(c) = caption {
        builder.caption(c, ("sans-serif", 16));
    }
    builder
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(75);
    let labels = (x_label, y_label);
    let scales = (x_log, y_log);
    match scales {
        (false, false) => draw_on(
            builder.build_cartesian_2d(x0..x1, y0..y1),
            labels,
            scales,
            series,
        ),
        (true, false) => draw_on(
            builder.build_cartesian_2d((x0..x1).log_scale(), y0..y1),
            labels,
            scales,
            series,
        ),
        (false, true) => draw_on(
            builder.build_cartesian_2d(x0..x1, (y0..y1).log_scale()),
            labels,
            scales,
            series,
        ),
        (true, true) => draw_on(
            builder.build_cartesian_2d((x0..x1).log_scale(), (y0..y1).log_scale()),
            labels,
            scales,
            series,
        ),
    }
    .map_err(|x| e(&x))
}

/// The mesh and the curves on a chart of any scale. The first six curves differ by colour;
/// later ones repeat the colours with markers (circle, triangle, cross in turn), so no two
/// curves look alike.
fn draw_on<'b, X, Y>(
    chart: Result<
        ChartContext<'b, SVGBackend<'b>, Cartesian2d<X, Y>>,
        DrawingAreaErrorKind<std::io::Error>,
    >,
    (x_label, y_label): (&str, &str),
    (x_log, y_log): (bool, bool),
    series: &[Series<'_>],
) -> Result<(), String>
where
    X: Ranged<ValueType = f64> + ValueFormatter<f64>,
    Y: Ranged<ValueType = f64> + ValueFormatter<f64>,
{
    let e = |e: &dyn std::fmt::Display| e.to_string();
    let mut chart = chart.map_err(|x| e(&x))?;
    chart
        .configure_mesh()
        .x_desc(x_label)
        .y_desc(y_label)
        .draw()
        .map_err(|x| e(&x))?;
    for (i, s) in series.iter().enumerate() {
        let color = COLORS[i % COLORS.len()];
        let pts: Vec<(f64, f64)> =
            s.x.iter()
                .zip(s.y)
                .filter(|(a, b)| drawable(**a, **b, x_log, y_log))
                .map(|(a, b)| (*a, *b))
                .collect();
        chart
            .draw_series(LineSeries::new(pts.clone(), color.stroke_width(2)))
            .map_err(|x| e(&x))?;
        // Markers on at most ~25 points per curve, so dense curves stay readable.
        let every = (pts.len() / 25).max(1);
        let marked = pts.iter().step_by(every).copied();
        match marker(i) {
            Marker::None => {}
            Marker::Circle => {
                chart
                    .draw_series(marked.map(|p| Circle::new(p, 4, color.stroke_width(2))))
                    .map_err(|x| e(&x))?;
            }
            Marker::Triangle => {
                chart
                    .draw_series(marked.map(|p| TriangleMarker::new(p, 5, color.stroke_width(2))))
                    .map_err(|x| e(&x))?;
            }
            Marker::Cross => {
                chart
                    .draw_series(marked.map(|p| Cross::new(p, 4, color.stroke_width(2))))
                    .map_err(|x| e(&x))?;
            }
        }
    }
    Ok(())
}

/// The marker of curve `i` (see [`draw_on`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Marker {
    None,
    Circle,
    Triangle,
    Cross,
}

fn marker(i: usize) -> Marker {
    match (i / COLORS.len()) % 4 {
        0 => Marker::None,
        1 => Marker::Circle,
        2 => Marker::Triangle,
        _ => Marker::Cross,
    }
}

/// The legend in its own column: a line sample and the label per series, top down.
fn draw_legend(
    area: &DrawingArea<SVGBackend<'_>, Shift>,
    series: &[Series<'_>],
) -> Result<(), String> {
    let e = |e: &dyn std::fmt::Display| e.to_string();
    for (i, s) in series.iter().enumerate() {
        let color = COLORS[i % COLORS.len()];
        let y = 30 + 22 * i as i32;
        area.draw(&PathElement::new(
            vec![(8, y), (30, y)],
            color.stroke_width(2),
        ))
        .map_err(|x| e(&x))?;
        let style = color.stroke_width(2);
        match marker(i) {
            Marker::None => Ok(()),
            Marker::Circle => area.draw(&Circle::new((19, y), 4, style)),
            Marker::Triangle => area.draw(&TriangleMarker::new((19, y), 5, style)),
            Marker::Cross => area.draw(&Cross::new((19, y), 4, style)),
        }
        .map_err(|x| e(&x))?;
        area.draw(&Text::new(
            s.label.to_string(),
            (36, y - 7),
            ("sans-serif", 13).into_font(),
        ))
        .map_err(|x| e(&x))?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> std::path::PathBuf {
        let dir = std::env::temp_dir().join(format!("afsv-plot-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        dir.join(name)
    }

    #[test]
    fn writes_an_svg() {
        let p = scratch("a.svg");
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
        let nan = [f64::NAN; 3];
        assert!(line_plot(
            &p,
            "t",
            "x",
            "y",
            &[Series {
                label: "a",
                x: &x,
                y: &nan
            }]
        )
        .is_err());
    }

    #[test]
    fn figures_carry_title_conditions_units_and_a_legend_beside_the_data() {
        let p = scratch("fig.svg");
        let x = [-20.0, 0.0, 20.0];
        let y = [-80.0, 0.0, 80.0];
        figure(
            &p,
            &Figure {
                title: "Fiala lateral force",
                conditions: "nominal tire, Fz = 100 kN",
                x: Axis::new("slip angle", "deg"),
                y: Axis::new("lateral force F_y", "kN"),
            },
            &[Series {
                label: "Fz = 100 kN, kappa = 0",
                x: &x,
                y: &y,
            }],
        )
        .unwrap();
        let svg = std::fs::read_to_string(&p).unwrap();
        for must in [
            "Fiala lateral force",
            "nominal tire, Fz = 100 kN",
            "slip angle (deg)",
            "lateral force F_y (kN)",
            "Fz = 100 kN, kappa = 0",
        ] {
            assert!(svg.contains(must), "{must} missing");
        }
        // The legend text starts right of the plot area's right edge.
        let legend_x = WIDTH
            - legend_width(&[Series {
                label: "Fz = 100 kN, kappa = 0",
                x: &x,
                y: &y,
            }]);
        let at = svg.find("Fz = 100 kN, kappa = 0").unwrap();
        let tag = &svg[svg[..at].rfind("<text").unwrap()..at];
        let x_attr: f64 = tag
            .split("x=\"")
            .nth(1)
            .and_then(|r| r.split('"').next())
            .and_then(|v| v.parse().ok())
            .unwrap();
        assert!(
            x_attr >= legend_x as f64,
            "legend at x = {x_attr}, plot ends at {legend_x}"
        );
    }

    #[test]
    fn log_axes_span_decades_and_later_curves_get_markers() {
        let p = scratch("log.svg");
        // alpha_r from 1.6e-7 to 4.1e-5 in x4 steps, as the roughness study runs it.
        let x: Vec<f64> = (0..5).map(|k| 1.6e-7 * 4f64.powi(k)).collect();
        let ys: Vec<Vec<f64>> = (0..8)
            .map(|c| x.iter().map(|a| (c as f64 + 1.0) * a.sqrt()).collect())
            .collect();
        let labels: Vec<String> = (0..8).map(|c| format!("curve {c}")).collect();
        let series: Vec<Series<'_>> = ys
            .iter()
            .zip(&labels)
            .map(|(y, label)| Series { label, x: &x, y })
            .collect();
        figure(
            &p,
            &Figure {
                title: "log-log",
                conditions: "",
                x: Axis::log("road roughness alpha_r", "m^3"),
                y: Axis::log("response", "-"),
            },
            &series,
        )
        .unwrap();
        let svg = std::fs::read_to_string(&p).unwrap();
        // Curves 7 and 8 repeat the first two colours with circles (on the data and in
        // the legend); the first six have none.
        let circles = svg.matches("<circle").count();
        assert_eq!(circles, 2 * (x.len() + 1), "{circles}");
        // Every curve is drawn although the abscissa spans 2.4 decades, and non-positive
        // values are left out on a log axis instead of failing.
        let zero = [0.0, 1e-6, 1e-5];
        let y = [1.0, 2.0, 3.0];
        figure(
            &p,
            &Figure {
                title: "t",
                conditions: "",
                x: Axis::log("x", "-"),
                y: Axis::new("y", "-"),
            },
            &[Series {
                label: "a",
                x: &zero,
                y: &y,
            }],
        )
        .unwrap();
        assert!(!drawable(0.0, 1.0, true, false));
        assert!(drawable(0.0, 1.0, false, false));
    }

    #[test]
    fn panels_have_their_own_axes() {
        let p = scratch("panels.svg");
        let z = [-7.5, 0.0, 7.5];
        let f = [100.0, 150.0, 210.0];
        let mpa = [5.0, 6.0, 7.5];
        panels(
            &p,
            "front-axle strut, 2 Hz, 7.5 mm",
            "last cycle of 5",
            2,
            &[
                Panel {
                    caption: "Force-deflection",
                    x: Axis::new("deflection", "mm"),
                    y: Axis::new("force", "kN"),
                    series: vec![Series {
                        label: "F_h",
                        x: &z,
                        y: &f,
                    }],
                },
                Panel {
                    caption: "Pressure-deflection",
                    x: Axis::new("deflection", "mm"),
                    y: Axis::new("pressure", "MPa"),
                    series: vec![Series {
                        label: "P_hc",
                        x: &z,
                        y: &mpa,
                    }],
                },
            ],
        )
        .unwrap();
        let svg = std::fs::read_to_string(&p).unwrap();
        for must in [
            "deflection (mm)",
            "force (kN)",
            "pressure (MPa)",
            "last cycle of 5",
            "P_hc",
        ] {
            assert!(svg.contains(must), "{must} missing");
        }
        assert!(panels(&p, "t", "", 2, &[]).is_err());
    }
}
