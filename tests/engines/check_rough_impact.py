"""Rough impacts (rough_impact/): a sphere onto a plane and a pair head-on
at 0.3 m/s with rough surfaces (sigma 2 um), damped (e 0.8). LIGGGHTS
gw_rough against LAMMPS dc/gw_rough every step within 1e-10 for each law
(tabulated rough sphere, Feng's law with tabulated and fitted
coefficients, the GW closed form with elastic and elastic-plastic
summits, with adhesive summits: LIGGGHTS cohesion gw_adhesion); the rough
force acting before the smooth surfaces touch, the summits' adhesion
pulling; 2 ranks against 1; bad coefficients."""
import engines

work, _, c = engines.start()
COLS = "time z1 vz1 fz1 x2 x3 vx2 fx2".split()
R = 1e-3
# (tag, LIGGGHTS variables, LAMMPS variables)
CASES = [
    ("table", {}, {}),
    ("feng", {"law": "feng"}, {"form": 1}),
    ("feng_fitted", {"law": "feng", "fit": "on"}, {"form": 1, "fit": 1}),
    ("closed_form", {"ell": "on", "n": 3.0}, {"form": 2, "n": 3.0}),
    ("closed_form_adhesive", {"ell": "on", "n": 3.0, "coh": "gw_adhesion", "w": 0.05},
     {"form": 2, "n": 3.0, "w": 0.05}),
    ("closed_form_plastic", {"ell": "on", "pl": "on", "n": 3.0, "h": 3e4}, {"form": 2, "pl": 1, "n": 3.0, "h": 3e4}),
]
for tag, vg, vl in CASES:
    g, l, _ = engines.side_by_side(c, "rough_impact", work, vg, vl, tag,
        "%s: LAMMPS dc/gw_rough against LIGGGHTS gw_rough" % tag, names=COLS)
    early = [r for r in l if r[1] > R and r[3] > 0.0]
    c.true(len(early) > 0 and l[-1][2] > 0 and l[-1][6] < 0 and l[-1][3] == 0.0,
           "%s: force before touch (%d steps, from %.3g um), rebound (e %.4f wall, %.4f pair)"
           % (tag, len(early), 1e6 * (max(r[1] for r in early) - R) if early else 0.0, l[-1][2] / 0.3,
              -l[-1][6] / 0.15))
    if "w" in vl:
        pull = [r for r in l if r[3] < 0.0]
        c.true(len(pull) > 0, "%s: the summits pull the wall sphere (%d steps, up to %.4g N)"
               % (tag, len(pull), -min(r[3] for r in pull) if pull else 0.0))

for tag, v in [("table", {}), ("adhesive", {"form": 2, "n": 3.0, "w": 0.05})]:
    d2, _ = engines.run("lammps", "rough_impact/in.lammps", work, ranks=2, variables=v, tag="lammps_2ranks_" + tag)
    d1, _ = engines.run("lammps", "rough_impact/in.lammps", work, variables=v, tag="lammps_1rank_" + tag)
    engines.compare(c, engines.out(d2), engines.out(d1), "%s: LAMMPS 2 ranks against 1" % tag, tol=0.0, names=COLS)

rc, text = engines.run("lammps", "rough_impact/in.lammps", work, variables={"mu": 60}, tag="bad_mu",
                       expect_error=True)
c.true(rc != 0 and "dc/gw_rough coefficient mu = 60 is outside [1, 50]" in text,
       "mu 60: error naming the sub-model, the coefficient and its range")
rc, text = engines.run("lammps", "rough_impact/in.lammps", work, variables={"w": 0.05}, tag="bad_w",
                       expect_error=True)
c.true(rc != 0 and "dc/gw_rough coefficient w = 0.05 needs form 2" in text,
       "w 0.05 with form 0: error naming the sub-model, the coefficient and what it needs")
c.finish()
