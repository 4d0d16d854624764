"""Arguments checked as carefully as the CLI checks its flags (issue 29, "Python as careful as the CLI").

The functions of the extension module are wrapped so that
- a keyword the function does not take is named, with the nearest one it does take
  (``porosity.radial(..., tolerence=1e-9)``: "unknown keyword 'tolerence' (did you mean 'tolerance'?)"),
- an argument of the wrong type is named with the type the function expects (``points=2.5``,
  ``threads=-1``), instead of pybind11's "incompatible function arguments",
- a number that is NaN or infinite, alone, in a sequence, an array or a scene dict, is rejected naming
  its argument (and its key inside a dict), instead of being computed with or reported as invalid JSON.
Every error is an InputError (a ValueError), as the C++ side raises for invalid input.
"""
from __future__ import annotations

import difflib
import functools
import math
import numbers
import re
from typing import Any, Callable, Optional

from ._ssimarch import InputError

_SIGNATURE = re.compile(r"^\s*(?:\d+\.\s+)?(\w+)\((.*)\)\s*->", re.M)


def _split_top_level(text: str) -> list[str]:
    """Splits a pybind11 parameter list at the commas outside brackets."""
    out, depth, start = [], 0, 0
    for i, c in enumerate(text):
        if c in "[(":
            depth += 1
        elif c in "])":
            depth -= 1
        elif c == "," and depth == 0:
            out.append(text[start:i].strip())
            start = i + 1
    if text[start:].strip():
        out.append(text[start:].strip())
    return out


def _parameters(fn: Callable) -> list[tuple[str, str]]:
    """(name, type) of every parameter of fn's pybind11 signature(s), in order, without * and **."""
    params: list[tuple[str, str]] = []
    for m in _SIGNATURE.finditer(fn.__doc__ or ""):
        for p in _split_top_level(m.group(2)):
            if p in ("*", "/") or p.startswith("**") or p.startswith("*"):
                continue
            name, _, rest = p.partition(":")
            kind = rest.split("=")[0].strip()
            if name.strip() and name.strip() not in dict(params):
                params.append((name.strip(), kind))
    return params


def _takes_any_keyword(fn: Callable) -> bool:
    return "**kwargs" in (fn.__doc__ or "").split("\n", 1)[0]


def non_finite(value: Any, where: str) -> Optional[str]:
    """The path (from `where`) of the first NaN or infinite number in value, or None."""
    if isinstance(value, bool):
        return None
    if isinstance(value, numbers.Real):
        return None if math.isfinite(float(value)) else f"{where}: not a finite number ({value})"
    if isinstance(value, dict):
        for k, v in value.items():
            found = non_finite(v, f"{where}.{k}" if where else str(k))
            if found:
                return found
        return None
    if isinstance(value, (list, tuple)):
        for i, v in enumerate(value):
            found = non_finite(v, f"{where}[{i}]")
            if found:
                return found
        return None
    try:
        import numpy as np
    except ImportError:  # the module needs numpy; without it nothing here is an array
        return None
    if isinstance(value, np.ndarray) and value.dtype.kind in "fc":
        bad = np.argwhere(~np.isfinite(value))
        if bad.size:
            index = ",".join(str(int(i)) for i in bad[0])
            return f"{where}[{index}]: not a finite number ({value[tuple(bad[0])]})"
    return None


def _python_type(kind: str) -> tuple:
    return {"float": (numbers.Real,), "int": (numbers.Integral,), "str": (str,), "bool": (bool,)}.get(kind, ())


def _explain(name: str, fn: Callable, args: tuple, kwargs: dict) -> str:
    params = _parameters(fn)
    known = [p for p, _ in params]
    if not _takes_any_keyword(fn):
        for k in kwargs:
            if k not in known:
                near = difflib.get_close_matches(k, known, n=1)
                hint = f" (did you mean '{near[0]}'?)" if near else f" (it takes: {', '.join(known)})"
                return f"{name}: unknown keyword '{k}'{hint}"
    given = dict(zip(known, args))
    given.update(kwargs)
    for p, kind in params:
        if p not in given:
            continue
        v, want = given[p], _python_type(kind)
        if want and (not isinstance(v, want) or (kind == "int" and isinstance(v, bool))):
            return f"{name}: {p}={v!r} is a {type(v).__name__}, expected {'an integer' if kind == 'int' else kind}"
        if kind == "int" and isinstance(v, numbers.Integral) and v < 0:
            return f"{name}: {p}={v!r}: expected a count or index, an integer >= 0"
    signature = (fn.__doc__ or "").split("\n", 1)[0]
    return f"{name}: these arguments do not fit {signature}"


def guarded(fn: Callable, name: str) -> Callable:
    """fn with the checks of this module (see the module's docstring)."""

    @functools.wraps(fn)
    def call(*args: Any, **kwargs: Any) -> Any:
        known = [p for p, _ in _parameters(fn)]
        for i, a in enumerate(args):
            # A scene given as a dict is named as the C++ reader names it: "<dict>: key.path".
            found = non_finite(a, "") if isinstance(a, dict) else non_finite(a, known[i] if i < len(known) else f"argument {i + 1}")
            if found:
                raise InputError(f"<dict>: {found}" if isinstance(a, dict) else found)
        # Keywords of a function that takes any (trace's options) are validated by the C++ side.
        for k, v in ({} if _takes_any_keyword(fn) else kwargs).items():
            found = non_finite(v, k)
            if found:
                raise InputError(found)
        try:
            return fn(*args, **kwargs)
        except TypeError as e:
            if "incompatible function arguments" not in str(e):
                raise
            raise InputError(_explain(name, fn, args, kwargs)) from None

    return call
