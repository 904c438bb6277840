#!/usr/bin/env python3
"""Regression: DMT adhesion (jkr_elliptic with adhesionLaw dmt), the
hard-material end of the Tabor range, on spheres (inputs/dmt_pulloff: a
sphere off a wall, two spheres off each other) and superquadrics
(inputs/superquadric_pulloff: an ellipsoid tip off a wall, two tips, the
second turned by 30 degrees), pulled apart at constant speed:
- while the surfaces overlap, the force is Hertz's less 2 pi w R (spheres;
  R the effective radius) or elliptic Hertz's less 2 pi w (R_major
  R_minor)^1/2 (superquadrics; relative radii of the tips from review
  Eqs. 3-4, elliptic Hertz evaluated here), within 1e-9 of the pull-off
  force; none once they part (no neck);
- the pull-off force is 2 pi w R (DMT's published limit) against JKR's
  3/2 pi w R from the same deck with adhesionLaw jkr;
- 2 MPI ranks equal 1 rank (the pairs straddle the ranks).
Usage: check_dmt_pulloff.py WORKDIR"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from regress import compare_tables, elliptic_contact, relative_radii, run, start, table

work, _, c = start()
E, nu, w, R = 5e6, 0.3, 0.5, 1e-3
Estar = 1.0 / (2.0 * (1 - nu ** 2) / E)
runs = {}
for name, deck, v, ranks in (("dmt", "dmt_pulloff/in.dmt_pulloff", {}, 1),
                             ("dmt_np2", "dmt_pulloff/in.dmt_pulloff", {}, 2),
                             ("jkr", "dmt_pulloff/in.dmt_pulloff", {"alaw": "jkr"}, 1),
                             ("sq_dmt", "superquadric_pulloff/in.superquadric_pulloff",
                              {"alaw": "dmt", "w": w, "omega": 30.0}, 1),
                             ("sq_dmt_np2", "superquadric_pulloff/in.superquadric_pulloff",
                              {"alaw": "dmt", "w": w, "omega": 30.0}, 2)):
    d = os.path.join(work, name)
    run(deck, d, ranks=ranks, variables=v, tag=name)
    runs[name] = table(os.path.join(d, "pulloff.txt"))


def hertz_sphere(Re, delta):
    return 4.0 / 3.0 * Estar * math.sqrt(Re) * delta ** 1.5


a1, b1, c1 = 0.001, 0.0006, 0.0015
a2, b2, c2 = 0.0015, 0.0006, 0.001
Rp = relative_radii(a2 / b2 ** 2, a2 / c2 ** 2, a2 / b2 ** 2, a2 / c2 ** 2, math.radians(30.0))
cases = [("sphere-wall", "dmt", "jkr", (R, R), lambda r: R - r[1], lambda r: r[2]),
         ("sphere-sphere", "dmt", "jkr", (R / 2, R / 2), lambda r: 2 * R - (r[4] - r[3]), lambda r: -r[5]),
         ("ellipsoid-wall", "sq_dmt", None, (a1 * a1 / c1, b1 * b1 / c1), lambda r: c1 - r[1], lambda r: r[2]),
         ("ellipsoid-ellipsoid", "sq_dmt", None, Rp, lambda r: 2 * a2 - (r[4] - r[3]), lambda r: -r[5])]
for name, key, jkr, (R1, R2), overlap, force in cases:
    rows = runs[key]
    F_po = 2 * math.pi * w * math.sqrt(R1 * R2)
    worst, n, apart = 0.0, 0, 0
    for r in rows:
        d = overlap(r)
        if d > 0:
            want = (hertz_sphere(R1, d) if R1 == R2 else elliptic_contact(R1, R2, Estar, d)[2]) - F_po
            worst = max(worst, abs(force(r) - want) / F_po)
            n += 1
        else:
            apart += 1
    c.true(n > 100 and apart > 100, "%s: %d rows in contact, %d apart" % (name, n, apart))
    c.true(all(force(r) == 0.0 for r in rows if overlap(r) <= 0), "%s: no force once apart (no neck)" % name)
    c.true(worst < 1e-9, "%s: force vs Hertz less 2 pi w (R1 R2)^1/2 = %.6g N: worst %.3g of it (tol 1e-9)"
           % (name, F_po, worst))
    # the last overlap before parting is below one step's travel (2e-9 m): Hertz's force there is ~1e-8 N
    c.rel(min(force(r) for r in rows), -F_po, 1e-5, "%s: pull-off force, DMT's 2 pi w (R1 R2)^1/2" % name)
    if jkr:
        c.rel(min(force(r) for r in runs[jkr]), -1.5 * math.pi * w * R1, 1e-6,
              "%s: adhesionLaw jkr on the same deck: pull-off JKR's 3/2 pi w R" % name)
compare_tables(c, runs["dmt_np2"], runs["dmt"], 1e-13, "spheres: 2 ranks equal 1 rank")
compare_tables(c, runs["sq_dmt_np2"], runs["sq_dmt"], 1e-13, "superquadrics: 2 ranks equal 1 rank")
c.finish()
