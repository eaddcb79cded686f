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

# BROAD's sampling interval: 2000/7 Hz.
BROAD_DT = 0.0035

COLUMNS = (
    "gyr_x", "gyr_y", "gyr_z",
    "acc_x", "acc_y", "acc_z",
    "mag_x", "mag_y", "mag_z",
)


def read_trial(path):
    """The gyro (rad/s), accelerometer (m/s^2) and magnetometer (uT) columns,
    one list of nine floats per sample. Reads the file as the Rust reader
    does (testkit/src/broad/data.rs): a UTF-8 byte-order mark is skipped,
    and so are blank lines; a file without samples, a missing column or a
    field that is not a number is an error naming the file and the line."""
    opener = gzip.open if path.endswith(".gz") else open
    with opener(path, "rt", encoding="utf-8-sig", newline="") as f:
        rows = csv.reader(f)
        header = [name.strip() for name in next(rows, [])]
        missing = [name for name in COLUMNS if name not in header]
        if missing:
            raise ValueError(f"{path}: line 1: no column {missing[0]!r}")
        columns = [header.index(name) for name in COLUMNS]
        data = []
        for row in rows:
            if all(not field.strip() for field in row):
                continue
            try:
                data.append([float(row[c]) for c in columns])
            except (IndexError, ValueError) as e:
                raise ValueError(f"{path}: line {rows.line_num}: {e}") from None
    if not data:
        raise ValueError(f"{path}: no samples")
    return data


def run_on_trial(script, estimates):
    """The command line of the peers' scripts: one trial's path in, a header
    and one line of 6D and 9D quaternions per sample out. `estimates(data)`
    yields each sample's eight components from the trial's samples (as
    `read_trial` gives them); a bad path or file is an error, not a trace."""
    if len(sys.argv) != 2:
        sys.exit(f"usage: {script} TRIAL.csv[.gz]")
    try:
        data = read_trial(sys.argv[1])
    except (OSError, ValueError) as e:
        sys.exit(f"error: {e}")
    out = sys.stdout
    out.write("w6,x6,y6,z6,w9,x9,y9,z9\n")
    for q in estimates(data):
        out.write(",".join(f"{v:.9g}" for v in q) + "\n")


def vqf_estimates(data):
    """VQF's causal 6D and 9D estimates of the samples, batch by batch."""
    import numpy as np
    from vqf import VQF

    data = np.array(data)
    gyr, acc, mag = (np.ascontiguousarray(data[:, i:i + 3]) for i in (0, 3, 6))
    six = VQF(BROAD_DT).updateBatch(gyr, acc)["quat6D"]
    nine = VQF(BROAD_DT).updateBatch(gyr, acc, mag)["quat9D"]
    for a, b in zip(six, nine):
        yield (*a, *b)


def main():
    run_on_trial("vqf_broad.py", vqf_estimates)


if __name__ == "__main__":
    main()
