//! Figures in the style of the report's: computed theory as lines, measured
//! points as open circles, the report's printed theory as small crosses.
//! PNG (bitmap backend) and SVG; text is drawn with DejaVu Sans embedded in the
//! binary (`assets/DejaVuSans.ttf`, licence `assets/LICENSE-DejaVu.txt`), so no
//! fontconfig or freetype is needed on the machine.

use std::path::Path;
use std::sync::OnceLock;

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::FontStyle;

use crate::ReproduceError;
use crate::tables::{Figure, Style};

const FONT: &[u8] = include_bytes!("../assets/DejaVuSans.ttf");
const FAMILY: &str = "sans-serif";

fn register_font() -> Result<(), ReproduceError> {
    static DONE: OnceLock<bool> = OnceLock::new();
    let ok = *DONE
        .get_or_init(|| plotters::style::register_font(FAMILY, FontStyle::Normal, FONT).is_ok());
    if ok {
        Ok(())
    } else {
        Err(ReproduceError::Plot(
            "embedded font: DejaVuSans.ttf is not a valid font".into(),
        ))
    }
}

const PALETTE: [RGBColor; 10] = [
    RGBColor(0, 0, 0),
    RGBColor(200, 30, 30),
    RGBColor(30, 90, 200),
    RGBColor(20, 140, 50),
    RGBColor(190, 110, 0),
    RGBColor(140, 40, 170),
    RGBColor(0, 150, 160),
    RGBColor(120, 80, 40),
    RGBColor(220, 60, 150),
    RGBColor(100, 100, 100),
];

fn color(i: usize) -> RGBColor {
    PALETTE[i % PALETTE.len()]
}

fn err(id: &str, e: impl std::fmt::Display) -> ReproduceError {
    ReproduceError::Plot(format!("{id}: {e}"))
}

/// (x range, y range) of a figure.
type Bounds = ((f64, f64), (f64, f64));

fn bounds(fig: &Figure) -> Result<Bounds, ReproduceError> {
    let pts = fig
        .series
        .iter()
        .flat_map(|s| s.points.iter())
        .filter(|p| p.0.is_finite() && p.1.is_finite());
    let (mut x0, mut x1, mut y0, mut y1) = (
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    );
    for p in pts {
        x0 = x0.min(p.0);
        x1 = x1.max(p.0);
        y0 = y0.min(p.1);
        y1 = y1.max(p.1);
    }
    if !(x0.is_finite() && y0.is_finite()) {
        return Err(err(&fig.id, "no finite points to plot"));
    }
    let pad = |a: f64, b: f64| {
        let d = if b > a {
            0.05 * (b - a)
        } else {
            0.05 * a.abs().max(1e-3)
        };
        (a - d, b + d)
    };
    // Show the origin when the data come near it (traction curves start at 0),
    // not for data far from zero (e.g. slopes 20..60 in the Appendix III plots).
    let y0 = if y0 > 0.0 && y0 < 0.3 * y1 { 0.0 } else { y0 };
    Ok((pad(x0, x1), pad(y0, y1)))
}

fn draw<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    fig: &Figure,
) -> Result<(), ReproduceError> {
    let id = fig.id.as_str();
    let ((x0, x1), (y0, y1)) = bounds(fig)?;
    root.fill(&WHITE).map_err(|e| err(id, e))?;
    let mut chart = ChartBuilder::on(&root)
        .caption(&fig.title, (FAMILY, 15))
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(|e| err(id, e))?;
    chart
        .configure_mesh()
        .x_desc(fig.x_label.as_str())
        .y_desc(fig.y_label.as_str())
        .label_style((FAMILY, 13))
        .axis_desc_style((FAMILY, 15))
        .light_line_style(RGBColor(235, 235, 235))
        .draw()
        .map_err(|e| err(id, e))?;
    for s in &fig.series {
        let c = color(s.color);
        let pts: Vec<(f64, f64)> = s
            .points
            .iter()
            .copied()
            .filter(|p| p.0.is_finite() && p.1.is_finite())
            .collect();
        match s.style {
            Style::Line => {
                chart
                    .draw_series(LineSeries::new(pts, c.stroke_width(2)))
                    .map_err(|e| err(id, e))?
                    .label(s.name.as_str())
                    .legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(2))
                    });
            }
            Style::Circles => {
                chart
                    .draw_series(
                        pts.into_iter()
                            .map(move |p| Circle::new(p, 4, c.stroke_width(1))),
                    )
                    .map_err(|e| err(id, e))?
                    .label(s.name.as_str())
                    .legend(move |(x, y)| Circle::new((x + 10, y), 4, c.stroke_width(1)));
            }
            Style::Crosses => {
                chart
                    .draw_series(
                        pts.into_iter()
                            .map(move |p| Cross::new(p, 3, c.stroke_width(1))),
                    )
                    .map_err(|e| err(id, e))?
                    .label(s.name.as_str())
                    .legend(move |(x, y)| Cross::new((x + 10, y), 3, c.stroke_width(1)));
            }
        }
    }
    chart
        .configure_series_labels()
        .label_font((FAMILY, 12))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .position(SeriesLabelPosition::LowerRight)
        .draw()
        .map_err(|e| err(id, e))?;
    root.present().map_err(|e| err(id, e))
}

/// Size of the figures in pixels.
pub const SIZE: (u32, u32) = (1000, 680);

/// Draw `fig` as `DIR/<id>.png` and `DIR/<id>.svg`.
pub fn write_figure(fig: &Figure, dir: &Path) -> Result<(), ReproduceError> {
    register_font()?;
    let png = dir.join(format!("{}.png", fig.id));
    let svg = dir.join(format!("{}.svg", fig.id));
    draw(BitMapBackend::new(&png, SIZE).into_drawing_area(), fig)?;
    draw(SVGBackend::new(&svg, SIZE).into_drawing_area(), fig)
}

/// A scalar field over a regular grid, for [`write_heatmaps`].
#[derive(Debug, Clone, PartialEq)]
pub struct Field {
    /// Panel title (e.g. "J4").
    pub name: String,
    /// Values, row-major: `values[iy * xs.len() + ix]`.
    pub values: Vec<f64>,
}

/// Five-stop viridis-like colour map on [0, 1].
fn colormap(t: f64) -> RGBColor {
    const STOPS: [(f64, f64, f64); 5] = [
        (68.0, 1.0, 84.0),
        (59.0, 82.0, 139.0),
        (33.0, 145.0, 140.0),
        (94.0, 201.0, 98.0),
        (253.0, 231.0, 37.0),
    ];
    let t = if t.is_finite() {
        t.clamp(0.0, 1.0)
    } else {
        0.0
    };
    let f = t * 4.0;
    let i = (f.floor() as usize).min(3);
    let w = f - i as f64;
    let (a, b) = (STOPS[i], STOPS[i + 1]);
    let mix = |p: f64, q: f64| (p + (q - p) * w).round() as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// Heat maps of several fields over the grid `xs` × `ys` in one PNG (2 × 2
/// panels for four fields), each with its own colour scale (min..max in the title).
pub fn write_heatmaps(
    path: &Path,
    title: &str,
    x_label: &str,
    y_label: &str,
    xs: &[f64],
    ys: &[f64],
    fields: &[Field],
) -> Result<(), ReproduceError> {
    register_font()?;
    let id = path.display().to_string();
    if xs.len() < 2 || ys.len() < 2 {
        return Err(err(
            &id,
            "the heat map needs at least 2 values on each axis",
        ));
    }
    let root = BitMapBackend::new(path, (1200, 1000)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(&id, e))?;
    let root = root.titled(title, (FAMILY, 18)).map_err(|e| err(&id, e))?;
    let cols = 2;
    let rows = fields.len().div_ceil(cols).max(1);
    let panels = root.split_evenly((rows, cols));
    let dx = (xs[xs.len() - 1] - xs[0]) / (xs.len() - 1) as f64;
    let dy = (ys[ys.len() - 1] - ys[0]) / (ys.len() - 1) as f64;
    for (panel, f) in panels.iter().zip(fields) {
        let (lo, hi) = f
            .values
            .iter()
            .filter(|v| v.is_finite())
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), v| {
                (l.min(*v), h.max(*v))
            });
        let span = if hi > lo { hi - lo } else { 1.0 };
        let mut chart = ChartBuilder::on(panel)
            .caption(
                format!("{} (dark {lo:.3} .. bright {hi:.3})", f.name),
                (FAMILY, 15),
            )
            .margin(10)
            .x_label_area_size(40)
            .y_label_area_size(50)
            .build_cartesian_2d(
                xs[0] - dx / 2.0..xs[xs.len() - 1] + dx / 2.0,
                ys[0] - dy / 2.0..ys[ys.len() - 1] + dy / 2.0,
            )
            .map_err(|e| err(&id, e))?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc(x_label)
            .y_desc(y_label)
            .label_style((FAMILY, 12))
            .axis_desc_style((FAMILY, 13))
            .draw()
            .map_err(|e| err(&id, e))?;
        let nx = xs.len();
        chart
            .draw_series(f.values.iter().enumerate().map(|(i, v)| {
                let (ix, iy) = (i % nx, i / nx);
                let (x, y) = (xs[ix], ys[iy.min(ys.len() - 1)]);
                Rectangle::new(
                    [(x - dx / 2.0, y - dy / 2.0), (x + dx / 2.0, y + dy / 2.0)],
                    colormap((v - lo) / span).filled(),
                )
            }))
            .map_err(|e| err(&id, e))?;
    }
    root.present().map_err(|e| err(&id, e))
}
