//! trajverify: the curve and trajectory algorithms of five papers, written once over the
//! number type and verified in exact rationals, MPFR and f64 side by side.
//!
//! Layers, each using only those below it (DESIGN.md; `tests/layers.rs` checks every
//! `crate::` reference against this order):
//! - [`cli`]: arguments and JSON in, JSON out, work budgets; no mathematics.
//! - [`claims`]: the published claims of each paper, each a check that calls the library.
//! - [`report`]: Markdown reports, SVG figures, `claims.json`; reads only [`ledger`] values.
//! - [`ledger`]: claim specs, outcomes, verdicts and the ledger that joins them.
//! - algorithms: [`hermite`] (paper 000), [`ph`] (paper 001), [`bspline`] (paper 002),
//!   [`gerbs`] (paper 003), [`param`] (paper 004); none uses another.
//! - building blocks: [`poly`] (Bernstein form, differences), [`quat`] (quaternions),
//!   [`curve`] (expressions, Taylor AD, fitted data), [`linalg`].
//! - [`scalar`]: the `Field` and `Real` traits over f64, MPFR and rationals.
//!
//! One algorithm, three number types: the Hermite data of the paper's Fig. 2 mapped to
//! Bernstein control points exactly, in MPFR and in f64.
//!
//! ```
//! use trajverify::hermite::HermiteData;
//! use trajverify::scalar::{BigRational, Field, Float};
//!
//! fn control_points<T: Field>(ctx: &T::Ctx) -> Vec<T> {
//!     let i = |v: i64| T::from_i64(v, ctx);
//!     let data = HermiteData::new(vec![i(0), i(0), i(0)], vec![i(1), i(1), i(0)], i(0), i(1)).unwrap();
//!     data.solve().unwrap().control_points
//! }
//!
//! let exact: Vec<BigRational> = control_points(&());
//! assert_eq!(exact[3], BigRational::new(3.into(), 5.into())); // the paper prints 0.6
//! let precise: Vec<Float> = control_points(&256);
//! assert!((precise[3].clone() - 0.6f64).abs() < 1e-16);
//! let fast: Vec<f64> = control_points(&());
//! assert!((fast[3] - 0.6).abs() < 1e-15);
//! ```

#![warn(rustdoc::broken_intra_doc_links)]

pub mod bspline;
pub mod claims;
pub mod cli;
pub mod curve;
pub mod gerbs;
pub mod hermite;
pub mod ledger;
pub mod linalg;
pub mod param;
pub mod ph;
pub mod poly;
pub mod quadrature;
pub mod quat;
pub mod report;
pub mod scalar;

// The main types of the algorithm layer at the crate root, for library users.
pub use bspline::cardinal::CardinalBSpline;
pub use gerbs::{bfbs::Bfbs, path::GerbsPath, Knots};
pub use hermite::HermiteData;
pub use param::natural::NaturalCubicSpline;
pub use ph::hermite::HermiteData as PhHermiteData;
pub use ph::PhCurve;
pub use scalar::{Field, Real, ScalarKind};
