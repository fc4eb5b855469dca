"""The Python package against numpy and against itself: `cargo bench --bench python` runs it in
the package's test environment (target/python-venv) and prints its lines.

1. 10^6 closed-form answers from a numpy array of mu, against numpy evaluating the same closed
   form (the statics' decision of src/statics/mod.rs for the default scene: too weak, jammed at
   the start, the jam angle, the palm's reach) three ways: term by term in trigonometric
   functions; as jamchart evaluates it (the friction angles as unit vectors composed, one
   arctangent); and the best form we could write, `numpy_statics_blocked`: one square root and
   one arctangent an answer, every decision taken on the half-angle tangent, in place, in
   blocks of `BLOCK` pushes whose temporaries stay in the processor's cache. All warm, the same
   inputs, runs interleaved; medians, and the ratio to the fastest numpy. Every form's
   statuses, theta_jam and x_jam are checked against jamchart's first. The bench runs this
   with MALLOC_TOP_PAD_ and MALLOC_MMAP_THRESHOLD_ set, so that glibc keeps numpy's 8 MB
   temporaries on the heap instead of mapping and unmapping each (page faults that are not
   numpy's arithmetic), and once with RAYON_NUM_THREADS=1 (jamchart on one thread; numpy uses
   one anyway).
2. Memory bandwidth: the bytes an answer moves at the least (mu read, status, theta_jam and
   x_jam written: 8 + 1 + 8 + 8 = 25 B) over jamchart's time, beside what numpy's copy of an
   80 MB array reaches on this machine (read and write counted alike), the bound for a
   computation that streams its inputs and answers through memory once.
3. The time of one scalar call, jc.solve(mu=0.3): an upper bound on the package's overhead.
Usage: python python_package.py [RUNS]
"""

import math
import os
from math import asin, atan, cos, degrees, nan, sin, tan
import statistics
import sys
import time

import numpy as np

import jamchart as jc

RUNS = int(sys.argv[1]) if len(sys.argv) > 1 else 15
N = 1_000_000
# The default scene (config/paper.toml). Python floats, numpy's forms take them as they are: a
# numpy float64 here made the pure-Python form's arithmetic numpy's scalar arithmetic, a quarter
# slower than with floats, which flattered jamchart's scalar call.
M, G, F, R, L, START = 1.0, 9.806, 200.0, 10.0, 150.0, math.radians(90.0)
MG = M * G


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


# Pushes per block: 13 float64 temporaries of 4096 (416 kB) stay in a 512 kB-1 MB L2 cache.
BLOCK = 4096


def numpy_statics_blocked(mu, block=BLOCK):
    """numpy_statics in the fewest passes we could write. With t = tan(alpha) = mu and the
    half-angle v = tan(asin(k) / 2) = k / (1 + sqrt(1 - k^2)), theta_jam / 2 = alpha + asin(k) / 2
    has the tangent u = (mu + v) / (1 - mu v): jammed at the start where u >= tan(start / 2) (or
    1 - mu v <= 0, theta_jam >= 180 deg), beyond the palm where x_jam = R / u > L, and
    theta_jam = 2 atan(u) only for the answer. The start margin mu R_n - R_t is taken times
    sqrt(1 + mu^2) > 0, which keeps its sign and spares the division. Each block's temporaries
    are allocated once and reused (`out=`), so the arrays touched stay in cache."""
    n = mu.size
    codes = {name: jc.STATUSES.index(name) for name in ("too_weak", "jammed_at_start",
                                                        "beyond_reach", "jams")}
    status = np.empty(n, np.uint8)
    theta_deg = np.empty(n)
    x_mm = np.empty(n)
    q, k, v, u, d, w = (np.empty(block) for _ in range(6))
    weak, held, past, fails = (np.empty(block, bool) for _ in range(4))
    cs, ss = np.cos(START), np.sin(START)
    tan_half_start = np.tan(0.5 * START)
    start_deg, x_start = np.degrees(START), R * (1.0 + cs) / ss
    for lo in range(0, n, block):
        m = mu[lo:lo + block]
        b = m.size
        q_, k_, v_, u_, d_, w_ = q[:b], k[:b], v[:b], u[:b], d[:b], w[:b]
        weak_, held_, past_, fails_ = weak[:b], held[:b], past[:b], fails[:b]
        # q = sqrt(1 + mu^2) = 1 / cos(alpha); k = m g sin(alpha) / F.
        np.multiply(m, m, out=q_)
        q_ += 1.0
        np.sqrt(q_, out=q_)
        np.divide(m, q_, out=k_)
        k_ *= M * G / F
        np.greater_equal(k_, 1.0, out=weak_)
        # v = k / (1 + sqrt(1 - k^2)) (k < 1 where it matters; clipped so weak lanes stay finite).
        np.minimum(k_, 1.0, out=v_)
        np.multiply(v_, v_, out=w_)
        np.subtract(1.0, w_, out=w_)
        np.sqrt(w_, out=w_)
        w_ += 1.0
        np.divide(v_, w_, out=v_)
        # u = (mu + v) / (1 - mu v), the tangent of theta_jam / 2.
        np.multiply(m, v_, out=d_)
        np.subtract(1.0, d_, out=d_)
        np.add(m, v_, out=u_)
        np.less_equal(d_, 0.0, out=held_)
        np.divide(u_, d_, out=u_)
        np.greater_equal(u_, tan_half_start, out=fails_)
        held_ |= fails_
        # The start margin times sqrt(1 + mu^2): mu (m g q + F (cs + ss mu)) - F (ss - cs mu).
        np.multiply(m, ss * F, out=w_)
        w_ += cs * F
        np.multiply(q_, M * G, out=v_)
        w_ += v_
        w_ *= m
        np.multiply(m, cs * F, out=v_)
        w_ += v_
        w_ -= ss * F
        np.greater_equal(w_, 0.0, out=fails_)
        held_ |= fails_
        # x_jam = R / u; beyond the palm where it lies past L.
        x = x_mm[lo:lo + b]
        np.divide(R, u_, out=x)
        np.greater(x, L, out=past_)
        st = status[lo:lo + b]
        st.fill(codes["jams"])
        np.copyto(st, codes["beyond_reach"], where=past_)
        np.copyto(st, codes["jammed_at_start"], where=held_)
        np.copyto(st, codes["too_weak"], where=weak_)
        th = theta_deg[lo:lo + b]
        np.arctan(u_, out=th)
        th *= 360.0 / np.pi
        # Only jams keep the jam; held at the start: the start angle and the disc's place there.
        np.not_equal(st, codes["jams"], out=fails_)
        np.copyto(th, np.nan, where=fails_)
        np.copyto(x, np.nan, where=fails_)
        np.equal(st, codes["jammed_at_start"], out=fails_)
        np.copyto(th, start_deg, where=fails_)
        np.copyto(x, x_start, where=fails_)
    return status, theta_deg, x_mm


def copy_bandwidth_gb_s(runs):
    """numpy's copy of an 80 MB float64 array: bytes read and written per second, median."""
    a = np.random.default_rng(2).uniform(size=10_000_000)
    b = np.empty_like(a)
    times = []
    for _ in range(runs):
        t = time.perf_counter()
        np.copyto(b, a)
        times.append(time.perf_counter() - t)
    return 2 * a.nbytes / statistics.median(times) / 1e9


def math_statics(mu):
    """One push in pure Python with `math`: numpy_statics's decision and answer, for the
    scalar call's comparison (what a notebook user could type instead of calling jamchart), as
    tight as we could write it: the functions imported by name (no attribute lookup a call) and
    m g taken once."""
    alpha = atan(mu)
    s = MG * sin(alpha) / F
    if s >= 1.0:
        return "too_weak", nan, nan
    theta = 2.0 * alpha + asin(s)
    margin = mu * (MG + F * cos(START - alpha)) - F * sin(START - alpha)
    if theta >= START or margin >= 0.0:
        return "jammed_at_start", degrees(START), R / tan(0.5 * START)
    x = R / tan(0.5 * theta)
    if x > L:
        return "beyond_reach", nan, nan
    return "jams", degrees(theta), x


def main():
    mu = np.random.default_rng(1).uniform(0.05, 1.2, N)
    threads = os.environ.get("RAYON_NUM_THREADS") or f"default ({os.cpu_count()} cores)"
    # The same answers first: a comparison of different work would mean nothing.
    ours = jc.solve(mu=mu)
    names = np.array(jc.STATUSES)
    forms = [("trigonometric", numpy_statics), ("composed", numpy_statics_composed),
             ("blocked", numpy_statics_blocked)]
    for name, form in forms:
        st, th, x = form(mu)
        st = names[st]
        agree = (ours.status == st).mean()
        close = np.allclose(ours.x_jam_mm, x, rtol=1e-12, equal_nan=True)
        close &= np.allclose(ours.theta_jam_deg, th, rtol=1e-12, equal_nan=True)
        print(f"statics 1e6, numpy {name}: the same statuses for {agree:.4%} of the pushes, "
              f"theta_jam and x_jam equal to 1e-12: {close}")
    times = {name: [] for name, _ in forms}
    ours_t = []
    for _ in range(RUNS):
        for name, form in forms:
            t = time.perf_counter()
            form(mu)
            times[name].append(time.perf_counter() - t)
        t = time.perf_counter()
        jc.solve(mu=mu)
        ours_t.append(time.perf_counter() - t)
    med = {name: statistics.median(t) for name, t in times.items()}
    b = statistics.median(ours_t)
    best = min(med, key=med.get)
    print(f"statics 1e6 from a numpy array, jamchart threads {threads}: numpy "
          + ", ".join(f"{med[n] * 1e3:.1f} ms ({n})" for n in med)
          + f", jamchart {b * 1e3:.1f} ms; fastest numpy ({best}) / jamchart = "
          f"{med[best] / b:.2f} (goal 3 with default threads, 2 on one; medians of {RUNS} "
          "interleaved runs)")
    moved = N * (8 + 1 + 8 + 8)
    print(f"memory: jamchart moves at least {moved / N:.0f} B an answer ({moved / 1e6:.0f} MB), "
          f"{moved / b / 1e9:.2f} GB/s; numpy's copy of 80 MB reaches "
          f"{copy_bandwidth_gb_s(RUNS):.1f} GB/s (read + write)")
    one = jc.solve(mu=0.3)
    st, th, x = math_statics(0.3)
    same = str(one.status) == st and math.isclose(float(one.x_jam_mm), x, rel_tol=1e-12)
    print(f"scalar mu = 0.3: jamchart {one.status}, x_jam {float(one.x_jam_mm):.6f} mm; pure "
          f"Python {st}, {x:.6f} mm; the same to 1e-12: {same}")
    calls = 20_000
    per, per_math = [], []
    for _ in range(RUNS):
        t = time.perf_counter()
        for _ in range(calls):
            jc.solve(mu=0.3)
        per.append((time.perf_counter() - t) / calls)
        t = time.perf_counter()
        for _ in range(calls):
            math_statics(0.3)
        per_math.append((time.perf_counter() - t) / calls)
    a, c = statistics.median(per), statistics.median(per_math)
    print(f"scalar call jc.solve(mu=0.3): {a * 1e6:.2f} us; the closed form in pure Python "
          f"(math): {c * 1e6:.2f} us; jamchart / pure Python = {a / c:.2f} (goal at most 1; "
          f"medians of {RUNS} interleaved runs of {calls} calls)")

main()
