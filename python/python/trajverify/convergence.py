"""Convergence studies of a user's curve (``trajverify report convergence``) as a typed result.

For each level n the curve is approximated on 2ⁿ uniform segments (the PHODCOS conversion of
paper 001, or paper 000's Hermite map with m derivatives) and the error max‖γ − p‖ is proven by
branch and bound in ball arithmetic (scalar ``ball:<bits>``; with the sampled maximum at p and
2p bits and f64 beside it), or only sampled (``mpfr:<bits>``: not certified, no proven order).
The observed orders between levels, the fitted order over the asymptotic levels and the order
expected from the method and the curve's smoothness come with it; the rules are the library's
(``algo::convergence``).
"""

from __future__ import annotations

import json
import os
import tempfile
from fractions import Fraction
from typing import Any, List, NamedTuple, Optional, Sequence, Tuple, Union

from ._cli import command
from ._numbers import exact_text, pair
from ._trajverify import TrajverifyError


class Level(NamedTuple):
    """One level of a study."""

    level: int
    segments: int
    status: str
    """``"resolved"`` (a digit is proven), ``"zero"`` (the method reproduces the curve at this
    precision) or ``"floor"`` (non-zero, without a digit); only resolved levels enter the orders."""
    error_proven: Optional[Tuple[Fraction, Fraction]]
    """lower ≤ E ≤ upper, the printed decimal bounds as exact Fractions (None without a proof)."""
    error_sampled: str
    """The sampled maximum's agreeing digits at p and 2p bits (a cross-check, not a bound)."""
    error_f64: Optional[float]
    """The same pipeline in f64."""
    order: Optional[float]
    """The observed order from the previous resolved level."""
    order_proven: Optional[Tuple[float, float]]
    """The interval the enclosures prove for that order."""

    @property
    def error(self) -> float:
        """The error as a float: the proven upper bound, else the sampled maximum."""
        if self.error_proven is not None:
            return float(self.error_proven[1])
        return float(self.error_sampled)


class Fit(NamedTuple):
    """The fitted order: a least-squares slope over the asymptotic levels."""

    outcome: str
    """``"fitted"``, ``"reproduced"`` (every level zero) or ``"too few levels"``."""
    order: Optional[float]
    ci95: Optional[float]
    """The half-width of the 95 % interval of the order (Student's t; None below 3 levels)."""
    levels: List[int]
    why: str
    expected_inside: Optional[bool]
    """Whether the expected order lies inside the 95 % interval (None without one)."""


class ConvergenceStudy:
    """The result of :func:`convergence`: `levels`, `fit`, `expected_order` and the report
    (`markdown`, `svg`); ``str()`` is the table, :meth:`plot` draws it with matplotlib."""

    def __init__(self, doc: dict, markdown: str, svg: str):
        self.doc = doc
        """The report's ``convergence.json`` as a dict."""
        self.markdown = markdown
        self.svg = svg
        self.curve: str = doc["curve"]
        self.method: str = doc["method"]
        self.scalar: str = doc["scalar"]
        self.proven: bool = doc["proven"]
        self.expected_order: int = doc["expected_order"]["order"]
        self.expected_reason: str = doc["expected_order"]["reason"]
        self.levels = [_level(r) for r in doc["rows"]]
        self.fit = _fit(doc["fit"])
        self.f64_stops_improving_at: Optional[int] = doc.get("f64_stops_improving_at")
        self.notes: List[str] = doc.get("notes", [])

    def __repr__(self) -> str:
        fit = f"fitted order {self.fit.order:.4f}" if self.fit.outcome == "fitted" and self.fit.order is not None else self.fit.outcome
        return f"ConvergenceStudy({self.method}, {len(self.levels)} levels, expected order {self.expected_order}, {fit})"

    def __str__(self) -> str:
        head = f"{self.method} on {self.curve}, {self.scalar}, expected order {self.expected_order}"
        lines = [head, f"{'N':>6}  {'error (upper bound)' if self.proven else 'error (sampled)':>24}  {'order':>8}  status"]
        for lv in self.levels:
            order = "" if lv.order is None else f"{lv.order:8.4f}"
            lines.append(f"{lv.segments:>6}  {lv.error:>24.6e}  {order:>8}  {lv.status}")
        if self.fit.outcome == "fitted" and self.fit.order is not None:
            ci = "" if self.fit.ci95 is None else f" ± {self.fit.ci95:.4f} (95 %)"
            lines.append(f"fitted order {self.fit.order:.4f}{ci} on levels {self.fit.levels}")
        else:
            lines.append(f"no fitted order: {self.fit.outcome} ({self.fit.why})")
        return "\n".join(lines)

    def _repr_markdown_(self) -> str:
        return self.markdown

    def _repr_svg_(self) -> str:
        return self.svg

    def plot(self, ax: Any = None) -> Any:
        """Error against segments on log–log axes (proven bounds as bars, f64 beside them) with
        matplotlib, which must be installed; returns the axes."""
        try:
            import matplotlib.pyplot as plt
        except ImportError:
            raise ImportError("ConvergenceStudy.plot needs matplotlib: pip install matplotlib") from None
        if ax is None:
            _, ax = plt.subplots()
        n = [lv.segments for lv in self.levels]
        ax.loglog(n, [lv.error for lv in self.levels], "o-", label="error" + (" (proven bound)" if self.proven else " (sampled)"))
        proven = [lv for lv in self.levels if lv.error_proven is not None]
        for lv in proven:
            ax.plot([lv.segments] * 2, [float(b) for b in lv.error_proven], "k-", lw=3)
        f64 = [(lv.segments, lv.error_f64) for lv in self.levels if lv.error_f64]
        if f64:
            ax.loglog(*zip(*f64), "x--", label="f64")
        ax.set_xlabel("segments N")
        ax.set_ylabel("max ‖γ − p‖")
        ax.set_title(f"{self.method}: expected order {self.expected_order}")
        ax.legend()
        return ax


def _level(row: dict) -> Level:
    proven = row.get("error_proven")
    order = row.get("order")
    return Level(
        row["level"],
        row["segments"],
        row["status"],
        None if proven is None else (Fraction(proven["lower"]), Fraction(proven["upper"])),
        row["error_sampled"],
        row.get("error_f64"),
        None if order is None else order["value"],
        None if order is None or order.get("proven") is None else tuple(order["proven"]),
    )


def _fit(fit: dict) -> Fit:
    return Fit(
        fit["outcome"],
        fit.get("order"),
        fit.get("ci95"),
        list(fit.get("levels", [])),
        fit.get("why", ""),
        fit.get("expected_inside"),
    )


def convergence(
    curve: str,
    interval: Sequence[Any],
    method: str = "phodcos",
    levels: Union[str, Sequence[int]] = "0-8",
    scalar: str = "ball:128",
    data: Optional[str] = None,
) -> ConvergenceStudy:
    """A convergence study of `curve` (an expression ``"[x(t), y(t), z(t)]"``; or `data`, a
    CSV file t, x, y, z fitted by a C⁴ quintic spline, with `curve` None) on `interval`
    (numbers or constants such as ``"4*pi"``, kept exact) by `method` (``"phodcos"`` or
    ``"hermite:M"``) on the `levels` (2ⁿ segments; ``"a-b"`` or a list), with the errors
    proven in ``ball:<bits>``. Progress is printed on stderr, as the command line does.

    A Python callable cannot be studied: the proof evaluates the curve in ball arithmetic,
    which only the expression language reaches.
    """
    if (curve is None) == (data is None):
        raise TrajverifyError("curve: give either an expression or a data file, not both or neither")
    if callable(curve):
        raise TrajverifyError("curve: a convergence study needs an expression (the proof evaluates it in balls)")
    if isinstance(levels, str):
        level_text = levels
    else:
        chosen = list(levels)
        if not chosen or any(isinstance(n, bool) or not isinstance(n, int) or n < 0 for n in chosen):
            raise TrajverifyError(f"levels: expected whole numbers n ≥ 0 (2ⁿ segments), found {chosen!r}")
        level_text = ",".join(str(n) for n in chosen)
    a, b = (str(exact_text(x, "interval")) for x in pair(interval, "interval"))
    with tempfile.TemporaryDirectory() as scratch:
        out = os.path.join(scratch, "report")
        args = ["report", "convergence"]
        args += ["--curve", curve] if curve is not None else ["--data", os.fspath(data)]
        args += ["--interval", a, b, "--method", method, "--levels", level_text, "--scalar", scalar, "--out", out]
        command(args)
        read = lambda name: open(os.path.join(out, name), encoding="utf-8").read()
        return ConvergenceStudy(json.loads(read("convergence.json")), read("convergence.md"), read("convergence.svg"))
