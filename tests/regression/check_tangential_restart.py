#!/usr/bin/env python3
"""Regression (issue deck f): a cmd_tangential loop between two spheres
(inputs/tangential_restart) stopped in the middle of an unloading branch
(write_restart at step 13700, after the first reversal) and continued with
read_restart reproduces the uninterrupted run to every printed digit: the
load history (turning points, slip profile) travels in LIGGGHTS' contact
history through the restart file.
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
c.finish()
