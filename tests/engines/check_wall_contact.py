"""A sphere's contact with a wall in both engines: two spheres hit the
plane z = 0 obliquely (one spinning), LAMMPS fix wall/gran granular with
dc/hertz_elliptic + dc/classical against LIGGGHTS' fix wall/gran ...
primitive with hertz_elliptic + classical.

LAMMPS applies the friction torque of a wall contact with the lever arm R
(fix wall/gran: torquesi scaled by radi), LIGGGHTS with R - delta/2 (as
LAMMPS does for a pair): the torque of a given tangential force differs by
the factor R / (R - delta/2), a relative delta/(2R) (up to 4 % here, a soft
contact). Measured:
- normal-only quantities (z, vz, fz) agree within 1e-10 at every step (the
  normal of a plane does not see the rotation);
- each engine's torque is its lever arm times n x F_t at every step;
- Coulomb sliding (mu = 0.05, sliding throughout), atom 1 (no spin at
  first: slip, force and spin stay along one line, the force is mu F_n
  along it in both engines): positions, velocities and forces within
  1e-10, the torque ratio R / (R - delta/2) at every step, the angular
  velocity differing by at most delta_max/(2R) relative;
- the rest (atom 2 of Coulomb, whose slip turns as delta changes at a rate
  set by the spin; spring-sliding with stick and slip, whose tangential
  spring sees the effective mass 1/m + c^2/I): every tangential column
  differs from the other engine's by at most delta_max/R of its largest
  value (the lever's delta/(2R) on the torque, and its effect on the slip
  velocity and so on the force).
2 ranks against 1 (the spheres on both sides of x = 0); a bad coefficient."""
import engines

work, _, c = engines.start()
R = 0.001
NAMES = "x y z vx vy vz omegax omegay omegaz fx fy fz tqx tqy tqz".split()
COLS = ["%s%d" % (n, i + 1) for i in range(2) for n in NAMES]
NORMAL = [COLS.index(n) for n in ("z1", "vz1", "fz1", "z2", "vz2", "fz2")]
TANGENTIAL = [k for k in range(30) if k not in NORMAL]


def dump(folder):
    """Per step both atoms' values, one row."""
    return [a + b for a, b in engines.dump(folder, 2)]


def lever_error(rows, lever):
    """max over steps and atoms of |tq - (-c n x F)| / |tq|, n = z, c = lever(delta)."""
    worst = 0.0
    for r in rows:
        for a in (0, 15):
            fx, fy, tx, ty = r[a + 9], r[a + 10], r[a + 12], r[a + 13]
            if fx == 0.0 and fy == 0.0:
                continue
            cl = lever(R - r[a + 2])
            t = (cl * fy, -cl * fx)
            worst = max(worst, max(abs(tx - t[0]), abs(ty - t[1])) / max(abs(tx), abs(ty)))
    return worst


runs = {}
for name, opts, tang, mu in (("coulomb", "classicalTangential coulomb", "dc/classical 0 2 0 0.05 0 0 0 0 0", 0.05),
                             ("springSliding", "classicalTangential springSliding",
                              "dc/classical 3 2 0 0.5 0 0 0 0 0", 0.5)):
    dg, _ = engines.run("liggghts", "wall_contact/in.liggghts", work, variables={"opts": opts, "mu": mu},
                        tag="liggghts_" + name)
    dl, _ = engines.run("lammps", "wall_contact/in.lammps", work, variables={"tangential": tang}, tag="lammps_" + name)
    g, l = dump(dg), dump(dl)
    runs[name] = l
    dmax = max(R - r[k] for r in g for k in (2, 17))
    c.true(l[-1][11] == 0.0 and l[-1][26] == 0.0 and dmax > 0, "%s: both spheres rebound, delta_max/(2R) = %.4g"
           % (name, dmax / (2 * R)))
    engines.compare(c, l, g, "%s: normal-only quantities (z, vz, fz) against LIGGGHTS" % name, columns=NORMAL,
                    names=COLS)
    c.true(lever_error(l, lambda d: R) < 1e-12 and lever_error(g, lambda d: R - 0.5 * d) < 1e-12,
           "%s: torque = -c n x F_t at every step with c = R in LAMMPS (%.2g), c = R - delta/2 in LIGGGHTS (%.2g)"
           % (name, lever_error(l, lambda d: R), lever_error(g, lambda d: R - 0.5 * d)))
    if name == "coulomb":
        # atom 1 (no spin at first): the slip, the force and the spin stay
        # along one line in both engines
        same = [COLS.index(n) for n in COLS if n.endswith("1") and not n.startswith(("omega", "tq"))]
        engines.compare(c, l, g, "coulomb, atom 1 (sliding throughout, along one line): positions, velocities, "
                        "forces against LIGGGHTS", columns=same, names=COLS)
        ratio = max(abs(a[k] / b[k] / (R / (R - 0.5 * (R - b[2]))) - 1.0) for a, b in zip(l, g)
                    for k in (12, 13) if b[k] != 0.0)
        c.true(ratio < 1e-10, "coulomb, atom 1: torque LAMMPS / LIGGGHTS = R / (R - delta/2) at every step "
               "(within %.2g)" % ratio)
        spin = max(abs(a[k] - b[k]) / abs(b[k]) for a, b in zip(l, g) for k in (6, 7) if b[k] != 0.0)
        dmax1 = max(R - r[2] for r in g)
        c.true(0.0 < spin <= dmax1 / (2 * R), "coulomb, atom 1: angular velocity relative difference %.4g <= "
               "delta_max/(2R) %.4g" % (spin, dmax1 / (2 * R)))
    # every tangential column (atom 2 of coulomb: its slip turns as delta
    # changes, at a rate set by the spin)
    worst, where = 0.0, None
    for k in TANGENTIAL:
        big = max(abs(r[k]) for r in g)
        e = max(abs(a[k] - b[k]) for a, b in zip(l, g)) / big if big > 0 else 0.0
        if e > worst:
            worst, where = e, COLS[k]
    c.true(0.0 < worst <= dmax / R, "%s: tangential columns differ by at most %.4g of their largest value (%s) "
           "<= delta_max/R %.4g" % (name, worst, where, dmax / R))

# 2 ranks against 1 (incremental: 6 history values per wall contact)
tang = "dc/classical 9 2 0 0.5 0 0 0 0 0"
d1, _ = engines.run("lammps", "wall_contact/in.lammps", work, variables={"tangential": tang}, tag="lammps_1rank")
d2, _ = engines.run("lammps", "wall_contact/in.lammps", work, variables={"tangential": tang}, ranks=2,
                    tag="lammps_2ranks")
engines.compare(c, dump(d2), dump(d1), "incremental: LAMMPS 2 ranks against 1", tol=0.0, names=COLS)

rc, text = engines.run("lammps", "wall_contact/in.lammps", work,
                       variables={"tangential": "dc/classical 3 2 7 0.5 0 0 0 0 0", "steps": 1}, tag="error",
                       expect_error=True)
c.true(rc != 0 and "dc/classical coefficient damp_mode = 7 is outside {0, 1, 2, 3}" in text,
       "error: damp_mode 7 named with its range")
c.finish()
