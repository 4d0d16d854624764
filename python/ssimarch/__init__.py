"""ssimarch: surface-surface intersection curves and porosity profiles of packed beds.

The bindings live in the extension module ssimarch._ssimarch, the surface constructors in
ssimarch.surfaces; see docs/python.md.
"""
import sys as _sys

from ._ssimarch import (Curve, InputError, Intersection, Surface, Topology, Trace, curve_geometry,
                        geometry_methods, porosity, trace, trace_options)
from .surfaces import (BSpline, Bezier, Capsule, Cone, Cylinder, Ellipsoid, ImplicitSurface, Paraboloid,
                       ParametricSurface, Plane, Sphere, Torus)

# `import ssimarch.porosity` and `from ssimarch.porosity import radial` find the extension's submodule.
_sys.modules[__name__ + ".porosity"] = porosity

__all__ = ["BSpline", "Bezier", "Capsule", "Cone", "Curve", "Cylinder", "Ellipsoid", "ImplicitSurface",
           "InputError", "Intersection", "Paraboloid", "ParametricSurface", "Plane", "Sphere", "Surface",
           "Topology", "Torus", "Trace", "curve_geometry", "geometry_methods", "porosity", "trace",
           "trace_options"]
