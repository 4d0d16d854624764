"""ssimarch.curve_geometry: every method on the circle where the unit sphere meets z = 1/2 (closed
form: radius rho = sqrt(3)/2, kappa = 1/rho, tau = 0, the normal towards the axis, the surface
normals at angle pi/3), numpy shapes, and the CLI's answer at one point."""
import json
import math
import subprocess

import numpy as np
import pytest

import ssimarch

RHO = math.sqrt(3) / 2
SCENE = {"surfaces": {"s": {"sphere": {"center": [0, 0, 0], "radius": 1}},
                      "p": {"plane": {"point": [0, 0, 0.5], "normal": [0, 0, 1]}}},
         "intersections": [{"name": "circle", "surfaces": ["s", "p"]}]}


def near_circle(phi):
    """Points off the circle whose nearest circle point is at angle phi."""
    phi = np.asarray(phi, dtype=float)
    return np.stack([0.8 * np.cos(phi), 0.8 * np.sin(phi), np.full_like(phi, 0.55)], -1)


def test_every_method_is_listed():
    assert ssimarch.geometry_methods() == ["exact", "ye-maekawa", "willmore", "stoyanov", "estimate",
                                           "barnhill-kersey", "mixed"]


@pytest.mark.parametrize("method", ["exact", "ye-maekawa", "willmore", "stoyanov", "estimate",
                                    "barnhill-kersey", "mixed"])
def test_circle_geometry_by_every_method(method):
    phi = np.linspace(0.1, 6.0, 8).reshape(2, 4)
    g = ssimarch.curve_geometry(SCENE, at=near_circle(phi), method=method, step=0.01)
    assert g["point"].shape == (2, 4, 3) and g["kappa"].shape == (2, 4) and g["params"].shape == (2, 4, 3)
    assert g["status"].shape == (2, 4) and g["on_curve"].all()
    np.testing.assert_allclose(g["point"], np.stack([RHO * np.cos(phi), RHO * np.sin(phi), 0.5 + 0 * phi], -1),
                               atol=1e-9)
    np.testing.assert_allclose(g["distance"], np.linalg.norm(g["point"] - near_circle(phi), axis=-1), atol=1e-12)
    np.testing.assert_allclose(g["theta"], math.pi / 3, atol=1e-9)
    # The estimates sample chords of 0.01: their curvature error is O(step^2 kappa^3).
    exact = method in ("exact", "ye-maekawa", "willmore", "stoyanov", "mixed")
    tol = 1e-7 if exact else 1e-3
    np.testing.assert_allclose(g["kappa"], 1 / RHO, rtol=tol)
    np.testing.assert_allclose(g["n"], -np.stack([np.cos(phi), np.sin(phi), 0 * phi], -1), atol=math.sqrt(tol))
    np.testing.assert_allclose(np.abs(g["t"][..., 2]), 0.0, atol=1e-9)
    np.testing.assert_allclose(g["tau"][np.isfinite(g["tau"])], 0.0, atol=10 * tol)
    if not exact:
        assert (g["samples"] > 0).all()


def test_toward_orients_the_tangent():
    at = near_circle([0.0])  # nearest point (rho, 0, 1/2): t = +-y
    up = ssimarch.curve_geometry(SCENE, at=at, toward=[0, 1, 0])
    down = ssimarch.curve_geometry(SCENE, at=at, toward=np.array([0, -1, 0]))
    np.testing.assert_allclose(up["t"][0], [0, 1, 0], atol=1e-12)
    np.testing.assert_allclose(down["t"][0], [0, -1, 0], atol=1e-12)


def test_two_surfaces_and_a_single_point():
    g = ssimarch.curve_geometry(ssimarch.Sphere([0, 0, 0], 1), ssimarch.Plane([0, 0, 0.5], [0, 0, 1]),
                                at=[0.8, 0.0, 0.55])
    assert g["kappa"].shape == () and float(g["kappa"]) == pytest.approx(1 / RHO, rel=1e-9)
    assert str(g["status"]) == "ok"


def test_the_cli_gives_the_same_values(cli, tmp_path):
    scene = tmp_path / "circle.json"
    scene.write_text(json.dumps(SCENE))
    out = json.loads(subprocess.run([cli, "curve-geometry", str(scene), "--intersection", "circle", "--at",
                                     "0.8,0.1,0.55", "--method", "ye-maekawa"],
                                    check=True, capture_output=True, text=True).stdout)
    g = ssimarch.curve_geometry(str(scene), at=[0.8, 0.1, 0.55], intersection="circle", method="ye-maekawa")
    for key in ("point", "t", "n", "b"):
        np.testing.assert_allclose(g[key], out[key], rtol=0, atol=1e-14)
    for key in ("kappa", "theta", "distance"):
        assert float(g[key]) == pytest.approx(out[key], abs=1e-14)
    np.testing.assert_allclose(g["params"], out["unknowns"], atol=1e-14)
    assert str(g["status"]) == out["status"]


def test_errors():
    with pytest.raises(ssimarch.InputError, match="^method: unknown method \"psychic\" .*exact"):
        ssimarch.curve_geometry(SCENE, at=[1, 0, 0], method="psychic")
    with pytest.raises(ssimarch.InputError, match="^step: must be a positive length"):
        ssimarch.curve_geometry(SCENE, at=[1, 0, 0], step=-1.0)
    with pytest.raises(ssimarch.InputError, match="^intersection: the scene has no intersection \"nope\""):
        ssimarch.curve_geometry(SCENE, at=[1, 0, 0], intersection="nope")
    with pytest.raises(ssimarch.InputError, match=r"^at: expected points as an array of shape \(\.\.\., 3\)"):
        ssimarch.curve_geometry(SCENE, at=[1, 0])
    two = dict(SCENE, intersections=SCENE["intersections"] * 2)
    two["intersections"] = [dict(SCENE["intersections"][0], name=n) for n in ("c1", "c2")]
    with pytest.raises(ssimarch.InputError, match="^intersection: the scene has 2 intersections"):
        ssimarch.curve_geometry(two, at=[1, 0, 0])
    empty = ssimarch.curve_geometry(SCENE, at=np.empty((0, 3)))
    assert empty["kappa"].shape == (0,) and empty["point"].shape == (0, 3)
