#!/usr/bin/env python3
"""Peer for `run natural-spline --scalar rational`: pure-Python `fractions`.

Reads the same JSON input as `trajverify run natural-spline` (`t`, `z` as numbers, `at`),
solves the natural cubic spline's tridiagonal system for the second derivatives exactly
(Thomas elimination in Fraction), and evaluates value, first and second derivative at
every point of `at`. Usage: natural_spline_fractions.py INPUT.json; prints the JSON output
(values, first, second as "p/q" strings, as `run` prints them) on stdout.
"""
import bisect
import json
import sys
from fractions import Fraction


def spline(t, z):
    n = len(t) - 1
    h = [t[i + 1] - t[i] for i in range(n)]
    # Unknowns M_1 … M_{n−1}; M_0 = M_n = 0 (natural ends).
    diag = [2 * (h[i - 1] + h[i]) for i in range(1, n)]
    rhs = [6 * ((z[i + 1] - z[i]) / h[i] - (z[i] - z[i - 1]) / h[i - 1]) for i in range(1, n)]
    for k in range(1, n - 1):
        w = h[k] / diag[k - 1]
        diag[k] -= w * h[k]
        rhs[k] -= w * rhs[k - 1]
    m = [Fraction(0)] * (n + 1)
    for k in range(n - 2, -1, -1):
        m[k + 1] = (rhs[k] - (h[k + 1] * m[k + 2] if k + 1 < n - 1 else 0)) / diag[k]
    return h, m


def evaluate(t, z, h, m, x):
    i = min(max(bisect.bisect_right(t, x) - 1, 0), len(t) - 2)
    a, b = t[i + 1] - x, x - t[i]
    hi = h[i]
    value = (m[i] * a**3 + m[i + 1] * b**3) / (6 * hi) + (z[i] / hi - m[i] * hi / 6) * a + (
        z[i + 1] / hi - m[i + 1] * hi / 6
    ) * b
    first = (-m[i] * a**2 + m[i + 1] * b**2) / (2 * hi) + (z[i + 1] - z[i]) / hi - (m[i + 1] - m[i]) * hi / 6
    second = (m[i] * a + m[i + 1] * b) / hi
    return value, first, second


def main():
    doc = json.load(open(sys.argv[1]), parse_float=str, parse_int=str)
    t = [Fraction(x) for x in doc["t"]]
    z = [Fraction(x) for x in doc["z"]]
    h, m = spline(t, z)
    rows = [evaluate(t, z, h, m, Fraction(x)) for x in doc["at"]]
    out = {key: [str(r[k]) for r in rows] for k, key in enumerate(("values", "first", "second"))}
    json.dump(out, sys.stdout, separators=(",", ":"))


if __name__ == "__main__":
    main()
