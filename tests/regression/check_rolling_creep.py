#!/usr/bin/env python3
"""Regression (issue 14): `rolling_friction kalker` on steady contacts with
imposed creepage (inputs/rolling_creep): spheres (in.rolling_sphere,
tangential cmd_tangential) and disc-like superquadrics, oblate spheroids on
their rim (in.rolling_disc, tangential classical), rolling on the plane
z = 0 (fix wall/gran) and on each other (pair_style gran), each body moved
at a constant velocity with a constant angular velocity.
Against the law evaluated independently (tests/reference/gen_rolling_creep.py:
elliptic Hertz patch, the rolling kinematics, Kalker's coefficients solved
by gen_kalker.py at the contacts' axis ratios, Vermeulen-Johnson or the
linear law with its bounds), from the bodies' positions, velocities and
angular velocities the run dumps (and, for superquadric pairs, LIGGGHTS'
contact point):
- the normal force (elliptic Hertz, to 1e-9);
- creep force (both components) and spin moment of every rolling contact,
  the torque of the creep force about the centre, for both creep models:
  longitudinal creepage 1e-4 .. 0.1 (the linear range to full saturation),
  lateral, spin, combined, rolling along the disc patch's major axis, its
  minor axis and at 30 degrees, pure rolling (no force);
- below rollingVelocityMin (a stationary body slipping, a sphere rolling
  at 5e-4 m/s) the tangential model acts instead: cmd_tangential's Mindlin
  loading curve, classical springSliding's 8 G* a x, and no spin moment;
- 2 MPI ranks equal 1 rank (bodies on both sides of the split, one
  crossing it), and the committed reference;
- a sphere launched without spin on the plane (in.rolling_release,
  integrated): it slides at mu m g (the saturated creep force), the slip
  ends at the time of Coulomb friction, and it rolls on at
  v0 / (1 + I / (m c^2)) with no force (no rolling resistance); without the
  rolling model (cmd_tangential alone) the same speed; beyond the plain
  law's explicit step limit, dt < 2 m_eff V / (G c^2 c11) (1.5 times, and
  slower rolling at 3.5, 10 and 100 times) the stepped law settles without
  chatter; at a 25th of it the creep force equals the independent law
  within 1e-3 at every unsaturated step.
Prints the creep force against the longitudinal creepage.
Usage: check_rolling_creep.py WORKDIR [--update]"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "reference"))
from regress import ROOT, compare_tables, mindlin_virgin, run, save_reference, start, table  # noqa: E402
import gen_rolling_creep as law  # noqa: E402

work, update, c = start()
E, NU, MU, D0, VMIN, STEPS, DT = 1e9, 0.25, 0.5, 2e-6, 1e-3, 100, 1e-7
G = E / (2 * (1 + NU))                       # Kalker's combined G of two like bodies
ESTAR = E / (2 * (1 - NU ** 2))
GSTAR = E / (4 * (2 - NU) * (1 + NU))         # Mindlin's G*
R, A, C = 1e-3, law.DISC_A, law.DISC_C
TABLE = law.load_coefficients()
ZERO2 = [[0.0, 0.0], [0.0, 0.0]]
SPHERE = lambda r: [[1 / r, 0.0], [0.0, 1 / r]]
DISC_Y = [[1 / A, 0.0], [0.0, A / C ** 2]]   # symmetry axis along y: rim curvature 1/A along x
DISC_X = [[A / C ** 2, 0.0], [0.0, 1 / A]]   # symmetry axis along x


def last_snapshot(path):
    """{id: row} of the last snapshot of a dump custom file."""
    block = open(path).read().split("ITEM: TIMESTEP\n")[-1].strip().split("\n")
    k = next(i for i, l in enumerate(block) if l.startswith("ITEM: ATOMS"))
    return {int(float(l.split()[0])): [float(v) for v in l.split()] for l in block[k + 1:]}


def pair_points(path):
    """{(id1, id2): contact point} of the last snapshot of a dump local file."""
    block = open(path).read().split("ITEM: TIMESTEP\n")[-1].strip().split("\n")
    k = next(i for i, l in enumerate(block) if l.startswith("ITEM: ENTRIES"))
    out = {}
    for l in block[k + 1:]:
        v = [float(x) for x in l.split()]
        out[tuple(sorted((int(v[0]), int(v[1]))))] = v[3:6]
    return out


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def contacts(shape, atoms, points):
    """The deck's contacts: (id of body i, id of body j or None for the
    wall, Ki, Kj, lever arm of i, lever arm of j, overlap); n = +z."""
    out = []
    col = {k: v for k, v in enumerate(("id", "type", "x", "y", "z", "vx", "vy", "vz", "wx", "wy", "wz",
                                       "fx", "fy", "fz", "tx", "ty", "tz"))}
    get = lambda i, name: atoms[i][[k for k, v in col.items() if v == name][0]]
    if shape == "sphere":
        for i in range(1, 25):
            d = R - get(i, "z")
            out.append((i, None, SPHERE(R), ZERO2, [0, 0, -(R - d / 2)], None, d))
        for lo, up in ((25, 26), (27, 28)):
            Ru, Rl = 0.6e-3, R
            d = Ru + Rl - (get(up, "z") - get(lo, "z"))
            out.append((up, lo, SPHERE(Ru), SPHERE(Rl), [0, 0, -(Ru - d / 2)], [0, 0, Rl - d / 2], d))
    else:
        for i in range(1, 21):
            out.append((i, None, DISC_Y, ZERO2, [0, 0, -A], None, A - get(i, "z")))
        for lo, up, Ku in ((21, 22, DISC_Y), (23, 24, DISC_X)):
            cp = points[(lo, up)]
            ri = [cp[k] - atoms[up][2 + k] for k in range(3)]
            rj = [cp[k] - atoms[lo][2 + k] for k in range(3)]
            out.append((up, lo, Ku, DISC_Y, ri, rj, 2 * A - (get(up, "z") - get(lo, "z"))))
    return out


def evaluate(shape, creep, atoms, points):
    """Per contact: (i, got dict, reference dict or None when not rolling,
    extras)."""
    res = []
    for i, j, Ki, Kj, ri, rj, d in contacts(shape, atoms, points):
        bi = atoms[i]
        vi, wi = bi[5:8], bi[8:11]
        mi = [vi[k] + cross(wi, ri)[k] for k in range(3)]
        if j is None:
            mj, dw = [0.0, 0.0, 0.0], wi
        else:
            aj = atoms[j]
            mj = [aj[5 + k] + cross(aj[8:11], rj)[k] for k in range(3)]
            dw = [wi[k] - aj[8 + k] for k in range(3)]
        s = (mi[0] - mj[0], mi[1] - mj[1])
        a, b, Fn, axis = law.patch(Ki, Kj, ESTAR, d)
        got = {"F": (bi[11], bi[12]), "Fn": bi[13], "tq": bi[14:17]}
        if j is not None:   # the lower body takes the opposite force
            got["Fj"] = (atoms[j][11], atoms[j][12])
        kin = law.rolling_law(Ki, Kj, s, dw, a, b, axis, Fn, G, MU, creep, TABLE)
        ref = kin if kin["V"] > VMIN else None
        res.append((i, j, got, ref, {"a": a, "b": b, "Fn": Fn, "s": s, "V": kin["V"], "ri": ri, "xi": kin["xi"],
                                     "eta": kin["eta"], "phi": kin["phi"]}))
    return res


def deck_run(shape, creep, ranks):
    d = os.path.join(work, "%s_%s_%d" % (shape, creep, ranks))
    log = run("rolling_creep/in.rolling_%s" % shape, d, ranks=ranks, variables={"creep": creep}, tag="run")
    atoms = last_snapshot(os.path.join(d, "forces.dump"))
    if ranks == 2:
        # the bodies of the middle column start 0.5 um left of the split at x = 0 and cross it
        crossed = [i for i in atoms if atoms[i][2] > 0 and abs(atoms[i][2]) < 1e-5]
        c.true("2 by 1 by 1 MPI processor grid" in log and len(crossed) >= 3,
               "%s, %s: 2 ranks split at x = 0, bodies %s crossed it" % (shape, creep, crossed))
    points = pair_points(os.path.join(d, "pair.dump")) if shape == "disc" else {}
    return d, atoms, points


curves = []
for shape in ("sphere", "disc"):
    for creep in ("vermeulenJohnson", "kalker"):
        d1, atoms, points = deck_run(shape, creep, 1)
        d2, atoms2, _ = deck_run(shape, creep, 2)
        tag = "%s, %s" % (shape, creep)
        # 2 ranks against 1
        worst = max(abs(atoms2[i][k] - atoms[i][k]) / max(abs(atoms[i][k]), 1e-300) if atoms[i][k] != atoms2[i][k]
                    else 0.0 for i in atoms for k in range(11, 17))
        c.true(set(atoms2) == set(atoms) and worst <= 1e-12,
               "%s: 2 ranks equal 1 rank (forces and torques of %d bodies, worst relative difference %.2g)"
               % (tag, len(atoms), worst))
        res = evaluate(shape, creep, atoms, points)
        wn = max(abs(g["Fn"] - x["Fn"]) / x["Fn"] for _, _, g, _, x in res)
        c.true(wn <= 1e-9, "%s: normal force = elliptic Hertz at the overlap (worst %.2g)" % (tag, wn))
        worst_f = worst_m = worst_t = 0.0
        nroll, zero_ok, pair_ok = 0, True, True
        for i, j, g, ref, x in res:
            if ref is None:
                continue
            nroll += 1
            muF = MU * x["Fn"]
            Fr = ref["F"]
            if math.hypot(*Fr) == 0.0:
                zero_ok = zero_ok and math.hypot(*g["F"]) <= 1e-12 * muF and abs(g["tq"][2]) <= 1e-12 * muF * x["a"]
                continue
            ef = math.hypot(g["F"][0] - Fr[0], g["F"][1] - Fr[1]) / math.hypot(*Fr)
            worst_f = max(worst_f, ef)
            # (relative to 1e-6 of the full-slip moment where the law gives none: the
            # superquadric contact point lies off the axis by rounding)
            Ms = 3 * math.pi / 16 * muF * x["b"]
            worst_m = max(worst_m, abs(g["tq"][2] - ref["Mz"]) / max(abs(ref["Mz"]), 1e-6 * Ms))
            # the creep force's torque about the centre (x, y components; z is the spin moment)
            t = cross(x["ri"], [g["F"][0], g["F"][1], 0.0])
            worst_t = max(worst_t, math.hypot(g["tq"][0] - t[0], g["tq"][1] - t[1]) / (math.hypot(*Fr) * abs(x["ri"][2])))
            if j is not None:
                pair_ok = pair_ok and g["Fj"] == (-g["F"][0], -g["F"][1])
            if i <= 14 and shape == "sphere" or i <= 8 and shape == "disc":
                curves.append((tag, x["xi"], g["F"][0] / muF, Fr[0] / muF))
        c.true(worst_f <= 2e-5, "%s: creep force of %d rolling contacts against the independent law: worst relative "
               "difference %.2g (tol 2e-5)" % (tag, nroll, worst_f))
        c.true(worst_m <= 2e-4, "%s: spin moment against the law: worst relative difference %.2g (tol 2e-4; "
               "where the law gives none, relative to 1e-6 of 3 pi mu F_n b / 16)"
               % (tag, worst_m))
        c.true(worst_t <= 1e-12, "%s: torque of the creep force about the centre = lever arm x force (worst %.2g)"
               % (tag, worst_t))
        c.true(zero_ok, "%s: pure rolling: no creep force, no spin moment" % tag)
        c.true(pair_ok, "%s: pairs: the lower body takes the opposite creep force" % tag)
        # not rolling: the tangential model's force
        for i, j, g, ref, x in res:
            if ref is not None:
                continue
            sm = math.hypot(*x["s"])
            X = STEPS * sm * DT
            if shape == "sphere":
                k0 = 8 * GSTAR * x["a"]
                muF = MU * x["Fn"]
                want = mindlin_virgin(k0 * X, muF)
                what = "cmd_tangential's Mindlin loading curve"
            else:
                want = 8 * GSTAR * x["a"] * X
                what = "classical springSliding's 8 G* a x"
            Fg = math.hypot(*g["F"])
            along = -(g["F"][0] * x["s"][0] + g["F"][1] * x["s"][1]) / (Fg * sm)
            c.rel(Fg, want, 2e-3, "%s: atom %d, V = %.3g m/s <= rollingVelocityMin: the tangential model acts, %s "
                  "(x = %.3g m)" % (tag, i, x["V"], what, X))
            c.true(along > 1 - 1e-12 and g["tq"][2] == 0.0,
                   "%s: atom %d: against the slip (cos %.15f), no spin moment" % (tag, i, along))
        # the committed reference
        ref_path = os.path.join(ROOT, "inputs", "rolling_creep", "reference", "forces_%s_%s.txt" % (shape, creep))
        mine = os.path.join(d1, "forces_table.txt")
        with open(mine, "w") as f:
            f.write("# id fx fy fz tqx tqy tqz\n")
            for i in sorted(atoms):
                f.write(" ".join("%.17g" % v for v in [i] + atoms[i][11:17]) + "\n")
        if update:
            save_reference(mine, ref_path)
        compare_tables(c, table(mine), table(ref_path), 1e-9, "%s: vs reference" % tag)

# A sphere launched without spin on the plane (in.rolling_release, nve/sphere):
# it slides at mu m g, spins up and ends rolling without slip; the angular
# momentum about the contact point gives v_f = v0 / (1 + I / (m c^2)).
V0, GRAV = 0.1, 9.81
m = 2500 * 4 / 3 * math.pi * R ** 3
I = 0.4 * m * R * R


def release(name, rmodel, dt, steps, every=10, v0=V0, rset="contactPatch off"):
    d = os.path.join(work, "release_" + name)
    run("rolling_creep/in.rolling_release", d, variables={"rmodel": rmodel, "dt": dt, "steps": steps,
        "every": every, "v0": v0, "rset": rset}, tag="run")
    return table(os.path.join(d, "release.txt"))


rows = release("kalker", "kalker", 1e-6, 12000)
cl = R - 0.5 * (R - rows[-1][5])                 # lever arm R - delta/2
v_f = V0 / (1 + I / (m * cl * cl))
tstar = V0 / (MU * GRAV * (1 + m * cl * cl / I))  # slip v - omega c reaches 0
slide = [r for r in rows if r[0] < 0.9 * tstar]
ws = max(abs(-r[3] - MU * m * GRAV) / (MU * m * GRAV) for r in slide)
c.true(ws <= 1e-9, "release: while sliding (creepage 2 down to 0.14) the saturated creep force is mu m g (worst %.2g, "
       "%d samples)" % (ws, len(slide)))
t_end = next(r[0] for r in rows if abs(r[1] - r[2] * cl) <= 1e-6 * V0)
c.rel(t_end, tstar, 1e-2, "release: sliding ends (slip below 1e-6 v0) at v0 / (mu g (1 + m c^2 / I))")
last = rows[-1]
c.rel(last[1], v_f, 1e-6, "release: rolls on at v0 / (1 + I / (m c^2)) (angular momentum about the contact point)")
c.true(abs(last[1] - last[2] * cl) <= 1e-9 * V0 and abs(last[3]) <= 1e-9 * MU * m * GRAV,
       "release: then no slip (%.2g m/s) and no creep force (%.2g N): no rolling resistance"
       % (last[1] - last[2] * cl, last[3]))
off = release("off", "off", 1e-6, 12000)
c.rel(off[-1][1], v_f, 1e-3, "release without the rolling model (cmd_tangential alone): the same final speed, "
      "within its undamped spring's oscillation")
# The creep force near zero creepage, F = -(G c^2 c11 / V) s, is a viscous
# force on the slip: an explicit step of the plain law flips it every step
# beyond dt = 2 m_eff V / (G c^2 c11), m_eff = 1 / (1/m + c^2/I). The
# stepped law (dc_rolling_force_step: the linear law times
# (1 + x^4)^-1/4, x = dt G c^2 c11 / (V m_eff)) settles at any step.
delta = R - last[5]
c11 = law.coefficients(TABLE, 1.0)[0]
inv_m = 1 / m + cl * cl / I
dt_s = 2 * v_f / (G * R * delta * c11 * inv_m)


def chatter(rows):
    """Samples (every step) where F_x changed sign in two steps running."""
    fx = [r[3] for r in rows]
    return sum(1 for i in range(2, len(fx)) if fx[i] * fx[i - 1] < 0 and fx[i - 1] * fx[i - 2] < 0)


for f in (0.8, 1.5):
    dt = f * dt_s
    r2 = release("dt%.1f" % f, "kalker", dt, int(0.012 / dt), every=1)
    tail = max(abs(r[3]) for r in r2[-20:]) / (MU * m * GRAV)
    c.true(tail <= 1e-6 and chatter(r2) == 0, "release at dt = %.1f x %.3g s (the plain law's stability limit): "
           "settles, %d chatter steps (|F_x| / mu m g at the end %.2g)" % (f, dt_s, chatter(r2), tail))
# Slower rolling at dt = 1e-6: v0 = 3 mm/s (rolling on at 2.1 mm/s, 3.5 times
# beyond the plain law's limit: it chattered at +-mu m g at every step),
# and speeds 10 and 100 times beyond; rollingVelocityMin 1e-5 m/s
for name, beyond in (("v0 3 mm/s", None), ("10 x the limit", 10.0), ("100 x the limit", 100.0)):
    v0 = 0.003 if beyond is None else V0 * (1e-6 / beyond) / dt_s
    vf = v0 / (1 + I / (m * cl * cl))
    r2 = release("slow%d" % (0 if beyond is None else beyond), "kalker", 1e-6, 20000, every=1, v0=v0,
                 rset="rollingVelocityMin 1e-5 rollingDistanceMin 0")
    rolling = r2[len(r2) // 4:]
    tail = max(abs(r[3]) for r in r2[-1000:]) / (MU * m * GRAV)
    c.true(chatter(rolling) == 0 and tail <= 1e-9 and abs(r2[-1][1] / vf - 1) <= 1e-6,
           "release, %s (v0 %.3g m/s, dt 1e-6 s = %.1f x the plain law's limit at the final speed): %d chatter steps "
           "in the last %d, |F_x| / mu m g at the end %.2g, final speed %.9g of v0 / (1 + I / (m c^2))"
           % (name, v0, 1e-6 / (dt_s * vf / v_f), chatter(rolling), len(rolling), tail, r2[-1][1] / vf))
# Where dt is below a tenth of the limit the force is Kalker's linear theory
# (Vermeulen-Johnson here) within 1e-3: every step of the end of sliding at
# dt = dt_s / 25, against the independent law from the dumped state (the
# velocities at the half step, at which LIGGGHTS evaluates the force)
dt = dt_s / 25
r2 = release("linear", "kalker", dt, int(0.0075 / dt), every=1)
worst, n_cmp = 0.0, 0
for r in r2:
    t, vx, wy, fx, fz, z = r
    d = R - z
    if d <= 0:
        continue
    vh, wh = vx - 0.5 * dt * fx / m, wy - 0.5 * dt * (-(R - 0.5 * d) * fx) / I
    a = math.sqrt(R * d)
    Fb = 4.0 / 3.0 * ESTAR * math.sqrt(R) * d ** 1.5
    out = law.rolling_law(SPHERE(R), ZERO2, (vh - wh * (R - 0.5 * d), 0.0), (0.0, wh, 0.0), a, a, (1.0, 0.0), Fb, G,
                          MU, "vermeulenJohnson", TABLE)
    if not (out["V"] > VMIN) or not (1e-3 <= out["saturation"] <= 0.9):
        continue
    worst, n_cmp = max(worst, abs(fx / out["F"][0] - 1)), n_cmp + 1
c.true(n_cmp >= 10 and worst <= 1e-3, "release at dt = %.3g s (a 25th of the plain law's limit): the creep force of "
       "%d unsaturated steps equals the independent law within %.2g (tol 1e-3)" % (dt, n_cmp, worst))

print("     creep force against longitudinal creepage (F_x / mu F_n: LIGGGHTS, independent law)")
for tag, xi, got, want in curves:
    print("     %-28s xi %+9.2e   %+.9f   %+.9f" % (tag, xi, got, want))
c.finish()
