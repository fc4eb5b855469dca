"""The Python package against numpy and against itself: `cargo bench --bench python` runs it in
the package's test environment (target/python-venv) and prints its lines.

1. 10^6 closed-form answers from a numpy array of mu, against numpy evaluating the same closed
   form vectorised (the statics' decision of src/statics.rs for the default scene: too weak,
   jammed at the start, the jam angle, the palm's reach) two ways: term by term in
   trigonometric functions, and as jamchart evaluates it (the friction angles as unit vectors
   composed, one arctangent); all warm, the same inputs, runs interleaved; medians, and the
   ratio to the faster numpy. The bench runs this with MALLOC_TOP_PAD_ and
   MALLOC_MMAP_THRESHOLD_ set, so that glibc keeps numpy's 8 MB temporaries on the heap
   instead of mapping and unmapping each (page faults that are not numpy's arithmetic).
2. The time of one scalar call, jc.solve(mu=0.3): an upper bound on the package's overhead.
Usage: python python_package.py [RUNS]
"""

import statistics
import sys
import time

import numpy as np

import jamchart as jc

RUNS = int(sys.argv[1]) if len(sys.argv) > 1 else 15
N = 1_000_000
# The default scene (config/paper.toml).
M, G, F, R, L, START = 1.0, 9.806, 200.0, 10.0, 150.0, np.radians(90.0)


def numpy_statics(mu):
    """The closed form's status, theta_jam (deg) and x_jam (mm), NaN where no jam."""
    alpha = np.arctan(mu)
    s = M * G * np.sin(alpha) / F
    too_weak = s > 1.0
    theta = 2.0 * alpha + np.arcsin(np.minimum(s, 1.0))
    # The ground holds at the start: the margin mu R_n - R_t at the start angle.
    margin = mu * (M * G + F * np.cos(START - alpha)) - F * np.sin(START - alpha)
    held = (theta >= START) | (margin >= 0.0)
    x = R / np.tan(0.5 * theta)
    beyond = x > L
    jams = ~too_weak & ~held & ~beyond
    status = np.where(too_weak, 1, np.where(held, 2, np.where(beyond, 3, 4))).astype(np.uint8)
    # Held at the start: the answer is the start angle and the disc's place there.
    at_start = held & ~too_weak
    theta_deg = np.where(jams, np.degrees(theta), np.where(at_start, np.degrees(START), np.nan))
    x_mm = np.where(jams, x, np.where(at_start, R / np.tan(0.5 * START), np.nan))
    return status, theta_deg, x_mm


def numpy_statics_composed(mu):
    """numpy_statics by jamchart's own evaluation: unit vectors (cos, sin) of the friction
    angles and of asin(m g sin(alpha) / F) multiplied as complex numbers, one arctangent."""
    c = 1.0 / np.sqrt(1.0 + mu * mu)
    s = mu * c
    k = M * G * s / F
    too_weak = k >= 1.0
    with np.errstate(invalid="ignore"):
        kb = np.sqrt((1.0 - k) * (1.0 + k))
    # The wedge alpha + alpha, then theta_jam = wedge + asin(k).
    wc, ws = c * c - s * s, 2.0 * s * c
    jc_, js = wc * kb - ws * k, ws * kb + wc * k
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.where(jc_ > 0.0, js / (1.0 + jc_), (1.0 - jc_) / js)
    half = np.arctan(t)
    theta = 2.0 * np.where(half < 0.0, half + np.pi, half)
    cs, ss = np.cos(START), np.sin(START)
    margin = mu * (M * G + F * (cs * c + ss * s)) - F * (ss * c - cs * s)
    held = (theta >= START) | (margin >= 0.0)
    x = R / t
    beyond = x > L
    jams = ~too_weak & ~held & ~beyond
    status = np.where(too_weak, 1, np.where(held, 2, np.where(beyond, 3, 4))).astype(np.uint8)
    at_start = held & ~too_weak
    theta_deg = np.where(jams, np.degrees(theta), np.where(at_start, np.degrees(START), np.nan))
    x_mm = np.where(jams, x, np.where(at_start, R * (1.0 + cs) / ss, np.nan))
    return status, theta_deg, x_mm


def main():
    mu = np.random.default_rng(1).uniform(0.05, 1.2, N)
    # The same answers first: a comparison of different work would mean nothing.
    ours = jc.solve(mu=mu)
    for name, form in [("trigonometric", numpy_statics), ("composed", numpy_statics_composed)]:
        st, th, x = form(mu)
        agree = (ours.status == np.array(jc.STATUSES)[st]).mean()
        close = np.allclose(ours.x_jam_mm, x, rtol=1e-12, equal_nan=True)
        close &= np.allclose(ours.theta_jam_deg, th, rtol=1e-12, equal_nan=True)
        print(f"statics 1e6, numpy {name}: the same statuses for {agree:.4%} of the pushes, "
              f"theta_jam and x_jam equal to 1e-12: {close}")
    trig_t, composed_t, ours_t = [], [], []
    for _ in range(RUNS):
        for form, times in [(numpy_statics, trig_t), (numpy_statics_composed, composed_t),
                            (lambda m: jc.solve(mu=m), ours_t)]:
            t = time.perf_counter()
            form(mu)
            times.append(time.perf_counter() - t)
    a, c, b = (statistics.median(t) for t in (trig_t, composed_t, ours_t))
    print(f"statics 1e6 from a numpy array: numpy {a * 1e3:.1f} ms (trigonometric), "
          f"{c * 1e3:.1f} ms (composed), jamchart {b * 1e3:.1f} ms; "
          f"faster numpy / jamchart = {min(a, c) / b:.2f} (goal 3; medians of {RUNS} interleaved runs)")
    calls = 20_000
    per = []
    for _ in range(RUNS):
        t = time.perf_counter()
        for _ in range(calls):
            jc.solve(mu=0.3)
        per.append((time.perf_counter() - t) / calls)
    print(f"scalar call jc.solve(mu=0.3): {statistics.median(per) * 1e6:.2f} us "
          f"(median of {RUNS} runs of {calls} calls)")


main()
