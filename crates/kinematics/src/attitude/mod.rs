//! Attitude rate equations (book §4.7–4.12) and attitude propagation.
//!
//! Every representation has a body form (ω_{B/A} resolved in B, the book's ω_B) and a spatial
//! form (resolved in A), each with its inverse. The representations themselves are the
//! rotation crate's: [`vectrix_rotation::EulerAngles`], [`vectrix_rotation::Quaternion`], and
//! `nalgebra::Vector3` for angle vectors, Gibbs vectors and MRPs.

mod angle_vector;
mod eigenaxis;
mod euler;
mod gibbs;
mod mrp;
mod propagate;
mod quaternion;

pub use angle_vector::{
    angle_vector_rate_body, angle_vector_rate_spatial, jacobian_left, jacobian_left_inverse, jacobian_right,
    jacobian_right_inverse, rewrap_angle_vector,
};
pub use eigenaxis::{
    alpha_spatial_from_eigenaxis_rates, eigenaxis_rates_from_omega_body, eigenaxis_rates_from_omega_spatial,
    omega_body_from_eigenaxis_rates, omega_spatial_from_eigenaxis_rates,
};
pub use euler::{
    euler_rate_matrix_body, euler_rate_matrix_spatial, euler_rates_from_omega_body,
    euler_rates_from_omega_spatial, omega_body_from_euler_rates, omega_spatial_from_euler_rates,
};
pub use gibbs::{
    gibbs_rate_body, gibbs_rate_spatial, omega_body_from_gibbs_rate, omega_spatial_from_gibbs_rate,
};
pub use mrp::{mrp_rate_body, mrp_rate_spatial, omega_body_from_mrp_rate, omega_spatial_from_mrp_rate};
pub use propagate::{GIBBS_LIMIT, Propagator, propagate_attitude};
pub use quaternion::{
    omega_body_from_quaternion_rate, omega_spatial_from_quaternion_rate, quaternion_rate_body,
    quaternion_rate_matrix, quaternion_rate_spatial,
};
