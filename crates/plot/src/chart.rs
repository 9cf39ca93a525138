//! The general panel every figure is drawn on: curves, markers, reference lines, arrows and
//! notes over linear or logarithmic axes, with a legend.

use crate::axis::{Axis, half_span};
use crate::error::PlotError;
use crate::svg::{DASHES, PALETTE, Svg, escape, num};

/// Width of a figure in pixels.
pub(crate) const WIDTH: f64 = 720.0;
/// Height of one panel in pixels.
pub(crate) const PANEL_HEIGHT: f64 = 400.0;
const LEFT: f64 = 72.0;
const RIGHT: f64 = 180.0;
const TOP: f64 = 36.0;
const BOTTOM: f64 = 52.0;
/// Points closer than this to the last point drawn are dropped [px] (see `render`).
const THIN_PX: f64 = 0.5;
/// Pixel coordinates are clamped to this magnitude so that huge values stay printable;
/// the clip path hides everything outside the plot area anyway.
const PIXEL_CLAMP: f64 = 1e4;

/// How a curve is stroked.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Stroke {
    /// A solid line.
    #[default]
    Solid,
    /// A dashed line.
    Dashed,
    /// A dotted line.
    Dotted,
}

/// One polyline of a [`Chart`]. Non-finite points (and non-positive ones on a log axis) break
/// the line into pieces instead of failing: a Bode magnitude at a jω zero is −∞ dB.
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    /// Legend entry; `None` keeps the curve out of the legend.
    pub name: Option<String>,
    /// Data points in order.
    pub points: Vec<(f64, f64)>,
    /// Palette index: colours cycle through seven, then the line style changes
    /// (see `Curve::style`).
    pub color: usize,
    /// Solid, dashed or dotted.
    pub stroke: Stroke,
    /// Draw a small circle at every point (work–precision diagrams).
    pub markers: bool,
}

impl Curve {
    /// A solid, named curve in palette colour `color`.
    pub fn new(name: impl Into<String>, points: Vec<(f64, f64)>, color: usize) -> Self {
        Self { name: Some(name.into()), points, color, stroke: Stroke::Solid, markers: false }
    }

    /// Colour and dash pattern: palette colour `color mod 7`; each time the colours wrap
    /// around, the line style moves one step along solid → dashed → dotted → dash-dot, so
    /// curves 0 and 7 (same colour) differ in style. An explicitly dashed curve (Nyquist's
    /// ω < 0 branch) keeps its difference from the solid curve of the same colour.
    pub(crate) fn style(&self) -> (&'static str, Option<&'static str>) {
        let own = match self.stroke {
            Stroke::Solid => 0,
            Stroke::Dashed => 1,
            Stroke::Dotted => 2,
        };
        let round = self.color / PALETTE.len();
        (PALETTE[self.color % PALETTE.len()], DASHES[(own + round) % DASHES.len()])
    }
}

/// Shape of a [`Marker`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shape {
    /// × (poles).
    Cross,
    /// ○ (zeros).
    Circle,
    /// A filled dot.
    Dot,
    /// + (the critical point −1).
    Plus,
}

/// A marker at a data point, with an optional text label.
#[derive(Debug, Clone, PartialEq)]
pub struct Marker {
    /// Data position.
    pub at: (f64, f64),
    /// Shape.
    pub shape: Shape,
    /// Palette index.
    pub color: usize,
    /// Text written next to the marker.
    pub label: Option<String>,
}

/// A dashed grey reference line at a constant data value (0 dB, −180°, a final value).
#[derive(Debug, Clone, PartialEq)]
pub struct RefLine {
    /// The constant coordinate.
    pub value: f64,
    /// Text written at the line's end.
    pub label: Option<String>,
}

/// A direction arrow head at `to`, pointing from `from` (both in data coordinates).
#[derive(Debug, Clone, PartialEq)]
pub struct Arrow {
    /// Tail (only its direction matters).
    pub from: (f64, f64),
    /// Head position.
    pub to: (f64, f64),
    /// Palette index.
    pub color: usize,
}

/// A general chart panel. [`crate::LineChart`] is the simple front end; the control figures
/// (Bode, Nyquist, root locus …) build a `Chart` directly.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Chart {
    /// Title above the panel.
    pub title: String,
    /// Label under the x axis.
    pub x_label: String,
    /// Label left of the y axis.
    pub y_label: String,
    /// Logarithmic x axis (decade ticks).
    pub log_x: bool,
    /// Logarithmic y axis (decade ticks).
    pub log_y: bool,
    /// Fixed x range; `None` fits the data, widened to whole ticks.
    pub x_range: Option<(f64, f64)>,
    /// Fixed y range; `None` fits the data, widened to whole ticks.
    pub y_range: Option<(f64, f64)>,
    /// Same data scale on both axes (Nyquist, root locus, phase portraits).
    pub equal_aspect: bool,
    /// Polylines.
    pub curves: Vec<Curve>,
    /// Point markers.
    pub markers: Vec<Marker>,
    /// Horizontal reference lines (y = value).
    pub hlines: Vec<RefLine>,
    /// Vertical reference lines (x = value).
    pub vlines: Vec<RefLine>,
    /// Arrow heads.
    pub arrows: Vec<Arrow>,
}

/// The plot area of a panel in pixels, left edge px and width pw, top py and height ph, with
/// the two axes that map data onto it.
struct Area {
    px: f64,
    pw: f64,
    py: f64,
    ph: f64,
    ax: Axis,
    ay: Axis,
}

impl Area {
    /// Pixel coordinates of a data point (y grows downward), clamped to ±[`PIXEL_CLAMP`].
    fn to_px(&self, (x, y): (f64, f64)) -> (f64, f64) {
        let sx = self.px + self.ax.frac(x) * self.pw;
        let sy = self.py + (1.0 - self.ay.frac(y)) * self.ph;
        (sx.clamp(-PIXEL_CLAMP, PIXEL_CLAMP), sy.clamp(-PIXEL_CLAMP, PIXEL_CLAMP))
    }

    /// Whether a pixel lies in the plot area (edges included).
    fn contains(&self, x: f64, y: f64) -> bool {
        (self.px..=self.px + self.pw).contains(&x) && (self.py..=self.py + self.ph).contains(&y)
    }
}

fn usable(v: f64, log: bool) -> bool {
    v.is_finite() && (!log || v > 0.0)
}

impl Chart {
    fn data_range(
        &self,
        pick: impl Fn(&(f64, f64)) -> f64,
        log: bool,
        refs: &[RefLine],
    ) -> Option<(f64, f64)> {
        let mut lo = f64::INFINITY;
        let mut hi = f64::NEG_INFINITY;
        let mut take = |v: f64| {
            if usable(v, log) {
                lo = lo.min(v);
                hi = hi.max(v);
            }
        };
        for c in &self.curves {
            c.points.iter().for_each(|p| take(pick(p)));
        }
        self.markers.iter().for_each(|m| take(pick(&m.at)));
        refs.iter().for_each(|r| take(r.value));
        (lo <= hi).then_some((lo, hi))
    }

    fn axes(&self, w: f64, h: f64) -> Result<(Axis, Axis), PlotError> {
        let fit = |fixed: Option<(f64, f64)>, data: Option<(f64, f64)>, name, log| match (fixed, data) {
            (Some((lo, hi)), _) if lo < hi => Axis::new(name, lo, hi, log, false),
            (Some((lo, hi)), _) => Err(PlotError::InvalidRange { axis: name, lo, hi }),
            (None, Some((lo, hi))) => Axis::new(name, lo, hi, log, true),
            (None, None) => Err(PlotError::Empty { figure: self.title.clone() }),
        };
        let xr = fit(self.x_range, self.data_range(|p| p.0, self.log_x, &self.vlines), "x", self.log_x)?;
        let yr = fit(self.y_range, self.data_range(|p| p.1, self.log_y, &self.hlines), "y", self.log_y)?;
        if !self.equal_aspect || self.log_x || self.log_y {
            return Ok((xr, yr));
        }
        // Equal aspect: widen the axis with fewer data units per pixel about its centre.
        // Half-units per pixel and the centre as lo/2 + hi/2: no overflow for data near ±1e308.
        let (ux, uy) = (half_span(xr.lo, xr.hi) / w, half_span(yr.lo, yr.hi) / h);
        let widen = |a: Axis, u: f64, px: f64, name| {
            let c = 0.5 * a.lo + 0.5 * a.hi;
            let (lo, hi) = (c - u * px, c + u * px);
            if lo.is_finite() && hi.is_finite() {
                Ok(Axis { lo, hi, log: false })
            } else {
                Err(PlotError::InvalidRange { axis: name, lo, hi })
            }
        };
        Ok(if ux > uy { (xr, widen(yr, ux, h, "y")?) } else { (widen(xr, uy, w, "x")?, yr) })
    }

    /// Draws the panel into `svg` with its top-left corner at (0, `y0`): frame and title, grid
    /// and ticks, reference lines, curves, arrows, markers, then the legend (in that order, so
    /// later layers draw on top).
    pub(crate) fn render(&self, svg: &mut Svg, y0: f64, id: &str) -> Result<(), PlotError> {
        let (pw, ph) = (WIDTH - LEFT - RIGHT, PANEL_HEIGHT - TOP - BOTTOM);
        let (ax, ay) = self.axes(pw, ph)?;
        let area = Area { px: LEFT, pw, py: y0 + TOP, ph, ax, ay };
        let Area { px, py, .. } = area;
        svg.clip_rect(id, px, py, pw, ph);
        svg.rect(px, py, pw, ph, "white", "#333333");
        svg.text(px + 0.5 * pw, y0 + 22.0, &self.title, 15.0, "middle", 0.0);
        self.draw_grid(svg, &area);
        self.draw_reference_lines(svg, &area);
        for c in &self.curves {
            self.draw_curve(svg, &area, c, id);
        }
        self.draw_arrows(svg, &area);
        self.draw_markers(svg, &area);
        self.draw_legend(svg, &area);
        Ok(())
    }

    /// Grid lines, tick labels (and the offset of near-constant data), axis labels.
    fn draw_grid(&self, svg: &mut Svg, area: &Area) {
        let Area { px, pw, py, ph, ref ax, ref ay } = *area;
        for t in ax.ticks() {
            let (x, _) = area.to_px((t.value, if ay.log { ay.lo } else { 0.0 }));
            let major = t.label.is_some();
            svg.line(x, py, x, py + ph, if major { "#d0d0d0" } else { "#ececec" }, 1.0, None);
            if let Some(l) = &t.label {
                svg.text_markup(x, py + ph + 17.0, l, 11.0, "middle");
            }
        }
        if let Some(off) = ay.offset() {
            // near-constant data: tick labels are differences from this value
            svg.text(px, py - 6.0, &format!("offset {}", crate::axis::offset_label(off)), 11.0, "start", 0.0);
        }
        for t in ay.ticks() {
            let (_, y) = area.to_px((if ax.log { ax.lo } else { 0.0 }, t.value));
            let major = t.label.is_some();
            svg.line(px, y, px + pw, y, if major { "#d0d0d0" } else { "#ececec" }, 1.0, None);
            if let Some(l) = &t.label {
                svg.text_markup(px - 6.0, y + 4.0, l, 11.0, "end");
            }
        }
        svg.text(px + 0.5 * pw, py + ph + 40.0, &self.x_label, 13.0, "middle", 0.0);
        svg.text(18.0, py + 0.5 * ph, &self.y_label, 13.0, "middle", -90.0);
    }

    /// The dashed horizontal and vertical reference lines that fall inside the plot area.
    fn draw_reference_lines(&self, svg: &mut Svg, area: &Area) {
        let Area { px, pw, py, ph, ref ax, ref ay } = *area;
        for r in &self.hlines {
            if usable(r.value, self.log_y) {
                let (_, y) = area.to_px((if ax.log { ax.lo } else { 0.0 }, r.value));
                if (py..=py + ph).contains(&y) {
                    svg.line(px, y, px + pw, y, "#777777", 1.0, Some("6 4"));
                    if let Some(l) = &r.label {
                        svg.text(px + pw - 4.0, y - 4.0, l, 10.0, "end", 0.0);
                    }
                }
            }
        }
        for r in &self.vlines {
            if usable(r.value, self.log_x) {
                let (x, _) = area.to_px((r.value, if ay.log { ay.lo } else { 0.0 }));
                if (px..=px + pw).contains(&x) {
                    svg.line(x, py, x, py + ph, "#777777", 1.0, Some("6 4"));
                    if let Some(l) = &r.label {
                        svg.text(x + 4.0, py + 12.0, l, 10.0, "start", 0.0);
                    }
                }
            }
        }
    }

    /// One curve, split at unusable points, thinned to the pixel, with its point markers.
    fn draw_curve(&self, svg: &mut Svg, area: &Area, c: &Curve, id: &str) {
        let (color, dash) = c.style();
        // Thinning: a point within THIN_PX of the last one kept is dropped (the last point of
        // every piece is kept). The dropped points and the path through them lie in that
        // disk, so the drawn line stays within THIN_PX of the full polyline everywhere:
        // exact to a pixel, with a file size that follows the drawing, not the sample count.
        let mut piece: Vec<(f64, f64)> = Vec::new();
        let mut pending: Option<(f64, f64)> = None;
        for &(x, y) in &c.points {
            if usable(x, self.log_x) && usable(y, self.log_y) {
                let p = area.to_px((x, y));
                match piece.last() {
                    Some(l) if (p.0 - l.0).hypot(p.1 - l.1) < THIN_PX => pending = Some(p),
                    _ => {
                        piece.push(p);
                        pending = None;
                    }
                }
            } else {
                piece.extend(pending.take());
                svg.polyline(&piece, color, 2.0, dash, Some(id));
                piece.clear();
            }
        }
        piece.extend(pending.take());
        svg.polyline(&piece, color, 2.0, dash, Some(id));
        if c.markers {
            for &(x, y) in &c.points {
                if usable(x, self.log_x) && usable(y, self.log_y) {
                    let (sx, sy) = area.to_px((x, y));
                    if area.contains(sx, sy) {
                        svg.circle(sx, sy, 3.0, color, color);
                    }
                }
            }
        }
    }

    /// Arrow heads whose tip lies inside the plot area.
    fn draw_arrows(&self, svg: &mut Svg, area: &Area) {
        for a in &self.arrows {
            let (fx, fy) = area.to_px(a.from);
            let (tx, ty) = area.to_px(a.to);
            let (dx, dy) = (tx - fx, ty - fy);
            let len = dx.hypot(dy);
            if len > 0.0 && area.contains(tx, ty) {
                let (ux, uy) = (dx / len, dy / len);
                let (l, w) = (10.0, 4.5);
                svg.polygon(
                    &[
                        (tx, ty),
                        (tx - l * ux - w * uy, ty - l * uy + w * ux),
                        (tx - l * ux + w * uy, ty - l * uy - w * ux),
                    ],
                    PALETTE[a.color % PALETTE.len()],
                );
            }
        }
    }

    /// Point markers (with their labels) inside the plot area.
    fn draw_markers(&self, svg: &mut Svg, area: &Area) {
        for m in &self.markers {
            if !(usable(m.at.0, self.log_x) && usable(m.at.1, self.log_y)) {
                continue;
            }
            let (x, y) = area.to_px(m.at);
            if !area.contains(x, y) {
                continue;
            }
            let color = PALETTE[m.color % PALETTE.len()];
            match m.shape {
                Shape::Cross => svg.cross(x, y, 5.0, color),
                Shape::Circle => svg.circle(x, y, 5.0, "none", color),
                Shape::Dot => svg.circle(x, y, 3.5, color, color),
                Shape::Plus => {
                    svg.line(x - 6.0, y, x + 6.0, y, color, 2.0, None);
                    svg.line(x, y - 6.0, x, y + 6.0, color, 2.0, None);
                }
            }
            if let Some(l) = &m.label {
                svg.text(x + 7.0, y - 7.0, l, 10.0, "start", 0.0);
            }
        }
    }

    /// The legend, right of the plot area, in curve order.
    fn draw_legend(&self, svg: &mut Svg, area: &Area) {
        let mut ly = area.py + 8.0;
        for c in self.curves.iter().filter(|c| c.name.is_some()) {
            let (color, dash) = c.style();
            let lx = area.px + area.pw + 12.0;
            svg.line(lx, ly, lx + 22.0, ly, color, 2.0, dash);
            if c.markers {
                svg.circle(lx + 11.0, ly, 3.0, color, color);
            }
            svg.text(lx + 28.0, ly + 4.0, c.name.as_deref().unwrap_or(""), 11.0, "start", 0.0);
            ly += 18.0;
        }
    }

    /// Renders the panel alone as an SVG document.
    ///
    /// # Errors
    /// [`PlotError::Empty`] when there is nothing with finite coordinates to fit the axes to;
    /// [`PlotError::InvalidRange`] for a bad fixed range.
    pub fn to_svg(&self) -> Result<String, PlotError> {
        Figure { title: String::new(), panels: vec![self.clone()] }.to_svg()
    }
}

/// Panels stacked vertically under one optional title (a Bode plot is two panels).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Figure {
    /// Title over all panels (empty: none).
    pub title: String,
    /// Panels from top to bottom.
    pub panels: Vec<Chart>,
}

impl Figure {
    /// Renders every panel into one deterministic SVG document.
    ///
    /// # Errors
    /// [`PlotError::Empty`] when there are no panels or a panel has no finite data.
    pub fn to_svg(&self) -> Result<String, PlotError> {
        if self.panels.is_empty() {
            return Err(PlotError::Empty { figure: self.title.clone() });
        }
        let head = if self.title.is_empty() { 0.0 } else { 30.0 };
        let mut svg = Svg::new(WIDTH, head + PANEL_HEIGHT * self.panels.len() as f64);
        if !self.title.is_empty() {
            svg.raw(&format!(
                r#"<text x="{}" y="22.00" font-size="17.00" text-anchor="middle" font-weight="bold">{}</text>"#,
                num(0.5 * WIDTH),
                escape(&self.title)
            ));
        }
        for (i, p) in self.panels.iter().enumerate() {
            p.render(&mut svg, head + PANEL_HEIGHT * i as f64, &format!("plot-area-{i}"))?;
        }
        Ok(svg.finish())
    }
}
