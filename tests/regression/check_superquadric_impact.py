#!/usr/bin/env python3
"""Regression (b): superquadric-wall and superquadric-superquadric impacts
with hertz_elliptic, for omega = 0 and 60 degrees between the principal
directions of the pair.
- Ellipsoid tip on a wall, and two ellipsoid tips head-on (symmetric: no
  torque, the collision stays one-dimensional): maximum overlap and collision
  time against the exact elliptic Hertz impact, delta_max = (15 m v^2 /
  (16 E* R_force^1/2))^(2/5), T_c = 2 I delta_max / v, with R_force = Rc gamma^2
  evaluated here independently of c_core (Python AGM for K, E; bisection on
  review Eq. 13 in its original form, ratio R_minor/R_major; Eq. 3-4 with
  the angle);
- stock superquadric `hertz` (volume-equivalent radius) printed beside it;
- each run against its committed reference, including a tumbling blocky
  (n = 4) superquadric on the wall.
Usage: check_superquadric_impact.py WORKDIR [--update]"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from regress import (ROOT, compare_tables, elliptic_hertz, hertz_impact, impact, relative_radii, run,
                     save_reference, start, subsample, table)

ref_dir = os.path.join(ROOT, "inputs", "superquadric_impact", "reference")
work, update, c = start()
EVERY = 10


def R_force(R1, R2):
    Rc, gamma = elliptic_hertz(R1, R2)
    return Rc * gamma * gamma


rho, Y, nu = 2500.0, 5e6, 0.3
Estar = 1.0 / (2.0 * (1 - nu ** 2) / Y)
a1, b1, c1 = 0.001, 0.0006, 0.0015          # atom 1, c axis down
a2, b2, c2 = 0.0015, 0.0006, 0.001          # atoms 2 and 3, a axis along x
m1 = rho * 4.0 / 3.0 * math.pi * a1 * b1 * c1
m2 = rho * 4.0 / 3.0 * math.pi * a2 * b2 * c2

for omega in ("0", "60"):
    runs = {}
    for model in ("hertz_elliptic", "hertz"):
        d = os.path.join(work, "%s_w%s" % (model, omega))
        run("superquadric_impact/in.superquadric_impact", d, variables={"model": model, "omega": omega}, tag=model)
        runs[model] = table(os.path.join(d, "impact.txt"))
    w = math.radians(float(omega))
    cases = [("wall", m1, 1.0, R_force(a1 * a1 / c1, b1 * b1 / c1), lambda r: c1 - r[1]),
             ("pair omega=%s" % omega, m2 / 2, 1.0,
              R_force(*relative_radii(a2 / b2 ** 2, a2 / c2 ** 2, a2 / b2 ** 2, a2 / c2 ** 2, w)),
              lambda r: 2 * a2 - (r[4] - r[3]))]
    for name, mb, v, Rf, ov in cases:
        if name == "wall" and omega != "0":
            continue
        tc, dmax = hertz_impact(mb, v, Estar, Rf)
        tc_sim, dmax_sim = impact(runs["hertz_elliptic"], ov)
        c.rel(dmax_sim, dmax, 1e-6, "%s: hertz_elliptic maximum overlap vs exact elliptic Hertz" % name)
        c.rel(tc_sim, tc, 1e-6, "%s: hertz_elliptic collision time vs exact elliptic Hertz" % name)
        tc_h, dmax_h = impact(runs["hertz"], ov)
        print("     %s: stock superquadric hertz max overlap off by %+.1f%%, collision time by %+.1f%%" %
              (name, 100 * (dmax_h / dmax - 1), 100 * (tc_h / tc - 1)))
    path = os.path.join(work, "hertz_elliptic_w%s" % omega, "impact.txt")
    ref = os.path.join(ref_dir, "impact_hertz_elliptic_w%s.txt" % omega)
    if update:
        save_reference(path, ref, EVERY)
    got = subsample(table(path), EVERY)
    c.true(any(abs(r[8]) > 0 for r in got), "blocky superquadric touched the wall (omega=%s)" % omega)
    compare_tables(c, got, table(ref), 1e-8, "hertz_elliptic omega=%s vs reference" % omega)
c.finish()
