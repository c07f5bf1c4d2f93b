//! Numerical building blocks over the generic scalars: dense linear algebra, polynomials in
//! Bernstein and power form (with binomial tables), quaternions, and quadrature rules.

pub mod krawczyk;
pub mod linalg;
pub mod poly;
pub mod quadrature;
pub mod quat;
