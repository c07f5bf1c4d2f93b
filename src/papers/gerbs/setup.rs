//! The documented inputs of the paper-003 checks: waypoints, radius, θ_o, basis parameters.
//!
//! The paper gives R = 80 and θ_o = π/8 (Sec. IV) and the knot vector of Fig. 1
//! ({0, 0, 1/4, 2/4, 3/4, 1, 1}, five waypoints) but not the waypoints; ours have two right
//! turns and one left turn, so both arc orientations are exercised.

use crate::algo::gerbs::bfbs::Bfbs;
use crate::algo::gerbs::erbs::{CentreReading, Erbs, ErbsParams};
use crate::algo::gerbs::path::{ArcConvention, GerbsPath, PathSpec};
use crate::algo::gerbs::proven_erbs::ProvenErbs;
use crate::algo::gerbs::Knots;
use crate::curve::integral::IntegralOptions;
use crate::scalar::ball::Ball;
use crate::scalar::{Field, Real};

/// Five waypoints (turns at W2: right, W3: left, W4: right).
pub const WAYPOINTS: [[i64; 2]; 5] = [[0, 0], [300, 100], [600, -50], [900, 150], [1200, 0]];
pub const RADIUS: i64 = 80;
/// Working precisions: results at LO bits certified against HI bits.
pub const LO: u32 = 128;
pub const HI: u32 = 256;

/// The ERBS parameter sets the report uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ErbsSet {
    /// The Fig. 2 caption literally: α = 0, β = 3, γ = 1, σ = 0.2, λ = 0.5.
    Fig2Literal,
    /// The caption with α = 1 (the smallest integer in Eq. 4's range α > 0).
    Fig2Alpha1,
    /// α = 1, β = 3, γ = 1, λ = 0.5, σ = 1: Ψ is C^∞ inside the interval too. Used for the
    /// ERBS paths of Figs. 3–7.
    Smooth,
}

impl ErbsSet {
    pub fn params<T: Real>(self, ctx: &T::Ctx) -> ErbsParams<T> {
        let r = |n: i64, d: i64| T::from_ratio(n, d, ctx);
        let (alpha, sigma) = match self {
            ErbsSet::Fig2Literal => (r(0, 1), r(1, 5)),
            ErbsSet::Fig2Alpha1 => (r(1, 1), r(1, 5)),
            ErbsSet::Smooth => (r(1, 1), r(1, 1)),
        };
        ErbsParams::unchecked(alpha, r(3, 1), r(1, 1), r(1, 2), sigma)
    }

    pub fn label(self) -> &'static str {
        match self {
            ErbsSet::Fig2Literal => "Fig. 2 literal (α = 0, σ = 0.2)",
            ErbsSet::Fig2Alpha1 => "α = 1, σ = 0.2",
            ErbsSet::Smooth => "α = 1, σ = 1",
        }
    }
}

pub fn waypoints<T: Real>(ctx: &T::Ctx) -> Vec<[T; 2]> {
    WAYPOINTS
        .iter()
        .map(|w| [T::from_i64(w[0], ctx), T::from_i64(w[1], ctx)])
        .collect()
}

pub fn spec<T: Real>(ctx: &T::Ctx, convention: ArcConvention) -> PathSpec<T> {
    PathSpec {
        waypoints: waypoints(ctx),
        radius: T::from_i64(RADIUS, ctx),
        theta_o: T::pi(ctx) / &T::from_i64(8, ctx),
        line_length: None,
        convention,
        turns: None,
        end_curves: Default::default(),
    }
}

pub fn fig1_knots<T: Field>(ctx: &T::Ctx) -> Knots<T> {
    Knots::uniform(5, ctx).expect("the knot vector of Fig. 1 is valid")
}

pub fn erbs<T: Real>(ctx: &T::Ctx, set: ErbsSet, reading: CentreReading) -> Erbs<T> {
    Erbs::new(&fig1_knots(ctx), vec![set.params(ctx)], reading).expect("one parameter set")
}

pub fn bfbs_path<T: Real>(ctx: &T::Ctx, convention: ArcConvention) -> GerbsPath<T, Bfbs> {
    GerbsPath::new(
        &spec(ctx, convention),
        Bfbs::uniform(2, WAYPOINTS.len()).expect("exponents"),
    )
    .expect("documented waypoints are valid")
}

pub fn erbs_path<T: Real>(
    ctx: &T::Ctx,
    set: ErbsSet,
    convention: ArcConvention,
) -> GerbsPath<T, Erbs<T>> {
    GerbsPath::new(&spec(ctx, convention), erbs(ctx, set, CentreReading::Cited))
        .expect("documented waypoints are valid")
}

/// The ERBS basis in balls at `bits` with its integrals proven ([`ProvenErbs`]): Taylor models
/// of order bits/6 (clamped to 12…40), as `run gerbs-path --scalar ball:…` builds it.
///
/// # Errors
/// The basis error, as text.
/// Each basis is built once per run and shared by the checks that need it (its proven
/// integrals are the costly part).
pub fn proven_erbs(bits: u32, set: ErbsSet) -> Result<ProvenErbs, String> {
    type Cache =
        std::sync::Mutex<std::collections::HashMap<(u32, ErbsSet), Result<ProvenErbs, String>>>;
    static CACHE: std::sync::OnceLock<Cache> = std::sync::OnceLock::new();
    let cache = CACHE.get_or_init(Default::default);
    // A poisoned lock only means another check panicked; the entries stay valid.
    let mut entries = cache
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    entries
        .entry((bits, set))
        .or_insert_with(|| build_proven_erbs(bits, set))
        .clone()
}

fn build_proven_erbs(bits: u32, set: ErbsSet) -> Result<ProvenErbs, String> {
    let options = IntegralOptions {
        order: (bits as usize / 6).clamp(12, 40),
        ..IntegralOptions::default()
    };
    ProvenErbs::new(
        &fig1_knots::<Ball>(&bits),
        vec![set.params::<Ball>(&bits)],
        CentreReading::Cited,
        options,
    )
    .map_err(|e| e.to_string())
}
