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
    let heading = crate::t!(
        "export-csv-heading",
        demo = demo,
        title = fig.title.as_str()
    );
    let mut out = format!("# {heading}\n");
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
            crate::t!("export-series", n = i + 1)
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

/// The keyword of the PNG `tEXt` chunk, the SVG `<metadata>` id and the CSV comment
/// that carry a view's state token (see `docs/embedding.md`, "State token").
pub const STAMP_KEY: &str = "zeta-state";

/// Whether `token` may be written into a file: the state token alphabet only
/// (base64url, `.`), so it can never break out of a comment, an XML element or a chunk.
fn token_ok(token: &str) -> bool {
    !token.is_empty()
        && token.len() <= 8192
        && token
            .bytes()
            .all(|b| b.is_ascii_alphanumeric() || matches!(b, b'-' | b'_' | b'.'))
}

/// CRC-32 (IEEE 802.3, reflected polynomial 0xEDB88320) as PNG chunks use it.
fn crc32(bytes: &[u8]) -> u32 {
    let mut crc = 0xFFFF_FFFFu32;
    for &b in bytes {
        crc ^= u32::from(b);
        for _ in 0..8 {
            let mask = (crc & 1).wrapping_neg();
            crc = (crc >> 1) ^ (0xEDB8_8320 & mask);
        }
    }
    !crc
}

fn png_text_chunk(keyword: &str, text: &str) -> Vec<u8> {
    let mut body = b"tEXt".to_vec();
    body.extend_from_slice(keyword.as_bytes());
    body.push(0);
    body.extend_from_slice(text.as_bytes());
    let len = (body.len() - 4) as u32;
    let mut out = len.to_be_bytes().to_vec();
    let crc = crc32(&body);
    out.extend_from_slice(&body);
    out.extend_from_slice(&crc.to_be_bytes());
    out
}

const PNG_SIGNATURE: [u8; 8] = [0x89, b'P', b'N', b'G', b'\r', b'\n', 0x1A, b'\n'];

/// `data` (a PNG, an SVG document or a CSV, by `format`) with `token` and `version`
/// written in: PNG `tEXt` chunks `zeta-state` and `zeta-version` after `IHDR`, an SVG
/// `<metadata id="zeta-state" data-version="…">` element, a first CSV line
/// `# zeta-state: <token> (Zeta Lab <version>)`. Unchanged when the token is not in the
/// token alphabet, the format is unknown or the PNG has no `IHDR` first.
pub fn stamp(format: &str, data: &[u8], token: &str, version: &str) -> Vec<u8> {
    let version: String = version
        .chars()
        .filter(|c| c.is_ascii_alphanumeric() || matches!(c, '.' | '-' | '+'))
        .collect();
    if !token_ok(token) {
        return data.to_vec();
    }
    match format {
        "png" => {
            // Signature (8) + IHDR chunk (4 length + 4 type + 13 data + 4 CRC).
            let ihdr_end = 8 + 25;
            if data.len() < ihdr_end
                || data[..8] != PNG_SIGNATURE
                || data.get(12..16) != Some(b"IHDR".as_slice())
            {
                return data.to_vec();
            }
            let mut out = data[..ihdr_end].to_vec();
            out.extend(png_text_chunk(STAMP_KEY, token));
            out.extend(png_text_chunk("zeta-version", &version));
            out.extend_from_slice(&data[ihdr_end..]);
            out
        }
        "svg" => {
            let text = String::from_utf8_lossy(data);
            let Some(open) = text.find("<svg") else {
                return data.to_vec();
            };
            let Some(end) = text[open..].find('>').map(|e| open + e + 1) else {
                return data.to_vec();
            };
            format!(
                "{}\n<metadata id=\"{STAMP_KEY}\" data-version=\"{version}\">{token}</metadata>{}",
                &text[..end],
                &text[end..]
            )
            .into_bytes()
        }
        "csv" => {
            let mut out = format!("# {STAMP_KEY}: {token} (Zeta Lab {version})\n").into_bytes();
            out.extend_from_slice(data);
            out
        }
        _ => data.to_vec(),
    }
}

/// The state token stamped into a PNG, SVG or CSV by [`stamp`], if there is one.
pub fn read_stamp(data: &[u8]) -> Option<String> {
    if data.len() >= 8 && data[..8] == PNG_SIGNATURE {
        let mut at = 8usize;
        while at + 12 <= data.len() {
            let len = u32::from_be_bytes(data.get(at..at + 4)?.try_into().ok()?) as usize;
            let kind = data.get(at + 4..at + 8)?;
            let body = data.get(at + 8..at.checked_add(8 + len)?)?;
            if kind == b"tEXt" {
                if let Some(rest) = body.strip_prefix(STAMP_KEY.as_bytes()) {
                    if let Some(token) = rest.strip_prefix(&[0u8]) {
                        let token = std::str::from_utf8(token).ok()?;
                        return token_ok(token).then(|| token.to_string());
                    }
                }
            }
            if kind == b"IDAT" || kind == b"IEND" {
                return None;
            }
            at = at.checked_add(12 + len)?;
        }
        return None;
    }
    let head = String::from_utf8_lossy(&data[..data.len().min(65536)]);
    let found = if let Some(i) = head.find(&format!("# {STAMP_KEY}: ")) {
        head[i + STAMP_KEY.len() + 4..].split_whitespace().next()
    } else if let Some(i) = head.find(&format!("id=\"{STAMP_KEY}\"")) {
        let rest = &head[i..];
        rest.find('>').and_then(|s| rest[s + 1..].split('<').next())
    } else {
        None
    };
    found.filter(|t| token_ok(t)).map(str::to_string)
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

    #[test]
    fn crc32_matches_the_published_check_value() {
        // The standard check value of CRC-32/ISO-HDLC over "123456789".
        assert_eq!(super::crc32(b"123456789"), 0xCBF4_3926);
    }

    #[test]
    fn stamped_exports_give_their_token_back() {
        let token = "1.ZGVtbz1yZWdpbWVz";
        let mut png = PNG_SIGNATURE.to_vec();
        png.extend(png_text_chunk("x", "y")[..0].iter());
        // A minimal IHDR (13 data bytes) then IEND.
        let mut ihdr = b"IHDR".to_vec();
        ihdr.extend([0, 0, 0, 1, 0, 0, 0, 1, 8, 6, 0, 0, 0]);
        png.extend(13u32.to_be_bytes());
        png.extend(&ihdr);
        png.extend(crc32(&ihdr).to_be_bytes());
        png.extend([0, 0, 0, 0, b'I', b'E', b'N', b'D', 0xAE, 0x42, 0x60, 0x82]);
        assert_eq!(read_stamp(&png), None);
        let stamped = stamp("png", &png, token, "0.1.0");
        assert_eq!(read_stamp(&stamped).as_deref(), Some(token));
        assert_eq!(&stamped[stamped.len() - 12..], &png[png.len() - 12..]);
        let svg = b"<?xml version=\"1.0\"?>\n<svg width=\"10\" height=\"10\"><rect/></svg>";
        let s = stamp("svg", svg, token, "0.1.0");
        assert!(String::from_utf8_lossy(&s)
            .contains("<metadata id=\"zeta-state\" data-version=\"0.1.0\">"));
        assert_eq!(read_stamp(&s).as_deref(), Some(token));
        let c = stamp("csv", b"# Zeta Lab\nt,x\n0,1\n", token, "0.1.0");
        assert!(String::from_utf8_lossy(&c)
            .starts_with("# zeta-state: 1.ZGVtbz1yZWdpbWVz (Zeta Lab 0.1.0)\n# Zeta Lab"));
        assert_eq!(read_stamp(&c).as_deref(), Some(token));
    }

    #[test]
    fn hostile_tokens_and_files_are_refused() {
        let svg = b"<svg></svg>";
        assert_eq!(stamp("svg", svg, "a\"><script>", "1"), svg.to_vec());
        assert_eq!(
            stamp("png", b"not a png at all, not at all......", "1.abc", "1"),
            b"not a png at all, not at all......".to_vec()
        );
        for junk in [
            &b""[..],
            b"\x89PNG\r\n\x1a\n\xff\xff\xff\xff",
            b"# zeta-state: <b>",
        ] {
            assert_eq!(read_stamp(junk), None);
        }
    }
}
