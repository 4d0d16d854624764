"""Surface evaluation on numpy arrays: the parallel loops give the single-threaded results bit for bit,
every derivative of the implicit form to order 4 against closed forms, and implicit surfaces made
without a box (evaluated; traced with the other surface's box; a clear error where no box can be had)."""
import math
import time

import numpy as np
import pytest

import ssimarch

# More points than three chunks of the parallel loop (python/array_loops.hpp: 4096 points), and not a
# multiple of one.
N = 3 * 4096 + 17


def parametric_cases():
    rng = np.random.default_rng(7)
    u, v = rng.uniform(0.0, 6.2, N), rng.uniform(-1.5, 1.5, N)
    surfaces = [ssimarch.Sphere([1, -2, 0.5], 2), ssimarch.Torus([0, 0, 0], [0, 0, 1], 3, 1),
                ssimarch.ParametricSurface("cos(u)*(2+sin(v))", "sin(u)*(2+sin(v))", "v*v", domain=((0, 6.3), (-2, 2))),
                ssimarch.Bezier(rng.normal(size=(4, 3, 3)))]
    return surfaces, u, v


def implicit_cases():
    rng = np.random.default_rng(8)
    p = rng.uniform(-2.0, 2.0, (N, 3))
    surfaces = [ssimarch.Sphere([1, -2, 0.5], 2), ssimarch.Torus([0, 0, 0], [0, 0, 1], 3, 1),
                ssimarch.ImplicitSurface("x^2*y + sin(z)*x - y^3/3 + exp(x*z/4)")]
    return surfaces, p


def assert_same(a, b):
    if isinstance(a, dict):
        assert a.keys() == b.keys()
        for k in a:
            np.testing.assert_array_equal(a[k], b[k], err_msg=str(k))
    else:
        np.testing.assert_array_equal(a, b)


@pytest.mark.parametrize("threads", [2, 3, 0])
def test_parallel_evaluation_equals_the_single_threaded_one(threads):
    surfaces, u, v = parametric_cases()
    for s in surfaces:
        for method in ("point", "normal", "curvatures"):
            f = getattr(s, method)
            assert_same(f(u, v, threads=threads), f(u, v, threads=1))
        assert_same(s.derivatives(u, v, order=4, threads=threads), s.derivatives(u, v, order=4, threads=1))
    surfaces, p = implicit_cases()
    for s in surfaces:
        for method in ("value", "gradient", "hessian", "normal", "curvatures"):
            f = getattr(s, method)
            assert_same(f(p, threads=threads), f(p, threads=1))
        assert_same(s.implicit_derivatives(p, order=4, threads=threads), s.implicit_derivatives(p, order=4, threads=1))


def test_parallel_evaluation_equals_one_call_per_point():
    # The serial reference outside the chunked loop: single points, one call each.
    surfaces, u, v = parametric_cases()
    for s in surfaces[:2]:
        many = s.point(u, v)
        for i in range(0, N, 997):
            np.testing.assert_array_equal(many[i], s.point(u[i], v[i], threads=1))
    with pytest.raises(TypeError):
        surfaces[0].point(u, v, threads=-1)


def implicit_closed_form(x, y, z):
    """f = x^2 y + x sin z - y^3/3 + exp(xz/4) and its partial derivatives {(i, j, k): value}."""
    e = np.exp(x * z / 4)
    s, c = np.sin(z), np.cos(z)
    d = {
        (0, 0, 0): x * x * y + x * s - y**3 / 3 + e,
        (1, 0, 0): 2 * x * y + s + z / 4 * e, (0, 1, 0): x * x - y * y, (0, 0, 1): x * c + x / 4 * e,
        (2, 0, 0): 2 * y + z * z / 16 * e, (1, 1, 0): 2 * x, (1, 0, 1): c + e / 4 + x * z / 16 * e,
        (0, 2, 0): -2 * y, (0, 1, 1): 0 * x, (0, 0, 2): -x * s + x * x / 16 * e,
        (3, 0, 0): z**3 / 64 * e, (2, 1, 0): 2 + 0 * x, (0, 3, 0): -2 + 0 * x, (1, 2, 0): 0 * x,
        (0, 0, 3): -x * c + x**3 / 64 * e, (2, 0, 1): z / 8 * e + z * z * x / 64 * e,
        (1, 0, 2): -s + x / 8 * e + x * x * z / 64 * e,
        (4, 0, 0): z**4 / 256 * e, (0, 0, 4): x * s + x**4 / 256 * e, (0, 4, 0): 0 * x,
        (2, 2, 0): 0 * x, (3, 0, 1): 3 * z * z / 64 * e + z**3 * x / 256 * e,
        (1, 0, 3): -c + 3 * x * x / 64 * e + x**3 * z / 256 * e,
        (2, 0, 2): e / 8 + x * z / 32 * e + x * z / 64 * e * 2 + x * x * z * z / 256 * e,
    }
    return d


def test_implicit_derivatives_to_order_four_are_the_closed_forms():
    s = ssimarch.ImplicitSurface("x^2*y + x*sin(z) - y^3/3 + exp(x*z/4)")
    rng = np.random.default_rng(9)
    p = rng.uniform(-1.5, 1.5, (5, 7, 3))
    d = s.implicit_derivatives(p, order=4)
    assert len(d) == 35 and all(i + j + k <= 4 for i, j, k in d)  # C(4 + 3, 3) partials
    assert all(a.shape == (5, 7) and a.dtype == np.float64 for a in d.values())
    for key, expected in implicit_closed_form(p[..., 0], p[..., 1], p[..., 2]).items():
        np.testing.assert_allclose(d[key], expected, rtol=1e-12, atol=1e-12, err_msg=str(key))
    # The orders below share the values; order 1 and 2 agree with gradient and hessian.
    d2 = s.implicit_derivatives(p, order=2)
    assert set(d2) == {k for k in d if sum(k) <= 2}
    g, h = s.gradient(p), s.hessian(p)
    for axis, key in enumerate([(1, 0, 0), (0, 1, 0), (0, 0, 1)]):
        np.testing.assert_allclose(d2[key], g[..., axis], rtol=1e-14, atol=1e-14)
    np.testing.assert_allclose(d2[(1, 0, 1)], h[..., 0, 2], rtol=1e-14, atol=1e-14)
    np.testing.assert_allclose(s.implicit_derivatives(p, order=0)[(0, 0, 0)], s.value(p), rtol=0, atol=0)
    with pytest.raises(ssimarch.InputError, match=r"^order: must be an integer in \[0, 4\]"):
        s.implicit_derivatives(p, order=5)
    with pytest.raises(ssimarch.InputError, match="no implicit form"):
        ssimarch.ParametricSurface("u", "v", "0", domain=((0, 1), (0, 1))).implicit_derivatives(p)
    with pytest.raises(ssimarch.InputError, match=r"points: expected points as an array of shape \(\.\.\., 3\)"):
        s.implicit_derivatives(np.zeros((2, 4)))
    assert s.implicit_derivatives(np.empty((0, 3)), order=3)[(1, 1, 1)].shape == (0,)


def test_implicit_derivatives_of_a_primitive():
    # The sphere's implicit form f = (|p - c|^2 - r^2) / (2 r) (surface/sphere.hpp): second
    # derivatives delta_ij / r, nothing above.
    c, r = np.array([1.0, -2.0, 0.5]), 2.0
    p = np.array([[0.3, 0.1, -0.7], [3.0, -2.0, 0.5]])
    d = ssimarch.Sphere(c, r).implicit_derivatives(p, order=4)
    np.testing.assert_allclose(d[(0, 0, 0)], ((p - c) ** 2).sum(-1) / (2 * r) - r / 2, atol=1e-14)
    np.testing.assert_allclose(d[(0, 2, 0)], 1 / r, atol=1e-14)
    for key in d:
        if sum(key) >= 3 or (sum(key) == 2 and max(key) == 1):
            np.testing.assert_allclose(d[key], 0.0, atol=1e-13, err_msg=str(key))


def test_an_implicit_surface_needs_no_box_to_evaluate():
    s = ssimarch.ImplicitSurface("x^2+y^2-1")
    assert s.box is None and s.description == {"implicit": "x^2+y^2-1"}
    p = np.array([[1.0, 0.0, 5.0], [0.6, 0.8, -100.0], [2.0, 1.0, 1e3]])  # anywhere: no region to stay in
    np.testing.assert_allclose(s.value(p), p[:, 0] ** 2 + p[:, 1] ** 2 - 1, atol=1e-12)
    np.testing.assert_allclose(s.normal(p[:2]), [[1, 0, 0], [0.6, 0.8, 0]], atol=1e-15)
    assert ssimarch.Surface({"implicit": "x+y+z"}).box is None
    boxed = ssimarch.ImplicitSurface("x^2+y^2-1", box=[[-2, 2], [-2, 2], [-1, 1]])
    assert boxed.box == ((-2.0, 2.0), (-2.0, 2.0), (-1.0, 1.0))


def test_a_box_less_implicit_surface_is_traced_in_the_other_surfaces_box():
    cylinder = ssimarch.ImplicitSurface("x^2+y^2-1")
    # Against a sphere of radius 2 (both implicit: the sphere's box bounds the search): the circles
    # of radius 1 at z = +-sqrt(3).
    run = ssimarch.trace(ssimarch.Sphere([0, 0, 0], 2), cylinder)["a-b"]
    assert len(run.curves) == 2 and all(c.closed for c in run.curves)
    for c in run.curves:
        assert c.length == pytest.approx(2 * math.pi, rel=1e-4)
        np.testing.assert_allclose(np.abs(c.xyz[:, 2]), math.sqrt(3), atol=1e-8)
    # Either order; against a surface with no implicit form (traced in its parameters).
    (c,) = ssimarch.trace(cylinder, ssimarch.ParametricSurface("u", "v", "0.5", domain=((-3, 3), (-3, 3))))["a-b"].curves
    assert c.closed and c.length == pytest.approx(2 * math.pi, rel=1e-4)
    at = np.array([[1.1, 0.0, 0.5], [0.0, -0.9, 0.5]])
    g = ssimarch.curve_geometry(ssimarch.Plane([0, 0, 0.5], [0, 0, 1], u=[-3, 3], v=[-3, 3]), cylinder, at=at)
    np.testing.assert_allclose(g["kappa"], 1.0, atol=1e-8)


def test_where_no_box_can_be_had_the_error_names_the_surface():
    with pytest.raises(ssimarch.InputError, match=r'^a\.box: the implicit surface "x\^2\+y\^2-1" has no box.*'
                                                  r'\(b has none either'):
        ssimarch.trace(ssimarch.ImplicitSurface("x^2+y^2-1"), ssimarch.ImplicitSurface("x+y"))
    scene = {"surfaces": {"s": ssimarch.Sphere([0, 0, 0], 2), "c": ssimarch.ImplicitSurface("x^2+y^2-1")},
             "intersections": [{"name": "s-c", "surfaces": ["s", "c"]}]}
    with pytest.raises(ssimarch.InputError, match=r'^surfaces\.c\.box: the implicit surface "x\^2\+y\^2-1" has no box'):
        ssimarch.trace(scene)


def test_the_gil_is_released_while_evaluating():
    # Python's main thread keeps running while another thread evaluates a large array: had the call
    # kept the GIL, the main thread would stand still until it returned.
    import threading

    f = "+".join(f"sin({k}*x+y)*cos(z-{k})" for k in range(1, 41))
    s = ssimarch.ImplicitSurface(f)
    points = np.random.default_rng(4).uniform(-1, 1, (200_000, 3))
    inside = threading.Event()
    done = []

    def work():
        inside.set()
        t0 = time.perf_counter()
        s.value(points, threads=1)
        done.append(time.perf_counter() - t0)

    worker = threading.Thread(target=work)
    worker.start()
    inside.wait()
    steps = 0
    while worker.is_alive():
        steps += 1
    worker.join()
    # Iterations run at millions per second; with the GIL held only a few switch intervals (5 ms)
    # before the call would count.
    assert done[0] > 0.05, "the evaluation was too short to tell"
    assert steps > 10_000, (steps, done)
