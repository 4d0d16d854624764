# Independent length of the transversal curve of two tori tangent along a circle (tests' reference).
# Torus A: R=2, r=1, axis z at the origin; torus B: R=3, r=2, axis y, centre (2,0,0).
# On A(u, v) = ((2+cos v) cos u, (2+cos v) sin u, sin v), B's implicit form G(u, v) = 0; one edge of
# the transversal curve runs from the tangent crossing (u = 0, cos v = -2/3) to the node (u = pi, v = 0):
# v(u) by Newton continuation in 80-bit floats, length by Gauss-Legendre panels.
import numpy as np
L = np.longdouble
def parts(u, v):
    cu, su, cv, sv = np.cos(u), np.sin(u), np.cos(v), np.sin(v)
    x, y, z = (2 + cv) * cu, (2 + cv) * su, sv
    Au = np.array([-(2 + cv) * su, (2 + cv) * cu, L(0)]); Av = np.array([-sv * cu, -sv * su, cv])
    q = (x - 2)**2 + y**2 + z**2 + 5
    g = q * q - 36 * ((x - 2)**2 + z**2)
    grad = np.array([4 * q * (x - 2) - 72 * (x - 2), 4 * q * y, 4 * q * z - 72 * z])
    return g, grad @ Au, grad @ Av, Au, Av
def solve_v(u, v):
    for _ in range(60):
        g, gu, gv, _, _ = parts(u, v)
        dv = -g / gv
        v = v + dv
        if abs(dv) < L(1e-18): break
    return v
xs, ws = np.polynomial.legendre.leggauss(24)
xs = xs.astype(L); ws = ws.astype(L)
pi = L(np.pi)  # float pi; fine: the edge ends at the node, the integrand is smooth there
panels = np.linspace(L(0), pi, 4001)
vstar = -(pi - np.arccos(L(2) / 3))
v = vstar
length = L(0)
for a, b in zip(panels[:-1], panels[1:]):
    us = (a + b) / 2 + (b - a) / 2 * xs
    for u, w in zip(us, ws):
        v = solve_v(u, v)
        g, gu, gv, Au, Av = parts(u, v)
        dvdu = -gu / gv
        length += w * (b - a) / 2 * np.sqrt(np.sum((Au + Av * dvdu)**2))
print("edge", repr(float(length)), "oval", repr(float(4 * length)), "end v", float(v))
