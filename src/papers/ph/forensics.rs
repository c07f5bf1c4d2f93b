//! Table 1's verdicts: every printed cell — the 14 errors and the 13 ratios — against the same
//! cell computed under one definition of the error, either the true maximum over ξ of Eq. (21)
//! (the proven enclosures of [`super::proven`]) or the maximum over one grid of a family of
//! sampled maxima declared before computing ([`Member`]; policy clause 6). A ratio cell is
//! compared with the ratio of two maxima of the same definition, never with the ratio of the
//! printed, rounded errors (that would be the table's internal consistency, which reproduces
//! nothing).
//!
//! Each row is one claim, decided by the rule written before computing (the verdict policy's
//! table clause, `docs/papers.md`):
//! 1. every cell of the row within ½ unit of its last printed digit under the true values:
//!    `reproduced`; within one unit: `reproduced-rounding`;
//! 2. otherwise `metric` when one member gives every cell of the row within one unit (the
//!    member that gives most cells of the table is tried first);
//! 3. otherwise `typo` when, under the true values or the table's best member, exactly one
//!    cell is off, it differs from that definition's value printed to the same digits in one
//!    symbol other than its last digit (a last digit alone is a numerical difference), and the
//!    next row's ratio, computed from the same cell, agrees within one unit;
//! 4. otherwise `discrepancy`.
//!
//! Every decision is proven. A member that gives a row is proven by its whole grid in balls
//! (each f64 grid point taken exactly, [`BallConversion`]); that no member gives a row is
//! proven member by member: its maximum lies between its distance at one of its points (in
//! balls, a lower bound) and the true maximum's upper bound, and where that interval does not
//! put a cell more than one unit off, its whole grid is evaluated in balls. An f64 screen of
//! every member on the coarse rows (N ≤ 64, where the error is above 10⁻⁹ and f64 carries the
//! printed digits many times over) only orders the members, picks the points of the lower
//! bounds and counts the cells each member gives: it names, it decides nothing.

use super::table1::{
    curve, farthest, interval, units_range, units_text, BallConversion, Row, Units, TABLE1,
};
use crate::algo::ph::grid::grid_distances;
use crate::algo::ph::hermite::FreeParameters;
use crate::algo::ph::piecewise::convert;
use crate::curve::enclosure::{ErrorEnclosure, ErrorModels};
use crate::papers::{Outcome, Verdict};
use crate::scalar::{BigRational, Field, Float};
use rayon::prelude::*;
use rug::float::Round;
use std::collections::HashMap;

/// Samples per segment of the equally spaced members.
pub const FAMILY_SAMPLES: std::ops::RangeInclusive<usize> = 2..=200;
/// Rows screened in f64 (Table 1 indices 0…6: N = 1…64).
pub const SCREENED: usize = 7;

/// One member of the family of sampled maxima declared before computing (policy clause 6):
/// the maximum of ‖γ − p‖ over the grid it names, every point a double as numpy forms it.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug)]
pub enum Member {
    /// The authors' code: linspace(1e-6, 1, 100·N) (`phodcos.py`, `n_eval = 100`).
    Authors,
    /// k equally spaced samples per segment with the joints: linspace(0, 1, k·N + 1).
    Joints(usize),
    /// numpy's linspace(0, 1, k·N), the common tool.
    Numpy(usize),
}

impl Member {
    /// The whole family: the authors' grid, then A_k and B_k for k in [`FAMILY_SAMPLES`].
    pub fn family() -> Vec<Member> {
        let mut family = vec![Member::Authors];
        family.extend(FAMILY_SAMPLES.map(Member::Joints));
        family.extend(FAMILY_SAMPLES.map(Member::Numpy));
        family
    }

    /// The member's short name (A_k, B_k).
    pub fn short(self) -> String {
        match self {
            Member::Authors => "the authors' grid".into(),
            Member::Joints(k) => format!("A{k}"),
            Member::Numpy(k) => format!("B{k}"),
        }
    }

    /// The member's grid, written out.
    pub fn name(self) -> String {
        match self {
            Member::Authors => "the authors' linspace(1e-6, 1, 100·N)".into(),
            Member::Joints(k) => format!("A{k} = linspace(0, 1, {k}·N + 1)"),
            Member::Numpy(k) => format!("B{k} = numpy linspace(0, 1, {k}·N)"),
        }
    }

    /// (first point, last point, number of points) for N segments.
    fn layout(self, segments: usize) -> (f64, f64, usize) {
        match self {
            Member::Authors => (1e-6, 1.0, super::table1::PAPER_GRID_PER_SEGMENT * segments),
            Member::Joints(k) => (0.0, 1.0, k * segments + 1),
            Member::Numpy(k) => (0.0, 1.0, k * segments),
        }
    }

    /// Point j of the grid for N segments, as numpy's linspace forms it.
    fn point(self, segments: usize, j: usize) -> f64 {
        let (a, b, m) = self.layout(segments);
        a + (b - a) * j as f64 / (m - 1) as f64
    }

    /// The grid for N segments.
    pub fn points(self, segments: usize) -> Vec<f64> {
        let m = self.layout(segments).2;
        (0..m).map(|j| self.point(segments, j)).collect()
    }

    /// The grid point nearest t.
    fn nearest(self, segments: usize, t: f64) -> f64 {
        let (a, b, m) = self.layout(segments);
        let j = ((t - a) / (b - a) * (m - 1) as f64).round();
        self.point(segments, j.clamp(0.0, (m - 1) as f64) as usize)
    }
}

/// A definition's maximum at one row: a proven interval (lower, upper).
type Bounds = (Float, Float);

/// f64 maxima of every member on the screened rows: `[row][member]` = (maximum, the grid point
/// where it is attained).
pub struct Screen {
    pub family: Vec<Member>,
    maxima: Vec<Vec<(f64, f64)>>,
}

impl Screen {
    /// Every member's maximum on the f64 conversions of the rows N = 1…64.
    fn new() -> Result<Screen, String> {
        let c = curve().compile::<f64>(&());
        let free = FreeParameters::zero(4, &());
        let family = Member::family();
        let maxima =
            (0..SCREENED)
                .map(|i| {
                    let segments = TABLE1[i].0;
                    let pw = convert(&c, (&0.0, &1.0), segments, 4, &free, false)
                        .map_err(|e| format!("the f64 conversion into {segments} segments: {e}"))?;
                    Ok(family
                        .par_iter()
                        .map(|m| {
                            let ts = m.points(segments);
                            let d = grid_distances(&c, &pw, &ts);
                            d.iter().zip(&ts).fold((0.0, 0.0), |best, (&d, &t)| {
                                if d > best.0 {
                                    (d, t)
                                } else {
                                    best
                                }
                            })
                        })
                        .collect())
                })
                .collect::<Result<_, String>>()?;
        Ok(Screen { family, maxima })
    }

    /// Member `m`'s screened maximum at row `i` as a point interval.
    fn bounds(&self, i: usize, m: usize) -> Bounds {
        let x = Float::with_val(64, self.maxima[i][m].0);
        (x.clone(), x)
    }

    /// The units of each cell of row `i` under member `m` (error, then ratio where there is one);
    /// an error when a printed cell does not parse.
    fn cells(&self, i: usize, m: usize) -> Result<Vec<f64>, String> {
        let prev = (i > 0).then(|| self.bounds(i - 1, m));
        cell_units(i, prev.as_ref(), &self.bounds(i, m))
            .map(|u| u.into_iter().map(farthest).collect())
    }
}

/// The units of row `i`'s cells under one definition with maxima `prev` (row i − 1) and `this`:
/// the error cell, then the ratio cell where the row has one.
fn cell_units(i: usize, prev: Option<&Bounds>, this: &Bounds) -> Result<Vec<Units>, String> {
    let (_, p_err, p_ratio) = TABLE1[i];
    let unparsed = || format!("Table 1's printed cell {p_err} / {p_ratio} does not parse");
    let mut units = vec![units_range(p_err, &this.0, &this.1).ok_or_else(unparsed)?];
    if let (Some(prev), true) = (prev, i > 0) {
        let (lo, hi) = ratio_bounds(prev, this);
        units.push(units_range(p_ratio, &lo, &hi).ok_or_else(unparsed)?);
    }
    Ok(units)
}

/// [lower_{n−1}/upper_n, upper_{n−1}/lower_n], rounded outward.
pub fn ratio_bounds(coarse: &Bounds, fine: &Bounds) -> Bounds {
    let bits = coarse.0.prec().max(fine.0.prec());
    (
        Float::with_val_round(bits, &coarse.0 / &fine.1, Round::Down).0,
        Float::with_val_round(bits, &coarse.1 / &fine.0, Round::Up).0,
    )
}

/// How many cells of the screened rows each definition gives within ½ and within one unit.
struct Ranking {
    /// Members by cells within ½ unit (then within one unit), most first: (index, ½, 1).
    members: Vec<(usize, usize, usize)>,
    /// The true values' counts.
    truth: (usize, usize),
    cells: usize,
}

impl Ranking {
    fn new(screen: &Screen, truth: &[Bounds]) -> Result<Ranking, String> {
        let count = |units: &[f64]| {
            (
                units.iter().filter(|&&u| u <= 0.5).count(),
                units.iter().filter(|&&u| u <= 1.0).count(),
            )
        };
        let mut members: Vec<(usize, usize, usize)> = (0..screen.family.len())
            .map(|m| {
                let mut units = Vec::new();
                for i in 0..SCREENED {
                    units.extend(screen.cells(i, m)?);
                }
                let (half, one) = count(&units);
                Ok((m, half, one))
            })
            .collect::<Result<_, String>>()?;
        members.sort_by_key(|&(m, half, one)| (std::cmp::Reverse((half, one)), m));
        let mut truth_units = Vec::new();
        for i in 0..SCREENED {
            let prev = (i > 0).then(|| &truth[i - 1]);
            truth_units.extend(cell_units(i, prev, &truth[i])?.into_iter().map(farthest));
        }
        Ok(Ranking {
            members,
            truth: count(&truth_units),
            cells: truth_units.len(),
        })
    }

    fn best(&self) -> usize {
        self.members[0].0
    }

    /// The sentence naming the table's best member, the runner-up and the true values.
    fn sentence(&self, screen: &Screen) -> String {
        let name = |k: usize| screen.family[self.members[k].0].name();
        format!(
            "Over the {} cells of the rows N = 1…64 (f64 screen of {} members: the authors' linspace(1e-6, 1, 100·N), \
             A_k = linspace(0, 1, k·N + 1) and B_k = numpy linspace(0, 1, k·N) for k = 2…200, declared before computing), \
             {} gives the most cells, {} within ½ unit and {} within one; the runner-up, {}, {} and {}; the true maxima {} and {}.",
            self.cells,
            screen.family.len(),
            name(0),
            self.members[0].1,
            self.members[0].2,
            name(1),
            self.members[1].1,
            self.members[1].2,
            self.truth.0,
            self.truth.1
        )
    }
}

/// Ball conversions, their error models and proven member maxima, each computed once.
#[derive(Default)]
struct Balls {
    conversions: HashMap<(usize, Option<usize>), BallConversion>,
    models: HashMap<usize, ErrorModels>,
    maxima: HashMap<(Member, usize), Bounds>,
}

/// The relative width the error models are fine enough for.
const MODEL_TARGET: f64 = 1e-6;
/// How far (in t) an f64 grid point may lie from where a region test places it, with margin.
const T_SLACK: f64 = 1e-12;

impl Balls {
    fn conversion(
        &mut self,
        segments: usize,
        segment: Option<usize>,
    ) -> Result<&BallConversion, String> {
        use std::collections::hash_map::Entry;
        match self.conversions.entry((segments, segment)) {
            Entry::Occupied(e) => Ok(e.into_mut()),
            Entry::Vacant(e) => Ok(e.insert(match segment {
                None => BallConversion::new(segments)?,
                Some(k) => BallConversion::segment(segments, k)?,
            })),
        }
    }

    /// Member `m`'s maximum over its grid at screened row `i`, proven: L = the proven distance
    /// at the screen's maximizer is a lower bound; the error models prove ‖γ − p‖ < L outside
    /// some regions ([`ErrorModels::regions_reaching`]), so the maximum is attained at a grid
    /// point inside them, and those points are evaluated in balls.
    fn member_max(&mut self, screen: &Screen, m: usize, i: usize) -> Result<Bounds, String> {
        let member = screen.family[m];
        if let Some(b) = self.maxima.get(&(member, i)) {
            return Ok(b.clone());
        }
        if i >= SCREENED {
            return Err(format!(
                "{} is not screened at N = {}",
                member.name(),
                TABLE1[i].0
            ));
        }
        let segments = TABLE1[i].0;
        let seed = exact_points(&[screen.maxima[i][m].1])?;
        let lower = self.conversion(segments, None)?.distances(&seed);
        let lower = lower
            .first()
            .ok_or("no distance at the seed point")?
            .clone();
        if !self.models.contains_key(&i) {
            let models = self.conversion(segments, None)?.models(MODEL_TARGET);
            self.models.insert(i, models);
        }
        let threshold = lower.lower().to_f64_round(Round::Down);
        let regions = self.models[&i].regions_reaching(threshold, 1.0 / 32.0);
        let (a, b, count) = member.layout(segments);
        let index = |t: f64| (t - a) / (b - a) * (count - 1) as f64;
        let mut candidates: Vec<usize> = Vec::new();
        for r in &regions {
            let t_lo = (r.segment as f64 + r.lo) / segments as f64 - T_SLACK;
            let t_hi = (r.segment as f64 + r.hi) / segments as f64 + T_SLACK;
            let first = index(t_lo).floor().max(0.0) as usize;
            let last = (index(t_hi).ceil() as usize).min(count - 1);
            candidates.extend((first..=last).filter(|&j| {
                let t = member.point(segments, j);
                t_lo <= t && t <= t_hi
            }));
        }
        candidates.sort_unstable();
        candidates.dedup();
        let points: Vec<f64> = candidates
            .iter()
            .map(|&j| member.point(segments, j))
            .collect();
        let max = self
            .conversion(segments, None)?
            .distances(&exact_points(&points)?)
            .into_iter()
            .fold(lower, |m, d| m.max_with(&d));
        let bounds = (max.lower(), max.upper());
        self.maxima.insert((member, i), bounds.clone());
        Ok(bounds)
    }

    /// The proven distance at the point t of row `i`'s conversion: a lower bound of the
    /// maximum of any grid containing t.
    fn distance_at(&mut self, i: usize, t: f64) -> Result<Float, String> {
        let segments = TABLE1[i].0;
        let k = ((t * segments as f64).floor() as usize).min(segments - 1);
        let exact = exact_points(&[t])?;
        // The screened rows' conversions are cheap and kept whole; beyond them, one segment.
        let part = (i >= SCREENED).then_some(k);
        let d = self.conversion(segments, part)?.distances(&exact);
        d.first()
            .map(|d| d.lower())
            .ok_or_else(|| format!("no distance at t = {t} with {segments} segments"))
    }
}

/// f64 grid points as exact rationals.
fn exact_points(ts: &[f64]) -> Result<Vec<BigRational>, String> {
    ts.iter()
        .map(|&t| {
            BigRational::from_float(t).ok_or_else(|| format!("a grid point {t} is not finite"))
        })
        .collect()
}

/// Everything a row's verdict is decided on.
struct Context<'a> {
    truth: &'a [Bounds],
    /// The true maximum's location at each row (global t, to pick the points of lower bounds).
    argmax: Vec<f64>,
    screen: &'a Screen,
    ranking: &'a Ranking,
}

/// The verdict of every printed row, each an outcome with its evidence; `rows` gives the
/// certified values shown, `enclosures` the proven ones decided on.
pub fn judge(
    rows: &[Row],
    enclosures: &[Option<&ErrorEnclosure>],
) -> (Vec<Outcome>, Result<BestMember, String>) {
    let scalar = format!("ball:{}", super::proven::BITS);
    let missing = enclosures.iter().position(Option::is_none);
    let prepared = match missing {
        Some(k) => Err(format!(
            "no proven enclosure of the error with {} segments (the conversion in balls failed)",
            TABLE1[k].0
        )),
        None => Screen::new().and_then(|screen| {
            let truth: Vec<Bounds> = enclosures
                .iter()
                .flatten()
                .map(|e| (e.lower.clone(), e.upper.clone()))
                .collect();
            let ranking = Ranking::new(&screen, &truth)?;
            Ok((screen, truth, ranking))
        }),
    };
    let (screen, truth, ranking) = match prepared {
        Ok(p) => p,
        Err(e) => {
            let failed = rows
                .iter()
                .map(|_| Outcome::failed(scalar.clone(), e.clone()));
            return (failed.collect(), Err(e));
        }
    };
    let argmax = rows
        .iter()
        .map(|r| (r.error.segment as f64 + r.error.xi.to_f64()) / r.segments as f64)
        .collect();
    let context = Context {
        truth: &truth,
        argmax,
        screen: &screen,
        ranking: &ranking,
    };
    let mut balls = Balls::default();
    let outcomes = (0..rows.len())
        .map(|i| {
            judge_row(i, &context, &mut balls)
                .map(|(verdict, evidence)| row_outcome(i, &rows[i], verdict, evidence))
                .unwrap_or_else(|e| Outcome::failed(scalar.clone(), e))
        })
        .collect();
    let best = ranking.best();
    let summary = (|| {
        Ok(BestMember {
            name: screen.family[best].name(),
            maxima: (0..SCREENED.min(rows.len()))
                .map(|r| balls.member_max(&screen, best, r))
                .collect::<Result<_, String>>()?,
            members_giving: (0..SCREENED)
                .map(|i| row_counts(i, &context))
                .collect::<Result<_, String>>()?,
        })
    })();
    (outcomes, summary)
}

/// What the report shows of the forensics: the table's best member, its proven maxima at the
/// screened rows, and per screened row how many members give every cell within ½ and within
/// one unit (f64 screen).
pub struct BestMember {
    pub name: String,
    pub maxima: Vec<(Float, Float)>,
    pub members_giving: Vec<(usize, usize)>,
}

/// Row `i`'s verdict and evidence by the rule of the module doc.
fn judge_row(i: usize, cx: &Context, balls: &mut Balls) -> Result<(Verdict, String), String> {
    let prev = (i > 0).then(|| &cx.truth[i - 1]);
    let truth_units = cell_units(i, prev, &cx.truth[i])?;
    let mut evidence = truth_sentence(i, cx, &truth_units);
    let worst = truth_units
        .iter()
        .copied()
        .map(farthest)
        .fold(0.0, f64::max);
    if worst <= 1.0 {
        return Ok((Verdict::by_printed_units(worst), evidence));
    }
    evidence.push(' ');
    evidence.push_str(&cx.ranking.sentence(cx.screen));
    if i < SCREENED {
        let (half, one) = row_counts(i, cx)?;
        evidence.push_str(&format!(
            " In the screen, {half} of {} members give every cell of this row within ½ unit and {one} within one.",
            cx.screen.family.len()
        ));
    }
    if let Some((m, units)) = matching_member(i, cx, balls)? {
        evidence.push_str(&format!(
            " Metric: {} gives every cell of the row within one unit, proven in balls (its whole grid, each point taken \
             exactly): {}.",
            m.name(),
            units.iter().map(|&u| units_text(u)).collect::<Vec<_>>().join(", ")
        ));
        return Ok((Verdict::Metric, evidence));
    }
    evidence.push_str(" No member of the family gives every cell of the row within one unit (each proven off in one cell).");
    match typo_reading(i, cx, balls)? {
        Typo::Holds(text) => {
            evidence.push(' ');
            evidence.push_str(&text);
            return Ok((Verdict::Typo, evidence));
        }
        Typo::Fails(notes) => {
            for note in notes {
                evidence.push(' ');
                evidence.push_str(&note);
            }
        }
    }
    evidence.push_str(
        " No reading changes one symbol of one cell so that the true values or the table's best member give every cell the \
         row prints and every later cell computed from it.",
    );
    Ok((Verdict::Discrepancy, evidence))
}

/// The true values' cells of row `i`, with the table's ranking.
fn truth_sentence(i: usize, cx: &Context, units: &[Units]) -> String {
    let (_, p_err, p_ratio) = TABLE1[i];
    let e = &cx.truth[i];
    let mut s = format!(
        "Decided on proven numbers (rule: the module doc of src/papers/ph/forensics.rs and the policy's table clause). \
         True maximum over ξ of ‖γ − p‖: proven {} by branch and bound in balls (`phodcos.table1.proven`), {} of the printed {p_err}",
        interval(&e.0, &e.1),
        units_text(units[0])
    );
    if let (Some(r), true) = (units.get(1), i > 0) {
        let (lo, hi) = ratio_bounds(&cx.truth[i - 1], e);
        s.push_str(&format!(
            "; true ratio E_{}/E_{} proven {}, {} of the printed {p_ratio}",
            TABLE1[i - 1].0,
            TABLE1[i].0,
            interval(&lo, &hi),
            units_text(*r)
        ));
    }
    s.push('.');
    s
}

/// How many members the screen finds giving every cell of row `i` within ½ and within one unit.
fn row_counts(i: usize, cx: &Context) -> Result<(usize, usize), String> {
    let all: Vec<f64> = (0..cx.screen.family.len())
        .map(|m| Ok(cx.screen.cells(i, m)?.into_iter().fold(0.0, f64::max)))
        .collect::<Result<_, String>>()?;
    Ok((
        all.iter().filter(|&&u| u <= 0.5).count(),
        all.iter().filter(|&&u| u <= 1.0).count(),
    ))
}

/// The first member, in the table's ranking, that gives every cell of row `i` within one unit,
/// proven; `None` when every member is proven off in some cell. On a screened row each
/// member's maxima are proven ([`Balls::member_max`]); beyond the screen only a lower bound is
/// (its distance at the grid point nearest the true maximizer), with the true maximum above
/// it, and a row it does not decide is an error.
fn matching_member(
    i: usize,
    cx: &Context,
    balls: &mut Balls,
) -> Result<Option<(Member, Vec<Units>)>, String> {
    for &(m, _, _) in &cx.ranking.members {
        let member = cx.screen.family[m];
        // First the rough bounds: the distance at one grid point below, the true maximum
        // above; most members are off by them alone.
        let mut rough = Vec::new();
        for (r, (segments, _, _)) in TABLE1
            .iter()
            .enumerate()
            .take(i + 1)
            .skip(i.saturating_sub(1))
        {
            let t = match r < SCREENED {
                true => cx.screen.maxima[r][m].1,
                false => member.nearest(*segments, cx.argmax[r]),
            };
            rough.push((balls.distance_at(r, t)?, cx.truth[r].1.clone()));
        }
        let prev = (i > 0).then(|| &rough[0]);
        let units = cell_units(i, prev, &rough[rough.len() - 1])?;
        if units.iter().any(|&(lo, hi)| lo > 1.0 || hi < -1.0) {
            continue;
        }
        let mut bounds = rough;
        for (slot, r) in (i.saturating_sub(1)..=i).enumerate() {
            if r < SCREENED {
                bounds[slot] = balls.member_max(cx.screen, m, r)?;
            }
        }
        let prev = (i > 0).then(|| &bounds[0]);
        let units = cell_units(i, prev, &bounds[bounds.len() - 1])?;
        if units.iter().any(|&(lo, hi)| lo > 1.0 || hi < -1.0) {
            continue;
        }
        if units.iter().all(|&u| farthest(u) <= 1.0) {
            return Ok(Some((member, units)));
        }
        return Err(format!(
            "{} at N = {}: its proven maximum does not decide whether a cell is within one unit",
            member.name(),
            TABLE1[i].0
        ));
    }
    Ok(None)
}

/// Step 3's answer: the reading that holds, or why each one-symbol reading found fails.
enum Typo {
    Holds(String),
    Fails(Vec<String>),
}

/// The typo reading of row `i` (step 3), under the true values, then under the table's best
/// member where it is screened at this row and the next.
fn typo_reading(i: usize, cx: &Context, balls: &mut Balls) -> Result<Typo, String> {
    let mut definitions: Vec<(String, Vec<Option<Bounds>>)> = vec![(
        "the true maxima".into(),
        cx.truth.iter().cloned().map(Some).collect(),
    )];
    if i + 1 < SCREENED {
        let best = cx.ranking.best();
        let mut values = vec![None; cx.truth.len()];
        for (r, slot) in values
            .iter_mut()
            .enumerate()
            .take(i + 2)
            .skip(i.saturating_sub(1))
        {
            *slot = Some(balls.member_max(cx.screen, best, r)?);
        }
        definitions.push((cx.screen.family[best].short(), values));
    }
    let mut notes = Vec::new();
    for (name, values) in definitions {
        match typo_under(i, &name, &values)? {
            Some(Ok(text)) => return Ok(Typo::Holds(text)),
            Some(Err(note)) => notes.push(note),
            None => {}
        }
    }
    Ok(Typo::Fails(notes))
}

/// Step 3 under one definition (`values[r]` its proven maximum at row r where computed):
/// `None` when it does not leave exactly one cell off by one symbol, else whether the next
/// row's ratio agrees (`Ok`, the evidence) or not (`Err`, why not).
fn typo_under(
    i: usize,
    name: &str,
    values: &[Option<Bounds>],
) -> Result<Option<Result<String, String>>, String> {
    let Some(this) = &values[i] else {
        return Ok(None);
    };
    let prev = if i > 0 { values[i - 1].as_ref() } else { None };
    if i > 0 && prev.is_none() {
        return Ok(None);
    }
    let units = cell_units(i, prev, this)?;
    let off: Vec<usize> = (0..units.len())
        .filter(|&c| farthest(units[c]) > 1.0)
        .collect();
    let [cell] = off[..] else {
        return Ok(None);
    };
    let (_, p_err, p_ratio) = TABLE1[i];
    let (printed, value) = match cell {
        0 => (p_err, this.clone()),
        _ => (
            p_ratio,
            prev.map(|p| ratio_bounds(p, this))
                .ok_or("no previous row")?,
        ),
    };
    let (Some(lo), Some(hi)) = (print_like(printed, &value.0), print_like(printed, &value.1))
    else {
        return Ok(None);
    };
    let which = if cell == 0 { "error" } else { "ratio" };
    if lo != hi {
        return Ok(Some(Err(format!(
            "Not a typo: under {name}, only the {which} cell is off, but its value does not print to one string at the cell's digits ({lo} to {hi})."
        ))));
    }
    if !one_symbol_not_last(printed, &lo) {
        return Ok(Some(Err(format!(
            "Not a typo: under {name}, only the {which} cell is off, and {name}'s value printed to the same digits, {lo}, differs from \
             the print {}.",
            match differing(printed, &lo) {
                Some(1) => "in its last digit only (a numerical difference, judged by clauses 4 and 6)",
                _ => "in more than one symbol",
            }
        ))));
    }
    let reading = format!(
        "under {name}, only the {which} cell is off, and it differs in one symbol (not its last digit) from {name}'s value \
         printed to the same digits, {lo}"
    );
    // The next row's ratio is computed from the same error cell.
    let mut next = String::new();
    if cell == 0 && i + 1 < values.len() {
        let Some(after) = &values[i + 1] else {
            return Ok(None);
        };
        let u = cell_units(i + 1, Some(this), after)?;
        let ratio = TABLE1[i + 1].2;
        match u.get(1) {
            Some(&r) if farthest(r) <= 1.0 => {
                next = format!(
                    "; the next row's ratio {ratio}, computed from the same error, agrees ({})",
                    units_text(r)
                )
            }
            Some(&r) => {
                return Ok(Some(Err(format!(
                    "Not a typo: {reading}, but the next row's ratio {ratio}, computed from the same error, is {} off.",
                    units_text(r)
                ))))
            }
            None => return Ok(None),
        }
    }
    Ok(Some(Ok(format!("Typo: {reading}{next}."))))
}

/// A value printed to the digits of the printed cell `printed`: as many decimals, and as many
/// integer digits before an exponent where the cell has one (`None` for a value ≤ 0).
pub fn print_like(printed: &str, value: &Float) -> Option<String> {
    let q = Field::to_rational(value)?;
    if q <= BigRational::from_integer(0.into()) {
        return None;
    }
    let (mantissa, has_exponent) = match printed.split_once(['e', 'E']) {
        Some((m, _)) => (m, true),
        None => (printed, false),
    };
    let (int_part, decimals) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let decimals = decimals.len();
    let ten = BigRational::from_integer(10.into());
    let pow = |e: i64| {
        let p = num_traits::pow(ten.clone(), e.unsigned_abs() as usize);
        if e < 0 {
            BigRational::from_integer(1.into()) / p
        } else {
            p
        }
    };
    let mut exponent = 0i64;
    if has_exponent {
        // The exponent giving the mantissa as many integer digits as the cell's.
        let digits = int_part.len() as i64;
        let mut e = value.to_f64().log10().floor() as i64 - (digits - 1);
        while q.clone() / pow(e) >= pow(digits) {
            e += 1;
        }
        while q.clone() / pow(e) < pow(digits - 1) {
            e -= 1;
        }
        exponent = e;
    }
    let scaled = q / pow(exponent) * pow(decimals as i64);
    let rounded = (scaled + BigRational::new(1.into(), 2.into()))
        .floor()
        .to_integer();
    let text = rounded.to_string();
    let text = format!("{:0>width$}", text, width = decimals + 1);
    let (whole, frac) = text.split_at(text.len() - decimals);
    let body = if decimals == 0 {
        whole.to_string()
    } else {
        format!("{whole}.{frac}")
    };
    Some(if has_exponent {
        format!("{body}e{exponent}")
    } else {
        body
    })
}

/// The positions where `a` and `b` differ (`None` for different lengths).
fn differences(a: &str, b: &str) -> Option<Vec<usize>> {
    (a.len() == b.len()).then(|| {
        a.bytes()
            .zip(b.bytes())
            .enumerate()
            .filter(|(_, (x, y))| x != y)
            .map(|(k, _)| k)
            .collect()
    })
}

/// How many characters `a` and `b` differ in (`None` for different lengths).
fn differing(a: &str, b: &str) -> Option<usize> {
    differences(a, b).map(|d| d.len())
}

/// Whether `a` and `b` differ in exactly one character, and that character is not the
/// mantissa's last digit.
fn one_symbol_not_last(a: &str, b: &str) -> bool {
    let last = a.find(['e', 'E']).unwrap_or(a.len()).saturating_sub(1);
    differences(a, b).is_some_and(|d| d.len() == 1 && d[0] != last)
}

/// Row `i`'s outcome: the certified values shown, the verdict and its finding.
fn row_outcome(i: usize, row: &Row, verdict: Verdict, evidence: String) -> Outcome {
    let (_, p_err, p_ratio) = TABLE1[i];
    let cert = row.error.certified();
    let reproduced = match &row.ratio_certified() {
        Some(r) => format!("error {}, ratio {}", cert.text, r.text),
        None => format!("error {}", cert.text),
    };
    let outcome = Outcome::new(
        reproduced.clone(),
        format!(
            "ball:{} (mpfr:{}/{} shown)",
            super::proven::BITS,
            super::table1::BITS,
            super::table1::HI_BITS
        ),
        verdict,
        evidence,
    );
    let paper = match p_ratio {
        "-" => format!("error {p_err}"),
        r => format!("error {p_err}, ratio {r}"),
    };
    let minor = crate::ledger::Severity::Minor;
    let finding = |difference: &str, reason: &str| {
        Outcome::new(
            reproduced.clone(),
            outcome.scalar.clone(),
            verdict,
            outcome.evidence.clone(),
        )
        .finding((&paper, &reproduced, difference), minor, reason)
    };
    match verdict {
        Verdict::Reproduced | Verdict::Failed => outcome,
        Verdict::Metric => finding(
            "the printed cells are maxima over a grid of the declared family, not the true maxima",
            "the order of Theorem 1 rests on the finer rows, which agree",
        ),
        Verdict::ReproducedRounding => finding(
            "a printed cell differs from the true value by one unit of its last digit",
            "a rounding of the last digit",
        ),
        Verdict::Typo => finding(
            "one symbol of one cell differs from the value every other cell agrees with",
            "a garbled symbol; the ratio column and the order are right",
        ),
        _ => finding(
            "neither the true maxima nor any grid of the declared family gives the printed cells, and no one-symbol reading does",
            "coarse rows, before the asymptotic range; Theorem 1's order rests on the finer rows, which agree",
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn prints_like_the_cell() {
        let f = |x: f64| Float::with_val(128, x);
        assert_eq!(
            print_like("1.186e-23", &f(1.185715e-21)).as_deref(),
            Some("1.186e-21")
        );
        assert_eq!(
            print_like("24.455e-6", &f(2.5454735e-5)).as_deref(),
            Some("25.455e-6")
        );
        assert_eq!(
            print_like("16.080e-4", &f(1.608048e-3)).as_deref(),
            Some("16.080e-4")
        );
        assert_eq!(
            print_like("0.0332", &f(0.03324539)).as_deref(),
            Some("0.0332")
        );
        assert_eq!(
            print_like("134.145", &f(134.149)).as_deref(),
            Some("134.149")
        );
    }

    #[test]
    fn one_symbol_excludes_the_last_digit() {
        assert!(one_symbol_not_last("1.186e-23", "1.186e-21"));
        assert!(one_symbol_not_last("24.455e-6", "25.455e-6"));
        assert!(!one_symbol_not_last("134.145", "134.149"));
        assert!(!one_symbol_not_last("24.455e-6", "25.477e-6"));
    }

    /// A segment converted alone is the same polynomial as in the whole conversion.
    #[test]
    fn a_segment_alone_is_the_same() {
        let (Ok(whole), Ok(alone)) = (BallConversion::new(4), BallConversion::segment(4, 2)) else {
            panic!("the conversions in balls failed");
        };
        let t = [BigRational::new(5.into(), 8.into())];
        let (a, b) = (&whole.distances(&t)[0], &alone.distances(&t)[0]);
        assert!(a.lower() <= b.upper() && b.lower() <= a.upper());
        assert!(a.upper() > 0);
    }
}
