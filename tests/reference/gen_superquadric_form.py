#!/usr/bin/env python3
"""Reference curvature forms of superquadrics for dc_superquadric_form
(tests/unit/test_curvature.c): f = (|x/a|^n2 + |y/b|^n2)^(n1/n2) + |z/c|^n1 - 1
(LIGGGHTS' shape function), a point p on f = 0 found by bisection along a
random direction, the tangent basis (u, v) of its unit normal, and the form
(u.Hu, u.Hv, v.Hv) / |grad f| with grad f and the Hessian by mpmath's
numerical differentiation of f itself (no closed form shared with the C
code), at 40 digits. Points keep every coordinate above 2 % of its
semi-axis (|x|^n is not smooth at 0 for fractional n). Writes
superquadric_form.csv: a,b,c,n1,n2,px,py,pz,ux,uy,uz,vx,vy,vz,f_uu,f_uv,f_vv.
Usage: python3 gen_superquadric_form.py > superquadric_form.csv"""
import random
import mpmath as mp

mp.mp.dps = 40
random.seed(20261129)


def f(s, n1, n2, x, y, z):
    a, b, c = s
    return (abs(x / a) ** n2 + abs(y / b) ** n2) ** (n1 / n2) + abs(z / c) ** n1 - 1


def grad_hess(s, n1, n2, p):
    fun = lambda x, y, z: f(s, n1, n2, x, y, z)
    g = [mp.diff(fun, p, tuple(1 if k == i else 0 for k in range(3))) for i in range(3)]
    H = [[mp.diff(fun, p, tuple((k == i) + (k == j) for k in range(3))) for j in range(3)] for i in range(3)]
    return g, H


print(__doc__.strip().split("\n")[0].replace("Reference", "# Reference"))
print("# a,b,c,n1,n2,px,py,pz,ux,uy,uz,vx,vy,vz,f_uu,f_uv,f_vv (gen_superquadric_form.py, mpmath 40 digits)")
blocks = [(2.0, 2.0), (3.0, 3.0), (4.0, 4.0), (4.0, 2.0), (2.0, 4.0), (2.5, 2.5), (5.5, 3.0), (3.0, 6.0), (8.0, 8.0), (10.0, 4.0)]
rows = 0
while rows < 120:
    n1, n2 = blocks[rows % len(blocks)]
    s = [mp.mpf(random.choice([0.5, 1.0, 1.5, 2.5, 3.5])) * mp.mpf("1e-3") for _ in range(3)]
    d = [mp.mpf(random.gauss(0, 1)) for _ in range(3)]
    lo, hi = mp.mpf(0), mp.mpf("1e-1")
    for _ in range(200):
        mid = (lo + hi) / 2
        if f(s, n1, n2, *[mid * di for di in d]) < 0:
            lo = mid
        else:
            hi = mid
    p = [(lo + hi) / 2 * di for di in d]
    if any(abs(p[k]) < 0.02 * s[k] for k in range(3)):
        continue
    g, H = grad_hess(s, n1, n2, p)
    gn = mp.sqrt(sum(x * x for x in g))
    n = [x / gn for x in g]
    # a tangent basis: u from the smallest normal component, v = n x u
    k = min(range(3), key=lambda i: abs(n[i]))
    e = [mp.mpf(1) if i == k else mp.mpf(0) for i in range(3)]
    ed = sum(e[i] * n[i] for i in range(3))
    u = [e[i] - ed * n[i] for i in range(3)]
    un = mp.sqrt(sum(x * x for x in u))
    u = [x / un for x in u]
    v = [n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0]]
    form = lambda x, y: sum(x[i] * H[i][j] * y[j] for i in range(3) for j in range(3)) / gn
    vals = [*s, n1, n2, *p, *u, *v, form(u, u), form(u, v), form(v, v)]
    print(",".join(mp.nstr(x, 20) if not isinstance(x, float) else repr(x) for x in vals))
    rows += 1
