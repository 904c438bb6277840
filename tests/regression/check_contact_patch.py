#!/usr/bin/env python3
"""Regression: the contact patch (dc/contract.h) that the project's normal
models publish through LIGGGHTS' contact history, read back with compute
pair/gran/local and wall/gran/local (`history`) for prescribed, oscillating
overlaps delta(t) = d0 + amp sin(2 pi t / T) (inputs/contact_patch):
- spheres, pair and wall, hertz_elliptic: a = b = (R delta)^1/2, elastic
  force 4/3 E* R^1/2 delta^3/2 = friction load, formed exactly while
  delta > 0, no axis;
- spheres, jkr_elliptic (w = 0.05 J/m^2): a and F of classical JKR at the
  prescribed overlap (inverted here by bisection on the stable branch),
  friction load F + 3 pi w R, formed in tension down to delta_break;
- spheres, gw_rough (Feng law): formed before touch (a = b = 0, F > 0),
  a = (R delta)^1/2 after;
- superquadrics, pair and wall, hertz_elliptic: semi-axes and force of the
  elliptic Hertz contact (review Eqs. 1-14, evaluated here independently of
  c_core), the major axis along the direction of the larger relative
  principal radius (wall: the ellipsoid's x axis; pair: from the sum of the
  two tips' curvature forms), a unit vector in the contact plane;
- superquadrics, jkr_elliptic: a >= b, friction load minus force constant
  (2 x pull-off force), the pair formed in tension (a mesh wall's contact
  ends at touch: LIGGGHTS measures no superquadric-mesh gap);
- 2 MPI ranks equal 1 rank; a run restarted half way (write_restart,
  read_restart) equals the uninterrupted run (jkr_elliptic spheres: the
  formed flag of a neck in tension survives the restart).
Usage: check_contact_patch.py WORKDIR"""
import math
import os
import re
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from regress import ROOT, elliptic_contact, jkr_sphere, run, start

work, _, c = start()
DIR = os.path.join(ROOT, "inputs", "contact_patch")
Y, nu, w, dt, T, EVERY = 5e6, 0.3, 0.05, 1e-7, 2e-4, 20
Estar = 1.0 / (2.0 * (1 - nu ** 2) / Y)
PATCH = ("a", "b", "ax", "ay", "az", "F", "Fb", "formed")


def patch_run(deck, name, model, ranks=1, steps=3000, extra=None, resume_from=None):
    """Runs deck (in.patch_<deck>) with the patch columns dumped; returns
    {"pair"|"wall": {step: [patch dict, ...]}}."""
    d = os.path.join(work, name)
    v = {"dir": DIR, "model": model, "steps": 0}
    v.update(extra or {})
    log = run("contact_patch/in.patch_%s" % deck, os.path.join(d, "probe"), variables=v, tag="probe")
    last = {}
    for first, final, kind in re.findall(r"contact patch in history values (\d+) to (\d+) \((pair|wall)\)", log):
        last[kind] = (int(first), int(final))
    c.true(set(last) == {"pair", "wall"} and all(b - a == 7 for a, b in last.values()),
           "%s: the model announces the 8 patch values for pair and wall (%s)" % (name, last))
    ncol = {k: 3 + b + 1 for k, (a, b) in last.items()}
    v.update(steps=steps, cols=" ".join("c_cp[%d]" % k for k in range(1, ncol["pair"] + 1)),
             colw=" ".join("c_cw[%d]" % k for k in range(1, ncol["wall"] + 1)))
    v["fmt"] = '"%s"' % " ".join(["%.17g"] * ncol["pair"])
    if ncol["pair"] != ncol["wall"]:
        raise SystemExit("FAIL %s: pair and wall history lengths differ, the deck takes one format" % name)
    deckname = "in.patch_%s" % deck
    if resume_from:
        os.makedirs(d, exist_ok=True)
        shutil.copy(os.path.join(work, resume_from, "patch.restart"), d)
        deckname += "_resume"
    run("contact_patch/" + deckname, d, ranks=ranks, variables=v, tag=name)
    out = {}
    for kind in ("pair", "wall"):
        first = last[kind][0] + 3
        blocks = {}
        for b in open(os.path.join(d, "%s.dump" % kind)).read().split("ITEM: TIMESTEP\n")[1:]:
            lines = b.strip().split("\n")
            rows = [list(map(float, l.split())) for l in lines[8:]]
            blocks[int(lines[0])] = [dict(zip(PATCH, r[first:first + 8])) for r in rows]
        out[kind] = blocks
    return out


def overlap(step, d0):
    return d0 + 3e-6 * math.sin(2 * math.pi * step * dt / T)


def rows(res, kind, d0):
    """(delta, patch) of every dumped contact row."""
    return [(overlap(s, d0), p) for s, ps in sorted(res[kind].items()) for p in ps]


def worst_rel(pairs):
    """max |got - want| / max |want| over (got, want) pairs."""
    scale = max(abs(w_) for g, w_ in pairs) or 1.0
    return max(abs(g - w_) for g, w_ in pairs) / scale


def same(x, y, what):
    steps = sorted(set(x["pair"]) & set(y["pair"]))
    ok = len(steps) > 10 and all(x[k][s] == y[k][s] for k in ("pair", "wall") for s in steps if s in x[k] and s in y[k])
    n = sum(len(x["pair"][s]) + len(x["wall"].get(s, [])) for s in steps)
    c.true(ok and n > 10, "%s: %d common dumps, %d contact rows, identical to the last digit" % (what, len(steps), n))


# --- spheres: pair R* = 1 x 1.5 / 2.5 mm, wall R = 0.8 mm; d0 = 1 um
Rs = {"pair": 0.6e-3, "wall": 0.8e-3}
he = patch_run("sphere", "sphere_hertz", "hertz_elliptic")
for kind, R in Rs.items():
    rs = rows(he, kind, 1e-6)
    touching = [(d, p) for d, p in rs if d > 0]
    c.true(len(touching) > 50 and all(p["formed"] == (1.0 if d > 0 else 0.0) for d, p in rs),
           "spheres %s, hertz_elliptic: formed exactly while delta > 0 (%d rows touching)" % (kind, len(touching)))
    c.true(worst_rel([(p["a"], math.sqrt(R * d)) for d, p in touching] +
                     [(p["b"], math.sqrt(R * d)) for d, p in touching]) < 1e-9,
           "spheres %s, hertz_elliptic: a = b = (R delta)^1/2 (tol 1e-9 of the largest)" % kind)
    F = [(p["F"], 4.0 / 3.0 * Estar * math.sqrt(R) * d ** 1.5) for d, p in touching]
    c.true(worst_rel(F) < 1e-9, "spheres %s, hertz_elliptic: elastic force = 4/3 E* R^1/2 delta^3/2 (worst %.3g)"
           % (kind, worst_rel(F)))
    c.true(all(p["Fb"] == p["F"] and p["ax"] == p["ay"] == p["az"] == 0.0 for d, p in touching),
           "spheres %s, hertz_elliptic: friction load = elastic force, no major axis" % kind)

jk = patch_run("sphere", "sphere_jkr", "jkr_elliptic")
for kind, R in Rs.items():
    rs = [(d, p) for d, p in rows(jk, kind, 1e-6) if p["formed"] == 1.0]
    d_break = -0.75 * (math.pi ** 2 * w ** 2 * R / Estar ** 2) ** (1.0 / 3.0)
    tension = [(d, p) for d, p in rs if d < 0]
    c.true(len(tension) > 5 and min(d for d, p in rs) >= d_break - 1e-12,
           "spheres %s, jkr_elliptic: %d formed rows in tension, none below delta_break = %.4g m"
           % (kind, len(tension), d_break))
    ref = [(d, p, jkr_sphere(R, Estar, w, d)) for d, p in rs]
    c.true(all(x is not None for d, p, x in ref), "spheres %s, jkr_elliptic: every formed row on the JKR branch" % kind)
    ref = [(d, p, x) for d, p, x in ref if x is not None]
    wa = worst_rel([(p["a"], x[0]) for d, p, x in ref])
    wf = worst_rel([(p["F"], x[1]) for d, p, x in ref])
    wb = worst_rel([(p["Fb"] - p["F"], 3 * math.pi * w * R) for d, p, x in ref])
    c.true(wa < 1e-9 and wf < 1e-9 and wb < 1e-12,
           "spheres %s, jkr_elliptic: a, F vs classical JKR, friction load F + 3 pi w R (worst %.3g, %.3g, %.3g)"
           % (kind, wa, wf, wb))
    c.true(all(p["Fb"] > 0 for d, p in rs), "spheres %s, jkr_elliptic: friction load > 0 in tension too" % kind)

gw = patch_run("sphere", "sphere_gw", "gw_rough")
for kind, R in Rs.items():
    rs = rows(gw, kind, 1e-6)
    before = [(d, p) for d, p in rs if d <= 0]
    after = [(d, p) for d, p in rs if d > 0]
    c.true(len(before) > 5 and all(p["formed"] == 1.0 and p["a"] == p["b"] == 0.0 and p["F"] > 0 for d, p in before),
           "spheres %s, gw_rough: %d rows before touch formed with force and no area" % (kind, len(before)))
    c.true(len(after) > 50 and worst_rel([(p["a"], math.sqrt(R * d)) for d, p in after]) < 1e-9
           and all(p["Fb"] == p["F"] for d, p in rs),
           "spheres %s, gw_rough: a = (R delta)^1/2 once touching, friction load = force" % kind)

same(patch_run("sphere", "sphere_jkr_np2", "jkr_elliptic", ranks=2), jk, "spheres, jkr_elliptic: 2 ranks vs 1")
half = patch_run("sphere", "sphere_jkr_half", "jkr_elliptic", steps=1160, extra={"restart": 1})
resumed = patch_run("sphere", "sphere_jkr_resumed", "jkr_elliptic", steps=1840, resume_from="sphere_jkr_half")
c.true(any(p["formed"] == 1.0 and p["F"] < 0 for p in half["pair"][1160]),
       "restart written while the pair's neck is in tension")
same(resumed, jk, "spheres, jkr_elliptic: restarted at step 1160 vs uninterrupted")

# --- superquadrics: wall tip radii a1^2/c1 (x), b1^2/c1 (y); the pair's tips
# have forms diag(a2/b2^2, a2/c2^2) in (y, z), atom 3's turned by 30 degrees
a1, b1, c1, a2, b2, c2, omega = 1.0e-3, 0.6e-3, 1.5e-3, 1.5e-3, 0.6e-3, 1.0e-3, math.radians(30.0)
ky, kz = a2 / b2 ** 2, a2 / c2 ** 2
co, si = math.cos(omega), math.sin(omega)
Fyy = ky + ky * co * co + kz * si * si
Fzz = kz + ky * si * si + kz * co * co
Fyz = (ky - kz) * co * si
mean, rad = 0.5 * (Fyy + Fzz), math.hypot(0.5 * (Fyy - Fzz), Fyz)
k_small = mean - rad
vy, vz = (Fyz, k_small - Fyy) if abs(Fyz) + abs(k_small - Fyy) > abs(k_small - Fzz) + abs(Fyz) else (k_small - Fzz, Fyz)
n = math.hypot(vy, vz)
geo = {"wall": (a1 * a1 / c1, b1 * b1 / c1, (1.0, 0.0, 0.0)),
       "pair": (1.0 / k_small, 1.0 / (mean + rad), (0.0, vy / n, vz / n))}
sq = patch_run("superquadric", "sq_hertz", "hertz_elliptic")
for kind, (R1, R2, axis) in geo.items():
    touching = [(d, p) for d, p in rows(sq, kind, 2e-6) if d > 1e-8]
    ref = [(p, elliptic_contact(R1, R2, Estar, d)) for d, p in touching]
    wa = worst_rel([(p["a"], x[0]) for p, x in ref] + [(p["b"], x[1]) for p, x in ref])
    wf = worst_rel([(p["F"], x[2]) for p, x in ref])
    c.true(len(ref) > 50 and wa < 1e-9 and wf < 1e-9,
           "superquadrics %s, hertz_elliptic: semi-axes and force vs elliptic Hertz (%d rows, worst %.3g, %.3g)"
           % (kind, len(ref), wa, wf))
    dots = [abs(p["ax"] * axis[0] + p["ay"] * axis[1] + p["az"] * axis[2]) for d, p in touching]
    c.true(min(dots) > 1 - 1e-9, "superquadrics %s, hertz_elliptic: major axis along %s (min |cos| %.12f)"
           % (kind, "(%.4f, %.4f, %.4f)" % axis, min(dots)))
sqj = patch_run("superquadric", "sq_jkr", "jkr_elliptic")
for kind in ("pair", "wall"):
    rs = [(d, p) for d, p in rows(sqj, kind, 2e-6) if p["formed"] == 1.0]
    diff = [p["Fb"] - p["F"] for d, p in rs]
    c.true(len(rs) > 50 and all(p["a"] >= p["b"] > 0 for d, p in rs)
           and max(diff) - min(diff) <= 1e-9 * max(diff) and min(diff) > 0,
           "superquadrics %s, jkr_elliptic: a >= b > 0, friction load - force = %.6g N constant" % (kind, diff[0]))
# superquadrics against mesh walls: LIGGGHTS hands no gap to surfacesClose,
# so the neck holds in tension for pairs (and primitive walls) only
tension = [d for d, p in rows(sqj, "pair", 2e-6) if p["formed"] == 1.0 and d < 0 and p["F"] < 0]
c.true(len(tension) > 5, "superquadrics pair, jkr_elliptic: %d formed rows in tension" % len(tension))
same(patch_run("superquadric", "sq_hertz_np2", "hertz_elliptic", ranks=2), sq, "superquadrics, hertz_elliptic: 2 ranks vs 1")
c.finish()
