"""What the Python package adds to a solve: `tiltpad.solve` against the command line's `tiltpad solve` on the same
case, and what two threads give over one.

    python python/benchmarks/overhead.py [--cli target/release/tiltpad] [--repeat 7] [--write-doc] [CASE ...]

Both should be release builds (`pip install ./python` builds one; `cargo build --release`). Per case, interleaved
and repeated (medians reported):

- CLI process: the wall time of `tiltpad solve CASE` (read, validate, solve, print the summary);
- CLI start: the same process stopped by an invalid value right after validation (start-up, reading and
  validating the case, no solve). CLI solve = process − start: what the solve costs inside the command line;
- equilibrium: the time each one's report gives for the equilibrium (`report.seconds`, `--json` for the CLI);
- Python: `tiltpad.solve(case)` on a loaded case (it resolves the case again, solves with the GIL released and
  wraps the result), then reading every result array once (each array is copied once, on its first read).

The ratio (Python + arrays) / CLI solve is what the Python package costs against the command line; the ratio
to the whole CLI process is what a script saves by not starting a process per solve. Then four solves of the
first case at four speeds, one after the other and on two threads (the GIL is released while solving).

`--write-doc` replaces the section "## Python package" of docs/PERFORMANCE.md with the table (`cargo xtask bench`
keeps that section as it is).
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import statistics
import subprocess
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import tiltpad

ROOT = Path(__file__).resolve().parents[2]
CASES = ["cases/compressor-bearing.toml", "cases/fillon-a.toml", "cases/compressor-bearing-tehd.toml"]
HEADING = "## Python package (`tiltpad.solve`)"
# A value out of range: the command line reads and validates the case, then stops before solving.
INVALID = "bearing.pads.preload=5"


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


def timed(f) -> float:
    t0 = time.perf_counter()
    f()
    return time.perf_counter() - t0


def measure(cli: str, rel: str, repeat: int) -> dict:
    path = str(ROOT / rel)
    case = tiltpad.load_case(path)
    process, start, py, arrays, eq_cli, eq_py = [], [], [], [], [], []
    values = 0
    with tempfile.TemporaryDirectory() as d:
        out = Path(d) / "out.json"
        for _ in range(repeat):
            process.append(timed(lambda: subprocess.run([cli, "solve", path], check=True, capture_output=True)))
            start.append(timed(lambda: subprocess.run([cli, "solve", path, "--set", INVALID], capture_output=True)))
            # The equilibrium's own time as each reports it (the same solver code in both).
            subprocess.run([cli, "solve", path, "--json", str(out)], check=True, capture_output=True)
            eq_cli.append(json.loads(out.read_text())["report"]["seconds"])
            holder = {}
            py.append(timed(lambda: holder.setdefault("r", tiltpad.solve(case))))
            r = holder["r"]
            eq_py.append(r.report["seconds"])
            arrays.append(timed(lambda: holder.setdefault("n", read_everything(r))))
            values = holder["n"]
    row = {name: statistics.median(v) for name, v in
           (("process", process), ("start", start), ("python", py), ("arrays", arrays), ("eq_cli", eq_cli),
            ("eq_py", eq_py))}
    row["cli_solve"] = row["process"] - row["start"]
    row["values"] = values
    row["case"] = rel
    row["nodes"] = sum(len(p.s_m) * len(p.z_m) for p in r.pads)
    return row


def threads(rel: str, repeat: int) -> tuple[float, float]:
    case = tiltpad.load_case(str(ROOT / rel))
    cases = [case.with_values({"operating.speed_rpm": n}) for n in (7000, 8000, 9000, 10000)]
    one, two = [], []
    for _ in range(repeat):
        one.append(timed(lambda: [tiltpad.solve(c) for c in cases]))
        with ThreadPoolExecutor(2) as pool:
            two.append(timed(lambda: list(pool.map(tiltpad.solve, cases))))
    return statistics.median(one), statistics.median(two)


def section(rows: list, one: float, two: float, repeat: int, load: tuple, command: str) -> str:
    lines = [
        HEADING,
        "",
        f"`{command}` (release builds of the command line and of the package, median of {repeat}, interleaved; "
        f"{os.cpu_count()} cores, load average {load[0]:.1f} before and {load[1]:.1f} after, Python "
        f"{platform.python_version()}). CLI solve = the `tiltpad solve` process less the same process stopped "
        "after validating the case; Python = `tiltpad.solve(case)` plus reading every result array once (one "
        "copy per array). The last column is the equilibrium's time as each one's report gives it "
        "(`report.seconds`, the same solver code): what the Python call does beyond the solver is the "
        "difference between its wall time and that.",
        "",
        "| case | film nodes | CLI process | CLI start | CLI solve | Python solve | arrays (values) | Python / CLI solve | Python / CLI process | equilibrium CLI / Python |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    for r in rows:
        py = r["python"] + r["arrays"]
        lines.append(
            f"| {r['case']} | {r['nodes']} | {1e3 * r['process']:.1f} ms | {1e3 * r['start']:.1f} ms | "
            f"{1e3 * r['cli_solve']:.1f} ms | {1e3 * r['python']:.1f} ms | {1e3 * r['arrays']:.2f} ms "
            f"({r['values']}) | {py / r['cli_solve']:.3f} | {py / r['process']:.3f} | "
            f"{1e3 * r['eq_cli']:.1f} / {1e3 * r['eq_py']:.1f} ms |"
        )
    worst = max((r["python"] + r["arrays"]) / r["cli_solve"] for r in rows)
    status = "met" if worst <= 1.05 else "not met"
    lines += [
        "",
        f"Target: a Python solve costs at most 5 % more than the command line's (Python / CLI solve ≤ 1.05): "
        f"**{status}**, largest ratio {worst:.3f}.",
        "",
        f"Four solves of {rows[0]['case']} (7000–10000 rpm): one thread {1e3 * one:.0f} ms, two threads "
        f"{1e3 * two:.0f} ms ({one / two:.2f}× faster; the GIL is released while solving).",
        "",
    ]
    return "\n".join(lines)


def replace_section(text: str) -> None:
    path = ROOT / "docs" / "PERFORMANCE.md"
    doc = path.read_text(encoding="utf-8")
    start = doc.find(HEADING)
    if start >= 0:
        end = doc.find("\n## ", start + len(HEADING))
        doc = doc[:start] + text + ("\n" + doc[end + 1:] if end >= 0 else "")
    else:
        # Where `cargo xtask bench` keeps it: after the notes, before the web build's section.
        web = doc.find("\n## Web build")
        doc = doc[:web + 1] + text + "\n" + doc[web + 1:] if web >= 0 else doc.rstrip("\n") + "\n\n" + text
    path.write_text(doc, encoding="utf-8")
    print(f"updated {path}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cli", default=str(ROOT / "target" / "release" / "tiltpad"))
    ap.add_argument("--repeat", type=int, default=7)
    ap.add_argument("--write-doc", action="store_true", help="replace the section of docs/PERFORMANCE.md")
    ap.add_argument("cases", nargs="*", default=CASES)
    args = ap.parse_args()
    load_before = os.getloadavg()[0]
    rows = []
    print(f"{'case':40} {'process':>9} {'start':>7} {'CLI solve':>9} {'Python':>8} {'arrays':>8} {'Py/CLI':>7}")
    for rel in args.cases:
        r = measure(args.cli, rel, args.repeat)
        rows.append(r)
        ratio = (r["python"] + r["arrays"]) / r["cli_solve"]
        print(f"{rel:40} {1e3 * r['process']:7.1f}ms {1e3 * r['start']:5.1f}ms {1e3 * r['cli_solve']:7.1f}ms "
              f"{1e3 * r['python']:6.1f}ms {1e3 * r['arrays']:6.2f}ms {ratio:7.3f}   equilibrium "
              f"{1e3 * r['eq_cli']:.1f} / {1e3 * r['eq_py']:.1f} ms")
    one, two = threads(args.cases[0], args.repeat)
    print(f"four solves of {args.cases[0]}: one thread {one:.3f} s, two threads {two:.3f} s")
    load = (load_before, os.getloadavg()[0])
    if args.write_doc:
        command = "python python/benchmarks/overhead.py --write-doc"
        if args.repeat != 7:
            command += f" --repeat {args.repeat}"
        replace_section(section(rows, one, two, args.repeat, load, command))


if __name__ == "__main__":
    main()
