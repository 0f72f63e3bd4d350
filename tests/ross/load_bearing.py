"""Loads a tiltpad coefficient file with ROSS itself and checks the numbers against tiltpad's CSV.

Not part of `cargo test` (ROSS is a Python package, not a dependency of tiltpad). Run it where
`pip install ross-rotordynamics` works (ROSS 2.3.0 needs plotly < 6):

    tiltpad coefficients cases/compressor-bearing.toml --speed-rpm 6000:11000:6 --node 8 \
        --ross /tmp/brg.toml --csv /tmp/brg.csv
    python tests/ross/load_bearing.py /tmp/brg.toml /tmp/brg.csv
"""

import csv
import sys

import numpy as np
import ross

toml_path, csv_path = sys.argv[1], sys.argv[2]
bearing = ross.BearingElement.load(toml_path)
with open(csv_path, newline="") as f:
    rows = list(csv.DictReader(f))

assert bearing.n == 8, bearing.n
freq = np.array([float(r["frequency_rad_s"]) for r in rows])
assert np.allclose(bearing.frequency, freq, rtol=0, atol=0), (bearing.frequency, freq)
for i, r in enumerate(rows):
    k = bearing.K(freq[i])
    c = bearing.C(freq[i])
    for (a, b), name in [((0, 0), "xx"), ((0, 1), "xy"), ((1, 0), "yx"), ((1, 1), "yy")]:
        assert np.isclose(k[a, b], float(r[f"k{name}_n_per_m"]), rtol=1e-9), (name, k[a, b], r)
        assert np.isclose(c[a, b], float(r[f"c{name}_ns_per_m"]), rtol=1e-9), (name, c[a, b], r)
print(f"ROSS {ross.__version__} loaded {toml_path}: node {bearing.n}, {len(freq)} frequencies, "
      f"K and C at every frequency equal to the CSV")
