//! Expo-rational B-splines (ERBS, Eqs. 3–5) with intrinsic parameters (α, β, γ, λ, σ) per
//! knot interval.
//!
//! On (t_k, t_{k+1}) the kernel is
//!
//! Ψ_k(t) = exp(−β |t − c_k|^{2σ} / ((t − t_k)(t_{k+1} − t)^γ)^α),
//!
//! normalized by S_k = ∫ Ψ_k (Eq. 5), and B rises as F_k(t) = ∫_{t_k}^t Ψ_k / S_k (Eq. 3).
//! The centre c_k is where the numerator vanishes. The ERBS definition the paper cites
//! (Dechevsky, Lakså, Bang 2006) has c_k = (1 − λ)t_k + λ t_{k+1}, a point of the interval;
//! Eq. (4) as printed, |t − (1−λ)t_k + λt_{k+1}|, puts it at (1 − λ)t_k − λt_{k+1}, outside
//! the interval for knots ≥ 0. [`CentreReading`] selects one; the claims compare them.
//!
//! F_k is computed by tanh–sinh quadrature, split at c_k when 2σ is not an even integer
//! (|t − c|^{2σ} then has a kink there that would slow the rule down); near t_{k+1} the
//! complement 1 − ∫_t^{t_{k+1}} Ψ/S is used so that no digits cancel, and the falling
//! B_k = 1 − F_k there is ∫_t^{t_{k+1}} Ψ/S itself (no cancellation against 1; the
//! running integrals are accurate relative to S_k, so a tiny value near a knot carries fewer
//! significant digits, which the certified output shows). Derivatives are exact:
//! F′ = Ψ/S and the higher ones come from Ψ's own Taylor series.
//!
//! For α > 0 every derivative of Ψ vanishes at both knots (Ψ ~ exp(−C/(t − t_k)^α)), so the
//! basis is C^∞ at the knots; inside the interval Ψ is as smooth as |t − c|^{2σ}, that is
//! C^∞ when σ is an integer and otherwise only C^{⌈2σ⌉−1} at c (the Fig. 2 value σ = 0.2
//! gives a Ψ with an infinite slope at c, so B″ is unbounded there).

// `!(x > 0)` is meant: a NaN parameter must fail the range checks too.
#![allow(clippy::neg_cmp_op_on_partial_ord)]
use super::quadrature::{default_tolerance, TanhSinh};
use super::{Blend, GerbsError, Knots, Located};
use crate::curve::taylor::Taylor;
use crate::scalar::{powi, Field, Real};

/// [`ErbsParams::smooth`] in f64.
impl Default for ErbsParams<f64> {
    fn default() -> Self {
        ErbsParams::smooth(&())
    }
}

/// The intrinsic parameters of one knot interval. The fields are read through accessors:
/// a set is made by [`ErbsParams::new`] (checked against Eq. (4)'s ranges), [`ErbsParams::smooth`]
/// or `Default`, or, outside those ranges on purpose, [`ErbsParams::unchecked`].
#[derive(Clone, Debug, PartialEq)]
pub struct ErbsParams<T> {
    /// α: the exponent of the denominator (t − t_k)(t_{k+1} − t)^γ of Eq. (4).
    pub(crate) alpha: T,
    /// β: the scale of the exponent of Eq. (4).
    pub(crate) beta: T,
    /// γ: the exponent of (t_{j+1} − t) in Eq. (4).
    pub(crate) gamma: T,
    /// λ: the centre c_k = (1 − λ)t_k + λt_{k+1} of the kernel (the cited definition).
    pub(crate) lambda: T,
    /// σ: the exponent of |t − c| in Eq. (4).
    pub(crate) sigma: T,
}

impl<T: Real> ErbsParams<T> {
    /// The library's default set: α = β = γ = σ = 1, λ = 1/2 — the kernel centred in each
    /// interval with a whole σ, so the basis is C^∞ everywhere (the paper's Fig. 2 set,
    /// σ = 0.2, leaves the curvature unbounded at each interval's centre, and its α = 0 lies
    /// outside Eq. (4)'s range; see paper 003's claims `gerbs.fig2.parameters`,
    /// `gerbs.sec3.erbs_path_smooth`).
    pub fn smooth(ctx: &T::Ctx) -> Self {
        let one = T::one_in(ctx);
        ErbsParams::unchecked(
            one.clone(),
            one.clone(),
            one.clone(),
            T::from_ratio(1, 2, ctx),
            one,
        )
    }

    /// Parameters checked against the ranges of Eq. (4): α > 0, β > 0, γ > 0,
    /// 0 ≤ λ ≤ 1, σ ≥ 0.
    ///
    /// # Errors
    /// [`GerbsError::Parameter`] naming the first parameter out of range (`params.alpha`,
    /// `params.beta`, `params.gamma`, `params.lambda`, `params.sigma`); NaN is out of range.
    pub fn new(alpha: T, beta: T, gamma: T, lambda: T, sigma: T) -> Result<Self, GerbsError> {
        let p = ErbsParams::unchecked(alpha, beta, gamma, lambda, sigma);
        let ctx = p.alpha.ctx();
        let zero = T::zero_in(&ctx);
        let bad = |field: &'static str, message: &str| {
            Err(GerbsError::Parameter {
                field,
                message: message.into(),
            })
        };
        if !(p.alpha > zero) {
            return bad("params.alpha", "the ERBS needs alpha > 0");
        }
        if !(p.beta > zero) {
            return bad("params.beta", "the ERBS needs beta > 0");
        }
        if !(p.gamma > zero) {
            return bad("params.gamma", "the ERBS needs gamma > 0");
        }
        if !(p.lambda >= zero && p.lambda <= T::one_in(&ctx)) {
            return bad("params.lambda", "the ERBS needs 0 <= lambda <= 1");
        }
        if !(p.sigma >= zero) {
            return bad("params.sigma", "the ERBS needs sigma >= 0");
        }
        Ok(p)
    }

    /// Parameters taken as given, outside the ranges of Eq. (4) too (the claims evaluate the
    /// Fig. 2 caption's α = 0 literally).
    pub fn unchecked(alpha: T, beta: T, gamma: T, lambda: T, sigma: T) -> Self {
        ErbsParams {
            alpha,
            beta,
            gamma,
            lambda,
            sigma,
        }
    }

    /// α.
    pub fn alpha(&self) -> &T {
        &self.alpha
    }
    /// β.
    pub fn beta(&self) -> &T {
        &self.beta
    }
    /// γ.
    pub fn gamma(&self) -> &T {
        &self.gamma
    }
    /// λ.
    pub fn lambda(&self) -> &T {
        &self.lambda
    }
    /// σ.
    pub fn sigma(&self) -> &T {
        &self.sigma
    }

    /// The same parameters in another number type, each mapped by `f`.
    pub fn map<U>(&self, f: impl Fn(&T) -> U) -> ErbsParams<U> {
        ErbsParams {
            alpha: f(&self.alpha),
            beta: f(&self.beta),
            gamma: f(&self.gamma),
            lambda: f(&self.lambda),
            sigma: f(&self.sigma),
        }
    }

    /// 2σ as an even integer, when it is one: |t − c|^{2σ} is then a polynomial.
    fn even_power(&self) -> Option<u32> {
        let two_sigma = self.sigma.to_f64() * 2.0;
        let r = two_sigma.round();
        (r == two_sigma && r >= 0.0 && r % 2.0 == 0.0 && r < 64.0).then_some(r as u32)
    }
}

/// One parameter set, or one per knot interval.
///
/// # Errors
/// [`GerbsError::Parameter`] (`params`) for any other count.
pub(crate) fn check_param_count<T: Field, P>(
    knots: &Knots<T>,
    params: &[P],
) -> Result<(), GerbsError> {
    let intervals = knots.as_slice().len() - 1;
    if params.len() != 1 && params.len() != intervals {
        return Err(GerbsError::Parameter {
            field: "params",
            message: format!(
                "give one value or one per knot interval ({intervals}), got {}",
                params.len()
            ),
        });
    }
    Ok(())
}

/// x as a small whole number, when it is exactly one.
fn whole<T: Real>(x: &T) -> Option<u32> {
    let r = x.to_f64().round();
    ((1.0..=64.0).contains(&r) && T::from_i64(r as i64, &x.ctx()) == *x).then_some(r as u32)
}

/// Where the numerator of Ψ_k vanishes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CentreReading {
    /// c_k = (1 − λ)t_k + λt_{k+1}: the cited ERBS definition.
    Cited,
    /// c_k = (1 − λ)t_k − λt_{k+1}: Eq. (4) as printed.
    AsPrinted,
}

/// An ERBS basis: parameters per knot interval (a single set is used for all).
#[derive(Clone, Debug)]
pub struct Erbs<T> {
    /// The knots the normalizers were computed on.
    knots: Vec<T>,
    params: Vec<ErbsParams<T>>,
    reading: CentreReading,
    /// S_j per interval j (paper numbering, index j − 1), zero for empty intervals.
    scale: Vec<T>,
    /// The quadrature rule of the working precision, shared by every integral.
    rule: TanhSinh<T>,
}

/// The most halvings of the tanh–sinh step for one integral.
const MAX_LEVEL: usize = 14;

impl<T: Real> Erbs<T> {
    /// The basis on `knots` with `params` (one set, or one per interval t_j…t_{j+1},
    /// j = 1 … n+1); computes every S_j by quadrature.
    ///
    /// # Errors
    /// [`GerbsError::Parameter`] (`params`) unless one set or one per knot interval is given; the
    /// sets themselves are not checked ([`ErbsParams::new`] does that).
    ///
    /// # Examples
    /// A path through five waypoints blended by the ERBS with the default parameters
    /// (α = β = γ = σ = 1, λ = ½): it passes through each waypoint at its knot.
    /// ```
    /// use trajverify::algo::gerbs::erbs::{CentreReading, Erbs, ErbsParams};
    /// use trajverify::algo::gerbs::path::{GerbsPath, PathSpec};
    /// use trajverify::algo::gerbs::{Knots, Side};
    /// let waypoints = vec![[0.0, 0.0], [300.0, 100.0], [600.0, -50.0], [900.0, 150.0], [1200.0, 0.0]];
    /// let knots = Knots::<f64>::uniform(5, &()).unwrap();
    /// let erbs = Erbs::new(&knots, vec![ErbsParams::default()], CentreReading::Cited).unwrap();
    /// let path = GerbsPath::new(&PathSpec::new(waypoints, 80.0, &()), erbs).unwrap();
    /// let w2 = path.at_knot(2, Side::Right).unwrap(); // knot 2 carries waypoint W2
    /// assert!((w2.point[0] - 300.0).abs() < 1e-9 && (w2.point[1] - 100.0).abs() < 1e-9);
    /// ```
    pub fn new(
        knots: &Knots<T>,
        params: Vec<ErbsParams<T>>,
        reading: CentreReading,
    ) -> Result<Self, GerbsError> {
        check_param_count(knots, &params)?;
        Ok(Erbs::with_normalizers(knots, params, reading, |erbs, j| {
            erbs.integral(knots, j, knots.at(j), knots.at(j + 1))
        }))
    }

    /// The basis with each S_j computed by `normalize(basis, j)` for the non-empty intervals
    /// (a proven quadrature for balls: [`super::proven_erbs`]); the parameter count is the
    /// caller's to check.
    pub(crate) fn with_normalizers(
        knots: &Knots<T>,
        params: Vec<ErbsParams<T>>,
        reading: CentreReading,
        normalize: impl Fn(&Erbs<T>, usize) -> T,
    ) -> Self {
        let intervals = knots.as_slice().len() - 1;
        let mut erbs = Erbs {
            knots: knots.as_slice().to_vec(),
            params,
            reading,
            scale: Vec::new(),
            rule: TanhSinh::new(&knots.at(1).ctx(), MAX_LEVEL),
        };
        erbs.scale = (1..=intervals)
            .map(|j| {
                let (a, b) = (knots.at(j), knots.at(j + 1));
                if a < b {
                    normalize(&erbs, j)
                } else {
                    T::zero_in(&a.ctx())
                }
            })
            .collect();
        erbs
    }

    /// The parameters of interval j.
    pub fn params(&self, j: usize) -> &ErbsParams<T> {
        &self.params[if self.params.len() == 1 { 0 } else { j - 1 }]
    }

    /// S_j = ∫_{t_j}^{t_{j+1}} Ψ_j (Eq. 5; 1/S_j of Eq. 8 for the BFBS).
    pub fn normalizer(&self, j: usize) -> &T {
        &self.scale[j - 1]
    }

    /// t − c_j written from the distance `left` = t − t_j, without cancellation near t_j.
    fn offset<R: Real>(&self, knots: &Knots<T>, j: usize, left: &R, lift: &impl Fn(&T) -> R) -> R {
        let p = self.params(j);
        let (a, b) = (knots.at(j), knots.at(j + 1));
        match self.reading {
            CentreReading::Cited => left.clone() - &lift(&(p.lambda.clone() * &(b.clone() - a))),
            CentreReading::AsPrinted => {
                left.clone() + &lift(&(p.lambda.clone() * &(a.clone() + b)))
            }
        }
    }

    /// The centre c_j of interval j under this basis's reading of Eq. (4), inside the
    /// interval or not.
    pub fn centre_point(&self, knots: &Knots<T>, j: usize) -> T {
        let (a, b) = (knots.at(j), knots.at(j + 1));
        let p = self.params(j);
        let one = T::one_in(&a.ctx());
        match self.reading {
            CentreReading::Cited => (one - &p.lambda) * a + &(p.lambda.clone() * b),
            CentreReading::AsPrinted => (one - &p.lambda) * a - &(p.lambda.clone() * b),
        }
    }

    /// The centre c_j if it lies strictly inside the interval.
    pub fn centre(&self, knots: &Knots<T>, j: usize) -> Option<T> {
        let c = self.centre_point(knots, j);
        (c > *knots.at(j) && c < *knots.at(j + 1)).then_some(c)
    }

    /// Ψ_j (unnormalized) in any Real R (T itself or a Taylor series over T), from the
    /// distances to both knots.
    pub fn kernel<R: Real>(
        &self,
        knots: &Knots<T>,
        j: usize,
        left: &R,
        right: &R,
        lift: impl Fn(&T) -> R,
    ) -> R {
        let x = self.offset(knots, j, left, &lift);
        self.kernel_at_offset(j, left, right, &x, lift)
    }

    /// [`Erbs::kernel`] with t − c_j given (exact next to the centre, where computing it from
    /// the distance to t_j would cancel).
    pub fn kernel_at_offset<R: Real>(
        &self,
        j: usize,
        left: &R,
        right: &R,
        x: &R,
        lift: impl Fn(&T) -> R,
    ) -> R {
        let p = self.params(j);
        let ctx = left.ctx();
        let numerator = match p.even_power() {
            Some(e) => powi(x, e),
            None => (lift(&p.sigma) * &R::from_i64(2, &ctx) * &x.abs().ln()).exp(),
        };
        if p.alpha.is_zero() {
            // α = 0 (outside Eq. 4's range, the Fig. 2 caption): no denominator, so Ψ is
            // defined at the knots too.
            return (-(lift(&p.beta) * &numerator)).exp();
        }
        // ((t − t_j)(t_{j+1} − t)^γ)^α: by multiplication when α and γ are whole numbers
        // (one exp per evaluation instead of three transcendentals).
        let denominator = match (whole(&p.alpha), whole(&p.gamma)) {
            (Some(a), Some(g)) => powi(&(left.clone() * &powi(right, g)), a),
            _ => (lift(&p.alpha) * &(left.ln() + &(lift(&p.gamma) * &right.ln()))).exp(),
        };
        (-(lift(&p.beta) * &numerator / &denominator)).exp()
    }

    /// ∫_lo^hi Ψ_j for t_j ≤ lo < hi ≤ t_{j+1}, split at the centre.
    pub fn integral(&self, knots: &Knots<T>, j: usize, lo: &T, hi: &T) -> T {
        let ctx = lo.ctx();
        if lo >= hi {
            return T::zero_in(&ctx);
        }
        let mut cuts = vec![lo.clone()];
        let centre = self
            .centre(knots, j)
            .filter(|_| self.params(j).even_power().is_none());
        if let Some(c) = &centre {
            if c > lo && c < hi {
                cuts.push(c.clone());
            }
        }
        cuts.push(hi.clone());
        let (a, b) = (knots.at(j), knots.at(j + 1));
        let tol = default_tolerance::<T>(&ctx);
        let mut total = T::zero_in(&ctx);
        for w in cuts.windows(2) {
            let (p, q) = (&w[0], &w[1]);
            let before = p.clone() - a; // t_j … p
            let after = b.clone() - q; // q … t_{j+1}
            let starts_at_centre = centre.as_ref() == Some(p);
            let ends_at_centre = centre.as_ref() == Some(q);
            let f = |l: &T, r: &T| {
                let (left, right) = (before.clone() + l, after.clone() + r);
                if starts_at_centre {
                    self.kernel_at_offset(j, &left, &right, l, |v| v.clone())
                } else if ends_at_centre {
                    self.kernel_at_offset(j, &left, &right, &(-r.clone()), |v| v.clone())
                } else {
                    self.kernel(knots, j, &left, &right, |v| v.clone())
                }
            };
            // Relative to S_j once it is known: F_j = ∫/S_j is then accurate to the working
            // precision in absolute terms. (Relative to the integral itself would keep the
            // digits of a tiny F_j near a knot too, but there the integrand is a boundary
            // layer of width ~(t − t_j)² and the rule needs its last levels: 5–50× slower.)
            let scale = self
                .scale
                .get(j - 1)
                .cloned()
                .unwrap_or_else(|| T::zero_in(&ctx));
            total += &self.rule.integrate((p, q), f, &tol, &scale).value;
        }
        total
    }
}

impl<T: Real> Blend<T> for Erbs<T> {
    fn built_on(&self) -> Option<&[T]> {
        Some(&self.knots)
    }

    fn break_points(&self, knots: &Knots<T>, j: usize) -> Vec<T> {
        match self.params(j).even_power() {
            Some(_) => Vec::new(),
            None => self.centre(knots, j).into_iter().collect(),
        }
    }

    fn rising(&self, knots: &Knots<T>, j: usize, t: &T, order: usize) -> Taylor<T> {
        self.pair(knots, j, t, order).1
    }

    fn falling(&self, knots: &Knots<T>, j: usize, t: &T, order: usize) -> Taylor<T> {
        self.pair(knots, j, t, order).0
    }

    /// 1 − F_j and F_j from one quadrature. The value is the integral over the nearer end of
    /// the interval; the side it belongs to takes it directly and the other its complement, so
    /// a value near 0 is not the difference of two numbers near 1.
    fn pair(&self, knots: &Knots<T>, j: usize, t: &T, order: usize) -> (Taylor<T>, Taylor<T>) {
        self.pair_located(knots, &Located::from_t(knots, t, j), order)
    }

    /// [`Blend::pair`] at a located parameter: the distances to the ends decide, exactly
    /// where they are exact, which end is t's own.
    fn pair_located(
        &self,
        knots: &Knots<T>,
        at: &Located<T>,
        order: usize,
    ) -> (Taylor<T>, Taylor<T>) {
        self.pair_with(knots, at, order, &|lo, hi| {
            self.integral(knots, at.interval, lo, hi)
        })
    }

    fn slope(&self, knots: &Knots<T>, j: usize, t: &T) -> T {
        self.slope_series(knots, j, t, 0).value().clone()
    }

    fn sweeps(&self) -> bool {
        true
    }

    fn increment(&self, knots: &Knots<T>, j: usize, from: &T, to: &T) -> T {
        self.integral(knots, j, from, to) / self.normalizer(j)
    }
}

impl<T: Real> Erbs<T> {
    /// [`Blend::pair`] with ∫Ψ_j over [lo, hi] computed by `integral` (tanh–sinh here, a
    /// proven quadrature for [`super::proven_erbs::ProvenErbs`]).
    pub(crate) fn pair_with(
        &self,
        knots: &Knots<T>,
        at: &Located<T>,
        order: usize,
        integral: &dyn Fn(&T, &T) -> T,
    ) -> (Taylor<T>, Taylor<T>) {
        let (j, t) = (at.interval, &at.t);
        let ctx = t.ctx();
        let (a, b) = (knots.at(j), knots.at(j + 1));
        let s = self.normalizer(j);
        let (zero, one) = (T::zero_in(&ctx), T::one_in(&ctx));
        // (∫ from the nearer end) / S, and whether that end is t_j. At or beyond an end the
        // integral is 0; which end is nearer is a choice of accuracy, not of value, so an
        // enclosure that cannot tell takes t_j without counting an undecided comparison
        // (t = 1/2 between the knots 1/3 and 2/3 is at the middle at every precision).
        // A distance that an enclosure cannot tell from 0 counts as inside: the interval was
        // decided on the exact t, and the integral over a span that small is proven small.
        let inside = |d: &T| zero.decide_lt(d) != Some(false);
        let (near, from_left) = if !inside(&at.after_start) {
            (zero.clone(), true)
        } else if !inside(&at.before_end) {
            (zero.clone(), false)
        } else if at.before_end.decide_lt(&at.after_start) != Some(true) {
            (integral(a, t) / s, true)
        } else {
            (integral(t, b) / s, false)
        };
        let other = one - &near;
        let (falling, rising) = if from_left {
            (other, near)
        } else {
            (near, other)
        };
        if order == 0 {
            return (Taylor::constant(falling), Taylor::constant(rising));
        }
        let flat_at_knots = !self.params(j).alpha.is_zero();
        let psi = if flat_at_knots && !(inside(&at.after_start) && inside(&at.before_end)) {
            // At a knot every derivative of Ψ is 0 (the limit; see `slope_series`).
            Taylor::constant(T::zero_in(&ctx)).with_order(order - 1)
        } else {
            self.kernel_series(knots, j, t, order - 1)
        };
        (
            Taylor::integrate(&(-psi.clone()), falling, order + 1),
            Taylor::integrate(&psi, rising, order + 1),
        )
    }

    /// F_j′ = Ψ_j/S_j as a series of `order` at t. At the knots every derivative of Ψ is 0
    /// for α > 0 (the limit), which the series at t_j cannot represent; it is evaluated at
    /// a knot only for α = 0, where the kernel has no denominator.
    pub(crate) fn slope_series(
        &self,
        knots: &Knots<T>,
        j: usize,
        t: &T,
        order: usize,
    ) -> Taylor<T> {
        let (a, b) = (knots.at(j), knots.at(j + 1));
        let flat_at_knots = !self.params(j).alpha.is_zero();
        // Decided without counting: an enclosure of t that overlaps a knot is taken as inside,
        // where the kernel's series over it is not finite, and is refused where printed.
        let beyond = |x: &T, y: &T| y.decide_lt(x) == Some(false);
        if flat_at_knots && (beyond(t, a) || beyond(b, t)) {
            return Taylor::constant(T::zero_in(&t.ctx())).with_order(order);
        }
        self.kernel_series(knots, j, t, order)
    }

    /// Ψ_j/S_j as a series of `order` at t inside interval j.
    fn kernel_series(&self, knots: &Knots<T>, j: usize, t: &T, order: usize) -> Taylor<T> {
        let (a, b) = (knots.at(j), knots.at(j + 1));
        let var = Taylor::variable(t.clone(), order);
        let left = var.clone() - &Taylor::constant(a.clone());
        let right = Taylor::constant(b.clone()) - &var;
        self.kernel(knots, j, &left, &right, |v| Taylor::constant(v.clone()))
            / &Taylor::constant(self.normalizer(j).clone())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algo::gerbs::{basis_derivatives, Side};

    #[test]
    fn erbs_is_a_partition_of_unity_with_derivative_psi_over_s() {
        let knots = Knots::<f64>::uniform(5, &()).expect("knots");
        let p = ErbsParams::new(1.0, 3.0, 1.0, 0.5, 1.0).expect("params");
        let e = Erbs::new(&knots, vec![p], CentreReading::Cited).expect("erbs");
        for t in [0.05, 0.3, 0.51, 0.99] {
            let d = basis_derivatives(&knots, &e, &t, 2, Side::Right).expect("inside");
            let sum: f64 = d.iter().map(|x| x[0]).sum();
            assert!((sum - 1.0).abs() < 1e-15, "{sum}");
            let slope: f64 = d.iter().map(|x| x[1]).sum();
            assert!(slope.abs() < 1e-12, "{slope}");
        }
        // Symmetric about the middle of an interval for λ = 1/2, γ = 1.
        let f = |t: f64| e.rising(&knots, 3, &t, 0).value().to_owned();
        assert!((f(0.375) - 0.5).abs() < 1e-14);
        assert!((f(0.3) + f(0.45) - 1.0).abs() < 1e-14);
    }
}
