//! Plot data out of the page: CSV of a figure's series, SVG of a figure, and the values
//! under a pointer (the crosshair read-out).

use crate::figure::{Figure, FigureKind};
use crate::format::si;
use crate::render::{render, PlotGeometry};
use crate::theme::Theme;
use plotters::prelude::{IntoDrawingArea, SVGBackend};

fn csv_field(s: &str) -> String {
    if s.contains([',', '"', '\n']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

/// The figure's series as CSV: `#` comment lines naming the demo and every parameter with
/// its unit, then a header row and the data. Series sharing one x grid become columns of
/// one table; otherwise the table is long (`series, x, y`).
pub fn csv(demo: &str, params: &[(&str, f64, &str)], fig: &Figure) -> String {
    let mut out = format!("# Zeta Lab, demo {demo}: {}\n", fig.title);
    for (key, value, unit) in params {
        let unit = if unit.is_empty() {
            String::new()
        } else {
            format!(" {unit}")
        };
        out.push_str(&format!("# {key} = {value}{unit}\n"));
    }
    let named: Vec<_> = fig.series.iter().filter(|s| !s.points.is_empty()).collect();
    let x_name = csv_field(&fig.x.title());
    let y_unit = if fig.y.unit.is_empty() {
        String::new()
    } else {
        format!(" [{}]", fig.y.unit)
    };
    let label = |i: usize, l: &str| {
        let l = if l.is_empty() {
            format!("series {}", i + 1)
        } else {
            l.to_string()
        };
        csv_field(&format!("{l}{y_unit}"))
    };
    let shared = named.windows(2).all(|w| {
        w[0].points.len() == w[1].points.len()
            && w[0]
                .points
                .iter()
                .zip(&w[1].points)
                .all(|(a, b)| a.0 == b.0)
    });
    if shared && !named.is_empty() {
        let cols: Vec<String> = named
            .iter()
            .enumerate()
            .map(|(i, s)| label(i, &s.label))
            .collect();
        out.push_str(&format!("{x_name},{}\n", cols.join(",")));
        for (row, p) in named[0].points.iter().enumerate() {
            out.push_str(&format!("{}", p.0));
            for s in &named {
                let y = s.points.get(row).map(|p| p.1).unwrap_or(f64::NAN);
                if y.is_finite() {
                    out.push_str(&format!(",{y}"));
                } else {
                    out.push(',');
                }
            }
            out.push('\n');
        }
    } else {
        out.push_str(&format!("series,{x_name},{}\n", csv_field(&fig.y.title())));
        for (i, s) in named.iter().enumerate() {
            let name = label(i, &s.label);
            for p in s
                .points
                .iter()
                .filter(|p| p.0.is_finite() && p.1.is_finite())
            {
                out.push_str(&format!("{name},{},{}\n", p.0, p.1));
            }
        }
    }
    out
}

/// The figure as a standalone SVG document of `w × h` px.
pub fn svg(fig: &Figure, w: u32, h: u32, theme: &Theme) -> Result<String, String> {
    let mut buf = String::new();
    {
        let root = SVGBackend::with_string(&mut buf, (w.clamp(16, 8000), h.clamp(16, 8000)))
            .into_drawing_area();
        render(&root, fig, theme, 1.0).map_err(|e| e.to_string())?;
    }
    Ok(buf)
}

/// One series' value under the pointer.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ProbePoint {
    /// Pixel position of the point (backend pixels).
    pub px: f64,
    /// Pixel position of the point (backend pixels).
    pub py: f64,
    /// Palette colour of the series.
    pub color: usize,
    /// "label = value unit".
    pub text: String,
}

/// What lies under the pointer at backend pixel `(px, py)`.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Probe {
    /// "x = … unit" at the pointer.
    pub x_text: String,
    /// "y = … unit" at the pointer.
    pub y_text: String,
    /// The nearest point of each labelled series at the pointer's x.
    pub points: Vec<ProbePoint>,
}

/// Reads the figure at a pointer position; `None` outside the plotting area or on schematics.
pub fn probe(fig: &Figure, geo: &PlotGeometry, px: f64, py: f64) -> Option<Probe> {
    if fig.kind == FigureKind::Schematic {
        return None;
    }
    let (x, y) = geo.to_data(px, py)?;
    let mut points = Vec::new();
    for s in fig.series.iter().filter(|s| !s.label.is_empty()) {
        let nearest = s
            .points
            .iter()
            .filter(|p| p.0.is_finite() && p.1.is_finite())
            .min_by(|a, b| (a.0 - x).abs().total_cmp(&(b.0 - x).abs()));
        if let Some(&(sx, sy)) = nearest {
            let (ppx, ppy) = geo.to_pixel(sx, sy);
            points.push(ProbePoint {
                px: ppx,
                py: ppy,
                color: s.style.ink.index(),
                text: format!("{} = {}", s.label, si(sy, fig.y.unit, 4)),
            });
        }
    }
    Some(Probe {
        x_text: format!("{} = {}", fig.x.label, si(x, fig.x.unit, 4)),
        y_text: format!("{} = {}", fig.y.label, si(y, fig.y.unit, 4)),
        points,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::figure::{Axis, LineStyle, Series};
    use crate::plot::Ink;

    fn fig() -> Figure {
        let pts = |k: f64| (0..5).map(|i| (i as f64 * 0.5, k * i as f64)).collect();
        Figure {
            series: vec![
                Series {
                    label: "a, b".into(),
                    points: pts(1.0),
                    style: LineStyle::solid(Ink::Blue, 1.0),
                },
                Series {
                    label: "c".into(),
                    points: pts(2.0),
                    style: LineStyle::solid(Ink::Vermillion, 1.0),
                },
            ],
            ..Figure::plot(
                "f",
                Axis::linear("time t", "s", (0.0, 2.0)),
                Axis::linear("x", "m", (0.0, 8.0)),
            )
        }
    }

    #[test]
    fn csv_has_parameters_header_and_shared_columns() {
        let text = csv(
            "regimes",
            &[("zeta", 0.2, ""), ("wn", 6.0, "rad/s")],
            &fig(),
        );
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines[1], "# zeta = 0.2");
        assert_eq!(lines[2], "# wn = 6 rad/s");
        assert_eq!(lines[3], "time t [s],\"a, b [m]\",c [m]");
        assert_eq!(lines[5], "0.5,1,2");
        assert_eq!(lines.len(), 9);
    }

    #[test]
    fn probe_finds_the_nearest_points() {
        let f = fig();
        let mut buf = String::new();
        let geo = {
            let root = SVGBackend::with_string(&mut buf, (600, 400)).into_drawing_area();
            render(&root, &f, &Theme::LIGHT, 1.0).unwrap()
        };
        let (px, py) = geo.to_pixel(1.02, 3.0);
        let p = probe(&f, &geo, px, py).unwrap();
        assert_eq!(p.points.len(), 2);
        assert_eq!(p.points[0].text, "a, b = 2.000 m");
        assert_eq!(p.points[1].text, "c = 4.000 m");
        assert!(p.x_text.starts_with("time t = 1.02"));
        assert!(probe(&f, &geo, 1.0, 1.0).is_none());
    }

    #[test]
    fn svg_is_a_document() {
        let s = svg(&fig(), 400, 300, &Theme::DARK).unwrap();
        assert!(s.starts_with("<svg") && s.contains("time t [s]"));
    }
}
