"""The Python package against the command line (same bytes), fractions (exact results),
mpmath (balls) and scipy (the peer, where installed), and on hostile input."""

import json
import math
import random
from fractions import Fraction
from math import comb

import numpy as np
import pytest

import trajverify as tv

from helpers import REPO, cli, exact, needs_cli


def random_hermite(rng, m, d):
    return [[rng.uniform(-10, 10) for _ in range(d)] for _ in range(m + 1)]


@needs_cli
def test_hermite_f64_equals_the_command_line_bit_for_bit():
    rng = random.Random(41)
    for m, d in [(0, 1), (2, 3), (5, 2), (12, 7)]:
        start, end = random_hermite(rng, m, d), random_hermite(rng, m, d)
        ours = tv.hermite(start, end, (0.0, 1.5))
        doc = {"start": [[exact(x) for x in p] for p in start],
               "end": [[exact(x) for x in p] for p in end], "interval": ["0", "1.5"]}
        theirs = np.array([[float(x) for x in p] for p in cli("hermite", doc)["control_points"]])
        assert ours.shape == theirs.shape
        assert np.array_equal(ours, theirs), (m, d)


def test_hermite_batch_is_hermite_per_problem():
    rng = np.random.default_rng(7)
    start, end = rng.normal(size=(40, 4, 3)), rng.normal(size=(40, 4, 3))
    batch = tv.hermite_batch(start, end, (0.0, 2.0))
    for i in range(40):
        assert np.array_equal(batch[i], tv.hermite(start[i], end[i], (0.0, 2.0)))
    numbers = tv.hermite_batch(start[:, :, 0], end[:, :, 0])
    assert np.array_equal(numbers[3], tv.hermite(start[3, :, 0], end[3, :, 0]))


def hermite_derivative(points, j, at_end, width):
    """The j-th derivative at an end of the Bernstein polynomial with `points` on [0, width],
    exactly: n!/(n−j)!/width^j Σ_i (−1)^(j−i) C(j, i) Δ-points."""
    n = len(points) - 1
    p = points[::-1] if at_end else points
    total = sum((-1) ** (j - i) * comb(j, i) * p[i] for i in range(j + 1))
    scale = Fraction(math.factorial(n), math.factorial(n - j)) / Fraction(width) ** j
    return total * scale * (-1) ** j if at_end else total * scale


def test_rational_hermite_meets_every_condition_exactly():
    start = [Fraction(1, 3), Fraction(-2, 7), 5, Fraction(1, 10)]
    end = [2, Fraction(3, 11), Fraction(-1, 9), 0]
    width = Fraction(3, 2)
    points = tv.hermite(start, end, (0, width), scalar="rational")
    assert all(isinstance(p, Fraction) for p in points)
    for j in range(4):
        assert hermite_derivative(points, j, False, width) == start[j]
        assert hermite_derivative(points, j, True, width) == end[j]


def test_balls_enclose_the_exact_values_as_mpmath_computes_them_at_four_times_the_precision():
    mpmath = pytest.importorskip("mpmath")
    start, end = [Fraction(1, 3), Fraction(2, 7)], [1, Fraction(-5, 3)]
    exact_points = tv.hermite(start, end, (0, 1), scalar="rational")
    balls = tv.hermite(start, end, (0, 1), scalar="ball:64")
    with mpmath.workprec(256):
        for q, ball in zip(exact_points, balls):
            assert q in ball
            x = mpmath.mpf(q.numerator) / q.denominator
            assert mpmath.mpf(ball.value) - mpmath.mpf(ball.radius) <= x <= mpmath.mpf(ball.value) + mpmath.mpf(ball.radius)


def test_hermite_agrees_with_scipy():
    interpolate = pytest.importorskip("scipy.interpolate")
    rng = np.random.default_rng(3)
    start, end = rng.normal(size=(6, 200)), rng.normal(size=(6, 200))
    ours = tv.hermite(start, end)
    theirs = interpolate.BPoly.from_derivatives([0, 1], [start, end]).c[:, 0, :]
    assert np.allclose(ours, theirs, rtol=1e-12, atol=1e-12)


@needs_cli
def test_natural_spline_f64_equals_the_command_line_bit_for_bit():
    rng = random.Random(5)
    t = sorted(rng.uniform(0, 50) for _ in range(60))
    z = [[rng.uniform(-3, 3), rng.uniform(-3, 3)] for _ in t]
    at = [t[0], t[-1]] + [rng.uniform(t[0], t[-1]) for _ in range(40)] + t[10:13]
    ours = tv.natural_spline(t, z, at)
    doc = {"t": [exact(x) for x in t], "z": [[exact(x) for x in p] for p in z], "at": [exact(x) for x in at]}
    theirs = cli("natural-spline", doc)
    for name in ("values", "first", "second"):
        expected = np.array([[float(x) for x in p] for p in theirs[name]])
        assert np.array_equal(getattr(ours, name), expected), name


def test_natural_spline_agrees_with_scipy():
    interpolate = pytest.importorskip("scipy.interpolate")
    rng = np.random.default_rng(11)
    t = np.sort(rng.uniform(0, 10, 300))
    z = rng.normal(size=300)
    at = rng.uniform(t[0], t[-1], 500)
    ours = tv.natural_spline(t, z, at)
    spline = interpolate.CubicSpline(t, z, bc_type="natural")
    for k, values in enumerate(ours):
        assert np.allclose(values, spline(at, k), rtol=1e-9, atol=1e-9)


def test_natural_spline_in_rationals_is_exact():
    jets = tv.natural_spline([0, 1, 3], [0, 2, Fraction(1, 3)], [Fraction(1, 2), 2], scalar="rational")
    assert all(isinstance(x, Fraction) for x in jets.values)
    # The natural spline's second derivative vanishes at the ends and is linear between knots.
    ends = tv.natural_spline([0, 1, 3], [0, 2, Fraction(1, 3)], [0, 3], scalar="rational")
    assert ends.second == [0, 0]


@needs_cli
def test_run_prints_what_the_command_line_prints():
    doc = {"waypoints": [[0, 0], [100, 20], [180, -40], [300, 0]], "radius": 30, "samples": 3}
    assert tv.run("dubins", doc) == cli("dubins", doc)
    doc = {"start": ["1/3", "2"], "end": ["1", "-1/7"], "interval": ["0", "2"]}
    for scalar in ("rational", "mpfr:128", "ball:128"):
        assert tv.run("hermite", doc, scalar) == cli("hermite", doc, scalar)


@pytest.mark.parametrize(
    "call, field",
    [
        (lambda: tv.hermite([0.0, math.nan], [1.0, 1.0]), "start"),
        (lambda: tv.hermite([0.0, 1.0], [1.0, math.inf]), "end"),
        (lambda: tv.hermite([0.0, 1.0], [1.0], (0.0, 1.0)), "end"),
        (lambda: tv.hermite([0.0, 1.0], [1.0, 1.0], (1.0, 1.0)), "interval"),
        (lambda: tv.hermite([0, 1], [1, 1], (1, 0), scalar="rational"), "interval"),
        (lambda: tv.hermite([[0.0], [1.0, 2.0]], [[1.0], [1.0]]), "start"),
        (lambda: tv.natural_spline([0.0, 1.0, 1.0], [0.0, 1.0, 2.0], [0.5]), "t[2]"),
        (lambda: tv.natural_spline([0.0, 1.0], [0.0, 1.0], [2.0]), "at[0]"),
        (lambda: tv.natural_spline([0.0, 1.0], [0.0, 1.0, 2.0], [0.5]), "z"),
        (lambda: tv.natural_spline([0.0], [0.0], [0.0]), "t"),
        (lambda: tv.run("dubins", {"waypoints": [[0, 0], [0, 0]], "radius": 1}), "waypoints"),
        (lambda: tv.run("hermite", "{not json"), "input"),
        (lambda: tv.run("no-such-algorithm", {}), "algorithm"),
        (lambda: tv.run("hermite", {"start": [1], "end": [1], "interval": [0, 1]}, "mpfr:x"), "scalar"),
        (lambda: tv.run("hermite", {"start": [True], "end": [1], "interval": [0, 1]}), "start"),
        (lambda: tv.hermite([0, 1], [1, 1], interval=(0, 1, 2)), "interval"),
        (lambda: tv.hermite([0, 1], [1, 1], interval=1), "interval"),
        (lambda: tv.hermite([0, 1], [1, 1], interval=("0", "2*pi")), "interval"),
        (lambda: tv.hermite([0, 1], [1, 1], scalar=5), "scalar"),
        (lambda: tv.hermite_batch(np.zeros(3), np.ones(3)), "start"),
        (lambda: tv.hermite_batch(np.zeros((0, 2)), np.ones((0, 2))), "start"),
        (lambda: tv.natural_spline([[0, 1], [2, 3]], [0, 1], [0.5]), "t"),
        (lambda: tv.run("hermite", {"start": [1], "end": [1], "interval": [0, 1]}, "float:2"), "scalar:"),
    ],
)
def test_hostile_input_raises_a_value_error_naming_the_field(call, field):
    with pytest.raises(tv.TrajverifyError) as caught:
        call()
    assert isinstance(caught.value, ValueError)
    assert field in str(caught.value), str(caught.value)


def test_hostile_shapes_and_values_never_crash():
    rng = random.Random(9)
    hostile = [math.nan, math.inf, -math.inf, 1e308, -1e308, 5e-324, 0.0, -0.0, 1e-300]
    for _ in range(200):
        m = rng.randrange(0, 5)
        start = [rng.choice(hostile + [rng.uniform(-1, 1)]) for _ in range(m + 1)]
        end = [rng.choice(hostile + [rng.uniform(-1, 1)]) for _ in range(rng.choice([m + 1, m + 2]))]
        interval = (rng.choice([0.0, 1.0, math.nan]), rng.choice([1.0, 0.0, 1e308]))
        try:
            out = tv.hermite(start, end, interval)
        except ValueError:
            continue
        assert np.all(np.isfinite(out))


def test_verify_returns_the_ledger():
    ledger = tv.verify("marin")  # one name, or a list
    claims = ledger["claims"]
    assert claims and all(c["paper"].startswith("004") for c in claims)
    assert len(ledger) == len(claims) == ledger.summary["total"]
    assert ledger.verdicts() == {k: v for k, v in ledger.summary["verdicts"].items() if v}
    first = ledger.claim(claims[0]["id"])
    assert isinstance(first, tv.Claim) and first.record == claims[0] and first.verdict == claims[0]["verdict"]
    assert all(c.verdict == "discrepancy" for c in ledger.by_verdict("discrepancy"))
    committed = REPO / "reports" / "claims.json"
    if committed.exists():
        mine = {c["id"]: c for c in json.loads(committed.read_text())["claims"]}
        assert all(mine[c["id"]] == c for c in claims), "verify() differs from reports/claims.json"


def python_examples(path, section=None):
    """The python blocks of a Markdown file (of one section when named)."""
    text = path.read_text()
    if section is not None:
        text = text.split(section, 1)[1].split("\n## ", 1)[0]
    return [block.split("```", 1)[0] for block in text.split("```python\n")[1:]]


@pytest.mark.parametrize("doc, section", [("README.md", "## From Python"), ("docs/python.md", None)])
def test_the_documented_python_examples_run(doc, section):
    path = REPO / doc
    if not path.exists():
        pytest.skip(f"{doc} is not beside the package")
    blocks = python_examples(path, section)
    assert blocks, f"{doc} has no python example"
    for block in blocks:
        exec(compile(block, doc, "exec"), {})


def test_balls_become_arbs_as_narrow_as_printed():
    flint = pytest.importorskip("flint")
    doc_end = ["1/3", "1"]
    for bits in (128, 512):
        ball = tv.hermite([0, 1], doc_end, scalar=f"ball:{bits}")[1]
        arb = ball.to_arb()
        with flint.ctx.workprec(4 * bits):
            assert arb.contains(flint.fmpq(1, 3))  # p₁ = x₀ + x₀′/3 = 0 + 1/3
            # arb keeps a radius in 30 bits, rounded up: at most a few parts in 10⁹ wider.
            assert float(arb.rad()) <= float(ball.rad) * (1 + 2**-26)
            assert not arb.contains(flint.fmpq(1, 3) + flint.fmpq(1, 2 ** (bits - 8)))


def test_numbers_as_exact_strings_and_the_default_scalar_work_in_f64():
    assert np.array_equal(tv.hermite(["1/3", 1.0], [1.0, "2e-1"]), tv.hermite([1 / 3, 1.0], [1.0, 0.2]))
    assert np.array_equal(tv.hermite([0, 1], [1, 1], interval=("0", "1/3")), tv.hermite([0, 1], [1, 1], (0, 1 / 3)))
    assert np.array_equal(tv.hermite([0, 1], [1, 1], scalar=None), tv.hermite([0, 1], [1, 1]))
    assert np.array_equal(tv.natural_spline([0, 1, 2], [0, 1, 0], [0.5], scalar=None).values, [0.6875])


def test_verify_refuses_a_directory_that_is_not_empty(tmp_path):
    (tmp_path / "keep.txt").write_text("mine")
    with pytest.raises(tv.TrajverifyError, match="out"):
        tv.verify("marin", out=tmp_path)
    assert [p.name for p in tmp_path.iterdir()] == ["keep.txt"]

