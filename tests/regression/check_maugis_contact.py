#!/usr/bin/env python3
"""Regression: Maugis-Dugdale adhesion in decks (jkr_elliptic with
adhesionLaw maugis and tabor; inputs/maugis_contact): a sphere pressed into
a wall and lifted, two spheres pressed together and parted (prescribed
motion), and two free spheres colliding head-on, with no damping.
The reference is an independent solution of the model in Python
(regress.MaugisDugdale: the branch solved for m = c/a by bisection, not the
C code's variable s, series or Newton; the overlap-controlled path by
following the whole curve of states and jumping at its folds; its pull-off
force against the mpmath table maugis.csv at lambda 0.5, 1, 2). Checks:
- the force at every overlap of the cycle (lambda 0.37 and 0.29: the zone
  acts before touch and after the contact ends; 3.7 and 2.9: the contact
  folds) within 1e-9 of the pull-off force; the zone starts at the
  approach overlap -h0 and the attraction ends at the model's separation
  overlap (the last attached overlap within one step of it);
- the loss of a collision (lambda 2.9): the rebound speed at 1.25 v_s is
  (v^2 - v_s^2)^1/2 with v_s = (2 W / m*)^1/2, W the hysteresis loop's
  area (quadrature along the curve here); at 0.8 v_s the spheres stick
  (the zone's loop at lambda 0.29 is 1/400 of it: its jumps are checked
  in the cycle's forces);
- adhesionLaw tabor picks JKR (Tabor 32), DMT (0.03) and Maugis-Dugdale
  (3.2) as the runs with those laws named, bit for bit;
- superquadrics (inputs/superquadric_pulloff with adhesionLaw maugis: an
  ellipsoid tip off a wall, two tips off each other, the second turned by
  30 degrees): the law of the sphere of elliptic Hertz's force radius
  R_force = Rc gamma^2 (review Eqs. 5, 11, 13, evaluated here) of the tips'
  relative radii (review Eqs. 3-4), the same checks of force and separation;
- 2 MPI ranks equal 1 rank (spheres and superquadrics).
Usage: check_maugis_contact.py WORKDIR"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from regress import MaugisDugdale, compare_tables, elliptic_hertz, relative_radii, run, start, table

work, _, c = start()
E, nu, w, r, rho = 5e6, 0.3, 0.5, 1e-3, 2500.0
Estar = E / (2.0 * (1 - nu ** 2))
mstar = rho * 4 / 3 * math.pi * r ** 3 / 2
# the Python model itself against the mpmath solution (tests/reference/maugis.csv): the pull-off force
K = 4.0 / 3.0 * Estar
for row in open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "reference", "maugis.csv")):
    v = row.strip().split(",")
    if v[0] == "pulloff" and v[1] in ("0.5", "1", "2"):
        lam = float(v[1])
        z0 = 32 * w / (9 * math.sqrt(3) * lam) * (r / (math.pi * w * K * K)) ** (1 / 3)
        m = MaugisDugdale(Estar, w, r, z0)
        c.rel(m.pulloff() / m.sF, float(v[2]), 1e-10, "the Python model's pull-off at lambda %s against mpmath" % v[1])
cases = {}
for z0 in (1e-5, 1e-6):
    pair = MaugisDugdale(Estar, w, r / 2, z0)
    vs = math.sqrt(2 * pair.loss() / mstar)
    cases[z0] = vs
    print("     z0 %g: lambda %.4g (pair), %.4g (wall); sticking speed v_s = %.6g m/s" % (z0, pair.lam, MaugisDugdale(Estar, w, r, z0).lam, vs))

runs = {}


def go(name, ranks=1, **v):
    d = os.path.join(work, name)
    run("maugis_contact/in.maugis_contact", d, ranks=ranks, variables=v, tag=name)
    runs[name] = table(os.path.join(d, "cycle.txt"))
    return runs[name]


go("zone", z0=1e-5)
go("zone_np2", ranks=2, z0=1e-5)
go("fold", z0=1e-6, v=1.25 * cases[1e-6])
go("fold_stick", z0=1e-6, v=0.8 * cases[1e-6])
go("tabor_md", alaw="tabor", z0=1e-6, v=1.25 * cases[1e-6])
for name, ranks in (("sq", 1), ("sq_np2", 2)):
    d = os.path.join(work, name)
    run("superquadric_pulloff/in.superquadric_pulloff", d, ranks=ranks, tag=name,
        variables={"alaw": "maugis", "w": w, "omega": 30.0, "z0": 1e-6, "steps": 6000})
    runs[name] = table(os.path.join(d, "pulloff.txt"))
for law in ("jkr", "dmt"):
    z0 = 1e-7 if law == "jkr" else 1e-4
    go("tabor_" + law, alaw="tabor", z0=z0)
    go(law, alaw=law, z0=z0)

# the prescribed cycles against the independent solution
a1, b1, c1 = 0.001, 0.0006, 0.0015     # superquadric_pulloff's ellipsoids: atom 1, c axis down
a2, b2, c2 = 0.0015, 0.0006, 0.001     # atoms 2 and 3, a axis along x, atom 3 turned by 30 degrees
Rp = relative_radii(a2 / b2 ** 2, a2 / c2 ** 2, a2 / b2 ** 2, a2 / c2 ** 2, math.radians(30.0))
for name, z0 in (("zone", 1e-5), ("fold", 1e-6), ("sq", 1e-6)):
    rows = runs[name]
    if name == "sq":
        R_force = lambda R1, R2: elliptic_hertz(R1, R2)[0] * elliptic_hertz(R1, R2)[1] ** 2
        cases_here = (("ellipsoid-wall", R_force(a1 * a1 / c1, b1 * b1 / c1), lambda q: c1 - q[1], lambda q: q[2]),
                      ("ellipsoid-ellipsoid", R_force(*Rp), lambda q: 2 * a2 - (q[4] - q[3]), lambda q: -q[5]))
    else:
        cases_here = (("sphere-wall", r, lambda q: r - q[1], lambda q: q[2]),
                      ("sphere-sphere", r / 2, lambda q: 2 * r - (q[4] - q[3]), lambda q: -q[5]))
    for what, R, overlap, force in cases_here:
        md = MaugisDugdale(Estar, w, R, z0)
        Ds = [overlap(q) / md.sd for q in rows]
        on = [i for i in range(1, len(rows)) if (force(rows[i]) == 0.0) != (force(rows[i - 1]) == 0.0)]
        near = set(j for i in on for j in range(i - 3, i + 3))
        keep = lambda i: i % 3 == 0 or i in near   # every third row, and every row where the force starts or ends
        ts = md.path(Ds, keep)
        Fc = 1.5 * md.sF
        worst, n_contact, n_zone = 0.0, 0, 0
        for i, (q, D, t) in enumerate(zip(rows, Ds, ts)):
            if not keep(i):
                continue
            want = 0.0 if t is None else md.at(t)[0] * md.sF
            worst = max(worst, abs(force(q) - want) / Fc)
            if t is not None:
                n_contact += t > md.c0
                n_zone += t <= md.c0
        c.true(worst < 1e-9, "%s %s (lambda %.3g): force along the cycle against the model, worst %.3g of 3/2 pi w R "
               "(tol 1e-9; %d rows in contact, %d with the zone alone)" % (name, what, md.lam, worst, n_contact, n_zone))
        # where the attraction starts and ends: the approach at -h0 = -2/(pi lambda) sd, the last attached state
        att = [i for i, q in enumerate(rows) if force(q) != 0.0]
        step = 2e-9 / md.sd
        D_first, D_last = Ds[att[0]], Ds[att[-1]]
        D_in = -2 / (math.pi * md.lam)
        if name != "sq":   # the superquadrics start pressed together
            c.true(D_in <= D_first < D_in + step * 1.01 and Ds[att[0] - 1] < D_in,
                   "%s %s: the zone reaches across at the approach overlap -h0 = %.6g m (first force at %.6g m)"
                   % (name, what, D_in * md.sd, D_first * md.sd))
        k = min(range(len(md.t) - 1), key=lambda j: md.D[j])
        t_sep, D_sep = md.fold(k)
        c.true(D_sep <= D_last < D_sep + step * 1.01 and Ds[att[-1] + 1] < D_sep,
               "%s %s: kept to the model's separation overlap %.6g m (%s; last force at %.6g m)"
               % (name, what, D_sep * md.sd, "the zone's fold" if t_sep <= md.c0 else "the contact's fold",
                  D_last * md.sd))

    if name != "fold":
        continue
    # the collision: rebound at 1.25 v_s
    vs = cases[z0]
    last = rows[-1]
    c.rel(last[9] - last[8], math.sqrt((1.25 * vs) ** 2 - vs ** 2), 2e-4,
          "%s: rebound speed at 1.25 v_s vs (v^2 - v_s^2)^1/2 (the loop's loss)" % name)

stick = runs["fold_stick"][-1]
md = MaugisDugdale(Estar, w, r / 2, 1e-6)
gap = stick[7] - stick[6] - 2 * r
c.true(stick[10] != 0.0 and gap < md.sd, "at 0.8 v_s the spheres stick: gap %.3g m, force %.3g N" % (gap, stick[10]))
compare_tables(c, runs["zone_np2"], runs["zone"], 1e-13, "spheres: 2 ranks equal 1 rank")
compare_tables(c, runs["sq_np2"], runs["sq"], 1e-13, "superquadrics: 2 ranks equal 1 rank")
compare_tables(c, runs["tabor_md"], runs["fold"], 0.0, "tabor at Tabor 3.2 and 2.5: Maugis-Dugdale")
compare_tables(c, runs["tabor_jkr"], runs["jkr"], 0.0, "tabor at Tabor 32 and 25: JKR")
compare_tables(c, runs["tabor_dmt"], runs["dmt"], 0.0, "tabor at Tabor 0.032 and 0.025: DMT")
c.finish()
