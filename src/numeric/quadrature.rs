//! Quadrature rules over any [`Real`]: tanh–sinh for the ERBS integrals (paper 003) and
//! 4-point Gauss–Legendre ([`gauss_legendre4`]) for polynomial integrands.
//!
//! Tanh–sinh (double-exponential) quadrature:
//! ∫_a^b f = Σ_k h w_k f(x_k) with x = m + r·tanh(π/2·sinh(kh)), m, r the midpoint and
//! half-width, and w = r·(π/2)·cosh(kh)/cosh²(π/2·sinh(kh)) (Takahasi & Mori 1974). The rule
//! converges double-exponentially for integrands analytic inside (a, b), whatever they do at
//! the ends, which suits the ERBS kernel exp(−β·…/((t−t_k)(t_{k+1}−t)^γ)^α): flat at both
//! knots. Each level halves h and adds only the new odd nodes; the iteration stops when two
//! levels agree to the tolerance.
//!
//! The integrand receives the distances (x − a, b − x), computed without cancellation from
//! E = exp(−2|s|): 1 − |tanh s| = 2E/(1+E), so kernels singular at an end see exact offsets.

use crate::scalar::Real;
use std::sync::OnceLock;

/// The value of a quadrature and how it was reached.
#[derive(Clone, Debug)]
pub struct Quadrature<T> {
    /// The approximation of the integral.
    pub value: T,
    /// |S_L − S_{L−1}| of the last two levels: the error estimate.
    pub change: T,
    /// The number of levels (halvings of the step) used.
    pub levels: usize,
    /// The number of integrand evaluations.
    pub evaluations: usize,
}

/// ∫_a^b f, f called as f(x − a, b − x), to relative tolerance `tol` (at most `max_level`
/// halvings of the step, h = 2^−level). Builds a one-off [`TanhSinh`] rule.
pub fn tanh_sinh<T: Real>(
    (a, b): (&T, &T),
    f: impl Fn(&T, &T) -> T,
    tol: &T,
    max_level: usize,
) -> Quadrature<T> {
    TanhSinh::new(&a.ctx(), max_level).integrate((a, b), f, tol, &T::zero_in(&a.ctx()))
}

/// One node of the rule on [−1, 1], for the half-width 1: the distances of x to the near
/// and far ends and the weight (π/2)·cosh(t)/cosh²(π/2·sinh t).
#[derive(Clone, Debug)]
struct Node<T> {
    near: T,
    far: T,
    weight: T,
    /// t = 0: the single node at the midpoint.
    centre: bool,
}

/// The tanh–sinh rule for one precision: the nodes of each level, computed the first time a
/// level is reached and kept (every integral of an ERBS basis or a path length reuses them,
/// so only the integrand is evaluated per node).
#[derive(Clone, Debug)]
pub struct TanhSinh<T> {
    t_max: f64,
    levels: Vec<OnceLock<Vec<Node<T>>>>,
}

impl<T: Real> TanhSinh<T> {
    /// The rule for the precision of `ctx` with at most `max_level` halvings of h.
    pub fn new(ctx: &T::Ctx, max_level: usize) -> Self {
        let bits = T::precision_bits(ctx) as f64;
        // Nodes beyond t_max carry weights below e^{−2 s_max}: cosh²(s) ≈ e^{2s}/4. An
        // integrand like 1/√(x − a) grows as e^{s} there, so s_max is twice what a bounded
        // integrand needs.
        let s_max = bits * std::f64::consts::LN_2 + 8.0;
        TanhSinh {
            t_max: (2.0 * s_max / std::f64::consts::PI).asinh(),
            levels: (0..=max_level).map(|_| OnceLock::new()).collect(),
        }
    }

    /// The nodes added at `level`: t = k for k = 0, 1, … at level 0, t = k·2^−level for odd
    /// k after that, up to t_max.
    fn nodes(&self, level: usize, ctx: &T::Ctx) -> &[Node<T>] {
        self.levels[level].get_or_init(|| {
            let one = T::one_in(ctx);
            let two = T::from_i64(2, ctx);
            let pi_half = T::pi(ctx) / &two;
            let h = crate::scalar::powi(&(one.clone() / &two), level as u32);
            let (first, step) = if level == 0 { (0, 1) } else { (1, 2) };
            let mut out = Vec::new();
            let mut k = first;
            loop {
                let t = T::from_i64(k, ctx) * &h;
                if t.to_f64() > self.t_max {
                    break;
                }
                let s = pi_half.clone() * &sinh(&t);
                // E = exp(−2|s|): 1 − |tanh s| = 2E/(1+E) without cancellation.
                let e = (-(s.abs() * &two)).exp();
                let sech2 = T::from_i64(4, ctx) * &e / &((one.clone() + &e) * &(one.clone() + &e));
                out.push(Node {
                    near: two.clone() * &e / &(one.clone() + &e),
                    far: two.clone() / &(one.clone() + &e),
                    weight: pi_half.clone() * &cosh(&t) * &sech2,
                    centre: k == 0,
                });
                k += step;
            }
            out
        })
    }

    /// ∫_a^b f, f called as f(x − a, b − x); stops when two levels differ by at most
    /// tol · max(|value|, scale) (a `scale` for running integrals that are tiny next to the
    /// total they will be divided by), or at the last level.
    pub fn integrate(
        &self,
        (a, b): (&T, &T),
        f: impl Fn(&T, &T) -> T,
        tol: &T,
        scale: &T,
    ) -> Quadrature<T> {
        let ctx = a.ctx();
        let half = (b.clone() - a) / &T::from_i64(2, &ctx);
        let mut evaluations = 0;
        let level_sum = |level: usize, evaluations: &mut usize| {
            let mut sum = T::zero_in(&ctx);
            for node in self.nodes(level, &ctx) {
                let w = half.clone() * &node.weight;
                if node.centre {
                    *evaluations += 1;
                    sum += &(w * &f(&half, &half));
                } else {
                    *evaluations += 2;
                    let (near, far) = (half.clone() * &node.near, half.clone() * &node.far);
                    // x near b on the right, its mirror near a on the left.
                    sum += &(w * &(f(&far, &near) + &f(&near, &far)));
                }
            }
            sum
        };
        let mut h = T::one_in(&ctx);
        let two = T::from_i64(2, &ctx);
        let mut sum = level_sum(0, &mut evaluations);
        let mut estimate = sum.clone() * &h;
        let mut change = estimate.clone().abs();
        let mut levels = 0;
        for level in 1..self.levels.len() {
            h /= &two;
            sum += &level_sum(level, &mut evaluations);
            let next = sum.clone() * &h;
            change = (next.clone() - &estimate).abs();
            estimate = next;
            levels = level;
            let size = estimate.clone().abs();
            let size = if size > *scale { size } else { scale.clone() };
            if level >= 3 && change <= tol.clone() * &size {
                break;
            }
        }
        Quadrature {
            value: estimate,
            change,
            levels,
            evaluations,
        }
    }
}

fn sinh<T: Real>(t: &T) -> T {
    let e = t.exp();
    (e.clone() - &(T::one_in(&t.ctx()) / &e)) / &T::from_i64(2, &t.ctx())
}

fn cosh<T: Real>(t: &T) -> T {
    let e = t.exp();
    (e.clone() + &(T::one_in(&t.ctx()) / &e)) / &T::from_i64(2, &t.ctx())
}

/// The relative tolerance that matches the working precision: 2^(8−p).
pub fn default_tolerance<T: Real>(ctx: &T::Ctx) -> T {
    T::epsilon(ctx) * &T::from_i64(128, ctx)
}

/// The 4-point Gauss–Legendre rule on [0, 1]: (node, weight) pairs, exact for polynomials of
/// degree ≤ 7, in the precision of `ctx`. Nodes ½ ∓ ½√((3 ∓ 2√(6/5))/7), weights
/// (18 ± √30)/72.
pub fn gauss_legendre4<T: Real>(ctx: &T::Ctx) -> [(T, T); 4] {
    let f = |x: i64| T::from_i64(x, ctx);
    let six_fifths = (f(6) / &f(5)).sqrt();
    let (a, b) = (
        ((f(3) - &(f(2) * &six_fifths)) / &f(7)).sqrt(),
        ((f(3) + &(f(2) * &six_fifths)) / &f(7)).sqrt(),
    );
    let w30 = f(30).sqrt();
    let (wa, wb) = ((f(18) + &w30) / &f(36), (f(18) - &w30) / &f(36));
    let half = T::from_ratio(1, 2, ctx);
    let two = f(2);
    [
        (half.clone() - &(a.clone() / &two), wa.clone() / &two),
        (half.clone() + &(a / &two), wa / &two),
        (half.clone() - &(b.clone() / &two), wb.clone() / &two),
        (half + &(b / &two), wb / &two),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::Float;

    #[test]
    fn gauss_legendre4_is_exact_to_degree_seven() {
        let moments = |n: i32| -> (f64, Float) {
            let f: f64 = gauss_legendre4::<f64>(&())
                .iter()
                .map(|(x, w)| w * x.powi(n))
                .sum();
            let m = gauss_legendre4::<Float>(&200)
                .iter()
                .fold(Float::with_val(200, 0), |acc, (x, w)| {
                    acc + w.clone() * crate::scalar::powi(x, n as u32)
                });
            (f, m)
        };
        for n in 0..=7 {
            let (f, m) = moments(n);
            let exact = 1.0 / (n as f64 + 1.0);
            assert!((f - exact).abs() < 1e-15, "x^{n} in f64: {f}");
            assert!(
                (m - Float::with_val(200, 1) / (n + 1)).abs() < 1e-55,
                "x^{n} in MPFR"
            );
        }
        // Degree 8 is not integrated exactly: the rule has four points.
        let (f, _) = moments(8);
        assert!((f - 1.0 / 9.0).abs() > 1e-6);
    }

    #[test]
    fn integrates_flat_and_singular_ends() {
        // ∫_0^1 exp(−1/(x(1−x))) dx = 0.00702985840661… (flat at both ends).
        let q = tanh_sinh(
            (&0.0, &1.0),
            |l: &f64, r: &f64| (-1.0 / (l * r)).exp(),
            &1e-14,
            12,
        );
        assert!(
            (q.value - 0.007_029_858_406_609_8).abs() < 1e-15,
            "{}",
            q.value
        );
        // ∫_0^1 1/√x dx = 2 (singular at 0), in MPFR-200.
        let ctx = 200u32;
        let q = tanh_sinh(
            (&Float::with_val(ctx, 0), &Float::with_val(ctx, 1)),
            |l: &Float, _: &Float| Float::with_val(ctx, 1) / l.clone().sqrt(),
            &default_tolerance::<Float>(&ctx),
            14,
        );
        let err = (q.value - Float::with_val(ctx, 2)).abs();
        assert!(err < Float::with_val(ctx, 1e-55), "{err}");
    }
}
