"""A design study with Dask: the batch split into shards, each shard a Dask task, on a local cluster or on any
Dask cluster (the scale-out path beyond one machine; `design_study.py` does the same over a process pool).

Each task is `tiltpad.batch(case, designs, shard=(i, n))`: the i-th of n contiguous blocks of the designs,
each design solved from scratch, so the shards' rows put together are the whole batch's, row for row,
whichever worker solved which shard. The solver releases the GIL, so a worker's threads solve in parallel
too.

    python examples/python/design_study_dask.py [--shards 8] [--workers 2] [--scheduler tcp://host:8786]

Without `--scheduler` a `LocalCluster` of `--workers` processes (one thread each) runs here; with it, the tasks
go to that cluster (its workers need the tiltpad package and read the case and designs from the text sent
with each task, so they need no shared file system). Needs `pip install './python[dask]'` (Dask's distributed scheduler and pandas).
"""

from __future__ import annotations

import argparse
from pathlib import Path

import tiltpad

ROOT = Path(__file__).resolve().parents[2]
CASE = ROOT / "cases" / "compressor-bearing.toml"
DESIGNS = ROOT / "cases" / "designs-compressor.csv"


def run_shard(case_text: str, designs_csv: str, index: int, count: int, fidelity: str):
    """One shard of the batch, on a Dask worker: the case and designs travel as text."""
    case = tiltpad.load_case(case_text)
    return tiltpad.batch(case, designs_csv, shard=(index, count), fidelity=fidelity)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--shards", type=int, default=8)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--fidelity", default="preview")
    ap.add_argument("--scheduler", default=None, help="address of a running Dask scheduler")
    ap.add_argument("--out", default="study-dask.csv")
    args = ap.parse_args()

    import pandas as pd
    from dask.distributed import Client, LocalCluster

    case_text, designs = CASE.read_text(), DESIGNS.read_text()
    if args.scheduler:
        client = Client(args.scheduler)
    else:
        client = Client(LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True))
    with client:
        futures = [
            client.submit(run_shard, case_text, designs, i, args.shards, args.fidelity, pure=False)
            for i in range(1, args.shards + 1)
        ]
        parts = client.gather(futures)
    table = pd.concat(parts, ignore_index=True)
    table.to_csv(args.out, index=False)
    failed = table[table["error"] != ""]
    print(f"{len(table)} designs in {args.shards} shards, {len(failed)} failed; wrote {args.out}")
    best = table[table["error"] == ""].sort_values("h_min_um", ascending=False).head(5)
    inputs = [c for c in table.columns if c.startswith(("bearing.", "operating."))]
    print(best[["design", *inputs, "eccentricity_ratio", "h_min_um", "p_max_mpa"]].to_string(index=False))


if __name__ == "__main__":
    main()
