#!/usr/bin/env python3
"""Kalker's creep coefficients c11, c22, c23, c33 of steady rolling with
full adhesion (Kalker's linear theory) on an elliptic contact, computed
independently of any published table.

Problem (quasi-identical bodies, combined G, nu: 1/G = (1/G1 + 1/G2)/2,
nu/G = (nu1/G1 + nu2/G2)/2). The contact a (along the rolling direction
x) by b moves at speed V over both bodies; the material enters at the
leading edge x = +a (1 - y^2/b^2)^1/2. With q the traction on body i and
u = u_i - u_j the difference of the surface displacements
(Cerruti: pi G u_x = int [((1-nu) + nu cos^2 t) q_x + nu cos t sin t q_y] dr dt
in polar coordinates around the field point, and alike for u_y), the
slip of i against j divided by V vanishes everywhere in the contact:
    du_x/dx = xi - phi y,   du_y/dx = eta + phi x,
xi, eta the creepages (rigid slip / V), phi the spin (omega_n / V); and
the traction vanishes at the leading edge. Integrated in x:
    u_x = xi x - phi x y + f(y),   u_y = eta x + phi x^2/2 + g(y).

Method (Kalker 1967's idea, Galin's theorem): a traction
q = P(X, Y) / (1 - X^2 - Y^2)^1/2 (X = x/a, Y = y/b) with P a polynomial
of total degree n gives a displacement that is a polynomial of degree n in
the ellipse. The displacement of each basis polynomial (orthonormal on the
disc for that weight, Dunkl & Xu) is computed by quadrature along rays from
collocation points: on a ray the weight's square root is that of a
quadratic, and r = m + h cos(psi) turns the ray integral into a smooth one
(Gauss-Legendre); the ray angle is uniform in the normalised ellipse
(trapezoidal rule, periodic and smooth). Both are converged to rounding
(the identity's null space has singular values <= 2e-15 of the largest).
The conditions above hold exactly (they are polynomial identities: a null
space of dimension n + 1 per component remains, the freedom of f and g);
in that space, the traction numerator on the leading half of the boundary
is made least in L2 (it cannot vanish there exactly for finite n). As n
grows this converges to the linear-theory solution; the values for
n = 8, 12, 16, 20 are extrapolated (Aitken's delta^2 on the last three)
and the error is estimated as the change of that extrapolation from the
previous three, plus half the gap between c23 and c32 (Kalker's
reciprocity: the lateral force from spin and the moment from lateral creep
have the same coefficient; here they converge to it from both sides).

Why it is right: Galin's theorem makes everything but the leading-edge
condition exact (checked: the null space's singular values, <= 2e-15);
the least-squares edge condition converges in the degree (steps shrink
geometrically, ratio ~0.4-0.5 per 4 degrees at a/b = 1..10); nu = 0 gives
c11 = c22 to 1e-11; the reciprocity c23 = c32, not imposed, comes out of
two different solves to 5e-6 (circle, nu = 0.25, degree 28); a/b = 0.01 meets Kalker's strip
asymptotes (c11 = pi^2/(4(1-nu)) to 6e-5 at nu = 0.25); Kalker's
published table (1990, Table E.3) agrees within 1.2 % (0.8 % for a/b in
[0.2, 5]), mostly from below (his expansion was of lower degree).

Coefficients (Kalker's form, G combined, c^2 = a b):
    F_x = -G c^2 c11 xi
    F_y = -G c^2 c22 eta - G c^3 c23 phi
    M_z = +G c^3 c23 eta - G c^4 c33 phi
(F, M_z: force on body i and moment about the normal n from j to i; xi,
eta along x = rolling direction and y = n x x.) Checks: nu = 0 gives
c11 = c22 (x and y decouple alike); the circle at nu = 0.25 converges to
c11 = 4.1128186, c22 = 3.6682949, c23 = 1.466110, c33 = 1.1843035 (n <= 28); the
slender limit a/b -> 0 approaches Kalker's asymptotes pi^2/(4(1-nu)), pi^2/4.

Rows of kalker.csv (beside this script):
    node,  a/b, nu, c11, c22, c23, c33, e11, e22, e23, e33
      the grid of the law's series: ln(a/b) at 17 Chebyshev-Lobatto points
      of [ln 0.1, ln 10], nu at 9 Chebyshev points of [0, 0.5] (and rows at
      nu = 0, 0.25, 0.5, off that grid);
    check, ...  (same columns) at the published table's axis ratios (off the
      grid), nu = 0, 0.25, 0.5, 0.3: not used by the law, tests of its
      interpolation;
    far, ...  a/b = 0.01, 0.03, 30, 100 (degrees 12..24; the expansion
      converges slowly there, e_ij says how well): the error of the law's
      asymptotes beyond the grid.
e_ij: estimated absolute error of c_ij.

Usage:
    python3 gen_kalker.py [--jobs 2]        # writes kalker.csv (17 min on 2 busy cores)
    python3 gen_kalker.py --table            # prints the table of rolling_kalker.c (from kalker.csv)
    python3 gen_kalker.py --far              # only the far rows, appended to kalker.csv
    python3 gen_kalker.py --point 0.5 0.3    # one case, with its convergence history
    python3 gen_kalker.py --oblique 2 0.25 45   # rolling at 45 degrees to the axis a of a/b = 2
    python3 gen_kalker.py --oblique-table    # writes kalker_oblique.csv (7 oblique cases)
Needs numpy (Debian: python3-numpy).
"""
import math
import os
import sys
import tempfile
import time

import numpy as np
from numpy.polynomial import legendre as npleg

HERE = os.path.dirname(os.path.abspath(__file__))
S_MAX = math.log(10.0)
N_NODES = 17
NU_CHEB = 9


def disc_index(n, ypar):
    """(m, k) of the basis with m + k <= n and parity k % 2 == ypar in Y."""
    return [(m, k) for k in range(ypar, n + 1, 2) for m in range(0, n - k + 1)]


def disc_basis(n, X, Y, idx):
    """Orthonormal polynomials on the unit disc for the weight
    (1 - X^2 - Y^2)^-1/2: C_m^(k+1/2)(X) (1-X^2)^(k/2) T_k(Y/(1-X^2)^1/2)."""
    s2 = np.maximum(1.0 - X * X, 0.0)
    U = [np.ones_like(X), Y.copy()]
    for k in range(2, n + 1):
        U.append(2 * Y * U[k - 1] - s2 * U[k - 2])
    out = np.empty(X.shape + (len(idx),))
    pos = {mk: i for i, mk in enumerate(idx)}
    for k in sorted(set(k for _, k in idx)):
        lam = k + 0.5
        mmax = max(m for m, kk in idx if kk == k)
        C = [np.ones_like(X), 2 * lam * X]
        for m in range(2, mmax + 1):
            C.append((2 * X * (m + lam - 1) * C[m - 1] - (m + 2 * lam - 2) * C[m - 2]) / m)
        hT = math.pi if k == 0 else math.pi / 2
        for m in range(mmax + 1):
            lh = (math.log(math.pi) + (1 - 2 * lam) * math.log(2) + math.lgamma(m + 2 * lam)
                  - math.lgamma(m + 1) - math.log(m + lam) - 2 * math.lgamma(lam))
            out[..., pos[(m, k)]] = C[m] * U[k] / math.sqrt(math.exp(lh) * hT)
    return out


def displacement_integrals(n, a, b, pts, idxs, ntau, npsi, chunk=4):
    """For each point and basis function: the integrals Jcc, Jss, Jcs with
    pi G u_x = ((1-nu)(Jcc+Jss) + nu Jcc).p + nu Jcs.q and
    pi G u_y = nu Jcs.p + ((1-nu)(Jcc+Jss) + nu Jss).q."""
    gx, gw = npleg.leggauss(npsi)
    tau = 2 * np.pi * (np.arange(ntau) + 0.5) / ntau
    den = np.sqrt(a * a * np.cos(tau) ** 2 + b * b * np.sin(tau) ** 2)
    c = a * np.cos(tau) / den
    s = b * np.sin(tau) / den
    dth = a * b / den ** 2 * (2 * np.pi / ntau)   # d(theta)/d(tau)
    A = c * c / a ** 2 + s * s / b ** 2
    out = [[np.zeros((len(pts), len(idx))) for _ in range(3)] for idx in idxs]
    for k0 in range(0, len(pts), chunk):
        P = pts[k0:k0 + chunk]
        x = P[:, 0][:, None]
        y = P[:, 1][:, None]
        B = x * c / a ** 2 + y * s / b ** 2
        C0 = 1 - x * x / a ** 2 - y * y / b ** 2
        D = np.sqrt(B * B + A * C0)
        R = (-B + D) / A
        R2 = (B + D) / A
        m = (R - R2) / 2
        h = (R + R2) / 2
        psi0 = np.arccos(np.clip(-m / h, -1, 1))
        psi = psi0[..., None] * (gx + 1) / 2
        w = ((psi0 * dth / np.sqrt(A))[..., None] / 2) * gw
        r = m[..., None] + h[..., None] * np.cos(psi)
        X = (x[..., None] + r * c[:, None]) / a
        Y = (y[..., None] + r * s[:, None]) / b
        wcc = w * (c * c)[:, None]
        wss = w * (s * s)[:, None]
        wcs = w * (c * s)[:, None]
        for q, idx in enumerate(idxs):
            Bv = disc_basis(n, X, Y, idx)   # (chunk, ntau, npsi, N)
            for t, wt in enumerate((wcc, wss, wcs)):
                out[q][t][k0:k0 + len(P)] = np.einsum("kij,kijn->kn", wt, Bv)
    return out


def area_integrals(n, idx):
    """int over the disc of B / (1-X^2-Y^2)^1/2, and times X, times Y."""
    gx, gw = npleg.leggauss(n + 10)
    psi = np.pi / 4 * (gx + 1)
    wpsi = np.pi / 4 * gw
    nt = 2 * n + 8
    th = 2 * np.pi * np.arange(nt) / nt
    S = np.sin(psi)[:, None]
    X = (S * np.cos(th)).ravel()
    Y = (S * np.sin(th)).ravel()
    w = ((wpsi * np.sin(psi))[:, None] * np.full(nt, 2 * np.pi / nt)).ravel()
    Bv = disc_basis(n, X, Y, idx)
    return w @ Bv, (w * X) @ Bv, (w * Y) @ Bv


class Galin:
    """One axis ratio g = a/b (a along the rolling direction) and degree n;
    any Poisson ratio. G = 1, c = (a b)^1/2 = 1."""

    def __init__(self, g, n, rmax=0.97):
        self.n = n
        a = math.sqrt(g)
        b = 1 / math.sqrt(g)
        self.a, self.b = a, b
        self.idx = {0: disc_index(n, 0), 1: disc_index(n, 1)}
        pts = []
        nr = n // 2 + 3
        for k in range(nr):
            rho = rmax * math.sin(math.pi / 2 * (k + 0.5) / nr)
            na = n + 2
            for j in range(na):   # upper half: the parity classes carry the rest
                t = math.pi * (j + 0.5 * (k % 2) + 0.25) / na
                pts.append((a * rho * math.cos(t), b * rho * math.sin(t)))
        self.pts = np.array(pts)
        J = displacement_integrals(n, a, b, self.pts, [self.idx[0], self.idx[1]], 6 * n + 160, n + 14)
        self.J = {0: J[0], 1: J[1]}
        self.K = {p: area_integrals(n, self.idx[p]) for p in (0, 1)}
        gx, gw = npleg.leggauss(3 * (n + 1))
        tk = np.pi / 2 * gx
        wk = np.sqrt(np.pi / 2 * gw)
        self.edge = {p: disc_basis(n, np.cos(tk), np.sin(tk), self.idx[p]) * wk[:, None] for p in (0, 1)}
        self.null_sv = 0.0

    def _solve(self, nu, ppar, rhs):
        """P of parity ppar in Y, Q of the other; rhs: list of (u_x, u_y) targets."""
        n, b = self.n, self.b
        Jp, Jq = self.J[ppar], self.J[1 - ppar]
        Np, Nq = Jp[0].shape[1], Jq[0].shape[1]
        Yn = self.pts[:, 1] / b
        jf = np.arange(ppar, n + 1, 2)
        jg = np.arange(1 - ppar, n + 1, 2)
        LY = npleg.legvander(Yn, n)
        M = len(Yn)
        E = np.zeros((2 * M, Np + Nq + len(jf) + len(jg)))
        E[:M, :Np] = ((1 - nu) * (Jp[0] + Jp[1]) + nu * Jp[0]) / np.pi
        E[:M, Np:Np + Nq] = nu * Jq[2] / np.pi
        E[:M, Np + Nq:Np + Nq + len(jf)] = -LY[:, jf]
        E[M:, :Np] = nu * Jp[2] / np.pi
        E[M:, Np:Np + Nq] = ((1 - nu) * (Jq[0] + Jq[1]) + nu * Jq[1]) / np.pi
        E[M:, Np + Nq + len(jf):] = -LY[:, jg]
        U, S, Vt = np.linalg.svd(E, full_matrices=False)
        rank = E.shape[1] - len(jf) - len(jg)
        if rank < len(S):
            self.null_sv = max(self.null_sv, S[rank] / S[0])
        ne = self.edge[ppar].shape[0]
        Le = np.zeros((2 * ne, E.shape[1]))
        Le[:ne, :Np] = self.edge[ppar]
        Le[ne:, Np:Np + Nq] = self.edge[1 - ppar]
        Z = Vt[rank:].T
        LZ = Le @ Z
        sols = []
        for rx, ry in rhs:
            r = np.concatenate([rx, ry])
            w0 = Vt[:rank].T @ ((U[:, :rank].T @ r) / S[:rank])
            w = w0 + Z @ np.linalg.lstsq(LZ, -Le @ w0, rcond=None)[0]
            sols.append((w[:Np], w[Np:Np + Nq]))
        return sols

    def coefficients(self, nu):
        a, b = self.a, self.b
        x, y = self.pts[:, 0], self.pts[:, 1]
        (px, _), = self._solve(nu, 0, [(x, 0 * x)])
        (pe, qe), (pf, qf) = self._solve(nu, 1, [(0 * x, x), (-x * y, x * x / 2)])
        K0e, KXe, _ = self.K[0]
        _, _, KYo = self.K[1]
        return (-a * b * (K0e @ px), -a * b * (K0e @ qe), -a * b * (K0e @ qf),
                -a * b * (a * (KXe @ qf) - b * (KYo @ pf)), a * b * (a * (KXe @ qe) - b * (KYo @ pe)))


def oblique(g, alpha, nu, n):
    """Rolling at angle alpha to the axis a of an ellipse a/b = g (c = 1,
    G = 1): the 3x3 matrix C with F_x = -(C11 xi + C12 eta + C13 phi),
    F_y = -(C21 xi + C22 eta + C23 phi), M_z = C31 xi + C32 eta - C33 phi in
    the rolling frame (x along the rolling direction). Kalker's form is the
    alpha = 0 case (C12 = C13 = C21 = C31 = 0, C32 = C23). Same method as
    Galin, without the parity split: u in the rolling frame is
    (xi x_r - phi x_r y_r + f(y_r), eta x_r + phi x_r^2/2 + g(y_r)), the
    leading edge the half of the boundary whose normal has e.n > 0."""
    a, b = math.sqrt(g), 1 / math.sqrt(g)
    idx = disc_index(n, 0) + disc_index(n, 1)
    pts = []
    nr = n // 2 + 3
    for k in range(nr):
        rho = 0.97 * math.sin(math.pi / 2 * (k + 0.5) / nr)
        na = 2 * n + 3
        for j in range(na):
            t = 2 * math.pi * (j + 0.5 * (k % 2) + 0.25) / na
            pts.append((a * rho * math.cos(t), b * rho * math.sin(t)))
    pts = np.array(pts)
    (Jcc, Jss, Jcs), = displacement_integrals(n, a, b, pts, [idx], 6 * n + 160, n + 14)
    N = len(idx)
    Uxp, Uxq = ((1 - nu) * (Jcc + Jss) + nu * Jcc) / np.pi, nu * Jcs / np.pi
    Uyp, Uyq = nu * Jcs / np.pi, ((1 - nu) * (Jcc + Jss) + nu * Jss) / np.pi
    ca, sa = math.cos(alpha), math.sin(alpha)
    x, y = pts[:, 0], pts[:, 1]
    xr, yr = x * ca + y * sa, -x * sa + y * ca
    LY = npleg.legvander(yr / math.sqrt(a * a * sa * sa + b * b * ca * ca), n)
    M, nf = len(x), n + 1
    E = np.zeros((2 * M, 2 * N + 2 * nf))
    E[:M, :N], E[:M, N:2 * N], E[:M, 2 * N:2 * N + nf] = ca * Uxp + sa * Uyp, ca * Uxq + sa * Uyq, -LY
    E[M:, :N], E[M:, N:2 * N], E[M:, 2 * N + nf:] = -sa * Uxp + ca * Uyp, -sa * Uxq + ca * Uyq, -LY
    U, S, Vt = np.linalg.svd(E, full_matrices=False)
    rank = E.shape[1] - 2 * nf
    gx, gw = npleg.leggauss(3 * (n + 1))
    tk = math.atan2(sa / b, ca / a) + np.pi / 2 * gx
    Bl = disc_basis(n, np.cos(tk), np.sin(tk), idx) * np.sqrt(np.pi / 2 * gw)[:, None]
    Le = np.zeros((2 * len(tk), E.shape[1]))
    Le[:len(tk), :N], Le[len(tk):, N:2 * N] = Bl, Bl
    Z = Vt[rank:].T
    K0, KX, KY = area_integrals(n, idx)
    res = []
    for rx, ry in [(xr, 0 * xr), (0 * xr, xr), (-xr * yr, xr * xr / 2)]:
        r = np.concatenate([rx, ry])
        w0 = Vt[:rank].T @ ((U[:, :rank].T @ r) / S[:rank])
        w = w0 + Z @ np.linalg.lstsq(Le @ Z, -Le @ w0, rcond=None)[0]
        p, q = w[:N], w[N:2 * N]
        Fx, Fy = a * b * (K0 @ p), a * b * (K0 @ q)
        res.append((ca * Fx + sa * Fy, -sa * Fx + ca * Fy, a * b * (a * (KX @ q) - b * (KY @ p))))
    return np.array([[-res[0][0], -res[1][0], -res[2][0]],
                     [-res[0][1], -res[1][1], -res[2][1]],
                     [res[0][2], res[1][2], -res[2][2]]]), S[rank] / S[0]


def aitken(x0, x1, x2):
    """Aitken's delta^2 where the last steps shrink geometrically (ratio <=
    0.8, same sign); else the last value (the sequence has settled)."""
    d1, d2 = x1 - x0, x2 - x1
    if d1 * d2 <= 0 or abs(d2) > 0.8 * abs(d1):
        return x2
    return x2 - d2 * d2 / (d2 - d1)


def extrapolate(g, nus, degrees=(8, 12, 16, 20), tol=2e-7, log=None):
    """Coefficients at the Poisson ratios nus, extrapolated in the degree:
    list of (c11, c22, c23, c33, e11, e22, e23, e33)."""
    hist = []
    for n in degrees:
        t0 = time.time()
        gal = Galin(g, n)
        hist.append([gal.coefficients(nu) for nu in nus])
        if log:
            log("g=%g n=%d %.0fs null-space sv %.1e: %s" % (g, n, time.time() - t0, gal.null_sv,
                " ".join("%.9f" % v for v in hist[-1][len(nus) // 2])))
        if gal.null_sv > 1e-12:
            raise RuntimeError("quadrature not converged (g=%g n=%d)" % (g, n))
        if len(hist) >= 4:
            worst = 0.0
            for i in range(len(nus)):
                for j in range(5):
                    s = [h[i][j] for h in hist[-4:]]
                    e = abs(aitken(*s[1:]) - aitken(*s[:3])) / abs(s[-1])
                    worst = max(worst, e)
            if worst < tol:
                break
    rows = []
    for i in range(len(nus)):
        seq = [[h[i][j] for h in hist] for j in range(5)]
        ext = [aitken(*s[-3:]) for s in seq]
        # change of the extrapolation from the previous three, and the last
        # step where the extrapolation was not used
        err = [abs(aitken(*s[-3:]) - aitken(*s[-4:-1])) + (abs(s[-1] - s[-2]) if aitken(*s[-3:]) == s[-1] else 0.0)
               for s in seq]
        c23 = 0.5 * (ext[2] + ext[4])
        e23 = 0.5 * abs(ext[2] - ext[4]) + max(err[2], err[4])
        rows.append((ext[0], ext[1], c23, ext[3], err[0], err[1], e23, err[3]))
    return rows


def nu_nodes():
    k = np.arange(NU_CHEB)
    cheb = 0.25 - 0.25 * np.cos((2 * k + 1) * np.pi / (2 * NU_CHEB))
    return [float(v) for v in cheb] + [0.0, 0.25, 0.5]


def node_logs():
    """Chebyshev-Lobatto points of [-ln 10, ln 10] in s = ln(a/b)."""
    return [-S_MAX * math.cos(math.pi * k / (N_NODES - 1)) if 2 * k != N_NODES - 1 else 0.0
            for k in range(N_NODES)]


def node_ratios():
    return [math.exp(s) for s in node_logs()]


def check_ratios():
    return [0.1 * k for k in range(2, 10)] + [1 / (0.1 * k) for k in range(2, 10)]


def check_nus():
    return [0.0, 0.25, 0.5, 0.3]


def far_ratios():
    """Beyond the table, where the law uses the asymptotes: slower convergence."""
    return [0.01, 0.03, 30.0, 100.0]


def work(item):
    tag, g, nus = item
    t0 = time.time()
    rows = extrapolate(g, nus, degrees=(12, 16, 20, 24) if tag == "far" else (8, 12, 16, 20))
    lines = ["%s,%.17g,%.17g,%s" % (tag, g, nu, ",".join("%.12g" % v for v in r)) for nu, r in zip(nus, rows)]
    sys.stderr.write("%s g=%.6g done in %.0f s\n" % (tag, g, time.time() - t0))
    with open(os.path.join(tempfile.gettempdir(), "kalker.partial"), "a") as f:   # progress
        f.write("\n".join(lines) + "\n")
    return lines


def write_table(jobs):
    items = [("node", g, nu_nodes()) for g in node_ratios()]
    items += [("check", g, check_nus()) for g in check_ratios()]
    items += [("far", g, [0.0, 0.25, 0.5]) for g in far_ratios()]
    # slow (elongated) cases first
    items.sort(key=lambda it: -abs(math.log(it[1])))
    if jobs > 1:
        import multiprocessing as mp
        with mp.Pool(jobs) as pool:
            results = pool.map(work, items, chunksize=1)
    else:
        results = [work(it) for it in items]
    order = sorted(range(len(items)), key=lambda i: ({"node": 0, "check": 1}.get(items[i][0], 2), items[i][1]))
    with open(os.path.join(HERE, "kalker.csv"), "w") as f:
        f.write("# generated by gen_kalker.py: Kalker's linear-theory creep coefficients, Galin polynomial\n")
        f.write("# traction expansion (degree 8..20) with least leading-edge traction, extrapolated in the degree\n")
        f.write("# tag,a/b,nu,c11,c22,c23,c33,e11,e22,e23,e33 (a along rolling; e: estimated absolute error)\n")
        f.write("# node rows: the law's grid (ln(a/b) at 17 Chebyshev-Lobatto points of [ln 0.1, ln 10]); check rows: off it;\n")
        f.write("# far rows: beyond the grid (degree 12..24; convergence slower there, see e_ij)\n")
        for i in order:
            for line in results[i]:
                f.write(line + "\n")


def c_table():
    """The law's table from the node rows: for each ln(a/b) node and
    coefficient, the Chebyshev series in t = 4 nu - 1 of ln c_ij."""
    rows = {}
    with open(os.path.join(HERE, "kalker.csv")) as f:
        for line in f:
            if not line.startswith("node,"):
                continue
            v = [float(t) for t in line.split(",")[1:]]
            x = max(-1.0, min(1.0, math.log(v[0]) / S_MAX))
            k = round(math.acos(-x) * (N_NODES - 1) / math.pi)
            rows.setdefault(k, {})[v[1]] = v[2:6]
    cheb_nu = nu_nodes()[:NU_CHEB]
    theta = (2 * np.arange(NU_CHEB) + 1) * np.pi / (2 * NU_CHEB)   # t_i = -cos(theta_i)
    print("static const double kalker_lnc[DC_KALKER_NODES][4][KALKER_NU_TERMS] = {")
    for k in range(N_NODES):
        print("  {")
        for j in range(4):
            f = np.array([math.log(rows[k][nu][j]) for nu in cheb_nu])
            coef = [(2.0 / NU_CHEB) * float(np.sum(f * np.cos(l * (np.pi - theta)))) for l in range(NU_CHEB)]
            coef[0] *= 0.5
            print("    {" + ", ".join("%.17g" % c for c in coef) + "},")
        print("  },")
    print("};")


def main():
    args = sys.argv[1:]
    if args and args[0] == "--table":
        c_table()
        return
    if args and args[0] == "--oblique-table":
        cases = [(2.0, 0.25, 20.0), (2.0, 0.25, 45.0), (2.0, 0.0, 45.0), (2.0, 0.5, 45.0),
                 (5.0, 0.25, 20.0), (5.0, 0.25, 45.0), (5.0, 0.25, 70.0)]
        with open(os.path.join(HERE, "kalker_oblique.csv"), "w") as f:
            f.write("# generated by gen_kalker.py --oblique-table: rolling at alpha to the axis a of an ellipse\n")
            f.write("# a/b = g (c = 1, G = 1), the expansion at degree 16 (change from degree 12 in the last column)\n")
            f.write("# F_x = -(C11 xi + C12 eta + C13 phi), F_y = -(C21 xi + C22 eta + C23 phi), M_z = C31 xi + C32 eta - C33 phi\n")
            f.write("# a/b,nu,alpha_deg,C11,C22,C23,C33,C32,C12,C21,C13,C31,max_change\n")
            for g, nu, adeg in cases:
                C12, _ = oblique(g, math.radians(adeg), nu, 12)
                C16, _ = oblique(g, math.radians(adeg), nu, 16)
                ch = float(np.max(np.abs(C16 - C12)))
                vals = [C16[0, 0], C16[1, 1], C16[1, 2], C16[2, 2], C16[2, 1], C16[0, 1], C16[1, 0], C16[0, 2], C16[2, 0]]
                f.write("%g,%g,%g,%s,%.2e\n" % (g, nu, adeg, ",".join("%.8g" % v for v in vals), ch))
                f.flush()
        return
    if args and args[0] == "--oblique":
        g, nu, alpha = float(args[1]), float(args[2]), math.radians(float(args[3]))
        for n in (8, 12, 16):
            C, null = oblique(g, alpha, nu, n)
            print("n=%d (null-space sv %.1e):" % (n, null))
            for row in C:
                print("   " + " ".join("%12.6f" % v for v in row), flush=True)
        return
    if args and args[0] == "--point":
        g, nu = float(args[1]), float(args[2])
        r = extrapolate(g, [nu], log=lambda s: print(s, flush=True))[0]
        print("c11 %.9f c22 %.9f c23 %.9f c33 %.9f  errors %.1e %.1e %.1e %.1e" % r)
        return
    if args and args[0] == "--far":
        # only the far rows, appended to an existing kalker.csv
        import multiprocessing as mp
        items = [("far", g, [0.0, 0.25, 0.5]) for g in far_ratios()]
        with mp.Pool(2) as pool:
            results = pool.map(work, items, chunksize=1)
        with open(os.path.join(HERE, "kalker.csv"), "a") as f:
            f.write("# far rows: beyond the grid (degree 12..24; convergence slower there, see e_ij)\n")
            for lines in results:
                for line in lines:
                    f.write(line + "\n")
        return
    jobs = int(args[1]) if args and args[0] == "--jobs" else 1
    write_table(jobs)


if __name__ == "__main__":
    main()
