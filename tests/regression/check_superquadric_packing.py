#!/usr/bin/env python3
"""Regression (c): 324 blocky superquadrics settling with hertz_elliptic on 1
and 2 MPI ranks. Different rank counts sum forces in different orders, so
trajectories diverge at round-off and then chaotically; what must agree is the
settled state: same atom count, both at rest (kinetic energy below 1e-5 J,
against about 1e-3 J while falling), mean height within 1% of each other,
and the 1-rank run against its committed reference: the rows up to step 5000
(free fall and first impacts, before round-off differences in any part of the
code are amplified by the dense packing: about tenfold per 1000 steps from
1e-15 at step 4000) within 1e-9, and the settled mean height within 1%.
Curvature reuse (setting curvatureTolerance t = 1e-4, curvatureCheck on),
on 1 and 2 ranks (atoms migrate, pairs change order): every reused geometry
within 20 t of the one recomputed at that step, on every contact (pairs and
the five walls), some contacts reused, the bed settled; with curvatureCheck 1e-9 the check stops the run (it is live).
Usage: check_superquadric_packing.py WORKDIR [--update]"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from regress import ROOT, compare_tables, run, save_reference, start, table

ref = os.path.join(ROOT, "inputs", "superquadric_packing", "reference", "packing_hertz_elliptic_1rank.txt")
work, update, c = start()
final = {}
for ranks in (1, 2):
    d = os.path.join(work, "ranks%d" % ranks)
    run("superquadric_packing/in.superquadric_packing", d, ranks=ranks,
        variables={"model": "hertz_elliptic", "steps": 15000}, tag="np%d" % ranks)
    rows = table(os.path.join(d, "packing.txt"))
    final[ranks] = rows[-1]
    c.true(rows[-1][1] == 324, "%d rank(s): 324 atoms kept (got %d)" % (ranks, rows[-1][1]))
    c.true(rows[-1][2] < 1e-5, "%d rank(s): settled, kinetic energy %.3g J < 1e-5 J" % (ranks, rows[-1][2]))
    if ranks == 1:
        if update:
            save_reference(os.path.join(d, "packing.txt"), ref)
        want = table(ref)
        compare_tables(c, [r for r in rows if r[0] <= 5000], [r for r in want if r[0] <= 5000],
                       1e-9, "1 rank vs reference, steps <= 5000")
        c.rel(rows[-1][3], want[-1][3], 0.01, "1 rank vs reference, settled mean height")
c.rel(final[2][3], final[1][3], 0.01, "mean height, 2 ranks vs 1 rank")

TOL, BOUND = 1e-4, 2e-3
for ranks in (1, 2):
    d = os.path.join(work, "reuse%d" % ranks)
    code, out = run("superquadric_packing/in.superquadric_packing", d, ranks=ranks, expect_error=True, tag="reuse",
                    variables={"model": "hertz_elliptic", "steps": 15000,
                               "settings": "curvatureTolerance %g curvatureCheck %g" % (TOL, BOUND)})
    c.true(code == 0, "%d rank(s), curvatureTolerance %g: every reused geometry within %g (the run completes; exit %d)"
           % (ranks, TOL, BOUND, code))
    stats = re.findall(r"curvature reused (\d+) times, computed (\d+) times; largest relative deviation (\S+), "
                       r"above curvatureTolerance on (\d+)", out)
    c.true(len(stats) == 6 * ranks, "%d rank(s): reuse figures printed for the pair and the five walls on every rank "
           "(got %d)" % (ranks, len(stats)))
    reused = sum(int(r[0]) for r in stats)
    computed = sum(int(r[1]) for r in stats)
    worst = max([float(r[2].rstrip(",")) for r in stats] or [float("nan")])
    above = sum(int(r[3]) for r in stats)
    print("     %d rank(s), reuse: %d reused, %d computed; largest deviation %.3g, %d reuses above t"
          % (ranks, reused, computed, worst, above))
    c.true(reused > 0, "%d rank(s): some contacts reuse their geometry (%d of %d)" % (ranks, reused, reused + computed))
    c.true(worst <= BOUND, "%d rank(s): largest deviation %.3g <= %g" % (ranks, worst, BOUND))
    rows = table(os.path.join(d, "packing.txt"))
    c.true(rows[-1][2] < 1e-5, "%d rank(s), reuse: settled, kinetic energy %.3g J < 1e-5 J" % (ranks, rows[-1][2]))
    # not asserted: another chaotic realization, its mean height lands among
    # the others' spread (3.66-3.71 mm seen over the runs and the reference)
    print("     %d rank(s), reuse: settled mean height %.6g m (exact 1-rank run %.6g m)"
          % (ranks, rows[-1][3], final[1][3]))
code, out = run("superquadric_packing/in.superquadric_packing", os.path.join(work, "reuse_live"), expect_error=True,
                tag="live", variables={"model": "hertz_elliptic", "steps": 3000,
                                       "settings": "curvatureTolerance %g curvatureCheck 1e-9" % TOL})
c.true(code != 0 and "curvatureCheck: the reused geometry" in out, "curvatureCheck 1e-9 stops the run (exit %d)" % code)
c.finish()
