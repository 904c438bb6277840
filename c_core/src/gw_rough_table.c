/* Rough-sphere law tabulated from the full GW solver; the table, its
   layout, smoothness and error are described in dc/gw_rough_table.h. */
#include "dc/gw_rough_table.h"
#include "dc/status.h"
#include "gw_rough_table_data.h"
#include "scaled_product.h"
#include <float.h>
#include <math.h>

#if DC_GW_TABLE_DATA_NNODE != DC_GW_TABLE_NNODE || DC_GW_TABLE_DATA_NMU != DC_GW_TABLE_NMU
#error "gw_rough_table_data.h does not match dc/gw_rough_table.h: regenerate it"
#endif

/* Clenshaw sum of a Chebyshev series, sum_k c[k] T_k(t) */
static double cheb_sum(const double *c, int n, double t)
{
  double b1 = 0.0, b2 = 0.0;
  for (int k = n - 1; k >= 1; k--) {
    const double b = 2.0 * t * b1 - b2 + c[k];
    b2 = b1;
    b1 = b;
  }
  return t * b1 - b2 + c[0];
}

int dc_gw_table_init(double mu, dc_gw_table_law *law)
{
  if (!(mu >= DC_GW_TABLE_MU_MIN && mu <= DC_GW_TABLE_MU_MAX)) return DC_EDOM;
  enum { N = DC_GW_TABLE_NNODE };
  double x[N], y[N], h[N - 1], d[N - 1], s[N], diag[N], sup[N];
  const double t = 2.0 * log(mu) / log(DC_GW_TABLE_MU_MAX) - 1.0;
  for (int i = 0; i < N; i++) {
    x[i] = dc_gw_table_node(i);
    y[i] = exp(cheb_sum(dc_gw_table_logp[i], DC_GW_TABLE_NMU, t));
  }
  for (int i = 0; i < N - 1; i++) {
    h[i] = x[i + 1] - x[i];
    d[i] = (y[i + 1] - y[i]) / h[i];
  }
  /* not-a-knot cubic spline (de Boor, A Practical Guide to Splines, CUBSPL)
     for the slopes s_i: tridiagonal, solved by elimination */
  diag[0] = h[1];
  sup[0] = h[0] + h[1];
  s[0] = ((h[0] + 2.0 * sup[0]) * h[1] * d[0] + h[0] * h[0] * d[1]) / sup[0];
  for (int i = 1; i < N - 1; i++) {
    const double sub = h[i], f = sub / diag[i - 1];
    diag[i] = 2.0 * (h[i - 1] + h[i]) - f * sup[i - 1];
    sup[i] = h[i - 1];
    s[i] = 3.0 * (h[i] * d[i - 1] + h[i - 1] * d[i]) - f * s[i - 1];
  }
  {
    const double g = h[N - 2] + h[N - 3], sub = g, f = sub / diag[N - 2];
    diag[N - 1] = h[N - 3] - f * sup[N - 2];
    s[N - 1] = (h[N - 2] * h[N - 2] * d[N - 3] + (2.0 * g + h[N - 2]) * h[N - 3] * d[N - 2]) / g - f * s[N - 2];
  }
  s[N - 1] /= diag[N - 1];
  for (int i = N - 2; i >= 0; i--) s[i] = (s[i] - sup[i] * s[i + 1]) / diag[i];
  /* cell 0: the Hermite cubic from (0, slope 0) at alpha' = -6 */
  y[0] = s[0] = 0.0;
  for (int i = 0; i < N - 1; i++) {
    double *c = law->c[i];
    c[0] = y[i];
    c[1] = h[i] * s[i];
    c[2] = 3.0 * (y[i + 1] - y[i]) - h[i] * (2.0 * s[i] + s[i + 1]);
    c[3] = 2.0 * (y[i] - y[i + 1]) + h[i] * (s[i] + s[i + 1]);
  }
  /* Hertz asymptote beyond X_HI, matched in value and slope: with
     c0 = 1 - P*(X) X^-3/2 (X = X_HI) and e = X d/dX (P* X^-3/2), the form
     1 - A q^2/3 - B q (q = X/alpha') needs A + B = c0, (2/3) A + B = e */
  const double X = x[N - 1], g = y[N - 1] / (X * sqrt(X));
  const double c0 = 1.0 - g, e = s[N - 1] / sqrt(X) - 1.5 * g;
  law->A = 3.0 * (c0 - e);
  law->B = 3.0 * e - 2.0 * c0;
  law->mu = mu;
  return DC_OK;
}

int dc_gw_table_pstar(const dc_gw_table_law *law, double ap, double *P, double *dP)
{
  if (!isfinite(ap)) return DC_EDOM;
  double v, d;
  if (!(ap > DC_GW_TABLE_X_LO)) {
    v = d = 0.0;
  } else if (ap < DC_GW_TABLE_X_HI) {
    dc_gw_table_cell_(law, ap, &v, &d);
  } else {
    /* the asymptote in the sigma-form: P* = alpha'^3/2 (1 - A q^2/3 - B q) */
    const double q = DC_GW_TABLE_X_HI / ap, q23 = cbrt(q * q), sa = sqrt(ap);
    v = ap * sa * (1.0 - law->A * q23 - law->B * q);
    d = sa * (1.5 - 5.0 / 6.0 * law->A * q23 - 0.5 * law->B * q);
    if (!isfinite(v)) return DC_ERANGE;
  }
  *P = v;
  *dP = d;
  return DC_OK;
}

int dc_gw_table_pair_init(const dc_gw_table_law *law, double Estar, double sigma, dc_gw_table_pair *p)
{
  if (!(Estar > 0 && isfinite(Estar) && sigma > 0 && isfinite(sigma))) return DC_EDOM;
  const double c = 4.0 / 3.0 * Estar, inv_sigma = 1.0 / sigma, c_sigma = c * sigma * sqrt(sigma);
  if (!(isfinite(c) && isfinite(inv_sigma) && c_sigma >= DBL_MIN && c_sigma <= DBL_MAX)) return DC_ERANGE;
  p->law = *law;
  p->c = c;
  p->sigma = sigma;
  p->inv_sigma = inv_sigma;
  p->c_sigma = c_sigma;
  return DC_OK;
}

/* The law for finite inputs with sigma > 0 where the pair's constants or
   the kernel's products leave the range of doubles: P* (or P/P_h(delta)
   beyond the table) in units of the length L (sigma, or delta beyond the
   table) and of the force 4/3 E* R^1/2 L^3/2, scales applied last. */
static void force_scaled(const dc_gw_table_law *law, double Estar, double R, double sigma, double delta,
                         double *P, double *kn)
{
  const double x = delta / sigma;
  double L = sigma, Pu, knu;
  if (!(x > DC_GW_TABLE_X_LO)) {
    Pu = knu = 0.0;
  } else if (x < DC_GW_TABLE_X_HI) {
    dc_gw_table_cell_(law, x, &Pu, &knu);
  } else {
    const double q = DC_GW_TABLE_X_HI / x, q23 = cbrt(q * q);
    Pu = 1.0 - law->A * q23 - law->B * q;
    knu = 1.5 - 5.0 / 6.0 * law->A * q23 - 0.5 * law->B * q;
    L = delta;
  }
  dc_rough_sphere_scale(Estar, R, L, Pu, knu, P, kn);
}

int dc_gw_table_force(const dc_gw_table_law *law, double Estar, double R, double sigma,
                      double delta, double *P, double *kn)
{
  if (!(Estar > 0 && isfinite(Estar) && R > 0 && isfinite(R) && sigma >= 0 &&
        isfinite(sigma) && isfinite(delta)))
    return DC_EDOM;
  double Pv, knv;
  if (sigma == 0.0) {                         /* Hertz */
    dc_rough_sphere_hertz(Estar, R, delta, &Pv, &knv);
  } else {
    const double c = 4.0 / 3.0 * Estar, inv_sigma = 1.0 / sigma, c_sigma = c * sigma * sqrt(sigma);
    Pv = knv = NAN;
    if (isfinite(c) && isfinite(inv_sigma) && c_sigma >= DBL_MIN && c_sigma <= DBL_MAX)
      dc_gw_table_kernel_(law, c, inv_sigma, c_sigma, sqrt(R), delta, &Pv, &knv);
    if (!(isfinite(Pv) && isfinite(knv))) force_scaled(law, Estar, R, sigma, delta, &Pv, &knv);
  }
  if (!(isfinite(Pv) && isfinite(knv))) return DC_ERANGE;
  *P = Pv;
  *kn = knv;
  return DC_OK;
}

int dc_gw_table_check(double mu, dc_param_error *err)
{
  return dc_param_check("roughnessMu", mu, DC_GW_TABLE_MU_MIN, 0, DC_GW_TABLE_MU_MAX, 0, "[1, 50]", err);
}
