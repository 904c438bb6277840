#!/usr/bin/env python3
"""The Johnson-Greenwood elliptic JKR geometry (dc_jkr_geometry,
c_core/src/jkr_elliptic.c; review Eqs. 19-23 in the Q/u form of
dc/jkr_elliptic.h) tabulated in the radius ratio: in the reduced variables
of jkr_elliptic.c (a = a_scale abar, delta = delta_scale dbar, F = F_scale
Pbar) everything dc_jkr_geometry finds depends on lam2 = R_minor/R_major
alone, so it is a function of t = ln lam2 in [ln 1e-6, 0):

  lane  0  e2_H/l2c      the Hertz shape (Qn = 0), l2c = 1 - lam2
        1  m1_H/lam2     the same as 1 - e^2
        2  e2_b/e2_H     separation point (min dbar)
        3  m1_b          the same as 1 - e^2
        4  e2_p/e2_H     pull-off point (min Pbar)
        5  m1_p/m1_H
        6  dbar_b   7  Pbar_b   8  dbar_p   9  Pbar_p
       10  X0  11  X1 = dX/drho  12  g1/l2c, g1 = dg/drho  13  P0 = Y/X^3/2
           (the first-order expansion at the Hertz state; the first-order
           coefficient of F, P1, is zero: below 1e-30 here)
       14  dbar_switch (the switch to that expansion, with the distance to
           the Hertz state 1e-8 of e2_H; for slender contacts, measured in
           1 - e^2, times (e2_H/m1_H)^4/3)
       15  guess_c1 (before its clipping at 0)  16  guess_c2
       17  rho0 = g0^1/2 X0^3/4
as jkr_elliptic.c defines them. Each is smooth and of order one (the
ratios to l2c and lam2 keep the relative precision of e^2 near the circle
and of 1 - e^2 for slender contacts), so 14 pieces of width 1 in t
(piece p: t in (-(p+1), -p]) of degree 14 (dc/poly14.h) do.

Values from mpmath (40 digits, the elliptic integrals with extra digits as
m -> 0): the Hertz shape by the Illinois method on Qn, the extrema by the
Illinois method on the complex-step derivative (h = 1e-30) of dbar and
Pbar in e^2, the derivatives at the Hertz state by the complex step.
Fit: interpolation at 15 Chebyshev nodes per piece, converted to powers
of x = t - centre, the constant term as head and rest. Check: at 40 points
per piece, the double evaluation in the C code's order against mpmath;
the worst relative error per lane goes into the header. Also writes
jkr_geometry_dense.csv (the reduced geometry at 300 ratios spread over
[1e-6, 1 - 1e-12], none at a fitting node) for the unit test.
Writes c_core/src/jkr_geometry_poly.h and tests/reference/jkr_geometry_dense.csv.
Run: python3 gen_jkr_geometry_poly.py   (a few minutes on 2 cores)"""
import os
from multiprocessing import Pool
import mpmath as mp
from poly14_fit import estrin, power_coefficients

mp.mp.dps = 40
HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
DEG = 14
PIECES = 14
NCHECK = 40
H = mp.mpf(10) ** -30
NAMES = ["e2_H/l2c", "m1_H/lam2", "e2_b/e2_H", "m1_b", "e2_p/e2_H", "m1_p/m1_H", "dbar_b", "Pbar_b", "dbar_p",
         "Pbar_p", "X0", "X1", "g1/l2c", "P0", "dbar_switch", "guess_c1", "guess_c2", "rho0"]


def ell(m):
    """K, E, D, B, C of m; the differences with enough extra digits that
    D = (K - E)/m, B and C = (D - B)/m keep full precision as m -> 0."""
    extra = int(max(0, -2 * mp.log10(abs(m)))) + 10
    with mp.workdps(mp.mp.dps + extra):
        mm = +m
        K, E = mp.ellipk(mm), mp.ellipe(mm)
        D = (K - E) / mm
        B = (E - (1 - mm) * K) / mm
        C = (D - B) / mm
    return +K, +E, +D, +B, +C


def jg(m, lam2):
    """The Johnson-Greenwood map at m = e^2 (dc/jkr_elliptic.h)."""
    K, E, D, B, C = ell(m)
    lam = mp.sqrt(lam2)
    m1 = 1 - m
    g = mp.sqrt(m1)
    Del = D * B + m1 * C * D + B * C
    Pi2 = ((1 + lam2) * C + D) / (lam * Del)
    Q = (m1 * D - lam2 * B) / (lam * Del)
    u = m / ((1 + mp.sqrt(g)) * (1 + g))
    rho = Q / u
    X = m1 * Pi2 * K + Q * B - 2 * K * rho
    Y = m1 * Pi2 / 3 + Q / 3 - rho
    out = dict(rho=rho, X=X, Y=Y, g=g)
    if rho != 0:
        abar = mp.cbrt(g / rho ** 2)
        out.update(dbar=abar ** 2 * X, Pbar=g * Y / rho ** 2)
    return out


def deriv(key, m, lam2):
    """d key/d e^2 by the complex step."""
    return mp.im(jg(mp.mpc(m, H), lam2)[key]) / H


def illinois(f, a, b, tol):
    fa, fb = f(a), f(b)
    assert fa * fb < 0, (a, b, fa, fb)
    side = 0
    for _ in range(400):
        c = (a * fb - b * fa) / (fb - fa)
        fc = f(c)
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
        if abs(b - a) < tol * abs(c) or fc == 0:
            return c
    raise RuntimeError("no convergence")


def geometry(t):
    """The 18 lanes at t = ln lam2 (and e2_H, e2_b, e2_p for the dense table)."""
    mp.mp.dps = 40
    t = mp.mpf(t)
    lam2, l2c = mp.exp(t), -mp.expm1(t)
    Qn = lambda m: (1 - m) * ell(m)[2] - lam2 * ell(m)[3]
    mH = illinois(Qn, mp.mpf(10) ** -30 * l2c, 1 - lam2 / 100, mp.mpf(10) ** -36)

    def upper(key, lo):
        gap = (mH - lo) / 2
        while deriv(key, mH - gap, lam2) <= 0:
            gap /= 8
        return mH - gap
    lo = mH / 10
    mb = illinois(lambda m: deriv("dbar", m, lam2), lo, upper("dbar", lo), mp.mpf(10) ** -34)
    mpl = illinois(lambda m: deriv("Pbar", m, lam2), mb, upper("Pbar", mb), mp.mpf(10) ** -34)
    Jb, Jp, J = jg(mb, lam2), jg(mpl, lam2), jg(mH, lam2)
    X0, Y0, g0 = J["X"], J["Y"], mp.sqrt(1 - mH)
    dr, dX = deriv("rho", mH, lam2), deriv("X", mH, lam2)
    dg = -1 / (2 * g0)
    g23X = g0 ** (mp.mpf(2) / 3) * X0
    switch = g23X * (mp.mpf("1e-8") * mH * abs(dr)) ** (-mp.mpf(4) / 3)
    span = abs(mH - mb)
    c2 = span * abs(dr) / g23X ** mp.mpf(0.75)
    dp = Jp["dbar"] - Jb["dbar"]
    c1 = (span / abs(mH - mpl) - 1 - c2 * dp ** mp.mpf(0.75)) / mp.sqrt(dp)
    m1H = 1 - mH
    lanes = [mH / l2c, m1H / lam2, mb / mH, 1 - mb, mpl / mH, (1 - mpl) / m1H, Jb["dbar"], Jb["Pbar"],
             Jp["dbar"], Jp["Pbar"], X0, dX / dr, dg / dr / l2c, Y0 / X0 ** mp.mpf(1.5), switch, c1, c2,
             mp.sqrt(g0) * X0 ** mp.mpf(0.75)]
    return lanes, (mH, mb, mpl)


def lanes_at(t):
    return geometry(t)[0]


def fit_piece(p):
    n = DEG
    a, b = -mp.mpf(p + 1), -mp.mpf(p)
    mid = (a + b) / 2
    per_lane = []
    for px in power_coefficients(lanes_at, a, b, n, mid):   # powers of x = t - mid
        head = float(px[0])
        per_lane.append([head, float(px[0] - head)] + [float(v) for v in px[1:]])
    worst = [0.0] * len(NAMES)
    for k in range(NCHECK + 1):
        t = float(a + (b - a) * (k + mp.mpf(1) / 3) / (NCHECK + 1))   # off the nodes
        exact = lanes_at(mp.mpf(t))
        for L in range(len(NAMES)):
            got = estrin(per_lane[L], t - float(mid))
            worst[L] = max(worst[L], float(abs(got / exact[L] - 1)))
    return float(mid), [[per_lane[L][j] for L in range(len(NAMES))] for j in range(n + 2)], worst


def dense_row(r):
    """ratio (a double) -> e2_H, e2_b, e2_p, dbar_b, Pbar_b, dbar_p, Pbar_p"""
    lanes, (mH, mb, mpl) = geometry(mp.log(mp.mpf(r)))
    return "%r,%s\n" % (r, ",".join(mp.nstr(v, 22, min_fixed=1, max_fixed=0)
                                  for v in (mH, mb, mpl, lanes[6], lanes[7], lanes[8], lanes[9])))


def main():
    with Pool(2) as pool:
        res = pool.map(fit_piece, range(PIECES), chunksize=1)
        ratios = sorted(set([float(mp.mpf(10) ** (-6 + 6 * mp.mpf(i) / 239 * mp.mpf("0.99999"))) for i in range(240)] +
                            [1.0 - float(mp.mpf(10) ** (-12 + 11 * mp.mpf(i) / 59)) for i in range(60)]))
        dense = pool.map(dense_row, ratios, chunksize=4)
    worst = [max(r[2][L] for r in res) for L in range(len(NAMES))]
    for L in range(len(NAMES)):
        print("lane %2d %-12s worst relative error %.3g" % (L, NAMES[L], worst[L]))
    with open(os.path.join(ROOT, "c_core", "src", "jkr_geometry_poly.h"), "w") as f:
        f.write("/* Generated by tests/reference/gen_jkr_geometry_poly.py: do not edit.\n")
        f.write("   The reduced Johnson-Greenwood geometry as polynomials of degree %d (dc/poly14.h)\n" % DEG)
        f.write("   in x = t - dc_jg_centre[p], t = ln(R_minor/R_major), piece p for t in\n")
        f.write("   (-(p+1), -p], p < %d. Lanes (worst relative error of the double evaluation):\n" % PIECES)
        for L in range(len(NAMES)):
            f.write("     %2d %-12s %.2g\n" % (L, NAMES[L], worst[L]))
        f.write("   */\n")
        f.write("#define DC_JG_PIECES %d\n#define DC_JG_NLANES %d\n" % (PIECES, len(NAMES)))
        f.write("static const double dc_jg_centre[%d] = {%s};\n" % (PIECES, ", ".join(repr(r[0]) for r in res)))
        f.write("static const double dc_jg_poly[%d][%d][%d] = {\n" % (PIECES, DEG + 2, len(NAMES)))
        for _, rows, _ in res:
            f.write(" {\n")
            for row in rows:
                f.write("  {%s},\n" % ", ".join(repr(v) for v in row))
            f.write(" },\n")
        f.write("};\n")
    with open(os.path.join(HERE, "jkr_geometry_dense.csv"), "w") as f:
        f.write("# generated by gen_jkr_geometry_poly.py (mpmath, 40 digits): the reduced\n")
        f.write("# Johnson-Greenwood geometry (dbar = delta/delta_scale, Pbar = F/F_scale)\n")
        f.write("ratio,e2_hertz,e2_break,e2_pull,dbar_break,Pbar_break,dbar_pull,Pbar_pull\n")
        f.writelines(dense)


if __name__ == "__main__":
    main()
