"""ssimarch: surface-surface intersection curves and porosity profiles of packed beds.

The bindings live in the extension module ssimarch._ssimarch, the surface constructors in
ssimarch.surfaces; see docs/python.md.
"""
import sys as _sys

from ._ssimarch import (Curve, InputError, Intersection, Surface, Topology, Trace, curve_geometry,
                        geometry_methods, intersect, porosity, read_step, section, trace, trace_options)
from .surfaces import (BSpline, Bezier, Capsule, Cone, Cylinder, Ellipsoid, ImplicitSurface, Paraboloid,
                       ParametricSurface, Plane, Sphere, Torus)

from ._arguments import guarded as _guarded

# Keyword typos, wrong types and NaN inputs named as the CLI names them (ssimarch/_arguments.py).
trace = _guarded(trace, "trace")
curve_geometry = _guarded(curve_geometry, "curve_geometry")
section = _guarded(section, "section")
intersect = _guarded(intersect, "intersect")
for _name in ("radial", "axial", "bulk", "bins", "map", "pack", "de_klerk"):
    if hasattr(porosity, _name):
        setattr(porosity, _name, _guarded(getattr(porosity, _name), "porosity." + _name))

# `import ssimarch.porosity` and `from ssimarch.porosity import radial` find the extension's submodule.
_sys.modules[__name__ + ".porosity"] = porosity

__all__ = ["BSpline", "Bezier", "Capsule", "Cone", "Curve", "Cylinder", "Ellipsoid", "ImplicitSurface",
           "InputError", "Intersection", "Paraboloid", "ParametricSurface", "Plane", "Sphere", "Surface",
           "Topology", "Torus", "Trace", "curve_geometry", "geometry_methods", "intersect", "porosity",
           "read_step", "section", "trace", "trace_options"]
