"""The hand-off to ROSS (the ``ross-rotordynamics`` package): tiltpad bearings as ``ross.BearingElement``.

ROSS interpolates a bearing element's coefficients between its sample frequencies with a cubic spline and
extrapolates it outside them. So :func:`bearing_element` samples the speed band as ``tiltpad coefficients
--ross`` does (the same sampler, with the same numbers): every interval between neighbouring speeds is checked
at its midpoint and halved where a cubic through the samples misses the solved coefficients by more than 0.5 %
of the largest term, or where a pad starts or stops floating. It warns (:class:`tiltpad.BandWarning`) when
the band does not cover the analysis speeds it is given (ROSS would extrapolate there) or when the
coefficients still jump between samples (ROSS's spline overshoots around a jump).

Importing this module does not import ROSS; the functions that build elements do, and raise ``ImportError``
with the install command when it is missing.
"""

from __future__ import annotations

import warnings
from typing import Any, Callable, List, Optional, Sequence, Union

from ._errors import BandWarning
from ._tiltpad import CancelToken, Case, Coefficients, coefficients

__all__ = ["bearing_element", "bearing_elements", "sample"]


def _ross() -> Any:
    try:
        import ross
    except ImportError as e:  # pragma: no cover - depends on the environment
        raise ImportError(
            "tiltpad.ross needs ROSS: pip install ross-rotordynamics (or the package's extra: pip install "
            "'./python[ross]')"
        ) from e
    return ross


def sample(
    case: Case,
    *,
    speeds_rpm: Sequence[float],
    analysis_speeds_rpm: Optional[Sequence[float]] = None,
    refine: bool = True,
    fidelity: Optional[str] = None,
    progress: Optional[Callable[[float, str], Any]] = None,
    cancel: Optional[CancelToken] = None,
    stacklevel: int = 2,
) -> Coefficients:
    """The coefficients a ROSS bearing element gets over ``speeds_rpm`` [rpm] (refined unless ``refine`` is
    False), each of the sampling's warnings issued as a :class:`tiltpad.BandWarning`."""
    table = coefficients(
        case,
        speeds_rpm=[float(s) for s in speeds_rpm],
        refine=refine,
        analysis_speeds_rpm=None if analysis_speeds_rpm is None else [float(s) for s in analysis_speeds_rpm],
        fidelity=fidelity,
        progress=progress,
        cancel=cancel,
    )
    for message in table.warnings:
        warnings.warn(BandWarning(message), stacklevel=stacklevel + 1)
    return table


def _element(ross: Any, table: Coefficients, n: int, tag: str) -> Any:
    k = table.k_n_per_m
    c = table.c_ns_per_m
    return ross.BearingElement(
        n=int(n),
        kxx=k[:, 0, 0].tolist(),
        kxy=k[:, 0, 1].tolist(),
        kyx=k[:, 1, 0].tolist(),
        kyy=k[:, 1, 1].tolist(),
        cxx=c[:, 0, 0].tolist(),
        cxy=c[:, 0, 1].tolist(),
        cyx=c[:, 1, 0].tolist(),
        cyy=c[:, 1, 1].tolist(),
        frequency=table.frequency_rad_s.tolist(),
        tag=tag,
    )


def bearing_element(
    case: Case,
    *,
    n: int,
    speeds_rpm: Sequence[float],
    tag: str = "tiltpad",
    analysis_speeds_rpm: Optional[Sequence[float]] = None,
    refine: bool = True,
    fidelity: Optional[str] = None,
    progress: Optional[Callable[[float, str], Any]] = None,
    cancel: Optional[CancelToken] = None,
) -> Any:
    """A ``ross.BearingElement`` at rotor node ``n`` with the reduced coefficients of ``case`` over the running
    speeds ``speeds_rpm`` [rpm] (its ``frequency`` is the running speed in rad/s; x horizontal, y vertical up,
    as in ROSS), sampled densely enough for ROSS's spline (see the module).

    ``analysis_speeds_rpm``: the speeds of the rotor analysis (a Campbell diagram's ``speed_range`` in rpm):
    a :class:`tiltpad.BandWarning` when the band does not cover them. The element equals the one
    ``tiltpad coefficients CASE --speed-rpm … --node n --ross FILE`` writes, read by
    ``ross.BearingElement.load(FILE)``.
    """
    return _elements(case, [n], [tag], speeds_rpm, analysis_speeds_rpm, refine, fidelity, progress, cancel)[0]


def bearing_elements(
    case: Case,
    *,
    nodes: Sequence[int],
    speeds_rpm: Sequence[float],
    tags: Union[str, Sequence[str]] = "tiltpad",
    analysis_speeds_rpm: Optional[Sequence[float]] = None,
    refine: bool = True,
    fidelity: Optional[str] = None,
    progress: Optional[Callable[[float, str], Any]] = None,
    cancel: Optional[CancelToken] = None,
) -> List[Any]:
    """One ``ross.BearingElement`` per node of ``nodes``, all with the coefficients of ``case`` (one sampling):
    the bearings of a rotor that carries the same bearing at several nodes. ``tags``: one per node, or one
    for all (then ``TAG_<node>``, as ``tiltpad coefficients --node 3,12 --tag TAG`` names them)."""
    nodes = [int(x) for x in nodes]
    if isinstance(tags, str):
        names = [tags] if len(nodes) == 1 else [f"{tags}_{x}" for x in nodes]
    else:
        names = [str(t) for t in tags]
        if len(names) != len(nodes):
            raise ValueError(f"{len(names)} tags for {len(nodes)} nodes: give one tag, or one per node")
    return _elements(case, nodes, names, speeds_rpm, analysis_speeds_rpm, refine, fidelity, progress, cancel)


def _elements(case, nodes, tags, speeds_rpm, analysis_speeds_rpm, refine, fidelity, progress, cancel) -> List[Any]:
    ross = _ross()
    # Warnings point at the caller of bearing_element(s): this frame, the public function, then the caller.
    table = sample(
        case,
        speeds_rpm=speeds_rpm,
        analysis_speeds_rpm=analysis_speeds_rpm,
        refine=refine,
        fidelity=fidelity,
        progress=progress,
        cancel=cancel,
        stacklevel=3,
    )
    return [_element(ross, table, x, t) for x, t in zip(nodes, tags)]
