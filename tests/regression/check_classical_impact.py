#!/usr/bin/env python3
"""Regression: the `classical` normal model (the lecture notes' classical
laws) in head-on impacts at 0.1, 1 and 3 m/s (inputs/classical_impact),
against the figures of tests/reference/classical.csv (gen_classical.py:
closed forms checked there against a 30-digit integration of
m delta'' = -F, the same E*, R, m and speeds):
- lsd, stiffness matched by energy (stock `hooke`'s K): duration, maximum
  overlap and restitution for e = 0.1, 0.5, 0.9, limitForce off (and on
  for e = 0.5) (a linear law: Tc and e do not depend on the speed, delta_max grows as v);
- matched stiffness at characteristicVelocity 1 m/s: duration matching gives
  Hertz's collision time, overlap matching its maximum overlap (lsd and
  hlsConstant);
- Walton-Braun hlsConstant (e = 0.2, 0.6) and hlsVariable
  (S = 1e5, 1e6 1/m): duration until the force ends, maximum overlap and
  force, residual overlap, restitution (constant, or falling with the speed);
- hertz with damping none (Tc, delta_max, F_max against the elastic closed
  form), and with tsuji damping the trajectory of hertz_elliptic's;
each at dt = 1 and 2 ns: the error falls with dt, and the figure at 1 ns
(lsd: extrapolated to dt = 0 from the two, its error being first order) is
within 1e-6 of the reference (lsd's rebound without limitForce: eta dt / m,
its dashpot force dropping to 0 within a step). Side by side: stock `hooke` and `classical lsd`
(energy) give the same trajectory; hlsVariable on 2 MPI ranks equals 1 rank
digit for digit. Bad input stops the run with a message naming it.
Usage: check_classical_impact.py WORKDIR"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from regress import ROOT, run, start, table

work, _, c = start()
DECK = "classical_impact/in.classical_impact"
SPEEDS = [0.1, 1.0, 3.0]
R = 5e-4
rows = [l.strip().split(",") for l in open(os.path.join(ROOT, "tests", "reference", "classical.csv"))
        if not l.startswith("#")]
const = [r for r in rows if r[0] == "const"][0]
C_T = float(const[1])
LSD, HERTZ, HLS_CONSTANT, HLS_VARIABLE = 0, 1, 2, 3
E_STAR, MEFF = 3e10, 5e-6
K_ENERGY = float([r for r in rows if r[0] == "match" and r[2] == "3"][0][8])   # (16/15)^4/5 (...)^2/5


def figures(rows_, k, law, limit):
    """(Tc, dmax, e, Fmax, dres) of atom k (1..3): the contact ends where the
    overlap returns to 0 (hertz; lsd without limitForce, whose force jumps
    to 0 there) or, for the
    others, where the force falls to 0 (linear extrapolation of the last two
    nonzero forces; hls keeps a residual overlap)."""
    t = [r[0] for r in rows_]
    z = [r[3 * k - 2] for r in rows_]
    f = [r[3 * k] for r in rows_]
    v0 = -(rows_[0][3 * k - 1] - f[0] / MEFF * (t[1] - t[0]) / 2)   # the impact velocity (first half kick undone)
    d = [R - x for x in z]
    last = max(i for i in range(len(f)) if f[i] != 0.0)
    if law == HERTZ or (law == LSD and not limit):
        i = next(i for i in range(1, len(d)) if d[i] < 0.0)
        tc = t[i - 1] + d[i - 1] / (d[i - 1] - d[i]) * (t[i] - t[i - 1])
        dres = 0.0
    else:
        s = f[last] / (f[last - 1] - f[last])   # steps past `last` to F = 0
        tc = t[last] + s * (t[last] - t[last - 1])
        dres = d[last] + s * (d[last] - d[last - 1])
    return tc, max(d), rows_[-1][3 * k - 1] / v0, max(f), dres


def run_law(tag, opts, dt, **var):
    d = os.path.join(work, "%s_%s" % (tag, dt))
    steps = int(round(12000 * 1e-9 / float(dt)))
    run(DECK, d, variables=dict(var, opts=opts, dt=dt, steps=steps), tag=tag)
    return table(os.path.join(d, "impact.txt"))


def compare(tag, opts, law, want, tol, limit=0, first_order=(), **var):
    """want[k]: the reference (Tc, dmax, e, Fmax, dres) of atom k (None: not
    compared). Runs at dt = 1 and 2 ns; the relative error (dres: relative
    to dmax) at 1 ns is not above the one at 2 ns (or below tol / 2, where
    where in the last step the force ends decides) and within tol (one for
    all, or one per figure). first_order: the figures on which the lsd
    dashpot, switching on within the first step, puts an error proportional
    to dt; they are extrapolated to dt = 0 (2 f(dt) - f(2 dt)) before they
    are compared."""
    got = {dt: run_law(tag, opts, dt, **var) for dt in ("1e-9", "2e-9")}
    for k, ref in enumerate(want, start=1):
        if ref is None:
            continue
        f1, f2 = (figures(got[dt], k, law, limit) for dt in ("1e-9", "2e-9"))
        for j, name in enumerate(("Tc", "dmax", "e", "Fmax", "dres")):
            if ref[j] is None:
                continue
            scale = ref[1] if name == "dres" else abs(ref[j])
            err1, err2 = abs(f1[j] - ref[j]) / scale, abs(f2[j] - ref[j]) / scale
            got_j = 2.0 * f1[j] - f2[j] if name in first_order else f1[j]
            err = abs(got_j - ref[j]) / scale
            t = tol[j] if isinstance(tol, tuple) else tol
            c.true(err <= t and err1 <= max(err2, 0.5 * t),
                   "%s, %g m/s: %s %.10g%s vs %.10g: rel. error %.2g (%.2g at dt = 1 ns, %.2g at 2 ns; tolerance %.2g)"
                   % (tag, SPEEDS[k - 1], name, got_j, " (extrapolated)" if name in first_order else "", ref[j], err,
                      err1, err2, t))
    return got


# lsd, energy-matched K: the v = 1 rows scaled (Tc, e fixed, dmax ~ v)
for e, limits in (("0.1", (0,)), ("0.5", (0, 1)), ("0.9", (0,))):
    for limit in limits:
        r = [x for x in rows if x[0] == "lsd" and float(x[1]) == float(e) and x[5] == str(limit)][0]
        c.rel(float(r[4]), K_ENERGY, 1e-15, "lsd rows of classical.csv use the energy-matched K")
        eta, Tc, dmax, eo = (float(x) for x in r[6:10])
        want = [(Tc, dmax * v, eo, None, None) for v in SPEEDS]
        # without limitForce the dashpot force (eta e v at the end) drops to 0 within a step, at a
        # point that moves with dt: the rebound velocity is exact to eta dt / m relative
        tol = 1e-6 if limit else (1e-6, 1e-6, max(1e-6, eta * 1e-9 / MEFF), 1e-6, 1e-6)
        compare("lsd_e%s_limit%d" % (e, limit), "classicalNormal lsd classicalStiffness energy limitForce %s"
                % ("on" if limit else "off"), LSD, want, tol, limit=limit,
                first_order=("Tc", "dmax", "e") if limit else ("Tc", "dmax"), e=e)

# matched stiffness at 1 m/s: the 1 m/s atom's figure equals Hertz's
for law, name in ((LSD, "lsd"), (HLS_CONSTANT, "hlsConstant")):
    for method, how, j in ((1, "duration", 0), (2, "overlap", 1)):
        r = [x for x in rows if x[0] == "match" and x[1] == str(law) and x[2] == str(method) and float(x[3]) == 0.8][0]
        ref = (float(r[9]), float(r[10]))
        want = [None, tuple(ref[j] if i == j else None for i in range(5)), None]
        compare("match_%s_%s" % (name, how), "classicalNormal %s classicalStiffness %s" % (name, how),
                law, want, 1e-6, first_order=("Tc", "dmax") if law == LSD else (), e="0.8")

# Walton-Braun: KL energy-matched (the hls rows' K_L)
for law, name, var, xs in ((HLS_CONSTANT, "hlsConstant", "e", ("0.2", "0.6")),
                           (HLS_VARIABLE, "hlsVariable", "S", ("1e5", "1e6"))):
    for x in xs:
        want = []
        for v in SPEEDS:
            r = [y for y in rows if y[0] == "hls" and y[1] == str(law) and float(y[3]) == float(x) and float(y[5]) == v][0]
            c.rel(float(r[2]), K_ENERGY, 1e-15, "hls rows of classical.csv use the energy-matched K_L")
            Tc, dmax, dres, Fmax, eo = (float(y) for y in r[6:11])
            want.append((Tc, dmax, eo, Fmax, dres))
        got = compare("%s_%s" % (name, x), "classicalNormal %s classicalStiffness energy" % name, law, want, 1e-6,
                      **{var: x})
        if law == HLS_VARIABLE:
            es = [figures(got["1e-9"], k, law, 0)[2] for k in (1, 2, 3)]
            c.true(es[0] > es[1] > es[2], "%s S = %s: restitution falls with the speed: %s" % (name, x, es))

# hertz: the elastic closed form
want = []
for v in SPEEDS:
    Khz = 4.0 / 3.0 * E_STAR * math.sqrt(R)
    dmax = (1.25 * MEFF * v * v / Khz) ** 0.4
    want.append((C_T * (MEFF ** 2 / (v * R * E_STAR ** 2)) ** 0.2, dmax, 1.0, Khz * dmax ** 1.5, None))
compare("hertz_none", "classicalNormal hertz damping none", HERTZ, want, 1e-6)

# classical hertz with Tsuji damping is hertz_elliptic's (inputs/damping_impact checks that against the integration)
side = {}
for model, opts in (("hertz_elliptic", "damping tsuji"), ("classical", "classicalNormal hertz damping tsuji")):
    d = os.path.join(work, "tsuji_" + model)
    run(DECK, d, variables={"model": model, "opts": opts, "e": "0.5"}, tag=model)
    side[model] = table(os.path.join(d, "impact.txt"))
a, b = side["hertz_elliptic"], side["classical"]
worst = max(abs(x[j] - y[j]) / max(abs(r[j]) for r in b) for x, y in zip(a, b) for j in range(1, 10))
c.true(len(a) == len(b) and worst < 1e-12, "classical hertz and hertz_elliptic, damping tsuji: the same trajectory "
       "(largest difference %.2g of each column's range)" % worst)

# side by side: stock hooke (K = 16/15 R^1/2 E* (15 m v^2 / (16 R^1/2 E*))^1/5) and classical lsd energy,
# the spheres starting off the plane (at exactly zero overlap stock hooke's dashpot acts, the law's does not)
for model, opts in (("hooke", "limitForce off"), ("classical", "classicalNormal lsd classicalStiffness energy")):
    d = os.path.join(work, "side_" + model)
    run(DECK, d, variables={"model": model, "opts": opts, "e": "0.5", "gap": "1.234e-8"}, tag=model)
    side[model] = table(os.path.join(d, "impact.txt"))
a, b = side["hooke"], side["classical"]
worst = max(abs(x[j] - y[j]) / max(abs(r[j]) for r in b) for x, y in zip(a, b) for j in range(1, 10))
c.true(len(a) == len(b) and worst < 1e-10, "stock hooke and classical lsd (energy) give the same trajectory: "
       "largest difference %.2g of each column's range" % worst)

# 2 ranks
d2 = os.path.join(work, "hlsVariable_np2")
run(DECK, d2, ranks=2, variables={"opts": "classicalNormal hlsVariable classicalStiffness energy", "S": "1e6"},
    tag="np2")
c.true(open(os.path.join(d2, "impact.txt")).read() == open(os.path.join(work, "hlsVariable_1e6_1e-9", "impact.txt")).read(),
       "hlsVariable on 2 ranks: the impact table equals the 1-rank run's digit for digit")

# bad input
for opts, var, words in (("classicalNormal hls", {}, ["hlsConstant", "hlsVariable", "lsd"]),
                         ("classicalNormal lsd damping kuwabaraKono", {}, ["classicalNormal hertz"]),
                         ("classicalNormal hlsVariable classicalStiffness duration", {}, ["classicalStiffness"]),
                         ("classicalNormal lsd", {"e": "0"}, ["coefficientRestitution"]),
                         ("classicalNormal hlsVariable", {"S": "-1"}, ["unloadingStiffnessSlope"])):
    tag = "bad%d" % len(words)
    code, out = run(DECK, os.path.join(work, "bad_" + opts.replace(" ", "_") + "".join(var)),
                    variables=dict(var, opts=opts, steps=10), tag="bad", expect_error=True)
    err = [l for l in out.splitlines() if "ERROR" in l]
    c.true(code != 0 and err and all(w in err[0] for w in words),
           "'%s' %s stops the run naming %s: %s" % (opts, var, words, err[0].strip() if err else "(no error)"))
c.finish()
