#!/usr/bin/env python3
"""Regression (issue deck a): oblique impacts of alumina spheres on an
alumina plane (Chung & Ooi 2011, test 5; inputs/oblique_impact), incidence
angles 5 to 85 degrees from the normal, elastic, mu = 0.092, with
`tangential cmd_tangential` and stock `tangential history`:
- gross sliding (tan(angle) > 7/2 mu (1 + e)): the rebound velocities equal
  the rigid-body result v_t' = v_t - mu (1 + e) v_n, v_n' = e v_n to 1e-4;
  the spin against 5/(2R) mu (1 + e) v_n to 3e-3 (LIGGGHTS' lever arm is
  R - delta/2, not R);
- below it (micro-slip) the two tangential models differ: printed side by
  side with the rigid-body rolling limit v_t' = 5/7 v_t and the classical
  analysis of Maw, Barber & Fawcett (1976) as computed independently by
  tests/reference/gen_oblique_mbf.py (rings with Cerruti's compliance, error
  ~1e-5): cmd_tangential is within 4e-3 (v_t') and 6e-3 (spin) of it; the
  difference is LIGGGHTS' lever arm R - delta/2 (with that lever the
  generator agrees to 5e-6 at 10-40 degrees, 4e-4 at 5 degrees, where the
  growing stuck contact passes the law's cap on profile pieces); stock
  tangential history is 0.1-0.3 off in v_t' there;
- `cmdMemory turningPoints` (the bounded-memory law): tangential
  restitution v_t'/v_t within 0.01 of the exact profile's at every angle
  (measured at most 0.0054, at 10 degrees: the rising load; equal in gross
  sliding), its own 2 ranks equal 1 rank;
- 2 MPI ranks equal 1 rank; under stock `hertz` (no published patch: the
  reader's circle (R delta)^1/2) the same rebounds as under hertz_elliptic;
  the cmd_tangential rebounds against their committed reference.
Usage: check_oblique_impact.py WORKDIR [--update]"""
import math
import os
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from regress import ROOT, compare_tables, run, start, table

work, update, c = start()
mu, e, v, R = 0.092, 1.0, 3.9, 0.0025
runs = {}
tp = "tangential_damping off cmdMemory turningPoints"
for name, model, tmodel, ranks, opts in (("cmd", "hertz_elliptic", "cmd_tangential", 1, None),
                                         ("cmd_np2", "hertz_elliptic", "cmd_tangential", 2, None),
                                         ("cmd_stock", "hertz", "cmd_tangential", 1, None),
                                         ("history", "hertz_elliptic", "history", 1, None),
                                         ("tp", "hertz_elliptic", "cmd_tangential", 1, tp),
                                         ("tp_np2", "hertz_elliptic", "cmd_tangential", 2, tp)):
    d = os.path.join(work, name)
    variables = {"model": model, "tmodel": tmodel}
    if opts:
        variables["opts"] = opts
    run("oblique_impact/in.oblique_impact", d, ranks=ranks, variables=variables, tag=name)
    runs[name] = table(os.path.join(d, "rebound.txt"))

mbf = {}
with open(os.path.join(ROOT, "tests", "reference", "oblique_mbf.csv")) as f:
    for line in f:
        if line.strip() and not line.startswith("#"):
            v_ = [float(x) for x in line.split(",")]
            mbf[v_[0]] = v_
print("     angle   v_t' cmd_tangential   v_t' history    v_t' MBF      rigid body        spin cmd   spin MBF")
for rc, rh in zip(runs["cmd"], runs["history"]):
    ang = rc[1]
    vn, vt = v * math.cos(math.radians(ang)), v * math.sin(math.radians(ang))
    sliding = vt / vn > 3.5 * mu * (1 + e)
    vt_rigid = vt - mu * (1 + e) * vn if sliding else 5.0 / 7.0 * vt
    w_rigid = 2.5 / R * mu * (1 + e) * vn if sliding else 5.0 / 7.0 * vt / R
    m_ = mbf[ang]
    print("     %5.1f   %14.9f   %14.9f   %12.9f   %14.9f   %10.3f   %10.3f" % (ang, rc[2], rh[2], m_[1], vt_rigid, rc[4], m_[3]))
    if not sliding or vt / vn < 1.1 * 3.5 * mu * (1 + e):
        c.rel(rc[2], m_[1], 4e-3, "%g deg (micro-slip): tangential rebound vs Maw-Barber-Fawcett" % ang)
        # 5 degrees: the contact grows fully stuck, a new profile piece each
        # step, and the law's 8-piece cap merges them: 4e-4 more than the lever arm
        c.rel(rc[4], m_[3], 7e-3 if ang == 5.0 else 6e-3, "%g deg (micro-slip): spin vs Maw-Barber-Fawcett" % ang)
    c.rel(rc[3], e * vn, 1e-6, "%g deg: normal rebound velocity" % ang)
    if sliding and vt / vn > 1.1 * 3.5 * mu * (1 + e):
        c.rel(rc[2], vt_rigid, 1e-4, "%g deg (gross sliding): tangential rebound vs rigid body" % ang)
        c.rel(rc[4], w_rigid, 3e-3, "%g deg (gross sliding): spin vs rigid body" % ang)
compare_tables(c, runs["cmd_np2"], runs["cmd"], 1e-13, "2 ranks equal 1 rank")
print("     angle   v_t'/v_t profile   v_t'/v_t turningPoints   difference")
for rc, rt in zip(runs["cmd"], runs["tp"]):
    vt = v * math.sin(math.radians(rc[1]))
    print("     %5.1f   %16.9f   %22.9f   %10.2e" % (rc[1], rc[2] / vt, rt[2] / vt, (rt[2] - rc[2]) / vt))
    c.abs_(rt[2] / vt, rc[2] / vt, 0.01, "%g deg: turningPoints' tangential restitution vs the exact profile's" % rc[1])
    c.rel(rt[3], rc[3], 1e-9, "%g deg: turningPoints' normal rebound" % rc[1])
compare_tables(c, runs["tp_np2"], runs["tp"], 1e-13, "turningPoints: 2 ranks equal 1 rank")
# under stock hertz cmd_tangential reads no published patch but the circle
# (R delta)^1/2 with friction load kn delta: the same contact as hertz_elliptic's
compare_tables(c, runs["cmd_stock"], runs["cmd"], 1e-12, "cmd_tangential under stock hertz (circular patch) equals it under hertz_elliptic")
ref = os.path.join(ROOT, "inputs", "oblique_impact", "reference", "rebound_cmd.txt")
if update:
    os.makedirs(os.path.dirname(ref), exist_ok=True)
    shutil.copy(os.path.join(work, "cmd", "rebound.txt"), ref)
compare_tables(c, runs["cmd"], table(ref), 1e-9, "vs reference")
c.finish()
