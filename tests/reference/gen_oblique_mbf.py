#!/usr/bin/env python3
"""Reference rebounds for the elastic oblique impact of a sphere on a plane
with Coulomb friction and Mindlin-Deresiewicz micro-slip, after the analysis
of Maw, Barber & Fawcett (MBF, "The oblique impact of elastic spheres",
Wear 38 (1976) 101-114), for Chung & Ooi (2011) test 5. Independent of the
C code and of LIGGGHTS; standard library and mpmath only.

Scenario: alumina sphere R = 2.5 mm, E = 380 GPa, nu = 0.23, rho = 4000
kg/m^3 on a plane of the same material (E* = E / (2 (1 - nu^2)), compliances
of the pair twice one body's), mu = 0.092, |v| = 3.9 m/s at 5 ... 85 degrees
from the normal, no normal damping (e = 1), I = 2/5 m R^2, lever arm R.
Output (oblique_mbf.csv beside this script): angle_deg, vt_rebound,
vn_rebound, omega_rebound. Signs: incident v_t > 0; omega about the axis for
which rolling gives omega R = v_t (omega_y for motion along +x on a plane
z = 0 below the sphere), so the contact-point velocity is V = v_t - R omega
and gross sliding gives v_t' = v_t - 2 mu v_n, omega' = 5 mu v_n / R;
vn_rebound > 0 away from the plane.

Model
  Normal: Hertz, a^2 = R delta, F = 4/3 E* R^1/2 delta^3/2, pressure
  p0 (1 - r^2/a^2)^1/2; for identical materials it is not coupled to the
  tangential problem. The time is parametrised by theta in (0, pi) with
  a = a_max sin theta (delta = delta_max sin^2 theta); dt/dtheta follows from
  the energy integral in closed form, smooth on the whole impact (the
  t^1/2 start and the turning point are regular in theta).
  Tangential: the traction q(r) is taken along the plane of incidence and
  as a function of r only (unidirectional, axisymmetric), as in an annulus
  analysis of MBF's kind; the lever arm R is used for the torque and for the
  contact-point velocity. The contact is discretised into N fixed annuli
  (rings) with boundaries b_k = a_max sin(k pi / 2N) (fine where the contact
  edge lingers, at a_max). Each ring carries a uniform traction (ring force
  f_j). Compliance: Cerruti's kernel for a tangential point force (Johnson,
  Eq. 3.86), averaged over the source and field angles, is
  (2 - nu)/(4 pi G) <1/rho>, i.e. the Boussinesq kernel times
  (2 - nu)/(2 (1 - nu)); a uniform traction on a disc then gives a closed
  form in K and E, and the area mean over ring i of the relative
  (sphere minus plane) displacement under a unit force on ring j is
  D_ij = 2 (2 - nu)/(pi G) * 2 [H(b_i+1, b_j+1) - H(b_i, b_j+1)
         - H(b_i+1, b_j) + H(b_i, b_j)] / (pi (b_i+1^2 - b_i^2)(b_j+1^2 - b_j^2)),
  H(r, c) = M^3/3 [(1 + k^2) E(k) - (1 - k^2) K(k)], M = max(r, c),
  k = min/max (a Galerkin matrix: symmetric, positive definite; 30 digits,
  then double). The averaging drops only the part of Cerruti's field that
  varies as cos 2 phi around a ring (zero in Mindlin's and Cattaneo's
  solutions, for which it is exact); kernel_check() compares it with direct
  quadrature of Eq. 3.86.
  Stick/slip with memory: the state is the set of ring forces. Over a time
  step the slip of ring i is dS_i = dX + (D df)_i (dX: rigid tangential
  displacement of the sphere's contact point, integral of v_t - R omega).
  A ring sticks (dS_i = 0, |f_i| <= mu P_i, P_i the Hertz load on the ring)
  or slips (f_i = -+ mu P_i, friction opposing dS_i); the rings are sorted by
  an active-set iteration with bordered updates of inv(D_stick). A ring
  enters contact with zero force when a(t) passes its inner radius and
  leaves when P_i -> 0, so the history (Mindlin-Deresiewicz) is carried by
  the traction field itself; all loading, unloading, reversal and re-stick
  sequences follow from the incremental conditions.
  Dynamics: m dv_t/dt = F, I domega/dt = -R F (F = sum f_j on the sphere).
  Within a step each ring's mobilisation f_j / P_j is interpolated linearly
  in theta and integrated against the exact Hertz load P_j(t) (Gauss-Legendre,
  8 points), for the impulses and for dX (including int (t1 - t) F dt), the
  end values being implicit (solved together with the stick set). The scheme
  is second order in the step and exact while a ring slips throughout, so
  gross sliding reproduces the rigid-body result to round-off.

Discretisation and convergence
  N rings, M time steps per ring event (steps uniform in theta,
  d theta = pi / (2 N M), 2 N M steps). At fixed N the error is second order
  in the step (at N = 200, M = 2 -> 4 changes v_t' by 1.2e-6 and omega' by
  2.2e-6, relative, at 10 degrees); the ring error is first order in 1/N (a
  ring enters contact as a whole while the edge crosses it, and the
  flat-punch-like stick increments at an edge lying between coarse rings
  are under-resolved), with a clean expansion:
  successive differences halve (observed order 1.0 at 5 degrees, about 1.4
  at 10 and 20 degrees). The table uses N = 100, 200, 400, M = 4 and the
  Richardson limit 2 x(400) - x(200); its change from 2 x(200) - x(100) is
  the quoted error estimate (1e-6 to 2e-5 relative). The 10-degree convergence
  table (N = 50, 100, 200; M = 1, 2, 4) is printed; raw values change by
  less than 1e-4 (relative) from N = 100 to 200.
  Independent cross-check: the method of dimensionality reduction (Popov &
  Hess) solves the same angle-averaged problem exactly while the stick zone
  is a central disc with an outer slip annulus, as it is here (the ring
  solution departs from that only for a few steps when the whole contact
  sticks at once and an outer ring sticks a step early); mdr_impact() with
  500 and 1000 springs and steps (second order, extrapolated) agrees with
  the ring limits to 1e-6 .. 5e-6 (relative).
  Other checks printed: Mindlin's no-slip stiffness 4 G a/(2 - nu) and the
  Mindlin-Deresiewicz loading / unloading curves at fixed contact
  (O(1/N^2)); gross-slip angles against the rigid-body result; MBF's
  threshold for gross slip throughout, psi1 >= 4 chi - 1; the no-slip limit
  of psi2 / psi1; the sign of psi2 for MBF's thin diametral slice
  (chi = 1.2558), which MBF report negative at low psi1.
  psi = 2(1 - nu)/(2 - nu) (v_t - R omega)/(mu v_n) (v_n incident) is MBF's
  dimensionless contact-point velocity (psi1 before, psi2 after impact);
  chi = (1 - nu)(1 + m R^2/I)/(2 - nu) = 1.5226 here.

Run: python3 gen_oblique_mbf.py            (about 4 minutes, writes the csv)
     python3 gen_oblique_mbf.py --quick    (no convergence table, no MDR)
     python3 gen_oblique_mbf.py --lever R-delta/2   (LIGGGHTS' lever arm
         R - delta/2 for the torque and the contact-point velocity; printed
         only, the csv keeps MBF's R)
"""
import argparse
import math
import os
import time
from operator import mul

import mpmath as mp

HERE = os.path.dirname(os.path.abspath(__file__))

# ---------------------------------------------------------------- scenario
R = 2.5e-3            # sphere radius [m]
E_MOD = 380e9         # Young's modulus of sphere and plane [Pa]
NU = 0.23             # Poisson's ratio of both
RHO = 4000.0          # density [kg/m^3]
MU = 0.092            # friction coefficient
SPEED = 3.9           # impact speed [m/s]
ANGLES = (5, 10, 20, 30, 40, 50, 60, 70, 80, 85)   # from the normal [deg]

G_MOD = E_MOD / (2.0 * (1.0 + NU))
E_STAR = E_MOD / (2.0 * (1.0 - NU * NU))           # Hertz modulus of the pair
MASS = RHO * 4.0 / 3.0 * math.pi * R ** 3
INERTIA = 0.4 * MASS * R * R
HALF_PI = 0.5 * math.pi
CHI_T = 2.0 * (1.0 - NU) / (2.0 - NU)              # tangential / normal stiffness


# ------------------------------------------------------- Gauss-Legendre
def gauss_legendre(n):
    """Nodes on [0, 1] and weights (Newton on P_n, double precision)."""
    xs, ws = [], []
    for i in range(1, n + 1):
        x = math.cos(math.pi * (i - 0.25) / (n + 0.5))
        for _ in range(100):
            p0, p1 = 1.0, x
            for k in range(2, n + 1):
                p0, p1 = p1, ((2 * k - 1) * x * p1 - (k - 1) * p0) / k
            dp = n * (x * p1 - p0) / (x * x - 1.0)
            dx = p1 / dp
            x -= dx
            if abs(dx) < 1e-16:
                break
        p0, p1 = 1.0, x
        for k in range(2, n + 1):
            p0, p1 = p1, ((2 * k - 1) * x * p1 - (k - 1) * p0) / k
        dp = n * (x * p1 - p0) / (x * x - 1.0)
        xs.append(0.5 * (1.0 - x))
        ws.append(1.0 / ((1.0 - x * x) * dp * dp))
    return xs, ws


# ------------------------------------------- ring-averaged compliance
def hfun_mp(r, c):
    """H(r, c) = int_0^r s U(s, c) ds, U(s, c) = c E(s/c) (s < c),
    s [E(c/s) - (1 - c^2/s^2) K(c/s)] (s > c); closed form
    M^3/3 [(1 + k^2) E(k) - (1 - k^2) K(k)], M = max(r, c), k = min/max."""
    r, c = mp.mpf(r), mp.mpf(c)
    if r == 0 or c == 0:
        return mp.mpf(0)
    if r == c:
        return 2 * r ** 3 / 3
    big, small = (r, c) if r > c else (c, r)
    m = (small / big) ** 2
    return big ** 3 / 3 * ((1 + m) * mp.ellipe(m) - (1 - m) * mp.ellipk(m))


def ring_bounds(n):
    """Ring boundaries b_k = sin(k pi / 2n), k = 0..n (units of a_max)."""
    b = [math.sin(k * math.pi / (2 * n)) for k in range(n + 1)]
    b[n] = 1.0
    return b


def compliance_matrix(n, dps=30):
    """Galerkin ring matrix for a_max = 1, in units of 2 (2 - nu)/(pi G a_max).

    D_ij = 2 [H(b_i+1, b_j+1) - H(b_i, b_j+1) - H(b_i+1, b_j) + H(b_i, b_j)]
           / (pi (b_i+1^2 - b_i^2) (b_j+1^2 - b_j^2))
    is the area mean over ring i of the (angle-averaged) tangential
    displacement of sphere relative to plane under a unit force spread
    uniformly over ring j (symmetric, positive definite)."""
    with mp.workdps(dps):
        bm = [mp.sin(k * mp.pi / (2 * n)) for k in range(n + 1)]
        bm[n] = mp.mpf(1)
        H = [[None] * (n + 1) for _ in range(n + 1)]
        for i in range(n + 1):
            for j in range(i, n + 1):
                H[i][j] = H[j][i] = hfun_mp(bm[i], bm[j])
        area = [bm[i + 1] ** 2 - bm[i] ** 2 for i in range(n)]
        D = [[0.0] * n for _ in range(n)]
        for i in range(n):
            for j in range(i, n):
                v = 2 * (H[i + 1][j + 1] - H[i][j + 1] - H[i + 1][j] + H[i][j]) / (mp.pi * area[i] * area[j])
                D[i][j] = D[j][i] = float(v)
    return D


# ------------------------------------------------------- linear algebra
def inverse_spd(A):
    """Inverse of a symmetric positive definite matrix (Gauss-Jordan)."""
    n = len(A)
    M = [list(row) + [1.0 if i == j else 0.0 for j in range(n)] for i, row in enumerate(A)]
    for c in range(n):
        piv = M[c][c]
        rowc = [v / piv for v in M[c]]
        M[c] = rowc
        for r in range(n):
            if r != c:
                fac = M[r][c]
                if fac != 0.0:
                    M[r] = [x - fac * y for x, y in zip(M[r], rowc)]
    return [row[n:] for row in M]


class StickInverse:
    """inv(D[S][S]) for the current stick set S, kept by bordering updates."""

    def __init__(self, D):
        self.D = D
        self.S = []
        self.B = []

    def add(self, p):
        D, S, B = self.D, self.S, self.B
        u = [D[i][p] for i in S]
        w = [sum(map(mul, row, u)) for row in B]
        inv_s = 1.0 / (D[p][p] - sum(map(mul, u, w)))
        ws = [x * inv_s for x in w]
        newB = [[x + wi * y for x, y in zip(row, ws)] + [-wsi]
                for row, wi, wsi in zip(B, w, ws)]
        newB.append([-x for x in ws] + [inv_s])
        self.B = newB
        S.append(p)

    def remove(self, p):
        S, B = self.S, self.B
        q = S.index(p)
        rowq = B[q]
        inv_d = 1.0 / rowq[q]
        newB = []
        for i, row in enumerate(B):
            if i == q:
                continue
            c = row[q] * inv_d
            r = [x - c * y for x, y in zip(row, rowq)]
            del r[q]
            newB.append(r)
        self.B = newB
        del S[q]

    def refactor(self):
        S = self.S
        self.B = inverse_spd([[self.D[i][j] for j in S] for i in S]) if S else []

    def solve(self, rhs):
        return [sum(map(mul, row, rhs)) for row in self.B]


# --------------------------------------------------------------- impact
class Impact:
    """One oblique impact with n rings and msub time steps per ring event."""

    def __init__(self, angle_deg, n, msub, D=None, lever="R", ngl=8, kgyr2=0.4, mu=MU):
        self.angle = angle_deg
        self.n, self.msub = n, msub
        th = math.radians(angle_deg)
        self.vn = SPEED * math.cos(th)
        self.vt = SPEED * math.sin(th)
        self.dmax = (15.0 * MASS * self.vn ** 2 / (16.0 * E_STAR * math.sqrt(R))) ** 0.4
        self.amax = math.sqrt(R * self.dmax)
        self.fmax = 4.0 / 3.0 * E_STAR * math.sqrt(R) * self.dmax ** 1.5
        self.kappa = 4.0 * E_STAR / (3.0 * R) * self.amax ** 3   # load outside b: kappa (a^2 - b^2)^1.5
        self.tscale = self.dmax / self.vn
        self.b = ring_bounds(n)
        self.bth = [k * math.pi / (2 * n) for k in range(n + 1)]
        Dt = D if D is not None else compliance_matrix(n)
        self.sc = 2.0 * (2.0 - NU) / (math.pi * G_MOD) / self.amax
        self.D = [[self.sc * x for x in row] for row in Dt]
        self.lever = lever
        self.mu = mu
        self.minv = 1.0 / MASS
        self.iinv = 1.0 / (kgyr2 * MASS * R * R)     # kgyr2 = I / (m R^2)
        self.gx, self.gw = gauss_legendre(ngl)

    # a = a_max sin(theta); dt/dtheta from the Hertz energy integral
    def tdot(self, th):
        s = math.sin(th)
        return self.tscale * 2.0 * math.sqrt(2.0) * s * math.cos(0.5 * (HALF_PI - th)) / math.sqrt(
            1.0 + s + s * s + s ** 3 + s ** 4)

    def ell(self, th):
        """Lever arm from the centre to the contact."""
        if self.lever == "R":
            return R
        return R - 0.5 * self.dmax * math.sin(th) ** 2

    @staticmethod
    def fold(th):
        return th if th <= HALF_PI else math.pi - th

    def ncontact(self, th):
        """Number of rings in contact (b_j < a strictly), a = sin(th)."""
        th = self.fold(th)
        ev = math.pi / (2 * self.n)
        k = int(round(th / ev))
        if abs(th - k * ev) < 1e-12:
            return k
        return int(math.floor(th / ev)) + 1

    def outside_load(self, th, k):
        """Hertz normal load outside r = b_k: kappa (a^2 - b_k^2)_+^1.5."""
        th = self.fold(th)
        x = math.sin(th - self.bth[k]) * math.sin(th + self.bth[k])
        return self.kappa * x ** 1.5 if x > 0.0 else 0.0

    def ring_loads(self, th, nr):
        q = [self.outside_load(th, k) for k in range(nr + 1)]
        return [q[j] - q[j + 1] for j in range(nr)]

    def solve_increment(self, inv, st, n1, g, y, P1, stats):
        """Stick/slip state at the step end: ring forces f (length n1) with
        dS_i = g_i + y.f + (D f)_i; stick rings dS_i = 0, |f_i| <= mu P_i;
        slip rings f_i = st_i mu P_i, st_i dS_i <= 0 (traction opposes slip)."""
        D, mu = self.D, self.mu
        fscale = mu * self.fmax
        gs = max(abs(x) for x in g) if g else 0.0
        sscale = 1e-13 * (gs + fscale * D[0][0])
        it = 0
        nref = 0
        while True:
            it += 1
            S = inv.S
            fn = [st[j] * mu * P1[j] if st[j] != 0 else 0.0 for j in range(n1)]
            if S:
                yl = sum(map(mul, y, fn))
                rhs = [-(g[i] + yl + sum(map(mul, D[i], fn))) for i in S]
                x = inv.solve(rhs)
                w = inv.solve([1.0] * len(S))
                ys = [y[i] for i in S]
                corr = sum(map(mul, ys, x)) / (1.0 + sum(map(mul, ys, w)))
                for k, i in enumerate(S):
                    fn[i] = x[k] - w[k] * corr
            yt = sum(map(mul, y, fn))
            u1 = [sum(map(mul, D[i], fn)) for i in range(n1)]
            dS = [g[i] + yt + u1[i] for i in range(n1)]
            viol = []
            refac = False
            for i in range(n1):
                if st[i] == 0:
                    ex = abs(fn[i]) - mu * P1[i]
                    if ex > 1e-13 * fscale:
                        viol.append((ex * D[i][i], i, 1 if fn[i] > 0 else -1))
                    elif abs(dS[i]) > 1e3 * sscale:
                        refac = True
                else:
                    ex = st[i] * dS[i]
                    if ex > sscale:
                        viol.append((ex, i, 0))
            if refac:
                nref += 1
                stats["refactor"] += 1
                if nref > 2:
                    raise RuntimeError("stick system ill-conditioned")
                inv.refactor()
                continue
            if not viol:
                break
            if it > 8:
                viol = [max(viol)]      # one change at a time against cycling
            if it > 500:
                raise RuntimeError("active set does not converge")
            for _, i, s in viol:
                if s == 0:
                    st[i] = 0
                    inv.add(i)
                else:
                    st[i] = s
                    inv.remove(i)
        stats["iters"] += it
        stats["maxit"] = max(stats["maxit"], it)
        return fn, u1, dS

    def run(self, trace=False):
        n, msub, D = self.n, self.msub, self.D
        nsteps = 2 * n * msub
        dth = math.pi / nsteps
        gx, gw = self.gx, self.gw
        ng = len(gx)
        v, om = self.vt, 0.0
        f = []            # ring forces at the step start (length n0)
        P0 = []           # ring loads at the step start
        u0 = []           # D f at the step start, rows < n0
        st = [0] * n      # 0 stick, +1 / -1 slip with f = +/- mu P
        inv = StickInverse(D)
        n0 = 0
        Jn = Ttot = 0.0
        stats = {"iters": 0, "maxit": 0, "refactor": 0}
        tr = []
        for step in range(nsteps):
            th0 = step * dth
            th1 = math.pi if step == nsteps - 1 else (step + 1) * dth
            n1 = self.ncontact(th1) if step < nsteps - 1 else 0
            nmax = max(n0, n1)
            # ---- quadrature of the step (Gauss-Legendre in theta)
            h = th1 - th0
            nodes = [th0 + h * x for x in gx]
            td = [self.tdot(x) for x in nodes]
            dt = h * sum(w * t for w, t in zip(gw, td))
            ell_int = h * sum(w * t * self.ell(x) for w, t, x in zip(gw, td, nodes))
            rem_t, rem_l = [], []       # t1 - t and int_t^t1 ell dt at the nodes
            for x in nodes:
                hh = th1 - x
                sub = [x + hh * yy for yy in gx]
                tds = [self.tdot(yy) for yy in sub]
                rem_t.append(hh * sum(w * t for w, t in zip(gw, tds)))
                rem_l.append(hh * sum(w * t * self.ell(yy) for w, t, yy in zip(gw, tds, sub)))
            Pn = [self.ring_loads(x, nmax) for x in nodes]
            Jn += h * sum(gw[k] * td[k] * sum(Pn[k]) for k in range(ng))
            W0 = [0.0] * nmax
            W1 = [0.0] * nmax
            L0 = [0.0] * nmax
            L1 = [0.0] * nmax
            Y0 = [0.0] * nmax
            Y1 = [0.0] * nmax
            for k in range(ng):
                tau = gx[k]
                c = h * gw[k] * td[k]
                el = self.ell(nodes[k])
                cy = c * (rem_t[k] * self.minv + el * rem_l[k] * self.iinv)
                for j, p in enumerate(Pn[k]):
                    if p == 0.0:
                        continue
                    a1 = tau * p
                    a0 = p - a1
                    W0[j] += c * a0
                    W1[j] += c * a1
                    L0[j] += c * el * a0
                    L1[j] += c * el * a1
                    Y0[j] += cy * a0
                    Y1[j] += cy * a1
            P1 = self.ring_loads(th1, n1)
            lam0 = [f[j] / P0[j] for j in range(n0)]
            gconst = v * dt - om * ell_int
            for j in range(min(n0, n1)):
                gconst += lam0[j] * Y0[j]
            for j in range(n1, n0):        # rings leaving: lambda kept over the step
                gconst += lam0[j] * (Y0[j] + Y1[j])
            for j in range(n0, n1):        # rings entering: lambda of the step end
                W1[j] += W0[j]
                L1[j] += L0[j]
                Y1[j] += Y0[j]
                W0[j] = L0[j] = Y0[j] = 0.0
            y = [Y1[j] / P1[j] for j in range(n1)]
            if n1 > n0:
                u0 = u0 + [sum(map(mul, D[i], f)) for i in range(n0, n1)]
            g = [gconst - u0[i] for i in range(n1)]
            for j in range(n1, n0):
                if st[j] == 0:
                    inv.remove(j)
                st[j] = 1
            for j in range(n0, n1):        # entering rings start slipping
                st[j] = -1 if gconst > 0 else 1
            fn, u1, dS = self.solve_increment(inv, st, n1, g, y, P1, stats)
            lam1 = [fn[j] / P1[j] for j in range(n1)]
            J = JL = 0.0
            for j in range(min(n0, n1)):
                J += lam0[j] * W0[j] + lam1[j] * W1[j]
                JL += lam0[j] * L0[j] + lam1[j] * L1[j]
            for j in range(n0, n1):
                J += lam1[j] * W1[j]
                JL += lam1[j] * L1[j]
            for j in range(n1, n0):
                J += lam0[j] * (W0[j] + W1[j])
                JL += lam0[j] * (L0[j] + L1[j])
            v += J * self.minv
            om -= JL * self.iinv
            Ttot += dt
            if trace:
                tr.append((Ttot, th1, v, om, v - self.ell(th1) * om, sum(fn), n1,
                           "".join("s" if st[j] == 0 else ("+" if st[j] > 0 else "-") for j in range(n1))))
            f, P0, u0, n0 = fn, P1, u1, n1
        self.stats = stats
        self.trace = tr
        self.Jn = Jn
        self.T = Ttot
        return v, om


# ------------------------------------------------- MDR cross-check
def mdr_impact(angle_deg, nspring, nhalf, ngl=8):
    """The same impact with the method of dimensionality reduction (Popov &
    Hess): a 1D bed of independent springs x in (0, a_max), normal stiffness
    E* per length (line load E* (delta - x^2/R)), tangential k_t = CHI_T E*
    per length, each spring |k_t w| <= mu E* (delta - x^2/R), sticking
    otherwise; springs enter at w = 0 when x < a. Exact for the
    angle-averaged problem while the stick zone is a central disc (Abel
    transform), so an independent check of the ring solution, not a part of
    it. Trapezoidal rule in time, steps uniform in theta (a = a_max sin).
    Returns (v_t', omega')."""
    th_in = math.radians(angle_deg)
    vn, vt = SPEED * math.cos(th_in), SPEED * math.sin(th_in)
    dmax = (15.0 * MASS * vn ** 2 / (16.0 * E_STAR * math.sqrt(R))) ** 0.4
    amax = math.sqrt(R * dmax)
    tscale = dmax / vn
    kt = CHI_T * E_STAR
    dx = amax / nspring
    xs = [(k + 0.5) * dx for k in range(nspring)]
    the = [math.asin(x / amax) for x in xs]        # entry angle of each spring
    gx, gw = gauss_legendre(ngl)

    def tdot(th):
        s = math.sin(th)
        return tscale * 2.0 * math.sqrt(2.0) * s * math.cos(0.5 * (HALF_PI - th)) / math.sqrt(
            1.0 + s + s * s + s ** 3 + s ** 4)

    kk = 1.0 / MASS + R * R / INERTIA
    nsteps = 2 * nhalf
    dth = math.pi / nsteps
    w = [0.0] * nspring
    v, om, T0 = vt, 0.0, 0.0
    for step in range(nsteps):
        th0, th1 = step * dth, (step + 1) * dth
        h = th1 - th0
        dt = h * sum(ww * tdot(th0 + h * x) for x, ww in zip(gx, gw))
        thf = th1 if th1 <= HALF_PI else math.pi - th1
        a1 = amax * math.sin(thf) if step < nsteps - 1 else 0.0
        delta = a1 * a1 / R
        k1 = 0
        while k1 < nspring and xs[k1] < a1:
            k1 += 1
        lim = [MU * (delta - xs[k] ** 2 / R) / CHI_T for k in range(k1)]   # |w| <= mu E* (.)/k_t
        fr = [1.0 if the[k] <= th0 else (th1 - the[k]) / h for k in range(k1)]
        wk = w[:k1]

        def tforce(dX):
            return -2.0 * kt * dx * sum(min(max(a + dX * b, -l), l) for a, b, l in zip(wk, fr, lim))

        def resid(dX):
            return dX - (v - R * om) * dt - kk * dt * dt * (T0 + tforce(dX)) / 4.0

        x0 = (v - R * om) * dt
        r0 = resid(x0)
        lo = hi = x0
        span = abs(x0) + 1e-16 + 1e-9 * amax
        while resid(lo) > 0.0:
            lo -= span
            span *= 2.0
        span = abs(x0) + 1e-16 + 1e-9 * amax
        while resid(hi) < 0.0:
            hi += span
            span *= 2.0
        xk, rk = x0, r0
        for _ in range(200):
            if rk == 0.0 or hi - lo <= 1e-15 * (abs(lo) + abs(hi)):
                break
            slope = 1.0 + kk * dt * dt / 4.0 * 2.0 * kt * dx * sum(
                b for a, b, l in zip(wk, fr, lim) if abs(a + xk * b) < l)
            xn = xk - rk / slope
            if not (lo < xn < hi):
                xn = 0.5 * (lo + hi)
            rn = resid(xn)
            if rn > 0.0:
                hi = xn
            else:
                lo = xn
            xk, rk = xn, rn
        dX = xk
        w = [min(max(a + dX * b, -l), l) for a, b, l in zip(wk, fr, lim)] + [0.0] * (nspring - k1)
        T1 = -2.0 * kt * dx * sum(w)
        J = 0.5 * dt * (T0 + T1)
        v += J / MASS
        om -= R * J / INERTIA
        T0 = T1
    return v, om


# ------------------------------------------------------------ checks
def kernel_check():
    """Ring-averaged Cerruti kernel against direct quadrature: the mean over
    the circle of radius r of u_x (one body, G = 1) under a unit traction
    along x on the disc c = 1, from Johnson's Eq. 3.86 for a tangential
    point force, u_x = 1/(2 pi G) [(1 - nu)/rho + nu (x - x')^2/rho^3],
    integrated in polar coordinates about the field point (radial integral
    exact: the chord length), the mean over the field angle phi by an
    8-point trapezoidal rule (exact for the degree-2 trigonometric
    dependence), the direction integral by mpmath; compared with
    (2 - nu)/pi U(r, 1). Returns the largest relative difference."""
    worst = 0.0
    with mp.workdps(25):
        nu = mp.mpf(NU)
        for r in (mp.mpf("0.3"), mp.mpf("0.8"), mp.mpf("1.5")):
            def chord(psi):
                disc = 1 - (r * mp.sin(psi)) ** 2
                if disc <= 0:
                    return mp.mpf(0)
                s2 = -r * mp.cos(psi) + mp.sqrt(disc)
                s1 = max(mp.mpf(0), -r * mp.cos(psi) - mp.sqrt(disc))
                return max(mp.mpf(0), s2 - s1)
            if r < 1:
                cuts = [0, mp.pi / 2, mp.pi, 3 * mp.pi / 2, 2 * mp.pi]
            else:
                w = mp.asin(1 / r)
                cuts = [mp.pi - w, mp.pi, mp.pi + w]
            tot = mp.mpf(0)
            for k in range(8):
                phi = 2 * mp.pi * k / 8      # field point at angle phi, traction along x
                tot += mp.quad(lambda psi: ((1 - nu) + nu * mp.cos(psi + phi) ** 2) * chord(psi), cuts)
            val = tot / 8 / (2 * mp.pi)
            if r < 1:
                U = mp.ellipe(r * r)
            else:
                U = r * (mp.ellipe(1 / r ** 2) - (1 - 1 / r ** 2) * mp.ellipk(1 / r ** 2))
            ref = (2 - nu) / mp.pi * U
            worst = max(worst, float(abs(val / ref - 1)))
    return worst


def static_checks(D, n):
    """Fixed Hertz contact (a = a_max), quasi-static tangential loading with
    the ring solver against Mindlin's closed forms for the pair
    (k0 = 4 G a/(2 - nu), delta_s = 3 mu N (2 - nu)/(8 G a)):
    no-slip stiffness, first loading T = mu N [1 - (1 - d/d_s)^1.5] and
    unloading from d* = 0.8 d_s: T = T* - 2 mu N [1 - (1 - (d* - d)/(2 d_s))^1.5].
    Returns (stiffness error, max |T - T_Mindlin| / mu N)."""
    imp = Impact(10, n, 1, D=D)
    Dm = imp.D
    a = imp.amax
    k0 = 4.0 * G_MOD * a / (2.0 - NU)
    B = inverse_spd(Dm)
    kerr = sum(sum(row) for row in B) / k0 - 1.0
    N = imp.fmax
    muN = MU * N
    ds = 3.0 * muN * (2.0 - NU) / (8.0 * G_MOD * a)
    P = imp.ring_loads(HALF_PI, n)
    st = [-1] * n
    inv = StickInverse(Dm)
    stats = {"iters": 0, "maxit": 0, "refactor": 0}
    f = [0.0] * n
    u = [0.0] * n
    X = 0.0
    worst = 0.0
    path = [0.8 * ds * k / 40 for k in range(1, 41)] + [0.8 * ds - 1.6 * ds * k / 80 for k in range(1, 81)]
    for Xn in path:
        dX = Xn - X
        g = [dX - u[i] for i in range(n)]
        f, u, _ = imp.solve_increment(inv, st, n, g, [0.0] * n, P, stats)
        X = Xn
        T = -sum(f)     # force of the sphere on the plane, along +x
        if dX > 0:
            Tm = muN * (1.0 - (1.0 - X / ds) ** 1.5)
        else:
            Ts = muN * (1.0 - 0.2 ** 1.5)
            Tm = Ts - 2.0 * muN * (1.0 - (1.0 - (0.8 * ds - X) / (2.0 * ds)) ** 1.5)
        worst = max(worst, abs(T - Tm) / muN)
    return kerr, worst


# -------------------------------------------------------------- driver
def psi(vt, vn):
    """MBF's dimensionless tangential velocity of the contact point."""
    return CHI_T * vt / (MU * vn)


def rigid(angle):
    th = math.radians(angle)
    vn, vt = SPEED * math.cos(th), SPEED * math.sin(th)
    return vt - MU * 2.0 * vn, 5.0 / (2.0 * R) * MU * 2.0 * vn


def richardson(x1, x2, x4):
    """Limit from values at N, 2N, 4N: first order (the observed order is
    close to 1 for the stick-dominated angles, 1.4 for the others), and the
    observed order p (None if the differences are not monotone)."""
    d1, d2 = x2 - x1, x4 - x2
    lim1 = 2.0 * x4 - x2
    p = None
    if d1 != 0.0 and d2 != 0.0 and d1 * d2 > 0.0 and abs(d2) < abs(d1):
        p = math.log(d1 / d2, 2.0)
    return lim1, p


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--rings", default="100,200,400",
                    help="ring counts N, 2N, 4N for the table and Richardson extrapolation")
    ap.add_argument("--sub", type=int, default=4, help="time steps per ring event (M)")
    ap.add_argument("--lever", choices=("R", "R-delta/2"), default="R",
                    help="lever arm centre-contact (R: MBF, written to the csv; "
                         "R-delta/2: LIGGGHTS' choice, printed only)")
    ap.add_argument("--quick", action="store_true", help="skip the MDR and convergence studies")
    ap.add_argument("--out", default=os.path.join(HERE, "oblique_mbf.csv"))
    args = ap.parse_args()
    t_start = time.time()
    ns = [int(x) for x in args.rings.split(",")]
    msub = args.sub
    lever = "R" if args.lever == "R" else "Rdelta"
    log = print

    # ---- building blocks
    log("kernel: ring-averaged Cerruti vs quadrature, max rel. diff %.1e" % kernel_check())
    mats = {}
    for n in sorted(set(ns + [50])):
        mats[n] = compliance_matrix(n)
    log("static Mindlin checks (fixed a = a_max): N, no-slip stiffness error, "
        "max |T - T_Mindlin|/mu N on loading 0 -> 0.8 delta_s -> -0.8 delta_s")
    for n in (50, 100, 200):
        if n not in mats:
            mats[n] = compliance_matrix(n)
        k, w = static_checks(mats[n], n)
        log("  %4d  %.2e  %.2e" % (n, k, w))

    # ---- convergence table, 10 degrees
    if not args.quick:
        log("\nconvergence, 10 degrees: N rings, M steps per ring event "
            "(d theta = pi/(2 N M), a = a_max sin theta), v_t' [m/s], omega' [rad/s]")
        prev = {}
        for n in (50, 100, 200):
            for m in (1, 2, 4):
                imp = Impact(10, n, m, D=mats[n], lever=lever)
                v, om = imp.run()
                ch = ""
                if (n // 2, m) in prev:
                    pv, pw = prev[(n // 2, m)]
                    ch = "  rel. change from N/2: %.1e %.1e" % (abs(v / pv - 1), abs(om / pw - 1))
                log("  N=%4d M=%d  %.10f  %.8f%s" % (n, m, v, om, ch))
                prev[(n, m)] = (v, om)

    # ---- all angles
    log("\nimpacts (M = %d): N, v_t', omega'" % msub)
    rows = []
    notes = []
    for ang in ANGLES:
        res = {}
        for n in ns:
            imp = Impact(ang, n, msub, D=mats[n], lever=lever)
            t0 = time.time()
            v, om = imp.run(trace=(n == ns[0]))
            res[n] = (v, om)
            if n == ns[0]:
                # steps whose stick set is not a central disc (an outer slip
                # annulus aside), and whether any ring ever sticks
                noncentral = 0
                for row in imp.trace:
                    core = row[7].rstrip("+-").lstrip("s")
                    if "s" in core:
                        noncentral += 1
                vn_out = imp.Jn / MASS - imp.vn
            log("  %2d deg N=%4d  %.12f  %.10f   (%.1f s, active-set iterations %d)"
                % (ang, n, v, om, time.time() - t0, imp.stats["iters"]))
            if n == ns[1] and abs(res[ns[1]][0] - res[ns[0]][0]) <= 1e-13 * abs(v) \
                    and abs(res[ns[1]][1] - res[ns[0]][1]) <= 1e-12 * abs(om):
                break
        rv, rw = rigid(ang)
        nf = max(res)
        if lever == "R":
            gross = abs(res[nf][0] / rv - 1) < 1e-9 and abs(res[nf][1] / rw - 1) < 1e-9
        else:   # no closed form with the lever R - delta/2: independent of N
            gross = all(abs(res[n][k] / res[nf][k] - 1) < 1e-9 for n in res for k in (0, 1))
        if gross:
            vl, wl = res[nf]
            ev = ew = 0.0
            kind = "gross slip"
            log("     gross slip: rel. diff. from rigid-body result (lever R) %.1e, %.1e"
                % (abs(vl / rv - 1), abs(wl / rw - 1)))
        else:
            vl, pv = richardson(*(res[n][0] for n in ns))
            wl, pw = richardson(*(res[n][1] for n in ns))
            # error estimate: change of the limit from (N, 2N) to (2N, 4N)
            ev = abs(vl - (2.0 * res[ns[1]][0] - res[ns[0]][0]))
            ew = abs(wl - (2.0 * res[ns[1]][1] - res[ns[0]][1]))
            log("     extrapolated %.10f (order %s, est. err %.1e)  %.8f (order %s, est. err %.1e)"
                % (vl, "%.2f" % pv if pv else "-", ev, wl, "%.2f" % pw if pw else "-", ew))
            kind = "partial slip"
        th = math.radians(ang)
        vn = SPEED * math.cos(th)
        rows.append((ang, vl, vn_out, wl, ev, ew, kind, noncentral, None,
                     psi(SPEED * math.sin(th), vn), psi(vl - R * wl, vn)))

    # ---- MDR cross-check
    mdr = {}
    if not args.quick and lever == "R":
        log("\nMDR cross-check (1D spring bed, K springs, K steps per half impact; "
            "second order, extrapolated with p = 2)")
        for ang, vl, _, wl, _, _, kind, central, _, _, _ in rows:
            if kind != "partial slip":
                continue
            a1 = mdr_impact(ang, 500, 500)
            a2 = mdr_impact(ang, 1000, 1000)
            ml = [(4.0 * y - x) / 3.0 for x, y in zip(a1, a2)]
            mdr[ang] = ml
            log("  %2d deg  K=500 %.10f %.8f  K=1000 %.10f %.8f  limit %.10f %.8f  "
                "ring/MDR - 1: %.1e %.1e (N = %d steps with a non-central stick set: %d of %d)"
                % (ang, a1[0], a1[1], a2[0], a2[1], ml[0], ml[1],
                   vl / ml[0] - 1, wl / ml[1] - 1, ns[0], central, 2 * ns[0] * msub))

    # ---- MBF's qualitative features
    chi = CHI_T * (1.0 + 1.0 / 0.4) / 2.0
    log("\nMBF: chi = (1 - nu)(1 + m R^2/I)/(2 - nu) = %.4f; gross slip throughout for "
        "psi1 >= 4 chi - 1 = %.4f (angle %.3f deg); psi2 = psi1 - 4 chi there"
        % (chi, 4 * chi - 1, math.degrees(math.atan((4 * chi - 1) * MU / CHI_T))))
    log("  angle  psi1  psi2  (psi = 2(1-nu)/(2-nu) (v_t - R omega)/(mu v_n), v_n incident)")
    for r in rows:
        log("  %2d  %8.4f  %8.4f  %s" % (r[0], r[9], r[10], r[6]))
    if not args.quick:
        n = ns[0]
        imp = Impact(5, n, msub, D=mats[n], lever=lever, mu=100.0)
        v, om = imp.run()
        log("  no-slip limit (mu = 100): psi2/psi1 = %.4f" % ((v - R * om) / imp.vt))
        # MBF's thin diametral slice: chi = 1.2558 (nu = 0.28, I = m R^2 / 2); only chi
        # matters, so the same chi from nu = 0.23 and I/(m R^2) = CHI_T / (2 chi - CHI_T)
        kg = CHI_T / (2.0 * 1.2558 - CHI_T)
        for p1 in (0.5, 1.2):
            ang = math.degrees(math.atan(p1 * MU / CHI_T))
            imp = Impact(ang, n, msub, D=mats[n], lever=lever, kgyr2=kg)
            v, om = imp.run()
            log("  chi = 1.2558 (MBF's slice), psi1 = %.1f: psi2 = %.4f" % (p1, psi(v - R * om, imp.vn)))
        for ang in (28.0, 28.6):
            imp = Impact(ang, n, msub, D=mats[n], lever=lever)
            v, om = imp.run()
            rv, rw = rigid(ang)
            log("  %.1f deg (psi1 = %.3f): v_t'/rigid - 1 = %.1e" % (ang, psi(imp.vt, imp.vn), v / rv - 1))

    if lever != "R":
        log("\nlever arm R - delta/2: nothing written")
        return
    with open(args.out, "w") as out:
        out.write("# generated by gen_oblique_mbf.py: elastic oblique impact of a sphere on a plane with\n")
        out.write("# Coulomb friction and Mindlin-Deresiewicz micro-slip (Maw, Barber & Fawcett 1976 analysis),\n")
        out.write("# Chung & Ooi (2011) test 5: alumina R = 2.5 mm, E = 380 GPa, nu = 0.23, rho = 4000 kg/m^3,\n")
        out.write("# plane of the same material, mu = 0.092, |v| = 3.9 m/s, no normal damping, lever arm R.\n")
        out.write("# angle_deg: incidence from the normal; vt_rebound: tangential velocity of the centre after\n")
        out.write("# impact [m/s] (incident v_t = 3.9 sin(angle) > 0); vn_rebound: normal velocity after impact,\n")
        out.write("# positive away from the plane [m/s] (= incident, e = 1); omega_rebound [rad/s]: spin about\n")
        out.write("# the axis for which rolling gives omega R = v_t (omega_y for motion along +x above z = 0).\n")
        out.write("# Ring (annulus) Galerkin solution, N = %s rings, %d steps per ring event; partial-slip\n" % (args.rings, msub))
        out.write("# angles: Richardson limit 2 x(%d) - x(%d); est. error (change of that limit from N to 2N)\n" % (ns[2], ns[1]))
        out.write("# and MDR cross-check below; gross-slip angles: equal to the rigid-body result to 1e-14.\n")
        for r in rows:
            extra = ""
            if r[6] == "partial slip":
                extra = " est. rel. err. v_t' %.0e, omega' %.0e" % (r[4] / abs(r[1]), r[5] / abs(r[3]))
                if r[0] in mdr:
                    extra += "; ring/MDR - 1: %.1e, %.1e" % (r[1] / mdr[r[0]][0] - 1, r[3] / mdr[r[0]][1] - 1)
            out.write("# %2d deg: %s, psi1 = %.4f, psi2 = %.4f;%s\n" % (r[0], r[6], r[9], r[10], extra))
        out.write("# angle_deg,vt_rebound,vn_rebound,omega_rebound\n")
        for r in rows:
            out.write("%d,%#.12g,%#.12g,%#.12g\n" % (r[0], r[1], r[2], r[3]))
    log("\nwrote %s (%.0f s)" % (args.out, time.time() - t_start))


if __name__ == "__main__":
    main()
