"""The library's other jobs in Python's idiom: each function builds the JSON document of a
``trajverify run`` algorithm from keyword arguments (numbers read exactly), runs it in process
and returns a typed result whose numbers are Python numbers of the run's scalar (numpy arrays
for f64, ``Fraction`` for rational, ``mpmath.mpf`` for mpfr, :class:`Ball` for ball).

`scalar=None` takes the algorithm's default, the command line's (``run --help``): f64 for
GERBS, Dubins, spline fits and ph-hermite; mpfr:256 for Marin and bang-bang; B-spline
bases and Gram entries are always exact.
"""

from __future__ import annotations

from typing import Any, List, NamedTuple, Optional, Sequence

from ._cli import run
from ._numbers import exact_text, from_text, from_texts
from ._numbers import points as points_of


def _scalar(out: dict) -> str:
    """The number type a run used (its output says; the B-spline jobs print only exact ones)."""
    return out.get("scalar", "rational")


# ----- paper 002: optimal B-splines and the bang-bang control -----


def bspline_basis(degree: int) -> list:
    """The pieces of the cardinal B-spline B_k (paper 002, Algorithm 1), exactly: entry j holds
    the power coefficients [c_0, …, c_k] of the piece on [j, j+1] in s = t − j, as Fractions.

    >>> bspline_basis(1)
    [[Fraction(0, 1), Fraction(1, 1)], [Fraction(1, 1), Fraction(-1, 1)]]
    """
    return from_text(run("bspline-basis", {"degree": degree})["pieces"], "rational")


def bspline_gram(degree: int) -> list:
    """The Gram entries ĝ_0 … ĝ_k of the k-th derivatives of the cardinal B-splines (paper 002,
    Sec. 5), exactly, as Fractions."""
    return from_text(run("bspline-gram", {"degree": degree})["entries"], "rational")


def spline_fit(
    times: Sequence[Any],
    values: Sequence[Any],
    degree: int = 3,
    controls: Optional[int] = None,
    weights: Optional[Sequence[Any]] = None,
    scalar: Optional[str] = None,
) -> Any:
    """The control points τ_1 … τ_M of the optimal B-spline of `degree` with `controls` = M
    control points (paper 002, Eqs. 14–15): interpolating the data (`values` numbers or
    points at `times`) when `weights` is None, smoothing with those weights otherwise. The
    basis is cardinal (knots at the integers), so the times lie inside its support (0, M+k+1)."""
    doc = {
        "degree": degree,
        "controls": len(times) if controls is None else controls,
        "times": list(times),
        "values": list(values),
        "weights": None if weights is None else list(weights),
    }
    out = run("spline-fit", doc, scalar)
    return from_texts(out["tau"], _scalar(out))


class BangBang(NamedTuple):
    """The minimum-L∞ control through x(2) = ξ (paper 002, Sec. 4)."""

    switching_times: list
    amplitude: Any
    exact: Optional[dict]
    """The closed forms (strings such as ``"2 - sqrt(2)"``) when the run found them."""


def bang_bang(xi: Any, scalar: Optional[str] = None) -> BangBang:
    """The bang-bang control of paper 002, Sec. 4 with end condition x(2) = `xi`."""
    out = run("bang-bang", {"xi": exact_text(xi, "xi")}, scalar)
    s = _scalar(out)
    return BangBang(from_text(out["switching_times"], s), from_text(out["amplitude"], s), out.get("exact"))


# ----- paper 004: Marin's parametrization -----


class Marin1D(NamedTuple):
    """The exact minimizing parametrization of scalar data (paper 004, Sec. 2)."""

    t: list
    case: str
    """Which of the paper's cases I, II, III the data fall in (decided on the exact input)."""


def marin_1d(z: Sequence[Any], scalar: Optional[str] = None) -> Marin1D:
    """Marin's parametrization t_0 = 0 < … < t_N = 1 of the values `z` (paper 004, Sec. 2)."""
    out = run("marin-1d", {"z": list(z)}, scalar)
    return Marin1D(from_texts(out["t"], _scalar(out)), out["case"])


class Marin(NamedTuple):
    """A minimizing parametrization of points (paper 004, Eq. 30) and its objective."""

    t: Any
    G: Any
    """The objective at t."""
    G_chord: Any
    """The objective at the chord-length parametrization, for comparison."""
    iterations: int
    converged: bool


def marin(
    points: Sequence[Sequence[Any]],
    weights: Optional[Sequence[Any]] = None,
    objective: str = "exact",
    scalar: Optional[str] = None,
) -> Marin:
    """The parameters t_0 = 0 < … < t_N = 1 minimizing Marin's objective (paper 004, Eq. 30;
    ``"exact"`` Eq. 31 or ``"approx"``) for `points` (N + 1 points of dimension K), with
    optional weights a_1 … a_K, one per coordinate (default 1)."""
    doc: dict = {"points": points_of(points, "points"), "objective": objective}
    if weights is not None:
        doc["weights"] = list(weights)
    out = run("marin", doc, scalar)
    s = _scalar(out)
    return Marin(
        from_texts(out["t"], s),
        from_text(out["G"], s),
        from_text(out["G_chord"], s),
        out["iterations"],
        bool(out.get("descent_converged", True)),
    )


# ----- paper 003: GERBS paths and Dubins words -----


class GerbsPath(NamedTuple):
    """A curvature-continuous GERBS path (paper 003, Algorithms 1–2), sampled."""

    t: Any
    points: Any
    curvature: Any
    length: Any
    at_waypoints: List[dict]
    """Per waypoint its parameter, point, tangent and curvature."""
    turns: List[int]


def gerbs_path(
    waypoints: Sequence[Sequence[Any]],
    radius: Any,
    theta_o: Any = "pi/8",
    kind: str = "erbs",
    params: Optional[dict] = None,
    samples: Optional[int] = None,
    line_length: Any = None,
    arcs: Optional[str] = None,
    scalar: Optional[str] = None,
) -> GerbsPath:
    """The GERBS path through `waypoints` (2-D) with turn `radius` and angle `theta_o`
    (``"bfbs"`` or ``"erbs"`` blending; `params` their parameters), sampled at `samples`
    parameters (default 101)."""
    doc: dict = {
        "waypoints": points_of(waypoints, "waypoints"),
        "radius": exact_text(radius, "radius"),
        "theta_o": exact_text(theta_o, "theta_o"),
        "kind": kind,
    }
    for key, value in (("params", params), ("samples", samples), ("arcs", arcs)):
        if value is not None:
            doc[key] = value
    if line_length is not None:
        doc["line_length"] = exact_text(line_length, "line_length")
    out = run("gerbs-path", doc, scalar)
    s = _scalar(out)
    at = [{k: from_texts(v, s) for k, v in w.items()} for w in out["at_waypoints"]]
    return GerbsPath(
        from_texts(out["t"], s),
        from_texts(out["points"], s),
        from_texts(out["curvature"], s),
        from_text(out["length"], s),
        at,
        out["turns"],
    )


def gerbs_basis(
    knots: Sequence[Any],
    at: Sequence[Any],
    kind: str = "erbs",
    params: Optional[dict] = None,
    derivatives: int = 0,
    side: Optional[str] = None,
    scalar: Optional[str] = None,
) -> list:
    """The BFBS or ERBS basis functions B_2 … B_(n+1) on `knots` and their first `derivatives`
    derivatives at each point of `at` (paper 003, Eqs. 3–9): entry [p][i][d]; None where a
    derivative does not exist."""
    doc: dict = {"knots": list(knots), "kind": kind, "at": list(at), "derivatives": derivatives}
    if params is not None:
        doc["params"] = params
    if side is not None:
        doc["side"] = side
    out = run("gerbs-basis", doc, scalar)
    s = _scalar(out)
    return [[[None if v is None else from_text(v, s) for v in b] for b in point] for point in out["values"]]


class DubinsLeg(NamedTuple):
    """The shortest Dubins path between two consecutive poses."""

    start: int
    end: int
    word: str
    """LSL, RSR, LSR, RSL, RLR or LRL."""
    lengths: Any
    length: Any
    samples: Any
    """Rows x, y, heading."""


class Dubins(NamedTuple):
    """Dubins paths through waypoints (paper 003, Fig. 7)."""

    headings: Any
    legs: List[DubinsLeg]
    length: Any


def dubins(
    waypoints: Sequence[Sequence[Any]],
    radius: Any,
    headings: Optional[Sequence[Any]] = None,
    samples: Optional[int] = None,
    scalar: Optional[str] = None,
) -> Dubins:
    """The shortest Dubins path of turn `radius` between consecutive `waypoints` (2-D) with
    `headings` (default: from the paper's Algorithm 1), each leg sampled at `samples` points
    (default 33)."""
    doc: dict = {"waypoints": points_of(waypoints, "waypoints"), "radius": exact_text(radius, "radius")}
    if headings is not None:
        doc["headings"] = [exact_text(h, "headings") for h in headings]
    if samples is not None:
        doc["samples"] = samples
    out = run("dubins", doc, scalar)
    s = _scalar(out)
    legs = [
        DubinsLeg(
            leg["from"],
            leg["to"],
            leg["word"],
            from_texts(leg["lengths"], s),
            from_text(leg["length"], s),
            from_texts(leg["samples"], s),
        )
        for leg in out["legs"]
    ]
    return Dubins(from_texts(out["headings"], s), legs, from_text(out["length"], s))


# ----- paper 001: one PH segment -----


class PhHermite(NamedTuple):
    """The degree-17 PH interpolant of C⁴ Hermite data (paper 001, Algorithm 1)."""

    preimage: Any
    """The 9 Bernstein coefficients of A(ξ), each [u, v, p, q]."""
    control_points: Any
    """The 18 control points [x, y, z]."""
    arc_length: Any


def ph_hermite(
    p_b: Sequence[Any],
    p_e: Sequence[Any],
    v_b: Sequence[Any],
    v_e: Sequence[Any],
    a_b: Sequence[Any],
    a_e: Sequence[Any],
    j_b: Sequence[Any],
    j_e: Sequence[Any],
    s_b: Sequence[Any],
    s_e: Sequence[Any],
    free: Optional[dict] = None,
    scalar: Optional[str] = None,
) -> PhHermite:
    """Algorithm 1 of paper 001: position, velocity, acceleration, jerk and snap at both ends
    (derivatives in ξ ∈ [0, 1]) → the PH interpolant. `free` holds θ and τ by name (``theta0``,
    ``tau1``, …), default 0. Rational is refused (Lemma 2 takes square roots)."""
    data = dict(p_b=p_b, p_e=p_e, v_b=v_b, v_e=v_e, a_b=a_b, a_e=a_e, j_b=j_b, j_e=j_e, s_b=s_b, s_e=s_e)
    doc: dict = {k: list(v) for k, v in data.items()}
    if free is not None:
        doc["free"] = free
    out = run("ph-hermite", doc, scalar)
    s = _scalar(out)
    return PhHermite(
        from_texts(out["preimage"], s), from_texts(out["control_points"], s), from_text(out["arc_length"], s)
    )
