#!/usr/bin/env python3
"""Regression: a small adhesive agglomerate (125 jkr_elliptic spheres) on 1
and 2 MPI ranks. Contacts are kept across the rank boundary and neighbour
rebuilds through LIGGGHTS' contact history: the contact count must agree
exactly and the sum of force magnitudes to 1e-9 (different summation order
only; seen: 1e-14) on every output row, the agglomerate must form (contacts
grow to > 200 counted per atom; kinetic energy falls below half), and the
1-rank run must match its committed reference.
Usage: check_adhesive_agglomerate.py WORKDIR [--update]"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from regress import ROOT, compare_tables, run, save_reference, start, table

work, update, c = start()
rows = {}
for ranks in (1, 2):
    d = os.path.join(work, "ranks%d" % ranks)
    run("adhesive_agglomerate/in.adhesive_agglomerate", d, ranks=ranks, tag="np%d" % ranks)
    rows[ranks] = table(os.path.join(d, "agglomerate.txt"))
one, two = rows[1], rows[2]
c.true(len(one) == len(two) and all(a[1] == b[1] for a, b in zip(one, two)),
       "contact count equal on 1 and 2 ranks on every row (final %d and %d)" % (one[-1][1], two[-1][1]))
worst = max(abs(a[2] - b[2]) / a[2] for a, b in zip(one, two) if a[2] > 0)
c.true(worst < 1e-9, "force sum, 2 ranks vs 1: worst rel. difference %.3g (tol 1e-9)" % worst)
c.true(one[-1][1] > 200, "agglomerate formed: %d contacts (per atom, summed)" % one[-1][1])
c.true(one[-1][3] < 0.5 * one[0][3], "contacts dissipate: kinetic energy fell from %.3g to %.3g J (to < 1/2)" % (one[0][3], one[-1][3]))
ref = os.path.join(ROOT, "inputs", "adhesive_agglomerate", "reference", "agglomerate_1rank.txt")
if update:
    save_reference(os.path.join(work, "ranks1", "agglomerate.txt"), ref)
compare_tables(c, one, table(ref), 1e-9, "1 rank vs reference")
c.finish()
