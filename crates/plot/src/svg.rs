//! A tiny deterministic SVG writer: fixed number formatting, fixed attribute order.

use std::fmt::Write;

/// Formats a coordinate with two decimals, never printing `-0.00`.
pub(crate) fn num(x: f64) -> String {
    let s = format!("{x:.2}");
    if s == "-0.00" { "0.00".to_string() } else { s }
}

/// Escapes text for SVG content and attributes.
pub(crate) fn escape(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

/// An SVG document under construction.
pub(crate) struct Svg {
    body: String,
    width: f64,
    height: f64,
}

/// Colours of successive series: Okabe and Ito's colour-universal-design palette (2008),
/// distinguishable under the common colour-vision deficiencies, without its yellow (#f0e442,
/// too faint on white). When the colours run out the line style changes instead
/// ([`DASHES`]), so that every series of a figure differs in colour or in style.
pub(crate) const PALETTE: [&str; 7] =
    ["#0072b2", "#d55e00", "#009e73", "#cc79a7", "#e69f00", "#56b4e9", "#000000"];

/// Line styles (SVG `stroke-dasharray`) in the order they are cycled: solid, dashed, dotted,
/// dash-dot.
pub(crate) const DASHES: [Option<&str>; 4] = [None, Some("8 5"), Some("2 4"), Some("8 4 2 4")];

impl Svg {
    pub(crate) fn new(width: f64, height: f64) -> Self {
        Self { body: String::new(), width, height }
    }

    pub(crate) fn raw(&mut self, s: &str) {
        self.body.push_str(s);
        self.body.push('\n');
    }

    #[allow(clippy::too_many_arguments)] // two points, stroke, width, dash: the SVG attributes
    pub(crate) fn line(
        &mut self,
        x1: f64,
        y1: f64,
        x2: f64,
        y2: f64,
        stroke: &str,
        width: f64,
        dash: Option<&str>,
    ) {
        let dash = dash.map(|d| format!(r#" stroke-dasharray="{d}""#)).unwrap_or_default();
        let _ = writeln!(
            self.body,
            r#"<line x1="{}" y1="{}" x2="{}" y2="{}" stroke="{stroke}" stroke-width="{}"{dash}/>"#,
            num(x1),
            num(y1),
            num(x2),
            num(y2),
            num(width)
        );
    }

    pub(crate) fn polyline(
        &mut self,
        pts: &[(f64, f64)],
        stroke: &str,
        width: f64,
        dash: Option<&str>,
        clip: Option<&str>,
    ) {
        if pts.is_empty() {
            return;
        }
        let mut p = String::new();
        for (i, (x, y)) in pts.iter().enumerate() {
            if i > 0 {
                p.push(' ');
            }
            p.push_str(&num(*x));
            p.push(',');
            p.push_str(&num(*y));
        }
        let dash = dash.map(|d| format!(r#" stroke-dasharray="{d}""#)).unwrap_or_default();
        let clip = clip.map(|c| format!(r#" clip-path="url(#{c})""#)).unwrap_or_default();
        let _ = writeln!(
            self.body,
            r#"<polyline points="{p}" fill="none" stroke="{stroke}" stroke-width="{}" stroke-linejoin="round"{dash}{clip}/>"#,
            num(width)
        );
    }

    pub(crate) fn rect(&mut self, x: f64, y: f64, w: f64, h: f64, fill: &str, stroke: &str) {
        let _ = writeln!(
            self.body,
            r#"<rect x="{}" y="{}" width="{}" height="{}" fill="{fill}" stroke="{stroke}"/>"#,
            num(x),
            num(y),
            num(w),
            num(h)
        );
    }

    pub(crate) fn circle(&mut self, x: f64, y: f64, r: f64, fill: &str, stroke: &str) {
        let _ = writeln!(
            self.body,
            r#"<circle cx="{}" cy="{}" r="{}" fill="{fill}" stroke="{stroke}" stroke-width="1.50"/>"#,
            num(x),
            num(y),
            num(r)
        );
    }

    pub(crate) fn cross(&mut self, x: f64, y: f64, r: f64, stroke: &str) {
        self.line(x - r, y - r, x + r, y + r, stroke, 1.5, None);
        self.line(x - r, y + r, x + r, y - r, stroke, 1.5, None);
    }

    pub(crate) fn polygon(&mut self, pts: &[(f64, f64)], fill: &str) {
        let p: Vec<String> = pts.iter().map(|(x, y)| format!("{},{}", num(*x), num(*y))).collect();
        let _ = writeln!(self.body, r#"<polygon points="{}" fill="{fill}"/>"#, p.join(" "));
    }

    /// Text; `anchor` is start, middle or end; `rotate` in degrees about the anchor point.
    pub(crate) fn text(&mut self, x: f64, y: f64, s: &str, size: f64, anchor: &str, rotate: f64) {
        let rot = if rotate != 0.0 {
            format!(r#" transform="rotate({} {} {})""#, num(rotate), num(x), num(y))
        } else {
            String::new()
        };
        let _ = writeln!(
            self.body,
            r#"<text x="{}" y="{}" font-size="{}" text-anchor="{anchor}"{rot}>{}</text>"#,
            num(x),
            num(y),
            num(size),
            escape(s)
        );
    }

    /// Text whose content is already SVG markup (used for 10<tspan>k</tspan> labels).
    pub(crate) fn text_markup(&mut self, x: f64, y: f64, markup: &str, size: f64, anchor: &str) {
        let _ = writeln!(
            self.body,
            r#"<text x="{}" y="{}" font-size="{}" text-anchor="{anchor}">{markup}</text>"#,
            num(x),
            num(y),
            num(size)
        );
    }

    pub(crate) fn clip_rect(&mut self, id: &str, x: f64, y: f64, w: f64, h: f64) {
        let _ = writeln!(
            self.body,
            r#"<defs><clipPath id="{id}"><rect x="{}" y="{}" width="{}" height="{}"/></clipPath></defs>"#,
            num(x),
            num(y),
            num(w),
            num(h)
        );
    }

    pub(crate) fn finish(self) -> String {
        format!(
            concat!(
                r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="sans-serif">"#,
                "\n",
                r#"<rect x="0" y="0" width="{w}" height="{h}" fill="white"/>"#,
                "\n{body}</svg>\n"
            ),
            w = num(self.width),
            h = num(self.height),
            body = self.body
        )
    }
}
