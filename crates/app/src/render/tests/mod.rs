use super::lines::segments;
use super::*;
use crate::figure::{Axis, LineStyle, Marker, MarkerShape, Series};
use crate::plot::Ink;

mod direct;

fn sample() -> Figure {
    Figure {
        series: vec![Series {
            label: "x(t)".into(),
            points: vec![(0.0, 0.0), (0.5, f64::NAN), (0.6, 1e300), (1.0, -0.5)],
            style: LineStyle::solid(Ink::Blue, 2.0),
        }],
        backdrop: 0,
        markers: vec![Marker {
            label: "p".into(),
            at: (0.5, 0.5),
            shape: MarkerShape::Cross,
            ink: Ink::Vermillion,
        }],
        origin_lines: true,
        ..Figure::plot(
            "test",
            Axis::linear("time t", "s", (0.0, 1.0)),
            Axis::linear("x", "m", (-1.0, 1.0)),
        )
    }
}

#[test]
fn draws_to_svg_with_axes_legend_and_markers() {
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (640, 360)).into_drawing_area();
        render(&root, &sample(), &Theme::LIGHT, 1.0).unwrap();
    }
    assert!(svg.contains("time t [s]"));
    assert!(svg.contains("x(t)"));
    assert!(
        svg.matches("<polyline").count() >= 2,
        "line split at the NaN"
    );
}

#[test]
fn log_axes_never_receive_zero_or_negative_values() {
    let mut fig = sample();
    fig.x = Axis {
        scale: AxisScale::Log,
        ..Axis::linear("r", "", (0.01, 100.0))
    };
    fig.series[0].points = vec![
        (0.0, 1.0),
        (-1.0, 1.0),
        (0.1, 0.5),
        (1.0, 0.2),
        (-0.5, 0.1),
        (10.0, 0.3),
    ];
    let (segs, _) = segments(&fig.series[0], &fig);
    assert_eq!(segs.len(), 2);
    assert!(segs.iter().flatten().all(|p| p.0 > 0.0));
    let mut svg = String::new();
    let root = SVGBackend::with_string(&mut svg, (640, 360)).into_drawing_area();
    render(&root, &fig, &Theme::LIGHT, 1.0).unwrap();
}

#[test]
fn heatmap_cells_are_filled_and_blank_where_undefined() {
    let mut fig = sample();
    fig.heatmap = Some(crate::figure::Heatmap {
        log: false,
        nx: 4,
        ny: 3,
        values: (0..12)
            .map(|i| if i == 5 { f64::NAN } else { i as f64 })
            .collect(),
        x_edges: (0.0, 1.0),
        y_edges: (-1.0, 1.0),
        scale: (0.0, 11.0),
        label: "metric [s]".into(),
    });
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (640, 360)).into_drawing_area();
        render(&root, &fig, &Theme::LIGHT, 1.0).unwrap();
    }
    let lo = crate::theme::viridis(0.0);
    let hi = crate::theme::viridis(1.0);
    let hex = |c: RGBColor| format!("#{:02X}{:02X}{:02X}", c.0, c.1, c.2);
    assert!(
        svg.contains(&hex(lo)) && svg.contains(&hex(hi)),
        "both ends of the colour map"
    );
    // The same map with every cell undefined: the same axes, legend and colour bar.
    let without = {
        let mut blank = fig.clone();
        if let Some(h) = &mut blank.heatmap {
            h.values = vec![f64::NAN; 12];
        }
        let mut s = String::new();
        let root = SVGBackend::with_string(&mut s, (640, 360)).into_drawing_area();
        render(&root, &blank, &Theme::LIGHT, 1.0).unwrap();
        drop(root);
        s
    };
    assert!(
        svg.contains("metric [s]"),
        "the colour bar names the metric and unit"
    );
    assert_eq!(
        svg.matches("<rect").count() - without.matches("<rect").count(),
        11
    );
}

#[test]
fn tick_labels_are_short_and_follow_the_language() {
    assert_eq!(tick_label(0.1 + 0.2), "0.3");
    assert_eq!(tick_label(2.0), "2");
    assert_eq!(tick_label(-0.05), "-0.05");
    assert_eq!(tick_label(1.000_000_000_000_000_2e-6), "1e-6");
    assert_eq!(tick_label(1e-7), "1e-7");
    assert_eq!(tick_label(24_000.0), "24000");
    // From a million up, an exponent, as below 10⁻⁴: a log axis of errors reads 1e-6 … 1e8.
    assert_eq!(tick_label(1e8), "1e8");
    assert_eq!(tick_label(2.5e6), "2.5e6");
    assert_eq!(tick_label(999_999.0), "999999");
    assert_eq!(tick_label(0.0), "0");
}

#[test]
fn a_tick_at_zero_reads_0_not_the_rounding_left_from_adding_steps() {
    use super::ticks::axis_tick_label;
    let linear = Axis::linear("x", "m", (-1.5, 1.5));
    assert_eq!(axis_tick_label(2.7255e-17, &linear), "0");
    assert_eq!(axis_tick_label(-6.93889e-18, &linear), "0");
    assert_eq!(axis_tick_label(0.5, &linear), "0.5");
    // A tiny axis keeps its tiny ticks: only values tiny against the span are zero.
    let tiny = Axis::linear("x", "m", (0.0, 1e-15));
    assert_eq!(axis_tick_label(2e-16, &tiny), "2e-16");
    // A log axis has no zero: a tick twelve decades below the top keeps its value.
    let log = Axis::log("f", "Hz", (1e-12, 1.0));
    assert_eq!(axis_tick_label(1e-12, &log), "1e-12");
}

#[test]
fn a_wide_log_axis_writes_every_decade_alike() {
    use super::ticks::axis_tick_label;
    // Six decades and more: every tick but 1 with an exponent.
    let errors = Axis::log("error", "m", (1e-14, 1e4));
    let labels: Vec<String> = [1e4, 100.0, 1.0, 0.01, 1e-4, 1e-6]
        .iter()
        .map(|&v| axis_tick_label(v, &errors))
        .collect();
    assert_eq!(labels, ["1e4", "1e2", "1", "1e-2", "1e-4", "1e-6"]);
    // Fewer decades (a frequency axis): plain numbers.
    let hz = Axis::log("f", "Hz", (0.1, 100.0));
    assert_eq!(axis_tick_label(0.2, &hz), "0.2");
    assert_eq!(axis_tick_label(50.0, &hz), "50");
}

#[test]
fn held_axes_keep_their_ranges_and_widen_only_for_data_that_leaves_them() {
    // Data shrunk under a third of a held axis: that axis takes the data's own range.
    let mut shrunk = sample();
    shrunk.x.range = (0.0, 9.6);
    shrunk.y.range = (-0.5, 0.5);
    hold_axes(&mut shrunk, Some(((0.0, 60.0), (-1.2, 1.2))));
    assert_eq!((shrunk.x.range, shrunk.y.range), ((0.0, 9.6), (-1.2, 1.2)));
    let mut decades = sample();
    decades.x = Axis::log("f", "Hz", (0.1, 100.0));
    decades.x.range = (1.0, 2.0);
    hold_axes(&mut decades, Some(((0.1, 100.0), (-1.0, 1.0))));
    assert_eq!(decades.x.range, (1.0, 2.0));
    decades.x.range = (1.0, 20.0); // 1.3 of 3 decades: held
    hold_axes(&mut decades, Some(((0.1, 100.0), (-1.0, 1.0))));
    assert_eq!(decades.x.range, (0.1, 100.0));
    let mut fig = sample();
    fig.x.range = (0.0, 1.2);
    fig.y.range = (-0.5, 0.5);
    hold_axes(&mut fig, Some(((0.0, 1.5), (-1.0, 1.0))));
    assert_eq!((fig.x.range, fig.y.range), ((0.0, 1.5), (-1.0, 1.0)));
    // Data leaving a held axis widen it past them by a quarter of the new span, on that
    // side only, so the next frames of a drag that keeps pushing find room.
    fig.y.range = (-2.0, 0.5);
    hold_axes(&mut fig, Some(((0.0, 1.5), (-1.0, 1.0))));
    assert_eq!(fig.y.range, (-2.75, 1.0));
    fig.y.range = (-2.5, 0.5);
    hold_axes(&mut fig, Some(((0.0, 1.5), (-2.75, 1.0))));
    assert_eq!(fig.y.range, (-2.75, 1.0), "within the margin: held");
    // Not across zero: magnitudes from 0.1 held at 0.5…1 widen down to 0, not below.
    fig.y.range = (0.1, 0.9);
    hold_axes(&mut fig, Some(((0.0, 1.5), (0.5, 1.0))));
    assert_eq!(fig.y.range, (0.0, 1.0));
    // On a log axis the margin is in decades: 1…100 held, data to 1000 → 10^(3 + 0.75).
    decades.x.range = (1.0, 1000.0);
    hold_axes(&mut decades, Some(((1.0, 100.0), (-1.0, 1.0))));
    let (lo, hi) = decades.x.range;
    assert_eq!(lo, 1.0);
    assert!((hi.log10() - 3.75).abs() < 1e-12, "{hi}");
    let mut drawing = Figure::schematic(
        "s",
        Axis::linear("x", "m", (0.0, 1.0)),
        Axis::linear("y", "m", (0.0, 1.0)),
    );
    hold_axes(&mut drawing, Some(((0.0, 5.0), (0.0, 5.0))));
    assert_eq!(drawing.x.range, (0.0, 1.0));
}

#[test]
fn log_axes_label_enough_ticks_to_read_a_value() {
    // Two decades: 1, 2, 5 in each.
    assert_eq!(
        log_ticks(0.1, 10.0),
        vec![0.1, 0.2, 0.5, 1.0, 2.0, 5.0, 10.0]
    );
    // Under one decade: still several labelled values.
    assert_eq!(log_ticks(0.5, 3.0), vec![0.5, 0.7, 1.0, 1.5, 2.0, 3.0]);
    assert!(log_ticks(1.1, 1.9).len() >= 2);
    // Many decades: the decades alone.
    assert_eq!(log_ticks(1e-3, 1e2).len(), 6);
    assert!(log_ticks(0.0, 1.0).is_empty());
}

#[test]
fn a_short_log_axis_labels_fewer_decades_evenly() {
    use super::ticks::thinned;
    // 1e-14 … 1e8 every other decade: twelve labels, in 70 px of a phone's plot.
    let ticks = log_ticks(1e-14, 1e8);
    assert_eq!(ticks.len(), 12);
    assert_eq!(thinned(&ticks, 12), ticks);
    // At most five: every fourth decade is six (1e-12 … 1e8), every sixth is four.
    assert_eq!(thinned(&ticks, 5), vec![1e-12, 1e-6, 1.0, 1e6]);
    // At most two: every tenth decade.
    assert_eq!(thinned(&ticks, 2), vec![1e-10, 1.0]);
    // Not all decades: the decades first (resonance's r axis keeps 1, where it resonates).
    let r = log_ticks(0.1, 10.0);
    assert_eq!(thinned(&r, 4), vec![0.1, 1.0, 10.0]);
    assert_eq!(thinned(&r, 2), vec![0.1, 10.0]);
    // Under two decades: every k-th tick.
    assert_eq!(
        thinned(&[0.5, 0.7, 1.0, 1.5, 2.0, 3.0], 3),
        vec![0.5, 1.0, 2.0]
    );
    assert_eq!(thinned(&[1.0, 10.0], 0), vec![1.0]);
    // One decade among them (2 … 30): spread by position, not the two that round to 10⁰.
    assert_eq!(thinned(&log_ticks(2.0, 30.0), 2), vec![2.0, 10.0]);
}

#[test]
fn a_log_axis_asked_for_the_usual_labels_keeps_every_labelled_tick() {
    use plotters::coord::ranged1d::{BoldPoints, Ranged};
    // An x axis (six asked for) over 0.1 … 10 has seven labelled ticks: all are kept (a
    // review found 1 dropped from resonance's r axis when every log axis was thinned).
    let axis = Axis::log("r", "", (0.1, 10.0));
    let ticks = super::scale::Scale::of(&axis).key_points(BoldPoints(super::chart::LABELS));
    assert_eq!(ticks, log_ticks(0.1, 10.0));
    // A short y axis asked for three keeps the decades.
    let fewer = super::scale::Scale::of(&axis).key_points(BoldPoints(3));
    assert_eq!(fewer, vec![0.1, 1.0, 10.0]);
}

#[test]
fn a_short_plot_labels_fewer_values_on_its_y_axis() {
    use super::chart::y_label_count;
    // A desktop plot (300 px of plotting area at scale 1, or 600 at 2) keeps six.
    assert_eq!(y_label_count(300, 1.0), 6);
    assert_eq!(y_label_count(600, 2.0), 6);
    // A phone's 80-px plotting area at scale 2: two, 2.5 label heights apart.
    assert_eq!(y_label_count(160, 2.0), 2);
    assert_eq!(y_label_count(10, 1.0), 2);
}

/// The top of the legend box in an SVG rendering, if a box was drawn.
fn legend_box_y(svg: &str) -> Option<f64> {
    // The legend box is the only rectangle filled with the background at 88 % opacity.
    let at = svg.find("opacity=\"0.88\"")?;
    let start = svg[..at].rfind("<rect")?;
    let y = svg[start..].split("y=\"").nth(1)?.split('"').next()?;
    y.parse().ok()
}

/// The band height of a placement below the chart (0 otherwise).
fn band_of(p: Placement) -> u32 {
    match p {
        Placement::Below(h) => h,
        _ => 0,
    }
}

/// The right edge of the legend box in an SVG rendering, if a box was drawn.
fn svg_box_right(svg: &str) -> Option<f64> {
    let at = svg.find("opacity=\"0.88\"")?;
    let rect = &svg[svg[..at].rfind("<rect")?..];
    let attr = |name: &str| -> Option<f64> {
        rect.split(&format!(" {name}=\""))
            .nth(1)?
            .split('"')
            .next()?
            .parse()
            .ok()
    };
    Some(attr("x")? + attr("width")?)
}

#[test]
fn the_legend_goes_where_the_curves_are_not() {
    // A curve along the top of the plot: the legend moves to the bottom.
    let mut fig = sample();
    fig.markers.clear();
    fig.series[0].points = (0..=50).map(|i| (f64::from(i) / 50.0, 0.9)).collect();
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (640, 360)).into_drawing_area();
        render(&root, &fig, &Theme::LIGHT, 1.0).unwrap();
    }
    let y = legend_box_y(&svg).expect("a legend box inside the plot");
    assert!(
        y > 180.0,
        "legend in the lower half, clear of the curve: y = {y}"
    );
    // Curves everywhere: the legend goes under the chart, outside the plotting area.
    fig.series = (0..12)
        .map(|k| {
            let level = -1.0 + f64::from(k) / 6.0;
            Series::new(
                format!("level {k}"),
                vec![(0.0, level), (1.0, level)],
                LineStyle::solid(Ink::Blue, 1.0),
            )
        })
        .collect();
    let mut svg = String::new();
    let g = {
        let root = SVGBackend::with_string(&mut svg, (640, 360)).into_drawing_area();
        render(&root, &fig, &Theme::LIGHT, 1.0).unwrap()
    };
    assert!(legend_box_y(&svg).is_none(), "no box over the data");
    assert!(svg.contains("level 11"), "every entry still drawn");
    assert!(
        g.area.3 < 300.0,
        "room left under the chart for the legend rows"
    );
}

#[test]
fn a_held_legend_stays_where_it_was_even_over_the_curves() {
    // Placed afresh, a curve along the top sends the box to a lower corner…
    let mut fig = sample();
    fig.markers.clear();
    fig.series[0].points = (0..=50).map(|i| (f64::from(i) / 50.0, 0.9)).collect();
    let draw = |legend: Option<Placement>| {
        let mut svg = String::new();
        let g = {
            let root = SVGBackend::with_string(&mut svg, (640, 360)).into_drawing_area();
            let out = Output {
                direct: None,
                legend,
            };
            render_with(&root, &fig, &Theme::LIGHT, 1.0, out).unwrap()
        };
        (svg, g)
    };
    let (_, free) = draw(None);
    let Placement::Inside(_, y) = free.legend else {
        panic!("a free corner: {:?}", free.legend)
    };
    assert!(y > 100, "a lower corner: y = {y}");
    // …held at the top-left (as a drag that began there holds it), it stays there.
    let (svg, held) = draw(Some(Placement::Inside(6, 6)));
    assert_eq!(held.legend, Placement::Inside(6, 6));
    let top = legend_box_y(&svg).expect("a box");
    assert!(top < 60.0, "drawn at the top, over the curve: {top}");
    // Held below the chart, it stays below; a spot too far right is moved in to fit.
    let (svg, below) = draw(Some(Placement::Below(0)));
    assert!(matches!(below.legend, Placement::Below(h) if h > 0));
    assert!(legend_box_y(&svg).is_none());
    assert!(
        below.area.3 < free.area.3,
        "room under the chart for the rows"
    );
    // A band held higher than the rows need stays that high (the chart does not move).
    let (_, tall) = draw(Some(Placement::Below(100)));
    assert_eq!(tall.legend, Placement::Below(100));
    assert!(
        (below.area.3 - tall.area.3 - (100.0 - f64::from(band_of(below.legend)))).abs() < 1.5,
        "{:?} {:?}",
        below.area,
        tall.area
    );
    let (svg, _) = draw(Some(Placement::Inside(5000, y)));
    let right = svg_box_right(&svg).expect("a box");
    assert!(
        right <= free.area.2 + 0.5,
        "inside the plot: {right} <= {}",
        free.area.2
    );
}

#[test]
fn released_axes_ease_from_the_held_ranges_to_the_figures_own() {
    let mut fig = sample();
    fig.x.range = (0.0, 1.0);
    ease_axes(&mut fig, Some(((0.0, 3.0), (-1.0, 1.0))), 0.5);
    assert_eq!(fig.x.range, (0.0, 2.0));
    let mut fig = sample();
    fig.x = Axis::log("f", "Hz", (1.0, 100.0));
    ease_axes(&mut fig, Some(((1.0, 10_000.0), (-1.0, 1.0))), 0.5);
    assert!((fig.x.range.1 - 1000.0).abs() < 1e-9);
    let mut fig = sample();
    ease_axes(&mut fig, Some(((0.0, 3.0), (-5.0, 5.0))), 1.0);
    assert_eq!(fig.x.range, (0.0, 1.0), "at 1 the figure's own ranges");
}

#[test]
fn geometry_round_trips_pixels_and_data() {
    let mut svg = String::new();
    let g = {
        let root = SVGBackend::with_string(&mut svg, (640, 360)).into_drawing_area();
        render(&root, &sample(), &Theme::LIGHT, 1.0).unwrap()
    };
    let (l, t, r, b) = g.area;
    assert!(l > 20.0 && r < 640.0 && t > 10.0 && b < 360.0 && l < r && t < b);
    let (px, py) = g.to_pixel(0.25, 0.5);
    let (x, y) = g.to_data(px, py).unwrap();
    assert!((x - 0.25).abs() < 1e-12 && (y - 0.5).abs() < 1e-12);
    assert!(g.to_data(0.0, 0.0).is_none());
}

#[test]
fn non_finite_points_split_lines_and_huge_ones_are_clamped() {
    let fig = sample();
    let (segs, clipped) = segments(&fig.series[0], &fig);
    assert_eq!(segs.len(), 2);
    assert!(segs[1][0].1 <= 1.05);
    assert!(clipped);
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (640, 360)).into_drawing_area();
        render(&root, &fig, &Theme::LIGHT, 1.0).unwrap();
    }
    assert!(svg.contains("clipped"), "the plot says it is clipped");
}

#[test]
fn a_drawn_axis_through_zero_labels_its_zero_tick_0() {
    // Ranges whose ticks are reached by adding steps that do not land exactly on zero.
    for &(lo, hi) in &[
        (-0.3, 0.3),
        (-0.7, 0.7),
        (-1.1, 0.9),
        (-0.33, 0.27),
        (-2.7, 3.3),
    ] {
        let mut fig = sample();
        fig.x.range = (lo, hi);
        fig.y.range = (lo, hi);
        let mut svg = String::new();
        {
            let root = SVGBackend::with_string(&mut svg, (640, 360)).into_drawing_area();
            render(&root, &fig, &Theme::LIGHT, 1.0).unwrap();
        }
        assert!(
            !svg.contains("e-1"),
            "{lo}..{hi}: a rounding tail in a tick label"
        );
    }
}

#[test]
fn titles_and_axis_names_longer_than_their_room_shrink_then_cut() {
    let draw = |fig: &Figure, w: u32| {
        let mut svg = String::new();
        {
            let root = SVGBackend::with_string(&mut svg, (w, 300)).into_drawing_area();
            render(&root, fig, &Theme::LIGHT, 1.0).unwrap();
        }
        svg
    };
    let short = draw(&sample(), 640);
    assert!(
        short.contains("test") && !short.contains('…'),
        "a short title stays whole: {short}"
    );

    // A little too long for a phone: drawn smaller, whole.
    let medium = "Settling into ±5 % of x₀, free response: 300 ms → 5.15 s";
    let fig = Figure {
        title: medium.into(),
        ..sample()
    };
    let svg = draw(&fig, 360);
    assert!(svg.contains(medium), "shrunk, not cut: {svg}");
    assert!(
        !svg.contains("font-size=\"15\""),
        "the title is smaller than 15 px"
    );

    // Far too long: cut with an ellipsis, never past the edge.
    let fig = Figure {
        title: "a very long title that no phone can hold ".repeat(6),
        y: Axis::linear(
            "an axis name far longer than the plot is tall ".repeat(4),
            "m",
            (0.0, 1.0),
        ),
        ..sample()
    };
    let svg = draw(&fig, 360);
    assert!(svg.matches('…').count() >= 2, "title and y name cut: {svg}");
}

#[test]
fn a_marker_label_near_the_right_edge_goes_left_of_its_point() {
    use super::lines::label_offset;
    // 100 px of label right of a point at x = 500 fits before an edge at 640 …
    assert_eq!(label_offset(500, 100, 640, 1.0), (8, -16));
    // … but not before one at 560: it goes left, ending a gap before the point.
    assert_eq!(label_offset(500, 100, 560, 1.0), (-108, -16));
    // The gap and the rise scale with the device pixel ratio.
    assert_eq!(label_offset(100, 10, 640, 2.0), (16, -32));
}

#[test]
fn a_text_marker_that_would_run_off_the_canvas_ends_left_of_its_anchor() {
    use super::lines::text_offset;
    // 100 px of text at x = 500 fits before an edge at 640 (drawn at the anchor) …
    assert_eq!(text_offset(500, 100, 640, 1.0), 0);
    // … but not before one at 560: it ends 12 px left of the anchor.
    assert_eq!(text_offset(500, 100, 560, 1.0), -112);
    assert_eq!(text_offset(500, 100, 560, 2.0), -124);
    // Drawn: the label of the current step on a convergence plot, just right of its line
    // at the right end of the axis, is written whole on the line's left.
    let text = "h = 300 ms";
    let label = |at: f64| {
        let fig = Figure {
            markers: vec![Marker::text(text, (at, 0.0), Ink::Sky)],
            ..sample()
        };
        let mut svg = String::new();
        let geometry = {
            let root = SVGBackend::with_string(&mut svg, (640, 360)).into_drawing_area();
            render(&root, &fig, &Theme::LIGHT, 1.0).unwrap()
        };
        let anchor = geometry.to_pixel(at, 0.0).0;
        let tag = svg
            .split("<text")
            .find(|t| t.contains(text))
            .unwrap_or_else(|| panic!("{text} drawn: {svg}"))
            .to_owned();
        let x: f64 = tag
            .split("x=\"")
            .nth(1)
            .unwrap()
            .split('"')
            .next()
            .unwrap()
            .parse()
            .unwrap();
        (x, anchor)
    };
    let (x, anchor) = label(0.5);
    assert!(
        (x - anchor).abs() <= 1.0,
        "in the middle: at its anchor ({x} vs {anchor})"
    );
    let (x, anchor) = label(0.99);
    assert!(
        x < anchor - 50.0,
        "at the edge: left of its anchor ({x} vs {anchor})"
    );
}

#[test]
fn a_phone_sized_plot_keeps_its_height_for_data() {
    // Quarter-car's response plot on a phone's stage (340 × 207 CSS px at DPR 2): five
    // entries, curves in every corner, so the legend goes in rows under the chart.
    let labels = [
        "comfort 0.3, 0.4",
        "performance 0.65, 0.7",
        "critical 1 (×)",
        "overdamped 2 (●)",
        "this design, ζ 0.300",
    ];
    let mut fig = sample();
    fig.markers.clear();
    fig.series = labels
        .iter()
        .enumerate()
        .map(|(k, label)| {
            let level = -0.9 + 0.45 * k as f64;
            let points = (0..=40)
                .map(|i| (f64::from(i) / 40.0, level * (1.0 - 2.0 * f64::from(i % 2))))
                .collect();
            Series::new(*label, points, LineStyle::solid(Ink::Blue, 1.5))
        })
        .collect();
    let scale = 2.0;
    let (w, h) = (680, 414);
    let mut svg = String::new();
    let g = {
        let root = SVGBackend::with_string(&mut svg, (w, h)).into_drawing_area();
        render(&root, &fig, &Theme::LIGHT, scale).unwrap()
    };
    assert!(matches!(g.legend, Placement::Below(_)), "{:?}", g.legend);
    for label in labels {
        assert!(svg.contains(label), "{label} drawn");
    }
    // Rows from the canvas's edge (three, not four from under the plot) and tick labels
    // and axis name closer under a short chart: over a third of the height is data.
    let data = (g.area.3 - g.area.1) / f64::from(h);
    assert!(
        data > 0.36,
        "plotting area {:.0} % of the height",
        data * 100.0
    );
    // A y axis name too long for that height keeps its symbol and unit whole.
    fig.y = Axis::linear("body displacement x", "mm", (-1.0, 1.0));
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (w, h)).into_drawing_area();
        render(&root, &fig, &Theme::LIGHT, scale).unwrap();
    }
    assert!(svg.contains("x [mm]"), "short name drawn");
    assert!(!svg.contains("displacement"), "no cut name");
}

#[test]
fn an_axis_short_title_is_its_symbol_and_unit() {
    let short =
        |label: &str, unit: &'static str| Axis::linear(label, unit, (0.0, 1.0)).short_title();
    assert_eq!(
        short("body displacement x", "mm").as_deref(),
        Some("x [mm]")
    );
    assert_eq!(
        short("normalised response y/y₀", "").as_deref(),
        Some("y/y₀")
    );
    assert_eq!(
        short("amplification |H| = X/(F₀/k)", "").as_deref(),
        Some("X/(F₀/k)")
    );
    // A word cut from its bracket, a plain word or a single word has no short form.
    assert_eq!(short("phase ∠H (lag of x behind F)", "°"), None);
    assert_eq!(
        short("an axis name far longer than the plot is tall", "m"),
        None
    );
    assert_eq!(short("time", "s"), None);
}

#[test]
fn a_curve_that_leaves_the_axes_is_cut_at_their_edge_not_drawn_along_it() {
    let mut fig = sample();
    // y range −1…1, widened 2 % of the span to ±1.04 for drawing.
    let top = 1.04;
    // A peak far above: two pieces, each reaching the edge where the curve crosses it.
    fig.series[0].points = vec![(0.0, 0.0), (0.5, 10.0), (1.0, 0.0)];
    let (segs, clipped) = segments(&fig.series[0], &fig);
    assert!(clipped);
    assert_eq!(segs.len(), 2, "{segs:?}");
    let near =
        |a: (f64, f64), b: (f64, f64)| (a.0 - b.0).abs() < 1e-12 && (a.1 - b.1).abs() < 1e-12;
    let crossing = 0.5 * top / 10.0; // where the line from (0, 0) to (0.5, 10) reaches the edge
    assert!(
        near(segs[0][0], (0.0, 0.0)) && near(segs[0][1], (crossing, top)),
        "{segs:?}"
    );
    assert!(
        near(segs[1][0], (1.0 - crossing, top)) && near(segs[1][1], (1.0, 0.0)),
        "{segs:?}"
    );
    // Nothing beyond the edge, nothing along it: no two points at the top in a row.
    for seg in &segs {
        assert!(seg.iter().all(|p| p.1 <= top + 1e-12));
        assert!(seg.windows(2).all(|w| !(w[0].1 == top && w[1].1 == top)));
    }
    // A line from far left to far right of the range crosses it whole.
    fig.series[0].points = vec![(-10.0, 0.5), (10.0, 0.5)];
    let (segs, _) = segments(&fig.series[0], &fig);
    assert_eq!(segs.len(), 1);
    assert!(
        near(segs[0][0], (-0.02, 0.5)) && near(segs[0][1], (1.02, 0.5)),
        "{segs:?}"
    );
    // One that passes beside the range is not drawn; one inside is drawn as it is.
    fig.series[0].points = vec![(-10.0, 5.0), (10.0, 5.0)];
    assert!(segments(&fig.series[0], &fig).0.is_empty());
    fig.series[0].points = vec![(0.1, 0.2), (0.3, -0.4), (0.9, 0.9)];
    let (segs, clipped) = segments(&fig.series[0], &fig);
    assert!(!clipped);
    assert_eq!(segs, [fig.series[0].points.clone()]);
    // On a log axis the cut is where the straight line of the plot (in log x) crosses it.
    fig.x = Axis::log("r", "", (0.1, 10.0));
    fig.series[0].points = vec![(0.1, 0.0), (10.0, 3.0)];
    let (segs, _) = segments(&fig.series[0], &fig);
    // From ln 0.1 to ln 10 the line rises 3; it reaches 1.04 at a fraction 1.04/3 of the way.
    let x = (0.1_f64.ln() + (top / 3.0) * (10.0_f64.ln() - 0.1_f64.ln())).exp();
    assert!(
        (segs[0][1].0 - x).abs() < 1e-9 && (segs[0][1].1 - top).abs() < 1e-12,
        "{segs:?}"
    );
}
