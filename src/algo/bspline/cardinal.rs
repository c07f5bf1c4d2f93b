//! The cardinal (uniform, integer-knot) B-spline B_k of degree k as exact piecewise
//! polynomials (paper 002, Sec. 2).
//!
//! B_k is supported on [0, k+1] and is a polynomial of degree k on each [j, j+1]. Piece j is
//! stored in the local variable s = t − j ∈ [0, 1]. Two independent constructions:
//! - [`CardinalBSpline::from_algorithm1`]: the paper's Algorithm 1 (Takayama & Kano): N₀,₀ = 1,
//!   N₀,ₖ = (1−s)/k·N₀,ₖ₋₁, Nₖ,ₖ = s/k·Nₖ₋₁,ₖ₋₁, Nⱼ,ₖ = (k−j+s)/k·Nⱼ₋₁,ₖ₋₁ + (1+j−s)/k·Nⱼ,ₖ₋₁,
//!   and piece j of B_k is N_{k−j,k} (Eq. 1);
//! - [`CardinalBSpline::from_de_boor_cox`]: the Cox–de Boor recursion on the knots 0, 1, …, k+1,
//!   B_{i,0} = 1 on [i, i+1), B_{i,p}(t) = (t−i)/p·B_{i,p−1}(t) + (i+p+1−t)/p·B_{i+1,p−1}(t),
//!   computed in the global variable t and shifted to local pieces at the end.
//!
//! Exact in rationals; the same code evaluates in MPFR and f64.

use crate::numeric::poly::Poly;
use crate::scalar::Field;
use rayon::prelude::*;

/// The degree from which a row of Algorithm 1's table is computed in parallel (below it the
/// threads would cost more than the row).
const PARALLEL_FROM_DEGREE: usize = 16;

/// B_k as k+1 polynomial pieces on [j, j+1], each in s = t − j.
#[derive(Clone, Debug, PartialEq)]
pub struct CardinalBSpline<T> {
    degree: usize,
    pieces: Vec<Poly<T>>,
}

impl<T: Field> CardinalBSpline<T> {
    /// B_k by the paper's Algorithm 1 and Eq. 1.
    pub fn from_algorithm1(k: usize, ctx: &T::Ctx) -> Self {
        let n = Self::algorithm1_table(k, ctx);
        let pieces = (0..=k).map(|j| n[k][k - j].clone()).collect();
        CardinalBSpline { degree: k, pieces }
    }

    /// The table N_{j,k'}(s) of Algorithm 1 for k' = 0…k: `table[k'][j]`.
    pub fn algorithm1_table(k: usize, ctx: &T::Ctx) -> Vec<Vec<Poly<T>>> {
        let i = |v: i64| T::from_i64(v, ctx);
        let mut table: Vec<Vec<Poly<T>>> = vec![vec![Poly::constant(i(1))]];
        for kk in 1..=k {
            let prev = &table[kk - 1];
            let inv_k = T::from_ratio(1, kk as i64, ctx);
            let entry = |j: usize| {
                if j == 0 {
                    // (1 − s)/k · N_{0,k−1}
                    Poly::linear(i(1), i(-1)).mul(&prev[0]).times(&inv_k)
                } else if j == kk {
                    // s/k · N_{k−1,k−1}
                    Poly::linear(i(0), i(1)).mul(&prev[kk - 1]).times(&inv_k)
                } else {
                    // (k − j + s)/k · N_{j−1,k−1} + (1 + j − s)/k · N_{j,k−1}
                    let left = Poly::linear(i((kk - j) as i64), i(1)).mul(&prev[j - 1]);
                    let right = Poly::linear(i(1 + j as i64), i(-1)).mul(&prev[j]);
                    left.plus(&right).times(&inv_k)
                }
            };
            // The entries of a row are independent: on two cores the large tables (degree 60
            // in rationals, where the fractions grow) take about half the time, with the
            // same operations on each entry, so the same values in every number type.
            let row = if kk >= PARALLEL_FROM_DEGREE {
                (0..=kk).into_par_iter().map(entry).collect()
            } else {
                (0..=kk).map(entry).collect()
            };
            table.push(row);
        }
        table
    }

    /// B_k by the Cox–de Boor recursion on integer knots (independent of Algorithm 1).
    pub fn from_de_boor_cox(k: usize, ctx: &T::Ctx) -> Self {
        let i = |v: i64| T::from_i64(v, ctx);
        // basis[i][j]: B_{i,p} on [j, j+1] as a polynomial in the global t, for j = 0…k.
        let mut basis: Vec<Vec<Poly<T>>> = (0..=k)
            .map(|b| {
                (0..=k)
                    .map(|j| {
                        if j == b {
                            Poly::constant(i(1))
                        } else {
                            Poly::zero()
                        }
                    })
                    .collect()
            })
            .collect();
        for p in 1..=k {
            let inv_p = T::from_ratio(1, p as i64, ctx);
            basis = (0..=k - p)
                .map(|b| {
                    (0..=k)
                        .map(|j| {
                            let rising = Poly::linear(i(-(b as i64)), i(1)).mul(&basis[b][j]); // (t − b)
                            let falling =
                                Poly::linear(i((b + p + 1) as i64), i(-1)).mul(&basis[b + 1][j]); // (b+p+1 − t)
                            rising.add(&falling).scale(&inv_p)
                        })
                        .collect()
                })
                .collect();
        }
        let pieces = (0..=k).map(|j| basis[0][j].shift(&i(j as i64))).collect();
        CardinalBSpline { degree: k, pieces }
    }

    /// The degree k of the spline.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// Piece j (the polynomial on [j, j+1] in s = t − j).
    pub fn piece(&self, j: usize) -> &Poly<T> {
        &self.pieces[j]
    }

    /// The polynomial pieces on [0, 1], …, [k, k+1], each in the local variable s = t − j.
    pub fn pieces(&self) -> &[Poly<T>] {
        &self.pieces
    }

    /// The d-th derivative as a B-spline-shaped piecewise polynomial (pieces differentiated).
    pub fn derivative(&self, d: usize) -> CardinalBSpline<T> {
        CardinalBSpline {
            degree: self.degree,
            pieces: self.pieces.iter().map(|p| p.nth_derivative(d)).collect(),
        }
    }

    /// The d-th derivative of B_k at t (right-continuous at the knots, zero outside the support).
    ///
    /// For an enclosure (a ball) that straddles an integer knot, so that the piece cannot be
    /// decided, every candidate piece is evaluated on the whole ball and the results are
    /// joined ([`Field::hull`]): each point of the ball takes its value from one of them,
    /// and a piece's polynomial evaluated on a ball encloses its values there.
    pub fn eval_derivative(&self, t: &T, d: usize) -> T {
        let ctx = t.ctx();
        // Knots n = 0 … k+1 that t is decided to have reached, and the undecided ones.
        let mut reached = 0usize;
        let mut undecided = Vec::new();
        for n in 0..=self.degree + 1 {
            match t.decide_lt(&T::from_i64(n as i64, &ctx)) {
                Some(false) => reached = n + 1,
                Some(true) => {}
                None => undecided.push(n),
            }
        }
        // Piece j (on [j, j + 1]) holds t when t has reached knot j but not j + 1; "piece"
        // −1 and k + 1 are the zero polynomial outside the support.
        let value = |j: usize| -> T {
            match j.checked_sub(1) {
                Some(piece) if piece <= self.degree => self.pieces[piece]
                    .nth_derivative(d)
                    .eval(&(t.clone() - &T::from_i64(piece as i64, &ctx))),
                _ => T::zero_in(&ctx),
            }
        };
        // `reached` counts knots passed for certain; each undecided knot may be passed too.
        let mut result = value(reached);
        for extra in 1..=undecided.len() {
            result = T::hull(&result, &value(reached + extra));
        }
        result
    }

    /// B_k(t).
    pub fn eval(&self, t: &T) -> T {
        self.eval_derivative(t, 0)
    }

    /// The one-sided d-th derivatives (from the left, from the right) at the integer knot j,
    /// j = 0…k+1 (outside the support the spline is the zero polynomial).
    pub fn one_sided_derivatives(&self, j: usize, d: usize, ctx: &T::Ctx) -> (T, T) {
        let zero = T::zero_in(ctx);
        let left = if j == 0 {
            zero.clone()
        } else {
            self.pieces[j - 1].nth_derivative(d).eval(&T::one_in(ctx))
        };
        let right = if j > self.degree {
            zero
        } else {
            self.pieces[j].nth_derivative(d).eval(&T::zero_in(ctx))
        };
        (left, right)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::BigRational;

    fn q(n: i64, d: i64) -> BigRational {
        BigRational::new(n.into(), d.into())
    }

    #[test]
    fn cubic_pieces_are_the_textbook_ones() {
        let b = CardinalBSpline::<BigRational>::from_algorithm1(3, &());
        let sixth = |c: &[i64]| Poly::new(c.iter().map(|&x| q(x, 6)).collect());
        assert_eq!(b.piece(0), &sixth(&[0, 0, 0, 1]));
        assert_eq!(b.piece(1), &sixth(&[1, 3, 3, -3]));
        assert_eq!(b.piece(2), &sixth(&[4, 0, -6, 3]));
        assert_eq!(b.piece(3), &sixth(&[1, -3, 3, -1]));
        assert_eq!(b.eval(&q(2, 1)), q(2, 3));
        assert_eq!(b.eval(&q(4, 1)), q(0, 1));
    }

    #[test]
    fn both_constructions_agree() {
        for k in 0..=8 {
            assert_eq!(
                CardinalBSpline::<BigRational>::from_algorithm1(k, &()),
                CardinalBSpline::from_de_boor_cox(k, &()),
                "k = {k}"
            );
        }
    }
}
