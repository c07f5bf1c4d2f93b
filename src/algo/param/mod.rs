//! Optimal data parametrization for parametric cubic spline interpolation (paper 004, Marin).
//!
//! - [`natural`]: natural cubic spline interpolation on any knots, with ∫θ″².
//! - [`natural_exact`]: the same spline in exact rationals by fraction-free elimination (one
//!   common denominator, one reduction per printed number).
//! - [`objective`]: the smoothness objective G(h) in its exact (Eq. 31) and approximate
//!   (Eq. 34) algebraic forms.
//! - [`one_d`]: the exact minimizing parametrization of scalar data, cases I–III (Sec. 2).
//!
//! - [`gradient`]: ∇G and its projection onto the simplex Σhᵢ = 1.
//! - [`proven`]: the minimizer of G proven in balls (Krawczyk, and a positive definite Hessian).
//! - [`descent`]: the minimization of G for K ≥ 1 components: gradient projection (Eq. 30)
//!   in f64, then Newton's method at any precision (`descend`, `polish`).
//!
//! A natural cubic spline through (0, 0), (1, 1), (2, 0), exactly and in f64: its second
//! derivative at the middle knot is −3 (the tridiagonal system 4M₁ = 6(−1 − 1)).
//!
//! ```
//! use trajverify::algo::param::natural::NaturalCubicSpline;
//! use trajverify::scalar::BigRational;
//!
//! let q = |n: i64| BigRational::from_integer(n.into());
//! let exact = NaturalCubicSpline::new(vec![q(0), q(1), q(2)], vec![q(0), q(1), q(0)]).unwrap();
//! assert_eq!(exact.eval_all(&q(1)), [q(1), q(0), q(-3)]);
//! let fast = NaturalCubicSpline::new(vec![0.0, 1.0, 2.0], vec![0.0, 1.0, 0.0]).unwrap();
//! assert!((fast.eval_all(&1.0)[2] + 3.0).abs() < 1e-14);
//! ```

pub mod descent;
pub mod gradient;
pub mod natural;
pub mod natural_exact;
pub mod objective;
pub mod one_d;
pub mod proven;
