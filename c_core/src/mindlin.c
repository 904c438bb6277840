/* Mindlin no-slip tangential stiffness (dc/mindlin.h, review Eqs. 56-58). */
#include "dc/mindlin.h"
#include "dc/status.h"
#include <math.h>

int dc_mindlin_pair_init(double E1, double nu1, double E2, double nu2, dc_mindlin_pair *p)
{
  if (!(E1 > 0.0 && isfinite(E1) && E2 > 0.0 && isfinite(E2) && nu1 > -1.0 && nu1 <= 0.5 &&
        nu2 > -1.0 && nu2 <= 0.5))
    return DC_EDOM;
  const double c1 = 2.0 * (1.0 + nu1) / E1, c2 = 2.0 * (1.0 + nu2) / E2; /* 1/G_i */
  const double s0 = c1 + c2, s1 = nu1 * c1 + nu2 * c2;
  if (!(isfinite(s0) && isfinite(s1))) return DC_ERANGE;   /* E_i so small that 1/G_i overflows */
  p->s0 = s0;
  p->s1 = s1;
  return DC_OK;
}

int dc_mindlin_stiffness(const dc_mindlin_pair *p, double a, double K, double D,
                         double *k_major, double *k_minor)
{
  if (!(a >= 0.0 && isfinite(a) && K > 0.0 && isfinite(K) && D > 0.0 && isfinite(D) && p->s0 > 0.0 &&
        isfinite(p->s0) && isfinite(p->s1)))
    return DC_EDOM;
  const double c_major = (p->s0 - p->s1) * K + p->s1 * D;   /* Eq. 57, theta = 0 */
  const double c_minor = p->s0 * K - p->s1 * D;             /* Eq. 57, theta = pi/2 */
  double km = 2.0 * M_PI * a / c_major, kn = 2.0 * M_PI * a / c_minor;
  /* 2 pi a overflowed: 2 pi (a/c) overflows only with the result */
  if (!isfinite(km)) km = 2.0 * M_PI * (a / c_major);
  if (!isfinite(kn)) kn = 2.0 * M_PI * (a / c_minor);
  if (!isfinite(km) || !isfinite(kn)) return DC_ERANGE;
  *k_major = km;
  *k_minor = kn;
  return DC_OK;
}

int dc_mindlin_chi(const dc_hertz_geom *g, double nu, double theta, double *chi)
{
  if (!(nu >= 0.0 && nu <= 0.5 && isfinite(theta))) return DC_EDOM;
  const double c = cos(theta), s = sin(theta);
  const double A = (1.0 - nu) * g->K + nu * g->D, B = g->K - nu * g->D;
  *chi = 1.0 / sqrt(A * A * c * c + B * B * s * s);
  return DC_OK;
}
