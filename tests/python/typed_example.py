"""A user's script that mypy --strict checks against the package's stubs."""

import numpy as np
import numpy.typing as npt

import jamchart as jc


def jam_positions(mu: npt.NDArray[np.float64]) -> npt.NDArray[np.float64]:
    r = jc.solve(mu=mu, radius_mm=12.5, mass_kg=0.4, force_n=40.0, palm_length_mm=80.0)
    return r.x_jam_mm


def one() -> float:
    s = jc.solve(mu=0.3, model="dynamics", method="nonsmooth")
    status: str = s.status
    print(status, s.record["model"])
    return s.theta_jam_deg


def worst_case() -> tuple[float, float] | None:
    box = jc.solve(mu=jc.Range(0.12, 0.3), force_n=jc.normal(40.0, 2.0), before_mm=[60.0])
    return box.x_jam_mm


chart = jc.render("universal", read_off={"mu": 0.27}, radius_mm=12.0, force_n=150.0)
svg: bytes = chart.svg
print(jam_positions(np.linspace(0.1, 0.5, 5)), one(), worst_case(), len(svg))
