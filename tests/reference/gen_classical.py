#!/usr/bin/env python3
"""Reference table for the classical contact laws of the lecture notes
(Lopez Rangel 2021; c_core/include/dc/classical_normal.h, classical_tangential.h).

For each normal law the figures of one head-on collision (duration, maximum
overlap, restitution, maximum force, residual overlap) two ways, with
mpmath at 30 digits:
- the closed forms (derived in classical_normal.h), and
- an independent integration of m delta'' = -F(delta, delta') (mpmath's
  Taylor-series odefun) with its events found by findroot.
The script asserts that the two agree (1e-18) wherever a closed form exists,
and writes the integrated figures for the laws without one (Hertz with
Kuwabara-Kono, BSHP, Tsuji and LIGGGHTS' restitution damping).

Hertz family: delta^3/2 and delta^q (q = 1/4, 1/2) are not analytic in t
where delta = 0, so the contact is integrated in three pieces, each of
analytic right-hand side: s = delta^1/4 as the variable while approaching
and while leaving (delta' bounded away from 0 there), the time t around
the turning point.

Tangential: the stable loop of Walton-Braun incrementally slipping friction
between displacements -X and X (amplitude from findroot, energy from quad,
the branch checked against an integration of dT/dx = K0 (1 - (T - T*)/(mu N - T*))^1/3).

Writes classical.csv beside this script. Run: python3 gen_classical.py
"""
import os
import mpmath as mp

mp.mp.dps = 30
here = os.path.dirname(os.path.abspath(__file__))
PI = mp.pi

# constants of the notes, exact
I_HZ = mp.sqrt(PI) * mp.gamma(mp.mpf(7) / 5) / mp.gamma(mp.mpf(9) / 10)   # int_0^1 (1-x^5/2)^-1/2
C_T = 2 * (mp.mpf(15) / 16) ** (mp.mpf(2) / 5) * I_HZ
K_DUR = PI ** 2 / C_T ** 2
K_OVL = (mp.mpf(16) / 15) ** (mp.mpf(4) / 5)
# BSHP first-order restitution, F_dis = K_HZ A' delta^1/2 delta':
# 1 - e = C1 A' (K_HZ/m)^2/5 v^1/5 + O(A'^2); C1 = 2/5 B(3/5, 3/2) (5/4)^3/5 2
C1_BSHP = 2 * mp.mpf(2) / 5 * mp.beta(mp.mpf(3) / 5, mp.mpf(3) / 2) * (mp.mpf(5) / 4) ** (mp.mpf(3) / 5)

# material pair (glass-like), SI
ESTAR = mp.mpf("3e10")
RAD = mp.mpf("5e-4")
MEFF = mp.mpf("5e-6")

# damping law codes of dc/damping.h
RESTITUTION, VISCOELASTIC, KUWABARA_KONO, TSUJI, NONE = 0, 1, 2, 3, 4
LSD, HERTZ, HLS_CONSTANT, HLS_VARIABLE = 0, 1, 2, 3


# ------------------------------------------------------------------ integrator
# Bulirsch-Stoer: modified midpoint steps extrapolated to zero step in h^2
# (Neville), to TOL relative; an event is a sign change of g(x, y) between
# two steps, located by findroot on the end point of one extrapolated step.
TOL = mp.mpf(10) ** (-27)


def _mmid(f, x, y, H, n):
    h = H / n
    z0 = list(y)
    z1 = [a + h * b for a, b in zip(y, f(x, y))]
    for i in range(1, n):
        fz = f(x + i * h, z1)
        z0, z1 = z1, [a + 2 * h * b for a, b in zip(z0, fz)]
    fz = f(x + H, z1)
    return [(a + b + h * c) / 2 for a, b, c in zip(z0, z1, fz)]


def bs_step(f, x, y, H):
    """y(x + H); raises if the extrapolation does not settle."""
    T = []
    for k in range(12):
        n = 2 * (k + 1)
        row = [_mmid(f, x, y, H, n)]
        for j in range(1, k + 1):
            r = (mp.mpf(n) / (n - 2 * j)) ** 2   # (n_k / n_{k-j})^2
            row.append([a + (a - b) / (r - 1) for a, b in zip(row[j - 1], T[k - 1][j - 1])])
        T.append(row)
        if k >= 3:
            err = max(abs(a - b) / max(abs(a), mp.mpf(1)) for a, b in zip(row[k], row[k - 1]))
            if err < TOL:
                return row[k]
    raise ArithmeticError("no convergence")


def bs_to(f, x, y, x1, H):
    """Integrates from x to x1 in steps of at most H (halved where needed)."""
    while x < x1:
        last = x1 - x <= H
        h = x1 - x if last else H
        try:
            y = bs_step(f, x, y, h)
        except ArithmeticError:
            H = H / 2
            continue
        x = x1 if last else x + h
    return y


def bs_event(f, x, y, H, g, xmax):
    """First x in (x, xmax] with g(x, y(x)) = 0 (g changes sign); returns x, y."""
    g0 = g(x, y)
    while x < xmax:
        h = min(H, xmax - x)
        try:
            y1 = bs_step(f, x, y, h)
        except ArithmeticError:
            H = H / 2
            continue
        g1 = g(x + h, y1)
        if (g0 > 0) != (g1 > 0) or g1 == 0:
            x0, y0 = x, y
            xe = mp.findroot(lambda xx: g(xx, bs_to(f, x0, y0, xx, h)) if xx > x0 else g0,
                             (x0, x0 + h), solver="anderson")
            return xe, bs_to(f, x0, y0, xe, h)
        x, y, g0 = x + h, y1, g1
    raise ArithmeticError("no event")


def close(a, b, tol=mp.mpf("1e-18")):
    return abs(a - b) <= tol * max(abs(b), mp.mpf("1e-300"))


# ------------------------------------------------------------------ LSD
def lsd_closed(K, eta, m, v, limit):
    psi = eta / (2 * m)
    W = mp.sqrt(K / m - psi ** 2)
    r = psi / W
    wm = mp.atan2(W, psi)
    dmax = v / W * mp.exp(-r * wm) * mp.sin(wm)
    if not limit:
        return PI / W, dmax, mp.exp(-PI * r)
    th = mp.atan2(eta * W, -(K - eta * psi))
    return th / W, dmax, abs(mp.exp(-r * th) * (mp.cos(th) - r * mp.sin(th)))


def lsd_ode(K, eta, m, v, limit):
    """Integrates m x'' = -K x - eta x' in units of (m/K)^1/2 and v."""
    T = mp.sqrt(m / K)
    z = eta * T / m
    f = lambda t, y: [y[1], -y[0] - z * y[1]]
    H = mp.mpf("0.1")
    tm, ym = bs_event(f, mp.mpf(0), [mp.mpf(0), mp.mpf(1)], H, lambda t, y: y[1], mp.mpf(10))
    if not limit:
        te, ye = bs_event(f, tm, ym, H, lambda t, y: y[0], mp.mpf(10))
    else:
        te, ye = bs_event(f, tm, ym, H, lambda t, y: y[0] + z * y[1], mp.mpf(10))
    return te * T, ym[0] * v * T, abs(ye[1])


def lsd_eta(e, m, K):
    l = mp.log(e)
    return -2 * l * mp.sqrt(m * K) / mp.sqrt(l ** 2 + PI ** 2)


def matched_k(law, method, e, E, R, m, v):
    base = (v * R * E ** 2 * mp.sqrt(m)) ** (mp.mpf(2) / 5)
    x = -mp.log(e) / PI
    if method == 1:   # duration
        return (K_DUR * (1 + x ** 2) if law == LSD else K_DUR / 4 * (1 + e) ** 2) * base
    if method == 2 and law == LSD and x > 0:   # overlap, damped LSD
        return K_OVL * mp.exp(-2 * x * mp.atan(1 / x)) * base
    return K_OVL * base


# ------------------------------------------------------------------ Hertz family
def hertz_damping(law, coef, E, R, m):
    """gamma = c delta^q of each damping law (dc/damping.h) as (c, q)."""
    S1 = 2 * E * mp.sqrt(R)      # S = S1 delta^1/2
    if law == RESTITUTION:       # -2 sqrt(5/6) beta (S m)^1/2
        return -2 * mp.sqrt(mp.mpf(5) / 6) * coef * mp.sqrt(S1 * m), mp.mpf(1) / 4
    if law == TSUJI:             # alpha (2/3 S m)^1/2
        return coef * mp.sqrt(mp.mpf(2) / 3 * S1 * m), mp.mpf(1) / 4
    if law == VISCOELASTIC:      # A S
        return coef * S1, mp.mpf(1) / 2
    if law == KUWABARA_KONO:     # eta delta^1/2
        return coef, mp.mpf(1) / 2
    return mp.mpf(0), mp.mpf(1) / 2


def hertz_ode(Khz, c, q, m, v, limit):
    """Collision of m x'' = -Khz x^3/2 - c x^q x', x(0) = 0, x'(0) = v.
    Returns Tc, dmax, e, F_max (elastic force at dmax)."""
    d0 = (mp.mpf(5) * m * v ** 2 / (4 * Khz)) ** (mp.mpf(2) / 5)   # elastic delta_max
    t0 = d0 / v
    C = c * d0 ** (q + 1) / (m * v)                                  # x'' = -5/4 x^3/2 - C x^q x'
    k = mp.mpf(5) / 4
    p = int(4 * q)   # x^q = s^p with x = s^4

    def rhs_s(s, Y):   # variable s = x^1/4: Y = (x', t)
        y = Y[0]
        return [4 * s ** 3 * (-k * s ** 6 - C * s ** p * y) / y, 4 * s ** 3 / y]

    def rhs_t(t, Y):   # Y = (x, x')
        x, y = Y
        return [y, -k * x ** mp.mpf(1.5) - C * x ** q * y]

    H = mp.mpf("0.05")
    x1 = mp.mpf("0.02")
    s1 = x1 ** mp.mpf(0.25)
    y1, t1 = bs_to(rhs_s, mp.mpf(0), [mp.mpf(1), mp.mpf(0)], s1, H)
    assert y1 > 0.5
    tm, Ym = bs_event(rhs_t, t1, [x1, y1], H, lambda t, Y: Y[1], t1 + 10)
    xm = Ym[0]
    F = lambda x, y: k * x ** mp.mpf(1.5) + C * x ** q * y
    if limit:
        g2 = lambda t, Y: min(Y[0] - xm / 4, F(Y[0], Y[1]))
    else:
        g2 = lambda t, Y: Y[0] - xm / 4
    t2, Y2 = bs_event(rhs_t, tm, Ym, H, g2, tm + 10)
    X2, Y2v = Y2
    assert Y2v < -0.1
    if limit and F(X2, Y2v) <= mp.mpf(10) ** -25:
        return t2 * t0, xm * d0, abs(Y2v), Khz * (xm * d0) ** mp.mpf(1.5)
    s2 = X2 ** mp.mpf(0.25)
    # leaving: variable r = s2 - s, from 0 to s2
    rhs_r = lambda r, Y: [-z for z in rhs_s(s2 - r, Y)]
    if not limit:
        ye, te = bs_to(rhs_r, mp.mpf(0), [Y2v, t2], s2, H)
    else:
        # F / s^p = k s^(6-p) + C y = 0
        re, Ye = bs_event(rhs_r, mp.mpf(0), [Y2v, t2], H, lambda r, Y: k * (s2 - r) ** (6 - p) + C * Y[0], s2)
        ye, te = Ye
    return te * t0, xm * d0, abs(ye), Khz * (xm * d0) ** mp.mpf(1.5)


def hertz_closed(Khz, m, v):
    dmax = (mp.mpf(5) / 4 * m * v ** 2 / Khz) ** (mp.mpf(2) / 5)
    return 2 * I_HZ * dmax / v, dmax, mp.mpf(1), Khz * dmax ** mp.mpf(1.5)


# ------------------------------------------------------------------ HLS
def hls_closed(law, KL, x, m, v):
    w = mp.sqrt(m / KL)
    dmax = v * w
    e = x if law == HLS_CONSTANT else 1 / mp.sqrt(1 + x * dmax)
    return PI / 2 * w * (1 + e), dmax, dmax * (1 - e ** 2), v * mp.sqrt(m * KL), e


def hls_ode(law, KL, x, m, v):
    """Loading x'' = -x, unloading x'' = -(KU/KL) (x - xres), units (m/KL)^1/2, v."""
    T = mp.sqrt(m / KL)
    H = mp.mpf("0.1")
    tm, Ym = bs_event(lambda t, y: [y[1], -y[0]], mp.mpf(0), [mp.mpf(0), mp.mpf(1)], H, lambda t, y: y[1], mp.mpf(10))
    dmax = Ym[0] * v * T
    Fmax = KL * dmax
    KU = KL / x ** 2 if law == HLS_CONSTANT else KL + x * Fmax
    r = KU / KL
    xres = Ym[0] * (1 - 1 / r)
    te, Ye = bs_event(lambda t, y: [y[1], -r * (y[0] - xres)], tm, Ym, H / mp.sqrt(r), lambda t, y: y[0] - xres,
                      tm + 10)
    return te * T, dmax, Ye[0] * v * T, Fmax, abs(Ye[1])


# ------------------------------------------------------------------ tangential
def wb_loop(K0, N, X):
    """Stable loop of Walton-Braun friction between -X and X at limit N."""
    def down(T_A, xi):   # from T_A at x = X, xi = X - x
        D = N + T_A
        u = 1 - 2 * K0 * xi / (3 * D)
        return T_A - D * (1 - max(u, 0) ** mp.mpf(1.5))
    T_A = mp.findroot(lambda T: down(T, 2 * X) + T, N / 2)
    assert 0 < T_A < N
    # branch check: integrate dT/dxi = -K0 (1 - (T* - T)/(N + T*))^1/3 from T* = T_A
    L = 3 * (N + T_A) / (2 * K0)   # units of the displacement
    gX = bs_to(lambda xi, T: [-K0 * L / (N + T_A) * mp.cbrt(1 - (T_A - (N + T_A) * T[0]) / (N + T_A))],
               mp.mpf(0), [T_A / (N + T_A)], X / L, mp.mpf("0.05"))[0] * (N + T_A)
    assert close(gX, down(T_A, X), mp.mpf("1e-20"))
    # energy: area between the branches, up(x) = -down(-x)
    W = mp.quad(lambda x: -down(T_A, X + x) - down(T_A, X - x), [-X, X])
    return T_A, W


def virgin(K0, N, x):
    return N * (1 - max(1 - 2 * K0 * x / (3 * N), 0) ** mp.mpf(1.5))


def fmt(v):
    return mp.nstr(v, 20) if isinstance(v, mp.mpf) else repr(v)


def main():
    rows = []
    # constants; the notes print c_T as 2.870 and 2.86, 1.198 and 0.2996
    rows.append(("const", C_T, K_DUR, K_OVL, K_DUR / 4, C1_BSHP))

    # matched stiffness at v = 1 m/s, checked against the Hertz collision
    v = mp.mpf(1)
    Khz = mp.mpf(4) / 3 * ESTAR * mp.sqrt(RAD)
    Tc_h, dmax_h, _, _ = hertz_closed(Khz, MEFF, v)
    Tc_o, dmax_o, e_o, _ = hertz_ode(Khz, mp.mpf(0), mp.mpf(1) / 2, MEFF, v, 0)
    assert close(Tc_o, Tc_h, mp.mpf("1e-20")) and close(dmax_o, dmax_h, mp.mpf("1e-20")) and close(e_o, 1)
    assert close(Tc_h, C_T * (MEFF ** 2 / (v * RAD * ESTAR ** 2)) ** (mp.mpf(1) / 5))
    assert close(dmax_h, (mp.mpf(15) / 16 * MEFF * v ** 2 / (mp.sqrt(RAD) * ESTAR)) ** (mp.mpf(2) / 5))
    for law in (LSD, HLS_CONSTANT):
        for method in (1, 2, 3):
            for e in (mp.mpf("0.3"), mp.mpf("0.8"), mp.mpf(1)):
                K = matched_k(law, method, e, ESTAR, RAD, MEFF, v)
                if law == LSD:
                    fig = lsd_closed(K, lsd_eta(e, MEFF, K), MEFF, v, 0)
                    Tc, dmax = fig[0], fig[1]
                else:
                    Tc, dmax = hls_closed(law, K, e, MEFF, v)[:2]
                if method == 1:
                    assert close(Tc, Tc_h)
                elif method == 2:
                    assert close(dmax, dmax_h)
                else:
                    assert close(K * dmax_h ** 2 / 2, mp.mpf(2) / 5 * Khz * dmax_h ** mp.mpf(2.5))
                rows.append(("match", law, method, e, ESTAR, RAD, MEFF, v, K, Tc_h, dmax_h))

    # LSD: closed forms against the integration
    K = matched_k(LSD, 3, 1, ESTAR, RAD, MEFF, v)
    for e in ("0.1", "0.5", "0.9", "1"):
        e = mp.mpf(e)
        eta = lsd_eta(e, MEFF, K)
        for limit in (0, 1):
            cf = lsd_closed(K, eta, MEFF, v, limit)
            od = lsd_ode(K, eta, MEFF, v, limit)
            for a, b in zip(cf, od):
                assert close(a, b), (e, limit, a, b)
            if not limit:
                assert close(cf[2], e)
            rows.append(("lsd", e, v, MEFF, K, limit, eta) + cf)

    # Hertz: elastic closed form, damped by integration
    for vv in ("0.01", "1", "10"):
        vv = mp.mpf(vv)
        cf = hertz_closed(Khz, MEFF, vv)
        od = hertz_ode(Khz, mp.mpf(0), mp.mpf(1) / 2, MEFF, vv, 0)
        for a, b in zip(cf, od):
            assert close(a, b, mp.mpf("1e-20"))
        rows.append(("hertz", NONE, 0, 0, ESTAR, RAD, MEFF, vv, 0) + cf)
    tsuji_dev = []
    for law in (TSUJI, RESTITUTION):
        for e in ("0.1", "0.3", "0.5", "0.7", "0.9"):
            e = mp.mpf(e)
            l = mp.log(e)
            coef = (-mp.mpf("2.2664") * l / mp.sqrt(l ** 2 + mp.mpf("10.1354")) if law == TSUJI
                    else l / mp.sqrt(l ** 2 + PI ** 2))
            c, q = hertz_damping(law, coef, ESTAR, RAD, MEFF)
            figs = []
            for vv in ("0.1", "1", "10"):
                vv = mp.mpf(vv)
                for limit in (0, 1):
                    fig = hertz_ode(Khz, c, q, MEFF, vv, limit)
                    figs.append((limit, fig[2]))
                    rows.append(("hertz", law, e, coef, ESTAR, RAD, MEFF, vv, limit) + fig)
            # restitution independent of the impact velocity (q = 1/4)
            for limit in (0, 1):
                es = [x for (lm, x) in figs if lm == limit]
                assert all(close(x, es[0], mp.mpf("1e-20")) for x in es), es
            e_actual = figs[0][1]
            tsuji_dev.append((law, e, e_actual))
            if law == RESTITUTION:
                # LIGGGHTS' damping gives e exactly
                assert close(e_actual, e, mp.mpf("1e-20"))
            else:
                # the notes' (Norouzi's) coefficient: within 1.7 %
                assert abs(e_actual / e - 1) < mp.mpf("0.017")
    for law, e, ea in tsuji_dev:
        print("%s e = %s: restitution %s (%+.3g %%)" % ("tsuji/norouzi" if law == TSUJI else "liggghts",
              mp.nstr(e, 3), mp.nstr(ea, 22), float((ea - e) / e * 100)))
    # Kuwabara-Kono and BSHP: velocity dependent
    for law, coef in ((KUWABARA_KONO, mp.mpf("1e3")), (VISCOELASTIC, mp.mpf("2e-7"))):
        c, q = hertz_damping(law, coef, ESTAR, RAD, MEFF)
        prev = None
        for vv in ("0.01", "0.1", "1", "10"):
            vv = mp.mpf(vv)
            for limit in (0, 1):
                fig = hertz_ode(Khz, c, q, MEFF, vv, limit)
                rows.append(("hertz", law, coef, coef, ESTAR, RAD, MEFF, vv, limit) + fig)
                if not limit:
                    if prev is not None:
                        assert fig[2] < prev   # restitution falls with the impact velocity
                    prev = fig[2]
                    print("law %d v = %s: restitution %s" % (law, mp.nstr(vv, 3), mp.nstr(fig[2], 10)))
    # KK: e is a function of c/(m K)^1/2 (m v^2/K)^1/10 only
    c = mp.mpf("1e3")
    e_a = hertz_ode(Khz, c, mp.mpf(1) / 2, MEFF, mp.mpf(1), 0)[2]
    m2, K2 = MEFF * 4, Khz * 3
    v2 = ((MEFF * 1 / Khz) / (m2 / K2)) ** mp.mpf(0.5) * mp.mpf(1)   # same m v^2/K
    c2 = c * mp.sqrt(m2 * K2 / (MEFF * Khz))
    e_b = hertz_ode(K2, c2, mp.mpf(1) / 2, m2, v2, 0)[2]
    assert close(e_a, e_b, mp.mpf("1e-20"))
    # BSHP series: notes' F_dis = K_HZ A' delta^1/2 delta' is A = 2/3 A' of dc_damping_viscoelastic
    g = []
    for Ap in (mp.mpf("1e-9"), mp.mpf("2e-9")):
        cc = Khz * Ap
        e = hertz_ode(Khz, cc, mp.mpf(1) / 2, MEFF, mp.mpf(1), 0)[2]
        g.append((1 - e) / (Ap * (Khz / MEFF) ** (mp.mpf(2) / 5)))
    c1 = 2 * g[0] - g[1]   # Richardson in A'
    print("BSHP first-order coefficient: integrated %s, closed form %s" % (mp.nstr(c1, 10), mp.nstr(C1_BSHP, 10)))
    assert abs(c1 - C1_BSHP) < 1e-6

    # HLS
    KL = matched_k(HLS_CONSTANT, 3, 1, ESTAR, RAD, MEFF, v)
    for law, xs in ((HLS_CONSTANT, ("0.2", "0.6", "1")), (HLS_VARIABLE, ("0", "1e4", "1e5", "1e6"))):
        for x in xs:
            x = mp.mpf(x)
            for vv in ("0.1", "1", "3"):
                vv = mp.mpf(vv)
                cf = hls_closed(law, KL, x, MEFF, vv)
                od = hls_ode(law, KL, x, MEFF, vv)
                for a, b in zip(cf, od):
                    assert abs(a - b) <= mp.mpf("1e-18") * max(abs(b), cf[1]), (law, x, vv, a, b)
                rows.append(("hls", law, KL, x, MEFF, vv) + cf)

    # Walton-Braun stable loops
    for K0, N, X in (("1e5", "1", "5e-6"), ("1e5", "1", "1e-5"), ("2e6", "0.5", "1e-7")):
        K0, N, X = mp.mpf(K0), mp.mpf(N), mp.mpf(X)
        T_A, W = wb_loop(K0, N, X)
        rows.append(("wbloop", K0, N, X, T_A, W, virgin(K0, N, X)))

    with open(os.path.join(here, "classical.csv"), "w") as f:
        f.write("# generated by gen_classical.py (mpmath, 30 digits): closed forms checked against\n")
        f.write("# an integration of the collision; Hertz with damping from the integration only\n")
        f.write("# const,c_T,K_duration,K_overlap,KL_duration/(1+e)^2,C1_bshp\n")
        f.write("# match,law,method,e,Estar,R,m,v,K,Tc_hertz,dmax_hertz\n")
        f.write("# lsd,e,v,m,K,limit,eta,Tc,dmax,e_out\n")
        f.write("# hertz,damping,param(e|A|eta),coef(dc_damping_gamma),Estar,R,m,v,limit,Tc,dmax,e_out,F_at_dmax\n")
        f.write("# hls,law,KL,e_or_S,m,v,Tc,dmax,dres,Fmax,e_out\n")
        f.write("# wbloop,K0,muN,X,T_A,W_cycle,T_virgin(X)\n")
        for r in rows:
            f.write(r[0] + "," + ",".join(fmt(x) for x in r[1:]) + "\n")
    print("wrote %d rows" % len(rows))


if __name__ == "__main__":
    main()
