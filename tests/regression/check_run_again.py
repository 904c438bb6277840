#!/usr/bin/env python3
"""Every project model runs any number of `run` commands: LIGGGHTS sets a
model up again at each run's start (connectToProperties), and that set-up
must start from the deck's settings, not from what the last one left. Two
spheres pressed between two plane walls, one sliding, each model as pair
and wall model: `run 10` twice ends where `run 20` ends. A run boundary
itself moves the velocity-dependent forces a little (LIGGGHTS' set-up
evaluates them with the whole-step velocities, the last step of a run with
the half-step ones): the stock hertz + history deck measures that
difference here, and each model must stay within 10 times it.
Usage: check_run_again.py WORKDIR"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from regress import ROOT, run, start

work, _, c = start()
props = lambda name: os.path.join(ROOT, "inputs", "deck_errors", name)
cases = [
    ("stock hertz + history (the run boundary's own effect)", "hertz tangential history", "props_full", ""),
    ("hertz_elliptic + history", "hertz_elliptic tangential history", "props_full", ""),
    ("hertz_elliptic + classical + kalker", "hertz_elliptic tangential classical rolling_friction kalker", "props_full", ""),
    ("hertz_elliptic + cmd_tangential + kalker", "hertz_elliptic tangential cmd_tangential rolling_friction kalker", "props_full", ""),
    ("classical lsd + classical", "classical tangential classical", "props_classical", "classicalNormal lsd"),
    ("classical hertz + history", "classical tangential history", "props_classical", "classicalNormal hertz"),
    ("classical hertz tsuji + history", "classical tangential history", "props_classical", "classicalNormal hertz damping tsuji"),
    ("classical hlsConstant + history", "classical tangential history", "props_classical", "classicalNormal hlsConstant"),
    ("classical hlsVariable + cmd_tangential", "classical tangential cmd_tangential", "props_classical", "classicalNormal hlsVariable"),
    ("hertz_elliptic viscoelastic + history", "hertz_elliptic tangential history", "props_viscoelastic", "viscoelastic on"),
    ("jkr_elliptic + cmd_tangential", "jkr_elliptic tangential cmd_tangential", "props_jkr", ""),
    ("gw_rough + cmd_tangential", "gw_rough tangential cmd_tangential", "props_rough", ""),
    ("gw_rough + gw_adhesion", "gw_rough tangential history cohesion gw_adhesion", "props_rough_adhesive", "gwElliptic on"),
    ("jamari_ep + classical", "jamari_ep tangential classical", "props_hardness", ""),
]


def last_row(log, step):
    """The thermo row of `step` last printed: step ke fx fy fz tqz of atom 1."""
    rows = [l.split() for l in log.splitlines()]
    rows = [r for r in rows if len(r) == 6 and r[0] == str(step)]
    return [float(x) for x in rows[-1][1:]]


bound = None
for k, (name, model, prop, settings) in enumerate(cases):
    base = {"model": model, "settings": settings, "props": props(prop), "x0": "0.00099", "walls": "1",
            "vy": "0.01", "cdf": "2.0"}
    whole = run("deck_errors/in.sphere_base", os.path.join(work, "case%d" % k), variables=dict(base, runs=1, steps=20),
                tag="whole", compiled=False)
    split = run("deck_errors/in.sphere_base", os.path.join(work, "case%d" % k), variables=dict(base, runs=2, steps=10),
                tag="split", compiled=False)
    a, b = last_row(whole, 20), last_row(split, 20)
    scale = max(abs(x) for x in a[1:])
    diff = max(abs(x - y) for x, y in zip(a[1:], b[1:])) / scale
    finite = all(math.isfinite(x) for x in a + b) and scale > 0.0
    if bound is None:
        bound = 10.0 * max(diff, 1e-12)
        c.true(finite and diff < 1e-4, "%s: two runs against one, largest force change %.3g of the largest force "
               "(the bound for the models: %.3g)" % (name, diff, bound))
        continue
    c.true(finite and diff <= bound, "%s: two runs end where one run ends: largest force change %.3g of the "
           "largest force (<= %.3g)" % (name, diff, bound))
c.finish()
