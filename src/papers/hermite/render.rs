//! The Markdown report of paper 000, written from the checks' [`Results`](super::Results).

use super::{
    conditioning, examples, figures, turn_proofs, Results, FIG2_FAST, FIG2_SLOW, ID, SHORT, TITLE,
};
use crate::ledger::{Claim, PaperOutput};
use crate::report::number;
use crate::report::number::Notation;
use crate::report::{plot, table};
use crate::scalar::Field;

fn figure_name(n: u32) -> String {
    super::super::figure_file(ID, n)
}

/// The report and figures of paper 000.
pub fn report(r: &Results, claims: Vec<Claim>) -> PaperOutput {
    let mut md = String::new();
    let mut figures = vec![(
        figure_name(2),
        plot::render_or_note(
            &figures::fig2_panels(&r.fig2_curves[0], &r.fig2_curves[1]),
            (1, 3),
            (1200, 380),
        ),
    )];
    md.push_str(&fig2(r));
    md.push_str(&format!(
        "## Eqs. 16–18: which control points each end determines\n\nEqs. 16–17 as printed give the start data m+2 control points and the end data m; the exact map gives each end m+1:\n\n\
         - printed: p_0…p_(m+1) from the start, p_(m+2)…p_(2m+1) from the end;\n- computed: {}.\n\n{}\n\n",
        r.ranges.reproduced, r.ranges.evidence
    ));
    md.push_str(&turn(r, &mut figures));
    md.push_str(&landing(r, &mut figures));
    md.push_str(&fig5_section(&r.kappa));
    figures.push((
        figure_name(5),
        plot::render_or_note(&figures::fig5_panels(&r.kappa), (1, 1), (900, 560)),
    ));
    super::super::report_output((ID, SHORT, TITLE), md, claims, figures)
}

fn fig2(r: &Results) -> String {
    let [fast, slow] = &r.fig2;
    let rows = [
        vec![
            "1".into(),
            number::printed(&format!("[{FIG2_FAST}]")),
            fast.reproduced.clone(),
            fast.verdict.as_str().into(),
        ],
        vec![
            "2".into(),
            number::printed(&format!("[{FIG2_SLOW}]")),
            slow.reproduced.clone(),
            slow.verdict.as_str().into(),
        ],
    ];
    format!(
        "## Fig. 2: control points for H = [0 0 0 | 1 1 0]\n\n{}\n![Fig. 2](./{})\n\n",
        table(
            &["duration", "published", "reproduced (exact)", "verdict"],
            &rows
        ),
        figure_name(2)
    )
}

/// The Fig. 3 table: the proven measures the claims rest on, then sampled ones (f64 on the
/// MPFR curve, for the figure's description only).
fn turn_table(
    metrics: &[examples::TurnMetrics],
    proven: &Result<Vec<turn_proofs::ProvenTurn>, String>,
) -> String {
    let sampled: Vec<Vec<f64>> = metrics
        .iter()
        .map(|t| {
            vec![
                t.duration,
                t.max_radial_deviation,
                t.farthest_from_end,
                t.turning_degrees,
                t.max_speed,
            ]
        })
        .collect();
    let rows: Vec<Vec<String>> = metrics
        .iter()
        .zip(number::columns(&sampled, 4))
        .enumerate()
        .map(|(i, (t, cells))| {
            let factor = if t.factor.1 == 1 {
                t.factor.0.to_string()
            } else {
                format!("{}/{}", t.factor.0, t.factor.1)
            };
            let proven_cells = match proven.as_ref().ok().and_then(|p| p.get(i)) {
                Some(p) => vec![
                    number::ball_in(&p.chord, 4, Notation::Scientific),
                    turn_proofs::arc_text_in(p, Notation::Scientific),
                    turn_proofs::distance_text(&p.net_turning_degrees),
                    number::bound(
                        p.recedes_at_least.to_f64_round(rug::float::Round::Down),
                        4,
                        rug::float::Round::Down,
                    ),
                ],
                None => vec!["—".to_string(); 4],
            };
            [
                vec![t.data.label().to_string(), factor, cells[0].clone()],
                proven_cells,
                cells[1..].to_vec(),
            ]
            .concat()
        })
        .collect();
    let mut md = table(
        &[
            "data",
            "× nominal",
            "duration",
            "Hausdorff to chord (proven)",
            "Hausdorff to arc (proven)",
            "net turning (°, proven)",
            "recedes ≥ (× start's distance, proven)",
            "max radial dev. (sampled)",
            "max dist. to end / start's (sampled)",
            "total tangent turning (°, sampled)",
            "peak speed (sampled)",
        ],
        &rows,
    );
    if let Err(e) = proven {
        md.push_str(&format!("\nThe proven measures failed: {e}.\n"));
    }
    md
}

fn turn(r: &Results, figures: &mut Vec<(String, String)>) -> String {
    let mut md = String::new();
    md.push_str("## Fig. 3: one turn, three durations\n\n");
    md.push_str(
        "Data (ours; the paper prints none): a uniform quarter turn of radius 1 at speed 1, start (0, 0) with velocity (1, 0), \
         end (1, 1) with velocity (0, 1); nominal duration π/2 (the circle's). The text gives only \"identical start and end speeds \
         but different directions\", so two readings are computed: with the circle's accelerations (0, 1) and (−1, 0) as well \
         (m = 2, quintic), and with velocities only (m = 1, cubic). Criteria fixed beforehand: *straight* = closer to the chord than to the arc (Hausdorff distance); \
         *circular* = closer to the arc than to the chord; *loops away* = the tangent turns through a full extra revolution (net turning ≠ 90°) and the distance to the terminal point rises by more than 1 % of the start's above the closest it had come. The claims rest on the proven columns (ball arithmetic at 128 bits, branch and bound); the sampled columns describe the figure.\n\n",
    );
    match &r.turn {
        Some(metrics) => {
            md.push_str(&turn_table(metrics, &r.turn_proven));
            md.push_str(&format!("\n![Fig. 3](./{})\n\n", figure_name(3)));
            figures.push((
                figure_name(3),
                plot::render_or_note(&figures::turn_figure(metrics), (1, 2), (1200, 640)),
            ));
        }
        None => md.push_str("The Fig. 3 instance failed to solve.\n\n"),
    }

    md
}

fn landing(r: &Results, figures: &mut Vec<(String, String)>) -> String {
    let mut md = String::new();
    md.push_str("## Fig. 4: landing\n\n");
    match &r.landing {
        Some((l, claim)) => {
            let rows: Vec<Vec<String>> = ["x", "y", "z"]
                .iter()
                .zip(&l.curve)
                .map(|(name, b)| {
                    vec![
                        name.to_string(),
                        b.control_points()
                            .iter()
                            .map(|c| c.to_plain_string())
                            .collect::<Vec<_>>()
                            .join(", "),
                    ]
                })
                .collect();
            md.push_str("Data (ours): runway along +x, threshold at the origin; start on the downwind leg at (0, 2000, 300) m flying (−60, 0, 0) m/s, zero acceleration; cross the threshold at (55, 0, 0) m/s, zero acceleration, after 60 s (a standard-rate 180° turn). Exact control points (m):\n\n");
            md.push_str(&table(&["coordinate", "control points p_0 … p_5"], &rows));
            md.push_str(&format!(
                "\n{}\n\n![Fig. 4](./{})\n\n",
                claim.evidence,
                figure_name(4)
            ));
            figures.push((
                figure_name(4),
                plot::render_or_note(&figures::landing_figure(l), (1, 2), (1100, 420)),
            ));
        }
        None => md.push_str("The landing instance failed to solve.\n\n"),
    }

    md
}

fn fmt_kappa(k: &Option<conditioning::Kappa>, digits: u32) -> String {
    k.as_ref().map_or("—".into(), |k| {
        number::float_in(
            &k.exact,
            digits.min(k.value.digits),
            number::Notation::Scientific,
        )
    })
}

fn fig5_section(rows: &[conditioning::KappaRow]) -> String {
    let mut md = String::from("## Fig. 5: condition number of the transform\n\n");
    md.push_str(
        "κ2 = σmax/σmin (Eq. 10) of the matrix taking p_0…p_(2m+1) to H (Eqs. 14–15), for m derivatives at each end. Certified \
         column: MPFR at p and 2p bits, shown to ten of its certified digits (`trajverify run hermite-condition` prints them \
         all). f64 columns: nalgebra's SVD and our one-sided Jacobi, each on the correctly rounded f64 matrix, with \
         their correct digits against the certified value. Proven column: bounds decided exactly by Sylvester's law of \
         inertia on BᵀB (claim hermite.fig5.proven), printed rounded outward.\n\n",
    );
    md.push_str(&fig5_unit_table(rows));
    md.push_str(
        "\nThe same κ2 for other durations T, and for the *binomial* matrix (the same matrix without the factors \
         n!/(n−j)!/T^j), each to six certified digits:\n\n",
    );
    let body: Vec<Vec<String>> = rows
        .iter()
        .map(|r| {
            vec![
                r.m.to_string(),
                fmt_kappa(&r.durations[0], 6),
                fmt_kappa(&r.durations[1], 6),
                fmt_kappa(&r.durations[2], 6),
                fmt_kappa(&r.binomial, 6),
            ]
        })
        .collect();
    md.push_str(&table(
        &["m", "T = 1/2", "T = 2", "T = 10", "binomial, T = 1"],
        &body,
    ));
    md.push_str(&format!(
        "\nGrowth law observed: {}.\n\nnalgebra's f64 value has no correct digit from m = {}.\n\n![Fig. 5](./{})\n\n",
        conditioning::growth_law(rows),
        conditioning::f64_breakdown(rows).map_or("— (never)".to_string(), |m| m.to_string()),
        figure_name(5)
    ));
    md
}

/// Fig. 5's κ2 at T = 1: certified, proven, and the two f64 answers with their correct digits.
fn fig5_unit_table(rows: &[conditioning::KappaRow]) -> String {
    let scientific = number::Notation::Scientific;
    let body: Vec<Vec<String>> = rows
        .iter()
        .map(|r| {
            let bits = r.unit.as_ref().map_or(0, |k| k.bits);
            let digits = r.unit.as_ref().map_or(0, |k| k.value.digits);
            let rel = match (r.nalgebra, &r.unit) {
                (Some(a), Some(k)) => number::sig_in(
                    crate::scalar::certify::relative_error(a, &k.exact),
                    2,
                    scientific,
                ),
                _ => "—".into(),
            };
            vec![
                r.m.to_string(),
                fmt_kappa(&r.unit, number::PROSE_DIGITS),
                format!("{digits} ({bits}/{} bits)", 2 * bits),
                r.proven.as_ref().map_or("—".into(), |(lo, hi)| {
                    format!(
                        "[{}, {}]",
                        number::bound_text(lo, 9, rug::float::Round::Down),
                        number::bound_text(hi, 9, rug::float::Round::Up)
                    )
                }),
                match r.nalgebra {
                    None => "— (overflow)".into(),
                    Some(k) if k.is_infinite() => "∞ (σmin = 0)".into(),
                    Some(k) => number::sig_in(k, number::PROSE_DIGITS, scientific),
                },
                rel,
                conditioning::f64_digits(r.nalgebra, &r.unit).to_string(),
                conditioning::f64_digits(r.jacobi_f64, &r.unit).to_string(),
            ]
        })
        .collect();
    table(
        &[
            "m",
            "κ2, T = 1 (certified)",
            "certified digits (precisions)",
            "proven enclosure (exact inertia)",
            "f64 nalgebra",
            "rel. error",
            "f64 nalgebra digits",
            "f64 Jacobi digits",
        ],
        &body,
    )
}
