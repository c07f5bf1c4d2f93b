"""trajverify from Python: the algorithms of five trajectory papers and their claims ledger.

The f64 jobs run in process on numpy arrays (without the GIL); every algorithm of the command
line's ``trajverify run`` is reachable through :func:`run` in every number type, and
:func:`verify` checks the papers' claims. Floats are taken as the exact doubles they are (as
``fractions.Fraction(0.1)`` does); pass a ``Fraction`` or a decimal string for 1/10.

Errors are exceptions: :class:`TrajverifyError` (a ``ValueError``) names the field of the
input the library refuses; ``RuntimeError`` reports a method that failed on accepted input.
"""

from __future__ import annotations

import json
import math
import os
import tempfile
from decimal import Decimal
from fractions import Fraction
from typing import Any, List, NamedTuple, Optional, Sequence, Tuple, Union

import numpy as np

from ._trajverify import TrajverifyError
from ._trajverify import hermite_f64 as _hermite_f64
from ._trajverify import natural_spline_f64 as _natural_spline_f64
from ._trajverify import run as _run
from ._trajverify import verify as _verify

__all__ = [
    "Ball",
    "SplineJet",
    "TrajverifyError",
    "hermite",
    "hermite_batch",
    "natural_spline",
    "run",
    "verify",
]

Number = Union[int, float, Fraction, Decimal, str]


def exact_text(x: Any, field: str = "input") -> Union[str, int]:
    """The exact text of a Python number for the library's exact reader: ints as they are,
    fractions as ``n/d``, floats as their exact decimal expansion, strings unchanged."""
    if isinstance(x, (np.integer, np.floating)):
        x = x.item()
    if isinstance(x, bool):
        raise TrajverifyError(f'field "{field}": expected a number, found a boolean')
    if isinstance(x, int):
        return x
    if isinstance(x, Fraction):
        return f"{x.numerator}/{x.denominator}"
    if isinstance(x, float):
        if not math.isfinite(x):
            raise TrajverifyError(f'field "{field}": {x} is not a finite number')
        return str(Decimal(x))
    if isinstance(x, Decimal):
        if not x.is_finite():
            raise TrajverifyError(f'field "{field}": {x} is not a finite number')
        return str(x)
    if isinstance(x, str):
        return x
    raise TrajverifyError(f'field "{field}": expected a number, found {type(x).__name__}')


def _exact_tree(value: Any, field: str) -> Any:
    """A JSON-ready copy of `value` with every number replaced by its exact text."""
    if isinstance(value, dict):
        return {k: _exact_tree(v, f"{field}.{k}" if field else k) for k, v in value.items()}
    if isinstance(value, np.ndarray):
        value = value.tolist()
    if isinstance(value, (list, tuple)):
        return [_exact_tree(v, f"{field}[{i}]") for i, v in enumerate(value)]
    if isinstance(value, str) or value is None:
        return value
    return exact_text(value, field)


def run(algorithm: str, input: Union[dict, str], scalar: Optional[str] = None) -> dict:
    """The output of ``trajverify run <algorithm> [--scalar <scalar>]`` on `input` (a dict,
    whose numbers are read exactly, or a JSON document), as a dict: the same JSON, byte for
    byte, as the command line prints (see ``docs/commands.md`` for every algorithm).

    >>> run("hermite", {"start": [0, 1], "end": [1, 1], "interval": [0, 1]}, "rational")["control_points"]
    ['0', '1/3', '2/3', '1']
    """
    text = input if isinstance(input, str) else json.dumps(_exact_tree(input, ""))
    return json.loads(_run(algorithm, text, scalar))


class Ball:
    """A proven enclosure printed by a ``ball:<bits>`` run: every point of the true value's
    ball lies in [mid − rad, mid + rad], as printed (decimal strings kept exactly)."""

    __slots__ = ("value", "radius")

    def __init__(self, value: str, radius: str):
        self.value, self.radius = value, radius

    @property
    def mid(self) -> Fraction:
        return Fraction(self.value)

    @property
    def rad(self) -> Fraction:
        return Fraction(self.radius)

    @property
    def lower(self) -> Fraction:
        return self.mid - self.rad

    @property
    def upper(self) -> Fraction:
        return self.mid + self.rad

    def __contains__(self, x: Number) -> bool:
        q = x if isinstance(x, Fraction) else Fraction(exact_text(x))
        return self.lower <= q <= self.upper

    def to_arb(self):
        """The same ball as a python-flint ``arb`` (needs python-flint)."""
        import flint

        return flint.arb(self.value, self.radius)

    def __repr__(self) -> str:
        return f"Ball({self.value} ± {self.radius})"


def _number(text: Any, scalar: str) -> Any:
    """A printed number of a `scalar` run as a Python number."""
    if isinstance(text, dict) and "value" in text and "radius" in text:
        return Ball(text["value"], text["radius"])
    if isinstance(text, list):
        return [_number(t, scalar) for t in text]
    if scalar == "rational":
        return Fraction(text)
    if scalar.startswith("mpfr:"):
        try:
            import mpmath
        except ImportError:
            return text
        with mpmath.workprec(int(scalar.split(":")[1])):
            return mpmath.mpf(text)
    return float(text)


def _floats(values: Any, field: str) -> np.ndarray:
    """`values` as a contiguous float array, or the refusal naming `field`."""
    try:
        return np.ascontiguousarray(values, dtype=float)
    except (TypeError, ValueError) as e:
        raise TrajverifyError(f'field "{field}": expected numbers or points of one dimension ({e})') from None


def _as_rows(values: Any, field: str) -> Tuple[np.ndarray, bool]:
    """(rows of one column per coordinate, whether the entries were points)."""
    array = _floats(values, field)
    if array.ndim == 1:
        return array.reshape(-1, 1), False
    if array.ndim == 2:
        return array, True
    raise TrajverifyError(f'field "{field}": expected numbers or points, found a {array.ndim}-D array')


def hermite(start: Any, end: Any, interval: Sequence[Number] = (0.0, 1.0), scalar: str = "f64") -> Any:
    """Bernstein control points of the degree-(2m+1) polynomial with the m+1 derivatives
    `start` at t0 and `end` at t1 (paper 000; scipy's ``BPoly.from_derivatives`` for two
    times). `start[j]` is the j-th derivative, a number or a point.

    f64 returns a numpy array (degree+1, d), or (degree+1,) for numbers; other scalars
    (``"rational"``, ``"mpfr:<bits>"``, ``"ball:<bits>"``) return lists of Fractions, mpmath
    numbers or :class:`Ball` enclosures.

    >>> hermite([0.0, 1.0], [1.0, 1.0]).tolist()
    [0.0, 0.3333333333333333, 0.6666666666666666, 1.0]
    """
    if scalar != "f64":
        doc = {"start": start, "end": end, "interval": list(interval)}
        out = run("hermite", doc, scalar)
        return _number(out["control_points"], scalar)
    rows_start, points = _as_rows(start, "start")
    rows_end, _ = _as_rows(end, "end")
    t0, t1 = (float(x) for x in interval)
    points_out = _hermite_f64(rows_start, rows_end, t1 - t0)
    return points_out if points else points_out[:, 0]


def hermite_batch(start: Any, end: Any, interval: Sequence[float] = (0.0, 1.0)) -> np.ndarray:
    """:func:`hermite` in f64 for N problems at once: `start` and `end` of shape (N, m+1) or
    (N, m+1, d); returns (N, 2m+2) or (N, 2m+2, d). One call, one pass without the GIL."""
    s, e = _floats(start, "start"), _floats(end, "end")
    if s.shape != e.shape or s.ndim not in (2, 3):
        raise TrajverifyError(
            f'field "end": shape {e.shape} where "start" has {s.shape} (expected (N, m+1) or (N, m+1, d))'
        )
    scalar_points = s.ndim == 2
    if scalar_points:
        s, e = s[:, :, None], e[:, :, None]
    n, m1, d = s.shape
    # One problem of N·d coordinates: the map acts on each coordinate alone.
    flat = lambda a: np.ascontiguousarray(a.transpose(1, 0, 2).reshape(m1, n * d))
    t0, t1 = (float(x) for x in interval)
    points = _hermite_f64(flat(s), flat(e), t1 - t0)
    out = points.reshape(-1, n, d).transpose(1, 0, 2)
    return out[:, :, 0] if scalar_points else out


class SplineJet(NamedTuple):
    """Values, first and second derivatives at the evaluation points."""

    values: Any
    first: Any
    second: Any


def natural_spline(t: Any, z: Any, at: Any, scalar: str = "f64") -> SplineJet:
    """The natural cubic spline through (t_i, z_i) (paper 004, Eq. 2.3; scipy's
    ``CubicSpline(t, z, bc_type="natural")``) and its first two derivatives at `at`.

    f64 returns numpy arrays (len(at),) or (len(at), d) for points; other scalars lists.

    >>> natural_spline([0.0, 1.0, 2.0], [0.0, 1.0, 0.0], [0.5]).values.tolist()
    [0.6875]
    """
    if scalar != "f64":
        out = run("natural-spline", {"t": t, "z": z, "at": at}, scalar)
        return SplineJet(*(_number(out[k], scalar) for k in ("values", "first", "second")))
    rows, points = _as_rows(z, "z")
    jets = _natural_spline_f64(_floats(t, "t"), np.ascontiguousarray(rows), _floats(at, "at"))
    return SplineJet(*(j if points else j[:, 0] for j in jets))


def verify(papers: Optional[List[str]] = None, out: Optional[str] = None) -> dict:
    """Check the papers' claims (all five, or those named: ids or short names such as
    ``"marin"``) and return the ledger (``claims.json``: ``summary`` and ``claims``, one dict
    per claim with its published and reproduced values, assurance and verdict). The reports
    and figures are written to `out` (must not exist or be empty), or to a temporary
    directory that is removed."""
    if out is not None:
        _verify(os.fspath(out), papers)
        with open(os.path.join(out, "claims.json"), encoding="utf-8") as f:
            return json.load(f)
    with tempfile.TemporaryDirectory() as scratch:
        target = os.path.join(scratch, "reports")
        _verify(target, papers)
        with open(os.path.join(target, "claims.json"), encoding="utf-8") as f:
            return json.load(f)
