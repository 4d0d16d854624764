"""Ctrl-C during a long porosity job raises KeyboardInterrupt promptly, and the module works after it."""
import os
import signal
import subprocess
import sys
import textwrap
import time

CHILD = textwrap.dedent("""
    import sys, time
    import numpy as np
    from ssimarch import porosity

    rng = np.random.default_rng(1)
    n = 4000
    beds = np.column_stack([rng.uniform(-4, 4, (n, 2)), rng.uniform(0, 40, n), np.full(n, 1.0)])
    print("start", flush=True)
    t0 = time.monotonic()
    try:
        # Far longer than the test waits: 2000 radii at an accuracy of 1e-13, one thread.
        porosity.radial(beds, 5.0, 2000, tolerance=1e-13, threads=1)
        print("finished", time.monotonic() - t0, flush=True)
    except KeyboardInterrupt:
        print("interrupted", time.monotonic() - t0, flush=True)
    # The stop flag is down again: a short job runs to its end.
    print("after", porosity.bulk(np.array([[0.0, 0.0, 0.0, 1.0]]), 2.0), flush=True)
""")


def test_sigint_interrupts_a_long_porosity_job():
    env = dict(os.environ)
    child = subprocess.Popen([sys.executable, "-c", CHILD], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             text=True, env=env)
    try:
        assert child.stdout.readline().strip() == "start", child.stderr.read()
        time.sleep(1.0)  # well inside the job
        assert child.poll() is None, "the job ended before the signal"
        sent = time.monotonic()
        child.send_signal(signal.SIGINT)
        out, err = child.communicate(timeout=60)
        latency = time.monotonic() - sent
    finally:
        if child.poll() is None:
            child.kill()
    lines = out.split("\n")
    assert lines[0].startswith("interrupted"), (out, err)
    # Promptly: the running chunk (1/256 of the job) finishes, then the call returns. Generous for a
    # loaded machine; the uninterrupted job takes minutes.
    assert latency < 15.0, latency
    assert lines[1].startswith("after ") and abs(float(lines[1].split()[1]) - (1 - 1 / 24)) < 1e-9, out
