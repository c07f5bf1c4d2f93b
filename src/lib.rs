//! trajverify: the curve and trajectory algorithms of five papers, written once over the
//! number type and verified in exact rationals, MPFR and f64 side by side.
//!
//! Layers, each using only those below it (DESIGN.md):
//! - [`cli`]: arguments and JSON in, JSON out; no mathematics.
//! - [`claims`]: the published claims of each paper, each a check that calls the library.
//! - [`report`]: the ledger (`claims.json`), Markdown reports, SVG figures.
//! - algorithms: [`hermite`] (paper 000).
//! - building blocks: [`poly`] (Bernstein form, differences), [`linalg`].
//! - [`scalar`]: the `Field` and `Real` traits over f64, MPFR and rationals.

pub mod claims;
pub mod cli;
pub mod hermite;
pub mod linalg;
pub mod poly;
pub mod report;
pub mod scalar;
