//! Natural cubic spline interpolation on arbitrary knots, over any [`Field`] (paper 004).
//!
//! For knots t₀ < … < t_N and ordinates z₀…z_N, with hᵢ = tᵢ − tᵢ₋₁, the second derivatives
//! mᵢ = θ″(tᵢ) satisfy m₀ = m_N = 0 and the tridiagonal system M·m = Q·z of paper 004
//! (Sec. 3): Mᵢ,ᵢ₋₁ = hᵢ/6, Mᵢᵢ = (hᵢ + hᵢ₊₁)/3, Mᵢ,ᵢ₊₁ = hᵢ₊₁/6 and
//! Qᵢ,ᵢ₋₁ = 1/hᵢ, Qᵢᵢ = −(1/hᵢ + 1/hᵢ₊₁), Qᵢ,ᵢ₊₁ = 1/hᵢ₊₁, i = 1…N−1. M is strictly diagonally
//! dominant, so elimination without pivoting (the Thomas algorithm) is stable; in rationals it
//! is exact. On [tᵢ₋₁, tᵢ], θ″ is linear between mᵢ₋₁ and mᵢ, so
//! ∫θ″² = Σᵢ hᵢ(mᵢ₋₁² + mᵢ₋₁mᵢ + mᵢ²)/3 = zᵀQᵀM⁻¹Qz (Eq. 31 for one component).

use crate::curve::parametric::{check_domain, CurveError, ParamCurve, ParamCurveArclen};
use crate::numeric::quadrature::gauss_legendre4;
use crate::scalar::ball::Ball;
use crate::scalar::{max_of, Field, Real};

/// Why a spline cannot be built.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum SplineError {
    /// Fewer than two knots.
    #[error("need at least two knots")]
    TooFewKnots,
    #[error("{knots} knots but {values} values")]
    /// Knots and values of different lengths.
    LengthMismatch {
        /// Number of knots.
        knots: usize,
        /// Number of values.
        values: usize,
    },
    #[error("{weights} weights α for {components} components")]
    /// A weight count that differs from the number of components.
    WeightCount {
        /// Number of weights α.
        weights: usize,
        /// Number of components.
        components: usize,
    },
    #[error("knot #{index} is not greater than the knot before it")]
    /// Knots that do not increase strictly.
    NotIncreasing {
        /// Index of the first knot not above its predecessor.
        index: usize,
    },
    #[error("points: {count} points, at most {max} (the minimization's cost grows as the cube of the count)")]
    /// More points than [`super::descent::MAX_PARAMETRIZE_POINTS`].
    TooManyPoints {
        /// The points given.
        count: usize,
        /// The most accepted.
        max: usize,
    },
    #[error("points: point #{index} repeats the point before it (no parametrization gives it a spacing)")]
    /// Two consecutive points that coincide.
    RepeatedPoint {
        /// Index of the repeat.
        index: usize,
    },
    #[error("alpha: weight #{index} is not a positive finite number")]
    /// A weight α_l that is zero, negative or not finite.
    BadWeight {
        /// Its index.
        index: usize,
    },
    #[error("{field} #{index} is not finite")]
    /// A knot or a value that is NaN or infinite.
    NotFinite {
        /// "knot" or "value".
        field: &'static str,
        /// Its index.
        index: usize,
    },
}

/// The natural cubic spline through (tᵢ, zᵢ).
#[derive(Clone, Debug)]
pub struct NaturalCubicSpline<T> {
    knots: Vec<T>,
    /// hᵢ = tᵢ − tᵢ₋₁ (`spacings[i − 1]`): the differences of the knots, or the exact
    /// spacings rounded once ([`NaturalCubicSpline::with_spacings`]).
    spacings: Vec<T>,
    values: Vec<T>,
    /// θ″ at the knots (zero at both ends).
    second: Vec<T>,
}

/// At least two knots, and one value per knot.
pub(super) fn check_lengths<T>(knots: &[T], values: &[T]) -> Result<(), SplineError> {
    if knots.len() < 2 {
        return Err(SplineError::TooFewKnots);
    }
    if knots.len() != values.len() {
        return Err(SplineError::LengthMismatch {
            knots: knots.len(),
            values: values.len(),
        });
    }
    Ok(())
}

/// Knots that increase strictly ([`SplineError::NotIncreasing`] names the first that does not).
pub(super) fn check_increasing<T: PartialOrd>(knots: &[T]) -> Result<(), SplineError> {
    match (1..knots.len()).find(|&i| knots[i] <= knots[i - 1]) {
        Some(index) => Err(SplineError::NotIncreasing { index }),
        None => Ok(()),
    }
}

/// The piece i with t in [tᵢ₋₁, tᵢ] of increasing `knots` t₀ < … < t_N, clamped to the first
/// and last piece: the first i ≥ 1 with t ≤ tᵢ, found by bisection. Generic over the knots'
/// type, so that a caller locates a point on its exact knots whatever type the spline is in.
pub fn piece_index<K: PartialOrd>(knots: &[K], t: &K) -> usize {
    let first_not_below = 1 + knots.get(1..).unwrap_or(&[]).partition_point(|k| k < t);
    first_not_below.min(knots.len().saturating_sub(1))
}

impl<T: Field> NaturalCubicSpline<T> {
    /// The natural cubic spline (zero second derivative at both ends) through (knots, values).
    ///
    /// # Errors
    /// [`SplineError::TooFewKnots`] for fewer than two knots; [`SplineError::LengthMismatch`]
    /// unless one value per knot; [`SplineError::NotIncreasing`] for the first knot not greater
    /// than the one before.
    pub fn new(knots: Vec<T>, values: Vec<T>) -> Result<Self, SplineError> {
        check_lengths(&knots, &values)?;
        for (field, list) in [("knot", &knots), ("value", &values)] {
            if let Some(index) = list.iter().position(|x| !x.is_finite()) {
                return Err(SplineError::NotFinite { field, index });
            }
        }
        check_increasing(&knots)?;
        Self::with_increasing_knots(knots, values)
    }

    /// As [`NaturalCubicSpline::new`] for knots the caller knows to increase (decided on
    /// exact values they were rounded from): the order is not compared again, so a ball
    /// whose knots overlap after rounding still gets its enclosure.
    ///
    /// # Errors
    /// [`SplineError::TooFewKnots`] or [`SplineError::LengthMismatch`] as
    /// [`NaturalCubicSpline::new`]; never [`SplineError::NotIncreasing`].
    pub fn with_increasing_knots(knots: Vec<T>, values: Vec<T>) -> Result<Self, SplineError> {
        let spacings = knots.windows(2).map(|w| w[1].clone() - &w[0]).collect();
        Self::with_spacings(knots, spacings, values)
    }

    /// As [`NaturalCubicSpline::with_increasing_knots`] with the spacings hᵢ = tᵢ − tᵢ₋₁
    /// given (`spacings[i − 1]`): a caller that has the knots exactly forms each spacing
    /// exactly and rounds it once, so knots 1e-30 apart keep a spacing of 1e-30 at any
    /// precision where their rounded values coincide.
    ///
    /// # Errors
    /// As [`NaturalCubicSpline::with_increasing_knots`], and
    /// [`SplineError::LengthMismatch`] unless one spacing per interval.
    pub fn with_spacings(
        knots: Vec<T>,
        spacings: Vec<T>,
        values: Vec<T>,
    ) -> Result<Self, SplineError> {
        check_lengths(&knots, &values)?;
        if spacings.len() + 1 != knots.len() {
            return Err(SplineError::LengthMismatch {
                knots: knots.len(),
                values: spacings.len() + 1,
            });
        }
        let second = second_derivatives(&spacings, &values);
        Ok(NaturalCubicSpline {
            knots,
            spacings,
            values,
            second,
        })
    }

    /// The knots t_0 < … < t_N.
    pub fn knots(&self) -> &[T] {
        &self.knots
    }

    /// θ″ at the knots.
    pub fn second_derivatives_at_knots(&self) -> &[T] {
        &self.second
    }

    /// The interval index i with t in [tᵢ₋₁, tᵢ] ([`piece_index`]).
    fn interval(&self, t: &T) -> usize {
        piece_index(&self.knots, t)
    }

    /// (θ, θ′, θ″)(t); outside [t₀, t_N] the end cubic pieces are extended.
    pub fn eval_all(&self, t: &T) -> [T; 3] {
        self.eval_on(t, self.interval(t))
    }

    /// (θ, θ′, θ″)(t) on the piece [tᵢ₋₁, tᵢ] (1 ≤ i ≤ N) the caller chose — for a t given
    /// exactly, located on its exact value (the spline is C², so a t within rounding of a
    /// knot gets the same value from either piece, but a ball at a knot could not decide
    /// which). An out-of-range i is clamped to the first or last piece.
    pub fn eval_on(&self, t: &T, i: usize) -> [T; 3] {
        let i = i.clamp(1, self.knots.len() - 1);
        let (a, b) = (&self.knots[i - 1], &self.knots[i]);
        self.eval_offsets(&(b.clone() - t), &(t.clone() - a), i)
    }

    /// (θ, θ′, θ″) on the piece [tᵢ₋₁, tᵢ] at the point whose distances to its ends are
    /// u = tᵢ − t and v = t − tᵢ₋₁. A caller with t exact computes u and v exactly and rounds
    /// them once: near a knot they keep their relative accuracy, which t − tᵢ₋₁ formed from a
    /// rounded t would not (θ″ there is proportional to the distance).
    pub fn eval_offsets(&self, u: &T, v: &T, i: usize) -> [T; 3] {
        let i = i.clamp(1, self.knots.len() - 1);
        let ctx = u.ctx();
        let h = self.spacings[i - 1].clone();
        let (za, zb, ma, mb) = (
            &self.values[i - 1],
            &self.values[i],
            &self.second[i - 1],
            &self.second[i],
        );
        let six = T::from_i64(6, &ctx);
        let two = T::from_i64(2, &ctx);
        // θ = ma·u³/(6h) + mb·v³/(6h) + (za/h − ma·h/6)·u + (zb/h − mb·h/6)·v, regrouped with
        // h² − u² = v(h + u) and h = u + v so that no term cancels another when u or v is
        // tiny (the exact distances then give the value its relative accuracy):
        // θ = (za·u + zb·v)/h − u·v·(ma·(2u + v) + mb·(u + 2v))/(6h).
        let value = (za.clone() * u + &(zb.clone() * v)) / &h
            - &(u.clone()
                * v
                * &(ma.clone() * &(two.clone() * u + v)
                    + &(mb.clone() * &(u.clone() + &(two.clone() * v))))
                / &(six.clone() * &h));
        // θ′ = (zb − za)/h + ma·(h² − 3u²)/(6h) + mb·(3v² − h²)/(6h).
        let three = T::from_i64(3, &ctx);
        let h2 = h.clone() * &h;
        let slope = (zb.clone() - za) / &h
            + &(ma.clone() * &(h2.clone() - &(three.clone() * u * u)) / &(six.clone() * &h))
            + &(mb.clone() * &(three * v * v - &h2) / &(six * &h));
        let curvature = (ma.clone() * u + &(mb.clone() * v)) / &h;
        [value, slope, curvature]
    }

    /// ∫ θ″² over [t₀, t_N], exactly from the piecewise-linear θ″.
    pub fn bending_energy(&self) -> T {
        let ctx = self.values[0].ctx();
        let three = T::from_i64(3, &ctx);
        let mut total = T::zero_in(&ctx);
        for i in 1..self.knots.len() {
            let h = self.spacings[i - 1].clone();
            let (a, b) = (&self.second[i - 1], &self.second[i]);
            let inner = a.clone() * a + &(a.clone() * b) + &(b.clone() * b);
            total += &(h * &inner / &three);
        }
        total
    }
}

impl<T: Real> NaturalCubicSpline<T> {
    /// The values of θ at its interior extrema on each interval (tᵢ₋₁, tᵢ), i = 1…N: θ′ is a
    /// quadratic on each interval, and its roots (by the cancellation-free quadratic formula)
    /// strictly inside the interval are the extrema that do not sit at a data point.
    pub fn interior_extreme_values(&self) -> Vec<Vec<T>> {
        let (t, m) = (&self.knots, &self.second);
        let ctx = t[0].ctx();
        let zero = T::zero_in(&ctx);
        (1..t.len())
            .map(|i| {
                let h = self.spacings[i - 1].clone();
                // θ′(t_{i−1} + v) = A v² + B v + C on [0, h].
                let a = (m[i].clone() - &m[i - 1]) / &(T::from_i64(2, &ctx) * &h);
                let b = m[i - 1].clone();
                // On the piece itself, by the distances to its ends (no knot is located: a
                // ball at a knot could not decide which piece holds it).
                let c = self.eval_offsets(&h, &zero, i)[1].clone();
                quadratic_roots(&a, &b, &c)
                    .into_iter()
                    .filter(|v| *v > zero && *v < h)
                    .map(|v| self.eval_offsets(&(h.clone() - &v), &v, i)[0].clone())
                    .collect()
            })
            .collect()
    }

    /// The overshoot on each interval [tᵢ₋₁, tᵢ], i = 1…N: how far θ leaves the range
    /// [min(zᵢ₋₁, zᵢ), max(zᵢ₋₁, zᵢ)] of its end values (zero when it stays inside). This is
    /// the overshoot of paper 004, Corollary 3 (i) and Fig. 9: an interpolant without
    /// overshoot has its extrema at the data.
    pub fn overshoots(&self) -> Vec<T> {
        let z = &self.values;
        let zero = T::zero_in(&z[0].ctx());
        self.interior_extreme_values()
            .into_iter()
            .enumerate()
            .map(|(k, extremes)| {
                // The range of the end values without comparing them (for balls, two equal
                // data that are not exact binary numbers cannot be ordered, and need not be).
                let (lo, hi) = (z[k].min_with(&z[k + 1]), z[k].max_with(&z[k + 1]));
                extremes
                    .into_iter()
                    .map(|value| {
                        let beyond = max_of(value.clone() - &hi, lo.clone() - &value);
                        max_of(beyond, zero.clone())
                    })
                    .fold(zero.clone(), |a, b| a.max_with(&b))
            })
            .collect()
    }

    /// ‖θ − φ‖²_H¹ = ∫ (θ − φ)² + (θ′ − φ′)² over [t₀, t_N], with φ the piecewise-linear
    /// interpolant of the same data (paper 004, Sec. 1 (i), bounds it by ∫θ″²). On each
    /// interval θ − φ is a cubic, so both integrands (degrees 6 and 4) are integrated exactly
    /// by the 4-point Gauss–Legendre rule.
    pub fn h1_distance_to_polyline_squared(&self) -> T {
        let (t, z) = (&self.knots, &self.values);
        let ctx = z[0].ctx();
        let nodes = gauss_legendre4::<T>(&ctx);
        let mut h1 = T::zero_in(&ctx);
        for i in 1..t.len() {
            let h = self.spacings[i - 1].clone();
            let slope = (z[i].clone() - &z[i - 1]) / &h;
            for (x, w) in &nodes {
                let at = t[i - 1].clone() + &(h.clone() * x);
                let [v, d, _] = self.eval_all(&at);
                let e = v - &(z[i - 1].clone() + &(slope.clone() * &(at - &t[i - 1])));
                let de = d - &slope;
                h1 += &((e.clone() * &e + &(de.clone() * &de)) * w * &h);
            }
        }
        h1
    }
}

/// The real roots of A v² + B v + C (all of them; none if A = B = 0). The larger-magnitude
/// root comes from q = −(B + sign(B)√(B² − 4AC))/2, the other from C/q, so neither suffers
/// cancellation.
fn quadratic_roots<T: Real>(a: &T, b: &T, c: &T) -> Vec<T> {
    let ctx = a.ctx();
    let zero = T::zero_in(&ctx);
    if a.is_zero() {
        return if b.is_zero() {
            Vec::new()
        } else {
            vec![-(c.clone() / b)]
        };
    }
    let discriminant = b.clone() * b - &(T::from_i64(4, &ctx) * a * c);
    if discriminant < zero {
        return Vec::new();
    }
    let root = discriminant.sqrt();
    let q = if *b >= zero {
        -(b.clone() + &root)
    } else {
        root - b
    } / &T::from_i64(2, &ctx);
    if q.is_zero() {
        return vec![zero];
    }
    vec![q.clone() / a, c.clone() / &q]
}

/// Solve M·m = Q·z for the interior second derivatives (Thomas algorithm) from the spacings
/// (`h[i − 1]` = hᵢ); m₀ = m_N = 0.
fn second_derivatives<T: Field>(h: &[T], z: &[T]) -> Vec<T> {
    let n = h.len();
    let ctx = z[0].ctx();
    let mut m = vec![T::zero_in(&ctx); n + 1];
    if n < 2 {
        return m;
    }
    let (three, six) = (T::from_i64(3, &ctx), T::from_i64(6, &ctx));
    // Rows i = 1…N−1: sub = hᵢ/6, diag = (hᵢ + hᵢ₊₁)/3, sup = hᵢ₊₁/6, rhs = (Qz)ᵢ.
    let mut diag: Vec<T> = (1..n)
        .map(|i| (h[i - 1].clone() + &h[i]) / &three)
        .collect();
    let sub: Vec<T> = (1..n).map(|i| h[i - 1].clone() / &six).collect();
    let sup: Vec<T> = (1..n).map(|i| h[i].clone() / &six).collect();
    let mut rhs: Vec<T> = (1..n)
        .map(|i| (z[i + 1].clone() - &z[i]) / &h[i] - &((z[i].clone() - &z[i - 1]) / &h[i - 1]))
        .collect();
    for r in 1..n - 1 {
        let factor = sub[r].clone() / &diag[r - 1];
        let d = factor.clone() * &sup[r - 1];
        diag[r] -= &d;
        let b = factor * &rhs[r - 1];
        rhs[r] -= &b;
    }
    for r in (0..n - 1).rev() {
        let mut v = rhs[r].clone();
        if r + 1 < n - 1 {
            v -= &(sup[r].clone() * &m[r + 2]);
        }
        m[r + 1] = v / &diag[r];
    }
    m
}

impl<T: Field> NaturalCubicSpline<T> {
    /// θ, θ′, θ″, θ‴, … at t ∈ [t₀, t_N] on the piece that starts at t (the last piece at
    /// t_N): θ‴ = (mᵢ − mᵢ₋₁)/hᵢ there, and every higher derivative is 0.
    fn jet(&self, t: &T, order: usize) -> Result<Vec<T>, CurveError> {
        let n = self.knots.len() - 1;
        check_domain(t, (&self.knots[0], &self.knots[n]))?;
        let i = (1 + self.knots[1..].partition_point(|k| k <= t)).min(n);
        let [value, slope, curvature] = self.eval_on(t, i);
        let h = self.spacings[i - 1].clone();
        let third = (self.second[i].clone() - &self.second[i - 1]) / &h;
        let zero = T::zero_in(&t.ctx());
        let mut jet = vec![value, slope, curvature, third];
        jet.resize(order + 1, zero);
        Ok(jet)
    }
}

impl NaturalCubicSpline<Ball> {
    /// Where θ′ may vanish on piece i (1 ≤ i ≤ N) — root isolation in ball arithmetic, with
    /// no comparison left undecided: θ′ is the quadratic A v² + B v + C in v = t − tᵢ₋₁ on
    /// [0, hᵢ]. An empty list when θ′ is enclosed away from 0 over the whole piece (θ is
    /// strictly monotone there: the enclosure of θ′ over the piece is computed by Horner's
    /// rule on the interval [0, hᵢ]) or has no real root (the discriminant's enclosure is
    /// negative); otherwise each real root's enclosure, clipped to [0, sup hᵢ] (a root proven
    /// outside the piece is dropped). Every root of θ′ on the piece lies in one of the balls
    /// returned; a ball need not hold a root (the discriminant may straddle 0).
    ///
    /// `None` for a piece index outside 1…N, or when a root cannot be enclosed (A may vanish
    /// while θ′ may change sign: the quadratic formula would divide by a ball holding 0).
    ///
    /// ```
    /// use trajverify::algo::param::natural::NaturalCubicSpline;
    /// use trajverify::scalar::{ball::Ball, Field};
    /// let ball = |n: i64| Ball::from_i64(n, &128);
    /// // Data 0, 1, 0 on knots 0, 1, 2: θ rises on the first piece and turns at t = 1.
    /// let s = NaturalCubicSpline::new(vec![ball(0), ball(1), ball(2)], vec![ball(0), ball(1), ball(0)])
    ///     .unwrap();
    /// let roots = s.slope_roots(1).unwrap();
    /// // The extremum at t = 1 (v = h = 1): every root of θ′ on [0, 1] is in the balls.
    /// assert!(roots.iter().any(|v| v.contains(&rug::Float::with_val(128, 1))));
    /// assert_eq!(s.slope_roots(3), None);
    /// ```
    pub fn slope_roots(&self, i: usize) -> Option<Vec<Ball>> {
        if i == 0 || i >= self.knots.len() {
            return None;
        }
        let h = &self.spacings[i - 1];
        let bits = h.mid().prec();
        let m = &self.second;
        let zero = Ball::zero_in(&bits);
        let two = Ball::from_i64(2, &bits);
        let a = (m[i].clone() - &m[i - 1]) / &(two.clone() * h);
        let b = m[i - 1].clone();
        let c = self.eval_offsets(h, &zero, i)[1].clone();
        let piece = Ball::hull(&zero, h);
        let slope = c.clone() + &(piece.clone() * &(b.clone() + &(piece * &a)));
        let discriminant = b.clone() * &b - &(Ball::from_i64(4, &bits) * &a * &c);
        if slope.lower() > 0 || slope.upper() < 0 || discriminant.upper() < 0 {
            return Some(Vec::new());
        }
        if a.lower() <= 0 && a.upper() >= 0 {
            return None;
        }
        // √ of the discriminant's non-negative part [max(lo, 0), hi].
        let root = discriminant.max_with(&zero).sqrt();
        let mut roots = Vec::new();
        for sign in [-1i64, 1] {
            let v = (-b.clone() + &(Ball::from_i64(sign, &bits) * &root)) / &(two.clone() * &a);
            if v.upper() < 0 || v.lower() > h.upper() {
                continue;
            }
            let low = v.lower().max(&rug::Float::with_val(bits, 0));
            let high = v.upper().min(&h.upper());
            roots.push(Ball::from_bounds(&low, &high));
        }
        Some(roots)
    }

    /// The pieces i (1 ≤ i ≤ N) whose interval [tᵢ₋₁, tᵢ] may meet the box `x` (knots that
    /// are balls count with their whole enclosure; a box beyond an end meets the end piece,
    /// which extends there as in [`NaturalCubicSpline::eval_all`]).
    pub fn pieces_meeting(&self, x: &Ball) -> Vec<usize> {
        let n = self.knots.len() - 1;
        let (lo, hi) = (x.lower(), x.upper());
        (1..=n)
            .filter(|&i| {
                let before = i == 1 || self.knots[i - 1].lower() <= hi;
                let after = i == n || self.knots[i].upper() >= lo;
                before && after
            })
            .collect()
    }

    /// Enclosures of (θ, θ′, θ″, θ‴) over every t in the box `x`: each piece that may meet the
    /// box ([`NaturalCubicSpline::pieces_meeting`]) evaluated on the whole box by the formulas
    /// of [`NaturalCubicSpline::eval_offsets`] (natural interval evaluation), θ‴ = (mᵢ − mᵢ₋₁)/hᵢ
    /// on a piece, and the hull taken over the pieces. This is an interval extension for a
    /// proven search ([`crate::numeric::maximum::proven_maximum`]); since θ″ is continuous and
    /// piecewise linear, θ‴'s hull also bounds θ″'s slope across a knot (a mean-value form of
    /// θ″ is valid). A box straddling a knot that is itself a ball is handled by the hull.
    ///
    /// ```
    /// use trajverify::algo::param::natural::NaturalCubicSpline;
    /// use trajverify::scalar::{ball::Ball, Field};
    /// use rug::Float;
    /// let ball = |n: i64| Ball::from_i64(n, &128);
    /// let s = NaturalCubicSpline::new(vec![ball(0), ball(1), ball(2)], vec![ball(0), ball(1), ball(0)])
    ///     .unwrap();
    /// let box_ = Ball::from_bounds(&Float::with_val(128, 0.5), &Float::with_val(128, 1.5));
    /// let [value, _, _, _] = s.enclose_over(&box_);
    /// // θ(1) = 1 lies in the box's enclosure, and so does θ(0.5).
    /// assert!(value.contains(&Float::with_val(128, 1)));
    /// assert!(value.contains(s.eval_all(&Ball::from_f64(0.5, &128))[0].mid()));
    /// ```
    pub fn enclose_over(&self, x: &Ball) -> [Ball; 4] {
        let mut hull: Option<[Ball; 4]> = None;
        for i in self.pieces_meeting(x) {
            let (a, b) = (&self.knots[i - 1], &self.knots[i]);
            let [value, slope, second] = self.eval_offsets(&(b.clone() - x), &(x.clone() - a), i);
            let third = (self.second[i].clone() - &self.second[i - 1]) / &self.spacings[i - 1];
            let piece = [value, slope, second, third];
            hull = Some(match hull {
                None => piece,
                Some(h) => [0, 1, 2, 3].map(|k| Ball::hull(&h[k], &piece[k])),
            });
        }
        // pieces_meeting always returns at least one piece (a spline has N ≥ 1 pieces and
        // the first and last are taken beyond the ends); an empty hull cannot occur, but a
        // ball of infinite radius would be the honest answer if it did.
        hull.unwrap_or_else(|| {
            let unknown = Ball::new(rug::Float::with_val(x.mid().prec(), 0), f64::INFINITY);
            [unknown.clone(), unknown.clone(), unknown.clone(), unknown]
        })
    }
}

impl<T: Field> ParamCurve<T, 1> for NaturalCubicSpline<T> {
    fn domain(&self) -> (T, T) {
        (
            self.knots[0].clone(),
            self.knots[self.knots.len() - 1].clone(),
        )
    }
    fn derivatives(&self, t: &T, order: usize) -> Result<Vec<[T; 1]>, CurveError> {
        crate::curve::parametric::check_order(order)?;
        Ok(self.jet(t, order)?.into_iter().map(|x| [x]).collect())
    }
    fn breakpoints(&self) -> Vec<T> {
        self.knots[1..self.knots.len() - 1].to_vec()
    }
}

impl<T: Real> ParamCurveArclen<T, 1> for NaturalCubicSpline<T> {}

/// The interpolating curve of paper 004: through points p₀ … p_N of Rᴰ at knots
/// t₀ < … < t_N, one natural cubic spline per coordinate ([`NaturalCubicSpline`]), C² in t.
///
/// # Examples
/// Marin's knots for four points of the plane ([`super::descent::parametrize`]) and the
/// spline through the points on them:
/// ```
/// use trajverify::algo::param::descent::{parametrize, ParametrizeOptions};
/// use trajverify::algo::param::natural::NaturalSplineCurve;
/// use trajverify::curve::parametric::ParamCurve;
///
/// let points = [[0.0, 0.0], [1.0, 2.0], [3.0, 3.0], [4.0, 1.0]];
/// let knots = parametrize(&points, &ParametrizeOptions::default()).unwrap().knots;
/// let curve = NaturalSplineCurve::new(knots.clone(), &points).unwrap();
/// let p = curve.point(&knots[2]).unwrap();
/// assert!((p[0] - 3.0).abs() < 1e-12 && (p[1] - 3.0).abs() < 1e-12);
/// assert_eq!(curve.derivative(&0.0, 2).unwrap(), [0.0, 0.0]); // natural end condition
/// ```
#[derive(Clone, Debug)]
pub struct NaturalSplineCurve<T, const D: usize> {
    components: Vec<NaturalCubicSpline<T>>,
}

impl<T: Field, const D: usize> NaturalSplineCurve<T, D> {
    /// The curve through `points` at `knots`.
    ///
    /// # Errors
    /// The errors of [`NaturalCubicSpline::new`] (too few knots, one point per knot,
    /// increasing knots); [`SplineError::LengthMismatch`] for D = 0.
    pub fn new(knots: Vec<T>, points: &[[T; D]]) -> Result<Self, SplineError> {
        if D == 0 {
            return Err(SplineError::LengthMismatch {
                knots: knots.len(),
                values: 0,
            });
        }
        let components = (0..D)
            .map(|c| {
                let values = points.iter().map(|p| p[c].clone()).collect();
                NaturalCubicSpline::new(knots.clone(), values)
            })
            .collect::<Result<Vec<_>, _>>()?;
        Ok(NaturalSplineCurve { components })
    }

    /// The spline of coordinate c.
    pub fn component(&self, c: usize) -> Option<&NaturalCubicSpline<T>> {
        self.components.get(c)
    }
}

impl<T: Field, const D: usize> ParamCurve<T, D> for NaturalSplineCurve<T, D> {
    fn domain(&self) -> (T, T) {
        self.components[0].domain()
    }
    fn derivatives(&self, t: &T, order: usize) -> Result<Vec<[T; D]>, CurveError> {
        crate::curve::parametric::check_order(order)?;
        let jets = self
            .components
            .iter()
            .map(|s| s.jet(t, order))
            .collect::<Result<Vec<_>, _>>()?;
        let jet = (0..=order)
            .map(|k| std::array::from_fn(|c| jets[c][k].clone()))
            .collect();
        crate::curve::parametric::finite_jet(jet, t)
    }
    fn breakpoints(&self) -> Vec<T> {
        self.components[0].breakpoints()
    }
}

impl<T: Real, const D: usize> ParamCurveArclen<T, D> for NaturalSplineCurve<T, D> {}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::BigRational;

    #[test]
    fn overshoot_is_the_excursion_beyond_the_end_values() {
        // Symmetric peak: the extremum sits on the middle knot, no overshoot.
        let sym = NaturalCubicSpline::new(vec![0.0, 0.5, 1.0], vec![0.0, 1.0, 0.0]).unwrap();
        assert_eq!(sym.overshoots(), vec![0.0, 0.0]);
        // Lopsided peak: θ′(0.1) > 0, so θ rises above 1 after the knot; the exact excursion
        // agrees with a dense sampling of the interval.
        let s = NaturalCubicSpline::new(vec![0.0, 0.1, 1.0], vec![0.0, 1.0, 0.0]).unwrap();
        let over = s.overshoots();
        let sampled = (0..=100_000)
            .map(|k| s.eval_all(&(0.1 + 0.9 * f64::from(k) / 1e5))[0] - 1.0)
            .fold(0.0, f64::max);
        assert_eq!(over[0], 0.0);
        assert!(
            over[1] > 0.01 && (over[1] - sampled).abs() < 1e-9,
            "{over:?} {sampled}"
        );
    }

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    #[test]
    fn reproduces_cubic_free_data_and_interpolates() {
        // Linear data: θ is the line, no bending.
        let s = NaturalCubicSpline::new(
            vec![q(0, 1), q(1, 3), q(1, 1)],
            vec![q(1, 1), q(2, 1), q(4, 1)],
        )
        .unwrap();
        for (t, z) in s.knots().to_vec().iter().zip([q(1, 1), q(2, 1), q(4, 1)]) {
            assert_eq!(s.eval_all(t)[0], z);
        }
        let lin = NaturalCubicSpline::new(
            vec![q(0, 1), q(1, 4), q(1, 1)],
            vec![q(0, 1), q(1, 2), q(2, 1)],
        )
        .unwrap();
        assert_eq!(lin.bending_energy(), q(0, 1));
        assert_eq!(lin.eval_all(&q(1, 2)), [q(1, 1), q(2, 1), q(0, 1)]);
    }

    #[test]
    fn h1_distance_vanishes_on_a_line_and_is_bounded_by_the_energy() {
        use crate::scalar::Float;
        let line = NaturalCubicSpline::new(vec![0.0, 1.0, 3.0], vec![1.0, 3.0, 7.0]).unwrap();
        assert!(line.h1_distance_to_polyline_squared().abs() < 1e-28);
        let f = |x: f64| Float::with_val(128, x);
        let bent =
            NaturalCubicSpline::new(vec![f(0.0), f(1.0), f(2.0)], vec![f(0.0), f(1.0), f(0.0)])
                .unwrap();
        let h1 = bent.h1_distance_to_polyline_squared();
        // Positive, and below ∫θ″² = 6 (Sec. 1 (i) of paper 004 on knots of spacing ≤ 1).
        assert!(h1 > 0 && h1 < bent.bending_energy(), "{h1}");
    }

    #[test]
    fn second_derivative_is_continuous_and_natural() {
        let t = vec![q(0, 1), q(1, 5), q(1, 2), q(7, 10), q(1, 1)];
        let z = vec![q(0, 1), q(1, 1), q(-1, 2), q(2, 1), q(1, 1)];
        let s = NaturalCubicSpline::new(t.clone(), z).unwrap();
        assert_eq!(s.eval_all(&t[0])[2], q(0, 1));
        assert_eq!(s.eval_all(&t[4])[2], q(0, 1));
        // θ′ continuous at an interior knot: compare the two pieces' formulas there.
        let eps = q(1, 1_000_000);
        let left = s.eval_all(&(t[2].clone() - &eps))[1].clone();
        let right = s.eval_all(&(t[2].clone() + &eps))[1].clone();
        assert!((left - right).abs() < q(1, 1000));
    }

    #[test]
    fn errors() {
        assert_eq!(
            NaturalCubicSpline::new(vec![q(0, 1)], vec![q(0, 1)]).unwrap_err(),
            SplineError::TooFewKnots
        );
        assert_eq!(
            NaturalCubicSpline::new(vec![q(0, 1), q(0, 1)], vec![q(0, 1), q(1, 1)]).unwrap_err(),
            SplineError::NotIncreasing { index: 1 }
        );
    }
}
