#!/usr/bin/env python3
"""Regression: adhesive superquadrics pulled apart at constant speed with
jkr_elliptic (w = 0.5 J/m^2): an ellipsoid tip off a wall, and two
ellipsoid tips (the second turned by 30 degrees) off each other.
- the force along the trajectory against the Johnson-Greenwood elliptic JKR
  law (review Eqs. 19-23, Eq. 20 as printed, lambda^2 = R_minor/R_major)
  evaluated here independently of c_core: elliptic integrals by the AGM, the
  stable branch inverted by bisection in the axis ratio g, with the relative
  radii of the tips from review Eqs. 3-4, at the overlap known from the
  prescribed positions (negative after the surfaces part: this checks the
  gap measured by the plugin too);
- the pull-off force (minimum force along the branch) and the separation
  overlap (the contact ends within one step of it);
- viscoelastic damping: the force minus the elastic JKR force equals
  A (d delta/dt) pi E* a / K(e^2) (dc/dissipation_adhesive.h);
- w = 0: jkr_elliptic equals hertz_elliptic exactly;
- 2 MPI ranks (the pair straddles the ranks) equal 1 rank; reference output.
Usage: check_superquadric_pulloff.py WORKDIR [--update]"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from regress import ROOT, compare_tables, ellipke, relative_radii, run, save_reference, start, subsample, table

work, update, c = start()
EVERY = 10

Y, nu, w, omega, A = 5e6, 0.3, 0.5, 30.0, 1e-5
Estar = 1.0 / (2.0 * (1 - nu ** 2) / Y)
a1, b1, c1 = 0.001, 0.0006, 0.0015                # atom 1, c axis down
a2, b2, c2 = 0.0015, 0.0006, 0.001                # atoms 2 and 3, a axis along x
speed, dt = 0.02, 1e-7                            # d delta/dt = -speed in both cases


class JG:
    """Johnson-Greenwood elliptic JKR for relative radii R1, R2 (review
    Eqs. 19-23), parametrised by the contact axis ratio g = b/a."""

    def __init__(self, R1, R2):
        self.Rmaj, self.Rmin = max(R1, R2), min(R1, R2)
        self.lam = math.sqrt(self.Rmin / self.Rmaj)
        self.Rh = math.sqrt(R1 * R2)
        self.gH = self.bisect(lambda g: self.terms(g)[0], 1e-3, 1.0 - 1e-9)
        self.g_break = self.golden(lambda g: self.state(g)[0])
        self.g_pull = self.golden(lambda g: self.state(g)[1])

    def terms(self, g):
        m = 1.0 - g * g
        K, E = ellipke(m)
        D = (K - E) / m
        B = K - D
        C = (D - B) / m
        lam = self.lam
        Pi2 = ((lam * lam + 1) * C + D) / (lam * ((D + C) * (B + g * g * C) - g * g * C * C))  # Eq. 23
        Pi1 = (lam + 1.0 / lam - B * Pi2) / D                                              # Eq. 22
        return Pi2 * g * g - Pi1, Pi1, Pi2, K, B, D

    def state(self, g):
        """(delta, F, a, e^2) at axis ratio g (Eqs. 19-21)."""
        Q, Pi1, Pi2, K, B, D = self.terms(g)
        u = 1.0 - math.sqrt(g)
        T = (Pi1 - Pi2 * g ** 2.5) / u
        pref = g * u * u / (Q * Q)
        F = 3 * math.pi * self.Rh * w * 8.0 / (3 * math.pi) * pref * (T - (Pi2 * g * g + Pi1) / 3.0)
        dbar = (2 ** 3.5 / (9 * math.pi ** 2)) ** (2.0 / 3.0) * pref ** (2.0 / 3.0) * (2 * K * T - Pi1 * B - g * g * Pi2 * D)
        delta = dbar / (4 * Estar / (9 * math.pi * w * math.sqrt(self.Rh))) ** (2.0 / 3.0)
        Abar = (4 * math.sqrt(2) / (3 * math.pi) * g ** 1.25 * u / abs(Q)) ** (4.0 / 3.0)
        area = Abar / (4 * Estar / (9 * math.pi ** 2.5 * w * self.Rh ** 2)) ** (2.0 / 3.0)
        return delta, F, math.sqrt(area / (math.pi * g)), 1.0 - g * g

    @staticmethod
    def bisect(f, lo, hi):
        flo = f(lo)
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if (f(mid) > 0) == (flo > 0):
                lo, flo = mid, f(mid)
            else:
                hi = mid
        return 0.5 * (lo + hi)

    def golden(self, f):
        lo, hi = self.gH * (1 + 1e-9), 1.0 - 1e-9
        r = (math.sqrt(5) - 1) / 2
        x1, x2 = hi - r * (hi - lo), lo + r * (hi - lo)
        f1, f2 = f(x1), f(x2)
        for _ in range(120):
            if f1 < f2:
                hi, x2, f2 = x2, x1, f1
                x1 = hi - r * (hi - lo)
                f1 = f(x1)
            else:
                lo, x1, f1 = x1, x2, f2
                x2 = lo + r * (hi - lo)
                f2 = f(x2)
        return 0.5 * (lo + hi)

    def at_overlap(self, delta):
        """State on the stable branch (g between the Hertz shape and the
        separation point, where delta decreases with g)."""
        g = self.bisect(lambda g: self.state(g)[0] - delta, self.gH * (1 + 1e-12), self.g_break)
        return self.state(g)


runs = {}
for name, extra, ranks in (("jkr", {}, 1), ("jkr_np2", {}, 2), ("visc", {"A": A}, 1),
                           ("w0", {"w": 0.0}, 1), ("w0_he", {"w": 0.0, "smooth": 1}, 1)):
    d = os.path.join(work, name)
    v = {"w": w, "omega": omega}
    v.update(extra)
    run("superquadric_pulloff/in.superquadric_pulloff", d, ranks=ranks, variables=v, tag=name)
    runs[name] = table(os.path.join(d, "pulloff.txt"))

rows, visc = runs["jkr"], runs["visc"]
cases = [("ellipsoid-wall", JG(a1 * a1 / c1, b1 * b1 / c1), lambda r: c1 - r[1], lambda r: r[2]),
         ("ellipsoid-ellipsoid", JG(*relative_radii(a2 / b2 ** 2, a2 / c2 ** 2, a2 / b2 ** 2, a2 / c2 ** 2,
                                                   math.radians(omega))),
          lambda r: 2 * a2 - (r[4] - r[3]), lambda r: -r[5])]
for name, law, overlap, force in cases:
    d_break, F_break = law.state(law.g_break)[:2]
    F_pull = law.state(law.g_pull)[1]
    print("     %s: radius ratio %.4f, pull-off force %.6g N (%.4f of 1.5 pi w Rhat), separation overlap %.6g m"
          % (name, law.Rmin / law.Rmaj, -F_pull, -F_pull / (1.5 * math.pi * w * law.Rh), d_break))
    touching = [r for r in rows if force(r) != 0.0]
    last = min(overlap(r) for r in touching)
    c.true(d_break <= last < d_break + 1.01 * speed * dt,
           "%s: contact kept down to the separation overlap (last %.6g, separation %.6g)" % (name, last, d_break))
    c.true(all(force(r) == 0.0 for r in rows if overlap(r) < d_break), "%s: no force past separation" % name)
    c.rel(min(force(r) for r in touching), F_pull, 1e-6, "%s: pull-off force vs elliptic JKR" % name)
    worst, worst_v, n, apart = 0.0, 0.0, 0, 0
    for r, rv in zip(rows[::EVERY], visc[::EVERY]):
        d = overlap(r)
        if force(r) == 0.0 or d < d_break + 1e-3 * abs(d_break):
            continue
        delta, F, a, e2 = law.at_overlap(d)
        scale = abs(F_pull)
        worst = max(worst, abs(force(r) - F) / scale)
        k_punch = math.pi * Estar * a / ellipke(e2)[0]
        worst_v = max(worst_v, abs(force(rv) - F - A * (-speed) * k_punch) / scale)
        apart += d < 0.0
        n += 1
    c.true(n > 30 and apart > 10, "%s: %d compared rows, %d with the surfaces apart" % (name, n, apart))
    c.true(worst < 1e-9, "%s: force vs elliptic JKR (scale: pull-off force): worst %.3g (tol 1e-9)" % (name, worst))
    c.true(worst_v < 1e-9, "%s: viscoelastic force - JKR force vs A d(delta)/dt k_punch: worst %.3g (tol 1e-9)"
           % (name, worst_v))

compare_tables(c, runs["w0"], runs["w0_he"], 0.0, "w = 0: jkr_elliptic equals hertz_elliptic")
compare_tables(c, runs["jkr_np2"], rows, 1e-13, "2 ranks equal 1 rank")
ref = os.path.join(ROOT, "inputs", "superquadric_pulloff", "reference", "pulloff.txt")
if update:
    save_reference(os.path.join(work, "jkr", "pulloff.txt"), ref, EVERY)
compare_tables(c, subsample(rows, EVERY), table(ref), 1e-9, "vs reference")
c.finish()
