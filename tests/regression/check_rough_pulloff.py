#!/usr/bin/env python3
"""Regression: a rough adhesive sphere pressed onto a wall and pulled off
(inputs/rough_pulloff), gw_rough (GW closed form) with cohesion gw_adhesion:
- the force along the path against the exact c_core law of rough contact
  with adhesive JKR summits (dc/gw_rough_adhesive.h, as `dclaw gw_rough
  --w` evaluates it, outside LIGGGHTS; less the elastic GW tail beyond
  -3 sigma, where gw_rough cuts its elastic force): on approach the loading
  branch within 1e-6, on retraction, once past the partly attached band
  next to the deepest overlap (|delta_break| of one summit, 1.11 um, from
  `dclaw jkr_elliptic --summary 1`), the unloading branch within 5e-5
  (the table's stated accuracy: 3.1e-7 and 2.5e-5), relative to the larger
  of |F| and its adhesive part (where the total crosses zero the adhesive
  part sets the scale), on rows where |F| > 1e-3 of the largest force;
- hysteresis: the pull-off force (the most negative force on retraction)
  exceeds the largest pull on approach, and equals the exact unloading
  branch's minimum within 1e-3;
- workOfAdhesion 0 equals gw_rough without a cohesion model exactly;
- 2 MPI ranks equal 1 rank.
Usage: check_rough_pulloff.py WORKDIR"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from regress import compare_tables, rough_adhesive_exact, run, start, summit_delta_break, table

work, _, c = start()
R, E, nu, sig, w, dmax = 1e-3, 5e6, 0.3, 1e-6, 0.05, 4e-6
Estar = 1.0 / (2 * (1 - nu ** 2) / E)


def exact(d0, d1, n):
    return rough_adhesive_exact((R, R), Estar, sig, w, d0, d1, n)


runs = {}
for name, variables, ranks in (("adhesive", {}, 1), ("adhesive_np2", {}, 2), ("w0", {"w": 0.0}, 1),
                               ("none", {"w": 0.0, "coh": "off"}, 1)):
    d = os.path.join(work, name)
    run("rough_pulloff/in.rough_pulloff", d, ranks=ranks, variables=variables, tag=name)
    runs[name] = table(os.path.join(d, "pull.txt"))

rows = runs["adhesive"]
deltas = [R - r[1] for r in rows]
k_turn = max(range(len(rows)), key=lambda k: deltas[k])
Fmax = max(abs(r[2]) for r in rows)
# sample rows on approach and on retraction; the exact law at their overlaps
approach = [k for k in range(1, k_turn, 7) if abs(rows[k][2]) > 1e-3 * Fmax]
# past the partly attached band: |delta_break| of one summit (dclaw
# jkr_elliptic --summary 1: 1.11 um here)
band = summit_delta_break((R, R), Estar, w)
retract = [k for k in range(k_turn + 1, len(rows), 7) if abs(rows[k][2]) > 1e-3 * Fmax
           and deltas[k] < deltas[k_turn] - band]


def worst(ks, col):
    """relative to the larger of the force and its adhesive part"""
    err = 0.0
    for k in ks:
        (_, Fl, Fu, Fel), = exact(deltas[k], deltas[k], 1)
        want = Fl if col == 1 else Fu
        err = max(err, abs(rows[k][2] - want) / max(abs(want), abs(want - Fel)))
    return err


el, eu = worst(approach, 1), worst(retract, 2)
c.true(len(approach) > 20 and el < 1e-6, "approach (%d rows): force vs the exact loading branch, worst %.3g (tol 1e-6)" % (len(approach), el))
c.true(len(retract) > 20 and eu < 5e-5, "retraction (%d rows): force vs the exact unloading branch, worst %.3g (tol 5e-5)" % (len(retract), eu))
pull_in = min(r[2] for r in rows[:k_turn])
pull_off = min(r[2] for r in rows[k_turn:])
grid = exact(-6 * sig, 0.5e-6, 2001)
pull_exact = min(Fu for _, _, Fu, _ in grid)
c.true(pull_off < pull_in < 0.0, "hysteresis: pull-off %.5g N beyond the largest pull on approach %.5g N" % (pull_off, pull_in))
c.rel(pull_off, pull_exact, 1e-3, "pull-off force vs the exact unloading branch's minimum (grid of 2001)")
compare_tables(c, runs["w0"], runs["none"], 0.0, "workOfAdhesion 0 equals gw_rough without cohesion")
compare_tables(c, runs["adhesive_np2"], rows, 1e-13, "2 ranks equal 1 rank")
c.finish()
