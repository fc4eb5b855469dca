"""Ctrl-C interrupts a long map: the package looks for it between chunks of work."""

import os
import signal
import subprocess
import sys
import time

SCRIPT = """
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


def test_ctrl_c_stops_a_long_map():
    p = subprocess.Popen([sys.executable, "-c", SCRIPT], stdout=subprocess.PIPE, text=True)
    assert p.stdout.readline().strip() == "ready"
    time.sleep(0.5)
    sent = time.monotonic()
    os.kill(p.pid, signal.SIGINT)
    out, _ = p.communicate(timeout=120)
    waited = time.monotonic() - sent
    assert out.startswith("interrupted"), out
    # Within a chunk of work per thread (one simulation here), not the map's minutes.
    assert waited < 30, waited
