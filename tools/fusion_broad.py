#!/usr/bin/env python3
"""Runs x-io's Fusion on one BROAD trial CSV and prints its estimates, for
the `broad` binary of `compare/` to score with the same metric as rigtform's
filter.

Fusion is x-io Technologies' AHRS (the revised algorithm of chapter 7 of
S. Madgwick's PhD thesis), installed from PyPI (`pip install imufusion`, MIT
license); this script only calls it. It runs as Fusion's README recommends:
gain 0.5, acceleration and magnetic rejection 10 degrees, a rejection
timeout of 5 s, the gyroscope range (2000 deg/s, the range x-io's example
sets: BROAD's rates stay below it), and Fusion's gyroscope bias algorithm
(default settings) in front of the AHRS; the earth frame is east-north-up,
BROAD's. Gyroscope in deg/s and accelerometer in g (BROAD's m/s^2 over
9.81), as Fusion takes them; the magnetometer in BROAD's uT (Fusion uses
its direction only). 6D (`update_no_magnetometer`) and 9D (`update`), from
the first sample.

imufusion 1.3.3's `AhrsSettings` constructor ignores its `convention`
argument (the frame stays north-west-up), so the script sets every setting
as a property and checks that each one took.

Usage: python3 tools/fusion_broad.py TRIAL.csv[.gz] > estimates.csv

Output: as tools/vqf_broad.py's, a header line, then one line per sample
with Fusion's 6D and 9D quaternions (sensor to ENU earth frame, scalar
first): `w6,x6,y6,z6,w9,x9,y9,z9`.
"""

import math

from vqf_broad import BROAD_DT, run_on_trial

# Standard gravity, for the accelerometer in g.
GRAVITY = 9.81

SETTINGS = {
    "sample_rate": 1.0 / BROAD_DT,
    "gain": 0.5,
    "gyroscope_range": 2000.0,
    "acceleration_rejection": 10.0,
    "magnetic_rejection": 10.0,
    "rejection_timeout": 5.0,
}


def make_ahrs(imufusion):
    """A Fusion AHRS and its bias algorithm, with SETTINGS and the ENU
    convention, each checked after it was set."""
    settings = imufusion.AhrsSettings()
    wanted = dict(SETTINGS, convention=imufusion.CONVENTION_ENU)
    for name, value in wanted.items():
        setattr(settings, name, value)
    for name, value in wanted.items():
        got = getattr(settings, name)
        if not math.isclose(got, value, rel_tol=1e-6):
            raise RuntimeError(f"imufusion did not take {name} = {value} (it holds {got})")
    ahrs = imufusion.Ahrs()
    ahrs.set_settings(settings)
    bias_settings = imufusion.BiasSettings()
    bias_settings.sample_rate = SETTINGS["sample_rate"]
    if not math.isclose(bias_settings.sample_rate, SETTINGS["sample_rate"], rel_tol=1e-6):
        raise RuntimeError("imufusion did not take the bias algorithm's sample rate")
    bias = imufusion.Bias()
    bias.set_settings(bias_settings)
    return ahrs, bias


def fusion_estimates(data):
    """Fusion's 6D and 9D estimates of the samples, one sample at a time,
    each behind its own gyroscope bias algorithm."""
    import imufusion
    import numpy as np

    data = np.array(data)
    gyr = np.degrees(data[:, 0:3])
    acc = data[:, 3:6] / GRAVITY
    mag = np.ascontiguousarray(data[:, 6:9])
    six, six_bias = make_ahrs(imufusion)
    nine, nine_bias = make_ahrs(imufusion)
    for g, a, m in zip(gyr, acc, mag):
        six.update_no_magnetometer(six_bias.update(g), a)
        nine.update(nine_bias.update(g), a, m)
        yield (*six.get_quaternion(), *nine.get_quaternion())


def main():
    run_on_trial("fusion_broad.py", fusion_estimates)


if __name__ == "__main__":
    main()
