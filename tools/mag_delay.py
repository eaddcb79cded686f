#!/usr/bin/env python3
"""Measures how long a recording's magnetometer lags its gyroscope, for
`FilterParams::mag_delay`, from the readings alone (no reference attitude).

A field fixed to the earth turns in the sensor frame against the sensor's
turn: `d mag / dt = -w x mag`, with `w` the body rate the gyro reads. If the
magnetometer's readings are `s` seconds late, the rate that fits them is
the gyro's of `s` seconds earlier. The script compares the readings' rate
of change (a central difference over +-3 samples, which spans the held
readings of a magnetometer slower than the gyro) with `-gyr(t - s) x mag(t)`
for shifts of whole samples, takes the shift with the smallest mean squared
difference and refines it by a parabola through it and its neighbours.
The gyro bias is not taken off: it is small against the turns that measure
the delay. The magnetometer must be calibrated (hard iron off): a field
fixed to the sensor does not turn.

Usage: python3 tools/mag_delay.py [--dt SECONDS] TRIAL.csv[.gz] ...
(BROAD trial CSVs, as the `broad` binary reads them; `--dt` defaults to
BROAD's 3.5 ms). Needs numpy. Prints one line per trial; exits non-zero,
naming the file, if a trial has a gyro or magnetometer reading that is not
finite (and which sample), turns too little, or has its best shift at the
end of the searched range.
"""

import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vqf_broad import BROAD_DT, read_trial  # noqa: E402

# Half the span of the central difference, in samples.
HALF_SPAN = 3
# The shifts searched, in samples: the gyro may lag too (negative).
SHIFTS = range(-10, 21)
# The least mean rate, rad/s, at which the shifts tell apart.
LEAST_RATE = 0.3


def delay_samples(gyr, mag):
    """The magnetometer's delay against the gyro, in samples (fractional)."""
    k = HALF_SPAN
    rate_of_change = (mag[2 * k:] - mag[:-2 * k]) / (2 * k)
    field = mag[k:-k]
    n = len(field)
    # The samples t (of `field`) compared at every shift.
    margin = max(abs(SHIFTS.start), SHIFTS.stop)
    inner = slice(margin, n - margin)
    residuals = []
    for s in SHIFTS:
        # gyr[t - s] beside mag[t] (field[t] is mag[t + k]).
        rate = gyr[margin + k - s:n - margin + k - s]
        r = rate_of_change[inner] + np.cross(rate, field[inner])
        residuals.append(np.mean(np.sum(r ** 2, axis=1)))
    residuals = np.array(residuals)
    best = int(np.argmin(residuals))
    if best == 0 or best == len(residuals) - 1:
        raise ValueError(
            f"the best shift lies at the end of the searched range "
            f"({SHIFTS.start} to {SHIFTS.stop - 1} samples)"
        )
    a, b, c = residuals[best - 1:best + 2]
    curvature = a - 2 * b + c
    # A flat minimum (equal neighbours) has no better estimate than itself.
    refinement = 0.5 * (a - c) / curvature if curvature > 0 else 0.0
    return SHIFTS.start + best + refinement


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("trials", nargs="+")
    parser.add_argument("--dt", type=float, default=BROAD_DT,
                        help="sampling interval in seconds (default: BROAD's)")
    args = parser.parse_args()
    if not (args.dt > 0 and np.isfinite(args.dt)):
        sys.exit(f"error: --dt {args.dt} is not a positive number of seconds")
    for path in args.trials:
        try:
            d = np.array(read_trial(path), dtype=float)
        except (OSError, ValueError) as e:
            sys.exit(f"error: {e}")
        gyr, mag = d[:, 0:3], d[:, 6:9]
        bad = ~np.isfinite(np.hstack([gyr, mag])).all(axis=1)
        if bad.any():
            sys.exit(
                f"error: {path}: sample {int(np.argmax(bad)) + 1} has a gyro or "
                f"magnetometer reading that is not a finite number"
            )
        mean_rate = np.mean(np.linalg.norm(gyr, axis=1))
        if len(d) < 200 or mean_rate < LEAST_RATE:
            sys.exit(
                f"error: {path}: turns too little to measure the delay "
                f"(mean rate {mean_rate:.2f} rad/s over {len(d)} samples; "
                f"at least {LEAST_RATE} rad/s and 200 samples needed)"
            )
        try:
            # Per sample: the gyro in rad per sample.
            s = delay_samples(gyr * args.dt, mag)
        except ValueError as e:
            sys.exit(f"error: {path}: {e}")
        print(f"{os.path.basename(path)}: the magnetometer lags the gyro by "
              f"{s:.2f} samples, {s * args.dt * 1000:.1f} ms")


if __name__ == "__main__":
    main()
