//! Forces, moments, wrenches and the laws of statics (book §6.4–6.5).

use vectrix_tensor::{Scalar, Vector};

use crate::Point;

/// A force f⃗_y applied at the inertia point y.
///
/// Book: §6.4.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AppliedForce<T: Scalar = f64> {
    /// f⃗_y.
    pub force: Vector<T>,
    /// The point y where it acts.
    pub at: Point<T>,
}

impl<T: Scalar> AppliedForce<T> {
    /// f⃗ applied at y.
    ///
    /// Book: §6.4, (6.4.1)–(6.4.2).
    pub fn new(force: Vector<T>, at: Point<T>) -> Self {
        Self { force, at }
    }

    /// Moment relative to w: M⃗_{y/w} = r⃗_{y/w} × f⃗_y (6.4.1).
    ///
    /// Book: (6.4.1).
    pub fn moment_about(&self, w: &Point<T>) -> Vector<T> {
        self.at.position_rel(w).cross(&self.force)
    }
}

/// A wrench: the total force f⃗_B on a body and its moment M⃗_{B/w} relative to a point w.
///
/// Book: §6.4, (6.4.2), (6.4.4); the pair ℱ_{B/w} = [f⃗_B; M⃗_{B/w}] of (7.10.8).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Wrench<T: Scalar = f64> {
    /// f⃗_B = Σ f⃗_{y_i}.
    pub force: Vector<T>,
    /// M⃗_{B/w}.
    pub moment: Vector<T>,
    /// The reference point w of the moment.
    pub about: Point<T>,
}

impl<T: Scalar> Wrench<T> {
    /// The zero wrench about w.
    ///
    /// Book: §6.4, (6.4.1)–(6.4.2).
    pub fn zero(about: Point<T>) -> Self {
        Self { force: Vector::zero(), moment: Vector::zero(), about }
    }

    /// The wrench of one force f⃗ at y, about w: (f⃗, r⃗_{y/w} × f⃗) (6.4.1).
    ///
    /// Book: (6.4.1).
    pub fn from_force(f: &AppliedForce<T>, about: Point<T>) -> Self {
        Self { force: f.force, moment: f.moment_about(&about), about }
    }

    /// A pure torque (couple) M⃗: zero force, the same moment about every point (6.4.5–7).
    ///
    /// Book: §6.4, torque.
    pub fn torque(m: Vector<T>, about: Point<T>) -> Self {
        Self { force: Vector::zero(), moment: m, about }
    }

    /// The resultant of forces and couples about w: f⃗_B = Σf⃗_i, M⃗_{B/w} = Σ r⃗_{y_i/w}×f⃗_i + ΣM⃗_j
    /// (6.4.2).
    ///
    /// Book: (6.4.2).
    pub fn resultant(forces: &[AppliedForce<T>], couples: &[Vector<T>], about: Point<T>) -> Self {
        let mut w = Self::zero(about);
        for f in forces {
            w.force += f.force;
            w.moment += f.moment_about(&about);
        }
        for m in couples {
            w.moment += *m;
        }
        w
    }

    /// The same wrench with its moment about z: M⃗_{B/z} = M⃗_{B/w} + r⃗_{w/z} × f⃗_B
    /// (the transfer law (6.4.4), M⃗_{/w} = M⃗_{/z} + r⃗_{z/w} × f⃗_B, solved for M⃗_{/z}).
    ///
    /// Book: Fact 6.4.1, (6.4.4).
    pub fn shift_to(&self, z: &Point<T>) -> Self {
        Self {
            force: self.force,
            moment: self.moment + self.about.position_rel(z).cross(&self.force),
            about: *z,
        }
    }

    /// The sum of two wrenches, the second shifted to this one's point first (6.4.4).
    ///
    /// Book: (6.4.2), (6.4.4).
    pub fn plus(&self, other: &Wrench<T>) -> Self {
        let o = other.shift_to(&self.about);
        Self { force: self.force + o.force, moment: self.moment + o.moment, about: self.about }
    }

    /// The negated wrench (the third-law reaction, Fact 6.9.2–6.9.3).
    ///
    /// Book: §6.4, (6.4.1)–(6.4.2).
    pub fn reaction(&self) -> Self {
        Self { force: -self.force, moment: -self.moment, about: self.about }
    }

    /// `true` when the forces are balanced, |f⃗_B| ≤ tol (§6.4).
    ///
    /// Book: §6.4, (6.4.1)–(6.4.2).
    pub fn is_balanced(&self, tol: f64) -> bool {
        self.force.norm().re() <= tol
    }

    /// The torque M⃗_B of balanced forces, the same about every point (6.4.5–7); `None` when
    /// |f⃗_B| > tol (then the moment depends on the point).
    ///
    /// Book: Fact 6.4.3, §6.4 (torque).
    pub fn as_torque(&self, tol: f64) -> Option<Vector<T>> {
        self.is_balanced(tol).then_some(self.moment)
    }

    /// Fact 6.4.4: adding −f⃗_B at a point z on the line through w parallel to f⃗_B balances the
    /// forces and leaves the moment unchanged, so M⃗_{B/w} becomes a torque. Returns that
    /// torque together with the compensating force; `z` must satisfy r⃗_{z/w} ∥ f⃗_B.
    ///
    /// Book: Fact 6.4.4.
    pub fn compensated_torque(&self, z: &Point<T>) -> (Vector<T>, AppliedForce<T>) {
        let comp = AppliedForce::new(-self.force, *z);
        (self.moment + comp.moment_about(&self.about), comp)
    }

    /// Equilibrium residual: the laws of statics f⃗_B = 0⃗ and M⃗_{B/w} = 0⃗ (§6.5) hold iff both
    /// returned magnitudes vanish. Returns (|f⃗_B|, |M⃗_{B/w}|).
    ///
    /// Book: §6.5.
    pub fn equilibrium_residual(&self) -> (T, T) {
        (self.force.norm(), self.moment.norm())
    }

    /// The laws of statics (§6.5): |f⃗_B| ≤ force_tol and |M⃗_{B/w}| ≤ moment_tol. When the
    /// forces balance, the moment is the same about every point, so the choice of w is free.
    ///
    /// Book: §6.5.
    pub fn is_in_equilibrium(&self, force_tol: f64, moment_tol: f64) -> bool {
        let (f, m) = self.equilibrium_residual();
        f.re() <= force_tol && m.re() <= moment_tol
    }
}
