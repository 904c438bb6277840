"""Elastic-plastic impacts (plastic_impact/): spheres onto a plane at 0.3,
1 and 3 m/s and a pair head-on at 1 m/s, well beyond first yield.
LIGGGHTS jamari_ep against LAMMPS dc/jamari_ep every step within 1e-10
(the defaults; damping on top of the plastic law; other Kv, Ch, Ca); the
coefficients of restitution against the LIGGGHTS run's, below 1 and
falling with the speed; 2 ranks against 1; a bad coefficient."""
import engines

work, _, c = engines.start()
COLS = "time z1 vz1 fz1 z2 vz2 fz2 z3 vz3 fz3 x4 x5 vx4 vx5 fx4".split()
V_IN = {2: 0.3, 5: 1.0, 8: 3.0, 12: 0.5}   # column of the velocity: its value before impact


def restitution(rows):
    last = rows[-1]
    return [abs(last[k]) / v for k, v in sorted(V_IN.items())]


for v in [{}, {"e": 0.7}, {"kv": 0.6, "ch": 1.2, "ca": 50}]:
    tag = "_".join("%s%g" % kv for kv in sorted(v.items())) or "defaults"
    g, l, _ = engines.side_by_side(c, "plastic_impact", work, v, v, tag,
        "%s: LAMMPS dc/jamari_ep against LIGGGHTS jamari_ep" % tag, names=COLS)
    eg, el = restitution(g), restitution(l)
    for k, (a, b) in enumerate(zip(el, eg)):
        c.rel(a, b, 1e-10, "%s: restitution of %s against LIGGGHTS" % (tag, ["wall 0.3 m/s", "wall 1 m/s",
                                                                          "wall 3 m/s", "pair 1 m/s"][k]))
    c.true(all(f == 0.0 for f in (l[-1][3], l[-1][6], l[-1][9], l[-1][14])) and 1 > el[0] > el[1] > el[2] > 0,
           "%s: all rebound, restitution below 1 and falling with the speed (%s)" % (tag, ", ".join("%.4f" % e for e in el)))

d2, _ = engines.run("lammps", "plastic_impact/in.lammps", work, ranks=2, tag="lammps_2ranks")
d1, _ = engines.run("lammps", "plastic_impact/in.lammps", work, tag="lammps_1rank")
engines.compare(c, engines.out(d2), engines.out(d1), "LAMMPS 2 ranks against 1", tol=0.0, names=COLS)

rc, text = engines.run("lammps", "plastic_impact/in.lammps", work, variables={"ca": 1}, tag="bad_ca",
                       expect_error=True)
c.true(rc != 0 and "dc/jamari_ep coefficient Ca (plasticityCa) = 1 is outside [2, inf)" in text,
       "Ca 1: error naming the sub-model, the coefficient and its range")
c.finish()
