#!/usr/bin/env python3
"""Regression (issue deck d): a sphere held on a plane at constant overlap and
turned about the contact normal (inputs/twisting), `tangential
cmd_tangential` with `cmdTwisting on`:
- the moment at small twist against Mindlin's no-slip torsional stiffness
  k = 16 a^3 / (3 s0) (s0 = sum 1/G_i; 16 G a^3/3 for one body on a rigid
  one, Johnson Sec. 7.3);
- full slip at M_s = 3 pi mu Fn a / 16 (Johnson Sec. 7.3);
- between them the law's Cattaneo-shaped curve M = M_s [1 - (1 - 2 k phi /
  (3 M_s))^3/2] (dc/cmd_tangential.h: its ends are exact, the partial-slip
  curve is not Lubkin's);
- stock `tangential history` has no twisting moment.
Usage: check_twisting.py WORKDIR"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from regress import run, start, table

work, _, c = start()
E, nu, mu, R, d0 = 1e9, 0.3, 0.5, 1e-3, 2e-6
G = E / (2 * (1 + nu))
Estar = 1.0 / (2 * (1 - nu ** 2) / E)
a = math.sqrt(R * d0)
Fn = 4.0 / 3.0 * Estar * math.sqrt(R) * d0 ** 1.5
k = 16 * a ** 3 / (3 * (2 / G))
Ms = 3 * math.pi * mu * Fn * a / 16
runs = {}
for name, tmodel, opts in (("cmd", "cmd_tangential", "cmdTwisting on"), ("history", "history", "tangential_damping off")):
    d = os.path.join(work, name)
    run("twisting/in.twisting", d, variables={"tmodel": tmodel, "opts": opts}, tag=name)
    runs[name] = table(os.path.join(d, "twist.txt"))
rows = runs["cmd"]
first = rows[0]
phi = first[0] * first[1]
# secant at the first step: k (1 - k phi / (6 M_s)) + O(phi^2) (slip starts at once)
c.rel(-first[2] / phi / (1 - k * phi / (6 * Ms)), k, 2e-6,
      "no-slip torsional stiffness 16 a^3/(3 s0) from the first step (phi = %.3g rad)" % phi)
c.rel(-rows[-1][2], Ms, 1e-9, "full slip at 3 pi mu Fn a / 16")
worst = 0.0
for r in rows:
    x = 2 * k * r[0] * r[1] / (3 * Ms)
    M = Ms * (1 - (1 - x) ** 1.5) if x < 1 else Ms
    worst = max(worst, abs(-r[2] - M) / Ms)
c.true(worst < 1e-9, "the whole curve against the law's Cattaneo-shaped form: worst %.3g of M_s (tol 1e-9)" % worst)
c.true(max(abs(r[2]) for r in runs["history"]) == 0.0, "stock tangential history: no twisting moment")
c.finish()
