# Type stubs of ssimarch.porosity. `particles`: an N×4 array (x, y, z, d) of spheres, an N×8 array
# (x, y, z, ux, uy, uz, d, l) of spherocylinders, or the path of a packing file (CSV, LAMMPS dump).
# `clumps`: with an array, the integer particle id of each row (rows with one id are the spheres of
# one clumped particle, docs/porosity.md); a packing file brings its own clump column.
import os
from typing import Any, Literal, Optional, Union

import numpy as np
import numpy.typing as npt

_Particles = Union[npt.ArrayLike, str, os.PathLike[str]]

def radial(
    particles: _Particles,
    radius: float,
    points: int = ...,
    *,
    height_range: tuple[float, float] | None = ...,
    tolerance: float = ...,
    threads: int = ...,
    overlaps: str = ...,
    clumps: npt.ArrayLike | None = ...,
) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]: ...
def axial(
    particles: _Particles,
    radius: float,
    slices: int = ...,
    *,
    height_range: tuple[float, float] | None = ...,
    tolerance: float = ...,
    threads: int = ...,
    overlaps: str = ...,
    clumps: npt.ArrayLike | None = ...,
) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]: ...
def bulk(
    particles: _Particles,
    radius: float,
    *,
    height_range: tuple[float, float] | None = ...,
    tolerance: float = ...,
    threads: int = ...,
    overlaps: str = ...,
    clumps: npt.ArrayLike | None = ...,
) -> float: ...
def bins(
    particles: _Particles,
    radius: float,
    bins: int = ...,
    *,
    height_range: tuple[float, float] | None = ...,
    tolerance: float = ...,
    threads: int = ...,
    overlaps: str = ...,
    clumps: npt.ArrayLike | None = ...,
) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64], npt.NDArray[np.float64]]: ...
def map(
    particles: _Particles,
    radius: float,
    radii: int = ...,
    heights: int = ...,
    *,
    height_range: tuple[float, float] | None = ...,
    tolerance: float = ...,
    threads: int = ...,
    overlaps: str = ...,
    clumps: npt.ArrayLike | None = ...,
) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64], npt.NDArray[np.float64]]: ...
def pack(
    kind: Literal["spheres", "spherocylinders"],
    container_radius: float,
    count: int = ...,
    *,
    diameter: float = ...,
    diameter_max: Optional[float] = ...,
    length: Optional[float] = ...,
    height: Optional[float] = ...,
    solid_fraction: Optional[float] = ...,
    seed: int = ...,
) -> tuple[npt.NDArray[np.float64], dict[str, Any]]: ...
def de_klerk(x_wall: npt.ArrayLike, eps_bulk: float) -> npt.NDArray[np.float64]: ...
