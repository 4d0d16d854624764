#!/usr/bin/env python3
"""Viviani's curve from Python: trace the sphere x^2 + y^2 + z^2 = 4 against the cylinder
x^2 + (y + 1)^2 = 1, then plot the curve coloured by its curvature and kappa, |tau| along it against
the closed forms (docs/python.md, "Examples").

With t the angle on the cylinder (x = sin t, y = -1 - cos t, z = 2 sin(t/2)), Viviani's curve of
a = 1 has kappa = sqrt(13 + 3 cos t) / (3 + cos t)^(3/2) and |tau| = 6 |cos(t/2)| / (13 + 3 cos t).

Usage: PYTHONPATH=build/python python3 examples/python/viviani_curvature.py [--output DIR]
Writes DIR/viviani_curvature.png; exits 1 if the traced curvature leaves the closed form.
"""
import argparse
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")  # files only; no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import ssimarch  # noqa: E402


def closed_form(xyz):
    """kappa and |tau| of Viviani's curve (a = 1) at points of it."""
    cos_t = -xyz[:, 1] - 1.0
    cos_half = np.sqrt(np.clip(1.0 - xyz[:, 2] ** 2 / 4.0, 0.0, None))
    return np.sqrt(13 + 3 * cos_t) / (3 + cos_t) ** 1.5, 6 * cos_half / (13 + 3 * cos_t)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--output", type=pathlib.Path, default=pathlib.Path("."))
    args = ap.parse_args()
    sphere = ssimarch.Sphere([0, 0, 0], 2)
    cylinder = ssimarch.Cylinder([0, -1, 0], [0, 0, 1], 1, range=[-3, 3])
    run = ssimarch.trace(sphere, cylinder, geometry="exact", step_length=0.02)["a-b"]
    print(f"{len(run.curves)} curve(s), length {sum(c.length for c in run.curves):.6f}, "
          f"singular points: {[p['type'] for p in run.singular_points]}")

    fig = plt.figure(figsize=(11, 4.5))
    ax3d = fig.add_subplot(1, 2, 1, projection="3d")
    ax = fig.add_subplot(1, 2, 2)
    worst = 0.0
    for c in run.curves:
        g = c.geometry
        s = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(c.xyz, axis=0), axis=1))])
        kappa, tau = closed_form(c.xyz)
        ok = np.isfinite(g["kappa"])
        worst = max(worst, float(np.max(np.abs(g["kappa"][ok] - kappa[ok]))))
        ax3d.scatter(*c.xyz.T, c=g["kappa"], cmap="viridis", s=4)
        ax.plot(s, g["kappa"], label="kappa (traced, exact method)")
        ax.plot(s, np.abs(g["tau"]), label="|tau| (traced)")
        ax.plot(s, kappa, "k:", label="kappa (closed form)")
        ax.plot(s, tau, "k--", lw=0.8, label="|tau| (closed form)")
    node = np.array([p["xyz"] for p in run.singular_points])
    if len(node):
        ax3d.scatter(*node.T, color="red", s=40, label="node")
    ax3d.set_title("Viviani's curve, coloured by curvature")
    ax.set_xlabel("arc length s")
    ax.set_title("curvature and torsion along the curve")
    ax.legend(fontsize=8)
    fig.tight_layout()
    args.output.mkdir(parents=True, exist_ok=True)
    out = args.output / "viviani_curvature.png"
    fig.savefig(out, dpi=100)
    print(f"wrote {out}; max |kappa - closed form| = {worst:.2e}")
    return 0 if worst < 1e-6 else 1


if __name__ == "__main__":
    sys.exit(main())
