//! The plot of an experiment: error against time, both axes logarithmic, one colour per series,
//! the Pareto front circled and joined by a line. SVG by `plotters` (no bitmap backend, no font
//! files: text is laid out by plotters' own estimate).

use plotters::prelude::*;

use crate::Experiment;
use crate::measure::pareto_front;

const COLORS: [RGBColor; 8] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(23, 190, 207),
];

/// The SVG of `experiment`'s plot. Never fails: a plot that cannot be drawn is an SVG that says
/// so.
#[must_use]
pub fn svg(experiment: &Experiment) -> String {
    let mut out = String::new();
    let result = {
        let root = SVGBackend::with_string(&mut out, (760, 460)).into_drawing_area();
        draw(&root, experiment).and_then(|()| root.present().map_err(|e| e.to_string()))
    };
    match result {
        Ok(()) => out,
        Err(e) => format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"760\" height=\"40\"><text x=\"10\" \
             y=\"25\">plot failed: {}</text></svg>\n",
            e.replace(['<', '>', '&'], " ")
        ),
    }
}

/// Bounds of a log axis that hold `values` (positive ones), with a margin.
fn log_bounds(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values
        .filter(|v| v.is_finite() && *v > 0.0)
        .fold((f64::INFINITY, 0.0f64), |(lo, hi), v| (lo.min(v), hi.max(v)));
    if lo.is_finite() && hi > 0.0 { (lo / 2.0, hi * 2.0) } else { (1e-9, 1.0) }
}

/// A tick label on a log axis: `0.02`, `150`, `1e-5`, `2.5e-7`.
fn tick(v: f64) -> String {
    if (0.01..1e4).contains(&v.abs()) {
        let s = format!("{v:.3}");
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        let s = format!("{v:.1e}");
        s.replace(".0e", "e")
    }
}

fn draw<DB: DrawingBackend>(
    root: &DrawingArea<DB, plotters::coord::Shift>,
    e: &Experiment,
) -> Result<(), String> {
    let err = |x: DrawingAreaErrorKind<DB::ErrorType>| x.to_string();
    root.fill(&WHITE).map_err(err)?;
    let raw = e.points();
    let (x0, x1) = log_bounds(raw.iter().map(|p| p.0));
    let (mut y0, y1) = log_bounds(raw.iter().map(|p| p.1));
    if raw.iter().any(|p| p.1 == 0.0) {
        y0 /= 10.0;
    }
    // Zero (and negative) errors sit on the bottom edge.
    let floor = y0 * 1.2;
    let points: Vec<(f64, f64)> =
        raw.iter().map(|&(t, v)| (t, if v.is_finite() && v > 0.0 { v } else { floor })).collect();
    let mut chart = ChartBuilder::on(root)
        // The English half of the title: SVG viewers without a CJK font show boxes otherwise
        // (the Markdown heading has both).
        .caption(e.title.rsplit(" / ").next().unwrap_or(e.title), ("sans-serif", 18))
        .margin(12)
        .x_label_area_size(44)
        .y_label_area_size(78)
        .build_cartesian_2d((x0..x1).log_scale(), (y0..y1).log_scale())
        .map_err(err)?;
    let x_desc = e.columns[e.time_column].name;
    let y_desc = e.columns[e.error_column].name;
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc(y_desc)
        .x_label_formatter(&|v| tick(*v))
        .y_label_formatter(&|v| tick(*v))
        .light_line_style(WHITE.mix(0.0))
        .draw()
        .map_err(err)?;
    let mut series: Vec<&str> = Vec::new();
    for r in &e.rows {
        let name = r.key[e.series_key].as_str();
        if !series.contains(&name) {
            series.push(name);
        }
    }
    for (i, name) in series.iter().enumerate() {
        let color = COLORS[i % COLORS.len()];
        let pts: Vec<(f64, f64)> = e
            .rows
            .iter()
            .zip(&points)
            .filter(|(r, _)| r.key[e.series_key] == *name)
            .map(|(_, &p)| p)
            .collect();
        chart
            .draw_series(pts.into_iter().map(move |p| Circle::new(p, 4, color.filled())))
            .map_err(err)?
            .label(*name)
            .legend(move |(x, y)| Circle::new((x, y), 4, color.filled()));
    }
    let front = pareto_front(&raw);
    let mut on_front: Vec<(f64, f64)> =
        points.iter().zip(&front).filter(|(_, f)| **f).map(|(p, _)| *p).collect();
    on_front.sort_by(|a, b| a.0.total_cmp(&b.0));
    chart
        .draw_series(LineSeries::new(on_front.clone(), BLACK.stroke_width(1)))
        .map_err(err)?
        .label("Pareto front")
        .legend(|(x, y)| PathElement::new(vec![(x - 8, y), (x + 8, y)], BLACK));
    chart
        .draw_series(on_front.into_iter().map(|p| Circle::new(p, 7, BLACK.stroke_width(1))))
        .map_err(err)?;
    chart
        .configure_series_labels()
        .border_style(BLACK)
        .background_style(WHITE.mix(0.85))
        .position(SeriesLabelPosition::UpperRight)
        .draw()
        .map_err(err)?;
    Ok(())
}
