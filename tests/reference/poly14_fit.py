"""What the generators of the degree-14 piecewise tables share
(c_core/include/dc/poly14.h): a lane-wise Chebyshev interpolant of a piece
turned into powers of x = t - centre, and the C code's evaluation order in
double arithmetic (to check the rounded coefficients as the C code uses
them)."""
from mpmath import mp


def power_coefficients(fn, a, b, n, centre):
    """For each lane of fn(t) (a list of mpf), the n + 1 coefficients (mpf)
    in powers of x = t - centre of its interpolant at the n + 1 Chebyshev
    nodes of [a, b]."""
    mid, h = (a + b) / 2, (b - a) / 2
    nodes = [mp.cos(mp.pi * (k + mp.mpf(1) / 2) / (n + 1)) for k in range(n + 1)]
    vals = [fn(mid + h * y) for y in nodes]
    T = [[mp.mpf(1)], [mp.mpf(0), mp.mpf(1)]]   # T_j in powers of y
    for j in range(2, n + 1):
        T.append([(2 * T[j - 1][i - 1] if i >= 1 else 0) - (T[j - 2][i] if i < len(T[j - 2]) else 0)
                  for i in range(j + 1)])
    s = centre - mid
    out = []
    for L in range(len(vals[0])):
        ch = [2 * sum(v[L] * mp.cos(mp.pi * j * (k + mp.mpf(1) / 2) / (n + 1)) for k, v in enumerate(vals)) / (n + 1)
              for j in range(n + 1)]
        ch[0] /= 2
        py = [sum(ch[j] * T[j][i] for j in range(i, n + 1) if i < len(T[j])) for i in range(n + 1)]
        px = [mp.mpf(0)] * (n + 1)   # y = (x + s)/h
        for i, bi in enumerate(py):
            for k in range(i + 1):
                px[k] += bi * mp.binomial(i, k) * s ** (i - k) / h ** i
        out.append(px)
    return out


def estrin_rest(c, x):
    """rest + x P(x) for c = (head, rest, c1, ..., c14), P = c1 + ... +
    c14 x^13 by Estrin's scheme, in the C code's order (Python floats)."""
    x2 = x * x
    x4 = x2 * x2
    x8 = x4 * x4
    d = c[2:]
    a = [d[2 * i] + d[2 * i + 1] * x for i in range(7)]
    b = [a[0] + a[1] * x2, a[2] + a[3] * x2, a[4] + a[5] * x2]
    P = (b[0] + b[1] * x4) + (b[2] + a[6] * x4) * x8
    return c[1] + x * P


def estrin(c, x):
    """The C code's value: head + (rest + x P(x)), one rounding at full size."""
    return c[0] + estrin_rest(c, x)
