"""A design study split into shards, each solved in its own process: the scale-out path beyond one machine.

Each shard is `tiltpad.batch(case, designs, shard=(i, n))`: the i-th of n contiguous blocks of the designs,
solved from scratch, so the shards' rows put together are the whole batch's, row for row, whichever machine
solved which shard. Here the shards go to a local process pool; the same function submitted to Dask
(`client.map(run_shard, range(1, n + 1))`), Ray or a Slurm array job (`--shard $SLURM_ARRAY_TASK_ID/$N`)
spreads them over machines.

    python examples/python/design_study.py [--shards 4] [--workers 2] [--out study.csv]

Needs pandas: pip install './python[pandas]'.
"""

from __future__ import annotations

import argparse
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import tiltpad

ROOT = Path(__file__).resolve().parents[2]
CASE = ROOT / "cases" / "compressor-bearing.toml"
DESIGNS = ROOT / "cases" / "designs-compressor.csv"


def run_shard(index: int, count: int, fidelity: str):
    """One shard of the batch (in a worker process: everything it needs is loaded here)."""
    case = tiltpad.load_case(str(CASE))
    return tiltpad.batch(case, DESIGNS.read_text(), shard=(index, count), fidelity=fidelity)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--shards", type=int, default=4)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--fidelity", default="preview")
    ap.add_argument("--out", default="study.csv")
    args = ap.parse_args()

    import pandas as pd

    with ProcessPoolExecutor(args.workers) as pool:
        futures = [pool.submit(run_shard, i, args.shards, args.fidelity) for i in range(1, args.shards + 1)]
        parts = [f.result() for f in futures]
    table = pd.concat(parts, ignore_index=True)
    table.to_csv(args.out, index=False)
    failed = table[table["error"] != ""]
    print(f"{len(table)} designs, {len(failed)} failed; wrote {args.out}")
    best = table[table["error"] == ""].sort_values("h_min_um", ascending=False).head(5)
    print(best[["design", *[c for c in table.columns if c.startswith("bearing.") or c.startswith("operating.")],
                "eccentricity_ratio", "h_min_um", "p_max_mpa"]].to_string(index=False))


if __name__ == "__main__":
    main()
