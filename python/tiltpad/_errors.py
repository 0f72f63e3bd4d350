"""The exceptions and warnings of tiltpad.

Every error of the solver library arrives as one of these, with the data the library's typed error carries:
``kind`` (the variant, snake_case: ``"out_of_range"``, ``"touchdown"`` …) and ``details`` (its fields), and
for case errors the ``key`` it concerns, the offending ``value`` and the ``allowed`` range, so a script can
react to the condition rather than parse the message. ``str(error)`` is the message the command line prints.
"""

from __future__ import annotations

from typing import Any, Optional


class TiltpadError(Exception):
    """Base of every tiltpad error.

    Attributes:
        kind: the variant of the library's error, snake_case (``"out_of_range"``, ``"touchdown"``, …).
        details: the variant's fields (numbers in SI or with their unit in the name), as the JSON form has them.
    """

    def __init__(self, message: str, kind: str = "", details: Optional[dict] = None):
        super().__init__(message)
        self.message = message
        self.kind = kind
        self.details = details or {}


class CaseError(TiltpadError, ValueError):
    """A case that cannot be read or is invalid: the same messages as ``tiltpad solve``.

    Attributes:
        key: the dotted case key concerned (``"bearing.pads.preload"``), or None (a TOML syntax error).
        value: the offending value (in the key's unit, as written), or None where there is no single value.
        allowed: the allowed values or range as the schema writes it (``"a finite number in [-1, 1)"``), or None.
    """

    def __init__(
        self,
        message: str,
        kind: str = "",
        details: Optional[dict] = None,
        key: Optional[str] = None,
        value: Any = None,
        allowed: Optional[str] = None,
    ):
        super().__init__(message, kind, details)
        self.key = key
        self.value = value
        self.allowed = allowed


class SolveError(TiltpadError, RuntimeError):
    """A solve that failed: touchdown, no stiffness along the load, a spent budget, … (``kind`` says which)."""


class Cancelled(TiltpadError):
    """The solve was cancelled: by a :class:`CancelToken`, by the progress callback returning False, or by
    Ctrl-C (then ``KeyboardInterrupt`` is raised instead)."""


class StudyError(TiltpadError, ValueError):
    """A sweep or a batch that cannot start: a bad axis, a bad designs table or shard."""


class RotorError(TiltpadError, RuntimeError):
    """A rotor analysis that cannot run or failed (its bearing solves, its eigen-solutions)."""


class TiltpadWarning(UserWarning):
    """Base of tiltpad's warnings."""


class BandWarning(TiltpadWarning):
    """Coefficients sampled over a speed band that may not serve the rotor analysis as they are: the band
    does not cover the analysis range (ROSS extrapolates), the coefficients jump between samples (ROSS's
    spline overshoots), or a speed failed and was left out."""
