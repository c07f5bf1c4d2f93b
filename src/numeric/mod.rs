//! Numerical building blocks over the generic scalars: dense linear algebra, polynomials in
//! Bernstein and power form (with binomial tables), quaternions, quadrature rules, and proven maxima by branch and bound.

pub mod krawczyk;
pub mod linalg;
pub mod maximum;
pub mod poly;
pub mod quadrature;
pub mod quat;
