//! `run marin-1d`, `run natural-spline` and `run marin`: the JSON shapes that `docs/commands.md` documents.

use super::budget::{self, check_output, Rates};
use super::dispatch::{run_field, run_real, run_real_or_exact, FieldJob, RealJob};
use super::input::{self, fail, InputError, RunError, ValuePath};
use super::json::{Map, Value};
use super::output::Out;
use super::Rendered;
use crate::algo::param::descent::{descend, refine, Descent};
use crate::algo::param::natural::NaturalCubicSpline;
use crate::algo::param::natural_exact::ExactNaturalSpline;
use crate::algo::param::objective::{chord_length_spacing, objective, Objective};
use crate::algo::param::one_d::{
    chord_length_1d, classify, parametrization_exact, Case, ParamError, Shape,
};
use crate::algo::param::proven::prove_minimum;
use crate::scalar::ball::{carried, Ball};
use crate::scalar::{Exact, Field, Float, Real, ScalarKind};
use rayon::prelude::*;

/// The most points accepted by `marin` (a dense Newton step on N unknowns).
pub const MAX_POINTS: usize = 500;

fn numbers(v: &Value, path: &str) -> Result<Vec<Exact>, InputError> {
    input::array(v, path)?
        .iter()
        .enumerate()
        .map(|(i, x)| input::number(x, format_args!("{path}[{i}]")))
        .collect()
}

fn param_error(e: ParamError, field: &str) -> InputError {
    InputError(format!("field \"{field}\": {e}"))
}

/// `run marin-1d`: the exact minimizing parametrization of scalar ordinates.
pub fn run_marin_1d(doc: &Map, scalar: ScalarKind) -> Result<Rendered, RunError> {
    input::only_fields(doc, &["z"])?;
    let z = numbers(input::field(doc, "z")?, "z")?;
    let case = classify(&z).map_err(|e| param_error(e, "z"))?;
    // The non-extreme points are placed by bisection on ψ (about 4p halvings at p bits), so
    // the cost grows with the precision beyond mpfr_factor. Measured at mpfr:256 (case III,
    // the dearest): N = 400 in 0.15 s and 1600 in 0.61 s on a parabola's ordinates, 1600
    // random ordinates in 0.22 s; f64 N = 16000 in 0.77 s.
    let n = z.len() as f64;
    let extra_bits = match scalar {
        ScalarKind::Mpfr(bits) => (bits as f64 / 256.0).max(1.0).powf(0.7),
        _ => 1.0,
    };
    let rates = Rates {
        f64: 2e-5,
        mpfr256: 1.2e-4 * extra_bits,
        rational: 1e-6,
    };
    rates.check(
        n.powf(1.2),
        scalar,
        "z",
        &format!("{} ordinates at {scalar}", z.len()),
    )?;
    let exact = || -> Result<Out<Exact>, RunError> {
        if case != Case::I {
            return fail(format!("option --scalar: rational covers only case I; these data are case {} and need square roots (use f64 or mpfr:<bits>)", case.name()));
        }
        let t = chord_length_1d(&z).map_err(|e| param_error(e, "z"))?;
        Ok(Out::object(vec![
            ("t", Out::nums(t)),
            ("case", Out::Text("I".into())),
        ]))
    };
    let shape = Shape::of_exact(&z).map_err(|e| param_error(e, "z"))?;
    run_real_or_exact(
        &MarinOneDJob {
            z: z.clone(),
            shape,
        },
        scalar,
        exact,
    )
}

/// The exact minimizing parametrization of scalar ordinates (Sec. 2) in one number type.
struct MarinOneDJob {
    z: Vec<Exact>,
    /// The signs of the differences, decided on the exact ordinates (the case and the
    /// extremes follow from them, never from the rounded values).
    shape: Shape,
}

impl RealJob for MarinOneDJob {
    fn run<T: Real>(&self, ctx: &T::Ctx) -> Result<Out<T>, RunError> {
        let zt: Vec<T> = self.z.iter().map(|q| T::from_exact(q, ctx)).collect();
        // |Δᵢ| exact, rounded once (a step of 1e-40 between values near 1 survives).
        let magnitudes: Vec<T> = self
            .z
            .windows(2)
            .map(|w| T::from_exact(&(w[1].clone() - &w[0]).abs(), ctx))
            .collect();
        let (t, case) = parametrization_exact(&zt, &magnitudes, &self.shape)
            .map_err(|e| param_error(e, "z"))?;
        Ok(Out::object(vec![
            ("t", Out::nums(t)),
            ("case", Out::Text(case.name().into())),
        ]))
    }

    /// Case III's root of ψ and the square roots of case II can lose every digit in f64 on
    /// nearly equal data.
    fn checks_f64(&self) -> bool {
        true
    }
}

/// `run natural-spline`: values and first and second derivatives at requested parameters.
pub fn run_natural_spline(doc: &Map, scalar: ScalarKind) -> Result<Rendered, RunError> {
    input::only_fields(doc, &["t", "z", "at"])?;
    let t = numbers(input::field(doc, "t")?, "t")?;
    let (z, is_point) = input::uniform_values_with(input::field(doc, "z")?, "z", |x, p| {
        input::number_value(x, p)
    })?;
    let at = numbers(input::field(doc, "at")?, "at")?;
    if t.len() < 2 {
        return fail("field \"t\": a spline needs at least two knots");
    }
    if z.len() != t.len() {
        return fail(format!(
            "field \"z\": {} values for {} knots",
            z.len(),
            t.len()
        ));
    }
    if let Some(i) = (1..t.len()).find(|&i| t[i] <= t[i - 1]) {
        return fail(format!(
            "field \"t[{i}]\": knots must increase ({} after {})",
            t[i],
            t[i - 1]
        ));
    }
    // A natural spline is defined on [t0, tN]; outside it the end pieces would be
    // extrapolated, which the user did not ask for.
    let (first, last) = (&t[0], &t[t.len() - 1]);
    if let Some(k) = at.iter().position(|x| x < first || x > last) {
        return fail(format!(
            "field \"at[{k}]\": {} lies outside the knots [{first}, {last}], where the spline is not defined",
            at[k]
        ));
    }
    let job = NaturalSplineJob {
        t,
        z,
        at,
        is_point,
        exact: scalar == ScalarKind::Rational,
    };
    job.check_budget(scalar)?;
    run_field(&job, scalar)
}

/// The knots, values (one list per point) and evaluation points of `natural-spline`. The
/// knots and points are exact (pieces are located and spacings formed on them); the values
/// stay JSON values until the run's number type reads them ([`input::number_in`]).
struct NaturalSplineJob<'a> {
    t: Vec<Exact>,
    z: Vec<Vec<&'a Value<'a>>>,
    at: Vec<Exact>,
    is_point: bool,
    /// Rational output: computed by fraction-free elimination
    /// ([`ExactNaturalSpline`], the same numbers as the generic spline in rationals).
    exact: bool,
}

impl FieldJob for NaturalSplineJob<'_> {
    fn run<T: Field>(&self, ctx: &T::Ctx) -> Result<Out<T>, RunError> {
        let rows = if self.exact {
            self.exact_rows(|q| T::from_exact(q, ctx))?
        } else {
            self.rows(ctx)?
        };
        Ok(columns(rows, self.is_point, ctx))
    }
}

/// Below this many spline evaluations a run does not start rayon's threads (their start
/// costs about as much as 64 rational evaluations, or thousands in f64).
const PARALLEL_EVALUATIONS: usize = 64;

/// Value, slope and curvature of every coordinate at each point.
type Rows<T> = Vec<Vec<[T; 3]>>;

impl NaturalSplineJob<'_> {
    /// Refuses a run whose estimated time or output exceeds the budget.
    fn check_budget(&self, scalar: ScalarKind) -> Result<(), RunError> {
        // A tridiagonal solve per coordinate and one bisection per point: about N + P operations
        // (measured: N = P = 160000 in 0.25 s in f64 since the points are evaluated on two
        // threads, 16000 in 0.56 s at mpfr:256). In rationals the second derivatives' numbers
        // grow to about N times the input's bits, and every operation on them costs about N^1.4
        // times the input's size factor (budget::exact_size_factor; measured with the
        // fraction-free solve, N = P, points on two threads: 800 knots of 6 digits in 0.93 s,
        // `cargo bench --bench cost_models -- natural-spline`).
        let (knots_n, dims) = (self.t.len() as f64, self.z[0].len() as f64);
        let units = dims * (knots_n + self.at.len() as f64);
        let exact_size = if scalar == ScalarKind::Rational {
            let mut values = Vec::new();
            for (index, point) in self.z.iter().enumerate() {
                for (coordinate, v) in point.iter().enumerate() {
                    let path = ValuePath {
                        name: "z",
                        index,
                        coordinate,
                        is_point: self.is_point,
                    };
                    values.push(input::number(v, path)?);
                }
            }
            budget::exact_size_factor(self.t.iter().chain(&values), 2.4)
        } else {
            1.0
        };
        let rates = Rates {
            f64: 1.2e-6,
            mpfr256: 4e-5,
            rational: 4.5e-10 * knots_n.powf(1.4) * exact_size,
        };
        rates.check(
            units,
            scalar,
            "t",
            &format!(
                "a spline on {} knots evaluated at {} points at {scalar}",
                self.t.len(),
                self.at.len()
            ),
        )?;
        check_output(3.0 * dims * self.at.len() as f64, "at", "this run")?;
        Ok(())
    }

    /// The values of coordinate `c` read by `read`.
    fn coordinate<T>(
        &self,
        c: usize,
        read: impl Fn(&Value, ValuePath) -> Result<T, InputError>,
    ) -> Result<Vec<T>, InputError> {
        self.z
            .iter()
            .enumerate()
            .map(|(index, v)| {
                let path = ValuePath {
                    name: "z",
                    index,
                    coordinate: c,
                    is_point: self.is_point,
                };
                read(v[c], path)
            })
            .collect()
    }

    /// [`Rows`] from `row`, called with the exact distances u = tᵢ − q and v = q − tᵢ₋₁ of
    /// each point q to the ends of its piece i, located on the exact point (the first i ≥ 1
    /// with q ≤ tᵢ). Each point is evaluated once and on its own (on two threads from
    /// [`PARALLEL_EVALUATIONS`]: in rationals each output costs a gcd of numbers of
    /// thousands of bits).
    fn rows_at<T: Send>(
        &self,
        row: impl Fn(&Exact, &Exact, usize) -> Vec<[T; 3]> + Sync,
    ) -> Rows<T> {
        let t = &self.t;
        let at_point = |q: &Exact| {
            let piece = crate::algo::param::natural::piece_index(t, q);
            row(&(t[piece].clone() - q), &(q.clone() - &t[piece - 1]), piece)
        };
        if self.at.len() * self.z[0].len() >= PARALLEL_EVALUATIONS {
            self.at.par_iter().map(carried(at_point)).collect()
        } else {
            self.at.iter().map(at_point).collect()
        }
    }

    /// The generic spline of each coordinate in `T`, evaluated at every point.
    fn rows<T: Field>(&self, ctx: &T::Ctx) -> Result<Rows<T>, InputError> {
        let conv = |q: &Exact| T::from_exact(q, ctx);
        let knots: Vec<T> = self.t.iter().map(conv).collect();
        // The knots increase exactly (checked on the input); each spacing is formed exactly
        // and rounded once, so knots closer than the precision keep their true spacing.
        let spacings: Vec<T> = self
            .t
            .windows(2)
            .map(|w| conv(&(w[1].clone() - &w[0])))
            .collect();
        let splines = (0..self.z[0].len())
            .map(|c| {
                let values = self.coordinate(c, |v, path| input::number_in(v, path, ctx))?;
                NaturalCubicSpline::with_spacings(knots.clone(), spacings.clone(), values)
                    .map_err(|e| InputError(format!("field \"t\": {e}")))
            })
            .collect::<Result<Vec<_>, _>>()?;
        Ok(self.rows_at(|u, v, piece| {
            // The exact distances rounded once.
            let (u, v) = (conv(u), conv(v));
            splines
                .iter()
                .map(|s| s.eval_offsets(&u, &v, piece))
                .collect()
        }))
    }

    /// The exact spline of each coordinate, evaluated at every point, each number given to
    /// `into` (the identity for rationals).
    fn exact_rows<T: Send>(
        &self,
        into: impl Fn(&Exact) -> T + Sync,
    ) -> Result<Rows<T>, InputError> {
        let splines = (0..self.z[0].len())
            .map(|c| {
                let values = self.coordinate(c, |v, path| input::number(v, path))?;
                ExactNaturalSpline::new(&self.t, values)
                    .map_err(|e| InputError(format!("field \"t\": {e}")))
            })
            .collect::<Result<Vec<_>, _>>()?;
        Ok(self.rows_at(|u, v, piece| {
            splines
                .iter()
                .map(|s| s.eval_offsets(u, v, piece).map(|x| into(&x)))
                .collect()
        }))
    }
}

/// The output: values, first and second derivatives, each a list over the points (of
/// lists over the coordinates for points).
fn columns<T: Field>(rows: Rows<T>, is_point: bool, ctx: &T::Ctx) -> Out<T> {
    let column = |j: usize| -> Out<T> {
        Out::List(
            rows.iter()
                .map(|row| {
                    let vals: Vec<T> = row.iter().map(|jet| jet[j].clone()).collect();
                    if is_point {
                        Out::nums(vals)
                    } else {
                        Out::Num(vals.into_iter().next().unwrap_or_else(|| T::zero_in(ctx)))
                    }
                })
                .collect(),
        )
    };
    Out::object(vec![
        ("values", column(0)),
        ("first", column(1)),
        ("second", column(2)),
    ])
}

struct MarinInput {
    /// Components: z[l][i].
    z: Vec<Vec<Exact>>,
    alpha: Vec<Exact>,
    form: Objective,
}

impl MarinInput {
    /// The components and weights rounded once into `T`.
    fn rounded<T: Field>(&self, ctx: &T::Ctx) -> (Vec<Vec<T>>, Vec<T>) {
        let to_t = |q: &Exact| T::from_exact(q, ctx);
        let z = self
            .z
            .iter()
            .map(|c| c.iter().map(to_t).collect())
            .collect();
        (z, self.alpha.iter().map(to_t).collect())
    }
}

fn read_marin(doc: &Map) -> Result<MarinInput, InputError> {
    input::only_fields(doc, &["points", "weights", "objective"])?;
    let (points, _) = input::uniform_values(input::field(doc, "points")?, "points")?;
    if points.len() < 2 {
        return fail("field \"points\": needs at least two points");
    }
    if points.len() > MAX_POINTS {
        return fail(format!(
            "field \"points\": {} points is more than the supported {MAX_POINTS}",
            points.len()
        ));
    }
    if let Some(i) = (1..points.len()).find(|&i| points[i] == points[i - 1]) {
        return fail(format!("field \"points[{i}]\": equal to the point before it (the paper's existence assumption needs z_i ≠ z_(i+1))"));
    }
    let k = points[0].len();
    let alpha = match doc.get("weights") {
        None | Some(Value::Null) => vec![Exact::from(1); k],
        Some(w) => numbers(w, "weights")?,
    };
    if alpha.len() != k {
        return fail(format!(
            "field \"weights\": {} weights for points of dimension {k}",
            alpha.len()
        ));
    }
    if let Some(i) = alpha.iter().position(|a| *a <= 0) {
        return fail(format!("field \"weights[{i}]\": weights must be positive"));
    }
    let form = input::choice(
        doc,
        "objective",
        &[
            ("exact", Objective::Exact),
            ("approx", Objective::Approximate),
        ],
        Some(Objective::Exact),
    )?;
    let z = (0..k)
        .map(|c| points.iter().map(|p| p[c].clone()).collect())
        .collect();
    Ok(MarinInput { z, alpha, form })
}

/// `run marin`: the minimizing parametrization of K-dimensional points (gradient projection
/// from chord length, then Newton's method in the chosen number type).
pub fn run_marin(doc: &Map, scalar: ScalarKind) -> Result<Rendered, RunError> {
    let data = read_marin(doc)?;
    // Gradient projection in f64 then Newton on N unknowns: about N^2.3 operations, in
    // proportion to the number of components. Measured with three components, N = 300:
    // exact objective 5 s in f64 and 34 s at mpfr:256, approximate 1.8 s and 9.8 s.
    let n = data.z[0].len() as f64;
    let units = n.powf(2.3) * (1.0 + data.z.len() as f64) / 4.0;
    let rates = match data.form {
        Objective::Exact => Rates {
            f64: 1.2e-5,
            mpfr256: 7.5e-5,
            rational: 0.0,
        },
        Objective::Approximate => Rates {
            f64: 4.5e-6,
            mpfr256: 2.4e-5,
            rational: 0.0,
        },
    };
    rates.check(
        units,
        scalar,
        "points",
        &format!(
            "{} points in {} components at {scalar}",
            data.z[0].len(),
            data.z.len()
        ),
    )?;
    let spline_error =
        |e: crate::algo::param::natural::SplineError| InputError(format!("field \"points\": {e}"));
    // The descent runs once, in f64: it only has to land in Newton's basin.
    let z64: Vec<Vec<f64>> = data
        .z
        .iter()
        .map(|c| c.iter().map(Field::to_f64).collect())
        .collect();
    let a64: Vec<f64> = data.alpha.iter().map(Field::to_f64).collect();
    let rough = descend(
        chord_length_spacing(&z64),
        &z64,
        &a64,
        data.form,
        &mut |_, _| {},
    )
    .map_err(spline_error)?;
    run_real(
        &MarinJob { data, rough },
        scalar,
        "option --scalar: the minimizer is irrational in general; use f64 or mpfr:<bits>",
    )
}

/// Newton's refinement of the f64 descent's end point in the chosen number type.
struct MarinJob {
    data: MarinInput,
    rough: Descent<f64>,
}

impl MarinJob {
    /// The output for these knots, G there and at chord length, and ‖π_B(∇G)‖ after Newton.
    fn output<T: Field>(&self, knots: Vec<T>, g: T, chord: T, gradient_norm: f64) -> Out<T> {
        let objective = if self.data.form == Objective::Exact {
            "exact (Eq. 31)"
        } else {
            "approx (Eq. 34)"
        };
        // t_0 = 0 and t_n = 1 are fixed by the constraints, exactly: printed as such, not as
        // 77 digits of "1.000…" at the working precision.
        let last = knots.len().saturating_sub(1);
        let knots = knots
            .into_iter()
            .enumerate()
            .map(|(i, t)| match i {
                0 => Out::Text("0".into()),
                i if i == last => Out::Text("1".into()),
                _ => Out::Num(t),
            })
            .collect();
        Out::object(vec![
            ("t", Out::List(knots)),
            ("G", Out::Num(g)),
            ("G_chord", Out::Num(chord)),
            // ‖π_B(∇G)‖ at the result: the stopping rule's quantity, at the working precision
            // after Newton.
            ("projected_gradient_norm", Out::F64(gradient_norm)),
            ("iterations", Out::Int(self.rough.iterations as i64)),
            ("descent_converged", Out::Bool(self.rough.converged)),
            ("objective", Out::Text(objective.into())),
        ])
    }
}

impl RealJob for MarinJob {
    fn run<T: Real>(&self, ctx: &T::Ctx) -> Result<Out<T>, RunError> {
        let (z, a) = self.data.rounded::<T>(ctx);
        let m = refine(&self.rough, &z, &a, self.data.form)
            .map_err(|e| InputError(format!("field \"points\": {e}")))?;
        let norm = m.projected_gradient_norm.to_f64();
        Ok(self.output(m.knots, m.objective, m.chord_objective, norm))
    }

    /// Newton's result at `bits` proven by Krawczyk's test and a positive definite reduced
    /// Hessian in balls (`algo::param::proven`): the knots and G are enclosures of a strict
    /// local minimum's.
    fn run_ball(&self, bits: u32) -> Result<Out<Ball>, RunError> {
        let (z, a) = self.data.rounded::<Float>(&bits);
        let m = refine(&self.rough, &z, &a, self.data.form)
            .map_err(|e| InputError(format!("field \"points\": {e}")))?;
        let h: Vec<Float> = m
            .knots
            .windows(2)
            .map(|w| Float::with_val(bits, &w[1] - &w[0]))
            .collect();
        let (zb, ab) = self.data.rounded::<Ball>(&bits);
        let proven = prove_minimum(&h, &zb, &ab, self.data.form).map_err(|e| {
            InputError(format!(
                "field \"points\": the minimizer is not proven at {bits} bits ({e}); raise the precision"
            ))
        })?;
        let chord = objective(&chord_length_spacing(&zb), &zb, &ab, self.data.form)
            .map_err(|e| InputError(format!("field \"points\": {e}")))?;
        Ok(self.output(
            proven.knots,
            proven.objective,
            chord,
            m.projected_gradient_norm.to_f64(),
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The rational run's fraction-free route against the generic spline in rationals: the
    /// same output, number for number, for points of two coordinates evaluated at knots
    /// (both ends included) and inside pieces.
    #[test]
    fn the_exact_route_gives_the_generic_splines_numbers() {
        let text = r#"{"t": [0, 0.3, 0.45, 1.2, 2, 2.05, 7], "z": [[0, 1], [0.25, -2], [1, 3.5], [-0.75, 0], [2, 2], [1, 1], [1e3, -1e-3]], "at": [0, 0.3, 0.31, 1, 2.05, 1.7, 6.999, 7]}"#;
        let doc = input::parse_document(text).unwrap();
        let t = numbers(input::field(&doc, "t").unwrap(), "t").unwrap();
        let (z, is_point) =
            input::uniform_values_with(input::field(&doc, "z").unwrap(), "z", |x, p| {
                input::number_value(x, p)
            })
            .unwrap();
        let at = numbers(input::field(&doc, "at").unwrap(), "at").unwrap();
        let job = |exact| NaturalSplineJob {
            t: t.clone(),
            z: z.clone(),
            at: at.clone(),
            is_point,
            exact,
        };
        let text_of = |exact| {
            let out: Out<Exact> = job(exact).run(&()).unwrap();
            super::super::output::render_plain(&out).to_string()
        };
        assert!(is_point);
        assert_eq!(text_of(true), text_of(false));
    }
}
