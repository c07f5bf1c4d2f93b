//! PH Hermite interpolation of C^m data by a preimage of degree n = 2m (paper 001, Sec. 5C,
//! Algorithm 1 for m = 4; Šír & Jüttler 2007, the paper's reference \[1\], for m = 2).
//!
//! Steps (Algorithm 1):
//! 1. Standard form (Definition 3): rotate the data by the unit quaternion U that takes
//!    v_b + v_e to the positive i axis, and translate p_b to 0.
//! 2. Hodograph ends (Eq. 16): the k-th derivative of h at ξ = 0 is (2n)!/(2n−k)! Δᵏh_0, so
//!    h_0 … h_{m−1} and h_{2n−m+1} … h_2n follow one by one from v, a, j, s at each end.
//! 3. A_0 and A_n by Lemma 2 from h_0 = A_0 ⋆ A_0 and h_2n = A_n ⋆ A_n (free angles θ_0, θ_n).
//! 4. A_k, k = 1…m−1, by Lemma 1 from C(2n,k) h_k = 2C(n,k) A_0 ⋆ A_k + (known products)
//!    (Eq. 15), free τ_k; symmetrically A_{n−k} from the end.
//! 5. A_m from the end point (Eq. 17): (2n+1)(p_e − p_b) = Σ_{ij} W_ij A_i i A_j* with
//!    W_ij = C(n,i)C(n,j)/C(2n,i+j). Completing the square in A_m gives
//!    A_p ⋆ A_p = λ (p_e − p_b) − c_p with A_p = Σ_j α_j A_j, α_j = W_mj/(2n+1), λ = α_m and
//!    c_p = Σ_{i,j≠m} (λ W_ij/(2n+1) − α_i α_j) A_i i A_j*; Lemma 2 (free θ_m) gives A_p,
//!    hence A_m. For n = 8 these are the printed 490/21879, 1/442, … of Eqs. (17a–c).
//! 6. Undo the rotation: A_i ← U* A_i (the hodograph U* h U is the original one); p_0 = p_b.
//!
//! Only steps 1, 3 and 5 take square roots. With all free parameters zero (φ* = 0) the
//! interpolant has approximation order 2m − 2 + … (6 for m = 4, Theorem 1; 4 for m = 2).

use super::weights::MiddleWeights;
use super::{binom, weights::middle_weights, PhCurve};
use crate::numeric::quat::{solve_linear, solve_quadratic, vec3, Quat};
use crate::scalar::{Field, Real};

/// Two-point Hermite data with derivatives with respect to ξ ∈ [0, 1].
#[derive(Clone, Debug, PartialEq)]
pub struct HermiteData<T> {
    /// p_b, the start point.
    pub p_b: [T; 3],
    /// p_e, the end point.
    pub p_e: [T; 3],
    /// p′(0), p″(0), …, p⁽ᵐ⁾(0): v_b, a_b, j_b, s_b for m = 4.
    pub start: Vec<[T; 3]>,
    /// p′(1), …, p⁽ᵐ⁾(1).
    pub end: Vec<[T; 3]>,
}

impl<T: Field> HermiteData<T> {
    /// m, the number of derivatives given at each end.
    pub fn order(&self) -> usize {
        self.start.len()
    }
    /// The data of a curve jet at both ends: `jet[k]` is the k-th derivative.
    ///
    /// # Errors
    /// [`PhHermiteError::Shape`] when a jet is empty (no point) or the two jets differ in
    /// length.
    pub fn from_jets(start: &[[T; 3]], end: &[[T; 3]]) -> Result<Self, PhHermiteError> {
        match (start.split_first(), end.split_first()) {
            (Some((p_b, start)), Some((p_e, end))) if start.len() == end.len() => Ok(HermiteData {
                p_b: p_b.clone(),
                p_e: p_e.clone(),
                start: start.to_vec(),
                end: end.to_vec(),
            }),
            _ => Err(PhHermiteError::Shape),
        }
    }
    /// Apply x ↦ f(x) to every vector and g to both points.
    pub fn map(
        &self,
        point: impl Fn(&[T; 3]) -> [T; 3],
        vector: impl Fn(&[T; 3]) -> [T; 3],
    ) -> Self {
        HermiteData {
            p_b: point(&self.p_b),
            p_e: point(&self.p_e),
            start: self.start.iter().map(&vector).collect(),
            end: self.end.iter().map(&vector).collect(),
        }
    }
    /// The reversed data of Theorem 4: the same curve traversed from p_e to p_b, so odd
    /// derivatives change sign.
    pub fn reversed(&self) -> Self {
        let flip = |v: &Vec<[T; 3]>| {
            v.iter()
                .enumerate()
                .map(|(k, d)| {
                    if k % 2 == 0 {
                        vec3::map(d, |x| -x.clone())
                    } else {
                        d.clone()
                    }
                })
                .collect()
        };
        HermiteData {
            p_b: self.p_e.clone(),
            p_e: self.p_b.clone(),
            start: flip(&self.end),
            end: flip(&self.start),
        }
    }
}

/// The free parameters φ of the interpolant family.
#[derive(Clone, Debug, PartialEq)]
pub struct FreeParameters<T> {
    /// θ_0 (Lemma 2 at the start).
    pub theta_start: T,
    /// θ_m (θ_4 for m = 4): the paper fixes it to 0.
    pub theta_mid: T,
    /// θ_n (θ_8 for m = 4).
    pub theta_end: T,
    /// τ_1 … τ_{m−1}.
    pub tau_start: Vec<T>,
    /// τ_{n−1}, τ_{n−2}, … τ_{m+1} (τ_7, τ_6, τ_5 for m = 4): entry k−1 belongs to A_{n−k}.
    pub tau_end: Vec<T>,
}

impl<T: Field> FreeParameters<T> {
    /// φ* = 0 for data with m derivatives. An m above
    /// [`super::piecewise::MAX_DERIVATIVES`] is sized as MAX_DERIVATIVES + 1 (a huge m would
    /// only exhaust memory): every interpolation refuses such parameters, as it refuses the m.
    pub fn zero(m: usize, ctx: &T::Ctx) -> Self {
        let m = m.min(super::piecewise::MAX_DERIVATIVES + 1);
        let z = T::zero_in(ctx);
        FreeParameters {
            theta_start: z.clone(),
            theta_mid: z.clone(),
            theta_end: z.clone(),
            tau_start: vec![z.clone(); m.saturating_sub(1)],
            tau_end: vec![z; m.saturating_sub(1)],
        }
    }
    /// The same parameters in another number type.
    pub fn map<U: Field>(&self, f: impl Fn(&T) -> U) -> FreeParameters<U> {
        FreeParameters {
            theta_start: f(&self.theta_start),
            theta_mid: f(&self.theta_mid),
            theta_end: f(&self.theta_end),
            tau_start: self.tau_start.iter().map(&f).collect(),
            tau_end: self.tau_end.iter().map(&f).collect(),
        }
    }
    /// Every parameter negated (Theorems 3 and 4).
    pub fn negated(&self) -> Self {
        let neg = |v: &Vec<T>| v.iter().map(|x| -x.clone()).collect();
        FreeParameters {
            theta_start: -self.theta_start.clone(),
            theta_mid: -self.theta_mid.clone(),
            theta_end: -self.theta_end.clone(),
            tau_start: neg(&self.tau_start),
            tau_end: neg(&self.tau_end),
        }
    }
}

/// Why the data have no interpolant of this form.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum PhHermiteError {
    /// v_b + v_e = 0.
    #[error("v_b + v_e = 0: the data have no standard form (Definition 3)")]
    NoStandardForm,
    /// A zero end tangent, named.
    #[error("{0} = 0: Lemma 2 needs a non-zero end tangent")]
    ZeroTangent(&'static str),
    /// Missing or unequal derivatives at the ends.
    #[error("the data need at least one derivative at each end, the same number at both")]
    Shape,
    /// The number of free τ parameters given and the number the data need.
    #[error("{0} free τ parameters given where the data need {1}")]
    FreeCount(usize, usize),
    /// A preimage with no control point, or of a degree beyond `MAX_PREIMAGE_DEGREE`.
    #[error("a PH preimage needs 1 to 31 control points (degree ≤ 30), got {0}")]
    PreimageDegree(usize),
    /// A conversion asked for no segment.
    #[error("a conversion needs at least one segment")]
    NoSegments,
    /// A conversion asked for more segments than [`super::piecewise::MAX_SEGMENTS`].
    #[error("segments: at most {max} segments, got {0}", max = super::piecewise::MAX_SEGMENTS)]
    TooManySegments(usize),
    /// More or fewer derivatives per joint than a conversion matches.
    #[error("derivatives: a conversion matches 1 to {max} derivatives at each joint, got {0}", max = super::piecewise::MAX_DERIVATIVES)]
    Derivatives(usize),
    /// An interpolant whose control points overflow the number type (the segment).
    #[error("segment {0}: the interpolant overflows the number type (coordinates too large; scale the curve)")]
    Overflow(usize),
    /// A conversion interval [a, b] without a < b (reversed, empty or NaN).
    #[error("the interval [a, b] needs a < b")]
    Interval,
    /// Data that are not finite (the curve undefined or overflowing at a segment end).
    #[error("the Hermite data are not finite at segment end {0}")]
    NotFinite(usize),
    /// A fit's tolerance that is not a positive finite number.
    #[error("tolerance: must be a positive finite number")]
    BadTolerance,
    /// No number of segments up to the limit met a fit's tolerance: (segments, error).
    #[error("tolerance: {0} segments still leave a conversion error of {1:e}")]
    Tolerance(usize, f64),
}

/// How step 5 chooses A_m.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MiddleRule {
    /// Lemma 2 applied to λ(p_e − p_b) − c_p (Eq. 17a): interpolates p_e.
    Derived,
    /// Lemma 2 applied to c_p, as Eq. (18) prints it.
    AsPrintedEq18,
}

/// The interpolant with free parameters `free` (Algorithm 1).
///
/// # Errors
/// As [`interpolate_with`].
pub fn interpolate<T: Real>(
    data: &HermiteData<T>,
    free: &FreeParameters<T>,
) -> Result<PhCurve<T>, PhHermiteError> {
    interpolate_with(data, free, MiddleRule::Derived)
}

/// [`interpolate`] with a choice of the rule for the middle control point.
///
/// # Errors
/// [`PhHermiteError::Shape`] for m = 0, m above [`super::piecewise::MAX_DERIVATIVES`] or
/// unequal derivative counts; [`PhHermiteError::FreeCount`] unless m − 1 τ at each end; [`PhHermiteError::ZeroTangent`]
/// for v_b or v_e = 0 (or no Lemma 2 solution at that end);
/// [`PhHermiteError::NoStandardForm`] for v_b + v_e = 0; [`PhHermiteError::NotFinite`] (end 0)
/// for data or free parameters that are NaN or infinite.
pub fn interpolate_with<T: Real>(
    data: &HermiteData<T>,
    free: &FreeParameters<T>,
    middle: MiddleRule,
) -> Result<PhCurve<T>, PhHermiteError> {
    let m = data.order();
    if m == 0 || m > super::piecewise::MAX_DERIVATIVES || data.end.len() != m {
        return Err(PhHermiteError::Shape);
    }
    // The fields are public: NaN or infinite data would give an `Ok` of NaN control points.
    let vectors = [&data.p_b, &data.p_e]
        .into_iter()
        .chain(&data.start)
        .chain(&data.end);
    let thetas = [&free.theta_start, &free.theta_mid, &free.theta_end];
    let taus = free.tau_start.iter().chain(&free.tau_end).chain(thetas);
    if vectors.flatten().chain(taus).any(|x| !x.is_finite()) {
        return Err(PhHermiteError::NotFinite(0));
    }
    if free.tau_start.len() != m - 1 || free.tau_end.len() != m - 1 {
        return Err(PhHermiteError::FreeCount(
            free.tau_start.len().max(free.tau_end.len()),
            m - 1,
        ));
    }
    let ctx = data.p_b[0].ctx();
    let is_zero = |v: &[T; 3]| v.iter().all(Field::is_zero);
    if is_zero(&data.start[0]) {
        return Err(PhHermiteError::ZeroTangent("v_b"));
    }
    if is_zero(&data.end[0]) {
        return Err(PhHermiteError::ZeroTangent("v_e"));
    }
    // Step 1: standard form.
    let u = standard_rotation(&vec3::add(&data.start[0], &data.end[0]))?;
    let turn = u.sandwich_matrix();
    let rotate = |v: &[T; 3]| vec3::transform(&turn, v);
    // The rotated derivatives of both ends in one buffer: the start data, then the end data
    // of the reversed parameter 1 − ξ (odd derivatives change sign), so that step 2 turns
    // the second half into h_2n, h_2n−1, ….
    let mut h: Vec<[T; 3]> = data
        .start
        .iter()
        .map(rotate)
        .chain(data.end.iter().enumerate().map(|(k, d)| {
            let r = rotate(d);
            if k % 2 == 1 {
                vec3::map(&r, |x| -x.clone())
            } else {
                r
            }
        }))
        .collect();
    let displacement = rotate(&vec3::sub(&data.p_e, &data.p_b));

    let n = 2 * m;
    let big = 2 * n;
    // Step 2: hodograph control points at both ends.
    let (h_start, h_end) = h.split_at_mut(m);
    end_coefficients(h_start, big, &ctx);
    end_coefficients(h_end, big, &ctx);
    let (h_start, h_end) = (&*h_start, &*h_end);

    // A_0 … A_n; A_m stays zero until step 5.
    let mut a: Vec<Quat<T>> = vec![Quat::zero(&ctx); n + 1];
    // Step 3.
    a[0] = solve_quadratic(&h_start[0], &free.theta_start)
        .map_err(|_| PhHermiteError::ZeroTangent("v_b"))?;
    a[n] = solve_quadratic(&h_end[0], &free.theta_end)
        .map_err(|_| PhHermiteError::ZeroTangent("v_e"))?;
    end_preimages(&mut a, h_start, h_end, free)?;
    middle_preimage(&mut a, &displacement, middle, &free.theta_mid);
    // Step 6.
    let back = u.conj();
    for aj in &mut a {
        *aj = back.mul(aj);
    }
    PhCurve::new(a, data.p_b.clone())
}

/// Step 4 of Algorithm 1: A_k from h_k (start) and A_{n−k} from h_{2n−k} (end), k = 1 … m−1,
/// with the free parameters τ; `a` holds A_0 and A_n on entry.
fn end_preimages<T: Real>(
    a: &mut [Quat<T>],
    h_start: &[[T; 3]],
    h_end: &[[T; 3]],
    free: &FreeParameters<T>,
) -> Result<(), PhHermiteError> {
    let (m, n) = (h_start.len(), a.len() - 1);
    let big = 2 * n;
    let ctx = a[0].ctx();
    // A_1 … A_{k−1} of the same side are known by the time A_k is solved for.
    for k in 1..m {
        for (side, h, tau) in [
            (0usize, &h_start, &free.tau_start),
            (1, &h_end, &free.tau_end),
        ] {
            let index = |i: usize| if side == 0 { i } else { n - i };
            let mut rhs = vec3::scale(&h[k], &T::from_i64(binom(big, k), &ctx));
            for i in 1..k {
                let w = -T::from_i64(binom(n, i) * binom(n, k - i), &ctx);
                vec3::axpy(&mut rhs, &w, &a[index(i)].star(&a[index(k - i)]));
            }
            let rhs = vec3::scale(
                &rhs,
                &(T::one_in(&ctx) / &T::from_i64(2 * binom(n, k), &ctx)),
            );
            let x = solve_linear(&rhs, &a[index(0)], &tau[k - 1]).ok_or(
                PhHermiteError::ZeroTangent(if side == 0 { "v_b" } else { "v_e" }),
            )?;
            a[index(k)] = x;
        }
    }
    Ok(())
}

/// Step 5 of Algorithm 1: the middle control point A_m from the others, so that the curve
/// ends at p_e (`MiddleRule::Derived`) or as Eq. (18) prints it.
fn middle_preimage<T: Real>(
    a: &mut [Quat<T>],
    displacement: &[T; 3],
    middle: MiddleRule,
    theta_mid: &T,
) {
    let n = a.len() - 1;
    let m = n / 2;
    let ctx = a[0].ctx();
    let weights = middle_weights(n);
    let c_p = c_p(weights, a);
    let target = match middle {
        MiddleRule::Derived => {
            vec3::sub(&vec3::scale(displacement, &weights.lambda.to(&ctx)), &c_p)
        }
        MiddleRule::AsPrintedEq18 => c_p,
    };
    let x = match solve_quadratic(&target, theta_mid) {
        Ok(x) => x,
        Err(_) => Quat::zero(&ctx), // A_p ⋆ A_p = 0 has the single solution A_p = 0.
    };
    let mut rest = Quat::zero(&ctx);
    for j in (0..=n).filter(|&j| j != m) {
        rest = rest + &a[j].scale(&weights.alpha[j].to(&ctx));
    }
    // α_m = λ, so dividing by it is multiplying by the exact 1/λ.
    a[m] = (x - &rest).scale(&weights.inverse_lambda.to(&ctx));
}

/// The unit quaternion U with U d U* a positive multiple of i: the shortest rotation
/// (1 + d̂·i + d̂×i, normalized), or j when d points along −i.
///
/// # Errors
/// [`PhHermiteError::NoStandardForm`] when the computed |d| is zero (d = 0, or |d|² underflows).
pub fn standard_rotation<T: Real>(d: &[T; 3]) -> Result<Quat<T>, PhHermiteError> {
    let ctx = d[0].ctx();
    let len = vec3::norm(d);
    if len.is_zero() {
        return Err(PhHermiteError::NoStandardForm);
    }
    let w = crate::numeric::quat::sum_with_norm(&len, d);
    let z = T::zero_in(&ctx);
    if w.is_zero() {
        return Ok(Quat::new(z.clone(), z.clone(), T::one_in(&ctx), z));
    }
    let q = Quat::new(w, z, d[2].clone(), -d[1].clone());
    let norm = q.norm2().sqrt();
    Ok(q.scale(&(T::one_in(&ctx) / &norm)))
}

/// h_0 … h_{m−1} in place of the derivatives `d[k]` = h⁽ᵏ⁾(0) of a Bernstein polynomial of
/// degree `big`: h^{(k)}(0) = big!/(big−k)! Σ_j (−1)^{k−j} C(k,j) h_j (Eq. 16), solved for h_k
/// with h_0 … h_{k−1} already in place.
pub fn end_coefficients<T: Field>(d: &mut [[T; 3]], big: usize, ctx: &T::Ctx) {
    let mut falling = 1i64;
    for k in 0..d.len() {
        if k > 0 {
            falling *= (big - k + 1) as i64;
        }
        let (known, rest) = d.split_at_mut(k);
        let hk = &mut rest[0];
        *hk = vec3::scale(hk, &(T::one_in(ctx) / &T::from_i64(falling, ctx)));
        for (j, hj) in known.iter().enumerate() {
            let sign = if (k - j) % 2 == 0 { -1 } else { 1 };
            vec3::axpy(hk, &T::from_i64(sign * binom(k, j), ctx), hj);
        }
    }
}

/// c_p of step 5: the part of the curve's displacement carried by every control point but
/// A_m, Σ_{i≤j} w_ij A_i ⋆ A_j with the cached exact weights (entry m of `a` is ignored).
///
/// ⋆ is bilinear, so the sum is taken row by row as Σ_i A_i ⋆ (Σ_{j≥i} w_ij A_j): one ⋆
/// product per row instead of one per pair (8 instead of 36 for n = 8).
pub fn c_p<T: Field>(weights: &MiddleWeights, a: &[Quat<T>]) -> [T; 3] {
    let ctx = a[0].ctx();
    let mut c = vec3::zero::<T>(&ctx);
    // `middle_weights` lists the terms row by row, so each row is one chunk (a row split in
    // two chunks would still sum correctly, with one more ⋆ product).
    for row in weights.c_p.chunk_by(|s, t| s.i == t.i) {
        let mut combination = Quat::zero(&ctx);
        for term in row {
            combination.add_scaled(&term.weight.to(&ctx), &a[term.j]);
        }
        let v = a[row[0].i].star(&combination);
        c = vec3::add(&c, &v);
    }
    c
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algo::ph::bernstein_jet;

    fn sample_data(m: usize) -> HermiteData<f64> {
        let v = |a: f64, b: f64, c: f64| [a, b, c];
        let start = [
            v(1.0, 0.3, -0.2),
            v(0.5, -1.0, 0.4),
            v(-2.0, 0.7, 1.1),
            v(3.0, 1.0, -0.5),
        ];
        let end = [
            v(0.8, -0.4, 0.6),
            v(-0.3, 0.9, 0.2),
            v(1.5, -0.6, -1.0),
            v(-2.0, 0.5, 2.5),
        ];
        HermiteData {
            p_b: v(0.1, -0.2, 0.3),
            p_e: v(1.0, 0.2, 0.5),
            start: start[..m].to_vec(),
            end: end[..m].to_vec(),
        }
    }

    #[test]
    fn c4_and_c2_interpolants_meet_their_data() {
        for m in [1, 2, 3, 4] {
            let data = sample_data(m);
            let mut free = FreeParameters::zero(m, &());
            free.theta_start = 0.3;
            free.theta_end = -0.2;
            free.theta_mid = 0.1;
            for t in free.tau_start.iter_mut().chain(free.tau_end.iter_mut()) {
                *t = 0.05;
            }
            let c = interpolate(&data, &free).unwrap();
            let pts = c.control_points();
            let s = bernstein_jet(&pts, &0.0, m);
            let e = bernstein_jet(&pts, &1.0, m);
            for d in 0..3 {
                assert!((s[0][d] - data.p_b[d]).abs() < 1e-12);
                assert!(
                    (e[0][d] - data.p_e[d]).abs() < 1e-12,
                    "m={m} {:?} {:?}",
                    e[0],
                    data.p_e
                );
                for k in 0..m {
                    assert!((s[k + 1][d] - data.start[k][d]).abs() < 1e-9, "m={m} k={k}");
                    assert!((e[k + 1][d] - data.end[k][d]).abs() < 1e-9, "m={m} k={k}");
                }
            }
        }
    }

    #[test]
    fn c_p_by_rows_is_the_sum_over_pairs_exactly() {
        use crate::scalar::BigRational;
        let r = |v: i64| BigRational::new(v.into(), 7.into());
        let a: Vec<Quat<BigRational>> = (0..9i64)
            .map(|k| Quat::new(r(k - 3), r(2 * k + 1), r(5 - k * k), r(k % 3 - 1)))
            .collect();
        let weights = middle_weights(8);
        let mut pairs = vec3::zero::<BigRational>(&());
        for term in &weights.c_p {
            vec3::axpy(&mut pairs, &term.weight.value, &a[term.i].star(&a[term.j]));
        }
        assert_eq!(c_p(weights, &a), pairs);
    }

    #[test]
    fn degenerate_data_are_rejected() {
        let mut d = sample_data(4);
        d.end[0] = vec3::map(&d.start[0], |x| -x);
        assert_eq!(
            interpolate(&d, &FreeParameters::zero(4, &())),
            Err(PhHermiteError::NoStandardForm)
        );
        let mut d = sample_data(4);
        d.start[0] = [0.0; 3];
        assert_eq!(
            interpolate(&d, &FreeParameters::zero(4, &())),
            Err(PhHermiteError::ZeroTangent("v_b"))
        );
    }
}
