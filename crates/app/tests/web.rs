//! Browser tests of the wasm boundary (run by `wasm-pack test --headless --chrome crates/app`):
//! every demo draws real pixels onto a canvas, and hostile input is answered with notices.
#![cfg(target_arch = "wasm32")]
#![allow(clippy::unwrap_used)]

use wasm_bindgen::JsCast;
use wasm_bindgen_test::*;
use web_sys::{CanvasRenderingContext2d, HtmlCanvasElement};
use zeta_app::demos;
use zeta_app::theme::Theme;
use zeta_app::web::Session;

wasm_bindgen_test_configure!(run_in_browser);

fn canvas(w: u32, h: u32) -> HtmlCanvasElement {
    let doc = web_sys::window().unwrap().document().unwrap();
    let c: HtmlCanvasElement = doc.create_element("canvas").unwrap().dyn_into().unwrap();
    c.set_width(w);
    c.set_height(h);
    doc.body().unwrap().append_child(&c).unwrap();
    c
}

/// Whether pixel `p` (RGBA) is close to `rgb`: within 40 per channel.
fn near(p: &[u8], rgb: (u8, u8, u8)) -> bool {
    let close = |a: u8, b: u8| (i32::from(a) - i32::from(b)).abs() < 40;
    close(p[0], rgb.0) && close(p[1], rgb.1) && close(p[2], rgb.2)
}

/// Counts the pixels of `c` close to `rgb` in the rectangle at `(x, y)` of `w` × `h`.
fn count_in(c: &HtmlCanvasElement, (x, y, w, h): (u32, u32, u32, u32), rgb: (u8, u8, u8)) -> usize {
    let ctx: CanvasRenderingContext2d = c.get_context("2d").unwrap().unwrap().dyn_into().unwrap();
    let data = ctx
        .get_image_data(f64::from(x), f64::from(y), f64::from(w), f64::from(h))
        .unwrap()
        .data();
    data.chunks(4).filter(|p| near(p, rgb)).count()
}

/// Counts pixels close to `rgb` (within 40 per channel).
fn count_colour(c: &HtmlCanvasElement, rgb: (u8, u8, u8)) -> usize {
    count_in(c, (0, 0, c.width(), c.height()), rgb)
}

/// Text is measured in the font asked for, however often: the canvas backend remembers
/// widths by font and text (`canvas::measure`), so a font's width must not answer for
/// another's, nor a text's for another text's.
#[wasm_bindgen_test]
fn text_is_measured_in_the_font_and_text_asked_for() {
    use plotters::prelude::*;
    use plotters_backend::DrawingBackend;
    let c = canvas(200, 100);
    let b = zeta_app::canvas::HtmlCanvas::new(&c).unwrap();
    let small = ("sans-serif", 12.0).into_font().color(&BLACK);
    let large = ("sans-serif", 24.0).into_font().color(&BLACK);
    let width = |text: &str, style: &TextStyle<'_>| b.estimate_text_size(text, style).unwrap().0;
    let (s, l) = (width("Wwww 123", &small), width("Wwww 123", &large));
    assert!(s > 20, "12 px text measured {s} px wide");
    assert!((2 * s).abs_diff(l) <= 2, "12 px: {s} px, 24 px: {l} px");
    // Asked again, in either order: the same answers.
    assert_eq!(
        (width("Wwww 123", &large), width("Wwww 123", &small)),
        (l, s)
    );
    assert!(width("Wwww 1234", &small) > s);
}

/// A canvas's backends remember what its 2D context holds from one drawing to the next
/// (`canvas::Surface`), and forget it whenever something else may have changed it: a
/// resize (even to the same size), or another backend's drawing on the same canvas. Each
/// case draws text in one font, disturbs the context, and draws again: the context must
/// hold the font (and the solid line) the second drawing asked for.
#[wasm_bindgen_test]
fn a_canvas_remembers_its_drawing_state_only_while_the_context_keeps_it() {
    use plotters::prelude::*;
    use plotters_backend::DrawingBackend;
    use zeta_app::canvas::{on_surface, HtmlCanvas, Surface};
    let c = canvas(200, 100);
    let ctx: CanvasRenderingContext2d = c.get_context("2d").unwrap().unwrap().dyn_into().unwrap();
    let surface = Surface::of(c.clone());
    let draw = || {
        let mut b = on_surface(&surface).unwrap();
        let style = ("sans-serif", 17.0).into_font().color(&BLACK);
        b.draw_text("x", &style, (5, 5)).unwrap();
        b.draw_line((0, 50), (200, 50), &BLACK.stroke_width(1))
            .unwrap();
    };
    let font = || ctx.font();
    let dashed = || ctx.get_line_dash().length() > 0;
    draw();
    assert_eq!(font(), "17px sans-serif");

    // Kept: the next frame's backend does not set the font again. (Shown by a font put on
    // behind its back, which it then leaves alone.)
    ctx.set_font("9px serif");
    draw();
    assert_eq!(
        font(),
        "9px serif",
        "the memory was not kept between drawings"
    );

    // A resize resets the context: the memory is dropped with it.
    c.set_width(201);
    draw();
    assert_eq!(font(), "17px sans-serif", "after a resize");
    // Even to the same size.
    c.set_width(c.width());
    assert_eq!(font(), "10px sans-serif");
    draw();
    assert_eq!(font(), "17px sans-serif", "after a resize to the same size");

    // Another backend draws on the canvas (a PNG export, a test): its font and dash stay
    // on the context, and the surface's next backend must not trust its own memory.
    {
        let mut other = HtmlCanvas::new(&c).unwrap();
        other
            .draw_text("y", &("serif", 30.0).into_font().color(&BLACK), (5, 5))
            .unwrap();
        ctx.set_line_dash(&js_sys::Array::of2(&4.0.into(), &4.0.into()))
            .unwrap();
    }
    draw();
    assert_eq!(font(), "17px sans-serif", "after another backend drew");
    // Every drawing starts solid, whatever dash was left on the context.
    assert!(!dashed(), "a dash left by another drawing");
}

/// Counts the pixels of row `y` close to `rgb` (as [`count_colour`]).
fn count_in_row(c: &HtmlCanvasElement, y: u32, rgb: (u8, u8, u8)) -> usize {
    count_in(c, (0, y, c.width(), 1), rgb)
}

/// Lines in one stroke are traced into one path and stroked once (`canvas::html::Batch`):
/// the run must be stroked before anything else changes what stroking it would do (a dash
/// set through the canvas's direct handle, a shape drawn over it) and when the drawing
/// ends, or lines come out dashed, over what was drawn after them, or not at all.
#[wasm_bindgen_test]
fn a_run_of_lines_is_stroked_before_whatever_follows_it() {
    use plotters::prelude::*;
    use plotters_backend::DrawingBackend;
    use zeta_app::render::Direct;
    let c = canvas(200, 100);
    let red = RGBColor(230, 0, 0).stroke_width(3);
    {
        let mut b = zeta_app::canvas::HtmlCanvas::new(&c).unwrap();
        let direct = b.direct();
        // A run of two solid red lines, then a dash for a blue line, then solid again.
        b.draw_line((0, 20), (199, 20), &red).unwrap();
        b.draw_line((0, 40), (199, 40), &red).unwrap();
        direct.dash(&[6.0, 6.0]);
        b.draw_line((0, 60), (199, 60), &RGBColor(0, 0, 230).stroke_width(3))
            .unwrap();
        direct.dash(&[]);
        // A run of two red lines, a black square drawn over the middle of both.
        b.draw_line((0, 75), (199, 75), &red).unwrap();
        b.draw_line((0, 85), (199, 85), &red).unwrap();
        b.draw_rect((90, 70), (111, 91), &BLACK.filled(), true)
            .unwrap();
        // Dropped with this last line unstroked.
        b.draw_line((0, 95), (199, 95), &red).unwrap();
    }
    let (red, blue) = ((230, 0, 0), (0, 0, 230));
    assert!(
        count_in_row(&c, 20, red) >= 198,
        "the first line was dashed"
    );
    assert!(
        count_in_row(&c, 40, red) >= 198,
        "the second line was dashed"
    );
    let dashed = count_in_row(&c, 60, blue);
    assert!(
        (80..130).contains(&dashed),
        "the dashed line: {dashed} of 200 px"
    );
    for y in [75, 85] {
        let n = count_in_row(&c, y, red);
        assert!(
            (170..190).contains(&n),
            "row {y}: {n} px red, the square covers 21"
        );
    }
    assert!(
        count_in_row(&c, 95, red) >= 198,
        "the last line, stroked when the drawing ended"
    );
}

/// A stretched image (a heatmap, a colour bar) goes through a scratch canvas of its size,
/// which keeps the last image put on it: the same image again is drawn from it, another of
/// the same size replaces it.
#[wasm_bindgen_test]
fn a_stretched_image_is_drawn_again_from_its_scratch_canvas_until_another_replaces_it() {
    use zeta_app::render::{Direct, Stretched};
    let stretch = |rgb: &[u8]| {
        let c = canvas(100, 50);
        let b = zeta_app::canvas::HtmlCanvas::new(&c).unwrap();
        b.direct().stretch(&Stretched {
            size: (2, 1),
            rgb,
            to: [0, 0, 100, 50],
            clip: [0, 0, 100, 50],
        });
        let left = count_in(&c, (0, 0, 50, 50), (rgb[0], rgb[1], rgb[2]));
        let right = count_in(&c, (50, 0, 50, 50), (rgb[3], rgb[4], rgb[5]));
        (left, right)
    };
    let (red_blue, green_red) = ([230, 0, 0, 0, 0, 230], [0, 200, 0, 230, 0, 0]);
    // First put, then drawn again from the scratch canvas, then another image, then back.
    for rgb in [red_blue, red_blue, green_red, red_blue] {
        assert_eq!(stretch(&rgb), (2500, 2500), "{rgb:?}");
    }
}

#[wasm_bindgen_test]
fn regimes_draws_its_curve_and_poles_onto_canvases() {
    let response = canvas(760, 400);
    let poles = canvas(400, 320);
    let mut s = Session::new("regimes").unwrap();
    assert!(s.attach("response", response.clone()));
    assert!(s.attach("poles", poles.clone()));
    assert!(!s.attach("no-such-plot", canvas(10, 10)));
    s.update(1.0, false).unwrap();
    let blue = Theme::LIGHT.palette[0];
    let vermillion = Theme::LIGHT.palette[1];
    // The response curve is drawn in the first palette colour, the pole crosses in the second.
    assert!(
        count_colour(&response, (blue.0, blue.1, blue.2)) > 500,
        "response curve drawn"
    );
    assert!(
        count_colour(&poles, (vermillion.0, vermillion.1, vermillion.2)) > 20,
        "poles drawn"
    );
    // Dark theme repaints the background.
    s.update(1.0, true).unwrap();
    let bg = Theme::DARK.background;
    assert!(count_colour(&response, (bg.0, bg.1, bg.2)) > 760 * 400 / 2);
}

#[wasm_bindgen_test]
fn every_demo_draws_every_plot() {
    for id in demos::ids() {
        let mut s = Session::new(id).unwrap();
        let spec = demos::create(id).unwrap().spec();
        let canvases: Vec<_> = spec
            .plots
            .iter()
            .map(|p| (p.key, canvas(480, 300)))
            .collect();
        for (k, c) in &canvases {
            assert!(s.attach(k, c.clone()));
        }
        s.update(2.0, false).unwrap();
        for (k, c) in &canvases {
            let white = count_colour(c, (255, 255, 255));
            assert!(
                white < 480 * 300 - 2000,
                "{id}/{k}: something besides background was drawn"
            );
        }
    }
}

#[wasm_bindgen_test]
fn hostile_queries_become_notices_not_errors() {
    let mut s = Session::new("regimes").unwrap();
    let notices = s
        .apply_query("?demo=regimes&zeta=%3Cscript%3Ealert(1)%3C/script%3E&wn=1e308&x0=NaN")
        .unwrap();
    let arr: js_sys::Array = notices.dyn_into().unwrap();
    assert_eq!(arr.length(), 3);
    assert!(Session::new("no-such-demo").is_err());
    s.update(1.0, false).unwrap();
}

/// The full module's (a first module has neither `pick` nor `probe`).
#[cfg(not(feature = "first"))]
#[wasm_bindgen_test]
fn a_click_on_a_plot_this_session_has_not_drawn_yet_still_picks() {
    // As after the full module takes over: the page shows the first module's drawing of
    // the map, and the new session has not drawn it (out of view at its update). The click
    // is read against what is seen: the session draws the plot first, the same pixels.
    let map = canvas(480, 480);
    let mut s = Session::new("design").unwrap();
    assert!(s.attach("map", map.clone()));
    s.set_visible("map", false);
    s.update(1.0, false).unwrap();
    let picked: js_sys::Array = s.pick("map", 200.0, 220.0).unwrap().dyn_into().unwrap();
    assert_eq!(picked.length(), 2, "k and c picked from the map");
    assert!(
        !s.probe("map", 200.0, 220.0).unwrap().is_undefined(),
        "and read by the pointer"
    );
}
