"""ssimarch: surface-surface intersection curves and porosity profiles of packed beds.

The bindings live in the extension module ssimarch._ssimarch; see docs/python.md.
"""
import sys as _sys

from ._ssimarch import Curve, InputError, Intersection, Trace, porosity, trace, trace_options

# `import ssimarch.porosity` and `from ssimarch.porosity import radial` find the extension's submodule.
_sys.modules[__name__ + ".porosity"] = porosity

__all__ = ["Curve", "InputError", "Intersection", "Trace", "porosity", "trace", "trace_options"]
