#!/usr/bin/env python3
"""Regression (issue deck c): an ellipsoid pressed into a plane and moved a
small distance along its contact ellipse's major axis, its minor axis and at
45 degrees (inputs/ellipsoid_shear), with `tangential cmd_tangential`:
- normal force and contact ellipse from elliptic Hertz (evaluated here,
  independently of c_core);
- the tangential force against Mindlin's no-slip stiffnesses of the ellipse
  (review Eqs. 56-57: k = 2 pi a / c, c_major = sum [(1-nu) K + nu D]/G,
  c_minor = sum [K - nu D]/G over both bodies, checked against a Cerruti
  quadrature in tests/reference/gen_mindlin.py) with the micro-slip of
  Eq. 59: F = mu Fn [1 - (1 - 2 w / (3 mu Fn))^3/2] along K0 s, w = |K0 s|;
  at 45 degrees the force is not parallel to the displacement (Eq. 58);
- stock `tangential history` beside it (one stiffness 8 G* (a b)^1/2, force
  parallel to the displacement).
Usage: check_ellipsoid_shear.py WORKDIR"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from regress import elliptic_contact, mindlin_ellipse, mindlin_ellipse_force, run, start, table

work, _, c = start()
E, nu, mu, s, d0 = 5e6, 0.3, 0.5, 2e-7, 5e-6
a1, b1, c1 = 1.0e-3, 0.6e-3, 1.5e-3
G = E / (2 * (1 + nu))
Estar = 1.0 / (2 * (1 - nu ** 2) / E)
a, b, Fn = elliptic_contact(a1 * a1 / c1, b1 * b1 / c1, Estar, d0)   # a along x
k_major, k_minor = mindlin_ellipse(a, b / a, nu, G)
k_stock = 8 * math.sqrt(a * b) / (2 * (2 - nu) / G)
print("     contact ellipse a = %.6g m, b = %.6g m; k_major %.6g, k_minor %.6g, stock 8 G* (ab)^1/2 %.6g N/m"
      % (a, b, k_major, k_minor, k_stock))
runs = {}
for tmodel in ("cmd_tangential", "history"):
    d = os.path.join(work, tmodel)
    run("ellipsoid_shear/in.ellipsoid_shear", d, variables={"tmodel": tmodel}, tag=tmodel)
    runs[tmodel] = table(os.path.join(d, "shear.txt"))
angle = lambda fx, fy, sx, sy: (math.degrees(math.atan2(fy, fx) - math.atan2(-sy, -sx)) + 180.0) % 360.0 - 180.0
for r, h in zip(runs["cmd_tangential"], runs["history"]):
    Fx, Fy, F = mindlin_ellipse_force(k_major, k_minor, s, r[1], mu * Fn)
    want = (Fx, Fy)
    sx, sy = s * math.cos(math.radians(r[1])), s * math.sin(math.radians(r[1]))   # the displacement, for the printout
    c.rel(r[7], Fn, 1e-9, "%g deg: normal force vs elliptic Hertz" % r[1])
    err = math.hypot(r[5] - want[0], r[6] - want[1]) / F
    c.true(err < 1e-6, "%g deg: tangential force (%.6g, %.6g) N vs Mindlin with micro-slip (%.6g, %.6g): %.3g (tol 1e-6)"
           % (r[1], r[5], r[6], want[0], want[1], err))
    print("     %g deg: force angle %.4f deg from the displacement (cmd_tangential), %.4f (stock history); |F| %.6g vs %.6g N"
          % (r[1], angle(r[5], r[6], sx, sy), angle(h[5], h[6], sx, sy), math.hypot(r[5], r[6]), math.hypot(h[5], h[6])))
c.finish()
