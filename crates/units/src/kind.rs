//! Compile-time kinds for typed values: the book's kinds of physical vectors and the scalars
//! around them.
//!
//! A kind is a zero-sized marker ([`Force`], [`Velocity`], …) carrying its [`Dimension`].
//! [`Measure<K>`] is an `f64` in SI tagged with a kind, so a force cannot be passed where a
//! length is expected, while unit names are checked at run time against the kind's dimension
//! (`Measure::<Force>::new(2.0, "lbf")`). With the `uom` feature, `uom`'s SI quantities convert
//! to and from measures of the matching kind, with units checked at compile time.
//!
//! Book: §1.6 (the thirteen kinds of physical vectors), §15.19.

use core::fmt;
use core::marker::PhantomData;
use core::ops::{Add, AddAssign, Div, Mul, Neg, Sub, SubAssign};

use serde::{Deserialize, Deserializer, de};

use crate::{Dimension, Number, Quantity, Unit, UnitError, UnitSystem};

/// A kind of physical quantity: a marker type with a dimension and a name.
///
/// Book: §1.6, §15.19.
pub trait Kind: Copy + Default + fmt::Debug + PartialEq + Send + Sync + 'static {
    /// The dimension every value of this kind has.
    const DIMENSION: Dimension;
    /// The name in messages.
    const NAME: &'static str;
}

/// Kind: a dimensionless quantity; its vectors include the axes of a frame and unit vectors.
///
/// Book: §1.6 (i).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
pub struct Dimensionless;

impl Kind for Dimensionless {
    const DIMENSION: Dimension = Dimension::DIMENSIONLESS;
    const NAME: &'static str = "dimensionless";
}

/// Kind: a plane angle, rad; its vectors are angle vectors θ⃗_{y⃗/x⃗}.
///
/// Book: §1.6 (iii).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
pub struct Angle;

impl Kind for Angle {
    const DIMENSION: Dimension = Dimension::ANGLE;
    const NAME: &'static str = "angle";
}

/// Kind: a length, m; its vectors are positions r⃗_{y/x}.
///
/// Book: §1.6 (iv).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
pub struct Length;

impl Kind for Length {
    const DIMENSION: Dimension = Dimension::LENGTH;
    const NAME: &'static str = "length";
}

/// Kind: a velocity, m/s, as v⃗_{y/x/A}.
///
/// Book: §1.6 (v).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
pub struct Velocity;

impl Kind for Velocity {
    const DIMENSION: Dimension = Dimension::VELOCITY;
    const NAME: &'static str = "velocity";
}

/// Kind: an acceleration, m/s², as a⃗_{y/x/A}.
///
/// Book: §1.6 (vi).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
pub struct Acceleration;

impl Kind for Acceleration {
    const DIMENSION: Dimension = Dimension::ACCELERATION;
    const NAME: &'static str = "acceleration";
}

/// Kind: a momentum or an impulse, kg·m/s = N·s, as p⃗_{y/x/A} (15.19.4).
///
/// Book: §1.6 (vii), (15.19.4).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
pub struct Momentum;

impl Kind for Momentum {
    const DIMENSION: Dimension = Dimension::MOMENTUM;
    const NAME: &'static str = "momentum";
}

/// Kind: a force, N = kg·m/s² (15.19.1).
///
/// Book: §1.6 (viii), (15.19.1).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
pub struct Force;

impl Kind for Force {
    const DIMENSION: Dimension = Dimension::FORCE;
    const NAME: &'static str = "force";
}

/// Kind: an angular velocity, rad/s, as ω⃗_{B/A}.
///
/// Book: §1.6 (ix).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
pub struct AngularVelocity;

impl Kind for AngularVelocity {
    const DIMENSION: Dimension = Dimension::ANGULAR_VELOCITY;
    const NAME: &'static str = "angular velocity";
}

/// Kind: an angular acceleration, rad/s², as α⃗_{B/A/C}.
///
/// Book: §1.6 (x).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
pub struct AngularAcceleration;

impl Kind for AngularAcceleration {
    const DIMENSION: Dimension = Dimension::ANGULAR_ACCELERATION;
    const NAME: &'static str = "angular acceleration";
}

/// Kind: an angular momentum, kg·m²/s, as H⃗_{B/w/A}.
///
/// Book: §1.6 (xi).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
pub struct AngularMomentum;

impl Kind for AngularMomentum {
    const DIMENSION: Dimension = Dimension::ANGULAR_MOMENTUM;
    const NAME: &'static str = "angular momentum";
}

/// Kind: a moment or torque, N·m, as M⃗_{B/y} and the torque M⃗_B (the book's two kinds share this dimension).
///
/// Book: §1.6 (xii), (xiii).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
pub struct Moment;

impl Kind for Moment {
    const DIMENSION: Dimension = Dimension::MOMENT;
    const NAME: &'static str = "moment";
}

/// Kind: a mass, kg (1 slug = 14.59 kg, (15.19.2)).
///
/// Book: §6.1, (15.19.2).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
pub struct Mass;

impl Kind for Mass {
    const DIMENSION: Dimension = Dimension::MASS;
    const NAME: &'static str = "mass";
}

/// Kind: a moment or product of inertia, kg·m², an entry of J⃗_{B/z} resolved in a frame.
///
/// Book: §6.2.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
pub struct MomentOfInertia;

impl Kind for MomentOfInertia {
    const DIMENSION: Dimension = Dimension::MOMENT_OF_INERTIA;
    const NAME: &'static str = "moment of inertia";
}

/// Kind: a time, s.
///
/// Book: §15.19.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
pub struct Time;

impl Kind for Time {
    const DIMENSION: Dimension = Dimension::TIME;
    const NAME: &'static str = "time";
}

/// Kind: an energy or work, J.
///
/// Book: §8.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
pub struct Energy;

impl Kind for Energy {
    const DIMENSION: Dimension = Dimension::ENERGY;
    const NAME: &'static str = "energy";
}

/// A value of kind `K`, stored in SI: the typed scalar of the units layer.
///
/// Construct it from SI ([`Measure::from_si`], free), from a value and a unit checked against
/// the kind ([`Measure::new`]), from a quantity string ([`Measure::parse`]), or (feature
/// `uom`) from the matching `uom` quantity with `.into()`. Read it in SI ([`Measure::si`], free)
/// or in any unit of its dimension ([`Measure::value_in`]). Sums, differences and real
/// multiples keep the kind; the ratio of two measures of one kind is a plain `f64`.
///
/// Book: §1.6, §15.19.
///
/// # Conventions
/// `#[repr(transparent)]` over `f64`: a `Measure` costs what its `f64` costs.
#[derive(Clone, Copy, PartialEq, PartialOrd, Default)]
#[repr(transparent)]
pub struct Measure<K: Kind> {
    si: f64,
    kind: PhantomData<K>,
}

impl<K: Kind> Measure<K> {
    /// A value already in SI (m, kg, s, rad and coherent products).
    ///
    /// Book: §15.19.
    #[inline]
    pub const fn from_si(si: f64) -> Self {
        Self { si, kind: PhantomData }
    }

    /// The value in SI.
    #[inline]
    pub const fn si(self) -> f64 {
        self.si
    }

    /// `value` in `unit` (a unit expression such as `"lbf"`, `"slug*ft^2"`), converted to SI
    /// with one rounding.
    ///
    /// Book: §15.19.
    ///
    /// # Errors
    /// Parse errors of [`Unit::parse`]; [`UnitError::DimensionMismatch`] when the unit is not
    /// of this kind's dimension; [`UnitError::NonFinite`], [`UnitError::Overflow`],
    /// [`UnitError::Underflow`] from the conversion.
    pub fn new(value: f64, unit: &str) -> Result<Self, UnitError> {
        Self::in_unit(value, &Unit::parse(unit)?)
    }

    /// `value` in a parsed unit, converted to SI with one rounding.
    ///
    /// # Errors
    /// As [`Measure::new`], without parse errors.
    pub fn in_unit(value: f64, unit: &Unit) -> Result<Self, UnitError> {
        unit.convert(value, &Unit::si(K::DIMENSION)).map(Self::from_si)
    }

    /// A quantity string of this kind's dimension (`"32.174 ft/s^2"`), converted exactly.
    ///
    /// # Errors
    /// As [`Quantity::parse`] and [`Quantity::to_si`].
    pub fn parse(text: &str) -> Result<Self, UnitError> {
        Quantity::parse(text)?.to_si(K::DIMENSION).map(Self::from_si)
    }

    /// The value in `unit`, rounded once.
    ///
    /// Book: §15.19.
    ///
    /// # Errors
    /// As [`Measure::new`].
    pub fn value_in(self, unit: &str) -> Result<f64, UnitError> {
        self.value_in_unit(&Unit::parse(unit)?)
    }

    /// The value in a parsed unit, rounded once.
    ///
    /// # Errors
    /// As [`Measure::in_unit`].
    pub fn value_in_unit(self, unit: &Unit) -> Result<f64, UnitError> {
        Unit::si(K::DIMENSION).convert(self.si, unit)
    }

    /// The value in the unit a [`UnitSystem`] uses for this kind.
    ///
    /// # Errors
    /// As [`Measure::in_unit`].
    pub fn value_in_system(self, system: UnitSystem) -> Result<f64, UnitError> {
        system.value_from_si(K::DIMENSION, self.si)
    }

    /// |self|.
    #[inline]
    pub fn abs(self) -> Self {
        Self::from_si(self.si.abs())
    }
}

impl<K: Kind> fmt::Debug for Measure<K> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Measure<{}>({:?} {})", K::NAME, self.si, UnitSystem::Si.label(K::DIMENSION))
    }
}

impl<K: Kind> fmt::Display for Measure<K> {
    /// The SI value and its unit, `3.5 m/s`; precision flags apply to the number.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(&self.si, f)?;
        let label = UnitSystem::Si.label(K::DIMENSION);
        if label != "1" { write!(f, " {label}") } else { Ok(()) }
    }
}

impl<K: Kind> Add for Measure<K> {
    type Output = Self;
    #[inline]
    fn add(self, rhs: Self) -> Self {
        Self::from_si(self.si + rhs.si)
    }
}

impl<K: Kind> Sub for Measure<K> {
    type Output = Self;
    #[inline]
    fn sub(self, rhs: Self) -> Self {
        Self::from_si(self.si - rhs.si)
    }
}

impl<K: Kind> AddAssign for Measure<K> {
    #[inline]
    fn add_assign(&mut self, rhs: Self) {
        self.si += rhs.si;
    }
}

impl<K: Kind> SubAssign for Measure<K> {
    #[inline]
    fn sub_assign(&mut self, rhs: Self) {
        self.si -= rhs.si;
    }
}

impl<K: Kind> Neg for Measure<K> {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        Self::from_si(-self.si)
    }
}

impl<K: Kind> Mul<f64> for Measure<K> {
    type Output = Self;
    #[inline]
    fn mul(self, k: f64) -> Self {
        Self::from_si(self.si * k)
    }
}

impl<K: Kind> Mul<Measure<K>> for f64 {
    type Output = Measure<K>;
    #[inline]
    fn mul(self, m: Measure<K>) -> Measure<K> {
        Measure::from_si(self * m.si)
    }
}

impl<K: Kind> Div<f64> for Measure<K> {
    type Output = Self;
    #[inline]
    fn div(self, k: f64) -> Self {
        Self::from_si(self.si / k)
    }
}

impl<K: Kind> Div for Measure<K> {
    type Output = f64;
    /// The ratio of two values of one kind, dimensionless.
    #[inline]
    fn div(self, rhs: Self) -> f64 {
        self.si / rhs.si
    }
}

impl<'de, K: Kind> Deserialize<'de> for Measure<K> {
    /// From a bare number (SI) or a quantity string of this kind's dimension; a wrong unit
    /// is a deserialization error carrying the [`UnitError`] message (a TOML deserializer adds
    /// the value's line and column).
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let n = Number::deserialize(d)?;
        n.to_si(K::DIMENSION).map(Self::from_si).map_err(de::Error::custom)
    }
}
