//! Generalized expo-rational B-splines (GERBS) for curvature-continuous paths (paper 003,
//! Andersen, Bouzidi, Kristiansen).
//!
//! A GERBS curve blends local curves, p(t) = Σ_{k=2}^{n+1} c_{k−1}(t) B_k(t) (Eqs. 1, 25), with
//! basis functions of support [t_{k−1}, t_{k+1}] built from one rising function per knot
//! interval (Eq. 6): on (t_j, t_{j+1}) the function F_j rises from 0 to 1 and
//!
//! B_k = F_{k−1} on (t_{k−1}, t_k],  B_k = 1 − F_k on (t_k, t_{k+1}),  0 elsewhere,
//!
//! so the B_k are a partition of unity and B_k(t_k) = 1: the curve passes through c_{k−1}(t_k).
//! Two kinds of F (the [`Blend`] trait):
//! - [`bfbs`]: Beta-function B-splines (Eqs. 7–9), F_j(t) = S_j ∫_{t_j}^t Ψ_j with the
//!   polynomial kernel Ψ_j ∝ (t−t_j)^{i_j}(t_{j+1}−t)^{i_{j+1}}, a regularized incomplete beta
//!   function, evaluated exactly in its Bernstein form; Eqs. 10–18 are its i = 2 case.
//! - [`erbs`]: expo-rational B-splines (Eqs. 3–5), F_j = ∫_{t_j}^t Ψ_j / S_j with
//!   Ψ_j = exp(−β|t − c|^{2σ}/((t−t_j)(t_{j+1}−t)^γ)^α), by tanh–sinh [`quadrature`] and
//!   derivatives B′ = ±Ψ/S from Ψ itself (Taylor AD, no differencing).
//!
//! [`path`] builds the local arcs and lines (Eqs. 19–24), Algorithm 1 (tangents and turn
//! directions) and Algorithm 2 (the blended path); [`dubins`] is the shortest-path baseline of
//! Fig. 7.
//!
//! **Indices count from 0** in the API an engineer calls: knot i ([`Knots::get`]; the paper's
//! t_{i+1}), knot interval i from knot i to knot i + 1 ([`Knots::interval`]),
//! [`path::GerbsPath::at_knot`], [`path::GerbsPath::at_on`], [`path::GerbsPath::series_on`].
//! The [`Blend`] trait, [`Located`] and [`basis_series_on`] — what the implementer of a new
//! kind of blend writes against — keep the paper's 1-based j of Eq. (6) (F_j on (t_j, t_{j+1})),
//! so that their code reads like the paper's equations; each says so.
//!
//! The BFBS basis (i = 2) on the knots of Fig. 1 at t = 3/10, exactly and in f64: a partition
//! of unity with B₃ = 2944/3125 and B₄ = 181/3125.
//!
//! ```
//! use trajverify::algo::gerbs::{basis_derivatives, bfbs::Bfbs, Knots, Side};
//! use trajverify::scalar::BigRational;
//!
//! let q = |n: i64, d: i64| BigRational::new(n.into(), d.into());
//! let knots = Knots::new([(0, 1), (0, 1), (1, 4), (1, 2), (3, 4), (1, 1), (1, 1)]
//!     .map(|(n, d)| q(n, d)).to_vec()).unwrap();
//! let bfbs = Bfbs::uniform(2, 5).unwrap();
//! let b = basis_derivatives(&knots, &bfbs, &q(3, 10), 0, Side::Right).unwrap();
//! assert_eq!((b[1][0].clone(), b[2][0].clone()), (q(2944, 3125), q(181, 3125)));
//! let knots64 = Knots::new(vec![0.0, 0.0, 0.25, 0.5, 0.75, 1.0, 1.0]).unwrap();
//! let b64 = basis_derivatives(&knots64, &bfbs, &0.3, 0, Side::Right).unwrap();
//! assert!((b64.iter().map(|d| d[0]).sum::<f64>() - 1.0).abs() < 1e-15);
//! ```

pub mod bfbs;
pub mod dubins;
pub mod erbs;
pub mod path;
pub mod proven_erbs;
/// The quadrature rules the ERBS uses (the building block [`crate::numeric::quadrature`]).
pub mod quadrature {
    pub use crate::numeric::quadrature::*;
}

use crate::curve::taylor::Taylor;
use crate::scalar::Field;

/// Bad input to the GERBS constructions, named by field.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum GerbsError {
    /// A bad knot vector, with the reason.
    #[error("knots: {0}")]
    Knots(String),
    /// Bad waypoints, with the reason.
    #[error("waypoints: {0}")]
    Waypoints(String),
    /// Another parameter out of range.
    #[error("{field}: {message}")]
    Parameter {
        /// The input field at fault.
        field: &'static str,
        /// What is wrong with it.
        message: String,
    },
}

/// The knot vector t_1 ≤ t_2 < t_3 < … < t_{n+1} ≤ t_{n+2} (the end knots may be double,
/// Section III) of n basis functions B_2 … B_{n+1}.
#[derive(Clone, Debug, PartialEq)]
pub struct Knots<T> {
    t: Vec<T>,
}

impl<T: Field> Knots<T> {
    /// Strictly increasing knots t_0 < … < t_n (at least two).
    ///
    /// # Errors
    /// [`GerbsError::Knots`] for fewer than 3 knots, a non-finite knot, or knots that do not
    /// increase (strictly, except that each end pair may be equal).
    pub fn new(t: Vec<T>) -> Result<Self, GerbsError> {
        if t.len() < 3 {
            return Err(GerbsError::Knots(format!(
                "need at least 3 knots (one basis function), got {}",
                t.len()
            )));
        }
        if !t.iter().all(Field::is_finite) {
            return Err(GerbsError::Knots("every knot must be finite".into()));
        }
        let last = t.len() - 1;
        for j in 1..=last {
            // Only the two end pairs may repeat.
            let strict = j != 1 && j != last;
            let bad = if strict {
                t[j] <= t[j - 1]
            } else {
                t[j] < t[j - 1]
            };
            if bad {
                return Err(GerbsError::Knots(format!(
                    "knots must increase (t_{} = {} after t_{} = {})",
                    j + 1,
                    t[j].to_f64(),
                    j,
                    t[j - 1].to_f64()
                )));
            }
        }
        Ok(Knots { t })
    }

    /// The exact knot vector `exact` rounded into `T`. Its order was decided exactly, so an
    /// enclosure type ([`Field::ENCLOSURE`]) is not compared again (two equal knots give two
    /// identical balls, which no comparison can order, and distinct knots closer than the
    /// precision give overlapping ones); a rounding type checks that rounding kept the knots
    /// increasing.
    ///
    /// # Errors
    /// [`GerbsError::Knots`] when rounding made two knots equal or reversed them.
    pub fn rounded(exact: &Knots<crate::scalar::Exact>, ctx: &T::Ctx) -> Result<Self, GerbsError> {
        let t = exact.t.iter().map(|q| T::from_exact(q, ctx)).collect();
        if T::ENCLOSURE {
            Ok(Knots { t })
        } else {
            Knots::new(t)
        }
    }

    /// The knot vector of Algorithm 2 for n waypoints: t_1 = t_2 = 0, t_{n+1} = t_{n+2} = 1,
    /// uniform steps 1/(n−1) in between (Fig. 1 for n = 5: {0, 0, 1/4, 2/4, 3/4, 1, 1}).
    ///
    /// # Errors
    /// [`GerbsError::Waypoints`] for n < 2.
    pub fn uniform(n: usize, ctx: &T::Ctx) -> Result<Self, GerbsError> {
        if n < 2 {
            return Err(GerbsError::Waypoints(format!(
                "need at least 2 waypoints for a knot vector, got {n}"
            )));
        }
        let mut t = vec![T::zero_in(ctx)];
        for j in 0..n {
            t.push(T::from_ratio(j as i64, (n - 1) as i64, ctx));
        }
        t.push(T::one_in(ctx));
        Knots::new(t)
    }

    /// Knot i, counted from 0 like every index of the API (`get(i)` is the paper's
    /// t_{i+1}); `None` past the last knot, i > n + 1.
    pub fn get(&self, i: usize) -> Option<&T> {
        self.t.get(i)
    }

    /// Knot t_j (1-based) for the algorithms, whose indices come from the knot vector
    /// itself (1 ≤ j ≤ n + 2).
    pub(crate) fn at(&self, j: usize) -> &T {
        &self.t[j - 1]
    }

    /// The number n of basis functions (knots t_1 … t_{n+2}).
    pub fn basis_count(&self) -> usize {
        self.t.len() - 2
    }

    /// The knots as a slice.
    pub fn as_slice(&self) -> &[T] {
        &self.t
    }

    /// The non-empty knot interval i holding t, counted from 0 (from knot i to knot i + 1:
    /// the paper's (t_{i+1}, t_{i+2})), with knot i ≤ t < knot i + 1 from the right or
    /// knot i < t ≤ knot i + 1 from the left; `None` outside the knots' range.
    pub fn interval(&self, t: &T, side: Side) -> Option<usize> {
        self.paper_interval(t, side).map(|j| j - 1)
    }

    /// [`Knots::interval`] in the paper's numbering: the j with t_j ≤ t < t_{j+1} (from
    /// the right), 1 ≤ j ≤ n + 1, as the algorithms and the [`Blend`] trait count.
    pub(crate) fn paper_interval(&self, t: &T, side: Side) -> Option<usize> {
        let m = self.t.len();
        (1..m)
            .filter(|&j| self.t[j - 1] < self.t[j])
            .find(|&j| match side {
                Side::Right => self.t[j - 1] <= *t && *t < self.t[j],
                Side::Left => self.t[j - 1] < *t && *t <= self.t[j],
            })
            .or_else(|| {
                // The end points: the only interval that reaches them.
                let first = (1..m).find(|&j| self.t[j - 1] < self.t[j])?;
                let last = (1..m).rev().find(|&j| self.t[j - 1] < self.t[j])?;
                if *t == self.t[0] {
                    Some(first)
                } else if *t == self.t[m - 1] {
                    Some(last)
                } else {
                    None
                }
            })
    }
}

/// Which one-sided limit to take at a knot.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// The limit from the left (t → t_j⁻).
    Left,
    /// The limit from the right (t → t_j⁺).
    Right,
}

/// The rising function F_j of one kind of GERBS on each knot interval (Eq. 6).
pub trait Blend<T: Field> {
    /// The Taylor series of F_j at t ∈ [t_j, t_{j+1}] to `order` (interval j in the paper's
    /// 1-based numbering).
    fn rising(&self, knots: &Knots<T>, j: usize, t: &T, order: usize) -> Taylor<T>;

    /// The series of 1 − F_j at t. Kinds override it to compute the complement directly:
    /// near t_{j+1}, where 1 − F_j is tiny, subtracting from 1 would leave only absolute
    /// accuracy.
    fn falling(&self, knots: &Knots<T>, j: usize, t: &T, order: usize) -> Taylor<T> {
        Taylor::constant(T::one_in(&t.ctx())).with_order(order) - &self.rising(knots, j, t, order)
    }

    /// Both 1 − F_j and F_j at t (kinds whose F_j is a quadrature compute it once).
    fn pair(&self, knots: &Knots<T>, j: usize, t: &T, order: usize) -> (Taylor<T>, Taylor<T>) {
        (
            self.falling(knots, j, t, order),
            self.rising(knots, j, t, order),
        )
    }

    /// F_j at a located parameter (interval j = `at.interval`). Kinds that can use the
    /// distances to the interval's ends override it (the BFBS is a polynomial in them);
    /// by default the distances are not used.
    fn rising_located(&self, knots: &Knots<T>, at: &Located<T>, order: usize) -> Taylor<T> {
        self.rising(knots, at.interval, &at.t, order)
    }

    /// 1 − F_j at a located parameter (see [`Blend::rising_located`]).
    fn falling_located(&self, knots: &Knots<T>, at: &Located<T>, order: usize) -> Taylor<T> {
        self.falling(knots, at.interval, &at.t, order)
    }

    /// Both 1 − F_j and F_j at a located parameter. Kinds whose F_j is a quadrature
    /// override it to compute F_j once for both.
    fn pair_located(
        &self,
        knots: &Knots<T>,
        at: &Located<T>,
        order: usize,
    ) -> (Taylor<T>, Taylor<T>) {
        (
            self.falling_located(knots, at, order),
            self.rising_located(knots, at, order),
        )
    }

    /// F_j′(t).
    fn slope(&self, knots: &Knots<T>, j: usize, t: &T) -> T {
        self.rising(knots, j, t, 1).derivatives()[1].clone()
    }

    /// F_j′ as a series of `order` at t inside interval j. Kinds whose F_j is a quadrature
    /// override it to give the integrand's series without the quadrature.
    fn slope_series(&self, knots: &Knots<T>, j: usize, t: &T, order: usize) -> Taylor<T> {
        self.rising(knots, j, t, order + 1).derivative_series()
    }

    /// An enclosure of F_j′ at every point of [lo, hi] that lies in interval j, for the
    /// pieces where its series is not finite (an essential singularity at a knot); `None`
    /// (the default) where the kind has no such bound.
    fn slope_range(&self, knots: &Knots<T>, j: usize, lo: &T, hi: &T) -> Option<T> {
        let _ = (knots, j, lo, hi);
        None
    }

    /// Whether F_j is a quadrature, so that a sweep over many points (a path length) should
    /// carry F_j from one point to the next with [`Blend::increment`] instead of integrating
    /// from a knot every time.
    fn sweeps(&self) -> bool {
        false
    }

    /// F_j(to) − F_j(from).
    fn increment(&self, knots: &Knots<T>, j: usize, from: &T, to: &T) -> T {
        self.rising(knots, j, to, 0).value().clone() - self.rising(knots, j, from, 0).value()
    }

    /// Points inside interval j where F_j is less smooth (quadrature splits there).
    fn break_points(&self, knots: &Knots<T>, j: usize) -> Vec<T> {
        let _ = (knots, j);
        Vec::new()
    }

    /// The number of basis functions the blend was built for, when it fixes one (a BFBS has
    /// one exponent per basis function); `None`, the default, for a blend that fits any
    /// knot vector.
    fn basis_count(&self) -> Option<usize> {
        None
    }

    /// The knots the blend was built on, when it depends on them (an ERBS keeps one
    /// normalizer per knot interval); `None`, the default, for a blend that fits any knot
    /// vector. A path refuses a blend built on other knots.
    fn built_on(&self) -> Option<&[T]> {
        None
    }
}

/// The series of B_2 … B_{n+1} at t to `order`, from the side `side` at a knot; every basis
/// function outside its support is the zero series. `None` outside [t_1, t_{n+2}].
pub fn basis_series<T: Field, B: Blend<T> + ?Sized>(
    knots: &Knots<T>,
    blend: &B,
    t: &T,
    order: usize,
    side: Side,
) -> Option<Vec<Taylor<T>>> {
    let j = knots.paper_interval(t, side)?;
    Some(basis_series_on(knots, blend, t, j, order))
}

/// A parameter t in knot interval j (the paper's 1-based j, t_j ≤ t ≤ t_{j+1}: interval
/// j − 1 of [`Knots::interval`]) with its distances to the interval's ends. A caller with t exact chooses j on the exact value ([`Knots::interval`])
/// and forms the distances exactly, rounding each once: rounding t onto a knot then switches
/// no branch, and a basis function that vanishes at the knot like (t − t_j)^i keeps its
/// relative accuracy (t − t_j formed from a rounded t would be 0).
#[derive(Clone, Debug)]
pub struct Located<T> {
    /// t itself.
    pub t: T,
    /// The knot interval j.
    pub interval: usize,
    /// t − t_j.
    pub after_start: T,
    /// t_{j+1} − t.
    pub before_end: T,
}

impl<T: Field> Located<T> {
    /// t in interval j, the distances formed from t.
    pub fn from_t(knots: &Knots<T>, t: &T, j: usize) -> Self {
        Located {
            t: t.clone(),
            interval: j,
            after_start: t.clone() - knots.at(j),
            before_end: knots.at(j + 1).clone() - t,
        }
    }
}

/// The series of B_2 … B_{n+1} at t to `order` on the knot interval j (1-based: t_j ≤ t ≤
/// t_{j+1}, non-empty), which the caller chose — for a parameter given exactly, by
/// [`Knots::interval`] on the exact value, so that rounding t onto a knot cannot switch
/// the one-sided branch (the rounded t stays in the closed interval, where the pieces on
/// interval j are their own smooth continuation).
pub fn basis_series_on<T: Field, B: Blend<T> + ?Sized>(
    knots: &Knots<T>,
    blend: &B,
    t: &T,
    j: usize,
    order: usize,
) -> Vec<Taylor<T>> {
    basis_series_located(knots, blend, &Located::from_t(knots, t, j), order)
}

/// The series of B_2 … B_{n+1} at a located parameter (see [`Located`]).
pub fn basis_series_located<T: Field, B: Blend<T> + ?Sized>(
    knots: &Knots<T>,
    blend: &B,
    at: &Located<T>,
    order: usize,
) -> Vec<Taylor<T>> {
    let n = knots.basis_count();
    let j = at.interval;
    let ctx = at.t.ctx();
    let zero = Taylor::constant(T::zero_in(&ctx)).with_order(order);
    let mut out = vec![zero; n];
    // On (t_j, t_{j+1}): B_j = 1 − F_j falls, B_{j+1} = F_j rises (B_k is index k − 2).
    // Each is computed on its own, so Σ B_k = 1 is a property, not a construction.
    match ((2..=n + 1).contains(&j), (2..=n + 1).contains(&(j + 1))) {
        (true, true) => {
            let (falling, rising) = blend.pair_located(knots, at, order);
            out[j - 2] = falling;
            out[j - 1] = rising;
        }
        (true, false) => out[j - 2] = blend.falling_located(knots, at, order),
        (false, true) => out[j - 1] = blend.rising_located(knots, at, order),
        (false, false) => {}
    }
    out
}

/// The derivatives B_k, B_k′, …, B_k^(order) of every basis function at t (k = 2 … n+1).
pub fn basis_derivatives<T: Field, B: Blend<T> + ?Sized>(
    knots: &Knots<T>,
    blend: &B,
    t: &T,
    order: usize,
    side: Side,
) -> Option<Vec<Vec<T>>> {
    basis_series(knots, blend, t, order, side).map(|s| s.iter().map(|b| b.derivatives()).collect())
}

/// As [`basis_derivatives`], at a parameter located by the caller ([`Located`]).
pub fn basis_derivatives_located<T: Field, B: Blend<T> + ?Sized>(
    knots: &Knots<T>,
    blend: &B,
    at: &Located<T>,
    order: usize,
) -> Vec<Vec<T>> {
    basis_series_located(knots, blend, at, order)
        .iter()
        .map(|b| b.derivatives())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::BigRational;

    #[test]
    fn knot_vectors_are_checked() {
        let k = Knots::<BigRational>::uniform(5, &()).expect("knots");
        let r = |n: i64, d: i64| BigRational::new(n.into(), d.into());
        assert_eq!(k.at(3), &r(1, 4));
        assert_eq!(k.basis_count(), 5);
        assert_eq!(k.paper_interval(&r(1, 4), Side::Right), Some(3));
        assert_eq!(k.paper_interval(&r(1, 4), Side::Left), Some(2));
        assert_eq!(k.paper_interval(&r(0, 1), Side::Left), Some(2));
        assert_eq!(k.paper_interval(&r(1, 1), Side::Right), Some(5));
        // The API counts from 0: knot 2 (= 1/4) to knot 3 from the right.
        assert_eq!(k.interval(&r(1, 4), Side::Right), Some(2));
        assert_eq!(k.interval(&r(1, 4), Side::Left), Some(1));
        assert_eq!(k.get(2), Some(&r(1, 4)));
        assert!(Knots::new(vec![0.0, 0.5, 0.5, 1.0]).is_err());
        assert!(Knots::new(vec![0.0, 0.0, 0.5, 1.0, 1.0]).is_ok());
        assert!(Knots::new(vec![0.0, 0.0, 0.0, 1.0]).is_err());
    }
}
