"""Type stubs of tiltpad's compiled module. Units: SI unless the name says otherwise (``_rpm``, ``_um``, ``_mpa``,
``_c`` for °C, ``_deg``); arrays are read-only ``numpy.ndarray`` of float64."""

from __future__ import annotations

import os
from typing import Any, Callable, Dict, List, Mapping, Optional, Sequence, Tuple, Union, final

import numpy as np
import numpy.typing as npt

_FloatArray = npt.NDArray[np.float64]
_Progress = Callable[[float, str], Any]

__version__: str
__all__ = [
    "CancelToken",
    "Case",
    "Coefficients",
    "Pad",
    "RotorResult",
    "Solution",
    "coefficients",
    "frf",
    "load_case",
    "rotor",
    "schema",
    "solve",
    "_sweep",
    "_batch",
    "_outputs",
    "__version__",
]

@final
class CancelToken:
    """A flag that stops the solves it is passed to, set from any thread (they raise ``tiltpad.Cancelled``)."""

    def __init__(self) -> None: ...
    def cancel(self) -> None: ...
    @property
    def cancelled(self) -> bool: ...

@final
class Case:
    """A bearing case: a case file (or TOML text) and the edits made to it, validated as ``tiltpad solve``
    validates it."""

    def set(self, key: str, value: Any) -> None:
        """Sets a dotted case key in its own unit (``"operating.speed_rpm"``, ``"bearing.pads.preload"``); a
        list sets per-pad values; None removes the key. Raises ``CaseError`` (key, value, allowed)."""
    def update(self, values: Mapping[str, Any]) -> None:
        """Sets several keys validated together (``{"bearing.pads.bore_radius_mm": None,
        "bearing.pads.preload": 0.3}``); an invalid result keeps none of them."""
    def with_values(self, values: Mapping[str, Any]) -> Case: ...
    def get(self, key: str) -> Any:
        """The value of a key as the file has it (its unit), None where the file leaves the default."""
    def __getitem__(self, key: str, /) -> Any: ...
    def __setitem__(self, key: str, value: Any, /) -> None: ...
    def copy(self) -> Case: ...
    @property
    def overrides(self) -> List[str]: ...
    @property
    def path(self) -> Optional[str]: ...
    @property
    def title(self) -> str: ...
    def to_toml(self) -> str: ...
    def save(self, path: Union[str, os.PathLike[str]]) -> None: ...

@final
class Pad:
    """One pad of a solution. Field arrays have shape ``(len(s_m), len(z_m))``: circumferential node i from the
    leading edge, axial node j."""

    @property
    def index(self) -> int: ...
    @property
    def tilt_rad(self) -> Optional[float]: ...
    @property
    def pivot_displacement_m(self) -> Optional[float]: ...
    @property
    def h_min_m(self) -> float: ...
    @property
    def h_min_angle_deg(self) -> float: ...
    @property
    def p_max_pa(self) -> float: ...
    @property
    def force_n(self) -> _FloatArray:
        """Film force on the journal (x, y) [N], shape (2,)."""
    @property
    def moment_nm(self) -> float: ...
    @property
    def friction_power_w(self) -> float: ...
    @property
    def cavitated_fraction(self) -> float: ...
    @property
    def unloaded(self) -> bool: ...
    @property
    def flows_m3_per_s(self) -> Dict[str, float]: ...
    @property
    def orifice_flows_m3_per_s(self) -> _FloatArray: ...
    @property
    def mode_amplitudes_m(self) -> _FloatArray: ...
    @property
    def s_m(self) -> _FloatArray:
        """Circumferential node coordinates along the pad from its leading edge [m], shape (ns,)."""
    @property
    def z_m(self) -> _FloatArray:
        """Axial node coordinates [m], shape (nz,)."""
    @property
    def theta_rad(self) -> _FloatArray:
        """Node angles in the bearing frame (from +x, counter-clockwise) [rad], shape (ns,)."""
    @property
    def half(self) -> bool:
        """The grid covers half the pad (symmetry plane at z = 0)."""
    @property
    def periodic(self) -> bool: ...
    @property
    def pressure_pa(self) -> _FloatArray:
        """Film pressure [Pa], shape (ns, nz)."""
    @property
    def film_thickness_m(self) -> _FloatArray:
        """Film thickness [m], shape (ns, nz)."""
    @property
    def viscosity_pa_s(self) -> _FloatArray: ...
    @property
    def cavitated(self) -> npt.NDArray[np.bool_]: ...
    @property
    def film_temperature_c(self) -> Optional[_FloatArray]: ...
    @property
    def pad_surface_temperature_c(self) -> Optional[_FloatArray]: ...
    @property
    def elastic_displacement_m(self) -> Optional[_FloatArray]: ...
    @property
    def thermal_growth_m(self) -> Optional[_FloatArray]: ...
    @property
    def pad_radii_m(self) -> Optional[_FloatArray]: ...
    @property
    def pad_temperature_c(self) -> Optional[_FloatArray]:
        """Pad solid temperature [°C], shape (layers, ns, nz)."""
    @property
    def thermal(self) -> Optional[Dict[str, Any]]: ...

@final
class Solution:
    """A solved bearing: scalars with the unit in the name, arrays as read-only NumPy arrays."""

    @property
    def title(self) -> str: ...
    @property
    def eccentricity(self) -> float:
        """Eccentricity ratio e / C_b [–]."""
    @property
    def eccentricity_ratio(self) -> float: ...
    @property
    def attitude_angle_deg(self) -> float: ...
    @property
    def journal_position_m(self) -> _FloatArray: ...
    @property
    def load_n(self) -> _FloatArray: ...
    @property
    def load_magnitude_n(self) -> float: ...
    @property
    def sommerfeld(self) -> Optional[float]: ...
    @property
    def h_min_m(self) -> float: ...
    @property
    def h_min_um(self) -> float: ...
    @property
    def h_min_angle_deg(self) -> float:
        """Where the film is thinnest: angle from +x, counter-clockwise [deg]."""
    @property
    def p_max_pa(self) -> float: ...
    @property
    def p_max_mpa(self) -> float: ...
    @property
    def friction_power_w(self) -> float: ...
    @property
    def churning_power_w(self) -> float: ...
    @property
    def total_power_loss_w(self) -> float: ...
    @property
    def friction_torque_nm(self) -> float: ...
    @property
    def t_max_film_c(self) -> Optional[float]: ...
    @property
    def t_max_pad_c(self) -> Optional[float]: ...
    @property
    def t_journal_c(self) -> Optional[float]: ...
    @property
    def speed_rpm(self) -> float: ...
    @property
    def speed_rad_s(self) -> float: ...
    @property
    def assembled_clearance_m(self) -> float: ...
    @property
    def film_viscosity_pa_s(self) -> float: ...
    @property
    def flows_m3_per_s(self) -> Dict[str, float]: ...
    @property
    def excitation_rad_s(self) -> float: ...
    @property
    def k_n_per_m(self) -> _FloatArray:
        """Reduced stiffness at the excitation frequency [N/m], shape (2, 2), rows/columns x, y."""
    @property
    def c_ns_per_m(self) -> _FloatArray:
        """Reduced damping [N·s/m], shape (2, 2)."""
    @property
    def full_k(self) -> _FloatArray: ...
    @property
    def full_c(self) -> _FloatArray: ...
    @property
    def full_m(self) -> _FloatArray: ...
    @property
    def full_coordinates(self) -> List[str]: ...
    @property
    def full_units(self) -> List[str]: ...
    @property
    def pads(self) -> Tuple[Pad, ...]: ...
    @property
    def report(self) -> Dict[str, Any]: ...
    @property
    def warnings(self) -> List[str]: ...
    @property
    def iterations(self) -> int: ...
    @property
    def seconds(self) -> float: ...
    @property
    def design_limits(self) -> Dict[str, Any]: ...
    @property
    def limits_exceeded(self) -> List[str]: ...
    @property
    def thermal(self) -> Optional[Dict[str, Any]]: ...
    @property
    def summary(self) -> str: ...
    def to_dict(self) -> Dict[str, Any]:
        """The JSON ``tiltpad solve --json`` writes."""
    def to_json(self) -> str: ...

@final
class Coefficients:
    """Reduced coefficients over frequency: ``frequency_rad_s`` (running speed of a speed band, or excitation
    frequency at the case's speed), ``k_n_per_m`` [N/m] and ``c_ns_per_m`` [N·s/m] of shape (n, 2, 2)."""

    @property
    def frequency_rad_s(self) -> _FloatArray: ...
    @property
    def speed_rpm(self) -> _FloatArray: ...
    @property
    def excitation_rad_s(self) -> _FloatArray: ...
    @property
    def k_n_per_m(self) -> _FloatArray: ...
    @property
    def c_ns_per_m(self) -> _FloatArray: ...
    @property
    def meaning(self) -> str: ...
    @property
    def warnings(self) -> List[str]: ...
    @property
    def warning_details(self) -> List[Dict[str, Any]]: ...
    @property
    def solves(self) -> int: ...
    def to_csv(self) -> str: ...
    def to_ross_toml(self, elements: Sequence[Tuple[int, str]], source: str = "tiltpad") -> str: ...
    def to_dict(self) -> Dict[str, _FloatArray]: ...
    def __len__(self) -> int: ...

@final
class RotorResult:
    """A rotor analysis over speed (``tiltpad rotor``)."""

    @property
    def title(self) -> str: ...
    @property
    def speeds_rpm(self) -> _FloatArray: ...
    @property
    def frequencies_hz(self) -> _FloatArray:
        """Damped natural frequencies [Hz], shape (speeds, modes); NaN where a speed has fewer modes."""
    @property
    def frequencies_rad_s(self) -> _FloatArray: ...
    @property
    def log_decrements(self) -> _FloatArray: ...
    @property
    def whirl(self) -> List[List[str]]: ...
    @property
    def min_log_dec(self) -> _FloatArray: ...
    @property
    def onset_rpm(self) -> Optional[float]: ...
    @property
    def critical_speeds(self) -> List[Dict[str, Any]]: ...
    @property
    def response_nodes(self) -> List[int]: ...
    @property
    def response_pp_um(self) -> _FloatArray: ...
    @property
    def api617_limit_um(self) -> _FloatArray: ...
    @property
    def warnings(self) -> List[str]: ...
    @property
    def summary(self) -> str: ...
    def to_dict(self) -> Dict[str, Any]: ...
    def to_csv(self) -> str: ...

def load_case(path_or_text: Union[str, os.PathLike[str]], *, set: Optional[Mapping[str, Any]] = None) -> Case:
    """Reads and validates a case file (or TOML text). Raises ``CaseError`` with key, value, allowed."""

def schema() -> List[Dict[str, Any]]:
    """Every case key: unit, allowed values, default and meaning (``tiltpad schema --json``)."""

def solve(
    case: Case,
    *,
    fidelity: Optional[str] = None,
    progress: Optional[_Progress] = None,
    cancel: Optional[CancelToken] = None,
) -> Solution:
    """Solves a case as ``tiltpad solve`` does (GIL released). ``fidelity``: "preview", "standard",
    "reference"."""

def coefficients(
    case: Case,
    *,
    speeds_rpm: Optional[Sequence[float]] = None,
    excitation_ratios: Optional[Sequence[float]] = None,
    refine: bool = False,
    analysis_speeds_rpm: Optional[Sequence[float]] = None,
    fidelity: Optional[str] = None,
    progress: Optional[_Progress] = None,
    cancel: Optional[CancelToken] = None,
) -> Coefficients:
    """Reduced coefficients over running speed [rpm] or excitation ratio ω/Ω (``tiltpad coefficients``)."""

def frf(
    case: Case,
    *,
    from_hz: float = 1.0,
    to_hz: float = 1000.0,
    points: int = 400,
    amplitude_v: Optional[float] = None,
    fidelity: Optional[str] = None,
    progress: Optional[_Progress] = None,
    cancel: Optional[CancelToken] = None,
) -> Dict[str, Any]:
    """Frequency responses of the controllable bearing (``tiltpad frf``): ``frequency_hz`` [Hz] and
    ``curves`` (name → unit, group, magnitude, phase_deg [°]). ``progress`` after each solver stage and each
    twentieth of the band."""

def rotor(
    path: Union[str, os.PathLike[str]],
    *,
    speeds_rpm: Sequence[float],
    coefficients: Optional[str] = None,
    shaft_modes: Optional[int] = None,
    modes: int = 6,
    progress: Optional[_Progress] = None,
    cancel: Optional[CancelToken] = None,
) -> RotorResult:
    """Rotor–bearing analysis of a rotor file over ``speeds_rpm`` (``tiltpad rotor``)."""

def _sweep(
    case: Case,
    axes: List[Tuple[str, List[Any]]],
    *,
    fidelity: Optional[str] = None,
    progress: Optional[_Progress] = None,
    cancel: Optional[CancelToken] = None,
) -> Dict[str, Any]: ...
def _batch(
    case: Case,
    designs: Any,
    *,
    shard: Optional[Tuple[int, int]] = None,
    workers: int = 1,
    fidelity: Optional[str] = None,
    progress: Optional[_Progress] = None,
    cancel: Optional[CancelToken] = None,
) -> Dict[str, Any]: ...
def _outputs() -> List[Tuple[str, str, float]]:
    """Every scalar attribute of ``Solution`` (from the library's table of outputs): its name, its JSON pointer
    in ``to_dict()`` and the factor dividing that value to give the attribute's."""
