//! B-splines and control theory (paper 002, Kano, Egerstedt, Nakata & Martin).
//!
//! - [`cardinal`]: the cardinal B-spline B_k as exact piecewise polynomials (Algorithm 1,
//!   Eq. 1), with an independent Cox–de Boor construction.
//! - [`gram`]: the Gram matrix of k-th derivatives (Sec. 5) by exact integration, its closed
//!   form ĝₘ = (−1)ᵐ C(2k, k+m), and an exact LDLᵀ test of positive definiteness.
//! - [`fit`]: splines S(t) = Σ τᵢ B_k(t − i + 1) (Eqs. 2, 16), the collocation matrix, and the
//!   optimal interpolating (Eq. 14) and smoothing (Eq. 15) control points.
//! - [`bang_bang`]: the minimum-L∞ control of Sec. 4: switching times and amplitude, and the
//!   trajectory it drives.
//! - [`dual`]: the dual certificate of Sec. 4.1 that proves the bang-bang control optimal.
//!
//! One algorithm, three number types: the Gram entries of B₃‴ (Sec. 5), exact in rationals,
//! and the same generic code in f64 and MPFR.
//!
//! ```
//! use trajverify::algo::bspline::gram::gram_entries;
//! use trajverify::scalar::{BigRational, Float};
//!
//! let exact: Vec<BigRational> = gram_entries(3, &());
//! assert_eq!(exact, [20, -15, 6, -1].map(|v| BigRational::from_integer(v.into())));
//! let fast: Vec<f64> = gram_entries(3, &());
//! assert!((fast[1] + 15.0).abs() < 1e-12);
//! let precise: Vec<Float> = gram_entries(3, &200);
//! assert!((precise[2].clone() - 6u32).abs() < 1e-50);
//! ```

pub mod bang_bang;
pub mod cardinal;
pub mod dual;
pub mod fit;
pub mod gram;

pub use cardinal::CardinalBSpline;
