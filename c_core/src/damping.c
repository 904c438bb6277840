/* Damping laws (dc/damping.h). */
#include "dc/damping.h"
#include "dc/elliptic_integrals.h"
#include "dc/status.h"
#include <float.h>
#include <math.h>

int dc_damping_beta(double e, double *beta)
{
  if (!(e > 0.0 && e <= 1.0)) return DC_EDOM;
  const double l = log(e);
  *beta = l / sqrt(l * l + M_PI * M_PI);
  return DC_OK;
}

int dc_damping_tsuji_alpha(double e, double *alpha)
{
  if (!(e > 0.0 && e <= 1.0)) return DC_EDOM;
  const double l = log(e);
  *alpha = -2.2664 * l / sqrt(l * l + 10.1354);
  return DC_OK;
}

int dc_punch_stiffness(double Estar, double a, double b, double *k)
{
  if (!(Estar > 0.0 && isfinite(Estar) && b > 0.0 && a >= b && isfinite(a))) return DC_EDOM;
  if (a == b) {
    double r = dc_punch_stiffness_circle(Estar, a);
    if (!isfinite(r)) r = 2.0 * (Estar * a);   /* 2 E* overflowed */
    if (!isfinite(r)) return DC_ERANGE;
    *k = r;
    return DC_OK;
  }
  const double g = b / a, m1 = g * g;
  double K;
  if (m1 >= DBL_MIN) {
    dc_ellint el;
    dc_ellint_m1(m1, &el);
    K = el.K;
  } else {
    /* (b/a)^2 underflows: K = ln(4 a/b) + O((b/a)^2 ln(a/b)), exact to
       rounding, from the logarithms of a and b (b/a itself may underflow) */
    K = 2.0 * M_LN2 + (log(a) - log(b));
  }
  double r = M_PI * Estar * a / K;
  if (!isfinite(r)) r = M_PI / K * a * Estar;   /* pi E* a overflowed; K > pi/2 */
  if (!isfinite(r)) return DC_ERANGE;
  *k = r;
  return DC_OK;
}
