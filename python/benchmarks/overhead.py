"""What the Python package adds to a solve: `tiltpad.solve` against `tiltpad solve --json` (the command line,
a process per solve) on the same case, and the cost of reading every result array once.

    python python/benchmarks/overhead.py [--cli target/release/tiltpad] [--repeat 5] [CASE ...]

Both should be release builds (`pip install ./python` builds one; `cargo build --release`). Prints one row per
case: the median wall time of each, their ratio, and the time to read every array of the result.
"""

from __future__ import annotations

import argparse
import statistics
import subprocess
import tempfile
import time
from pathlib import Path

import tiltpad

ROOT = Path(__file__).resolve().parents[2]
CASES = ["cases/compressor-bearing.toml", "cases/fillon-a.toml", "cases/compressor-bearing-tehd.toml"]


def read_everything(r) -> int:
    n = 0
    for name in ("k_n_per_m", "c_ns_per_m", "full_k", "full_c", "full_m", "load_n", "journal_position_m"):
        n += getattr(r, name).size
    for p in r.pads:
        for name in ("pressure_pa", "film_thickness_m", "viscosity_pa_s", "cavitated", "s_m", "z_m", "theta_rad"):
            n += getattr(p, name).size
        for name in ("film_temperature_c", "pad_surface_temperature_c", "pad_temperature_c"):
            a = getattr(p, name)
            n += 0 if a is None else a.size
    return n


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cli", default=str(ROOT / "target" / "release" / "tiltpad"))
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("cases", nargs="*", default=CASES)
    args = ap.parse_args()
    print(f"{'case':40} {'CLI [s]':>9} {'Python [s]':>10} {'ratio':>7} {'arrays [ms]':>11} {'values':>9}")
    for rel in args.cases:
        path = str(ROOT / rel)
        case = tiltpad.load_case(path)
        cli, py, arrays = [], [], []
        with tempfile.TemporaryDirectory() as d:
            out = Path(d) / "out.json"
            for _ in range(args.repeat):
                t0 = time.perf_counter()
                subprocess.run([args.cli, "solve", path, "--json", str(out)], check=True, capture_output=True)
                cli.append(time.perf_counter() - t0)
                t0 = time.perf_counter()
                r = tiltpad.solve(case)
                py.append(time.perf_counter() - t0)
                t0 = time.perf_counter()
                n = read_everything(r)
                arrays.append(time.perf_counter() - t0)
        c, p, a = statistics.median(cli), statistics.median(py), statistics.median(arrays)
        print(f"{rel:40} {c:9.3f} {p:10.3f} {p / c:7.3f} {1e3 * a:11.2f} {n:9d}")


if __name__ == "__main__":
    main()
