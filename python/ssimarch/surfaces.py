"""Constructors of ssimarch.Surface, one per surface type of the scene format.

Each builds the scene-format description (docs/scene-format.md, "Surfaces") and hands it to
Surface, whose C++ side parses it with the scene reader: a surface built here is accepted and
rejected exactly as in a scene file, with the same messages (``surface.sphere.radius: must be > 0``).
Numbers may be expression strings using ``constants`` (``radius="R"``, ``constants={"R": 2}``).
"""
from __future__ import annotations

from typing import Any, Mapping, Optional, Sequence

from ._arguments import non_finite
from ._ssimarch import InputError, Surface

__all__ = ["Plane", "Sphere", "Cylinder", "Cone", "Torus", "Ellipsoid", "Paraboloid", "Capsule",
           "ParametricSurface", "ImplicitSurface", "Bezier", "BSpline"]


def _surface(kind: str, fields: dict, constants: Optional[Mapping[str, float]]) -> Surface:
    """The surface {kind: fields}; keyword arguments left at None are left out (the scene default)."""
    given = {k: v for k, v in fields.items() if v is not None}
    found = non_finite(given, kind)
    if found:
        raise InputError(found)
    return Surface({kind: given}, constants)


def Plane(point, normal, *, u=None, v=None, reference=None, constants=None) -> Surface:
    """Plane through `point` with `normal`; parameter rectangle u, v (default: unbounded, clipped to the other surface)."""
    return _surface("plane", dict(point=point, normal=normal, u=u, v=v, reference=reference), constants)


def Sphere(center=(0.0, 0.0, 0.0), radius=1.0, *, axis=None, reference=None, constants=None) -> Surface:
    """Sphere; `axis` places the poles of its parametrisation (default z)."""
    return _surface("sphere", dict(center=center, radius=radius, axis=axis, reference=reference), constants)


def Cylinder(point, axis, radius, *, range=None, reference=None, constants=None) -> Surface:  # noqa: A002
    """Circular cylinder about the line point + t axis; `range` its axial extent (default: unbounded)."""
    return _surface("cylinder", dict(point=point, axis=axis, radius=radius, range=range, reference=reference),
                    constants)


def Cone(apex, axis, half_angle, *, range=None, reference=None, constants=None) -> Surface:  # noqa: A002
    """Circular cone, half angle in radians; `range` the signed axial extent from the apex (default: unbounded, both nappes)."""
    return _surface("cone", dict(apex=apex, axis=axis, half_angle=half_angle, range=range, reference=reference),
                    constants)


def Torus(center, axis, major_radius, minor_radius, *, reference=None, constants=None) -> Surface:
    """Torus about `axis` through `center`."""
    return _surface("torus", dict(center=center, axis=axis, major_radius=major_radius, minor_radius=minor_radius,
                                  reference=reference), constants)


def Ellipsoid(center, radii, *, axis=None, reference=None, constants=None) -> Surface:
    """Ellipsoid with semi-axes `radii` along the frame of `axis` (default z)."""
    return _surface("ellipsoid", dict(center=center, radii=radii, axis=axis, reference=reference), constants)


def Paraboloid(vertex, axis, focal_length, *, u=None, v=None, reference=None, constants=None) -> Surface:
    """Paraboloid opening along `axis`; one focal length (of revolution) or two (elliptic)."""
    return _surface("paraboloid", dict(vertex=vertex, axis=axis, focal_length=focal_length, u=u, v=v,
                                       reference=reference), constants)


def Capsule(center, axis, radius, length, *, reference=None, constants=None) -> Surface:
    """Spherocylinder: the points at distance `radius` from the segment center +- (length/2) axis."""
    return _surface("capsule", dict(center=center, axis=axis, radius=radius, length=length, reference=reference),
                    constants)


def ParametricSurface(x: str, y: str, z: str, *, domain: Sequence[Sequence[Any]],
                      periodic: Sequence[str] = (), constants: Optional[Mapping[str, float]] = None) -> Surface:
    """F(u, v) = (x, y, z), expressions in u and v (docs/expressions.md) on domain ((u_lo, u_hi), (v_lo, v_hi));
    `periodic` lists the directions that wrap ("u", "v")."""
    if len(domain) != 2:
        raise InputError(f"domain: expected ((u_lo, u_hi), (v_lo, v_hi)), got {domain!r}")
    spec: dict[str, Any] = {"parametric": [x, y, z], "u": list(domain[0]), "v": list(domain[1])}
    if periodic:
        spec["periodic"] = list(periodic)
    return Surface(spec, constants)


def ImplicitSurface(f: str, *, box: Optional[Sequence[Sequence[Any]]] = None,
                    constants: Optional[Mapping[str, float]] = None) -> Surface:
    """f(x, y, z) = 0, an expression in x, y, z. `box` ((x_lo, x_hi), (y_lo, y_hi), (z_lo, z_hi)) is the region
    where intersections are searched: evaluation needs none; trace(a, b) without one uses the other surface's
    box, and a scene (a dict) needs it."""
    spec: dict[str, Any] = {"implicit": f}
    if box is not None:
        spec["box"] = [list(b) for b in box]
    return Surface(spec, constants)


def _net(control_points, weights) -> dict:
    import numpy as np

    net = np.asarray(control_points, dtype=np.float64)
    if net.ndim != 3 or net.shape[2] != 3 or net.shape[0] < 1 or net.shape[1] < 1:
        raise InputError(f"control_points: expected an array of shape (rows, columns, 3), got shape {net.shape}")
    found = non_finite(net, "control_points") or (non_finite(np.asarray(weights, dtype=np.float64), "weights")
                                                  if weights is not None else None)
    if found:
        raise InputError(found)
    out = {"control_points": net.tolist()}
    if weights is not None:
        w = np.asarray(weights, dtype=np.float64)
        if w.shape != net.shape[:2]:
            raise InputError(f"weights: expected shape {net.shape[:2]} (one per control point), got shape {w.shape}")
        out["weights"] = w.tolist()
    return out


def Bezier(control_points, weights=None) -> Surface:
    """Tensor-product Bezier patch on [0, 1]^2 from an (n+1, m+1, 3) control net (row index along u); optional
    (n+1, m+1) weights make it rational."""
    return Surface({"bezier": _net(control_points, weights)})


def BSpline(control_points, knots_u, knots_v, degree, weights=None) -> Surface:
    """Tensor-product B-spline (NURBS with weights) from an (n_u, n_v, 3) control net; `degree` p or (p, q);
    knots_u has n_u + p + 1 knots, knots_v n_v + q + 1."""
    import numpy as np

    spec = _net(control_points, weights)
    spec["knots_u"] = np.asarray(knots_u, dtype=np.float64).tolist()
    spec["knots_v"] = np.asarray(knots_v, dtype=np.float64).tolist()
    spec["degree"] = list(degree) if isinstance(degree, (tuple, list)) else degree
    return Surface({"bspline": spec})
