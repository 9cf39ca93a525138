//! Dimensions: exponents of mass, length, time and plane angle (book §15.19).

use core::fmt;

/// Largest exponent magnitude a dimension or a unit factor may carry.
///
/// Physical dimensions of mechanics stay within ±4; the bound keeps exact factor arithmetic
/// small and turns runaway powers such as `(m^10)^10` into a typed error.
pub const MAX_EXPONENT: i32 = 16;

/// A physical dimension M^m L^l T^t A^a: exponents of mass, length, time and plane angle.
///
/// # Conventions
/// Plane angle is a base dimension of its own (A), so that `rad/s` (angular velocity) and
/// `1/s` or `Hz` (frequency) are told apart, and a bare `Hz` for an angular rate is refused
/// instead of silently losing 2π. Every other quantity keeps the SI convention that the
/// radian does not appear: torque and moment are `N*m` (= `J`, M L² T⁻²), angular momentum
/// `kg*m^2/s`, moment of inertia `kg*m^2`. A dimension is *accepted* only when it equals the
/// expected one exactly, so `N*m` is a moment and `N*m/rad` a rotational stiffness. Electric
/// current and temperature are not needed by the book's mechanics and are not modelled.
///
/// Book: §15.19, (15.19.1)–(15.19.5); §1.6 (the kinds of physical vectors).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Dimension {
    /// Exponent of mass M.
    pub mass: i8,
    /// Exponent of length L.
    pub length: i8,
    /// Exponent of time T.
    pub time: i8,
    /// Exponent of plane angle A.
    pub angle: i8,
}

impl Dimension {
    /// M^m L^l T^t A^a.
    ///
    /// Book: §15.19.
    pub const fn new(mass: i8, length: i8, time: i8, angle: i8) -> Self {
        Self { mass, length, time, angle }
    }

    /// Dimensionless (also: a ratio of like quantities).
    pub const DIMENSIONLESS: Self = Self::new(0, 0, 0, 0);
    /// Mass, kg.
    pub const MASS: Self = Self::new(1, 0, 0, 0);
    /// Length (position, displacement), m.
    pub const LENGTH: Self = Self::new(0, 1, 0, 0);
    /// Time, s.
    pub const TIME: Self = Self::new(0, 0, 1, 0);
    /// Plane angle, rad.
    pub const ANGLE: Self = Self::new(0, 0, 0, 1);
    /// Area, m².
    pub const AREA: Self = Self::new(0, 2, 0, 0);
    /// Volume, m³.
    pub const VOLUME: Self = Self::new(0, 3, 0, 0);
    /// Velocity, m/s.
    pub const VELOCITY: Self = Self::new(0, 1, -1, 0);
    /// Acceleration, m/s².
    pub const ACCELERATION: Self = Self::new(0, 1, -2, 0);
    /// Angular velocity, rad/s.
    pub const ANGULAR_VELOCITY: Self = Self::new(0, 0, -1, 1);
    /// Angular acceleration, rad/s².
    pub const ANGULAR_ACCELERATION: Self = Self::new(0, 0, -2, 1);
    /// Frequency or rate, 1/s (no angle: `Hz`).
    pub const FREQUENCY: Self = Self::new(0, 0, -1, 0);
    /// Force, N = kg·m/s² (15.19.1).
    pub const FORCE: Self = Self::new(1, 1, -2, 0);
    /// Moment, torque, energy and work, N·m = J.
    pub const MOMENT: Self = Self::new(1, 2, -2, 0);
    /// Energy and work, J (the dimension of [`Dimension::MOMENT`]).
    pub const ENERGY: Self = Self::MOMENT;
    /// Power, W.
    pub const POWER: Self = Self::new(1, 2, -3, 0);
    /// Pressure and stress, Pa.
    pub const PRESSURE: Self = Self::new(1, -1, -2, 0);
    /// Momentum and impulse, kg·m/s = N·s (15.19.4).
    pub const MOMENTUM: Self = Self::new(1, 1, -1, 0);
    /// Angular momentum, kg·m²/s.
    pub const ANGULAR_MOMENTUM: Self = Self::new(1, 2, -1, 0);
    /// Moment of inertia, kg·m².
    pub const MOMENT_OF_INERTIA: Self = Self::new(1, 2, 0, 0);
    /// Density, kg/m³.
    pub const DENSITY: Self = Self::new(1, -3, 0, 0);
    /// Translational stiffness, N/m.
    pub const STIFFNESS: Self = Self::new(1, 0, -2, 0);
    /// Translational damping, N·s/m.
    pub const DAMPING: Self = Self::new(1, 0, -1, 0);
    /// Rotational stiffness, N·m/rad.
    pub const ROTATIONAL_STIFFNESS: Self = Self::new(1, 2, -2, -1);
    /// Rotational damping, N·m·s/rad.
    pub const ROTATIONAL_DAMPING: Self = Self::new(1, 2, -1, -1);
    /// Gravitational parameter μ = G M, m³/s².
    pub const GRAVITATIONAL_PARAMETER: Self = Self::new(0, 3, -2, 0);

    /// The dimensions with a name in messages, and that name.
    const NAMED: [(Self, &'static str); 26] = [
        (Self::DIMENSIONLESS, "dimensionless"),
        (Self::MASS, "mass"),
        (Self::LENGTH, "length"),
        (Self::TIME, "time"),
        (Self::ANGLE, "angle"),
        (Self::AREA, "area"),
        (Self::VOLUME, "volume"),
        (Self::VELOCITY, "velocity"),
        (Self::ACCELERATION, "acceleration"),
        (Self::ANGULAR_VELOCITY, "angular velocity"),
        (Self::ANGULAR_ACCELERATION, "angular acceleration"),
        (Self::FREQUENCY, "frequency"),
        (Self::FORCE, "force"),
        (Self::MOMENT, "moment or energy"),
        (Self::POWER, "power"),
        (Self::PRESSURE, "pressure"),
        (Self::MOMENTUM, "momentum or impulse"),
        (Self::ANGULAR_MOMENTUM, "angular momentum"),
        (Self::MOMENT_OF_INERTIA, "moment of inertia"),
        (Self::DENSITY, "density"),
        (Self::STIFFNESS, "stiffness"),
        (Self::DAMPING, "damping"),
        (Self::ROTATIONAL_STIFFNESS, "rotational stiffness"),
        (Self::ROTATIONAL_DAMPING, "rotational damping"),
        (Self::GRAVITATIONAL_PARAMETER, "gravitational parameter"),
        (Self::new(0, 0, -2, 0), "1/time²"),
    ];

    /// The name used in messages (`"velocity"`, `"moment of inertia"`, …), if this dimension
    /// has one.
    ///
    /// Book: §1.6, §15.19.
    pub fn name(&self) -> Option<&'static str> {
        Self::NAMED.iter().find(|(d, _)| d == self).map(|&(_, n)| n)
    }

    /// Exponents in the order (M, L, T, A).
    pub const fn exponents(&self) -> [i8; 4] {
        [self.mass, self.length, self.time, self.angle]
    }

    /// self · other (exponents add), or `None` past [`MAX_EXPONENT`].
    pub fn checked_mul(&self, other: &Self) -> Option<Self> {
        self.checked_combine(other, 1)
    }

    /// self / other (exponents subtract), or `None` past [`MAX_EXPONENT`].
    pub fn checked_div(&self, other: &Self) -> Option<Self> {
        self.checked_combine(other, -1)
    }

    /// self^n, or `None` past [`MAX_EXPONENT`].
    pub fn checked_pow(&self, n: i32) -> Option<Self> {
        let e = self.exponents().map(|x| i32::from(x) * n);
        Self::from_exponents(e)
    }

    fn checked_combine(&self, other: &Self, sign: i32) -> Option<Self> {
        let (a, b) = (self.exponents(), other.exponents());
        Self::from_exponents([0, 1, 2, 3].map(|i| i32::from(a[i]) + sign * i32::from(b[i])))
    }

    pub(crate) fn from_exponents(e: [i32; 4]) -> Option<Self> {
        if e.iter().any(|x| x.abs() > MAX_EXPONENT) {
            return None;
        }
        Some(Self::new(e[0] as i8, e[1] as i8, e[2] as i8, e[3] as i8))
    }

    /// The coherent SI unit of this dimension in the quantity grammar, e.g. `kg*m^2/s^2`.
    ///
    /// Book: §15.19.
    pub fn si_symbol(&self) -> String {
        let mut up = Vec::new();
        let mut down = Vec::new();
        for (sym, e) in ["kg", "m", "s", "rad"].into_iter().zip(self.exponents()) {
            match e {
                0 => {}
                1 => up.push(sym.to_string()),
                e if e > 0 => up.push(format!("{sym}^{e}")),
                -1 => down.push(sym.to_string()),
                e => down.push(format!("{sym}^{}", -e)),
            }
        }
        let mut s = if up.is_empty() { "1".to_string() } else { up.join("*") };
        for d in down {
            s.push('/');
            s.push_str(&d);
        }
        s
    }
}

impl fmt::Display for Dimension {
    /// `velocity (m/s)`, or the SI form alone for a dimension without a name.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.name() {
            Some(n) if *self == Self::DIMENSIONLESS => f.write_str(n),
            Some(n) => write!(f, "{n} ({})", self.si_symbol()),
            None => write!(f, "{}", self.si_symbol()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_and_si_symbols() {
        assert_eq!(Dimension::VELOCITY.to_string(), "velocity (m/s)");
        assert_eq!(Dimension::MOMENT_OF_INERTIA.to_string(), "moment of inertia (kg*m^2)");
        assert_eq!(Dimension::FREQUENCY.si_symbol(), "1/s");
        assert_eq!(Dimension::ROTATIONAL_DAMPING.si_symbol(), "kg*m^2/s/rad");
        assert_eq!(Dimension::new(1, 3, -1, 0).to_string(), "kg*m^3/s");
        assert_eq!(Dimension::DIMENSIONLESS.to_string(), "dimensionless");
    }

    #[test]
    fn every_named_dimension_is_named_once() {
        for (i, (d, _)) in Dimension::NAMED.iter().enumerate() {
            assert!(Dimension::NAMED.iter().skip(i + 1).all(|(e, _)| e != d), "{d:?}");
        }
    }

    #[test]
    fn arithmetic_is_bounded() {
        assert_eq!(Dimension::FORCE.checked_mul(&Dimension::LENGTH), Some(Dimension::MOMENT));
        assert_eq!(Dimension::MOMENT.checked_div(&Dimension::ANGLE), Some(Dimension::ROTATIONAL_STIFFNESS));
        assert_eq!(Dimension::LENGTH.checked_pow(17), None);
    }
}
