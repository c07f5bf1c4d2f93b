//! Dubins shortest paths between poses (Dubins 1957), the baseline of Fig. 7.
//!
//! In coordinates scaled by the turn radius R and rotated so the goal lies on the x axis at
//! distance d, with start and goal headings a, b, each of the six words LSL, RSR, LSR, RSL,
//! RLR, LRL has closed-form segment lengths (t, p, q) (Shkel & Lumelsky 2001, Table 1); the
//! shortest feasible one is the Dubins path. Lengths are returned in the original units. The
//! curvature is ±1/R on arcs and 0 on the straight: it jumps at every arc–line junction.

use super::path::tangents;
use super::GerbsError;
use crate::scalar::Real;

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

/// One Dubins word and its three segment lengths.
#[derive(Clone, Debug)]
pub struct DubinsPath<T> {
    /// The start pose (x, y, heading).
    pub start: [T; 3],
    /// The turning radius R.
    pub radius: T,
    /// The three steps of the word (e.g. L S R).
    pub word: [Step; 3],
    /// Segment lengths in path units (angle × R for arcs).
    pub lengths: [T; 3],
}

/// x reduced to [0, 2π). The multiple of 2π is found in f64 and the remainder corrected by
/// at most a few steps of 2π, so the reduction is exact in intent only for |x| well inside
/// the working precision (callers keep angles within ±1e6 rad); a non-finite x is returned
/// as it is, and the correction loop is bounded so no input can make it spin.
fn mod2pi<T: Real>(x: T) -> T {
    if !x.is_finite() {
        return x;
    }
    let two_pi = T::pi(&x.ctx()) * &T::from_i64(2, &x.ctx());
    let k = (x.to_f64() / two_pi.to_f64()).floor();
    if !k.is_finite() {
        return x;
    }
    let mut r = x - &(two_pi.clone() * &T::from_f64(k, &two_pi.ctx()));
    let zero = T::zero_in(&r.ctx());
    for _ in 0..64 {
        if r < zero {
            r += &two_pi;
        } else if r >= two_pi {
            r -= &two_pi;
        } else {
            break;
        }
    }
    r
}

/// The headings Algorithm 1 gives the waypoints: atan2 of its tangent directions m_i.
pub fn algorithm1_headings<T: Real>(w: &[[T; 2]]) -> Result<Vec<T>, GerbsError> {
    Ok(tangents(w)?.m.iter().map(|m| m[1].atan2(&m[0])).collect())
}

/// The shortest Dubins path of radius `radius` from each pose (W_i, heading_i) to the next;
/// `Err(i)` when no word joins pose i to pose i + 1 (0-based).
pub fn through_poses<T: Real>(
    w: &[[T; 2]],
    headings: &[T],
    radius: &T,
) -> Result<Vec<DubinsPath<T>>, usize> {
    let pose = |i: usize| [w[i][0].clone(), w[i][1].clone(), headings[i].clone()];
    (0..w.len().saturating_sub(1))
        .map(|i| shortest(&pose(i), &pose(i + 1), radius).ok_or(i))
        .collect()
}

/// The summed length of consecutive legs.
pub fn total_length<T: Real>(legs: &[DubinsPath<T>], ctx: &T::Ctx) -> T {
    let mut total = T::zero_in(ctx);
    for leg in legs {
        total += &leg.total();
    }
    total
}

/// The shortest of the six words from pose `start` = (x, y, heading) to `goal`.
pub fn shortest<T: Real>(start: &[T; 3], goal: &[T; 3], radius: &T) -> Option<DubinsPath<T>> {
    all_words(start, goal, radius).into_iter().min_by(|p, q| {
        p.total()
            .partial_cmp(&q.total())
            .unwrap_or(std::cmp::Ordering::Equal)
    })
}

/// Every feasible word (up to six).
pub fn all_words<T: Real>(start: &[T; 3], goal: &[T; 3], radius: &T) -> Vec<DubinsPath<T>> {
    use Step::{L, R, S};
    let ctx = radius.ctx();
    let c = |v: i64| T::from_i64(v, &ctx);
    let dx = goal[0].clone() - &start[0];
    let dy = goal[1].clone() - &start[1];
    let d = (dx.clone() * &dx + &(dy.clone() * &dy)).sqrt() / radius;
    let theta = mod2pi(dy.atan2(&dx));
    let a = mod2pi(start[2].clone() - &theta);
    let b = mod2pi(goal[2].clone() - &theta);
    let (sa, ca) = a.sin_cos();
    let (sb, cb) = b.sin_cos();
    let cab = (a.clone() - &b).sin_cos().1;
    let d2 = d.clone() * &d;
    let zero = c(0);
    let acos = |x: T| (c(1) - &(x.clone() * &x)).sqrt().atan2(&x);
    let mut out: Vec<([Step; 3], [T; 3])> = Vec::new();
    // LSL
    let p2 = c(2) + &d2 - &(c(2) * &cab) + &(c(2) * &d * &(sa.clone() - &sb));
    if p2 >= zero {
        let t1 = (cb.clone() - &ca).atan2(&(d.clone() + &sa - &sb));
        out.push((
            [L, S, L],
            [mod2pi(t1.clone() - &a), p2.sqrt(), mod2pi(b.clone() - &t1)],
        ));
    }
    // RSR
    let p2 = c(2) + &d2 - &(c(2) * &cab) + &(c(2) * &d * &(sb.clone() - &sa));
    if p2 >= zero {
        let t1 = (ca.clone() - &cb).atan2(&(d.clone() - &sa + &sb));
        out.push((
            [R, S, R],
            [mod2pi(a.clone() - &t1), p2.sqrt(), mod2pi(t1 - &b)],
        ));
    }
    // LSR
    let p2 = c(-2) + &d2 + &(c(2) * &cab) + &(c(2) * &d * &(sa.clone() + &sb));
    if p2 >= zero {
        let p = p2.sqrt();
        let t2 = (-ca.clone() - &cb).atan2(&(d.clone() + &sa + &sb)) - &c(-2).atan2(&p);
        out.push(([L, S, R], [mod2pi(t2.clone() - &a), p, mod2pi(t2 - &b)]));
    }
    // RSL
    let p2 = c(-2) + &d2 + &(c(2) * &cab) - &(c(2) * &d * &(sa.clone() + &sb));
    if p2 >= zero {
        let p = p2.sqrt();
        let t2 = (ca.clone() + &cb).atan2(&(d.clone() - &sa - &sb)) - &c(2).atan2(&p);
        out.push((
            [R, S, L],
            [mod2pi(a.clone() - &t2), p, mod2pi(b.clone() - &t2)],
        ));
    }
    let two_pi = T::pi(&ctx) * &c(2);
    // RLR
    let x = (c(6) - &d2 + &(c(2) * &cab) + &(c(2) * &d * &(sa.clone() - &sb))) / &c(8);
    if x.clone().abs() <= c(1) {
        let phi = (ca.clone() - &cb).atan2(&(d.clone() - &sa + &sb));
        let p = mod2pi(two_pi.clone() - &acos(x));
        let t = mod2pi(a.clone() - &phi + &mod2pi(p.clone() / &c(2)));
        let q = mod2pi(a.clone() - &b - &t + &p);
        out.push(([R, L, R], [t, p, q]));
    }
    // LRL
    let x = (c(6) - &d2 + &(c(2) * &cab) + &(c(2) * &d * &(sb.clone() - &sa))) / &c(8);
    if x.clone().abs() <= c(1) {
        let phi = (ca.clone() - &cb).atan2(&(d.clone() + &sa - &sb));
        let p = mod2pi(two_pi - &acos(x));
        let t = mod2pi(-a.clone() - &phi + &(p.clone() / &c(2)));
        let q = mod2pi(b.clone() - &a - &t + &p);
        out.push(([L, R, L], [t, p, q]));
    }
    out.into_iter()
        .map(|(word, l)| DubinsPath {
            start: start.clone(),
            radius: radius.clone(),
            word,
            lengths: l.map(|x| x * radius),
        })
        .collect()
}

impl<T: Real> DubinsPath<T> {
    /// The total length of the three steps.
    pub fn total(&self) -> T {
        self.lengths[0].clone() + &self.lengths[1] + &self.lengths[2]
    }

    /// The word as letters, e.g. "LSR".
    pub fn word_name(&self) -> String {
        self.word
            .iter()
            .map(|s| match s {
                Step::L => 'L',
                Step::S => 'S',
                Step::R => 'R',
            })
            .collect()
    }

    /// The pose (x, y, heading) after arc length `s` from the start.
    pub fn pose_at(&self, s: &T) -> [T; 3] {
        let mut pose = self.start.clone();
        let mut left = s.clone();
        for (step, len) in self.word.iter().zip(&self.lengths) {
            let zero = T::zero_in(&s.ctx());
            let run = if left < *len {
                left.clone()
            } else {
                len.clone()
            };
            if run <= zero {
                break;
            }
            pose = advance(&pose, *step, &run, &self.radius);
            left -= &run;
        }
        pose
    }

    /// The signed curvature on each segment (1/R on L, −1/R on R, 0 on S).
    /// `count` ≥ 2 poses at equal arc-length steps from the start to the end of the path.
    pub fn samples(&self, count: usize) -> Vec<[T; 3]> {
        let ctx = self.radius.ctx();
        let last = count.max(2) as i64 - 1;
        let length = self.total();
        (0..=last)
            .map(|k| self.pose_at(&(length.clone() * &T::from_ratio(k, last, &ctx))))
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_word_reaches_the_goal_pose() {
        let poses = [
            ([0.0, 0.0, 0.3], [300.0, 100.0, -1.2]),
            ([0.0, 0.0, 0.0], [50.0, 10.0, 3.0]),
            ([10.0, -5.0, 2.0], [-40.0, 60.0, -2.5]),
            ([0.0, 0.0, 0.0], [0.0, 30.0, 3.1]),
        ];
        for (s, g) in poses {
            let words = all_words(&s, &g, &80.0);
            assert!(!words.is_empty());
            for w in &words {
                let end = w.pose_at(&w.total());
                let dh = mod2pi(end[2] - g[2] + 1.0) - 1.0;
                assert!(
                    (end[0] - g[0]).abs() < 1e-9 && (end[1] - g[1]).abs() < 1e-9 && dh.abs() < 1e-9,
                    "{} misses {g:?}: {end:?}",
                    w.word_name()
                );
            }
        }
    }
}
