#!/usr/bin/env python3
"""Regression: Maugis-Dugdale adhesion in decks (jkr_elliptic with
adhesionLaw maugis and tabor; inputs/maugis_contact): a sphere pressed into
a wall and lifted, two spheres pressed together and parted (prescribed
motion), and two free spheres colliding head-on, with no damping.
The reference is an independent solution of the model here in Python:
the contact branch (Johnson & Greenwood 1997's equations, solved for m =
c/a by bisection with arcsec m = arccos(1/m), not the C code's variable s,
series or Newton), the zone-only states (closed form), and the
overlap-controlled path found by following the whole equilibrium curve
(zone c from 0 to the branch end, then the contact radius) on a grid:
a state moves along the curve while the overlap does, and where the curve
turns back (a fold) it jumps at constant overlap to the next rising part
of the curve, or apart. Checks:
- the force at every overlap of the cycle (lambda 0.37 and 0.29: the zone
  acts before touch and after the contact ends; 3.7 and 2.9: the contact
  folds) within 1e-9 of the pull-off force; the zone starts at the
  approach overlap -h0 and the attraction ends at the model's separation
  overlap (the last attached overlap within one step of it);
- the loss of a collision (lambda 2.9): the rebound speed at 1.25 v_s is
  (v^2 - v_s^2)^1/2 with v_s = (2 W / m*)^1/2, W the hysteresis loop's
  area (quadrature along the curve here); at 0.8 v_s the spheres stick
  (the zone's loop at lambda 0.29 is 1/400 of it: its jumps are checked
  in the cycle's forces);
- adhesionLaw tabor picks JKR (Tabor 32), DMT (0.03) and Maugis-Dugdale
  (3.2) as the runs with those laws named, bit for bit;
- superquadrics (inputs/superquadric_pulloff with adhesionLaw maugis: an
  ellipsoid tip off a wall, two tips off each other, the second turned by
  30 degrees): the law of the sphere of elliptic Hertz's force radius
  R_force = Rc gamma^2 (review Eqs. 5, 11, 13, evaluated here) of the tips'
  relative radii (review Eqs. 3-4), the same checks of force and separation;
- 2 MPI ranks equal 1 rank (spheres and superquadrics).
Usage: check_maugis_contact.py WORKDIR"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from regress import compare_tables, elliptic_hertz, relative_radii, run, start, table

work, _, c = start()
E, nu, w, r, rho = 5e6, 0.3, 0.5, 1e-3, 2500.0
Estar = E / (2.0 * (1 - nu ** 2))
K = 4.0 / 3.0 * Estar


class MD:
    """Maugis-Dugdale of a sphere pair (effective radius R) for the
    surfaces' equilibrium separation z0, in Johnson & Greenwood's units."""

    def __init__(self, R, z0):
        self.R = R
        sigma0 = 16 * w / (9 * math.sqrt(3) * z0)      # Lennard-Jones' largest stress
        self.lam = 2 * sigma0 * (R / (math.pi * w * K * K)) ** (1 / 3)
        self.sd = (math.pi ** 2 * w * w * R / K ** 2) ** (1 / 3)
        self.sF = math.pi * w * R
        lam = self.lam
        A, B = math.pi * lam / 4, 4 * lam * lam / 3 * (math.pi / 2 - 1)
        self.c0 = (-B + math.sqrt(B * B + 4 * A)) / (2 * A)   # the branch end's zone radius
        # the curve: t in [0, c0] the zone's radius, t > c0 the contact radius a = t - c0
        n = 3000
        ts = [self.c0 * k / n for k in range(n + 1)]
        amax = 3.0
        ts += [self.c0 + amax * (k / n) ** 1.5 for k in range(1, n + 1)]
        self.t = ts
        self.D = [self.at(x)[1] for x in ts]

    def m_of(self, a):
        lam = self.lam
        f = lambda m: (lam * a * a / 2 * (math.sqrt(m * m - 1) + (m * m - 2) * math.acos(1 / m))
                       + 4 * lam * lam * a / 3 * (math.sqrt(m * m - 1) * math.acos(1 / m) - m + 1) - 1)
        lo, hi = 1.0, 2.0
        while f(hi) < 0:
            lo, hi = hi, 2 * hi
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if mid in (lo, hi):
                break
            lo, hi = (mid, hi) if f(mid) < 0 else (lo, mid)
        return 0.5 * (lo + hi)

    def at(self, t):
        """(P, D) on the curve."""
        lam = self.lam
        if t <= self.c0:   # the zone alone: gap h0 at r = c, uniform stress sigma0 inside
            return -math.pi / 2 * lam * t * t, t * t / 2 - 8 * lam * t / (3 * math.pi) - 2 / (math.pi * lam)
        a = t - self.c0
        m = self.m_of(a)
        s = math.sqrt(m * m - 1)
        return a ** 3 - lam * a * a * (s + m * m * math.acos(1 / m)), a * a - 4 * lam * a * s / 3

    def solve(self, k, D, lo=None):
        """t in cell k (D rising across it; from lo if given) with D(t) = D, by bisection."""
        lo, hi = self.t[k] if lo is None else lo, self.t[k + 1]
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if mid in (lo, hi):
                break
            lo, hi = (mid, hi) if self.at(mid)[1] < D else (lo, mid)
        return 0.5 * (lo + hi)

    def rising(self, k):
        return self.D[k + 1] > self.D[k]

    def fold(self, k):
        """The least D near cell k (golden section over cells k-1..k+1): (t, D)."""
        lo, hi = self.t[max(k - 1, 0)], self.t[min(k + 2, len(self.t) - 1)]
        g = (3 - math.sqrt(5)) / 2
        for _ in range(200):
            x1, x2 = lo + g * (hi - lo), hi - g * (hi - lo)
            if self.at(x1)[1] <= self.at(x2)[1]:
                hi = x2
            else:
                lo = x1
            if hi - lo < 1e-15 * (1 + hi):
                break
        x = 0.5 * (lo + hi)
        return x, self.at(x)[1]

    def path(self, Ds, solve=lambda i: True):
        """The overlap-controlled states along the overlaps Ds: per overlap
        the curve's parameter t (where solve(index)), or None (apart)."""
        out, k = [], None
        for i, D in enumerate(Ds):
            if k is None:
                if D >= self.D[0]:   # the zone reaches the surfaces: the first rising crossing
                    k = next((j for j in range(len(self.t) - 1) if self.rising(j) and self.D[j] <= D <= self.D[j + 1]), None)
            else:
                while k + 1 < len(self.t) - 1 and D > self.D[k + 1]:
                    k += 1
                while k is not None and D < self.D[k]:
                    if k > 0 and self.rising(k - 1):
                        k -= 1
                        continue
                    tf, Df = self.fold(k)   # the curve turns back here
                    if D >= Df:
                        break
                    # the jump: the next rising part at smaller t, or apart
                    k = next((j for j in range(k - 1, -1, -1) if self.rising(j) and self.D[j] <= D <= self.D[j + 1]), None)
            if k is not None and not solve(i):
                out.append(self.t[k])   # attached, not solved here
            elif k is not None and not (self.D[k] <= D):
                out.append(self.fold_solve(k, D))
            else:
                out.append(None if k is None else self.solve(k, D))
        return out

    def fold_solve(self, k, D):
        """D lies between the fold and cell k's lower end: the rising side of the fold."""
        return self.solve(k, D, lo=self.fold(k)[0])

    def loss(self):
        """The work a collision loses (J): minus the integral of P dD along
        the curve from the retraction's last fold to the approach's landing
        point (trapezoid in D, Richardson on 2 grids)."""
        lam = self.lam
        t_in = self.path([-2 / (math.pi * lam)])[0]
        # the retraction ends at the curve's least D below t_in
        k = min(range(len(self.t) - 1), key=lambda j: self.D[j] if self.t[j] < t_in else 1e300)
        t_f = self.fold(k)[0]

        def trap(n):
            pts = [self.at(t_f + (t_in - t_f) * j / n) for j in range(n + 1)]
            return sum(0.5 * (pts[j][0] + pts[j + 1][0]) * (pts[j + 1][1] - pts[j][1]) for j in range(n))

        I1, I2 = trap(1000), trap(2000)
        return -(I2 + (I2 - I1) / 3) * self.sF * self.sd


mstar = rho * 4 / 3 * math.pi * r ** 3 / 2
cases = {}
for z0 in (1e-5, 1e-6):
    pair = MD(r / 2, z0)
    vs = math.sqrt(2 * pair.loss() / mstar)
    cases[z0] = vs
    print("     z0 %g: lambda %.4g (pair), %.4g (wall); sticking speed v_s = %.6g m/s" % (z0, pair.lam, MD(r, z0).lam, vs))

runs = {}


def go(name, ranks=1, **v):
    d = os.path.join(work, name)
    run("maugis_contact/in.maugis_contact", d, ranks=ranks, variables=v, tag=name)
    runs[name] = table(os.path.join(d, "cycle.txt"))
    return runs[name]


go("zone", z0=1e-5)
go("zone_np2", ranks=2, z0=1e-5)
go("fold", z0=1e-6, v=1.25 * cases[1e-6])
go("fold_stick", z0=1e-6, v=0.8 * cases[1e-6])
go("tabor_md", alaw="tabor", z0=1e-6, v=1.25 * cases[1e-6])
for name, ranks in (("sq", 1), ("sq_np2", 2)):
    d = os.path.join(work, name)
    run("superquadric_pulloff/in.superquadric_pulloff", d, ranks=ranks, tag=name,
        variables={"alaw": "maugis", "w": w, "omega": 30.0, "z0": 1e-6, "steps": 6000})
    runs[name] = table(os.path.join(d, "pulloff.txt"))
for law in ("jkr", "dmt"):
    z0 = 1e-7 if law == "jkr" else 1e-4
    go("tabor_" + law, alaw="tabor", z0=z0)
    go(law, alaw=law, z0=z0)

# the prescribed cycles against the independent solution
a1, b1, c1 = 0.001, 0.0006, 0.0015     # superquadric_pulloff's ellipsoids: atom 1, c axis down
a2, b2, c2 = 0.0015, 0.0006, 0.001     # atoms 2 and 3, a axis along x, atom 3 turned by 30 degrees
Rp = relative_radii(a2 / b2 ** 2, a2 / c2 ** 2, a2 / b2 ** 2, a2 / c2 ** 2, math.radians(30.0))
for name, z0 in (("zone", 1e-5), ("fold", 1e-6), ("sq", 1e-6)):
    rows = runs[name]
    if name == "sq":
        R_force = lambda R1, R2: elliptic_hertz(R1, R2)[0] * elliptic_hertz(R1, R2)[1] ** 2
        cases_here = (("ellipsoid-wall", R_force(a1 * a1 / c1, b1 * b1 / c1), lambda q: c1 - q[1], lambda q: q[2]),
                      ("ellipsoid-ellipsoid", R_force(*Rp), lambda q: 2 * a2 - (q[4] - q[3]), lambda q: -q[5]))
    else:
        cases_here = (("sphere-wall", r, lambda q: r - q[1], lambda q: q[2]),
                      ("sphere-sphere", r / 2, lambda q: 2 * r - (q[4] - q[3]), lambda q: -q[5]))
    for what, R, overlap, force in cases_here:
        md = MD(R, z0)
        Ds = [overlap(q) / md.sd for q in rows]
        on = [i for i in range(1, len(rows)) if (force(rows[i]) == 0.0) != (force(rows[i - 1]) == 0.0)]
        near = set(j for i in on for j in range(i - 3, i + 3))
        keep = lambda i: i % 3 == 0 or i in near   # every third row, and every row where the force starts or ends
        ts = md.path(Ds, keep)
        Fc = 1.5 * md.sF
        worst, n_contact, n_zone = 0.0, 0, 0
        for i, (q, D, t) in enumerate(zip(rows, Ds, ts)):
            if not keep(i):
                continue
            want = 0.0 if t is None else md.at(t)[0] * md.sF
            worst = max(worst, abs(force(q) - want) / Fc)
            if t is not None:
                n_contact += t > md.c0
                n_zone += t <= md.c0
        c.true(worst < 1e-9, "%s %s (lambda %.3g): force along the cycle against the model, worst %.3g of 3/2 pi w R "
               "(tol 1e-9; %d rows in contact, %d with the zone alone)" % (name, what, md.lam, worst, n_contact, n_zone))
        # where the attraction starts and ends: the approach at -h0 = -2/(pi lambda) sd, the last attached state
        att = [i for i, q in enumerate(rows) if force(q) != 0.0]
        step = 2e-9 / md.sd
        D_first, D_last = Ds[att[0]], Ds[att[-1]]
        D_in = -2 / (math.pi * md.lam)
        if name != "sq":   # the superquadrics start pressed together
            c.true(D_in <= D_first < D_in + step * 1.01 and Ds[att[0] - 1] < D_in,
                   "%s %s: the zone reaches across at the approach overlap -h0 = %.6g m (first force at %.6g m)"
                   % (name, what, D_in * md.sd, D_first * md.sd))
        k = min(range(len(md.t) - 1), key=lambda j: md.D[j])
        t_sep, D_sep = md.fold(k)
        c.true(D_sep <= D_last < D_sep + step * 1.01 and Ds[att[-1] + 1] < D_sep,
               "%s %s: kept to the model's separation overlap %.6g m (%s; last force at %.6g m)"
               % (name, what, D_sep * md.sd, "the zone's fold" if t_sep <= md.c0 else "the contact's fold",
                  D_last * md.sd))

    if name != "fold":
        continue
    # the collision: rebound at 1.25 v_s
    vs = cases[z0]
    last = rows[-1]
    c.rel(last[9] - last[8], math.sqrt((1.25 * vs) ** 2 - vs ** 2), 2e-4,
          "%s: rebound speed at 1.25 v_s vs (v^2 - v_s^2)^1/2 (the loop's loss)" % name)

stick = runs["fold_stick"][-1]
md = MD(r / 2, 1e-6)
gap = stick[7] - stick[6] - 2 * r
c.true(stick[10] != 0.0 and gap < md.sd, "at 0.8 v_s the spheres stick: gap %.3g m, force %.3g N" % (gap, stick[10]))
compare_tables(c, runs["zone_np2"], runs["zone"], 1e-13, "spheres: 2 ranks equal 1 rank")
compare_tables(c, runs["sq_np2"], runs["sq"], 1e-13, "superquadrics: 2 ranks equal 1 rank")
compare_tables(c, runs["tabor_md"], runs["fold"], 0.0, "tabor at Tabor 3.2 and 2.5: Maugis-Dugdale")
compare_tables(c, runs["tabor_jkr"], runs["jkr"], 0.0, "tabor at Tabor 32 and 25: JKR")
compare_tables(c, runs["tabor_dmt"], runs["dmt"], 0.0, "tabor at Tabor 0.032 and 0.025: DMT")
c.finish()
