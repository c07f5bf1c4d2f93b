//! The algorithms of the five papers, each written once over [`Field`](crate::scalar::Field)
//! or [`Real`](crate::scalar::Real); none uses another.
//!
//! - [`hermite`]: two-point Hermite data → Bernstein control points (paper 000).
//! - [`ph`]: Pythagorean-hodograph curves, moving frames, PHODCOS conversion (paper 001).
//! - [`bspline`]: cardinal B-splines, optimal interpolating/smoothing splines, bang-bang control (paper 002).
//! - [`gerbs`]: GERBS blending, BFBS/ERBS bases, curvature-continuous UAV paths, Dubins (paper 003).
//! - [`param`]: natural cubic splines and the optimal knot parametrization of Marin (paper 004).
//!
//! Built on them: [`convergence`], convergence studies of the PHODCOS and Hermite methods on
//! any curve (the one module here that uses other algorithms).

pub mod bspline;
pub mod convergence;
pub mod gerbs;
pub mod hermite;
pub mod param;
pub mod ph;
