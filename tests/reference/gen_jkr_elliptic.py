#!/usr/bin/env python3
"""Reference tables for c_core/src/jkr_elliptic.c (elliptic JKR after
Johnson & Greenwood 2005, review Eqs. 19-28, and classical JKR).

Independent of the C code and of the closed forms in jkr_elliptic.h: the
contact problem is solved from first principles with mpmath.

  pressure   p = (al + be X^2 + ga Y^2) / sqrt(1 - X^2 - Y^2),  X = x/a, Y = y/b
  Estar * displacement (sum of both bodies) inside the ellipse is
     al U_P + be U_X + ga U_Y,  with U_H the Hertz-density potential
     U_H = (a b / 2) int_0^oo [1 - x^2/(a^2+s) - y^2/(b^2+s)] ds / S(s),
     S = sqrt((a^2+s)(b^2+s)s),  U_X = a dU_H/da,  U_Y = b dU_H/db,
     U_P = U_H + U_X + U_Y   (the derivatives taken under the integral),
  all integrals by mpmath quadrature.
  Curvatures: x^2 and y^2 coefficients = -Estar/(2 R_major), -Estar/(2 R_minor).
  Energy release rate w = K_I^2/(2 Estar) at the end of each axis:
     (al + be) sqrt(pi a) = -sqrt(2 Estar w),  (al + ga) sqrt(pi b) = the same.
  For a given axis ratio g = b/a the first three conditions are linear in
  (al, be, ga); the fourth is then A1 a^3/2 + A2 = 0, solved for a. Then
     delta = constant term / Estar,  F = 2 pi a b (al + (be + ga)/3).
The separation point (min delta) and pull-off point (min F): a scan of
g brackets each minimum, then a bracketed root search (Illinois) on
mpmath.diff of the exact, uncached delta(g) and F(g). The Hertz shape
(w = 0) from findroot on the y-end condition with w = 0.

Inputs are the double-precision numbers the C test reads (R_minor =
0.999e-3 is not a double; the problem is ill-conditioned in R_minor near
R_major, with condition number ~ 1/(1 - ratio), so the reference must be
for the same inputs), and each tabulated e^2 is a double, so that the
forward-map check e^2 -> delta, F starts from exactly the tabulated state.

Writes (in this folder):
  jkr_elliptic_extrema.csv  radius ratio -> Hertz e^2, separation point
                            (e^2, delta, F), pull-off point (e^2, delta, F)
  jkr_elliptic_force.csv    states on the stable branch: delta -> F, a, b, e^2
  jkr_sphere.csv            classical JKR: delta -> F, a (quartic by findroot)
Run: python3 gen_jkr_elliptic.py   (about a minute)
"""
import csv
import os
import mpmath as mp

mp.mp.dps = 30
HERE = os.path.dirname(os.path.abspath(__file__))

R_MAJOR = mp.mpf(1e-3)   # the double nearest 1e-3, exactly
ESTAR = mp.mpf(1e9)
W = mp.mpf(0.05)
RATIOS = ['0.999', '0.9', '0.7', '0.5', '0.3', '0.1', '0.03', '0.01', '0.003', '0.001']


def integrals(g):
    """The six potential integrals for a = 1, b = g (s = t^2)."""
    b2 = mp.mpf(g) ** 2

    def I(pa, pb):
        f = lambda t: 2 / ((1 + t * t) ** (pa + mp.mpf(1) / 2) * (b2 + t * t) ** (pb + mp.mpf(1) / 2))
        return mp.quad(f, [0, mp.sqrt(b2), 1, mp.inf])
    return [I(0, 0), I(1, 0), I(0, 1), I(2, 0), I(1, 1), I(0, 2)]


class Shape:
    """Everything at one axis ratio g that does not depend on the size a."""

    def __init__(self, g, R1, R2):
        self.g, self.R1, self.R2 = mp.mpf(g), R1, R2
        self.J = integrals(g)

    def solve(self, a, w):
        g, (J0, J1, J2, J11, J12, J22) = self.g, self.J
        b = g * a
        I0, I1, I2 = J0 / a, J1 / a ** 3, J2 / a ** 3
        I11, I12, I22 = J11 / a ** 5, J12 / a ** 5, J22 / a ** 5
        s = a * b / 2
        UH = (s * I0, -s * I1, -s * I2)
        UX = (s * (I0 - a * a * I1), -s * (I1 - 3 * a * a * I11), -s * (I2 - a * a * I12))
        UY = (s * (I0 - b * b * I2), -s * (I1 - b * b * I12), -s * (I2 - 3 * b * b * I22))
        UP = tuple(UH[i] + UX[i] + UY[i] for i in range(3))
        A = mp.matrix([[UP[1], UX[1], UY[1]], [UP[2], UX[2], UY[2]], [1, 1, 0]])
        rhs = mp.matrix([-ESTAR / (2 * self.R1), -ESTAR / (2 * self.R2),
                         -mp.sqrt(2 * ESTAR * w / (mp.pi * a))])
        al, be, ga = mp.lu_solve(A, rhs)
        resid = (al + ga) * mp.sqrt(mp.pi * b) + mp.sqrt(2 * ESTAR * w)
        delta = (al * UP[0] + be * UX[0] + ga * UY[0]) / ESTAR
        F = 2 * mp.pi * a * b * (al + (be + ga) / 3)
        return resid, delta, F

    def state(self, w):
        """(a, b, delta, F) with both energy conditions met. The solution of
        the linear system is a v1 + a^-1/2 v2 (curvature rows scale as 1/a),
        so the y-end residual is A1 a^3/2 + A2: a in closed form, then the
        residual is checked."""
        A1 = self.solve(mp.mpf(1), 0)[0]
        A2 = self.solve(mp.mpf(1), w)[0] - A1
        a = (-A2 / A1) ** (mp.mpf(2) / 3)
        resid, delta, F = self.solve(a, w)
        assert abs(resid) < mp.mpf(10) ** -18 * abs(A2)
        return a, self.g * a, delta, F


def hertz_g(R1, R2):
    # residual is (al + ga) sqrt(pi b) with al + be = 0
    def r(g):
        sh = Shape(g, R1, R2)
        g_ = sh.g
        J0, J1, J2, J11, J12, J22 = sh.J
        a = mp.mpf(1)
        b = g_
        s = a * b / 2
        UH = (s * J0, -s * J1, -s * J2)
        UX = (s * (J0 - J1), -s * (J1 - 3 * J11), -s * (J2 - J12))
        UY = (s * (J0 - b * b * J2), -s * (J1 - b * b * J12), -s * (J2 - 3 * b * b * J22))
        UP = tuple(UH[i] + UX[i] + UY[i] for i in range(3))
        A = mp.matrix([[UP[1], UX[1], UY[1]], [UP[2], UX[2], UY[2]], [1, 1, 0]])
        al, be, ga = mp.lu_solve(A, mp.matrix([-1 / R1, -1 / R2, 0]))
        return (al + ga) * R1
    lam = mp.sqrt(R2 / R1)
    g0 = lam ** (mp.mpf(4) / 3)  # rough start, refined below
    return mp.findroot(r, (g0 * mp.mpf('0.5'), min(g0 * 2, 1 - (1 - g0) / 4)), solver='anderson')


def extremum(fun, lo, hi):
    """The g in [lo, hi] where d fun/dg = 0, given a sign change of the
    derivative over the bracket. The derivative is mp.diff of the exact
    (uncached) evaluation; mp.diff evaluates fun at raised working precision
    with a step matched to it. The root is found by the Illinois variant of
    regula falsi, which keeps the bracket, until it is narrower than 1e-24."""
    d = lambda g: mp.diff(fun, g)
    a, b = mp.mpf(lo), mp.mpf(hi)
    fa, fb = d(a), d(b)
    assert fa * fb < 0, 'no sign change of the derivative over the bracket'
    side = 0
    for _ in range(200):
        c = (a * fb - b * fa) / (fb - fa)
        fc = d(c)
        if fc == 0:
            return c
        if fc * fb > 0:
            b, fb = c, fc
            if side == -1:
                fa /= 2
            side = -1
        else:
            a, fa = c, fc
            if side == 1:
                fb /= 2
            side = 1
        if abs(b - a) < mp.mpf(10) ** -24:
            return c
    raise RuntimeError('extremum search did not converge')


def main():
    ext_rows, force_rows = [], []
    for ratio in RATIOS:
        r = mp.mpf(ratio)
        R1, R2 = R_MAJOR, mp.mpf(float(R_MAJOR * r))
        gH = hertz_g(R1, R2)
        st = lambda g: Shape(g, R1, R2).state(W)
        dfun = lambda g: st(g)[2]
        ffun = lambda g: st(g)[3]
        # scan: the minima of delta(g) and F(g) on (gH, 1) lie between the
        # neighbours of the smallest sampled value (each has one minimum).
        # Geometric in g - gH: for slender contacts both minima lie within
        # a few per cent of (1 - gH) from the Hertz shape.
        gs = [gH + (1 - gH) * mp.mpf(10) ** (-mp.mpf(k) / 8) for k in range(32, 0, -1)]
        sts = [st(g) for g in gs]
        kd = min(range(len(gs)), key=lambda k: sts[k][2])
        kf = min(range(len(gs)), key=lambda k: sts[k][3])
        assert 0 < kd < len(gs) - 1 and 0 < kf < len(gs) - 1
        g_b = extremum(dfun, gs[kd - 1], gs[kd + 1])
        g_p = extremum(ffun, gs[kf - 1], gs[kf + 1])
        ab, bb, db, Fb = st(g_b)
        ap, bp, dp, Fp = st(g_p)
        ext_rows.append([ratio, R1, R2, ESTAR, W, 1 - gH ** 2, 1 - g_b ** 2, db, Fb,
                         1 - g_p ** 2, dp, Fp])
        print(ratio, 'e2_H', mp.nstr(1 - gH ** 2, 8), 'delta_b', mp.nstr(db, 10), 'F_pull', mp.nstr(Fp, 10),
              'F_pull/(1.5 pi w Rhat)', mp.nstr(-Fp / (1.5 * mp.pi * W * mp.sqrt(R1 * R2)), 10))
        # stable branch: g from g_b towards gH (e^2 from e2_b to e2_H)
        for t in ['0.001', '0.05', '0.3', '0.7', '0.95', '0.999']:
            g = g_b + (gH - g_b) * mp.mpf(t)
            g = mp.sqrt(1 - mp.mpf(float(1 - g * g)))  # e^2 exactly a double
            a, b, d, F = st(g)
            force_rows.append([ratio, R1, R2, ESTAR, W, t, d, F, a, b, 1 - g ** 2])

    with open(os.path.join(HERE, 'jkr_elliptic_extrema.csv'), 'w', newline='') as f:
        wr = csv.writer(f)
        wr.writerow(['ratio', 'R_major', 'R_minor', 'Estar', 'w', 'e2_hertz', 'e2_break', 'delta_break',
                     'F_break', 'e2_pull', 'delta_pull', 'F_pull'])
        for row in ext_rows:
            wr.writerow([row[0]] + [repr(float(v)) for v in row[1:5]] + [mp.nstr(v, 20) for v in row[5:]])
    with open(os.path.join(HERE, 'jkr_elliptic_force.csv'), 'w', newline='') as f:
        wr = csv.writer(f)
        wr.writerow(['ratio', 'R_major', 'R_minor', 'Estar', 'w', 'branch_fraction', 'delta', 'F', 'a', 'b', 'e2'])
        for row in force_rows:
            wr.writerow([row[0]] + [repr(float(v)) for v in row[1:5]] + [row[5]] +
                        [mp.nstr(v, 20) for v in row[6:10]] + [repr(float(row[10]))])

    # classical JKR: delta = a^2/R - sqrt(2 pi w a/E*), F = 4E* a^3/(3R) - sqrt(8 pi w E* a^3)
    rows = []
    R = mp.mpf(2e-3)
    # w = 1e-12: overlaps on both sides of the solver's switch to the
    # Hertz-dominated expansion (delta = 1e10 delta_scale, i.e. k ~ -5.8e9)
    for w, ks in [(0.05, None), (1e-6, None), (1e-12, ['-1e9', '-1e11', '-1e13'])]:
        w = mp.mpf(w)
        ac = mp.cbrt(mp.pi * w * R * R / (8 * ESTAR))
        dc = ac * ac / R - mp.sqrt(2 * mp.pi * w * ac / ESTAR)
        for k in ks or ['0.999999', '0.5', '0', '-0.5', '-10', '-1000', '-1e6']:
            # delta = dc * k (k = 0.999999: just inside the separation point)
            delta = mp.mpf(float(dc * mp.mpf(k)))
            f = lambda a: a * a / R - mp.sqrt(2 * mp.pi * w * a / ESTAR) - delta
            hi = ac * 2
            while f(hi) < 0:
                hi *= 2
            a = mp.findroot(f, (ac, hi), solver='anderson')
            F = 4 * ESTAR * a ** 3 / (3 * R) - mp.sqrt(8 * mp.pi * w * ESTAR * a ** 3)
            rows.append([R, ESTAR, w, delta, F, a])
    with open(os.path.join(HERE, 'jkr_sphere.csv'), 'w', newline='') as f:
        wr = csv.writer(f)
        wr.writerow(['R', 'Estar', 'w', 'delta', 'F', 'a'])
        for row in rows:
            wr.writerow([repr(float(v)) for v in row[:4]] + [mp.nstr(v, 20) for v in row[4:]])


if __name__ == '__main__':
    main()
