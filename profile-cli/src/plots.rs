//! SVG plots of tables: frequency against time and step, acceleration against time.

use std::path::Path;

use plotters::prelude::*;
use profile_core::{AccelWindows, Spec};

/// One table as plotted: `(time of the step's start in s, frequency in Hz)`
/// per step, the table's acceleration over windows of entries (as the
/// figures read it), and the curve's own acceleration.
pub struct Series {
    pub label: String,
    pub color: RGBColor,
    /// Per step: start time (s), step frequency (Hz).
    pub steps: Vec<(f64, f64)>,
    /// Between consecutive windows of entries ([`AccelWindows`], sized by
    /// the curve's acceleration as for the figures): the time of the edge
    /// between them (s), the change of their mean frequency over the time
    /// between their centres (Hz/s).
    pub accel: Vec<(f64, f64)>,
    /// The curve's acceleration from its unrounded periods, step by step
    /// (empty when its edges cannot be computed).
    pub curve_accel: Vec<(f64, f64)>,
}

/// The table's acceleration (`periods` in s) over [`AccelWindows`], each
/// sized by the curve's own frequency and acceleration there (`exact`: the
/// curve's periods in s, entry by entry), at the edge between windows.
fn table_accel(periods: &[f64], exact: &[f64], scale: f64) -> Vec<(f64, f64)> {
    let total: f64 = periods.iter().sum();
    let mut windows = AccelWindows::new(total * scale / 4.0);
    let (mut out, mut t, mut start) = (Vec::new(), 0.0, 0.0);
    let mut before: Option<f64> = None;
    for (&p, &e) in periods.iter().zip(exact) {
        t += p;
        let f = 1.0 / e;
        let accel = before.map_or(0.0, |b| (f - 1.0 / b) / ((b + e) / 2.0));
        before = Some(e);
        if let Some(a) = windows.push(p * scale, scale, f, accel) {
            out.push((start, a));
        }
        if windows.open_ticks() == 0.0 {
            start = t;
        }
    }
    out
}

/// Acceleration of `periods` (in s) between the mean frequencies of
/// consecutive windows of `w` periods, at the edge between them.
fn windowed_accel(periods: &[f64], w: usize) -> Vec<(f64, f64)> {
    let mut edges = Vec::with_capacity(periods.len() + 1);
    let mut t = 0.0;
    edges.push(t);
    for p in periods {
        t += p;
        edges.push(t);
    }
    (2 * w..=periods.len())
        .map(|end| {
            let (a, b, c) = (edges[end - 2 * w], edges[end - w], edges[end]);
            let (older, newer) = (b - a, c - b);
            let accel = (w as f64 / newer - w as f64 / older) / ((older + newer) / 2.0);
            (b, accel)
        })
        .collect()
}

impl Series {
    /// From periods in ticks on a timer of `frequency_scale` ([`Timer::frequency_scale`](profile_core::Timer::frequency_scale)),
    /// a table of `spec`.
    pub fn new(
        label: &str,
        color: RGBColor,
        periods: &[u32],
        frequency_scale: f64,
        spec: &Spec,
    ) -> Self {
        let seconds: Vec<f64> = periods
            .iter()
            .map(|&p| p as f64 / frequency_scale)
            .collect();
        let mut t = 0.0;
        let mut steps = Vec::with_capacity(periods.len());
        for &dt in &seconds {
            steps.push((t, 1.0 / dt));
            t += dt;
        }
        let mut edges = vec![0.0];
        let exact: Vec<f64> = if spec.for_each_exact_edge(|_, t| edges.push(t)).is_ok() {
            edges.windows(2).map(|w| w[1] - w[0]).collect()
        } else {
            Vec::new()
        };
        Series {
            label: label.to_string(),
            color,
            steps,
            accel: table_accel(&seconds, &exact, frequency_scale),
            curve_accel: windowed_accel(&exact, 1),
        }
    }

    fn duration(&self) -> f64 {
        self.steps.last().map_or(0.0, |s| s.0)
    }
}

type PlotResult = Result<(), Box<dyn std::error::Error>>;

fn bounds(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
        (lo.min(v), hi.max(v))
    });
    if !lo.is_finite() || !hi.is_finite() {
        return (0.0, 1.0);
    }
    let pad = ((hi - lo) * 0.05).max(1e-9);
    (lo.min(0.0), hi + pad)
}

fn chart<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    caption: &str,
    x_desc: &str,
    y_desc: &str,
    series: &[(&Series, Vec<(f64, f64)>)],
) -> PlotResult
where
    DB::ErrorType: 'static,
{
    let lines: Vec<Line> = series
        .iter()
        .map(|(s, points)| Line {
            label: s.label.clone(),
            color: s.color,
            points: points.clone(),
        })
        .collect();
    chart_lines(
        area,
        caption,
        x_desc,
        y_desc,
        &lines,
        Some(SeriesLabelPosition::LowerRight),
    )
}

/// One labelled line of a chart.
pub struct Line {
    pub label: String,
    pub color: RGBColor,
    pub points: Vec<(f64, f64)>,
}

fn chart_lines<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    caption: &str,
    x_desc: &str,
    y_desc: &str,
    series: &[Line],
    legend: Option<SeriesLabelPosition>,
) -> PlotResult
where
    DB::ErrorType: 'static,
{
    let (x0, x1) = bounds(series.iter().flat_map(|l| l.points.iter().map(|q| q.0)));
    let (y0, y1) = bounds(series.iter().flat_map(|l| l.points.iter().map(|q| q.1)));
    let mut chart = ChartBuilder::on(area)
        .caption(caption, ("sans-serif", 18))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(80)
        .build_cartesian_2d(x0..x1, y0..y1)?;
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc(y_desc)
        .draw()?;
    for s in series {
        let color = s.color;
        chart
            .draw_series(LineSeries::new(
                s.points.iter().copied(),
                color.stroke_width(2),
            ))?
            .label(s.label.clone())
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
            });
    }
    if series.len() > 1 {
        let position = legend.unwrap_or_else(|| {
            // At the right, in the widest empty band between the lines.
            let (width, height) = chart.plotting_area().dim_in_pixel();
            let mut ys: Vec<f64> = series
                .iter()
                .flat_map(|l| l.points.iter())
                .filter(|p| p.0 >= x0 + (x1 - x0) * 0.4)
                .map(|p| p.1)
                .chain([y0, y1])
                .collect();
            ys.sort_by(f64::total_cmp);
            let (lo, hi) = ys
                .windows(2)
                .map(|w| (w[0], w[1]))
                .fold((y0, y0), |best, gap| {
                    if gap.1 - gap.0 > best.1 - best.0 {
                        gap
                    } else {
                        best
                    }
                });
            let middle = (y1 - (lo + hi) / 2.0) / (y1 - y0) * height as f64;
            let box_height = 20.0 * series.len() as f64 + 10.0;
            let box_width =
                7.0 * series.iter().map(|l| l.label.len()).max().unwrap_or(0) as f64 + 60.0;
            SeriesLabelPosition::Coordinate(
                (width as f64 - box_width - 10.0).max(0.0) as i32,
                (middle - box_height / 2.0).max(0.0) as i32,
            )
        });
        chart
            .configure_series_labels()
            .border_style(BLACK)
            .background_style(WHITE.mix(0.8))
            .position(position)
            .draw()?;
    }
    Ok(())
}

/// One profile: frequency against time, against step, acceleration against time.
/// A profile's resonance band on its charts: `(lowest, highest)` steps/s
/// and the seconds the ramp spends inside.
pub type Band = (f64, f64, f64);

pub fn profile(path: &Path, title: &str, s: &Series, bands: &[Band]) -> PlotResult {
    let root = SVGBackend::new(path, (900, 1000)).into_drawing_area();
    root.fill(&WHITE)?;
    let areas = root.split_evenly((3, 1));
    let by_step: Vec<(f64, f64)> = s
        .steps
        .iter()
        .enumerate()
        .map(|(i, p)| (i as f64, p.1))
        .collect();
    let mut frequency = vec![Line {
        label: s.label.clone(),
        color: s.color,
        points: s.steps.clone(),
    }];
    let end = s.duration();
    for &(lo, hi, inside) in bands {
        frequency.push(Line {
            label: format!(
                "avoid {lo}..{hi} steps/s: the ramp {:.3} ms inside",
                inside * 1e3
            ),
            color: RED,
            points: vec![(0.0, lo), (end, lo), (end, hi), (0.0, hi), (0.0, lo)],
        });
    }
    chart_lines(
        &areas[0],
        &format!("{title}: frequency against time"),
        "time (s)",
        "step frequency (Hz)",
        &frequency,
        Some(SeriesLabelPosition::LowerRight),
    )?;
    chart(
        &areas[1],
        &format!("{title}: frequency against step"),
        "step",
        "step frequency (Hz)",
        &[(s, by_step)],
    )?;
    let mut lines = vec![Line {
        label: "table, between windows (rounding under 5% of the curve's)".to_string(),
        color: s.color,
        points: s.accel.clone(),
    }];
    if !s.curve_accel.is_empty() {
        lines.push(Line {
            label: "curve, from unrounded periods".to_string(),
            color: BLACK,
            points: s.curve_accel.clone(),
        });
    }
    chart_lines(
        &areas[2],
        &format!("{title}: acceleration against time"),
        "time (s)",
        "acceleration (Hz/s)",
        &lines,
        Some(SeriesLabelPosition::UpperRight),
    )?;
    root.present()?;
    Ok(())
}

/// Several tables on one chart: frequency against time (or step).
pub fn overlay(path: &Path, title: &str, series: &[Series], by_step: bool) -> PlotResult {
    let root = SVGBackend::new(path, (900, 560)).into_drawing_area();
    root.fill(&WHITE)?;
    let points: Vec<(&Series, Vec<(f64, f64)>)> = series
        .iter()
        .map(|s| {
            let p = if by_step {
                s.steps
                    .iter()
                    .enumerate()
                    .map(|(i, p)| (i as f64, p.1))
                    .collect()
            } else {
                s.steps.clone()
            };
            (s, p)
        })
        .collect();
    let x_desc = if by_step { "step index" } else { "time (s)" };
    chart(&root, title, x_desc, "step frequency (Hz)", &points)?;
    root.present()?;
    Ok(())
}

/// A compact layout (runs or segments) over the curve it stands for:
/// frequency against time for both, and every pulse edge's distance from
/// the curve's, for the compact layout and the table of one entry per step.
/// `frequency` and `edges` are lines of `(time in s, Hz)` and
/// `(step, ticks)`.
pub fn compact(path: &Path, title: &str, frequency: &[Line], edges: &[Line]) -> PlotResult {
    let root = SVGBackend::new(path, (900, 840)).into_drawing_area();
    root.fill(&WHITE)?;
    let areas = root.split_evenly((2, 1));
    chart_lines(
        &areas[0],
        &format!("{title}: frequency against time"),
        "time (s)",
        "step frequency (Hz)",
        frequency,
        Some(SeriesLabelPosition::LowerRight),
    )?;
    chart_lines(
        &areas[1],
        &format!("{title}: pulse edge against the curve's"),
        "step",
        "edge error (ticks)",
        edges,
        Some(SeriesLabelPosition::UpperRight),
    )?;
    root.present()?;
    Ok(())
}

/// Tables side by side, each on its own time axis.
pub fn side_by_side(path: &Path, title: &str, series: &[Series]) -> PlotResult {
    let root = SVGBackend::new(path, (1200, 480)).into_drawing_area();
    root.fill(&WHITE)?;
    let (top, body) = root.split_vertically(36);
    top.titled(title, ("sans-serif", 20))?;
    let areas = body.split_evenly((1, series.len().max(1)));
    for (area, s) in areas.iter().zip(series) {
        let caption = format!("{} ({:.3} s)", s.label, s.duration());
        chart(
            area,
            &caption,
            "time (s)",
            "step frequency (Hz)",
            &[(s, s.steps.clone())],
        )?;
    }
    root.present()?;
    Ok(())
}

/// A motor-bound profile: the torque each edge needs against the torque the
/// motor gives there, against step and against step frequency.
/// `edges` holds `(step, step frequency in Hz, needed N·m, available N·m)`;
/// `curve` the pull-out curve before the safety factor, `(Hz, N·m)`.
pub fn torque(
    path: &Path,
    title: &str,
    edges: &[(u32, f64, f64, f64)],
    curves: &[(&str, Vec<(f64, f64)>)],
) -> PlotResult {
    let root = SVGBackend::new(path, (900, 760)).into_drawing_area();
    root.fill(&WHITE)?;
    let areas = root.split_evenly((2, 1));
    let needed = RGBColor(0xd6, 0x27, 0x28);
    let available = RGBColor(0x1f, 0x77, 0xb4);
    let pull_out = [
        RGBColor(0x80, 0x80, 0x80),
        RGBColor(0x2c, 0xa0, 0x2c),
        RGBColor(0x94, 0x67, 0xbd),
    ];
    let line = |label: &str, color, points: Vec<(f64, f64)>| Line {
        label: label.to_string(),
        color,
        points,
    };
    chart_lines(
        &areas[0],
        &format!("{title}: torque against step"),
        "step",
        "torque (N·m)",
        &[
            line(
                "needed: J α + friction + damping ω",
                needed,
                edges.iter().map(|e| (e.0 as f64, e.2)).collect(),
            ),
            line(
                "available: pull-out curve / safety",
                available,
                edges.iter().map(|e| (e.0 as f64, e.3)).collect(),
            ),
        ],
        None,
    )?;
    // The pull-out curves over the frequencies the ramp covers.
    let top = edges.iter().map(|e| e.1).fold(0.0, f64::max);
    let mut lines = vec![
        line("needed", needed, edges.iter().map(|e| (e.1, e.2)).collect()),
        line(
            "available",
            available,
            edges.iter().map(|e| (e.1, e.3)).collect(),
        ),
    ];
    for ((label, curve), color) in curves.iter().zip(pull_out) {
        let mut outline: Vec<(f64, f64)> = curve.iter().copied().filter(|p| p.0 <= top).collect();
        if let Some(&(hz, nm)) = curve.iter().find(|p| p.0 > top) {
            // Up to the ramp's top, interpolated.
            let &(h0, n0) = outline.last().unwrap_or(&(hz, nm));
            let t = if hz > h0 { (top - h0) / (hz - h0) } else { 0.0 };
            outline.push((top, n0 + (nm - n0) * t));
        }
        lines.push(line(label, color, outline));
    }
    chart_lines(
        &areas[1],
        &format!("{title}: torque against step frequency"),
        "step frequency (Hz)",
        "torque (N·m)",
        &lines,
        None,
    )?;
    root.present()?;
    Ok(())
}
