//! trajverify: the curve and trajectory algorithms of five papers, written once over the
//! number type and verified in exact rationals, MPFR and f64 side by side.
//!
//! The library is [`scalar`], [`numeric`], [`curve`] and [`algo`]. The command line
//! (`cli`), the claims (`ledger`, `papers`) and the reports (`report`) are public only so the
//! binary and the tests can reach them; they are hidden from these docs and are not an API.
//! (Hidden rather than a separate crate: the binary, the snapshot tests and `verify` share
//! them, and a workspace split would compile GMP/MPFR's bindings twice for no user.)
//!
//! Layers, each using only those below it (`docs/design.md`, "Architecture"; `tests/layers.rs` checks every
//! `crate::` reference against this order):
//! - `cli`: arguments and JSON in, JSON out, work budgets; parse, one algorithm call, print.
//! - `papers`: the published claims of each paper, each a check that calls the library.
//! - `report`: Markdown reports, SVG figures, `claims.json`; reads only `ledger` values.
//! - `ledger`: claim specs, outcomes, verdicts and the ledger that joins them.
//! - [`algo`]: [`hermite`](algo::hermite) (paper 000), [`ph`](algo::ph) (paper 001),
//!   [`bspline`](algo::bspline) (paper 002), [`gerbs`](algo::gerbs) (paper 003),
//!   [`param`](algo::param) (paper 004); none uses another.
//! - [`curve`]: expressions, Taylor AD, curves fitted to data.
//! - [`numeric`]: [`linalg`](numeric::linalg), [`poly`](numeric::poly) (Bernstein form,
//!   differences, binomials), [`quat`](numeric::quat) (quaternions),
//!   [`quadrature`](numeric::quadrature).
//! - [`scalar`]: the `Field` and `Real` traits over f64, MPFR and rationals.
//! - [`cancel`]: stopping a long computation midway (the checkpoints every long loop calls);
//!   every layer may use it.
//!
//! One algorithm, three number types: the Hermite data of the paper's Fig. 2 mapped to
//! Bernstein control points exactly, in MPFR and in f64.
//!
//! ```
//! use trajverify::algo::hermite::HermiteData;
//! use trajverify::scalar::{BigRational, Field, Float};
//!
//! fn control_points<T: Field>(ctx: &T::Ctx) -> Vec<T> {
//!     let i = |v: i64| T::from_i64(v, ctx);
//!     let data = HermiteData::new(vec![i(0), i(0), i(0)], vec![i(1), i(1), i(0)], (i(0), i(1))).unwrap();
//!     data.solve().unwrap().into_control_points()
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
#![deny(missing_docs)]

pub mod algo;
pub mod cancel;
#[doc(hidden)]
pub mod cli;
pub mod curve;
#[doc(hidden)]
pub mod ledger;
pub mod numeric;
#[doc(hidden)]
pub mod papers;
#[doc(hidden)]
pub mod report;
pub mod scalar;

// The main types of the algorithm layer at the crate root, for library users.
pub use algo::bspline::cardinal::CardinalBSpline;
pub use algo::gerbs::{bfbs::Bfbs, path::GerbsPath, Knots};
pub use algo::hermite::HermiteData;
pub use algo::param::natural::NaturalCubicSpline;
pub use algo::ph::hermite::HermiteData as PhHermiteData;
pub use algo::ph::PhCurve;
pub use curve::bezier::BezierCurve;
pub use curve::parametric::{ParamCurve, ParamCurveArclen, ParamCurveFrame};
pub use scalar::{Field, Real, ScalarKind};
