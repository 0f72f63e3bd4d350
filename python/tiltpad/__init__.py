"""tiltpad: tilting-pad journal bearings (with controllable lubrication) for Python.

The solver is the tiltpad Rust library, compiled into this package: the same case files, the same dotted case
keys and validation, the same numbers as the ``tiltpad`` command line.

    >>> import tiltpad
    >>> case = tiltpad.load_case("cases/compressor-bearing.toml")
    >>> case.set("bearing.pads.preload", 0.3)
    >>> result = tiltpad.solve(case, fidelity="preview")
    >>> result.eccentricity, result.h_min_um, result.k_n_per_m.shape
    (0.31..., 27.4..., (2, 2))

Units: SI inside and in every attribute whose name carries no other unit; an engineering unit is always in the
name (``speed_rpm``, ``h_min_um``, ``p_max_mpa``, ``t_max_film_c``). Case keys take the unit their name or the
schema (:func:`schema`) gives.

Every solve releases the GIL, so a thread pool runs solves in parallel; each long call takes
``progress(fraction, message)`` (return ``False`` to stop) and ``cancel`` (a :class:`CancelToken`).
"""

from __future__ import annotations

from typing import Any, Callable, Dict, Iterable, Mapping, Optional, Sequence, Tuple, Union

from . import _tiltpad
from ._errors import (
    BandWarning,
    Cancelled,
    CaseError,
    RotorError,
    SolveError,
    StudyError,
    TiltpadError,
    TiltpadWarning,
)
from ._tiltpad import (
    CancelToken,
    Case,
    Coefficients,
    Pad,
    RotorResult,
    Solution,
    coefficients,
    frf,
    load_case,
    rotor,
    schema,
    solve,
)

__version__: str = _tiltpad.__version__

__all__ = [
    "BandWarning",
    "CancelToken",
    "Cancelled",
    "Case",
    "CaseError",
    "Coefficients",
    "Pad",
    "RotorError",
    "RotorResult",
    "Solution",
    "SolveError",
    "StudyError",
    "TiltpadError",
    "TiltpadWarning",
    "batch",
    "coefficients",
    "frf",
    "load_case",
    "rotor",
    "schema",
    "solve",
    "sweep",
    "table",
]


def table(columns: Dict[str, Any], as_frame: Optional[bool] = None) -> Any:
    """The columns of a study as a pandas DataFrame when pandas is installed (or ``as_frame=True``), else the
    dict of columns itself (NumPy arrays for numbers, lists for inputs, limits and errors)."""
    if as_frame is False:
        return columns
    try:
        import pandas as pd
    except ImportError:
        if as_frame:
            raise
        return columns
    return pd.DataFrame(columns)


def sweep(
    case: Case,
    axes: Union[Mapping[str, Iterable[Any]], Sequence[Tuple[str, Iterable[Any]]]],
    *,
    fidelity: Optional[str] = None,
    progress: Optional[Callable[[float, str], Any]] = None,
    cancel: Optional[CancelToken] = None,
    as_frame: Optional[bool] = None,
) -> Any:
    """Solves ``case`` at every point of the grid of ``axes`` (``{"bearing.pads.preload": [0.1, 0.3, 0.5],
    "operating.speed_rpm": np.linspace(3000, 12000, 10)}``: the last key varies fastest), warm-starting each
    point from the previous one, as ``tiltpad sweep`` does.

    Returns the command line's CSV columns (``point``, the keys, ``eccentricity_ratio`` … ``h_min_um``,
    ``p_max_mpa``, ``t_max_film_c``, ``kxx_n_per_m`` …, ``limits_exceeded``, ``seconds``, ``error``) as a pandas
    DataFrame, or a dict of arrays without pandas (``as_frame=False`` forces the dict). A point that fails keeps
    its row, with NaN outputs and its message in ``error``. Releases the GIL while solving.
    """
    items = list(axes.items()) if isinstance(axes, Mapping) else list(axes)
    pairs = [(str(k), list(v)) for k, v in items]
    cols = _tiltpad._sweep(case, pairs, fidelity=fidelity, progress=progress, cancel=cancel)
    return table(cols, as_frame)


def batch(
    case: Case,
    designs: Any,
    *,
    shard: Optional[Tuple[int, int]] = None,
    workers: int = 1,
    fidelity: Optional[str] = None,
    progress: Optional[Callable[[float, str], Any]] = None,
    cancel: Optional[CancelToken] = None,
    as_frame: Optional[bool] = None,
) -> Any:
    """Solves one design per row of ``designs`` on top of ``case``, each from scratch (so a row does not depend
    on the rows before it), as ``tiltpad batch`` does.

    ``designs``: a pandas DataFrame, a dict of columns ``{key: [values…]}``, a list of dicts ``[{key: value}]``,
    or the text of a designs CSV (``cases/designs-compressor.csv``). Empty cells (None, NaN) keep the case's
    value. ``shard=(i, n)`` runs the i-th of n contiguous parts (1-based), as ``--shard i/n``: the union of
    the shards is the whole batch, row for row. ``workers`` threads solve blocks of rows in parallel.

    Returns the CSV columns (``design``, the keys, the outputs, ``limits_exceeded``, ``seconds``, ``error``)
    as a DataFrame, or a dict without pandas.
    """
    if hasattr(designs, "to_dict") and hasattr(designs, "columns"):
        designs = {str(c): list(designs[c]) for c in designs.columns}
    cols = _tiltpad._batch(
        case, designs, shard=shard, workers=workers, fidelity=fidelity, progress=progress, cancel=cancel
    )
    return table(cols, as_frame)


def __getattr__(name: str) -> Any:
    # `tiltpad.ross` imports ROSS (slow, optional): loaded on first use.
    if name == "ross":
        import importlib

        return importlib.import_module(".ross", __name__)
    raise AttributeError(f"module 'tiltpad' has no attribute {name!r}")
