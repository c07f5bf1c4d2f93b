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

pub mod bang_bang;
pub mod cardinal;
pub mod fit;
pub mod gram;

pub use cardinal::CardinalBSpline;
