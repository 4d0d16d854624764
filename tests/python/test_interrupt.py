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
    # Spherocylinders: their profiles are adaptive quadrature (uncut spheres have a closed form that
    # would finish before the signal).
    axes = rng.normal(size=(n, 3))
    axes /= np.linalg.norm(axes, axis=1)[:, None]
    beds = np.column_stack([rng.uniform(-3.5, 3.5, (n, 2)), rng.uniform(0, 40, n), axes,
                            np.full(n, 1.0), np.full(n, 1.0)])
    print("start", flush=True)
    t0 = time.monotonic()
    try:
        # Far longer than the test waits (tens of seconds): 2000 radii at an accuracy of 1e-13, one thread.
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


TRACE_CHILD = textwrap.dedent("""
    import sys, time
    import ssimarch

    # Once before the signal can come: the first call imports modules lazily (json, inside the
    # bindings), and a SIGINT that lands inside an import lock is dropped by Python's import
    # machinery (seen in CI on a loaded machine: the trace then ran to its end).
    ssimarch.trace(sys.argv[1], only="viviani")
    print("start", flush=True)
    t0 = time.monotonic()
    try:
        # About ten seconds: a step of R/66000 along Viviani's curve (500 000 points; at R/4000 an idle
        # machine finished within the test's 0.3 s wait).
        ssimarch.trace(sys.argv[1], only="viviani", step_length=0.00003, max_points=10000000)
        print("finished", time.monotonic() - t0, flush=True)
    except KeyboardInterrupt:
        print("interrupted", time.monotonic() - t0, flush=True)
""")


def test_sigint_during_a_trace_raises_keyboard_interrupt(viviani):
    # A trace polls no flag in this module's own code: the call runs to its end, then the pending
    # KeyboardInterrupt is raised and the result dropped (docs/python.md, Interrupting).
    child = subprocess.Popen([sys.executable, "-c", TRACE_CHILD, str(viviani)], stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True, env=dict(os.environ))
    try:
        assert child.stdout.readline().strip() == "start", child.stderr.read()
        time.sleep(0.3)
        assert child.poll() is None, "the trace ended before the signal"
        child.send_signal(signal.SIGINT)
        out, err = child.communicate(timeout=120)
    finally:
        if child.poll() is None:
            child.kill()
    assert out.startswith("interrupted"), (out, err)
    assert child.returncode == 0, err


EVALUATION_CHILD = textwrap.dedent("""
    import time
    import numpy as np
    import ssimarch

    # A costly f (200 terms): a chunk of 4096 points takes a fraction of a second, the array tens.
    f = "+".join(f"sin({k}*x+y)*cos(z-{k})*exp(-{k}*x*x/1000)" for k in range(1, 201))
    s = ssimarch.ImplicitSurface(f)
    probe = np.random.default_rng(2).uniform(-1, 1, (4096, 3))
    t0 = time.monotonic()
    reference = s.value(probe, threads=1)
    rate = len(probe) / (time.monotonic() - t0)
    n = int(min(max(rate * 2 * 40, 2e5), 2e7))  # about 40 s on two threads
    points = np.random.default_rng(3).uniform(-1, 1, (n, 3))
    print("start", n, flush=True)
    t0 = time.monotonic()
    try:
        s.value(points, threads=2)
        print("finished", time.monotonic() - t0, flush=True)
    except KeyboardInterrupt:
        print("interrupted", time.monotonic() - t0, flush=True)
    # The flag is down again: the next evaluation runs to its end, with the same values.
    print("after", bool(np.array_equal(s.value(probe, threads=2), reference)), flush=True)
""")


def test_sigint_interrupts_a_long_evaluation_on_a_large_array():
    child = subprocess.Popen([sys.executable, "-c", EVALUATION_CHILD], stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True, env=dict(os.environ))
    try:
        assert child.stdout.readline().startswith("start "), child.stderr.read()
        time.sleep(1.0)
        assert child.poll() is None, "the evaluation ended before the signal"
        sent = time.monotonic()
        child.send_signal(signal.SIGINT)
        out, err = child.communicate(timeout=60)
        latency = time.monotonic() - sent
    finally:
        if child.poll() is None:
            child.kill()
    lines = out.split("\n")
    assert lines[0].startswith("interrupted"), (out, err)
    # Within a chunk per thread (python/array_loops.hpp); generous for a loaded machine.
    assert latency < 15.0, latency
    assert lines[1] == "after True", out
