#!/usr/bin/env python3
"""MPI porosity end to end (SSIMARCH_MPI=ON builds only; docs/scaling.md): `mpirun -n N ssimarch
porosity` with 1, 2 and 3 ranks writes the same files, byte for byte, as the plain single-process
run (CSV and LAMMPS inputs, spheres and spherocylinders, several profiles at once); a rank with no
particles; an empty packing; a malformed row in the middle of a large dump (one clear error naming
file:line, exit status 2, no output file); the overlap search (the summary's counts, the warning,
--strict) is the same on every rank count.

    mpi_porosity_test.py SSIMARCH MPIRUN WORKDIR
"""
import json
import os
import random
import subprocess
import sys
from pathlib import Path

SSIMARCH, MPIRUN, WORK = sys.argv[1], sys.argv[2], Path(sys.argv[3])
MPI_FLAGS = ["--oversubscribe", "--allow-run-as-root"]
failures = []


def run(ranks, args):
    cmd = ([SSIMARCH] if ranks == 0 else [MPIRUN, *MPI_FLAGS, "-n", str(ranks), SSIMARCH]) + args
    env = dict(os.environ, OMPI_MCA_rmaps_base_oversubscribe="1")
    return subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=300)


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL:", what, flush=True)


def profiles_equal(packing, radius, extra, tag):
    """Runs 0 (no mpirun), 1, 2, 3 ranks; every output file must equal the plain run's."""
    outs = {}
    for ranks in (0, 1, 2, 3):
        d = WORK / f"{tag}_{ranks}"
        d.mkdir(parents=True, exist_ok=True)
        r = run(ranks, ["porosity", str(packing), "--container-radius", str(radius), *extra,
                        "-o", str(d / "p.csv"), "--summary", str(d / "s.json"), "--threads", "2"])
        check(r.returncode == 0, f"{tag}: {ranks} ranks exit {r.returncode}: {r.stderr[-2000:]}")
        if r.returncode:
            return
        check(r.stderr.count("bulk porosity:") == 1, f"{tag}: {ranks} ranks: one report, from rank 0: {r.stderr}")
        files = {p.name: p.read_bytes() for p in sorted(d.iterdir()) if p.suffix == ".csv"}
        summary = json.loads((d / "s.json").read_text())
        for k in ("timings_s", "outputs"):
            summary.pop(k, None)
        outs[ranks] = (files, summary)
    base = outs[0]
    check(len(base[0]) >= 2, f"{tag}: several profile files {list(base[0])}")
    for ranks in (1, 2, 3):
        for name, data in base[0].items():
            check(outs[ranks][0].get(name) == data, f"{tag}: {name} differs on {ranks} ranks")
        check(outs[ranks][1] == base[1], f"{tag}: summary differs on {ranks} ranks: {outs[ranks][1]} vs {base[1]}")


def strict_equal(packing, radius):
    """The overlap search on 0 (no mpirun), 1, 2, 3 ranks: the same warning (pair count, worst pair and
    depth), said once; under --strict the same failure, exit status 1, no output."""
    said = {}
    for ranks in (0, 1, 2, 3):
        out = WORK / f"strict_{ranks}.csv"
        r = run(ranks, ["porosity", str(packing), "--container-radius", str(radius), "--radii", "10", "-q",
                        "-o", str(out), "--threads", "2"])
        warning = [l for l in r.stderr.splitlines() if "pairs of particles overlap" in l]
        check(r.returncode == 0 and len(warning) == 1, f"overlaps on {ranks} ranks: {r.returncode} {r.stderr}")
        out.unlink(missing_ok=True)
        s = run(ranks, ["porosity", str(packing), "--container-radius", str(radius), "--radii", "10", "--strict",
                        "-o", str(out)])
        check(s.returncode == 1 and "--strict" in s.stderr and not out.exists(),
              f"--strict on {ranks} ranks: {s.returncode} {s.stderr}")
        said[ranks] = warning[0] if warning else None
    check(len(set(said.values())) == 1 and said[0], f"overlap warnings differ: {said}")


def spheres_csv(path, n, R, seed):
    """Random spheres in a cylinder (overlaps allowed: the profiles do not care)."""
    rng = random.Random(seed)
    with open(path, "w") as f:
        f.write("x,y,z,d\n")
        for _ in range(n):
            r, t = (R - 0.3) * rng.random() ** 0.5, 6.283185307179586 * rng.random()
            import math
            f.write(f"{r * math.cos(t)!r},{r * math.sin(t)!r},{12 * rng.random()!r},{0.4 + 0.4 * rng.random()!r}\n")


def lammps_dump(path, n, seed, bad_line=None):
    rng = random.Random(seed)
    lines = ["ITEM: TIMESTEP", "0", "ITEM: NUMBER OF ATOMS", str(n), "ITEM: BOX BOUNDS pp pp pp",
             "-4 4", "-4 4", "0 12", "ITEM: ATOMS id type x y z radius"]
    for i in range(n):
        lines.append(f"{i + 1} 1 {rng.uniform(-3, 3)!r} {rng.uniform(-3, 3)!r} {rng.uniform(0, 12)!r} 0.25")
    if bad_line:
        lines[bad_line - 1] = "17 1 0.5 zz 3.0 0.25"
    Path(path).write_text("\n".join(lines) + "\n")


def main():
    WORK.mkdir(parents=True, exist_ok=True)
    bed = WORK / "bed.csv"
    spheres_csv(bed, 3000, 4.0, 1)
    profiles_equal(bed, 4.0, ["--radii", "60", "--axial", "25", "--map", "6,5"], "spheres")
    strict_equal(bed, 4.0)
    rods = WORK / "rods.csv"
    rng = random.Random(2)
    with open(rods, "w") as f:
        f.write("x,y,z,ux,uy,uz,d,l\n")
        for _ in range(150):
            f.write(",".join(repr(v) for v in (rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(0, 6),
                                                rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1), 0.5, 1.0)) + "\n")
    # These random rods overlap heavily; their union's shell volumes are nested quadratures of
    # minutes per run (docs/porosity.md), so the ranks are compared on the per-particle sums here
    # and on the union with the spheres above.
    profiles_equal(rods, 3.0, ["--bins", "12", "--axial", "10", "--tolerance", "1e-7", "--overlaps", "sum"], "rods")
    dump = WORK / "bed.dump"
    lammps_dump(dump, 4000, 3)
    profiles_equal(dump, 4.0, ["--radii", "40", "--axial", "20"], "dump")
    # One particle, three ranks: two have nothing to do.
    one = WORK / "one.csv"
    one.write_text("x,y,z,d\n0.5,0,1,1\n")
    profiles_equal(one, 2.0, ["--radii", "20", "--axial", "7"], "one")
    # An empty packing (header only): the same error, said once, exit status 2, no output.
    empty = WORK / "empty.csv"
    empty.write_text("x,y,z,d\n")
    for ranks in (0, 2, 3):
        out = WORK / f"empty_{ranks}.csv"
        r = run(ranks, ["porosity", str(empty), "--container-radius", "1", "-o", str(out)])
        check(r.returncode != 0 and "no particles" in r.stderr and r.stderr.count("error:") == 1,
              f"empty on {ranks} ranks: {r.returncode} {r.stderr}")
        check(not out.exists(), f"empty on {ranks} ranks wrote {out}")
    # A malformed row in the middle of a large dump: named by file:line on every rank count.
    bad = WORK / "bad.dump"
    lammps_dump(bad, 200000, 4, bad_line=123457)
    for ranks in (0, 1, 2, 3):
        out = WORK / f"bad_{ranks}.csv"
        r = run(ranks, ["porosity", str(bad), "--container-radius", "4", "-o", str(out)])
        check(r.returncode == 2 and f"{bad}:123457:" in r.stderr and "column 'y': not a number: 'zz'" in r.stderr
              and r.stderr.count("error:") == 1, f"bad row on {ranks} ranks: {r.returncode} {r.stderr}")
        check(not out.exists(), f"bad row on {ranks} ranks wrote {out}")
    print("failures:", len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
