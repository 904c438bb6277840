"""Helpers shared by the regression checks: run a LIGGGHTS deck, read its
column outputs, compare against committed references and analytic values,
and report 'N passed, N failed'."""
import math
import os
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
LIGGGHTS = os.environ.get("DC_LIGGGHTS", os.path.join(ROOT, "build", "bin", "liggghts"))
# c_core's laws outside LIGGGHTS (built beside it)
DCLAW = os.path.join(os.path.dirname(LIGGGHTS), "..", "c_core", "dclaw")


class Checks:
    def __init__(self, name):
        self.name, self.passed, self.failed = name, 0, 0

    def true(self, ok, what):
        if ok:
            self.passed += 1
        else:
            self.failed += 1
        print("%s %s" % ("ok  " if ok else "FAIL", what))

    def rel(self, got, want, tol, what):
        err = abs(got - want) / max(abs(want), 1e-300)
        self.true(math.isfinite(got) and err <= tol, "%s: got %.12g want %.12g rel.err %.3g (tol %.3g)" % (what, got, want, err, tol))

    def abs_(self, got, want, tol, what):
        err = abs(got - want)
        self.true(math.isfinite(got) and err <= tol, "%s: got %.12g want %.12g abs.err %.3g (tol %.3g)" % (what, got, want, err, tol))

    def finish(self):
        print("%s: %d passed, %d failed" % (self.name, self.passed, self.failed))
        sys.exit(1 if self.failed else 0)


def start():
    """The entry of every check_<case>.py WORKDIR [--update]: (the work
    folder, whether to rewrite the committed references, the Checks of
    <case>)."""
    if len(sys.argv) < 2:
        raise SystemExit("usage: %s WORKDIR [--update]" % sys.argv[0])
    name = os.path.basename(sys.argv[0])[len("check_"):-len(".py")]
    return sys.argv[1], "--update" in sys.argv, Checks(name)


def run(deck, workdir, ranks=1, variables=None, tag="run", expect_error=False, compiled=True):
    """Runs `deck` (a path under inputs/, or an absolute one) in workdir; returns the log text.
    With expect_error, returns (exit code, screen output + log) instead of
    failing on a non-zero exit. compiled=False lets the deck's combination
    run on LIGGGHTS' generic path (a check of set-up, not of speed)."""
    os.makedirs(workdir, exist_ok=True)
    deck_path = os.path.join(ROOT, "inputs", deck)
    # screen output is captured (LIGGGHTS' error path crashes with -screen none)
    cmd = [LIGGGHTS, "-in", deck_path, "-log", "log.%s" % tag]
    for k, v in (variables or {}).items():
        cmd += ["-var", k, str(v)]
    if ranks > 1:
        # oversubscribing makes Open MPI yield the core: only when it must
        extra = ["--oversubscribe"] if (os.cpu_count() or 1) < ranks else []
        cmd = ["mpirun", "-np", str(ranks)] + extra + cmd
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    p = subprocess.run(cmd, cwd=workdir, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, errors="replace")
    log_path = os.path.join(workdir, "log.%s" % tag)
    log = open(log_path, errors="replace").read() if os.path.exists(log_path) else ""
    if expect_error:
        return p.returncode, p.stdout + log
    if p.returncode != 0:
        print(p.stdout[-3000:])
        print(log[-3000:])
        raise SystemExit("FAIL %s: LIGGGHTS exited with %d (%s)" % (deck, p.returncode, " ".join(cmd)))
    # every model combination a deck uses is compiled (plugin/liggghts/gen_whitelist.py)
    if compiled and "not compiled for speed" in p.stdout + log:
        raise SystemExit("FAIL %s: a contact-model combination of this deck is not compiled: "
                         "plugin/liggghts/gen_whitelist.py missed it (%s)" % (deck, " ".join(cmd)))
    return log


def table(path):
    """Whitespace-separated numeric columns, '#' comments skipped."""
    rows = []
    with open(path) as f:
        for line in f:
            if line.strip() and not line.startswith("#"):
                rows.append([float(x) for x in line.split()])
    return rows


def compare_tables(checks, got, want, tol, what):
    """Row-by-row relative comparison (scale: column max) of two tables."""
    if len(got) != len(want) or not got:
        checks.true(False, "%s: %d rows, reference has %d" % (what, len(got), len(want)))
        return
    ncol = len(want[0])
    scale = [max(abs(r[c]) for r in want) or 1.0 for c in range(ncol)]
    worst = max(abs(g[c] - w[c]) / scale[c] for g, w in zip(got, want) for c in range(ncol))
    checks.true(worst <= tol, "%s: worst column-scaled difference %.3g (tol %.3g)" % (what, worst, tol))


def save_reference(src, dst, every=1):
    """Copies a table keeping every n-th data row (used by --update)."""
    os.makedirs(os.path.dirname(dst), exist_ok=True)
    with open(src) as f, open(dst, "w") as g:
        k = 0
        for line in f:
            if line.startswith("#"):
                g.write(line)
            elif line.strip():
                if k % every == 0:
                    g.write(line)
                k += 1


def hertz_impact(mass, v, Estar, R_force):
    """Analytic elastic Hertz impact (lecture notes, 004 seed) for a force
    4/3 E* R_force^1/2 delta^3/2: (collision time, maximum overlap), with
    delta_max = (15 m v^2 / (16 E* R_force^1/2))^(2/5) and T_c = 2 I delta_max / v,
    I = int_0^1 (1 - x^(5/2))^(-1/2) dx = sqrt(pi) Gamma(7/5) / Gamma(9/10)."""
    dmax = (15.0 * mass * v * v / (16.0 * Estar * math.sqrt(R_force))) ** 0.4
    I = math.sqrt(math.pi) * math.gamma(1.4) / math.gamma(0.9)
    return 2.0 * I * dmax / v, dmax


def impact(rows, overlap):
    """Collision time (zero crossings of the overlap interpolated linearly)
    and maximum overlap of a trajectory; rows start with the time."""
    d = [overlap(r) for r in rows]
    t = [r[0] for r in rows]
    k0 = next(k for k in range(1, len(d)) if d[k] > 0 >= d[k - 1])
    k1 = next(k for k in range(k0, len(d)) if d[k] <= 0)
    t0 = t[k0 - 1] + (t[k0] - t[k0 - 1]) * (-d[k0 - 1]) / (d[k0] - d[k0 - 1])
    t1 = t[k1 - 1] + (t[k1] - t[k1 - 1]) * d[k1 - 1] / (d[k1 - 1] - d[k1])
    return t1 - t0, max(d)


def subsample(rows, every):
    return rows[::every]


def ellipke(m):
    """Complete elliptic integrals K(m), E(m) by the AGM (A-S 17.6)."""
    a, b, s, w = 1.0, math.sqrt(1.0 - m), m / 2.0, 0.5
    for _ in range(60):
        if abs(a - b) <= 4e-16 * a:
            break
        cn = (a - b) / 2.0
        a, b = (a + b) / 2.0, math.sqrt(a * b)
        w *= 2.0
        s += w * cn * cn
    K = math.pi / (2.0 * a)
    return K, K * (1.0 - s)


def elliptic_hertz(R1, R2):
    """(Rc, gamma) of review Eqs. 5, 11, 13 for relative principal radii R1,
    R2, independent of c_core: bisection on Eq. 13 in its original form with
    r = R_minor/R_major. F = 4/3 E* Rc^1/2 delta^3/2 gamma."""
    Rmaj, Rmin = max(R1, R2), min(R1, R2)
    r = Rmin / Rmaj
    Rc = Rmaj * Rmin / (Rmaj + Rmin)
    if r == 1.0:
        return Rc, math.sqrt(2.0)
    g = lambda m: m - (1.0 - r * ellipke(m)[1] / ((1.0 + r) * ellipke(m)[0] - ellipke(m)[1]))
    lo, hi = 1e-12, 1.0 - 1e-16          # g < 0 just above 0 (for r < 1), g > 0 near 1
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if g(mid) < 0.0:
            lo = mid
        else:
            hi = mid
    m = 0.5 * (lo + hi)
    K, E = ellipke(m)
    return Rc, math.pi * math.sqrt(2.0) * math.sqrt(E) / (2.0 * K ** 1.5 * math.sqrt(1.0 - m))


def jkr_sphere(R, Estar, w, delta):
    """Classical JKR (Johnson, Kendall & Roberts 1971) on the stable branch:
    (contact radius a, force F) at overlap delta, by bisection on
    delta(a) = a^2/R - (2 pi w a/E*)^1/2 above its minimum; None below the
    separation overlap."""
    dl = lambda a: a * a / R - math.sqrt(2 * math.pi * w * a / Estar)
    a_b = (math.pi * w * R * R / (8 * Estar)) ** (1.0 / 3.0)
    if delta < dl(a_b):
        return None
    lo, hi = a_b, a_b + math.sqrt(R * max(delta, 0.0)) + 1e-3
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if dl(mid) < delta else (lo, mid)
    a = 0.5 * (lo + hi)
    return a, 4 * Estar * a ** 3 / (3 * R) - math.sqrt(8 * math.pi * w * Estar * a ** 3)


def elliptic_contact(R1, R2, Estar, delta):
    """Elliptic Hertz (review Eqs. 1-14, Johnson 4.2) independently of
    c_core: e^2 by bisection on Eq. 13, semi-axes a^2 = 2 R_major delta D/K,
    b = a (1 - e^2)^1/2, force 4/3 E* (Rc delta)^1/2 delta gamma; returns
    (a, b, F)."""
    Rmaj, Rmin = max(R1, R2), min(R1, R2)
    r = Rmin / Rmaj
    f = lambda m: m - (1.0 - r * ellipke(m)[1] / ((1.0 + r) * ellipke(m)[0] - ellipke(m)[1]))
    lo, hi = 1e-12, 1.0 - 1e-16
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if f(mid) < 0.0 else (lo, mid)
    m = 0.5 * (lo + hi)
    K, E = ellipke(m)
    D = (K - E) / m
    a = math.sqrt(2 * Rmaj * delta * D / K)
    gamma = math.pi * math.sqrt(2.0) * math.sqrt(E) / (2.0 * K ** 1.5 * math.sqrt(1.0 - m))
    Rc = Rmaj * Rmin / (Rmaj + Rmin)
    return a, a * math.sqrt(1.0 - m), 4.0 / 3.0 * Estar * math.sqrt(Rc * delta) * delta * gamma


def mindlin_ellipse(a, g, nu, G):
    """Mindlin's no-slip stiffnesses (k_major, k_minor) of a contact ellipse
    of semi-major axis a and axis ratio g = b/a between two like bodies
    (review Eqs. 56-57: compliance 2 [(1 - nu) K + nu D] / G along the major
    axis, 2 [K - nu D] / G along the minor, K and D of e^2 = 1 - g^2)."""
    m = 1.0 - g * g
    K, E = ellipke(m)
    D = (K - E) / m
    return 2 * math.pi * a / (2 * ((1 - nu) * K + nu * D) / G), 2 * math.pi * a / (2 * (K - nu * D) / G)


def mindlin_virgin(w, muFn):
    """Mindlin's first-loading tangential force (review Eq. 59) for the
    elastic (no-slip) force w = |K0 s| below gross sliding:
    mu Fn [1 - (1 - 2 w / (3 mu Fn))^3/2]."""
    return muFn * (1 - (1 - 2 * w / (3 * muFn)) ** 1.5)


def mindlin_ellipse_force(k_major, k_minor, s, angle_deg, muFn):
    """Eq. 59 on a contact ellipse: a displacement s at angle_deg from the
    major axis, the elastic force K0 s = (k_major s_x, k_minor s_y); the
    force opposes K0 s with magnitude mindlin_virgin(|K0 s|). Returns
    (F_x, F_y, |F|)."""
    ang = math.radians(angle_deg)
    wx, wy = k_major * s * math.cos(ang), k_minor * s * math.sin(ang)
    wl = math.hypot(wx, wy)
    F = mindlin_virgin(wl, muFn)
    return -F * wx / wl, -F * wy / wl, F


def relative_radii(k1I, k2I, k1II, k2II, w):
    """Relative principal radii from the principal curvatures of two bodies
    whose principal directions make the angle w (review Eqs. 3-4)."""
    s = k1I + k2I + k1II + k2II
    d = math.sqrt((k1I - k2I) ** 2 + (k1II - k2II) ** 2 + 2 * (k1I - k2I) * (k1II - k2II) * math.cos(2 * w))
    return 2.0 / (s - d), 2.0 / (s + d)


def dclaw(law, **keys):
    """`dclaw LAW --key value ...`: its CSV output as (header, rows of floats)."""
    args = [DCLAW, law]
    for k, v in keys.items():
        args += ["--" + k, repr(v) if isinstance(v, float) else str(v)]
    out = subprocess.run(args, capture_output=True, text=True, check=True).stdout.strip().split("\n")
    return out[0].split(","), [[float(x) for x in l.split(",")] for l in out[1:]]


def rough_adhesive_exact(radii, Estar, sigma, w, d0, d1, n):
    """(delta, loading F, unloading F, elastic F) of the exact rough contact
    with adhesive JKR summits (dclaw gw_rough --w, asperityCount 1) at n
    overlaps from d0 to d1, as gw_rough with cohesion gw_adhesion carries it:
    gw_rough cuts the elastic GW force at delta = -3 sigma (its Gaussian
    tail) and the cohesion model adds the adhesive part, so beyond the cut
    the forces lack the elastic tail (elastic F 0 there)."""
    head, rows = dclaw("gw_rough", R1=radii[0], R2=radii[1], Estar=Estar, sigma=sigma, n_asp=1, w=w, delta_min=d0,
                       delta_max=d1, n=n)
    il, iu, ig = head.index("force_adhesive_loading"), head.index("force_adhesive_unloading"), head.index("force_gw_elliptic")
    return [(r[0], r[il] - (r[ig] if r[0] <= -3 * sigma else 0.0), r[iu] - (r[ig] if r[0] <= -3 * sigma else 0.0),
             r[ig] if r[0] > -3 * sigma else 0.0) for r in rows]


def summit_delta_break(radii, Estar, w):
    """|delta_break| of one JKR summit of these relative radii (dclaw
    jkr_elliptic --summary 1): the width of gw_adhesion's partly attached band."""
    head, rows = dclaw("jkr_elliptic", R1=radii[0], R2=radii[1], Estar=Estar, w=w, summary=1)
    return -rows[0][head.index("delta_break")]


class MaugisDugdale:
    """Maugis-Dugdale of a sphere pair (effective radius R, E*, work of
    adhesion w) for the surfaces' equilibrium separation z0, in Johnson &
    Greenwood's units, independently of c_core: the contact branch from
    Johnson & Greenwood 1997's equations solved for m = c/a by bisection
    (arcsec m = arccos(1/m)), the zone-only states in closed form, and the
    overlap-controlled path found by following the whole curve of states
    (zone c from 0 to the branch end, then the contact radius) on a grid:
    a state moves along the curve while the overlap does, and where the
    curve turns back it jumps at constant overlap to the next rising part,
    or apart."""

    def __init__(self, Estar, w, R, z0):
        K = 4.0 / 3.0 * Estar
        self.R = R
        sigma0 = 16 * w / (9 * math.sqrt(3) * z0)      # Lennard-Jones' largest stress
        self.lam = 2 * sigma0 * (R / (math.pi * w * K * K)) ** (1 / 3)
        self.sd = (math.pi ** 2 * w * w * R / K ** 2) ** (1 / 3)
        self.sF = math.pi * w * R
        lam = self.lam
        A, B = math.pi * lam / 4, 4 * lam * lam / 3 * (math.pi / 2 - 1)
        self.c0 = (-B + math.sqrt(B * B + 4 * A)) / (2 * A)   # the branch end's zone radius
        # the curve: t in [0, c0] the zone's radius, t > c0 the contact radius a = t - c0
        n = 3000
        ts = [self.c0 * k / n for k in range(n + 1)]
        amax = 3.0
        ts += [self.c0 + amax * (k / n) ** 1.5 for k in range(1, n + 1)]
        self.t = ts
        self.D = [self.at(x)[1] for x in ts]

    def m_of(self, a):
        lam = self.lam
        f = lambda m: (lam * a * a / 2 * (math.sqrt(m * m - 1) + (m * m - 2) * math.acos(1 / m))
                       + 4 * lam * lam * a / 3 * (math.sqrt(m * m - 1) * math.acos(1 / m) - m + 1) - 1)
        lo, hi = 1.0, 2.0
        while f(hi) < 0:
            lo, hi = hi, 2 * hi
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if mid in (lo, hi):
                break
            lo, hi = (mid, hi) if f(mid) < 0 else (lo, mid)
        return 0.5 * (lo + hi)

    def at(self, t):
        """(P, D) on the curve."""
        lam = self.lam
        if t <= self.c0:   # the zone alone: gap h0 at r = c, uniform stress sigma0 inside
            return -math.pi / 2 * lam * t * t, t * t / 2 - 8 * lam * t / (3 * math.pi) - 2 / (math.pi * lam)
        a = t - self.c0
        m = self.m_of(a)
        s = math.sqrt(m * m - 1)
        return a ** 3 - lam * a * a * (s + m * m * math.acos(1 / m)), a * a - 4 * lam * a * s / 3

    def solve(self, k, D, lo=None):
        """t in cell k (D rising across it; from lo if given) with D(t) = D, by bisection."""
        lo, hi = self.t[k] if lo is None else lo, self.t[k + 1]
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if mid in (lo, hi):
                break
            lo, hi = (mid, hi) if self.at(mid)[1] < D else (lo, mid)
        return 0.5 * (lo + hi)

    def rising(self, k):
        return self.D[k + 1] > self.D[k]

    def least(self, lo, hi, which):
        """The t in (lo, hi) where P (which = 0) or D (1) is least, by golden section."""
        g = (3 - math.sqrt(5)) / 2
        for _ in range(200):
            x1, x2 = lo + g * (hi - lo), hi - g * (hi - lo)
            if self.at(x1)[which] <= self.at(x2)[which]:
                hi = x2
            else:
                lo = x1
            if hi - lo < 1e-15 * (1 + hi):
                break
        return 0.5 * (lo + hi)

    def fold(self, k):
        """The least D near cell k (over cells k-1..k+1): (t, D)."""
        x = self.least(self.t[max(k - 1, 0)], self.t[min(k + 2, len(self.t) - 1)], 1)
        return x, self.at(x)[1]

    def path(self, Ds, solve=lambda i: True):
        """The overlap-controlled states along the overlaps Ds: per overlap
        the curve's parameter t (where solve(index)), or None (apart)."""
        out, k = [], None
        for i, D in enumerate(Ds):
            if k is None:
                if D >= self.D[0]:   # the zone reaches the surfaces: the first rising crossing
                    k = next((j for j in range(len(self.t) - 1) if self.rising(j) and self.D[j] <= D <= self.D[j + 1]), None)
            else:
                while k + 1 < len(self.t) - 1 and D > self.D[k + 1]:
                    k += 1
                while k is not None and D < self.D[k]:
                    if k > 0 and self.rising(k - 1):
                        k -= 1
                        continue
                    tf, Df = self.fold(k)   # the curve turns back here
                    if D >= Df:
                        break
                    # the jump: the next rising part at smaller t, or apart
                    k = next((j for j in range(k - 1, -1, -1) if self.rising(j) and self.D[j] <= D <= self.D[j + 1]), None)
            if k is not None and not solve(i):
                out.append(self.t[k])   # attached, not solved here
            elif k is not None and not (self.D[k] <= D):
                out.append(self.fold_solve(k, D))
            else:
                out.append(None if k is None else self.solve(k, D))
        return out

    def fold_solve(self, k, D):
        """D lies between the fold and cell k's lower end: the rising side of the fold."""
        return self.solve(k, D, lo=self.fold(k)[0])

    def pulloff(self):
        """The pull-off force under load control (N): the least force of the
        contact branch (the curve beyond the zone), by golden section around
        the grid's least."""
        n0 = next(j for j, t in enumerate(self.t) if t > self.c0)
        k = min(range(n0, len(self.t)), key=lambda j: self.at(self.t[j])[0])
        x = self.least(self.t[max(k - 1, n0)], self.t[min(k + 1, len(self.t) - 1)], 0)
        return min(self.at(x)[0], self.at(self.t[n0])[0]) * self.sF

    def loss(self):
        """The work a collision loses (J): minus the integral of P dD along
        the curve from the retraction's last fold to the approach's landing
        point (trapezoid in D, Richardson on 2 grids)."""
        lam = self.lam
        t_in = self.path([-2 / (math.pi * lam)])[0]
        # the retraction ends at the curve's least D below t_in
        k = min(range(len(self.t) - 1), key=lambda j: self.D[j] if self.t[j] < t_in else 1e300)
        t_f = self.fold(k)[0]

        def trap(n):
            pts = [self.at(t_f + (t_in - t_f) * j / n) for j in range(n + 1)]
            return sum(0.5 * (pts[j][0] + pts[j + 1][0]) * (pts[j + 1][1] - pts[j][1]) for j in range(n))

        I1, I2 = trap(1000), trap(2000)
        return -(I2 + (I2 - I1) / 3) * self.sF * self.sd
