//! A whole figure as data: the curves, axes, title and conditions a report builds from a
//! result (`afsv_design::report`), written to an SVG by [`Chart::write`] through the drawing
//! functions of this crate ([`crate::figure`], [`crate::panels`], [`crate::line_plot`]).
//! Building a chart computes and decides (which curves, which units, which scales) without
//! touching a file; writing it draws exactly what it holds.

use crate::{figure, line_plot, line_plot_log_x, panels, Axis, Figure, Panel, Series};
use std::path::Path;

/// One curve of a chart: legend label, x values, y values.
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    /// Legend label.
    pub label: String,
    /// Abscissa.
    pub x: Vec<f64>,
    /// Ordinate.
    pub y: Vec<f64>,
}

impl Curve {
    /// A curve labelled `label` through the points `(x[i], y[i])`.
    pub fn new(label: impl Into<String>, x: Vec<f64>, y: Vec<f64>) -> Self {
        Self {
            label: label.into(),
            x,
            y,
        }
    }

    /// The curve as the drawing functions take it.
    pub fn series(&self) -> Series<'_> {
        Series {
            label: &self.label,
            x: &self.x,
            y: &self.y,
        }
    }
}

/// One panel of a [`Chart::Panels`]: its caption, axes and curves.
#[derive(Debug, Clone, PartialEq)]
pub struct ChartPanel {
    /// Caption of the panel.
    pub caption: String,
    /// Abscissa.
    pub x: Axis<'static>,
    /// Ordinate.
    pub y: Axis<'static>,
    /// Curves.
    pub curves: Vec<Curve>,
}

/// A figure as data, in one of the three layouts of this crate.
#[derive(Debug, Clone, PartialEq)]
pub enum Chart {
    /// One plot with a title, a conditions line and axes with units ([`crate::figure`]).
    Figure {
        /// First title line: what is plotted.
        title: String,
        /// Second title line: the conditions (may be empty).
        conditions: String,
        /// Abscissa.
        x: Axis<'static>,
        /// Ordinate.
        y: Axis<'static>,
        /// Curves.
        curves: Vec<Curve>,
    },
    /// Panels in a grid of `columns` columns under one title ([`crate::panels`]).
    Panels {
        /// First title line.
        title: String,
        /// Second title line (may be empty).
        conditions: String,
        /// Columns of the grid.
        columns: usize,
        /// The panels, row by row.
        panels: Vec<ChartPanel>,
    },
    /// One plot with the axis labels as text, units written in ([`crate::line_plot`]; a
    /// logarithmic abscissa with `log_x`, [`crate::line_plot_log_x`]).
    Lines {
        /// Title.
        title: String,
        /// Abscissa label, e.g. `time (s)`.
        x_label: String,
        /// Ordinate label.
        y_label: String,
        /// Logarithmic abscissa.
        log_x: bool,
        /// Curves.
        curves: Vec<Curve>,
    },
}

/// The curves as the drawing functions take them.
fn series(curves: &[Curve]) -> Vec<Series<'_>> {
    curves.iter().map(Curve::series).collect()
}

impl Chart {
    /// The number of curves over all panels.
    pub fn curve_count(&self) -> usize {
        match self {
            Chart::Figure { curves, .. } | Chart::Lines { curves, .. } => curves.len(),
            Chart::Panels { panels, .. } => panels.iter().map(|p| p.curves.len()).sum(),
        }
    }

    /// Draw the chart into an SVG at `path` (only that file is written; marking it as
    /// afsv's is the caller's output guard).
    pub fn write(&self, path: &Path) -> Result<(), String> {
        match self {
            Chart::Figure {
                title,
                conditions,
                x,
                y,
                curves,
            } => figure(
                path,
                &Figure {
                    title,
                    conditions,
                    x: *x,
                    y: *y,
                },
                &series(curves),
            ),
            Chart::Panels {
                title,
                conditions,
                columns,
                panels: cells,
            } => {
                let cells: Vec<Panel<'_>> = cells
                    .iter()
                    .map(|p| Panel {
                        caption: &p.caption,
                        x: p.x,
                        y: p.y,
                        series: series(&p.curves),
                    })
                    .collect();
                panels(path, title, conditions, *columns, &cells)
            }
            Chart::Lines {
                title,
                x_label,
                y_label,
                log_x,
                curves,
            } => {
                let draw = if *log_x { line_plot_log_x } else { line_plot };
                draw(path, title, x_label, y_label, &series(curves))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> std::path::PathBuf {
        let dir = std::env::temp_dir().join(format!("afsv-plot-chart-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        dir.join(name)
    }

    fn curve() -> Curve {
        Curve::new("a", vec![0.0, 1.0, 2.0], vec![1.0, 0.0, 1.0])
    }

    #[test]
    fn each_layout_draws_the_same_svg_as_its_function() {
        let c = curve();
        let (by_chart, by_fn) = (scratch("chart.svg"), scratch("fn.svg"));
        let same = |chart: Chart, draw: &dyn Fn(&Path) -> Result<(), String>| {
            chart.write(&by_chart).unwrap();
            draw(&by_fn).unwrap();
            assert_eq!(
                std::fs::read(&by_chart).unwrap(),
                std::fs::read(&by_fn).unwrap()
            );
        };
        let (x, y) = (Axis::new("time", "s"), Axis::log("force", "kN"));
        same(
            Chart::Figure {
                title: "t".into(),
                conditions: "c".into(),
                x,
                y,
                curves: vec![c.clone()],
            },
            &|p| {
                figure(
                    p,
                    &Figure {
                        title: "t",
                        conditions: "c",
                        x,
                        y,
                    },
                    &[c.series()],
                )
            },
        );
        same(
            Chart::Panels {
                title: "t".into(),
                conditions: String::new(),
                columns: 2,
                panels: vec![ChartPanel {
                    caption: "p".into(),
                    x,
                    y,
                    curves: vec![c.clone()],
                }],
            },
            &|p| {
                panels(
                    p,
                    "t",
                    "",
                    2,
                    &[Panel {
                        caption: "p",
                        x,
                        y,
                        series: vec![c.series()],
                    }],
                )
            },
        );
        for log_x in [false, true] {
            let draw = if log_x { line_plot_log_x } else { line_plot };
            same(
                Chart::Lines {
                    title: "t".into(),
                    x_label: "x (m)".into(),
                    y_label: "y (m)".into(),
                    log_x,
                    curves: vec![c.clone()],
                },
                &|p| draw(p, "t", "x (m)", "y (m)", &[c.series()]),
            );
        }
    }

    #[test]
    fn curves_are_counted_over_panels_and_an_empty_chart_is_refused() {
        let panel = |n| ChartPanel {
            caption: "p".into(),
            x: Axis::new("x", "-"),
            y: Axis::new("y", "-"),
            curves: vec![curve(); n],
        };
        let chart = Chart::Panels {
            title: "t".into(),
            conditions: String::new(),
            columns: 1,
            panels: vec![panel(2), panel(3)],
        };
        assert_eq!(chart.curve_count(), 5);
        let empty = Chart::Lines {
            title: "t".into(),
            x_label: "x".into(),
            y_label: "y".into(),
            log_x: false,
            curves: Vec::new(),
        };
        assert!(empty.write(&scratch("empty.svg")).is_err());
    }
}
