//! Optimal data parametrization for parametric cubic spline interpolation (paper 004, Marin).
//!
//! - [`natural`]: natural cubic spline interpolation on any knots, with ∫θ″².
//! - [`objective`]: the smoothness objective G(h) in its exact (Eq. 31) and approximate
//!   (Eq. 34) algebraic forms.
//! - [`one_d`]: the exact minimizing parametrization of scalar data, cases I–III (Sec. 2).
//!
//! Not yet here (issue 5 continues): the gradient of G, gradient projection (Eq. 30) for K > 1,
//! and the experiments of Tables II–VII.

pub mod descent;
pub mod gradient;
pub mod natural;
pub mod objective;
pub mod one_d;
