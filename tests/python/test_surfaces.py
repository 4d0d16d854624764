"""ssimarch.Surface and its constructors against closed forms: points, derivatives, normals and
curvatures of both forms on numpy arrays, input edge cases, and traces of Python-built surfaces."""
import json
import math
import subprocess

import numpy as np
import pytest

import ssimarch

C = np.array([1.0, -2.0, 0.5])  # sphere centre
R = 2.0  # sphere radius


def sphere_closed_form(u, v):
    """F(u, v) = c + r (cos v (cos u, sin u, 0) + sin v z) (docs/scene-format.md, sphere, axis z)."""
    u, v = np.broadcast_arrays(np.asarray(u, dtype=float), np.asarray(v, dtype=float))
    return C + R * np.stack([np.cos(v) * np.cos(u), np.cos(v) * np.sin(u), np.sin(v)], axis=-1)


@pytest.fixture(scope="module")
def sphere():
    return ssimarch.Sphere(C, R)


def test_sphere_description_type_and_domain(sphere):
    assert sphere.type == "sphere" and sphere.is_parametric and sphere.is_implicit
    assert sphere.description == {"sphere": {"center": C.tolist(), "radius": R}}
    (u0, u1), (v0, v1) = sphere.domain
    assert (u0, u1) == pytest.approx((0.0, 2 * math.pi)) and (v0, v1) == pytest.approx((-math.pi / 2, math.pi / 2))
    assert sphere.periodic == (True, False)
    box = np.array(sphere.box)
    assert np.all(box[:, 0] <= C - R) and np.all(box[:, 1] >= C + R)


def test_points_broadcast_over_arrays(sphere):
    u = np.linspace(0.0, 2 * math.pi, 7)[:, None]  # (7, 1)
    v = np.linspace(-1.2, 1.2, 5)[None, :]  # (1, 5)
    p = sphere.point(u, v)
    assert p.shape == (7, 5, 3) and p.dtype == np.float64
    np.testing.assert_allclose(p, sphere_closed_form(u, v), rtol=0, atol=1e-14)
    # A single point, lists and float32 / Fortran-ordered input.
    np.testing.assert_allclose(sphere.point(0.3, 0.2), sphere_closed_form(0.3, 0.2), atol=1e-14)
    assert sphere.point(0.3, 0.2).shape == (3,)
    grid_u, grid_v = np.meshgrid(np.linspace(0, 6, 4), np.linspace(-1, 1, 3))
    ref = sphere.point(grid_u, grid_v)
    np.testing.assert_array_equal(sphere.point(np.asfortranarray(grid_u), grid_v), ref)
    np.testing.assert_array_equal(sphere.point(grid_u.tolist(), grid_v.tolist()), ref)
    uf, vf = grid_u.astype(np.float32), grid_v.astype(np.float32)
    np.testing.assert_array_equal(sphere.point(uf, vf), sphere.point(uf.astype(np.float64), vf.astype(np.float64)))
    assert sphere.point(np.empty((0,)), np.empty((0,))).shape == (0, 3)


def test_derivatives_are_the_closed_forms(sphere):
    u = np.array([0.1, 1.7, 4.0])
    v = np.array([-0.9, 0.2, 1.1])
    d = sphere.derivatives(u, v, order=2)
    assert set(d) == {(0, 0), (1, 0), (0, 1), (2, 0), (1, 1), (0, 2)}
    cu, su, cv, sv = np.cos(u), np.sin(u), np.cos(v), np.sin(v)
    z = np.zeros_like(u)
    expected = {
        (0, 0): sphere_closed_form(u, v),
        (1, 0): R * np.stack([-cv * su, cv * cu, z], -1),
        (0, 1): R * np.stack([-sv * cu, -sv * su, cv], -1),
        (2, 0): R * np.stack([-cv * cu, -cv * su, z], -1),
        (1, 1): R * np.stack([sv * su, -sv * cu, z], -1),
        (0, 2): R * np.stack([-cv * cu, -cv * su, -sv], -1),
    }
    for k, e in expected.items():
        assert d[k].shape == (3, 3)
        np.testing.assert_allclose(d[k], e, rtol=0, atol=1e-13, err_msg=str(k))
    # Order 4: d^4F/du^4 = F_uu'' = R cos v (cos u, sin u, 0) (period 4 in u).
    d4 = sphere.derivatives(u, v, order=4)
    assert len(d4) == 15
    np.testing.assert_allclose(d4[(4, 0)], R * np.stack([cv * cu, cv * su, z], -1), atol=1e-12)
    assert set(sphere.derivatives(u, v, order=0)) == {(0, 0)}


def test_normals_and_curvatures_of_both_forms(sphere):
    u = np.linspace(0.0, 6.0, 11)
    v = np.linspace(-1.4, 1.4, 11)
    p = sphere.point(u, v)
    outward = (p - C) / R
    np.testing.assert_allclose(sphere.normal(u, v), outward, atol=1e-13)
    np.testing.assert_allclose(sphere.normal(p), outward, atol=1e-13)
    # f = (|p - c|^2 - r^2) / (2r): grad f = (p - c)/r, Hessian I/r.
    np.testing.assert_allclose(sphere.value(p), 0.0, atol=1e-14)
    np.testing.assert_allclose(sphere.value(C + [0.0, 0.0, 3.0]), (9.0 - R * R) / (2 * R), atol=1e-14)
    np.testing.assert_allclose(sphere.gradient(p), outward, atol=1e-13)
    np.testing.assert_allclose(sphere.hessian(p), np.broadcast_to(np.eye(3) / R, (11, 3, 3)), atol=1e-13)
    # Signed as the library's k_n (surface/derivatives.hpp): -1/r with the outward normal.
    for k in (sphere.curvatures(u, v), sphere.curvatures(p)):
        np.testing.assert_allclose(k["gaussian"], 1 / R**2, atol=1e-12)
        np.testing.assert_allclose(k["mean"], -1 / R, atol=1e-12)
        np.testing.assert_allclose(k["k1"], -1 / R, atol=1e-6)  # umbilic: the split of equal roots is sqrt(eps)
        np.testing.assert_allclose(k["k2"], -1 / R, atol=1e-6)
    # At a pole Fu = 0: no normal, no curvatures (NaN), never a silently normalised zero vector.
    assert np.all(np.isnan(sphere.normal(0.0, math.pi / 2)))
    assert math.isnan(sphere.curvatures(0.0, math.pi / 2)["gaussian"])


def test_torus_against_numpy_closed_form():
    big, small = 3.0, 1.0
    torus = ssimarch.Torus([0, 0, 0], [0, 0, 1], big, small)
    u, v = np.meshgrid(np.linspace(0, 2 * math.pi, 9), np.linspace(0, 2 * math.pi, 13))
    ring = big + small * np.cos(v)
    expected = np.stack([ring * np.cos(u), ring * np.sin(u), small * np.sin(v)], -1)
    np.testing.assert_allclose(torus.point(u, v), expected, atol=1e-14)
    # Gaussian curvature cos v / (r (R + r cos v)) (do Carmo 3.3, Example 4).
    np.testing.assert_allclose(torus.curvatures(u, v)["gaussian"], np.cos(v) / (small * ring), atol=1e-12)


def test_parametric_expression_surface():
    s = ssimarch.ParametricSurface("u", "v", "u*v", domain=((-1, 1), (-1, 1)))
    assert s.type == "parametric" and not s.is_implicit and s.periodic == (False, False)
    u = np.array([0.5, -0.25, 0.9])
    v = np.array([0.3, 0.7, -0.6])
    np.testing.assert_allclose(s.point(u, v), np.stack([u, v, u * v], -1), atol=0)
    d = s.derivatives(u, v, order=2)
    np.testing.assert_allclose(d[(1, 0)], np.stack([np.ones(3), np.zeros(3), v], -1), atol=0)
    np.testing.assert_allclose(d[(0, 1)], np.stack([np.zeros(3), np.ones(3), u], -1), atol=0)
    np.testing.assert_allclose(d[(1, 1)], np.tile([0.0, 0.0, 1.0], (3, 1)), atol=0)
    np.testing.assert_allclose(d[(2, 0)], 0.0, atol=0)
    # The saddle z = xy: K = -1 / (1 + x^2 + y^2)^2.
    np.testing.assert_allclose(s.curvatures(u, v)["gaussian"], -1 / (1 + u * u + v * v) ** 2, atol=1e-14)
    with pytest.raises(ssimarch.InputError, match="no implicit form"):
        s.value([[0.0, 0.0, 0.0]])
    k = ssimarch.ParametricSurface("a*cos(u)", "a*sin(u)", "v", domain=((0, "2*pi"), (0, 1)), periodic=["u"],
                                   constants={"a": 2.0})
    np.testing.assert_allclose(k.point(math.pi / 2, 0.5), [0.0, 2.0, 0.5], atol=1e-15)
    assert k.periodic == (True, False) and k.constants == {"a": 2.0}


def test_implicit_expression_surface():
    s = ssimarch.ImplicitSurface("x^2+y^2-1", box=[[-2, 2], [-2, 2], [-1, 1]])
    assert s.type == "implicit" and s.is_implicit and not s.is_parametric and s.domain is None
    p = np.array([[1.0, 0.0, 0.3], [0.6, 0.8, -0.5], [2.0, 1.0, 0.0]])
    np.testing.assert_allclose(s.value(p), p[:, 0] ** 2 + p[:, 1] ** 2 - 1, atol=1e-15)
    np.testing.assert_allclose(s.gradient(p), np.stack([2 * p[:, 0], 2 * p[:, 1], 0 * p[:, 0]], -1), atol=1e-15)
    np.testing.assert_allclose(s.hessian(p)[0], np.diag([2.0, 2.0, 0.0]), atol=1e-15)
    np.testing.assert_allclose(s.normal(p[:2]), [[1, 0, 0], [0.6, 0.8, 0]], atol=1e-15)
    # Cylinder of radius 1: K = 0, |H| = 1/2.
    k = s.curvatures(p[:2])
    np.testing.assert_allclose(k["gaussian"], 0.0, atol=1e-14)
    np.testing.assert_allclose(np.abs(k["mean"]), 0.5, atol=1e-14)
    assert np.all(np.isnan(s.normal([0.0, 0.0, 0.0])))  # grad f = 0 on the axis
    with pytest.raises(ssimarch.InputError, match="no parametric form"):
        s.point(0.0, 0.0)


def test_bezier_patch_from_a_numpy_net():
    # Bilinear patch: F(u, v) = sum P_ij B_i(u) B_j(v), degree (1, 1).
    net = np.array([[[0, 0, 0], [0, 1, 1]], [[1, 0, 2], [1, 1, -1]]], dtype=np.float32)
    s = ssimarch.Bezier(net)
    u, v = np.meshgrid(np.linspace(0, 1, 5), np.linspace(0, 1, 4))
    n = net.astype(np.float64)
    expected = (((1 - u) * (1 - v))[..., None] * n[0, 0] + ((1 - u) * v)[..., None] * n[0, 1]
                + (u * (1 - v))[..., None] * n[1, 0] + (u * v)[..., None] * n[1, 1])
    np.testing.assert_allclose(s.point(u, v), expected, atol=1e-15)
    # Rational quadratic quarter circle times a line: on the cylinder x^2 + y^2 = 1.
    w = math.sqrt(0.5)
    arc = ssimarch.Bezier(np.array([[[1, 0, 0], [1, 0, 1]], [[1, 1, 0], [1, 1, 1]], [[0, 1, 0], [0, 1, 1]]]),
                          weights=np.array([[1, 1], [w, w], [1, 1]]))
    p = arc.point(*np.meshgrid(np.linspace(0, 1, 7), np.linspace(0, 1, 3)))
    np.testing.assert_allclose(p[..., 0] ** 2 + p[..., 1] ** 2, 1.0, atol=1e-14)
    with pytest.raises(ssimarch.InputError, match=r"control_points: expected an array of shape \(rows, columns, 3\)"):
        ssimarch.Bezier(np.zeros((2, 2, 2)))
    with pytest.raises(ssimarch.InputError, match="weights"):
        ssimarch.Bezier(net, weights=np.ones((3, 2)))


def test_nurbs_of_the_scene_format_docs():
    # docs/scene-format.md, bspline: a quarter of the cylinder x^2 + y^2 = 1, 0 <= z <= 1.
    w = math.sqrt(0.5)
    s = ssimarch.BSpline(np.array([[[1, 0, 0], [1, 0, 1]], [[1, 1, 0], [1, 1, 1]], [[0, 1, 0], [0, 1, 1]]]),
                         knots_u=[0, 0, 0, 1, 1, 1], knots_v=np.array([0, 0, 1, 1]), degree=(2, 1),
                         weights=[[1, 1], [w, w], [1, 1]])
    assert s.type == "bspline"
    u, v = np.meshgrid(np.linspace(0, 1, 9), np.linspace(0, 1, 4))
    p = s.point(u, v)
    np.testing.assert_allclose(p[..., 0] ** 2 + p[..., 1] ** 2, 1.0, atol=1e-14)
    np.testing.assert_allclose(p[..., 2], v, atol=1e-15)
    np.testing.assert_allclose(s.normal(u, v)[..., 2], 0.0, atol=1e-14)


def test_other_primitives_build_and_evaluate():
    surfaces = [
        ssimarch.Plane([0, 0, 1], [0, 0, 1]),
        ssimarch.Cylinder([0, 0, 0], [0, 0, 1], 1.5, range=[-2, 2]),
        ssimarch.Cone([0, 0, 0], [0, 0, 1], 0.5),
        ssimarch.Ellipsoid([0, 0, 0], [1, 2, 3]),
        ssimarch.Paraboloid([0, 0, 0], [0, 0, 1], 0.25),
        ssimarch.Capsule([0, 0, 0], [0, 0, 1], 0.5, 2.0),
    ]
    for s in surfaces:
        (u0, u1), (v0, v1) = s.domain
        u, v = np.meshgrid(np.linspace(u0, u1, 6), np.linspace(v0, v1, 5)[1:-1])
        p = s.point(u, v)
        # Both forms describe one surface: f vanishes on F(u, v).
        np.testing.assert_allclose(s.value(p), 0.0, atol=1e-13, err_msg=s.type)


def test_surface_errors_carry_the_scene_readers_message():
    with pytest.raises(ssimarch.InputError, match=r"^surface\.sphere\.radius: must be > 0, got -1") as e:
        ssimarch.Sphere([0, 0, 0], -1)
    assert isinstance(e.value, ValueError)
    with pytest.raises(ssimarch.InputError, match="radus"):
        ssimarch.Surface({"sphere": {"center": [0, 0, 0], "radius": 1, "radus": 1}})
    with pytest.raises(ssimarch.InputError, match="unmatched"):
        ssimarch.ParametricSurface("cos(u", "v", "0", domain=((0, 1), (0, 1)))
    with pytest.raises(ssimarch.InputError, match="R"):
        ssimarch.Sphere([0, 0, 0], "R")  # no constants given
    with pytest.raises(ssimarch.InputError, match="constants.R"):
        ssimarch.Sphere([0, 0, 0], "R", constants={"R": "two"})
    assert ssimarch.Sphere([0, 0, 0], "R", constants={"R": 2}).point(0.0, 0.0) == pytest.approx([2, 0, 0])


def test_evaluation_input_errors(sphere):
    with pytest.raises(ssimarch.InputError, match="do not broadcast"):
        sphere.point(np.zeros(3), np.zeros(4))
    with pytest.raises(ssimarch.InputError, match=r"points: expected points as an array of shape \(\.\.\., 3\)"):
        sphere.value(np.zeros((4, 2)))
    with pytest.raises(ssimarch.InputError, match="^u: expected numbers"):
        sphere.point("0.5", 0.0)
    with pytest.raises(ssimarch.InputError, match="^u: expected a numeric array"):
        sphere.point(np.array(["a"]), 0.0)
    with pytest.raises(ssimarch.InputError, match=r"^order: must be an integer in \[0, 4\]"):
        sphere.derivatives(0.0, 0.0, order=5)


def test_vectorised_equals_one_call_per_point(sphere):
    rng = np.random.default_rng(3)
    u, v = rng.uniform(0, 6, 50), rng.uniform(-1.5, 1.5, 50)
    many = sphere.normal(u, v)
    for i in range(0, 50, 7):
        np.testing.assert_array_equal(many[i], sphere.normal(u[i], v[i]))


def test_trace_two_python_surfaces_is_the_circle():
    # Unit sphere and the plane z = 1/2: the circle of radius sqrt(3)/2.
    a = ssimarch.Sphere([0, 0, 0], 1)
    b = ssimarch.Plane([0, 0, 0.5], [0, 0, 1])
    result = ssimarch.trace(a, b, step_length=0.05)
    run = result["a-b"]
    assert run.surfaces == ("a", "b")
    (c,) = run.curves
    assert c.closed and c.length == pytest.approx(math.pi * math.sqrt(3), rel=1e-4)
    np.testing.assert_allclose(np.linalg.norm(c.xyz, axis=1), 1.0, atol=1e-9)
    with pytest.raises(TypeError):
        ssimarch.trace(a)
    with pytest.raises(TypeError):
        ssimarch.trace(a, "plane")


def test_surfaces_and_arrays_inside_a_scene_dict():
    torus = ssimarch.Torus(np.zeros(3), np.array([0, 0, 1]), 2.0, 0.5)
    scene = {"surfaces": {"torus": torus, "plane": {"plane": {"point": np.array([0.0, 0.0, 0.0]),
                                                              "normal": [0, 0, 1], "u": [-3, 3], "v": [-3, 3]}}},
             "intersections": [{"name": "equator", "surfaces": ["torus", "plane"]}]}
    run = ssimarch.trace(scene)["equator"]
    # The plane through the torus' centre cuts two circles, radii 2.5 and 1.5.
    lengths = sorted(c.length for c in run.curves)
    assert lengths == pytest.approx([2 * math.pi * 1.5, 2 * math.pi * 2.5], rel=1e-4)


def test_trace_with_constants_of_both_surfaces():
    a = ssimarch.Sphere([0, 0, 0], "R", constants={"R": 1.0})
    b = ssimarch.Plane([0, 0, "h"], [0, 0, 1], constants={"h": 0.6})
    (c,) = ssimarch.trace(a, b)["a-b"].curves
    assert c.length == pytest.approx(2 * math.pi * 0.8, rel=1e-4)
    clash = ssimarch.Plane([0, 0, "R"], [0, 0, 1], constants={"R": 0.5})
    with pytest.raises(ssimarch.InputError, match="constants.R"):
        ssimarch.trace(a, clash)


def strip_timing(x):
    if isinstance(x, dict):
        return {k: strip_timing(v) for k, v in x.items() if k != "time_ms"}
    if isinstance(x, list):
        return [strip_timing(v) for v in x]
    return x


def test_python_surfaces_round_trip_through_the_cli(cli, tmp_path):
    # The descriptions written as a scene file give the CLI the same curves as trace(a, b).
    a = ssimarch.Torus([0, 0, 0], [0, 0, 1], 2.0, 0.5)
    b = ssimarch.ParametricSurface("u", "v", "0.3*u", domain=((-3, 3), (-3, 3)))
    scene = tmp_path / "scene.json"
    scene.write_text(json.dumps({"surfaces": {"a": a.description, "b": b.description},
                                 "intersections": [{"name": "a-b", "surfaces": ["a", "b"]}]}))
    out = subprocess.run([cli, "trace", "-q", str(scene)], check=True, capture_output=True, text=True).stdout
    mine = ssimarch.trace(a, b)
    assert strip_timing(json.loads(mine.to_json())) == strip_timing(json.loads(out))
    assert len(mine["a-b"].curves) >= 1


def test_arguments_are_named_as_the_cli_names_flags():
    # Issue 29: pybind11's "incompatible function arguments", a JSON parser's text and NaN results
    # were what a user saw; every one now names the argument (or key) and the rule.
    one = np.array([[0.0, 0.0, 0.0, 1.0]])
    with pytest.raises(ssimarch.InputError, match=r"unknown keyword 'tolerence' \(did you mean 'tolerance'\?\)"):
        ssimarch.porosity.radial(one, 2.0, 10, tolerence=1e-9)
    with pytest.raises(ssimarch.InputError, match=r"points=2.5 is a float, expected an integer"):
        ssimarch.porosity.radial(one, 2.0, points=2.5)
    with pytest.raises(ssimarch.InputError, match=r"threads=-1: expected a count or index"):
        ssimarch.porosity.radial(one, 2.0, 10, threads=-1)
    with pytest.raises(ssimarch.InputError, match=r"particles\[0,1\]: not a finite number \(nan\)"):
        ssimarch.porosity.bulk(np.array([[0.0, np.nan, 0.0, 1.0]]), 2.0)
    with pytest.raises(ssimarch.InputError, match=r"control_points\[0,0,0\]: not a finite number \(nan\)"):
        ssimarch.Bezier([[[math.nan, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 0]]])
    with pytest.raises(ssimarch.InputError, match=r"sphere.radius: not a finite number \(inf\)"):
        ssimarch.Sphere([0, 0, 0], math.inf)
    scene = {"surfaces": {"s": {"sphere": {"center": [0, 0, 0], "radius": math.nan}},
                          "p": {"plane": {"point": [0, 0, 0], "normal": [0, 0, 1]}}},
             "intersections": [{"name": "c", "surfaces": ["s", "p"]}]}
    with pytest.raises(ssimarch.InputError, match=r"<dict>: surfaces.s.sphere.radius: not a finite number \(nan\)"):
        ssimarch.trace(scene)
    a, b = ssimarch.Sphere([0, 0, 0], 2.0), ssimarch.Plane([0, 0, 1], [0, 0, 1])
    with pytest.raises(ssimarch.InputError, match=r"toward\[0\]: not a finite number \(nan\)"):
        ssimarch.curve_geometry(a, b, at=[[1.7, 0, 1]], toward=[math.nan, 0, 0])
    # An unbounded plane (no u, v) meets the sphere in its whole circle (issue 29: 0 curves before).
    run = ssimarch.trace(a, b)["a-b"]
    assert len(run.curves) == 1 and run.curves[0].closed
    assert run.curves[0].length == pytest.approx(2 * math.pi * math.sqrt(3), rel=1e-9)
