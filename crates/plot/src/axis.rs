//! Axis scales and tick placement: "nice" 1–2–5 steps on linear axes, decades on log axes.

use crate::error::PlotError;

/// A tick: data value, label markup, and whether it is major (labelled).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Tick {
    pub value: f64,
    pub label: Option<String>,
}

/// One axis: data range (after padding to ticks) and scale.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Axis {
    pub lo: f64,
    pub hi: f64,
    pub log: bool,
}

impl Axis {
    /// An axis covering `[lo, hi]`, widened to whole ticks (decades on a log axis) when `nice`.
    pub(crate) fn new(
        name: &'static str,
        lo: f64,
        hi: f64,
        log: bool,
        nice: bool,
    ) -> Result<Self, PlotError> {
        if !(lo.is_finite() && hi.is_finite()) || lo > hi || (log && lo <= 0.0) {
            return Err(PlotError::InvalidRange { axis: name, lo, hi });
        }
        let (mut lo, mut hi) = (lo, hi);
        if log {
            let (mut a, mut b) = (lo.log10(), hi.log10());
            if b - a < 1e-12 {
                a -= 0.5;
                b += 0.5;
            }
            if nice {
                a = a.floor();
                b = b.ceil();
            }
            lo = 10f64.powf(a);
            hi = 10f64.powf(b);
        } else {
            if hi - lo <= 1e-12 * lo.abs().max(hi.abs()).max(1e-300) {
                let d = if lo == 0.0 { 1.0 } else { 0.5 * lo.abs() };
                lo -= d;
                hi += d;
            }
            if nice {
                let step = nice_step(hi - lo);
                lo = (lo / step).floor() * step;
                hi = (hi / step).ceil() * step;
            }
        }
        Ok(Self { lo, hi, log })
    }

    /// Position in [0, 1] of a data value.
    pub(crate) fn frac(&self, v: f64) -> f64 {
        if self.log {
            (v.log10() - self.lo.log10()) / (self.hi.log10() - self.lo.log10())
        } else {
            (v - self.lo) / (self.hi - self.lo)
        }
    }

    /// Ticks with labels; minor ticks (2…9 per decade) on log axes spanning few decades.
    pub(crate) fn ticks(&self) -> Vec<Tick> {
        if self.log {
            let (a, b) = (self.lo.log10().ceil() as i32, self.hi.log10().floor() as i32);
            let decades = (b - a).max(0);
            let every = (decades / 8 + 1).max(1);
            let mut out = Vec::new();
            for k in a..=b {
                let label =
                    ((k - a) % every == 0).then(|| format!(r#"10<tspan dy="-6" font-size="9">{k}</tspan>"#));
                out.push(Tick { value: 10f64.powi(k), label });
                if decades <= 6 && k < b {
                    for m in 2..10 {
                        out.push(Tick { value: m as f64 * 10f64.powi(k), label: None });
                    }
                }
            }
            out
        } else {
            let step = nice_step(self.hi - self.lo);
            let first = (self.lo / step - 1e-9).ceil() as i64;
            let last = (self.hi / step + 1e-9).floor() as i64;
            let off = self.offset();
            let decimals = (-step.log10().floor()).max(0.0) as usize;
            (first..=last)
                .map(|i| {
                    let v = i as f64 * step;
                    let label = match off {
                        // differences from the offset, in engineering form: "+2e-9"
                        Some(o) => {
                            let d = v - o;
                            if d.abs() < 0.5 * step {
                                "0".to_string()
                            } else {
                                format!("{d:+.1e}").replace(".0e", "e")
                            }
                        }
                        None => {
                            let mut s = format!("{v:.decimals$}");
                            if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') {
                                s.remove(0);
                            }
                            s
                        }
                    };
                    Tick { value: v, label: Some(label) }
                })
                .collect()
        }
    }

    /// For a linear axis whose span is tiny against its values (a near-constant series, e.g. an
    /// energy conserved to 1e-9), the value that tick labels are measured from: the tick value
    /// nearest the middle. `None` when plain labels fit (fewer than 7 significant digits).
    pub(crate) fn offset(&self) -> Option<f64> {
        if self.log {
            return None;
        }
        let step = nice_step(self.hi - self.lo);
        let big = self.lo.abs().max(self.hi.abs());
        if big <= 1e5 * step {
            return None;
        }
        Some((0.5 * (self.lo + self.hi) / step).round() * step)
    }
}

/// The offset of a near-constant axis, with enough digits to be exact to its last tick.
pub(crate) fn offset_label(o: f64) -> String {
    let s = format!("{o:.12e}");
    match s.split_once('e') {
        Some((m, e)) => format!("{}e{e}", m.trim_end_matches('0').trim_end_matches('.')),
        None => s,
    }
}

/// A step of 1, 2 or 5 × 10^k giving about six intervals over `span`.
pub(crate) fn nice_step(span: f64) -> f64 {
    let raw = span / 6.0;
    let mag = 10f64.powf(raw.log10().floor());
    let f = raw / mag;
    let m = if f < 1.5 {
        1.0
    } else if f < 3.5 {
        2.0
    } else if f < 7.5 {
        5.0
    } else {
        10.0
    };
    m * mag
}

#[cfg(test)]
mod offset_tests {
    use super::*;

    #[test]
    fn near_constant_axes_label_differences_from_an_offset() {
        // an energy of −0.5 J conserved to 1e-9
        let a = Axis::new("y", -0.5 - 1e-9, -0.5 + 2e-9, false, true).unwrap();
        let o = a.offset().expect("offset notation");
        assert!((o + 0.5).abs() < 1e-9);
        assert_eq!(offset_label(-0.5), "-5e-1");
        let labels: Vec<String> = a.ticks().into_iter().filter_map(|t| t.label).collect();
        assert!(labels.iter().all(|l| l.len() <= 8), "{labels:?}");
        // distinct labels: legible, not clipped copies of −0.500000000
        let mut dedup = labels.clone();
        dedup.dedup();
        assert_eq!(dedup, labels);
        // an ordinary axis keeps plain labels
        assert!(Axis::new("y", 0.0, 10.0, false, true).unwrap().offset().is_none());
    }
}
