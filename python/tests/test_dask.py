"""The Dask path (examples/python/design_study_dask.py): shards of a batch as Dask tasks give the rows of one
batch, row for row. Skips with a clear message where Dask is not installed."""

from __future__ import annotations

import numpy as np
import pytest

import tiltpad
from conftest import CASES

try:
    import dask
except ImportError as e:  # pragma: no cover - depends on the environment
    pytest.skip(f"Dask is not installed here ({e}); pip install dask to run the Dask tests", allow_module_level=True)

CASE = CASES / "compressor-bearing.toml"
DESIGNS = CASES / "designs-compressor.csv"


def run_shard(case_text: str, designs_csv: str, index: int, count: int):
    return tiltpad.batch(tiltpad.load_case(case_text), designs_csv, shard=(index, count), fidelity="preview",
                         as_frame=False)


def test_dask_shards_join_into_the_whole_batch():
    case_text, designs = CASE.read_text(), DESIGNS.read_text()
    tasks = [dask.delayed(run_shard)(case_text, designs, i, 3) for i in range(1, 4)]
    # The threaded scheduler: the solves release the GIL, so the tasks' threads solve in parallel.
    parts = dask.compute(*tasks, scheduler="threads", num_workers=2)
    whole = run_shard(case_text, designs, 1, 1)
    assert sum(len(p["design"]) for p in parts) == len(whole["design"]) == 12
    for column in ("design", "eccentricity_ratio", "h_min_um", "kyy_n_per_m", "error"):
        joined = np.concatenate([np.asarray(p[column]) for p in parts])
        np.testing.assert_array_equal(joined, np.asarray(whole[column]), err_msg=column)
