#!/usr/bin/env python3
"""Radial porosity of a sphere bed read from a LAMMPS dump, against the de Klerk (2003) correlation
(docs/python.md, "Examples").

The bed is generated here (ssimarch.porosity.pack, drop and roll, container diameter 10 d) and
written as the LAMMPS text dump a DEM code would write; the profile is computed from that file
over the height range one bed height away from the floor and the top, where the bed is not
disturbed by them.

Usage: PYTHONPATH=build/python python3 examples/python/porosity_profile.py [--output DIR] [--count N]
Writes DIR/bed.dump and DIR/porosity_profile.png; exits 1 if the profile breaks eps(R) = 1 or the
mean of eps over the cross-section differs from the bulk porosity.
"""
import argparse
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")  # files only; no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from ssimarch import porosity  # noqa: E402


def write_lammps_dump(path: pathlib.Path, spheres: np.ndarray, radius: float) -> None:
    """One snapshot: ITEM: ATOMS id type x y z radius (the columns docs/porosity.md reads)."""
    top = spheres[:, 2].max() + spheres[:, 3].max()
    with path.open("w") as f:
        f.write(f"ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n{len(spheres)}\n")
        f.write(f"ITEM: BOX BOUNDS ff ff ff\n{-radius} {radius}\n{-radius} {radius}\n0 {top}\n")
        f.write("ITEM: ATOMS id type x y z radius\n")
        for i, (x, y, z, d) in enumerate(spheres, start=1):
            f.write(f"{i} 1 {x:.17g} {y:.17g} {z:.17g} {d / 2:.17g}\n")


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--output", type=pathlib.Path, default=pathlib.Path("."))
    ap.add_argument("--count", type=int, default=700)
    args = ap.parse_args()
    d, radius = 1.0, 5.0
    spheres, info = porosity.pack("spheres", radius, args.count, diameter=d, seed=1)
    args.output.mkdir(parents=True, exist_ok=True)
    dump = args.output / "bed.dump"
    write_lammps_dump(dump, spheres, radius)

    z0, z1 = info["height_range"]
    core = (z0 + 2 * d, z1 - 2 * d)
    r, eps = porosity.radial(dump, radius, 300, height_range=core, tolerance=1e-7)
    bulk = porosity.bulk(dump, radius, height_range=core)
    x_wall = (radius - r) / d
    print(f"{len(spheres)} spheres, bed height {z1 - z0:.3f}, bulk porosity {bulk:.4f} over z in "
          f"[{core[0]:.2f}, {core[1]:.2f}]")

    fig, ax = plt.subplots(figsize=(7, 4))
    ax.plot(x_wall, eps, label="ssimarch (exact, from the LAMMPS dump)")
    ax.plot(x_wall, porosity.de_klerk(x_wall, bulk), "k--", label="de Klerk (2003)")
    ax.axhline(bulk, color="grey", lw=0.7, label=f"bulk {bulk:.3f}")
    ax.set_xlabel("distance from the wall (R - r) / d")
    ax.set_ylabel("porosity")
    ax.set_xlim(0, radius / d)
    ax.legend()
    fig.tight_layout()
    out = args.output / "porosity_profile.png"
    fig.savefig(out, dpi=100)

    # Checks: spheres touch the wall only at points (eps(R) = 1), and the area average of eps(r)
    # over the cross-section is the bulk porosity (trapezoid rule on 300 radii, r = 0 added).
    rr, ee = np.concatenate([[0.0], r]), np.concatenate([[eps[0]], eps])
    mean = np.trapz(ee * 2 * rr, rr) / radius**2
    print(f"wrote {out}; eps(R) = {eps[-1]:.9f}, area mean {mean:.5f} vs bulk {bulk:.5f}")
    return 0 if abs(eps[-1] - 1.0) < 1e-6 and abs(mean - bulk) < 5e-3 else 1


if __name__ == "__main__":
    sys.exit(main())
