/* Rough no-slip tangential stiffness (Hisakado-Tsukizoe, review Eqs. 78-84);
   formulas and seed corrections in dc/rough_tangential.h. */
#include "dc/rough_tangential.h"
#include "dc/gw_integrals.h"
#include "dc/status.h"
#include "scaled_product.h"
#include <float.h>
#include <math.h>


int dc_rough_tangential_stiffness(double G, double chi, double n_asp, double R_asp,
                                  double sigma, double delta, double *kt)
{
  if (!(G > 0.0 && isfinite(G) && chi > 0.0 && isfinite(chi) && n_asp > 0.0 &&
        isfinite(n_asp) && R_asp > 0.0 && isfinite(R_asp) && sigma >= 0.0 &&
        isfinite(sigma) && isfinite(delta)))
    return DC_EDOM;
  const double pre = 2.0 * M_PI * n_asp * G * chi;
  double k, len, F12 = 1.0;
  if (sigma == 0.0 || sigma <= 1e-80 * fabs(delta)) {
    if (!(delta > 0.0)) { *kt = 0.0; return DC_OK; }
    len = delta;
    k = pre * sqrt(R_asp * delta);
  } else {
    dc_gw_F(DC_GW_F12, -delta / sigma, &F12);
    len = sigma;
    k = pre * sqrt(R_asp * sigma) * F12;   /* Eq. 83 with chi* = chi F_1/2 */
  }
  if (!isfinite(k)) {
    /* a product overflowed: the same without intermediate overflow */
    k = dc_scaled_product(7, (const double[]){2.0 * M_PI, n_asp, G, chi, sqrt(R_asp), sqrt(len), F12});
    if (!isfinite(k)) return DC_ERANGE;
  }
  *kt = k;
  return DC_OK;
}

int dc_rough_tangential_axes(const dc_hertz_geom *g, double n_asp, double sigma, double delta, double *a, double *b)
{
  if (!(n_asp > 0.0 && isfinite(n_asp) && sigma >= 0.0 && isfinite(sigma) && isfinite(delta))) return DC_EDOM;
  double ar;
  if (sigma == 0.0 || sigma <= 1e-80 * fabs(delta)) {
    if (!(delta > 0.0)) { *a = *b = 0.0; return DC_OK; }
    ar = n_asp * sqrt(2.0 * g->R_major * delta * g->D / g->K);   /* dc_hertz_contact's a */
    if (!isfinite(ar))
      ar = dc_scaled_product(4, (const double[]){n_asp, sqrt(2.0 * g->D / g->K), sqrt(g->R_major), sqrt(delta)});
  } else {
    double F12;
    dc_gw_F(DC_GW_F12, -delta / sigma, &F12);
    ar = n_asp * sqrt(2.0 * g->R_major * sigma * g->D / g->K) * F12;   /* Eq. 83 */
    if (!isfinite(ar) || (ar < DBL_MIN && F12 >= DBL_MIN))
      ar = dc_scaled_product(5, (const double[]){n_asp, sqrt(2.0 * g->D / g->K), sqrt(g->R_major), sqrt(sigma), F12});
  }
  if (!isfinite(ar)) return DC_ERANGE;
  *a = ar;
  *b = ar * sqrt(g->m1);
  return DC_OK;
}
