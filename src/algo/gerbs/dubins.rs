//! Dubins shortest paths between poses (Dubins 1957), the baseline of Fig. 7.
//!
//! In coordinates scaled by the turn radius R and rotated so the goal lies on the x axis at
//! distance d, with start and goal headings a, b relative to the chord, each of the six words
//! LSL, RSR, LSR, RSL, RLR, LRL has closed-form segment lengths (t, p, q) (Shkel & Lumelsky
//! 2001, Table 1); the shortest feasible one is the Dubins path. Lengths are returned in the
//! original units. The curvature is ±1/R on arcs and 0 on the straight: it jumps at every
//! arc–line junction.
//!
//! **Decisions on the exact input.** The lengths are continuous in the poses, but the path is
//! not: which word is shortest, whether a word exists, and whether an arc angle reduced
//! modulo 2π is 0 or 2π (a full loop) are discrete decisions. Rounded poses could take any of
//! them the wrong way at every precision alike, so two precisions agreeing would certify a
//! wrong path. [`plan`] therefore takes them once, on the exact input ([`ExactLeg`]:
//! rational waypoints and radius, headings as rationals, constant expressions or the
//! relative angles of Algorithm 1), in ball arithmetic at rising precision (128 bits,
//! doubling up to [`PLAN_BITS_CAP`]) until every comparison is proven; [`DubinsPlan::path`]
//! then evaluates the chosen word in any number type by replaying the decisions, with no
//! comparison of its own. Exact zeros stay exact (a heading along the chord, an arc of
//! length 0), so a straight leg is decided exactly. When words tie to the cap precision the
//! choice is harmless only if they describe the same path (equal steps once the segments
//! that are zero to the cap are dropped); then the first word in the order above is taken,
//! otherwise the leg is refused ([`DubinsError`]): its shortest path is not unique.

use super::path::unit_tangents;
use super::GerbsError;
use crate::curve::expr::ExactReal;
use crate::curve::parametric::check_domain;
use crate::scalar::ball::Ball;
use crate::scalar::double_interval::DoubleInterval;
use crate::scalar::{BigRational, Exact, Field, Real};
use rug::Float;

/// L (left turn), S (straight) or R (right turn).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Step {
    /// A left turn on the circle of radius R.
    L,
    /// A straight segment.
    S,
    /// A right turn on the circle of radius R.
    R,
}

use Step::{L, R, S};

/// The six words, in the order ties are broken.
pub const WORDS: [[Step; 3]; 6] = [
    [L, S, L],
    [R, S, R],
    [L, S, R],
    [R, S, L],
    [R, L, R],
    [L, R, L],
];

/// The highest precision at which [`plan`] tries to decide a comparison.
pub const PLAN_BITS_CAP: u32 = 4096;

/// One Dubins word and its three segment lengths (read through accessors; made by the
/// planner, [`shortest`] and [`through_poses`], which decide the word exactly).
#[derive(Clone, Debug)]
pub struct DubinsPath<T> {
    /// The start pose (x, y, heading).
    pub(crate) start: [T; 3],
    /// The turning radius R.
    pub(crate) radius: T,
    /// The three steps of the word (e.g. L S R).
    pub(crate) word: [Step; 3],
    /// Segment lengths in path units (angle × R for arcs).
    pub(crate) lengths: [T; 3],
}

/// Why no Dubins path was chosen for a leg.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum DubinsError {
    /// The start and goal points coincide, or the radius is not positive.
    #[error("leg {leg}: {reason}")]
    Degenerate {
        /// The leg (0-based).
        leg: usize,
        /// What is wrong.
        reason: String,
    },
    /// A comparison the choice depends on could not be decided at [`PLAN_BITS_CAP`] bits.
    #[error("leg {leg}: {what} cannot be decided at {PLAN_BITS_CAP} bits")]
    Undecided {
        /// The leg (0-based).
        leg: usize,
        /// Which decision.
        what: String,
    },
    /// Two words that describe different paths have the same length to the cap precision.
    #[error("leg {leg}: the shortest path is not unique: {first} and {second} have the same length to {PLAN_BITS_CAP} bits")]
    Tie {
        /// The leg (0-based).
        leg: usize,
        /// One word.
        first: String,
        /// Another word of the same length.
        second: String,
    },
    /// An argument outside what the function is defined for (an arc length that is not a
    /// number or lies outside the path).
    #[error("{field}: {message}")]
    Argument {
        /// The argument.
        field: &'static str,
        /// What is wrong.
        message: String,
    },
}

/// A heading of a Dubins leg, as the exact planner needs it: its angle relative to the
/// leg's chord is what the word formulas use.
#[derive(Clone, Debug, PartialEq)]
pub enum LegHeading {
    /// Along the chord (relative angle exactly 0): the end waypoints of Algorithm 1.
    AlongChord,
    /// ±φ/2, half the signed turn angle φ = atan2(u ∧ v, u · v) between the chords u and v
    /// that meet at the waypoint (given exactly by their wedge and dot products): an
    /// interior heading of Algorithm 1, the bisector of the two chords, is −φ/2 relative to
    /// the outgoing chord and +φ/2 relative to the incoming one.
    HalfTurn {
        /// +1 or −1.
        sign: i32,
        /// u ∧ v.
        wedge: Exact,
        /// u · v.
        dot: Exact,
    },
    /// An absolute heading (radians), given exactly; relative angle heading − atan2(dy, dx).
    Absolute(ExactReal),
}

/// One leg, given exactly: the chord from `from` to `to`, the radius and the two headings.
#[derive(Clone, Debug, PartialEq)]
pub struct ExactLeg {
    /// The start waypoint.
    pub from: [Exact; 2],
    /// The goal waypoint.
    pub to: [Exact; 2],
    /// The turn radius R (> 0).
    pub radius: Exact,
    /// The heading at `from`.
    pub start: LegHeading,
    /// The heading at `to`.
    pub goal: LegHeading,
}

impl ExactLeg {
    fn chord(&self) -> [Exact; 2] {
        [
            self.to[0].clone() - &self.from[0],
            self.to[1].clone() - &self.from[1],
        ]
    }
}

/// The legs through `waypoints` with the headings of Algorithm 1, given exactly (the
/// waypoints must pass [`super::path::check_waypoints`]).
pub fn algorithm1_legs(waypoints: &[[Exact; 2]], radius: &Exact) -> Vec<ExactLeg> {
    let n = waypoints.len();
    // Each chord once, and each interior waypoint's wedge and dot once (both legs that meet
    // there read them).
    let chords: Vec<[Exact; 2]> = waypoints
        .windows(2)
        .map(|p| {
            [
                Exact::from(&p[1][0] - &p[0][0]),
                Exact::from(&p[1][1] - &p[0][1]),
            ]
        })
        .collect();
    let turns: Vec<(Exact, Exact)> = chords
        .windows(2)
        .map(|uv| {
            let [u, v] = [&uv[0], &uv[1]];
            let wedge = Exact::from(&u[0] * &v[1]) - Exact::from(&u[1] * &v[0]);
            let dot = Exact::from(&u[0] * &v[0]) + Exact::from(&u[1] * &v[1]);
            (wedge, dot)
        })
        .collect();
    // The heading at waypoint i relative to the chord leaving (sign −1) or arriving (+1).
    let heading = |i: usize, sign: i32| {
        if i == 0 || i == n - 1 {
            return LegHeading::AlongChord;
        }
        let (wedge, dot) = turns[i - 1].clone();
        LegHeading::HalfTurn { sign, wedge, dot }
    };
    (0..n.saturating_sub(1))
        .map(|i| ExactLeg {
            from: waypoints[i].clone(),
            to: waypoints[i + 1].clone(),
            radius: radius.clone(),
            start: heading(i, -1),
            goal: heading(i + 1, 1),
        })
        .collect()
}

/// The legs between consecutive poses (waypoint, absolute heading), given exactly.
pub fn legs_with_headings(
    waypoints: &[[Exact; 2]],
    headings: &[ExactReal],
    radius: &Exact,
) -> Vec<ExactLeg> {
    (0..waypoints.len().saturating_sub(1))
        .map(|i| ExactLeg {
            from: waypoints[i].clone(),
            to: waypoints[i + 1].clone(),
            radius: radius.clone(),
            start: LegHeading::Absolute(headings[i].clone()),
            goal: LegHeading::Absolute(headings[i + 1].clone()),
        })
        .collect()
}

/// The discrete choices of one leg, decided on its exact input by [`plan`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DubinsPlan {
    /// Index into [`WORDS`].
    pub word: usize,
    /// The multiples k of 2π removed from each angle reduced modulo 2π, in the order the
    /// word's formulas reduce them.
    turns: Vec<i64>,
    /// Segments whose length is exactly zero.
    zero: [bool; 3],
}

/// What the word formulas need, in one number type: chord length d/R and the sines and
/// cosines of the relative headings.
struct Frame<T> {
    d: T,
    a: T,
    b: T,
    sa: T,
    ca: T,
    sb: T,
    cb: T,
    cab: T,
    two_pi: T,
}

impl<T: Real> Frame<T> {
    fn new(leg: &ExactLeg, ctx: &T::Ctx) -> (Frame<T>, T, T) {
        let q = |x: &Exact| T::from_exact(x, ctx);
        let [dx, dy] = leg.chord().map(|c| q(&c));
        let radius = q(&leg.radius);
        let d = (dx.clone() * &dx + &(dy.clone() * &dy)).sqrt() / &radius;
        let theta = dy.atan2(&dx);
        let relative = |h: &LegHeading| match h {
            LegHeading::AlongChord => T::zero_in(ctx),
            LegHeading::HalfTurn { sign, wedge, dot } => {
                q(wedge).atan2(&q(dot)) * &T::from_ratio(*sign as i64, 2, ctx)
            }
            LegHeading::Absolute(h) => h.eval::<T>(ctx) - &theta,
        };
        let (a, b) = (relative(&leg.start), relative(&leg.goal));
        let (sa, ca) = a.sin_cos();
        let (sb, cb) = b.sin_cos();
        let cab = (a.clone() - &b).sin_cos().1;
        let two_pi = T::pi(ctx) * &T::from_i64(2, ctx);
        let heading = theta.clone() + &a;
        (
            Frame {
                d,
                a,
                b,
                sa,
                ca,
                sb,
                cb,
                cab,
                two_pi,
            },
            heading,
            radius,
        )
    }
}

/// Where the discrete choices come from: decided in balls while planning, replayed after.
trait Choices<T> {
    /// Whether a word exists (its condition x ≥ 0); `None`: undecided.
    fn feasible(&mut self, x: &T) -> Option<bool>;
    /// The k with x − 2πk in [0, 2π); `None`: undecided (x is within the ball of a
    /// multiple of 2π).
    fn turns(&mut self, x: &T, two_pi: &T) -> Option<i64>;
}

/// x − 2πk for the k the choices give.
fn reduce<T: Real, C: Choices<T>>(x: T, f: &Frame<T>, c: &mut C) -> (T, bool) {
    match c.turns(&x, &f.two_pi) {
        Some(k) => (
            x - &(f.two_pi.clone() * &T::from_i64(k, &f.two_pi.ctx())),
            true,
        ),
        None => {
            // Undecided: take the nearest multiple (an arc near 0; its loop variant, 2π
            // longer, is never shortest when a decided word ties this one).
            let k = (x.to_f64() / f.two_pi.to_f64()).round() as i64;
            (
                x - &(f.two_pi.clone() * &T::from_i64(k, &f.two_pi.ctx())),
                false,
            )
        }
    }
}

/// √x for x ≥ 0 up to rounding (an enclosure of √max(x, 0) for balls).
fn root<T: Real>(x: T) -> T {
    x.max_with(&T::zero_in(&x.ctx())).sqrt()
}

/// The lengths (in units of R) of word `w`, or `None` when it does not exist; the flag says
/// whether every choice was decided.
fn word_lengths<T: Real, C: Choices<T>>(
    w: usize,
    f: &Frame<T>,
    c: &mut C,
) -> Option<([T; 3], bool)> {
    let ctx = f.d.ctx();
    let k = |v: i64| T::from_i64(v, &ctx);
    let d2 = f.d.clone() * &f.d;
    let Frame {
        d,
        a,
        b,
        sa,
        ca,
        sb,
        cb,
        cab,
        ..
    } = f;
    let mut decided = true;
    // An undecided condition keeps the word as a candidate (it may exist), marked undecided.
    fn feasible<T, C: Choices<T>>(c: &mut C, x: &T, decided: &mut bool) -> bool {
        c.feasible(x).unwrap_or_else(|| {
            *decided = false;
            true
        })
    }
    let lengths = match w {
        0 => {
            // LSL
            let p2 = k(2) + &d2 - &(k(2) * cab) + &(k(2) * d * &(sa.clone() - sb));
            if !feasible(c, &p2, &mut decided) {
                return None;
            }
            let t1 = (cb.clone() - ca).atan2(&(d.clone() + sa - sb));
            [t1.clone() - a, root(p2), b.clone() - &t1]
        }
        1 => {
            // RSR
            let p2 = k(2) + &d2 - &(k(2) * cab) + &(k(2) * d * &(sb.clone() - sa));
            if !feasible(c, &p2, &mut decided) {
                return None;
            }
            let t1 = (ca.clone() - cb).atan2(&(d.clone() - sa + sb));
            [a.clone() - &t1, root(p2), t1 - b]
        }
        2 => {
            // LSR
            let p2 = k(-2) + &d2 + &(k(2) * cab) + &(k(2) * d * &(sa.clone() + sb));
            if !feasible(c, &p2, &mut decided) {
                return None;
            }
            let p = root(p2);
            let t2 = (-ca.clone() - cb).atan2(&(d.clone() + sa + sb)) - &k(-2).atan2(&p);
            [t2.clone() - a, p, t2 - b]
        }
        3 => {
            // RSL
            let p2 = k(-2) + &d2 + &(k(2) * cab) - &(k(2) * d * &(sa.clone() + sb));
            if !feasible(c, &p2, &mut decided) {
                return None;
            }
            let p = root(p2);
            let t2 = (ca.clone() + cb).atan2(&(d.clone() - sa - sb)) - &k(2).atan2(&p);
            [a.clone() - &t2, p, b.clone() - &t2]
        }
        4 | 5 => {
            // RLR (4) and LRL (5): x = cos of the middle arc's supplement.
            let sign = if w == 4 { 1 } else { -1 };
            let x = (k(6) - &d2 + &(k(2) * cab) + &(k(2 * sign) * d * &(sa.clone() - sb))) / &k(8);
            let slack = k(1) - &(x.clone() * &x);
            if !feasible(c, &slack, &mut decided) {
                return None;
            }
            let acos = root(slack).atan2(&x);
            let phi = if w == 4 {
                (ca.clone() - cb).atan2(&(d.clone() - sa + sb))
            } else {
                (ca.clone() - cb).atan2(&(d.clone() + sa - sb))
            };
            let (p, ok) = reduce(f.two_pi.clone() - &acos, f, c);
            decided &= ok;
            let (half, ok) = reduce(p.clone() / &k(2), f, c);
            decided &= ok;
            let first = if w == 4 {
                a.clone() - &phi + &half
            } else {
                -a.clone() - &phi + &half
            };
            let (t, ok) = reduce(first, f, c);
            decided &= ok;
            let last = if w == 4 {
                a.clone() - b - &t + &p
            } else {
                b.clone() - a - &t + &p
            };
            let (q, ok) = reduce(last, f, c);
            decided &= ok;
            return Some(([t, p, q], decided));
        }
        _ => return None,
    };
    // The two arcs of an *S* word, reduced into [0, 2π).
    let [first, straight, last] = lengths;
    let (first, ok1) = reduce(first, f, c);
    let (last, ok2) = reduce(last, f, c);
    Some(([first, straight, last], decided && ok1 && ok2))
}

/// Choices decided in balls, recorded for replay.
struct Deciding {
    turns: Vec<i64>,
}

impl Choices<Ball> for Deciding {
    fn feasible(&mut self, x: &Ball) -> Option<bool> {
        let (lo, hi) = (x.lower(), x.upper());
        if lo >= 0 {
            Some(true)
        } else if hi < 0 {
            Some(false)
        } else if Field::is_zero(x) {
            Some(true)
        } else {
            None
        }
    }
    fn turns(&mut self, x: &Ball, two_pi: &Ball) -> Option<i64> {
        if Field::is_zero(x) {
            self.turns.push(0);
            return Some(0);
        }
        let q = x.clone() / two_pi;
        let (lo, hi) = (q.lower(), q.upper());
        let (klo, khi) = (lo.floor(), hi.floor());
        if !klo.is_finite() || klo != khi {
            return None;
        }
        let k = klo.to_f64() as i64;
        self.turns.push(k);
        Some(k)
    }
}

/// Choices replayed from a plan.
struct Replaying<'a> {
    turns: std::slice::Iter<'a, i64>,
}

impl<T> Choices<T> for Replaying<'_> {
    fn feasible(&mut self, _: &T) -> Option<bool> {
        Some(true)
    }
    fn turns(&mut self, _: &T, _: &T) -> Option<i64> {
        Some(self.turns.next().copied().unwrap_or(0))
    }
}

/// A word evaluated in balls while planning.
struct Candidate {
    word: usize,
    lengths: [Ball; 3],
    decided: bool,
    turns: Vec<i64>,
}

impl Candidate {
    fn total(&self) -> Ball {
        self.lengths[0].clone() + &self.lengths[1] + &self.lengths[2]
    }
    /// The path's steps without the segments that are zero to this precision.
    fn signature(&self) -> Vec<(Step, &Ball)> {
        WORDS[self.word]
            .iter()
            .zip(&self.lengths)
            .filter(|(_, l)| !(Field::is_zero(*l) || l.contains(&Float::new(l.ctx()))))
            .map(|(s, l)| (*s, l))
            .collect()
    }
    fn same_path(&self, other: &Candidate) -> bool {
        let (a, b) = (self.signature(), other.signature());
        a.len() == b.len()
            && a.iter()
                .zip(&b)
                .all(|((s, x), (t, y))| s == t && x.lower() <= y.upper() && y.lower() <= x.upper())
    }
}

/// The shortest word of `leg` (number `index` in error messages), decided on its exact
/// input (see the module doc).
///
/// # Errors
/// [`DubinsError::Degenerate`] for a radius ≤ 0, coincident points, or no word joining the
/// poses; [`DubinsError::Undecided`] when the shortest word cannot be decided, and
/// [`DubinsError::Tie`] when two different paths have equal lengths, at [`PLAN_BITS_CAP`] bits
/// (precision doubles from 128 until then).
pub fn plan(leg: &ExactLeg, index: usize) -> Result<DubinsPlan, DubinsError> {
    if leg.radius <= 0 {
        return Err(DubinsError::Degenerate {
            leg: index,
            reason: "the radius must be positive".into(),
        });
    }
    if leg.from == leg.to {
        return Err(DubinsError::Degenerate {
            leg: index,
            reason: "the start and goal points coincide".into(),
        });
    }
    if let Some(quick) = plan_in_intervals(leg) {
        return Ok(quick);
    }
    plan_in_balls(leg, index)
}

/// The plan decided in balls at 128 bits, doubling up to [`PLAN_BITS_CAP`].
fn plan_in_balls(leg: &ExactLeg, index: usize) -> Result<DubinsPlan, DubinsError> {
    let mut bits = 128;
    loop {
        match plan_at(leg, index, bits) {
            Ok(p) => return Ok(p),
            Err(e) if bits >= PLAN_BITS_CAP => return Err(e),
            Err(_) => bits *= 2,
        }
    }
}

/// Choices decided in double intervals, strictly: the first choice an interval cannot
/// decide ends the try ([`plan_in_intervals`]).
struct Quick {
    turns: Vec<i64>,
    stuck: bool,
}

impl Choices<DoubleInterval> for Quick {
    fn feasible(&mut self, x: &DoubleInterval) -> Option<bool> {
        let decided = if x.lo() > 0.0 {
            Some(true)
        } else if x.hi() < 0.0 {
            Some(false)
        } else {
            None
        };
        self.stuck |= decided.is_none();
        decided
    }
    fn turns(&mut self, x: &DoubleInterval, two_pi: &DoubleInterval) -> Option<i64> {
        let q = *x / two_pi;
        let (low, high) = (q.lo().floor(), q.hi().floor());
        if !q.is_finite() || low != high || low.abs() > 1e15 {
            self.stuck = true;
            return None;
        }
        self.turns.push(low as i64);
        Some(low as i64)
    }
}

/// The plan of `leg` when double intervals decide every choice of every word strictly and
/// one word is shorter than all others with no segment that may be 0; `None` otherwise.
///
/// Such a plan is the plan of the ball ladder: every decision it records is proven (an
/// interval encloses the exact value), the shortest word is unique, and no segment is an
/// exact zero, so the tie and exact-zero rules of [`plan_at`], the only places where the
/// precision could matter, are not reached — provided the balls settle what the intervals
/// settled, which they do at 128 bits in practice (their enclosures are about 2⁻⁷⁵ as wide,
/// with the same mean-value bound for atan2); a ball ladder that could not would refuse the
/// leg, where this plan is still proven. What it saves is MPFR's `atan2`, most of a plan's
/// cost; the legs it cannot decide (a word at the edge of existing, an arc near 0 or 2π,
/// near-ties, an exactly straight leg) go to the balls as before.
fn plan_in_intervals(leg: &ExactLeg) -> Option<DubinsPlan> {
    let (frame, _, _) = Frame::<DoubleInterval>::new(leg, &());
    let mut candidates = Vec::with_capacity(WORDS.len());
    for w in 0..WORDS.len() {
        let mut quick = Quick {
            turns: Vec::new(),
            stuck: false,
        };
        let lengths = word_lengths(w, &frame, &mut quick);
        if quick.stuck {
            return None;
        }
        if let Some((lengths, _)) = lengths {
            let total = lengths[0] + lengths[1] + lengths[2];
            candidates.push((w, lengths, total, quick.turns));
        }
    }
    let best = candidates
        .iter()
        .min_by(|a, b| a.2.hi().total_cmp(&b.2.hi()))?;
    let unique = candidates
        .iter()
        .all(|c| c.0 == best.0 || c.2.lo() > best.2.hi());
    let no_zero = best.1.iter().all(|l| l.lo() > 0.0 || l.hi() < 0.0);
    (unique && no_zero && best.2.is_finite()).then(|| DubinsPlan {
        word: best.0,
        turns: best.3.clone(),
        zero: [false; 3],
    })
}

fn plan_at(leg: &ExactLeg, index: usize, bits: u32) -> Result<DubinsPlan, DubinsError> {
    crate::cancel::checkpoint();
    let (frame, _, _) = Frame::<Ball>::new(leg, &bits);
    let mut candidates = Vec::new();
    for w in 0..WORDS.len() {
        let mut deciding = Deciding { turns: Vec::new() };
        if let Some((lengths, decided)) = word_lengths(w, &frame, &mut deciding) {
            candidates.push(Candidate {
                word: w,
                lengths,
                decided,
                turns: deciding.turns,
            });
        }
    }
    let undecided = |what: String| DubinsError::Undecided { leg: index, what };
    let totals: Vec<Ball> = candidates.iter().map(Candidate::total).collect();
    let best_upper = totals
        .iter()
        .map(Ball::upper)
        .min_by(|x, y| x.partial_cmp(y).unwrap_or(std::cmp::Ordering::Equal))
        .ok_or_else(|| DubinsError::Degenerate {
            leg: index,
            reason: "no Dubins word joins the two poses".into(),
        })?;
    // Every word that may be the shortest.
    let tied: Vec<&Candidate> = candidates
        .iter()
        .zip(&totals)
        .filter(|(_, t)| t.lower() <= best_upper)
        .map(|(c, _)| c)
        .collect();
    let Some(chosen) = tied.iter().find(|c| c.decided) else {
        return Err(undecided(format!(
            "the {} word (an arc within rounding of 0 or 2π, or a word at the edge of existing)",
            name(&WORDS[tied[0].word])
        )));
    };
    if let Some(other) = tied.iter().find(|c| !c.same_path(chosen)) {
        return Err(DubinsError::Tie {
            leg: index,
            first: name(&WORDS[chosen.word]),
            second: name(&WORDS[other.word]),
        });
    }
    Ok(DubinsPlan {
        word: chosen.word,
        turns: chosen.turns.clone(),
        zero: std::array::from_fn(|i| Field::is_zero(&chosen.lengths[i])),
    })
}

impl DubinsPlan {
    /// The planned word of `leg` evaluated in `T` (no comparison is made: the decisions are
    /// replayed).
    pub fn path<T: Real>(&self, leg: &ExactLeg, ctx: &T::Ctx) -> DubinsPath<T> {
        let (frame, heading, radius) = Frame::<T>::new(leg, ctx);
        let mut replay = Replaying {
            turns: self.turns.iter(),
        };
        let zero = T::zero_in(ctx);
        let lengths = word_lengths(self.word, &frame, &mut replay)
            .map_or_else(|| [zero.clone(), zero.clone(), zero.clone()], |(l, _)| l);
        let lengths: [T; 3] = std::array::from_fn(|i| {
            if self.zero[i] {
                zero.clone()
            } else {
                lengths[i].clone() * &radius
            }
        });
        DubinsPath {
            start: [
                T::from_exact(&leg.from[0], ctx),
                T::from_exact(&leg.from[1], ctx),
                heading,
            ],
            radius,
            word: WORDS[self.word],
            lengths,
        }
    }
}

/// The shortest path of every leg, each decided on its exact input and evaluated in `T`;
/// the first leg that cannot be decided is the error.
///
/// # Errors
/// The error of [`plan`] for the first leg that fails, its 0-based index as `leg`.
pub fn shortest_exact<T: Real>(
    legs: &[ExactLeg],
    ctx: &T::Ctx,
) -> Result<Vec<DubinsPath<T>>, DubinsError> {
    legs.iter()
        .enumerate()
        .map(|(i, leg)| plan(leg, i).map(|p| p.path(leg, ctx)))
        .collect()
}

fn name(word: &[Step; 3]) -> String {
    word.iter()
        .map(|s| match s {
            Step::L => 'L',
            Step::S => 'S',
            Step::R => 'R',
        })
        .collect()
}

/// The headings Algorithm 1 gives the waypoints: atan2 of its tangent directions m_i.
///
/// # Errors
/// [`GerbsError::Waypoints`] as [`unit_tangents`] (fewer than 3, non-finite, repeated or
/// collinear waypoints). The turn signs, which the headings do not need, are not decided.
pub fn algorithm1_headings<T: Real>(w: &[[T; 2]]) -> Result<Vec<T>, GerbsError> {
    Ok(unit_tangents(w)?
        .iter()
        .map(|m| m[1].atan2(&m[0]))
        .collect())
}

/// The values of `T` as exact rationals (every f64, MPFR and rational number is one).
fn exact<T: Field>(x: &T) -> Option<BigRational> {
    x.to_rational()
}

/// The shortest Dubins path of radius `radius` from each pose (W_i, heading_i) to the next,
/// decided exactly on the values as given (see the module doc); `Err(i)` when leg i (0-based)
/// has no decidable shortest path, or one whose lengths overflow the number type.
///
/// # Errors
/// `Err(i)`, the first such leg.
pub fn through_poses<T: Real>(
    w: &[[T; 2]],
    headings: &[T],
    radius: &T,
) -> Result<Vec<DubinsPath<T>>, usize> {
    let ctx = radius.ctx();
    let radius_q = radius.to_exact().ok_or(0usize)?;
    (0..w.len().saturating_sub(1))
        .map(|i| {
            let point = |p: &[T; 2]| Some([p[0].to_exact()?, p[1].to_exact()?]);
            let heading = |h: &T| exact(h).map(|q| LegHeading::Absolute(ExactReal::Exact(q)));
            let leg = (|| {
                Some(ExactLeg {
                    from: point(&w[i])?,
                    to: point(&w[i + 1])?,
                    radius: radius_q.clone(),
                    start: heading(&headings[i])?,
                    goal: heading(&headings[i + 1])?,
                })
            })()
            .ok_or(i)?;
            let path = plan(&leg, i).map(|p| p.path(&leg, &ctx)).map_err(|_| i)?;
            // Lengths that overflow the number type (a radius near 1e300) are no path.
            let finite = path.lengths.iter().chain(&path.start).all(Field::is_finite);
            if finite {
                Ok(path)
            } else {
                Err(i)
            }
        })
        .collect()
}

/// The shortest of the six words from pose `start` = (x, y, heading) to `goal`, decided
/// exactly on the values as given; `None` when it cannot be decided (see [`plan`]).
///
/// # Examples
/// Two poses on the x axis, both heading along it: the shortest word is the straight line.
/// ```
/// use trajverify::algo::gerbs::dubins::shortest;
/// let path = shortest(&[0.0, 0.0, 0.0], &[10.0, 0.0, 0.0], &1.0).unwrap();
/// assert!((path.total() - 10.0).abs() < 1e-12);
/// let middle = path.pose_at(&5.0).unwrap();
/// assert!((middle[0] - 5.0).abs() < 1e-12 && middle[1].abs() < 1e-12);
/// assert!(path.pose_at(&11.0).is_err()); // beyond the path's length
/// ```
pub fn shortest<T: Real>(start: &[T; 3], goal: &[T; 3], radius: &T) -> Option<DubinsPath<T>> {
    through_poses(
        &[
            [start[0].clone(), start[1].clone()],
            [goal[0].clone(), goal[1].clone()],
        ],
        &[start[2].clone(), goal[2].clone()],
        radius,
    )
    .ok()?
    .pop()
}

/// The summed length of consecutive legs.
pub fn total_length<T: Real>(legs: &[DubinsPath<T>], ctx: &T::Ctx) -> T {
    let mut total = T::zero_in(ctx);
    for leg in legs {
        total += &leg.total();
    }
    total
}

impl<T: Real> DubinsPath<T> {
    /// The total length of the three steps.
    pub fn total(&self) -> T {
        self.lengths[0].clone() + &self.lengths[1] + &self.lengths[2]
    }

    /// The start pose (x, y, heading).
    pub fn start(&self) -> &[T; 3] {
        &self.start
    }

    /// The turning radius R.
    pub fn radius(&self) -> &T {
        &self.radius
    }

    /// The three steps of the word (e.g. L S R).
    pub fn word(&self) -> &[Step; 3] {
        &self.word
    }

    /// The segment lengths in path units (angle × R for arcs).
    pub fn lengths(&self) -> &[T; 3] {
        &self.lengths
    }

    /// The word as letters, e.g. "LSR".
    pub fn word_name(&self) -> String {
        name(&self.word)
    }

    /// The pose (x, y, heading) after arc length `s` from the start, 0 ≤ s ≤ the path's
    /// length.
    ///
    /// # Errors
    /// [`DubinsError::Argument`] (field `s`) for an `s` that is not finite or lies (provably)
    /// outside [0, length].
    pub fn pose_at(&self, s: &T) -> Result<[T; 3], DubinsError> {
        let zero = T::zero_in(&s.ctx());
        let length = self.total();
        if check_domain(s, (&zero, &length)).is_err() {
            return Err(DubinsError::Argument {
                field: "s",
                message: format!(
                    "{} is not an arc length along the path [0, {}]",
                    s.to_f64(),
                    length.to_f64()
                ),
            });
        }
        let pose = self.pose_along(s);
        if pose.iter().all(Field::is_finite) {
            Ok(pose)
        } else {
            Err(DubinsError::Argument {
                field: "s",
                message: "the pose there is not finite".into(),
            })
        }
    }

    /// The pose after arc length `s`, clamped to the path. Each step advances by
    /// min(max(left, 0), its length): continuous in `s`, so no comparison decides a branch
    /// (a sample on a junction gives the same pose from either step), and a step of length
    /// 0 is passed over.
    pub(crate) fn pose_along(&self, s: &T) -> [T; 3] {
        let zero = T::zero_in(&s.ctx());
        let mut pose = self.start.clone();
        let mut left = s.clone();
        for (step, len) in self.word.iter().zip(&self.lengths) {
            if len.is_zero() {
                continue;
            }
            let run = left.max_with(&zero).min_with(len);
            pose = advance(&pose, *step, &run, &self.radius);
            left -= &run;
        }
        pose
    }

    /// `count` ≥ 2 poses at equal arc-length steps from the start to the end of the path.
    pub fn samples(&self, count: usize) -> Vec<[T; 3]> {
        crate::cancel::checkpoint();
        let ctx = self.radius.ctx();
        let last = count.max(2) as i64 - 1;
        let length = self.total();
        (0..=last)
            .map(|k| self.pose_along(&(length.clone() * &T::from_ratio(k, last, &ctx))))
            .collect()
    }

    /// The signed curvature of each step (±1/R on turns, 0 on the straight).
    pub fn curvatures(&self) -> [T; 3] {
        let ctx = self.radius.ctx();
        self.word.map(|s| match s {
            Step::L => T::one_in(&ctx) / &self.radius,
            Step::R => -(T::one_in(&ctx) / &self.radius),
            Step::S => T::zero_in(&ctx),
        })
    }
}

/// Move along one segment kind by arc length `run`.
fn advance<T: Real>(pose: &[T; 3], step: Step, run: &T, radius: &T) -> [T; 3] {
    let [x, y, h] = pose.clone();
    let (sh, ch) = h.sin_cos();
    match step {
        Step::S => [x + &(ch * run), y + &(sh * run), h],
        Step::L | Step::R => {
            let sign = T::from_i64(if step == Step::L { 1 } else { -1 }, &radius.ctx());
            let dh = sign.clone() * run / radius;
            let h2 = h.clone() + &dh;
            let (s2, c2) = h2.sin_cos();
            let r = sign * radius;
            [x + &(r.clone() * &(s2 - &sh)), y - &(r * &(c2 - &ch)), h2]
        }
    }
}

/// The lower bound of a ball rounded down to a double (for tests).
#[cfg(test)]
fn low(x: &Ball) -> f64 {
    x.lower().to_f64_round(rug::float::Round::Down)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64) -> Exact {
        Exact::from(n)
    }

    fn reduce2pi(x: f64) -> f64 {
        x.rem_euclid(2.0 * std::f64::consts::PI)
    }

    #[test]
    fn every_word_reaches_the_goal_pose() {
        let poses = [
            ([0.0, 0.0, 0.3], [300.0, 100.0, -1.2]),
            ([0.0, 0.0, 0.0], [50.0, 10.0, 3.0]),
            ([10.0, -5.0, 2.0], [-40.0, 60.0, -2.5]),
            ([0.0, 0.0, 0.0], [0.0, 30.0, 3.1]),
        ];
        for (s, g) in poses {
            let path = shortest(&s, &g, &80.0).expect("decided");
            let end = path.pose_at(&path.total()).expect("the end of the path");
            let dh = reduce2pi(end[2] - g[2] + 1.0) - 1.0;
            assert!(
                (end[0] - g[0]).abs() < 1e-9 && (end[1] - g[1]).abs() < 1e-9 && dh.abs() < 1e-9,
                "{} misses {g:?}: {end:?}",
                path.word_name()
            );
        }
    }

    /// The interval plan, where it decides, is the ball ladder's plan, on Algorithm 1's legs
    /// and on legs with absolute headings through random waypoints; and it decides most legs
    /// (otherwise it would save nothing).
    #[test]
    fn interval_plans_are_the_ball_plans() {
        let mut word = crate::scalar::xorshift(0x9e37_79b9_7f4a_7c15);
        let mut next = |modulus: u64| (word() % modulus) as i64;
        let waypoints: Vec<[Exact; 2]> = (0..400)
            .map(|i| {
                let x = Exact::from((i * 2000 + next(1500), 10));
                [x, Exact::from((next(4001) - 2000, 10))]
            })
            .collect();
        let radius = Exact::from((next(900) + 100, 10));
        let headings: Vec<ExactReal> = (0..waypoints.len())
            .map(|_| ExactReal::Exact(BigRational::new((next(2001) - 1000).into(), 150.into())))
            .collect();
        let mut legs = algorithm1_legs(&waypoints, &radius);
        legs.extend(legs_with_headings(&waypoints, &headings, &radius));
        let mut decided = 0;
        for (i, leg) in legs.iter().enumerate() {
            if let Some(quick) = plan_in_intervals(leg) {
                decided += 1;
                assert_eq!(Ok(quick), plan_in_balls(leg, i), "leg {i}: {leg:?}");
            }
        }
        assert!(
            decided * 10 >= legs.len() * 9,
            "{decided} of {}",
            legs.len()
        );
    }

    /// Legs the intervals cannot decide go to the balls: an exactly straight leg (segments
    /// exactly 0) and a leg whose two shortest words tie exactly.
    #[test]
    fn undecidable_legs_go_to_the_balls() {
        let zero = || LegHeading::Absolute(ExactReal::Exact(BigRational::from_integer(0.into())));
        let straight = ExactLeg {
            from: [q(0), q(0)],
            to: [q(100), q(0)],
            radius: q(10),
            start: zero(),
            goal: zero(),
        };
        assert_eq!(plan_in_intervals(&straight), None);
        assert_eq!(plan(&straight, 0).map(|p| p.zero), Ok([true, false, true]));
        // A U-turn is symmetric about its chord: each word and its mirror image (left and
        // right exchanged) are equally long, so no word is shorter than all others.
        let pi = ExactReal::parse("pi").expect("pi");
        let u_turn = ExactLeg {
            from: [q(0), q(0)],
            to: [q(1), q(0)],
            radius: q(10),
            start: zero(),
            goal: LegHeading::Absolute(pi),
        };
        assert_eq!(plan_in_intervals(&u_turn), None);
    }

    #[test]
    fn a_straight_leg_is_exactly_straight_and_sampled_along_it() {
        let leg = ExactLeg {
            from: [q(0), q(0)],
            to: [q(100), q(0)],
            radius: q(10),
            start: LegHeading::Absolute(ExactReal::Exact(BigRational::from_integer(0.into()))),
            goal: LegHeading::Absolute(ExactReal::Exact(BigRational::from_integer(0.into()))),
        };
        let plan = plan(&leg, 0).expect("decided");
        let path = plan.path::<f64>(&leg, &());
        assert_eq!(path.lengths, [0.0, 100.0, 0.0]);
        let xs: Vec<f64> = path.samples(3).iter().map(|p| p[0]).collect();
        assert_eq!(xs, vec![0.0, 50.0, 100.0]);
        let ball = plan.path::<Ball>(&leg, &64);
        assert!(Field::is_zero(&ball.lengths[0]) && Field::is_zero(&ball.lengths[2]));
        assert!(low(&ball.lengths[1]) > 99.9);
    }
}
