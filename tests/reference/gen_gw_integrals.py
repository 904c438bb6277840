#!/usr/bin/env python3
"""Reference values and Chebyshev tables for the Greenwood-Williamson integrals

    F_n(h) = int_h^inf (s - h)^n phi(s) ds,   phi = standard normal density,

for n = 0, 1/2, 1, 3/2 (review Eqs. 31-32, 35-36, 82-84; Feng Eq. 17).

Writes
  tests/reference/gw_integrals.csv      n,h,F_n(h) by direct mpmath quadrature
                                        (40 digits), h from -40 to 38
  c_core/src/gw_integrals_cheb.h        Chebyshev coefficients used by the fast
                                        path of c_core/src/gw_integrals.c

and checks, before writing anything, every closed form the C code uses
(Bessel-K forms for h > 0, Bessel-I forms for h < 0, the parabolic-cylinder
form) against the quadrature. Run from anywhere: python3 gen_gw_integrals.py
"""
import os
import mpmath as mp

mp.mp.dps = 40
HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
NS = [mp.mpf(0), mp.mpf(1) / 2, mp.mpf(1), mp.mpf(3) / 2]
NNAME = ["0", "0.5", "1", "1.5"]


def phi(h):
    return mp.exp(-h * h / 2) / mp.sqrt(2 * mp.pi)


def F_quad(n, h):
    """Direct quadrature: int_0^inf t^n phi(t + h) dt (independent of any closed form)."""
    f = lambda t: t ** n * phi(t + h)
    if h > 0:
        # phi(t + h) = phi(h) exp(-h t - t^2/2): integrate the scaled integrand
        s = 1 / h
        pts = [0, s, 4 * s, 16 * s, 64 * s, mp.inf]
        return phi(h) * mp.quad(lambda t: t ** n * mp.exp(-h * t - t * t / 2), pts)
    else:
        x = -h
        pts = [0, x / 2, x, x + 1, x + 4, x + 10, mp.inf] if x > 0 else [0, 1, 4, 10, mp.inf]
    return mp.quad(f, pts)


def F_pcf(n, h):
    """F_n(h) = Gamma(n+1) phi(h) e^{h^2/4} D_{-n-1}(h) (parabolic cylinder)."""
    return mp.gamma(n + 1) * phi(h) * mp.exp(h * h / 4) * mp.pcfd(-n - 1, h)


def F_bessel(n, h):
    """The closed forms coded in C (checked here against F_quad)."""
    if h > 0:
        z = h * h / 4
        K14, K34 = mp.besselk(0.25, z), mp.besselk(0.75, z)
        if n == mp.mpf(1) / 2:   # review Eq. 84 reduced to K (see gw_integrals.h)
            return h ** 1.5 * mp.exp(-h * h / 4) * (K34 - K14) / (4 * mp.sqrt(mp.pi))
        if n == mp.mpf(3) / 2:   # review Eq. 35
            return mp.sqrt(h) * mp.exp(-h * h / 4) * ((h * h + 1) * K14 - h * h * K34) / (4 * mp.sqrt(mp.pi))
    else:
        x = -h
        z = x * x / 4
        Im14, I14 = mp.besseli(-0.25, z), mp.besseli(0.25, z)
        Im34, I34 = mp.besseli(-0.75, z), mp.besseli(0.75, z)
        # F_{-1/2}(h) = sqrt(pi/8) sqrt(x) e^{-z} (I_{-1/4} + I_{1/4})(z)
        Fm = mp.sqrt(mp.pi / 8) * mp.sqrt(x) * mp.exp(-z) * (Im14 + I14)
        # F_{1/2}(h) = sqrt(2 pi)/8 x^{3/2} e^{-z} (I_{-1/4} + I_{1/4} + I_{-3/4} + I_{3/4})(z)
        Fh = mp.sqrt(2 * mp.pi) / 8 * x ** 1.5 * mp.exp(-z) * (Im14 + I14 + Im34 + I34)
        if n == mp.mpf(1) / 2:
            return Fh
        if n == mp.mpf(3) / 2:
            return Fm / 2 + x * Fh   # recurrence F_{n+1} = n F_{n-1} - h F_n
    raise ValueError


def closed(n, h):
    if n == 0:
        return mp.erfc(h / mp.sqrt(2)) / 2
    if n == 1:
        return phi(h) - h * mp.erfc(h / mp.sqrt(2)) / 2
    return F_bessel(n, h)


def verify():
    worst = 0
    for h in [mp.mpf(x) for x in ("-7.3", "-2", "-0.4", "-0.001", "0.001", "0.3", "1", "2.5", "6", "11")]:
        for n in NS:
            q = F_quad(n, h)
            for other in (F_pcf(n, h), closed(n, h)):
                worst = max(worst, abs(other / q - 1))
    assert worst < mp.mpf(10) ** -25, worst
    # recurrence and derivative identities on the quadrature itself
    for h in [mp.mpf(-3), mp.mpf("0.7")]:
        for n in (mp.mpf(1) / 2, mp.mpf(1)):
            lhs = F_quad(n + 1, h)
            rhs = n * F_quad(n - 1, h) - h * F_quad(n, h)
            assert abs(lhs / rhs - 1) < mp.mpf(10) ** -20  # quad of F_{-1/2}: ~1e-22
        d = mp.diff(lambda s: F_quad(mp.mpf(3) / 2, s), h)
        assert abs(d / (-mp.mpf(3) / 2 * F_quad(mp.mpf(1) / 2, h)) - 1) < mp.mpf(10) ** -20
    print("closed forms and identities agree with quadrature, worst rel.err %.2e" % float(worst))


def table():
    hs = [mp.mpf(x) / 4 for x in range(-20, 41)]            # -5 .. 10 step 0.25
    hs += [mp.mpf(x) for x in ("1e-3", "-1e-3", "1e-8", "-1e-8", "0.1", "-0.1")]
    hs += [mp.mpf(x) for x in (-40, -20, -12, -10.5, -9.99, -8, 12, 15, 19.9, 20.5, 25, 30, 37)]
    # evaluate at the double nearest to each h, so the C tests compare at
    # exactly the same argument (F is ill-conditioned in h for large |h|)
    hs = sorted(set(mp.mpf(float(h)) for h in hs))
    path = os.path.join(HERE, "gw_integrals.csv")
    with open(path, "w") as f:
        f.write("# F_n(h) = int_h^inf (s-h)^n phi(s) ds by mpmath quadrature, 40 digits; gen_gw_integrals.py\n")
        f.write("n,h,F\n")
        for n, nm in zip(NS, NNAME):
            for h in hs:
                f.write("%s,%s,%s\n" % (nm, repr(float(h)), mp.nstr(F_quad(n, h), 25)))
    print("wrote", path)


# Chebyshev pieces. h in [-10, 0): F_n(h) itself on unit intervals;
# h in [0, 20): G_n(h) = F_n(h)/phi(h) on unit intervals (smooth, slowly
# varying, no underflow). Beyond: asymptotic series in the C code.
HLO, HMID, HHI = -10, 0, 20
DEG = 17


def cheb_coeffs(f, a, b, deg):
    N = deg + 1
    xs = [mp.cos(mp.pi * (k + mp.mpf(1) / 2) / N) for k in range(N)]
    fs = [f((b - a) / 2 * x + (b + a) / 2) for x in xs]
    c = []
    for j in range(N):
        s = mp.fsum(fs[k] * mp.cos(mp.pi * j * (k + mp.mpf(1) / 2) / N) for k in range(N))
        c.append(2 * s / N)
    c[0] /= 2
    return c


def cheb_tables():
    out = []
    out.append("/* Generated by tests/reference/gen_gw_integrals.py: do not edit.\n"
               "   Chebyshev coefficients of F_n(h) on [k, k+1), k = -10..-1, and of\n"
               "   G_n(h) = F_n(h)/phi(h) on [k, k+1), k = 0..19, for n = 0, 1/2, 1, 3/2.\n"
               "   Series truncated where |c_j| < 2e-18 max|f| on the interval; unused\n"
               "   trailing coefficients are 0. Evaluate with x = 2(h - k) - 1. */")
    out.append("#define DC_GW_CHEB_HLO %d" % HLO)
    out.append("#define DC_GW_CHEB_HHI %d" % HHI)
    out.append("#define DC_GW_CHEB_NCOEF %d" % (DEG + 1))
    maxdeg = 0
    out.append("static const double dc_gw_cheb[4][%d][%d] = {" % (HHI - HLO, DEG + 1))
    for n in NS:
        out.append(" {")
        for k in range(HLO, HHI):
            if k < HMID:
                f = lambda h, n=n: F_pcf(n, h) if n not in (0, 1) else closed(n, h)
            else:
                f = lambda h, n=n: (F_pcf(n, h) if n not in (0, 1) else closed(n, h)) / phi(h)
            c = cheb_coeffs(f, mp.mpf(k), mp.mpf(k + 1), DEG + 6)
            scale = max(abs(v) for v in c)
            last = max(j for j in range(len(c)) if abs(c[j]) > 2e-18 * scale)
            assert last <= DEG, (n, k, last)
            maxdeg = max(maxdeg, last)
            c = c[:DEG + 1]
            for j in range(last + 1, DEG + 1):
                c[j] = 0
            out.append("  {" + ", ".join(mp.nstr(v, 20, min_fixed=1, max_fixed=0) if v != 0 else "0" for v in c) + "},")
        out.append(" },")
    out.append("};")
    path = os.path.join(ROOT, "c_core", "src", "gw_integrals_cheb.h")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")
    print("wrote", path, "max degree used", maxdeg)


if __name__ == "__main__":
    verify()
    table()
    cheb_tables()
