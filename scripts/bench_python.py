"""Times the Python package against scipy on the jobs they share, in one process, and prints
the ratios (best of several calls; run after `maturin develop --release`, see the README):

- Hermite control points: one 2000-dimensional problem with 12 derivatives at each end, and
  10⁴ problems of 3 derivatives in 3-D (scipy: one `BPoly.from_derivatives` per problem, the
  only way it takes different data per problem; a vectorised y of shape (2, m, N·d) in one
  call for the batch, which is the fastest scipy form);
- natural cubic spline on 2·10⁴ knots evaluated with two derivatives at 2·10⁴ points;
- Dubins paths through 2000 waypoints (1999 legs, two samples each), when pydubins is
  installed: its 1.0.1 sdist does not build on Python ≥ 3.11 (generated C for an older
  Python, no `core.pxd`); its repository (AndrewWalker/pydubins) builds with Cython < 3 after
  deleting the generated `dubins/dubins.c` (`pip install --no-build-isolation .`).
  trajverify decides every word on the exact input in ball arithmetic (docs/design.md) and
  pydubins in doubles, so this is the price of that guarantee, not of the same computation.
"""

import math
import time

import numpy as np

import trajverify as tv


def best(call, repeat=20):
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        call()
        times.append(time.perf_counter() - start)
    return min(times)


def main():
    try:
        from scipy.interpolate import BPoly, CubicSpline
    except ImportError:
        print("scipy is not installed: nothing to compare against")
        return
    rng = np.random.default_rng(40)
    rows = []
    start, end = rng.uniform(-10, 10, (12, 2000)), rng.uniform(-10, 10, (12, 2000))
    ours = best(lambda: tv.hermite(start, end))
    theirs = best(lambda: BPoly.from_derivatives([0, 1], [start, end]))
    rows.append(("Hermite, one 2000-dimensional problem, m = 11", ours, theirs))

    batch_start, batch_end = rng.normal(size=(10_000, 3, 3)), rng.normal(size=(10_000, 3, 3))
    ours = best(lambda: tv.hermite_batch(batch_start, batch_end), 10)
    flat = lambda a: a.transpose(1, 0, 2).reshape(3, -1)
    theirs = best(lambda: BPoly.from_derivatives([0, 1], [flat(batch_start), flat(batch_end)]), 10)
    rows.append(("Hermite, 10⁴ problems of 3 derivatives in 3-D", ours, theirs))

    t = np.sort(rng.choice(np.arange(0, 1_000_000) / 100, 20_000, replace=False))
    z = rng.uniform(-10, 10, 20_000)
    at = rng.uniform(t[0], t[-1], 20_000)
    ours = best(lambda: tv.natural_spline(t, z, at), 10)

    def scipy_spline():
        spline = CubicSpline(t, z, bc_type="natural")
        return spline(at), spline(at, 1), spline(at, 2)

    theirs = best(scipy_spline, 10)
    rows.append(("natural spline, 2·10⁴ knots and points, two derivatives", ours, theirs))

    dubins_row = dubins_times(rng)
    if dubins_row is not None:
        rows.append(dubins_row)

    print("| job | trajverify | peer | trajverify / peer |")
    print("|---|---|---|---|")
    for job, ours, theirs in rows:
        print(f"| {job} | {ours * 1e3:.3f} ms | {theirs * 1e3:.3f} ms | {ours / theirs:.2f}× |")


def dubins_times(rng):
    """(job, ours, pydubins) on 1999 legs, or None without pydubins. Both get the same
    headings (the chord directions of the neighbours) and return two samples per leg."""
    try:
        import dubins
    except ImportError:
        print("pydubins is not installed: Dubins is not compared")
        return None
    x, waypoints = 0.0, []
    for _ in range(2000):
        x += rng.uniform(100, 300)
        waypoints.append([x, rng.uniform(-200, 200)])
    w = waypoints
    n = len(w)
    headings = [math.atan2(w[min(i + 1, n - 1)][1] - w[max(i - 1, 0)][1],
                           w[min(i + 1, n - 1)][0] - w[max(i - 1, 0)][0]) for i in range(n)]
    ours = best(lambda: tv.dubins(w, 80, headings=headings, samples=2), 5)

    def theirs_call():
        for i in range(n - 1):
            path = dubins.shortest_path((*w[i], headings[i]), (*w[i + 1], headings[i + 1]), 80.0)
            path.sample_many(path.path_length() / 2)

    return ("Dubins, 1999 legs, two samples each (pydubins)", ours, best(theirs_call, 5))


if __name__ == "__main__":
    main()
