"""Mindlin twisting in both engines: a sphere on the plane z = 0 turned
about the normal and a sphere pair turned about the line of centres at
constant overlap, through 0.02 rad (full slip) and back. LIGGGHTS
hertz_elliptic + cmd_tangential cmdTwisting on against LAMMPS
dc/hertz_elliptic + dc/cmd_tangential + twisting dc/cmd_twisting every
printed step within 1e-10, exact profile and turning points; the first
steps on Mindlin's torsional stiffness 16 a^3 / (3 s0), the full-slip
moment 3 pi mu N a / 16; the pair's moments equal and opposite; the
turning points' moment equal to the exact profile's (constant normal
force)."""
import math

import engines

work, _, c = engines.start()
COLS = "time wz3 tz3 wx2 tx1 tx2".split()
E, NU, MU, R, D0 = 1e9, 0.3, 0.5, 1e-3, 2e-6
runs = {}
for mem, name in ((0, "profile"), (1, "turningPoints")):
    g, l, _ = engines.side_by_side(c, "twisting", work, {"memory": name}, {"memory": mem}, name,
        "cmdMemory %s: LAMMPS dc/cmd_twisting against LIGGGHTS cmdTwisting on" % name, names=COLS)
    runs[name] = l

l = runs["profile"]
G = E / (2 * (1 + NU))
s0 = 2 / G                                   # sum of 1/G_i, two bodies of one material
Es = E / (2 * (1 - NU * NU))
for what, Reff, wcol, mcol, sign in (("wall", R, 1, 2, -1), ("pair", R / 2, 3, 4, 1)):
    a = math.sqrt(Reff * D0)
    N = 4.0 / 3.0 * Es * math.sqrt(Reff) * D0 ** 1.5
    k = 16 * a ** 3 / (3 * s0)
    Ms = 3 * math.pi / 16 * MU * N * a
    r = l[0]
    slope = sign * r[mcol] / (k * r[wcol] * r[0])
    c.true(abs(slope - 1) < 3e-3, "%s: first printed step on the torsional stiffness 16 a^3/(3 s0): %.6g" % (what, slope))
    top = max(abs(x[mcol]) for x in l) / Ms
    c.true(abs(top - 1) < 1e-10, "%s: full slip at 3 pi mu N a / 16 (largest moment / that %.15g)" % (what, top))
    c.true(abs(l[-1][mcol]) < 0.9 * Ms, "%s: turned back, the moment unloads (%.4g of full slip)"
           % (what, abs(l[-1][mcol]) / Ms))
worst = max(abs(x[4] + x[5]) for x in l) / max(abs(x[4]) for x in l)
c.true(worst < 1e-12, "pair: moments on atoms 1 and 2 equal and opposite (%.2g)" % worst)

tp = runs["turningPoints"]
Msw = 3 * math.pi / 16 * MU * 4.0 / 3.0 * Es * math.sqrt(R) * D0 ** 1.5 * math.sqrt(R * D0)
worst = max(abs(a[2] - b[2]) for a, b in zip(tp, l)) / Msw
c.true(worst < 1e-10, "wall: turningPoints against the exact profile: largest difference %.3g of full slip" % worst)
c.finish()
