"""Numbers between Python and the library: the exact text of a Python number, the printed
numbers of each scalar as Python numbers (``Fraction``, ``mpmath.mpf``, :class:`Ball`), and
numpy arrays checked for shape."""

from __future__ import annotations

import math
from decimal import Decimal
from fractions import Fraction
from typing import Any, Tuple, Union

import numpy as np

from ._trajverify import TrajverifyError

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


def exact_tree(value: Any, field: str) -> Any:
    """A JSON-ready copy of `value` with every number replaced by its exact text."""
    if isinstance(value, dict):
        return {k: exact_tree(v, f"{field}.{k}" if field else k) for k, v in value.items()}
    if isinstance(value, np.ndarray):
        value = value.tolist()
    if isinstance(value, (list, tuple)):
        return [exact_tree(v, f"{field}[{i}]") for i, v in enumerate(value)]
    if isinstance(value, str) or value is None:
        return value
    return exact_text(value, field)


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

    def __float__(self) -> float:
        """The midpoint rounded to a double."""
        return float(self.mid)

    def to_arb(self):
        """The same ball as a python-flint ``arb`` (needs python-flint): the printed midpoint
        is read at a precision that holds all its digits (python-flint's default of 53 bits
        would widen a 128-bit ball to 1e-16), and any rounding of it is added to the radius."""
        import flint

        digits = sum(c.isdigit() for c in self.value)
        with flint.ctx.workprec(max(53, int(digits * 3.33) + 64)):
            return flint.arb(self.value, self.radius)

    def __repr__(self) -> str:
        return f"Ball({self.value} ± {self.radius})"


def from_text(text: Any, scalar: str) -> Any:
    """A printed number (or nested lists of them) of a `scalar` run as Python numbers: floats
    for f64, ``Fraction`` for rational, ``mpmath.mpf`` at the run's precision for mpfr (the
    decimal string when mpmath is absent), :class:`Ball` for ball."""
    if isinstance(text, dict) and "value" in text and "radius" in text:
        return Ball(text["value"], text["radius"])
    if isinstance(text, list):
        return [from_text(t, scalar) for t in text]
    if scalar == "rational":
        return Fraction(text)
    if scalar.startswith("ball:"):
        return Ball(text, "0")  # a number a ball run prints plainly is exact
    if scalar.startswith("mpfr:"):
        try:
            import mpmath
        except ImportError:
            return text
        with mpmath.workprec(int(scalar.split(":")[1])):
            return mpmath.mpf(text)
    return float(text)


def _to_float(x: Any, field: str) -> Any:
    """A number, or nested lists of them, as floats: strings such as "1/3" or "1e-3" are read
    exactly, then rounded once (``float(Fraction)`` rounds correctly)."""
    if isinstance(x, (list, tuple, np.ndarray)):
        return [_to_float(v, field) for v in x]
    if isinstance(x, str):
        try:
            return float(Fraction(x))
        except (ValueError, ZeroDivisionError):
            raise TrajverifyError(f'field "{field}": "{x}" is not a number') from None
    return x


def floats(values: Any, field: str) -> np.ndarray:
    """`values` as a contiguous float array, or the refusal naming `field`."""
    try:
        return np.ascontiguousarray(values, dtype=float)
    except (TypeError, ValueError):
        pass
    try:
        return np.ascontiguousarray(_to_float(values, field), dtype=float)
    except (TypeError, ValueError) as e:
        raise TrajverifyError(f'field "{field}": expected numbers or points of one dimension ({e})') from None


def vector(values: Any, field: str) -> np.ndarray:
    """`values` as a 1-D float array, or the refusal naming `field`."""
    array = floats(values, field)
    if array.ndim != 1:
        raise TrajverifyError(f'field "{field}": expected a list of numbers, found an array of shape {array.shape}')
    return array


def pair(values: Any, field: str) -> Tuple[Any, Any]:
    """The two ends of an interval, or the refusal naming `field`."""
    if isinstance(values, (str, bytes)) or not hasattr(values, "__len__") or len(values) != 2:
        raise TrajverifyError(f'field "{field}": expected two ends [t0, t1], found {values!r}')
    return values[0], values[1]


def interval_floats(values: Any, field: str = "interval") -> Tuple[float, float]:
    """The two ends of an interval as doubles (exact strings such as "1/3" rounded once)."""
    a, b = pair(values, field)
    ends = floats([a, b], field)
    return float(ends[0]), float(ends[1])


def points(values: Any, field: str) -> list:
    """A list of points (each a list of numbers), or the refusal naming `field`."""
    if isinstance(values, np.ndarray):
        values = values.tolist()
    try:
        rows = [list(p) for p in values]
    except TypeError:
        raise TrajverifyError(f'field "{field}": expected a list of points [[x, y, ...], ...]') from None
    return rows


def scalar_name(scalar: Any, default: str = "f64") -> str:
    """The number type asked for (None: `default`), or the refusal naming the argument."""
    if scalar is None:
        return default
    if not isinstance(scalar, str):
        raise TrajverifyError(f'scalar: expected "f64", "rational", "mpfr:<bits>" or "ball:<bits>", found {scalar!r}')
    return scalar


def as_rows(values: Any, field: str) -> Tuple[np.ndarray, bool]:
    """(rows of one column per coordinate, whether the entries were points)."""
    array = floats(values, field)
    if array.ndim == 1:
        return array.reshape(-1, 1), False
    if array.ndim == 2:
        return array, True
    raise TrajverifyError(f'field "{field}": expected numbers or points, found a {array.ndim}-D array')


def from_texts(texts: Any, scalar: str) -> Any:
    """:func:`from_text` for a list of printed numbers: a float numpy array for f64 (nested
    lists of one shape become its axes), Python lists otherwise."""
    values = from_text(texts, scalar)
    if scalar == "f64" and isinstance(values, list):
        return np.array(values, dtype=float)
    return values
