#!/usr/bin/env python3
"""Regression (jamari_ep): elastic-plastic impacts on a wall, no damping.
- Spheres at nine speeds (inputs/jamari_impact/in.jamari_impact): the
  coefficient of restitution and the maximum overlap against the energy
  balance of the law evaluated independently (tests/reference/
  gen_jamari_impact.py, mpmath): e = 1 below the yield velocity, falling
  above it; in the fully plastic range e ~ v^-1/4 (the slope between 10 and
  30 m/s); stock thornton_ning on the same spheres printed beside it. The
  restitution converges with the time step (1e-9 s against 2e-9 s: the
  error falls, and is below 1e-5 at 1e-9 s, about 3000 steps per impact at
  30 m/s).
- The same on 2 MPI ranks: the same numbers to every printed digit.
- Ellipsoids (in.jamari_impact_ellipsoid): restitution and maximum overlap
  against the same independent evaluation with the tip's radii.
- A restart in the middle of the impacts continues exactly.
Usage: check_jamari_impact.py WORKDIR"""
import math
import os
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from regress import ROOT, run, start, table

work, _, c = start()
D = os.path.join(ROOT, "inputs", "jamari_impact")
ref = {}
onset = {}
for line in open(os.path.join(ROOT, "tests", "reference", "jamari_impact.csv")):
    f = line.strip().split(",")
    if f[0] == "onset":
        onset[f[1]] = [float(x) for x in f[2:]]
    elif f[0] in ("sphere", "ellipsoid"):
        ref.setdefault(f[0], []).append([float(x) for x in f[1:]])


def outcome(rows, k, tip):
    """(e, maximum overlap) of atom k (1-based) from the printed z, vz."""
    z = [r[2 * k - 1] for r in rows]
    v0, v1 = rows[0][2 * k], rows[-1][2 * k]
    return v1 / -v0, tip - min(z)


runs = {}
for model in ("jamari_ep", "thornton_ning"):
    d = os.path.join(work, model)
    run("jamari_impact/in.jamari_impact", d, variables={"model": model, "dir": D}, tag=model)
    runs[model] = table(os.path.join(d, "impact.txt"))
dh = os.path.join(work, "jamari_ep_dt2")
run("jamari_impact/in.jamari_impact", dh, variables={"model": "jamari_ep", "dir": D, "dt": "2e-9", "steps": 15000}, tag="dt2")
runs["dt2"] = table(os.path.join(dh, "impact.txt"))
d2 = os.path.join(work, "jamari_ep_2ranks")
run("jamari_impact/in.jamari_impact", d2, ranks=2, variables={"model": "jamari_ep", "dir": D}, tag="np2")
two = open(os.path.join(d2, "impact.txt")).read()
c.true(two == open(os.path.join(work, "jamari_ep", "impact.txt")).read(),
       "2 ranks: the impact table equals the 1-rank run's digit for digit")

d1, d2_, vy = onset["sphere"]
print("     yield velocity %.4g m/s (delta_n1 %.4g m, delta_n2 %.4g m)" % (vy, d1, d2_))
print("     v [m/s]   e jamari_ep   e reference   e thornton_ning   error at dt 2e-9 / at 1e-9")
e_sim = {}
for k, (v, dmax, dres, e) in enumerate(ref["sphere"], start=1):
    es, ds = outcome(runs["jamari_ep"], k, 0.001)
    et, _ = outcome(runs["thornton_ning"], k, 0.001)
    eh, _ = outcome(runs["dt2"], k, 0.001)
    e_sim[v] = es
    print("     %7.3f   %.9f   %.9f   %.6f          %.3g" % (v, es, e, et, abs(eh - e) / max(abs(es - e), 1e-300)))
    if v < vy:
        c.true(abs(es - 1.0) <= 1e-6, "sphere %g m/s below the yield velocity: e = %.9f (1 within 1e-6)" % (v, es))
    else:
        c.rel(es, e, 1e-5, "sphere %g m/s: restitution vs the law's energy balance" % v)
        c.true(abs(es - e) < abs(eh - e), "sphere %g m/s: the error falls with the time step (%.3g at 2e-9 s, %.3g at 1e-9 s)"
               % (v, abs(eh - e) / e, abs(es - e) / e))
    c.rel(ds, dmax, 1e-4, "sphere %g m/s: maximum overlap (printed every 10 steps)" % v)
c.true(all(e_sim[a] > e_sim[b] for a, b in zip(sorted(e_sim)[1:], sorted(e_sim)[2:]) if a > vy),
       "restitution falls with the speed above the yield velocity")
slope = math.log(e_sim[30.0] / e_sim[10.0]) / math.log(3.0)
c.true(abs(slope + 0.25) <= 0.02, "fully plastic range: d ln e / d ln v = %.4f (-1/4 within 0.02)" % slope)

de = os.path.join(work, "ellipsoid")
run("jamari_impact/in.jamari_impact_ellipsoid", de, tag="ell")
rows = table(os.path.join(de, "impact.txt"))
for k, (v, dmax, dres, e) in enumerate(ref["ellipsoid"], start=1):
    es, ds = outcome(rows, k, 0.0015)
    c.rel(es, e, 1e-6, "ellipsoid %g m/s (tip radii a^2/c, b^2/c): restitution vs the law's energy balance" % v)
    c.rel(ds, dmax, 1e-4, "ellipsoid %g m/s: maximum overlap" % v)

# restart in the middle: at step 4000 the three fastest spheres are in contact
STOP = 4000
run("jamari_impact/in.jamari_impact", os.path.join(work, "half"),
    variables={"model": "jamari_ep", "dir": D, "steps": STOP, "restart": 1}, tag="half")
os.makedirs(os.path.join(work, "resumed"), exist_ok=True)
shutil.copy(os.path.join(work, "half", "impact.restart"), os.path.join(work, "resumed"))
run("jamari_impact/in.jamari_impact_resume", os.path.join(work, "resumed"),
    variables={"model": "jamari_ep", "dir": D, "steps": 30000 - STOP}, tag="resumed")
full = [l.split() for l in open(os.path.join(work, "jamari_ep", "impact.txt")) if not l.startswith("#")]
res = [l.split() for l in open(os.path.join(work, "resumed", "impact.txt")) if not l.startswith("#")]
k0 = STOP // 10
inside = sum(1 for k in range(1, 10) if float(full[k0][2 * k - 1]) < 0.001)
c.true(inside >= 3, "the restart is written mid-impact (%d spheres in contact)" % inside)
same = len(res) == len(full) - k0 and all(a[1:] == b[1:] for a, b in zip(res, full[k0:]))
c.true(same, "continued from the restart file: %d rows equal the uninterrupted run's digit for digit" % len(res))
c.finish()
