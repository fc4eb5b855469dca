"""The V-locator's 200 x 200 capacity map by numpy's closed form for the symmetric V: the
baseline `cargo bench --bench locator` times beside `grid::capacity_map`.

The closed form of src/locator/symmetric.rs: with x = tan(gamma / 2), a V that self-locks
(x < mu) holds every load, and otherwise P_max / W = 1 / (|cos phi| x + sin phi), unbounded
where the bracket is <= 0. Grid: included angle gamma 10-170 deg (columns), load direction
phi -90-90 deg (rows), mu = 0.3 on both flanks (LocatorParams' default). The trigonometry is
done once per axis sample and the cells by broadcasting, as the Rust fast path does.

Prints the median wall time of RUNS maps in ms on one line: `numpy_ms <value>`.
Usage: python vlocator.py [RUNS]
"""

import sys
import time

import numpy as np

MU = 0.3
N = 200


def capacity_map():
    gamma = np.radians(np.linspace(10.0, 170.0, N))
    phi = np.radians(np.linspace(-90.0, 90.0, N))
    x = np.tan(0.5 * gamma)
    bracket = np.abs(np.cos(phi))[:, None] * x[None, :] + np.sin(phi)[:, None]
    held_always = (x < MU)[None, :] | (bracket <= 0.0)
    with np.errstate(divide="ignore"):
        return np.where(held_always, np.nan, 1.0 / bracket)


def main(runs):
    capacity_map()  # warm up
    times = []
    for _ in range(runs):
        t0 = time.perf_counter()
        capacity_map()
        times.append(time.perf_counter() - t0)
    times.sort()
    print(f"numpy_ms {times[len(times) // 2] * 1e3:.4f}")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 101)
