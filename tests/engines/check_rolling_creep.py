"""Rolling contact with the creep law in both engines (scene
rolling_creep/cases.in, after inputs/rolling_creep/in.rolling_sphere):
spheres moved on a wall with imposed creepage, a sphere released on the
wall that slides and ends rolling, a pair rolling on each other across
the ranks' cut. LIGGGHTS rolling_friction kalker with tangential classical
against LAMMPS rolling dc/kalker with tangential dc/classical, both creep
models, every atom's position, velocity, force and torque at every step
within 1e-10; where the wall's tangential model acts (atoms 7, 8: not
rolling) the torque of LAMMPS' fix wall/gran, whose lever arm is the
radius R, times (R - delta/2)/R (LIGGGHTS' lever arm). 2 ranks against 1;
the hand-over in the pair and the release; bad coefficients."""
import os
import engines

work, _, c = engines.start()
SCENE = os.path.join(engines.HERE, "rolling_creep")
NAMES = "x y z vx vy vz omegax omegay omegaz fx fy fz tqx tqy tqz".split()
NATOMS, R = 11, 0.001
WALL_TANGENTIAL = (7, 8)   # below rollingVelocityMin, at rest: the tangential model acts


def dump(folder):
    """Rows per step: atoms 1..11 by id, 15 values each."""
    return engines.dump(folder, NATOMS)


def flat(rows, lammps_wall_lever=False):
    out = []
    for step in rows:
        r = []
        for i, a in enumerate(step):
            a = list(a)
            if lammps_wall_lever and i + 1 in WALL_TANGENTIAL:
                delta = R - a[2]
                for k in (12, 13, 14):
                    a[k] *= (R - 0.5 * delta) / R
            r += a
        out.append(r)
    return out


COLS = ["%s%d" % (n, i + 1) for i in range(NATOMS) for n in NAMES]
FZ9, VZ9 = COLS.index("fz9"), COLS.index("vz9")
CMP = [k for k in range(len(COLS)) if k not in (FZ9, VZ9)]
WEIGHT = 2500 * 4.0 / 3.0 * 3.141592653589793 * R ** 3 * 9.81
var = {"dir": SCENE}
runs = {}
for lig, num in (("vermeulenJohnson", 1), ("kalker", 0)):
    dg, _ = engines.run("liggghts", "rolling_creep/in.liggghts", work, variables=dict(var, creep=lig),
                        tag="liggghts_" + lig)
    dl, _ = engines.run("lammps", "rolling_creep/in.lammps", work, variables=dict(var, creep=num),
                        tag="lammps_" + lig)
    g, l = dump(dg), dump(dl)
    runs[lig] = l
    engines.compare(c, flat(l, True), flat(g), "creep %s: LAMMPS dc/kalker + dc/classical against LIGGGHTS kalker + "
                    "classical (atoms 7, 8 torque times (R - delta/2)/R)" % lig, names=COLS, columns=CMP)
    # the released sphere's fz and vz: the weight's residual, rounding of
    # the weight (1e-16 m g): within 1e-10 of m g and of v0
    wz = max(max(abs(a[FZ9] - b[FZ9]) for a, b in zip(flat(l), flat(g))) / WEIGHT,
             max(abs(a[VZ9] - b[VZ9]) for a, b in zip(flat(l), flat(g))) / 0.005)
    c.true(wz <= 1e-10, "creep %s: released sphere fz, vz within %.3g of the weight, of v0 (tol 1e-10)" % (lig, wz))
    # the wall's tangential torque: LAMMPS / LIGGGHTS = R / (R - delta/2) exactly
    a = l[-1][7]
    ratio = a[13] / g[-1][7][13]
    want = R / (R - 0.5 * (R - a[2]))
    c.true(abs(ratio / want - 1.0) < 1e-12, "creep %s: atom 8 torque LAMMPS / LIGGGHTS %.15g = R/(R - delta/2) %.15g"
           % (lig, ratio, want))
    # the pair hands over from the tangential model (a spring that grows)
    # to the creep law once it has rolled 0.1 a (step ~135)
    f100, f200 = l[100][9][11], l[200][9][11]
    c.true(abs(f200) > 5 * abs(f100) > 0 and l[200][9][11] == l[3000][9][11],
           "creep %s: pair hand-over: atom 10 fz %.4g at step 100 (spring), %.4g at 200 and 3000 (creep)"
           % (lig, f100, f200))
    # the released sphere ends rolling: vx = omega_y (R - delta/2), 5/7 v0
    s = l[-1][8]
    roll = s[3] / (s[7] * (R - 0.5 * (R - s[2])))
    c.true(abs(roll - 1.0) < 1e-3 and abs(s[3] / 0.005 - 5.0 / 7.0) < 1e-3,
           "creep %s: released sphere rolls at the end: vx / (omega_y c) = %.6f, vx / v0 = %.6f (5/7 = %.6f)"
           % (lig, roll, s[3] / 0.005, 5.0 / 7.0))
# the hand-over to and from the Cattaneo-Mindlin law (LIGGGHTS tangential
# cmd_tangential, LAMMPS dc/cmd_tangential)
dg, _ = engines.run("liggghts", "rolling_creep/in.liggghts", work, variables=dict(var, tmodel="cmd_tangential"),
                    tag="liggghts_cmd")
dl, _ = engines.run("lammps", "rolling_creep/in.lammps", work,
                    variables=dict(var, creep=1, tangential="dc/cmd_tangential 0.5 0 0 0"), tag="lammps_cmd")
engines.compare(c, flat(dump(dl), True), flat(dump(dg)), "LAMMPS dc/kalker + dc/cmd_tangential against LIGGGHTS "
                "kalker + cmd_tangential (atoms 7, 8 torque times (R - delta/2)/R)", names=COLS, columns=CMP)

# the two creep models differ (the pair: Vermeulen-Johnson's saturation)
fk, fv = runs["kalker"][-1][9][11], runs["vermeulenJohnson"][-1][9][11]
c.true(abs(fk - fv) > 1e-2 * abs(fv), "creep models differ: atom 10 fz kalker %.6g, vermeulenJohnson %.6g" % (fk, fv))

# 2 ranks (the pair across the cut at x = 0) against 1
d2, _ = engines.run("lammps", "rolling_creep/in.lammps", work, ranks=2, variables=var, tag="lammps_2ranks")
engines.compare(c, flat(dump(d2)), flat(runs["vermeulenJohnson"]), "LAMMPS 2 ranks against 1", tol=0.0, names=COLS)

# bad coefficients and set-up errors
for v, msg in (({"creep": 2}, "dc/kalker coefficient creep = 2 is outside {0 kalker, 1 vermeulenJohnson}"),
               ({"vmin": 0}, "dc/kalker coefficient vmin (rollingVelocityMin) = 0 is outside (0, inf)"),
               ({"dmin": -1}, "dc/kalker coefficient dmin (rollingDistanceMin) = -1 is outside [0, inf)"),
               ({"tangential": "mindlin NULL 1.0 0.5"}, "dc/kalker needs a tangential sub-model that hands"),
               ({"normal": "hertz/material", "damping": "tsuji"}, "needs one of the project's normal sub-models"),
               ({"steps": 1, "tangential": "dc/classical 3 2 0 -0.5 0 0 0 0 0"},
                "dc/classical coefficient mu (coefficientFriction) = -0.5 is outside")):
    rc, text = engines.run("lammps", "rolling_creep/in.lammps", work, variables=dict(var, **v), tag="error",
                           expect_error=True)
    c.true(rc != 0 and msg in text, "error %s: %s" % (v, msg))
c.finish()
