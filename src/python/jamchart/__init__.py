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

from . import _jamchart
from ._jamchart import *  # noqa: F401,F403 (the names of _jamchart.__all__)

__all__ = list(_jamchart.__all__)

__doc__ = (__doc__ or "") + """
A notebook session, end to end (the guide's; each ``# %%`` starts a cell)::

""" + "\n".join("    " + line for line in _jamchart._session().splitlines()) + "\n"
