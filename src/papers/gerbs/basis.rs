//! Basis checks: Eqs. (10)–(18) exactly, partition of unity, B_k(t_k) = 1, the smoothness
//! of BFBS and ERBS at the knots, the Fig. 2 caption taken literally, and Eq. (4)'s centre.

use super::setup::{erbs, fig1_knots, ErbsSet, HI, LO};
use crate::algo::gerbs::bfbs::{phi_printed, theta_printed, Bfbs};
use crate::algo::gerbs::erbs::{CentreReading, Erbs};
use crate::algo::gerbs::{basis_derivatives, Blend, Knots, Side};
use crate::papers::{Outcome, Verdict};
use crate::scalar::certify::{certify, Certified};
use crate::scalar::{BigRational, Field, Float};

fn r(n: i64, d: i64) -> BigRational {
    BigRational::new(n.into(), d.into())
}

/// Eqs. (12)–(13) and (14)–(18) against S∫Ψ of Eq. (7) with i = 2 and its exact derivatives,
/// on the grid a ∈ {0…5}, b ∈ {6…11}, t ∈ {0…5}: (a − b)⁵ times either side is a polynomial
/// of degree ≤ 5 in each of a, b, t, so agreement on the grid is the identity.
pub fn closed_forms() -> (Outcome, Outcome) {
    let bfbs = Bfbs::uniform(2, 1).expect("exponent");
    let (mut values, mut derivs, mut points) = (0, 0, 0);
    for a in 0..6 {
        for b in 6..12 {
            let knots = Knots::new(vec![r(a, 1), r(b, 1), r(b + 1, 1)]).expect("knots");
            for t in 0..6 {
                let t = r(t, 1);
                let f = bfbs.rising(&knots, 1, &t, 2).derivatives();
                let one_minus: Vec<BigRational> = f
                    .iter()
                    .enumerate()
                    .map(|(k, x)| if k == 0 { r(1, 1) - x } else { -x.clone() })
                    .collect();
                let phi = phi_printed(&r(a, 1), &r(b, 1), &t);
                let theta = theta_printed(&r(a, 1), &r(b, 1), &t);
                values += (phi[0] != f[0]) as usize + (theta[0] != one_minus[0]) as usize;
                derivs += (1..3)
                    .filter(|&k| phi[k] != f[k] || theta[k] != one_minus[k])
                    .count();
                points += 1;
            }
        }
    }
    let grid = format!("{points} grid points (a, b, t)");
    (
        Outcome::new(
            format!("Φ and Θ of Eqs. (12)–(13) equal S_k∫Ψ_k and 1 − S_k∫Ψ_k at all {grid}; {values} mismatches"),
            "rational",
            Verdict::holds(values == 0),
            "S∫Ψ computed as the regularized incomplete beta function I_u(3, 3) in Bernstein form, u = (t − a)/(b − a); both sides times (a − b)⁵ are polynomials of degree ≤ 5 in each variable, so equality on a 6×6×6 grid with a ≠ b proves the identity",
        ),
        Outcome::new(
            format!("DΦ, DDΦ, DΘ, DDΘ of Eqs. (14)–(18) equal the exact first and second derivatives at all {grid}; {derivs} mismatches"),
            "rational",
            Verdict::holds(derivs == 0),
            "derivatives from Taylor-mode AD of the incomplete beta polynomial in exact rationals",
        ),
    )
}

/// Partition of unity and B_k(t_k) = 1: BFBS exactly on the Fig. 1 knots; ERBS through the
/// consistency of its quadrature (∫_{t_k}^m Ψ + ∫_m^{t_{k+1}} Ψ = S_k, which is what makes the
/// two halves of B_k meet), certified at two precisions.
pub fn partition() -> (Outcome, Outcome) {
    let knots = fig1_knots::<BigRational>(&());
    let bfbs = Bfbs::uniform(2, 5).expect("exponents");
    let mut worst_sum = 0usize;
    let mut at_knot = 0usize;
    for i in 0..=40 {
        let t = r(i, 40);
        for side in [Side::Left, Side::Right] {
            let d = basis_derivatives(&knots, &bfbs, &t, 1, side).expect("inside");
            let sum: BigRational = d.iter().map(|x| x[0].clone()).sum();
            let slope: BigRational = d.iter().map(|x| x[1].clone()).sum();
            worst_sum += (sum != r(1, 1) || !slope.is_zero()) as usize;
        }
    }
    for k in 2..=6 {
        let t = knots.at(k).clone();
        for side in [Side::Left, Side::Right] {
            let d = basis_derivatives(&knots, &bfbs, &t, 0, side).expect("inside");
            at_knot += (d[k - 2][0] != r(1, 1)) as usize;
        }
    }
    // ERBS: the halves of every interval against S.
    let gap = |bits: u32, set: ErbsSet| -> Float {
        let e = erbs::<Float>(&bits, set, CentreReading::Cited);
        let k = fig1_knots::<Float>(&bits);
        let mut worst = Float::with_val(bits, 0);
        for j in 2..=5 {
            let (a, b) = (k.at(j).clone(), k.at(j + 1).clone());
            // A third of the way along (not the midpoint, where the quadrature splits anyway).
            let m = a.clone() + (b.clone() - &a) / Float::with_val(bits, 3);
            let g = ((e.integral(&k, j, &a, &m) + e.integral(&k, j, &m, &b)) / e.normalizer(j)
                - Float::with_val(bits, 1))
            .abs();
            if g > worst {
                worst = g;
            }
        }
        worst
    };
    let g_lo = gap(LO, ErbsSet::Smooth);
    let g_hi = gap(HI, ErbsSet::Smooth);
    let g2 = gap(LO, ErbsSet::Fig2Alpha1);
    let ok_erbs = g_lo < Float::with_val(LO, 1e-35) && g_hi < Float::with_val(HI, 1e-72);
    (
        Outcome::new(
            format!(
                "BFBS (i = 2, Fig. 1 knots): Σ B_k = 1 and Σ B_k′ = 0 exactly at 41 points from both sides ({worst_sum} failures); ERBS: the quadrature halves of each interval sum to S_k within {} (128 bits), {} (256 bits), {} (α = 1, σ = 0.2, 128 bits)",
                fmt_e(&g_lo), fmt_e(&g_hi), fmt_e(&g2)
            ),
            "rational, mpfr:128, mpfr:256",
            Verdict::holds(worst_sum == 0 && ok_erbs),
            "B_j = 1 − F_j and B_{j+1} = F_j on (t_j, t_{j+1}), each computed on its own (the BFBS falling side as the complementary Bernstein sum over r = 0…i_j), so Σ B_k = 1 is checked, not built in; for the ERBS F_j is a quadrature, so the check that counts is that ∫ from both ends meets S_j (split a third of the way along each interval)",
        ),
        Outcome::new(
            format!("B_k(t_k) = 1 exactly for k = 2…6 from both sides ({at_knot} failures)"),
            "rational",
            Verdict::holds(at_knot == 0),
            "BFBS on the knots of Fig. 1; for the ERBS F_k(t_k) = 0 by definition of the running integral",
        ),
    )
}

/// Two significant digits in scientific notation, at any exponent (MPFR's range is far wider
/// than a double's: the ERBS derivatives at the knots reach 10^-9016).
pub fn fmt_e(x: &Float) -> String {
    crate::report::number::float_in(x, 2, crate::report::number::Notation::Scientific)
}

/// One row of the smoothness table.
pub struct SmoothRow {
    pub basis: String,
    pub knot: String,
    /// Largest |jump| of B^(r) over the basis functions, r = 1 … shown.
    pub jumps: Vec<String>,
    pub class: String,
}

/// The largest jump of B^(r), r = 1 … i_k + 1, over all basis functions at knot t_k, exactly,
/// and the order up to which all of them are continuous.
pub fn knot_jumps(knots: &Knots<BigRational>, bfbs: &Bfbs, k: usize) -> (Vec<BigRational>, usize) {
    let order = bfbs.exponent(k) as usize + 1;
    let t = knots.at(k).clone();
    let sides =
        [Side::Left, Side::Right].map(|side| basis_derivatives(knots, bfbs, &t, order, side));
    let [Some(left), Some(right)] = sides else {
        return (Vec::new(), 0);
    };
    let jump = |r: usize| {
        left.iter()
            .zip(&right)
            .map(|(a, b)| (a[r].clone() - &b[r]).abs())
            .fold(r_zero(), |m, x| if x > m { x } else { m })
    };
    let jumps: Vec<BigRational> = (1..=order).map(jump).collect();
    let smooth_to = jumps.iter().take_while(|j| j.is_zero()).count();
    (jumps, smooth_to)
}

/// BFBS: jumps of every B^(r) at each interior knot, exactly, for two exponent patterns.
pub fn bfbs_smoothness() -> (Outcome, Vec<SmoothRow>) {
    let mut rows = Vec::new();
    let knots = fig1_knots::<BigRational>(&());
    let mut failures = Vec::new();
    let mut summary = Vec::new();
    for exps in [vec![2u32, 2, 2, 2, 2], vec![3, 2, 4, 2, 3]] {
        let bfbs = Bfbs::new(exps.clone()).expect("exponents");
        for k in 3..=5 {
            let ik = bfbs.exponent(k) as usize;
            let (jumps, smooth_to) = knot_jumps(&knots, &bfbs, k);
            if smooth_to != ik {
                failures.push(format!(
                    "knot t_{k} of {exps:?}: C^{smooth_to}, expected C^{ik}"
                ));
            }
            rows.push(SmoothRow {
                basis: format!("BFBS i = {exps:?}"),
                knot: format!("t_{k}"),
                jumps: jumps.iter().map(|j| format!("{}", j)).collect(),
                class: format!("C^{smooth_to}"),
            });
        }
        summary.push(format!(
            "{exps:?}: C^{} at the interior knots (min i_k = {})",
            bfbs.smoothness(),
            bfbs.smoothness()
        ));
    }
    let outcome = Outcome::new(
        format!(
            "{}; every B^(r) is continuous for r ≤ i_k and jumps at r = i_k + 1{}",
            summary.join("; "),
            if failures.is_empty() { String::new() } else { format!(" — except {}", failures.join(", ")) }
        ),
        "rational",
        Verdict::holds(failures.is_empty()),
        "one-sided derivatives of all basis functions at t_3, t_4, t_5 of Fig. 1, exact; per-knot orders follow i_k, so the path is C^m with m = min i_k",
    );
    (outcome, rows)
}

fn r_zero() -> BigRational {
    r(0, 1)
}

/// max over r ≤ 8 of |B_k^(r)(t)| for the ERBS of `set`, at `bits`.
fn erbs_max_derivative(bits: u32, e: &Erbs<Float>, t: &Float, side: Side) -> Float {
    let k = fig1_knots::<Float>(&bits);
    let d = basis_derivatives(&k, e, t, 8, side).expect("inside");
    let mut worst = Float::with_val(bits, 0);
    for b in &d {
        for x in &b[1..] {
            let a = x.clone().abs();
            if a > worst {
                worst = a;
            }
        }
    }
    worst
}

/// ERBS with α > 0: derivatives 1…8 of every basis function at t_k ± ε shrink faster than any
/// power of ε (Ψ ~ exp(−C/ε)); for the literal Fig. 2 caption (α = 0) B′ jumps at the knots.
/// Returns the smoothness outcome, the Fig. 2 outcome and the report rows.
pub fn erbs_smoothness() -> (Outcome, Outcome, Vec<SmoothRow>) {
    let (smooth, mut rows) = erbs_decay();
    let (fig2, row) = fig2_literal();
    rows.push(row);
    (smooth, fig2, rows)
}

/// The decay of every derivative at the knots for the two parameter sets with α > 0.
fn erbs_decay() -> (Outcome, Vec<SmoothRow>) {
    let mut rows = Vec::new();
    let h = Float::with_val(HI, 0.25);
    let mut decay = Vec::new();
    let mut all_small = true;
    for set in [ErbsSet::Smooth, ErbsSet::Fig2Alpha1] {
        let e_lo = erbs::<Float>(&LO, set, CentreReading::Cited);
        let e_hi = erbs::<Float>(&HI, set, CentreReading::Cited);
        let mut cells = Vec::new();
        for div in [10, 100, 1000] {
            let eps = h.clone() / div;
            let mut worst = Float::with_val(HI, 0);
            for k in 3..=5 {
                let tk: Float = Float::with_val(HI, k - 2) / 4u32;
                for (t, side) in [
                    (tk.clone() - &eps, Side::Left),
                    (tk.clone() + &eps, Side::Right),
                ] {
                    let v = erbs_max_derivative(HI, &e_hi, &t, side);
                    let v_lo = erbs_max_derivative(LO, &e_lo, &Float::with_val(LO, &t), side);
                    let c: Certified = certify(&v_lo, &v);
                    if c.digits < 2 {
                        all_small = false;
                    }
                    if v > worst {
                        worst = v;
                    }
                }
            }
            if div == 1000 && worst > Float::with_val(HI, 1e-100) {
                all_small = false;
            }
            cells.push(fmt_e(&worst));
        }
        decay.push(format!("{}: {}", set.label(), cells.join(", ")));
        rows.push(SmoothRow {
            basis: format!("ERBS {}", set.label()),
            knot: "t_3, t_4, t_5 at ε = h/10, h/100, h/1000".into(),
            jumps: cells,
            class: "C^∞ at the knots".into(),
        });
    }
    let smooth = Outcome::new(
        format!(
            "max over k, r = 1…8 of |B_k^(r)(t_k ± ε)| for ε = h/10, h/100, h/1000: {}",
            decay.join("; ")
        ),
        "mpfr:128, mpfr:256",
        Verdict::holds(all_small),
        "every derivative of Ψ = exp(−β|t−c|^{2σ}/((t−t_k)(t_{k+1}−t)^γ)^α) tends to 0 at the knots faster than any power for α > 0; shown by the decay over three decades of ε, each value certified at two precisions (≥ 2 agreeing digits)",
    );
    (smooth, rows)
}

/// The Fig. 2 caption as printed (α = 0): B′ jumps at the knots; with α = 1, σ = 0.2, B″ is
/// unbounded at the interval centres.
fn fig2_literal() -> (Outcome, SmoothRow) {
    let literal = |bits: u32| -> (Float, Float) {
        let e = erbs::<Float>(&bits, ErbsSet::Fig2Literal, CentreReading::Cited);
        let k = fig1_knots::<Float>(&bits);
        let t = k.at(4).clone();
        let l = basis_derivatives(&k, &e, &t, 1, Side::Left).expect("in");
        let rr = basis_derivatives(&k, &e, &t, 1, Side::Right).expect("in");
        // B_4 at its own knot: B′ from the left Ψ_3/S_3, from the right −Ψ_4/S_4.
        (l[2][1].clone(), rr[2][1].clone())
    };
    let (l_lo, r_lo) = literal(LO);
    let (l_hi, r_hi) = literal(HI);
    let cl = certify(&l_lo, &l_hi);
    let cr = certify(&r_lo, &r_hi);
    // σ = 0.2 with α = 1: Ψ′ near the interval centre grows like δ^(2σ−1).
    let e = erbs::<Float>(&HI, ErbsSet::Fig2Alpha1, CentreReading::Cited);
    let k = fig1_knots::<Float>(&HI);
    let c = e.centre(&k, 3).expect("cited centre inside");
    let growth: Vec<String> = [3, 6, 9]
        .iter()
        .map(|&p| {
            let t = c.clone() + Float::with_val(HI, 10f64.powi(-p));
            let d = basis_derivatives(&k, &e, &t, 2, Side::Right).expect("in");
            format!("δ = 1e-{p}: |B″| = {}", fmt_e(&d[2][2].clone().abs()))
        })
        .collect();
    let row = SmoothRow {
        basis: format!("ERBS {}", ErbsSet::Fig2Literal.label()),
        knot: "t_4 (B_4′ from left, right)".into(),
        jumps: vec![
            crate::report::number::certified(&cl, crate::report::number::PROSE_DIGITS),
            crate::report::number::certified(&cr, crate::report::number::PROSE_DIGITS),
        ],
        class: "C^0".into(),
    };
    let fig2 = Outcome::new(
        format!(
            "α = 0 as printed: B_4′(t_4−) = {}, B_4′(t_4+) = {} — the basis (and the path) is only C^0 at every knot; with α = 1 and σ = 0.2 it is C^∞ at the knots but B″ is unbounded at the interval centres ({})",
            cl.text, cr.text, growth.join(", ")
        ),
        "mpfr:128, mpfr:256",
        Verdict::Discrepancy,
        "the caption's α = 0 lies outside Eq. (4)'s range α > 0: the denominator is 1, Ψ_k(t_k) = exp(−β|t_k − c|^{0.4}) ≠ 0 and B′ jumps; the text calls the ERBS basis of Fig. 2 C^∞. And |t − c|^{2σ} with 2σ = 0.4 has an infinite slope at c (cited reading), so curvature is unbounded there whatever α",
    );
    (fig2, row)
}

/// Eq. (4)'s centre as printed against the cited definition: where the centre falls on the
/// Fig. 1 knots and how symmetric B_k is about t_k under each reading.
pub fn centre_reading() -> (Outcome, Vec<Vec<String>>) {
    let k = fig1_knots::<f64>(&());
    let mut rows = Vec::new();
    let mut sym = Vec::new();
    for (reading, name) in [
        (CentreReading::Cited, "cited: (1−λ)t_k + λt_{k+1}"),
        (CentreReading::AsPrinted, "printed: (1−λ)t_k − λt_{k+1}"),
    ] {
        let e = erbs::<f64>(&(), ErbsSet::Fig2Alpha1, reading);
        let (a, b) = (*k.at(3), *k.at(4));
        let centre = e.centre_point(&k, 3);
        // Asymmetry of B_4 about t_4 = 1/2 and where Ψ_3 peaks on (1/4, 1/2).
        let b4 = |t: f64| {
            let side = if t < 0.5 { Side::Left } else { Side::Right };
            basis_derivatives(&k, &e, &t, 1, side).expect("in")[2].clone()
        };
        let asym = (1..25)
            .map(|i| {
                let s = 0.25 * i as f64 / 25.0;
                (b4(0.5 - s)[0] - b4(0.5 + s)[0]).abs()
            })
            .fold(0.0, f64::max);
        let (mut best, mut arg) = (0.0, a);
        for i in 1..400 {
            let t = a + (b - a) * i as f64 / 400.0;
            let v = b4(t)[1].abs();
            if v > best {
                best = v;
                arg = t;
            }
        }
        sym.push(asym);
        rows.push(vec![
            name.to_string(),
            crate::report::number::sig(centre, 4),
            crate::report::number::sig((arg - a) / (b - a), 4),
            crate::report::number::sig_in(asym, 4, crate::report::number::Notation::Scientific),
        ]);
    }
    (
        Outcome::new(
            format!(
                "on (1/4, 1/2) with λ = 0.5 the printed centre is {} (outside the interval), the cited one {}; B_4 is symmetric about t_4 under the cited reading (asymmetry {:.1e}) and not under the printed one ({:.2})",
                rows[1][1], rows[0][1], sym[0], sym[1]
            ),
            "f64",
            Verdict::Discrepancy,
            "as printed, |t − (1−λ)t_k + λt_{k+1}| vanishes at (1−λ)t_k − λt_{k+1} ≤ t_k for knots ≥ 0, so λ no longer places the peak inside the interval; the cited ERBS definition (Dechevsky, Lakså, Bang 2006) has |t − ((1−λ)t_k + λt_{k+1})|. The extracted text has no figure pixels; Fig. 2's caption sets λ = 0.5, which only has its role of a centred, symmetric bump under the cited reading, so the report uses it",
        ),
        rows,
    )
}
