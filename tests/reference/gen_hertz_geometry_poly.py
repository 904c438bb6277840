#!/usr/bin/env python3
"""Piecewise polynomials of everything dc_hertz_geometry returns
(c_core/src/hertz_elliptic.c), as functions of t = ln r, r = R_minor/R_major
in [1e-12, 1] (review Eqs. 11-13):

  lane 0  e^2/(-t) for t > -1/2 (pieces 0, 1), (1 - e^2)/r below
  lane 1  B = (E - (1 - m) K)/m   lane 2  E   lane 3  D = (K - E)/m   (of m = e^2;
          K = B + D, as in dc_ellint, so that K - D is B to a rounding)
  lane 4  gamma r^1/2       lane 5  beta r^1/2         (Eqs. 11, 12)
  lane 6  gamma^2 r/(1 + r) = R_force/R_major
  lane 7  beta r^1/2/(1 + r) = R_area/(R_major r^1/2)

Each lane is smooth and of order one on the whole range (no cancellation
at either end), so that one evaluation gives every output to about an ulp.
Pieces: u = TAU - t in octaves [2^k, 2^(k+1)) split in four (the exponent
and two leading mantissa bits of u index them), from u = 1.5 (t = 0) to
u = 1.5 - ln 1e-12 = 29.13: 18 pieces that widen with |t|, where the
lanes vary more slowly (like powers of 1/K, K ~ -t/2). In piece
p the polynomial variable is x = t - TC[p], TC the centre of the piece,
or 0 for the first piece (so that x = t keeps full precision as r -> 1).

Values from mpmath (34 digits): 1 - e^2 solves Eq. 13 in its original form
(e^2 = 1 - r E/((1+r) K - E)) by the secant method in ln(1 - e^2), K, E
from ellipk, ellipe. Fit: interpolation at DEG+1 Chebyshev nodes per piece,
converted exactly to powers of x and rounded to doubles, the constant term
as the sum of a head of 26 bits and a rest (the C code adds the head last,
and multiplies R_major by the head of lane 6 exactly). Check: at 64
points per piece the polynomial with those doubles, evaluated in double
arithmetic in the order of the C code (Estrin's scheme), against mpmath;
the worst relative error per lane goes into the header.
Writes c_core/src/hertz_geometry_poly.h.
Run: python3 gen_hertz_geometry_poly.py   (seconds)"""
import os
from multiprocessing import Pool
import mpmath as mp
from poly14_fit import estrin_rest, power_coefficients

mp.mp.dps = 34
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DEG = 14
TAU = 1.5
T_LO = float(mp.log(mp.mpf("1e-12")))   # the domain's end, DC_HERTZ_RATIO_MIN
NCHECK = 64
NLANES = 8


def m1_of(r):
    """1 - e^2 at ratio r (Eq. 13), secant in x = ln(1 - e^2) from review
    Eq. 14 (or e^2 ~ 4/3 (1 - r) near the circle), to a step of 1e-30."""
    if r == 1:
        return mp.mpf(1)

    def G(x):
        m1 = mp.exp(x)
        m = -mp.expm1(x)
        K, E = mp.ellipk(m), mp.ellipe(m)
        return (m1 * ((1 + r) * K - E) - r * E) / m
    a_over_b = -0.177 + mp.sqrt(0.5 / r * mp.log(16 / r)) + 0.16 * mp.log(r)
    x0 = -2 * mp.log(a_over_b) if a_over_b > 1 else mp.log(r) * 4 / 3
    if 1 - r < mp.mpf("1e-3"):
        x0 = mp.log(1 - 4 * (1 - r) / 3)
    x1 = x0 * (1 + mp.mpf("1e-3"))
    g0, g1 = G(x0), G(x1)
    for _ in range(100):
        x0, x1, g0 = x1, x1 - g1 * (x1 - x0) / (g1 - g0), g1
        g1 = G(x1)
        if abs(x1 - x0) < mp.mpf(10) ** -30 * abs(x1):
            return mp.exp(x1)
    raise RuntimeError("no convergence at r = %s" % r)


def lanes(t, top):
    """The eight lanes at t (mpf); top: lane 0 is e^2/(-t)."""
    mp.mp.dps = 34
    r = mp.exp(t)
    m1 = m1_of(r)
    m = 1 - m1
    K, E = mp.ellipk(m), mp.ellipe(m)
    D = (K - E) / m if m != 0 else mp.pi / 4
    gamma = mp.pi * mp.sqrt(2) * mp.sqrt(E) / (2 * K ** 1.5 * mp.sqrt(m1))   # Eq. 11
    beta = 2 * E / (K * mp.sqrt(m1))                                       # Eq. 12
    sr = mp.sqrt(r)
    if top:
        lane0 = m / (-t) if t != 0 else mp.mpf(4) / 3
    else:
        lane0 = m1 / r
    B = (E - m1 * K) / m if m != 0 else mp.pi / 4
    return [lane0, B, E, D, gamma * sr, beta * sr, gamma ** 2 * r / (1 + r), beta * sr / (1 + r)]


def pieces():
    """(t_lo, t_hi, t_c, top) of the 18 pieces, index 0 at t = 0."""
    out = []
    for e in range(0, 5):
        for k in range(4):
            ulo, uhi = 2.0 ** e * (1 + k / 4), 2.0 ** e * (1 + (k + 1) / 4)
            if uhi <= TAU:
                continue
            lo, hi = TAU - uhi, min(0.0, TAU - ulo)
            if hi <= T_LO:
                continue
            tc = 0.0 if hi == 0.0 else TAU - (ulo + uhi) / 2
            out.append((max(lo, T_LO - 1e-9), hi, tc, len(out) < 2))
    return out


def head26(v):
    """v rounded to 26 significant bits (a double whose products with
    26-bit numbers are exact)."""
    m, e = mp.frexp(v)
    return float(mp.ldexp(mp.nint(mp.ldexp(m, 26)), e - 26))


def fit_piece(piece):
    lo, hi, tc, top = piece
    lo, hi, tc = mp.mpf(lo), mp.mpf(hi), mp.mpf(tc)
    n = DEG
    per_lane = []
    for px in power_coefficients(lambda t: lanes(t, top), lo, hi, n, tc):   # powers of x = t - tc
        hi0 = head26(px[0])
        per_lane.append([hi0, float(px[0] - hi0)] + [float(v) for v in px[1:]])
    coefs = [[per_lane[L][j] for L in range(NLANES)] for j in range(n + 2)]
    # check in double arithmetic against mpmath
    worst = [0.0] * (NLANES + 1)
    for k in range(NCHECK + 1):
        t = float(lo + (hi - lo) * k / NCHECK)
        if t < T_LO:
            t = T_LO
        x = t - float(tc)
        exact = lanes(mp.mpf(t), top)
        for L in range(NLANES):
            sl = estrin_rest(per_lane[L], x)
            got = per_lane[L][0] + sl
            worst[L] = max(worst[L], float(abs(got / exact[L] - 1)))
            if L == 6:
                worst[NLANES] = max(worst[NLANES], abs(sl / per_lane[L][0]))
    return coefs, worst


def main():
    ps = pieces()
    assert len(ps) == 18, len(ps)
    with Pool(2) as pool:
        res = pool.map(fit_piece, ps, chunksize=1)
    worst = [max(r[1][L] for r in res) for L in range(NLANES + 1)]
    names = ["e2/(-t) | m1/r", "B", "E", "D", "gamma r^1/2", "beta r^1/2", "R_force/R_major", "R_area/(R_major r^1/2)"]
    for L in range(NLANES):
        print("lane %d %-24s worst relative error %.3g" % (L, names[L], worst[L]))
    print("lane 6: |s|/head <= %.3g" % worst[NLANES])
    with open(os.path.join(ROOT, "c_core", "src", "hertz_geometry_poly.h"), "w") as f:
        f.write("/* Generated by tests/reference/gen_hertz_geometry_poly.py: do not edit.\n")
        f.write("   Elliptic Hertz geometry (review Eqs. 11-13) as polynomials of degree %d in\n" % DEG)
        f.write("   x = t - dc_hg_tc[p], t = ln(R_minor/R_major); piece p from u = %.1f - t,\n" % TAU)
        f.write("   p = 4 k + j - 2 for u in [2^k (1 + j/4), 2^k (1 + (j+1)/4)) (the exponent\n")
        f.write("   and two leading mantissa bits of u).\n")
        f.write("   Lanes: %s;\n" % "; ".join("%d %s" % (L, names[L]) for L in range(NLANES)))
        f.write("   lane 0 is e^2/(-t) in pieces 0 and 1 (t > -1/2), (1 - e^2)/r in the others.\n")
        f.write("   Rows: the constant term as a head of 26 bits and the rest, then the\n")
        f.write("   coefficients of x^1 .. x^%d; lane 6: |rest + x P(x)| <= %.2g of the head.\n"
                % (DEG, worst[NLANES]))
        f.write("   Worst relative error of the double evaluation (64 points per piece):\n    ")
        f.write(", ".join("%d: %.2g" % (L, worst[L]) for L in range(NLANES)) + ". */\n")
        f.write("#define DC_HG_PIECES %d\n#define DC_HG_NROWS %d\n#define DC_HG_NLANES %d\n#define DC_HG_TAU %r\n"
                % (len(ps), DEG + 2, NLANES, TAU))
        f.write("#define DC_HG_TOP_PIECES 2\n")
        f.write("static const double dc_hg_tc[%d] = {%s};\n" % (len(ps), ", ".join(repr(p[2]) for p in ps)))
        f.write("static const double dc_hg_poly[%d][%d][%d] = {\n" % (len(ps), DEG + 2, NLANES))
        for coefs, _ in res:
            f.write(" {\n")
            for row in coefs:
                f.write("  {%s},\n" % ", ".join(repr(v) for v in row))
            f.write(" },\n")
        f.write("};\n")


if __name__ == "__main__":
    main()
