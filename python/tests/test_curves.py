"""PH splines from expressions and Python callables, Taylor arithmetic, convergence studies."""

import json
import math
import subprocess
from fractions import Fraction

import numpy as np
import pytest

import trajverify as tv
from trajverify._jet import jet_function

from helpers import CLI, cli, needs_cli

HELIX = "[cos(t), sin(t), t/5]"


def helix(t):
    return (np.cos(t), np.sin(t), t / 5)


def test_taylor_arithmetic_gives_the_derivatives_of_a_callable():
    # f = (sin 2t · exp(t/3), sqrt(1 + t²) + atan t, t^2.5 / (1 + log(2 + t)) − tan(t/2)), at t = 0.7.
    def f(t):
        return (
            np.sin(2 * t) * np.exp(t / 3),
            np.sqrt(1 + t**2) + np.arctan(t),
            t**2.5 / (1 + np.log(2 + t)) - np.tan(t / 2),
        )

    jet = np.array(jet_function(f)(0.7, 4)).reshape(5, 3)
    # The reference: the same functions differentiated by mpmath at 60 digits.
    mpmath = pytest.importorskip("mpmath")
    with mpmath.workdps(60):
        g = [
            lambda t: mpmath.sin(2 * t) * mpmath.exp(t / 3),
            lambda t: mpmath.sqrt(1 + t**2) + mpmath.atan(t),
            lambda t: t**2.5 / (1 + mpmath.log(2 + t)) - mpmath.tan(t / 2),
        ]
        reference = np.array([[float(mpmath.diff(gi, mpmath.mpf("0.7"), k)) for gi in g] for k in range(5)])
    assert np.allclose(jet, reference, rtol=1e-12, atol=1e-12), jet - reference


def test_a_callable_and_the_same_expression_give_the_same_spline():
    by_expression = tv.ph_spline(HELIX, (0.0, 6.0), segments=32)
    by_callable = tv.ph_spline(helix, (0.0, 6.0), segments=32)
    assert by_callable.segments == 32 and by_callable.control_points.shape == (32, 18, 3)
    assert np.allclose(by_expression.control_points, by_callable.control_points, rtol=0, atol=1e-13)


@needs_cli
def test_ph_spline_is_run_phodcos_bit_for_bit():
    ours = tv.ph_spline(HELIX, (0.0, 2.0), segments=4)
    theirs = cli("phodcos", {"curve": HELIX, "interval": ["0", "2"], "segments": 4})
    assert np.array_equal(ours.preimages, np.array(theirs["preimages"], dtype=float))
    assert ours.sampled_error == float(theirs["max_error"])


def test_arc_length_frames_and_omega_of_a_helix():
    spline = tv.ph_spline(helix, (0.0, 6.0), segments=32)
    # The helix has speed √(1 + 1/25); the spline's own length is exact up to rounding and
    # within the conversion error's reach of the curve's.
    assert abs(spline.length - 6 * math.sqrt(1.04)) < 1e-8
    t = np.linspace(0.0, 6.0, 13)
    s = spline.arc_length(t)
    assert np.all(np.diff(s) > 0) and s[0] == 0.0
    assert np.allclose(spline.parameter_at_length(s), t, atol=1e-11)
    frames = spline.frames(t)
    assert frames.axes.shape == (13, 3, 3) and frames.omega.shape == (13, 3)
    for axes in frames.axes:
        assert np.allclose(axes @ axes.T, np.eye(3), atol=1e-13)
    velocity = spline.derivative(t, 1)
    assert np.allclose(frames.axes[:, 0, :], velocity / np.linalg.norm(velocity, axis=1)[:, None], atol=1e-13)
    assert np.allclose(frames.speed, np.linalg.norm(velocity, axis=1), rtol=1e-13)
    # ω: ė_k = ω × e_k, checked by central differences at interior points.
    h = 1e-5
    for u in (0.9, 2.3, 4.1):
        f = spline.frames(u)
        de = (spline.frames(u + h).axes - spline.frames(u - h).axes) / (2 * h)
        for k in range(3):
            assert np.allclose(de[k], np.cross(f.omega, f.axes[k]), atol=1e-6)


def test_a_ball_spline_encloses_the_conversion_computed_at_four_times_the_precision():
    b128 = tv.ph_spline(HELIX, ("0", "6"), segments=16, scalar="ball:128")
    b512 = tv.ph_spline(HELIX, ("0", "6"), segments=16, scalar="ball:512")
    f64 = tv.ph_spline(HELIX, (0.0, 6.0), segments=16)
    t = ["0", "1/3", "2.5", "6"]
    coarse, fine = b128.derivatives(t, 2), b512.derivatives(t, 2)
    assert coarse.shape == (4, 3, 3) and isinstance(coarse[0, 0, 0], tv.Ball)
    for ball, reference in zip(coarse.reshape(-1), fine.reshape(-1)):
        assert reference.mid in ball and ball.rad < Fraction(1, 10**25)
    assert np.allclose(f64.derivatives([0.0, 1 / 3, 2.5, 6.0], 2), [[[float(x.mid) for x in row] for row in p] for p in coarse], atol=1e-12)
    assert b512.length.mid in b128.length
    frames = b128.frames(["1", "2"])
    assert frames.axes.shape == (2, 3, 3) and frames.speed.shape == (2,)
    assert b128.control_points.shape == (16, 18, 3) and b128.preimages.shape == (16, 9, 4)
    # mpfr: the digits those balls prove, as mpmath numbers.
    mpmath = pytest.importorskip("mpmath")
    digits = tv.ph_spline(HELIX, ("0", "6"), segments=16, scalar="mpfr:128")(["1/3"])
    with mpmath.workprec(128):
        assert digits[0, 0] == mpmath.mpf(coarse[1, 0, 0].value)


def test_shapes_follow_the_parameters():
    spline = tv.ph_spline(HELIX, (0.0, 1.0), segments=2)
    assert spline(0.5).shape == (3,)
    assert spline([0.1, 0.2]).shape == (2, 3)
    assert spline(np.zeros((2, 3))).shape == (2, 3, 3)
    assert spline.derivatives(0.5, 4).shape == (5, 3)
    assert np.shape(spline.arc_length(0.5)) == ()
    assert spline.frames([[0.1, 0.2]]).axes.shape == (1, 2, 3, 3)


def test_tolerance_doubles_the_segments_until_the_sampled_error_is_met():
    spline = tv.ph_spline(HELIX, (0.0, 6.0), segments=1, tolerance=1e-9)
    assert spline.sampled_error <= 1e-9
    coarser = tv.ph_spline(HELIX, (0.0, 6.0), segments=spline.segments // 2)
    assert coarser.sampled_error > 1e-9


@pytest.mark.parametrize(
    "call, field",
    [
        (lambda: tv.ph_spline(HELIX, (1.0, 0.0)), "interval"),
        (lambda: tv.ph_spline(HELIX, (0.0, math.nan)), "interval"),
        (lambda: tv.ph_spline(HELIX, (0.0, 1.0), segments=0), "segments"),
        (lambda: tv.ph_spline(HELIX, (0.0, 1.0), derivatives=13), "derivatives"),
        (lambda: tv.ph_spline(HELIX, (0.0, 1.0), tolerance=-1.0), "tolerance"),
        (lambda: tv.ph_spline(HELIX, (0.0, 1.0), segments=1, tolerance=1e-300), "tolerance"),
        (lambda: tv.ph_spline("[t, t^2]", (0.0, 1.0)), "curve"),
        (lambda: tv.ph_spline("[sqrt(t - 10), t, t]", (0.0, 1.0)), "curve"),
        (lambda: tv.ph_spline(lambda t: (math.sin(t), t, t), (0.0, 1.0)), "curve"),
        (lambda: tv.ph_spline(lambda t: (t, t), (0.0, 1.0)), "curve"),
        (lambda: tv.ph_spline(42, (0.0, 1.0)), "curve"),
        (lambda: tv.ph_spline(helix, (0, 1), scalar="ball:64"), "curve"),
        (lambda: tv.ph_spline(HELIX, (0, 1), tolerance=1e-6, scalar="ball:64"), "tolerance"),
        (lambda: tv.ph_spline(HELIX, (0, 1), scalar="interval:64"), "scalar"),
        (lambda: tv.ph_spline(HELIX, ("1", "1/2"), scalar="ball:64"), "interval"),
        (lambda: tv.ph_spline(HELIX, ("0", "1"), scalar="ball:64")("2"), "t"),
        (lambda: tv.ph_spline(HELIX, (0.0, 1.0))(1.5), "t"),
        (lambda: tv.ph_spline(HELIX, (0.0, 1.0)).parameter_at_length(99.0), "s: 99"),
        (lambda: tv.convergence(lambda t: t, (0, 1)), "curve"),
        (lambda: tv.convergence(HELIX, (0, 1), levels=[-1, 2]), "levels"),
        (lambda: tv.ph_spline(HELIX, (0, 6), segments=2**70), "segments"),
        (lambda: tv.ph_spline(HELIX, (0.0, 1.0)).derivatives(0.5, -1), "order"),
        (lambda: tv.ph_spline(lambda t: (np.sqrt(t - 10), t, t), (0.0, 6.0)), "curve"),
        (lambda: tv.ph_spline(lambda t: (1 / (t - 3), t, t), (0.0, 6.0)), "curve"),
        (lambda: tv.ph_spline(lambda t: ("a", "b", "c"), (0.0, 6.0)), "curve"),
        (lambda: tv.ph_spline(HELIX, (0.0,)), "interval"),
        (lambda: tv.phodcos(HELIX, "01", segments=4), "interval"),
        (lambda: tv.phodcos(helix, (0, 1), segments=4), "curve"),
        (lambda: tv.convergence(HELIX, (0, 1), levels=[3, 2]), "levels"),
    ],
)
def test_hostile_curves_raise_a_value_error_naming_the_field(call, field):
    with pytest.raises(tv.TrajverifyError) as caught:
        call()
    assert field in str(caught.value), str(caught.value)


def test_an_exception_of_the_callable_reaches_the_caller():
    def broken(t):
        raise KeyError("inside the user's curve")

    with pytest.raises(KeyError, match="inside the user's curve"):
        tv.ph_spline(broken, (0.0, 1.0))


def test_a_convergence_study_proves_the_classical_order_of_cubic_hermite():
    study = tv.convergence(HELIX, ("0", "2"), method="hermite:1", levels=range(2, 7))
    assert study.expected_order == 4 and study.proven
    assert [lv.segments for lv in study.levels] == [4, 8, 16, 32, 64]
    for lv in study.levels:
        lower, upper = lv.error_proven
        assert 0 < lower <= upper and lv.status == "resolved"
        assert lower <= lv.error_f64 * (1 + 1e-9) and lv.error_f64 <= upper * (1 + 1e-9)
    assert study.fit.outcome == "fitted" and study.fit.expected_inside
    assert abs(study.fit.order - 4) <= study.fit.ci95 + 0.01
    assert "fitted order" in str(study) and study.svg.startswith("<svg")


@needs_cli
def test_a_convergence_study_is_the_command_line_report(tmp_path):
    study = tv.convergence(HELIX, ("-1", "1/2"), method="hermite:2", levels="1-4", scalar="ball:64")
    args = [str(CLI), "report", "convergence", "--curve", HELIX, "--interval", "-1", "1/2",
            "--method", "hermite:2", "--levels", "1-4", "--scalar", "ball:64", "--out", str(tmp_path)]
    subprocess.run(args, check=True, capture_output=True)
    assert study.doc == json.loads((tmp_path / "convergence.json").read_text())
    assert study.markdown == (tmp_path / "convergence.md").read_text()


def slow_helix(t):
    import time

    time.sleep(0.002)
    return helix(t)


def interrupt_after(seconds):
    import os
    import signal
    import threading

    # Python raises KeyboardInterrupt on SIGINT only if SIGINT was not ignored when it started;
    # a process started in the background by a non-interactive shell (a CI script run with
    # `nohup … &`) inherits it ignored. Install Python's own handler, as an interactive
    # interpreter has it, so that the test sends what a user's Ctrl-C sends.
    signal.signal(signal.SIGINT, signal.default_int_handler)
    timer = threading.Timer(seconds, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    return timer


@pytest.mark.parametrize(
    "call",
    [
        # κ₂ proven in 64-bit balls for m = 40: seconds of work (docs/limits.md).
        lambda out: tv.run("hermite-condition", {"derivatives": 40, "interval": [0, 1], "matrix": "transform"}, "ball:64"),
        # κ₂ at two MPFR precisions for m = 40: about 9 s of Jacobi sweeps.
        lambda out: tv.run("hermite-condition", {"derivatives": 40, "interval": [0, 1], "matrix": "transform"}, "mpfr:1024"),
        # A convergence study: about 6 s of conversions and proven maxima.
        lambda out: tv.run("convergence", {"curve": HELIX, "interval": [0, 6], "levels": [12, 13]}),
        # All five papers: about a minute.
        lambda out: tv.verify(out=out),
        # A slow Python curve (2 ms a jet) on 1000 segments.
        lambda out: tv.ph_spline(slow_helix, (0.0, 6.0), segments=1000),
    ],
)
def test_ctrl_c_stops_the_wait_at_once_and_the_work_soon_after(call, tmp_path):
    import time

    from trajverify._trajverify import python_workers, running_jobs

    out = tmp_path / "reports"
    started = time.perf_counter()
    interrupt_after(0.3)
    with pytest.raises(KeyboardInterrupt):
        call(str(out))
    assert time.perf_counter() - started < 1.5
    # The library's loops stop at their next checkpoint (trajverify::cancel): the work ends
    # within a fraction of a second (uninterrupted, each job above runs for seconds).
    interrupted = time.perf_counter()
    while running_jobs() + python_workers() > 0:
        assert time.perf_counter() - interrupted < 2.0, "the interrupted job is still running"
        time.sleep(0.01)
    # Nothing half written, and the package still answers afterwards.
    assert not out.exists() or not any(out.iterdir())
    assert tv.hermite([0.0, 1.0], [1.0, 1.0]).tolist()[1] == 1 / 3


def test_a_convergence_study_plots_with_matplotlib():
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    study = tv.convergence(HELIX, ("0", "2"), method="hermite:1", levels="2-4", scalar="ball:64")
    ax = study.plot()
    errors = ax.get_lines()[0].get_ydata()
    assert list(errors) == [lv.error for lv in study.levels]
    assert ax.get_xscale() == "log" and ax.get_yscale() == "log"


def test_the_interpreter_exits_cleanly_after_an_interrupted_python_curve():
    # A worker that asks for the GIL while Python 3.11 finalises would abort the process.
    import subprocess
    import sys

    script = """
import os, signal, threading, numpy as np, trajverify as tv
signal.signal(signal.SIGINT, signal.default_int_handler)  # even if started with SIGINT ignored
threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
try:
    tv.ph_spline(lambda t: (np.cos(t), np.sin(t), t / 5), (0, 6), segments=200000)
except KeyboardInterrupt:
    print("interrupted")
"""
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=60)
    assert done.returncode == 0 and done.stdout.strip() == "interrupted", done.stderr

