#!/usr/bin/env python3
"""Regression (issue deck b): a sphere held at a constant overlap on a plane
that is moved back and forth tangentially (inputs/shear_cycle), with
`tangential cmd_tangential`:
- the first loading up to the displacement amplitude against Mindlin's
  loading curve F = mu Fn [1 - (1 - 2 k0 x / (3 mu Fn))^3/2] (review Eq. 59,
  k0 = 8 G* a the no-slip stiffness of the pair, a = (R d0)^1/2);
- the energy dissipated per stabilised cycle against review Eq. 69,
  E = 36 (mu Fn)^2 / (5 k0) [1 - (1 - x)^5/3 - 5x/6 (1 + (1 - x)^2/3)],
  x = F*/(mu Fn) (Eq. 69 written with the pair stiffness), within 1%;
- stock `tangential history` beside it (a linear spring: no loss below
  mu Fn);
- the loop against its committed reference;
- `tangential classical` (classicalTangential springSliding, stiffness
  mindlin 8 G* a) at amplitude 2 um, beyond sliding: the first loading slope
  k0 and the energy per cycle 4 mu Fn (X - mu Fn / k0) of a linear spring
  with Coulomb sliding, within 1%; incremental (Walton-Braun) beside it.
Usage: check_shear_cycle.py WORKDIR [--update]"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from regress import ROOT, compare_tables, run, save_reference, start, subsample, table

work, update, c = start()
E, nu, mu, R, d0, amp = 1e9, 0.3, 0.5, 1e-3, 2e-6, 5e-7
G = E / (2 * (1 + nu))
a = math.sqrt(R * d0)
k0 = 8 * a / (2 * (2 - nu) / G)
Estar = 1.0 / (2 * (1 - nu ** 2) / E)
Fn = 4.0 / 3.0 * Estar * math.sqrt(R) * d0 ** 1.5
EVERY = 10


def cycles(rows, n=3):
    per = (len(rows)) // n
    return [rows[k * per:(k + 1) * per + 1] for k in range(n)]


def loop_energy(cyc):
    return abs(sum(0.5 * (p[2] + q[2]) * (q[1] - p[1]) for p, q in zip(cyc[:-1], cyc[1:])))


runs = {}
for tmodel in ("cmd_tangential", "history"):
    d = os.path.join(work, tmodel)
    run("shear_cycle/in.shear_cycle", d, variables={"dir": os.path.join(ROOT, "inputs", "shear_cycle"),
                                                    "tmodel": tmodel}, tag=tmodel)
    runs[tmodel] = table(os.path.join(d, "loop.txt"))

rows = runs["cmd_tangential"]
c.rel(rows[-1][3], Fn, 1e-9, "normal force = Hertz at the held overlap")
quarter = max(rows[:len(rows) // 12 + 2], key=lambda r: r[1])
x = k0 * quarter[1]
F_mindlin = mu * Fn * (1 - (1 - 2 * x / (3 * mu * Fn)) ** 1.5)
c.rel(abs(quarter[2]), F_mindlin, 1e-3, "first loading at the amplitude vs Mindlin (Eq. 59)")
last = cycles(rows)[-1]
Fs = max(abs(r[2]) for r in last)
xs = Fs / (mu * Fn)
E69 = 36 * (mu * Fn) ** 2 / (5 * k0) * (1 - (1 - xs) ** (5.0 / 3.0) - 5 * xs / 6 * (1 + (1 - xs) ** (2.0 / 3.0)))
W = loop_energy(last)
c.rel(W, E69, 1e-2, "energy per stabilised cycle (F*/mu Fn = %.3f) vs Eq. 69" % xs)
Wh = loop_energy(cycles(runs["history"])[-1])
print("     energy per cycle: cmd_tangential %.6g J, Eq. 69 %.6g J, stock tangential history %.3g J" % (W, E69, Wh))
# a linear spring's loop has no area; what the trapezoid sum over the
# sampled wall positions leaves is below 1% of the Mindlin loop
c.true(Wh < 1e-2 * W, "stock tangential history: no loss below mu Fn (%.3g J, sampling residue)" % Wh)
# the classical linear spring with sliding at an amplitude beyond sliding
X = 2e-6
dcl = os.path.join(work, "classical")
run("shear_cycle/in.shear_cycle", dcl, variables={"dir": os.path.join(ROOT, "inputs", "shear_cycle"), "tmodel": "classical",
                                                  "opts": "tangential_damping off classicalTangential springSliding",
                                                  "amp": X}, tag="classical")
rc = table(os.path.join(dcl, "loop.txt"))
early = [r for r in rc[1:len(rc) // 12] if 0 < abs(r[2]) < 0.5 * mu * Fn]
slope = max(abs(r[2] / r[1]) for r in early)
c.rel(slope, k0, 1e-3, "classical springSliding: first loading slope vs 8 G* a (%d rows)" % len(early))
Wc = loop_energy(cycles(rc)[-1])
Wspring = 4 * mu * Fn * (X - mu * Fn / k0)
c.rel(Wc, Wspring, 1e-2, "classical springSliding: energy per cycle vs 4 mu Fn (X - mu Fn / k0)")
dci = os.path.join(work, "classical_incremental")
run("shear_cycle/in.shear_cycle", dci, variables={"dir": os.path.join(ROOT, "inputs", "shear_cycle"), "tmodel": "classical",
                                                  "opts": "tangential_damping off classicalTangential incremental",
                                                  "amp": X}, tag="incremental")
Wi = loop_energy(cycles(table(os.path.join(dci, "loop.txt")))[-1])
c.true(0.0 < Wi < Wspring, "classical incremental: a loop with less loss than the linear spring's (%.4g J < %.4g J)" % (Wi, Wspring))
print("     amplitude %g m: energy per cycle, classical springSliding %.6g J (closed form %.6g J), incremental %.6g J"
      % (X, Wc, Wspring, Wi))
ref = os.path.join(ROOT, "inputs", "shear_cycle", "reference", "loop.txt")
if update:
    save_reference(os.path.join(work, "cmd_tangential", "loop.txt"), ref, EVERY)
compare_tables(c, subsample(rows, EVERY), table(ref), 1e-9, "vs reference")
c.finish()
