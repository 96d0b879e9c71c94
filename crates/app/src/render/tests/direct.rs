//! What a backend that draws itself (`Direct`) is asked to do: the legend's trial muted,
//! the static layer named by what it shows, a heatmap and its colour bar as one image each.

use super::*;
use std::cell::Cell;

/// A stretched image as drawn: size, pixels, where it goes and its clip.
type Drawn = ((u32, u32), Vec<u8>, [i32; 4], [i32; 4]);

/// What of every static layer a recording backend says it keeps (then it has drawn it).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
enum Keeps {
    #[default]
    Nothing,
    Whole,
    /// The part under the backdrop, when there is a backdrop.
    Axes,
}

/// A backend's own drawing, recorded: the images stretched, the calls in order, what of
/// every static layer it says it keeps, and the note it returns with a whole kept layer
/// (the last one noted).
#[derive(Default)]
struct Recorder(
    std::cell::RefCell<Vec<Drawn>>,
    std::cell::RefCell<Vec<String>>,
    Keeps,
    std::cell::Cell<LayerNote>,
);

impl Direct for Recorder {
    fn dash(&self, _: &[f64]) {}
    fn stretch(&self, image: &Stretched<'_>) {
        let copy = (image.size, image.rgb.to_vec(), image.to, image.clip);
        self.0.borrow_mut().push(copy);
        self.1.borrow_mut().push("stretch".into());
    }
    fn mute(&self, on: bool) {
        self.1.borrow_mut().push(format!("mute {on}"));
    }
    fn begin_layer(&self, keys: LayerKeys) -> Option<Kept> {
        let LayerKeys { axes, whole } = keys;
        self.1.borrow_mut().push(format!("begin {axes} {whole}"));
        match self.2 {
            Keeps::Whole => Some(Kept::Whole(self.3.get())),
            Keeps::Axes if keys.has_backdrop() => Some(Kept::Axes),
            _ => None,
        }
    }
    fn axes_done(&self, LayerKeys { axes, whole }: LayerKeys) {
        self.1.borrow_mut().push(format!("axes {axes} {whole}"));
    }
    fn end_layer(&self, LayerKeys { axes, whole }: LayerKeys, note: LayerNote) {
        self.1.borrow_mut().push(format!("end {axes} {whole}"));
        self.3.set(note);
    }
}

/// The calls a backend that draws itself gets for `fig`.
fn calls(fig: &Figure) -> Vec<String> {
    drawn(fig).0
}

/// The calls a backend that draws itself gets for `fig`, and what was drawn (SVG).
fn drawn(fig: &Figure) -> (Vec<String>, String) {
    let rec = Recorder::default();
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (640, 360)).into_drawing_area();
        render_with(&root, fig, &Theme::LIGHT, 1.0, Output::with_direct(&rec)).unwrap();
    }
    (rec.1.into_inner(), svg)
}

#[test]
fn the_legend_trial_is_muted_and_the_static_layer_is_named_by_what_it_shows() {
    let fig = sample();
    let seen = calls(&fig);
    assert_eq!(seen.len(), 5, "{seen:?}");
    assert_eq!(
        seen[..2],
        ["mute true", "mute false"],
        "the trial layout draws nothing"
    );
    let key = seen[2].strip_prefix("begin ").unwrap();
    assert_eq!(seen[3], format!("axes {key}"));
    assert_eq!(seen[4], format!("end {key}"));
    // Other data, same axes and title: the same layer.
    let mut moved = fig.clone();
    moved.series[0].points[0].1 = 0.7;
    moved.markers[0].at = (0.2, 0.1);
    assert_eq!(calls(&moved)[2], seen[2]);
    // Another title, even one long enough to be drawn smaller: the same layer, the title
    // drawn over it (a map's title names its data's range, which a drag moves every frame).
    let long = "a title much longer than the room a plot of 640 pixels gives it".repeat(2);
    for title in ["test 2", long.as_str()] {
        let mut retitled = fig.clone();
        retitled.title = title.into();
        let (again, svg) = drawn(&retitled);
        assert_eq!(again[2], seen[2], "{title}");
        assert_eq!(
            svg.matches("test 2").count(),
            usize::from(title == "test 2")
        );
    }
    // Another range, axis name or theme: another layer.
    let mut ranged = fig.clone();
    ranged.y.range = (-1.0, 2.0);
    let mut named = fig.clone();
    named.x.label = "time τ".into();
    for other in [ranged, named] {
        assert_ne!(calls(&other)[2], seen[2]);
    }
    let dark = {
        let rec = Recorder::default();
        let mut svg = String::new();
        let root = SVGBackend::with_string(&mut svg, (640, 360)).into_drawing_area();
        render_with(&root, &fig, &Theme::DARK, 1.0, Output::with_direct(&rec)).unwrap();
        rec.1.into_inner()
    };
    assert_ne!(dark[2], seen[2]);
}

#[test]
fn a_heatmap_is_one_image_of_a_pixel_per_cell_over_its_cells_and_so_is_its_colour_bar() {
    let mut fig = sample();
    fig.series.clear();
    fig.markers.clear();
    fig.heatmap = Some(crate::figure::Heatmap {
        log: false,
        nx: 2,
        ny: 2,
        // Row-major from the bottom row: bottom (0, NaN), top (0.5, 1).
        values: vec![0.0, f64::NAN, 0.5, 1.0],
        x_edges: (0.0, 1.0),
        y_edges: (-1.0, 1.0),
        scale: (0.0, 1.0),
        label: String::new(),
    });
    let rec = Recorder::default();
    let mut svg = String::new();
    let geo = {
        let root = SVGBackend::with_string(&mut svg, (320, 160)).into_drawing_area();
        render_with(&root, &fig, &Theme::LIGHT, 1.0, Output::with_direct(&rec)).unwrap()
    };
    let rgb = |c: RGBColor| [c.0, c.1, c.2];
    let images = rec.0.into_inner();
    assert_eq!(images.len(), 2, "the heatmap and its colour bar");
    let (size, pixels, to, clip) = &images[0];
    assert_eq!(*size, (2, 2));
    // Rows top to bottom; a blank cell shows the background.
    let v = crate::theme::viridis;
    let want: Vec<u8> = [v(0.5), v(1.0), v(0.0), Theme::LIGHT.background]
        .into_iter()
        .flat_map(rgb)
        .collect();
    assert_eq!(pixels, &want);
    // Over the cells, which fill the plotting area here, and clipped to it.
    let (l, t, r, b) = geo.area;
    let near = |a: i32, b: f64| (f64::from(a) - b).abs() <= 1.0;
    assert!(
        near(to[0], l) && near(to[1], t) && near(to[2], r) && near(to[3], b),
        "{to:?} {:?}",
        geo.area
    );
    assert!(
        near(clip[0], l) && near(clip[1], t) && near(clip[2], r) && near(clip[3], b),
        "{clip:?}"
    );
    // The bar: one column, its top the high end of the map, right of the plot.
    let (size, pixels, to, _) = &images[1];
    assert_eq!(size.0, 1);
    assert!(size.1 >= 2);
    assert_eq!(pixels.len(), 3 * size.1 as usize);
    let (top, bottom) = (&pixels[..3], &pixels[pixels.len() - 3..]);
    let (hi, lo) = (rgb(v(1.0)), rgb(v(0.0)));
    let dist = |a: &[u8], b: [u8; 3]| {
        a.iter()
            .zip(b)
            .map(|(x, y)| x.abs_diff(y) as u32)
            .sum::<u32>()
    };
    assert!(
        dist(top, hi) < 30 && dist(bottom, lo) < 30,
        "{top:?} {bottom:?}"
    );
    assert!(f64::from(to[0]) > r);
    // No cell was also drawn as a rectangle.
    let without = {
        let mut plain = String::new();
        let mut fig = fig.clone();
        fig.heatmap = None;
        let root = SVGBackend::with_string(&mut plain, (320, 160)).into_drawing_area();
        render_with(
            &root,
            &fig,
            &Theme::LIGHT,
            1.0,
            Output::with_direct(&Recorder::default()),
        )
        .unwrap();
        drop(root);
        plain
    };
    assert_eq!(
        svg.matches("<rect").count(),
        without.matches("<rect").count() + 1,
        "only the bar's frame"
    );
}

/// `fig` drawn by a backend that keeps (all or part of) its static layer or lacks it: the
/// layer's keys and the SVG of what was drawn through plotters.
fn layered(fig: &Figure, keeps: Keeps) -> (String, String) {
    let draw = |rec: &Recorder| {
        let mut svg = String::new();
        {
            let root = SVGBackend::with_string(&mut svg, (640, 360)).into_drawing_area();
            render_with(&root, fig, &Theme::LIGHT, 1.0, Output::with_direct(rec)).unwrap();
        }
        svg
    };
    // Drawn whole first, as a canvas draws a layer before it keeps it: that drawing notes
    // what the frames over the layer still show.
    let whole = Recorder::default();
    draw(&whole);
    let rec = Recorder(Default::default(), Default::default(), keeps, whole.3);
    let svg = draw(&rec);
    let calls = rec.1.into_inner();
    let key = calls.iter().find_map(|c| c.strip_prefix("begin ")).unwrap();
    (key.to_owned(), svg)
}

#[test]
fn a_kept_layer_holds_the_mesh_and_the_backdrop_and_its_key_their_points() {
    // A thin family behind the data, one of its curves leaving the axes.
    let mut fig = sample();
    fig.markers.clear();
    fig.origin_lines = false;
    let family = |k: f64| Series {
        label: String::new(),
        points: (0..=20)
            .map(|i| (f64::from(i) / 20.0, k * f64::from(i) / 20.0))
            .collect(),
        style: LineStyle::dotted(Ink::Black, 1.2),
    };
    fig.series.splice(0..0, [family(0.5), family(3.0)]);
    fig.series[2].points = vec![(0.0, 0.1), (1.0, 0.2)];
    fig.series[2].label.clear(); // no legend line
    fig.backdrop = 2;
    let (key, whole) = layered(&fig, Keeps::Nothing);
    let (kept_key, drawn) = layered(&fig, Keeps::Whole);
    assert_eq!(kept_key, key);
    // Drawn whole: grid, tick labels, the backdrop and the data; over a kept layer only
    // the data, the title and the note that a curve leaves the axes (the backdrop's).
    let lines = |svg: &str| svg.matches("<polyline").count();
    assert_eq!(lines(&drawn), 1, "{drawn}");
    assert!(lines(&whole) > 3, "{whole}");
    assert!(whole.contains("time t [s]") && !drawn.contains("time t [s]"));
    let note = crate::t!("plot-clipped");
    assert!(drawn.contains(&note) && whole.contains(&note));
    // Without that curve, nothing is clipped.
    let mut inside = fig.clone();
    inside.series[1] = family(0.9);
    assert!(!layered(&inside, Keeps::Whole).1.contains(&note));
    // The layer is another when a backdrop point moves, not when a data point does.
    let mut moved = fig.clone();
    moved.series[2].points[0].1 = 0.5;
    assert_eq!(layered(&moved, Keeps::Nothing).0, key);
    moved.series[0].points[3].1 = 0.11;
    assert_ne!(layered(&moved, Keeps::Nothing).0, key);
    // Under a heatmap, drawn over the layer, there is no backdrop.
    let mut mapped = fig.clone();
    mapped.heatmap = Some(crate::figure::Heatmap {
        log: false,
        nx: 1,
        ny: 1,
        values: vec![0.5],
        x_edges: (0.0, 1.0),
        y_edges: (-1.0, 1.0),
        scale: (0.0, 1.0),
        label: String::new(),
    });
    let (_, over_map) = layered(&mapped, Keeps::Whole);
    assert_eq!(lines(&over_map), 3, "{over_map}");
}

#[test]
fn a_layer_kept_under_its_backdrop_serves_a_drag_that_moves_the_backdrop() {
    // An exact solution (the backdrop) under a numerical one, as `integrators` draws it.
    let mut fig = sample();
    fig.markers.clear();
    fig.origin_lines = false;
    let exact = Series {
        label: String::new(),
        points: (0..=20).map(|i| (f64::from(i) / 20.0, 0.3)).collect(),
        style: LineStyle::dotted(Ink::Black, 1.2),
    };
    fig.series.insert(0, exact);
    fig.series[1].points = vec![(0.0, 0.1), (1.0, 0.2)];
    fig.series[1].label.clear(); // no legend line
    fig.backdrop = 1;
    let keys = |fig: &Figure| {
        let (keys, _) = layered(fig, Keeps::Nothing);
        let (axes, whole) = keys.split_once(' ').unwrap();
        (axes.to_owned(), whole.to_owned())
    };
    let (axes, whole) = keys(&fig);
    assert_ne!(axes, whole, "a backdrop: two keys");
    // The backdrop moves (a dragged ζ moves the exact solution): the same part under it.
    let mut moved = fig.clone();
    moved.series[0].points[4].1 = 0.35;
    let (moved_axes, moved_whole) = keys(&moved);
    assert_eq!(moved_axes, axes);
    assert_ne!(moved_whole, whole);
    // Over that part: the backdrop and the data are drawn, the grid and tick labels not.
    let lines = |svg: &str| svg.matches("<polyline").count();
    let (_, under) = layered(&moved, Keeps::Axes);
    let (_, over_whole) = layered(&moved, Keeps::Whole);
    let (_, drawn_whole) = layered(&moved, Keeps::Nothing);
    assert_eq!(lines(&under), 2, "backdrop and data: {under}");
    assert_eq!(lines(&over_whole), 1, "the data only: {over_whole}");
    assert!(lines(&drawn_whole) > 3, "{drawn_whole}");
    assert!(!under.contains("time t [s]") && drawn_whole.contains("time t [s]"));
    // Without a backdrop the two keys are one (which tells a backend there is no part
    // under a backdrop to keep).
    let mut bare = fig.clone();
    bare.series.remove(0);
    bare.backdrop = 0;
    let (bare_axes, bare_whole) = keys(&bare);
    assert_eq!(bare_axes, bare_whole);
}

/// `fig` drawn by a backend that keeps `keeps` of its static layer, noted with `note`,
/// the legend held in rows under the chart (`rows`) or placed afresh: the note the whole
/// layer's drawing gave and the SVG drawn through plotters.
fn drawn_over(fig: &Figure, keeps: Keeps, note: LayerNote, rows: bool) -> (LayerNote, String) {
    let rec = Recorder(
        Default::default(),
        Default::default(),
        keeps,
        Cell::new(note),
    );
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (640, 360)).into_drawing_area();
        let out = Output {
            direct: Some(&rec),
            legend: rows.then_some(Placement::Below(0)),
        };
        render_with(&root, fig, &Theme::LIGHT, 1.0, out).unwrap();
    }
    (rec.3.get(), svg)
}

#[test]
fn over_the_part_under_a_moved_backdrop_the_rows_and_the_clipped_note_are_drawn_afresh() {
    let mut fig = sample();
    fig.markers.clear();
    fig.series[0].label = "design ζ 0.30".into();
    fig.series[0].points = vec![(0.0, 0.1), (1.0, 0.2)];
    let backdrop = Series {
        label: String::new(),
        points: vec![(0.0, 0.2), (1.0, 0.3)],
        style: LineStyle::dotted(Ink::Black, 1.2),
    };
    fig.series.insert(0, backdrop);
    fig.backdrop = 1;
    // The rows are not in the part under the backdrop: drawn once, their band not cleared
    // (as many rectangles as over a whole layer that holds them), and noted with the layer.
    let stale = LayerNote::default();
    let (note, over) = drawn_over(&fig, Keeps::Axes, stale, true);
    assert_eq!(over.matches("design ζ 0.30").count(), 1, "{over}");
    assert_ne!(note.rows, 0, "the whole layer's note names its rows");
    let (_, over_whole) = drawn_over(&fig, Keeps::Whole, note, true);
    assert!(!over_whole.contains("design ζ 0.30"), "{over_whole}");
    let rects = |svg: &str| svg.matches("<rect").count();
    assert_eq!(rects(&over), rects(&over_whole), "the band not cleared");
    // A backdrop that leaves the axes: the plot says so, whatever an older note said.
    let clipped = crate::t!("plot-clipped");
    assert!(!over.contains(&clipped), "{over}");
    fig.series[0].points[1].1 = 3.0;
    let (note, out) = drawn_over(&fig, Keeps::Axes, stale, false);
    assert!(out.contains(&clipped), "{out}");
    assert!(note.clipped);
}

/// `fig` drawn with its legend held in rows under the chart, by a backend that keeps its
/// static layer (noted as `note`) or lacks one: the calls and the SVG drawn through plotters.
fn below(fig: &Figure, keeps: bool, note: LayerNote) -> (LayerNote, String) {
    let rec = Recorder(
        Default::default(),
        Default::default(),
        if keeps { Keeps::Whole } else { Keeps::Nothing },
        Cell::new(note),
    );
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (640, 360)).into_drawing_area();
        let out = Output {
            direct: Some(&rec),
            legend: Some(Placement::Below(0)),
        };
        render_with(&root, fig, &Theme::LIGHT, 1.0, out).unwrap();
    }
    (rec.3.get(), svg)
}

#[test]
fn legend_rows_under_the_chart_are_kept_with_the_layer_until_they_change() {
    let mut fig = sample();
    fig.series[0].label = "design ζ 0.30".into();
    // Drawn whole: the rows are part of the layer, and its note says which rows.
    let (note, whole) = below(&fig, false, LayerNote::default());
    assert!(whole.contains("design ζ 0.30"), "{whole}");
    assert_ne!(note.rows, 0);
    // Over that layer: not drawn again, nor is their band cleared.
    let (_, over) = below(&fig, true, note);
    assert!(!over.contains("design ζ 0.30"), "{over}");
    let rects = |svg: &str| svg.matches("<rect").count();
    // A label that names a value moved on: the band is cleared and the new rows drawn.
    fig.series[0].label = "design ζ 0.31".into();
    let (_, moved) = below(&fig, true, note);
    assert!(moved.contains("design ζ 0.31"), "{moved}");
    assert_eq!(rects(&moved), rects(&over) + 1, "the band cleared");
    // The same for another swatch under the same label.
    let mut restyled = sample();
    restyled.series[0].label = "design ζ 0.30".into();
    restyled.series[0].style = LineStyle::dashed(Ink::Blue, 2.0);
    assert!(below(&restyled, true, note).1.contains("design ζ 0.30"));
    // Without a layer (vector output) the rows are drawn after the data, as always.
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (640, 360)).into_drawing_area();
        let out = Output {
            direct: None,
            legend: Some(Placement::Below(0)),
        };
        render_with(&root, &fig, &Theme::LIGHT, 1.0, out).unwrap();
    }
    assert!(svg.contains("design ζ 0.31"));
}
