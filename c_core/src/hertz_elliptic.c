/* Elliptic Hertz contact: eccentricity, correction factors, force and area
   (review Eqs. 1-5, 11-14; conventions and seed corrections in the header). */
#include "dc/hertz_elliptic.h"
#include "dc/elliptic_integrals.h"
#include "dc/status.h"
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
  eccentricity(ratio, &g->e2, &g->m1);
  if (ratio >= 0.25) dc_ellint_m(g->e2, &el);
  else dc_ellint_m1(g->m1, &el);
  g->K = el.K; g->E = el.E; g->D = el.D;
  /* with q = 1/(K (1-e^2)^1/2): Eq. 11 squared is gamma^2 = pi^2/2 E/(K^3 (1-e^2))
     = pi^2/2 E q^3 (1-e^2)^1/2, Eq. 12 is beta = 2 E q */
  const double sm1 = sqrt(g->m1);
  const double q = 1.0 / (el.K * sm1);
  const double gamma2 = 0.5 * M_PI * M_PI * el.E * q * q * q * sm1;
  g->gamma = sqrt(gamma2);                                                   /* Eq. 11 */
  g->beta = 2.0 * el.E * q;                                                  /* Eq. 12 */
  g->R_force = g->Rc * gamma2;
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
