#!/usr/bin/env python3
"""Boundary-element reference for the partial-slip tangential and twisting
behaviour of elliptic Hertz contacts, independent of the C code; it checks
the spring-bed law of c_core (dc/cmd_tangential.h).

Problem. Two elastic half-spaces touch over a fixed ellipse x^2/a^2 +
y^2/b^2 <= 1 (a >= b, x along the major axis) under the Hertz pressure
p = p0 (1 - x^2/a^2 - y^2/b^2)^1/2, P = 2 pi a b p0 / 3. The normal and
tangential problems are uncoupled (Goodman: identical or quasi-identical
bodies), the pressure stays fixed. A rigid tangential shift delta (or a
rigid twist phi about the normal) of one body relative to the other is
applied in small steps; each point obeys Coulomb's law |q| <= mu p (stick:
no slip increment in the step; slip: q on the limit, along the slip
increment). Units: a = 1, compliance sums s0 = sum 1/G_i = 1, s1 =
sum nu_i/G_i = nu (one body of G = 1 on a rigid one), mu = 1, P = 1.

Discretisation. Uniform N x N grid of rectangular cells over the bounding
box (hx = 2a/N, hy = 2b/N), uniform traction per cell. The influence
coefficients are the closed-form integrals of Cerruti's surface kernel
(Johnson, Contact Mechanics, Eq. 3.86) over a rectangle, both bodies
together:
  u_x = 1/(2 pi) int [(s0 - s1)/r + s1 X^2/r^3] q_x + s1 X Y/r^3 q_y dA,
  u_y = 1/(2 pi) int s1 X Y/r^3 q_x + [(s0 - s1)/r + s1 Y^2/r^3] q_y dA,
with the primitives (d^2/dXdY of each gives the integrand)
  1/r: X asinh(Y/|X|) + Y asinh(X/|Y|),  X^2/r^3: Y asinh(X/|Y|),
  Y^2/r^3: X asinh(Y/|X|),  XY/r^3: -r,
applied by FFT (the kernel depends on the cell offset only). The Coulomb
limit of a cell is mu times the mean pressure over the cell (12 x 12 sub-
points, scaled so that the cells carry exactly P): cells cut by the rim
carry their share. No-slip problems (infinite mu) use the cells whose centre
lies inside the ellipse and are solved by conjugate gradients.

Load step. With the traction q_prev and displacement u_prev = C q_prev of
the previous step and the rigid increment d(x, y) (uniform for a shift,
dphi (-y, x) for a twist), the step's traction minimises
  1/2 q.C q - q.(u_prev + d)  over |q_i| <= mu p_i,
whose optimality conditions are exactly Coulomb's law for the step (C is
symmetric positive definite; the slip increment is d - C (q - q_prev) and
lies in the normal cone of the discs). Solved by FISTA (projected
accelerated gradient, step 1/L from a power iteration, gradient restart)
to a fixed-point residual below 1e-7 of the full-slip displacement, warm
started from the previous step. Stick cells: those where the last
projection is inactive. Stick fraction reported as the equivalent radius
fraction sqrt(A_stick / (pi a b)) (for a homothetic stick ellipse this is
c/a, the law's `stick`).

Validation (printed): (1) circle no-slip stiffness 8 a/(2 s0 - s1) (one body
on a rigid one: 8 G a/(2 - nu)); (2) the Cattaneo-Mindlin curve F = mu P
[1 - (1 - delta/delta_s)^3/2], delta_s = 3 mu P/(2 k) (Johnson Eq. 7.42),
and its stick radius c/a = (1 - delta/delta_s)^1/2, at nu = 0 where it is
exact (for nu != 0 the Cattaneo traction leaves a small slip across the
force direction: the BEM difference there is printed too); (3) the ellipse
no-slip stiffnesses along the axes, Mindlin 1949: k = 2 pi a/(s0 c),
c_major = (1 - t) K + t D, c_minor = K - t D, t = s1/s0, K, D of
e^2 = 1 - b^2/a^2 (the forms of c_core/src/mindlin.c); (4) circle torsion:
no-slip stiffness 16 a^3/(3 s0) and Lubkin's partial-slip curve, full slip
M_s = 3 pi mu P a/16. Each at N = 32, 64, 128 (Richardson from 64, 128
where the order is clean).

Lubkin's solution (circle of radius a, stick radius c), as used here: the
traction is a superposition of rigid-twist (Reissner-Sagoci) tractions
w(t) dt r (t^2 - r^2)^-1/2 on discs r < t, t in [c, a], each turning its
disc rigidly by pi s0 w(t) dt / 4 (so the stick zone r < c turns rigidly);
in the slip annulus c < r < a the sum must be mu p(r): an Abel equation for
w on [c, a], w = -(2/pi) H'(t), with
  H(t) = mu p0 [K(k') - E(k')],  k'^2 = 1 - t^2/a^2  (modulus k'),
  twist   phi = s0 H(c) / 2,
  moment  M = 8/3 c^3 H(c) + 8 int_c^a H(t) t^2 dt,
(for one body on a rigid one, s0 = 1/G: phi = mu p0 (K - E)/(2 G); c = 0
gives M_s, c -> a the stiffness 16 a^3/(3 s0)). Torsion is independent of
nu (a circumferential traction is divergence-free), so this is exact for
every nu; the BEM reproduces it (validation 4). The moment is computed by
Gauss-Legendre quadrature (t = c + (a - c) u^2), K and E by the AGM.

Reference curves (written to cmd_bem.csv, nu = 0.3, grid N = 64):
  load, b/a, theta: monotonic shift along theta (degrees from the major
    axis), x = delta/delta_slip, delta_slip = 3 mu P / (2 |K0 e_theta|),
    K0 = diag(k_major, k_minor) (Mindlin): the displacement at which the
    spring-bed law reaches full slip; b/a = 1, 0.7, 0.5, 0.3, theta = 0,
    22.5, 45, 67.5, 90; x in steps of 0.05 up to 1, then of 0.1 up to 2,
    then 2.25 .. 3 (gross sliding: the force turns towards the sliding
    direction);
  load_nu0: the same at nu = 0, b/a = 0.3, theta = 45 (where the
    superposition of Mindlin tractions is exact for any direction);
  unload: b/a = 1 and 0.5, theta = 45: loading to x = 0.75, then the shift
    reversed down to x = -0.75;
  twist: b/a = 1 and 0.5, x = phi/phi_s, phi_s = 3 M_s/(2 k_twist), k_twist
    the no-slip torsional stiffness (circle 16 a^3/(3 s0); ellipse: the
    closed form quoted in dc/cmd_tangential.h, checked here against the
    BEM), M_s = 3/8 mu P a E(e^2);
  lubkin: the exact circle curve at the same x.
Columns: tag, b_over_a, theta_deg, x, F (|F|/mu P or M/M_s), psi_deg (angle
of F from the major axis), F_major, F_minor (components / mu P), stick.

Comparison with the law (optional): --law PATH runs tests/reference/
cmd_bem_driver.c (built as its comment says) along the same histories and
prints the markdown tables of cmd_bem_comparison.md; with --compare-only
the curves are read from cmd_bem.csv instead of being solved again.

Run: python3 gen_cmd_bem.py [--law /tmp/cmd_bem_driver] [--quick]
     python3 gen_cmd_bem.py --compare-only --law /tmp/cmd_bem_driver
(needs numpy: Debian's python3-numpy, /usr/bin/python3; about 3 minutes on
2 cores, --quick skips the N = 128 grids).
"""
import argparse
import os
import subprocess
import sys
import time

try:
    import numpy as np
except ImportError:  # pyenv interpreters without numpy: Debian's has it
    if os.path.exists("/usr/bin/python3") and os.path.realpath(sys.executable) != "/usr/bin/python3":
        os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)
    raise

NU = 0.3
N_REF = 64
np.seterr(divide="ignore", invalid="ignore", over="ignore")
HERE = os.path.dirname(os.path.abspath(__file__))


# ---------------------------------------------------------------- special functions

def ellipk_e(m):
    """K(m), E(m) (parameter m = k^2) by the AGM, vectorised."""
    m = np.asarray(m, float)
    a = np.ones_like(m)
    b = np.sqrt(1.0 - m)
    s = 0.5 * m
    p = 0.5
    for _ in range(30):
        c = 0.5 * (a - b)
        a, b = 0.5 * (a + b), np.sqrt(a * b)
        p *= 2.0
        s = s + p * c * c
    K = np.pi / (2.0 * a)
    return K, K * (1.0 - s)


def mindlin_k(b, nu, s0=1.0):
    """Mindlin's no-slip stiffnesses (k_major, k_minor), a = 1."""
    m = 1.0 - b * b
    if m == 0.0:
        k = 8.0 / (2.0 * s0 - nu * s0)
        return k, k
    K, E = ellipk_e(m)
    D = (K - E) / m
    return 2 * np.pi / (s0 * ((1 - nu) * K + nu * D)), 2 * np.pi / (s0 * (K - nu * D))


def twist_k(b, nu, s0=1.0):
    """No-slip torsional stiffness quoted in dc/cmd_tangential.h (a = 1)."""
    if b == 1.0:
        return 16.0 / (3.0 * s0)
    m = 1.0 - b * b
    K, E = ellipk_e(m)
    D = (K - E) / m
    B = (E - (1 - m) * K) / m
    C = (D - B) / m
    t = nu
    a11 = (1 - t) * B + t * (D - C)
    a22 = (1 - t) * D + t * (D - C)
    det = a11 * a22 - t * t * C * (B - D + C)
    return 2 * np.pi / 3 * ((B - 2 * t * (B - D + C)) + b * b * (D - 2 * t * C)) / det / s0


def slip_moment(b):
    """M_s = 3/8 mu P a E(e^2) (mu P = 1, a = 1)."""
    return 0.375 * float(ellipk_e(1.0 - b * b)[1])


# ---------------------------------------------------------------- Lubkin

_GL_U, _GL_W = np.polynomial.legendre.leggauss(160)
_GL_U = 0.5 * (_GL_U + 1.0)
_GL_W = 0.5 * _GL_W


def lubkin(c, s0=1.0):
    """Circle a = 1, mu P = 1: twist phi and moment M at stick radius c
    (array), Lubkin's solution (module docstring)."""
    c = np.atleast_1d(np.asarray(c, float))
    p0 = 3.0 / (2.0 * np.pi)

    def H(t):
        K, E = ellipk_e(1.0 - t * t)
        return p0 * (K - E)

    u = _GL_U[None, :]
    t = c[:, None] + (1.0 - c[:, None]) * u * u
    dt = 2.0 * (1.0 - c[:, None]) * u * _GL_W[None, :]
    Hc = np.where(c > 0, H(np.maximum(c, 1e-300)), np.inf)
    M = np.where(c > 0, 8.0 / 3.0 * c ** 3 * np.where(c > 0, Hc, 0.0), 0.0) + 8.0 * (H(t) * t * t * dt).sum(1)
    return 0.5 * s0 * Hc, M


def lubkin_at(phi, s0=1.0):
    """Lubkin's moment and stick radius at the twists phi (bisection in c)."""
    phi = np.asarray(phi, float)
    lo = np.full(phi.shape, 1e-12)
    hi = np.full(phi.shape, 1.0 - 1e-15)
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        big = lubkin(mid, s0)[0] > phi   # twist decreases with c
        lo = np.where(big, mid, lo)
        hi = np.where(big, hi, mid)
    c = 0.5 * (lo + hi)
    return lubkin(c, s0)[1], c


# ---------------------------------------------------------------- the BEM

def _asinh_terms(u, v):
    au, av = np.abs(u), np.abs(v)
    t1 = np.where(au > 0, u * np.arcsinh(v / np.where(au > 0, au, 1.0)), 0.0)
    t2 = np.where(av > 0, v * np.arcsinh(u / np.where(av > 0, av, 1.0)), 0.0)
    return t1, t2


class Grid:
    def __init__(self, N, b, nu, s0=1.0):
        a = 1.0
        s1 = nu * s0
        self.N, self.b, self.nu = N, b, nu
        hx, hy = 2 * a / N, 2 * b / N
        self.A = hx * hy
        xc = -a + hx * (np.arange(N) + 0.5)
        yc = -b + hy * (np.arange(N) + 0.5)
        self.X, self.Y = np.meshgrid(xc, yc, indexing="ij")
        ns = 12
        sub = (np.arange(ns) + 0.5) / ns - 0.5
        acc = np.zeros((N, N))
        for du in sub:
            for dv in sub:
                r2 = ((self.X + du * hx) / a) ** 2 + ((self.Y + dv * hy) / b) ** 2
                acc += np.sqrt(np.clip(1.0 - r2, 0.0, None))
        self.p = acc / (acc.sum() * self.A)          # mean pressure per cell, sum p A = P = 1
        self.inside = ((self.X / a) ** 2 + (self.Y / b) ** 2 < 1.0).astype(float)
        self.active = (self.p > 0).astype(float)
        M = 2 * N
        i = np.arange(M)
        i = np.where(i < N, i, i - M)
        DX, DY = np.meshgrid(i * hx, i * hy, indexing="ij")

        def rect(f):
            X1, X2, Y1, Y2 = DX - hx / 2, DX + hx / 2, DY - hy / 2, DY + hy / 2
            return f(X2, Y2) - f(X1, Y2) - f(X2, Y1) + f(X1, Y1)

        I1 = rect(lambda u, v: sum(_asinh_terms(u, v)))
        Ixx = rect(lambda u, v: _asinh_terms(u, v)[1])
        Iyy = rect(lambda u, v: _asinh_terms(u, v)[0])
        Ixy = rect(lambda u, v: -np.hypot(u, v))
        c = 1.0 / (2.0 * np.pi)
        Kxx = c * ((s0 - s1) * I1 + s1 * Ixx)
        Kyy = c * ((s0 - s1) * I1 + s1 * Iyy)
        Kxy = c * s1 * Ixy
        for K in (Kxx, Kyy, Kxy):
            K[N, :] = 0.0
            K[:, N] = 0.0
        self.M = M
        self.fxx, self.fyy, self.fxy = (np.fft.rfft2(K) for K in (Kxx, Kyy, Kxy))
        self.L = self._lmax()

    def mv(self, qx, qy):
        M, N = self.M, self.N
        Qx = np.fft.rfft2(qx, (M, M))
        Qy = np.fft.rfft2(qy, (M, M))
        ux = np.fft.irfft2(self.fxx * Qx + self.fxy * Qy, (M, M))[:N, :N]
        uy = np.fft.irfft2(self.fxy * Qx + self.fyy * Qy, (M, M))[:N, :N]
        return ux, uy

    def _lmax(self):
        rng = np.random.default_rng(1)
        x = rng.standard_normal((2, self.N, self.N)) * self.active
        lam = 0.0
        for _ in range(80):
            y = np.array(self.mv(x[0], x[1])) * self.active
            lam = np.sqrt((y * y).sum() / (x * x).sum())
            x = y / np.sqrt((y * y).sum())
        return 1.02 * lam

    def noslip(self, wx, wy, tol=1e-12):
        """C q = w on the cells inside (conjugate gradients)."""
        mk = self.inside
        qx, qy = np.zeros_like(wx), np.zeros_like(wy)
        rx, ry = wx * mk, wy * mk
        px, py = rx.copy(), ry.copy()
        rr = r0 = (rx * rx + ry * ry).sum()
        for _ in range(5000):
            ax, ay = self.mv(px, py)
            ax, ay = ax * mk, ay * mk
            al = rr / (px * ax + py * ay).sum()
            qx += al * px
            qy += al * py
            rx -= al * ax
            ry -= al * ay
            rn = (rx * rx + ry * ry).sum()
            if rn < tol * tol * r0:
                break
            px = rx + rn / rr * px
            py = ry + rn / rr * py
            rr = rn
        return qx, qy

    def step(self, st, dx, dy, tol):
        """One load step from state st = (qx, qy, ux, uy) with the rigid
        increment field (dx, dy); returns the new state and the slip mask."""
        qx, qy, ux, uy = st
        wx, wy = ux + dx, uy + dy
        g, L = self.p, self.L
        yx, yy, t = qx.copy(), qy.copy(), 1.0
        vx, vy = ux, uy
        for it in range(100000):
            zx = yx - (vx - wx) / L
            zy = yy - (vy - wy) / L
            s = np.minimum(1.0, g / np.maximum(np.hypot(zx, zy), 1e-300))
            nx, ny = zx * s, zy * s
            ddx, ddy = nx - qx, ny - qy
            if ((yx - nx) * ddx + (yy - ny) * ddy).sum() > 0:
                t = 1.0   # restart
            tn = 0.5 * (1.0 + np.sqrt(1.0 + 4.0 * t * t))
            beta = (t - 1.0) / tn
            res = L * np.sqrt(((nx - yx) ** 2 + (ny - yy) ** 2).max())
            qx, qy = nx, ny
            yx, yy, t = nx + beta * ddx, ny + beta * ddy, tn
            vx, vy = self.mv(yx, yy)
            if res < tol and it > 2:
                break
        ux, uy = self.mv(qx, qy)
        zx = qx - (ux - wx) / L
        zy = qy - (uy - wy) / L
        slip = (np.hypot(zx, zy) > g * (1.0 + 1e-9)) & (self.active > 0)
        return (qx, qy, ux, uy), slip, it

    def zero(self):
        z = np.zeros((self.N, self.N))
        return (z, z.copy(), z.copy(), z.copy())

    def run(self, incs, kind, tol):
        """incs: list of shift increments (dx, dy) or twist increments dphi.
        Per step: Fx, Fy, M, stick radius fraction."""
        st = self.zero()
        out = []
        its = 0
        for inc in incs:
            if kind == "shift":
                dx, dy = inc[0] + 0 * self.X, inc[1] + 0 * self.X
            else:
                dx, dy = -inc * self.Y, inc * self.X
            st, slip, it = self.step(st, dx, dy, tol)
            its += it
            qx, qy = st[0], st[1]
            stick = self.active * (~slip)
            out.append((qx.sum() * self.A, qy.sum() * self.A, (self.X * qy - self.Y * qx).sum() * self.A,
                        np.sqrt(stick.sum() * self.A / (np.pi * self.b))))
        return np.array(out), its


# ---------------------------------------------------------------- histories

X_LOAD = np.concatenate([np.arange(1, 21) * 0.05, 1.0 + np.arange(1, 11) * 0.1, [2.25, 2.5, 2.75, 3.0]])
X_UNLOAD_TOP = 0.75
X_UNLOAD = np.concatenate([np.arange(1, 16) * 0.05, 0.75 - np.arange(1, 31) * 0.05])
X_TWIST = np.concatenate([np.arange(1, 21) * 0.05, [1.25, 1.5, 2.0, 2.5, 3.0]])


def delta_slip(b, nu, th):
    km, kn = mindlin_k(b, nu)
    return 1.5 / np.hypot(km * np.cos(th), kn * np.sin(th))


def shift_incs(xs, b, nu, th_deg):
    th = np.radians(th_deg)
    ds = delta_slip(b, nu, th)
    d = np.diff(np.concatenate([[0.0], xs])) * ds
    return [(v * np.cos(th), v * np.sin(th)) for v in d]


def phi_slip(b, nu):
    return 1.5 * slip_moment(b) / twist_k(b, nu)


def twist_incs(xs, b, nu):
    return list(np.diff(np.concatenate([[0.0], xs])) * phi_slip(b, nu))


def summarise(res):
    F = np.hypot(res[:, 0], res[:, 1])
    psi = np.degrees(np.arctan2(res[:, 1], res[:, 0]))
    return F, psi


# ---------------------------------------------------------------- validation

def validate(quick):
    Ns = (32, 64) if quick else (32, 64, 128)
    err = {}
    print("Validation (a = 1, s0 = 1, mu P = 1)")
    # (1), (3) no-slip stiffnesses
    print("(1, 3) no-slip stiffness, nu = 0.3: relative error k_BEM/k_Mindlin - 1 "
          "(axis: major, minor); Richardson (order 1) from the two finest")
    for b in (1.0, 0.7, 0.5, 0.3):
        km, kn = mindlin_k(b, NU)
        rows = []
        for N in Ns:
            G = Grid(N, b, NU)
            one, zero = np.ones((N, N)), np.zeros((N, N))
            qx, _ = G.noslip(one, zero)
            _, qy = G.noslip(zero, one)
            rows.append((qx.sum() * G.A / km - 1.0, qy.sum() * G.A / kn - 1.0))
        txt = "  ".join(f"N={N}: {e0:+.2e} {e1:+.2e}" for N, (e0, e1) in zip(Ns, rows))
        r0 = 2 * rows[-1][0] - rows[-2][0]
        r1 = 2 * rows[-1][1] - rows[-2][1]
        print(f"  b/a={b}: {txt}  Richardson: {r0:+.1e} {r1:+.1e}")
        err.setdefault("k", []).append(max(abs(rows[-1][0]), abs(rows[-1][1])))
    # (2) Cattaneo-Mindlin, circle, nu = 0 (exact) and nu = 0.3
    print("(2) Cattaneo-Mindlin, circle, x = delta/delta_s = 0.05 .. 1 (20 steps): "
          "max |F - F_CM| / mu P, max |stick - (1 - x)^1/2| (radius)")
    xs = np.arange(1, 21) * 0.05
    Fcm = 1.0 - (1.0 - xs) ** 1.5
    ccm = np.sqrt(1.0 - xs)
    for nu in (0.0, 0.3):
        for N in (Ns if nu == 0.0 else Ns[:2]):
            G = Grid(N, 1.0, nu)
            res, its = G.run(shift_incs(xs, 1.0, nu, 0.0), "shift", 1e-7 * delta_slip(1.0, nu, 0.0))
            F, _ = summarise(res)
            eF = np.abs(F - Fcm).max()
            ec = np.abs(res[:-1, 3] - ccm[:-1]).max()
            print(f"  nu={nu} N={N}: force {eF:.2e}, stick radius {ec:.3f} (cell {2.0 / N:.3f}), "
                  f"max |F_minor| {np.abs(res[:, 1]).max():.1e}, FISTA iterations {its}")
            if nu == 0.0:
                err[("cm", N)] = eF
                err[("cm_stick", N)] = ec
    # (4) torsion
    print("(4) circle torsion: no-slip k/(16/3) - 1; Lubkin curve at phi/phi_s = 0.05 .. 3: "
          "max |M - M_Lubkin| / M_s")
    ktw, Ms = 16.0 / 3.0, 3.0 * np.pi / 16.0
    M0 = float(lubkin(np.array([0.0]))[1][0])
    print(f"  Lubkin c -> 0: M/M_s = {M0 / Ms:.15f};  c = 1 - 1e-6: M/(phi k) = "
          f"{float(lubkin(np.array([1 - 1e-6]))[1][0] / (lubkin(np.array([1 - 1e-6]))[0][0] * ktw)):.8f}")
    ps = phi_slip(1.0, NU)
    Ml, cl = lubkin_at(X_TWIST * ps)
    for N in Ns:
        G = Grid(N, 1.0, NU)
        qx, qy = G.noslip(-G.Y, G.X)
        k = (G.X * qy - G.Y * qx).sum() * G.A
        res, its = G.run(twist_incs(X_TWIST, 1.0, NU), "twist", 1e-7 * ps)
        eM = np.abs(res[:, 2] - Ml).max() / Ms
        ec = np.abs(res[:, 3] - cl).max()
        print(f"  N={N}: k {k / ktw - 1:+.2e}, curve {eM:.2e}, stick radius {ec:.3f}, FISTA iterations {its}")
        err[("tw", N)] = eM
        err[("tw_stick", N)] = ec
    return err


# ---------------------------------------------------------------- reference curves

def reference(quick):
    rows = []
    tol_of = lambda d: 1e-7 * d
    t0 = time.time()
    grids = {}
    for b in (1.0, 0.7, 0.5, 0.3):
        grids[b] = Grid(N_REF, b, NU)
    for b in (1.0, 0.7, 0.5, 0.3):
        for th in (0.0, 22.5, 45.0, 67.5, 90.0):
            res, _ = grids[b].run(shift_incs(X_LOAD, b, NU, th), "shift", tol_of(delta_slip(b, NU, np.radians(th))))
            F, psi = summarise(res)
            for i, x in enumerate(X_LOAD):
                rows.append(("load", b, th, x, F[i], psi[i], res[i, 0], res[i, 1], res[i, 3]))
    G0 = Grid(N_REF, 0.3, 0.0)
    res, _ = G0.run(shift_incs(X_LOAD, 0.3, 0.0, 45.0), "shift", tol_of(delta_slip(0.3, 0.0, np.pi / 4)))
    F, psi = summarise(res)
    for i, x in enumerate(X_LOAD):
        rows.append(("load_nu0", 0.3, 45.0, x, F[i], psi[i], res[i, 0], res[i, 1], res[i, 3]))
    for b in (1.0, 0.5):
        res, _ = grids[b].run(shift_incs(X_UNLOAD, b, NU, 45.0), "shift", tol_of(delta_slip(b, NU, np.pi / 4)))
        F, psi = summarise(res)
        for i, x in enumerate(X_UNLOAD):
            rows.append(("unload", b, 45.0, x, F[i], psi[i], res[i, 0], res[i, 1], res[i, 3]))
    for b in (1.0, 0.5):
        res, _ = grids[b].run(twist_incs(X_TWIST, b, NU), "twist", tol_of(phi_slip(b, NU)))
        Ms = slip_moment(b)
        for i, x in enumerate(X_TWIST):
            rows.append(("twist", b, 0.0, x, res[i, 2] / Ms, 0.0, 0.0, 0.0, res[i, 3]))
    Ml, cl = lubkin_at(X_TWIST * phi_slip(1.0, NU))
    for i, x in enumerate(X_TWIST):
        rows.append(("lubkin", 1.0, 0.0, x, Ml[i] / slip_moment(1.0), 0.0, 0.0, 0.0, cl[i]))
    print(f"reference curves at N = {N_REF}: {time.time() - t0:.0f} s")
    # discretisation and step-size checks on the hardest cases
    chk = {}
    th = 45.0
    b = 0.3
    ds = delta_slip(b, NU, np.radians(th))
    base = np.array([r[4:6] for r in rows if r[0] == "load" and r[1] == b and r[2] == th])
    xs2 = np.concatenate([np.arange(1, 41) * 0.025, 1.0 + np.arange(1, 41) * 0.05])
    res2, _ = grids[b].run(shift_incs(xs2, b, NU, th), "shift", tol_of(ds))
    F2, psi2 = summarise(res2)
    sel = [int(np.argmin(np.abs(xs2 - x))) for x in X_LOAD]
    chk["step"] = (np.abs(F2[sel] - base[:, 0]).max(), np.abs(psi2[sel] - base[:, 1]).max())
    if not quick:
        Gf = Grid(2 * N_REF, b, NU)
        resf, _ = Gf.run(shift_incs(X_LOAD, b, NU, th), "shift", tol_of(ds))
        Ff, psif = summarise(resf)
        chk["grid_shift"] = (np.abs(Ff - base[:, 0]).max(), np.abs(psif - base[:, 1]).max())
        Gf = Grid(2 * N_REF, 0.5, NU)
        resf, _ = Gf.run(twist_incs(X_TWIST, 0.5, NU), "twist", tol_of(phi_slip(0.5, NU)))
        baset = np.array([r[4] for r in rows if r[0] == "twist" and r[1] == 0.5])
        chk["grid_twist"] = np.abs(resf[:, 2] / slip_moment(0.5) - baset).max()
        qx, qy = Gf.noslip(-Gf.Y, Gf.X)
        chk["ktw_ellipse_128"] = (Gf.X * qy - Gf.Y * qx).sum() * Gf.A / twist_k(0.5, NU) - 1.0
    G = grids[0.5]
    qx, qy = G.noslip(-G.Y, G.X)
    chk["ktw_ellipse_64"] = (G.X * qy - G.Y * qx).sum() * G.A / twist_k(0.5, NU) - 1.0
    print("checks of the reference grid (b/a = 0.3, theta = 45; twist b/a = 0.5):")
    print(f"  step halved: max |dF| {chk['step'][0]:.1e} mu P, max |dpsi| {chk['step'][1]:.3f} deg")
    if "grid_shift" in chk:
        print(f"  N = {2 * N_REF} vs {N_REF}: shift max |dF| {chk['grid_shift'][0]:.1e} mu P, "
              f"max |dpsi| {chk['grid_shift'][1]:.3f} deg; twist max |dM| {chk['grid_twist']:.1e} M_s")
        print(f"  ellipse no-slip torsional stiffness, BEM/closed form - 1: N=64 {chk['ktw_ellipse_64']:+.2e}, "
              f"N=128 {chk['ktw_ellipse_128']:+.2e}")
    else:
        print(f"  ellipse no-slip torsional stiffness, BEM/closed form - 1: N=64 {chk['ktw_ellipse_64']:+.2e}")
    return rows, chk


def write_csv(rows, err, chk, path):
    eF = max(err.get(("cm", N_REF), 0.0), chk.get("grid_shift", (0.0, 0.0))[0], chk["step"][0])
    eM = max(err.get(("tw", N_REF), 0.0), chk.get("grid_twist", 0.0))
    epsi = max(chk.get("grid_shift", (0.0, 0.0))[1], chk["step"][1])
    est = max(err.get(("cm_stick", N_REF), 0.0), err.get(("tw_stick", N_REF), 0.0))
    with open(path, "w") as f:
        f.write(f"# gen_cmd_bem.py: BEM of elliptic Hertz contacts in partial slip, grid N = {N_REF} x {N_REF} "
                f"rectangular cells over the bounding box (hx = 2a/N, hy = 2b/N), nu = {NU}, s0 = 1, a = 1, "
                f"mu P = 1, load steps in x of 0.05 up to 1 then 0.1 (shift) or 0.25..0.5 (twist); estimated "
                f"discretisation error (against exact solutions at this grid, N = {2 * N_REF} and halved steps): "
                f"force <= {eF:.1e} mu P, direction <= {epsi:.2f} deg, moment <= {eM:.1e} M_s, "
                f"stick radius <= {est:.3f}\n")
        f.write("# x = delta/delta_slip (load, unload) or phi/phi_slip (twist, lubkin); F = |F|/mu P or M/M_s; "
                "psi_deg = angle of F from the major axis; F_major, F_minor / mu P; stick = sqrt(A_stick/(pi a b))\n")
        f.write("tag,b_over_a,theta_deg,x,F,psi_deg,F_major,F_minor,stick\n")
        for r in rows:
            f.write(f"{r[0]},{r[1]:g},{r[2]:g},{r[3]:.4f},{r[4]:.6f},{r[5]:.4f},{r[6]:.6f},{r[7]:.6f},{r[8]:.4f}\n")


def read_csv(path):
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or line.startswith("tag,"):
                continue
            v = line.strip().split(",")
            rows.append((v[0],) + tuple(float(t) for t in v[1:]))
    return rows


# ---------------------------------------------------------------- the law

def run_law(law, b, nu, steps):
    inp = "".join(f"{s[0]:.17g} {s[1]:.17g} {s[2]:.17g}\n" for s in steps)
    out = subprocess.run([law, f"{b:.17g}", f"{nu:.17g}"], input=inp, capture_output=True, text=True, check=True)
    return np.array([[float(v) for v in line.split()] for line in out.stdout.splitlines()])


def angdiff(a, b):
    return (a - b + 180.0) % 360.0 - 180.0


def compare(law, rows):
    out = []
    P = out.append
    XS = (0.1, 0.25, 0.5, 0.75, 0.9, 1.0, 1.5, 2.0, 3.0)
    summary = []
    detail = []
    cases = [(b, th, NU, "load") for b in (1.0, 0.7, 0.5, 0.3) for th in (0.0, 22.5, 45.0, 67.5, 90.0)]
    cases.append((0.3, 45.0, 0.0, "load_nu0"))
    for b, th, nu, tag in cases:
        ref = np.array([r[3:] for r in rows if r[0] == tag and r[1] == b and r[2] == th])
        lw = run_law(law, b, nu, [(dx, dy, 0.0) for dx, dy in shift_incs(ref[:, 0], b, nu, th)])
        Fl, psil = np.hypot(lw[:, 0], lw[:, 1]), np.degrees(np.arctan2(lw[:, 1], lw[:, 0]))
        dF = Fl - ref[:, 1]
        dpsi = np.abs(angdiff(psil, ref[:, 2]))
        trans = np.sin(np.radians(dpsi)) * ref[:, 1]
        dvec = np.hypot(lw[:, 0] - ref[:, 3], lw[:, 1] - ref[:, 4])
        part = ref[:, 0] <= 1.0 + 1e-9
        relF = np.abs(dF[part]) / ref[part, 1]
        dst = np.abs(lw[:, 2] - ref[:, 5])[ref[:, 0] < 1.0 - 1e-9]
        summary.append((b, th, nu, np.abs(dF).max(), relF.max(), dpsi[part].max(), dpsi[~part].max(),
                        trans[part].max(), trans.max(), dvec.max(), dst.max()))
        for x in XS:
            i = int(np.argmin(np.abs(ref[:, 0] - x)))
            detail.append((b, th, nu, ref[i, 0], ref[i, 1], Fl[i], dF[i], ref[i, 2], psil[i], ref[i, 5], lw[i, 2]))
    P("### Monotonic shift: maximum deviations (law - BEM), x = delta/delta_slip in (0, 3]\n")
    P("| b/a | theta | nu | max abs dF (% mu P) | max rel dF, x <= 1 (%) | max abs dpsi, x <= 1 (deg) "
      "| max abs dpsi, 1 < x <= 3 (deg) | max transverse, x <= 1 (% mu P) | max transverse, x <= 3 (% mu P) "
      "| max abs dF vector (% mu P) | max abs d stick, x < 1 |")
    P("|---|---|---|---|---|---|---|---|---|---|---|")
    for t in summary:
        P(f"| {t[0]:g} | {t[1]:g} | {t[2]:g} | {100 * t[3]:.2f} | {100 * t[4]:.2f} | {t[5]:.2f} | {t[6]:.2f} "
          f"| {100 * t[7]:.2f} | {100 * t[8]:.2f} | {100 * t[9]:.2f} | {t[10]:.3f} |")
    P("\n### Monotonic shift: curves (F = |F|/mu P, psi = angle of F from the major axis in degrees, "
      "stick = stuck radius fraction)\n")
    P("| b/a | theta | nu | x | F BEM | F law | dF (% mu P) | dF/F (%) | psi BEM | psi law | dpsi (deg) "
      "| stick BEM | stick law | d stick |")
    P("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for d in detail:
        P(f"| {d[0]:g} | {d[1]:g} | {d[2]:g} | {d[3]:.2f} | {d[4]:.4f} | {d[5]:.4f} | {100 * d[6]:+.2f} "
          f"| {100 * d[6] / d[4]:+.2f} | {d[7]:.2f} | {d[8]:.2f} | {angdiff(d[8], d[7]):+.2f} | {d[9]:.3f} "
          f"| {d[10]:.3f} | {d[10] - d[9]:+.3f} |")
    # unloading
    for b in (1.0, 0.5):
        ref = np.array([r[3:] for r in rows if r[0] == "unload" and r[1] == b])
        lw = run_law(law, b, NU, [(dx, dy, 0.0) for dx, dy in shift_incs(X_UNLOAD, b, NU, 45.0)])
        dvec = np.hypot(lw[:, 0] - ref[:, 3], lw[:, 1] - ref[:, 4])
        P(f"\n### Unloading from x = {X_UNLOAD_TOP} at theta = 45 deg, b/a = {b:g} "
          f"(components along the axes / mu P; max abs dF vector {100 * dvec.max():.2f} % mu P)\n")
        P("| step | x | F_major BEM | F_major law | F_minor BEM | F_minor law | abs dF vector (% mu P) "
          "| stick BEM | stick law |")
        P("|---|---|---|---|---|---|---|---|---|")
        for i in range(len(X_UNLOAD)):
            if i % 3 == 2 or i == len(X_UNLOAD) - 1:
                P(f"| {'load' if i < 15 else 'unload'} | {ref[i, 0]:+.2f} | {ref[i, 3]:+.4f} | {lw[i, 0]:+.4f} "
                  f"| {ref[i, 4]:+.4f} | {lw[i, 1]:+.4f} | {100 * dvec[i]:.2f} | {ref[i, 5]:.3f} | {lw[i, 2]:.3f} |")
    # twist
    P("\n### Twist (M/M_s against x = phi/phi_slip; Lubkin exact for the circle)\n")
    P("| x | Lubkin (b/a = 1) | BEM b/a = 1 | law b/a = 1 | law - Lubkin (% M_s) | stick Lubkin | stick law "
      "| BEM b/a = 0.5 | law b/a = 0.5 | law - BEM (% M_s) | stick BEM | stick law |")
    P("|---|---|---|---|---|---|---|---|---|---|---|---|")
    tw = {}
    for b in (1.0, 0.5):
        tw[b] = run_law(law, b, NU, [(0.0, 0.0, d) for d in twist_incs(X_TWIST, b, NU)])
    lub = np.array([r[3:] for r in rows if r[0] == "lubkin"])
    r1 = np.array([r[3:] for r in rows if r[0] == "twist" and r[1] == 1.0])
    r5 = np.array([r[3:] for r in rows if r[0] == "twist" and r[1] == 0.5])
    m1 = tw[1.0][:, 3] / slip_moment(1.0)
    m5 = tw[0.5][:, 3] / slip_moment(0.5)
    for i, x in enumerate(X_TWIST):
        P(f"| {x:.2f} | {lub[i, 1]:.4f} | {r1[i, 1]:.4f} | {m1[i]:.4f} | {100 * (m1[i] - lub[i, 1]):+.2f} "
          f"| {lub[i, 5]:.3f} | {tw[1.0][i, 4]:.3f} | {r5[i, 1]:.4f} | {m5[i]:.4f} | {100 * (m5[i] - r5[i, 1]):+.2f} "
          f"| {r5[i, 5]:.3f} | {tw[0.5][i, 4]:.3f} |")
    P(f"\nTwist, max abs deviation: circle law - Lubkin {100 * np.abs(m1 - lub[:, 1]).max():.2f} % M_s "
      f"(BEM - Lubkin {100 * np.abs(r1[:, 1] - lub[:, 1]).max():.2f} %); ellipse b/a = 0.5 law - BEM "
      f"{100 * np.abs(m5 - r5[:, 1]).max():.2f} % M_s")
    return "\n".join(out)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--law", help="cmd_bem_driver binary: print the comparison tables")
    ap.add_argument("--quick", action="store_true", help="skip the N = 128 grids")
    ap.add_argument("--csv", default=os.path.join(HERE, "cmd_bem.csv"))
    ap.add_argument("--tables", help="write the comparison tables to this file (else stdout)")
    ap.add_argument("--compare-only", action="store_true",
                    help="no BEM: read the curves from --csv and compare them with --law")
    args = ap.parse_args()
    if args.compare_only:
        rows = read_csv(args.csv)
        tab = compare(args.law, rows)
        if args.tables:
            with open(args.tables, "w") as f:
                f.write(tab + "\n")
        else:
            print(tab)
        return
    t0 = time.time()
    err = validate(args.quick)
    print(f"validation: {time.time() - t0:.0f} s")
    rows, chk = reference(args.quick)
    write_csv(rows, err, chk, args.csv)
    print(f"wrote {args.csv} ({len(rows)} rows), {time.time() - t0:.0f} s in all")
    if args.law:
        tab = compare(args.law, rows)
        if args.tables:
            with open(args.tables, "w") as f:
                f.write(tab + "\n")
        else:
            print(tab)


if __name__ == "__main__":
    main()
