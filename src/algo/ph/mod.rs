//! Spatial Pythagorean-hodograph (PH) curves from a quaternion preimage (paper 001, Sec. 4B).
//!
//! A preimage A(ξ) = Σ A_i B_i^n(ξ) of degree n defines the hodograph h = A i A* (Eq. 9) of
//! degree 2n, whose Bernstein coefficients are the exact products (Eq. 28, App. C)
//!
//! h_k = Σ_{i+j=k} C(n,i) C(n,j) / C(2n,k) · A_i i A_j*,
//!
//! and the curve p of degree 2n+1 with control points p_i = p_0 + Σ_{j<i} h_j /(2n+1) (Eq. 10d).
//! The parametric speed σ = |A|² is a polynomial (Eq. 8d), so the arc length (Eq. 13a) is the
//! exact integral Σ σ_k /(2n+1). The Euler–Rodrigues frame (Eq. 11) is
//! R = [A i A*, A j A*, A k A*]/|A|² and its angular velocity (Eq. 12) is, in closed form,
//!
//! ω = 2 vec(A′ A*)/|A|²  (world components),  χ = Rᵀω = 2 vec(A* A′)/|A|²  (Eq. 12b),
//!
//! since R is the rotation of the unit quaternion A/|A| and the real part of A′A* only
//! changes |A|. Curvature and torsion follow Eq. (13b) and the standard torsion formula
//! (p′×p″)·p‴ / |p′×p″|² (Eq. (13c) as printed divides by |p‴|², see the claims).
//!
//! [`hermite`] builds PH curves from C² and C⁴ Hermite data (Algorithm 1 and its C²
//! predecessor), [`piecewise`] converts whole curves (Sec. 5E–F), [`symbolic`] derives the
//! paper's coefficient tables exactly.
//!
//! Algorithm 1 on the Hermite data of a straight segment, in f64 and in MPFR: the degree-17 PH
//! interpolant is the segment itself, of length 1.
//!
//! ```
//! use trajverify::algo::ph::hermite::{interpolate, FreeParameters, HermiteData};
//! use trajverify::scalar::{Float, Real};
//!
//! fn segment_length<T: Real>(ctx: &T::Ctx) -> T {
//!     let v = |x: i64, y: i64| [T::from_i64(x, ctx), T::from_i64(y, ctx), T::zero_in(ctx)];
//!     let data = HermiteData {
//!         p_b: v(0, 0),
//!         p_e: v(1, 0),
//!         start: vec![v(1, 0), v(0, 0), v(0, 0), v(0, 0)],
//!         end: vec![v(1, 0), v(0, 0), v(0, 0), v(0, 0)],
//!     };
//!     interpolate(&data, &FreeParameters::zero(4, ctx)).unwrap().arc_length()
//! }
//! assert!((segment_length::<f64>(&()) - 1.0).abs() < 1e-13);
//! let precise: Float = segment_length(&256);
//! assert!((precise - 1u32).abs() < 1e-60);
//! ```

pub mod grid;
pub mod hermite;
pub mod piecewise;
pub mod symbolic;
pub mod weights;

use crate::curve::taylor::Taylor;
use crate::numeric::quat::{vec3, Quat};
use crate::scalar::{Field, Real};

/// C(n, k) from the compile-time Pascal triangle of [`crate::numeric::poly::binom`] (every entry the
/// PH code needs, n ≤ 2·[`MAX_PREIMAGE_DEGREE`], fits in it).
pub use crate::numeric::poly::bernstein::bernstein_jet;
pub use crate::numeric::poly::binom;

/// The largest preimage degree accepted (keeps every binomial product inside i64).
pub const MAX_PREIMAGE_DEGREE: usize = 30;

/// The weight of A_i i A_j* in the hodograph coefficient h_{i+j}: C(n,i)C(n,j)/C(2n,i+j).
pub fn product_weight<T: Field>(n: usize, i: usize, j: usize, ctx: &T::Ctx) -> T {
    T::from_ratio(binom(n, i) * binom(n, j), binom(2 * n, i + j), ctx)
}

/// A spatial PH curve on ξ ∈ [0, 1]: its preimage control points and its start point (read
/// through accessors; made by [`PhCurve::new`], which checks the preimage's degree).
#[derive(Clone, Debug, PartialEq)]
pub struct PhCurve<T> {
    /// A_0 … A_n.
    pub(crate) preimage: Vec<Quat<T>>,
    /// p(0) = p_0.
    pub(crate) start: [T; 3],
}

/// Position, frame and angular velocity of a PH curve at one parameter value.
#[derive(Clone, Debug)]
pub struct FrameState<T> {
    /// The point p(ξ).
    pub point: [T; 3],
    /// The columns e1, e2, e3 of the Euler–Rodrigues frame (Eq. 11).
    pub frame: [[T; 3]; 3],
    /// ω in world coordinates (Eq. 12 with χ_k = e_k · ω).
    pub omega: [T; 3],
    /// The parametric speed σ = |A|² = |p′|.
    pub speed: T,
}

impl<T: Field> PhCurve<T> {
    /// The PH curve with hodograph A(ξ) ⋆ A(ξ) from the Bernstein preimage `preimage`, starting at `start`.
    ///
    /// # Errors
    /// [`hermite::PhHermiteError::PreimageDegree`] without a control point, or with more than
    /// `MAX_PREIMAGE_DEGREE + 1`.
    pub fn new(preimage: Vec<Quat<T>>, start: [T; 3]) -> Result<Self, hermite::PhHermiteError> {
        if preimage.is_empty() || preimage.len() > MAX_PREIMAGE_DEGREE + 1 {
            return Err(hermite::PhHermiteError::PreimageDegree(preimage.len()));
        }
        Ok(PhCurve { preimage, start })
    }
    /// The preimage control points A_0 … A_n.
    pub fn preimage(&self) -> &[Quat<T>] {
        &self.preimage
    }
    /// The start point p(0) = p_0.
    pub fn start(&self) -> &[T; 3] {
        &self.start
    }
    /// The same curve with every coefficient mapped by `f`: e.g. a curve computed in f64 as
    /// exact balls (`|x| Ball::from_f64(*x, &bits)`), to bound its own error in ball
    /// arithmetic.
    pub fn map<U: Field>(&self, f: impl Fn(&T) -> U) -> PhCurve<U> {
        PhCurve {
            preimage: self
                .preimage
                .iter()
                .map(|q| Quat::from_components(q.components().each_ref().map(&f)))
                .collect(),
            start: self.start.each_ref().map(&f),
        }
    }
    /// n, the degree of the preimage.
    pub fn preimage_degree(&self) -> usize {
        self.preimage.len() - 1
    }
    fn ctx(&self) -> T::Ctx {
        self.start[0].ctx()
    }

    /// The 2n+1 hodograph control points h_0 … h_2n (Eqs. 15 and 28).
    pub fn hodograph(&self) -> Vec<[T; 3]> {
        let mut h = vec![vec3::zero::<T>(&self.ctx()); 2 * self.preimage_degree() + 1];
        self.add_hodograph(&mut h);
        h
    }

    /// Add h_k to `h[k]` for k = 0 … 2n.
    fn add_hodograph(&self, h: &mut [[T; 3]]) {
        let ctx = self.ctx();
        // Each pair (i, j), i ≤ j, contributes A_i ⋆ A_j; (i, j) and (j, i) give the same
        // vector, so the cached weight of i < j holds the factor 2.
        let mut v = vec3::zero::<T>(&ctx);
        for term in weights::product_terms(self.preimage_degree()) {
            self.preimage[term.i].star_into(&self.preimage[term.j], &mut v);
            vec3::axpy(&mut h[term.i + term.j], &term.weight.to(&ctx), &v);
        }
    }

    /// The 2n+2 control points p_0 … p_{2n+1} (Eq. 10d).
    pub fn control_points(&self) -> Vec<[T; 3]> {
        let ctx = self.ctx();
        // One buffer: h_k is accumulated in slot k + 1, then the running sum
        // p_{k+1} = p_k + h_k/(2n+1) overwrites it.
        let mut points = vec![vec3::zero::<T>(&ctx); 2 * self.preimage_degree() + 2];
        self.add_hodograph(&mut points[1..]);
        let inv = T::one_in(&ctx) / &T::from_i64(points.len() as i64 - 1, &ctx);
        points[0] = self.start.clone();
        for k in 1..points.len() {
            let mut next = points[k - 1].clone();
            vec3::axpy(&mut next, &inv, &points[k]);
            points[k] = next;
        }
        points
    }

    /// The Bernstein coefficients σ_0 … σ_2n of the parametric speed σ = |A|² (Eq. 8d).
    pub fn speed_coefficients(&self) -> Vec<T> {
        let n = self.preimage_degree();
        let ctx = self.ctx();
        let mut s = vec![T::zero_in(&ctx); 2 * n + 1];
        for term in weights::product_terms(n) {
            let (i, j) = (term.i, term.j);
            s[i + j].mul_add_assign(
                &term.weight.to(&ctx),
                &self.preimage[i].dot(&self.preimage[j]),
            );
        }
        s
    }

    /// The arc length L = ∫₀¹ σ dξ (Eq. 13a), exactly: the mean of the σ_k.
    pub fn arc_length(&self) -> T {
        let s = self.speed_coefficients();
        let ctx = self.ctx();
        let mut total = T::zero_in(&ctx);
        for x in &s {
            total += x;
        }
        total / &T::from_i64(s.len() as i64, &ctx)
    }

    /// A(ξ), A′(ξ), …, A⁽ᵒʳᵈᵉʳ⁾(ξ).
    pub fn preimage_jet(&self, xi: &T, order: usize) -> Vec<Quat<T>> {
        let ctrl: Vec<[T; 4]> = self.preimage.iter().map(Quat::components).collect();
        bernstein_jet(&ctrl, xi, order)
            .into_iter()
            .map(Quat::from_components)
            .collect()
    }

    /// p(ξ) by de Casteljau on the control points.
    pub fn point(&self, xi: &T) -> [T; 3] {
        bernstein_jet(&self.control_points(), xi, 0).swap_remove(0)
    }

    /// p, p′, …, p⁽ᵒʳᵈᵉʳ⁾ at ξ from precomputed control points (order ≤ 2n+1).
    pub fn jet_from_control_points(points: &[[T; 3]], xi: &T, order: usize) -> Vec<[T; 3]> {
        bernstein_jet(points, xi, order)
    }

    /// The preimage as a quaternion of Taylor series at ξ (to `order`), for derivatives of
    /// any function of A by generic code.
    pub fn preimage_taylor(&self, xi: &T, order: usize) -> Quat<Taylor<T>> {
        let jet = self.preimage_jet(xi, order);
        let series =
            |f: &dyn Fn(&Quat<T>) -> T| Taylor::from_derivatives(jet.iter().map(f).collect());
        Quat::new(
            series(&|q| q.w.clone()),
            series(&|q| q.x.clone()),
            series(&|q| q.y.clone()),
            series(&|q| q.z.clone()),
        )
    }
}

/// The Euler–Rodrigues frame columns and ω from A and A′ (Eqs. 11–12), in any field.
pub fn frame_and_omega<T: Field>(a: &Quat<T>, da: &Quat<T>) -> ([[T; 3]; 3], [T; 3]) {
    let ctx = a.ctx();
    let n2 = a.norm2();
    let inv = T::one_in(&ctx) / &n2;
    // Column k of the map v ↦ A v A* is A e_k A*: the k-th frame vector times |A|².
    let turn = a.sandwich_matrix();
    let frame = [0, 1, 2].map(|k| {
        [
            turn[0][k].clone() * &inv,
            turn[1][k].clone() * &inv,
            turn[2][k].clone() * &inv,
        ]
    });
    let two = T::from_i64(2, &ctx);
    let omega = vec3::scale(&da.mul(&a.conj()).vector(), &(two * &inv));
    (frame, omega)
}

impl<T: Real> PhCurve<T> {
    /// Position, frame, ω and σ at ξ.
    pub fn frame_state(&self, points: &[[T; 3]], xi: &T) -> FrameState<T> {
        let jet = self.preimage_jet(xi, 1);
        let (frame, omega) = frame_and_omega(&jet[0], &jet[1]);
        FrameState {
            point: bernstein_jet(points, xi, 0).swap_remove(0),
            frame,
            omega,
            speed: jet[0].norm2(),
        }
    }

    /// Curvature and torsion at ξ (Eq. 13b, and the standard torsion formula).
    pub fn curvature_torsion(&self, points: &[[T; 3]], xi: &T) -> (T, T) {
        curvature_torsion(&bernstein_jet(points, xi, 3))
    }
}

/// κ = |p′×p″|/|p′|³ and τ = (p′×p″)·p‴/|p′×p″|² from a jet [p, p′, p″, p‴].
pub fn curvature_torsion<T: Real>(jet: &[[T; 3]]) -> (T, T) {
    let c = vec3::cross(&jet[1], &jet[2]);
    let c2 = vec3::dot(&c, &c);
    let speed = vec3::norm(&jet[1]);
    let kappa = c2.sqrt() / &(speed.clone() * &speed * &speed);
    let tau = vec3::dot(&c, &jet[3]) / &c2;
    (kappa, tau)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::BigRational;

    fn q(v: [i64; 4]) -> Quat<BigRational> {
        Quat::from_components(v.map(|x| BigRational::from_integer(x.into())))
    }

    #[test]
    fn the_compile_time_pascal_triangle_holds_every_binomial_to_n_60() {
        for n in 0..=2 * MAX_PREIMAGE_DEGREE {
            let row_sum: i128 = (0..=n).map(|k| i128::from(binom(n, k))).sum();
            assert_eq!(row_sum, 1i128 << n, "row {n}");
            for k in 0..=n {
                assert_eq!(binom(n, k), binom(n, n - k));
            }
        }
        assert_eq!(binom(60, 30), 118_264_581_564_861_424);
        assert_eq!(binom(17, 5), 6188);
        assert_eq!(binom(3, 4), 0);
    }

    #[test]
    fn hodograph_is_a_i_a_conj_pointwise() {
        let c = PhCurve::new(
            vec![
                q([1, 2, 0, -1]),
                q([0, 1, 3, 2]),
                q([2, -1, 1, 0]),
                q([1, 1, 1, 1]),
            ],
            [0, 0, 0].map(|x: i64| BigRational::from_integer(x.into())),
        )
        .unwrap();
        let h = c.hodograph();
        let s = c.speed_coefficients();
        for xi in [(1, 3), (2, 7), (5, 4)] {
            let x = BigRational::new(xi.0.into(), xi.1.into());
            let a = &c.preimage_jet(&x, 0)[0];
            let direct = a.star_square();
            let via = bernstein_jet(&h, &x, 0).swap_remove(0);
            assert_eq!(direct, via);
            let sigma = bernstein_jet(&s.iter().map(|v| [v.clone()]).collect::<Vec<_>>(), &x, 0);
            assert_eq!(sigma[0][0], a.norm2());
            // p′ = h: derivative of the control polygon's curve.
            let p = PhCurve::jet_from_control_points(&c.control_points(), &x, 1);
            assert_eq!(p[1], direct);
        }
    }

    #[test]
    fn frame_is_orthonormal_and_omega_rotates_it() {
        let c = PhCurve::new(
            vec![
                Quat::new(1.0, 0.2, -0.3, 0.5),
                Quat::new(0.4, 1.0, 0.1, 0.2),
                Quat::new(-0.3, 0.5, 1.1, 0.0),
            ],
            [0.0; 3],
        )
        .unwrap();
        let pts = c.control_points();
        let xi = 0.37;
        let st = c.frame_state(&pts, &xi);
        for a in 0..3 {
            for b in 0..3 {
                let d = vec3::dot(&st.frame[a], &st.frame[b]);
                assert!((d - if a == b { 1.0 } else { 0.0 }).abs() < 1e-14);
            }
        }
        // e_k′ = ω × e_k, checked by a central difference.
        let eps = 1e-6;
        let plus = c.frame_state(&pts, &(xi + eps));
        let minus = c.frame_state(&pts, &(xi - eps));
        for k in 0..3 {
            let fd = vec3::scale(&vec3::sub(&plus.frame[k], &minus.frame[k]), &(0.5 / eps));
            let w = vec3::cross(&st.omega, &st.frame[k]);
            for d in 0..3 {
                assert!((fd[d] - w[d]).abs() < 1e-8, "{fd:?} {w:?}");
            }
        }
        // e1 is the unit tangent.
        let p = PhCurve::jet_from_control_points(&pts, &xi, 1);
        let t = vec3::scale(&p[1], &(1.0 / vec3::norm(&p[1])));
        for (td, fd) in t.iter().zip(&st.frame[0]) {
            assert!((td - fd).abs() < 1e-14);
        }
        assert!((vec3::norm(&p[1]) - st.speed).abs() < 1e-14);
    }
}
