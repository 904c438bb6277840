"""Oblique impacts with Cattaneo-Mindlin-Deresiewicz friction in both
engines: a sphere pair (sliding, spinning: the contact sticks, slips and
twists) and a sphere onto the plane z = 0. LIGGGHTS hertz_elliptic +
cmd_tangential (cmdMemory profile | turningPoints, cmdTwisting on,
cmdDissipation, two materials) against LAMMPS dc/hertz_elliptic + dc/cmd_tangential +
dc/cmd_twisting, every column of every step within 1e-10; LIGGGHTS' stock
hertz against LAMMPS' hertz/material under the same tangential law; the
wall sphere turning (LAMMPS' wall torque lever arm is the radius, LIGGGHTS'
radius - delta/2: measured, not equal); 2 ranks against 1; bad
coefficients."""
import engines

work, _, c = engines.start()
COLS = ("time x1 z1 vx1 vy1 vz1 wx1 wy1 wz1 fx1 fy1 fz1 wx2 "
        "x3 z3 vx3 vz3 wx3 wy3 wz3 fx3 fz3").split()
PAIR = [k for k, n in enumerate(COLS) if not n.endswith("3")]
MEM = {0: "profile", 1: "turningPoints"}


def both(tag, lig, lmp, columns=None, tol=1e-10, what=None):
    return engines.side_by_side(c, "oblique_impact", work, lig, lmp, tag, what or tag, tol=tol, columns=columns,
                                names=COLS)


for mem in (0, 1):
    g, l, _ = both("%s_twist" % MEM[mem], {"memory": MEM[mem]}, {"memory": mem},
                   what="cmdMemory %s, cmdTwisting on: LAMMPS dc/cmd_tangential + dc/cmd_twisting against LIGGGHTS"
                   % MEM[mem])
    # the contacts stuck and slipped: the pair's spin about x changed, the
    # wall sphere left with a changed sideways velocity
    c.true(abs(l[-1][COLS.index("wx1")] - 40.0) > 1.0 and abs(l[-1][COLS.index("vx3")] - 0.64) > 0.1,
           "%s: friction and twist acted (wx1 %.4g from 40, vx3 %.4g from 0.64)"
           % (MEM[mem], l[-1][COLS.index("wx1")], l[-1][COLS.index("vx3")]))
both("profile_dissipation", {"memory": "profile", "diss": "on", "tvisc": 2e-6}, {"memory": 0, "tvisc": 2e-6},
     what="cmdDissipation on (t_visc 2e-6 s): LAMMPS against LIGGGHTS")
both("turningPoints_notwist", {"memory": "turningPoints", "twist": "off"}, {"memory": 1, "twist": "twisting none"},
     what="turningPoints, no twisting: LAMMPS against LIGGGHTS")

# atom 2 of another material: LAMMPS mixes the pair 1-2 (E* and G* of the
# two materials in dc/hertz_elliptic, Mindlin's compliances from them)
both("mixed", {"E2": 2e7, "nu2": 0.2}, {"mixed": 1, "E2": 2e7, "nu2": 0.2},
     what="two materials (E 5e6 and 2e7, nu 0.3 and 0.2), LAMMPS' mixing: LAMMPS against LIGGGHTS")

# stock normal models: LIGGGHTS hertz, LAMMPS hertz/material (undamped),
# the circular patch of radius (R delta)^1/2 in both
both("stock_hertz", {"normal": "hertz", "e": 1.0},
     {"normal": "hertz/material", "damping": "velocity", "e": 0.0},
     what="LAMMPS hertz/material + dc/cmd_tangential against LIGGGHTS hertz + cmd_tangential")

# the wall sphere turning: the pair stays equal, the wall sphere's spin
# differs by the lever arm (radius against radius - delta/2)
g, l, _ = both("spin3", {"spin3": 1}, {"spin3": 1}, columns=PAIR,
               what="wall sphere turning: the pair's columns")
k = COLS.index("wy3")
d = max(abs(a[k] - b[k]) for a, b in zip(l, g)) / max(abs(b[k]) for b in g)
c.true(1e-4 < d < 0.05, "wall sphere turning: omega_y differs by %.3g of its largest value (LAMMPS' wall lever "
       "arm is the radius, LIGGGHTS' radius - delta/2)" % d)

# 2 ranks (the pair on both sides of x = 0) against 1
d1, _ = engines.run("lammps", "oblique_impact/in.lammps", work, variables={"memory": 1}, tag="lammps_1rank")
d2, _ = engines.run("lammps", "oblique_impact/in.lammps", work, variables={"memory": 1}, ranks=2, tag="lammps_2ranks")
engines.compare(c, engines.out(d2), engines.out(d1), "LAMMPS 2 ranks against 1", tol=0.0, names=COLS)

# bad coefficients name the sub-model, the coefficient and its range
for v, want in [({"memory": 2}, "dc/cmd_tangential coefficient memory = 2 is outside {0 (profile), 1 (turningPoints)}"),
                ({"mu": -0.1}, "dc/cmd_tangential coefficient mu = -0.1 is outside [0, inf)"),
                ({"tvisc": -1e-6}, "dc/cmd_tangential coefficient t_visc = -1e-06 is outside [0, inf) s"),
                ({"rough": 1}, "dc/cmd_tangential coefficient rough = 1 (tangentialRoughness) needs a normal"),
                ({"tang": "mindlin"}, "dc/cmd_twisting needs tangential dc/cmd_tangential, not mindlin"),
                ({"twist": "twisting marshall"}, "dc/cmd_tangential with twisting marshall: marshall reads a linear")]:
    rc, text = engines.run("lammps", "oblique_impact/in.lammps", work, variables=v, expect_error=True,
                           tag="error_%s" % "_".join(str(x) for x in v))
    c.true(rc != 0 and want in text, "error %s: %s" % (v, "found" if want in text else text[-400:]))
c.finish()
