"""Ctrl-C interrupts a long map: the package looks for it between chunks of work."""

import os
import signal
import subprocess
import sys
import time

MAP = """
import sys, time, numpy as np, jamchart as jc
print("ready", flush=True)
t = time.monotonic()
try:
    # Minutes of simulations (a RADAU5 run takes about 0.5 ms on one core): a map that
    # finished before the signal would prove nothing.
    jc.solve(model="dynamics", mu=np.linspace(0.2, 0.6, 400_000), method="radau5")
    print("finished", time.monotonic() - t, flush=True)
except KeyboardInterrupt:
    print("interrupted", time.monotonic() - t, flush=True)
"""


# A Monte Carlo of min-norm searches without the fast path (about 3 ms a sample, 5 min of one
# core; twice as many were within noise of the 10 min limit and were refused at times): its
# draws look for Ctrl-C too.
MONTE_CARLO = """
import sys, time, jamchart as jc
print("ready", flush=True)
t = time.monotonic()
try:
    jc.solve(model="min-norm", fast_path=False, mu=jc.normal(0.3, 0.03), samples=100_000)
    print("finished", time.monotonic() - t, flush=True)
except KeyboardInterrupt:
    print("interrupted", time.monotonic() - t, flush=True)
"""


def _interrupted_within(script: str) -> float:
    """Runs `script`, sends it Ctrl-C half a second in; how long it took to stop."""
    p = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True)
    assert p.stdout.readline().strip() == "ready"
    time.sleep(0.5)
    sent = time.monotonic()
    os.kill(p.pid, signal.SIGINT)
    out, _ = p.communicate(timeout=120)
    waited = time.monotonic() - sent
    assert out.startswith("interrupted"), out
    return waited


def test_ctrl_c_stops_a_long_map():
    # Within a chunk of work per thread (one simulation here), not the map's minutes.
    waited = _interrupted_within(MAP)
    assert waited < 30, waited


def test_ctrl_c_stops_a_long_monte_carlo():
    # Within a chunk of 1024 samples per thread (about 0.3 s), not the draws' minute.
    waited = _interrupted_within(MONTE_CARLO)
    assert waited < 20, waited
