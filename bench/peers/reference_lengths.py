#!/usr/bin/env python3
"""Reference lengths of two peers cases, independent of ssimarch.

occt_bug33244 (two cones of OpenCASCADE's tests/lowalgos/intss/bug33244, each trimmed to |h| <= 3
from its apex): cone 1 is parameterised by (theta, h); for each theta the cone-2 equation is a
quadratic in h whose real roots are the curve's points (solved in the cancellation-free form: the
leading coefficient nearly vanishes); the length is the polyline length on 2^18 angles per root
branch, each cut exactly (bisection) where it leaves a trim: 13.9478623648 (a 30-digit mpmath
quadrature between the exact trim crossings gives 13.94786236484130). Also writes the
scene's apex coordinates.

occt_bug28222_2 (tests/lowalgos/intss/bug28222_2, two cylinders with perpendicular axes at distance
d = 5): in the thin cylinder's frame (angle t, position s along its axis) the thick cylinder is
(d + r sin t)^2 + (s - s0)^2 = R^2, so the two loops are s = s0 +- sqrt(R^2 - (d + r sin t)^2) and
each has length int_0^2pi sqrt(r^2 + s'(t)^2) dt, integrated by mpmath (30 digits) when it is
installed (python3-mpmath), else by the trapezoidal rule on 2^14 angles (periodic and analytic:
it converges geometrically).
Usage: bench/peers/reference_lengths.py
"""
import math

class V(tuple):
    def __add__(a, b): return V(x + y for x, y in zip(a, b))
    def __sub__(a, b): return V(x - y for x, y in zip(a, b))
    def __mul__(a, k): return V(x * k for x in a)
    __rmul__ = __mul__
    def __truediv__(a, k): return V(x / k for x in a)
    def dot(a, b): return sum(x * y for x, y in zip(a, b))
    def norm(a): return math.sqrt(a.dot(a))
    def cross(a, b): return V((a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]))

def cone(loc, d, alpha, radius):
    d = V(d) / V(d).norm()
    apex = V(loc) - radius / math.tan(alpha) * d
    return apex, d, math.tan(alpha)

C1 = cone((-1.11630646267172, -4.54487349779333, 13.2493435203532),
          (-1.05794851588922e-07, -1.39278337794573e-08, 0.999999999999994), 0.785398163360967, 0.560000000061149)
C2 = cone((-2.08647872350287e-07, -5.78732475509323, 13.2493436211),
          (-1.05794850062242e-07, -1.39278350756825e-08, 0.999999999999994), 0.785398163396248, 0.785398163396248)
H = 3.0  # trim: |axial distance from the apex| <= H on both cones

def frame(d):
    a = V((1.0, 0, 0)) if abs(d[0]) < 0.9 else V((0, 1.0, 0))
    e0 = a - a.dot(d) * d
    e0 = e0 / e0.norm()
    return e0, d.cross(e0)

def points(theta):
    """The curve's points over cone 1's ruling at theta: list of (h1, point) for real roots."""
    (A1, d1, t1), (A2, d2, t2) = C1, C2
    e0, e1 = frame(d1)
    w = d1 + t1 * (math.cos(theta) * e0 + math.sin(theta) * e1)  # p = A1 + h w
    q = A1 - A2
    # |p-A2|^2 - (1 + t2^2) ((p-A2).d2)^2 = 0 as a h^2 + b h + c
    k = 1 + t2 * t2
    a = w.dot(w) - k * w.dot(d2) ** 2
    b = 2 * (q.dot(w) - k * q.dot(d2) * w.dot(d2))
    c = q.dot(q) - k * q.dot(d2) ** 2
    disc = b * b - 4 * a * c
    if disc < 0:
        return []
    # The two cones' half-angles agree to 4e-11, so a is nearly 0 and changes sign with theta:
    # (-b +- sqrt(disc)) / 2a loses every digit of the finite root to cancellation and swaps the
    # roots' order where a does (the first version of this script, 13.9504584900, was off by
    # 2.6e-3 for that). Numerical Recipes §5.6: q = -(b + sign(b) sqrt(disc))/2, roots c/q (finite)
    # and q/a, in that order.
    q = -0.5 * (b + math.copysign(math.sqrt(disc), b))
    if q == 0:
        return []
    r = [c / q, q / a if a != 0 else math.inf]
    return [(h, A1 + h * w) for h in r if math.isfinite(h)]

def inside(h, p):
    A2, d2, _ = C2
    return abs(h) <= H and abs((p - A2).dot(d2)) <= H

def branch_length(k, n=1 << 18):
    total, prev = 0.0, None
    for i in range(n + 1):
        th = 2 * math.pi * i / n
        pts = points(th)
        cur = (th, pts[k]) if len(pts) > k else None
        if prev and cur:
            (ta, (ha, pa)), (tb, (hb, pb)) = prev, cur
            ia, ib = inside(ha, pa), inside(hb, pb)
            if ia and ib:
                total += (pb - pa).norm()
            elif ia != ib:  # cut where the branch crosses a trim
                lo, hi = (ta, tb)
                for _ in range(60):
                    mid = 0.5 * (lo + hi)
                    hm, pm = points(mid)[k]
                    if inside(hm, pm) == ia: lo = mid
                    else: hi = mid
                pc = points(0.5 * (lo + hi))[k][1]
                total += (pc - (pa if ia else pb)).norm()
        prev = cur
    return total

def bug28222_2_loop_length():
    """One loop's length (both are equal: the two signs of the square root mirror each other)."""
    p = V((-35.0, 13.3706576198285, 30.5814570420266))
    a = V((0.0, -0.258819045102521, -0.965925826289068))
    a = a / a.norm()
    b = V((1.0, 0, 0)).cross(a)  # across both axes: the thin axis lies at distance p.b from the thick one
    d, r, big_r = p.dot(b), 11.0, 16.5
    try:
        import mpmath as mp
        mp.mp.dps = 30
        d = mp.mpf(d)
        speed = lambda t: mp.sqrt(r ** 2 + ((d + r * mp.sin(t)) * r * mp.cos(t)) ** 2 / (big_r ** 2 - (d + r * mp.sin(t)) ** 2))
        return float(mp.quad(speed, mp.linspace(0, 2 * mp.pi, 9)))
    except ImportError:
        n = 1 << 14
        def speed(t):
            w = d + r * math.sin(t)
            return math.sqrt(r * r + (w * r * math.cos(t)) ** 2 / (big_r * big_r - w * w))
        return 2 * math.pi / n * sum(speed(2 * math.pi * i / n) for i in range(n))

if __name__ == "__main__":
    loop = bug28222_2_loop_length()
    print("occt_bug28222_2: loop %.13f, total %.13f" % (loop, 2 * loop))
    print("apex 1", repr(tuple(C1[0])), "axis", repr(tuple(C1[1])))
    print("apex 2", repr(tuple(C2[0])), "axis", repr(tuple(C2[1])))
    L = [branch_length(k) for k in (0, 1)]
    print("branch lengths", L, "total %.10f" % sum(L))
