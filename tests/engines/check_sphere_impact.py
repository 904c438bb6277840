"""Sphere impacts (a pair head-on, a sphere onto a wall) in both engines:
the project's hertz_elliptic with each damping law in LIGGGHTS against
dc/hertz_elliptic with the same dc/ damping law in LAMMPS, every column of
every step within 1e-10; undamped, dc/hertz_elliptic against LAMMPS' own
hertz/material to rounding; 2 ranks against 1 in LAMMPS."""
import engines

work, _, c = engines.start()
COLS = "time x1 x2 vx1 vx2 fx1 z3 vz3 fz3".split()
# (LIGGGHTS damping, LAMMPS damping, e, coef)
LAWS = [("restitution", "dc/restitution", 0.5, None),
        ("restitution", "dc/restitution", 0.1, None),
        ("viscoelastic", "dc/viscoelastic", 1.0, 2e-5),
        ("kuwabaraKono", "dc/kuwabara_kono", 1.0, 3e-3),
        ("tsuji", "dc/tsuji", 0.5, None)]
for lig, lmp, e, coef in LAWS:
    v = {"e": e, "damping": lig}
    w = {"e": e, "damping": lmp}
    if coef is not None:
        v["coef"] = w["coef"] = coef
    tag = "%s_e%g" % (lig, e)
    g, l, _ = engines.side_by_side(c, "sphere_impact", work, v, w, tag,
        "damping %s e %g: LAMMPS dc/hertz_elliptic + %s against LIGGGHTS hertz_elliptic" % (lig, e, lmp), names=COLS)
    # the impacts happened: a rebound of the pair and of the wall sphere
    c.true(l[-1][4] > 0 and l[-1][7] > 0 and max(abs(r[5]) for r in l) > 0,
           "damping %s e %g: both impacts rebound (vx2 %.4g, vz3 %.4g)" % (lig, e, l[-1][4], l[-1][7]))

# undamped: LAMMPS' own hertz/material (damping velocity with 0)
dl, _ = engines.run("lammps", "sphere_impact/in.lammps", work, variables={"e": 1.0}, tag="lammps_undamped")
dh, _ = engines.run("lammps", "sphere_impact/in.lammps", work,
                    variables={"normal": "hertz/material", "damping": "velocity", "coef": 0.0}, tag="hertz_material")
engines.compare(c, engines.out(dl), engines.out(dh), "undamped: dc/hertz_elliptic against LAMMPS hertz/material",
                tol=1e-13, names=COLS)

# 2 ranks (the pair on both sides of the cut at x = 0) against 1
d2, _ = engines.run("lammps", "sphere_impact/in.lammps", work, ranks=2, tag="lammps_2ranks")
d1, _ = engines.run("lammps", "sphere_impact/in.lammps", work, tag="lammps_1rank")
engines.compare(c, engines.out(d2), engines.out(d1), "LAMMPS 2 ranks against 1", tol=0.0, names=COLS)
c.finish()
