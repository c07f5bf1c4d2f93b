"""Taylor arithmetic: the derivatives of a Python callable of t, exact up to rounding.

A :class:`Jet` is a truncated Taylor series c_0 + c_1 h + … + c_n h^n of a function at t
(c_k = f⁽ᵏ⁾(t)/k!). Calling the user's curve with the jet of the identity, [t, 1, 0, …],
runs its own arithmetic on series: each operation is the classical recurrence of automatic
differentiation (Griewank & Walther, *Evaluating Derivatives*, ch. 13), so the k-th derivative
comes out as k!·c_k with the rounding of ordinary arithmetic — no finite differences, no step
size. The library's own expressions are differentiated the same way in Rust
(``curve::taylor``).

The callable may use + − × ÷, powers and numpy's functions (``np.sin``, ``np.exp``, …, which
numpy hands to the jet through ``__array_ufunc__``). ``math.sin`` cannot see a jet and raises
``TypeError``: a jet deliberately has no ``__float__``, which would drop the derivatives
silently.
"""

from __future__ import annotations

import math
from typing import Any, Callable, List, Sequence

import numpy as np

from ._trajverify import TrajverifyError


def _div(x: float, y: float) -> float:
    """x / y, NaN for y = 0 (a pole: the library reports the curve not finite there)."""
    return x / y if y != 0 else math.nan


def _at(f: Callable[[float], float], x: float) -> float:
    """f(x), or NaN outside f's domain or range (as numpy gives): the library then reports
    where the curve is not finite, naming the segment, rather than a math domain error."""
    try:
        return float(f(x))
    except (ValueError, OverflowError, ZeroDivisionError):
        return math.nan


class Jet:
    """The Taylor coefficients c_0 … c_n of a function at a point."""

    __slots__ = ("c",)

    def __init__(self, c: Sequence[float]):
        self.c = [float(x) for x in c]

    # ----- construction -----
    def _lift(self, other: Any) -> "Jet":
        if isinstance(other, Jet):
            return other
        if isinstance(other, (int, float, np.integer, np.floating)):
            return Jet([float(other)] + [0.0] * (len(self.c) - 1))
        raise TypeError(f"a jet cannot be combined with {type(other).__name__}")

    @staticmethod
    def _series(n: int) -> List[float]:
        return [0.0] * n

    # ----- arithmetic -----
    def __add__(self, other: Any) -> "Jet":
        o = self._lift(other)
        return Jet([a + b for a, b in zip(self.c, o.c)])

    __radd__ = __add__

    def __sub__(self, other: Any) -> "Jet":
        o = self._lift(other)
        return Jet([a - b for a, b in zip(self.c, o.c)])

    def __rsub__(self, other: Any) -> "Jet":
        return self._lift(other) - self

    def __neg__(self) -> "Jet":
        return Jet([-a for a in self.c])

    def __pos__(self) -> "Jet":
        return self

    def __mul__(self, other: Any) -> "Jet":
        if not isinstance(other, Jet):
            o = self._lift(other).c[0]
            return Jet([a * o for a in self.c])
        a, b = self.c, other.c
        return Jet([sum(a[j] * b[k - j] for j in range(k + 1)) for k in range(len(a))])

    __rmul__ = __mul__

    def __truediv__(self, other: Any) -> "Jet":
        b = self._lift(other).c
        a, q = self.c, self._series(len(self.c))
        for k in range(len(a)):
            q[k] = _div(a[k] - sum(b[j] * q[k - j] for j in range(1, k + 1)), b[0])
        return Jet(q)

    def __rtruediv__(self, other: Any) -> "Jet":
        return self._lift(other) / self

    def __pow__(self, p: Any) -> "Jet":
        if isinstance(p, Jet):
            return (self.log() * p).exp()
        if isinstance(p, (int, np.integer)) or (isinstance(p, float) and p.is_integer() and abs(p) <= 64):
            n = int(p)
            result = self._lift(1.0)
            base = self if n >= 0 else 1.0 / self
            for _ in range(abs(n)):
                result = result * base
            return result
        # a^α by the recurrence of (a^α)' a = α a' a^α; needs a_0 ≠ 0.
        alpha, a = float(p), self.c
        r = self._series(len(a))
        r[0] = _at(lambda x: x**alpha if x > 0 or alpha.is_integer() else math.nan, a[0])
        for k in range(1, len(a)):
            r[k] = _div(sum(((alpha + 1) * j - k) * a[j] * r[k - j] for j in range(1, k + 1)), k * a[0])
        return Jet(r)

    def __rpow__(self, base: Any) -> "Jet":
        return (self * math.log(float(base))).exp()

    # ----- elementary functions -----
    def exp(self) -> "Jet":
        a, e = self.c, self._series(len(self.c))
        e[0] = _at(math.exp, a[0])
        for k in range(1, len(a)):
            e[k] = sum(j * a[j] * e[k - j] for j in range(1, k + 1)) / k
        return Jet(e)

    def log(self) -> "Jet":
        a, r = self.c, self._series(len(self.c))
        r[0] = _at(math.log, a[0])
        for k in range(1, len(a)):
            r[k] = _div(a[k] - sum(j * r[j] * a[k - j] for j in range(1, k)) / k, a[0])
        return Jet(r)

    def _sin_cos(self):
        a, n = self.c, len(self.c)
        s, c = self._series(n), self._series(n)
        s[0], c[0] = math.sin(a[0]), math.cos(a[0])
        for k in range(1, n):
            s[k] = sum(j * a[j] * c[k - j] for j in range(1, k + 1)) / k
            c[k] = -sum(j * a[j] * s[k - j] for j in range(1, k + 1)) / k
        return Jet(s), Jet(c)

    def sin(self) -> "Jet":
        return self._sin_cos()[0]

    def cos(self) -> "Jet":
        return self._sin_cos()[1]

    def tan(self) -> "Jet":
        s, c = self._sin_cos()
        return s / c

    def sinh(self) -> "Jet":
        return (self.exp() - (-self).exp()) * 0.5

    def cosh(self) -> "Jet":
        return (self.exp() + (-self).exp()) * 0.5

    def tanh(self) -> "Jet":
        return self.sinh() / self.cosh()

    def sqrt(self) -> "Jet":
        a, r = self.c, self._series(len(self.c))
        r[0] = _at(math.sqrt, a[0])
        for k in range(1, len(a)):
            r[k] = _div(a[k] - sum(r[j] * r[k - j] for j in range(1, k)), 2 * r[0])
        return Jet(r)

    def _integral_of(self, derivative: "Jet", value: float) -> "Jet":
        """The series whose value is `value` and whose derivative series is `derivative`."""
        return Jet([value] + [derivative.c[k - 1] / k for k in range(1, len(self.c))])

    def _derivative(self) -> "Jet":
        return Jet([k * self.c[k] for k in range(1, len(self.c))] + [0.0])

    def arctan(self) -> "Jet":
        return self._integral_of(self._derivative() / (1.0 + self * self), math.atan(self.c[0]))

    def arcsin(self) -> "Jet":
        return self._integral_of(self._derivative() / (1.0 - self * self).sqrt(), _at(math.asin, self.c[0]))

    def arccos(self) -> "Jet":
        return self._integral_of(-self._derivative() / (1.0 - self * self).sqrt(), _at(math.acos, self.c[0]))

    # ----- numpy -----
    _UFUNCS = {
        "add": lambda a, b: a + b,
        "subtract": lambda a, b: a - b,
        "multiply": lambda a, b: a * b,
        "true_divide": lambda a, b: a / b,
        "divide": lambda a, b: a / b,
        "power": lambda a, b: a**b,
        "negative": lambda a: -a,
        "positive": lambda a: a,
        "square": lambda a: a * a,
        "reciprocal": lambda a: 1.0 / a,
    }

    def __array_ufunc__(self, ufunc, method, *inputs, **kwargs):
        if method != "__call__" or kwargs:
            return NotImplemented
        name = ufunc.__name__
        if name in Jet._UFUNCS:
            return Jet._UFUNCS[name](*inputs)
        if len(inputs) == 1 and name in ("exp", "log", "sin", "cos", "tan", "sinh", "cosh", "tanh", "sqrt",
                                          "arctan", "arcsin", "arccos"):
            return getattr(inputs[0], name)()
        return NotImplemented

    def __repr__(self) -> str:
        return f"Jet({self.c})"


def jet_function(curve: Callable[[Any], Sequence[Any]]) -> Callable[[float, int], List[float]]:
    """The function the library calls for a Python curve: (t, order) ↦ the derivatives
    γ(t), γ′(t), …, γ⁽ᵒʳᵈᵉʳ⁾(t) as (order + 1)·3 floats, row by row."""

    def jet(t: float, order: int) -> List[float]:
        identity = Jet([t, 1.0] + [0.0] * (order - 1)) if order >= 1 else Jet([t])
        try:
            components = list(curve(identity))
        except TypeError as e:
            raise TrajverifyError(
                "curve: the callable must be built from + - * /, ** and numpy functions (np.sin, "
                f"np.exp, ...) so that its derivatives can be taken exactly; it raised: {e}"
            ) from None
        if len(components) != 3:
            raise TrajverifyError(f"curve: the callable returned {len(components)} components, expected 3 (x, y, z)")
        try:
            series = [identity._lift(c).c for c in components]
        except TypeError as e:
            raise TrajverifyError(f"curve: the callable must return three numbers (x, y, z); {e}") from None
        flat = []
        factorial = 1.0
        for k in range(order + 1):
            factorial *= max(k, 1)
            flat.extend(s[k] * factorial for s in series)
        return flat

    return jet
