"""Ctrl-C interrupts a long simulate/batch/study at once (the library call runs on a worker
thread; the caller waits in 50 ms slices and runs Python's signal handlers)."""

import os
import signal
import subprocess
import sys
import time

import pytest

# A run of about 20 s on the 2-core sandbox (1000 s of record at dt = 5e-5 s: 2e7 steps; history
# thinned so memory stays small). Without the worker thread, SIGINT was only seen at its end.
CHILD = r"""
import sys, time
import numpy as np
import pounding

what = sys.argv[1]
text = pounding.default_simulate_scenario().replace("history_every = 10", "history_every = 100000")
t = np.arange(0, 1000, 0.01)
rec = (0.3 * np.sin(2 * np.pi * 1.1 * t), 0.01)
print("go", flush=True)
t0 = time.monotonic()
try:
    if what == "simulate":
        pounding.simulate(text, rec, dt=5e-5)
    else:
        pounding.batch(text, [rec] * 4, [1.0, 2.0], dt=5e-5, threads=1)
except KeyboardInterrupt:
    print(f"interrupted {time.monotonic() - t0:.3f}", flush=True)
    sys.exit(3)
print(f"finished {time.monotonic() - t0:.3f}", flush=True)
"""


@pytest.mark.skipif(os.name == "nt", reason="SIGINT to a child process is POSIX")
@pytest.mark.parametrize("what", ["simulate", "batch"])
def test_sigint_interrupts_a_long_run_at_once(what):
    p = subprocess.Popen([sys.executable, "-c", CHILD, what], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True)
    try:
        assert p.stdout.readline().strip() == "go"
        time.sleep(1.0)  # well inside the call
        sent = time.monotonic()
        p.send_signal(signal.SIGINT)
        out, err = p.communicate(timeout=60)
        waited = time.monotonic() - sent
    finally:
        if p.poll() is None:
            p.kill()
    assert p.returncode == 3, (out, err)
    assert out.startswith("interrupted"), out
    assert waited < 3.0, f"KeyboardInterrupt took {waited:.1f} s after SIGINT"
