"""Impacts with the classical normal laws (classical_impact/): spheres onto
a plane at 0.3, 1 and 3 m/s and a pair head-on at 1 m/s. LIGGGHTS
classical against LAMMPS dc/classical every step within 1e-10 for each
law (linear spring-dashpot with matched and given stiffness and
limitForce, Hertz with two damping laws, both hysteretic linear springs);
the linear spring-dashpot's restitution against its coefficient e; 2 ranks
against 1; a bad coefficient and the damping sub-model check."""
import engines

work, _, c = engines.start()
COLS = "time z1 vz1 fz1 z2 vz2 fz2 z3 vz3 fz3 x4 x5 vx4 vx5 fx4".split()
# (tag, LIGGGHTS variables, LAMMPS variables)
CASES = [
    ("lsd_energy", {"claw": "lsd", "cstiff": "energy"}, {"law": 0, "stiff": 3, "damp": 0.5}),
    ("lsd_given_limit", {"claw": "lsd", "cstiff": "given", "lim": "on"},
     {"law": 0, "stiff": 0, "damp": 0.5, "limit": 1}),
    ("hertz_restitution", {"claw": "hertz", "damping": "restitution"}, {"law": 1, "dlaw": 0, "damp": 0.5}),
    ("hertz_kuwabaraKono", {"claw": "hertz", "damping": "kuwabaraKono", "eta": 2e3},
     {"law": 1, "dlaw": 2, "damp": 2e3}),
    ("hertz_viscoelastic", {"claw": "hertz", "damping": "viscoelastic", "A": 1e-7},
     {"law": 1, "dlaw": 1, "damp": 1e-7}),
    ("hertz_tsuji", {"claw": "hertz", "damping": "tsuji"}, {"law": 1, "dlaw": 3, "damp": 0.5}),
    ("lsd_duration", {"claw": "lsd", "cstiff": "duration"}, {"law": 0, "stiff": 1, "damp": 0.5}),
    ("hlsConstant_overlap", {"claw": "hlsConstant", "cstiff": "overlap"}, {"law": 2, "stiff": 2, "damp": 0.5}),
    ("hlsVariable_energy", {"claw": "hlsVariable", "cstiff": "energy"}, {"law": 3, "stiff": 3, "damp": 1.0}),
]
for tag, vg, vl in CASES:
    g, l, _ = engines.side_by_side(c, "classical_impact", work, vg, vl, tag,
        "%s: LAMMPS dc/classical against LIGGGHTS classical" % tag, names=COLS)
    last = l[-1]
    e = [last[2] / 0.3, last[5] / 1.0, last[8] / 3.0, last[13] / 0.5]
    c.true(all(0 < x < 1 for x in e), "%s: all rebound (restitution %s)" % (tag, ", ".join("%.4f" % x for x in e)))
    if tag == "lsd_energy":
        # the linear spring-dashpot without limit: e at every speed
        for x in e:
            c.rel(x, 0.5, 1e-3, "lsd: restitution against e = 0.5 (time step 1e-8)")

d2, _ = engines.run("lammps", "classical_impact/in.lammps", work, ranks=2, tag="lammps_2ranks")
d1, _ = engines.run("lammps", "classical_impact/in.lammps", work, tag="lammps_1rank")
engines.compare(c, engines.out(d2), engines.out(d1), "LAMMPS 2 ranks against 1", tol=0.0, names=COLS)

rc, text = engines.run("lammps", "classical_impact/in.lammps", work, variables={"law": 7}, tag="bad_law",
                       expect_error=True)
c.true(rc != 0 and "dc/classical coefficient law = 7 is outside" in text,
       "law 7: error naming the sub-model, the coefficient and its range")
rc, text = engines.run("lammps", "classical_impact/in.lammps", work, variables={"stiff": 0, "kn": -1},
                       tag="bad_kn", expect_error=True)
c.true(rc != 0 and "dc/classical coefficient kn = -1 is outside" in text,
       "kn -1: error naming the sub-model, the coefficient and its range")
rc, text = engines.run("lammps", "classical_impact/in.lammps", work, variables={"damping": "dc/restitution"},
                       tag="bad_damping", expect_error=True)
c.true(rc != 0 and "use damping dc/classical" in text, "damping dc/restitution: error (the law's own dashpot)")
c.finish()
