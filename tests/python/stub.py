"""The package's type stubs, made from the declared keywords (`_jamchart.keywords`): the
keyword lists of `__init__.pyi` are the settings' declaration's. `test_typing.py` compares the
committed stub with this; `JAMCHART_WRITE_STUB=1 pytest tests/python/test_typing.py` rewrites it
after a setting is added."""

HEAD = '''"""Types of the package jamchart: every keyword is a declared setting (its unit in its name).

The keyword lists below are the settings' declaration's (a test compares them); the docs of
each are in help(jamchart.solve).
"""

from typing import Any, Dict, List, Literal, Mapping, Optional, Sequence, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

__version__: str
STATUSES: List[str]
CHART_FORMAT: str

class Distribution:
    """A distribution of one input: normal, uniform or lognormal."""
    @property
    def nominal(self) -> float: ...
    def quantile(self, p: float) -> float: ...
    def cdf(self, x: float) -> float: ...

def normal(mean: float, sd: float) -> Distribution: ...
def uniform(low: float, high: float) -> Distribution: ...
def lognormal(median: float, sigma: float) -> Distribution: ...

_Array = Union[npt.NDArray[Any], List[float], List[List[float]]]
_Values = Union[float, _Array]
_Uncertain = Union[float, Tuple[float, float], Distribution, str]
_UncertainValues = Union[float, _Array, Tuple[float, float], Distribution, str]

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
    def save(self, path: Union[str, "os.PathLike[str]"]) -> None: ...

def scenes() -> List[str]: ...
def keywords(function: str = "solve") -> List[str]: ...
'''
def params(K, fn, replace):
    out = []
    for name, default, ty in K(fn):
        ty = replace.get(ty, ty)
        d = " = ..." if default is not None else ""
        out.append(f"    {name}: {ty}{d},")
    return "\n".join(out)

def stub(K):
    """The whole `__init__.pyi` for the keywords `K(function)` gives."""
    body = []
    over = [({"_Values": "float", "_UncertainValues": "float"}, "Solution", "  # type: ignore[overload-overlap]"),
            ({"_UncertainValues": "_Values"}, "Solutions", "  # type: ignore[overload-overlap]"),
            ({}, "BoxAnswer", "")]
    for rep, ret, ign in over:
        body.append(f"@overload\ndef solve({ign}\n    *,\n{params(K, 'solve', rep)}\n) -> {ret}: ...")
    body.append(f"def render(\n    scene: Union[str, \"os.PathLike[str]\"],\n    *,\n{params(K, 'render', {})}\n) -> Chart: ...")
    body.append(f"def design(\n    *,\n{params(K, 'design', {})}\n) -> Dict[str, Any]: ...")
    body.append(f"def vlocator(\n    *,\n{params(K, 'vlocator', {})}\n) -> Dict[str, Any]: ...")
    text = HEAD.replace("from typing import", "import os\nfrom typing import") + "\n" + "\n\n".join(body) + "\n"
    return text
