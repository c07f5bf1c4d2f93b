"""Pythagorean-hodograph splines (paper 001): a curve converted to C⁴ PH segments (Algorithm 2,
φ* = 0, the roll correction of Eq. 22), evaluated on numpy arrays with its exact arc length,
inverse arc length, Euler–Rodrigues frames and angular velocity ω.

:func:`ph_spline` converts in f64 in process; :func:`phodcos` runs the same conversion in any
number type through ``trajverify run phodcos`` (with the proven maximum error for mpfr and
ball).
"""

from __future__ import annotations

import atexit
import time
from typing import Any, Callable, NamedTuple, Optional, Sequence, Tuple, Union

import numpy as np

from ._cli import run
from ._jet import jet_function
from ._numbers import exact_text, floats, from_text, from_texts, interval_floats, pair, scalar_name
from ._trajverify import TrajverifyError
from ._trajverify import ph_fit as _ph_fit
from ._trajverify import ph_fit_ball as _ph_fit_ball
from ._trajverify import python_workers as _python_workers


@atexit.register
def _wait_for_python_curves(timeout: float = 30.0) -> None:
    """At exit, let an interrupted conversion of a Python curve finish its current call (it
    answers NaN to the rest, so this is short): Python 3.11 ends a thread that asks for the
    GIL during finalisation in a way that aborts the process."""
    deadline = time.monotonic() + timeout
    while _python_workers() > 0 and time.monotonic() < deadline:
        time.sleep(0.01)

CurveSpec = Union[str, Callable[[Any], Sequence[Any]]]


class Frames(NamedTuple):
    """The Euler–Rodrigues frame along the spline (paper 001, Eqs. 11–12), per parameter."""

    points: np.ndarray
    """γ(t), shape (…, 3)."""
    axes: np.ndarray
    """Rows e₁ (the unit tangent), e₂, e₃, shape (…, 3, 3)."""
    omega: np.ndarray
    """The angular velocity per unit of t in world coordinates (ėₖ = ω × eₖ), shape (…, 3)."""
    speed: np.ndarray
    """The parametric speed |γ′(t)|, shape (…)."""


def _parameters(t: Any, field: str) -> Tuple[np.ndarray, Tuple[int, ...]]:
    """The parameters flat, and the shape of `t` (``()`` for a number)."""
    return floats(t, field).reshape(-1), np.shape(t)


class PhSpline:
    """A piecewise PH spline built by :func:`ph_spline`: a curve of t on [a, b].

    Evaluation takes a number or an array of parameters and returns arrays of that shape with
    trailing axes for the coordinates: float arrays for f64; for ``"ball:<bits>"`` object
    arrays of :class:`Ball` (proven enclosures, as ``run`` prints them) and for
    ``"mpfr:<bits>"`` of ``mpmath.mpf`` holding the digits those balls prove. A parameter
    outside [a, b] raises :class:`TrajverifyError`.
    """

    def __init__(self, native: Any, scalar: str = "f64", interval: Any = None):
        self._native = native
        self.scalar = scalar
        self._interval = interval

    @property
    def _f64(self) -> bool:
        return self.scalar == "f64"

    def _values(self, printed: list, shape: Tuple[int, ...]) -> np.ndarray:
        """Printed balls (value, radius) as an object array of the scalar's numbers."""
        out = np.empty(len(printed), dtype=object)
        for i, (value, radius) in enumerate(printed):
            out[i] = from_text({"value": value, "radius": radius} if self.scalar.startswith("ball:") else value, self.scalar)
        return out.reshape(shape)

    def _texts(self, t: Any, field: str) -> Tuple[list, Tuple[int, ...]]:
        array = np.asarray(t, dtype=object)
        return [str(exact_text(x, field)) for x in array.reshape(-1)], array.shape

    @property
    def interval(self) -> Tuple[Any, Any]:
        """(a, b)."""
        return self._native.interval() if self._f64 else self._interval

    @property
    def segments(self) -> int:
        """The number N of uniform segments."""
        return self._native.segments()

    @property
    def sampled_error(self) -> Optional[float]:
        """The conversion error max‖γ − p‖ (Eq. 21) measured after an f64 fit: the maximum of
        16 samples per segment refined by Newton's method, an estimate, not a bound (None in
        balls; for a proven bound use :func:`phodcos` with ``scalar="ball:128"``, or
        :func:`trajverify.convergence`)."""
        return self._native.sampled_error() if self._f64 else None

    @property
    def length(self) -> Any:
        """The whole arc length, exact up to rounding (the speed of a PH curve is a polynomial)."""
        if self._f64:
            return self._native.length()
        return self._values([self._native.length()], ())[()]

    def __call__(self, t: Any) -> np.ndarray:
        """γ(t): shape t.shape + (3,)."""
        return self.derivative(t, 0)

    def derivatives(self, t: Any, order: int = 1) -> np.ndarray:
        """γ(t), γ′(t), …, γ⁽ᵒʳᵈᵉʳ⁾(t): shape t.shape + (order + 1, 3)."""
        if isinstance(order, bool) or not isinstance(order, (int, np.integer)) or not 0 <= order <= 64:
            raise TrajverifyError(f"order: expected a whole number from 0 to 64, found {order!r}")
        if not self._f64:
            texts, shape = self._texts(t, "t")
            return self._values(self._native.derivatives(texts, int(order)), shape + (order + 1, 3))
        flat, shape = _parameters(t, "t")
        return self._native.derivatives(flat, int(order)).reshape(shape + (order + 1, 3))

    def derivative(self, t: Any, k: int = 1) -> np.ndarray:
        """γ⁽ᵏ⁾(t): shape t.shape + (3,)."""
        return self.derivatives(t, k)[..., k, :]

    def arc_length(self, t: Any) -> np.ndarray:
        """s(t) = ∫ₐᵗ |γ′|, exact up to rounding: shape t.shape."""
        if not self._f64:
            texts, shape = self._texts(t, "t")
            return self._values(self._native.arc_length(texts), shape)
        flat, shape = _parameters(t, "t")
        return self._native.arc_length(flat).reshape(shape)

    def parameter_at_length(self, s: Any, tolerance: float = 1e-12) -> np.ndarray:
        """The parameter t with s(t) = s (for constant-speed trajectories), to |s(t) − s| ≤
        `tolerance`, by safeguarded Newton on the exact arc length: shape s.shape (f64)."""
        if not self._f64:
            raise TrajverifyError(f"scalar: parameter_at_length is a search in f64; this spline is {self.scalar}")
        flat, shape = _parameters(s, "s")
        return self._native.parameter_at_length(flat, float(tolerance)).reshape(shape)

    def frames(self, t: Any) -> Frames:
        """The Euler–Rodrigues frames and ω at t (see :class:`Frames`)."""
        if self._f64:
            flat, shape = _parameters(t, "t")
            rows = self._native.frames(flat).reshape(shape + (16,))
        else:
            texts, shape = self._texts(t, "t")
            rows = self._values(self._native.frames(texts), shape + (16,))
        return Frames(
            rows[..., 0:3],
            rows[..., 3:12].reshape(shape + (3, 3)),
            rows[..., 12:15],
            rows[..., 15],
        )

    @property
    def control_points(self) -> np.ndarray:
        """The Bézier control points of every segment, shape (N, degree + 1, 3); segment k in
        its local parameter ξ = (t − t_k)/h ∈ [0, 1]."""
        if self._f64:
            return self._native.control_points().reshape(self.segments, -1, 3)
        flat = self._native.control_points()
        return self._values(flat, (self.segments, len(flat) // (3 * self.segments), 3))

    @property
    def preimages(self) -> np.ndarray:
        """The preimage A(ξ) of every segment as Bernstein coefficients, quaternions (w, x, y, z):
        shape (N, preimage degree + 1, 4)."""
        if self._f64:
            return self._native.preimages().reshape(self.segments, -1, 4)
        flat = self._native.preimages()
        return self._values(flat, (self.segments, len(flat) // (4 * self.segments), 4))

    def __repr__(self) -> str:
        a, b = self.interval
        error = "" if self.sampled_error is None else f", sampled error {self.sampled_error:.3g}"
        return f"PhSpline([{a}, {b}], {self.segments} segments, {self.scalar}{error})"


def ph_spline(
    curve: CurveSpec,
    interval: Sequence[Any],
    segments: int = 8,
    tolerance: Optional[float] = None,
    derivatives: int = 4,
    roll: bool = True,
    scalar: Optional[str] = "f64",
) -> PhSpline:
    """The C⁴ PH spline of `curve` on `interval` (paper 001, Algorithm 2; the library's ``fit``
    with its defaults): `segments` uniform segments, or with `tolerance` doubled from there
    until the sampled error is at most `tolerance`; `derivatives` = m matched at every joint
    (degree-(4m+1) segments); `roll` applies Eq. 22 so the frame and ω are continuous.

    `curve` is an expression ``"[x(t), y(t), z(t)]"`` (numbers, t, pi, + - * / ^, sin cos tan
    exp ln sqrt atan) or a Python callable ``f(t) -> (x, y, z)`` written with arithmetic and
    numpy functions: its derivatives are taken by Taylor arithmetic, exactly up to rounding.

    `scalar` ``"f64"`` (the default) converts in doubles; ``"ball:<bits>"`` converts an
    expression in ball arithmetic on the exact interval (its ends read exactly), so that every
    number the spline gives is a proven enclosure of what exact arithmetic would give for
    that conversion, and ``"mpfr:<bits>"`` returns those balls' proven digits as mpmath numbers.
    In balls the number of segments is given (no `tolerance`: the sampled error is an f64
    search).

    There is no work budget: an expression converts 65536 segments in about half a second, but
    a Python callable is called for every joint and every sample of the error search (about
    20 calls a segment), so its time is the user's code's; Ctrl-C stops it.

    >>> import numpy as np
    >>> helix = ph_spline(lambda t: (np.cos(t), np.sin(t), t / 5), (0.0, 6.0), segments=32)
    >>> round(float(helix.length), 9) == round(6 * 1.04 ** 0.5, 9)
    True
    """
    if isinstance(segments, bool) or not isinstance(segments, (int, np.integer)) or not 1 <= segments < 2**32:
        raise TrajverifyError(f"segments: expected a positive integer below 2^32, found {segments!r}")
    if isinstance(derivatives, bool) or not isinstance(derivatives, (int, np.integer)) or not 1 <= derivatives < 2**32:
        raise TrajverifyError(f"derivatives: expected a positive integer, found {derivatives!r}")
    scalar = scalar_name(scalar)
    if scalar != "f64":
        kind, _, bits = scalar.partition(":")
        if kind not in ("mpfr", "ball") or not bits.isdigit() or not 2 <= int(bits) <= 1 << 16:
            raise TrajverifyError(f'scalar: expected "f64", "mpfr:<bits>" or "ball:<bits>", found {scalar!r}')
        if not isinstance(curve, str):
            raise TrajverifyError("curve: a conversion in balls needs an expression (a callable is differentiated in doubles)")
        if tolerance is not None:
            raise TrajverifyError("tolerance: only with scalar f64 (the sampled error is an f64 search); give segments")
        ends = tuple(str(exact_text(x, "interval")) for x in pair(interval, "interval"))
        native = _ph_fit_ball(curve, ends, int(segments), int(derivatives), bool(roll), int(bits))
        return PhSpline(native, scalar, ends)
    a, b = interval_floats(interval)
    if isinstance(curve, str):
        spec: Any = curve
    elif callable(curve):
        spec = jet_function(curve)
    else:
        raise TrajverifyError(f"curve: expected an expression string or a callable, found {type(curve).__name__}")
    tol = None if tolerance is None else float(tolerance)
    return PhSpline(_ph_fit(spec, (a, b), int(segments), tol, int(derivatives), bool(roll)))


class Phodcos(NamedTuple):
    """A PHODCOS conversion from :func:`phodcos`."""

    segments: int
    max_error: Any
    """The conversion error: proven by branch and bound for mpfr and ball (digits of the
    enclosure, or a :class:`Ball`), the sampled maximum for f64."""
    sampled_error: Any
    """The sampled maximum (f64 only; None otherwise)."""
    preimages: list
    """Per segment the 9 Bernstein coefficients of A(ξ), each [u, v, p, q]."""


def phodcos(
    curve: str,
    interval: Sequence[Any],
    segments: Optional[int] = None,
    tolerance: Any = None,
    max_segments: Optional[int] = None,
    scalar: str = "f64",
) -> Phodcos:
    """``trajverify run phodcos``: `curve` (an expression) converted to C⁴ PH segments on
    `interval` (numbers, read exactly) in any number type, with `segments` or a `tolerance`
    (then at most `max_segments`, default 4096)."""
    if not isinstance(curve, str):
        raise TrajverifyError("curve: phodcos needs an expression string (ph_spline takes a Python callable)")
    doc: dict = {"curve": curve, "interval": [exact_text(x, "interval") for x in pair(interval, "interval")]}
    if segments is not None:
        doc["segments"] = segments
    if tolerance is not None:
        doc["tolerance"] = exact_text(tolerance, "tolerance")
    if max_segments is not None:
        doc["max_segments"] = max_segments
    out = run("phodcos", doc, scalar)
    s, sampled = out["scalar"], out.get("sampled_error")
    return Phodcos(
        out["segments"],
        from_text(out["max_error"], s),
        None if sampled is None else from_text(sampled, s),
        from_texts(out["preimages"], s),
    )
