"""The typed jobs (trajverify.jobs) against the command line's output on the same input, and
their exact results against fractions."""

from fractions import Fraction

import numpy as np
import pytest

import trajverify as tv

from helpers import cli, needs_cli

WAYPOINTS = [[0, 0], [100, 20], [180, -40], [300, 0]]


def floats(texts):
    return np.array(texts, dtype=float)


@needs_cli
def test_dubins_is_the_command_line():
    ours = tv.dubins(WAYPOINTS, 30, samples=5)
    theirs = cli("dubins", {"waypoints": WAYPOINTS, "radius": 30, "samples": 5})
    assert ours.length == float(theirs["length"])
    assert np.array_equal(ours.headings, floats(theirs["headings"]))
    for leg, other in zip(ours.legs, theirs["legs"], strict=True):
        assert (leg.start, leg.end, leg.word) == (other["from"], other["to"], other["word"])
        assert np.array_equal(leg.samples, floats(other["samples"]))
        assert leg.length == float(other["length"])


@needs_cli
@pytest.mark.parametrize("kind", ["bfbs", "erbs"])
def test_gerbs_path_is_the_command_line(kind):
    ours = tv.gerbs_path(WAYPOINTS, 30, kind=kind, samples=11)
    theirs = cli("gerbs-path", {"waypoints": WAYPOINTS, "radius": 30, "theta_o": "pi/8", "kind": kind, "samples": 11})
    assert np.array_equal(ours.points, floats(theirs["points"]))
    assert np.array_equal(ours.curvature, floats(theirs["curvature"]))
    assert ours.length == float(theirs["length"]) and ours.turns == theirs["turns"]
    assert len(ours.at_waypoints) == len(WAYPOINTS)


@needs_cli
def test_gerbs_basis_is_the_command_line():
    doc = {"knots": [0, 1, 2, 3, 4], "kind": "erbs", "at": [0.5, 1.5, 2.0], "derivatives": 2}
    ours = tv.gerbs_basis(doc["knots"], doc["at"], derivatives=2)
    theirs = cli("gerbs-basis", doc)
    assert ours == [[[None if v is None else float(v) for v in b] for b in p] for p in theirs["values"]]


@needs_cli
def test_marin_is_the_command_line_at_its_default_precision():
    mpmath = pytest.importorskip("mpmath")
    points = [[0, 0], [1, 2], [3, 3], [4, 0], [6, 1]]
    ours = tv.marin(points)
    theirs = cli("marin", {"points": points, "objective": "exact"})
    with mpmath.workprec(256):
        assert ours.t == [mpmath.mpf(x) for x in theirs["t"]]
        assert ours.G == mpmath.mpf(theirs["G"]) and ours.G < ours.G_chord
    assert ours.iterations == theirs["iterations"] and ours.converged


def test_marin_1d_case_one_is_exact():
    # Monotone data are case I: t_i proportional to the values' cumulative increments.
    result = tv.marin_1d([0, 1, 3, 6], scalar="rational")
    assert result.case == "I"
    assert result.t == [Fraction(0), Fraction(1, 6), Fraction(1, 2), Fraction(1)]


def test_spline_fit_interpolates_exactly():
    times, values = [1, 2, 3, 4, 5], [Fraction(1, 3), 2, 0, -1, 5]
    tau = tv.spline_fit(times, values, degree=3, controls=5, scalar="rational")
    basis = tv.bspline_basis(3)

    def cardinal(x):
        # B_3(x) from its exact pieces; zero outside [0, 4].
        j = int(x)
        if not 0 <= j < 4:
            return Fraction(0)
        s = x - j
        return sum(c * s**i for i, c in enumerate(basis[j]))

    for t, z in zip(times, values):
        assert sum(tau[i] * cardinal(Fraction(t) - i) for i in range(5)) == z


def test_bspline_pieces_form_a_partition_of_unity_and_gram_entries_are_exact():
    for k in (1, 3, 6):
        pieces = tv.bspline_basis(k)
        # Σ_j B_k(s + j) = 1 for s in [0, 1): the pieces' power coefficients sum to (1, 0, …).
        assert [sum(col) for col in zip(*pieces)] == [1] + [0] * k
    assert tv.bspline_gram(2) == [6, -4, 1]


def test_bang_bang_has_the_closed_form_of_the_paper():
    mpmath = pytest.importorskip("mpmath")
    result = tv.bang_bang("2/3")
    assert result.exact["switching_times"] == ["2 - sqrt(2)", "2", "2 + sqrt(2)"]
    with mpmath.workprec(256):
        assert abs(result.switching_times[0] - (2 - mpmath.sqrt(2))) < mpmath.mpf(2) ** -250


@needs_cli
def test_ph_hermite_and_phodcos_are_the_command_line():
    zero = [0, 0, 0]
    data = dict(p_b=zero, p_e=[1, 0, 0], v_b=[1, 0, 0], v_e=[1, 0.5, 0], a_b=zero, a_e=zero,
                j_b=zero, j_e=zero, s_b=zero, s_e=zero)
    ours = tv.ph_hermite(**data)
    theirs = cli("ph-hermite", data)
    assert np.array_equal(ours.control_points, floats(theirs["control_points"]))
    balls = tv.phodcos("[cos(t), sin(t), t/5]", ["0", "1"], segments=2, scalar="ball:64")
    assert isinstance(balls.max_error, tv.Ball) and balls.max_error.lower >= 0 and balls.sampled_error is None
    theirs = cli("phodcos", {"curve": "[cos(t), sin(t), t/5]", "interval": ["0", "1"], "segments": 2}, "ball:64")
    assert balls.max_error.value == theirs["max_error"]["value"]


@pytest.mark.parametrize(
    "call, field",
    [
        (lambda: tv.dubins([[0, 0], [0, 0]], 1), "waypoints"),
        (lambda: tv.dubins(WAYPOINTS, -1), "radius"),
        (lambda: tv.gerbs_path(WAYPOINTS, 30, kind="spline"), "kind"),
        (lambda: tv.marin([[0, 0]]), "points"),
        (lambda: tv.marin_1d([0, 1, 3, 2], scalar="rational"), "scalar: rational"),  # not "option --scalar"
        (lambda: tv.spline_fit([0], [1], controls=1), "times"),
        (lambda: tv.bang_bang(float("nan")), "xi"),
        (lambda: tv.bspline_basis(-1), "degree"),
        (lambda: tv.dubins([0, 0, 1, 1], 1), "waypoints"),
        (lambda: tv.marin([0, 1, 2, 3]), "points"),
    ],
)
def test_hostile_jobs_raise_a_value_error_naming_the_field(call, field):
    with pytest.raises(tv.TrajverifyError) as caught:
        call()
    assert field in str(caught.value), str(caught.value)


def test_a_ball_run_gives_balls_even_for_the_numbers_it_prints_exactly():
    result = tv.marin([[0, 0], [1, 2], [3, 3], [4, 0]], scalar="ball:128")
    assert all(isinstance(t, tv.Ball) for t in result.t)
    assert result.t[0].rad == 0 and 0 in result.t[0] and 1 in result.t[-1]

