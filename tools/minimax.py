#!/usr/bin/env python3
"""Minimax coefficients of the polynomial kernels in src/float/ (atan2.rs, sin_cos.rs).

    pip install mpmath
    python3 tools/minimax.py atan|sin|cos|atan_f64|sin_f64|constants

Remez exchange on a dense Chebyshev grid, in 50-digit arithmetic. Each
kernel is `leading terms + x^k P(s)` with `s = x^2`; the script finds `P`
that minimizes the largest weighted error (relative for atan and sin,
absolute for cos) and prints its coefficients, the f32 each rounds to, and
the approximation error. `atan_f64` and `sin_f64` are the wider-range
kernels of `float/double.rs`, evaluated in f64: their coefficients are
printed as f64. `constants` prints the split constants and the
bits of 2/pi the argument reduction uses.
"""
import struct
import sys

import mpmath as mp

mp.mp.dps = 50


def f32(x):
    return struct.unpack("f", struct.pack("f", float(x)))[0]


def remez(f, weight, degree, lo, hi, iterations=15, grid=1500):
    """Coefficients c of sum c_k s^k minimizing max |weight (f - sum)| on [lo, hi]."""
    n = degree + 1
    xs = [lo + (hi - lo) * (1 - mp.cos(mp.pi * i / grid)) / 2 for i in range(grid + 1)]
    fx = [f(x) for x in xs]
    wx = [weight(x) for x in xs]
    ref = [int(round(grid * (1 - mp.cos(mp.pi * i / n)) / 2)) for i in range(n + 1)]
    for _ in range(iterations):
        a = mp.matrix(n + 1, n + 1)
        b = mp.matrix(n + 1, 1)
        for row, i in enumerate(ref):
            for k in range(n):
                a[row, k] = xs[i] ** k
            a[row, n] = (-1) ** row / wx[i]
            b[row] = fx[i]
        sol = mp.lu_solve(a, b)
        c = [sol[k] for k in range(n)]
        err = [wx[i] * (fx[i] - sum(c[k] * xs[i] ** k for k in range(n))) for i in range(len(xs))]
        # The new reference: the largest error of each run of one sign.
        runs, run = [], [0]
        for i in range(1, len(xs)):
            if mp.sign(err[i]) == mp.sign(err[run[-1]]):
                run.append(i)
            else:
                runs.append(max(run, key=lambda j: abs(err[j])))
                run = [i]
        runs.append(max(run, key=lambda j: abs(err[j])))
        while len(runs) > n + 1:
            runs.pop(0 if abs(err[runs[0]]) < abs(err[runs[-1]]) else -1)
        if len(runs) == n + 1:
            ref = runs
    return c, max(abs(e) for e in err)


def show(name, c, e):
    print(f"{name}: max weighted error {mp.nstr(e, 5)}")
    for k, x in enumerate(c):
        print(f"  s^{k}: {mp.nstr(x, 15):>22}  f32 {f32(x)!r}")


TINY = mp.mpf(10) ** -8  # the error weight vanishes at 0; start just above


def odd(f):
    """The function P to fit and its weight, for an odd `f(x) = x + x^3 P(x^2)`
    approximated for relative error, both of `s = x^2`."""
    g = lambda s: (f(mp.sqrt(s)) - mp.sqrt(s)) / (s * mp.sqrt(s))
    w = lambda s: s * mp.sqrt(s) / f(mp.sqrt(s))
    return g, w


def atan():
    # atan(u) = u + u^3 P(u^2) on |u| <= tan(1/2), relative error.
    hi = mp.tan(mp.mpf(1) / 2) ** 2
    show("atan, degree 5 in u^2", *remez(*odd(mp.atan), 5, TINY, hi))


def sin():
    # sin(r) = r + r^3 P(r^2) on |r| <= pi/4, relative error.
    hi = (mp.pi / 4) ** 2
    show("sin, degree 2 in r^2", *remez(*odd(mp.sin), 2, TINY, hi))


def cos():
    # cos(r) = 1 - r^2/2 + r^4 P(r^2) on |r| <= pi/4, error relative to cos.
    hi = (mp.pi / 4) ** 2
    g = lambda s: (mp.cos(mp.sqrt(s)) - 1 + s / 2) / (s * s)
    w = lambda s: s * s / mp.cos(mp.sqrt(s))
    show("cos, degree 2 in r^2", *remez(g, w, 2, TINY, hi))


def show_f64(name, c, e):
    print(f"{name}: max weighted error {mp.nstr(e, 5)}")
    for k, x in enumerate(c):
        print(f"  s^{k}: {float(x)!r}")


def atan_f64():
    # atan(u) = u + u^3 P(u^2) on 0 <= u <= 1, relative error.
    show_f64("atan on [0, 1], degree 7 in u^2", *remez(*odd(mp.atan), 7, TINY, mp.mpf(1)))


def sin_f64():
    # sin(x) = x + x^3 P(x^2) on 0 <= x <= pi/2, relative error.
    hi = (mp.pi / 2) ** 2
    show_f64("sin on [0, pi/2], degree 3 in x^2", *remez(*odd(mp.sin), 3, TINY, hi))


def constants():
    for name, value in [("PIO2", mp.pi / 2), ("PIO4", mp.pi / 4), ("PI", mp.pi)]:
        head = f32(value)
        tail = f32(value - mp.mpf(head))
        print(f"{name}_HI {head!r} ({struct.pack('>f', head).hex()}), "
              f"{name}_LO {tail!r} ({struct.pack('>f', tail).hex()})")
    print(f"TAN_HALF {f32(mp.tan(mp.mpf(1) / 2))!r}")
    with mp.workdps(120):  # 224 bits need more than the default 50 digits
        bits = int(mp.floor(2 / mp.pi * mp.mpf(2) ** 224))
    words = [(bits >> (32 * (6 - i))) & 0xFFFFFFFF for i in range(7)]
    print("TWO_OVER_PI 0, " + ", ".join(f"0x{w:08X}" for w in words))
    print(f"TWO_PI_FIXED {int(mp.nint(2 * mp.pi * mp.mpf(2) ** 61))}")


if __name__ == "__main__":
    kernels = {"atan": atan, "sin": sin, "cos": cos, "atan_f64": atan_f64, "sin_f64": sin_f64}
    {**kernels, "constants": constants}[sys.argv[1]]()
