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

with open(os.path.join(here, "cmd_tangential.csv"), "w") as out:
    out.write("# generated by gen_cmd_tangential.py (mpmath, 40 digits); rows described there\n")
    for r in rows:
        out.write(r + "\n")
print(len(rows), "rows")
