#!/usr/bin/env python3
"""Reference table for c_core's Cattaneo-Mindlin-Deresiewicz law
(dc/cmd_tangential.h), independent of the C code.

Rows (first field a tag; a = 1, one elastic body of G = 1 on a rigid one,
i.e. compliance sums s0 = 1, s1 = nu; mu F_n = 1 where a force is scaled):

noslip, b/a, nu, theta, k, psi
    A force at angle theta from the major axis, carried by Mindlin's
    traction F/(2 pi a b) (1 - x^2/a^2 - y^2/b^2)^-1/2, displaces the
    contact by u (Cerruti's kernel, Johnson Eq. 3.86, cross term included,
    integrated by mpmath at 40 digits, the radial integral in closed form
    as in gen_mindlin.py): k = |F|/|u|, psi = the angle of u (review Eq. 58).
micro, b/a, nu, theta, psi, x, F, delta
    Review Eqs. 59-61 at force angle theta (0, pi/2: Eqs. 60-61 with Phi;
    pi/4: Eq. 59 with chi): the force F (mu F_n = 1) at the displacement
    delta = x delta_L, delta_L = 3 mu F_n Phi / (16 G^ a), in the direction
    psi of Eq. 58.
loop, r, x, F_virgin, F_unload, F_reload
    Mindlin-Deresiewicz for the circle (k0 = 1, mu F_n = 1, r = F*/mu F_n):
    first loading (Eq. 59), unloading from F* (Eq. 67) and reloading from
    -F* at delta = x (inside [-delta*, delta*]).
nested, delta, F
    Nested reversals at constant F_n (k0 = 1, mu F_n = 1): Masing's rules
    with memory on a stack of turning points (virgin curve Eq. 59, branches
    F_r + 2 psi((delta - delta_r)/2), a branch that reaches the turning point
    before last continues on the earlier branch; the first branch rejoins
    the virgin curve at the mirror point), along legs through 0, 1.0, 0.2,
    0.8, 0.4, 0.9, 1.2, -0.5, 0.3, -2, 0 (4 points per leg).
energy, r, E_eq69, E_quad
    Energy per cycle k0 E_d / (mu F_n)^2: review Eq. 69 in pair form, and
    the area of the loop of Eq. 67 by quadrature (they agree to 1e-30).
twist, b/a, nu, k, k_eq77, Ms
    No-slip torsional stiffness (one body, G = 1, a = 1): the traction
    (-P y, Q x) (1 - x^2/a^2 - y^2/b^2)^-1/2 that turns the contact rigidly,
    from the two displacement gradients at the centre by quadrature (angular
    integrals numerical), and review Eq. 77 read for two identical bodies
    (k_eq77 = 2 / C_tau); Ms = full-slip moment / (mu F_n a) by quadrature
    of the Hertz pressure. That this traction turns the whole contact
    rigidly (not only at the centre) is checked at one off-centre point by
    a 2D quadrature (b/a = 0.5, nu = 0.3; to 1e-9).

Varying normal force (circle, Hertz: a = (N/N0)^1/3, k0 = a, mu = 1/2,
N0 = 2, so mu N0 = 1; C0 = 1/k0 at the current radius):
eq70, delta, N, T
    Review Eq. 70 (slip branch) from (N0, 0) with N = N0 + delta
    (mu dN/d delta = 1/2 < k0): dT = theta k0 d delta + mu dN (1 - theta),
    theta^3 = 1 - T/(mu N), integrated by mpmath's odefun.
eq70ns, delta, N, T
    Eq. 70, no slip (N = N0 + 4 delta: mu dN > k0 d delta): T = int k0 d delta.
eq71, delta, N, T
    First loading at N0 to T* = 0.6, then delta decreases while
    N = N0 + (delta* - delta): Eq. 71 corrected (header of
    dc/cmd_tangential.h): dT = theta k0 d delta - mu dN (1 - theta),
    theta^3 = 1 - (T* + mu (N - N0) - T)/(2 mu N).
eq71ns, delta, N, T
    The same with N = N0 + 4 (delta* - delta): no slip, dT = k0 d delta.
oblique, phase, T, delta
    Force-controlled oscillation (Eqs. 72-74), Theta = mu/Xi = 1/2,
    Lambda* = 1/2, N = N0 + T/Xi: delta(T) = int S dT on the phases
    0 OP (Eq. 72), 1 PRY (Eq. 73, first line), 2 YS (Eq. 73 second line,
    corrected), 3 SUV (Eq. 74), 4 VWS (Eq. 74 with Theta, Lambda reversed).
energy75, Theta, Lambda*, E
    Energy per stabilised cycle, Eq. 75 (pair form, 36/5 (mu N0)^2 / k0(N0)),
    equal to the area of the SUVWS loop by quadrature (checked here).
Eqs. 70-74 (as corrected) are checked here against an independent
brute-force simulation of the spring bed (3000 springs, force control by
bisection), to 1e-6.
Run: python3 gen_cmd_tangential.py  (writes cmd_tangential.csv beside it)
"""
import os
import sys
import mpmath as mp

mp.mp.dps = 40
here = os.path.dirname(os.path.abspath(__file__))
rows = []


def emit(tag, *vals):
    rows.append(tag + "," + ",".join(mp.nstr(mp.mpf(v), 25) if not isinstance(v, str) else v for v in vals))


def rho(phi, g):
    # distance from the centre to the ellipse x^2 + y^2/g^2 = 1 along phi
    return 1 / mp.sqrt(mp.cos(phi) ** 2 + mp.sin(phi) ** 2 / g ** 2)


def displacement(g, nu, theta):
    """u of a unit force at angle theta under Mindlin's traction (G = 1)."""
    ct, st = mp.cos(theta), mp.sin(theta)
    def fx(phi):
        c, s = mp.cos(phi), mp.sin(phi)
        return rho(phi, g) * (ct * ((1 - nu) + nu * c * c) + st * nu * c * s)
    def fy(phi):
        c, s = mp.cos(phi), mp.sin(phi)
        return rho(phi, g) * (st * ((1 - nu) + nu * s * s) + ct * nu * c * s)
    pts = mp.linspace(0, 2 * mp.pi, 9)
    pre = 1 / (2 * mp.pi * g) / (2 * mp.pi) * (mp.pi / 2)
    return pre * mp.quad(fx, pts), pre * mp.quad(fy, pts)


# ---- no-slip stiffness and psi in 12 directions
for g in ("1", "0.5", "0.2", "0.05"):
    for nu in ("0", "0.3", "0.5"):
        for k in range(12):
            th = mp.pi * k / 12 - mp.pi / 6
            ux, uy = displacement(mp.mpf(g), mp.mpf(nu), th)
            emit("noslip", g, nu, th, 1 / mp.sqrt(ux * ux + uy * uy), mp.atan2(uy, ux))

# ---- micro-slip, review Eqs. 59-61
for g in ("1", "0.5", "0.2"):
    for nu in ("0.3",):
        G, nuv, gg = mp.mpf(1), mp.mpf(nu), mp.mpf(g)
        m = 1 - gg * gg
        K, E = mp.ellipk(m), mp.ellipe(m)
        D = (K - E) / m if m != 0 else mp.pi / 4
        Ghat = 1 / ((2 - nuv) / G)   # one body on a rigid one
        for th in (mp.mpf(0), mp.pi / 2, mp.pi / 4):
            if th == 0:
                Phi = 4 / (mp.pi * (2 - nuv)) * ((1 - nuv) * K + nuv * D)        # Eq. 61
            elif th == mp.pi / 2:
                Phi = 4 / (mp.pi * (2 - nuv)) * (K - nuv * D)
            else:                                                                # Eq. 59 via chi
                chi = 1 / mp.sqrt(((1 - nuv) * K + nuv * D) ** 2 * mp.cos(th) ** 2 + (K - nuv * D) ** 2 * mp.sin(th) ** 2)
                Phi = 8 * Ghat / (2 * mp.pi * G * chi)   # 16 G^ a/(3 Phi) = 4 pi G a chi / 3
            dL = 3 * Phi / (16 * Ghat)                   # mu F_n = 1, a = 1 (Eq. 62)
            ps = mp.atan((K - nuv * D) / ((1 - nuv) * K + nuv * D) * mp.tan(th)) if th != mp.pi / 2 else th   # Eq. 58
            for j in range(1, 9):
                x = mp.mpf(j) / 8
                emit("micro", g, nu, th, ps, x, 1 - (1 - x) ** mp.mpf(1.5), x * dL)

# ---- the circle's loop (k0 = 1, mu F_n = 1: delta_L = 3/2)
dL = mp.mpf(3) / 2
psi = lambda d: 1 - (1 - d / dL) ** mp.mpf(1.5)            # Eq. 59, d in [0, dL]
phi = lambda F: dL * (1 - (1 - F) ** (mp.mpf(2) / 3))      # its inverse
for r in ("0.2", "0.5", "0.8", "0.95"):
    r = mp.mpf(r)
    ds = phi(r)
    for j in range(0, 9):
        x = -ds + 2 * ds * j / 8
        Fv = psi(x) if x >= 0 else mp.mpf(0)
        Fu = r - 2 * psi((ds - x) / 2)                     # Eq. 67 solved for F
        Fr = -r + 2 * psi((x + ds) / 2)
        emit("loop", r, x, Fv, Fu, Fr)
    # Eq. 69 with (2 - nu)/(G a) -> 8/k0 (pair form); the area of the loop
    E69 = mp.mpf(36) / 5 * (1 - (1 - r) ** (mp.mpf(5) / 3) - 5 * r / 6 * (1 + (1 - r) ** (mp.mpf(2) / 3)))
    du = lambda F: ds - 2 * phi((r - F) / 2)                # unloading branch delta(F)
    Eq = mp.quad(lambda F: du(F) - (-du(-F)), [-r, r])   # between unloading and reloading
    if abs(Eq - E69) > mp.mpf(10) ** -30:
        sys.exit("Eq. 69 disagrees with the loop area")
    emit("energy", r, E69, Eq)


# ---- nested reversals: Masing with memory (k0 = 1, mu F_n = 1, delta_L = 3/2)
def vpsi(d):   # virgin curve, odd, full slip beyond delta_L
    x = min(abs(d) / dL, mp.mpf(1))
    return mp.sign(d) * (1 - (1 - x) ** mp.mpf(1.5))


class Masing:
    def __init__(self):
        self.tp, self.d, self.s = [], mp.mpf(0), 0

    def force(self, d):
        if not self.tp:
            return vpsi(d)
        dr, Fr = self.tp[-1]
        return Fr + 2 * vpsi((d - dr) / 2)

    def move(self, d):
        s = mp.sign(d - self.d)
        if s == 0:
            return self.force(d)
        if self.s != 0 and s != self.s:
            self.tp.append((self.d, self.force(self.d)))    # a reversal
        self.s = s
        while True:
            if len(self.tp) >= 2 and s * (d - self.tp[-2][0]) >= 0:
                self.tp = self.tp[:-2]                      # memory: back on the earlier branch
            elif len(self.tp) == 1 and s * (d + self.tp[0][0]) >= 0 and s * self.tp[0][0] < 0:
                self.tp = []                                # back on the virgin curve
            else:
                break
        self.d = d
        return self.force(d)


M = Masing()
legs = [0, 1.0, 0.2, 0.8, 0.4, 0.9, 1.2, -0.5, 0.3, -2, 0]
for i in range(1, len(legs)):
    a0, a1 = mp.mpf(str(legs[i - 1])), mp.mpf(str(legs[i]))
    for j in range(1, 5):
        d = a0 + (a1 - a0) * j / 4
        emit("nested", d, M.move(d))


# ---- twisting: no-slip stiffness by quadrature, Eq. 77, full-slip moment
def twist(g, nu):
    # d u_x/d y and d u_y/d x at the centre per unit P and Q (G = 1):
    # (1/2 pi)(pi/2) int rho(phi) [...] dphi (radial integral in closed form)
    def I(f):
        return mp.quad(lambda p: rho(p, g) * f(mp.cos(p), mp.sin(p)), mp.linspace(0, 2 * mp.pi, 9)) / 4
    uxy_P = -I(lambda c, s: (1 - nu) * s * s + 3 * nu * c * c * s * s)
    uxy_Q = I(lambda c, s: nu * (-c * c + 3 * c * c * s * s))
    uyx_Q = I(lambda c, s: (1 - nu) * c * c + 3 * nu * c * c * s * s)
    uyx_P = -I(lambda c, s: nu * (-s * s + 3 * c * c * s * s))
    # rigid turn by omega = 1: d u_x/d y = -1, d u_y/d x = 1
    M = mp.matrix([[uxy_P, uxy_Q], [uyx_P, uyx_Q]])
    P, Q = mp.lu_solve(M, mp.matrix([-1, 1]))
    a, b = mp.mpf(1), g
    return 2 * mp.pi / 3 * a * b * (Q * a * a + P * b * b)


def twist_PQ(g, nu):
    def I(f):
        return mp.quad(lambda p: rho(p, g) * f(mp.cos(p), mp.sin(p)), mp.linspace(0, 2 * mp.pi, 9)) / 4
    M = mp.matrix([[-I(lambda c, s: (1 - nu) * s * s + 3 * nu * c * c * s * s), I(lambda c, s: nu * (-c * c + 3 * c * c * s * s))],
                   [-I(lambda c, s: nu * (-s * s + 3 * c * c * s * s)), I(lambda c, s: (1 - nu) * c * c + 3 * nu * c * c * s * s)]])
    return mp.lu_solve(M, mp.matrix([-1, 1]))


def rigid_off_centre(g, nu, x0, y0):
    """u at (x0, y0) under the traction of twist(): polar quadrature about the point."""
    P, Q = twist_PQ(g, nu)
    def R(p):
        c, s = mp.cos(p), mp.sin(p)
        A, B, C = c * c + s * s / g ** 2, x0 * c + y0 * s / g ** 2, x0 * x0 + y0 * y0 / g ** 2 - 1
        return (-B + mp.sqrt(B * B - A * C)) / A
    def comp(k):
        def inner(p):
            c, s = mp.cos(p), mp.sin(p)
            def f(r):
                x, y = x0 + r * c, y0 + r * s
                q = 1 - x * x - y * y / g ** 2
                w = 1 / mp.sqrt(q) if q > 0 else 0
                qx, qy = -P * y * w, Q * x * w
                if k == 0:
                    return qx * ((1 - nu) + nu * c * c) + qy * nu * c * s
                return qy * ((1 - nu) + nu * s * s) + qx * nu * c * s
            return mp.quad(f, [0, R(p)])
        return mp.quad(inner, mp.linspace(0, 2 * mp.pi, 17)) / (2 * mp.pi)
    return comp(0), comp(1)


mp.mp.dps = 15
ux, uy = rigid_off_centre(mp.mpf("0.5"), mp.mpf("0.3"), mp.mpf("0.3"), mp.mpf("0.2"))
if abs(ux + mp.mpf("0.2")) > 1e-9 or abs(uy - mp.mpf("0.3")) > 1e-9:
    sys.exit("the twisting traction does not turn the contact rigidly off the centre")
mp.mp.dps = 40

for g in ("1", "0.7", "0.5", "0.2", "0.05"):
    for nu in ("0", "0.3", "0.5"):
        gg, nuv = mp.mpf(g), mp.mpf(nu)
        k = twist(gg, nuv)
        m = 1 - gg * gg
        K, E = mp.ellipk(m), mp.ellipe(m)
        if m == 0:
            D = B = mp.pi / 4
            C = mp.pi / 16
        else:
            D = (K - E) / m
            B = K - D
            C = (D - B) / m
        Ct = mp.mpf(3) / 8 * 8 * (B * D - nuv * C * E) / (mp.pi * (E - 4 * nuv * (1 - m) * C))   # Eq. 77, G = a = 1
        # full slip: mu int p r dA, p = 3 F/(2 pi a b) (1 - rho^2)^1/2
        Ms = 3 / (2 * mp.pi) * mp.quad(lambda t: mp.sqrt(1 - t * t) * t * t, [0, 1]) * \
            mp.quad(lambda p: mp.sqrt(mp.cos(p) ** 2 + gg * gg * mp.sin(p) ** 2), [0, mp.pi / 2, mp.pi, 3 * mp.pi / 2, 2 * mp.pi])
        emit("twist", g, nu, k, 2 / Ct, Ms)



# ---- varying normal force (circle, Hertz)
MU, NZ = mp.mpf(1) / 2, mp.mpf(2)
aN = lambda N: (N / NZ) ** (mp.mpf(1) / 3)    # contact radius, k0 = a


def ode(f, x0, y0, xs):
    sol = mp.odefun(f, x0, y0)
    return [sol(x) for x in xs]


# Eq. 70, slip (g = 1) and no slip (g = 4)
xs = [mp.mpf(j) / 10 for j in range(1, 13)]
f70 = lambda d, T: mp.cbrt(1 - T / (MU * (NZ + d))) * aN(NZ + d) + MU * (1 - mp.cbrt(1 - T / (MU * (NZ + d))))
for d, T in zip(xs, ode(f70, mp.mpf(0), mp.mpf(0), xs)):
    emit("eq70", d, NZ + d, T)
for d in xs:
    g = 4
    emit("eq70ns", d, NZ + g * d, 3 * NZ / (4 * g) * ((1 + g * d / NZ) ** (mp.mpf(4) / 3) - 1))
# Eq. 71 (corrected): virgin to T* = 0.6 at N0 (delta_L = 3/2), then unloading
Tst = mp.mpf("0.6")
dst = mp.mpf(3) / 2 * (1 - (1 - Tst) ** (mp.mpf(2) / 3))
def f71(e, T):   # e = delta* - delta, dT/de
    N = NZ + e
    th = mp.cbrt(1 - (Tst + MU * (N - NZ) - T) / (2 * MU * N))
    return -(th * aN(N) + MU * (1 - th))
es = [mp.mpf(j) / 10 for j in range(1, 10)]
for e, T in zip(es, ode(f71, mp.mpf(0), Tst, es)):
    # the formula holds until the reverse front reaches the first one
    c = mp.cbrt(1 - Tst / (MU * NZ))
    th = mp.cbrt(1 - (Tst + MU * e - T) / (2 * MU * (NZ + e)))
    if th * aN(NZ + e) <= c:
        sys.exit("eq71 rows past the memory point")
    emit("eq71", dst - e, NZ + e, T)
for e in es:
    g = 4
    emit("eq71ns", dst - e, NZ + g * e, Tst - 3 * NZ / (4 * g) * ((1 + g * e / NZ) ** (mp.mpf(4) / 3) - 1))

# Eqs. 72-74: Theta = 1/2, Lambda* = 1/2
TH, LS = mp.mpf(1) / 2, mp.mpf(1) / 2
XI, TS, UP = MU / TH, LS * MU * NZ, (TH - 1) / (TH + 1)
C0 = lambda T: 1 / aN(NZ + T / XI)
Lm = lambda T: T / (MU * NZ)
third = mp.mpf(1) / 3
S_OP = lambda T: C0(T) * (TH + (1 - TH) * (1 - Lm(T) / (1 + TH * Lm(T))) ** -third)
S_PRY = lambda T: C0(T) * (-TH + (1 + TH) * (1 - (1 - TH) * (LS - Lm(T)) / (2 * (1 + TH * Lm(T)))) ** -third)
S_YS = lambda T: C0(T) * (-TH + (1 + TH) * (1 + Lm(T) / (1 + TH * Lm(T))) ** -third)
S_SUV = lambda T: C0(T) * (TH + (1 - TH) * (1 - (1 + TH) * (LS + Lm(T)) / (2 * (1 + TH * Lm(T)))) ** -third)
S_VWS = S_PRY
phases = [(S_OP, 0, TS), (S_PRY, TS, UP * TS), (S_YS, UP * TS, -TS), (S_SUV, -TS, TS), (S_VWS, TS, -TS)]
d0 = mp.mpf(0)
ends = []
for ph, (S, t0, t1) in enumerate(phases):
    for j in range(1, 9):
        T = t0 + (t1 - t0) * j / 8
        emit("oblique", ph, T, d0 + mp.quad(S, [t0, T]))
    d0 += mp.quad(S, [t0, t1])
    ends.append(d0)
if abs(ends[4] - ends[2]) > mp.mpf(10) ** -25:
    sys.exit("the stabilised loop does not close")
E_loop = mp.quad(lambda T: T * (S_SUV(T) - S_VWS(T)), [-TS, TS])
E75 = mp.mpf(36) / 5 * (MU * NZ) ** 2 * (1 / (4 * TH) * (-(1 / UP) * (1 - TH * LS) ** (mp.mpf(5) / 3) + UP * (1 + TH * LS) ** (mp.mpf(5) / 3))
                                        - 1 / (1 - TH ** 2) * (1 - LS) ** (mp.mpf(2) / 3) * (1 - (1 + 5 * TH ** 2) / 6 * LS))
if abs(E_loop - E75) > mp.mpf(10) ** -25 * E75:
    sys.exit("Eq. 75 is not the area of the stabilised loop")
emit("energy75", TH, LS, E75)


# ---- the formulas against a brute-force spring bed (floats, independent)
def bed_check():
    mu, N0, K, amax = 0.5, 2.0, 3000, 2.2
    dx = amax / K
    xs = [(i + 0.5) * dx for i in range(K)]
    lam = 1.5 * mu * N0        # limits lam (a^2 - x^2) integrate to mu N (k0 = a)
    aof = lambda N: (N / N0) ** (1 / 3)
    def step(u, dd, N):
        a2 = aof(N) ** 2
        for i, x in enumerate(xs):
            if x * x >= a2:
                u[i] = 0.0
                continue
            v, l = u[i] + dd, lam * (a2 - x * x)
            u[i] = l if v > l else (-l if v < -l else v)
    T = lambda u: sum(u) * dx
    bad = []
    u = [0.0] * K                                # Eq. 70
    for i in range(2400):
        step(u, 1.2 / 2400, N0 + 1.2 * (i + 1) / 2400)
    bad.append((T(u), float([r for r in rows if r.startswith("eq70,1.2,")][0].split(",")[3])))
    u = [0.0] * K                                # Eq. 71
    for i in range(2000):
        step(u, float(dst) / 2000, N0)
    for i in range(1800):
        step(u, -0.9 / 1800, N0 + 0.9 * (i + 1) / 1800)
    bad.append((T(u), float([r for r in rows if r.startswith("eq71,") and r.split(",")[2].startswith("2.9")][0].split(",")[3])))
    u, d = [0.0] * K, 0.0                        # Eqs. 72-74, force control
    def goto(Tt, d):
        N, lo, hi = N0 + Tt / float(XI), -0.05, 0.05
        for _ in range(50):
            mid, c = 0.5 * (lo + hi), u[:]
            step(c, mid, N)
            lo, hi = (mid, hi) if T(c) < Tt else (lo, mid)
        step(u, 0.5 * (lo + hi), N)
        return d + 0.5 * (lo + hi)
    n = 100
    for ph, (S, t0, t1) in enumerate(phases):
        for i in range(n):
            d = goto(float(t0 + (t1 - t0) * (i + 1) / n), d)
        bad.append((d, float(ends[ph])))
    worst = max(abs(got - want) / max(1.0, abs(want)) for got, want in bad)
    print("brute-force spring bed vs Eqs. 70-74: %d checks, worst difference %.1e" % (len(bad), worst))
    if worst > 1e-6:
        sys.exit("the brute-force spring bed disagrees with Eqs. 70-74")


bed_check()

with open(os.path.join(here, "cmd_tangential.csv"), "w") as out:
    out.write("# generated by gen_cmd_tangential.py (mpmath, 40 digits); rows described there\n")
    for r in rows:
        out.write(r + "\n")
print(len(rows), "rows")
