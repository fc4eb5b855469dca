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
from typing import Any, Callable, Optional, Sequence

from . import _jamchart
from ._jamchart import *  # noqa: F401,F403 (the names of _jamchart.__all__)

__all__ = list(_jamchart.__all__)

__doc__ = (__doc__ or "") + """
A notebook session, end to end (the guide's; each ``# %%`` starts a cell)::

""" + "\n".join("    " + line for line in _jamchart._session().splitlines()) + "\n"


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


def _wrap(name: str, positional: Sequence[str]) -> Callable[..., Any]:
    """The function `name` of the extension, called with its keywords as one dict, under the
    signature and docstring of its declared keywords."""
    native = getattr(_jamchart, name)
    declared = _jamchart._signature(name)
    required = [k for k, d in declared if d is None]
    # Keywords alone, to a function without positional or required ones (solve in a loop):
    # nothing to move or check on the way.
    bare = not positional and not required

    def positionals(args: Any, keywords: Any) -> Any:
        """The positional arguments of a call, those given by keyword taken out of `keywords`;
        its mistakes refused."""
        given = list(args) + [keywords.pop(p) for p in positional[len(args):] if p in keywords]
        if len(given) != len(positional):
            raise TypeError(f"{name}() takes {len(positional)} positional argument(s) "
                            f"({', '.join(positional)}) but {len(given)} were given")
        missing = [k for k in required if k not in keywords]
        if missing:
            raise TypeError(f"{name}() missing required keyword argument: '{missing[0]}'")
        return given

    # The comprehensions live in `positionals`: here they would make each call's keywords a
    # cell. The native call stays here, one frame below the caller's line, where its warnings
    # point.
    def function(*args: Any, **keywords: Any) -> Any:
        if bare and not args:
            return native(keywords)
        return native(*positionals(args, keywords), keywords)

    params = [inspect.Parameter(p, inspect.Parameter.POSITIONAL_OR_KEYWORD) for p in positional]
    params += [
        inspect.Parameter(k, inspect.Parameter.KEYWORD_ONLY, default=_default(d))
        for k, d in declared
    ]
    function.__signature__ = inspect.Signature(params)  # type: ignore[attr-defined]
    function.__doc__ = _jamchart._doc(name)
    function.__name__ = function.__qualname__ = name
    return function


for _name, _positional in _jamchart._functions():
    globals()[_name] = _wrap(_name, _positional)
