#!/usr/bin/env python3
"""Polynomial pieces for the complete elliptic integrals in
c_core/src/elliptic_integrals.c, and a dense mpmath table to test them.

The C code evaluates D = (K-E)/m, B = (E-m1 K)/m, C = (D-B)/m and E (m1 = 1-m)
as lanes of one polynomial evaluation and forms K = B + D (a sum of positive
terms). D, B, C, E are analytic in |m| < 1:
  D = pi/4 2F1(3/2,1/2;2;m),  B = pi/4 2F1(1/2,1/2;2;m),
  C = pi/16 2F1(3/2,3/2;3;m), E = pi/2 2F1(-1/2,1/2;1;m).
  * m1 in [1/16, 1]: 16 pieces, four per octave of m1, [2^e (1 + k/4),
    2^e (1 + (k+1)/4)], e = -4..-1, k = 0..3. On each, a polynomial in
    x = m - (1 - c1) = c1 - m1, with c1 the centre in m1, or c1 = 1 (m = 0)
    for the piece [7/8, 1] (so D and B start from the same double pi/4).
  * m1 in (0, 1/16): F = P_F(m1) + ln(m1) Q_F(m1) with P_F, Q_F analytic in
    |m1| < 1. From the ln coefficient of K, -K(m1)/pi (A-S 17.3.26), and
    Legendre's relation: Q_K = -K(m1)/pi, Q_E = -(K(m1) - E(m1))/pi,
    Q_D = (Q_K - Q_E)/m, Q_B = (Q_E - m1 Q_K)/m, Q_C = (Q_D - Q_B)/m; then
    P_F = F - ln(m1) Q_F, for F = D, B, C (E = B + m1 D there, a sum of
    positive terms). Polynomials in m1.
Each polynomial interpolates at Chebyshev nodes of its interval (40 digits)
and is converted to monomial coefficients, rounded to double; the number of
coefficients is the smallest giving a truncation error below TOL (relative).
The reported worst error is that of the double coefficients in exact
arithmetic over 41 points per piece (and a log grid of m1 down to 1e-300).

ellint_dense.csv is independent of the fits: K, E by mpmath ellipk/ellipe
with enough digits that m = 1 - m1 is exact, and D, B, C from their
definitions (differences), at m in [0, 1), at m1 down to 1e-300 and at both
sides of every piece edge.
Writes c_core/src/elliptic_integrals_poly.h and tests/reference/ellint_dense.csv.
Run: python3 gen_ellint_fast.py"""
import math
import os
import mpmath as mp

mp.mp.dps = 40
HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
TOL = mp.mpf("3e-17")
# the piece index in elliptic_integrals.c (exponent and two mantissa bits of
# m1, offset 1023 - 4) assumes these two
OCT_LO = -4          # polynomial pieces for m1 >= 2^OCT_LO, logarithmic form below
SUB = 4              # pieces per octave of m1
L = mp.mpf(2) ** OCT_LO
NAMES = "DBCE"


def dbce(m1):
    """D, B, C, E at parameter m = 1 - m1 (m1 an mpf; exact 1 - m1)."""
    with mp.workdps(mp.mp.dps + max(0, int(-mp.log10(m1)))):
        m = 1 - m1
        v = (mp.pi / 4 * mp.hyp2f1(1.5, 0.5, 2, m), mp.pi / 4 * mp.hyp2f1(0.5, 0.5, 2, m),
             mp.pi / 16 * mp.hyp2f1(1.5, 1.5, 3, m), mp.pi / 2 * mp.hyp2f1(-0.5, 0.5, 1, m))
    return tuple(+x for x in v)


def q_dbce(m1):
    """ln(m1) coefficients Q_D, Q_B, Q_C, Q_E near m = 1."""
    m = 1 - m1
    K1, E1 = mp.ellipk(m1), mp.ellipe(m1)
    QK, QE = -K1 / mp.pi, -(K1 - E1) / mp.pi
    QD, QB = (QK - QE) / m, (QE - m1 * QK) / m
    return QD, QB, (QD - QB) / m, QE


def p_dbce(m1):
    f, q, lg = dbce(m1), q_dbce(m1), mp.log(m1)
    return tuple(f[i] - lg * q[i] for i in range(4))


def cheb_monomial(f, a, b, n, x0):
    """Interpolate f on [a, b] at n Chebyshev nodes; monomial coefficients in
    (t - x0) for t in [a, b]."""
    c, h = (a + b) / 2, (b - a) / 2
    nodes = [mp.cos(mp.pi * (k + mp.mpf(1) / 2) / n) for k in range(n)]
    vals = [f(c + h * y) for y in nodes]
    ch = [2 * sum(v * mp.cos(mp.pi * j * (k + mp.mpf(1) / 2) / n) for k, v in enumerate(vals)) / n
          for j in range(n)]
    ch[0] /= 2
    # Chebyshev -> monomials in y = (t - c)/h: T_{j+1} = 2y T_j - T_{j-1}
    T = [[mp.mpf(1)], [mp.mpf(0), mp.mpf(1)]]
    while len(T) < n:
        a1, a0 = T[-1], T[-2]
        T.append([(2 * a1[i - 1] if i > 0 else 0) - (a0[i] if i < len(a0) else 0) for i in range(len(a1) + 1)])
    py = [sum(ch[j] * (T[j][i] if i < len(T[j]) else 0) for j in range(n)) for i in range(n)]
    # y = (s + x0 - c)/h with s = t - x0: expand by the binomial theorem
    d = (x0 - c) / h
    return [sum(py[i] * mp.binomial(i, k) * d ** (i - k) for i in range(k, n)) / h ** k for k in range(n)]


def horner(c, x):
    s = mp.mpf(0)
    for a in reversed(c):
        s = s * x + a
    return s


def poly_pieces():
    edges = []
    for e in range(OCT_LO, 0):
        for k in range(SUB):
            edges.append((mp.mpf(2) ** e * (1 + mp.mpf(k) / SUB), mp.mpf(2) ** e * (1 + mp.mpf(k + 1) / SUB)))
    return edges


def fit_poly_pieces(n):
    """Expansion points c1 and, per piece, coefficients [j][lane] in
    x = c1 - m1 for D, B, C, E; worst truncation and double-coefficient errors."""
    out, trunc, worst = [], [mp.mpf(0)] * 4, [mp.mpf(0)] * 4
    for lo, hi in poly_pieces():
        c1 = (lo + hi) / 2 if hi < 1 else hi
        pts = [lo + (hi - lo) * j / 40 for j in range(41)]
        ref = [dbce(t) for t in pts]
        lanes = []
        for i in range(4):
            # fitted in m1 about c1; x = -(m1 - c1) flips the odd terms
            cm = cheb_monomial(lambda t: dbce(t)[i], lo, hi, n, c1)
            cx = [(-1) ** k * cm[k] for k in range(n)]
            cd = [mp.mpf(float(v)) for v in cx]
            for t, r in zip(pts, ref):
                trunc[i] = max(trunc[i], abs(horner(cx, c1 - t) / r[i] - 1))
                worst[i] = max(worst[i], abs(horner(cd, c1 - t) / r[i] - 1))
            lanes.append([float(v) for v in cx])
        out.append((float(c1), [[lanes[i][j] for i in range(4)] for j in range(n)]))
    return out, trunc, worst


def log_grid():
    return [L * j / 40 for j in range(1, 41)] + [mp.mpf(10) ** -k for k in (3, 5, 8, 12, 20, 50, 100, 200, 300)]


def fit_log(n):
    """Coefficients [j][lane] in m1 of the lanes P_D, P_B, Q_D, Q_B, P_C, Q_C
    on (0, L]; worst truncation and double-coefficient errors of D, B, C."""
    P = [cheb_monomial(lambda t: p_dbce(t)[i], mp.mpf(0), L, n, mp.mpf(0)) for i in range(3)]
    Q = [cheb_monomial(lambda t: q_dbce(t)[i], mp.mpf(0), L, n, mp.mpf(0)) for i in range(3)]
    trunc, worst = [mp.mpf(0)] * 3, [mp.mpf(0)] * 3
    for t in log_grid():
        r, lg = dbce(t), mp.log(t)
        for i in range(3):
            trunc[i] = max(trunc[i], abs((horner(P[i], t) + lg * horner(Q[i], t)) / r[i] - 1))
            Pd = [mp.mpf(float(v)) for v in P[i]]
            Qd = [mp.mpf(float(v)) for v in Q[i]]
            worst[i] = max(worst[i], abs((horner(Pd, t) + lg * horner(Qd, t)) / r[i] - 1))
    lanes = [P[0], P[1], Q[0], Q[1], P[2], Q[2]]
    return [[float(lanes[i][j]) for i in range(6)] for j in range(n)], trunc, worst


def smallest(fit, n0):
    n = n0
    while True:
        res = fit(n)
        print("  %d coefficients: truncation %s, with double coefficients %s" % (n, mp.nstr(max(res[1]), 3), mp.nstr(max(res[2]), 3)))
        if max(res[1]) < TOL:
            return n, res
        n += 1


def fmt(v):
    return repr(float(v))


def errs(w):
    return " ".join("%s %s" % (NAMES[i], mp.nstr(w[i], 2)) for i in range(len(w)))


def write_header():
    print("polynomial pieces m1 in [1/16, 1]:")
    na, (pieces, trunc_a, worst_a) = smallest(fit_poly_pieces, 12)
    print("logarithmic form m1 in (0, 1/16):")
    nl, (logc, trunc_l, worst_l) = smallest(fit_log, 10)
    path = os.path.join(ROOT, "c_core", "src", "elliptic_integrals_poly.h")
    with open(path, "w") as f:
        f.write("/* Generated by tests/reference/gen_ellint_fast.py: do not edit.\n")
        f.write("   D, B, C, E from polynomials, K = B + D, m1 = 1 - m:\n")
        f.write("   m1 in [1/16, 1]: piece p = [2^e (1 + k/4), 2^e (1 + (k+1)/4)], p = 4 (e + 4) + k,\n")
        f.write("     F = sum_j dc_ellint_poly[p][j][lane] x^j, lanes D, B, C, E,\n")
        f.write("     x = dc_ellint_c1[p] - m1 (= m - (1 - c1)), c1 the centre of the piece or\n")
        f.write("     1 (m = 0) for the last one;\n")
        f.write("   m1 in (0, 1/16): F = P_F(m1) + ln(m1) Q_F(m1) for F = D, B, C, E = B + m1 D;\n")
        f.write("     P_F, Q_F = sum_j dc_ellint_log[j][lane] m1^j, lanes P_D, P_B, Q_D, Q_B, P_C, Q_C.\n")
        f.write("   Worst relative error of the double coefficients in exact arithmetic\n")
        f.write("   (truncation alone below %s):\n" % mp.nstr(max(max(trunc_a), max(trunc_l)), 2))
        f.write("     pieces %s;\n" % errs(worst_a))
        f.write("     logarithmic form (m1 down to 1e-300) %s. */\n" % errs(worst_l))
        f.write("#define DC_ELLINT_PIECES %d\n" % len(pieces))
        f.write("#define DC_ELLINT_NPOLY %d\n" % na)
        f.write("#define DC_ELLINT_NLOG %d\n" % nl)
        f.write("static const double dc_ellint_c1[%d] = {%s};\n" % (len(pieces), ", ".join(fmt(p[0]) for p in pieces)))
        f.write("static const double dc_ellint_poly[%d][%d][4] = {\n" % (len(pieces), na))
        for c1, cs in pieces:
            f.write(" {\n")
            for c in cs:
                f.write("  {%s},\n" % ", ".join(fmt(v) for v in c))
            f.write(" },\n")
        f.write("};\n")
        f.write("static const double dc_ellint_log[%d][6] = {\n" % nl)
        for c in logc:
            f.write(" {%s},\n" % ", ".join(fmt(v) for v in c))
        f.write("};\n")
    print("wrote %s" % path)


def ref_row(m1):
    """K, E, D, B, C at m = 1 - m1 by ellipk/ellipe (m1 an mpf)."""
    digits = 40 + 2 * int(max(-mp.log10(m1), -mp.log10(1 - m1) if m1 < 1 else 0))
    with mp.workdps(digits):
        m = 1 - m1
        K, E = mp.ellipk(m), mp.ellipe(m)
        if m == 0:
            v = (K, E, mp.pi / 4, mp.pi / 4, mp.pi / 16)
        else:
            D = (K - E) / m
            B = (E - m1 * K) / m
            v = (K, E, D, B, (D - B) / m)
    return v


def write_table():
    rows = []
    ms = [i / 200.0 for i in range(200)] + [1e-300, 1e-100, 1e-30, 1e-16, 1e-8, 1e-4, 0.999, 0.99999, 1 - 2.0 ** -30]
    m1s = [10.0 ** (-300.0 * i / 150) for i in range(151)] + [0.3, 0.7, 0.9, 0.99, 1 - 1e-8, 1 - 2.0 ** -53]
    for lo, hi in poly_pieces():
        for b in (float(lo), float(hi)):
            for v in (math.nextafter(b, 0), b, math.nextafter(b, 2)):
                if v <= 1.0:
                    m1s.append(v)
                    if 1 - v < 1 and 1 - v >= 0:
                        ms.append(1 - v)
    seen = set()
    for kind, xs in (("m", ms), ("m1", m1s)):
        for x in sorted(set(xs)):
            if (kind, x) in seen:
                continue
            seen.add((kind, x))
            with mp.workdps(700):
                m1 = 1 - mp.mpf(x) if kind == "m" else mp.mpf(x)
            rows.append((kind, x) + ref_row(m1))
    # D, B, C by the hypergeometric series as a check of the table itself
    for r in rows[::7]:
        with mp.workdps(700):
            m1 = 1 - mp.mpf(r[1]) if r[0] == "m" else mp.mpf(r[1])
        if m1 > mp.mpf(10) ** -30:
            h = dbce(m1)
            assert all(abs(h[i] / r[4 + i] - 1) < mp.mpf(10) ** -30 for i in range(3)), r
            assert abs(h[3] / r[3] - 1) < mp.mpf(10) ** -30, r
    path = os.path.join(HERE, "ellint_dense.csv")
    with open(path, "w") as f:
        f.write("# generated by gen_ellint_fast.py (mpmath ellipk/ellipe, 40+ digits)\n")
        f.write("# kind,x,K,E,D,B,C  (kind m: x = m; kind m1: x = 1 - m)\n")
        for r in rows:
            f.write("%s,%r,%s\n" % (r[0], r[1], ",".join(mp.nstr(v, 20) for v in r[2:])))
    print("wrote %s (%d rows)" % (path, len(rows)))


if __name__ == "__main__":
    write_header()
    write_table()
