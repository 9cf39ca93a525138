//! Typed physical vectors: a kernel [`Vector`] tagged with its kind (book §1.6).

use core::fmt;
use core::marker::PhantomData;
use core::ops::{Add, AddAssign, Div, Mul, Neg, Sub, SubAssign};

use nalgebra::Matrix3;
use vectrix_frames::{Frame, Resolve};
use vectrix_statics::{MassProperties, Point, StaticsError};
use vectrix_tensor::Vector;
use vectrix_units::kind::{
    Acceleration, AngularAcceleration, AngularMomentum, AngularVelocity, Force, Length, Mass, Moment,
    MomentOfInertia, Momentum, Velocity,
};
use vectrix_units::{Kind, Measure, Unit, UnitError, UnitSystem};

/// A physical vector of kind `K` (position, velocity, force, moment, angular velocity, …):
/// frame-free like [`Vector`], with SI components inside and its kind in the type.
///
/// Numbers enter through a frame with units ([`Physical::new`] from [`Measure`]s or, with the
/// `uom` feature, `uom` quantities; [`Physical::parse`] from quantity strings;
/// [`Physical::in_unit`]) and leave through a frame with units ([`Physical::resolve`] typed,
/// [`Physical::resolve_in`] in a named unit). [`Physical::si`] hands the kernel its `Vector`
/// for free. Sums keep the kind; the book's products change it by type: r⃗ × f⃗ is a moment,
/// ω⃗ × r⃗ a velocity, m v⃗ a momentum ([`CrossKind`]).
///
/// Book: §1.6 (the kinds of physical vectors), §1.5 (resolution), (2.4.15).
///
/// # Conventions
/// `#[repr(transparent)]` over [`Vector`]: no cost over the untyped vector.
#[derive(Clone, Copy, PartialEq)]
#[repr(transparent)]
pub struct Physical<K: Kind> {
    v: Vector,
    kind: PhantomData<K>,
}

impl<K: Kind> Physical<K> {
    /// The vector whose components in `frame` are these measures: x⃗ = F_A x|_A (2.4.15).
    ///
    /// Book: (2.4.15), §1.6.
    #[inline]
    pub fn new<M: Into<Measure<K>>>(frame: &Frame, components: [M; 3]) -> Self {
        Self::from_si(frame.vector(components.map(|c| c.into().si())))
    }

    /// Components given in one unit (`[1.0, 0.0, -2.0]` in `"ft/s"`), converted exactly.
    ///
    /// Book: (2.4.15), §15.19.
    ///
    /// # Errors
    /// Parse errors of the unit; [`UnitError::DimensionMismatch`] when the unit is not of
    /// this kind; [`UnitError::NonFinite`], [`UnitError::Overflow`], [`UnitError::Underflow`]
    /// from a component's conversion.
    pub fn in_unit(frame: &Frame, components: [f64; 3], unit: &str) -> Result<Self, UnitError> {
        let u = Unit::parse(unit)?;
        let [x, y, z] = components;
        Ok(Self::new(frame, [Measure::in_unit(x, &u)?, Measure::in_unit(y, &u)?, Measure::in_unit(z, &u)?]))
    }

    /// Components as quantity strings (`["0 ft/s^2", "-32.174 ft/s^2", "0 m/s^2"]`), each
    /// checked against this kind's dimension and converted exactly.
    ///
    /// Book: (2.4.15), §15.19.
    ///
    /// # Errors
    /// As [`Measure::parse`], for the first component that fails.
    pub fn parse(frame: &Frame, components: [&str; 3]) -> Result<Self, UnitError> {
        let [x, y, z] = components;
        Ok(Self::new(frame, [Measure::<K>::parse(x)?, Measure::parse(y)?, Measure::parse(z)?]))
    }

    /// Tags a kernel vector holding SI values with this kind.
    #[inline]
    pub const fn from_si(v: Vector) -> Self {
        Self { v, kind: PhantomData }
    }

    /// The kernel vector, in SI (free).
    #[inline]
    pub const fn si(&self) -> Vector {
        self.v
    }

    /// The zero vector of this kind.
    #[inline]
    pub fn zero() -> Self {
        Self::from_si(Vector::zero())
    }

    /// x⃗|_A with typed components (1.5.1).
    ///
    /// Book: (1.5.1), (2.4.14).
    #[inline]
    pub fn resolve(&self, frame: &Frame) -> [Measure<K>; 3] {
        let c = self.v.resolve(frame);
        [c[0], c[1], c[2]].map(Measure::from_si)
    }

    /// x⃗|_A in a named unit of this kind (`"ft/s"`), each component rounded once.
    ///
    /// Book: (1.5.1), §15.19.
    ///
    /// # Errors
    /// Parse errors of the unit, [`UnitError::DimensionMismatch`] for a unit of another
    /// dimension, [`UnitError::Overflow`] / [`UnitError::Underflow`], and
    /// [`UnitError::NonFinite`] for a non-finite component.
    pub fn resolve_in(&self, frame: &Frame, unit: &str) -> Result<[f64; 3], UnitError> {
        let u = Unit::parse(unit)?;
        let [x, y, z] = self.resolve(frame);
        Ok([x.value_in_unit(&u)?, y.value_in_unit(&u)?, z.value_in_unit(&u)?])
    }

    /// x⃗|_A in the unit a [`UnitSystem`] uses for this kind.
    ///
    /// # Errors
    /// As [`Physical::resolve_in`], without parse errors.
    pub fn resolve_in_system(&self, frame: &Frame, system: UnitSystem) -> Result<[f64; 3], UnitError> {
        let [x, y, z] = self.resolve(frame);
        Ok([x.value_in_system(system)?, y.value_in_system(system)?, z.value_in_system(system)?])
    }

    /// |x⃗|.
    ///
    /// Book: §1.6.
    #[inline]
    pub fn magnitude(&self) -> Measure<K> {
        Measure::from_si(self.v.norm())
    }

    /// The component along the unit vector n̂, x⃗·n̂ (the book's "along n̂" or "around n̂").
    ///
    /// Book: §1.6 (projection onto a direction).
    #[inline]
    pub fn along(&self, n_hat: &Vector) -> Measure<K> {
        Measure::from_si(self.v.dot(n_hat))
    }

    /// x⃗ × y⃗ with the kind the book gives the product ([`CrossKind`]).
    ///
    /// Book: §1.6; r⃗ × f⃗ (§6.3), ω⃗ × r⃗ (§4.8), r⃗ × p⃗ (§7).
    #[inline]
    pub fn cross<R: Kind>(&self, rhs: &Physical<R>) -> Physical<<K as CrossKind<R>>::Output>
    where
        K: CrossKind<R>,
    {
        Physical::from_si(self.v.cross(&rhs.v))
    }
}

/// The kind of a cross product x⃗ × y⃗ of two kinds, as the book forms them.
///
/// * position × force → moment, M⃗ = r⃗ × f⃗ (§6.3)
/// * position × momentum → angular momentum, H⃗ = r⃗ × p⃗ (§7.3)
/// * angular velocity × position → velocity, ω⃗ × r⃗ (transport theorem, §4.8)
/// * angular velocity × velocity → acceleration, ω⃗ × v⃗ (§4.9)
/// * angular acceleration × position → acceleration, α⃗ × r⃗ (§4.9)
///
/// Book: §1.6, §4.8–4.9, §6.3, §7.3.
pub trait CrossKind<R: Kind>: Kind {
    /// The product's kind.
    type Output: Kind;
}

impl CrossKind<Force> for Length {
    type Output = Moment;
}

impl CrossKind<Momentum> for Length {
    type Output = AngularMomentum;
}

impl CrossKind<Length> for AngularVelocity {
    type Output = Velocity;
}

impl CrossKind<Velocity> for AngularVelocity {
    type Output = Acceleration;
}

impl CrossKind<Length> for AngularAcceleration {
    type Output = Acceleration;
}

impl<K: Kind> fmt::Debug for Physical<K> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Physical<{}>({:?} [{}])", K::NAME, self.v, UnitSystem::Si.label(K::DIMENSION))
    }
}

impl<K: Kind> Add for Physical<K> {
    type Output = Self;
    #[inline]
    fn add(self, rhs: Self) -> Self {
        Self::from_si(self.v + rhs.v)
    }
}

impl<K: Kind> Sub for Physical<K> {
    type Output = Self;
    #[inline]
    fn sub(self, rhs: Self) -> Self {
        Self::from_si(self.v - rhs.v)
    }
}

impl<K: Kind> AddAssign for Physical<K> {
    #[inline]
    fn add_assign(&mut self, rhs: Self) {
        self.v += rhs.v;
    }
}

impl<K: Kind> SubAssign for Physical<K> {
    #[inline]
    fn sub_assign(&mut self, rhs: Self) {
        self.v -= rhs.v;
    }
}

impl<K: Kind> Neg for Physical<K> {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        Self::from_si(-self.v)
    }
}

impl<K: Kind> Mul<f64> for Physical<K> {
    type Output = Self;
    #[inline]
    fn mul(self, k: f64) -> Self {
        Self::from_si(self.v * k)
    }
}

impl<K: Kind> Div<f64> for Physical<K> {
    type Output = Self;
    #[inline]
    fn div(self, k: f64) -> Self {
        Self::from_si(self.v / k)
    }
}

/// p⃗ = m v⃗ (§7.2).
impl Mul<Physical<Velocity>> for Measure<Mass> {
    type Output = Physical<Momentum>;
    #[inline]
    fn mul(self, v: Physical<Velocity>) -> Physical<Momentum> {
        Physical::from_si(v.v * self.si())
    }
}

/// f⃗ = m a⃗, Newton's second law (§7.2).
impl Mul<Physical<Acceleration>> for Measure<Mass> {
    type Output = Physical<Force>;
    #[inline]
    fn mul(self, a: Physical<Acceleration>) -> Physical<Force> {
        Physical::from_si(a.v * self.si())
    }
}

/// Tags a kernel [`Vector`] (in SI) with a kind: `omega.as_physical::<AngularVelocity>()`,
/// for typed reads of kernel results.
///
/// Book: §1.6.
pub trait AsPhysical {
    /// The same vector as a [`Physical<K>`] (free).
    fn as_physical<K: Kind>(&self) -> Physical<K>;
}

impl AsPhysical for Vector {
    #[inline]
    fn as_physical<K: Kind>(&self) -> Physical<K> {
        Physical::from_si(*self)
    }
}

/// Mass properties from typed values: mass m_B, centre of mass c (its position r⃗_{c/o}) and
/// J⃗_{B/c} resolved in `frame` (matrix entries as they stand, so the off-diagonal entries are
/// the book's −J_xy, −J_xz, −J_yz), validated like [`MassProperties::new`].
///
/// Book: §6.1–6.2, (6.2.1)–(6.2.3).
///
/// # Errors
/// As [`MassProperties::new`]: non-finite, negative or zero mass, non-finite centre, and an
/// inertia that is not symmetric, not positive semidefinite, or violates λ₁ ≤ λ₂ + λ₃.
pub fn mass_properties(
    frame: &Frame,
    mass: Measure<Mass>,
    centre: Physical<Length>,
    j_c: [[Measure<MomentOfInertia>; 3]; 3],
) -> Result<MassProperties, StaticsError> {
    let m = Matrix3::from_fn(|r, c| j_c[r][c].si());
    MassProperties::new(mass.si(), Point::at(centre.si()), frame.dyadic(&m))
}

/// Mass properties with J⃗_{B/c} diagonal in `frame` (principal axes): J_xx, J_yy, J_zz.
///
/// Book: §6.2, §6.5 (principal axes).
///
/// # Errors
/// As [`mass_properties`].
pub fn principal_mass_properties(
    frame: &Frame,
    mass: Measure<Mass>,
    centre: Physical<Length>,
    principal: [Measure<MomentOfInertia>; 3],
) -> Result<MassProperties, StaticsError> {
    let z = Measure::from_si(0.0);
    let [a, b, c] = principal;
    mass_properties(frame, mass, centre, [[a, z, z], [z, b, z], [z, z, c]])
}

/// Typed reads of [`MassProperties`].
///
/// Book: §6.1–6.2.
pub trait TypedMassProperties {
    /// m_B.
    fn mass_measure(&self) -> Measure<Mass>;
    /// r⃗_{c/o}, the centre of mass relative to the problem's reference point.
    fn centre_position(&self) -> Physical<Length>;
    /// J⃗_{B/c} resolved in `frame`, entry by entry.
    fn inertia_resolved(&self, frame: &Frame) -> [[Measure<MomentOfInertia>; 3]; 3];
}

impl TypedMassProperties for MassProperties {
    fn mass_measure(&self) -> Measure<Mass> {
        Measure::from_si(self.mass())
    }

    fn centre_position(&self) -> Physical<Length> {
        Physical::from_si(self.centre_of_mass().position())
    }

    fn inertia_resolved(&self, frame: &Frame) -> [[Measure<MomentOfInertia>; 3]; 3] {
        let j = self.inertia_about_centre().resolve(frame);
        [0, 1, 2].map(|r| [0, 1, 2].map(|c| Measure::from_si(j[(r, c)])))
    }
}
