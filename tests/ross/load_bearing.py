"""Loads a tiltpad coefficient file with ROSS itself and checks the numbers against tiltpad's CSV.

Not part of `cargo test` (ROSS is a Python package, not a dependency of tiltpad). Run it where
`pip install ross-rotordynamics` works (ROSS 2.3.0 needs plotly < 6):

    tiltpad coefficients cases/compressor-bearing.toml --speed-rpm 6000:11000:6 --node 8 \
        --ross /tmp/brg.toml --csv /tmp/brg.csv
    python tests/ross/load_bearing.py /tmp/brg.toml /tmp/brg.csv 8

The coefficients ROSS stores must equal the CSV exactly; K(f) and C(f), which ROSS evaluates through a
smoothing spline, only to the spline's accuracy.
"""

import csv
import sys

import numpy as np
import ross

toml_path, csv_path, node = sys.argv[1], sys.argv[2], int(sys.argv[3])
bearing = ross.BearingElement.load(toml_path)
with open(csv_path, newline="") as f:
    rows = list(csv.DictReader(f))

assert bearing.n == node, bearing.n
freq = np.array([float(r["frequency_rad_s"]) for r in rows])
assert np.allclose(bearing.frequency, freq, rtol=0, atol=0), (bearing.frequency, freq)
for kind, unit in [("k", "n_per_m"), ("c", "ns_per_m")]:
    for name in ["xx", "xy", "yx", "yy"]:
        stored = np.asarray(getattr(bearing, f"{kind}{name}"), dtype=float)
        expected = np.array([float(r[f"{kind}{name}_{unit}"]) for r in rows])
        assert np.array_equal(stored, expected), (kind + name, stored, expected)
scale = max(abs(float(r["kyy_n_per_m"])) for r in rows)
for i, r in enumerate(rows):
    k = bearing.K(freq[i])
    for (a, b), name in [((0, 0), "xx"), ((0, 1), "xy"), ((1, 0), "yx"), ((1, 1), "yy")]:
        assert abs(k[a, b] - float(r[f"k{name}_n_per_m"])) < 1e-3 * scale, (name, k[a, b], r)
print(f"ROSS {ross.__version__} loaded {toml_path}: node {bearing.n}, {len(freq)} frequencies, "
      f"stored K and C equal to the CSV, K(f) through ROSS's spline within 0.1 % of K_yy")
