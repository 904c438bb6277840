#!/usr/bin/env python3
"""Reference table for c_core/src/gw_rough_adhesive.c: Greenwood-Williamson
rough contact with adhesive (JKR) summits, the Fuller & Tabor (1975)
construction (review Eq. 29 with f = the JKR summit law; elliptic summits
after Johnson & Greenwood 2005).

  F(delta)  = n_asp int_{s0}^oo f(delta + sigma s) phi(s) ds,
  A(delta)  = the same with the summit area,
  kn(delta) = dF/d delta = n_asp [int f'(u) phi ds + f(u0) phi(s0)/sigma],
  s0 = (u0 - delta)/sigma, u0 = 0 (loading: summits attach on touch) or
  u0 = delta_break (unloading: summits stay attached to the separation
  point of the summit law), phi the standard normal density.

Independent of the C code, which inverts the summit law at each quadrature
node (dc_jkr_sphere / dc_jkr_contact): here nothing is inverted. The
integrals are taken over the summit's contact-state parameter p, along
which the summit compression u(p), force f(p) and area A(p) are explicit,
with ds = u'(p) dp / sigma:
  spheres, p = contact radius a (classical JKR):
    u = a^2/R - (2 pi w a/E*)^1/2,  f = 4 E* a^3/(3R) - (8 pi w E* a^3)^1/2,
    A = pi a^2; the branch starts at a_b = (pi w R^2/(8 E*))^1/3
    (unloading, u'(a_b) = 0) or a_0 = (2 pi w R^2/E*)^1/3 (loading, u = 0);
  ellipses, p = e^2 (Johnson-Greenwood, the equations of jkr_elliptic.h),
    on the stable branch from the separation point e2_break (unloading) or
    from the root of u(e^2) = 0 (loading) to the Hertz shape e2_hertz
    (u -> oo). Derivatives in e^2 by mpmath.diff. These formulas are
    first checked against gen_jkr_elliptic.Shape, which solves the
    elliptic contact from the potential integrals of the pressure.
In p the integrands are smooth (the vertical tangent of f(u) at the
separation point is a zero of u'(p)), so Gauss-Legendre panels between
breakpoints (every 1/2 in s, geometric steps in u - u0 on the scale of
delta_break, the zero of f for int |f|) converge fast; every value is
computed with 30 and with 20 nodes per panel and the two must agree to
1e-20 (F against int |f| phi ds, the area relative, kn against
|kn| + int |f| phi ds / sigma). The Gaussian is cut where phi < e^-80 of its
largest value on the range. Columns:
  shape (0 sphere, 1 ellipse), R_major, R_minor, Estar, w, sigma, n_asp,
  theta = Estar sigma^3/2 / (w Rhat^1/2) (Fuller-Tabor adhesion parameter
  without their numerical factor), h = -delta/sigma, delta, branch
  (0 loading, 1 unloading), F, area, kn, Fabs = n_asp int |f| phi ds.
Inputs are doubles (written with repr) and the values are for exactly
those. Also checked here: the parametric integral against a direct
integral over u with the sphere law inverted by findroot (one case), and
w -> 0 against the closed form 4/3 E* R^1/2 sigma^3/2 F_3/2(h).
Run: python3 gen_gw_rough_adhesive.py   (about 10 minutes)
"""
import csv
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import gen_jkr_elliptic as gje  # noqa: E402  (sets mp.dps on import)
import mpmath as mp  # noqa: E402

mp.mp.dps = 40
ESTAR = mp.mpf(1e9)
assert gje.ESTAR == ESTAR
SIGMA = mp.mpf(1e-7)
N_ASP = mp.mpf(100)
R_MAJOR = mp.mpf(1e-3)
ELL_RATIO_MINOR = mp.mpf(2e-4)  # R_minor/R_major = 0.2
WS_SPHERE = ['2', '0.5', '0.1', '0.02', '1e-3', '1e-5']   # theta 0.5 .. 1e5
WS_ELLIPSE = ['2', '0.5', '0.1', '0.02', '1e-3']
HS = ['-6', '-3', '-1', '0', '0.5', '1', '2', '3', '5']
S_CUT2 = 160  # phi(s)/phi(s_ref) >= e^-80 on the range


def phi(s):
    return mp.exp(-s * s / 2) / mp.sqrt(2 * mp.pi)


_GL = {}


def gl(n):
    """Gauss-Legendre nodes and weights on [-1, 1] at the working precision."""
    key = (n, mp.mp.prec)
    if key in _GL:
        return _GL[key]
    xs, ws = [], []
    for i in range(1, n + 1):
        x = mp.cos(mp.pi * (i - mp.mpf(1) / 4) / (n + mp.mpf(1) / 2))
        for _ in range(100):
            p0, p1 = mp.mpf(1), x
            for k in range(2, n + 1):
                p0, p1 = p1, ((2 * k - 1) * x * p1 - (k - 1) * p0) / k
            dp = n * (x * p1 - p0) / (x * x - 1)
            dx = p1 / dp
            x -= dx
            if abs(dx) < mp.mpf(10) ** (-mp.mp.dps - 5):
                break
        p0, p1 = mp.mpf(1), x
        for k in range(2, n + 1):
            p0, p1 = p1, ((2 * k - 1) * x * p1 - (k - 1) * p0) / k
        dp = n * (x * p1 - p0) / (x * x - 1)
        xs.append(x)
        ws.append(2 / ((1 - x * x) * dp * dp))
    _GL[key] = (xs, ws)
    return xs, ws


class Sphere:
    """Classical JKR summit, parameter p = contact radius a."""

    def __init__(self, R, w):
        self.R, self.w = R, w
        self.p_break = mp.cbrt(mp.pi * w * R * R / (8 * ESTAR))
        self.p_zero_u = mp.cbrt(2 * mp.pi * w * R * R / ESTAR)
        # f = 0: a^3/2 = (3R/(4E*)) (8 pi w E*)^1/2
        self.p_zero_f = ((3 * R / (4 * ESTAR)) * mp.sqrt(8 * mp.pi * w * ESTAR)) ** (mp.mpf(2) / 3)
        self.p_far = None

    def u(self, a):
        return a * a / self.R - mp.sqrt(2 * mp.pi * self.w * a / ESTAR)

    def eval(self, a):
        """u, f, A, du/dp, df/dp."""
        R, w = self.R, self.w
        u = a * a / R - mp.sqrt(2 * mp.pi * w * a / ESTAR)
        f = 4 * ESTAR * a ** 3 / (3 * R) - mp.sqrt(8 * mp.pi * w * ESTAR * a ** 3)
        du = 2 * a / R - mp.sqrt(2 * mp.pi * w / (ESTAR * a)) / 2
        df = 4 * ESTAR * a * a / R - mp.mpf(3) / 2 * mp.sqrt(8 * mp.pi * w * ESTAR * a)
        return u, f, mp.pi * a * a, du, df

    def p_of_u(self, target):
        """Bisection on the stable branch (breakpoints only)."""
        lo, hi = self.p_break, self.p_break * 2
        while self.u(hi) < target:
            hi *= 2
        for _ in range(200):
            mid = (lo + hi) / 2
            if self.u(mid) < target:
                lo = mid
            else:
                hi = mid
            if hi - lo < mp.mpf(10) ** -30 * hi:
                break
        return (lo + hi) / 2


class Ellipse:
    """Johnson-Greenwood elliptic JKR summit, parameter p = e^2 (jkr_elliptic.h)."""

    def __init__(self, R1, R2, w):
        self.R1, self.R2, self.w = R1, R2, w
        self.lam2 = R2 / R1
        self.lam = mp.sqrt(self.lam2)
        self.Rhat = mp.sqrt(R1 * R2)
        # Hertz shape: Qn = (1 - lam^2) B - m (D - C) = 0
        self.m_hertz = mp.findroot(lambda m: self._Qn(m), (mp.mpf('0.01'), mp.mpf('0.99')), solver='illinois')
        # separation point: the minimum of u(e^2) on (0, e2_hertz)
        ms = sorted([self.m_hertz * mp.mpf(10) ** (-mp.mpf(k) / 8) for k in range(1, 24)] +
                    [self.m_hertz * (1 - mp.mpf(10) ** (-mp.mpf(k) / 8)) for k in range(4, 40)])
        us = [self.u(m) for m in ms]
        k = min(range(len(ms)), key=lambda i: us[i])
        assert 0 < k < len(ms) - 1
        self.p_break = gje.extremum(self.u, ms[k - 1], ms[k + 1])
        hi = ms[k + 1]
        while self.u(hi) < 0:
            hi = (hi + self.m_hertz) / 2
        self.p_zero_u = mp.findroot(self.u, (self.p_break, hi), solver='illinois')
        while self.eval0(hi)[1] < 0:
            hi = (hi + self.m_hertz) / 2
        self.p_zero_f = mp.findroot(lambda m: self.eval0(m)[1], (self.p_break, hi), solver='illinois')

    @staticmethod
    def _ell(m):
        K, E = mp.ellipk(m), mp.ellipe(m)
        D = (K - E) / m
        B = K - D
        C = (D - B) / m
        return K, E, D, B, C

    def _Qn(self, m):
        K, E, D, B, C = self._ell(m)
        return (1 - self.lam2) * B - m * (D - C)

    def eval0(self, m):
        """u, f, A at e^2 = m (review Eqs. 19-23 as in jkr_elliptic.h), and a, b."""
        K, E, D, B, C = self._ell(m)
        lam, lam2, w = self.lam, self.lam2, self.w
        g2 = 1 - m
        g = mp.sqrt(g2)
        Del = D * B + g2 * C * D + B * C
        Pi2 = ((1 + lam2) * C + D) / (lam * Del)
        Pi1 = (lam + 1 / lam - B * Pi2) / D
        Q = g2 * Pi2 - Pi1
        rho = Q / (1 - mp.sqrt(g))
        X = g2 * Pi2 * K + Q * B - 2 * K * rho
        Y = g2 * Pi2 / 3 + Q / 3 - rho
        a = mp.cbrt(8 * w * self.Rhat ** 2 / (mp.pi * ESTAR) * g / rho ** 2)
        u = a * a * X / (2 * self.Rhat)
        f = 8 * w * self.Rhat * g * Y / rho ** 2
        return u, f, mp.pi * a * a * g, a, g * a

    def u(self, m):
        return self.eval0(m)[0]

    def eval(self, m):
        u, f, A, _, _ = self.eval0(m)
        du = mp.diff(lambda t: self.eval0(t)[0], m)
        df = mp.diff(lambda t: self.eval0(t)[1], m)
        return u, f, A, du, df

    def p_of_u(self, target):
        lo, hi = self.p_break, self.m_hertz
        for _ in range(300):
            mid = (lo + hi) / 2
            if self.u(mid) < target:
                lo = mid
            else:
                hi = mid
            if hi - lo < mp.mpf(10) ** -32:
                break
        return (lo + hi) / 2


def check_ellipse_against_shape(el):
    """The e^2 formulas against gen_jkr_elliptic's first-principles solve."""
    worst = 0
    for t in ['0.01', '0.3', '0.9']:
        m = el.p_break + (el.m_hertz - el.p_break) * mp.mpf(t)
        u, f, A, a, b = el.eval0(m)
        sh = gje.Shape(mp.sqrt(1 - m), el.R1, el.R2)
        a2, b2, d2, F2 = sh.state(el.w)
        for x, y in ((u, d2), (f, F2), (a, a2), (b, b2)):
            worst = max(worst, abs(x / y - 1))
    assert worst < mp.mpf(10) ** -20, worst
    return worst


def integrate(law, delta, branch, n):
    """F, A, kn, Fabs (per summit count n_asp = 1) with n GL nodes per panel."""
    p0 = law.p_zero_u if branch == 0 else law.p_break
    u0 = law.eval(p0)[0] if branch == 1 else mp.mpf(0)
    s0 = (u0 - delta) / SIGMA
    s_ref = max(s0, 0)
    s_max = mp.sqrt(s_ref * s_ref + S_CUT2)
    ub = abs(law.u(law.p_break))
    svals = {s_max}
    k = int(mp.floor(2 * s0)) + 1
    while mp.mpf(k) / 2 < s_max:
        svals.add(mp.mpf(k) / 2)
        k += 1
    j = -8
    while s0 + ub * mp.mpf(2) ** j / SIGMA < s_max:
        svals.add(s0 + ub * mp.mpf(2) ** j / SIGMA)
        j += 1
    pts = sorted(set([p0] + [law.p_of_u(delta + SIGMA * s) for s in svals if s > s0]))
    if pts[0] < law.p_zero_f < pts[-1]:
        pts = sorted(set(pts + [law.p_zero_f]))
    xs, ws = gl(n)
    IF = IA = IK = IB = mp.mpf(0)
    for lo, hi in zip(pts[:-1], pts[1:]):
        c, hw = (lo + hi) / 2, (hi - lo) / 2
        for x, wgt in zip(xs, ws):
            p = c + hw * x
            u, f, A, du, df = law.eval(p)
            ph = phi((u - delta) / SIGMA) * wgt * hw / SIGMA
            IF += f * ph * du
            IA += A * ph * du
            IB += abs(f) * ph * du
            IK += df * ph
    f0 = law.eval(p0)[1]
    IK += f0 * phi(s0) / SIGMA
    return IF, IA, IK, IB


def table_rows(law, shape, R1, R2, w, Rhat):
    rows = []
    theta = ESTAR * SIGMA ** mp.mpf(1.5) / (w * mp.sqrt(Rhat))
    for hs in HS:
        delta = mp.mpf(float(-mp.mpf(hs) * SIGMA))
        for branch in (0, 1):
            a = integrate(law, delta, branch, 30)
            b = integrate(law, delta, branch, 20)
            scale = (a[3], a[1], abs(a[2]) + a[3] / SIGMA, a[3])
            for x, y, sc in zip(a, b, scale):
                assert abs(x - y) < mp.mpf(10) ** -20 * sc, (shape, w, hs, branch, x, y)
            F, A, K, B = (N_ASP * v for v in a)
            rows.append([shape, R1, R2, ESTAR, w, SIGMA, N_ASP, theta, mp.mpf(hs), delta, branch, F, A, K, B])
            print(shape, mp.nstr(w, 3), hs, branch, 'F', mp.nstr(F, 12), 'A', mp.nstr(A, 12), 'kn', mp.nstr(K, 12))
    return rows


def check_direct(law, delta, branch):
    """Sphere: the same F by integrating over u, the law inverted by findroot."""
    u0 = law.u(law.p_break) if branch == 1 else mp.mpf(0)
    s0 = (u0 - delta) / SIGMA

    def f_of_s(s):
        u = delta + SIGMA * s
        a = mp.findroot(lambda a: law.u(a) - u, law.p_of_u(u))
        return law.eval(a)[1] * phi(s)
    s_max = mp.sqrt(max(s0, 0) ** 2 + S_CUT2)
    pts = [s0] + [mp.mpf(k) for k in range(int(mp.ceil(s0)), int(s_max) + 1) if k > s0] + [s_max]
    return mp.quad(f_of_s, pts)


def main():
    # the parametric integral against a direct one (sphere, unloading: the
    # vertical tangent at s0 is handled by tanh-sinh's endpoint clustering)
    mp.mp.dps = 25
    sp = Sphere(R_MAJOR, mp.mpf('0.5'))
    d = mp.mpf(float(-SIGMA / 2))
    direct = check_direct(sp, d, 1)
    param = integrate(sp, d, 1, 30)
    assert abs(direct / param[0] - 1) < mp.mpf(10) ** -15, (direct, param[0])
    print('direct vs parametric (sphere, unloading, h = 0.5): %.1e' % float(abs(direct / param[0] - 1)))
    # w -> 0: 4/3 E* R^1/2 sigma^3/2 F_3/2(h), F_3/2(h) = Gamma(5/2) phi(h) e^{h^2/4} D_{-5/2}(h)
    mp.mp.dps = 40
    sp = Sphere(R_MAJOR, mp.mpf('1e-40'))
    for hs in ('-1', '1'):
        h = mp.mpf(hs)
        F = integrate(sp, -h * SIGMA, 0, 30)[0]
        F32 = mp.gamma(mp.mpf(5) / 2) * phi(h) * mp.exp(h * h / 4) * mp.pcfd(mp.mpf(-5) / 2, h)
        ref = 4 * ESTAR * mp.sqrt(R_MAJOR) * SIGMA ** mp.mpf(1.5) * F32 / 3
        assert abs(F / ref - 1) < mp.mpf(10) ** -12, (F, ref)
        print('w = 1e-40, h = %s: F / Hertz-GW - 1 = %.1e' % (hs, float(F / ref - 1)))

    rows = []
    for w in WS_SPHERE:
        w = mp.mpf(w)
        rows += table_rows(Sphere(R_MAJOR, w), 0, R_MAJOR, R_MAJOR, w, R_MAJOR)
    for w in WS_ELLIPSE:
        w = mp.mpf(w)
        el = Ellipse(R_MAJOR, ELL_RATIO_MINOR, w)
        print('ellipse w = %s: e2_hertz %s, e2_break %s; e^2 formulas vs Shape: %.1e' % (
            mp.nstr(w, 3), mp.nstr(el.m_hertz, 10), mp.nstr(el.p_break, 10),
            float(check_ellipse_against_shape(el))))
        rows += table_rows(el, 1, R_MAJOR, ELL_RATIO_MINOR, w, el.Rhat)
    with open(os.path.join(HERE, 'gw_rough_adhesive.csv'), 'w', newline='') as f:
        wr = csv.writer(f)
        wr.writerow(['shape', 'R_major', 'R_minor', 'Estar', 'w', 'sigma', 'n_asp', 'theta', 'h', 'delta',
                     'branch', 'F', 'area', 'kn', 'Fabs'])
        for r in rows:
            wr.writerow([r[0]] + [repr(float(v)) for v in r[1:7]] + [mp.nstr(r[7], 10), mp.nstr(r[8], 3),
                         repr(float(r[9])), r[10]] + [mp.nstr(v, 22) for v in r[11:]])


if __name__ == '__main__':
    main()
