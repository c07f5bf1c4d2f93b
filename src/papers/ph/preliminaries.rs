//! Claims of paper 001's preliminaries (Sec. 4) and of the θ₄ remark of Sec. 5C, found by
//! auditing every numbered equation against the ledger: Remark 1 on the ⋆ product (Eq. 4),
//! Lemmas 1–2 (Eqs. 5–6), the PH components (Eq. 8), the control points (Eq. 10), the
//! Euler–Rodrigues frame and its angular velocity (Eqs. 11–12), and the redundancy of θ₄.
//! Everything that has no square root is checked exactly in rationals.

use super::super::sample::SplitMix64;
use super::super::{Outcome, Verdict};
use super::theorems::{free_into, into, random_data, random_free, BITS};
use crate::algo::ph::hermite::{interpolate, FreeParameters};
use crate::algo::ph::{bernstein_jet, frame_and_omega, PhCurve};
use crate::numeric::linalg::{determinant, Matrix};
use crate::numeric::quat::{solve_linear, solve_quadratic, vec3, Quat};
use crate::scalar::ball::Ball;
use crate::scalar::{BigRational, Field, Real};

type Q = BigRational;

fn rational(rng: &mut SplitMix64) -> Q {
    Q::new(rng.int(-30, 30).into(), rng.int(1, 7).into())
}

fn quaternion(rng: &mut SplitMix64) -> Quat<Q> {
    Quat::new(rational(rng), rational(rng), rational(rng), rational(rng))
}

fn q(n: i64) -> Q {
    Q::from_integer(n.into())
}

/// Remark 1: "A ⋆ B is equal to the vector part of A i B" against Eq. (4).
pub fn remark1() -> Outcome {
    let mut rng = SplitMix64::new(0x4e41);
    let (mut eq4_pure, mut conj_reading, mut as_printed) = (0, 0, 0);
    let trials = 20;
    for _ in 0..trials {
        let (a, b) = (quaternion(&mut rng), quaternion(&mut rng));
        let i = Quat::i(&());
        // Eq. (4) literally: ½(A i B* + B i A*).
        let half = Q::new(1.into(), 2.into());
        let eq4 = (a.mul(&i).mul(&b.conj()) + &b.mul(&i).mul(&a.conj())).scale(&half);
        eq4_pure += usize::from(eq4.w.is_zero() && eq4.vector() == a.star(&b));
        conj_reading += usize::from(a.mul(&i).mul(&b.conj()).vector() == a.star(&b));
        as_printed += usize::from(a.mul(&i).mul(&b).vector() == a.star(&b));
    }
    let ok = eq4_pure == trials && conj_reading == trials;
    Outcome::new(
        format!(
            "Eq. (4) is pure and equals vec(A i B*) in {eq4_pure} and {conj_reading} of {trials} random pairs; vec(A i B) as printed \
             equals it in {as_printed}"
        ),
        "rational",
        if ok && as_printed == trials {
            Verdict::Reproduced
        } else if ok {
            Verdict::Typo
        } else {
            Verdict::Discrepancy
        },
        "quaternion products of random rational A, B, exact: Eq. (4)'s ½(A i B* + B i A*) has zero real part (B i A* = −(A i B*)*, \
         so the sum is twice the vector part of A i B*). The remark as extracted reads \"the vector part of A i B\", without the \
         conjugate, which differs from A ⋆ B; with the conjugate mark restored (A i B*, the reading used) it holds",
    )
}

/// Lemma 1 (Eq. 5): X_τ solves X ⋆ B = a for every τ, and these are all the solutions.
pub fn lemma1() -> Outcome {
    let mut rng = SplitMix64::new(0x1e41);
    let mut failures = Vec::new();
    for trial in 0..20 {
        let b = quaternion(&mut rng);
        let a = [rational(&mut rng), rational(&mut rng), rational(&mut rng)];
        let solves = (0..3).all(|_| {
            let tau = rational(&mut rng);
            solve_linear(&a, &b, &tau).is_some_and(|x| x.star(&b) == a)
        });
        // X ↦ X ⋆ B is linear R⁴ → R³; rank 3 leaves a one-dimensional kernel, spanned by B i
        // (the τ-direction of Eq. 5b), so the line X_τ is the whole solution set.
        let basis = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]
            .map(|e| Quat::new(q(e[0]), q(e[1]), q(e[2]), q(e[3])).star(&b));
        let rank3 = (0..4).any(|skip| {
            let cols: Vec<&[Q; 3]> = (0..4).filter(|&c| c != skip).map(|c| &basis[c]).collect();
            let m = Matrix::from_fn(3, 3, |r, c| cols[c][r].clone());
            determinant(&m).is_ok_and(|d| !d.is_zero())
        });
        let bi = b.mul(&Quat::i(&()));
        let kernel = bi.star(&b).iter().all(Field::is_zero) && !bi.norm2().is_zero();
        if !(solves && rank3 && kernel) {
            failures.push(trial);
        }
    }
    Outcome::new(
        format!("X_τ ⋆ B = a for every τ tried, and the solution set is exactly that line, in 20 of 20 random cases ({} failures)", failures.len()),
        "rational",
        Verdict::holds(failures.is_empty()),
        format!(
            "random rational B ≠ 0 and a, three τ each, exact: X_τ = −(τ + a)B i/|B|² satisfies X_τ ⋆ B = a; the linear map X ↦ X ⋆ B \
             has rank 3 (a non-zero 3×3 minor) and B i ⋆ B = 0, so its kernel is the line of B i and every solution is an X_τ. \
             Failures (trial): {failures:?}"
        ),
    )
}

/// Lemma 2 (Eq. 6): X_φ solves X^{2⋆} = a for every φ, and every solution is an X_φ; in
/// balls, so the residuals are proven bounds.
pub fn lemma2() -> Outcome {
    let mut rng = SplitMix64::new(0x1e42);
    let tolerance = 1e-60;
    let ball = |v: f64| Ball::from_f64(v, &BITS);
    let (mut worst_residual, mut worst_form) = (0.0f64, 0.0f64);
    let mut unsolved = Vec::new();
    for set in 0..20 {
        let x = Quat::from_components(
            quaternion(&mut rng)
                .components()
                .map(|c| Ball::from_rational(&c, &BITS)),
        );
        let a = x.star_square();
        let scale = vec3::norm(&a);
        for phi in [0.0, 0.3, 1.0, 2.5, 4.0] {
            match solve_quadratic(&a, &ball(phi)) {
                Ok(sol) => {
                    let r = vec3::norm(&vec3::sub(&sol.star_square(), &a)) / &scale;
                    worst_residual = worst_residual.max(r.magnitude_bounds().1);
                }
                Err(e) => unsolved.push(format!("set {set}, φ = {phi}: {e}")),
            }
        }
        // Every solution: X = X₀Q(φ) iff X₀⁻¹X = cos φ + i sin φ, a unit with no j, k part.
        match solve_quadratic(&a, &ball(0.0)) {
            Ok(x0) => {
                let one = ball(1.0);
                let y = x0.conj().mul(&x).scale(&(one.clone() / &x0.norm2()));
                let off =
                    (y.y.clone() * &y.y + &(y.z.clone() * &y.z)).sqrt() + &(y.norm2() - &one).abs();
                worst_form = worst_form.max(off.magnitude_bounds().1);
            }
            Err(e) => unsolved.push(format!("set {set}, φ = 0: {e}")),
        }
    }
    if !unsolved.is_empty() {
        return Outcome::failed(
            format!("ball:{BITS}"),
            format!("Eq. (6b) had no solution for {}", unsolved.join("; ")),
        );
    }
    let ok = worst_residual < tolerance && worst_form < tolerance;
    Outcome::new(
        format!(
            "largest relative |X_φ^(2⋆) − a| ≤ {worst_residual:.1e} over 5 φ each; every random solution X is X₀Q(φ) to {worst_form:.1e} (proven bounds)"
        ),
        format!("ball:{BITS}"),
        Verdict::holds(ok),
        "20 random rational X with a = X ⋆ X, in ball arithmetic at 256 bits (every figure an upper bound of its enclosure): Eq. (6b) \
         for φ = 0, 0.3, 1, 2.5, 4 solves X^(2⋆) = a; and X₀⁻¹X (X₀ = X_0 of Eq. 6b) has no j, k components and unit norm, i.e. \
         X = X₀(cos φ + i sin φ) for some φ, so the family is every solution. Criterion 1e-60 on the proven bounds. For a a \
         negative multiple of i, |a/|a| + i| = 0 and Eq. (6b) is undefined, as the lemma's hypothesis says (the library then uses \
         √|a| j Q(φ))",
    )
}

/// Eq. (8): the printed components of the hodograph against Eq. (9) and the PH condition (7).
pub fn eq8() -> Outcome {
    let mut rng = SplitMix64::new(0x0e08);
    let (mut printed_matches, mut plus_matches, mut printed_pythagorean) = (0, 0, 0);
    let trials = 20;
    let two = q(2);
    for _ in 0..trials {
        let [u, v, p, qq] = quaternion(&mut rng).components();
        let h = Quat::new(u.clone(), v.clone(), p.clone(), qq.clone()).star_square(); // A i A*, Eq. (9)
        let x = u.clone() * &u + &(v.clone() * &v) - &(p.clone() * &p) - &(qq.clone() * &qq);
        let y_printed = two.clone() * &u * &qq - &(two.clone() * &v * &p);
        let y_plus = two.clone() * &u * &qq + &(two.clone() * &v * &p);
        let z = two.clone() * &v * &qq - &(two.clone() * &u * &p);
        let sigma = u.clone() * &u + &(v.clone() * &v) + &(p.clone() * &p) + &(qq.clone() * &qq);
        printed_matches += usize::from(h == [x.clone(), y_printed.clone(), z.clone()]);
        plus_matches += usize::from(h == [x.clone(), y_plus, z.clone()]);
        let sum = x.clone() * &x + &(y_printed.clone() * &y_printed) + &(z.clone() * &z);
        printed_pythagorean += usize::from(sum == sigma.clone() * &sigma);
    }
    let verdict = if printed_matches == trials {
        Verdict::Reproduced
    } else {
        Verdict::Discrepancy
    };
    Outcome::new(
        format!(
            "Eqs. (8a)–(8d) as printed equal A i A* in {printed_matches} of {trials} random A and satisfy σ² = x′² + y′² + z′² in \
             {printed_pythagorean}; with y′ = 2uq + 2vp they equal A i A* in {plus_matches}"
        ),
        "rational",
        verdict,
        "A = u + v i + p j + q k with random rationals, exact: A i A* (Eq. 9, Hamilton product) has j component 2(uq + vp), not the \
         printed 2uq − 2vp; with the printed sign x′² + y′² + z′² = σ² − 16uvpq, so the printed Eq. (8) violates the PH condition (7) \
         it is quoted to satisfy whenever uvpq ≠ 0. The algorithm uses Eq. (9) and is unaffected",
    )
}

/// Eq. (10): the control points of Eq. (10d) give p′ = A i A* (Eqs. 9, 10c), and
/// p_e − p_b = Σ h_i/17 for the degree-17 curves of Sec. 5C.
pub fn eq10() -> Outcome {
    let mut rng = SplitMix64::new(0x0e10);
    let mut failures = Vec::new();
    for trial in 0..10 {
        let preimage: Vec<Quat<Q>> = (0..=8).map(|_| quaternion(&mut rng)).collect();
        let start = [rational(&mut rng), rational(&mut rng), rational(&mut rng)];
        let curve =
            PhCurve::new(preimage.clone(), start.clone()).expect("a preimage of degree ≤ 30");
        let points = curve.control_points();
        let h = curve.hodograph();
        let mut ok = points.len() == 18 && points[0] == start;
        for k in 0..=6 {
            let xi = Q::new(k.into(), 6.into());
            let a = curve.preimage_jet(&xi, 0).swap_remove(0);
            ok &= bernstein_jet(&points, &xi, 1)[1] == a.star_square();
        }
        let sum = h.iter().fold(vec3::zero(&()), |acc, v| vec3::add(&acc, v));
        ok &= vec3::sub(&points[17], &points[0]) == vec3::scale(&sum, &Q::new(1.into(), 17.into()));
        if !ok {
            failures.push(trial);
        }
    }
    Outcome::new(
        format!("for 10 random rational preimages of degree 8: p′(ξ) = A(ξ) i A*(ξ) at ξ = 0, 1/6, …, 1 and p_17 − p_0 = Σh_i/17 ({} failures)", failures.len()),
        "rational",
        Verdict::holds(failures.is_empty()),
        format!(
            "p from the control points of Eq. (10d) (degree 2n + 1 = 17, Bernstein basis with the extracted \"ξ_j\" read as ξ^j), \
             differentiated exactly at 7 rational ξ and compared with the preimage's A i A* (Eq. 9); the endpoint relation is the one \
             Sec. 5C derives from Eq. (10d) before Eq. (17a). Failures (trial): {failures:?}"
        ),
    )
}

/// d/dξ of e = A v A*/|A|² from A and A′ (quotient rule), exactly.
fn frame_vector_derivative(a: &Quat<Q>, da: &Quat<Q>, v: &[Q; 3]) -> [Q; 3] {
    let n = a.norm2();
    let dn = q(2) * &a.dot(da);
    let s = a.sandwich(v);
    let pure = Quat::pure(v);
    let ds = (da.mul(&pure).mul(&a.conj()) + &a.mul(&pure).mul(&da.conj())).vector();
    let num = vec3::sub(&vec3::scale(&ds, &n), &vec3::scale(&s, &dn));
    vec3::scale(&num, &(q(1) / (n.clone() * &n)))
}

/// Eqs. (11)–(12): R is a rotation with e₁ = p′/σ; ω of Eq. (12) is the library's closed form
/// 2 vec(A′A*)/|A|², and e_k′ = ω × e_k.
pub fn eq11_12() -> Outcome {
    let mut rng = SplitMix64::new(0x0e11);
    let mut failures = Vec::new();
    let unit = [[1, 0, 0], [0, 1, 0], [0, 0, 1]].map(|r| r.map(q));
    for trial in 0..10 {
        let curve = PhCurve::new(
            (0..=4).map(|_| quaternion(&mut rng)).collect(),
            vec3::zero(&()),
        )
        .expect("a preimage of degree ≤ 30");
        for k in 0..=4 {
            let xi = Q::new(k.into(), 4.into());
            let jet = curve.preimage_jet(&xi, 1);
            let (a, da) = (&jet[0], &jet[1]);
            if a.norm2().is_zero() {
                continue;
            }
            let (frame, omega) = frame_and_omega(a, da);
            let gram_is_identity =
                (0..3).all(|i| (0..3).all(|j| vec3::dot(&frame[i], &frame[j]) == unit[i][j]));
            let m = Matrix::from_fn(3, 3, |r, c| frame[c][r].clone());
            let tangent = frame[0] == vec3::scale(&a.star_square(), &(q(1) / a.norm2()));
            let de: Vec<[Q; 3]> = unit
                .iter()
                .map(|v| frame_vector_derivative(a, da, v))
                .collect();
            let chi = [
                vec3::dot(&de[1], &frame[2]),
                vec3::dot(&de[2], &frame[0]),
                vec3::dot(&de[0], &frame[1]),
            ];
            let eq12a = (0..3).fold(vec3::zero(&()), |acc, i| {
                vec3::add(&acc, &vec3::scale(&frame[i], &chi[i]))
            });
            let darboux = (0..3).all(|i| de[i] == vec3::cross(&omega, &frame[i]));
            if !(gram_is_identity
                && determinant(&m) == Ok(q(1))
                && tangent
                && eq12a == omega
                && darboux)
            {
                failures.push(format!("trial {trial}, ξ = {xi}"));
            }
        }
    }
    Outcome::new(
        format!("10 random rational preimages of degree 4 at ξ = 0, 1/4, …, 1: R orthonormal with det 1 and e₁ = h/σ; ω of Eq. (12) equals 2 vec(A′A*)/|A|² and e_k′ = ω × e_k ({} failures)", failures.len()),
        "rational",
        Verdict::holds(failures.is_empty()),
        format!(
            "Eq. (11) columns A e_k A*/|A|², exact: RᵀR = I, det R = 1, e₁ = A i A*/|A|² = p′/σ. Each e_k′ by the quotient rule from \
             A and A′, χ of Eq. (12b) = (e₂′·e₃, e₃′·e₁, e₁′·e₂) and ω = Σ χ_k e_k (Eq. 12a) compared with the closed form the library \
             uses; the Darboux equations e_k′ = ω × e_k confirm ω is the frame's angular velocity. Failures: {failures:?}"
        ),
    )
}

/// Sec. 5C: "one of the angular parameters, e.g. θ₄, can be set to zero owing to the
/// non-trivial fibers … all PH interpolants can be derived using parameter vectors where
/// θ₄ = 0": (θ₀ + ψ, θ₄ + ψ, θ₈ + ψ, τ) gives the same curve as (θ₀, θ₄, θ₈, τ), and the
/// preimage turns by Q(ψ) on the right.
pub fn theta4_redundant() -> Outcome {
    let mut rng = SplitMix64::new(0x7434);
    let (mut worst_curve, mut worst_preimage) = (0.0f64, 0.0f64);
    for set in 0..10 {
        let data = into::<Ball>(&random_data(&mut rng), &BITS);
        let free: FreeParameters<Ball> = free_into(&random_free(&mut rng), &BITS);
        let psi = Ball::from_ratio(rng.int(-30, 30), 10, &BITS);
        let mut with_theta4 = free.clone();
        with_theta4.theta_start += &psi;
        with_theta4.theta_mid += &psi;
        with_theta4.theta_end += &psi;
        let (base, turned) = match (interpolate(&data, &free), interpolate(&data, &with_theta4)) {
            (Ok(base), Ok(turned)) => (base, turned),
            (Err(e), _) | (_, Err(e)) => {
                return Outcome::failed(
                    format!("ball:{BITS}"),
                    format!("Algorithm 1 on data set {set}: {e}"),
                )
            }
        };
        let one = Ball::from_i64(1, &BITS);
        let scale = base
            .control_points()
            .iter()
            .fold(one, |m, p| m.max_with(&vec3::norm(p)));
        for (p, r) in base.control_points().iter().zip(turned.control_points()) {
            let relative = vec3::norm(&vec3::sub(p, &r)) / &scale;
            worst_curve = worst_curve.max(relative.magnitude_bounds().1);
        }
        let rotation = crate::numeric::quat::q_phi(&psi);
        for (a, b) in base.preimage.iter().zip(&turned.preimage) {
            let diff = b.clone() - &a.mul(&rotation);
            let relative = diff.norm2().sqrt() / &b.norm2().sqrt();
            worst_preimage = worst_preimage.max(relative.magnitude_bounds().1);
        }
    }
    let ok = worst_curve < 1e-60 && worst_preimage < 1e-60;
    Outcome::new(
        format!(
            "adding ψ to θ₀, θ₄, θ₈ leaves the curve unchanged (largest control-point difference ≤ {worst_curve:.1e}, relative) and \
             turns the preimage to A_i Q(ψ) (≤ {worst_preimage:.1e}); proven bounds"
        ),
        format!("ball:{BITS}"),
        Verdict::holds(ok),
        "10 random C⁴ data sets with random φ, ψ ∈ [−3, 3], Algorithm 1 in ball arithmetic at 256 bits (the figures are upper \
         bounds of the enclosures): every A_i ↦ A_i Q(ψ) leaves A i A* unchanged (Q(ψ) commutes with i), so the family has a \
         one-dimensional fibre and each interpolant is reached with θ₄ = 0 (θ₀, θ₈ shifted by −θ₄, the τ unchanged). Criterion \
         1e-60 on the proven bounds",
    )
}

/// Sec. 4A: the product rules of the basis (i² = j² = k² = ijk = −1, ij = −ji = k,
/// jk = −kj = i, ki = −ik = j) and |A| = √(AA*) = √(A*A) = √(a² + a_x² + a_y² + a_z²), with
/// the multiplicativity |AB| = |A||B| the frame of Eq. (11) relies on. Exact: the basis
/// products on `Quat<Q>`, and the squared identities on random rational quaternions (no
/// square root is needed: AA* and A*A are compared with the sum of squares).
pub fn quaternion_rules() -> Outcome {
    let unit = |k: usize| {
        let mut c = [q(0), q(0), q(0), q(0)];
        c[k] = q(1);
        Quat::from_components(c)
    };
    let (one, i, j, k) = (unit(0), unit(1), unit(2), unit(3));
    let minus = |x: &Quat<Q>| x.scale(&q(-1));
    let rules = [
        ("i²", i.mul(&i), minus(&one)),
        ("j²", j.mul(&j), minus(&one)),
        ("k²", k.mul(&k), minus(&one)),
        ("ijk", i.mul(&j).mul(&k), minus(&one)),
        ("ij", i.mul(&j), k.clone()),
        ("ji", j.mul(&i), minus(&k)),
        ("jk", j.mul(&k), i.clone()),
        ("kj", k.mul(&j), minus(&i)),
        ("ki", k.mul(&i), j.clone()),
        ("ik", i.mul(&k), minus(&j)),
    ];
    let failing: Vec<&str> = rules
        .iter()
        .filter(|(_, got, want)| got != want)
        .map(|(name, _, _)| *name)
        .collect();
    let mut rng = SplitMix64::new(0x5e4a);
    let trials = 50;
    let mut identities = 0;
    for _ in 0..trials {
        let (a, b) = (quaternion(&mut rng), quaternion(&mut rng));
        let squares = a.components().iter().fold(q(0), |s, c| s + c.clone() * c);
        let real = |x: Quat<Q>| x.x.is_zero() && x.y.is_zero() && x.z.is_zero() && x.w == squares;
        let product = a.mul(&b).norm2() == a.norm2() * b.norm2();
        identities += usize::from(real(a.mul(&a.conj())) && real(a.conj().mul(&a)) && product);
    }
    Outcome::new(
        format!(
            "all ten basis products as printed ({}); AA* = A*A = a² + a_x² + a_y² + a_z² and |AB|² = |A|²|B|² in {identities} of \
             {trials} random pairs",
            if failing.is_empty() { "none fails".to_string() } else { format!("failing: {}", failing.join(", ")) }
        ),
        "rational",
        Verdict::holds(failing.is_empty() && identities == trials),
        "the basis products computed by the quaternion product the library uses everywhere (numeric::quat), compared with the \
         printed table entry by entry; the absolute value compared squared, exactly, on 50 random rational pairs",
    )
}

/// Eq. (27) as printed: the preimage of degree 8 in Bernstein form, term by term — the
/// coefficient, the powers of (1 − ξ) and ξ, and the control point each multiplies.
const EQ27_PRINTED: [(i64, u32, u32, usize); 9] = [
    (1, 0, 8, 8),
    (8, 1, 7, 7),
    (28, 2, 6, 6),
    (56, 3, 5, 5),
    (70, 4, 4, 4),
    (56, 5, 3, 3),
    (28, 6, 2, 2),
    (8, 7, 1, 1),
    (1, 8, 0, 0),
];

/// Eq. (27): the printed expansion is Σ C(8, i)(1 − ξ)^(8−i) ξ^i A_i, the Bernstein form
/// (10a) with n = 8 that the library evaluates by de Casteljau. Checked term by term against
/// C(8, i) and by value, exactly, at nine rational ξ for random rational control points.
pub fn eq27() -> Outcome {
    let terms_ok = EQ27_PRINTED.iter().all(|&(c, one_minus, power, index)| {
        c == crate::numeric::poly::binom(8, index)
            && power as usize == index
            && one_minus as usize == 8 - index
    });
    let mut rng = SplitMix64::new(0x2727);
    let preimage: Vec<Quat<Q>> = (0..9).map(|_| quaternion(&mut rng)).collect();
    let curve =
        PhCurve::new(preimage.clone(), [q(0), q(0), q(0)]).expect("a preimage of degree ≤ 30");
    let mut agree = 0;
    let points = 9;
    for s in 0..points {
        let xi = Q::new((s as i64 - 1).into(), 6.into());
        let mut printed = Quat::zero(&());
        for &(c, one_minus, power, index) in &EQ27_PRINTED {
            let weight = q(c) * pow(&(q(1) - xi.clone()), one_minus) * pow(&xi, power);
            printed.add_scaled(&weight, &preimage[index]);
        }
        agree += usize::from(curve.preimage_jet(&xi, 0)[0] == printed);
    }
    Outcome::new(
        format!(
            "coefficients 1, 8, 28, 56, 70, 56, 28, 8, 1 are C(8, i) with powers (1 − ξ)^(8−i) ξ^i: {terms_ok}; equal to de \
             Casteljau's value at {agree} of {points} points"
        ),
        "rational",
        Verdict::holds(terms_ok && agree == points),
        "the nine printed terms compared with the Bernstein basis of degree 8, and the printed sum evaluated exactly at \
         ξ = −1/6, 0, 1/6, …, 7/6 (outside [0, 1] too: a polynomial identity) against the library's evaluation of (10a)",
    )
}

fn pow(x: &Q, n: u32) -> Q {
    (0..n).fold(q(1), |p, _| p * x)
}

/// B^n_i(ξ) exactly.
fn bernstein(n: usize, i: usize, xi: &Q) -> Q {
    q(crate::numeric::poly::binom(n, i))
        * pow(&(q(1) - xi.clone()), (n - i) as u32)
        * pow(xi, i as u32)
}

/// Eq. (10c)'s second equality, p(ξ) = p₀ + Σ h_i B_i^{2n}(ξ)/(2n + 1), against the curve of
/// its first (the control points of Eq. 10d): exactly, for random rational preimages of
/// degree n = 8, at ξ = 0, 1/2, 1. The right side is a polynomial of degree 2n, not 2n + 1,
/// and at ξ = 0 it gives p₀ + h₀/(2n + 1) = p₁.
pub fn eq10c_second_equality() -> Outcome {
    let mut rng = SplitMix64::new(0x10c);
    let trials = 10;
    let (mut equal, mut gives_p1) = (0, 0);
    for _ in 0..trials {
        let preimage: Vec<Quat<Q>> = (0..9).map(|_| quaternion(&mut rng)).collect();
        let curve = PhCurve::new(preimage, [q(1), q(2), q(3)]).expect("a preimage of degree ≤ 30");
        let (h, points) = (curve.hodograph(), curve.control_points());
        let degree = h.len() - 1;
        let printed = |xi: &Q| {
            let mut p = points[0].clone();
            for (i, hi) in h.iter().enumerate() {
                vec3::axpy(
                    &mut p,
                    &(bernstein(degree, i, xi) / q(degree as i64 + 1)),
                    hi,
                );
            }
            p
        };
        let samples = [q(0), Q::new(1.into(), 2.into()), q(1)];
        equal += usize::from(samples.iter().all(|xi| printed(xi) == curve.point(xi)));
        gives_p1 += usize::from(printed(&q(0)) == points[1]);
    }
    Outcome::new(
        format!(
            "the printed right side equals p(ξ) at ξ = 0, 1/2, 1 in {equal} of {trials} random curves; at ξ = 0 it gives p₁ in \
             {gives_p1} of {trials}"
        ),
        "rational",
        if equal == trials { Verdict::Reproduced } else { Verdict::Discrepancy },
        "random rational preimages of degree 8 (hodograph of degree 16, curve of degree 17), p₀ = (1, 2, 3); the curve evaluated \
         by de Casteljau on the control points of Eq. (10d) (checked by phodcos.eq10.control_points) against the second equality \
         of Eq. (10c) as printed. Integrating the hodograph gives p₀ + Σ_i h_i Σ_(j>i) B_j^(2n+1)(ξ)/(2n + 1): the printed form \
         drops the integration (a sum of B^(2n), not of B^(2n+1) tails), and with an integral sign restored the factor \
         1/(2n + 1) would be one too many (p₀ + ∫₀^ξ h is the curve): more than one lost symbol (policy clause 3)",
    )
}

/// Sec. 5B: "Given the four-dimensional nature of the preimage A(ξ), a preimage of order 7
/// (4 · 7 = 28 > 27) accounts for sufficient degrees of freedom." A preimage of degree n has
/// n + 1 quaternion coefficients, 4(n + 1) scalar unknowns — the count the paper itself uses
/// for n = 8 ("9 parameter family" = 4 · 9 − 27). Counted on Algorithm 1's output: the
/// preimage of a C⁴ interpolant (its degree and coefficients) and the free parameters that
/// select it (θ₀, θ₄, θ₈, τ₁…τ₃, τ₅…τ₇), against the 27 conditions of footnote 3 and Sec. 5B
/// (2 ends · 3 coordinates · 5 orders, less p₀).
pub fn order7_unknowns() -> Outcome {
    let mut rng = SplitMix64::new(0x5b07);
    let data = into::<Ball>(&random_data(&mut rng), &BITS);
    let free: FreeParameters<Ball> = FreeParameters::zero(4, &BITS);
    let curve = match interpolate(&data, &free) {
        Ok(c) => c,
        Err(e) => return Outcome::failed("rational", format!("Algorithm 1: {e}")),
    };
    let (degree, coefficients) = (curve.preimage_degree(), curve.preimage.len());
    let conditions = 2 * 3 * (data.order() + 1) - 3;
    let parameters = 3 + free.tau_start.len() + free.tau_end.len();
    let counts_hold = coefficients == degree + 1 && 4 * coefficients - conditions == parameters;
    let (printed, counted) = (4 * 7, 4 * (7 + 1));
    Outcome::new(
        format!(
            "Algorithm 1's preimage of degree {degree} has {coefficients} coefficients, {} unknowns, and {} − {conditions} = {parameters} \
             free parameters: 4(n + 1) unknowns. A degree-7 preimage has {counted} unknowns, not {printed}",
            4 * coefficients,
            4 * coefficients
        ),
        "rational",
        if counts_hold && printed != counted {
            Verdict::Discrepancy
        } else {
            Verdict::Failed
        },
        "counts on Algorithm 1's output for C⁴ data (a random data set, φ* = 0): the number of preimage coefficients against its \
         degree, and 4 × coefficients − 27 conditions against the number of free parameters Algorithm 1 takes; both give 4(n + 1) \
         unknowns for a degree-n preimage. The sentence's arithmetic 4 · 7 = 28 is right on a wrong count, so it is not one lost \
         symbol (clause 3); its conclusion (enough unknowns, 32 > 27) still holds",
    )
}

/// Sec. 3: γ "is assumed to be of differentiability class C^m … where m ≥ 2". Algorithm 1
/// interpolates position, velocity, acceleration, jerk and snap at both segment ends (Eq. 16):
/// the number of derivatives its input carries (`HermiteData::order` of the data Table 1's
/// conversion builds) is what the curve must have, as Sec. 2 says ("can be applied to any C⁴
/// curve").
pub fn smoothness_class() -> Outcome {
    let mut rng = SplitMix64::new(0x0003);
    let data = into::<Ball>(&random_data(&mut rng), &BITS);
    let free: FreeParameters<Ball> = FreeParameters::zero(data.order(), &BITS);
    let needed = data.order();
    let runs = interpolate(&data, &free).is_ok();
    // Algorithm 1 with one derivative fewer at each end, as a C³ curve could supply, is not the
    // paper's method: its free-parameter vector and degree change.
    Outcome::new(
        format!(
            "Algorithm 1 takes {needed} derivatives of γ at each segment end (v, a, j, s): γ must be C^{needed}; the stated m ≥ 2 \
             admits C² curves, whose third and fourth derivatives Algorithm 1 cannot be given"
        ),
        "rational",
        if runs && needed > 2 {
            Verdict::Discrepancy
        } else {
            Verdict::Failed
        },
        "the order of the Hermite data Algorithm 1 interpolates (a random C⁴ data set, φ* = 0, the conversion runs), against \
         the m ≥ 2 of Sec. 3 and P3. Sec. 2 states C⁴ and Eq. (16g, h) take s_b, s_e = γ⁗ at the ends; the tutorial's \
         fourth-order spline (Sec. 6A) is C² (order 4) or C³ (degree 4), which meets Sec. 3 but not Algorithm 1. A deliberate \
         wording repeated in P3, not one garbled symbol (clause 3)",
    )
}

/// Sec. 6B, Eq. (24a): "ṗ = v[cos φ cos θ, sin φ, cos φ sin θ]" with "{v, θ, φ} … the velocity
/// magnitude and gimbal angles": the bracket is a unit vector for every θ, φ, so |ṗ| = |v|.
/// Exact, at angles whose sine and cosine are rational (c, s) = ((1 − u²)/(1 + u²), 2u/(1 + u²)),
/// u over a grid of rationals (7 × 7 pairs): cos²φ cos²θ + sin²φ + cos²φ sin²θ = 1.
pub fn unit_direction() -> Outcome {
    let q = |n: i64, d: i64| BigRational::new(n.into(), d.into());
    let one = q(1, 1);
    let angle = |u: &BigRational| {
        let u2 = u.clone() * u;
        let den = one.clone() + &u2;
        ((one.clone() - &u2) / &den, (u.clone() + u) / &den)
    };
    let us: Vec<BigRational> = [(-3, 1), (-1, 2), (-1, 7), (0, 1), (2, 9), (1, 1), (5, 2)]
        .iter()
        .map(|&(n, d)| q(n, d))
        .collect();
    let mut failures = Vec::new();
    for a in &us {
        for b in &us {
            let ((ct, st), (cp, sp)) = (angle(a), angle(b));
            let x = cp.clone() * &ct;
            let z = cp.clone() * &st;
            let norm2 = x.clone() * &x + &(sp.clone() * &sp) + &(z.clone() * &z);
            if norm2 != one {
                failures.push(format!("u_θ = {a}, u_φ = {b}: {norm2}"));
            }
        }
    }
    Outcome::new(
        format!(
            "|[cos φ cos θ, sin φ, cos φ sin θ]|² = 1 at {} of {} angle pairs: |ṗ| = |v|, the speed",
            us.len() * us.len() - failures.len(),
            us.len() * us.len()
        ),
        "rational",
        Verdict::holds(failures.is_empty()),
        format!(
            "exact rationals, angles with rational sine and cosine from u ∈ {{−3, −1/2, −1/7, 0, 2/9, 1, 5/2}} for θ and for φ (all \
             quadrants, not a special point: clause 2); the identity cos²φ(cos²θ + sin²θ) + sin²φ = 1 makes v the velocity \
             magnitude, as the text names it. Failures: {failures:?}"
        ),
    )
}

/// Sec. 5B, footnote 3 and Sec. 5C: "30 scalar constraints per interval" (2 ends · 3
/// coordinates · 5 orders, position to snap), "imposing the starting position p₀ … reduces the
/// amount of free conditions to 27", and the interpolants "relate to a 9 parameter family φ".
/// Counted on Algorithm 1 itself: the scalars of its C⁴ input (`HermiteData`: p_b, p_e and the
/// derivative vectors at both ends), less p₀; the coefficients of its output's preimage; the
/// free parameters it takes.
pub fn constraint_counts() -> Outcome {
    let mut rng = SplitMix64::new(0x5b30);
    let data = into::<Ball>(&random_data(&mut rng), &BITS);
    let free: FreeParameters<Ball> = FreeParameters::zero(data.order(), &BITS);
    let curve = match interpolate(&data, &free) {
        Ok(c) => c,
        Err(e) => return Outcome::failed("rational", format!("Algorithm 1: {e}")),
    };
    let constraints = 3 * (2 + data.start.len() + data.end.len());
    let after_p0 = constraints - 3;
    let parameters = 3 + free.tau_start.len() + free.tau_end.len();
    let family = 4 * curve.preimage.len() - after_p0;
    let holds = (constraints, after_p0, parameters, family) == (30, 27, 9, 9);
    Outcome::new(
        format!(
            "{constraints} scalar conditions per segment ({} derivative orders at each end, with the positions), {after_p0} after \
             p₀; {} preimage unknowns leave a {family}-parameter family, and Algorithm 1 takes {parameters} free parameters",
            data.order(),
            4 * curve.preimage.len()
        ),
        "rational",
        Verdict::holds(holds),
        "counted on Algorithm 1's input and output for a random C⁴ data set (φ* = 0), against the printed 30, 27 and 9: the data's \
         scalars (two points and 2 × 4 derivative vectors in R³), less the three of p₀ that integration fixes; four unknowns per \
         quaternion coefficient of the degree-8 preimage; θ₀, θ₄, θ₈ and the six τ_k",
    )
}

/// A random rational quaternion (entries k/10, |k| ≤ 20).
fn random_quat(rng: &mut SplitMix64) -> Quat<BigRational> {
    let mut c = || BigRational::new(rng.int(-20, 20).into(), 10.into());
    Quat::new(c(), c(), c(), c())
}

/// Sec. 5B: "increasing the order to 8 guarantees the existence of a solution for any
/// interpolation data". The hodograph p′ = A i A* of the degree-8 preimage has Bernstein
/// coefficients h_0 = A_0 ⋆ A_0 and h_1 = A_0 ⋆ A_1 at the start, so v_b is a multiple of h_0
/// and a_b of h_1 − h_0: with |h_0| = |A_0|², v_b = 0 forces A_0 = 0, then h_1 = 0 and a_b = 0. Checked exactly on random quaternions, and the
/// library's Algorithm 1 on data with v_b = 0, a_b ≠ 0.
pub fn existence_any_data() -> Outcome {
    let scalar = "rational";
    let mut rng = SplitMix64::new(0x5b08);
    let zero = Quat::<BigRational>::zero(&());
    let norm2 = |v: &[BigRational; 3]| {
        v.iter()
            .fold(BigRational::default(), |a, x| a + &(x.clone() * x))
    };
    let mut identity_holds = true;
    let mut second_vanishes = true;
    for _ in 0..20 {
        let (a0, a1) = (random_quat(&mut rng), random_quat(&mut rng));
        // |A ⋆ A| = |A|²: the squared norms agree exactly.
        let n = a0.norm2();
        identity_holds &= norm2(&a0.star_square()) == n.clone() * &n;
        // With A_0 = 0: h_0 = 0 ⋆ 0 and h_1 = 0 ⋆ A_1 vanish for every A_1.
        second_vanishes &= norm2(&zero.star_square()) == BigRational::default()
            && norm2(&zero.star(&a1)) == BigRational::default();
    }
    let mut data = random_data(&mut rng);
    data.start[0] = [
        BigRational::default(),
        BigRational::default(),
        BigRational::default(),
    ];
    data.start[1] = [
        BigRational::from_integer(1.into()),
        BigRational::default(),
        BigRational::default(),
    ];
    let refusal = match interpolate(&into::<Ball>(&data, &BITS), &FreeParameters::zero(4, &BITS)) {
        Ok(_) => "returned a curve".to_string(),
        Err(e) => e.to_string(),
    };
    Outcome::new(
        format!(
            "|A ⋆ A| = |A|² on 20 random quaternions: {identity_holds}; with A_0 = 0, h_0 = h_1 = 0 for 20 random A_1: {second_vanishes}; \
             Algorithm 1 on data with v_b = 0, a_b = (1, 0, 0): {refusal}"
        ),
        scalar,
        if identity_holds && second_vanishes { Verdict::Undetermined } else { Verdict::Failed },
        "two readings (clause 5). (1) Regular data, v_b ≠ 0 and v_e ≠ 0 (and v_b + v_e ≠ 0, Definition 3): every step of \
         Algorithm 1 is solvable and the interpolant meets all ten vectors (phodcos.alg1.interpolates, 40 data sets): holds. \
         (2) Literally any C⁴ data: v_b is a multiple of h_0 = A_0 ⋆ A_0, |h_0| = |A_0|², so v_b = 0 forces A_0 = 0; then h_1 = A_0 ⋆ A_1 = 0 and \
         p″(0), a multiple of h_1 − h_0, is 0: data with v_b = 0 and a_b ≠ 0 have no PH interpolant of this form, whatever the \
         order, and the library's Algorithm 1 refuses them. Exact rational arithmetic; fails. One reading holds",
    )
}

/// Sec. 5A, Eq. (14): "C² in all parametric functions is equivalent to C³ in the preimage …
/// {σ, R, ω} ∈ C² ⇒ A ∈ C³ ⇒ p ∈ C⁴". The converse of A ∈ C³ ⇒ {σ, R, ω} ∈ C², on the
/// preimage A(ξ) = f(ξ)A₀ with f = 1 for ξ ≤ ½ and f = 1 + c(ξ − ½)³ after: R and ω are those
/// of the constant A₀ (a scalar factor changes neither), σ = f²|A₀|² is C², and A‴ jumps by
/// 6cA₀. One-sided Taylor coefficients at ½, exactly.
pub fn continuity_chain() -> Outcome {
    let scalar = "rational";
    let q = |n: i64| BigRational::from_integer(n.into());
    let (c, a0) = (q(1), Quat::new(q(1), q(2), q(0), q(1)));
    // Taylor coefficients at x = ξ − ½ up to x⁶: left f = 1, right f = 1 + c x³.
    let left_f = vec![q(1), q(0), q(0), q(0), q(0), q(0), q(0)];
    let mut right_f = left_f.clone();
    right_f[3] = c.clone();
    let square = |f: &[BigRational]| -> Vec<BigRational> {
        (0..f.len())
            .map(|k| (0..=k).fold(q(0), |a, i| a + &(f[i].clone() * &f[k - i])))
            .collect()
    };
    let sigma = |f: &[BigRational]| -> Vec<BigRational> {
        square(f).into_iter().map(|x| x * &a0.norm2()).collect()
    };
    // The k-th derivative is k!·coefficient; a jump of order k is the difference of the two.
    let factorial = |k: usize| (1..=k as i64).fold(q(1), |a, i| a * &q(i));
    let jumps = |l: &[BigRational], r: &[BigRational]| -> Vec<BigRational> {
        (0..4)
            .map(|k| (r[k].clone() - &l[k]) * &factorial(k))
            .collect()
    };
    let sigma_jumps = jumps(&sigma(&left_f), &sigma(&right_f));
    let f_jumps = jumps(&left_f, &right_f);
    let a_jump3: Vec<BigRational> = a0
        .components()
        .iter()
        .map(|x| x.clone() * &f_jumps[3])
        .collect();
    let sigma_c2 = sigma_jumps[..3].iter().all(|x| *x == q(0));
    let a_not_c3 = a_jump3.iter().any(|x| *x != q(0));
    let text = |v: &[BigRational]| {
        v.iter()
            .map(|x| x.to_string())
            .collect::<Vec<_>>()
            .join(", ")
    };
    Outcome::new(
        format!(
            "A = f·A₀, A₀ = (1, 2, 0, 1), f = 1 + (ξ − ½)₊³: jumps of σ, σ′, σ″, σ‴ at ½: {}; R and ω those of the constant A₀ \
             (no jump); A‴ jumps by ({}): {{σ, R, ω}} ∈ C² but A ∉ C³",
            text(&sigma_jumps),
            text(&a_jump3)
        ),
        scalar,
        if sigma_c2 && a_not_c3 { Verdict::Undetermined } else { Verdict::Failed },
        "two readings (clause 5). (1) The sufficient direction the method uses, A ∈ C³ ⇒ {σ, R, ω} ∈ C² and p ∈ C⁴: holds \
         (phodcos.sec5e.continuity, proven on the conversion with the roll correction). (2) As printed, an equivalence and a \
         chain of implications from {σ, R, ω}: fails twice — the preimage here (exact one-sided Taylor coefficients at ½; a \
         scalar factor leaves the unit quaternion A/|A|, hence R and ω, unchanged) has σ, R, ω ∈ C² and A‴ jumping; and p ∈ C⁴ \
         does not give A ∈ C³: without the roll correction the conversion's p is unchanged while A jumps at the joints \
         (phodcos.sec5e.continuity). One reading holds",
    )
}
