/* Brent's bracketed root finder (dc/root_find.h). */
#include "dc/root_find.h"
#include "dc/status.h"
#include <math.h>

int dc_root_brent_ends(dc_root_fn f, void *ctx, double a, double b, double fa, double fb, double rtol,
                       double atol, int max_iter, dc_root_result *r)
{
  if (!(isfinite(a) && isfinite(b) && isfinite(fa) && isfinite(fb) && rtol >= 0.0 && isfinite(rtol) &&
        atol >= 0.0 && isfinite(atol) && max_iter >= 1))
    return DC_EDOM;
  if (!((fa <= 0.0 && fb >= 0.0) || (fa >= 0.0 && fb <= 0.0))) return DC_EDOM;
  /* b: the best point so far, a: the previous one, c: the other end of the
     bracket [b, c]; sa, sb, sc their slots */
  double c = a, fc = fa, d = b - a, e = d;
  int sa = 0, sb = 1, sc = 0, n = 0;
  for (int it = 0; it < max_iter; it++) {
    if ((fb > 0.0) == (fc > 0.0)) { c = a; fc = fa; sc = sa; d = e = b - a; }
    if (fabs(fc) < fabs(fb)) {
      a = b; b = c; c = a; fa = fb; fb = fc; fc = fa;
      sa = sb; sb = sc; sc = sa;
    }
    const double tol = rtol * fabs(b) + atol;
    double xm = 0.5 * (c - b);
    if (!isfinite(xm)) xm = 0.5 * c - 0.5 * b;   /* c - b overflowed (a bracket wider than DBL_MAX) */
    if (fabs(xm) <= tol || fb == 0.0) {
      r->x = b; r->fx = fb; r->slot = sb; r->evaluations = n;
      return DC_OK;
    }
    if (fabs(e) >= tol && fabs(fa) > fabs(fb)) {
      /* inverse quadratic interpolation (secant when a == c) */
      double s = fb / fa, pp, q;
      if (a == c) { pp = 2.0 * xm * s; q = 1.0 - s; }
      else {
        const double qq = fa / fc, rr = fb / fc;
        pp = s * (2.0 * xm * qq * (qq - rr) - (b - a) * (rr - 1.0));
        q = (qq - 1.0) * (rr - 1.0) * (s - 1.0);
      }
      if (pp > 0.0) q = -q; else pp = -pp;
      if (2.0 * pp < fmin(3.0 * xm * q - fabs(tol * q), fabs(e * q))) { e = d; d = pp / q; }
      else { d = xm; e = d; }
    } else { d = xm; e = d; }
    a = b; fa = fb; sa = sb;
    b += fabs(d) > tol ? d : (xm > 0.0 ? tol : -tol);
    /* a slot held neither by a (the old b) nor by c */
    sb = 0;
    while (sb == sa || sb == sc) sb++;
    fb = f(b, ctx, sb);
    n++;
    if (!isfinite(fb)) {
      /* f failed inside the bracket: the last point where it did not */
      r->x = a; r->fx = fa; r->slot = sa; r->evaluations = n;
      return DC_ENOCONV;
    }
  }
  r->x = b; r->fx = fb; r->slot = sb; r->evaluations = n;
  return DC_ENOCONV;
}

int dc_root_brent(dc_root_fn f, void *ctx, double a, double b, double rtol, double atol, int max_iter,
                  dc_root_result *r)
{
  if (!(isfinite(a) && isfinite(b))) return DC_EDOM;
  const double fa = f(a, ctx, 0), fb = f(b, ctx, 1);
  const int st = dc_root_brent_ends(f, ctx, a, b, fa, fb, rtol, atol, max_iter, r);
  if (st != DC_EDOM) r->evaluations += 2;
  return st;
}
