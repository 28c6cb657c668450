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
}

impl<'a> Axis<'a> {
    /// `quantity (unit)`.
    pub const fn new(quantity: &'a str, unit: &'a str) -> Self {
        Self { quantity, unit }
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
        &fig.x.label(),
        &fig.y.label(),
        series,
    )
}

/// [`figure`] with the axis labels as text and the conditions line `conditions` (may be
/// empty).
fn render(
    path: &Path,
    title: &str,
    conditions: &str,
    x_label: &str,
    y_label: &str,
    series: &[Series<'_>],
) -> Result<(), String> {
    let err = |e: &dyn std::fmt::Display| format!("{}: {e}", path.display());
    let ranges = ranges(series).ok_or_else(|| format!("nothing to plot in {}", path.display()))?;
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
            let ranges = ranges(&p.series).ok_or_else(|| {
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
    render(path, title, "", x_label, y_label, series)
}

/// Padded (x0, x1, y0, y1) over the finite points of `series`, or `None` without any.
fn ranges(series: &[Series<'_>]) -> Option<(f64, f64, f64, f64)> {
    let (mut x0, mut x1, mut y0, mut y1) = (
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    );
    for s in series {
        for (&a, &b) in s.x.iter().zip(s.y) {
            if a.is_finite() && b.is_finite() {
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
        x1 = x0 + 1.0;
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
    draw_labelled(area, caption, &x.label(), &y.label(), ranges, series)
}

fn draw_labelled(
    area: &DrawingArea<SVGBackend<'_>, Shift>,
    caption: Option<&str>,
    x_label: &str,
    y_label: &str,
    (x0, x1, y0, y1): (f64, f64, f64, f64),
    series: &[Series<'_>],
) -> Result<(), String> {
    let e = |e: &dyn std::fmt::Display| e.to_string();
    let mut builder = ChartBuilder::on(area);
    if let Some(c) = caption {
        builder.caption(c, ("sans-serif", 16));
    }
    let mut chart = builder
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(75)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(|x| e(&x))?;
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
                .filter(|(a, b)| a.is_finite() && b.is_finite())
                .map(|(a, b)| (*a, *b))
                .collect();
        chart
            .draw_series(LineSeries::new(pts, color.stroke_width(2)))
            .map_err(|x| e(&x))?;
    }
    Ok(())
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
