#!/usr/bin/env python3
"""Regression (issue deck f): a cmd_tangential loop between two spheres
(inputs/tangential_restart) stopped in the middle of an unloading branch
(write_restart at step 13700, after the first reversal) and continued with
read_restart reproduces the uninterrupted run to every printed digit: the
load history (turning points, slip profile) travels in LIGGGHTS' contact
history through the restart file. The same for two rough spheres (gw_rough
gwElliptic on, sigma 1e-6 per sphere, with tangentialRoughness on: the
summits' patch), which also run on 2 MPI ranks, one sphere on each, equal
to 1 rank digit for digit; and for two adhesive spheres (jkr_elliptic with
adhesionLaw maugis, lambda 1.85: the Maugis-Dugdale state and its pull-off
force, which sets the friction load, travel in the contact history too),
and for the bounded-memory law (cmdMemory turningPoints: the force, its
branch and its turning points), whose loop (at a normal force that changes
by 4.5e-5 as the sphere wiggles) is within 5e-5 of the exact profile's.
Usage: check_tangential_restart.py WORKDIR"""
import os
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from regress import ROOT, run, start

work, _, c = start()
D = os.path.join(ROOT, "inputs", "tangential_restart")
STOP = 13700


def rows(path):
    return [l.split() for l in open(path) if not l.startswith("#")]


run("tangential_restart/in.tangential_restart", os.path.join(work, "full"), variables={"dir": D}, tag="full")
run("tangential_restart/in.tangential_restart", os.path.join(work, "half"),
    variables={"dir": D, "steps": STOP, "restart": 1}, tag="half")
os.makedirs(os.path.join(work, "resumed"), exist_ok=True)
shutil.copy(os.path.join(work, "half", "loop.restart"), os.path.join(work, "resumed"))
run("tangential_restart/in.tangential_restart_resume", os.path.join(work, "resumed"),
    variables={"dir": D, "steps": 30000 - STOP}, tag="resumed")
full, half, res = (rows(os.path.join(work, k, "loop.txt")) for k in ("full", "half", "resumed"))
k0 = STOP // 10
# the stop lies on an unloading branch: the force has passed its maximum and is falling
fs = [float(r[2]) for r in full[:k0]]
c.true(max(fs) > fs[-1] > min(fs[k0 // 2:]) and fs[-1] < fs[-2],
       "restart written on an unloading branch (force %.4g N, turning point %.4g N)" % (fs[-1], max(fs)))
c.true(half == full[:k0], "the first part equals the uninterrupted run (%d rows)" % len(half))
same = len(res) == len(full) - k0 and all(a[1:] == b[1:] for a, b in zip(res, full[k0:]))
c.true(same, "continued from the restart file: %d rows equal the uninterrupted run's digit for digit" % len(res))

def restarted(prefix, variables):
    """The deck with `variables` run whole on 1 and on 2 ranks, and stopped
    at STOP then resumed from its restart file: the rows of (whole, 2 ranks,
    first part, resumed part)."""
    out = {}
    for tag, ranks, extra in (("full", 1, {}), ("np2", 2, {}), ("half", 1, {"steps": STOP, "restart": 1})):
        v = dict(variables, **extra)
        run("tangential_restart/in.tangential_restart", os.path.join(work, prefix + tag), ranks=ranks, variables=v,
            tag=prefix + tag)
        out[tag] = rows(os.path.join(work, prefix + tag, "loop.txt"))
    d = os.path.join(work, prefix + "resumed")
    os.makedirs(d, exist_ok=True)
    shutil.copy(os.path.join(work, prefix + "half", "loop.restart"), d)
    v = {k: x for k, x in variables.items() if k != "x1"}
    v["steps"] = 30000 - STOP
    run("tangential_restart/in.tangential_restart_resume", d, variables=v, tag=prefix + "resumed")
    return out["full"], out["np2"], out["half"], rows(os.path.join(d, "loop.txt"))


def same_runs(what, whole, np2, half, resumed):
    c.true(half == whole[:k0], "%s: the first part equals the uninterrupted run" % what)
    c.true(len(resumed) == len(whole) - k0 and all(a[1:] == b[1:] for a, b in zip(resumed, whole[k0:])),
           "%s, continued from the restart file: %d rows equal the uninterrupted run's digit for digit"
           % (what, len(resumed)))
    c.true(np2 == whole, "%s on 2 ranks (one sphere each): %d rows equal 1 rank digit for digit" % (what, len(whole)))


# rough spheres, tangentialRoughness on: restart and 2 ranks
rough = restarted("rough_", {"dir": D, "nmodel": "gw_rough", "nset": "gwElliptic on tangentialRoughness on",
                             "sigma": 1e-6, "cdf": 1.01, "x1": -0.001})
rf = [float(r[2]) for r in rough[0]]
c.true(max(abs(a - b) for a, b in zip(rf, fs + [float(r[2]) for r in full[k0:]])) > 1e-3 * max(rf),
       "rough spheres: the summits' law differs from the smooth one (force amplitude %.4g N against %.4g N)"
       % (max(rf), max(float(r[2]) for r in full)))
same_runs("rough spheres", *rough)

# Maugis-Dugdale (jkr_elliptic adhesionLaw maugis): restart and 2 ranks
md = restarted("md_", {"dir": D, "nmodel": "jkr_elliptic", "nset": "adhesionLaw maugis", "cdf": 1.01, "x1": -0.001})
mf = [float(r[2]) for r in md[0]]
c.true(max(mf) > 1.001 * max(float(r[2]) for r in full),
       "adhesive spheres: the law acts (the adhesive contact is larger: force amplitude %.4g N against %.4g N)"
       % (max(mf), max(float(r[2]) for r in full)))
same_runs("adhesive spheres", *md)

# the bounded-memory law (cmdMemory turningPoints): restart and 2 ranks; its
# loops are the exact profile's but for the normal force's change as the
# sphere wiggles (the overlap changes by dy^2 / 2 d: 3e-5 of it, 4.5e-5 of
# the force; measured 1.1e-5 of the amplitude)
tp = restarted("tp_", {"dir": D, "nset": "cmdMemory turningPoints", "x1": -0.001})
whole = fs + [float(r[2]) for r in full[k0:]]
dev = max(abs(float(r[2]) - f) for r, f in zip(tp[0], whole)) / max(abs(f) for f in whole)
c.true(len(tp[0]) == len(whole) and dev <= 5e-5,
       "turningPoints: the loop equals the exact profile's (max difference %.2g of the amplitude)" % dev)
same_runs("turningPoints", *tp)
c.finish()
