/* Complete elliptic integrals by the arithmetic-geometric mean.
   With a0 = 1, b0 = sqrt(m1), c0^2 = m and c_{n+1} = c_n^2 / (4 a_{n+1}):
     K = pi / (2 a_N),  K - E = K sum_{n>=0} 2^(n-1) c_n^2   (Abramowitz-Stegun 17.6).
   Writing t_n = c_n / m (n >= 1, t_1 = 1/(4 a_1), t_{n+1} = m t_n^2/(4 a_{n+1}))
   and S = sum_{n>=1} 2^(n-1) t_n^2 gives, with no cancellation at m -> 0:
     D = K (1/2 + m S),  B = K (1/2 - m S),  C = 2 K S,  E = K - m D.
   As m -> 1, E = K - m D cancels (log10 K digits lost); there Legendre's
   relation E K' + E' K - K K' = pi/2 (A-S 17.3.13) with the complementary
   K' = K(m1), D' = D(m1) gives E = pi/(2K') + m1 K D'/K' without cancellation,
   and B = (E - m1 K)/m. */
#include "dc/elliptic_integrals.h"
#include "dc/status.h"
#include <math.h>

static void ellint_agm(double m, double m1, dc_ellint *out)
{
  double a = 0.5 * (1.0 + sqrt(m1));        /* a_1 */
  double b = sqrt(sqrt(m1));                /* b_1 = sqrt(a_0 b_0) */
  double t = 0.25 / a;                      /* t_1 */
  double w = 1.0;                           /* 2^(n-1) */
  double S = t * t;
  for (int n = 1; n < 40 && fabs(a - b) > 1e-15 * a; n++) {
    double an = 0.5 * (a + b);
    b = sqrt(a * b);
    a = an;
    t = m * t * t / (4.0 * a);
    w *= 2.0;
    S += w * t * t;
  }
  /* a and b agree to 1e-15: one more mean is exact to rounding */
  a = 0.5 * (a + b);
  const double K = M_PI / (2.0 * a);
  out->K = K;
  out->D = K * (0.5 + m * S);
  out->B = K * (0.5 - m * S);
  out->C = 2.0 * K * S;
  out->E = K * (1.0 - m * (0.5 + m * S));
}

static void ellint_all(double m, double m1, dc_ellint *out)
{
  ellint_agm(m, m1, out);
  if (m1 < 0.1) {
    dc_ellint c;
    ellint_agm(m1, m, &c);
    out->E = M_PI / (2.0 * c.K) + m1 * out->K * c.D / c.K;
    out->B = (out->E - m1 * out->K) / m;
  }
}

int dc_ellint_m(double m, dc_ellint *out)
{
  if (!(m >= 0.0 && m < 1.0)) return DC_EDOM;
  ellint_all(m, 1.0 - m, out);
  return DC_OK;
}

int dc_ellint_m1(double m1, dc_ellint *out)
{
  if (!(m1 > 0.0 && m1 <= 1.0)) return DC_EDOM;
  ellint_all(1.0 - m1, m1, out);
  return DC_OK;
}
