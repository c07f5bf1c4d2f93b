//! Convergence studies: how fast an approximation method's error falls on a curve as its
//! segments are halved, measured so that no printed order can be wrong.
//!
//! For each level n the curve γ on [a, b] is approximated on 2ⁿ uniform segments by a
//! [`Method`] — the C⁴ PH conversion of paper 001 (Algorithm 2 with φ* = 0) or paper 000's
//! two-point Hermite map on every segment — and the error E = max_ξ ‖γ(ξ) − p(ξ)‖ (paper 001,
//! Eq. 21) is measured three ways:
//!
//! - **proven** (`StudyOptions::proof`, the default): lower ≤ E ≤ upper by branch and bound in
//!   ball arithmetic ([`crate::curve::enclosure`]), a proof of the maximum, not a search;
//! - **sampled**: the maximum over 16 samples per segment refined by Newton, at p bits and
//!   recomputed at 2p bits. Agreement certifies the *arithmetic* of that value, not the search
//!   (a maximum the samples miss is missed at both precisions), so it is a cross-check beside
//!   the proof and, without one, it is labelled a sampled maximum, never certified;
//! - **f64**: the same pipeline in double precision, to show where f64 stops being enough.
//!
//! Each level is then classified ([`Status`]): *resolved* (the enclosure proves a first digit;
//! without a proof, the two precisions agree on one and the value lies above the precision
//! floor 2^(16−p) of the curve's size), *zero* (the error cannot be told from 0 at this
//! precision: the method reproduces the curve there), or *floor* (non-zero but without a
//! digit). Only resolved levels enter the orders:
//!
//! - the observed order between consecutive levels, log₂(E_{n−1}/E_n)/(n − (n−1)), with a
//!   proven interval from the enclosures;
//! - the fitted order, a least-squares slope of log₂ E against log₂ N over the **asymptotic
//!   levels**, chosen by a rule declared here and reported with the fit: the finest resolved
//!   levels whose observed orders stay within three times the change between the two finest
//!   orders (at least [`ASYMPTOTIC_SPREAD`]) of the finest one — where the orders still move,
//!   coarser levels are pre-asymptotic and would bias a constant-order fit — with a 95 %
//!   interval from Student's t on the residuals when three or more levels are used; when
//!   that spread exceeds [`SETTLED_SPREAD`] the orders have not settled and none is fitted;
//! - set against the **expected order**, derived from the method and the curve's smoothness
//!   ([`Method::expected_order`]): 6 for PHODCOS by Theorem 1 of paper 001, 2m + 2 for Hermite
//!   by the classical remainder, capped at k + 1 for a piecewise polynomial curve that is only
//!   C^k at its knots (a data spline is C⁴, so its fifth derivative jumps inside segments and
//!   the error there is O(h⁵)).
//!
//! When every level is zero the method reproduces the curve and no order is fitted. Before
//! any level is computed the curve is proven regular on [a, b] ([`crate::curve::regularity`]):
//! finite derivatives up to the method's order and a tangent that never vanishes, or the study
//! is refused naming t.
//!
//! ```
//! use trajverify::algo::convergence::{study, FitOutcome, Method, StudyOptions};
//! use trajverify::curve::{interval::Interval, ExprCurve};
//!
//! let curve = ExprCurve::parse("[cos(t), sin(t), t/5]").unwrap();
//! // Ends are exact: rationals, doubles or constants such as "4*pi" (enclosed in balls).
//! let interval = Interval::parse("0", "2").unwrap();
//! let options = StudyOptions {
//!     method: Method::Hermite(1),
//!     levels: vec![2, 3, 4, 5, 6],
//!     ..StudyOptions::default()
//! };
//! let result = study(&curve, &interval, &options, &mut |_, _| {}).unwrap();
//! // Cubic Hermite interpolation: order 4, and every error is proven.
//! assert_eq!(result.expected.order, 4);
//! match &result.fit {
//!     FitOutcome::Fitted(fit) => assert!((fit.order - 4.0).abs() < 0.2),
//!     other => panic!("{other:?}"),
//! }
//! assert!(result.rows.iter().all(|r| r.proven.is_some()));
//! ```

use crate::curve::adapter::OwnedCurve;
use crate::curve::approx::{
    certified_max_error, conversion_error, BernsteinPieces, PiecewiseBernstein, DEFAULT_SAMPLES,
};
use crate::curve::enclosure::{proven_error, ProofOptions};
use crate::curve::interval::Interval;
use crate::curve::parametric::ParamCurve;
use crate::curve::regularity::{self, Irregular, Regularity};
use crate::curve::spline::{ClampedSpline, PeriodicSpline};
use crate::curve::{Curve, ExprCurve};
use crate::scalar::ball::Ball;
use crate::scalar::certify::agreeing_digits;
use crate::scalar::{Field, Float, Real};
use rug::float::Round;

/// The deepest level accepted (2¹⁴ segments).
pub const MAX_LEVEL: u32 = 14;
/// The asymptotic levels' rule (declared before any study is run): an observed order belongs
/// to the asymptotic range while it lies within max(3·|o_N − o_{N−1}|, this) of the finest
/// order o_N, where o_N − o_{N−1} is how much the two finest orders still move.
pub const ASYMPTOTIC_SPREAD: f64 = 0.01;
/// The orders have not settled when that spread exceeds this (the two finest differ by more
/// than 1/6): no level is asymptotic yet and no order is fitted.
pub const SETTLED_SPREAD: f64 = 0.5;
/// The relative width the proven enclosures aim for.
pub const TARGET_WIDTH: f64 = 1e-6;
/// Boxes one enclosure may evaluate.
const MAX_BOXES: usize = 4_000_000;

/// The approximation whose error is measured.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// C⁴ PH interpolants with φ* = 0 (paper 001, Algorithm 2).
    Phodcos,
    /// Piecewise Hermite–Bernstein interpolation with m derivatives at every joint
    /// (paper 000's map on each segment; degree 2m + 1).
    Hermite(usize),
}

/// The most derivatives per joint for [`Method::Hermite`]: degree 2m + 1 ≤ 17, what the
/// proven enclosure's Taylor models cover.
pub const MAX_HERMITE_DERIVATIVES: usize = (crate::curve::enclosure::ORDER - 1) / 2;

/// The precisions a study accepts (bits): MPFR's floor, and a ceiling that keeps a study of
/// nine levels, proven, within minutes (its cost grows about as bits²).
pub const STUDY_BITS: (u32, u32) = (16, 4096);

/// How smooth the curve is, which caps the order any method can show on it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Smoothness {
    /// Analytic on the interval (a curve given by an expression, once proven regular).
    Analytic,
    /// A piecewise polynomial that is C^k at its knots, its (k+1)-th derivative jumping there.
    Piecewise {
        /// k.
        continuity: usize,
    },
}

/// The order the theory predicts, and why.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ExpectedOrder {
    /// The order.
    pub order: usize,
    /// Where it comes from.
    pub reason: String,
}

impl Method {
    /// `"phodcos"` or `"hermite:M"` (M = 0 … [`MAX_HERMITE_DERIVATIVES`]).
    ///
    /// # Errors
    /// [`StudyError::Method`] for any other text (matched exactly, untrimmed), including
    /// `hermite:M` with M above [`MAX_HERMITE_DERIVATIVES`].
    pub fn parse(text: &str) -> Result<Method, StudyError> {
        if text == "phodcos" {
            return Ok(Method::Phodcos);
        }
        match text.strip_prefix("hermite:").map(str::parse::<usize>) {
            Some(Ok(m)) if m <= MAX_HERMITE_DERIVATIVES => Ok(Method::Hermite(m)),
            _ => Err(StudyError::Method(format!(
                "{text:?} is not \"phodcos\" or \"hermite:M\" with M in 0…{MAX_HERMITE_DERIVATIVES}"
            ))),
        }
    }

    /// The derivatives of the curve the method reads at every joint.
    pub fn derivatives(self) -> usize {
        match self {
            Method::Phodcos => 4,
            Method::Hermite(m) => m,
        }
    }

    /// The order E = O(hᵏ) the theory gives on a curve of this smoothness.
    pub fn expected_order(self, smoothness: Smoothness) -> ExpectedOrder {
        let (order, reason) = match self {
            Method::Phodcos => (
                6,
                "Theorem 1 of paper 001: C⁴ PH interpolation converges as O(h⁶)".to_string(),
            ),
            Method::Hermite(m) => (
                2 * m + 2,
                format!(
                    "the classical Hermite remainder, E ≤ max‖γ⁽{}⁾‖ h^{} / ({}! 4^{}); paper 000 claims no order",
                    2 * m + 2,
                    2 * m + 2,
                    2 * m + 2,
                    m + 1
                ),
            ),
        };
        match smoothness {
            Smoothness::Piecewise { continuity } if continuity + 1 < order => ExpectedOrder {
                order: continuity + 1,
                reason: format!(
                    "{reason}, for a smooth curve; this curve is only C^{continuity}: its derivative of order {} \
                     jumps at knots inside the segments, so the error there is O(h^{})",
                    continuity + 1,
                    continuity + 1
                ),
            },
            _ => ExpectedOrder { order, reason },
        }
    }

    /// A name for reports: "the PHODCOS conversion", "piecewise Hermite–Bernstein (m = 2)".
    pub fn title(self) -> String {
        match self {
            Method::Phodcos => "the PHODCOS conversion".into(),
            Method::Hermite(m) => format!("piecewise Hermite–Bernstein interpolation (m = {m})"),
        }
    }

    /// The pieces the method builds, for reports.
    pub fn pieces(self) -> String {
        match self {
            Method::Phodcos => "C⁴ PH interpolants (φ* = 0)".into(),
            Method::Hermite(m) => format!(
                "two-point Hermite interpolants of degree {} in Bernstein form (paper 000, Eqs. 11–18; C^{m} at the joints)",
                2 * m + 1
            ),
        }
    }

    /// The approximation of `curve` on `segments` pieces of [a, b], in any number type.
    fn fit<T: Real, C: Curve<T> + ?Sized>(
        self,
        curve: &C,
        (a, b): (&T, &T),
        segments: usize,
    ) -> Result<Fitted<T>, String> {
        Ok(match self {
            Method::Phodcos => {
                let zero = crate::algo::ph::hermite::FreeParameters::zero(4, &a.ctx());
                Fitted::Ph(
                    crate::algo::ph::piecewise::convert(curve, (a, b), segments, 4, &zero, false)
                        .map_err(|e| e.to_string())?,
                )
            }
            Method::Hermite(m) => Fitted::Hermite(
                crate::algo::hermite::piecewise::interpolate_curve(
                    curve,
                    (a, b),
                    &crate::algo::hermite::piecewise::InterpolationOptions {
                        segments,
                        derivatives: m,
                    },
                )
                .map_err(|e| e.to_string())?,
            ),
        })
    }
}

/// A curve a study can evaluate in every number type it needs.
pub trait StudyCurve: Sync {
    /// The curve in f64.
    fn in_f64(&self) -> Box<dyn Curve<f64> + '_>;
    /// The curve in MPFR at `bits`.
    fn in_mpfr(&self, bits: u32) -> Box<dyn Curve<Float> + '_>;
    /// The curve in ball arithmetic at `bits`.
    fn in_ball(&self, bits: u32) -> Box<dyn Curve<Ball> + '_>;
    /// Its smoothness (for the expected order).
    fn smoothness(&self) -> Smoothness;
    /// Prove it regular on [a, b] up to `order` derivatives ([`regularity::check`]); `None`
    /// when the curve is regular by construction.
    fn regularity(
        &self,
        interval: &Interval,
        order: usize,
        bits: u32,
    ) -> Result<Option<Regularity>, Irregular> {
        regularity::check(&*self.in_ball(bits), interval, order, bits).map(Some)
    }
    /// Its size, max |coordinate| over 33 equally spaced points (the scale of the precision
    /// floor).
    fn size(&self, interval: &Interval) -> f64 {
        let c = self.in_f64();
        let (a, b) = interval.to_f64();
        (0..=32)
            .map(|i| a + (b - a) * f64::from(i) / 32.0)
            .flat_map(|t| c.jet(&t, 0).into_iter().flatten())
            .map(f64::abs)
            .filter(|x| x.is_finite())
            .fold(1e-300, f64::max)
    }
}

/// A curve written as a generic Rust function (`curve::function`): analytic by assumption,
/// proven regular by the study.
impl<F: crate::curve::function::CurveFn> StudyCurve for crate::curve::function::FnCurve<F> {
    fn in_f64(&self) -> Box<dyn Curve<f64> + '_> {
        Box::new(self)
    }
    fn in_mpfr(&self, _bits: u32) -> Box<dyn Curve<Float> + '_> {
        Box::new(self)
    }
    fn in_ball(&self, _bits: u32) -> Box<dyn Curve<Ball> + '_> {
        Box::new(self)
    }
    fn smoothness(&self) -> Smoothness {
        Smoothness::Analytic
    }
}

/// A library curve (any [`ParamCurve`] of dimension D ≤ 3: a Bézier curve, a GERBS path, a
/// natural spline, …) built by the caller in each number type a study needs, so that it can be
/// studied like an expression. `build` rounds the curve's data into the context once; a
/// member that cannot be built there becomes a curve without values, which the study's
/// conversions refuse ("not finite") rather than use.
///
/// A curve made of several polynomial pieces is proven through
/// [`crate::curve::adapter::OwnedCurve`], whose seam bound at a breakpoint is infinite: its
/// proven errors are unbounded above (never wrong), so study such a curve sampled
/// (`proof: false`), or prove a curve of one piece.
///
/// # Examples
/// A cubic Bézier curve studied like an expression: its PH conversion converges at order 6.
/// ```
/// use trajverify::algo::convergence::{study, CurveFamily, Family, Smoothness, StudyOptions};
/// use trajverify::curve::bezier::BezierCurve;
/// use trajverify::curve::interval::Interval;
/// use trajverify::scalar::Real;
///
/// struct Arc;
/// impl CurveFamily<2> for Arc {
///     type Member<T: Real> = BezierCurve<T, 2>;
///     fn build<T: Real>(&self, ctx: &T::Ctx) -> Option<BezierCurve<T, 2>> {
///         let p = |x: i64, y: i64| [T::from_i64(x, ctx), T::from_i64(y, ctx)];
///         let (a, b) = (T::from_i64(0, ctx), T::from_i64(1, ctx));
///         BezierCurve::new(vec![p(0, 0), p(1, 2), p(3, 3), p(4, 1)], (a, b)).ok()
///     }
///     fn smoothness(&self) -> Smoothness {
///         Smoothness::Analytic
///     }
/// }
/// let options = StudyOptions { levels: vec![1, 2, 3, 4], ..StudyOptions::default() };
/// let result = study(&Family(Arc), &Interval::unit(), &options, &mut |_, _| {}).unwrap();
/// assert!(result.rows.iter().all(|r| r.proven.is_some()));
/// ```
pub trait CurveFamily<const D: usize>: Sync {
    /// The curve in the number type `T`.
    type Member<T: Real>: ParamCurve<T, D> + Sync;
    /// The curve with its data rounded into `ctx`; `None` where it cannot be built.
    fn build<T: Real>(&self, ctx: &T::Ctx) -> Option<Self::Member<T>>;
    /// Its smoothness (for the expected order).
    fn smoothness(&self) -> Smoothness;
}

/// A [`CurveFamily`] as a study's curve.
pub struct Family<F, const D: usize>(pub F);

/// A member that could not be built: no values.
struct Unbuilt;

impl<T: Real> Curve<T> for Unbuilt {
    fn jet(&self, t: &T, order: usize) -> Vec<[T; 3]> {
        vec![std::array::from_fn(|_| T::from_f64(f64::NAN, &t.ctx())); order + 1]
    }
}

fn member<'a, T: Real + 'a, F: CurveFamily<D>, const D: usize>(
    family: &F,
    ctx: &T::Ctx,
) -> Box<dyn Curve<T> + 'a>
where
    F::Member<T>: 'a,
{
    match family.build::<T>(ctx) {
        Some(c) => Box::new(OwnedCurve::<_, D>(c)),
        None => Box::new(Unbuilt),
    }
}

impl<F: CurveFamily<D>, const D: usize> StudyCurve for Family<F, D> {
    fn in_f64(&self) -> Box<dyn Curve<f64> + '_> {
        member::<f64, F, D>(&self.0, &())
    }
    fn in_mpfr(&self, bits: u32) -> Box<dyn Curve<Float> + '_> {
        member::<Float, F, D>(&self.0, &bits)
    }
    fn in_ball(&self, bits: u32) -> Box<dyn Curve<Ball> + '_> {
        member::<Ball, F, D>(&self.0, &bits)
    }
    fn smoothness(&self) -> Smoothness {
        self.0.smoothness()
    }
    fn regularity(
        &self,
        interval: &Interval,
        order: usize,
        bits: u32,
    ) -> Result<Option<Regularity>, Irregular> {
        // A box across a breakpoint would be evaluated on one piece only: the regularity
        // proof covers curves of one piece, and a piecewise one is not proven regular.
        match self.0.build::<Ball>(&bits) {
            Some(c) if c.breakpoints().is_empty() => {
                regularity::check(&OwnedCurve::<_, D>(c), interval, order, bits).map(Some)
            }
            _ => Ok(None),
        }
    }
}

impl StudyCurve for ExprCurve {
    fn in_f64(&self) -> Box<dyn Curve<f64> + '_> {
        Box::new(self.compile::<f64>(&()))
    }
    fn in_mpfr(&self, bits: u32) -> Box<dyn Curve<Float> + '_> {
        Box::new(self.compile::<Float>(&bits))
    }
    fn in_ball(&self, bits: u32) -> Box<dyn Curve<Ball> + '_> {
        Box::new(self.compile::<Ball>(&bits))
    }
    fn smoothness(&self) -> Smoothness {
        Smoothness::Analytic
    }
}

/// A quintic spline through data: a piecewise polynomial, finite everywhere, C⁴ at its knots.
macro_rules! spline_study_curve {
    ($t:ty) => {
        impl StudyCurve for $t {
            fn in_f64(&self) -> Box<dyn Curve<f64> + '_> {
                Box::new(self)
            }
            fn in_mpfr(&self, _: u32) -> Box<dyn Curve<Float> + '_> {
                Box::new(self)
            }
            fn in_ball(&self, _: u32) -> Box<dyn Curve<Ball> + '_> {
                Box::new(self)
            }
            fn smoothness(&self) -> Smoothness {
                Smoothness::Piecewise {
                    continuity: self.degree().saturating_sub(1),
                }
            }
            fn regularity(
                &self,
                _: &Interval,
                _: usize,
                _: u32,
            ) -> Result<Option<Regularity>, Irregular> {
                Ok(None)
            }
        }
    };
}
spline_study_curve!(PeriodicSpline);
spline_study_curve!(ClampedSpline);

/// What a study measures and how.
#[derive(Clone, Debug)]
pub struct StudyOptions {
    /// The approximation.
    pub method: Method,
    /// The levels n (2ⁿ segments), increasing, within 0 … [`MAX_LEVEL`].
    pub levels: Vec<u32>,
    /// The MPFR precision p of the sampled maximum (recomputed at 2p) and of the balls.
    pub bits: u32,
    /// Prove every error by branch and bound (the default); without it the errors are
    /// sampled maxima, not certified.
    pub proof: bool,
}

impl Default for StudyOptions {
    /// PHODCOS, levels 0 … 8, 128 bits, proven.
    fn default() -> Self {
        StudyOptions {
            method: Method::Phodcos,
            levels: (0..=8).collect(),
            bits: 128,
            proof: true,
        }
    }
}

/// Why a study cannot be made.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum StudyError {
    /// An unknown method.
    #[error("{0}")]
    Method(String),
    /// Bad levels.
    #[error("{0}")]
    Levels(String),
    /// A precision outside [`STUDY_BITS`].
    #[error("{0}")]
    Bits(String),
    /// The curve is not regular on the interval.
    #[error(transparent)]
    Irregular(#[from] Irregular),
    /// The method failed at a level (e.g. a tangent that vanishes at a joint of a data curve).
    #[error("the {what} failed on {segments} segments: {message}")]
    Failed {
        /// Which computation.
        what: &'static str,
        /// At how many segments.
        segments: usize,
        /// The method's error.
        message: String,
    },
}

/// How well a level's error is known.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    /// A first digit is proven (or, without a proof, agreed by two precisions above the
    /// precision floor): the level enters the orders.
    Resolved,
    /// The error cannot be told from 0 at this precision: the method reproduces the curve
    /// here (E ≤ the upper bound).
    Zero,
    /// Non-zero but without a digit at this precision (the precision floor).
    Floor,
}

/// One level of a study.
#[derive(Clone, Debug)]
pub struct Row {
    /// n.
    pub level: u32,
    /// 2ⁿ.
    pub segments: usize,
    /// The sampled and Newton-refined maximum at p bits and the same maximum recomputed at 2p
    /// bits (their agreement certifies the arithmetic of the value, not the search).
    pub sampled: (Float, Float),
    /// Proven bounds lower ≤ E ≤ upper, when the study proves.
    pub proven: Option<(Float, Float)>,
    /// The f64 pipeline's error, `None` when it is not finite in f64.
    pub f64_error: Option<f64>,
    /// How well E is known.
    pub status: Status,
    /// The sampled maximum lies below the proven lower bound: the sampled search missed the
    /// true maximum at this level.
    pub search_missed: bool,
}

impl Row {
    /// The value the orders use: the geometric centre of the enclosure when proven, the
    /// sampled maximum at 2p bits otherwise (as a double; see [`Row::log2_value`] for values
    /// beyond its range).
    pub fn value(&self) -> f64 {
        self.log2_value().exp2()
    }

    /// log₂ of [`Row::value`], computed in MPFR (an error of 1e2000 has one).
    pub fn log2_value(&self) -> f64 {
        let log2 = |x: &Float| Float::with_val(64, x.log2_ref()).to_f64();
        match &self.proven {
            Some((lo, hi)) => (log2(lo) + log2(hi)) / 2.0,
            None => log2(&self.sampled.1),
        }
    }

    /// The best known value of E for comparing f64 with: the order value of a resolved level,
    /// else the sampled maximum where its two precisions agree on a digit (a level at the
    /// proof's floor), else none.
    pub fn reference(&self) -> Option<f64> {
        match self.status {
            Status::Resolved => Some(self.value()),
            _ if self.sampled_digits() >= 1 && !self.sampled.1.is_zero() => {
                Some(self.sampled.1.to_f64())
            }
            _ => None,
        }
    }

    /// The significant digits the sampled value's two precisions agree on.
    pub fn sampled_digits(&self) -> u32 {
        agreeing_digits(&self.sampled.0, &self.sampled.1)
    }
}

/// The observed order between a level and the previous resolved one.
#[derive(Clone, Debug, PartialEq)]
pub struct ObservedOrder {
    /// From the values the orders use.
    pub value: f64,
    /// A proven interval from the enclosures, when proven.
    pub proven: Option<(f64, f64)>,
}

/// The least-squares order over the asymptotic levels.
#[derive(Clone, Debug, PartialEq)]
pub struct OrderFit {
    /// The fitted order.
    pub order: f64,
    /// Half-width of the 95 % interval (`None` from two levels, which fit exactly).
    pub ci95: Option<f64>,
    /// The levels used.
    pub levels: Vec<u32>,
    /// Why these levels (the rule applied, and what it left out).
    pub why: String,
    /// Whether the expected order lies in the 95 % interval (`None` without an interval).
    pub expected_inside: Option<bool>,
    /// The observed orders across the fitted levels move by more than the 95 % interval:
    /// (first, last) — the constant-order fit is biased by terms of higher order in h.
    pub drift: Option<(f64, f64)>,
}

/// What the orders say.
#[derive(Clone, Debug, PartialEq)]
pub enum FitOutcome {
    /// Every error is zero to the working precision: the method reproduces the curve.
    Reproduced {
        /// The largest bound of E over the levels.
        bound: f64,
    },
    /// Fewer than two resolved levels, with the reason.
    TooFew(String),
    /// An order was fitted.
    Fitted(OrderFit),
}

/// The result of a study.
#[derive(Clone, Debug)]
pub struct Study {
    /// The method.
    pub method: Method,
    /// The precision p.
    pub bits: u32,
    /// Whether the errors are proven.
    pub proof: bool,
    /// One row per level.
    pub rows: Vec<Row>,
    /// Per row, the observed order from the previous row when both are resolved.
    pub orders: Vec<Option<ObservedOrder>>,
    /// The fitted order or why there is none.
    pub fit: FitOutcome,
    /// The order the theory predicts.
    pub expected: ExpectedOrder,
    /// The row from which f64 stops improving while the true error keeps falling.
    pub f64_floor: Option<usize>,
    /// The first row whose f64 error is more than 10 % from the reference value.
    pub f64_departs: Option<usize>,
    /// The precision floor 2^(16−p) of the curve's size, below which a sampled value is noise.
    pub precision_floor: f64,
    /// With a proof, the floor below which the enclosures cannot resolve E: about
    /// √(2^−p) of the curve's size (they bound the squared norm, whose rounding is 2^−p).
    pub proof_floor: Option<f64>,
    /// What the regularity check proved (`None` for a curve regular by construction).
    pub regularity: Option<Regularity>,
    /// Findings a reader must see: a near-cusp, a sampled search that missed the maximum.
    pub notes: Vec<String>,
}

/// Check and sort the levels: increasing, within 0 … [`MAX_LEVEL`], at least one.
///
/// # Errors
/// [`StudyError::Levels`] when `levels` is empty, not strictly increasing, or has an entry
/// above [`MAX_LEVEL`].
pub fn check_levels(levels: &[u32]) -> Result<(), StudyError> {
    if levels.is_empty()
        || levels.windows(2).any(|w| w[1] <= w[0])
        || levels.iter().any(|&n| n > MAX_LEVEL)
    {
        return Err(StudyError::Levels(format!(
            "levels must increase within 0…{MAX_LEVEL}, got {levels:?}"
        )));
    }
    Ok(())
}

/// Run the study of `curve` on [a, b]; `progress(level, segments)` is called after each level.
///
/// # Errors
/// The interval is ordered by construction ([`Interval`]: its ends are exact, rounded to
/// each precision, enclosed in balls for the proof). [`StudyError::Levels`] as [`check_levels`];
/// [`StudyError::Bits`] for a precision outside [`STUDY_BITS`]; [`StudyError::Method`] for
/// [`Method::Hermite`] above [`MAX_HERMITE_DERIVATIVES`];
/// [`StudyError::Irregular`] when the regularity check fails (except `BeyondBallRange` without
/// a proof); [`StudyError::Failed`] when a level's MPFR conversion (at `bits` or `2·bits`) or,
/// with a proof, its ball conversion fails. A failing f64 conversion is not an error.
pub fn study<C: StudyCurve + ?Sized>(
    curve: &C,
    interval: &Interval,
    options: &StudyOptions,
    progress: &mut dyn FnMut(u32, usize),
) -> Result<Study, StudyError> {
    check_levels(&options.levels)?;
    let (low, high) = STUDY_BITS;
    if !(low..=high).contains(&options.bits) {
        return Err(StudyError::Bits(format!(
            "bits: the precision must lie in {low}…{high}, got {}",
            options.bits
        )));
    }
    let method = options.method;
    if let Method::Hermite(m) = method {
        if m > MAX_HERMITE_DERIVATIVES {
            return Err(StudyError::Method(format!(
                "method: hermite:{m} has more than {MAX_HERMITE_DERIVATIVES} derivatives per joint"
            )));
        }
    }
    let regularity = match curve.regularity(interval, method.derivatives(), options.bits) {
        // Balls cannot enclose such values; without a proof MPFR carries them, and a
        // non-finite jet still stops the conversion at its joint.
        Err(Irregular::BeyondBallRange { .. }) if !options.proof => None,
        other => other?,
    };
    let size = curve.size(interval);
    let precision_floor = size * 2f64.powi(16 - options.bits.min(1000) as i32);
    let proof_floor = options
        .proof
        .then(|| 16.0 * size * 2f64.powi(-(options.bits.min(2000) as i32) / 2));
    let mut rows = Vec::with_capacity(options.levels.len());
    for &n in &options.levels {
        crate::cancel::checkpoint();
        rows.push(level(curve, interval, options, n, precision_floor)?);
        progress(n, 1 << n);
    }
    let orders = observed_orders(&rows);
    let expected = method.expected_order(curve.smoothness());
    let fit = fit_orders(&rows, &orders, &expected);
    let mut notes = Vec::new();
    if let Some(r) = &regularity {
        if r.speed_ratio() < 1e-2 {
            notes.push(format!(
                "the speed ‖γ′‖ falls to {:.1e} of its largest value near t ≈ {:.4}: the curve nearly has a cusp there, \
                 and segments of equal parameter length resolve it only once they are short there (the coarse levels' errors are large)",
                r.speed_ratio(),
                r.slowest_at
            ));
        }
    }
    for r in rows.iter().filter(|r| r.search_missed) {
        notes.push(format!(
            "at {} segments the sampled maximum lies below the proven lower bound: the sampled search missed the true maximum",
            r.segments
        ));
    }
    Ok(Study {
        method,
        bits: options.bits,
        proof: options.proof,
        f64_floor: f64_floor(&rows),
        f64_departs: f64_departs(&rows),
        rows,
        orders,
        fit,
        expected,
        precision_floor,
        proof_floor,
        regularity,
        notes,
    })
}

/// Compute and classify one level.
fn level<C: StudyCurve + ?Sized>(
    curve: &C,
    interval: &Interval,
    options: &StudyOptions,
    n: u32,
    floor: f64,
) -> Result<Row, StudyError> {
    let segments = 1usize << n;
    let (method, bits) = (options.method, options.bits);
    let failed = |what: &'static str| {
        move |message: String| StudyError::Failed {
            what,
            segments,
            message,
        }
    };
    let e = certified_max_error(
        |p| curve.in_mpfr(p),
        |c, p| {
            let (a, b): (Float, Float) = interval.ends(&p);
            method.fit(&**c, (&a, &b), segments)
        },
        bits,
        2 * bits,
    )
    .map_err(failed("conversion"))?;
    let sampled = (e.lo, e.hi);
    let proven = if options.proof {
        let c = curve.in_ball(bits);
        // Balls enclosing the exact ends: the proven error holds for the true interval.
        let (a, b): (Ball, Ball) = interval.ends(&bits);
        let pw = method
            .fit(&*c, (&a, &b), segments)
            .map_err(failed("ball conversion"))?;
        let e = proven_error(
            &*c,
            &pw,
            &ProofOptions {
                target: TARGET_WIDTH,
                max_boxes: MAX_BOXES,
                ..ProofOptions::default()
            },
        )
        .map_err(|e| failed("proven error")(e.to_string()))?;
        Some((e.lower, e.upper))
    } else {
        None
    };
    let f64_error = {
        let c = curve.in_f64();
        method
            .fit(&*c, (&interval.to_f64().0, &interval.to_f64().1), segments)
            .ok()
            .map(|pw| conversion_error(&*c, &pw, DEFAULT_SAMPLES).max)
            .filter(|x| x.is_finite())
    };
    let status = classify(&sampled, proven.as_ref(), floor);
    // A sampled maximum (at either precision) below the proven lower bound, beyond their
    // rounding, missed the true maximum.
    let search_missed = proven.as_ref().is_some_and(|(lo, _)| {
        let bound = Float::with_val(bits, lo) * (1.0 - 1e-9);
        sampled.0 < bound || sampled.1 < bound
    });
    Ok(Row {
        level: n,
        segments,
        sampled,
        proven,
        f64_error,
        status,
        search_missed,
    })
}

/// The status of a level from its enclosure, or without one from its sampled values.
///
/// Without a proof: zero when both sampled values lie below the precision floor, floor when
/// they agree on no digit or the value lies below it, resolved otherwise. With a proof the
/// enclosure decides (resolved: it proves a first digit), except that a lower bound of 0 is
/// "zero" only when the sampled values are zero too: an error the samples resolve but the
/// proof cannot bound away from 0 at this precision is at the proof's floor.
fn classify(sampled: &(Float, Float), proven: Option<&(Float, Float)>, floor: f64) -> Status {
    let below = |x: &Float| x.clone().abs() <= floor;
    let sampled_status = if below(&sampled.0) && below(&sampled.1) {
        Status::Zero
    } else if agreeing_digits(&sampled.0, &sampled.1) == 0 || below(&sampled.1) {
        Status::Floor
    } else {
        Status::Resolved
    };
    let Some((lo, hi)) = proven else {
        return sampled_status;
    };
    if !hi.is_finite() || !lo.is_finite() {
        Status::Floor
    } else if *lo <= 0 {
        if sampled_status == Status::Zero {
            Status::Zero
        } else {
            Status::Floor
        }
    } else if Ball::from_bounds(lo, hi).proven_digits().0 >= 1 {
        Status::Resolved
    } else {
        Status::Floor
    }
}

/// The observed order of each row from the previous one, when both are resolved.
fn observed_orders(rows: &[Row]) -> Vec<Option<ObservedOrder>> {
    let mut out = vec![None];
    for w in rows.windows(2) {
        let (prev, cur) = (&w[0], &w[1]);
        if prev.status != Status::Resolved || cur.status != Status::Resolved {
            out.push(None);
            continue;
        }
        let steps = f64::from(cur.level - prev.level);
        // (+ 0.0 turns a −0 into 0.)
        let value = (prev.log2_value() - cur.log2_value()) / steps + 0.0;
        let proven = match (&prev.proven, &cur.proven) {
            (Some((plo, phi)), Some((clo, chi))) => {
                let low = Float::with_val_round(64, plo / chi, Round::Down).0;
                let high = Float::with_val_round(64, phi / clo, Round::Up).0;
                let log = |x: Float, round: Round| {
                    Float::with_val_round(64, x.log2_ref(), round)
                        .0
                        .to_f64_round(round)
                };
                Some((log(low, Round::Down) / steps, log(high, Round::Up) / steps))
            }
            _ => None,
        };
        out.push(Some(ObservedOrder { value, proven }));
    }
    out
}

/// Student's t quantile for a two-sided 95 % interval with `df` degrees of freedom.
fn t95(df: usize) -> f64 {
    const TABLE: [f64; 10] = [
        12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
    ];
    TABLE
        .get(df.wrapping_sub(1))
        .copied()
        .unwrap_or(if df > 30 { 1.96 } else { 2.1 })
}

/// The slope of the least-squares line through `points` and the half-width of its 95 %
/// interval (Student's t on the residuals; `None` from two points, which fit exactly).
fn least_squares(points: &[(f64, f64)]) -> (f64, Option<f64>) {
    let k = points.len();
    let mx = points.iter().map(|p| p.0).sum::<f64>() / k as f64;
    let my = points.iter().map(|p| p.1).sum::<f64>() / k as f64;
    let sxx: f64 = points.iter().map(|p| (p.0 - mx).powi(2)).sum();
    let slope = points.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum::<f64>() / sxx;
    let ci95 = (k > 2).then(|| {
        let rss: f64 = points
            .iter()
            .map(|p| (p.1 - my - slope * (p.0 - mx)).powi(2))
            .sum();
        t95(k - 2) * (rss / (k - 2) as f64 / sxx).sqrt()
    });
    (slope, ci95)
}

/// The orders across the window when they move by more than the 95 % interval claims (a
/// window of two levels has one order and cannot show it).
fn drift(window: &[Option<ObservedOrder>], ci95: Option<f64>) -> Option<(f64, f64)> {
    let orders: Vec<f64> = window
        .iter()
        .filter_map(|o| o.as_ref().map(|o| o.value))
        .collect();
    match (orders.first(), orders.last(), ci95) {
        (Some(&a), Some(&b), Some(ci)) if orders.len() >= 2 && (b - a).abs() > ci => Some((a, b)),
        _ => None,
    }
}

/// Why the rows outside the window `first..=last` are left out of the fit.
fn left_out(
    rows: &[Row],
    orders: &[Option<ObservedOrder>],
    first: usize,
    last: usize,
) -> Vec<String> {
    let mut out = Vec::new();
    if first > 0 {
        out.push(match &orders[first] {
            Some(o) => format!(
                "coarser levels are pre-asymptotic (the order into n = {} is {:.3})",
                rows[first].level, o.value
            ),
            None => format!(
                "n = {} and coarser are not resolved or not consecutive",
                rows[first].level
            ),
        });
    }
    let dropped: Vec<u32> = rows[last + 1..].iter().map(|r| r.level).collect();
    if !dropped.is_empty() {
        out.push(format!(
            "n = {dropped:?} are not resolved at this precision (below its floor)"
        ));
    }
    out
}

/// The fit over the asymptotic levels (see the module doc for the rule).
fn fit_orders(
    rows: &[Row],
    orders: &[Option<ObservedOrder>],
    expected: &ExpectedOrder,
) -> FitOutcome {
    if rows.iter().all(|r| r.status == Status::Zero) {
        let bound = rows
            .iter()
            .map(|r| {
                r.proven
                    .as_ref()
                    .map_or(r.sampled.1.to_f64(), |p| p.1.to_f64())
            })
            .fold(0.0, f64::max);
        return FitOutcome::Reproduced { bound };
    }
    // The finest run of consecutive resolved rows joined by observed orders.
    let Some(last) = (1..rows.len()).rev().find(|&i| orders[i].is_some()) else {
        let resolved = rows.iter().filter(|r| r.status == Status::Resolved).count();
        return FitOutcome::TooFew(format!(
            "{resolved} level(s) resolved and no two consecutive ones: no order can be measured"
        ));
    };
    let finest = orders[last].as_ref().map_or(0.0, |o| o.value);
    let moving = orders[last - 1]
        .as_ref()
        .map_or(0.0, |o| (finest - o.value).abs());
    let spread = (3.0 * moving).max(ASYMPTOTIC_SPREAD);
    if spread > SETTLED_SPREAD {
        let previous = orders[last - 1].as_ref().map_or(finest, |o| o.value);
        return FitOutcome::TooFew(format!(
            "the observed orders have not settled (the two finest are {previous:.3} and {finest:.3}): no level is in the \
             asymptotic range yet; finer levels are needed"
        ));
    }
    // The pair joined by the finest order is always in; coarser rows join while their
    // order into the window stays within the spread.
    let mut first = last - 1;
    while first > 0
        && orders[first]
            .as_ref()
            .is_some_and(|o| (o.value - finest).abs() <= spread)
    {
        first -= 1;
    }
    // Rows first … last are joined by orders within the spread (orders[first] itself is not).
    let window = &rows[first..=last];
    let left_out = left_out(rows, orders, first, last);
    let points: Vec<(f64, f64)> = window
        .iter()
        .map(|r| ((r.segments as f64).log2(), r.log2_value()))
        .collect();
    let k = points.len();
    let (slope, ci95) = least_squares(&points);
    let order = -slope;
    let drift = drift(&orders[first + 1..=last], ci95);
    let levels: Vec<u32> = window.iter().map(|r| r.level).collect();
    let mut why = format!(
        "the finest {k} resolved levels (n = {}…{}), whose observed orders lie within {spread:.3} of the finest one \
         (three times the change between the two finest orders, at least {ASYMPTOTIC_SPREAD})",
        levels[0],
        levels[k - 1]
    );
    if !left_out.is_empty() {
        why.push_str("; ");
        why.push_str(&left_out.join("; "));
    }
    FitOutcome::Fitted(OrderFit {
        order,
        ci95,
        expected_inside: ci95.map(|ci| (order - expected.order as f64).abs() <= ci),
        levels,
        why,
        drift,
    })
}

/// The row of the smallest f64 error, when a later row's true error is smaller still by more
/// than a factor 2: f64 stops improving there.
fn f64_floor(rows: &[Row]) -> Option<usize> {
    let best = (0..rows.len())
        .filter(|&i| rows[i].f64_error.is_some())
        .min_by(|&i, &j| {
            rows[i]
                .f64_error
                .partial_cmp(&rows[j].f64_error)
                .unwrap_or(std::cmp::Ordering::Equal)
        })?;
    let here = rows[best].reference()?;
    let keeps_falling = rows[best + 1..]
        .iter()
        .any(|r| r.reference().is_some_and(|v| v < here / 2.0));
    keeps_falling.then_some(best)
}

/// The first row whose f64 error differs from the reference value by more than 10 %.
fn f64_departs(rows: &[Row]) -> Option<usize> {
    rows.iter().position(|r| {
        r.reference()
            .is_some_and(|v| r.f64_error.is_none_or(|e| ((e - v) / v).abs() > 0.1))
    })
}

/// A fit by either method: both are pieces in Bernstein form.
enum Fitted<T> {
    Ph(crate::algo::ph::piecewise::PiecewisePh<T>),
    Hermite(PiecewiseBernstein<T>),
}

impl<T: Real> BernsteinPieces<T> for Fitted<T> {
    fn interval(&self) -> (&T, &T) {
        match self {
            Fitted::Ph(p) => p.interval(),
            Fitted::Hermite(p) => p.interval(),
        }
    }
    fn count(&self) -> usize {
        match self {
            Fitted::Ph(p) => p.count(),
            Fitted::Hermite(p) => p.count(),
        }
    }
    fn control_points(&self, k: usize) -> Vec<[T; 3]> {
        match self {
            Fitted::Ph(p) => p.control_points(k),
            Fitted::Hermite(p) => p.control_points(k),
        }
    }
}
