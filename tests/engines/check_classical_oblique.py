"""The classical tangential laws in an oblique impact of two spheres (the
pair across x = 0, one spinning): LIGGGHTS hertz_elliptic + tangential
classical with each law and its stiffness and damping settings against
LAMMPS dc/hertz_elliptic + tangential dc/classical with the same
coefficients, both spheres' position, velocity, angular velocity, force
and torque at every step within 1e-10; 2 ranks against 1; bad
coefficients."""
import engines

work, _, c = engines.start()
NAMES = "x y z vx vy vz omegax omegay omegaz fx fy fz tqx tqy tqz".split()
COLS = ["%s%d" % (n, i + 1) for i in range(2) for n in NAMES]
KT, GT, ET, ETAL, TV = 200, 0.01, 0.5, 0.1, 1e-6


def dump(folder):
    """Per step both atoms' values, one row."""
    return [a + b for a, b in engines.dump(folder, 2)]


# (LIGGGHTS settings, law, kt_mode, damp_mode); coulomb with mu = 0.05:
# it slides throughout (at a stick its direction flips from step to step
# with the sign of a velocity of rounding size, in either engine)
LAWS = [("classicalTangential coulomb", 0, 2, 0),
        ("classicalTangential viscous", 1, 2, 0),
        ("classicalTangential viscousSliding", 2, 2, 0),
        ("classicalTangential springSliding", 3, 2, 0),
        ("classicalTangential springSliding classicalTangentialStiffness given", 3, 0, 0),
        ("classicalTangential springDashpotSliding classicalTangentialStiffness ratio "
         "classicalTangentialDamping restitution", 4, 1, 2),
        ("classicalTangential springDashpotSliding classicalTangentialDamping given", 4, 2, 1),
        ("classicalTangential diRenzo classicalTangentialDamping normal", 5, 2, 3),
        ("classicalTangential langston", 6, 2, 0),
        ("classicalTangential zheng", 7, 2, 0),
        ("classicalTangential tsuji", 8, 2, 0),
        ("classicalTangential incremental classicalTangentialStiffness given", 9, 0, 0)]
lig_vars = {"kt": KT, "gammat": GT, "et": ET, "etal": ETAL, "tvisc": TV}
for opts, law, ktm, dm in LAWS:
    tag = "_".join(opts.split()[1::2])
    mu = 0.05 if law == 0 else 0.5
    dg, _ = engines.run("liggghts", "classical_oblique/in.liggghts", work,
                        variables=dict(lig_vars, opts=opts, mu=mu), tag="liggghts_" + tag)
    tang = "dc/classical %d %d %d %g %g %g %g %g %g" % (law, ktm, dm, mu, KT, GT, ET, ETAL, TV)
    dl, _ = engines.run("lammps", "classical_oblique/in.lammps", work, variables={"tangential": tang},
                        tag="lammps_" + tag)
    g, l = dump(dg), dump(dl)
    engines.compare(c, l, g, "%s: LAMMPS `%s` against LIGGGHTS" % (opts, tang), names=COLS)
    # the impact happened, with a tangential force and a spin-up of atom 2
    # (the contact ends near step 4080: forces zero at the end)
    c.true(max(abs(r[10]) for r in l) > 0 and abs(l[-1][15 + 8]) > 0 and l[-1][9] == 0.0,
           "%s: tangential force (max |fy1| %.3g N), atom 2 spun up (omega_z %.4g 1/s), apart at the end"
           % (opts, max(abs(r[10]) for r in l), l[-1][15 + 8]))

# 2 ranks (the pair on both sides of the cut at x = 0) against 1
tang = "dc/classical 9 0 0 0.5 %g 0 0 0 0" % KT
d1, _ = engines.run("lammps", "classical_oblique/in.lammps", work, variables={"tangential": tang}, tag="lammps_1rank")
d2, _ = engines.run("lammps", "classical_oblique/in.lammps", work, variables={"tangential": tang}, ranks=2,
                    tag="lammps_2ranks")
engines.compare(c, dump(d2), dump(d1), "incremental: LAMMPS 2 ranks against 1", tol=0.0, names=COLS)

# bad coefficients
for tang, msg in (("dc/classical 10 2 0 0.5 0 0 0 0 0", "dc/classical coefficient law = 10 is outside {0, 1, ..., 9}"),
                  ("dc/classical 3.5 2 0 0.5 0 0 0 0 0", "dc/classical coefficient law = 3.5 is outside"),
                  ("dc/classical 3 0 0 0.5 0 0 0 0 0", "dc/classical coefficient kt (kt) = 0 is outside"),
                  ("dc/classical 4 2 2 0.5 0 0 1.5 0 0", "dc/classical coefficient e_t"),
                  ("dc/classical 6 2 0 0.5 0 0 0 -1 0", "dc/classical coefficient eta_l (langstonDamping) = -1")):
    rc, text = engines.run("lammps", "classical_oblique/in.lammps", work, variables={"tangential": tang, "steps": 1},
                           tag="error", expect_error=True)
    c.true(rc != 0 and msg in text, "error `%s`: %s" % (tang, msg))
c.finish()
