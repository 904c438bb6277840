#!/usr/bin/env python3
"""Regression: rough adhesive superquadrics pressed together and pulled
apart (inputs/rough_superquadric_pulloff), gw_rough (GW closed form) with
cohesion gw_adhesion, elliptic summits: an ellipsoid tip on a wall
(relative radii a^2/c, b^2/c: ratio 0.36) and two ellipsoid tips, one
turned by 30 degrees (radii from both tips' curvatures, review Eqs. 3-4:
ratio 0.29); the overlaps from the prescribed positions.
- the force along each path against the exact c_core law of rough contact
  with elliptic adhesive JKR summits (dc/gw_rough_adhesive.h with
  dc_jkr_geometry summits, as `dclaw gw_rough --R1 --R2 --w` evaluates it,
  outside LIGGGHTS; less the elastic GW tail beyond -3 sigma, which
  gw_rough cuts): on approach the loading branch, on retraction past the
  partly attached band (|delta_break| of one summit, from `dclaw
  jkr_elliptic --summary 1`) the unloading branch, relative to the larger of |F|
  and its adhesive part (where the total crosses zero the adhesive part
  sets the scale; the table for elliptic summits: 1e-4 at these ratios,
  c_core/include/dc/gw_rough_adhesive_table.h; the run adds the gap and
  curvature the plugin measures);
- hysteresis: the pull-off force exceeds the largest pull on approach and
  equals the exact unloading branch's minimum within 1e-3;
- workOfAdhesion 0 equals gw_rough without a cohesion model exactly;
- a mesh plane instead of the primitive wall: no force apart (LIGGGHTS
  measures no gap to a mesh for superquadrics), the primitive wall's while
  the tip overlaps, and a warning;
- 2 MPI ranks equal 1 rank.
Usage: check_rough_superquadric_pulloff.py WORKDIR"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from regress import (ROOT, compare_tables, relative_radii, rough_adhesive_exact, run, start, summit_delta_break,
                     table)

work, _, c = start()
E, nu, w, dmax = 5e6, 0.3, 0.05, 4e-6
sig = math.sqrt(2.0) * 1e-6                       # two rough surfaces
Estar = 1.0 / (2 * (1 - nu ** 2) / E)
a1, b1, c1 = 0.001, 0.0006, 0.0015                # atom 1, c axis down
a2, b2, c2 = 0.0015, 0.0006, 0.001                # atoms 2 and 3, a axis along x
WALL = (a1 * a1 / c1, b1 * b1 / c1)
PAIR = relative_radii(a2 / b2 ** 2, a2 / c2 ** 2, a2 / b2 ** 2, a2 / c2 ** 2, math.radians(30.0))


def exact(radii, d0, d1, n):
    return rough_adhesive_exact(radii, Estar, sig, w, d0, d1, n)


runs = {}
logs = {}
D = os.path.join(ROOT, "inputs", "rough_superquadric_pulloff")
for name, variables, ranks in (("adhesive", {}, 1), ("adhesive_np2", {}, 2), ("w0", {"w": 0.0}, 1),
                               ("none", {"w": 0.0, "coh": "off"}, 1), ("mesh", {"mesh": 1, "dir": D}, 1)):
    d = os.path.join(work, name)
    logs[name] = run("rough_superquadric_pulloff/in.rough_superquadric_pulloff", d, ranks=ranks, variables=variables,
                     tag=name)
    runs[name] = table(os.path.join(d, "pull.txt"))

rows = runs["adhesive"]
for what, radii, delta_of, force_of in (("wall", WALL, lambda r: c1 - r[1], lambda r: r[2]),
                                        ("pair", PAIR, lambda r: 2 * a2 - (r[4] - r[3]), lambda r: -r[5])):
    deltas = [delta_of(r) for r in rows]
    forces = [force_of(r) for r in rows]
    k_turn = max(range(len(rows)), key=lambda k: deltas[k])
    Fmax = max(abs(f) for f in forces)
    # retraction rows past the partly attached band: |delta_break| of one
    # elliptic summit (dclaw jkr_elliptic --summary 1: 0.80 um on the wall)
    band = summit_delta_break(radii, Estar, w)
    approach = [k for k in range(1, k_turn, 7) if abs(forces[k]) > 1e-3 * Fmax]
    retract = [k for k in range(k_turn + 1, len(rows), 7) if abs(forces[k]) > 1e-3 * Fmax
               and deltas[k] < deltas[k_turn] - band]

    def worst(ks, col):
        """relative to the larger of the force and its adhesive part"""
        err = 0.0
        for k in ks:
            (_, Fl, Fu, Fel), = exact(radii, deltas[k], deltas[k], 1)
            want = Fl if col == 1 else Fu
            err = max(err, abs(forces[k] - want) / max(abs(want), abs(want - Fel)))
        return err

    el, eu = worst(approach, 1), worst(retract, 2)
    c.true(len(approach) > 20 and el < 1e-4, "%s (radii %.4g, %.4g mm), approach (%d rows): force vs the exact loading "
           "branch, worst %.3g (tol 1e-4)" % (what, radii[0] * 1e3, radii[1] * 1e3, len(approach), el))
    c.true(len(retract) > 20 and eu < 1e-4, "%s, retraction (%d rows): force vs the exact unloading branch, worst %.3g "
           "(tol 1e-4)" % (what, len(retract), eu))
    pull_in = min(forces[:k_turn])
    pull_off = min(forces[k_turn:])
    grid = exact(radii, -6 * sig, 0.5e-6, 2001)
    pull_exact = min(Fu for _, _, Fu, _ in grid)
    c.true(pull_off < pull_in < 0.0, "%s: hysteresis: pull-off %.5g N beyond the largest pull on approach %.5g N"
           % (what, pull_off, pull_in))
    c.rel(pull_off, pull_exact, 1e-3, "%s: pull-off force vs the exact unloading branch's minimum (grid of 2001)" % what)
compare_tables(c, runs["w0"], runs["none"], 0.0, "workOfAdhesion 0 equals gw_rough without cohesion")
# a mesh plane: LIGGGHTS measures no gap to a mesh for superquadrics, so the
# wall force acts only while the tip overlaps it (there it is the primitive
# wall's), and the run says so once
mesh = runs["mesh"]
apart = [k for k in range(len(rows)) if c1 - rows[k][1] < -1e-9]
touch = [k for k in range(len(rows)) if c1 - rows[k][1] > 1e-9]
c.true(len(mesh) == len(rows) and all(mesh[k][2] == 0.0 for k in apart) and len(touch) > 20 and
       max(abs(mesh[k][2] - rows[k][2]) for k in touch) <= 1e-9 * max(abs(rows[k][2]) for k in touch),
       "mesh wall: no force while the tip is apart (%d rows), the primitive wall's force while it overlaps (%d rows)"
       % (len(apart), len(touch)))
c.true(logs["mesh"].count("superquadrics on a mesh wall") == 1, "mesh wall: the run warns once that the pull "
       "acts only while the surfaces touch")
compare_tables(c, runs["adhesive_np2"], rows, 1e-13, "2 ranks equal 1 rank")
c.finish()
