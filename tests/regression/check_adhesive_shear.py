#!/usr/bin/env python3
"""Regression (issue deck e): an adhesive sphere pair (jkr_elliptic) held in
tension (overlap -0.4 um, the neck formed) and sheared (inputs/adhesive_shear):
- with `tangential cmd_tangential` friction acts while the contact is
  formed: the tangential force (the force on atom 1 less its component
  along the centre line) grows and slides at mu (F + 3 pi w R*), F the
  classical JKR force at the held overlap (evaluated here by bisection);
- the normal force stays the JKR force;
- stock `tangential history` gives no friction in tension (its contact
  ends when the surfaces part);
- superquadrics (in.adhesive_shear_superquadric, two ellipsoid tips): the
  friction acts in tension too and slides at mu (F + 2 F_pulloff) of the
  elliptic JKR contact (F and F_pulloff from dclaw, i.e. c_core's law: this
  checks the plumbing) within 2%: the force is split along the centre line,
  while the contact normal of the offset tips tilts by about dy/(R_i + R_j)
  and moves up to 1.2% of the normal force into the measured friction;
- Maugis-Dugdale (adhesionLaw maugis, z0 = 1 um: lambda 0.63): the
  normal force in tension is the model's at the held overlap and friction
  slides at mu (F + 2 |F_c|), F_c its pull-off force under load control
  (both from regress.MaugisDugdale, independent of c_core);
- the cmd_tangential run against its committed reference.
Usage: check_adhesive_shear.py WORKDIR [--update]"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from regress import ROOT, MaugisDugdale, compare_tables, dclaw, jkr_sphere, run, save_reference, start, subsample, table

work, update, c = start()
E, nu, mu, w, R, d1 = 5e6, 0.3, 0.5, 0.05, 0.5e-3, -4e-7
Estar = 1.0 / (2 * (1 - nu ** 2) / E)
a1, F1 = jkr_sphere(R, Estar, w, d1)
F_slide = mu * (F1 + 3 * math.pi * w * R)
EVERY = 20


def split(r):
    """(normal force on 1 along 2 -> 1 as repulsion, tangential magnitude)."""
    dist = math.hypot(r[1], r[2])
    ex, ey = -r[1] / dist, -r[2] / dist          # unit vector from 2 to 1
    fn = r[3] * ex + r[4] * ey
    return fn, math.hypot(r[3] - fn * ex, r[4] - fn * ey)


runs = {}
for tmodel in ("cmd_tangential", "history"):
    d = os.path.join(work, tmodel)
    run("adhesive_shear/in.adhesive_shear", d, variables={"tmodel": tmodel}, tag=tmodel)
    runs[tmodel] = [r for r in table(os.path.join(d, "shear.txt")) if r[2] > 0]
rows = runs["cmd_tangential"]
fn0, ft0 = split(rows[0])
c.rel(fn0, F1, 1e-6, "normal force in tension = classical JKR at the held overlap")
c.true(F1 < 0, "the neck is in tension (F = %.6g N)" % F1)
# the overlap drifts with the shear (r grows as the offset does): the
# sliding force at each row's own overlap
worst = 0.0
for r in rows[len(rows) // 2:]:
    fn, ft = split(r)
    F = jkr_sphere(R, Estar, w, 0.002 - math.hypot(r[1], r[2]))[1]
    worst = max(worst, abs(ft / (mu * (F + 3 * math.pi * w * R)) - 1))
c.true(worst < 1e-6, "sliding in tension at mu (F + 3 pi w R*) (%.6g N at the held overlap): worst %.3g (tol 1e-6)"
       % (F_slide, worst))
c.true(max(split(r)[1] for r in runs["history"]) < 1e-3 * F_slide,
       "stock tangential history: no friction in tension (max %.3g N)" % max(split(r)[1] for r in runs["history"]))
# Maugis-Dugdale: the force at each row's overlap on the contact branch (the path pressed to 1.5 um and back)
d = os.path.join(work, "maugis")
run("adhesive_shear/in.adhesive_shear", d, variables={"alaw": "maugis", "z0": 1e-6}, tag="maugis")
md = MaugisDugdale(Estar, w, R, 1e-6)
md_rows = [r for r in table(os.path.join(d, "shear.txt")) if r[2] > 0]
F_c = md.pulloff()
worst_n = worst_t = 0.0
for r in md_rows[len(md_rows) // 2:]:
    fn, ft = split(r)
    D = (0.002 - math.hypot(r[1], r[2])) / md.sd
    t = md.path([1.5e-6 / md.sd, D])[1]   # from the pressed state back to the row's overlap
    F = md.at(t)[0] * md.sF
    worst_n = max(worst_n, abs(fn - F) / abs(F_c))
    worst_t = max(worst_t, abs(ft / (mu * (F - 2 * F_c)) - 1))
c.true(t > md.c0 and F < 0, "maugis (lambda %.3g): held in contact, in tension (F = %.6g N)" % (md.lam, F))
c.true(worst_n < 1e-9, "maugis: normal force against the model at the held overlap: worst %.3g of F_c (tol 1e-9)" % worst_n)
c.true(worst_t < 1e-6, "maugis: sliding at mu (F + 2 |F_c|), F_c = %.6g N: worst %.3g (tol 1e-6)" % (F_c, worst_t))
# superquadrics: relative radii of the two tips (each b^2/a = 0.24 mm across,
# c^2/a = 0.667 mm along z; halved for the pair)
for tmodel in ("cmd_tangential", "history"):
    d = os.path.join(work, "sq_" + tmodel)
    run("adhesive_shear/in.adhesive_shear_superquadric", d, variables={"tmodel": tmodel}, tag=tmodel)
    runs["sq_" + tmodel] = [r for r in table(os.path.join(d, "shear.txt")) if r[2] > 0]
law = {"R1": 0.5 * 1e-3 ** 2 / 1.5e-3, "R2": 0.5 * 0.6e-3 ** 2 / 1.5e-3, "Estar": Estar, "w": w}
head, rows = dclaw("jkr_elliptic", summary=1, **law)
F_pull = rows[0][head.index("pulloff_force")]
head, rows = dclaw("jkr_elliptic", delta_min=-2e-7, delta_max=-2e-7, n=1, **law)
F_sq = rows[0][head.index("force")]
slide = [split(r)[1] for r in runs["sq_cmd_tangential"][len(runs["sq_cmd_tangential"]) // 2:]]
want = mu * (F_sq + 2 * F_pull)
c.true(F_sq < 0 and all(abs(x / want - 1) < 2e-2 for x in slide),
       "superquadrics in tension (F = %.4g N): friction slides at mu (F + 2 F_pulloff) = %.4g N (measured %.4g .. %.4g)"
       % (F_sq, want, min(slide), max(slide)))
c.true(max(split(r)[1] for r in runs["sq_history"]) < 2e-2 * want,
       "superquadrics, stock tangential history: no friction in tension (%.3g N, the normal force's tilt)"
       % max(split(r)[1] for r in runs["sq_history"]))
ref = os.path.join(ROOT, "inputs", "adhesive_shear", "reference", "shear.txt")
if update:
    save_reference(os.path.join(work, "cmd_tangential", "shear.txt"), ref, EVERY)
full = table(os.path.join(work, "cmd_tangential", "shear.txt"))
compare_tables(c, subsample(full, EVERY), table(ref), 1e-9, "vs reference")
c.finish()
