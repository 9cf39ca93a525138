//! The `f64` kernels of the kernel crate, chosen by [`crate::Scalar::fast_path`]: one module per
//! computation, each tested against the generic code it stands for.

pub(crate) mod hooke;
