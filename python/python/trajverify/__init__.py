"""trajverify from Python: the algorithms of five trajectory papers and their claims ledger.

The f64 jobs run in process on numpy arrays (without the GIL): :func:`hermite`,
:func:`hermite_batch`, :func:`natural_spline` and :func:`ph_spline` (a curve given as an
expression or a Python callable, with evaluation, exact arc length, frames and ω). Every other
job is a typed function over the command line's ``trajverify run`` in every number type
(:mod:`trajverify.jobs`: GERBS, Dubins, Marin, B-spline fits, bang-bang, one PH segment;
:func:`phodcos`); :func:`run` reaches any algorithm with a dict; :func:`convergence` studies a
curve with proven errors; :func:`verify` checks the papers' claims. Floats are taken as the exact doubles they are (as
``fractions.Fraction(0.1)`` does); pass a ``Fraction`` or a decimal string for 1/10.

Errors are exceptions: :class:`TrajverifyError` (a ``ValueError``) names the field of the
input the library refuses; ``RuntimeError`` reports a method that failed on accepted input.
"""

from __future__ import annotations

import json
import os
import tempfile
from typing import Any, List, NamedTuple, Optional, Sequence

import numpy as np

from ._cli import command, run
from ._numbers import (
    Ball,
    Number,
    as_rows,
    exact_text,
    floats,
    from_text,
    interval_floats,
    pair,
    scalar_name,
    vector,
)
from ._trajverify import TrajverifyError
from ._trajverify import hermite_f64 as _hermite_f64
from ._trajverify import natural_spline_f64 as _natural_spline_f64
from .convergence import ConvergenceStudy, convergence
from .jobs import (
    bang_bang,
    bspline_basis,
    bspline_gram,
    dubins,
    gerbs_basis,
    gerbs_path,
    marin,
    marin_1d,
    ph_hermite,
    spline_fit,
)
from .ledger import Claim, Ledger
from .ph import Frames, PhSpline, ph_spline, phodcos

__version__ = "0.1.0"

__all__ = [
    "Ball",
    "Claim",
    "ConvergenceStudy",
    "Frames",
    "Ledger",
    "PhSpline",
    "SplineJet",
    "TrajverifyError",
    "bang_bang",
    "bspline_basis",
    "bspline_gram",
    "command",
    "convergence",
    "dubins",
    "exact_text",
    "gerbs_basis",
    "gerbs_path",
    "hermite",
    "hermite_batch",
    "marin",
    "marin_1d",
    "natural_spline",
    "ph_hermite",
    "ph_spline",
    "phodcos",
    "run",
    "spline_fit",
    "verify",
]

def hermite(start: Any, end: Any, interval: Sequence[Number] = (0.0, 1.0), scalar: Optional[str] = "f64") -> Any:
    """Bernstein control points of the degree-(2m+1) polynomial with the m+1 derivatives
    `start` at t0 and `end` at t1 (paper 000; scipy's ``BPoly.from_derivatives`` for two
    times). `start[j]` is the j-th derivative, a number or a point.

    f64 returns a numpy array (degree+1, d), or (degree+1,) for numbers; other scalars
    (``"rational"``, ``"mpfr:<bits>"``, ``"ball:<bits>"``) return lists of Fractions, mpmath
    numbers or :class:`Ball` enclosures.

    >>> hermite([0.0, 1.0], [1.0, 1.0]).tolist()
    [0.0, 0.3333333333333333, 0.6666666666666666, 1.0]
    """
    scalar = scalar_name(scalar)
    if scalar != "f64":
        doc = {"start": start, "end": end, "interval": list(pair(interval, "interval"))}
        out = run("hermite", doc, scalar)
        return from_text(out["control_points"], scalar)
    rows_start, points = as_rows(start, "start")
    rows_end, _ = as_rows(end, "end")
    t0, t1 = interval_floats(interval)
    points_out = _hermite_f64(rows_start, rows_end, t1 - t0)
    return points_out if points else points_out[:, 0]


def hermite_batch(start: Any, end: Any, interval: Sequence[float] = (0.0, 1.0)) -> np.ndarray:
    """:func:`hermite` in f64 for N problems at once: `start` and `end` of shape (N, m+1) or
    (N, m+1, d); returns (N, 2m+2) or (N, 2m+2, d). One call, one pass without the GIL."""
    s, e = floats(start, "start"), floats(end, "end")
    if s.ndim not in (2, 3):
        raise TrajverifyError(f'field "start": expected shape (N, m+1) or (N, m+1, d), found {s.shape}')
    if s.shape != e.shape:
        raise TrajverifyError(f'field "end": shape {e.shape} where "start" has {s.shape}')
    if s.shape[0] == 0:
        raise TrajverifyError('field "start": no problems (N = 0)')
    scalar_points = s.ndim == 2
    if scalar_points:
        s, e = s[:, :, None], e[:, :, None]
    n, m1, d = s.shape
    # One problem of N·d coordinates: the map acts on each coordinate alone.
    flat = lambda a: np.ascontiguousarray(a.transpose(1, 0, 2).reshape(m1, n * d))
    t0, t1 = interval_floats(interval)
    points = _hermite_f64(flat(s), flat(e), t1 - t0)
    out = points.reshape(-1, n, d).transpose(1, 0, 2)
    return out[:, :, 0] if scalar_points else out


class SplineJet(NamedTuple):
    """Values, first and second derivatives at the evaluation points."""

    values: Any
    first: Any
    second: Any


def natural_spline(t: Any, z: Any, at: Any, scalar: Optional[str] = "f64") -> SplineJet:
    """The natural cubic spline through (t_i, z_i) (paper 004, Eq. 2.3; scipy's
    ``CubicSpline(t, z, bc_type="natural")``) and its first two derivatives at `at`.

    f64 returns numpy arrays (len(at),) or (len(at), d) for points; other scalars lists.

    >>> natural_spline([0.0, 1.0, 2.0], [0.0, 1.0, 0.0], [0.5]).values.tolist()
    [0.6875]
    """
    scalar = scalar_name(scalar)
    if scalar != "f64":
        out = run("natural-spline", {"t": t, "z": z, "at": at}, scalar)
        return SplineJet(*(from_text(out[k], scalar) for k in ("values", "first", "second")))
    rows, points = as_rows(z, "z")
    jets = _natural_spline_f64(vector(t, "t"), np.ascontiguousarray(rows), vector(at, "at"))
    return SplineJet(*(j if points else j[:, 0] for j in jets))


def _verify(out: str, papers: Optional[List[str]]) -> None:
    args = ["verify", "--out", out]
    for paper in [papers] if isinstance(papers, str) else papers or []:
        args += ["--paper", paper]
    command(args)


def verify(papers: Optional[List[str]] = None, out: Optional[str] = None) -> Ledger:
    """Check the papers' claims (all five, or those named: ids or short names such as
    ``"marin"``) and return the ledger (``claims.json`` as a :class:`Ledger`: a dict with
    ``summary`` and ``claims`` as JSON records; ``ledger.claims`` gives them as :class:`Claim`
    objects). `papers` is a list, or one name. The reports and figures are written to `out`
    (which must not exist or be empty), or to a temporary directory that is removed."""
    if out is not None:
        if os.path.isdir(out) and os.listdir(out):
            raise TrajverifyError(f"out: {os.fspath(out)} is not empty (give a new or an empty directory)")
        _verify(os.fspath(out), papers)
        with open(os.path.join(out, "claims.json"), encoding="utf-8") as f:
            return Ledger(json.load(f))
    with tempfile.TemporaryDirectory() as scratch:
        target = os.path.join(scratch, "reports")
        _verify(target, papers)
        with open(os.path.join(target, "claims.json"), encoding="utf-8") as f:
            return Ledger(json.load(f))
