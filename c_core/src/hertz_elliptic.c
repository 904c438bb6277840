/* Elliptic Hertz contact: eccentricity, correction factors, force and area
   (review Eqs. 1-5, 11-14; conventions and seed corrections in the header). */
#include "dc/hertz_elliptic.h"
#include "dc/elliptic_integrals.h"
#include "dc/status.h"
#include <math.h>

#include "hertz_eccentricity_cheb.h"

/* r(m) = (1 - m) D / B and s = d ln r / d ln m1 = 1/2 + C/(2D) + m1 C/(2B),
   from dD/dm = (D - C)/(2 m1) and dB/dm = C/2. */
static double ratio_slope(const dc_ellint *el, double m1)
{
  return 0.5 + 0.5 * el->C / el->D + 0.5 * m1 * el->C / el->B;
}

int dc_hertz_eccentricity_approx(double ratio, double *e2)
{
  if (!(ratio >= DC_HERTZ_RATIO_MIN && ratio <= 1.0)) return DC_EDOM;
  /* review Eq. 14: a/b = -0.177 + (ln(16/r)/(2r))^1/2 + 0.16 ln r */
  const double a_over_b = -0.177 + sqrt(0.5 / ratio * log(16.0 / ratio)) + 0.16 * log(ratio);
  *e2 = fmax(0.0, 1.0 - 1.0 / (a_over_b * a_over_b));
  return DC_OK;
}

/* ln(1 - e^2) to ~3e-11 relative from the Chebyshev fit of q(t) = ln(1-e^2)/t
   (tests/reference/gen_hertz_eccentricity_cheb.py), t = ln ratio < 0. */
static double log_m1_guess(double t)
{
  int p = 0;
  while (p < DC_HERTZ_CHEB_PIECES - 1 && t > dc_hertz_cheb_hi[p]) p++;
  const double lo = dc_hertz_cheb_lo[p], hi = dc_hertz_cheb_hi[p];
  const double x = (2.0 * t - lo - hi) / (hi - lo), x2 = 2.0 * x;
  const double *c = dc_hertz_cheb[p];
  double b1 = 0.0, b2 = 0.0;
  for (int j = DC_HERTZ_CHEB_NCOEF - 1; j > 0; j--) {
    const double b0 = x2 * b1 - b2 + c[j];
    b2 = b1;
    b1 = b0;
  }
  return t * (x * b1 - b2 + c[0]);
}

/* Newton's method for r(m) = ratio, in m while e^2 is moderate (so small e^2
   keeps its relative precision) and in x = ln(1 - m) when the ellipse is
   slender. Once a step is below 1e-8 (relative) it is applied to m and, by the
   exact derivatives dK/dm = B/(2 m1), dE/dm = -D/2, dD/dm = (D - C)/(2 m1),
   to K, E, D: the error left is O(step^2), below rounding. */
static int solve_eccentricity(double ratio, double *m_out, double *m1_out, dc_ellint *el)
{
  const double y = log_m1_guess(log(ratio));
  if (ratio > 0.25) {
    double m = -expm1(y);
    for (int it = 0; it < 30; it++) {
      const double m1 = 1.0 - m;
      dc_ellint_m(m, el);
      const double r = m1 * el->D / el->B;
      /* dr/dm = -r s / m1 */
      const double dm = (r - ratio) * m1 / (r * ratio_slope(el, m1));
      /* near the circle m is only as precise as 1 - ratio: eps absolute */
      if (fabs(dm) <= fmax(1e-8 * m, 4e-16)) {
        el->K += 0.5 * el->B / m1 * dm;
        el->E -= 0.5 * el->D * dm;
        el->D += 0.5 * (el->D - el->C) / m1 * dm;
        *m_out = m + dm;
        *m1_out = m1 - dm;
        return DC_OK;
      }
      m = fmin(fmax(m + dm, 0.0), 0.9);
    }
  } else {
    double x = y, m1 = exp(y);
    for (int it = 0; it < 30; it++) {
      dc_ellint_m1(m1, el);
      /* Newton on ln r(x) = ln ratio; ln(1 + u) ~ u is exact to O(u^2),
         and u ~ 3e-11 from the fitted start */
      const double u = m1 * el->D / (el->B * ratio) - 1.0;
      const double dx = -(fabs(u) < 1e-6 ? u : log1p(u)) / ratio_slope(el, m1);
      if (fabs(dx) <= 1e-8) {
        /* dm = -m1 dx */
        el->K -= 0.5 * el->B * dx;
        el->E += 0.5 * m1 * el->D * dx;
        el->D -= 0.5 * (el->D - el->C) * dx;
        *m1_out = m1 * (1.0 + dx + 0.5 * dx * dx);
        *m_out = 1.0 - *m1_out;
        return DC_OK;
      }
      x = fmin(x + dx, log(0.5));
      m1 = exp(x);
    }
  }
  return DC_ENOCONV;
}

int dc_hertz_eccentricity(double ratio, double *e2, double *m1)
{
  if (!(ratio >= DC_HERTZ_RATIO_MIN && ratio <= 1.0)) return DC_EDOM;
  dc_ellint el;
  if (ratio == 1.0) { *e2 = 0.0; *m1 = 1.0; return DC_OK; }
  return solve_eccentricity(ratio, e2, m1, &el);
}

int dc_hertz_geometry(double R1, double R2, dc_hertz_geom *g)
{
  if (!(R1 > 0.0 && R2 > 0.0 && isfinite(R1) && isfinite(R2))) return DC_EDOM;
  const double Rmaj = fmax(R1, R2), Rmin = fmin(R1, R2);
  const double ratio = Rmin / Rmaj;
  if (ratio < DC_HERTZ_RATIO_MIN) return DC_EDOM;
  g->R_major = Rmaj;
  g->R_minor = Rmin;
  g->Rc = Rmaj * Rmin / (Rmaj + Rmin);
  if (ratio == 1.0) {
    g->e2 = 0.0; g->m1 = 1.0;
    g->K = g->E = 0.5 * M_PI; g->D = 0.25 * M_PI;
    g->gamma = M_SQRT2; g->beta = 2.0;
    g->R_force = Rmaj;        /* = Rc gamma^2 exactly */
    g->R_area = Rmaj;         /* = Rc beta exactly */
    return DC_OK;
  }
  dc_ellint el;
  int st = solve_eccentricity(ratio, &g->e2, &g->m1, &el);
  if (st != DC_OK) return st;
  g->K = el.K; g->E = el.E; g->D = el.D;
  const double sm1 = sqrt(g->m1);
  g->gamma = M_PI * M_SQRT2 * sqrt(el.E) / (2.0 * el.K * sqrt(el.K) * sm1);  /* Eq. 11 */
  g->beta = 2.0 * el.E / (el.K * sm1);                                       /* Eq. 12 */
  g->R_force = g->Rc * g->gamma * g->gamma;
  g->R_area = g->Rc * g->beta;
  return DC_OK;
}

int dc_hertz_contact(const dc_hertz_geom *g, double Estar, double delta, dc_hertz_state *s)
{
  if (!(Estar > 0.0 && delta >= 0.0 && isfinite(delta))) return DC_EDOM;
  const double root = sqrt(g->R_force * delta);
  s->F = 4.0 / 3.0 * Estar * root * delta;                 /* Eq. 1 */
  s->kn = 2.0 * Estar * root;
  s->area = M_PI * g->R_area * delta;                      /* Eq. 2 */
  s->a = sqrt(2.0 * g->R_major * delta * g->D / g->K);
  s->b = s->a * sqrt(g->m1);
  return DC_OK;
}
