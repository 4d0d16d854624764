"""Exact rational B-spline (NURBS) forms of ssimarch's primitives, laid out as OpenCASCADE's
GeomConvert lays them out (issue 27): a full circle as three rational quadratic arcs of 120
degrees (7 poles, knots 0, 2pi/3, 4pi/3, 2pi, the middle weights cos 60 = 1/2), a half circle as
two arcs of 90 degrees (5 poles, weights sqrt(1/2)), straight directions of degree 1. Surfaces of
revolution are the tensor product of the circle in u and the profile in v (The NURBS Book, 2nd
ed., sections 7.5 and 8.5); an ellipsoid is the unit sphere's net mapped by the affine map that
makes it; a paraboloid's rectangle is an exact degree-2 Bezier patch (its Bernstein coefficients
of u, u^2). Used by scripts/metamorphic (transform `nurbs`) and scripts/nurbs-scene.

Parameters are not the primitives' (the B-spline's seam sits where OpenCASCADE puts it, at
u = 0 of the frame; a sphere's poles stay on its axis), so only the point set is the same, which
is what the comparisons check. Unbounded primitives (a plane without u/v, a cylinder or cone
without range), capsules and expression surfaces have no form here: None.
"""
import math


class V(tuple):
    """A 3-vector without numpy (the scripts run on any python3)."""

    def __add__(self, o):
        return V(a + b for a, b in zip(self, o))

    def __sub__(self, o):
        return V(a - b for a, b in zip(self, o))

    def __mul__(self, s):
        return V(a * s for a in self)

    __rmul__ = __mul__

    def dot(self, o):
        return sum(a * b for a, b in zip(self, o))

    def norm(self):
        return math.sqrt(self.dot(self))

    def cross(self, o):
        return V((self[1] * o[2] - self[2] * o[1], self[2] * o[0] - self[0] * o[2], self[0] * o[1] - self[1] * o[0]))

SAFE = {k: getattr(math, k) for k in ("sin", "cos", "tan", "asin", "acos", "atan", "atan2", "sqrt", "exp", "log", "pi", "e")}


def value(x, constants):
    """A scene number: a JSON number or an expression string of the scene's constants."""
    if isinstance(x, (int, float)) and not isinstance(x, bool):
        return float(x)
    env = dict(SAFE)
    for k, v in (constants or {}).items():
        env[k] = value(v, constants)
    return float(eval(str(x).replace("^", "**"), {"__builtins__": {}}, env))


def frame(axis, reference=None):
    """ssimarch's Frame::from_axis: e2 = axis, e0 = reference (or the coordinate axis least
    aligned with the axis, x first on ties) without its axial part, e1 = e2 x e0."""
    e2 = V(axis)
    e2 = e2 * (1 / e2.norm())
    if reference is None:
        k = min(range(3), key=lambda i: (abs(e2[i]), i))
        reference = V(1.0 if i == k else 0.0 for i in range(3))
    r = V(reference)
    e0 = r - e2 * r.dot(e2)
    e0 = e0 * (1 / e0.norm())
    return e0, e2.cross(e0), e2


def arc(a, b, pieces):
    """Rational quadratic arc of the unit circle from angle a to b in `pieces` equal arcs:
    (2D poles, weights, knots in radians)."""
    d = (b - a) / pieces
    poles, weights, knots = [], [], [a] * 3
    for k in range(pieces):
        t0, tm = a + k * d, a + (k + 0.5) * d
        poles += [(math.cos(t0), math.sin(t0)), (math.cos(tm) / math.cos(d / 2), math.sin(tm) / math.cos(d / 2))]
        weights += [1.0, math.cos(d / 2)]
        if k > 0:
            knots += [t0, t0]
    poles.append((math.cos(b), math.sin(b)))
    weights.append(1.0)
    knots += [b] * 3
    return poles, weights, knots


def full_circle():
    return arc(0.0, 2 * math.pi, 3)


def revolution(origin, e, profile, profile_weights, profile_knots, profile_degree):
    """Surface of revolution of the profile (rho, h) about e[2] through origin, u the angle."""
    circle, wu, ku = full_circle()
    net, weights = [], []
    for (c, s), wi in zip(circle, wu):
        net.append([list(origin + (e[0] * c + e[1] * s) * rho + e[2] * h) for rho, h in profile])
        weights.append([wi * wj for wj in profile_weights])
    return bspline(2, profile_degree, ku, profile_knots, net, weights)


def bspline(p, q, ku, kv, net, weights=None):
    d = {"degree": [p, q], "knots_u": list(ku), "knots_v": list(kv), "control_points": [[[float(x) for x in pt] for pt in row] for row in net]}
    if weights is not None:
        d["weights"] = [[float(w) for w in row] for row in weights]
    return {"bspline": d}


def sphere_like(center, radii, e):
    """Ellipsoid (sphere when the radii agree) of semi-axes radii along e: the unit sphere's net
    with each local coordinate scaled."""
    half, wv, kv = arc(-math.pi / 2, math.pi / 2, 2)
    scaled = [e[0] * radii[0], e[1] * radii[1], e[2] * radii[2]]
    return revolution(V(center), scaled, [(c, s) for c, s in half], wv, kv, 2)


def to_nurbs(spec, constants=None):
    """The exact NURBS of a surface spec of the scene format, or None."""
    if not isinstance(spec, dict) or len(spec) != 1:
        return None
    kind, d = next(iter(spec.items()))
    if kind == "spherocylinder" or kind == "capsule" or kind in ("bezier", "bspline", "nurbs", "parametric", "implicit", "step"):
        return None
    v = lambda x: value(x, constants)  # noqa: E731
    vec = lambda p: V(v(c) for c in p)  # noqa: E731
    ref = vec(d["reference"]) if "reference" in d else None
    if kind == "plane":
        if "u" not in d or "v" not in d:
            return None
        e = frame(vec(d["normal"]), ref)
        o = vec(d["point"])
        (u0, u1), (v0, v1) = [v(x) for x in d["u"]], [v(x) for x in d["v"]]
        net = [[o + e[0] * a + e[1] * b for b in (v0, v1)] for a in (u0, u1)]
        return bspline(1, 1, [u0, u0, u1, u1], [v0, v0, v1, v1], net)
    if kind == "sphere":
        e = frame(vec(d.get("axis", [0, 0, 1])), ref)
        r = v(d["radius"])
        return sphere_like(vec(d["center"]), [r, r, r], e)
    if kind == "ellipsoid":
        e = frame(vec(d.get("axis", [0, 0, 1])), ref)
        return sphere_like(vec(d["center"]), [v(x) for x in d["radii"]], e)
    if kind == "cylinder":
        if "range" not in d:
            return None
        e = frame(vec(d["axis"]), ref)
        h0, h1 = [v(x) for x in d["range"]]
        r = v(d["radius"])
        return revolution(vec(d["point"]), e, [(r, h0), (r, h1)], [1.0, 1.0], [h0, h0, h1, h1], 1)
    if kind == "cone":
        if "range" not in d:
            return None
        e = frame(vec(d["axis"]), ref)
        h0, h1 = [v(x) for x in d["range"]]
        t = math.tan(v(d["half_angle"]))
        return revolution(vec(d["apex"]), e, [(t * h0, h0), (t * h1, h1)], [1.0, 1.0], [h0, h0, h1, h1], 1)
    if kind == "torus":
        e = frame(vec(d.get("axis", [0, 0, 1])), ref)
        R, r = v(d["major_radius"]), v(d["minor_radius"])
        circle, wv, kv = full_circle()
        return revolution(vec(d["center"]), e, [(R + r * c, r * s) for c, s in circle], wv, kv, 2)
    if kind == "paraboloid":
        if "u" not in d or "v" not in d:
            return None
        e = frame(vec(d["axis"]), ref)
        fl = d["focal_length"]
        fu, fv = ([v(x) for x in fl] if isinstance(fl, list) else [v(fl)] * 2)
        (u0, u1), (v0, v1) = [v(x) for x in d["u"]], [v(x) for x in d["v"]]
        bu, bv = (u0, (u0 + u1) / 2, u1), (v0, (v0 + v1) / 2, v1)
        su, sv = (u0 * u0, u0 * u1, u1 * u1), (v0 * v0, v0 * v1, v1 * v1)  # Bernstein coefficients of u^2
        o = vec(d["vertex"])
        net = [[o + e[0] * bu[i] + e[1] * bv[j] + e[2] * (su[i] / (4 * fu) + sv[j] / (4 * fv)) for j in range(3)] for i in range(3)]
        return bspline(2, 2, [u0] * 3 + [u1] * 3, [v0] * 3 + [v1] * 3, net)
    return None
