"""Pythagorean-hodograph splines (paper 001): a curve converted to C⁴ PH segments (Algorithm 2,
φ* = 0, the roll correction of Eq. 22), evaluated on numpy arrays with its exact arc length,
inverse arc length, Euler–Rodrigues frames and angular velocity ω.

:func:`ph_spline` converts in f64 in process; :func:`phodcos` runs the same conversion in any
number type through ``trajverify run phodcos`` (with the proven maximum error for mpfr and
ball).
"""

from __future__ import annotations

from typing import Any, Callable, NamedTuple, Optional, Sequence, Tuple, Union

import numpy as np

from ._cli import run
from ._jet import jet_function
from ._numbers import exact_text, floats, from_text, from_texts
from ._trajverify import TrajverifyError
from ._trajverify import ph_fit as _ph_fit

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
    """A piecewise PH spline in f64 built by :func:`ph_spline`: a curve of t on [a, b].

    Evaluation takes a number or an array of parameters and returns arrays of that shape with
    trailing axes for the coordinates. A parameter outside [a, b] raises
    :class:`TrajverifyError`.
    """

    def __init__(self, native: Any):
        self._native = native

    @property
    def interval(self) -> Tuple[float, float]:
        """(a, b)."""
        return self._native.interval()

    @property
    def segments(self) -> int:
        """The number N of uniform segments."""
        return self._native.segments()

    @property
    def sampled_error(self) -> float:
        """The conversion error max‖γ − p‖ (Eq. 21) measured after the fit: the maximum of 16
        samples per segment refined by Newton's method, an estimate, not a bound (for a proven
        bound use :func:`phodcos` with ``scalar="ball:128"``, or :func:`trajverify.convergence`)."""
        return self._native.sampled_error()

    @property
    def length(self) -> float:
        """The whole arc length, exact up to rounding (the speed of a PH curve is a polynomial)."""
        return self._native.length()

    def __call__(self, t: Any) -> np.ndarray:
        """γ(t): shape t.shape + (3,)."""
        return self.derivative(t, 0)

    def derivatives(self, t: Any, order: int = 1) -> np.ndarray:
        """γ(t), γ′(t), …, γ⁽ᵒʳᵈᵉʳ⁾(t): shape t.shape + (order + 1, 3)."""
        flat, shape = _parameters(t, "t")
        return self._native.derivatives(flat, int(order)).reshape(shape + (order + 1, 3))

    def derivative(self, t: Any, k: int = 1) -> np.ndarray:
        """γ⁽ᵏ⁾(t): shape t.shape + (3,)."""
        return self.derivatives(t, k)[..., k, :]

    def arc_length(self, t: Any) -> np.ndarray:
        """s(t) = ∫ₐᵗ |γ′|, exact up to rounding: shape t.shape."""
        flat, shape = _parameters(t, "t")
        return self._native.arc_length(flat).reshape(shape)

    def parameter_at_length(self, s: Any, tolerance: float = 1e-12) -> np.ndarray:
        """The parameter t with s(t) = s (for constant-speed trajectories), to |s(t) − s| ≤
        `tolerance`, by safeguarded Newton on the exact arc length: shape s.shape."""
        flat, shape = _parameters(s, "s")
        return self._native.parameter_at_length(flat, float(tolerance)).reshape(shape)

    def frames(self, t: Any) -> Frames:
        """The Euler–Rodrigues frames and ω at t (see :class:`Frames`)."""
        flat, shape = _parameters(t, "t")
        rows = self._native.frames(flat).reshape(shape + (16,))
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
        return self._native.control_points().reshape(self.segments, -1, 3)

    @property
    def preimages(self) -> np.ndarray:
        """The preimage A(ξ) of every segment as Bernstein coefficients, quaternions (w, x, y, z):
        shape (N, preimage degree + 1, 4)."""
        return self._native.preimages().reshape(self.segments, -1, 4)

    def __repr__(self) -> str:
        a, b = self.interval
        return f"PhSpline([{a}, {b}], {self.segments} segments, sampled error {self.sampled_error:.3g})"


def ph_spline(
    curve: CurveSpec,
    interval: Sequence[float],
    segments: int = 8,
    tolerance: Optional[float] = None,
    derivatives: int = 4,
    roll: bool = True,
) -> PhSpline:
    """The C⁴ PH spline of `curve` on `interval` in f64 (paper 001, Algorithm 2; the library's
    ``fit`` with its defaults): `segments` uniform segments, or with `tolerance` doubled from
    there until the sampled error is at most `tolerance`; `derivatives` = m matched at every
    joint (degree-(4m+1) segments); `roll` applies Eq. 22 so the frame and ω are continuous.

    `curve` is an expression ``"[x(t), y(t), z(t)]"`` (numbers, t, pi, + - * / ^, sin cos tan
    exp ln sqrt atan) or a Python callable ``f(t) -> (x, y, z)`` written with arithmetic and
    numpy functions: its derivatives are taken by Taylor arithmetic, exactly up to rounding.

    >>> import numpy as np
    >>> helix = ph_spline(lambda t: (np.cos(t), np.sin(t), t / 5), (0.0, 6.0), segments=32)
    >>> round(float(helix.length), 9) == round(6 * 1.04 ** 0.5, 9)
    True
    """
    a, b = (float(x) for x in interval)
    if isinstance(curve, str):
        spec: Any = curve
    elif callable(curve):
        spec = jet_function(curve)
    else:
        raise TrajverifyError(f"curve: expected an expression string or a callable, found {type(curve).__name__}")
    if isinstance(segments, bool) or not isinstance(segments, (int, np.integer)) or segments < 1:
        raise TrajverifyError(f"segments: expected a positive integer, found {segments!r}")
    if isinstance(derivatives, bool) or not isinstance(derivatives, (int, np.integer)) or derivatives < 1:
        raise TrajverifyError(f"derivatives: expected a positive integer, found {derivatives!r}")
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
    `interval` (numbers or constants such as ``"4*pi"``, read exactly) in any number type,
    with `segments` or a `tolerance` (then at most `max_segments`, default 4096)."""
    doc: dict = {"curve": curve, "interval": [exact_text(x, "interval") for x in interval]}
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
