"""Types of the package jamchart: every keyword is a declared setting (its unit in its name).

The keyword lists below are the settings' declaration's (a test compares them); the docs of
each are in help(jamchart.solve).
"""

import os
from typing import Any, Dict, List, Literal, Mapping, Optional, Sequence, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

__version__: str
STATUSES: List[str]
CHART_FORMAT: str

class Range:
    """Every value from low to high, none more likely: the worst case over them."""
    def __init__(self, low: float, high: float) -> None: ...
    @property
    def low(self) -> float: ...
    @property
    def high(self) -> float: ...
    @property
    def nominal(self) -> float: ...

class Distribution:
    """A distribution of one input: normal, uniform or lognormal."""
    @property
    def nominal(self) -> float: ...
    def quantile(self, p: float) -> float: ...
    def cdf(self, x: float) -> float: ...

_Array = Union[npt.NDArray[Any], List[float], List[List[float]]]
_Values = Union[float, _Array]
_Uncertain = Union[float, Range, Distribution, str]
_UncertainValues = Union[float, _Array, Range, Distribution, str]

class Solution:
    """One push's answer."""
    @property
    def model(self) -> str: ...
    @property
    def status(self) -> str: ...
    @property
    def theta_jam_deg(self) -> float: ...
    @property
    def x_jam_mm(self) -> float: ...
    @property
    def elapsed_s(self) -> float: ...
    @property
    def inputs(self) -> Dict[str, Any]: ...
    @property
    def record(self) -> Dict[str, Any]: ...
    def to_dict(self) -> Dict[str, Any]: ...

class Solutions:
    """Many pushes' answers, shaped like the broadcast inputs."""
    @property
    def model(self) -> str: ...
    @property
    def status(self) -> npt.NDArray[np.str_]: ...
    @property
    def status_code(self) -> npt.NDArray[np.uint8]: ...
    @property
    def theta_jam_deg(self) -> npt.NDArray[np.float64]: ...
    @property
    def x_jam_mm(self) -> npt.NDArray[np.float64]: ...
    @property
    def past_palm_x_jam_mm(self) -> npt.NDArray[np.float64]: ...
    @property
    def shape(self) -> Tuple[int, ...]: ...
    @property
    def inputs(self) -> Dict[str, Any]: ...
    def __len__(self) -> int: ...
    def to_pandas(self) -> Any: ...

class BoxAnswer:
    """The answer over a range or distribution of inputs."""
    @property
    def model(self) -> str: ...
    @property
    def theta_jam_deg(self) -> Optional[Tuple[float, float]]: ...
    @property
    def x_jam_mm(self) -> Optional[Tuple[float, float]]: ...
    @property
    def statuses(self) -> List[str]: ...
    @property
    def probability(self) -> List[Tuple[float, float]]: ...
    @property
    def quantiles(self) -> List[Tuple[float, float]]: ...
    @property
    def record(self) -> Dict[str, Any]: ...
    def to_dict(self) -> Dict[str, Any]: ...

class Comparison:
    """Every model's answer to one push (solve(model="all")), and which to design to."""
    @property
    def models(self) -> List[str]: ...
    @property
    def solutions(self) -> Dict[str, Solution]: ...
    @property
    def guidance(self) -> str: ...
    @property
    def inputs(self) -> Dict[str, Any]: ...
    def to_dict(self) -> Dict[str, Any]: ...
    def to_pandas(self) -> Any: ...

class _Report:
    """An answer whose JSON document's keys are its attributes."""
    @property
    def headline(self) -> str: ...
    @property
    def report(self) -> str: ...
    def to_dict(self) -> Dict[str, Any]: ...
    def __getattr__(self, name: str) -> Any: ...

class DesignAnswer(_Report):
    """jamchart.design's answer; each key of `jamchart design --format json` is an attribute."""

class VlocatorAnswer(_Report):
    """jamchart.vlocator's answer; each key of `jamchart vlocator --format json` is an attribute."""

class Chart:
    """A drawn design chart."""
    @property
    def name(self) -> str: ...
    @property
    def kind(self) -> str: ...
    @property
    def svg(self) -> bytes: ...
    @property
    def png(self) -> bytes: ...
    @property
    def data(self) -> Any: ...
    @property
    def data_format(self) -> str: ...
    def save(
        self, path: Union[str, "os.PathLike[str]"], *, paper: Optional[Literal["a4", "letter"]] = None
    ) -> None: ...

@overload
def solve(  # type: ignore[overload-overlap]
    *,
    model: Literal["statics", "min-norm", "dynamics"] = ...,
    mu: float = ...,
    mu_ground: float = ...,
    mu_palm: float = ...,
    radius_mm: float = ...,
    mass_kg: float = ...,
    force_n: float = ...,
    gravity_m_s2: float = ...,
    start_angle_deg: float = ...,
    palm_length_mm: float = ...,
    palm_offset_mm: float = ...,
    push_ratio: float = ...,
    formulation: Literal["translational", "rolling"] = ...,
    bisection_tol_rad: float = ...,
    fast_path: bool = ...,
    max_iter: int = ...,
    tol_feas: float = ...,
    tol_gap: float = ...,
    tol_infeas: float = ...,
    mode: Literal["motion", "force"] = ...,
    omega_deg_s: float = ...,
    force_band: float = ...,
    stiffness_n_per_mm_e: float = ...,
    exponent: float = ...,
    damping_n_s_per_mm: float = ...,
    damping_depth_mm: float = ...,
    mu_static: float = ...,
    mu_static_ground: Optional[float] = ...,
    mu_static_palm: Optional[float] = ...,
    stiction_velocity_mm_s: float = ...,
    friction_velocity_mm_s: float = ...,
    method: Literal["radau5", "dopri5", "nonsmooth"] = ...,
    rtol: float = ...,
    atol: Optional[float] = ...,
    max_steps: int = ...,
    nonsmooth_step_deg: Optional[float] = ...,
    disc: Literal["slides", "rolls"] = ...,
    verify: bool = ...,
    max_jam_error: float = ...,
    jam_speed_ratio: float = ...,
    arm_speed_ratio: float = ...,
    after_jam_s: float = ...,
    before_mm: Union[float, Sequence[float]] = ...,
    quantiles: Sequence[float] = ...,
    samples: Optional[int] = ...,
    seed: int = ...,
) -> Solution: ...

@overload
def solve(  # type: ignore[overload-overlap]
    *,
    model: Literal["statics", "min-norm", "dynamics"] = ...,
    mu: _Values = ...,
    mu_ground: _Values = ...,
    mu_palm: _Values = ...,
    radius_mm: _Values = ...,
    mass_kg: _Values = ...,
    force_n: _Values = ...,
    gravity_m_s2: _Values = ...,
    start_angle_deg: _Values = ...,
    palm_length_mm: _Values = ...,
    palm_offset_mm: _Values = ...,
    push_ratio: _Values = ...,
    formulation: Literal["translational", "rolling"] = ...,
    bisection_tol_rad: float = ...,
    fast_path: bool = ...,
    max_iter: int = ...,
    tol_feas: float = ...,
    tol_gap: float = ...,
    tol_infeas: float = ...,
    mode: Literal["motion", "force"] = ...,
    omega_deg_s: float = ...,
    force_band: float = ...,
    stiffness_n_per_mm_e: float = ...,
    exponent: float = ...,
    damping_n_s_per_mm: float = ...,
    damping_depth_mm: float = ...,
    mu_static: float = ...,
    mu_static_ground: Optional[float] = ...,
    mu_static_palm: Optional[float] = ...,
    stiction_velocity_mm_s: float = ...,
    friction_velocity_mm_s: float = ...,
    method: Literal["radau5", "dopri5", "nonsmooth"] = ...,
    rtol: float = ...,
    atol: Optional[float] = ...,
    max_steps: int = ...,
    nonsmooth_step_deg: Optional[float] = ...,
    disc: Literal["slides", "rolls"] = ...,
    verify: bool = ...,
    max_jam_error: float = ...,
    jam_speed_ratio: float = ...,
    arm_speed_ratio: float = ...,
    after_jam_s: float = ...,
    before_mm: Union[float, Sequence[float]] = ...,
    quantiles: Sequence[float] = ...,
    samples: Optional[int] = ...,
    seed: int = ...,
) -> Solutions: ...

@overload
def solve(  # type: ignore[overload-overlap]
    *,
    model: Literal["statics", "min-norm", "dynamics"] = ...,
    mu: _UncertainValues = ...,
    mu_ground: _UncertainValues = ...,
    mu_palm: _UncertainValues = ...,
    radius_mm: _Values = ...,
    mass_kg: _UncertainValues = ...,
    force_n: _UncertainValues = ...,
    gravity_m_s2: _Values = ...,
    start_angle_deg: _Values = ...,
    palm_length_mm: _Values = ...,
    palm_offset_mm: _Values = ...,
    push_ratio: _Values = ...,
    formulation: Literal["translational", "rolling"] = ...,
    bisection_tol_rad: float = ...,
    fast_path: bool = ...,
    max_iter: int = ...,
    tol_feas: float = ...,
    tol_gap: float = ...,
    tol_infeas: float = ...,
    mode: Literal["motion", "force"] = ...,
    omega_deg_s: float = ...,
    force_band: float = ...,
    stiffness_n_per_mm_e: float = ...,
    exponent: float = ...,
    damping_n_s_per_mm: float = ...,
    damping_depth_mm: float = ...,
    mu_static: float = ...,
    mu_static_ground: Optional[float] = ...,
    mu_static_palm: Optional[float] = ...,
    stiction_velocity_mm_s: float = ...,
    friction_velocity_mm_s: float = ...,
    method: Literal["radau5", "dopri5", "nonsmooth"] = ...,
    rtol: float = ...,
    atol: Optional[float] = ...,
    max_steps: int = ...,
    nonsmooth_step_deg: Optional[float] = ...,
    disc: Literal["slides", "rolls"] = ...,
    verify: bool = ...,
    max_jam_error: float = ...,
    jam_speed_ratio: float = ...,
    arm_speed_ratio: float = ...,
    after_jam_s: float = ...,
    before_mm: Union[float, Sequence[float]] = ...,
    quantiles: Sequence[float] = ...,
    samples: Optional[int] = ...,
    seed: int = ...,
) -> BoxAnswer: ...

@overload
def solve(
    *,
    model: Literal["all"] = ...,
    mu: float = ...,
    mu_ground: float = ...,
    mu_palm: float = ...,
    radius_mm: float = ...,
    mass_kg: float = ...,
    force_n: float = ...,
    gravity_m_s2: float = ...,
    start_angle_deg: float = ...,
    palm_length_mm: float = ...,
    palm_offset_mm: float = ...,
    push_ratio: float = ...,
    formulation: Literal["translational", "rolling"] = ...,
    bisection_tol_rad: float = ...,
    fast_path: bool = ...,
    max_iter: int = ...,
    tol_feas: float = ...,
    tol_gap: float = ...,
    tol_infeas: float = ...,
    mode: Literal["motion", "force"] = ...,
    omega_deg_s: float = ...,
    force_band: float = ...,
    stiffness_n_per_mm_e: float = ...,
    exponent: float = ...,
    damping_n_s_per_mm: float = ...,
    damping_depth_mm: float = ...,
    mu_static: float = ...,
    mu_static_ground: Optional[float] = ...,
    mu_static_palm: Optional[float] = ...,
    stiction_velocity_mm_s: float = ...,
    friction_velocity_mm_s: float = ...,
    method: Literal["radau5", "dopri5", "nonsmooth"] = ...,
    rtol: float = ...,
    atol: Optional[float] = ...,
    max_steps: int = ...,
    nonsmooth_step_deg: Optional[float] = ...,
    disc: Literal["slides", "rolls"] = ...,
    verify: bool = ...,
    max_jam_error: float = ...,
    jam_speed_ratio: float = ...,
    arm_speed_ratio: float = ...,
    after_jam_s: float = ...,
    before_mm: Union[float, Sequence[float]] = ...,
    quantiles: Sequence[float] = ...,
    samples: Optional[int] = ...,
    seed: int = ...,
) -> Comparison: ...

def render(
    scene: Union[str, "os.PathLike[str]"],
    *,
    read_off: Optional[Mapping[str, float]] = ...,
    set: Optional[Mapping[str, Any]] = ...,
    style: Optional[Literal["colour", "print"]] = ...,
    mu: _Uncertain = ...,
    mu_ground: _Uncertain = ...,
    mu_palm: _Uncertain = ...,
    radius_mm: float = ...,
    mass_kg: _Uncertain = ...,
    force_n: _Uncertain = ...,
    gravity_m_s2: float = ...,
    start_angle_deg: float = ...,
    palm_length_mm: float = ...,
    palm_offset_mm: float = ...,
    formulation: Literal["translational", "rolling"] = ...,
    bisection_tol_rad: float = ...,
    fast_path: bool = ...,
    max_iter: int = ...,
    tol_feas: float = ...,
    tol_gap: float = ...,
    tol_infeas: float = ...,
    mode: Literal["motion", "force"] = ...,
    omega_deg_s: float = ...,
    force_band: float = ...,
    stiffness_n_per_mm_e: float = ...,
    exponent: float = ...,
    damping_n_s_per_mm: float = ...,
    damping_depth_mm: float = ...,
    mu_static: float = ...,
    mu_static_ground: Optional[float] = ...,
    mu_static_palm: Optional[float] = ...,
    stiction_velocity_mm_s: float = ...,
    friction_velocity_mm_s: float = ...,
    method: Literal["radau5", "dopri5", "nonsmooth"] = ...,
    rtol: float = ...,
    atol: Optional[float] = ...,
    max_steps: int = ...,
    nonsmooth_step_deg: Optional[float] = ...,
    disc: Literal["slides", "rolls"] = ...,
    verify: bool = ...,
    max_jam_error: float = ...,
    jam_speed_ratio: float = ...,
    arm_speed_ratio: float = ...,
    after_jam_s: float = ...,
) -> Chart: ...

def design(
    *,
    x_target_mm: float,
    mu: _Uncertain = ...,
    mu_ground: _Uncertain = ...,
    mu_palm: _Uncertain = ...,
    radius_mm: float = ...,
    mass_kg: _Uncertain = ...,
    force_n: _Uncertain = ...,
    gravity_m_s2: float = ...,
    start_angle_deg: float = ...,
    palm_length_mm: float = ...,
    palm_offset_mm: float = ...,
) -> DesignAnswer: ...

def vlocator(
    *,
    included_angle_deg: Optional[float] = ...,
    flank_angles: Optional[Tuple[float, float]] = ...,
    mu: _Uncertain = ...,
    mu_left: _Uncertain = ...,
    mu_right: _Uncertain = ...,
    mass_kg: _Uncertain = ...,
    gravity_m_s2: _Uncertain = ...,
    load_n: _Uncertain = ...,
    load_angle_deg: _Uncertain = ...,
    load_at_rim_deg: Optional[float] = ...,
    rotation: Literal["free", "blocked"] = ...,
) -> VlocatorAnswer: ...

def normal(mean: float, sd: float) -> Distribution: ...

def uniform(low: float, high: float) -> Distribution: ...

def lognormal(median: float, sigma: float) -> Distribution: ...

def scenes() -> List[str]: ...

def keywords(function: str = "solve") -> List[str]: ...
