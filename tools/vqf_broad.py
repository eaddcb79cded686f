#!/usr/bin/env python3
"""Runs VQF on one BROAD trial CSV and prints its estimates, for the `broad`
binary of `compare/` to score with the same metric as rigtform's filter.

VQF is the BROAD authors' filter (D. Laidig, T. Seel, "VQF: Highly accurate
IMU orientation estimation with bias estimation and magnetic disturbance
rejection", Information Fusion 91, 2023), installed from PyPI
(`pip install vqf`, MIT license); this script only calls it. It runs the
causal filter, `VQF(Ts).updateBatch`, with its default parameters, 6D and
9D, from the first sample.

Usage: python3 tools/vqf_broad.py TRIAL.csv[.gz] > estimates.csv

Output: a header line, then one line per sample with VQF's 6D and 9D
quaternions (sensor to ENU earth frame, scalar first):
`w6,x6,y6,z6,w9,x9,y9,z9`.
"""

import csv
import gzip
import sys

import numpy as np
from vqf import VQF

# BROAD's sampling interval: 2000/7 Hz.
BROAD_DT = 0.0035


def read_trial(path):
    """The gyro (rad/s), accelerometer (m/s^2) and magnetometer (uT) columns."""
    opener = gzip.open if path.endswith(".gz") else open
    with opener(path, "rt", newline="") as f:
        rows = csv.reader(f)
        header = next(rows)
        columns = [header.index(name) for name in (
            "gyr_x", "gyr_y", "gyr_z",
            "acc_x", "acc_y", "acc_z",
            "mag_x", "mag_y", "mag_z",
        )]
        data = np.array([[float(row[c]) for c in columns] for row in rows])
    return (np.ascontiguousarray(data[:, 0:3]),
            np.ascontiguousarray(data[:, 3:6]),
            np.ascontiguousarray(data[:, 6:9]))


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: vqf_broad.py TRIAL.csv[.gz]")
    gyr, acc, mag = read_trial(sys.argv[1])
    six = VQF(BROAD_DT).updateBatch(gyr, acc)["quat6D"]
    nine = VQF(BROAD_DT).updateBatch(gyr, acc, mag)["quat9D"]
    out = sys.stdout
    out.write("w6,x6,y6,z6,w9,x9,y9,z9\n")
    for a, b in zip(six, nine):
        out.write(",".join(f"{v:.9g}" for v in (*a, *b)) + "\n")


if __name__ == "__main__":
    main()
