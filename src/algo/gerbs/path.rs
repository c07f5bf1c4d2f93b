//! Local curves, Algorithms 1 and 2: the GERBS path through waypoints (Sec. III).
//!
//! Algorithm 1 gives each waypoint W_i a unit tangent m_i (the bisector of the incoming and
//! outgoing directions; the segment direction at the ends) and a turn sign
//! s_i = sign(m₁ ∧ m₂) (+1 left, −1 right; s_1 = −s_2, s_n = −s_{n−1}). Interior waypoints get
//! a circular arc (Eqs. 19–22) of radius R through W_i: centre p_c = W_i + R s_i (−m_y, m_x)
//! (Eq. 20, with cos(φ + sπ/2) = −s sin φ), angles from θ₁ to θ₂ over the local parameter
//! u ∈ [0, 1], W_i at u = 1/2. The ends get lines (Eqs. 23–24) of length l. Algorithm 2
//! blends c_{k−1} with B_k on the knots of Fig. 1, the local parameter of c_{k−1} being
//! u = (t − t_{k−1})/(t_{k+1} − t_{k−1}), so c_{k−1}(1/2) = W_{k−1} sits at t_k.
//!
//! Eqs. (21)–(22) as printed, θ₁ = φ − sπ/2 + θ_o and θ₂ = φ − sπ/2 − θ_o, always sweep the
//! arc clockwise: that is the travel direction for a right turn (s = −1) but runs a left
//! turn backwards, so the path's tangent at a left-turn waypoint is −m_i.
//! [`ArcConvention::TurnDirection`] sweeps by s: θ₁ = φ − sπ/2 − sθ_o, θ₂ = φ − sπ/2 + sθ_o.

// `!(x > 0)` is meant: a NaN parameter must fail the range checks too.
#![allow(clippy::neg_cmp_op_on_partial_ord)]
use super::quadrature::TanhSinh;
use super::{basis_series_located, Blend, GerbsError, Knots, Located, Side};
use crate::curve::integral::{integrate, integrate_with, IntegralOptions};
use crate::curve::parametric::{check_domain, CurveError, ParamCurve, ParamCurveArclen};
use crate::curve::taylor::Taylor;
use crate::numeric::quadrature::default_tolerance;
use crate::scalar::ball::{carried, Ball};
use crate::scalar::{Field, Float, Real};
use rayon::prelude::*;
use rug::float::Round;
use std::cell::RefCell;

/// Unit tangents m_i and turn signs s_i of Algorithm 1.
#[derive(Clone, Debug, PartialEq)]
pub struct Tangents<T> {
    /// Unit tangent m_i at each waypoint.
    pub m: Vec<[T; 2]>,
    /// Turn sign s_i at each interior waypoint: +1 left, −1 right, 0 straight.
    pub s: Vec<i32>,
}

fn unit<T: Real>(v: [T; 2]) -> [T; 2] {
    let len = (v[0].clone() * &v[0] + &(v[1].clone() * &v[1])).sqrt();
    [v[0].clone() / &len, v[1].clone() / &len]
}

fn direction<T: Real>(from: &[T; 2], to: &[T; 2]) -> [T; 2] {
    unit([to[0].clone() - &from[0], to[1].clone() - &from[1]])
}

/// (W_i − W_{i−1}) ∧ (W_{i+1} − W_i): positive for a left turn at W_i, negative for a right
/// one, zero when the three points are collinear. No root is taken, so with rational
/// waypoints the sign is exact.
pub fn turn_wedge<T: Field>(w: &[[T; 2]], i: usize) -> T {
    let a = [
        w[i][0].clone() - &w[i - 1][0],
        w[i][1].clone() - &w[i - 1][1],
    ];
    let b = [
        w[i + 1][0].clone() - &w[i][0],
        w[i + 1][1].clone() - &w[i][1],
    ];
    a[0].clone() * &b[1] - &(a[1].clone() * &b[0])
}

/// Check waypoints for Algorithm 1: at least 3, finite, no repeats of consecutive points,
/// no interior triple whose turn sign is undefined (collinear, straight or reversing).
///
/// # Errors
/// [`GerbsError::Waypoints`] for fewer than 3 waypoints, a non-finite coordinate, a waypoint
/// equal to the one before, or an interior triple whose [`turn_wedge`] (computed in `T`) is
/// zero.
pub fn check_waypoints<T: Field>(w: &[[T; 2]]) -> Result<(), GerbsError> {
    if w.len() < 3 {
        return Err(GerbsError::Waypoints(format!(
            "need at least 3 waypoints, got {}",
            w.len()
        )));
    }
    if let Some(i) = w
        .iter()
        .position(|p| !p[0].is_finite() || !p[1].is_finite())
    {
        return Err(GerbsError::Waypoints(format!(
            "waypoint {} is not finite",
            i + 1
        )));
    }
    for i in 1..w.len() {
        if w[i] == w[i - 1] {
            return Err(GerbsError::Waypoints(format!(
                "waypoint {} repeats waypoint {}",
                i + 1,
                i
            )));
        }
    }
    for i in 1..w.len() - 1 {
        if turn_wedge(w, i).is_zero() {
            return Err(GerbsError::Waypoints(format!(
                "waypoints {}, {}, {} are collinear: the turn direction at {} is undefined",
                i,
                i + 1,
                i + 2,
                i + 1
            )));
        }
    }
    Ok(())
}

/// The turn signs s_i of Algorithm 1 (+1 left, −1 right; s_1 = −s_2, s_n = −s_{n−1}),
/// decided exactly: the wedge of each interior triple is formed in rationals from the
/// values as given (every f64 and MPFR number is a rational), so no rounding of the wedge
/// can flip a sign. For waypoints that were themselves rounded from exact input, decide on
/// the exact input and pass the signs in [`PathSpec::turns`].
///
/// # Errors
/// [`GerbsError::Waypoints`] as [`check_waypoints`], on the values in `T` and again exactly.
pub fn turn_signs<T: Field>(w: &[[T; 2]]) -> Result<Vec<i32>, GerbsError> {
    check_waypoints(w)?;
    // GMP rationals: the wedges' products and sums normalise by gcds, which GMP does far
    // faster than num-rational (the sign is the same exact sign in either).
    let exact: Vec<[rug::Rational; 2]> = w
        .iter()
        .map(|p| {
            let q = |x: &T| {
                x.to_exact()
                    .ok_or_else(|| GerbsError::Waypoints("every waypoint must be finite".into()))
            };
            Ok([q(&p[0])?, q(&p[1])?])
        })
        .collect::<Result<_, GerbsError>>()?;
    exact_turn_signs(&exact)
}

/// [`turn_signs`] on rational waypoints.
///
/// # Errors
/// [`GerbsError::Waypoints`] as [`check_waypoints`].
pub fn exact_turn_signs<E: Field<Ctx = ()>>(w: &[[E; 2]]) -> Result<Vec<i32>, GerbsError> {
    check_waypoints(w)?;
    let n = w.len();
    let mut s = vec![0];
    for i in 1..n - 1 {
        let wedge = turn_wedge(w, i);
        s.push(if wedge > E::zero_in(&()) { 1 } else { -1 });
    }
    s.push(-s[n - 2]);
    s[0] = -s[1];
    Ok(s)
}

/// Algorithm 1, with the turn signs decided exactly on the waypoints as given
/// ([`turn_signs`]).
///
/// # Errors
/// As [`turn_signs`].
pub fn tangents<T: Real>(w: &[[T; 2]]) -> Result<Tangents<T>, GerbsError> {
    let s = turn_signs(w)?;
    tangents_with_turns(w, s)
}

/// Algorithm 1 with turn signs `s` decided by the caller (one per waypoint, as
/// [`exact_turn_signs`] returns them).
///
/// # Errors
/// [`GerbsError::Waypoints`] as [`check_waypoints`]; [`GerbsError::Parameter`] (`turns`)
/// unless `s` has one entry per waypoint, each +1 or −1; [`GerbsError::Waypoints`] when the
/// directions between waypoints overflow.
pub fn tangents_with_turns<T: Real>(w: &[[T; 2]], s: Vec<i32>) -> Result<Tangents<T>, GerbsError> {
    check_waypoints(w)?;
    let n = w.len();
    if s.len() != n {
        return Err(GerbsError::Parameter {
            field: "turns",
            message: format!(
                "expected one turn sign per waypoint ({n}), found {}",
                s.len()
            ),
        });
    }
    if let Some(i) = s.iter().position(|&x| x != 1 && x != -1) {
        return Err(GerbsError::Parameter {
            field: "turns",
            message: format!(
                "turn sign {} of waypoint {} is not +1 (left) or -1 (right)",
                s[i],
                i + 1
            ),
        });
    }
    let m = bisector_tangents(w)?;
    Ok(Tangents { m, s })
}

/// The unit tangents m_i of Algorithm 1 alone (no turn signs): the chord's direction at the
/// ends, the bisector of the two chords' directions in between.
///
/// # Errors
/// [`GerbsError::Waypoints`] as [`check_waypoints`], or when the directions between
/// waypoints overflow.
pub fn unit_tangents<T: Real>(w: &[[T; 2]]) -> Result<Vec<[T; 2]>, GerbsError> {
    check_waypoints(w)?;
    bisector_tangents(w)
}

/// [`unit_tangents`] on waypoints already checked.
fn bisector_tangents<T: Real>(w: &[[T; 2]]) -> Result<Vec<[T; 2]>, GerbsError> {
    let n = w.len();
    let mut m = vec![direction(&w[0], &w[1])];
    for i in 1..n - 1 {
        let (a, b) = (direction(&w[i - 1], &w[i]), direction(&w[i], &w[i + 1]));
        m.push(unit([a[0].clone() + &b[0], a[1].clone() + &b[1]]));
    }
    m.push(direction(&w[n - 2], &w[n - 1]));
    if m.iter().flatten().any(|x| !x.is_finite()) {
        return Err(GerbsError::Waypoints(
            "the directions between waypoints are not finite (coordinates too large or too close to represent their differences)".into(),
        ));
    }
    Ok(m)
}

/// How θ₁ and θ₂ of an arc are chosen.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ArcConvention {
    /// Eqs. (21)–(22) as printed: θ₁,₂ = φ − sπ/2 ± θ_o (always clockwise).
    AsPrinted,
    /// Sweep in the turn direction: θ₁,₂ = φ − sπ/2 ∓ sθ_o.
    TurnDirection,
}

/// The local curves at the first and last waypoints. Sec. III, Eqs. (23)–(24), Fig. 4 and
/// Sec. IV put straight lines there; Algorithm 2 as printed (steps 4–5) builds an arc at every
/// waypoint, with Algorithm 1's end signs s_1 = −s_2 and s_n = −s_{n−1}.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum EndCurves {
    /// Straight lines of length l (the text and the figures; the default).
    #[default]
    Lines,
    /// Arcs like the interior ones (Algorithm 2 as printed).
    Arcs,
}

/// One local curve, parametrized by u ∈ [0, 1].
#[derive(Clone, Debug, PartialEq)]
pub enum LocalCurve<T> {
    /// origin + u·(l m): the start line of Eq. (23); for the end line of Eq. (24) the
    /// origin is W_n − l m.
    Line {
        /// The point at u = 0.
        origin: [T; 2],
        /// The displacement from u = 0 to u = 1, l·m.
        step: [T; 2],
    },
    /// centre + R (cos θ, sin θ), θ = (1 − u)θ₁ + uθ₂ (Eq. 19).
    Arc {
        /// The centre of the circle.
        centre: [T; 2],
        /// The radius R.
        radius: T,
        /// The angle θ₁ at u = 0.
        theta1: T,
        /// The angle θ₂ at u = 1.
        theta2: T,
    },
}

impl<T: Real> LocalCurve<T> {
    /// The curve as series in t, given the local parameter u as a series.
    pub fn series(&self, u: &Taylor<T>) -> [Taylor<T>; 2] {
        let k = |v: &T| Taylor::constant(v.clone());
        match self {
            LocalCurve::Line { origin, step } => [
                k(&origin[0]) + &(u.clone() * &k(&step[0])),
                k(&origin[1]) + &(u.clone() * &k(&step[1])),
            ],
            LocalCurve::Arc {
                centre,
                radius,
                theta1,
                theta2,
            } => {
                let theta = k(theta1) + &(u.clone() * &k(&(theta2.clone() - theta1)));
                let (s, c) = theta.sin_cos();
                [
                    k(&centre[0]) + &(c * &k(radius)),
                    k(&centre[1]) + &(s * &k(radius)),
                ]
            }
        }
    }

    /// The point at u.
    pub fn at(&self, u: &T) -> [T; 2] {
        let [x, y] = self.series(&Taylor::constant(u.clone()));
        [x.value().clone(), y.value().clone()]
    }
}

/// The inputs of a GERBS path.
#[derive(Clone, Debug)]
pub struct PathSpec<T> {
    /// The waypoints W_0 … W_n.
    pub waypoints: Vec<[T; 2]>,
    /// The arc radius R.
    pub radius: T,
    /// θ_o, the half-angle of each arc (Algorithm 1).
    pub theta_o: T,
    /// l of Eqs. (23)–(24); `None`: 2Rθ_o, the length of each arc.
    pub line_length: Option<T>,
    /// How the arc angles θ₁, θ₂ are chosen (the paper's printed formula or the turn direction).
    pub convention: ArcConvention,
    /// The turn signs of Algorithm 1, decided by the caller on exact waypoints
    /// ([`exact_turn_signs`]); `None`: decided exactly on `waypoints` as given.
    pub turns: Option<Vec<i32>>,
    /// Lines or arcs at the first and last waypoints ([`EndCurves`]).
    pub end_curves: EndCurves,
}

impl<T: Real> PathSpec<T> {
    /// The inputs of a path through `waypoints` with arcs of radius `radius`, and the rest
    /// as in the paper: θ_o = π/8 (Sec. IV), lines of length 2Rθ_o, arcs swept in the turn
    /// direction (Eqs. (21)–(22) as printed make left turns run backwards; see
    /// [`ArcConvention`]), turns decided exactly on the waypoints, straight lines at the
    /// first and last waypoints (the text; Algorithm 2's arcs there miss them).
    ///
    /// # Examples
    /// ```
    /// use trajverify::algo::gerbs::bfbs::Bfbs;
    /// use trajverify::algo::gerbs::path::{GerbsPath, PathSpec};
    /// use trajverify::algo::gerbs::Side;
    /// let waypoints = vec![[0.0, 0.0], [300.0, 100.0], [600.0, -50.0], [900.0, 150.0], [1200.0, 0.0]];
    /// let spec = PathSpec::new(waypoints, 80.0, &());
    /// let path = GerbsPath::new(&spec, Bfbs::uniform(2, 5).unwrap()).unwrap();
    /// // The path passes through W2 at the knot t = 1/4.
    /// let p = path.at(&0.25, Side::Right).unwrap();
    /// assert!((p.point[0] - 300.0).abs() < 1e-9 && (p.point[1] - 100.0).abs() < 1e-9);
    /// assert!(path.at(&1.5, Side::Right).is_err());
    /// ```
    pub fn new(waypoints: Vec<[T; 2]>, radius: T, ctx: &T::Ctx) -> Self {
        PathSpec {
            waypoints,
            radius,
            theta_o: T::pi(ctx) / &T::from_i64(8, ctx),
            line_length: None,
            convention: ArcConvention::TurnDirection,
            turns: None,
            end_curves: EndCurves::default(),
        }
    }
}

/// The line length l of the end lines after checking R, θ_o and l: the given l, or 2R|θ_o|.
fn checked_line_length<T: Real>(spec: &PathSpec<T>) -> Result<T, GerbsError> {
    let ctx = spec.radius.ctx();
    let zero = T::zero_in(&ctx);
    if !(spec.radius > zero) || !spec.radius.is_finite() {
        return Err(GerbsError::Parameter {
            field: "radius",
            message: "the arc radius R must be a positive number".into(),
        });
    }
    if !(spec.theta_o.clone().abs() < T::pi(&ctx)) || spec.theta_o.is_zero() {
        return Err(GerbsError::Parameter {
            field: "theta_o",
            message: "theta_o must lie in (-pi, pi) and not be 0".into(),
        });
    }
    match &spec.line_length {
        Some(l) if !(*l > zero) || !l.is_finite() => Err(GerbsError::Parameter {
            field: "line_length",
            message: "the line length l must be a positive number".into(),
        }),
        Some(l) => Ok(l.clone()),
        None => Ok(T::from_i64(2, &ctx) * &spec.radius * &spec.theta_o.clone().abs()),
    }
}

/// Whether the local curves fit between the waypoints: each reaches less than half-way to
/// its neighbouring waypoints — an arc spans the chord 2R·sin(|θ_o|/2) from W_i to each of its
/// ends, an end line has length l (an end arc counts as an arc). Beyond that, neighbouring
/// local curves overlap and the blend of Algorithm 2 no longer follows the waypoints' polygon.
/// Decided in `T` (for balls: refused unless provably inside).
fn check_fit<T: Real>(spec: &PathSpec<T>, length: &T) -> Result<(), GerbsError> {
    let w = &spec.waypoints;
    let n = w.len();
    let ctx = spec.radius.ctx();
    let two = T::from_i64(2, &ctx);
    let chord = two.clone() * &spec.radius * &(spec.theta_o.clone().abs() / &two).sin();
    let lines = spec.end_curves == EndCurves::Lines;
    for i in 0..n {
        let end_line = lines && (i == 0 || i == n - 1);
        let reach = if end_line { length } else { &chord };
        let field = if end_line && spec.line_length.is_some() {
            "line_length"
        } else {
            "radius"
        };
        for j in [i.wrapping_sub(1), i + 1] {
            let Some(other) = w.get(j) else { continue };
            let (dx, dy) = (other[0].clone() - &w[i][0], other[1].clone() - &w[i][1]);
            let half = (dx.clone() * &dx + &(dy.clone() * &dy)).sqrt() / &two;
            if reach.decide_lt(&half) != Some(true) {
                return Err(GerbsError::Parameter {
                    field,
                    message: format!(
                        "does not fit: the local curve at waypoint {} reaches {} of the {} to waypoint {} (it must stay below half)",
                        i + 1,
                        reach.to_f64(),
                        (half.clone() * &two).to_f64(),
                        j + 1
                    ),
                });
            }
        }
    }
    Ok(())
}

/// The local curves c_1 … c_n of Algorithm 2 (lines or arcs at the ends, [`EndCurves`]; arcs inside), with the
/// tangents of Algorithm 1 (or the given ones).
///
/// # Errors
/// Without `given`, those of [`tangents_with_turns`] or [`tangents`]; with it,
/// [`GerbsError::Parameter`] (`tangents`) unless it has one tangent and one turn sign per
/// waypoint; [`GerbsError::Parameter`] for a `radius` that is not positive and finite,
/// θ_o = 0 or |θ_o| ≥ π (`theta_o`, NaN too), or a `line_length` that is not positive and
/// finite.
pub fn local_curves<T: Real>(
    spec: &PathSpec<T>,
    given: Option<&Tangents<T>>,
) -> Result<(Vec<LocalCurve<T>>, Tangents<T>), GerbsError> {
    let tan = match given {
        Some(t) => t.clone(),
        None => match &spec.turns {
            Some(s) => tangents_with_turns(&spec.waypoints, s.clone())?,
            None => tangents(&spec.waypoints)?,
        },
    };
    let n = spec.waypoints.len();
    if tan.m.len() != n || tan.s.len() != n {
        return Err(GerbsError::Parameter {
            field: "tangents",
            message: format!(
                "{} tangents and {} turn signs for {n} waypoints: one of each per waypoint",
                tan.m.len(),
                tan.s.len()
            ),
        });
    }
    let length = checked_line_length(spec)?;
    check_fit(spec, &length)?;
    let ctx = spec.radius.ctx();
    let pi = T::pi(&ctx);
    let half_pi = pi / &T::from_i64(2, &ctx);
    let mut curves = Vec::with_capacity(n);
    for (i, w) in spec.waypoints.iter().enumerate() {
        let m = &tan.m[i];
        let step = [length.clone() * &m[0], length.clone() * &m[1]];
        let line_here = spec.end_curves == EndCurves::Lines;
        if i == 0 && line_here {
            curves.push(LocalCurve::Line {
                origin: w.clone(),
                step,
            });
        } else if i == n - 1 && line_here {
            curves.push(LocalCurve::Line {
                origin: [w[0].clone() - &step[0], w[1].clone() - &step[1]],
                step,
            });
        } else {
            let s = T::from_i64(tan.s[i] as i64, &ctx);
            let centre = [
                w[0].clone() - &(spec.radius.clone() * &s * &m[1]),
                w[1].clone() + &(spec.radius.clone() * &s * &m[0]),
            ];
            let phi = m[1].atan2(&m[0]);
            let base = phi - &(s.clone() * &half_pi);
            let (theta1, theta2) = match spec.convention {
                ArcConvention::AsPrinted => (base.clone() + &spec.theta_o, base - &spec.theta_o),
                ArcConvention::TurnDirection => (
                    base.clone() - &(s.clone() * &spec.theta_o),
                    base + &(s * &spec.theta_o),
                ),
            };
            curves.push(LocalCurve::Arc {
                centre,
                radius: spec.radius.clone(),
                theta1,
                theta2,
            });
        }
    }
    Ok((curves, tan))
}

/// A point of the path with its derivatives and curvature.
#[derive(Clone, Debug, PartialEq)]
pub struct PathPoint<T> {
    /// The parameter value.
    pub t: T,
    /// p(t).
    pub point: [T; 2],
    /// p′(t).
    pub d1: [T; 2],
    /// p″(t).
    pub d2: [T; 2],
    /// Signed curvature (x′y″ − y′x″)/|p′|³.
    pub curvature: T,
    /// dκ/dt.
    pub curvature_rate: T,
}

/// The most points [`GerbsPath::sample`] returns in one call.
pub const MAX_SAMPLES: usize = 10_000_000;

/// The point as computed, or an error naming `t` where a derivative or the curvature is not
/// finite (zero speed, or the kernel centre of an ERBS with a fractional σ, where p″ and κ are
/// unbounded).
fn finite_point<T: Field>(p: PathPoint<T>) -> Result<PathPoint<T>, GerbsError> {
    let values = p.point.iter().chain(&p.d1).chain(&p.d2);
    let finite = values
        .chain([&p.curvature, &p.curvature_rate])
        .all(Field::is_finite);
    if finite {
        Ok(p)
    } else {
        Err(GerbsError::Parameter {
            field: "t",
            message: "the path's derivatives or curvature are not finite there (zero speed, or the centre of an \
                      ERBS kernel with a fractional sigma, where they are unbounded)"
                .into(),
        })
    }
}

/// The blended path p(t) = Σ c_{k−1}(t) B_k(t) (Eq. 25, Algorithm 2), a planar curve of
/// t ∈ [t_1, t_{n+2}] ([0, 1] for the knots of [`GerbsPath::new`]): it implements
/// [`ParamCurve`] (points are `[T; 2]`) and [`ParamCurveArclen`].
///
/// # Examples
/// A curvature-continuous path through five waypoints (the BFBS with i = 2), in f64:
/// ```
/// use trajverify::algo::gerbs::{bfbs::Bfbs, path::{GerbsPath, PathSpec}};
/// use trajverify::curve::parametric::{curvature, ParamCurve, ParamCurveArclen};
///
/// let waypoints = vec![[0.0, 0.0], [300.0, 100.0], [600.0, -50.0], [900.0, 150.0], [1200.0, 0.0]];
/// let spec = PathSpec::new(waypoints, 80.0, &());
/// let path = GerbsPath::new(&spec, Bfbs::uniform(2, 5).unwrap()).unwrap();
/// assert_eq!(path.domain(), (0.0, 1.0));
/// let start = path.point(&0.0).unwrap();
/// assert!(start[0].abs() < 1e-9 && start[1].abs() < 1e-9); // the path starts at W1
/// assert!(curvature(&path, &0.5).unwrap() < 1.0 / 80.0 + 1e-9);
/// assert!(path.length().unwrap() > 1200.0);
/// assert!(path.point(&1.5).is_err());
/// ```
pub struct GerbsPath<T, B> {
    knots: Knots<T>,
    blend: B,
    curves: Vec<LocalCurve<T>>,
    tangents: Tangents<T>,
    /// Whether `knots` are the uniform knots of Algorithm 2 (built by [`GerbsPath::new`]),
    /// on which [`GerbsPath::sample`] locates its samples exactly.
    uniform_knots: bool,
}

/// The knots, the blend and the curves agree: n curves, n + 2 knots, and a blend built for n
/// basis functions (or for any).
fn check_parts<T: Field, B: Blend<T>>(
    knots: &Knots<T>,
    blend: &B,
    curves: &[LocalCurve<T>],
) -> Result<(), GerbsError> {
    let n = curves.len();
    if knots.basis_count() != n {
        return Err(GerbsError::Knots(format!(
            "{} knots for {n} local curves: need n + 2",
            knots.as_slice().len()
        )));
    }
    if let Some(built) = blend.built_on() {
        let path = knots.as_slice();
        let differ =
            |(a, b): (&T, &T)| a.decide_lt(b) == Some(true) || b.decide_lt(a) == Some(true);
        if built.len() != path.len() || built.iter().zip(path).any(differ) {
            return Err(GerbsError::Parameter {
                field: "blend",
                message: format!(
                    "the basis was built on {} other knots than the path's {}: build it on the path's knots",
                    built.len(),
                    path.len()
                ),
            });
        }
    }
    match blend.basis_count() {
        Some(count) if count != n => Err(GerbsError::Parameter {
            field: "params.i",
            message: format!("{count} exponents for {n} basis functions (one per waypoint)"),
        }),
        _ => Ok(()),
    }
}

impl<T: Real, B: Blend<T>> GerbsPath<T, B> {
    /// Algorithm 2 on the knots of Fig. 1 with the given basis.
    ///
    /// # Errors
    /// The errors of [`local_curves`] (too few or repeated waypoints, a radius that does
    /// not fit, …) and [`GerbsError::Parameter`] for a BFBS whose number of exponents is
    /// not the number of waypoints.
    pub fn new(spec: &PathSpec<T>, blend: B) -> Result<Self, GerbsError> {
        let (curves, tangents) = local_curves(spec, None)?;
        let knots = Knots::uniform(spec.waypoints.len(), &spec.radius.ctx())?;
        check_parts(&knots, &blend, &curves)?;
        Ok(GerbsPath {
            knots,
            blend,
            curves,
            tangents,
            uniform_knots: true,
        })
    }

    /// The path from explicit parts (knots must have n + 2 entries for n curves).
    ///
    /// # Errors
    /// [`GerbsError::Knots`] unless there are n + 2 knots for n curves;
    /// [`GerbsError::Parameter`] for a blend built for another number of basis functions.
    pub fn from_parts(
        knots: Knots<T>,
        blend: B,
        curves: Vec<LocalCurve<T>>,
        tangents: Tangents<T>,
    ) -> Result<Self, GerbsError> {
        check_parts(&knots, &blend, &curves)?;
        Ok(GerbsPath {
            knots,
            blend,
            curves,
            tangents,
            uniform_knots: false,
        })
    }

    /// The knot vector, one knot per local curve and the two end knots.
    pub fn knots(&self) -> &Knots<T> {
        &self.knots
    }

    /// The blending function of the basis.
    pub fn blend(&self) -> &B {
        &self.blend
    }

    /// The local curves c_k (lines and arcs).
    pub fn curves(&self) -> &[LocalCurve<T>] {
        &self.curves
    }

    /// The tangents and turn signs of Algorithm 1.
    pub fn tangents(&self) -> &Tangents<T> {
        &self.tangents
    }

    /// p as series in t to `order` at t ∈ [0, 1], one-sided at knots (the side decided on t
    /// as given; for a t rounded from an exact value use [`GerbsPath::series_on`]).
    pub fn series(&self, t: &T, order: usize, side: Side) -> [Taylor<T>; 2] {
        match self.knots.paper_interval(t, side) {
            Some(j) => self.series_in(t, j, order),
            None => {
                let zero = Taylor::constant(T::zero_in(&t.ctx())).with_order(order);
                [zero.clone(), zero]
            }
        }
    }

    /// p as series in t to `order` on knot interval i (counted from 0: from knot i to knot
    /// i + 1), chosen by the caller.
    ///
    /// # Errors
    /// [`GerbsError::Parameter`] (field `interval`) unless interval i exists and is not empty.
    pub fn series_on(&self, t: &T, i: usize, order: usize) -> Result<[Taylor<T>; 2], GerbsError> {
        self.check_interval(i)?;
        Ok(self.series_in(t, i + 1, order))
    }

    /// [`GerbsPath::series_on`] on the paper's interval j = i + 1, unchecked (the callers
    /// inside the crate take j from the knot vector).
    pub(crate) fn series_in(&self, t: &T, j: usize, order: usize) -> [Taylor<T>; 2] {
        self.series_located(&Located::from_t(&self.knots, t, j), order)
    }

    /// `Ok` when knot interval i (from 0) exists and is not empty, decided on the knots.
    fn check_interval(&self, i: usize) -> Result<(&T, &T), GerbsError> {
        let knots = self.knots.as_slice();
        let (Some(a), Some(b)) = (knots.get(i), knots.get(i + 1)) else {
            return Err(GerbsError::Parameter {
                field: "interval",
                message: format!(
                    "interval {i} does not exist: the intervals are numbered 0 to {}",
                    knots.len() - 2
                ),
            });
        };
        if a.decide_lt(b) != Some(true) {
            return Err(GerbsError::Parameter {
                field: "interval",
                message: format!("interval {i} is empty (knots {i} and {} are equal)", i + 1),
            });
        }
        Ok((a, b))
    }

    /// [`GerbsPath::series_on`] at a located parameter (its distances to the interval's ends
    /// given, exactly where they are known exactly).
    pub fn series_located(&self, at: &Located<T>, order: usize) -> [Taylor<T>; 2] {
        let t = &at.t;
        let ctx = t.ctx();
        let basis = basis_series_located(&self.knots, &self.blend, at, order);
        let var = Taylor::variable(t.clone(), order);
        // B_k is basis[k − 2]; a basis function outside its support is the zero series.
        let active = basis
            .iter()
            .enumerate()
            .filter(|(_, b)| !b.c.iter().all(Field::is_zero))
            .map(|(i, b)| (i + 2, b));
        self.blend_local_curves(&var, order, &ctx, active)
    }

    /// Σ c_{k−1} B_k over the given (k, B_k), as series in t (`var`) to `order`.
    fn blend_local_curves<'b>(
        &self,
        var: &Taylor<T>,
        order: usize,
        ctx: &T::Ctx,
        basis: impl IntoIterator<Item = (usize, &'b Taylor<T>)>,
    ) -> [Taylor<T>; 2]
    where
        T: 'b,
    {
        let zero = Taylor::constant(T::zero_in(ctx)).with_order(order);
        let mut p = [zero.clone(), zero];
        for (k, b) in basis {
            let c = self.local_series(k, var);
            p[0] += &(c[0].clone() * b);
            p[1] += &(c[1].clone() * b);
        }
        p
    }

    /// The local curve c_{k−1} blended by B_k, as series in t (`var`): its local parameter
    /// is u = (t − t_{k−1})/(t_{k+1} − t_{k−1}).
    fn local_series(&self, k: usize, var: &Taylor<T>) -> [Taylor<T>; 2] {
        let (lo, hi) = (self.knots.at(k - 1), self.knots.at(k + 1));
        let u = (var.clone() - &Taylor::constant(lo.clone())) / &Taylor::constant(hi.clone() - lo);
        self.curves[k - 2].series(&u)
    }

    /// Point, derivatives and curvature at t (one-sided at a knot, decided on t as given).
    ///
    /// # Errors
    /// [`GerbsError::Parameter`] (field `t`) for t outside [t_1, t_{n+2}] or NaN: the path is
    /// defined on its knots only.
    pub fn at(&self, t: &T, side: Side) -> Result<PathPoint<T>, GerbsError> {
        match self.knots.interval(t, side) {
            Some(i) => self.at_on(t, i),
            None => Err(GerbsError::Parameter {
                field: "t",
                message: "outside the knot vector's range (or not a number)".into(),
            }),
        }
    }

    /// Point, derivatives and curvature at knot i (counted from 0, i = 0 … n + 1: the
    /// paper's t_{i+1}), from the side `side`: the knot interval is decided on the index, not
    /// on a comparison of values.
    ///
    /// # Errors
    /// [`GerbsError::Parameter`] (field `knot`) for i > n + 1, and (field `t`) where the
    /// path's derivatives or curvature are not finite there.
    pub fn at_knot(&self, i: usize, side: Side) -> Result<PathPoint<T>, GerbsError> {
        let Some(t) = self.knots.get(i).cloned() else {
            return Err(GerbsError::Parameter {
                field: "knot",
                message: format!(
                    "knot {i} does not exist: the knots are numbered 0 to {}",
                    self.knots.as_slice().len() - 1
                ),
            });
        };
        // The paper's numbering from here on: t_k is knot i.
        let k = i + 1;
        let last = self.knots.as_slice().len();
        // The non-empty interval that ends (from the left) or starts (from the right) at t_k.
        let nonempty = |j: usize| self.knots.at(j) < self.knots.at(j + 1);
        let j = match side {
            Side::Right => (k..last).find(|&j| nonempty(j)),
            Side::Left => (1..k).rev().find(|&j| nonempty(j)),
        };
        let j = j.or_else(|| self.knots.paper_interval(&t, side));
        match j {
            Some(j) => {
                // t is the interval's start (from the right) or end (from the left), or a knot
                // equal to it: that distance is exactly 0, not t_k − t_j formed from two
                // roundings of one knot (an enclosure of 1/3 minus itself is not 0).
                let mut at = Located::from_t(&self.knots, &t, j);
                match side {
                    Side::Right if j >= k => at.after_start = T::zero_in(&t.ctx()),
                    Side::Left if j < k => at.before_end = T::zero_in(&t.ctx()),
                    _ => {}
                }
                finite_point(self.point_from(&t, self.series_located(&at, 3)))
            }
            None => finite_point(self.point_from(&t, self.series(&t, 3, side))),
        }
    }

    /// Point, derivatives and curvature at t on knot interval i (counted from 0: from knot
    /// i to knot i + 1), chosen by the caller (for a t rounded from an exact value whose
    /// interval is known).
    ///
    /// # Errors
    /// [`GerbsError::Parameter`]: field `interval` unless interval i exists and is not
    /// empty; field `t` for a t that is not finite or lies outside the interval (for balls:
    /// provably outside), or where the derivatives or curvature are not finite.
    pub fn at_on(&self, t: &T, i: usize) -> Result<PathPoint<T>, GerbsError> {
        let (a, b) = self.check_interval(i)?;
        // Provably outside only (decided without counting an undecided comparison): a ball
        // that touches the interval is evaluated there.
        if check_domain(t, (a, b)).is_err() {
            return Err(GerbsError::Parameter {
                field: "t",
                message: format!("not finite or outside knot interval {i}"),
            });
        }
        finite_point(self.point_from(t, self.series_in(t, i + 1, 3)))
    }

    fn point_from(&self, t: &T, [x, y]: [Taylor<T>; 2]) -> PathPoint<T> {
        let (dx, dy) = (x.derivative_series(), y.derivative_series());
        let (ddx, ddy) = (dx.derivative_series(), dy.derivative_series());
        let speed2 = dx.clone() * &dx + &(dy.clone() * &dy);
        let cross = dx.clone() * &ddy - &(dy.clone() * &ddx);
        let kappa = cross / &(speed2.clone() * &speed2.sqrt());
        let d = |s: &Taylor<T>, k: usize| s.derivatives()[k].clone();
        PathPoint {
            t: t.clone(),
            point: [d(&x, 0), d(&y, 0)],
            d1: [d(&x, 1), d(&y, 1)],
            d2: [d(&x, 2), d(&y, 2)],
            curvature: d(&kappa, 0),
            curvature_rate: d(&kappa, 1),
        }
    }

    /// `count` ≥ 2 evenly spaced points t = i/(count − 1) of [0, 1] (from the right, the last
    /// from the left). On the uniform knots of Algorithm 2 (t_k = (k − 2)/(n − 1)) the knot
    /// interval of each sample is decided exactly in integers, j = ⌊i(n − 1)/(count − 1)⌋ + 2,
    /// (the paper's numbering; interval j − 1 from 0), so rounding i/(count − 1) onto a knot
    /// cannot switch sides; other knot vectors locate
    /// the rounded value.
    ///
    /// # Errors
    /// [`GerbsError::Parameter`]: field `count` above [`MAX_SAMPLES`]; field `t` where a
    /// sample's derivatives or curvature are not finite.
    pub fn sample(&self, count: usize) -> Result<Vec<PathPoint<T>>, GerbsError> {
        if count > MAX_SAMPLES {
            return Err(GerbsError::Parameter {
                field: "count",
                message: format!("at most {MAX_SAMPLES} samples, got {count}"),
            });
        }
        let ctx = self.knots.at(1).ctx();
        let last = count.max(2) - 1;
        let n = self.curves.len();
        let uniform = self.uniform_knots;
        (0..=last)
            .map(|i| {
                let t = T::from_ratio(i as i64, last as i64, &ctx);
                if uniform && n >= 2 {
                    // The interval counted from 0 (the paper's j − 1).
                    let interval = if i == last {
                        n - 1
                    } else {
                        // i(n−1) fits: i ≤ MAX samples and n ≤ 10⁵ in every caller.
                        (i as u128 * (n as u128 - 1) / last as u128) as usize + 1
                    };
                    self.at_on(&t, interval)
                } else {
                    // t = i/last lies in [0, 1] = [t_1, t_{n+2}]: its interval exists.
                    let side = if i == last { Side::Left } else { Side::Right };
                    match self.knots.interval(&t, side) {
                        Some(interval) => self.at_on(&t, interval),
                        None => finite_point(self.point_from(&t, self.series(&t, 3, side))),
                    }
                }
            })
            .collect()
    }

    /// The arc length ∫|p′| dt, by tanh–sinh on each knot interval (split at the basis's
    /// break points), to relative tolerance `tol`. When F_j is itself a quadrature (ERBS),
    /// F_j is carried from node to node: each node integrates Ψ_j only from the nearest node
    /// already done, not from the knot. The knot intervals are independent and run in
    /// parallel; their lengths are added in knot order, so the sum does not depend on the
    /// number of threads.
    pub fn length_within(&self, tol: &T) -> T
    where
        B: Sync,
    {
        let ctx = tol.ctx();
        let rule = TanhSinh::new(&ctx, 12);
        let knots = self.knots.as_slice();
        let pieces: Vec<T> = (1..knots.len())
            .into_par_iter()
            .map(carried(|j| self.interval_length(j, &rule, tol)))
            .collect();
        let mut total = T::zero_in(&ctx);
        for piece in &pieces {
            total += piece;
        }
        total
    }

    /// ∫|p′| dt over knot interval j (zero when it is empty).
    fn interval_length(&self, j: usize, rule: &TanhSinh<T>, tol: &T) -> T {
        let ctx = tol.ctx();
        let (zero, one) = (T::zero_in(&ctx), T::one_in(&ctx));
        let mut total = zero.clone();
        let (a, b) = (self.knots.at(j), self.knots.at(j + 1));
        if a >= b {
            return total;
        }
        // (t, F_j(t)) already known on this interval, sorted by t.
        let known = RefCell::new(vec![(a.clone(), zero.clone()), (b.clone(), one.clone())]);
        let carried = |t: &T| -> T {
            let mut known = known.borrow_mut();
            let i = known.partition_point(|(s, _)| s <= t);
            let (prev, next) = (&known[i - 1], &known[i.min(known.len() - 1)]);
            if prev.0 == *t {
                return prev.1.clone();
            }
            let f = if t.clone() - &prev.0 <= next.0.clone() - t {
                prev.1.clone() + &self.blend.increment(&self.knots, j, &prev.0, t)
            } else {
                next.1.clone() - &self.blend.increment(&self.knots, j, t, &next.0)
            };
            known.insert(i, (t.clone(), f.clone()));
            f
        };
        let mut cuts = vec![a.clone()];
        cuts.extend(self.blend.break_points(&self.knots, j));
        cuts.push(b.clone());
        for w in cuts.windows(2) {
            let speed = |l: &T, _: &T| {
                let t = w[0].clone() + l;
                let d = if self.blend.sweeps() {
                    self.velocity(j, &t, &carried(&t), &self.blend.slope(&self.knots, j, &t))
                } else {
                    let [x, y] = self.series(&t, 1, Side::Right);
                    [x.derivatives()[1].clone(), y.derivatives()[1].clone()]
                };
                (d[0].clone() * &d[0] + &(d[1].clone() * &d[1])).sqrt()
            };
            total += &rule.integrate((&w[0], &w[1]), speed, tol, &zero).value;
        }
        total
    }

    /// p′(t) on knot interval j from F_j(t) and F_j′(t): the falling B_j = 1 − F_j and the
    /// rising B_{j+1} = F_j blend their local curves, p′ = Σ c′ B + c B′.
    fn velocity(&self, j: usize, t: &T, f: &T, slope: &T) -> [T; 2] {
        let ctx = t.ctx();
        let n = self.curves.len();
        let one = T::one_in(&ctx);
        let mut d = [T::zero_in(&ctx), T::zero_in(&ctx)];
        let active = [
            (j, one - f, -slope.clone()),
            (j + 1, f.clone(), slope.clone()),
        ];
        for (k, basis, basis_slope) in active {
            if !(2..=n + 1).contains(&k) {
                continue;
            }
            let c = self.local_series(k, &Taylor::variable(t.clone(), 1));
            for (di, ci) in d.iter_mut().zip(&c) {
                let cd = ci.derivatives();
                *di += &(cd[1].clone() * &basis + &(cd[0].clone() * &basis_slope));
            }
        }
        d
    }
}

impl<B: Blend<Ball>> GerbsPath<Ball, B> {
    /// The length ∫|p′| dt **proven**: on every knot interval (split at the blend's break
    /// points) the speed's Taylor models in balls are integrated with a proven remainder
    /// ([`crate::curve::integral`]), where [`GerbsPath::length_within`] estimates it by
    /// tanh–sinh. The ball encloses the length; `options` set how far it is narrowed.
    ///
    /// # Errors
    /// [`GerbsError::Parameter`] (field `kind`) for a blend whose F_j is itself a quadrature
    /// (the ERBS), whose series a ball does not enclose; (field `waypoints`) when the speed
    /// has no finite enclosure somewhere (a cusp, where |p′| = 0).
    pub fn proven_length(&self, options: &IntegralOptions) -> Result<Ball, GerbsError>
    where
        B: Sync,
    {
        let knots = self.knots.as_slice();
        let bits = knots[0].ctx();
        // The knot intervals in parallel (each carries the caller's tally of undecided
        // comparisons); the sum in interval order, so the ball does not depend on threads.
        let pieces: Vec<Result<Ball, GerbsError>> = (1..knots.len())
            .into_par_iter()
            .map(carried(|j| self.proven_interval_length(j, options)))
            .collect();
        let mut total = Ball::zero_in(&bits);
        for piece in pieces {
            total += &piece?;
        }
        Ok(total)
    }

    /// The proven length over knot interval j (0 when it is empty).
    fn proven_interval_length(
        &self,
        j: usize,
        options: &IntegralOptions,
    ) -> Result<Ball, GerbsError>
    where
        B: Sync,
    {
        if self.blend.sweeps() {
            self.proven_sweep_length(j, options)
        } else {
            self.proven_closed_length(j, options)
        }
    }

    /// The proven length over knot interval j of a path whose F_j is a quadrature (ERBS).
    /// F_j is carried along the interval: its value at an exact point is the proven
    /// increment from the nearest point already known, and over a piece [p, q] it lies
    /// between F_j(p) and F_j(q) (F_j rises: F_j′ = Ψ_j/S_j ≥ 0). With F_j′'s series
    /// ([`Blend::slope_series`]) that gives the speed's Taylor models; on the pieces where
    /// they are not finite (next to a knot, where Ψ_j has an essential singularity, or at
    /// the kernel's centre) the speed is bounded from F_j′'s range ([`Blend::slope_range`])
    /// and the integral over the piece is its width times that bound. Knots known only as
    /// balls (1/3) are replaced by exact inner ends, the span between them bounded the same
    /// way.
    fn proven_sweep_length(&self, j: usize, options: &IntegralOptions) -> Result<Ball, GerbsError> {
        let (a, b) = (self.knots.at(j), self.knots.at(j + 1));
        let bits = a.ctx();
        let not_proven = |what: String| GerbsError::Parameter {
            field: "waypoints",
            message: format!("the path's length is not proven on knot interval {j}: {what}"),
        };
        let zero = Ball::zero_in(&bits);
        if a.rad() == 0.0 && b.rad() == 0.0 && a.mid() >= b.mid() {
            return Ok(zero); // an empty interval (a doubled end knot)
        }
        // The inner ends at the working precision (rounded inward: outside the knots' balls),
        // so that the integrator's tolerance is relative to the working precision.
        let (lo, _) = Float::with_val_round(bits, a.upper(), Round::Up);
        let (hi, _) = Float::with_val_round(bits, b.lower(), Round::Down);
        if !(lo < hi) {
            // An interval within its knots' rounding: its length is bounded like an end.
            return self
                .speed_bound(j, &Ball::hull(a, b), None)
                .ok_or_else(|| not_proven("no bound of the speed".into()));
        }
        let rising = CarriedRising::new(&self.knots, &self.blend, j);
        let speed = |t: &Ball, order: usize| -> Option<Taylor<Ball>> {
            let slope = self.blend.slope_series(&self.knots, j, t, order);
            if !slope.c.iter().all(Field::is_finite) {
                return None;
            }
            let f = Taylor::integrate(&slope, rising.over(t), order + 2);
            let speed = speed_series(self.series_from_rising(t, j, order + 1, f));
            speed.c.iter().all(Field::is_finite).then_some(speed)
        };
        let bound = |p: &Float, q: &Float| -> Option<Ball> {
            let f = Ball::hull(&rising.at(p), &rising.at(q));
            self.speed_bound(j, &Ball::from_bounds(p, q), Some(f))
        };
        // The spans [t_j, lo] and [hi, t_{j+1}] inside the knots' balls.
        let mut total = zero.clone();
        for end in [a, b] {
            if end.rad() > 0.0 {
                let span = self
                    .speed_bound(j, end, None)
                    .ok_or_else(|| not_proven("no bound of the speed at a knot".into()))?;
                total += &span;
            }
        }
        let mut cuts = vec![Ball::exact(lo)];
        for c in self.blend.break_points(&self.knots, j) {
            let c = Ball::exact(c.mid().clone());
            if cuts[0].decide_lt(&c) == Some(true) && c.mid() < &hi {
                cuts.push(c);
            }
        }
        cuts.push(Ball::exact(hi));
        for w in cuts.windows(2) {
            let piece = integrate_with(&speed, &bound, (&w[0], &w[1]), options)
                .map_err(|e| not_proven(e.to_string()))?;
            total += &piece.value;
        }
        Ok(total)
    }

    /// A bound of ∫|p′| over the part of the ball `piece` inside interval j: the piece's
    /// width times the bounds of |p′| there, from F_j over the piece (`rising`, or [0, 1]
    /// when none is given) and F_j′'s range there.
    fn speed_bound(&self, j: usize, piece: &Ball, rising: Option<Ball>) -> Option<Ball> {
        let bits = piece.ctx();
        let (lo, hi) = (Ball::exact(piece.lower()), Ball::exact(piece.upper()));
        let slope = self.blend.slope_range(&self.knots, j, &lo, &hi)?;
        let value =
            rising.unwrap_or_else(|| Ball::hull(&Ball::zero_in(&bits), &Ball::one_in(&bits)));
        let series = Taylor {
            c: vec![value, slope],
        };
        let [x, y] = self.series_from_rising(piece, j, 1, series);
        let (dx, dy) = (x.c[1].clone(), y.c[1].clone());
        let speed = (dx.clone() * &dx + &(dy.clone() * &dy)).sqrt();
        // |p′| ≥ 0: its lower bound is clamped there. The integral over the piece lies
        // between its width times the two bounds (rounded outward), so it narrows as the
        // piece's width squared.
        let zero = Float::with_val(bits, 0);
        let upper = speed.upper();
        let lower = speed.lower().max(&zero);
        let width = Float::with_val(bits + 64, piece.upper() - piece.lower());
        let (high, _) = Float::with_val_round(bits + 64, &upper * &width, Round::Up);
        let (low, _) = Float::with_val_round(bits + 64, &lower * &width, Round::Down);
        (high.is_finite() && low <= high).then(|| Ball::from_bounds(&low, &high))
    }

    /// The path's series at t on interval j from F_j's series (`rising`, of `order`): the
    /// falling B_j = 1 − F_j and the rising B_{j+1} = F_j blend their local curves.
    fn series_from_rising(
        &self,
        t: &Ball,
        j: usize,
        order: usize,
        rising: Taylor<Ball>,
    ) -> [Taylor<Ball>; 2] {
        let bits = t.ctx();
        let n = self.curves.len();
        let falling = Taylor::constant(Ball::one_in(&bits)).with_order(order) - &rising;
        let var = Taylor::variable(t.clone(), order);
        let active = [(j, &falling), (j + 1, &rising)]
            .into_iter()
            .filter(|(k, _)| (2..=n + 1).contains(k));
        self.blend_local_curves(&var, order, &bits, active)
    }

    /// The proven length over knot interval j of a path whose F_j is in closed form.
    fn proven_closed_length(&self, j: usize, options: &IntegralOptions) -> Result<Ball, GerbsError>
    where
        B: Sync,
    {
        let (a, b) = (self.knots.at(j), self.knots.at(j + 1));
        let mut total = Ball::zero_in(&a.ctx());
        if a >= b {
            return Ok(total);
        }
        let speed = |t: &Ball, order: usize| -> Option<Taylor<Ball>> {
            let speed = speed_series(self.series_in(t, j, order + 1));
            speed.c.iter().all(Field::is_finite).then_some(speed)
        };
        let mut cuts = vec![a.clone()];
        cuts.extend(self.blend.break_points(&self.knots, j));
        cuts.push(b.clone());
        for w in cuts.windows(2) {
            let piece =
                integrate(&speed, (&w[0], &w[1]), options).map_err(|e| GerbsError::Parameter {
                    field: "waypoints",
                    message: format!("the path's length is not proven on knot interval {j}: {e}"),
                })?;
            total += &piece.value;
        }
        Ok(total)
    }
}

/// |p′| as a series, from p's series [x, y] (one order shorter).
fn speed_series([x, y]: [Taylor<Ball>; 2]) -> Taylor<Ball> {
    let (dx, dy) = (x.derivative_series(), y.derivative_series());
    (dx.clone() * &dx + &(dy.clone() * &dy)).sqrt()
}

/// F_j along knot interval j of a blend whose F_j is a quadrature, in balls: the values
/// known so far (the knots, F_j = 0 and 1, and exact points), each new point's value the
/// proven increment from the nearest known one.
struct CarriedRising<'a, B> {
    knots: &'a Knots<Ball>,
    blend: &'a B,
    j: usize,
    /// (t, F_j(t)) sorted by t.
    known: RefCell<Vec<(Ball, Ball)>>,
}

impl<'a, B: Blend<Ball>> CarriedRising<'a, B> {
    fn new(knots: &'a Knots<Ball>, blend: &'a B, j: usize) -> Self {
        let (a, b) = (knots.at(j), knots.at(j + 1));
        let bits = a.ctx();
        let known = vec![
            (a.clone(), Ball::zero_in(&bits)),
            (b.clone(), Ball::one_in(&bits)),
        ];
        CarriedRising {
            knots,
            blend,
            j,
            known: RefCell::new(known),
        }
    }

    /// F_j at the exact point x of the interval.
    fn at(&self, x: &Float) -> Ball {
        let mut known = self.known.borrow_mut();
        let i = known.partition_point(|(s, _)| s.mid() <= x);
        let prev = &known[i - 1];
        if prev.0.mid() == x && prev.0.rad() == 0.0 {
            return prev.1.clone();
        }
        let t = Ball::exact(x.clone());
        let distance = |from: &Ball, to: &Float| Float::with_val(64, to - from.mid()).abs();
        let f = match known.get(i) {
            Some(next) if distance(&next.0, x) < distance(&prev.0, x) => {
                next.1.clone() - &self.blend.increment(self.knots, self.j, &t, &next.0)
            }
            _ => prev.1.clone() + &self.blend.increment(self.knots, self.j, &prev.0, &t),
        };
        known.insert(i, (t, f.clone()));
        f
    }

    /// F_j over a ball: at its exact midpoint, or between its ends' values (F_j rises).
    fn over(&self, t: &Ball) -> Ball {
        if t.rad() == 0.0 {
            self.at(t.mid())
        } else {
            Ball::hull(&self.at(&t.lower()), &self.at(&t.upper()))
        }
    }
}

impl<T: Real, B: Blend<T>> ParamCurve<T, 2> for GerbsPath<T, B> {
    fn domain(&self) -> (T, T) {
        let k = self.knots.as_slice();
        (k[0].clone(), k[k.len() - 1].clone())
    }

    /// From the right at an inner knot, from the left at the last one.
    fn derivatives(&self, t: &T, order: usize) -> Result<Vec<[T; 2]>, CurveError> {
        crate::curve::parametric::check_order(order)?;
        let (start, end) = self.domain();
        check_domain(t, (&start, &end))?;
        let side = if *t == end { Side::Left } else { Side::Right };
        let j = self
            .knots
            .paper_interval(t, side)
            .ok_or_else(|| CurveError::OutsideDomain {
                t: t.to_f64(),
                start: start.to_f64(),
                end: end.to_f64(),
            })?;
        let [x, y] = self.series_in(t, j, order);
        let (dx, dy) = (x.derivatives(), y.derivatives());
        Ok((0..=order)
            .map(|k| [dx[k].clone(), dy[k].clone()])
            .collect())
    }

    /// The inner knots and the points where a basis function is less smooth.
    fn breakpoints(&self) -> Vec<T> {
        let knots = self.knots.as_slice();
        let (first, last) = (&knots[0], &knots[knots.len() - 1]);
        let mut out = Vec::new();
        for j in 1..knots.len() {
            // Inner knots only (a double end knot is no break inside the domain).
            if *first < knots[j - 1] && knots[j - 1] < *last {
                out.push(knots[j - 1].clone());
            }
            if knots[j - 1] < knots[j] {
                out.extend(self.blend.break_points(&self.knots, j));
            }
        }
        out.dedup();
        out
    }
}

impl<T: Real, B: Blend<T> + Sync> ParamCurveArclen<T, 2> for GerbsPath<T, B> {
    /// [`GerbsPath::length_within`] the default tolerance 2^(8−p), which carries an ERBS's
    /// quadrature from node to node.
    fn length(&self) -> Result<T, CurveError> {
        Ok(self.length_within(&default_tolerance(&self.knots.at(1).ctx())))
    }
}
