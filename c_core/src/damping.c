/* Damping laws (dc/damping.h). */
#include "dc/damping.h"
#include "dc/elliptic_integrals.h"
#include "dc/status.h"
#include <math.h>

int dc_damping_beta(double e, double *beta)
{
  if (!(e > 0.0 && e <= 1.0)) return DC_EDOM;
  const double l = log(e);
  *beta = l / sqrt(l * l + M_PI * M_PI);
  return DC_OK;
}

int dc_punch_stiffness(double Estar, double a, double b, double *k)
{
  if (!(Estar > 0.0 && isfinite(Estar) && b > 0.0 && a >= b && isfinite(a))) return DC_EDOM;
  if (a == b) {
    *k = dc_punch_stiffness_circle(Estar, a);
    return DC_OK;
  }
  const double g = b / a;
  dc_ellint el;
  dc_ellint_m1(g * g, &el);
  const double r = M_PI * Estar * a / el.K;
  if (!isfinite(r)) return DC_ERANGE;
  *k = r;
  return DC_OK;
}
