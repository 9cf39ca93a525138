//! The `f64` kernels of the rotation layer, chosen by type through [`vectrix_tensor::Scalar`]'s
//! fast path (never by a test when the program runs): one module per computation, each tested
//! against the generic code it stands for. The one-value fast paths (sine, cosine, atan2, the
//! series of the exponential map) are `Scalar`'s own hooks; `tests` holds every public
//! conversion that takes them to the generic code on the hard sets.

pub(crate) mod log;
#[cfg(test)]
mod tests;
