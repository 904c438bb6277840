#!/usr/bin/env python3
"""Regression: rough superquadric contacts with gw_rough (GW closed form,
sigma = 10 um per surface, one asperity: n_asp = 1).
- ellipsoid tip on a wall and two ellipsoid tips head-on, the second turned
  by 30 degrees: the force along the trajectory against the elliptic GW
  closed form F = 4/3 E* Rc^1/2 sigma^3/2 gamma F_3/2(-delta/sigma), with
  Rc, gamma from the tips' curvatures (review Eqs. 3-5, 11, 13) and F_3/2 by
  mpmath quadrature, both evaluated here independently of c_core, at the
  overlap known from the positions (negative before touch: this checks the
  gap measured by the plugin too);
- no force before delta = -3 sigma, force from there on (before touch);
- sigma = 0: gw_rough equals hertz_elliptic exactly;
- 2 MPI ranks (the pair straddles the ranks) equal 1 rank; reference output.
gwPlastic on: equal to the elastic law where no summit yields; lower peak
force where they do.
Usage: check_rough_superquadric.py WORKDIR [--update]"""
import math
import os
import sys

import mpmath as mp

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from regress import ROOT, compare_tables, elliptic_hertz, relative_radii, run, save_reference, start, subsample, table

work, update, c = start()
mp.mp.dps = 20
EVERY = 10

Y, nu, sig1, omega = 5e6, 0.3, 1e-5, 30.0
Estar = 1.0 / (2.0 * (1 - nu ** 2) / Y)
sig = math.sqrt(2.0) * sig1                       # two rough surfaces
a1, b1, c1 = 0.001, 0.0006, 0.0015                # atom 1, c axis down
a2, b2, c2 = 0.0015, 0.0006, 0.001                # atoms 2 and 3, a axis along x
step = 1.0e-7                                     # approach per time step (v dt), both cases


def F32(h):
    """F_3/2(h) = int_h^inf (s - h)^3/2 phi(s) ds by quadrature."""
    return float(mp.quad(lambda s: (s - h) ** 1.5 * mp.npdf(s), [h, h + 1, h + 10, mp.inf]))


runs = {}
for name, smooth, sigma, ranks, extra in (("rough", 0, sig1, 1, {}), ("rough_np2", 0, sig1, 2, {}),
                                          ("smooth_gw", 0, 0.0, 1, {}), ("smooth_he", 1, 0.0, 1, {}),
                                          ("plastic_hard", 0, sig1, 1, {"plastic": 1, "hardness": 1e30}),
                                          ("plastic_soft", 0, sig1, 1, {"plastic": 1, "hardness": 2e4})):
    d = os.path.join(work, name)
    run("rough_superquadric/in.rough_superquadric", d, ranks=ranks,
        variables=dict({"smooth": smooth, "sigma": sigma, "omega": omega}, **extra), tag=name)
    runs[name] = table(os.path.join(d, "rough.txt"))

rows = runs["rough"]
cases = [("ellipsoid-wall", elliptic_hertz(a1 * a1 / c1, b1 * b1 / c1), lambda r: c1 - r[1], lambda r: r[3]),
         ("ellipsoid-ellipsoid", elliptic_hertz(*relative_radii(a2 / b2 ** 2, a2 / c2 ** 2, a2 / b2 ** 2, a2 / c2 ** 2,
                                                               math.radians(omega))),
          lambda r: 2 * a2 - (r[5] - r[4]), lambda r: -r[8])]
for name, (Rc, gamma), overlap, force in cases:
    early = sum(1 for r in rows if overlap(r) <= -3 * sig and force(r) != 0.0)
    c.true(early == 0, "%s: no force before delta = -3 sigma (%d rows with force)" % (name, early))
    first = next(overlap(r) for r in rows if force(r) != 0.0)
    c.true(-3 * sig < first <= -3 * sig + 1.01 * step,
           "%s: force begins within one step after delta = -3 sigma (first at delta/sigma = %.5f)" % (name, first / sig))
    worst, before, n = 0.0, 0, 0
    for r in rows[::EVERY]:
        d, f = overlap(r), force(r)
        if d <= -3 * sig:
            continue
        want = 4.0 / 3.0 * Estar * math.sqrt(Rc) * sig ** 1.5 * gamma * F32(-d / sig)
        worst = max(worst, abs(f - want) / want)
        before += d < 0.0
        n += 1
    c.true(before > 20 and n > before, "%s: %d compared rows, %d before touch" % (name, n, before))
    # positions carry 15 digits: the overlap (and F) to ~1e-11 of the rough range
    c.true(worst < 1e-9, "%s: force vs elliptic GW closed form: worst rel. difference %.3g (tol 1e-9)" % (name, worst))

compare_tables(c, runs["smooth_gw"], runs["smooth_he"], 0.0, "sigma = 0: gw_rough equals hertz_elliptic")
compare_tables(c, runs["rough_np2"], rows, 1e-13, "2 ranks equal 1 rank")
# gwPlastic: summits too hard to yield give the elastic law exactly; soft
# summits (hardness 2e4 Pa) yield and carry less force at the same overlap
compare_tables(c, runs["plastic_hard"], rows, 0.0, "gwPlastic on, hardness 1e30 Pa: equals the elastic GW law")
soft = runs["plastic_soft"]
fe, fp = max(r[3] for r in rows), max(r[3] for r in soft)
c.true(fp < 0.9 * fe, "gwPlastic on, hardness 2e4 Pa: wall impact peak force %.4g N below the elastic %.4g N" % (fp, fe))
ref = os.path.join(ROOT, "inputs", "rough_superquadric", "reference", "rough.txt")
if update:
    save_reference(os.path.join(work, "rough", "rough.txt"), ref, EVERY)
compare_tables(c, subsample(rows, EVERY), table(ref), 1e-9, "vs reference")
c.finish()
