//! Conversions between [`Measure`] kinds and the `uom` crate's SI quantities (feature `uom`).
//!
//! `uom` checks units at compile time (`Force::new::<pound_force>(2.0)`); its `f64`
//! quantities store the SI base value, so the conversion to and from a [`Measure`] of the
//! matching kind moves that value unchanged. Pairs: Length, Mass, Time, Angle, Velocity,
//! Acceleration, Momentum, Force, AngularVelocity, AngularAcceleration, AngularMomentum,
//! Torque ↔ Moment, MomentOfInertia, Energy, Ratio ↔ Dimensionless.
//!
//! Book: §15.19.

use uom::si::f64 as q;

use crate::Measure;
use crate::kind as k;

/// `From` both ways between `Measure<kind>` and a `uom` quantity whose base unit is the SI
/// unit of the kind (so the stored value is the same number).
macro_rules! uom_pair {
    ($kind:ty, $uom:ty, $unit:ty) => {
        impl From<$uom> for Measure<$kind> {
            #[inline]
            fn from(x: $uom) -> Self {
                Measure::from_si(x.get::<$unit>())
            }
        }

        impl From<Measure<$kind>> for $uom {
            #[inline]
            fn from(m: Measure<$kind>) -> Self {
                <$uom>::new::<$unit>(m.si())
            }
        }
    };
}

uom_pair!(k::Length, q::Length, uom::si::length::meter);
uom_pair!(k::Mass, q::Mass, uom::si::mass::kilogram);
uom_pair!(k::Time, q::Time, uom::si::time::second);
uom_pair!(k::Angle, q::Angle, uom::si::angle::radian);
uom_pair!(k::Velocity, q::Velocity, uom::si::velocity::meter_per_second);
uom_pair!(k::Acceleration, q::Acceleration, uom::si::acceleration::meter_per_second_squared);
uom_pair!(k::Momentum, q::Momentum, uom::si::momentum::kilogram_meter_per_second);
uom_pair!(k::Force, q::Force, uom::si::force::newton);
uom_pair!(k::AngularVelocity, q::AngularVelocity, uom::si::angular_velocity::radian_per_second);
uom_pair!(
    k::AngularAcceleration,
    q::AngularAcceleration,
    uom::si::angular_acceleration::radian_per_second_squared
);
uom_pair!(
    k::AngularMomentum,
    q::AngularMomentum,
    uom::si::angular_momentum::kilogram_square_meter_per_second
);
uom_pair!(k::Moment, q::Torque, uom::si::torque::newton_meter);
uom_pair!(k::MomentOfInertia, q::MomentOfInertia, uom::si::moment_of_inertia::kilogram_square_meter);
uom_pair!(k::Energy, q::Energy, uom::si::energy::joule);
uom_pair!(k::Dimensionless, q::Ratio, uom::si::ratio::ratio);

#[cfg(test)]
mod tests {
    use uom::si::f64::{Force, Length, Mass, MomentOfInertia};
    use uom::si::force::pound_force;
    use uom::si::length::foot;
    use uom::si::mass::slug;

    use crate::{Measure, kind};

    // uom 0.38 prints its imperial factors to 7 significant digits (lbf = 4.448222 N,
    // lb = 0.4535924 kg, slug = 14.59390 kg), so a uom pound-force is the exact one only to
    // half a unit of that last digit; this crate's own factors are exact.
    #[test]
    fn uom_quantities_convert_to_measures() {
        let f: Measure<kind::Force> = Force::new::<pound_force>(1.0).into();
        assert_eq!(f.si(), 4.448_222);
        let exact = Measure::<kind::Force>::parse("1 lbf").unwrap().si();
        assert!((f.si() - exact).abs() <= 0.5e-6, "{} vs {exact}", f.si());
        assert!(f.si() != exact);
        let l: Measure<kind::Length> = Length::new::<foot>(3.0).into();
        assert_eq!(l.si(), 3.0 * 0.3048);
        // uom has no slug·ft² unit: build it as slug × ft × ft
        let ft = Length::new::<foot>(1.0);
        let j: MomentOfInertia = Mass::new::<slug>(1.0) * ft * ft;
        let j: Measure<kind::MomentOfInertia> = j.into();
        let exact = Measure::<kind::MomentOfInertia>::parse("1 slug*ft^2").unwrap().si();
        // 14.59390 vs 14.5939029…: half a unit of uom's 5th decimal, times ft² = 0.0929
        assert!((j.si() - exact).abs() <= 0.5e-5 * 0.3048 * 0.3048, "{} vs {exact}", j.si());
        let back: Length = l.into();
        assert_eq!(back.get::<uom::si::length::meter>(), 3.0 * 0.3048);
    }
}
