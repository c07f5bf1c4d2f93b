#!/usr/bin/env python3
"""Peer for `run bspline-basis` / `run bspline-gram`: pure-Python `fractions`.

The cardinal B-spline B_k on the integer knots 0…k+1 by the Cox–de Boor recursion (the
same O(k³) field operations as the paper's Algorithm 1, which `run` uses), each
piece a polynomial in s = t − j with Fraction coefficients (what `run bspline-basis`
prints), and the Gram entries ĝ_m = ∫ B_k^(k)(t) B_k^(k)(t − m) dt from those pieces (what
`run bspline-gram` prints). Usage: bspline_fractions.py basis|gram K; prints the time of
the computation alone (seconds) on stderr and a checksum on stdout.
"""
import sys
import time
from fractions import Fraction


def mul(p, q):
    out = [Fraction(0)] * (len(p) + len(q) - 1)
    for i, a in enumerate(p):
        for j, b in enumerate(q):
            out[i + j] += a * b
    return out


def add(p, q):
    if len(p) < len(q):
        p, q = q, p
    out = list(p)
    for i, b in enumerate(q):
        out[i] += b
    return out


def pieces(k):
    """The pieces of B_k by the cardinal Cox–de Boor recursion
    B_p(t) = (t B_{p−1}(t) + (p + 1 − t) B_{p−1}(t − 1)) / p, on piece j in s = t − j."""
    b = [[Fraction(1)]]
    for p in range(1, k + 1):
        inv = Fraction(1, p)
        new = []
        for j in range(p + 1):
            rising = mul([Fraction(j), Fraction(1)], b[j]) if j < p else []  # t = s + j
            falling = mul([Fraction(p + 1 - j), Fraction(-1)], b[j - 1]) if j > 0 else []
            new.append([c * inv for c in add(rising, falling)])
        b = new
    return b


def derivative(p):
    return [c * i for i, c in enumerate(p)][1:]


def integrate01(p):
    return sum(c / (i + 1) for i, c in enumerate(p))


def gram(k):
    d = pieces(k)
    for _ in range(k):
        d = [derivative(p) for p in d]
    return [
        sum((integrate01(mul(d[j], d[j - m])) for j in range(m, k + 1) if d[j] and d[j - m]), Fraction(0))
        for m in range(k + 1)
    ]


def main():
    what, k = sys.argv[1], int(sys.argv[2])
    start = time.perf_counter()
    result = pieces(k) if what == "basis" else gram(k)
    elapsed = time.perf_counter() - start
    flat = [c for p in result for c in p] if what == "basis" else result
    print(sum(abs(c.numerator) % 1000003 for c in flat))
    print(f"{elapsed:.6f}", file=sys.stderr)


if __name__ == "__main__":
    main()
