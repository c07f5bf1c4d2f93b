"""Times the Python package against scipy on the jobs they share, in one process, and prints
the ratios (best of several calls; run after `maturin develop --release`, see the README):

- Hermite control points: one 2000-dimensional problem with 12 derivatives at each end, and
  10⁴ problems of 3 derivatives in 3-D (scipy: one `BPoly.from_derivatives` per problem, the
  only way it takes different data per problem; a vectorised y of shape (2, m, N·d) in one
  call for the batch, which is the fastest scipy form);
- natural cubic spline on 2·10⁴ knots evaluated with two derivatives at 2·10⁴ points.

pydubins does not build on Python ≥ 3.11 (its 1.0.1 source), so Dubins is not compared here.
"""

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

    print("| job | trajverify | scipy | trajverify / scipy |")
    print("|---|---|---|---|")
    for job, ours, theirs in rows:
        print(f"| {job} | {ours * 1e3:.3f} ms | {theirs * 1e3:.3f} ms | {ours / theirs:.2f}× |")


if __name__ == "__main__":
    main()
