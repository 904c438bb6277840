/* Elliptic Hertz contact: eccentricity, correction factors, force and area
   (review Eqs. 1-5, 11-14; conventions and seed corrections in the header). */
#include "dc/hertz_elliptic.h"
#include "dc/elliptic_integrals.h"
#include "dc/status.h"
#include "scaled_product.h"
#include <float.h>
#include <math.h>

#include "hertz_eccentricity_cheb.h"

int dc_hertz_eccentricity_approx(double ratio, double *e2)
{
  if (!(ratio >= DC_HERTZ_RATIO_MIN && ratio <= 1.0)) return DC_EDOM;
  /* review Eq. 14: a/b = -0.177 + (ln(16/r)/(2r))^1/2 + 0.16 ln r */
  const double a_over_b = -0.177 + sqrt(0.5 / ratio * log(16.0 / ratio)) + 0.16 * log(ratio);
  *e2 = fmax(0.0, 1.0 - 1.0 / (a_over_b * a_over_b));
  return DC_OK;
}

static double clenshaw(const double *c, double x)
{
  const double x2 = 2.0 * x;
  double b1 = 0.0, b2 = 0.0;
  for (int j = DC_ECC_NCOEF - 1; j > 0; j--) {
    const double b0 = x2 * b1 - b2 + c[j];
    b2 = b1;
    b1 = b0;
  }
  return x * b1 - b2 + c[0];
}

/* e^2 and 1 - e^2 solving Eq. 13 for ratio in [DC_HERTZ_RATIO_MIN, 1]:
   e^2 = (1 - r) h(r) for r >= 1/4 and 1 - e^2 = r g(ln r) below, with h, g
   the Chebyshev fits of tests/reference/gen_hertz_eccentricity_cheb.py
   (relative error < 1e-16, so both keep full precision at both ends). */
static void eccentricity(double ratio, double *m, double *m1)
{
  if (ratio >= 0.25) {
    const double inv_w = DC_ECC_H_PIECES / 0.75;
    const double s = (ratio - 0.25) * inv_w;
    const int p = s < DC_ECC_H_PIECES - 1 ? (int)s : DC_ECC_H_PIECES - 1;
    *m = (1.0 - ratio) * clenshaw(dc_ecc_h[p], 2.0 * (s - p) - 1.0);
    *m1 = 1.0 - *m;
  } else {
    const double inv_w = DC_ECC_G_PIECES / (DC_ECC_G_THI - DC_ECC_G_TLO);
    const double s = fmax(0.0, (log(ratio) - DC_ECC_G_TLO) * inv_w);
    const int p = s < DC_ECC_G_PIECES - 1 ? (int)s : DC_ECC_G_PIECES - 1;
    *m1 = ratio * clenshaw(dc_ecc_g[p], 2.0 * (s - p) - 1.0);
    *m = 1.0 - *m1;
  }
}

int dc_hertz_eccentricity(double ratio, double *e2, double *m1)
{
  if (!(ratio >= DC_HERTZ_RATIO_MIN && ratio <= 1.0)) return DC_EDOM;
  eccentricity(ratio, e2, m1);
  return DC_OK;
}

int dc_hertz_geometry(double R1, double R2, dc_hertz_geom *out)
{
  if (!(R1 > 0.0 && R2 > 0.0 && isfinite(R1) && isfinite(R2))) return DC_EDOM;
  const double Rmaj = fmax(R1, R2), Rmin = fmin(R1, R2);
  const double ratio = Rmin / Rmaj;
  if (ratio < DC_HERTZ_RATIO_MIN) return DC_EDOM;
  dc_hertz_geom g;
  g.R_major = Rmaj;
  g.R_minor = Rmin;
  /* Eq. 5; where R_major R_minor would overflow or leave the normal range,
     the equal R_minor/(1 + ratio), which cannot */
  const double prod = Rmaj * Rmin;
  g.Rc = prod >= DBL_MIN && prod <= DBL_MAX ? prod / (Rmaj + Rmin) : Rmin / (1.0 + ratio);
  if (ratio == 1.0) {
    g.e2 = 0.0; g.m1 = 1.0;
    g.K = g.E = 0.5 * M_PI; g.D = 0.25 * M_PI;
    g.gamma = M_SQRT2; g.beta = 2.0;
    g.R_force = Rmaj;        /* = Rc gamma^2 exactly */
    g.R_area = Rmaj;         /* = Rc beta exactly */
    *out = g;
    return DC_OK;
  }
  dc_ellint el;
  eccentricity(ratio, &g.e2, &g.m1);
  if (ratio >= 0.25) dc_ellint_m(g.e2, &el);
  else dc_ellint_m1(g.m1, &el);
  g.K = el.K; g.E = el.E; g.D = el.D;
  /* with q = 1/(K (1-e^2)^1/2): Eq. 11 squared is gamma^2 = pi^2/2 E/(K^3 (1-e^2))
     = pi^2/2 E q^3 (1-e^2)^1/2, Eq. 12 is beta = 2 E q */
  const double sm1 = sqrt(g.m1);
  const double q = 1.0 / (el.K * sm1);
  const double gamma2 = 0.5 * M_PI * M_PI * el.E * q * q * q * sm1;
  g.gamma = sqrt(gamma2);                                                   /* Eq. 11 */
  g.beta = 2.0 * el.E * q;                                                  /* Eq. 12 */
  g.R_force = g.Rc * gamma2;
  g.R_area = g.Rc * g.beta;
  if (!(isfinite(g.R_force) && isfinite(g.R_area))) {
    /* R_force, R_area <= R_major (equal for the circle); near the circle,
       with R_major within rounding of DBL_MAX, the products above round past
       it: the same as fractions of R_major, which exceed 1 by rounding only */
    g.R_force = Rmaj * fmin(1.0, g.Rc / Rmaj * gamma2);
    g.R_area = Rmaj * fmin(1.0, g.Rc / Rmaj * g.beta);
  }
  if (!(isfinite(g.R_force) && isfinite(g.R_area))) return DC_ERANGE;   /* not reached */
  *out = g;
  return DC_OK;
}


int dc_hertz_contact(const dc_hertz_geom *g, double Estar, double delta, dc_hertz_state *s)
{
  if (!(Estar > 0.0 && isfinite(Estar) && delta >= 0.0 && isfinite(delta))) return DC_EDOM;
  const double root = sqrt(g->R_force * delta);
  dc_hertz_state h;
  h.F = 4.0 / 3.0 * Estar * root * delta;                 /* Eq. 1 */
  h.kn = 2.0 * Estar * root;
  h.area = M_PI * g->R_area * delta;                      /* Eq. 2 */
  h.a = sqrt(2.0 * g->R_major * delta * g->D / g->K);
  h.b = h.a * sqrt(g->m1);
  /* where an intermediate product overflowed: the same expression without
     overflow before the end; DC_ERANGE if a result itself does */
  const double sR = sqrt(g->R_force), sd = sqrt(delta);
  if (!isfinite(h.F)) h.F = dc_scaled_product(5, (const double[]){4.0 / 3.0, Estar, sR, sd, delta});
  if (!isfinite(h.kn)) h.kn = dc_scaled_product(4, (const double[]){2.0, Estar, sR, sd});
  if (!isfinite(h.area)) h.area = dc_scaled_product(3, (const double[]){M_PI, g->R_area, delta});
  if (!isfinite(h.a)) {
    h.a = dc_scaled_product(3, (const double[]){sqrt(2.0 * g->D / g->K), sqrt(g->R_major), sd});
    h.b = h.a * sqrt(g->m1);
  }
  if (!(isfinite(h.F) && isfinite(h.kn) && isfinite(h.area) && isfinite(h.a))) return DC_ERANGE;
  *s = h;
  return DC_OK;
}

int dc_hertz_normal(const dc_hertz_geom *g, double Estar, double delta, dc_contact *c)
{
  dc_hertz_state s = {0.0, 0.0, 0.0, 0.0, 0.0};
  if (!isfinite(delta)) return DC_EDOM;
  if (delta > 0.0) {
    const int st = dc_hertz_contact(g, Estar, delta, &s);
    if (st != DC_OK) return st;
  } else if (!(Estar > 0.0 && isfinite(Estar))) {
    return DC_EDOM;
  }
  c->F = c->F_bound = s.F;
  c->kn = s.kn;
  c->area = s.area;
  c->a = s.a;
  c->b = s.b;
  c->formed = delta > 0.0;
  return DC_OK;
}
