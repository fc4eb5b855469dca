"""jamchart: where a pushed circular workpiece jams, on numpy arrays.

A palm hinged at the origin closes and pushes a disc of radius r along the ground; the disc jams
where the ground friction can hold it. ``solve`` gives the palm angle theta_jam (deg) and the
disc position x_jam (mm) there, by the closed-form statics (default), the minimum-norm contact
forces or the dynamic simulation, for one scene, numpy arrays of scenes (broadcast, answered
in parallel with the GIL released) or a range or distribution of inputs. ``render`` draws the
design charts, ``design`` answers the inverse questions and ``vlocator`` a disc in a V-block.

Every keyword is a setting of ``jamchart settings`` under its TOML key, with its unit in its
name (``radius_mm``, ``force_n``); ``help(jamchart.solve)`` lists them with units, defaults and
valid values. Bad input raises ValueError with the command line's message.

>>> import numpy as np, jamchart as jc
>>> r = jc.solve(mu=np.linspace(0.1, 0.5, 100_000), radius_mm=12.5, mass_kg=0.4,
...              force_n=40, palm_length_mm=80)
>>> r.theta_jam_deg.shape
(100000,)
"""

from __future__ import annotations

import ast
import inspect
from typing import Any, Callable, Dict, List, Optional, Tuple, Union

from . import _jamchart
from ._jamchart import (
    CHART_FORMAT,
    STATUSES,
    BoxAnswer,
    Chart,
    DesignAnswer,
    Distribution,
    Solution,
    Solutions,
    VlocatorAnswer,
    __version__,
    lognormal,
    normal,
    scenes,
    uniform,
)

__all__ = [
    "BoxAnswer",
    "CHART_FORMAT",
    "Chart",
    "DesignAnswer",
    "Distribution",
    "STATUSES",
    "Solution",
    "Solutions",
    "VlocatorAnswer",
    "design",
    "keywords",
    "lognormal",
    "normal",
    "render",
    "scenes",
    "solve",
    "uniform",
    "vlocator",
]


def solve(**keywords: Any) -> Union[Solution, Solutions, BoxAnswer]:
    return _jamchart.solve(keywords)


def render(scene: str, **keywords: Any) -> Chart:
    return _jamchart.render(scene, keywords)


def design(**keywords: Any) -> DesignAnswer:
    if "x_target_mm" not in keywords:
        raise TypeError("design() missing required keyword argument: 'x_target_mm'")
    return _jamchart.design(keywords)


def vlocator(**keywords: Any) -> VlocatorAnswer:
    return _jamchart.vlocator(keywords)


def keywords(function: str = "solve") -> List[str]:
    """The keywords `function` takes ("solve", "render", "design" or "vlocator"), in order.

    Each is a setting of ``jamchart settings`` under its TOML key; ``help(jamchart.solve)``
    gives each one's unit, default and valid values.
    """
    return [name for name, _, _ in _jamchart.keywords(function)]


class _Shown:
    """A default shown in a signature as it is written (``1e-9``, ``None``)."""

    def __init__(self, text: str) -> None:
        self.text = text

    def __repr__(self) -> str:
        return self.text


def _default(text: Optional[str]) -> Any:
    if text is None:
        return inspect.Parameter.empty
    try:
        return ast.literal_eval(text)
    except (ValueError, SyntaxError):
        return _Shown(text)


def _sign(function: Callable[..., Any], name: str, positional: Tuple[str, ...] = ()) -> None:
    """Gives `function` the signature and docstring of the declared keywords of `name`."""
    params = [
        inspect.Parameter(p, inspect.Parameter.POSITIONAL_OR_KEYWORD) for p in positional
    ]
    params += [
        inspect.Parameter(k, inspect.Parameter.KEYWORD_ONLY, default=_default(d))
        for k, d, _ in _jamchart.keywords(name)
    ]
    function.__signature__ = inspect.Signature(params)  # type: ignore[attr-defined]
    function.__doc__ = _jamchart.doc(name)


_sign(solve, "solve")
_sign(render, "render", positional=("scene",))
_sign(design, "design")
_sign(vlocator, "vlocator")
