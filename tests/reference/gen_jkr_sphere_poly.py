#!/usr/bin/env python3
"""Tabulated inverse of the classical JKR curve (c_core/src/jkr_sphere.c,
dc/jkr_sphere.h), the same for every material, in two reduced forms
(Johnson, Kendall & Roberts 1971):

  H, the Hertz-like end, in nu = kappa^2, kappa = (2 pi w a0/E*)^1/2/delta,
    a0 = (R delta)^1/2: the contact radius is a = psi a0, psi^2 = 1 + kappa
    psi^1/2 (the JKR relation delta = a^2/R - (2 pi w a/E*)^1/2 divided by
    delta). psi is analytic in kappa (its singularities, the separation
    point, lie at |kappa| = 1.755, arg +-135 deg), so psi(kappa) = A(nu) +
    kappa B(nu) with A, B the even and odd parts, analytic in nu: nu needs
    no square root beyond a0's, and kappa = nu^1/2 is taken while A and B
    are evaluated. On nu in [0, 1/4] (the hot path, dc_jkr_sphere_near_hertz)
    psi = (1 + nu A1) + kappa (1/2 + nu B1), A1 = (A - 1)/nu, B1 = (B -
    1/2)/nu of degree DEG0 in nu itself (short dependency chains: the
    terms of order nu are below 0.02 of psi there, so A1 and B1 need only
    ~1e-15); then lanes A, B of degree DEG on 16 pieces of width 1 up to
    16.25 (kappa = 4: the reduced overlap dbar = delta/delta_scale >=
    0.575, where kappa = pi 2^-1/4 dbar^-3/4). The odd part comes from the
    continuation of psi to kappa < 0 (psi^2 + |kappa| psi^1/2 = 1, 0 < psi
    <= 1).
  S, from the separation point up, in s = U^1/2, U = (dbar - dbar_b)/(2 x_b^4)
    (x = x_b (1 + y), x^2 = a/a_scale, y^2 (y^2 + 4 y + 6) = U); lane y/s
    on s in [0, 2] (dbar <= 0.575), 4 pieces.
  Both forms are analytic on their ranges (the square-root behaviour at the
  separation point is in s itself), so a polynomial of degree DEG per
  piece does.

Values from mpmath (40 digits, findroot on the two relations). Fit:
interpolation at DEG+1 Chebyshev nodes per piece, converted exactly to
powers of x = nu - centre (or s - centre) and rounded to doubles, the
constant term as a head and a rest that the C code adds last (dc/poly14.h,
as gen_hertz_geometry_poly.py). Check: at 200 points per piece the double
evaluation in the order of the C code against mpmath, for A, B, psi =
head_A + (rest_A + kappa B) (kappa rounded, as in C) and y/s; the worst relative errors go
into the header.
Writes c_core/src/jkr_sphere_poly.h. Run: python3 gen_jkr_sphere_poly.py"""
import os
import mpmath as mp
from poly14_fit import estrin, estrin_rest, power_coefficients

mp.mp.dps = 40
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DEG = 14
DEG0 = 8
NU_0 = 0.25                              # piece 0: nu in [0, NU_0]
H_EDGES = [NU_0 + k for k in range(17)]  # then width 1 up to 16.25
S_H, S_PIECES = 2, 4
NCHECK = 200


def psi_signed(k):
    """psi^2 = 1 + k psi^1/2 for k >= 0 (psi >= 1) and its continuation to
    k < 0 (0 < psi <= 1)."""
    if k == 0:
        return mp.mpf(1)
    if k > 0:
        return mp.findroot(lambda q: q * q - 1 - k * mp.sqrt(q), 1 + k / 2 if k < 1 else k ** (mp.mpf(2) / 3) + 1)
    m = -k
    return mp.findroot(lambda q: q * q - 1 + m * mp.sqrt(q), 1 - m / 2 if m < 0.5 else 1 / (m * m + 1))


def lanes_h(nu):
    """A(nu), B(nu): psi(kappa) = A + kappa B, kappa = nu^1/2."""
    if nu == 0:
        return [mp.mpf(1), mp.mpf(1) / 2]
    k = mp.sqrt(nu)
    p, m = psi_signed(k), psi_signed(-k)
    return [(p + m) / 2, (p - m) / (2 * k)]


def lanes_h0(nu):
    """A1 = (A - 1)/nu, B1 = (B - 1/2)/nu (finite as nu -> 0)."""
    if nu == 0:
        nu = mp.mpf(10) ** -30
    A, B = lanes_h(nu)
    return [(A - 1) / nu, (B - mp.mpf(1) / 2) / nu]


def fit0():
    """Piece 0: A1, B1 of degree DEG0 in powers of nu on [0, NU_0], and the
    worst relative error of psi = (1 + nu A1) + kappa (1/2 + nu B1) in
    double arithmetic (kappa rounded, as in C) at NCHECK points."""
    n, h = DEG0, mp.mpf(NU_0) / 2
    nodes = [mp.cos(mp.pi * (k + mp.mpf(1) / 2) / (n + 1)) for k in range(n + 1)]
    vals = [lanes_h0(h + h * y) for y in nodes]
    lanes = []
    for L in range(2):
        ch = [2 * sum(v[L] * mp.cos(mp.pi * j * (k + mp.mpf(1) / 2) / (n + 1)) for k, v in enumerate(vals)) / (n + 1)
              for j in range(n + 1)]
        ch[0] /= 2
        T = [[mp.mpf(1)], [mp.mpf(0), mp.mpf(1)]]
        for j in range(2, n + 1):
            T.append([(2 * T[j - 1][i - 1] if i >= 1 else 0) - (T[j - 2][i] if i < len(T[j - 2]) else 0)
                      for i in range(j + 1)])
        py = [sum(ch[j] * T[j][i] for j in range(i, n + 1) if i < len(T[j])) for i in range(n + 1)]
        px = [mp.mpf(0)] * (n + 1)   # y = (nu - h)/h
        for i, bi in enumerate(py):
            for k in range(i + 1):
                px[k] += bi * mp.binomial(i, k) * (-h) ** (i - k) / h ** i
        lanes.append([float(v) for v in px])
    worst = 0.0
    for k in range(NCHECK + 1):
        nu = float(mp.mpf(NU_0) * k / NCHECK)
        x2 = nu * nu
        x4 = x2 * x2
        x8 = x4 * x4
        y = []
        for c in lanes:
            q = [c[2 * i] + c[2 * i + 1] * nu for i in range(4)]
            y.append(((q[0] + q[1] * x2) + (q[2] + q[3] * x2) * x4) + c[8] * x8)
        kappa = float(mp.sqrt(mp.mpf(nu)))
        psi = (1.0 + nu * y[0]) + kappa * (0.5 + nu * y[1])
        worst = max(worst, float(abs(psi / psi_signed(mp.sqrt(mp.mpf(nu))) - 1)))
    return [[lanes[L][j] for L in range(2)] for j in range(n + 1)], worst


def lanes_s(s):
    """y/s, y^2 (y^2 + 4 y + 6) = s^2, y >= 0 (-> 6^-1/2 as s -> 0)."""
    if s == 0:
        return [1 / mp.sqrt(6)]
    y = mp.findroot(lambda y: y * y * (y * y + 4 * y + 6) - s * s, s / mp.sqrt(6) if s < 1 else mp.sqrt(s / 2))
    return [y / s]


def fit(fn, edges, psi_check=False):
    """[(centre, coefs[row][lane])] on the pieces between the edges, and
    the worst relative error per lane (and of psi = A + kappa B)."""
    out, worst = [], None
    n = DEG
    for p in range(len(edges) - 1):
        a, b = mp.mpf(edges[p]), mp.mpf(edges[p + 1])
        mid = (a + b) / 2
        per_lane = []
        for px in power_coefficients(fn, a, b, n, mid):   # powers of x = t - mid
            head = float(px[0])
            per_lane.append([head, float(px[0] - head)] + [float(v) for v in px[1:]])
        nl = len(per_lane)
        if worst is None:
            worst = [0.0] * (nl + 1)
        for k in range(NCHECK + 1):
            t = float(a + (b - a) * k / NCHECK)
            exact = fn(mp.mpf(t))
            got = [estrin(per_lane[L], t - float(mid)) for L in range(nl)]
            for L in range(nl):
                worst[L] = max(worst[L], float(abs(got[L] / exact[L] - 1)))
            if psi_check:
                # psi = head_A + (rest_A + kappa B): one rounding at full size
                kappa = mp.sqrt(mp.mpf(t))
                psi = per_lane[0][0] + (estrin_rest(per_lane[0], t - float(mid)) + float(kappa) * got[1])
                worst[nl] = max(worst[nl], float(abs(psi / psi_signed(kappa) - 1)))
        out.append((float(mid), [[per_lane[L][j] for L in range(nl)] for j in range(n + 2)]))
    return out, worst


def write_table(f, name, pieces, nl):
    f.write("static const double %s_centre[%d] = {%s};\n" % (name, len(pieces), ", ".join(repr(c) for c, _ in pieces)))
    f.write("static const double %s[%d][%d][%d] = {\n" % (name, len(pieces), DEG + 2, nl))
    for _, rows in pieces:
        f.write(" {\n")
        for row in rows:
            f.write("  {%s},\n" % ", ".join(repr(v) for v in row))
        f.write(" },\n")
    f.write("};\n")


def main():
    h0, w0 = fit0()
    h, wh = fit(lanes_h, H_EDGES, psi_check=True)
    s, ws = fit(lanes_s, [S_H * k / S_PIECES for k in range(S_PIECES + 1)])
    print("H: psi %.3g on piece 0, A %.3g, B %.3g, psi %.3g on the others; S: y/s %.3g (worst relative error)"
          % (w0, wh[0], wh[1], wh[2], ws[0]))
    with open(os.path.join(ROOT, "c_core", "src", "jkr_sphere_poly.h"), "w") as f:
        f.write("/* Generated by tests/reference/gen_jkr_sphere_poly.py: do not edit.\n")
        f.write("   The inverse of the classical JKR curve in reduced variables, degree %d\n" % DEG)
        f.write("   polynomials in x = v - centre (dc/poly14.h: rows head and rest of the\n")
        f.write("   constant term, then the coefficients of x^1 .. x^%d).\n" % DEG)
        f.write("   H (declared in dc/jkr_sphere.h): psi^2 = 1 + kappa psi^1/2, nu = kappa^2;\n")
        f.write("      on nu in [0, %g] psi = (1 + nu A1) + kappa (1/2 + nu B1), A1 and B1 of\n" % NU_0)
        f.write("      degree %d in nu (dc_jkr_psi0, lanes A1, B1), worst relative error of\n" % DEG0)
        f.write("      psi %.2g; then pieces of width 1 up to %g, psi = A(nu) + kappa B(nu)\n" % (w0, H_EDGES[-1]))
        f.write("      (dc_jkr_psi_poly, lanes A, B): A %.2g, B %.2g, psi %.2g.\n" % (wh[0], wh[1], wh[2]))
        f.write("   S: v = s in [0, %d], %d pieces, lane y/s (y^2 (y^2 + 4y + 6) = s^2);\n" % (S_H, S_PIECES))
        f.write("      worst relative error %.2g. */\n" % ws[0])
        f.write("#define DC_JKR_S_H %d.0\n#define DC_JKR_S_PIECES %d\n" % (S_H, S_PIECES))
        f.write("const double dc_jkr_psi0[%d][2] = {\n" % (DEG0 + 1))
        for row in h0:
            f.write(" {%s},\n" % ", ".join(repr(v) for v in row))
        f.write("};\n")
        f.write("const double dc_jkr_psi_centre[DC_JKR_NU_PIECES] = {%s};\n" % ", ".join(repr(c) for c, _ in h))
        f.write("const double dc_jkr_psi_poly[DC_JKR_NU_PIECES][DC_POLY14_NROWS][2] = {\n")
        for _, rows in h:
            f.write(" {\n")
            for row in rows:
                f.write("  {%s},\n" % ", ".join(repr(v) for v in row))
            f.write(" },\n")
        f.write("};\n")
        write_table(f, "dc_jkr_poly_s", s, 1)
    assert len(h) == 16


if __name__ == "__main__":
    main()
