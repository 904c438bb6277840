/* Evaluation of the library's generated piecewise polynomials (the
   tables of c_core/src/hertz_geometry_poly.h and jkr_sphere_poly.h, from
   the generators in tests/reference), public for the inline hot paths
   that read them (dc/jkr_sphere.h). One piece is a table c[16][nl] of nl
   lanes: the constant term as a head and a rest, then the coefficients of
   x^1 .. x^14. */
#ifndef DC_POLY14_H
#define DC_POLY14_H

#define DC_POLY14_NROWS 16

/* Lanes f < n (of nl) at x: y[f] = head + s[f], s[f] = rest + x P(x), P = c1 +
   ... + c14 x^13 by Estrin's scheme, in the order the generators check
   (the only rounding at full size is the last addition); s is returned
   for callers that need the value split. */
static inline void dc_poly14(const double *c, int nl, int n, double x, double *y, double *s)
{
  const double x2 = x * x, x4 = x2 * x2, x8 = x4 * x4;
  for (int f = 0; f < n; f++) {
    const double *k = c + f;
    const double a0 = k[2 * nl] + k[3 * nl] * x, a1 = k[4 * nl] + k[5 * nl] * x;
    const double a2 = k[6 * nl] + k[7 * nl] * x, a3 = k[8 * nl] + k[9 * nl] * x;
    const double a4 = k[10 * nl] + k[11 * nl] * x, a5 = k[12 * nl] + k[13 * nl] * x;
    const double a6 = k[14 * nl] + k[15 * nl] * x;
    const double b0 = a0 + a1 * x2, b1 = a2 + a3 * x2, b2 = a4 + a5 * x2;
    const double P = (b0 + b1 * x4) + (b2 + a6 * x4) * x8;
    s[f] = k[nl] + x * P;
    y[f] = k[0] + s[f];
  }
}

#endif
