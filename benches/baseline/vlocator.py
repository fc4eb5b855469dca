"""The V-locator's 200 x 200 capacity map by numpy's closed form for the symmetric V: the
baseline `cargo bench --bench locator` times beside `grid::capacity_map`.

The closed form of src/locator/symmetric.rs: with x = tan(gamma / 2), a V that self-locks
(x < mu) holds every load, and otherwise P_max / W = 1 / (|cos phi| x + sin phi), unbounded
where the bracket is <= 0. Grid: included angle gamma 10-170 deg (columns), load direction
phi -90-90 deg (rows), mu = 0.3 on both flanks (LocatorParams' default). The trigonometry is
done once per axis sample and the cells by broadcasting, as the Rust fast path does.

Timed warm: one process, a warm-up map first, then RUNS maps. Warm needs one more thing than a
warm-up: glibc gives the top of its heap back to the kernel whenever more than its trim
threshold is free there, and a map's temporaries (five 320 kB arrays) are freed at its end, so
every map would fault its pages in anew (about 300 minor faults a map, most of its time).
The bench runs this script with MALLOC_TOP_PAD_ set, which keeps that much of the heap when it
trims; the minor faults per timed map are printed to show the heap stayed warm (0 when it did).

Prints the median wall time of RUNS maps in ms and the minor page faults per timed map on one
line: `numpy_ms <value> faults_per_map <value>`.
Usage: python vlocator.py [RUNS]
"""

import resource
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
    faults = resource.getrusage(resource.RUSAGE_SELF).ru_minflt
    times = []
    for _ in range(runs):
        t0 = time.perf_counter()
        capacity_map()
        times.append(time.perf_counter() - t0)
    faults = resource.getrusage(resource.RUSAGE_SELF).ru_minflt - faults
    times.sort()
    print(f"numpy_ms {times[len(times) // 2] * 1e3:.4f} faults_per_map {faults / runs:.2f}")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 101)
