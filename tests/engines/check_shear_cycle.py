"""Mindlin-Deresiewicz loops in both engines: a sphere pair and a sphere on
the plane z = 0 at constant overlap, moved sideways back and forth (1.5
cycles, partial slip). LIGGGHTS hertz_elliptic + cmd_tangential against
LAMMPS dc/hertz_elliptic + dc/cmd_tangential every printed step within
1e-10, exact profile and turning points; on the wall the first steps'
force on Mindlin's virgin curve mu N (1 - (1 - u/u*)^3/2), u* = 3 mu N /
(2 k), k = 8 G* a; the loop's area against Mindlin-Deresiewicz's; the
turning points' loop equal to the exact profile's (constant normal force)."""
import math

import engines

work, _, c = engines.start()
COLS = "time dy fy1 fx1 fz1 x3 fx3 fy3 fz3".split()
E, NU, MU, R, D0, AMP = 1e9, 0.3, 0.5, 1e-3, 2e-6, 5e-7
runs = {}
for mem, name in ((0, "profile"), (1, "turningPoints")):
    g, l, _ = engines.side_by_side(c, "shear_cycle", work, {"memory": name}, {"memory": mem}, name,
        "cmdMemory %s: LAMMPS dc/cmd_tangential against LIGGGHTS cmd_tangential" % name, names=COLS)
    runs[name] = l

# the wall sphere (R = 1 mm on a plane; the plane's material is the sphere's)
l = runs["profile"]
G = E / (2 * (1 + NU))
Gs = G / (2 * (2 - NU))
k = 8 * Gs * math.sqrt(R * D0)
N = l[0][8]
us = 1.5 * MU * N / k
u, F = l[0][5] - 0.004, -l[0][6]
virgin = MU * N * (1 - (1 - u / us) ** 1.5)
c.true(abs(F / virgin - 1) < 1e-5, "wall, first printed step: force %.6g on Mindlin's virgin curve %.6g (%.2g)"
       % (F, virgin, F / virgin - 1))

# the loop of the last full cycle (t from 0.5 to 1.5 periods) against
# Mindlin-Deresiewicz's dissipated energy at this amplitude; the force lags
# the displacement by the time step (about 0.6 % of the area here)
cyc = [r for r in l if 0.5e-3 - 1e-12 <= r[0] <= 1.5e-3 + 1e-12]
area = abs(sum(0.5 * (p[6] + q[6]) * (q[5] - p[5]) for p, q in zip(cyc, cyc[1:])))
sa = AMP / us


def virgin_f(s):
    return 1 - (1 - s) ** 1.5


n = 20000
W = 0.0
for i in range(n):
    s = -sa + (i + 0.5) * 2 * sa / n
    down = virgin_f(sa) - 2 * (1 - (1 - (sa - s) / 2) ** 1.5)
    up = -virgin_f(sa) + 2 * (1 - (1 - (s + sa) / 2) ** 1.5)
    W += (down - up) * 2 * sa / n
W = abs(W) * MU * N * us
c.true(abs(area / W - 1) < 0.01, "wall loop area %.5g J against Mindlin-Deresiewicz %.5g J (%.2g)"
       % (area, W, area / W - 1))

# the wall's normal force is constant: the turning points' loop is the
# exact profile's (the pair's normal turns and its force changes by parts
# in 1e9 as atom 2 moves: there the bounded memory differs slightly)
tp = runs["turningPoints"]
worst = max(abs(a[6] - b[6]) for a, b in zip(tp, l)) / (MU * N)
c.true(worst < 1e-12, "wall: turningPoints against the exact profile: largest difference %.3g mu N" % worst)
Np = abs(l[0][3])
pair = max(abs(a[2] - b[2]) for a, b in zip(tp, l)) / (MU * Np)
c.true(pair < 1e-4, "pair: turningPoints against the exact profile: largest difference %.3g mu N" % pair)
c.finish()
