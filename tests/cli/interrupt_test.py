#!/usr/bin/python3
"""Ctrl-C (core/interrupt.hpp): a long `ssimarch packing` and a long `ssimarch porosity` run are sent
SIGINT once their first progress line (--progress json) shows they are working; each must stop with
exit status 130 and the message "interrupted", leave an earlier output file as it was and no
temporary file behind. Run by ctest (tests/cli/CMakeLists.txt): interrupt_test.py SSIMARCH WORK_DIR."""
import json
import signal
import subprocess
import sys
import time
from pathlib import Path

SSIMARCH, WORK = sys.argv[1], Path(sys.argv[2])
WORK.mkdir(parents=True, exist_ok=True)
failures = []


def check(ok, what):
    print(("ok:   " if ok else "FAIL: ") + what)
    if not ok:
        failures.append(what)


def interrupt(name, args, output, stage):
    output.write_text("earlier output\n")
    before = set(WORK.iterdir())
    p = subprocess.Popen([SSIMARCH, *map(str, args), "--progress", "json", "-o", output],
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    # The first progress line of the long stage (readline blocks until the run reports or ends).
    line, working = "start", False
    while line and not working:
        line = p.stderr.readline()
        progress = json.loads(line)["progress"] if line.startswith('{"progress"') else {}
        working = progress.get("stage") == stage and progress["fraction"] < 1
    check(working, f"{name}: the {stage} stage was working when interrupted: {line.strip()!r}")
    p.send_signal(signal.SIGINT)
    try:
        _, err = p.communicate(timeout=120)
    except subprocess.TimeoutExpired:
        p.kill()
        _, err = p.communicate()
        check(False, f"{name}: stopped within 120 s of SIGINT")
    check(p.returncode == 130, f"{name}: exit status {p.returncode} (130 expected)")
    check("ssimarch: interrupted; no output was written" in err, f"{name}: the message says interrupted")
    check(output.read_text() == "earlier output\n", f"{name}: the earlier output is untouched")
    check(set(WORK.iterdir()) == before, f"{name}: no temporary file left: {sorted(set(WORK.iterdir()) - before)}")


start = time.monotonic()
# About 10^6 spheres: minutes of drop-and-roll, far longer than the time to the first report.
interrupt("packing", ["packing", "spheres", "--container-radius", 60, "--count", 1000000], WORK / "packing_out.csv", "packing")
bed = WORK / "bed.csv"
subprocess.run([SSIMARCH, "packing", "spheres", "--container-radius", "6", "--count", "1500", "-q", "-o", str(bed)], check=True)
# A map of 1000 x 1000 cells (the most a map may have) of that bed: seconds, far longer than the
# first report, which the map stage writes as it starts.
interrupt("porosity", ["porosity", bed, "--container-radius", 6, "--map", "1000,1000", "--threads", 2],
          WORK / "map_out.csv", "map")
print(f"interrupt_test: {'FAILED' if failures else 'OK'} in {time.monotonic() - start:.1f} s")
sys.exit(1 if failures else 0)
