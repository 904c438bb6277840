#!/usr/bin/env python3
"""Reference table for the Jamari-Schipper elastic-plastic law (jamari_ep).

Independent of the C code: mpmath at 50 digits, the Hertz eccentricity by
bisection on review Eq. 13 (ratio the right way up, as in gen_hertz_elliptic.py),
the loading curve from review Eqs. 1-2 and 41-46 as printed (Eq. 43 with
(R_i R_j)^1/2; Eq. 44 with lambda = (R_minor/R_major)^1/2 and with the
other ratio), and the unloading branch of dc/jamari_ep.h in its own form:
a Hertz contact with Rc scaled by s, where the recovery u = delta_max -
delta_res and s_A solve F* = 4/3 E* (s_A Rc)^1/2 gamma u^3/2 and A_max =
pi s_A Rc beta u together, F* = min(F_max, Hertz force at delta_max), then s
from F_max = 4/3 E* (s Rc)^1/2 gamma u^3/2 (s >= 1 asserted), and
F = min(4/3 E* (s Rc)^1/2 gamma (delta - delta_res)^3/2, F_load).

Checks made here (assertions): both printed forms of Eq. 41 agree; Eq. 44
equals c_A Rc beta/(2 (R_i R_j)^1/2) and is the same for lambda and
1/lambda; F and A are continuous at delta_n1 and delta_n2; the slopes there
equal the closed forms of the header (kappa); the branch is continuous at
delta_max; the dissipated energy is >= 0.

Writes jamari_ep.csv beside this script, rows tagged by their first field:
  case,id,R1,R2,Estar,H,K_v,c_h,c_A
  limits,id,delta_n1,delta_n2
  path,id,delta,F,area,a,kn,delta_res   (a load-unload-reload path, in order;
        delta_res is the history after the step, 0 before first yield)
  energy,id,delta_max,D                (int F_load - int F_unload, one cycle)
  fig8,ratio,delta_n2/(c_A delta_n1)   (R_minor/R_major; review Fig. 8)
Run: python3 gen_jamari_ep.py
"""
import os
import mpmath as mp

mp.mp.dps = 50
here = os.path.dirname(os.path.abspath(__file__))


def eccentricity(r):
    """m1 = 1 - e^2 from Eq. 13 in the form e^2 = 1 - r E/((1+r) K - E), by bisection in ln m1."""
    r = mp.mpf(r)
    if r == 1:
        return mp.mpf(1)

    def g(x):
        m1 = mp.exp(x)
        m = 1 - m1
        K, E = mp.ellipk(m), mp.ellipe(m)
        return (m1 * ((1 + r) * K - E) - r * E) / m

    lo, hi = 2 * mp.log(r) - 10, mp.mpf(-1e-30) * (1 - r)
    assert g(lo) * g(hi) < 0
    for _ in range(400):
        mid = (lo + hi) / 2
        if g(mid) * g(hi) > 0:
            hi = mid
        else:
            lo = mid
        if hi - lo < mp.mpf(10) ** -45:
            break
    return mp.exp((lo + hi) / 2)


class Law:
    def __init__(self, R1, R2, Estar, H, Kv, ch, cA):
        self.Ri, self.Rj = mp.mpf(max(R1, R2)), mp.mpf(min(R1, R2))
        self.Es, self.H, self.Kv, self.ch, self.cA = (mp.mpf(v) for v in (Estar, H, Kv, ch, cA))
        r = self.Rj / self.Ri
        self.m1 = eccentricity(r)
        m = 1 - self.m1
        self.K, self.E = mp.ellipk(m), mp.ellipe(m)
        self.Rc = self.Ri * self.Rj / (self.Ri + self.Rj)                                        # Eq. 5
        self.gamma = mp.pi * mp.sqrt(2) * mp.sqrt(self.E) / (2 * self.K ** 1.5 * mp.sqrt(self.m1))  # Eq. 11
        self.beta = 2 * self.E / (self.K * mp.sqrt(self.m1))                                      # Eq. 12
        KvH = self.Kv * self.H
        d1a = mp.pi ** 2 / 4 * self.Rc * self.beta ** 2 / self.gamma ** 2 * KvH ** 2 / self.Es ** 2   # Eq. 41, form 1
        d1b = 2 * self.Rc * KvH ** 2 / self.Es ** 2 * self.E * self.K                              # Eq. 41, form 2
        assert abs(d1a / d1b - 1) < mp.mpf(10) ** -40, (d1a, d1b)
        self.d1 = d1a
        lam = mp.sqrt(r)
        f44 = lambda l: self.cA * (l / (1 + l ** 2)) / mp.sqrt(self.m1) * self.E / self.K        # Eq. 44
        d2 = f44(lam) * self.d1
        assert abs(f44(1 / lam) * self.d1 / d2 - 1) < mp.mpf(10) ** -40
        assert abs(d2 / (self.cA * self.Rc * self.beta / (2 * mp.sqrt(self.Ri * self.Rj)) * self.d1) - 1) < mp.mpf(10) ** -40
        self.ratio44 = d2 / (self.cA * self.d1)
        self.d2 = max(d2, self.d1)
        self.Ap = 2 * mp.pi * mp.sqrt(self.Ri * self.Rj)                                         # Eq. 42 / delta

    def hertz(self, d):
        return 4 * self.Es * mp.sqrt(self.Rc) * d ** 1.5 * self.gamma / 3, mp.pi * self.Rc * d * self.beta   # Eqs. 1-2

    def load(self, d):
        """(F, A) on the loading curve."""
        d = mp.mpf(d)
        if d <= 0:
            return mp.mpf(0), mp.mpf(0)
        if d <= self.d1:
            return self.hertz(d)
        if d >= self.d2:
            A = self.Ap * d                                                  # Eq. 42
            return A * self.ch * self.H, A                                   # Eq. 43 (R_i R_j)
        t = (d - self.d1) / (self.d2 - self.d1)
        Ae = mp.pi * self.Rc * d * self.beta
        A = Ae + (self.Ap * d - Ae) * (3 * t ** 2 - 2 * t ** 3)              # Eq. 46
        p = self.ch * self.H - self.H * (self.ch - 2 * self.Kv / 3) * \
            (mp.log(self.d2) - mp.log(d)) / (mp.log(self.d2) - mp.log(self.d1))   # Eq. 45
        return A * p, A

    def branch(self, dmax):
        """(s, delta_res, F_max, A_max) of the unloading branch from dmax > d1."""
        Fm, Am = self.load(dmax)
        c = 4 * self.Es * mp.sqrt(self.Rc) * self.gamma / 3
        # the Hertz patch of area A_max with radii s Rc: A_max = pi s Rc beta u
        # and, for the elastic part of the force F* = min(F_max, Hertz at
        # dmax), F* = c s^1/2 u^3/2; so s u = L, u = F*/(c L^1/2)
        L = Am / (mp.pi * self.Rc * self.beta)
        u = min(Fm, self.hertz(dmax)[0]) / (c * mp.sqrt(L))
        s = (Fm / (c * u ** 1.5)) ** 2          # the branch through (dmax, F_max)
        assert s >= 1
        return s, dmax - u, Fm, Am

    def unload(self, d, dmax):
        """(F, A, capped) on the branch from dmax, capped by the loading force."""
        d = mp.mpf(d)
        s, dres, Fm, Am = self.branch(dmax)
        if d <= dres:
            return mp.mpf(0), mp.mpf(0), False
        Fb = 4 * self.Es * mp.sqrt(s * self.Rc) * self.gamma * (d - dres) ** 1.5 / 3
        A = Am * (d - dres) / (dmax - dres)
        Fl = self.load(d)[0]
        return (Fl, A, True) if Fl < Fb else (Fb, A, False)

    def semi_axis(self, A):
        return mp.sqrt(A / (mp.pi * mp.sqrt(self.m1)))

    def energy(self, dmax):
        """int_0^dmax F_load - int_dres^dmax F_unload (capped)."""
        dmax = mp.mpf(dmax)
        pts = [mp.mpf(0)] + [x for x in (self.d1, self.d2) if x < dmax] + [dmax]
        W = mp.quad(lambda x: self.load(x)[0], pts)
        if dmax <= self.d1:
            return W - mp.quad(lambda x: self.hertz(x)[0], [0, dmax])
        dres = self.branch(dmax)[1]
        # the cap switches where F_branch = F_load: split there
        n = 64
        grid = [dres + (dmax - dres) * k / n for k in range(n + 1)]
        pts = sorted(set(grid + [x for x in (self.d1, self.d2) if dres < x < dmax]))
        Wu = mp.quad(lambda x: self.unload(x, dmax)[0], pts)
        return W - Wu


def deriv(f, d, side):
    """One-sided derivative of f at d (side +1 / -1), by a degree-8 polynomial fit."""
    return mp.diff(f, mp.mpf(d), direction=side)


CASES = [
    # id, R1, R2, Estar, H, K_v, c_h, c_A, peaks (in delta_n1): the path loads
    # to peak 1, unloads past delta_res, reloads to peak 1, loads to peak 2,
    # unloads again
    (1, 1e-3, 1e-3, 1.15e11, 2e9, 0.454 + 0.41 * 0.3, 1.0, 108.0, (20.0, 200.0)),   # steel sphere
    (2, 2e-3, 1e-3, 3.9e10, 1e9, 0.454 + 0.41 * 0.33, 1.0, 108.0, (7.0, 90.0)),     # aluminium ellipse
    (3, 0.5, 5e-4, 1e11, 3e9, 0.454 + 0.41 * 0.0, 1.0, 108.0, (1.3, 60.0)),         # slender, nu = 0: kappa > 1/2
    (4, 2e-3, 2e-3, 7e10, 1.5e9, 0.6, 1.8, 2.5, (1.1, 3.1)),                       # delta_n2 = 1.25 delta_n1: cap
    (5, 4e-3, 1e-3, 2e11, 4e9, 0.454 + 0.41 * 0.28, 1.2, 2.0, (1.45, 4.2)),           # Eq. 44 < delta_n1: jump
    (6, 1e-3, 1e-3, 1.15e11, 2e9, 0.454, 1.0, 108.0, (1.05, 30.0)),                 # sphere, nu = 0
]


def path_of(law, peaks):
    d1 = float(law.d1)
    p1, p2 = peaks[0] * d1, peaks[1] * d1
    load1 = [d1 * f for f in (0.25, 0.7, 0.99)] + [d1 + (p1 - d1) * k / 6 for k in range(1, 7)]
    down = lambda top: [top * (1 - k / 12) for k in range(1, 13)] + [-0.05 * d1]
    load2 = [p1 + (p2 - p1) * k / 8 for k in range(1, 9)]
    un1 = down(p1)
    re1 = list(reversed(un1))[1:]          # reload through the same overlaps
    return load1 + un1 + re1 + load2 + down(p2)


def main():
    rows = []
    for cid, R1, R2, Es, H, Kv, ch, cA, peaks in CASES:
        law = Law(R1, R2, Es, H, Kv, ch, cA)
        rows.append("case,%d,%r,%r,%r,%r,%r,%r,%r" % (cid, R1, R2, Es, H, Kv, ch, cA))
        rows.append("limits,%d,%s,%s" % (cid, mp.nstr(law.d1, 25), mp.nstr(law.d2, 25)))
        # continuity and slopes at delta_n1, delta_n2 (the review's regimes)
        F1h = law.hertz(law.d1)
        F = lambda x: law.load(x)[0]
        Lq = mp.log(law.d2 / law.d1)
        if law.d2 > law.d1:
            t1 = (law.d2 - law.d1) * mp.mpf(10) ** -30
            assert abs(F(law.d1 + t1) / F1h[0] - 1) < mp.mpf(10) ** -25
            assert abs(law.load(law.d1 + t1)[1] / F1h[1] - 1) < mp.mpf(10) ** -25
            Fp = law.load(law.d2)
            Fm = law.load(law.d2 - t1)
            assert abs(Fm[0] / Fp[0] - 1) < mp.mpf(10) ** -25 and abs(Fm[1] / Fp[1] - 1) < mp.mpf(10) ** -25
            kappa = (law.ch - 2 * law.Kv / 3) / (2 * law.Kv / 3 * Lq)
            h = (law.d2 - law.d1) * mp.mpf(10) ** -20
            s1 = (F(law.d1 + 2 * h) - F(law.d1 + h)) / h
            assert abs(s1 / ((1 + kappa) * F1h[0] / law.d1) - 1) < mp.mpf(10) ** -15
            s2 = (F(law.d2 - h) - F(law.d2 - 2 * h)) / h
            want = (1 + (law.ch - 2 * law.Kv / 3) / (law.ch * Lq)) * Fp[0] / law.d2
            assert abs(s2 / want - 1) < mp.mpf(10) ** -15
            print("case %d: delta_n2/delta_n1 = %s, kappa = %s" % (cid, mp.nstr(law.d2 / law.d1, 8), mp.nstr(kappa, 6)))
        else:
            print("case %d: Eq. 44 gives %s delta_n1 (< 1): no elastic-plastic range" %
                  (cid, mp.nstr(law.cA * law.ratio44, 8)))
        dmax = mp.mpf(0)
        capped_rows = 0
        for d in path_of(law, peaks):
            D = mp.mpf(d)
            if D >= dmax:
                Fv, Av = law.load(D)
                active = F
                if D > law.d1:
                    dmax = D
                dres = law.branch(dmax)[1] if dmax > law.d1 else mp.mpf(0)
                # stay clear of the regime boundaries (slopes jump there)
                assert abs(D / law.d1 - 1) > 1e-6 and abs(D / law.d2 - 1) > 1e-6
            else:
                Fv, Av, capped = law.unload(D, dmax)
                s, dres, Fm_, Am_ = law.branch(dmax)
                if D <= dres:
                    active = None
                else:
                    # clear of delta_res (cancellation in delta - delta_res) and of the cap's switch
                    assert (D - dres) / (dmax - dres) > 1e-3, (cid, d)
                    Fb = 4 * law.Es * mp.sqrt(s * law.Rc) * law.gamma * (D - dres) ** 1.5 / 3
                    assert abs(law.load(D)[0] / Fb - 1) > 1e-6, (cid, d)
                    capped_rows += capped
                    active = F if capped else \
                        (lambda x, s=s, dres=dres: 4 * law.Es * mp.sqrt(s * law.Rc) * law.gamma * (x - dres) ** 1.5 / 3)
                    assert abs(D / law.d1 - 1) > 1e-6 and abs(D / law.d2 - 1) > 1e-6
            kn = deriv(active, D, 1) if active is not None else mp.mpf(0)
            a = law.semi_axis(Av)
            rows.append("path,%d,%r,%s,%s,%s,%s,%s" % (cid, d, mp.nstr(Fv, 20), mp.nstr(Av, 20), mp.nstr(a, 20),
                                                     mp.nstr(kn, 20), mp.nstr(dres, 20)))
        # continuity of the branch at delta_max, and the energy of one cycle
        for f in (1.0 + 1e-6, 1.01, 1.3, 3.0, 30.0, 300.0):
            dm = law.d1 * f
            s, dres, Fm_, Am_ = law.branch(dm)
            assert dres > 0, (cid, f)
            Fb = law.unload(dm, dm)
            assert abs(Fb[0] / Fm_ - 1) < mp.mpf(10) ** -40
            D = law.energy(dm)
            assert D >= 0, (cid, f, D)
            rows.append("energy,%d,%r,%s" % (cid, float(dm), mp.nstr(D, 20)))
        print("case %d: %d capped rows on the path" % (cid, capped_rows))
    for r in (1.0, 0.9, 0.8, 0.7, 0.6, 0.5, 0.3, 0.1, 0.01, 1e-3, 1e-6, 1e-9, 1e-12):
        law = Law(1.0, r, 1e11, 1e9, 0.5, 1.0, 108.0)
        rows.append("fig8,%r,%s" % (r, mp.nstr(law.ratio44, 20)))
    with open(os.path.join(here, "jamari_ep.csv"), "w") as f:
        f.write("# generated by gen_jamari_ep.py (mpmath, 50 digits)\n")
        f.write("# case,id,R1,R2,Estar,H,K_v,c_h,c_A | limits,id,delta_n1,delta_n2 |\n")
        f.write("# path,id,delta,F,area,a,kn,delta_res | energy,id,delta_max,D | fig8,ratio,delta_n2/(c_A delta_n1)\n")
        for r in rows:
            f.write(r + "\n")


if __name__ == "__main__":
    main()
