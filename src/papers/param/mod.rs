//! Paper 004: Marin, *An Approach to Data Parametrization in Parametric Cubic Spline
//! Interpolation Problems*, J. Approx. Theory (1984).
//!
//! Claims checked so far: the exact 1-D minimizers (case I, Table I, Eqs. 8 and 11,
//! Corollaries 2 and 3), the plane-curve example (Table III, the second-derivative comparison
//! of Figs. 3–5), the robot example (Tables VI–VII), the corner example (Fig. 6) and the H¹
//! inequality of Sec. 1.

mod data;
mod figures;
mod geometry;
mod objective_claims;
mod one_d;
mod overshoot;
mod plane;
mod render;
mod robot;

use super::{ClaimSpec, Ledger, Paper, PaperOutput};
use crate::scalar::parse::parse_rational;
use crate::scalar::BigRational;

/// The paper's id (file name in `../shared/papers`).
pub const ID: &str = "004_2a9dc6e62cca15f1";
/// The short name: the prefix of every claim id and a `--paper` value.
pub const SHORT: &str = "marin";
/// Authors and title.
pub const TITLE: &str = "Marin, An Approach to Data Parametrization in Parametric Cubic Spline Interpolation Problems, J. Approx. Theory (1984)";

/// The claims of the paper, in report order.
pub const SPECS: &[ClaimSpec] = &[
    ClaimSpec { id: "marin.sec1.h1_inequality", location: "Sec. 1 (i)", statement: "‖θ − φ‖²_H¹ = ∫(e² + e'²) ≤ ∫θ''² for each component, φ the piecewise linear interpolant", published: None },
    ClaimSpec { id: "marin.case1.chord_length", location: "Sec. 2, case I, Eq. 7", statement: "for strictly monotone data the minimizing parametrization is normalized accumulated chord length, θ is linear and G = 0", published: None },
    ClaimSpec { id: "marin.table1.t_star", location: "Table I, Eq. 9, Corollary 1", statement: "the minimizing parametrization of the Table I ordinates", published: Some("Table I, column t_i*") },
    ClaimSpec { id: "marin.cor1.numerical", location: "Sec. 2, Corollary 1 (case II)", statement: "for alternating data the parametrization of Eq. 9 is the minimizer of G", published: None },
    ClaimSpec { id: "marin.eq8.interior_slope", location: "Sec. 2, Lemma, Eq. 8", statement: "at the minimizing parametrization of alternating data, dθ/dt(t_i*) = 0 at every interior knot", published: None },
    ClaimSpec { id: "marin.eq11.jump", location: "Eqs. 11–12", statement: "the jump in the second derivative given by Eq. 11 vanishes at the minimizing parametrization", published: None },
    ClaimSpec { id: "marin.cor2.unique_minimizer", location: "Sec. 2, case III, Corollary 2", statement: "the parametrization of Eqs. 16–17 is the unique minimizer of G for general scalar data", published: None },
    ClaimSpec { id: "marin.cor3.properties", location: "Corollary 3 (i)–(iii)", statement: "no overshoots; breakpoints only at the extremes; |θ''| = 3(Σ ε_j √|D_j|)² at the interior extremes, alternating in sign", published: None },
    ClaimSpec { id: "marin.remark.existence", location: "Sec. 1, Remark (Existence of Solutions)", statement: "z_i ≠ z_(i+1) implies that G(h) becomes infinite if any component of h vanishes", published: None },
    ClaimSpec { id: "marin.eq31.bending_energy", location: "Sec. 3, Eq. 31", statement: "G(h) = Σ α_l⁻² (z^l)ᵀQᵀM⁻¹Qz^l is the smoothness objective Σ α_l⁻² ∫θ_l''² of the natural splines", published: None },
    ClaimSpec { id: "marin.eq30.nonincreasing", location: "Sec. 3, after Eq. 30", statement: "the gradient-projection iterates have nonincreasing objective values G(h⁽⁰⁾), G(h⁽¹⁾), …", published: None },
    ClaimSpec { id: "marin.table3.chord", location: "Table III, column t^C1; Eq. 5", statement: "normalized accumulated chord length of the Table II data", published: Some("Table III, column t_i^C1") },
    ClaimSpec { id: "marin.table3.exact", location: "Table III, column t^EX; Eqs. 30–31", statement: "the minimizing parametrization of the Table II data with the exact objective (31)", published: Some("Table III, column t_i^EX") },
    ClaimSpec { id: "marin.table3.approx", location: "Table III, column t^AP; Eqs. 30, 34", statement: "the minimizing parametrization of the Table II data with the approximate objective (34)", published: Some("Table III, column t_i^AP") },
    ClaimSpec { id: "marin.fig3_5.second_derivatives", location: "Sec. 3, Figs. 3–5", statement: "the minimizing parametrizations substantially reduce the second derivatives of both components compared with chord length", published: None },
    ClaimSpec { id: "marin.sec2.third_derivative_jumps", location: "Sec. 2, after Corollary 3, bullet (ii)", statement: "for higher-dimensional data the minimizing parametrization reduces the jump in the third derivative at breakpoints not coinciding with relative extreme values", published: None },
    ClaimSpec { id: "marin.sec2.overshoots_reduced", location: "Sec. 2, after Corollary 3, bullet (i)", statement: "for higher-dimensional data the minimizing parametrization reduces position overshoots (compared with chord length)", published: None },
    ClaimSpec { id: "marin.fig6.corner", location: "Sec. 3, Fig. 6", statement: "with widely spaced data near a corner, chord length gives oscillations whose amplitude the minimizing parametrization reduces", published: None },
    ClaimSpec { id: "marin.table6.chord_6d", location: "Table VI, column t^CL; Eq. 5", statement: "normalized accumulated chord length of the six-dimensional axis data of Table IV", published: Some("Table VI, column t_i^CL") },
    ClaimSpec { id: "marin.table6.chord_wc", location: "Table VI, column t^WC; Eq. 5", statement: "normalized accumulated chord length of the work-centre positions of Table V", published: Some("Table VI, column t_i^WC") },
    ClaimSpec { id: "marin.table6.approx", location: "Table VI, column t^AP; Eqs. 30, 34", statement: "the minimizing parametrization of the axis data with objective (34) and α = 1, 1, 2, 6, 6, 6", published: Some("Table VI, column t_i^AP") },
    ClaimSpec { id: "marin.table7.max_acceleration", location: "Table VII", statement: "the maximum second derivative of each axis' natural cubic spline for each parametrization", published: Some("Table VII (18 values)") },
    ClaimSpec { id: "marin.fig9.overshoots", location: "Sec. 3, Fig. 9", statement: "for axis #3, overshoots occur in several areas with t^CL and t^WC and are eliminated with t^AP", published: None },
    ClaimSpec { id: "marin.fig9.oscillations", location: "Sec. 3, Fig. 9", statement: "for axis #3, t^AP aligns the spline's local extrema with the data's: the unwanted oscillations of t^CL and t^WC are eliminated", published: None },
    ClaimSpec { id: "marin.table7.reduction", location: "Sec. 3, after Table VII", statement: "reduction by a factor of two or more was obtained on five of the six axes", published: Some("five of the six axes") },
];

/// The paper: its specs and its checks.
pub fn paper() -> Paper {
    Paper {
        id: ID,
        short: SHORT,
        title: TITLE,
        specs: SPECS,
        verify,
    }
}

/// Parts of the paper with a quantitative statement that no claim covers, and why (shown in
/// the report's "Not checked" section).
const NOT_CHECKED: &[(&str, &str)] = &[
    (
        "Fig. 7",
        "a diagram of the six-axis manipulator, no numbers",
    ),
    (
        "Fig. 8 (work-centre paths in the xz plane)",
        "needs the manipulator's forward kinematics, which the paper does not give",
    ),
    (
        "Sec. 2, after Corollary 3, bullet (iii) for higher-dimensional data (second-derivative oscillations more centred about zero)",
        "the paper defines no measure of centring; bullets (i) and (ii) are claims",
    ),
];

/// A printed decimal as an exact rational (the transcribed tables parse by construction; a
/// test checks every entry).
pub(crate) fn num(s: &str) -> BigRational {
    parse_rational(s).unwrap_or_else(|_| BigRational::from_integer(0.into()))
}

/// What the checks of paper 004 computed, for the report.
struct Results {
    h1: Vec<geometry::H1Row>,
    table1: Option<one_d::TableOne>,
    plane: plane::PlaneSection,
    corner: Option<geometry::CornerCurves>,
    robot: robot::RobotSection,
    /// Fig. 9: the overshoots of axis #3 on each parametrization.
    fig9: Vec<overshoot::OvershootRow>,
}

/// Run every check of paper 004 and build its report.
pub fn verify() -> PaperOutput {
    let mut ledger = Ledger::new(ID, SPECS);
    ledger.record("marin.remark.existence", objective_claims::existence());
    ledger.record(
        "marin.eq31.bending_energy",
        objective_claims::eq31_is_bending_energy(),
    );
    ledger.record(
        "marin.eq30.nonincreasing",
        objective_claims::nonincreasing_objective(),
    );
    let h1 = geometry::h1_inequality(&mut ledger);
    let table1 = one_d::section(&mut ledger);
    let plane = plane::section(&mut ledger);
    let corner = geometry::corner(&mut ledger);
    let robot = robot::section(&mut ledger);
    ledger.record(
        "marin.sec2.overshoots_reduced",
        overshoot::reduced(&plane.parametrizations, &robot.approx),
    );
    let (fig9, [overshoots, oscillations]) = overshoot::fig9(&robot.approx);
    ledger.record("marin.fig9.overshoots", overshoots);
    ledger.record("marin.fig9.oscillations", oscillations);
    let results = Results {
        h1,
        table1,
        plane,
        corner,
        robot,
        fig9,
    };
    render::report(&results, ledger.finish())
}

#[cfg(test)]
mod tests {
    use super::data::*;

    #[test]
    fn every_transcribed_number_parses() {
        let all = TABLE1
            .iter()
            .flat_map(|(a, b)| [*a, *b])
            .chain(TABLE2.iter().flat_map(|(a, b)| [*a, *b]))
            .chain(TABLE3.iter().flat_map(|(a, b, c)| [*a, *b, *c]));
        for s in all {
            assert!(crate::scalar::parse::parse_rational(s).is_ok(), "{s}");
        }
    }
}
