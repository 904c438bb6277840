#!/usr/bin/env python3
"""Regression (a): sphere-sphere and sphere-wall normal impacts.
- hertz_elliptic equals stock hertz (positions and velocities) to round-off,
  elastic (e = 1) and damped (e = 0.5);
- elastic impacts: collision time and maximum overlap against the analytic
  Hertz values (lecture notes, 004 seed: delta_max = (15 m v^2/(16 E* R^1/2))^(2/5),
  T_c = 2 I delta_max / v with I = int_0^1 (1 - x^(5/2))^(-1/2) dx =
  sqrt(pi) Gamma(7/5)/Gamma(9/10) = 1.4716..., i.e. the notes' 2.87 (m^2/(v R E*^2))^(1/5));
- `viscoelastic on` (Brilliantov, review Eq. 37, A = 2e-5 s): rebound
  velocities against an RK4 integration of m d''= -4/3 E* R^1/2 (d^3/2 +
  3/2 A d^1/2 d');
- every run against its committed reference (inputs/sphere_impact/reference).
Usage: check_sphere_impact.py WORKDIR [--update]"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from regress import ROOT, compare_tables, hertz_impact, impact, run, save_reference, start, subsample, table

ref_dir = os.path.join(ROOT, "inputs", "sphere_impact", "reference")
work, update, c = start()
EVERY = 10

runs = {}
for model in ("hertz", "hertz_elliptic"):
    for e in ("1.0", "0.5"):
        d = os.path.join(work, "%s_e%s" % (model, e))
        run("sphere_impact/in.sphere_impact", d, variables={"model": model, "e": e}, tag=model)
        runs[(model, e)] = os.path.join(d, "impact.txt")

d = os.path.join(work, "hertz_elliptic_visco")
run("sphere_impact/in.sphere_impact", d, variables={"model": "hertz_elliptic", "e": "1.0", "settings": "viscoelastic on"}, tag="visco")
runs[("hertz_elliptic", "visco")] = os.path.join(d, "impact.txt")

for e in ("1.0", "0.5"):
    a, b = table(runs[("hertz", e)]), table(runs[("hertz_elliptic", e)])
    compare_tables(c, b, a, 1e-14, "hertz_elliptic vs stock hertz, e=%s" % e)

# analytic elastic impact
R, rho, Y, nu = 1e-3, 2500.0, 5e6, 0.3
m = rho * 4.0 / 3.0 * math.pi * R ** 3
Estar = 1.0 / (2.0 * (1 - nu ** 2) / Y)           # two equal bodies (wall: same material)



rows = table(runs[("hertz_elliptic", "1.0")])
cases = [("sphere-sphere", m / 2, R / 2, 1.0, lambda r: 2 * R - (r[2] - r[1])),
         ("sphere-wall", m, R, 1.0, lambda r: R - r[5])]
for name, mb, Rb, v, ov in cases:
    tc, dmax = hertz_impact(mb, v, Estar, Rb)
    tc_sim, dmax_sim = impact(rows, ov)
    # velocity-Verlet with dt = 1e-7 over ~3000 steps: seen errors < 1e-7
    c.rel(dmax_sim, dmax, 1e-6, "%s maximum overlap vs analytic" % name)
    c.rel(tc_sim, tc, 1e-6, "%s collision time vs analytic" % name)
    print("     %s: T_c = %.6e s (notes' 2.87 form: %.6e), delta_max = %.6e m" %
          (name, tc_sim, 2.87 * (mb * mb / (v * Rb * Estar * Estar)) ** 0.2, dmax_sim))



def brilliantov_rebound(mb, Rb, Es, A, v, steps=200000):
    """Rebound speed of a Brilliantov viscoelastic Hertz impact (RK4)."""
    k = 4.0 / 3.0 * Es * math.sqrt(Rb) / mb
    acc = lambda d, u: -k * (max(d, 0.0) ** 1.5 + 1.5 * A * math.sqrt(max(d, 0.0)) * u)
    h = 4.0 * (15.0 * mb * v * v / (16.0 * Es * math.sqrt(Rb))) ** 0.4 / v / steps
    d, u = 0.0, v
    while True:
        k1d, k1u = u, acc(d, u)
        k2d, k2u = u + 0.5 * h * k1u, acc(d + 0.5 * h * k1d, u + 0.5 * h * k1u)
        k3d, k3u = u + 0.5 * h * k2u, acc(d + 0.5 * h * k2d, u + 0.5 * h * k2u)
        k4d, k4u = u + h * k3u, acc(d + h * k3d, u + h * k3u)
        dn = d + h / 6 * (k1d + 2 * k2d + 2 * k3d + k4d)
        un = u + h / 6 * (k1u + 2 * k2u + 2 * k3u + k4u)
        if dn < 0.0:
            return -(u + (un - u) * d / (d - dn))
        d, u = dn, un


# LIGGGHTS' velocity Verlet evaluates the damping force with the half-step
# velocity: an O(dt) error, measured 1.0e-5 and 1.4e-5 at dt = 1e-7 and
# 0.6e-5 and 0.9e-5 at dt = 5e-8 (the RK4 reference is converged to 3e-9).
last = table(runs[("hertz_elliptic", "visco")])[-1]
c.rel(last[4] - last[3], brilliantov_rebound(m / 2, R / 2, Estar, 2e-5, 1.0), 2e-5,
      "sphere-sphere viscoelastic rebound velocity vs RK4")
c.rel(last[6], brilliantov_rebound(m, R, Estar, 2e-5, 1.0), 2e-5,
      "sphere-wall viscoelastic rebound velocity vs RK4")

for (model, e), path in runs.items():
    ref = os.path.join(ref_dir, "impact_%s_e%s.txt" % (model, e))
    if update:
        save_reference(path, ref, EVERY)
    compare_tables(c, subsample(table(path), EVERY), table(ref), 1e-9, "%s e=%s vs reference" % (model, e))
c.finish()
